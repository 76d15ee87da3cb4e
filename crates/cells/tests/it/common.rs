//! Maps, exact helpers and the law checker shared by the tests.

use rug::Integer;
use std::collections::BTreeSet;
use wai_cells::{OnMap, RaySide, VisibilityRay};
use wai_exact::{
    compare_along, locate_rat, sees, side_of_line, side_of_line_rat, Containment, Line, Point,
    RatPoint, Side, Sight,
};
use wai_map::Map;

pub fn map(pts: &[(i128, i128)]) -> Map {
    let ring = pts.iter().map(|&(x, y)| Point::new(x, y)).collect();
    let (m, norm) = Map::from_ring(ring).expect("test maps are valid");
    assert!(norm.is_identity(), "test maps are given in normal form");
    m
}

pub fn rat(x: i64, y: i64, w: i64) -> RatPoint {
    RatPoint::new(Integer::from(x), Integer::from(y), Integer::from(w)).unwrap()
}

pub fn pt(x: i128, y: i128) -> RatPoint {
    RatPoint::from(Point::new(x, y))
}

/// A large step divisor: `p + (p − q) / K` is "just beyond" `p`. The test
/// maps have coordinates far below 2^40, so every feature not through `p` is
/// farther than `|p − q| / K` (a crude but ample bound).
const K: u128 = 1 << 100;

/// `p + (p − q) / K`, exactly.
pub fn just_beyond(p: &RatPoint, q: &RatPoint) -> RatPoint {
    let k = Integer::from(K);
    // ((K + 1) p − q) / K in homogeneous coordinates over W = wp · wq · K.
    let (wp, wq) = (p.hw(), q.hw());
    let x = Integer::from(&k + 1u32) * p.hx() * wq - Integer::from(q.hx() * wp);
    let y = Integer::from(&k + 1u32) * p.hy() * wq - Integer::from(q.hy() * wp);
    let w = k * wp * wq;
    RatPoint::new(x, y, w).unwrap()
}

/// The sign of `(b − a) · (c − a)` for rational points.
fn dot_sign(a: &RatPoint, b: &RatPoint, c: &RatPoint) -> std::cmp::Ordering {
    b.sub(a).dot_sign(&c.sub(a))
}

/// For `x` on the line through `a` and `b`: whether it is on the closed
/// segment `ab`.
fn on_closed_segment(a: &RatPoint, b: &RatPoint, x: &RatPoint) -> bool {
    dot_sign(a, b, x).is_ge() && dot_sign(b, a, x).is_ge()
}

/// A comparable form of a ray: (anchor, from, side, end kind, end index,
/// end point, grazed).
pub type RayKey = (usize, usize, RaySide, bool, usize, RatPoint, Vec<usize>);

pub fn key(r: &VisibilityRay) -> RayKey {
    let (vertex, i) = match r.end.on_map {
        OnMap::Vertex(i) => (true, i),
        OnMap::Edge(i) => (false, i),
    };
    (
        r.anchor,
        r.from,
        r.side,
        vertex,
        i,
        r.end.point.clone(),
        r.grazed.clone(),
    )
}

/// The brute-force set of (anchor, from) pairs with a ray of positive
/// length: v adjacent to or visible from v_r (`sees`), and the point just
/// beyond v_r away from v inside the map.
pub fn brute_force_pairs(map: &Map) -> BTreeSet<(usize, usize)> {
    let v = map.vertices();
    let n = v.len();
    let mut out = BTreeSet::new();
    for &a in map.reflex_vertices() {
        for j in (0..n).filter(|&j| j != a) {
            let (pa, pj) = (RatPoint::from(v[a]), RatPoint::from(v[j]));
            let adjacent = j == (a + 1) % n || a == (j + 1) % n;
            if !adjacent && sees(v, &pa, &pj) != Sight::Visible {
                continue;
            }
            if locate_rat(v, &just_beyond(&pa, &pj)) == Containment::Inside {
                out.insert((a, j));
            }
        }
    }
    out
}

