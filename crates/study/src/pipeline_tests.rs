//! Tests of the study's stages against the slower ways they replace: the
//! trapezoid count against the localizer's overlays, the cell edges by
//! supporting lines against Def 5.2 read off exact points, the witness
//! views by rule against visibility queries.

use crate::preprocessing::trapezoids;
use wai_cells::Decomposition;
use wai_exact::Point;
use wai_localize::Localizer;
use wai_map::Map;

fn maps() -> Vec<Map> {
    let mut maps = Vec::new();
    for kind in wai_gen::RANDOM_KINDS {
        for (n, seed) in [(8, 1), (14, 2), (24, 3)] {
            maps.push(wai_gen::random(kind.id, n, seed).expect("a random map"));
        }
    }
    for layout in wai_gen::LAYOUTS {
        maps.push((layout.generate)(1));
    }
    for (id, k) in [
        ("corridor-niches", 2),
        ("convex-niches", 2),
        ("window-grid", 2),
        ("overlap-fan", 1),
    ] {
        maps.push(wai_gen::family(id, &[k]).expect("a family map"));
    }
    maps.extend((0..24).map(wai_gen::bytes::map_from_seed));
    // Every free polyomino of 6 cells: collinear walls everywhere.
    maps.extend(
        wai_gen::polyominoes(6, wai_gen::Symmetry::Free)
            .iter()
            .map(wai_gen::Polyomino::to_map),
    );
    maps
}

#[test]
fn the_count_is_the_localizers() {
    for map in maps() {
        let d = Decomposition::new(&map);
        let want = Localizer::from_decomposition(&d).trapezoids();
        assert_eq!(trapezoids(&d), Some(want), "{:?}", map.name());
    }
}

/// `Study::cell_edges` (by supporting lines, in integers) against Def
/// 5.2 read off the kernel's edges and the cells' exact points.
#[test]
fn cell_edges_by_lines_are_cell_edges_by_points() {
    use wai_embed::wedge::{classify_cell_edges, embedding_wedge_lines};
    let mut edges = 0;
    for map in maps() {
        let study = crate::Study::new(&map);
        let arr = study.arrangement();
        for (class, cells) in study.cell_edges().iter().enumerate() {
            for c in cells {
                let h = &study.embeddings()[class][c.embedding];
                let valid = study.valid_candidates(class, c.embedding);
                let lines = embedding_wedge_lines(&map, &h.embedding, valid);
                let by_points = classify_cell_edges(h.kernel(), &lines, &arr.face_points(c.cell));
                assert_eq!(c.kinds, by_points, "{:?}, cell {}", map.name(), c.cell);
                edges += c.kinds.len();
            }
        }
    }
    assert!(edges > 10_000, "{edges} edges compared");
}

#[test]
fn coordinates_past_the_bound_fall_back_to_the_localizer() {
    // The L room (0,0), (4,0), (4,2), (2,2), (2,4), (0,4) under the linear
    // map with rows (A, B) and (C, D), positive determinant: with entries
    // near 2^5 the i128 paths count; near 2^48 a line's coefficients are
    // near 2^50 and the slab boundaries' products pass 2^127, so the count
    // is the localizer's.
    let ring = [(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)];
    let room = |m: [i128; 4]| {
        let pts = ring
            .iter()
            .map(|&(x, y)| Point::new(m[0] * x + m[1] * y, m[2] * x + m[3] * y))
            .collect();
        Map::from_ring(pts).unwrap().0
    };
    let big = 1i128 << 48;
    for (m, fits) in [
        ([33, 7, 5, 31], true),
        (
            [big + 3, (big >> 1) - 7, (big >> 2) + 11, 2 * big + 5],
            false,
        ),
    ] {
        let map = room(m);
        let d = Decomposition::new(&map);
        assert_eq!(trapezoids(&d).is_some(), fits, "{m:?}");
        let study = crate::Study::new(&map);
        let want = study.localizer().trapezoids();
        assert_eq!(study.preprocessing_size(), want, "{m:?}");
    }
}

/// `Study::views` (by rule for 2-cells) against V_w of a visibility query
/// at every witness cell.
#[test]
fn views_by_rule_are_views_by_query() {
    let mut cells = 0;
    for map in maps() {
        let study = crate::Study::new(&map);
        for (class, hs) in study.embeddings().iter().enumerate() {
            for (i, h) in hs.iter().enumerate() {
                let w = &study.witnesses()[class][i];
                let by_query = wai_embed::witness_views(study.index(), &h.embedding, w);
                assert_eq!(study.views()[class][i], by_query, "{:?}", map.name());
                cells += by_query.len();
            }
        }
    }
    assert!(cells > 10_000, "{cells} witness cells compared");
}
