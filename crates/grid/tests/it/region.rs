//! From cells to a map: rooms, pillars, pinches, specks, the chosen
//! component, and random grids checked cell by cell against the traced map.

use crate::{image, meta, q};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::Integer;
use wai_exact::{locate, Containment, Point};
use wai_grid::occupancy::{free_cells, free_values};
use wai_grid::trace::{region, Choice};
use wai_grid::{import_parts, GridError, ImportOptions};
use wai_map::Map;

fn area_m2(map: &Map) -> rug::Rational {
    rug::Rational::from((
        map.area_twice(),
        Integer::from(map.scale() * map.scale()) * 2u32,
    ))
}

#[test]
fn a_room_with_a_pillar() {
    let img = image(&[
        "#######", //
        "#.....#", "#.##..#", "#.##..#", "#.....#", "#######",
    ]);
    let (map, report) =
        import_parts(&meta("0.5", ("-1", "2")), &img, &ImportOptions::default()).unwrap();
    assert_eq!((map.n(), map.hole_count(), map.r()), (8, 1, 4));
    assert_eq!(report.region.region_cells, 16);
    assert_eq!(report.region.holes, 1);
    assert_eq!(area_m2(&map), q("4"));
    // Metres in the grid's frame: the free room spans x in [-1/2, 2],
    // y in [5/2, 9/2]; the pillar [0, 1] × [3, 4].
    let (lo, hi) = map.bounding_box();
    let s = map.scale().to_i128().unwrap();
    assert_eq!(
        (lo.x * 2, lo.y * 2, hi.x, hi.y * 2),
        (-s, 5 * s, 2 * s, 9 * s)
    );
    assert_eq!(map.units(), Some(&wai_map::Units::Metres));
    assert!(map.holes().next().unwrap().contains(&Point::new(0, 3 * s)));
}

#[test]
fn a_pinch_gives_up_one_free_cell() {
    let img = image(&[
        "######", //
        "#....#", "#.#..#", "#..#.#", "#....#", "######",
    ]);
    let (map, report) =
        import_parts(&meta("1", ("0", "0")), &img, &ImportOptions::default()).unwrap();
    assert_eq!(report.region.pinch_cells, 1);
    assert_eq!(report.region.region_cells, 16 - 2 - 1);
    // The two diagonal obstacles and the cell given up: one hole.
    assert_eq!((map.hole_count(), report.region.holes), (1, 1));
    assert_eq!(area_m2(&map), q("13"));
}

#[test]
fn specks_below_the_area_are_filled_and_larger_obstacles_are_holes() {
    let img = image(&[
        "########", //
        "#......#", "#.#..#.#", "#....#.#", "#......#", "########",
    ]);
    let all = import_parts(&meta("0.1", ("0", "0")), &img, &ImportOptions::default()).unwrap();
    assert_eq!(all.0.hole_count(), 2);
    let opts = ImportOptions {
        min_hole_area: q("0.02"), // two cells of 0.01 m²
        ..ImportOptions::default()
    };
    let (map, report) = import_parts(&meta("0.1", ("0", "0")), &img, &opts).unwrap();
    assert_eq!(
        (report.region.specks_filled, report.region.speck_cells),
        (1, 1)
    );
    assert_eq!((map.hole_count(), report.region.holes), (1, 1));
    assert_eq!(area_m2(&map), q("0.22"));
}

#[test]
fn the_component_holding_a_point_or_the_largest() {
    let img = image(&[
        "#########", //
        "#...#..?#",
        "#...#..##",
        "#...#####",
        "#########",
    ]);
    let m = meta("1", ("0", "0"));
    let (largest, r) = import_parts(&m, &img, &ImportOptions::default()).unwrap();
    assert_eq!((r.region.components, r.region.region_cells), (2, 9));
    assert_eq!(area_m2(&largest), q("9"));
    let at = |x: &str, y: &str| ImportOptions {
        at: Some((q(x), q(y))),
        ..ImportOptions::default()
    };
    // The small room (unknown cells are obstacles): 4 cells.
    let (small, _) = import_parts(&m, &img, &at("5.5", "3.5")).unwrap();
    assert_eq!(area_m2(&small), q("4"));
    let e = import_parts(&m, &img, &at("4.5", "2.5")).unwrap_err();
    assert!(
        e.to_string().contains(
            "the point (4.5, 2.5) lies in cell (column 4, row 2 from the top), which is not free"
        ),
        "{e}"
    );
    let e = import_parts(&m, &img, &at("-1", "2")).unwrap_err();
    assert!(e.to_string().contains("lies outside the grid"), "{e}");
    let none = image(&["##", "#?"]);
    assert!(matches!(
        import_parts(&m, &none, &ImportOptions::default()),
        Err(GridError::NoFreeCell)
    ));
}

