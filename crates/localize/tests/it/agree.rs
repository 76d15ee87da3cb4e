//! The localizer against the brute-force oracle and against the map-side
//! skeleton, at viewpoints in every cell of every dimension (points on
//! rays, 0-cells) and at random points.

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::Integer;
use wai_cells::Decomposition;
use wai_exact::{Containment, RatPoint};
use wai_localize::{oracle, Localizer, RobotView};
use wai_map::Map;
use wai_visibility::VisibilityIndex;

/// Tallies of one map's queries.
#[derive(Debug, Default)]
pub struct Tally {
    pub queries: usize,
    pub answers: usize,
    pub max_answers: usize,
    pub on_lower: usize,
    /// Directions the one-shot oracle swept for ray exits.
    pub one_shot_sweeps: usize,
}

/// Viewpoints: every cell's representative, every lower cell's, and
/// `random` random points with small denominators inside the map.
pub fn viewpoints(d: &Decomposition<'_>, random: usize, seed: u64) -> Vec<RatPoint> {
    let mut pts: Vec<RatPoint> = d
        .cells()
        .iter()
        .map(|&c| d.representative(c).clone())
        .collect();
    pts.extend(d.lower_cells().iter().map(|c| d.lower_representative(c)));
    let map = d.map();
    let (lo, hi) = map.bounding_box();
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut added = 0;
    let mut tries = 0;
    while added < random && tries < 100 * random {
        tries += 1;
        let w: i128 = rng.random_range(1..=8);
        let x = rng.random_range(lo.x * w..=hi.x * w);
        let y = rng.random_range(lo.y * w..=hi.y * w);
        let p = RatPoint::from_i128(x, y, w).expect("w > 0");
        if map.locate(&p) == Containment::Inside {
            pts.push(p);
            added += 1;
        }
    }
    pts
}

/// Localize from every viewpoint and compare with the oracle; panics with
/// the map and the point on any disagreement.
pub fn check_map(map: &Map, random: usize, seed: u64) -> Tally {
    let d = Decomposition::new(map);
    let loc = Localizer::from_decomposition(&d);
    let index = VisibilityIndex::new(map);
    let lower_from = d.cells().len();
    let mut t = Tally::default();
    for (i, p) in viewpoints(&d, random, seed).iter().enumerate() {
        // The skeleton from V alone is the map-side one, the answer holds
        // p, and the localizer, the brute force and the one-shot agree.
        let c = oracle::cross_check(&loc, &index, p)
            .unwrap_or_else(|e| panic!("{:?}: at {p}: {e}", map.name()));
        let (view, sk, answer) = (&c.view, &c.skeleton, &c.answer);
        // The input check accepts every true visibility polygon unchanged.
        let checked = RobotView::new(view.vertices().to_vec())
            .unwrap_or_else(|e| panic!("{:?}: V at {p} refused: {e}", map.name()));
        assert_eq!(&checked, view, "V at {p} was changed by the input check");
        assert_eq!(
            wai_visibility::reconstruct(&sk.key, &sk.robot),
            view.from_origin(sk.origin_index),
            "Thm 3.2 at {p}"
        );
        assert!(
            answer.nowhere.is_none(),
            "{:?}: no answer at {p}: {:?}",
            map.name(),
            answer.nowhere
        );
        let positions = answer.positions();
        t.one_shot_sweeps += c.one_shot_sweeps;
        // Point location equals testing every cell (the fast path where it
        // answers, the degenerate path on slab lines and pieces).
        let k = answer.class.expect("class");
        let o = loc.overlay(k);
        let exact = o.locate_exact(&sk.robot);
        if let Some(fast) = o.locate_fast(&sk.robot) {
            assert_eq!(fast, exact.as_slice());
        }
        assert_eq!(o.locate(&sk.robot), exact, "{:?}: at {p}", map.name());
        t.queries += 1;
        t.answers += positions.len();
        t.max_answers = t.max_answers.max(positions.len());
        if i >= lower_from && i < lower_from + d.lower_cells().len() {
            t.on_lower += 1;
        }
    }
    t
}

