//! The pictures the commands draw: a legend entry for every kind of mark,
//! a scale bar in the map's units, lon/lat maps drawn projected, and the
//! cells of adjacent classes in different colours.

use super::{text, wai};
use std::collections::{BTreeMap, BTreeSet};

/// The texts of the legend's entries.
pub(crate) fn legend_entries(svg: &str) -> Vec<String> {
    wai_render::legend_texts(svg)
}

/// The label of a picture's scale bar ("5 m", "20 map units").
pub(crate) fn scale_bar(svg: &str) -> Option<String> {
    let g = &svg[svg.find(r#"<g class="scale-bar">"#)?..];
    let g = &g[..g.find("</g>")?];
    let t = &g[g.find("<text")?..];
    let t = &t[t.find('>')? + 1..];
    Some(t[..t.find("</text>")?].to_string())
}

fn tmp(name: &str) -> std::path::PathBuf {
    std::env::temp_dir().join(format!("wai-pictures-{}-{name}", std::process::id()))
}

fn assert_entries(svg: &str, needles: &[&str]) {
    let entries = legend_entries(svg);
    for needle in needles {
        assert!(
            entries.iter().any(|e| e.contains(needle)),
            "{needle}: {entries:?}"
        );
    }
}

/// The polygons of the cells picture: (pixel points, fill, class).
fn cell_polygons(svg: &str) -> Vec<(Vec<String>, String, usize)> {
    svg.split("<polygon ")
        .skip(1)
        .filter_map(|p| {
            // Cells carry a tooltip; the map's self-closed polygons do not.
            let p = &p[..p.find("</polygon>")?];
            let attr = |name: &str| {
                let i = p.find(&format!("{name}=\"")).unwrap() + name.len() + 2;
                p[i..i + p[i..].find('"').unwrap()].to_string()
            };
            let class: usize = p[p.find("<title>class ")? + 13..]
                .split('<')
                .next()?
                .parse()
                .ok()?;
            let points = attr("points").split(' ').map(str::to_string).collect();
            Some((points, attr("fill"), class))
        })
        .collect()
}

#[test]
fn cells_of_adjacent_classes_differ_in_colour_on_a_map_of_many_classes() {
    let map = wai(
        &[
            "gen",
            "--random",
            "random-simple-star",
            "--n",
            "24",
            "--seed",
            "5",
        ],
        b"",
    );
    assert!(map.status.success(), "{}", text(&map.stderr));
    let svg_path = tmp("cells.svg");
    let out = wai(
        &["decompose", "-", "--svg", svg_path.to_str().unwrap()],
        &map.stdout,
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    let svg = std::fs::read_to_string(&svg_path).unwrap();
    std::fs::remove_file(&svg_path).ok();
    let cells = cell_polygons(&svg);
    let classes: BTreeSet<usize> = cells.iter().map(|c| c.2).collect();
    assert!(classes.len() >= 100, "{} classes", classes.len());
    // Every class has one colour, and cells sharing an edge as drawn
    // differ when their classes do.
    let mut colour_of: BTreeMap<usize, &str> = BTreeMap::new();
    let mut by_edge: BTreeMap<(String, String), Vec<(usize, &str)>> = BTreeMap::new();
    for (pts, fill, class) in &cells {
        assert_eq!(
            *colour_of.entry(*class).or_insert(fill),
            fill,
            "class {class}"
        );
        for i in 0..pts.len() {
            let (a, b) = (pts[i].clone(), pts[(i + 1) % pts.len()].clone());
            if a != b {
                by_edge
                    .entry(if a < b { (a, b) } else { (b, a) })
                    .or_default()
                    .push((*class, fill));
            }
        }
    }
    let mut pairs = 0;
    for sharing in by_edge.values() {
        for (i, (c, f)) in sharing.iter().enumerate() {
            for (d, g) in &sharing[i + 1..] {
                if c != d {
                    pairs += 1;
                    assert_ne!(f, g, "classes {c} and {d} share an edge and a colour");
                }
            }
        }
    }
    assert!(pairs > 100, "{pairs} edges between classes");
    let distinct: BTreeSet<&str> = colour_of.values().copied().collect();
    assert!(distinct.len() >= 20, "{} colours", distinct.len());
    assert_entries(&svg, &["map walls", "2-cells", "adjacent classes differ"]);
    assert!(scale_bar(&svg).unwrap().ends_with("map units"));
}

#[test]
fn visibility_and_map_pictures_have_legends_and_scale_bars() {
    let l_room = super::L_ROOM.as_bytes();
    let svg_path = tmp("vis.svg");
    let out = wai(
        &[
            "vis",
            "-",
            "--at",
            "3,1/2",
            "--svg",
            svg_path.to_str().unwrap(),
        ],
        l_room,
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    let svg = std::fs::read_to_string(&svg_path).unwrap();
    std::fs::remove_file(&svg_path).ok();
    assert_entries(
        &svg,
        &[
            "map (walls and inside)",
            "visibility polygon V_p",
            "spurious edge",
            "artificial edge",
            "viewpoint p",
        ],
    );
    assert_eq!(scale_bar(&svg).as_deref(), Some("0.5 map units"));
    let out = wai(&["render", "-"], l_room);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let svg = text(&out.stdout);
    assert_entries(&svg, &["convex vertex", "reflex vertex"]);
    assert_eq!(scale_bar(&svg).as_deref(), Some("0.5 map units"));
}

#[test]
fn a_lonlat_map_is_drawn_projected_with_a_scale_bar_in_metres() {
    let floor = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../data/datasets/westport/westport-house-floor-gf.json"
    );
    let out = wai(&["render", floor], b"");
    assert!(out.status.success(), "{}", text(&out.stderr));
    let svg = text(&out.stdout);
    let bar = scale_bar(&svg).expect("a scale bar");
    assert!(bar.ends_with(" m"), "{bar}");
    assert!(svg.contains("equirectangular"), "{svg}");
}