/// Check every law of visibility rays on `rays` computed for `map`; panic
/// with the map's name on the first violation. Returns the ray count.
pub fn check_rays(map: &Map, rays: &[VisibilityRay]) -> usize {
    let name = map.name().unwrap_or("unnamed");
    let v = map.vertices();
    let n = v.len();
    assert!(
        rays.len() <= map.r() * (n - 1),
        "{name}: {} rays > r (n - 1)",
        rays.len()
    );
    for ray in rays {
        let (a, j) = (ray.anchor, ray.from);
        let ctx = format!("{name}: ray from {j} anchored at {a}");
        assert!(map.is_reflex(a), "{ctx}: anchor not reflex");
        assert_ne!(a, j, "{ctx}");
        assert_eq!(ray.line, Line::new(v[j], v[a]).unwrap(), "{ctx}: line");
        assert_eq!((ray.source(), ray.start()), (v[j], v[a]), "{ctx}");
        let start = RatPoint::from(v[a]);
        let end = &ray.end.point;
        // On the line, beyond v_r, away from v, positive length.
        assert_eq!(
            side_of_line_rat(&ray.line, end),
            Side::On,
            "{ctx}: end off line"
        );
        assert!(
            dot_sign(&start, end, &RatPoint::from(v[j])).is_lt(),
            "{ctx}: the ray does not move away from v"
        );
        // The end on the boundary, where on_map says.
        assert_eq!(locate_rat(v, end), Containment::OnBoundary, "{ctx}: end");
        match ray.end.on_map {
            OnMap::Vertex(i) => assert_eq!(*end, RatPoint::from(v[i]), "{ctx}: end vertex"),
            OnMap::Edge(i) => {
                let (p, q) = (RatPoint::from(v[i]), RatPoint::from(v[(i + 1) % n]));
                let e = Line::new(v[i], v[(i + 1) % n]).unwrap();
                assert_eq!(side_of_line_rat(&e, end), Side::On, "{ctx}: end edge");
                assert!(on_closed_segment(&p, &q, end), "{ctx}: end edge");
                assert!(*end != p && *end != q, "{ctx}: an edge end at a vertex");
            }
        }
        // The map vertices on the closed ray, by brute force, are the
        // anchor, the grazed vertices and an end vertex, in this order.
        let mut touched: Vec<usize> = (0..n)
            .filter(|&k| {
                k != a
                    && side_of_line(&ray.line, v[k]) == Side::On
                    && on_closed_segment(&start, end, &RatPoint::from(v[k]))
            })
            .collect();
        touched.sort_by(|&x, &y| compare_along(&ray.line, v[x], v[y]));
        let mut expected = ray.grazed.clone();
        if let OnMap::Vertex(i) = ray.end.on_map {
            expected.push(i);
        }
        assert_eq!(touched, expected, "{ctx}: vertices on the ray");
        // Grazed vertices have both incident edges strictly on one side.
        for &u in &ray.grazed {
            let sp = side_of_line(&ray.line, v[(u + n - 1) % n]);
            let sn = side_of_line(&ray.line, v[(u + 1) % n]);
            assert!(sp != Side::On && sp == sn, "{ctx}: {u} is not grazed");
        }
        // Every piece between consecutive boundary contacts is seen through
        // the interior: the open ray meets the boundary only at grazed
        // vertices.
        let mut stops: Vec<RatPoint> = vec![start.clone()];
        stops.extend(ray.grazed.iter().map(|&u| RatPoint::from(v[u])));
        stops.push(end.clone());
        for w in stops.windows(2) {
            assert_eq!(
                sees(v, &w[0], &w[1]),
                Sight::Visible,
                "{ctx}: piece {} – {}",
                w[0],
                w[1]
            );
            let mid = RatPoint::midpoint(&w[0], &w[1]);
            assert_eq!(locate_rat(v, &mid), Containment::Inside, "{ctx}: midpoint");
        }
        // Just beyond the end: outside the map or on its boundary.
        assert_ne!(
            locate_rat(v, &just_beyond(end, &start)),
            Containment::Inside,
            "{ctx}: the ray could go on"
        );
        // The side: the anchor's incident edges lie on it (or on the line).
        let sides = [v[(a + n - 1) % n], v[(a + 1) % n]].map(|p| side_of_line(&ray.line, p));
        assert!(
            sides
                .iter()
                .all(|&s| s == Side::On || s == ray.side.as_side())
                && sides.contains(&ray.side.as_side()),
            "{ctx}: side {:?} but the anchor's neighbours are {sides:?}",
            ray.side
        );
    }
    // Completeness and no duplicates.
    let got: BTreeSet<(usize, usize)> = rays.iter().map(|r| (r.anchor, r.from)).collect();
    assert_eq!(got.len(), rays.len(), "{name}: duplicate rays");
    assert_eq!(
        got,
        brute_force_pairs(map),
        "{name}: rays against brute force"
    );
    // Ordered by anchor, then by source.
    let order: Vec<(usize, usize)> = rays.iter().map(|r| (r.anchor, r.from)).collect();
    assert!(order.windows(2).all(|w| w[0] < w[1]), "{name}: order");
    rays.len()
}

/// [`check_rays`] on the map's own rays.
pub fn check_map(map: &Map) -> usize {
    check_rays(map, &wai_cells::visibility_rays(map))
}
