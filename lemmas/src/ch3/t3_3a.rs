//! Claim T3.3a (Theorem 3.3(1)): every visibility cell — every bounded face
//! of the arrangement of the map edges and all visibility rays (Def 3.8) —
//! is a convex polygon.
//!
//! Convex means: walking the cell's boundary counter-clockwise never turns
//! clockwise (no reflex vertex), never reverses (no spike), and the edge
//! directions turn once around (winding 1). Straight (180°) vertices are
//! allowed — the thesis's proof only excludes reflex vertices — and
//! counted (case **straight vertex**). They are rare: rays end only on ∂M, so no
//! ray ends on another ray inside the map; a cell gets one only where its
//! boundary passes straight through a vertex of degree ≥ 3 whose other
//! edges lie outside the cell.
//!
//! ## Trust
//! Exhaustive over the cells of each map, exact. The checker builds the
//! decomposition with the production code ([`wai_cells::visibility_rays`],
//! [`wai_cells::Arrangement::new`]) and examines **every** cell: each turn
//! of its boundary is an exact orientation of three rational points, and
//! the winding is counted from the exact angular order of the edge
//! directions. The verdict rests on the arrangement's faces being the
//! faces of the true arrangement (its `sanity_check` — topology, and
//! geometry: every edge on its support, faces of positive area — is run
//! first, and a failure is a violation of this claim, since then no cell
//! can be vouched for) and on the rays being all rays of Def 3.8 (tested in
//! `wai-cells` against a brute-force enumeration).
//!
//! ## Cases
//! The proof's two kinds of cell vertex, counted per vertex of every cell:
//! **boundary vertex** (on ∂M: a map vertex or a ray's end; a reflex one
//! would send rays into the cell) and **interior vertex** (two or more rays
//! crossing inside M, which cannot be reflex because rays run from ∂M to
//! ∂M); and, among them, **straight vertex** (a 180° turn).

use std::cmp::Ordering;

use rug::Rational;
use serde_json::json;
use wai_exact::RatPoint;

use crate::framework::{Case, Checker, Report, Violation};
use wai_study::sample;
use wai_study::Study;

const ID: &str = "T3.3a";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study).with_cases(&[
    Case {
        name: BOUNDARY,
        what: "a cell vertex on the map boundary (a map vertex or the end of a ray; Thm \
               3.3's proof, part 1)",
    },
    Case {
        name: INTERIOR,
        what: "a cell vertex inside the map, where rays cross (Thm 3.3's proof, part 1)",
    },
    Case {
        name: STRAIGHT,
        what: "a cell vertex where the boundary runs straight on (180 degrees)",
    },
]);

/// Case: a cell vertex on ∂M.
pub const BOUNDARY: &str = "boundary vertex";
/// Case: a cell vertex inside M.
pub const INTERIOR: &str = "interior vertex";
/// Case: a straight cell vertex.
pub const STRAIGHT: &str = "straight vertex";

/// Checks T3.3a on every cell of a map: one instance per cell.
fn check_study(study: &Study<'_>) -> Report {
    let map = study.map();
    let arr = study.arrangement();
    let mut report = Report::new(ID);
    if let Err(e) = study.arrangement_sanity() {
        report.record(Some(Violation::with_data(
            format!(
                "map {}: the arrangement fails its sanity check: {e}",
                sample::map_name(map)
            ),
            json!({"map": sample::map_name(map), "sanity_check": e}),
        )));
        return report;
    }
    for f in arr.cells() {
        for v in arr.face_vertices(f) {
            report.hit(if arr.is_on_map_boundary(v) {
                BOUNDARY
            } else {
                INTERIOR
            });
        }
        let ring: Vec<RatPoint> = arr.face_points(f);
        report.absorb(check_cell(sample::map_name(map), f, &ring));
    }
    report
}

/// The directions of a cell's edges (from vertex i to i + 1), each scaled
/// by a positive factor (signs of cross and dot products, and the angular
/// order, are those of the true directions).
///
/// Implementation note: for points `(x, y) / w` (w > 0) the direction
/// from a to b scaled by `wa·wb` is `(xb·wa − xa·wb, yb·wa − ya·wb)`. When
/// every component is below 2^62 the cross and dot products of two are
/// below 2^125: exact in `i128` (`Small`). Otherwise the rational
/// differences (`Big`).
enum Dirs {
    Small(Vec<(i128, i128)>),
    Big(Vec<(Rational, Rational)>),
}

