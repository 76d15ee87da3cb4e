//! `wai vis`: the visibility polygon V_p and skeleton V*_p of a viewpoint.

use crate::failure::Failure;
use crate::input::load_with_holes;
use rug::{Integer, Rational};
use std::path::PathBuf;
use wai_exact::RatPoint;
use wai_map::{format_exact, parse_exact, Map};
use wai_render::{visibility_svg, MapStyle};
use wai_visibility::{EdgeKind, OnMap, Skeleton, SkeletonEdge, VisibilityIndex, VisibilityPolygon};

/// Parse `x,y` (exact numbers in the map's input units) into map units.
pub fn parse_viewpoint(text: &str, map: &Map) -> Result<RatPoint, Failure> {
    let parts: Vec<&str> = text.split(',').map(str::trim).collect();
    let [xs, ys] = parts[..] else {
        return Err(Failure::usage(format!("--at {text:?}: expected x,y")));
    };
    let coord = |s: &str, which: &str| {
        parse_exact(s).map_err(|e| {
            Failure::usage(format!(
                "--at {text:?}: {which} {s:?} is not an exact number: {e}"
            ))
        })
    };
    let (x, y) = (coord(xs, "x")?, coord(ys, "y")?);
    let scale = map.scale();
    Ok(RatPoint::from_rationals(x * scale, y * scale))
}

/// A point in the map's input units, as text.
pub(crate) fn show(map: &Map, p: &RatPoint) -> String {
    let den = Integer::from(p.hw() * map.scale());
    let c = |n: &Integer| format_exact(&Rational::from((n.clone(), den.clone())));
    format!("({}, {})", c(p.hx()), c(p.hy()))
}

fn show_int(map: &Map, p: wai_exact::Point) -> String {
    show(map, &RatPoint::from(p))
}

fn kind_name(k: EdgeKind) -> &'static str {
    match k {
        EdgeKind::Spurious => "spurious",
        EdgeKind::Full => "full",
        EdgeKind::Half => "half",
        EdgeKind::Partial => "partial",
    }
}

fn place(on: OnMap) -> String {
    match on {
        OnMap::Vertex(i) => format!("map vertex {i}"),
        OnMap::Edge(i) => format!("on map edge {i}"),
    }
}

fn text(map: &Map, vp: &VisibilityPolygon, sk: &Skeleton) -> String {
    let mut s = format!(
        "viewpoint {}\n\nV_p: {} vertices\n",
        show(map, vp.viewpoint()),
        vp.len()
    );
    for (i, v) in vp.vertices().iter().enumerate() {
        s.push_str(&format!(
            "  {i:>3} {:<28} {}{}\n",
            show(map, &v.point),
            place(v.on_map),
            if v.spurious { ", spurious" } else { "" }
        ));
    }
    s.push_str("edges:\n");
    let n = vp.len();
    for (i, e) in vp.edges().iter().enumerate() {
        let on = e
            .map_edge
            .map_or(String::new(), |m| format!(" on map edge {m}"));
        let blocking = if e.blocking.is_empty() {
            String::new()
        } else {
            let b: Vec<String> = e
                .blocking
                .iter()
                .map(|&k| format!("V_p vertex {k}"))
                .collect();
            format!(", blocked by {}", b.join(" and "))
        };
        s.push_str(&format!(
            "  {i:>3} -> {:<3} {}{on}{blocking}\n",
            (i + 1) % n,
            kind_name(e.kind)
        ));
    }
    let key = sk.key();
    s.push_str(&format!(
        "\nskeleton V*_p: origin v0 = {} (map vertex {}), {} vertices, {} artificial edges\n",
        show_int(map, sk.origin()),
        sk.map_vertices()[0],
        sk.vertices().len(),
        sk.artificial_count()
    ));
    let k = sk.vertices().len();
    for (i, e) in sk.edges().iter().enumerate() {
        let (dx, dy) = key.offsets[i];
        let what = match e {
            SkeletonEdge::Full { map_edge } => format!("full (map edge {map_edge})"),
            SkeletonEdge::Artificial { label, map_edge } => format!(
                "artificial, label {}·x + {}·y = {} relative to v0 (line of map edge {map_edge})",
                label.a, label.b, label.c
            ),
        };
        s.push_str(&format!(
            "  {i:>3} v0 + ({dx}, {dy}) [map vertex {}] -> {}: {what}\n",
            sk.map_vertices()[i],
            (i + 1) % k
        ));
    }
    let ker = sk.kernel();
    let pts: Vec<String> = ker.vertices().iter().map(|p| show(map, p)).collect();
    s.push_str(&format!(
        "kernel of V*_p: {} vertices {}\n",
        pts.len(),
        pts.join(" ")
    ));
    s
}

