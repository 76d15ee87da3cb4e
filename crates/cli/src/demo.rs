//! `wai demo`: the main job on the built-in default map (an office floor):
//! its numbers, a visibility polygon and skeleton, the decomposition, two
//! localizations, and the pictures in `--out`.

use std::path::{Path, PathBuf};

use wai_map::json::{from_json, to_json};
use wai_render::{map_svg, MapStyle};

use crate::failure::Failure;
use crate::input::note_normalisation;
use crate::output::write_file;

/// The built-in default map: an office floor, a corridor with five rooms.
pub const DEFAULT_MAP: &str = include_str!("../maps/office-floor.json");

#[derive(clap::Args, Debug)]
pub struct Args {
    /// Folder for the output files.
    #[arg(long, default_value = "target/wai-demo")]
    pub out: PathBuf,
}

pub fn run(args: &Args) -> Result<(), Failure> {
    let out = args.out.as_path();
    let loaded = from_json(DEFAULT_MAP.as_bytes())
        .map_err(|e| Failure::invalid(format!("built-in map: {e}")))?;
    let builtin = Path::new("<built-in office-floor>");
    note_normalisation(builtin, &loaded);
    let map = &loaded.map;
    outln!("The built-in default map (wai demo):\n");
    out!("{}", crate::info::text(map));
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
    outln!(
        "\nV_p of viewpoint (9, 2): {} vertices; edges {} full, {} half, {} partial, {} spurious",
        vp.len(),
        count(Full),
        count(Half),
        count(Partial),
        count(Spurious)
    );
    outln!(
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
    outln!(
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
    outln!("wrote {}", cells_path.display());
    let vis_path = out.join("office-floor-vis.svg");
    write_file(
        &vis_path,
        &wai_render::visibility_svg(map, &vp, Some(&sk), &MapStyle::default()),
    )?;
    outln!(
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
    outln!(
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
    outln!(
        "localize the view from (5, -3.5) on corridor-niches k=6: {} positions: {}",
        answer.placements.len(),
        answer
            .placements
            .iter()
            .map(|a| crate::vis::show(&corridor, &a.position))
            .collect::<Vec<_>>()
            .join(", ")
    );
    outln!("wrote {}", loc_path.display());
    outln!("(`wai vis MAP --at x,y` for any viewpoint, `wai decompose MAP` for any map, `wai localize MAP --at x,y | --polygon V.json` for any view)");
    Ok(())
}