impl Dirs {
    fn of(ring: &[RatPoint]) -> Dirs {
        let k = ring.len();
        let small = || -> Option<Vec<(i128, i128)>> {
            let t: Vec<[i128; 3]> = ring
                .iter()
                .map(|p| Some([p.hx().to_i128()?, p.hy().to_i128()?, p.hw().to_i128()?]))
                .collect::<Option<_>>()?;
            let fits = |c: i128| c.unsigned_abs() < 1 << 62;
            (0..k)
                .map(|i| {
                    let (a, b) = (t[i], t[(i + 1) % k]);
                    let dx = b[0]
                        .checked_mul(a[2])?
                        .checked_sub(a[0].checked_mul(b[2])?)?;
                    let dy = b[1]
                        .checked_mul(a[2])?
                        .checked_sub(a[1].checked_mul(b[2])?)?;
                    (fits(dx) && fits(dy)).then_some((dx, dy))
                })
                .collect()
        };
        match small() {
            Some(d) => Dirs::Small(d),
            None => Dirs::Big(
                (0..k)
                    .map(|i| {
                        let (a, b) = (coords(&ring[i]), coords(&ring[(i + 1) % k]));
                        (b.0 - a.0, b.1 - a.1)
                    })
                    .collect(),
            ),
        }
    }

    fn is_zero(&self, i: usize) -> bool {
        match self {
            Dirs::Small(d) => d[i] == (0, 0),
            Dirs::Big(d) => d[i].0 == 0 && d[i].1 == 0,
        }
    }

    fn cross(&self, i: usize, j: usize) -> Ordering {
        match self {
            Dirs::Small(d) => (d[i].0 * d[j].1 - d[i].1 * d[j].0).cmp(&0),
            Dirs::Big(d) => {
                (Rational::from(&d[i].0 * &d[j].1) - Rational::from(&d[i].1 * &d[j].0)).cmp0()
            }
        }
    }

    fn dot(&self, i: usize, j: usize) -> Ordering {
        match self {
            Dirs::Small(d) => (d[i].0 * d[j].0 + d[i].1 * d[j].1).cmp(&0),
            Dirs::Big(d) => {
                (Rational::from(&d[i].0 * &d[j].0) + Rational::from(&d[i].1 * &d[j].1)).cmp0()
            }
        }
    }

    /// The upper or lower half of the directions, for the angular order
    /// from the positive x axis: 0 for angles in [0, π), 1 for [π, 2π).
    fn half(&self, i: usize) -> u8 {
        let upper = match self {
            Dirs::Small(d) => d[i].1 > 0 || (d[i].1 == 0 && d[i].0 > 0),
            Dirs::Big(d) => d[i].1 > 0 || (d[i].1 == 0 && d[i].0 > 0),
        };
        u8::from(!upper)
    }

    /// Whether direction `i` comes strictly before `j` counter-clockwise
    /// from the positive x axis.
    fn angle_less(&self, i: usize, j: usize) -> bool {
        let (hi, hj) = (self.half(i), self.half(j));
        hi < hj || (hi == hj && self.cross(i, j) == Ordering::Greater)
    }
}

fn coords(p: &RatPoint) -> (Rational, Rational) {
    (
        Rational::from((p.hx().clone(), p.hw().clone())),
        Rational::from((p.hy().clone(), p.hw().clone())),
    )
}

/// T3.3a on one cell polygon, its vertices in boundary order
/// (counter-clockwise): one instance, violated if some vertex is reflex (a
/// clockwise turn), a spike (the boundary reverses), a repeated point, or
/// the boundary winds other than once around. The violation names the map
/// (`map_name`), the cell's index and every offending vertex as an exact
/// point. Each straight vertex is counted (case [`STRAIGHT`]).
pub fn check_cell(map_name: &str, cell: usize, ring: &[RatPoint]) -> Report {
    let mut report = Report::new(ID);
    let k = ring.len();
    let dirs = Dirs::of(ring);
    let mut reflex = Vec::new();
    let mut spikes = Vec::new();
    let mut repeated = Vec::new();
    let mut descents = 0usize;
    for (i, cur) in ring.iter().enumerate() {
        let (din, dout) = ((i + k - 1) % k, i);
        if dirs.is_zero(din) || dirs.is_zero(dout) {
            repeated.push(cur.to_string());
            continue;
        }
        // The turn at cur: the orientation of (prev, cur, next).
        match dirs.cross(din, dout) {
            Ordering::Less => reflex.push(cur.to_string()),
            Ordering::Equal if dirs.dot(din, dout) == Ordering::Less => {
                spikes.push(cur.to_string())
            }
            Ordering::Equal => report.hit(STRAIGHT),
            Ordering::Greater => {}
        }
        if dirs.angle_less(dout, din) {
            descents += 1;
        }
    }
    let winding_ok = k >= 3 && descents == 1;
    let ok = reflex.is_empty() && spikes.is_empty() && repeated.is_empty() && winding_ok;
    report.record((!ok).then(|| {
        let what = if let Some(v) = reflex.first() {
            format!("reflex vertex {v}")
        } else if let Some(v) = spikes.first() {
            format!("spike at {v}")
        } else if let Some(v) = repeated.first() {
            format!("repeated vertex {v}")
        } else {
            format!("the boundary winds {descents} times around")
        };
        Violation::with_data(
            format!("map {map_name}, cell {cell} is not convex: {what}"),
            json!({
                "map": map_name,
                "cell": cell,
                "reflex_vertices": reflex,
                "spikes": spikes,
                "repeated_vertices": repeated,
                "winding": descents,
                "cell_vertices": ring.iter().map(ToString::to_string).collect::<Vec<_>>(),
            }),
        )
    }));
    report
}

