//! The CGAL peer (`wai_benches::cgal`) against hand-computed visibility
//! polygons, and (ignored) its query times on AGPLIB and generated maps:
//!
//! ```sh
//! benches/peers/build.sh
//! cargo test --release -p wai-benches --test cgal -- --ignored --nocapture
//! ```
//!
//! Without the peer binary the tests pass after printing
//! "CGAL peer not built; run benches/peers/build.sh".

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::Integer;
use std::cmp::Ordering;
use std::io::Write;
use wai_benches::cgal::{self, drop_collinear, CgalPeer};
use wai_exact::{locate_rat, Containment, Point, RatPoint};
use wai_map::Map;

/// Print past the test harness's capture, so a skipped test is visible.
fn say(msg: &str) {
    let _ = writeln!(std::io::stderr(), "{msg}");
}

fn peer() -> Option<CgalPeer> {
    if !cgal::available() {
        say(&format!(
            "CGAL peer not built; run benches/peers/build.sh (looked for {})",
            cgal::binary_path().display()
        ));
        return None;
    }
    Some(CgalPeer::spawn().expect("the CGAL peer starts"))
}

fn pt(x: i128, y: i128) -> Point {
    Point::new(x, y)
}

/// `(x, y)` as `(num/den)` pairs.
fn rp(x: (i64, i64), y: (i64, i64)) -> RatPoint {
    cgal::rat_point(
        rug::Rational::from((x.0, x.1)),
        rug::Rational::from((y.0, y.1)),
    )
}

fn ip(x: i64, y: i64) -> RatPoint {
    rp((x, 1), (y, 1))
}

fn map(ring: &[(i128, i128)]) -> Map {
    let (m, norm) = Map::from_ring(ring.iter().map(|&(x, y)| pt(x, y)).collect()).expect("valid");
    assert!(norm.is_identity());
    m
}

/// The L-shaped room [0,4]x[0,2] ∪ [0,2]x[0,4]; reflex vertex (2, 2).
fn l_room() -> Map {
    map(&[(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)])
}

#[test]
fn l_room_exact_polygons() {
    let Some(mut cgal) = peer() else { return };
    let m = l_room();
    cgal.set_polygon(m.vertices(), m.scale()).unwrap();
    assert_eq!(cgal.scale(), Some(&Integer::from(1)));

    // From (3, 1/2) the ray through (2, 2), direction (-1, 3/2), meets the
    // top edge y = 4 at x = 2/3; the strip right of it is hidden.
    let v = cgal.visibility(&rp((3, 1), (1, 2))).unwrap();
    let want = vec![
        ip(0, 0),
        ip(4, 0),
        ip(4, 2),
        ip(2, 2),
        rp((2, 3), (4, 1)),
        ip(0, 4),
    ];
    assert_eq!(v, want);

    // From (1/2, 3) the ray through (2, 2), direction (3/2, -1), meets the
    // right wall x = 4 at y = 2/3.
    let v = cgal.visibility(&rp((1, 2), (3, 1))).unwrap();
    let want = vec![
        ip(0, 0),
        ip(4, 0),
        rp((4, 1), (2, 3)),
        ip(2, 2),
        ip(2, 4),
        ip(0, 4),
    ];
    assert_eq!(v, want);

    // From (1, 1) (in the kernel) everything is seen.
    let v = cgal.visibility(&ip(1, 1)).unwrap();
    let all: Vec<RatPoint> = m.vertices().iter().map(|&p| RatPoint::from(p)).collect();
    assert_eq!(v, all);

    // From (3, 1) the window through (2, 2) ends exactly at the vertex
    // (0, 4): it is reported once, no extra point.
    let v = cgal.visibility(&ip(3, 1)).unwrap();
    assert_eq!(v, vec![ip(0, 0), ip(4, 0), ip(4, 2), ip(2, 2), ip(0, 4)]);
}