fn json(map: &Map, vp: &VisibilityPolygon, sk: &Skeleton) -> String {
    let den = |p: &RatPoint| Integer::from(p.hw() * map.scale());
    let pt = |p: &RatPoint| {
        serde_json::json!([
            format_exact(&Rational::from((p.hx().clone(), den(p)))),
            format_exact(&Rational::from((p.hy().clone(), den(p))))
        ])
    };
    let vertices: Vec<_> = vp
        .vertices()
        .iter()
        .map(|v| {
            let (kind, index) = match v.on_map {
                OnMap::Vertex(i) => ("vertex", i),
                OnMap::Edge(i) => ("edge", i),
            };
            serde_json::json!({"at": pt(&v.point), "on_map": {kind: index}, "spurious": v.spurious})
        })
        .collect();
    let edges: Vec<_> = vp
        .edges()
        .iter()
        .map(|e| serde_json::json!({"kind": kind_name(e.kind), "map_edge": e.map_edge, "blocking": e.blocking}))
        .collect();
    let key = sk.key();
    let sk_edges: Vec<_> = sk
        .edges()
        .iter()
        .map(|e| match e {
            SkeletonEdge::Full { map_edge } => {
                serde_json::json!({"kind": "full", "map_edge": map_edge})
            }
            SkeletonEdge::Artificial { label, map_edge } => serde_json::json!({
                "kind": "artificial", "map_edge": map_edge,
                "label": [label.a.to_string(), label.b.to_string(), label.c.to_string()]
            }),
        })
        .collect();
    let v = serde_json::json!({
        "viewpoint": pt(vp.viewpoint()),
        "visibility_polygon": {"vertices": vertices, "edges": edges},
        "skeleton": {
            "origin": pt(&RatPoint::from(sk.origin())),
            "origin_map_vertex": sk.map_vertices()[0],
            "map_vertices": sk.map_vertices(),
            "offsets_map_units": key.offsets.iter().map(|(x, y)| [x.to_string(), y.to_string()]).collect::<Vec<_>>(),
            "edges": sk_edges,
            "kernel": sk.kernel().vertices().iter().map(pt).collect::<Vec<_>>(),
        },
    });
    format!(
        "{}\n",
        serde_json::to_string_pretty(&v).expect("plain JSON")
    )
}

#[derive(clap::Args, Debug)]
pub struct Args {
    #[arg(help = crate::input::MAP_HELP)]
    pub map: PathBuf,
    /// The viewpoint `x,y`, exact numbers in the map's units (e.g. `3/2,0.25`).
    #[arg(long, allow_hyphen_values = true)]
    pub at: String,
    /// Print JSON instead of text.
    #[arg(long)]
    pub json: bool,
    /// Also draw V_p, its spurious edges and the skeleton into this SVG file.
    #[arg(long)]
    pub svg: Option<PathBuf>,
    #[command(flatten)]
    pub format: crate::input::FormatArg,
}

pub fn run(args: &Args) -> Result<(), Failure> {
    let (path, at, as_json, svg) = (&args.map, &args.at, args.json, args.svg.as_deref());
    let loaded = load_with_holes(path, args.format)?;
    let map = &loaded.map;
    let p = parse_viewpoint(at, map)?;
    let index = VisibilityIndex::new(map);
    let vp = index.visibility_polygon(&p).map_err(|e| {
        Failure::invalid(format!(
            "{}: {}",
            path.display(),
            e.to_string().replace(&p.to_string(), &show(map, &p))
        ))
    })?;
    let sk = Skeleton::of(map, &vp)
        .map_err(|e| Failure::invalid(format!("internal: skeleton of V_p: {e}")))?;
    if let Some(out) = svg {
        let picture = visibility_svg(map, &vp, Some(&sk), &MapStyle::default());
        std::fs::write(out, picture).map_err(|e| Failure::io(format!("{}: {e}", out.display())))?;
    }
    out!(
        "{}",
        if as_json {
            json(map, &vp, &sk)
        } else {
            text(map, &vp, &sk)
        }
    );
    Ok(())
}