#[cfg(test)]
mod tests {
    use super::*;
    use wai_exact::Point;

    fn ring(pts: &[(i128, i128)]) -> Vec<RatPoint> {
        pts.iter()
            .map(|&(x, y)| RatPoint::from(Point::new(x, y)))
            .collect()
    }

    #[test]
    fn the_l_room_has_five_convex_cells() {
        let pts = [(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)];
        let map = wai_map::Map::from_ring(pts.iter().map(|&(x, y)| Point::new(x, y)).collect())
            .unwrap()
            .0;
        let r = CHECKER.run(&Study::new(&map));
        assert_eq!(
            (r.examined, r.violations.len()),
            (5, 0),
            "{:?}",
            r.violations
        );
        assert!(!r.cases.contains_key(INTERIOR), "no two rays cross");
    }

    #[test]
    fn generated_maps_pass() {
        let map = wai_gen::family("corridor-niches", &[2]).unwrap();
        let r = CHECKER.run(&Study::new(&map));
        assert!(r.examined > 5);
        assert!(r.violations.is_empty(), "{:?}", r.violations);
        assert!(
            r.cases.get(INTERIOR).is_some_and(|&k| k > 0),
            "{:?}",
            r.cases
        );
        let map = wai_gen::random("special-orthogonal", 16, 3).unwrap();
        let r = CHECKER.run(&Study::new(&map));
        assert!(r.violations.is_empty(), "{:?}", r.violations);
        let case = |c: &str| r.cases.get(c).copied().unwrap_or(0);
        assert!(
            case(BOUNDARY) + case(INTERIOR) >= 3 * r.examined,
            "{:?}",
            r.cases
        );
    }

    #[test]
    fn a_square_with_a_straight_vertex_is_convex() {
        let r = check_cell(
            "planted",
            1,
            &ring(&[(0, 0), (1, 0), (2, 0), (2, 2), (0, 2)]),
        );
        assert_eq!((r.examined, r.violations.len()), (1, 0));
        assert_eq!(r.cases.get(STRAIGHT), Some(&1));
    }

    /// The `i128` directions and the rational ones give the same verdicts:
    /// the planted rings again with coordinates beyond 2^62.
    #[test]
    fn large_coordinates_take_the_rational_path_with_the_same_verdicts() {
        let rings = [
            ring(&[(0, 0), (1, 0), (2, 0), (2, 2), (0, 2)]),
            ring(&[(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)]),
            ring(&[(0, 4), (-3, -4), (4, 1), (-4, 1), (3, -4)]),
            ring(&[(0, 0), (2, 0), (2, 2), (2, 3), (2, 2), (0, 2)]),
        ];
        for r in &rings {
            let big: Vec<RatPoint> = r
                .iter()
                .map(|p| {
                    let s = rug::Integer::from(1) << 70u32;
                    RatPoint::new(
                        rug::Integer::from(p.hx() * &s) + 1u32,
                        rug::Integer::from(p.hy() * &s),
                        s,
                    )
                    .unwrap()
                })
                .collect();
            assert!(matches!(Dirs::of(&big), Dirs::Big(_)));
            assert!(matches!(Dirs::of(r), Dirs::Small(_)));
            let (a, b) = (check_cell("planted", 1, r), check_cell("planted", 1, &big));
            assert_eq!(a.violations.len(), b.violations.len());
            assert_eq!(a.cases, b.cases);
        }
    }

    #[test]
    fn a_reflex_vertex_is_reported() {
        // An L-shaped "cell": (2, 2) is reflex.
        let l = ring(&[(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)]);
        let r = check_cell("planted", 7, &l);
        assert_eq!((r.examined, r.violations.len()), (1, 1));
        let v = &r.violations[0];
        assert_eq!(v.data["map"], "planted");
        assert_eq!(v.data["cell"], 7);
        assert_eq!(v.data["reflex_vertices"], json!(["(2, 2)"]));
        assert!(v.what.contains("reflex vertex (2, 2)"), "{}", v.what);
    }

    #[test]
    fn a_clockwise_or_doubly_wound_ring_is_reported() {
        let mut cw = ring(&[(0, 0), (2, 0), (2, 2), (0, 2)]);
        cw.reverse();
        assert_eq!(check_cell("planted", 1, &cw).violations.len(), 1);
        // A pentagram: every turn is left, but it winds twice.
        let star = ring(&[(0, 4), (-3, -4), (4, 1), (-4, 1), (3, -4)]);
        let r = check_cell("planted", 1, &star);
        assert_eq!(r.violations.len(), 1);
        assert_eq!(r.violations[0].data["winding"], 2);
        // A spike: the boundary runs out and back.
        let spike = ring(&[(0, 0), (2, 0), (2, 2), (2, 3), (2, 2), (0, 2)]);
        let r = check_cell("planted", 1, &spike);
        assert_eq!(r.violations.len(), 1);
        assert_eq!(r.violations[0].data["spikes"], json!(["(2, 3)"]));
    }
}