#[test]
fn scaled_map_uses_the_integer_frame() {
    let Some(mut cgal) = peer() else { return };
    // The L room scaled by 10/3: integer coordinates 10x over scale 3 (the
    // least scale, so the map keeps it).
    let ring = [(0, 0), (40, 0), (40, 20), (20, 20), (20, 40), (0, 40)];
    let (m, _) = Map::from_scaled_ring(
        ring.iter().map(|&(x, y)| pt(x, y)).collect(),
        Integer::from(3),
    )
    .unwrap();
    cgal.set_polygon(m.vertices(), m.scale()).unwrap();
    assert_eq!(cgal.scale(), Some(&Integer::from(3)));
    let v = cgal.visibility(&ip(30, 5)).unwrap();
    let want = vec![
        ip(0, 0),
        ip(40, 0),
        ip(40, 20),
        ip(20, 20),
        rp((20, 3), (40, 1)),
        ip(0, 40),
    ];
    assert_eq!(v, want);
}

#[test]
fn errors_keep_the_session() {
    let Some(mut cgal) = peer() else { return };
    assert!(cgal
        .visibility(&ip(1, 1))
        .unwrap_err()
        .contains("no polygon"));
    let m = l_room();
    cgal.set_polygon(m.vertices(), m.scale()).unwrap();
    let outside = cgal.visibility(&ip(3, 3)).unwrap_err();
    assert!(outside.contains("outside"), "{outside}");
    let on_edge = cgal.visibility(&ip(0, 1)).unwrap_err();
    assert!(on_edge.contains("edge"), "{on_edge}");
    let on_vertex = cgal.visibility(&ip(2, 2)).unwrap_err();
    assert!(on_vertex.contains("vertex"), "{on_vertex}");
    // A clockwise ring is refused; the old polygon is gone.
    let cw: Vec<Point> = m.vertices().iter().rev().copied().collect();
    assert!(cgal.set_polygon(&cw, m.scale()).is_err());
    assert!(cgal.visibility(&ip(1, 1)).is_err());
    cgal.set_polygon(m.vertices(), m.scale()).unwrap();
    assert_eq!(cgal.visibility(&ip(1, 1)).unwrap().len(), 6);
    assert!(cgal.bench(&ip(1, 1), 5).unwrap() > 0);
    assert!(cgal.bench_exact(&ip(1, 1), 5).unwrap() > 0);
}

/// A comb: base [0,10]x[0,2], teeth [0,1], [3,4], [6,7], [9,10] up to y = 5.
fn comb() -> Map {
    map(&[
        (0, 0),
        (10, 0),
        (10, 5),
        (9, 5),
        (9, 2),
        (7, 2),
        (7, 5),
        (6, 5),
        (6, 2),
        (4, 2),
        (4, 5),
        (3, 5),
        (3, 2),
        (1, 2),
        (1, 5),
        (0, 5),
    ])
}

/// CGAL's convention, pinned: with the viewpoint on the line of map edges,
/// every map vertex along the seen straight stretch is reported.
#[test]
fn collinear_vertices_are_reported() {
    let Some(mut cgal) = peer() else { return };
    let m = comb();
    cgal.set_polygon(m.vertices(), m.scale()).unwrap();
    // (1/2, 2) is in the first tooth, on the line y = 2 of the base's top
    // edges: it sees the first tooth and the base.
    let v = cgal.visibility(&rp((1, 2), (2, 1))).unwrap();
    let want: Vec<RatPoint> = [
        (0, 0),
        (10, 0),
        (10, 2),
        (9, 2),
        (7, 2),
        (6, 2),
        (4, 2),
        (3, 2),
        (1, 2),
        (1, 5),
        (0, 5),
    ]
    .iter()
    .map(|&(x, y)| ip(x, y))
    .collect();
    assert_eq!(v, want);
    let corners: Vec<RatPoint> = [(0, 0), (10, 0), (10, 2), (1, 2), (1, 5), (0, 5)]
        .iter()
        .map(|&(x, y)| ip(x, y))
        .collect();
    assert_eq!(drop_collinear(&v), corners);

    // From (5, 1) the windows through (9, 2), (6, 2), (4, 2), (1, 2).
    let v = cgal.visibility(&ip(5, 1)).unwrap();
    let want = vec![
        ip(0, 0),
        ip(10, 0),
        rp((10, 1), (9, 4)),
        ip(9, 2),
        ip(7, 2),
        ip(7, 3),
        ip(6, 2),
        ip(4, 2),
        ip(3, 3),
        ip(3, 2),
        ip(1, 2),
        rp((0, 1), (9, 4)),
    ];
    assert_eq!(v, want);
}

