//! The subcommands.

use crate::input::{load, note_normalisation, Format};
use crate::Failure;
use rug::{Integer, Rational};
use std::path::{Path, PathBuf};
use wai_map::json::{from_json, to_json};
use wai_map::{format_exact, Loaded, Map};
use wai_render::{map_svg, MapStyle};

/// The built-in default map: an office floor, a corridor with five rooms.
pub const DEFAULT_MAP: &str = include_str!("../maps/office-floor.json");

#[derive(clap::Args, Debug)]
pub struct GenArgs {
    /// A thesis family by id (see --list).
    #[arg(long, conflicts_with_all = ["random", "layout"], required_unless_present_any = ["random", "layout", "list"])]
    pub family: Option<String>,
    /// A family parameter; repeat for families with several.
    #[arg(long = "param")]
    pub params: Vec<u32>,
    /// A random kind by id (see --list).
    #[arg(long, conflicts_with = "layout")]
    pub random: Option<String>,
    /// A seeded chapter 4 layout by id (see --list): repeated rooms whose
    /// embeddings overlap.
    #[arg(long)]
    pub layout: Option<String>,
    /// Vertex count target for random kinds.
    #[arg(long, default_value_t = 20)]
    pub n: usize,
    /// Seed for random kinds and layouts (the same seed gives the same map).
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Output file; standard output if absent.
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// List the families and random kinds.
    #[arg(long)]
    pub list: bool,
}

fn write_file(path: &Path, text: &str) -> Result<(), Failure> {
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).map_err(|e| Failure::io(format!("{}: {e}", dir.display())))?;
    }
    std::fs::write(path, text).map_err(|e| Failure::io(format!("{}: {e}", path.display())))
}

fn output(out: Option<&Path>, text: &str) -> Result<(), Failure> {
    match out {
        Some(path) => write_file(path, text),
        None => {
            print!("{text}");
            Ok(())
        }
    }
}

/// The exact area in input units.
fn area(map: &Map) -> Rational {
    let scale2 = Integer::from(map.scale() * map.scale());
    Rational::from((map.area_twice(), scale2 * 2u32))
}

fn unit(map: &Map, c: i128) -> String {
    format_exact(&Rational::from((Integer::from(c), map.scale().clone())))
}

fn info_text(map: &Map) -> String {
    let (lo, hi) = map.bounding_box();
    let reflex: Vec<String> = map.reflex_vertices().iter().map(usize::to_string).collect();
    format!(
        "name:         {}\nvertices n:   {}\nreflex r:     {}  [{}]\narea:         {}\northogonal:   {}\nscale:        1/{} (coordinates are integers over this denominator)\nbounding box: ({}, {}) – ({}, {})\n",
        map.name().unwrap_or("-"),
        map.n(),
        map.r(),
        reflex.join(", "),
        format_exact(&area(map)),
        if map.is_orthogonal() { "yes" } else { "no" },
        map.scale(),
        unit(map, lo.x),
        unit(map, lo.y),
        unit(map, hi.x),
        unit(map, hi.y),
    )
}

fn info_json(loaded: &Loaded) -> String {
    let map = &loaded.map;
    let (lo, hi) = map.bounding_box();
    let v = serde_json::json!({
        "name": map.name(),
        "n": map.n(),
        "r": map.r(),
        "reflex_vertices": map.reflex_vertices(),
        "area": format_exact(&area(map)),
        "orthogonal": map.is_orthogonal(),
        "scale": map.scale().to_string(),
        "bounding_box": [[unit(map, lo.x), unit(map, lo.y)], [unit(map, hi.x), unit(map, hi.y)]],
        "normalisation": {
            "reversed": loaded.normalisation.reversed,
            "removed_collinear": loaded.normalisation.removed_collinear,
        },
    });
    format!(
        "{}\n",
        serde_json::to_string_pretty(&v).expect("plain JSON values")
    )
}