fn maps() -> Vec<Map> {
    let mut m = Vec::new();
    for seed in 0..4 {
        m.push(wai_gen::random("random-orthogonal", 16, seed).unwrap());
        m.push(wai_gen::random("special-orthogonal", 16, seed).unwrap());
        m.push(wai_gen::random("special-comb", 20, seed).unwrap());
        m.push(wai_gen::random("random-simple-2opt", 12, seed).unwrap());
    }
    m.push(wai_gen::family("corridor-niches", &[4]).unwrap());
    m.push(wai_gen::family("overlap-fan", &[1]).unwrap());
    m.push(wai_gen::layout("repeated-niches", 0).unwrap());
    m
}

#[test]
fn localizer_agrees_with_brute_force_on_every_cell_and_random_points() {
    let mut total = Tally::default();
    for map in maps() {
        let t = check_map(&map, 40, 7);
        total.queries += t.queries;
        total.answers += t.answers;
        total.max_answers = total.max_answers.max(t.max_answers);
        total.on_lower += t.on_lower;
        total.one_shot_sweeps += t.one_shot_sweeps;
    }
    eprintln!("{total:?}");
    assert!(total.queries > 1000);
    assert!(
        total.on_lower > 100,
        "points on 1- and 0-cells were examined"
    );
    assert!(total.max_answers >= 3, "some query has several answers");
}

#[test]
fn repeated_rooms_give_every_room() {
    // corridor-niches k = 4: four identical niches; a point deep in one
    // niche is seen the same from the same spot of each.
    let map = wai_gen::family("corridor-niches", &[4]).unwrap();
    let loc = Localizer::new(&map);
    let index = VisibilityIndex::new(&map);
    let d = Decomposition::new(&map);
    let best = d
        .cells()
        .iter()
        .map(|&c| {
            let p = d.representative(c).clone();
            let v = RobotView::from_visibility(&index.visibility_polygon(&p).unwrap());
            loc.localize(&v).placements.len()
        })
        .max()
        .unwrap();
    assert!(best >= 4, "largest answer set {best}");
}

#[test]
fn a_polygon_nothing_sees_gets_the_empty_answer_with_its_reason() {
    let map = wai_gen::family("corridor-niches", &[2]).unwrap();
    let loc = Localizer::new(&map);
    // A unit square around the robot: no map has it (its corners are at
    // half-integer offsets from each other? No: integer, but no cell sees a
    // square of side 2 in this map).
    let sq = |x: i128, y: i128| RatPoint::from_i128(x, y, 1).unwrap();
    let v = RobotView::new(vec![sq(-1, -1), sq(1, -1), sq(1, 1), sq(-1, 1)]).unwrap();
    let a = loc.localize(&v);
    assert!(a.placements.is_empty());
    assert!(a.nowhere.is_some());
    let _ = Integer::new();
}

/// Polygons that look right but are seen from nowhere, or from elsewhere:
/// the skeleton of cell c1 rebuilt (Thm 3.2) around the representative of
/// another cell c2, as if the robot stood there. Star-shaped and with a
/// known skeleton, but the robot's position is in no cell of that class
/// (unless c2's embedding shares it): the localizer must answer exactly
/// what the brute force answers, and say "no cell" when that is empty.
#[test]
fn rebuilt_skeletons_around_the_wrong_point_answer_as_the_brute_force() {
    let mut no_cell = 0;
    let mut checked = 0;
    for map in [
        wai_gen::family("corridor-niches", &[3]).unwrap(),
        wai_gen::random("special-orthogonal", 14, 2).unwrap(),
        wai_gen::random("random-simple-2opt", 10, 1).unwrap(),
    ] {
        let d = Decomposition::new(&map);
        let loc = Localizer::from_decomposition(&d);
        let index = VisibilityIndex::new(&map);
        let cells: Vec<usize> = d.cells().iter().copied().take(40).collect();
        for &c1 in &cells {
            let key = &d.skeletons()[d.skeleton_of(c1)];
            let o = map.vertices()[d.origin_of(c1)];
            for &c2 in &cells {
                if d.skeleton_of(c2) == d.skeleton_of(c1) {
                    continue;
                }
                let q = d.representative(c2);
                let w = q.hw();
                let rel = RatPoint::new(
                    q.hx() - Integer::from(w * o.x),
                    q.hy() - Integer::from(w * o.y),
                    w.clone(),
                )
                .unwrap();
                let pts: Vec<RatPoint> = wai_visibility::reconstruct(key, &rel)
                    .iter()
                    .map(|p| {
                        let (pw, rw) = (p.hw(), rel.hw());
                        RatPoint::new(
                            Integer::from(p.hx() * rw) - Integer::from(rel.hx() * pw),
                            Integer::from(p.hy() * rw) - Integer::from(rel.hy() * pw),
                            Integer::from(pw * rw),
                        )
                        .unwrap()
                    })
                    .collect();
                let Ok(view) = RobotView::new(pts) else {
                    continue;
                };
                if let Ok(sk) = view.skeleton() {
                    assert_eq!(
                        wai_visibility::reconstruct(&sk.key, &sk.robot),
                        view.from_origin(sk.origin_index)
                    );
                }
                let answer = loc.localize(&view);
                assert_eq!(
                    answer.positions(),
                    oracle::one_shot(index.map(), &view).positions,
                    "{:?}: one-shot, skeleton of cell {c1} around cell {c2}",
                    map.name()
                );
                assert_eq!(
                    answer.positions(),
                    oracle::brute_force(&index, &view),
                    "{:?}: skeleton of cell {c1} around cell {c2}",
                    map.name()
                );
                checked += 1;
                if matches!(answer.nowhere, Some(wai_localize::Nowhere::NoCell(_))) {
                    no_cell += 1;
                }
            }
        }
    }
    eprintln!("{checked} rebuilt views, {no_cell} in no cell");
    assert!(checked > 100 && no_cell > 10, "{checked} {no_cell}");
}