/// Two notches on opposite sides of the line y = 5 through the viewpoint:
/// the closed visible set has the needle (7,5)-(10,5); CGAL's regularized
/// output has no needle.
#[test]
fn no_needles() {
    let Some(mut cgal) = peer() else { return };
    let m = map(&[
        (0, 0),
        (6, 0),
        (6, 5),
        (7, 5),
        (7, 0),
        (10, 0),
        (10, 10),
        (4, 10),
        (4, 5),
        (3, 5),
        (3, 10),
        (0, 10),
    ]);
    cgal.set_polygon(m.vertices(), m.scale()).unwrap();
    let v = cgal.visibility(&ip(1, 5)).unwrap();
    let want: Vec<RatPoint> = [(0, 0), (6, 0), (6, 5), (4, 5), (3, 5), (3, 10), (0, 10)]
        .iter()
        .map(|&(x, y)| ip(x, y))
        .collect();
    assert_eq!(v, want);
}

#[test]
fn drop_collinear_keeps_corners() {
    let sq = [
        ip(0, 0),
        ip(1, 0),
        ip(2, 0),
        ip(2, 0),
        ip(2, 2),
        ip(0, 2),
        ip(0, 1),
    ];
    assert_eq!(
        drop_collinear(&sq),
        vec![ip(0, 0), ip(2, 0), ip(2, 2), ip(0, 2)]
    );
    let tri = [ip(0, 0), ip(1, 0), ip(0, 1)];
    assert_eq!(drop_collinear(&tri), tri.to_vec());
}

// ---------------------------------------------------------------------------
// Query times (ignored: run with --release -- --ignored --nocapture).

/// Up to `count` interior query points: centroids of three consecutive
/// vertices, starting at evenly spread vertices.
fn queries(m: &Map, count: usize) -> Vec<RatPoint> {
    let v = m.vertices();
    let n = v.len();
    let mut out: Vec<RatPoint> = Vec::new();
    for j in 0..count {
        for k in 0..n {
            let i = (j * n / count + k) % n;
            let (a, b, c) = (v[(i + n - 1) % n], v[i], v[(i + 1) % n]);
            let q = RatPoint::new(
                Integer::from(a.x) + b.x + c.x,
                Integer::from(a.y) + b.y + c.y,
                Integer::from(3),
            )
            .expect("w = 3");
            if locate_rat(v, &q) == Containment::Inside && !out.contains(&q) {
                out.push(q);
                break;
            }
        }
    }
    out
}

/// `count` random interior points with integer coordinates in the map's
/// bounding box (rejection sampling, seeded).
fn random_queries(m: &Map, count: usize, seed: u64) -> Vec<RatPoint> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let (lo, hi) = m.bounding_box();
    let mut out = Vec::new();
    for _ in 0..100_000 {
        if out.len() == count {
            break;
        }
        let q = RatPoint::from(pt(
            rng.random_range(lo.x..=hi.x),
            rng.random_range(lo.y..=hi.y),
        ));
        if locate_rat(m.vertices(), &q) == Containment::Inside {
            out.push(q);
        }
    }
    out
}

/// Angular order around the origin, exactly (no point is the origin).
fn angle_cmp(a: Point, b: Point) -> Ordering {
    let half = |p: Point| p.y < 0 || (p.y == 0 && p.x < 0);
    half(a)
        .cmp(&half(b))
        .then_with(|| (b.x * a.y).cmp(&(a.x * b.y)))
}

/// A random star-shaped polygon around the origin: `n` random points of
/// `[-2^30, 2^30]^2` in angular order (equal angles dropped).
fn star(n: usize, seed: u64) -> Map {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let c = 1i128 << 30;
    let mut pts: Vec<Point> = (0..n)
        .map(|_| pt(rng.random_range(-c..=c), rng.random_range(-c..=c)))
        .filter(|p| p.x != 0 || p.y != 0)
        .collect();
    pts.sort_by(|&a, &b| angle_cmp(a, b));
    pts.dedup_by(|a, b| angle_cmp(*a, *b) == Ordering::Equal);
    Map::from_ring(pts).expect("a star polygon").0
}