pub fn info(path: &Path, json: bool, format: Format) -> Result<(), Failure> {
    let loaded = load(path, format)?;
    if json {
        print!("{}", info_json(&loaded));
    } else {
        print!("{}", info_text(&loaded.map));
    }
    Ok(())
}

pub fn render(
    path: &Path,
    out: Option<&Path>,
    labels: bool,
    size: u32,
    format: Format,
) -> Result<(), Failure> {
    let loaded = load(path, format)?;
    let style = MapStyle {
        size: f64::from(size.clamp(50, 20_000)),
        vertex_labels: labels,
    };
    output(out, &map_svg(&loaded.map, &style))
}

pub fn demo(out: &Path) -> Result<(), Failure> {
    let loaded = from_json(DEFAULT_MAP.as_bytes())
        .map_err(|e| Failure::invalid(format!("built-in map: {e}")))?;
    let builtin = Path::new("<built-in office-floor>");
    note_normalisation(builtin, &loaded);
    let map = &loaded.map;
    println!("The built-in default map (wai demo):\n");
    print!("{}", info_text(map));
    let json_path = out.join("office-floor.json");
    let svg_path = out.join("office-floor.svg");
    write_file(&json_path, &to_json(map))?;
    let style = MapStyle {
        vertex_labels: true,
        ..MapStyle::default()
    };
    write_file(&svg_path, &map_svg(map, &style))?;
    // The visibility polygon and skeleton of a viewpoint in the corridor.
    let index = wai_visibility::VisibilityIndex::new(map);
    let p = wai_exact::RatPoint::from(wai_exact::Point::new(9, 2));
    let vp = index
        .visibility_polygon(&p)
        .map_err(|e| Failure::invalid(format!("built-in map: {e}")))?;
    let sk = wai_visibility::Skeleton::of(map, &vp)
        .map_err(|e| Failure::invalid(format!("built-in map: skeleton: {e}")))?;
    let count = |k: wai_visibility::EdgeKind| vp.edges().iter().filter(|e| e.kind == k).count();
    use wai_visibility::EdgeKind::{Full, Half, Partial, Spurious};
    println!(
        "\nV_p of viewpoint (9, 2): {} vertices; edges {} full, {} half, {} partial, {} spurious",
        vp.len(),
        count(Full),
        count(Half),
        count(Partial),
        count(Spurious)
    );
    println!(
        "V*_p: origin v0 = {} (map vertex {}), {} vertices, {} artificial edges, kernel with {} vertices",
        sk.origin(),
        sk.map_vertices()[0],
        sk.vertices().len(),
        sk.artificial_count(),
        sk.kernel().vertices().len()
    );
    // The visibility cell decomposition with its classes.
    let d = wai_cells::Decomposition::new(map);
    let c = d.counts();
    println!(
        "decomposition: {} visibility rays, {} 2-cells, N = {}, {} classes, max |EC| = {}; \
         1-cells {} kept / {} absorbed, 0-cells {} kept / {} absorbed",
        c.rays,
        c.cells,
        c.total_complexity,
        c.classes,
        c.max_class_complexity,
        c.one_cells.kept,
        c.one_cells.absorbed,
        c.zero_cells.kept,
        c.zero_cells.absorbed
    );
    let cells = crate::decompose::cell_rings(&d);
    let cells_path = out.join("office-floor-cells.svg");
    let caption = format!(
        "{} 2-cells, {} kept 1-cells, {} kept 0-cells in {} classes",
        c.cells, c.one_cells.kept, c.zero_cells.kept, c.classes
    );
    write_file(
        &cells_path,
        &wai_render::cells_svg(
            map,
            &cells,
            &crate::decompose::kept_lower_cells(&d),
            None,
            &MapStyle::default(),
            &caption,
        ),
    )?;
    println!("wrote {}", cells_path.display());
    let vis_path = out.join("office-floor-vis.svg");
    write_file(
        &vis_path,
        &wai_render::visibility_svg(map, &vp, Some(&sk), &MapStyle::default()),
    )?;
    println!(
        "\nwrote {}, {} and {}",
        json_path.display(),
        svg_path.display(),
        vis_path.display()
    );
    // Localization (Alg 3.13/3.14): the robot at (9, 2) sees V_p; where
    // can it be? Then the same on a corridor with six identical niches,
    // where one view has six answers.
    let loc = wai_localize::Localizer::from_decomposition(&d);
    let view = wai_localize::RobotView::from_visibility(&vp);
    let answer = loc.localize(&view);
    println!(
        "\nlocalize V_p of (9, 2) on this map: {} position(s): {}",
        answer.placements.len(),
        answer
            .placements
            .iter()
            .map(|a| crate::vis::show(map, &a.position))
            .collect::<Vec<_>>()
            .join(", ")
    );
    let corridor = wai_gen::family("corridor-niches", &[6])
        .map_err(|e| Failure::invalid(format!("corridor-niches: {e}")))?;
    let at = wai_exact::RatPoint::from_i128(10, -7, 2).expect("w = 2");
    let vq = wai_visibility::VisibilityIndex::new(&corridor)
        .visibility_polygon(&at)
        .map_err(|e| Failure::invalid(format!("corridor-niches: {e}")))?;
    let view = wai_localize::RobotView::from_visibility(&vq);
    let answer = wai_localize::Localizer::new(&corridor).localize(&view);
    let loc_path = out.join("corridor-niches-localize.svg");
    write_file(
        &loc_path,
        &crate::localize::answers_svg(&corridor, &view, &answer),
    )?;
    println!(
        "localize the view from (5, -3.5) on corridor-niches k=6: {} positions: {}",
        answer.placements.len(),
        answer
            .placements
            .iter()
            .map(|a| crate::vis::show(&corridor, &a.position))
            .collect::<Vec<_>>()
            .join(", ")
    );
    println!("wrote {}", loc_path.display());
    println!("(`wai vis MAP --at x,y` for any viewpoint, `wai decompose MAP` for any map, `wai localize MAP --at x,y | --polygon V.json` for any view)");
    Ok(())
}