/// The same checks on maps scaled by 2^60: coordinates beyond the fast
/// paths' reach, so every predicate takes GMP.
#[test]
fn scaled_maps_take_the_exact_paths_and_agree() {
    for map in [
        wai_gen::random("special-orthogonal", 12, 1).unwrap(),
        wai_gen::family("corridor-niches", &[2]).unwrap(),
    ] {
        let scaled = map.scaled_up(60).unwrap();
        let t = check_map(&scaled, 10, 5);
        assert!(t.queries > 50);
    }
}

/// The degenerate point location (on slab lines and pieces) against
/// testing every cell, at the points where it is needed: every cell
/// vertex, the midpoint and a third of every cell edge, every 0-cell, and
/// every point where a piece meets a slab line (vertices and crossings).
#[test]
fn degenerate_point_location_equals_testing_every_cell() {
    use rug::{Integer, Rational};
    use wai_localize::overlay::Shape;
    let mut checked = 0;
    let mut degenerate = 0;
    for map in maps() {
        let loc = Localizer::new(&map);
        for k in 0..loc.classes() {
            let o = loc.overlay(k);
            let mut pts: Vec<RatPoint> = Vec::new();
            let along = |a: &RatPoint, b: &RatPoint, t: i64, of: i64| {
                // a + (b − a)·t/of
                let (aw, bw) = (a.hw(), b.hw());
                let w = Integer::from(aw * bw) * of;
                let x = Integer::from(a.hx() * bw) * (of - t) + Integer::from(b.hx() * aw) * t;
                let y = Integer::from(a.hy() * bw) * (of - t) + Integer::from(b.hy() * aw) * t;
                RatPoint::new(x, y, w).unwrap()
            };
            for it in &o.items {
                match &it.shape {
                    Shape::Polygon(ring) => {
                        for (i, a) in ring.iter().enumerate() {
                            let b = &ring[(i + 1) % ring.len()];
                            pts.push(a.clone());
                            pts.push(along(a, b, 1, 2));
                            pts.push(along(a, b, 1, 3));
                        }
                    }
                    Shape::Segment(a, b) => {
                        pts.extend([a.clone(), b.clone(), along(a, b, 1, 2), along(a, b, 1, 3)]);
                    }
                    Shape::Point(a) => pts.push(a.clone()),
                }
            }
            for (i, x) in o.xs.iter().enumerate() {
                for s in [i.checked_sub(1), Some(i)].into_iter().flatten() {
                    let Some(slab) = o.slabs.get(s) else { continue };
                    for &l in &slab.pieces {
                        let l = &o.lines[l as usize];
                        let y = (Rational::from(&l.c) - Rational::from(&l.a) * x)
                            / Rational::from(&l.b);
                        let w = Integer::from(x.denom() * y.denom());
                        pts.push(
                            RatPoint::new(
                                Integer::from(x.numer() * y.denom()),
                                Integer::from(y.numer() * x.denom()),
                                w,
                            )
                            .unwrap(),
                        );
                    }
                }
            }
            for p in &pts {
                if o.locate_fast(p).is_none() {
                    degenerate += 1;
                }
                assert_eq!(
                    o.locate(p),
                    o.locate_exact(p),
                    "{:?}: class {k} at {p}",
                    map.name()
                );
                checked += 1;
            }
        }
    }
    eprintln!("{checked} points located, {degenerate} on slab lines or pieces");
    assert!(degenerate > 10_000, "{degenerate}");
}