/// A random skyline: columns `[i, i+1] x [0, h_i]`, `h_i` random in
/// `1..=1000`, neighbours different: an orthogonal polygon with `2k + 2`
/// vertices.
fn skyline(k: usize, seed: u64) -> Map {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut h: Vec<i128> = Vec::with_capacity(k);
    while h.len() < k {
        let v = rng.random_range(1..=1000);
        if h.last() != Some(&v) {
            h.push(v);
        }
    }
    let mut ring = vec![pt(0, 0), pt(k as i128, 0)];
    for i in (0..k).rev() {
        ring.push(pt(i as i128 + 1, h[i]));
        ring.push(pt(i as i128, h[i]));
    }
    Map::from_ring(ring).expect("a skyline").0
}

fn agplib(path: &str) -> Option<Map> {
    let full = format!(
        "{}/../data/datasets/agplib/{path}",
        env!("CARGO_MANIFEST_DIR")
    );
    match std::fs::read(&full) {
        Ok(bytes) => Some(wai_map::json::from_json(&bytes).expect("valid map").map),
        Err(e) => {
            say(&format!("skipping {full}: {e}"));
            None
        }
    }
}

fn median(mut v: Vec<u64>) -> u64 {
    v.sort_unstable();
    v[v.len() / 2]
}

#[test]
#[ignore = "timing run: cargo test --release -p wai-benches --test cgal -- --ignored --nocapture"]
fn query_times() {
    let Some(mut cgal) = peer() else { return };
    let mut maps: Vec<(String, Map)> = Vec::new();
    for p in [
        "simple/randsimple-100-1.json",
        "simple/randsimple-1000-1.json",
        "simple/randsimple-2500-1.json",
        "ortho/random-1000-1.json",
    ] {
        if let Some(m) = agplib(p) {
            maps.push((p.to_owned(), m));
        }
    }
    for (kind, n) in [("random-simple-star", 4096), ("random-orthogonal", 4096)] {
        maps.push((
            format!("gen {kind} n={n} seed=1"),
            wai_gen::random(kind, n, 1).expect("generator"),
        ));
    }
    maps.push(("star 10000 seed=1".to_owned(), star(10_000, 1)));
    maps.push(("skyline 4999 columns seed=1".to_owned(), skyline(4999, 1)));

    say(
        "query sets: `corner` = centroids of 3 consecutive vertices (5 spread over the ring), \
         `random` = 5 random interior points, `origin` = the star's centre (sees all)",
    );
    say("map | n | r | set | |V(q)| median | collinear/dup vertices | median ns (lazy) | median ns (exact) | preprocessing ms");
    for (name, m) in &maps {
        let t0 = std::time::Instant::now();
        cgal.set_polygon(m.vertices(), m.scale()).unwrap();
        let pre_ms = t0.elapsed().as_millis();
        let mut sets = vec![
            ("corner", queries(m, 5)),
            ("random", random_queries(m, 5, 7)),
        ];
        if name.starts_with("star") {
            sets.push(("origin", vec![RatPoint::from(pt(0, 0))]));
        }
        for (set, qs) in sets {
            assert!(!qs.is_empty(), "{name}: no {set} query point");
            let reps = if m.n() <= 1000 { 201 } else { 51 };
            let (mut lazy, mut exact, mut sizes) = (Vec::new(), Vec::new(), Vec::new());
            let mut extra = 0usize;
            for q in &qs {
                let v = cgal.visibility(q).unwrap();
                // Every vertex of a visibility polygon lies on the map boundary.
                for p in &v {
                    assert_eq!(
                        locate_rat(m.vertices(), p),
                        Containment::OnBoundary,
                        "{name}: {p} from {q}"
                    );
                }
                let distinct: std::collections::HashSet<&RatPoint> = v.iter().collect();
                assert_eq!(distinct.len(), v.len(), "{name}: repeated vertex from {q}");
                extra += v.len() - drop_collinear(&v).len();
                sizes.push(v.len() as u64);
                lazy.push(cgal.bench(q, reps).unwrap());
                exact.push(cgal.bench_exact(q, reps).unwrap());
            }
            say(&format!(
                "{name} | {} | {} | {set} x{} | {} | {extra} | {} | {} | {pre_ms}",
                m.n(),
                m.r(),
                qs.len(),
                median(sizes),
                median(lazy),
                median(exact),
            ));
        }
    }
}