pub fn gen(args: &GenArgs) -> Result<(), Failure> {
    if args.list {
        print!("{}", catalogue());
        return Ok(());
    }
    let map = match (&args.family, &args.random, &args.layout) {
        (Some(family), _, _) => wai_gen::family(family, &args.params),
        (None, Some(kind), _) => wai_gen::random(kind, args.n, args.seed),
        (None, None, Some(id)) => wai_gen::layout(id, args.seed),
        (None, None, None) => {
            return Err(Failure::usage(
                "give --family ID, --random KIND or --layout ID (see --list)",
            ))
        }
    }
    .map_err(|e| Failure::usage(e.to_string()))?;
    output(args.out.as_deref(), &to_json(&map))?;
    if let Some(out) = &args.out {
        eprintln!("wrote {} (n = {}, r = {})", out.display(), map.n(), map.r());
    }
    Ok(())
}

/// The families and random kinds, for `gen --list`.
fn catalogue() -> String {
    let mut s = String::from("Thesis families (gen --family ID --param P ...):\n");
    for f in wai_gen::FAMILIES {
        s.push_str(&format!(
            "  {:<20} {}\n  {:<20} n = {}, r = {}; {} [{}]\n",
            f.id,
            f.params,
            "",
            f.n,
            f.r,
            f.reference,
            f.claims.join(", ")
        ));
    }
    s.push_str("\nRandom kinds (gen --random KIND --n N --seed S):\n");
    for k in wai_gen::RANDOM_KINDS {
        s.push_str(&format!(
            "  {:<20} {} (n from {} to {}; vertices: {})\n",
            k.id, k.method, k.min_n, k.max_n, k.vertices
        ));
    }
    s.push_str("\nChapter 4 and 5 layouts (gen --layout ID --seed S):\n");
    for l in wai_gen::LAYOUTS {
        s.push_str(&format!("  {:<20} {}\n", l.id, l.shows));
    }
    s
}
