//! `wai map-from-log`: a map built from a laser log's scans, through an
//! occupancy grid, into an exact map with holes.

use crate::failure::Failure;
use crate::output::{output, write_file};
use std::path::PathBuf;
use wai_grid::{import_parts, ImportOptions};
use wai_map::{format_exact, parse_exact};
use wai_scan::carmen;
use wai_scan::log_map::{occupancy_grid, yaml, GridOptions};

/// Which scans of the log build the map.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum Half {
    All,
    /// Scans 0, 2, 4, … (the other half can then be localized against it).
    Even,
    Odd,
}

impl Half {
    pub fn picks(self, k: usize) -> bool {
        match self {
            Half::All => true,
            Half::Even => k.is_multiple_of(2),
            Half::Odd => k % 2 == 1,
        }
    }
}

#[derive(clap::Args, Debug)]
pub struct Args {
    /// A CARMEN log (FLASER, ROBOTLASER1, ODOM lines), plain or .gz.
    pub log: PathBuf,
    /// Metres per cell of the occupancy grid (exact decimal).
    #[arg(long, default_value = "0.05")]
    pub resolution: String,
    /// The scans that build the map.
    #[arg(long, value_enum, default_value_t = Half::All)]
    pub scans: Half,
    /// Fill enclosed obstacles below this area (m²): people, chair legs,
    /// noise.
    #[arg(long, value_name = "M2", default_value = "0.05")]
    pub min_hole_area: String,
    /// Drop boundary corners within this many metres (exact
    /// Douglas–Peucker). Default: keep every corner.
    #[arg(long, value_name = "METRES")]
    pub simplify: Option<String>,
    /// Write the map here (JSON map format); default standard output.
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Also write the occupancy grid as a map_server pair PREFIX.pgm and
    /// PREFIX.yaml.
    #[arg(long, value_name = "PREFIX")]
    pub grid_out: Option<PathBuf>,
}

fn number(option: &str, text: &str) -> Result<rug::Rational, Failure> {
    parse_exact(text)
        .map_err(|e| Failure::usage(format!("--{option} {text:?}: not an exact number: {e}")))
}

/// Read a log, naming the file in errors.
pub fn read_log(path: &std::path::Path) -> Result<carmen::CarmenLog, Failure> {
    let bytes = crate::input::read_bytes(path)?;
    carmen::read(&bytes).map_err(|e| Failure::invalid(format!("{}: {e}", path.display())))
}

/// How to build a map from a log's scans.
pub struct Build<'a> {
    pub resolution: rug::Rational,
    pub min_hole_area: rug::Rational,
    pub simplify: Option<rug::Rational>,
    pub half: Half,
    /// Also write the occupancy grid as PREFIX.pgm and PREFIX.yaml.
    pub grid_out: Option<&'a std::path::Path>,
}

impl Build<'_> {
    /// The options of `wai map-from-log` (and `wai eval-log`), read.
    pub fn parse<'a>(
        resolution: &str,
        min_hole_area: &str,
        simplify: Option<&str>,
        half: Half,
        grid_out: Option<&'a std::path::Path>,
    ) -> Result<Build<'a>, Failure> {
        let resolution = number("resolution", resolution)?;
        if resolution <= 0 {
            return Err(Failure::usage("--resolution: must be above 0"));
        }
        let min_hole_area = number("min-hole-area", min_hole_area)?;
        let simplify = simplify.map(|t| number("simplify", t)).transpose()?;
        Ok(Build {
            resolution,
            min_hole_area,
            simplify,
            half,
            grid_out,
        })
    }
}

/// The map built from the scans of `log` (read from `path`) that `build`
/// picks, and a line saying what was done.
pub fn build_map(
    path: &std::path::Path,
    log: &carmen::CarmenLog,
    build: &Build<'_>,
) -> Result<(wai_map::Map, String), Failure> {
    let resolution = &build.resolution;
    let picked: Vec<usize> = (0..log.scans.len())
        .filter(|&k| build.half.picks(k))
        .collect();
    if picked.is_empty() {
        return Err(Failure::invalid(format!(
            "{}: no scan in the {:?} half",
            path.display(),
            build.half
        )));
    }
    let (meta, image) = occupancy_grid(
        log,
        &picked,
        &GridOptions {
            resolution: resolution.clone(),
            margin: 2,
        },
    );
    let cells = image.width as u64 * image.height as u64;
    if cells > 200_000_000 {
        return Err(Failure::invalid(format!(
            "{}: the scans span {} × {} cells at {} m; use a coarser --resolution",
            path.display(),
            image.width,
            image.height,
            format_exact(resolution)
        )));
    }
    if let Some(prefix) = build.grid_out {
        let pgm = prefix.with_extension("pgm");
        let name = pgm
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        if let Some(dir) = pgm.parent().filter(|d| !d.as_os_str().is_empty()) {
            std::fs::create_dir_all(dir)
                .map_err(|e| Failure::io(format!("{}: {e}", dir.display())))?;
        }
        std::fs::write(&pgm, wai_grid::pgm::to_pgm(&image))
            .map_err(|e| Failure::io(format!("{}: {e}", pgm.display())))?;
        write_file(&prefix.with_extension("yaml"), &yaml(&meta, &name))?;
    }
    let options = ImportOptions {
        min_hole_area: build.min_hole_area.clone(),
        simplify: build.simplify.clone(),
        ..ImportOptions::default()
    };
    let (map, report) =
        import_parts(&meta, &image, &options).map_err(|e| Failure::invalid(e.to_string()))?;
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let map = map
        .with_name(format!("{name} ({:?} scans)", build.half).to_lowercase())
        .with_source(format!(
            "{} of {} scans of the laser log {name} through a {} m occupancy grid",
            picked.len(),
            log.scans.len(),
            format_exact(resolution)
        ));
    let g = &report.region;
    let said = format!(
        "{}: {} scans of {} into {} × {} cells of {} m; free component {} cells; {} pinch cell(s) given up; {} speck(s) filled; map: {} vertices (r = {}), {} hole(s){}",
        path.display(),
        picked.len(),
        log.scans.len(),
        image.width,
        image.height,
        format_exact(resolution),
        g.region_cells,
        g.pinch_cells,
        g.specks_filled,
        map.n(),
        map.r(),
        map.hole_count(),
        if report.simplified_away > 0 {
            format!("; {} of {} vertices simplified away", report.simplified_away, report.traced_vertices)
        } else {
            String::new()
        }
    );
    Ok((map, said))
}

pub fn run(args: &Args) -> Result<(), Failure> {
    let build = Build::parse(
        &args.resolution,
        &args.min_hole_area,
        args.simplify.as_deref(),
        args.scans,
        args.grid_out.as_deref(),
    )?;
    let log = read_log(&args.log)?;
    let (map, said) = build_map(&args.log, &log, &build)?;
    eprintln!("{said}");
    output(args.out.as_deref(), &wai_map::json::to_json(&map))
}