/// Maps with holes (sec. 6.4): the localizer against the brute force and
/// the one-shot query at every cell of every dimension and at random points
/// of the free space.
#[test]
fn localizer_agrees_with_brute_force_on_maps_with_holes() {
    let mut total = Tally::default();
    // The random kinds (the chapter 4 layouts with pillars are one large
    // map per seed, for the claim checkers).
    for kind in wai_gen::HOLED_KINDS
        .iter()
        .filter(|k| ["orthogonal-pillars", "simple-holes"].contains(&k.id))
    {
        for seed in 0..8 {
            let map = wai_gen::random_with_holes(
                kind.id,
                8 + 2 * (seed as usize % 3),
                1 + seed as usize % 3,
                seed,
            )
            .unwrap();
            assert!(map.has_holes());
            let t = check_map(&map, 40, seed);
            total.queries += t.queries;
            total.answers += t.answers;
            total.max_answers = total.max_answers.max(t.max_answers);
            total.on_lower += t.on_lower;
            total.one_shot_sweeps += t.one_shot_sweeps;
        }
    }
    // Two identical rooms off a corridor, each with a pillar: from most of
    // a room the other room looks the same (several answers).
    let rooms = two_rooms(&[9, 29]);
    let t = check_map(&rooms, 200, 1);
    assert!(t.max_answers >= 2, "two rooms with pillars: {t:?}");
    total.queries += t.queries;
    total.answers += t.answers;
    total.max_answers = total.max_answers.max(t.max_answers);
    total.on_lower += t.on_lower;
    eprintln!("maps with holes: {total:?}");
    assert!(total.queries >= 10_000, "{} queries", total.queries);
    assert!(
        total.on_lower > 1000,
        "points on 1- and 0-cells were examined"
    );
    assert!(total.max_answers >= 2, "some query has several answers");
}

/// Step 5 of the one-shot query: two identical rooms off a corridor, a
/// pillar in the second only. What the robot sees in the empty room fits
/// the second room wall for wall (steps 1–4 pass there), but the pillar
/// would stand inside it: the robot is in the first room only.
#[test]
fn the_one_shot_query_rules_out_a_placement_around_a_pillar() {
    let map = two_rooms(&[29]);
    let index = VisibilityIndex::new(&map);
    let p = RatPoint::from_i128(5, 14, 1).unwrap();
    let view = RobotView::from_visibility(&index.visibility_polygon(&p).unwrap());
    assert_eq!(oracle::brute_force(&index, &view), vec![p.clone()]);
    assert_eq!(oracle::one_shot(&map, &view).positions, vec![p.clone()]);
    let c = oracle::cross_check(&Localizer::new(&map), &index, &p).unwrap();
    assert_eq!(c.answer.positions(), vec![p]);
}

/// Two identical 8 × 10 rooms off a 40 m corridor (doors at x = 7..9 and
/// 27..29), with a unit pillar at (x, 10) for each x of `pillars`.
fn two_rooms(pillars: &[i128]) -> Map {
    let pts = |v: &[(i128, i128)]| {
        v.iter()
            .map(|&(x, y)| wai_exact::Point::new(x, y))
            .collect::<Vec<_>>()
    };
    let outer = pts(&[
        (0, 0),
        (40, 0),
        (40, 4),
        (29, 4),
        (29, 5),
        (32, 5),
        (32, 15),
        (24, 15),
        (24, 5),
        (27, 5),
        (27, 4),
        (9, 4),
        (9, 5),
        (12, 5),
        (12, 15),
        (4, 15),
        (4, 5),
        (7, 5),
        (7, 4),
        (0, 4),
    ]);
    let holes = pillars
        .iter()
        .map(|&x| pts(&[(x, 10), (x + 1, 10), (x + 1, 11), (x, 11)]))
        .collect();
    Map::from_rings(outer, holes).unwrap().0
}