#[test]
fn thresholds_are_exact_and_negate_reverses_the_scale() {
    let mut m = meta("1", ("0", "0"));
    m.free_thresh = q("0.2");
    let free = free_values(&m, 255);
    // (255 - 204) / 255 = 0.2 exactly: not below the threshold.
    assert!(!free[204] && free[205] && free[255] && !free[0]);
    m.negate = true;
    let free = free_values(&m, 255);
    assert!(free[0] && free[50] && !free[51] && !free[255]);
}

#[test]
fn simplification_keeps_the_boundary_within_the_tolerance() {
    // A staircase wall: every step a corner.
    let img = image(&[
        "##########", //
        "#........#",
        "#.......##",
        "#......###",
        "#.....####",
        "##########",
    ]);
    let m = meta("0.05", ("0", "0"));
    let (exact, report) = import_parts(&m, &img, &ImportOptions::default()).unwrap();
    assert_eq!(report.simplified_away, 0);
    let opts = ImportOptions {
        simplify: Some(q("0.05")),
        ..ImportOptions::default()
    };
    let (simple, report) = import_parts(&m, &img, &opts).unwrap();
    assert!(report.simplified_away >= 4, "{report:?}");
    assert_eq!(simple.n() + report.simplified_away, exact.n());
}

/// Twice the centre of cell (c, r) on the map's integer grid, for the map
/// of `meta("1", ("0", "0"))` (corners at integers · scale).
fn doubled_centre(map: &Map, c: usize, r: usize) -> Point {
    let s = map.scale().to_i128().unwrap();
    Point::new((2 * c as i128 + 1) * s, (2 * r as i128 + 1) * s)
}

fn doubled(ring: &[Point]) -> Vec<Point> {
    ring.iter().map(|p| Point::new(2 * p.x, 2 * p.y)).collect()
}

#[test]
fn random_grids_trace_exactly_the_region() {
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    let mut checked = 0;
    let mut with_holes = 0;
    let mut with_pinches = 0;
    for _ in 0..300 {
        let (w, h) = (rng.random_range(2..14), rng.random_range(2..12));
        let p_free = rng.random_range(0.5..0.95);
        let rows: Vec<String> = (0..h)
            .map(|_| {
                (0..w)
                    .map(|_| match rng.random::<f64>() {
                        x if x < p_free => '.',
                        x if x < p_free + 0.05 => '?',
                        _ => '#',
                    })
                    .collect()
            })
            .collect();
        let rows: Vec<&str> = rows.iter().map(String::as_str).collect();
        let img = image(&rows);
        let m = meta("1", ("0", "0"));
        let free = free_cells(&m, &img);
        let Some((mask, report)) = region(&free, w, h, Choice::Largest, 0) else {
            continue;
        };
        let (map, _) = import_parts(&m, &img, &ImportOptions::default())
            .unwrap_or_else(|e| panic!("{e}\n{}", rows.join("\n")));
        // The region is free, pinch-free and as counted.
        assert!(mask.iter().zip(&free).all(|(&m, &f)| !m || f));
        assert_eq!(
            mask.iter().filter(|&&m| m).count() as u64,
            report.region_cells
        );
        assert_eq!(area_m2(&map), rug::Rational::from(report.region_cells));
        // Every cell centre is in the map's free space iff in the region.
        let outer = doubled(map.outer());
        let holes: Vec<Vec<Point>> = map.holes().map(doubled).collect();
        for r in 0..h {
            for c in 0..w {
                let p = doubled_centre(&map, c, r);
                let inside = locate(&outer, p) == Containment::Inside
                    && holes
                        .iter()
                        .all(|hole| locate(hole, p) == Containment::Outside);
                assert_eq!(
                    inside,
                    mask[r * w + c],
                    "cell ({c}, {r})\n{}",
                    rows.join("\n")
                );
            }
        }
        checked += 1;
        with_holes += usize::from(map.has_holes());
        with_pinches += usize::from(report.pinch_cells > 0);
    }
    // The generator reached the cases that matter.
    assert!(
        checked >= 250 && with_holes >= 30 && with_pinches >= 30,
        "{checked} {with_holes} {with_pinches}"
    );
}
