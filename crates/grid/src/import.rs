//! The whole import: files, cells, region, rings, map.

use crate::error::GridError;
use crate::meta::{self, GridMeta};
use crate::pgm::{self, Image};
use crate::trace::{self, Choice, RegionReport};
use crate::{occupancy, simplify};
use rug::{Integer, Rational};
use std::path::Path;
use wai_exact::Point;
use wai_map::{format_exact, Map};

/// Bytes per cell while importing (pixels, masks, labels, boundary): what
/// [`ImportOptions::max_cells`] is weighed with.
pub const BYTES_PER_CELL: u64 = 12;

/// What [`import`] is asked to do beyond the file's own settings.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ImportOptions {
    /// A point of the free space wanted, in metres in the grid's frame: its
    /// 4-connected free component is traced. Without it, the largest.
    pub at: Option<(Rational, Rational)>,
    /// Enclosed obstacles of less than this area (m²) are specks: filled.
    pub min_hole_area: Rational,
    /// Douglas–Peucker tolerance in metres; none keeps every corner.
    pub simplify: Option<Rational>,
    /// Refuse grids of more cells than this.
    pub max_cells: u64,
}

impl Default for ImportOptions {
    fn default() -> Self {
        ImportOptions {
            at: None,
            min_hole_area: Rational::new(),
            simplify: None,
            max_cells: 200_000_000,
        }
    }
}

/// What an import found and changed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Report {
    pub width: usize,
    pub height: usize,
    pub region: RegionReport,
    /// Vertices of the traced boundary (every corner where it turns).
    pub traced_vertices: usize,
    /// Vertices dropped by the simplification (0 without it).
    pub simplified_away: usize,
}

/// A map imported from an occupancy grid.
#[derive(Clone, Debug)]
pub struct Imported {
    pub map: Map,
    pub meta: GridMeta,
    pub report: Report,
}

/// Read the `map_server` pair named by the YAML file `yaml` and trace its
/// free space into a map.
pub fn import(yaml: &Path, options: &ImportOptions) -> Result<Imported, GridError> {
    let io = |path: &Path, error| GridError::Io {
        path: path.to_path_buf(),
        error,
    };
    let size = std::fs::metadata(yaml).map_err(|e| io(yaml, e))?.len();
    if size > 1 << 20 {
        return Err(GridError::Yaml {
            path: yaml.to_path_buf(),
            line: 0,
            message: format!("{size} bytes: not the YAML file of a map (expected a few lines)"),
        });
    }
    let text = std::fs::read(yaml).map_err(|e| io(yaml, e))?;
    let text = String::from_utf8(text).map_err(|e| GridError::Yaml {
        path: yaml.to_path_buf(),
        line: 0,
        message: format!("not UTF-8 text: {e}"),
    })?;
    let meta = meta::parse(yaml, &text)?;
    let image_path = meta.image_path(yaml);
    let image_err = |message: String| GridError::Image {
        path: image_path.clone(),
        message,
    };
    // Refuse before reading a file too large to hold as cells.
    let bytes_cap = options.max_cells.saturating_mul(2).saturating_add(1 << 16);
    let image_size = std::fs::metadata(&image_path)
        .map_err(|e| io(&image_path, e))?
        .len();
    let head_len = image_size.min(4096) as usize;
    let head = read_prefix(&image_path, head_len).map_err(|e| io(&image_path, e))?;
    let header = pgm::header(&head).map_err(image_err)?;
    let cells = header.width as u64 * header.height as u64;
    if cells > options.max_cells || image_size > bytes_cap.saturating_mul(4) {
        return Err(GridError::TooLarge {
            path: image_path.clone(),
            width: header.width as u64,
            height: header.height as u64,
            cells,
            max: options.max_cells,
            bytes_per_cell: BYTES_PER_CELL,
        });
    }
    let bytes = std::fs::read(&image_path).map_err(|e| io(&image_path, e))?;
    let image = pgm::pixels(&bytes, &header).map_err(image_err)?;
    drop(bytes);
    let name = yaml
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    let (map, report) = import_parts(&meta, &image, options)?;
    let source = format!(
        "occupancy grid {} ({} × {} cells of {} m, origin ({}, {}))",
        meta.image,
        image.width,
        image.height,
        format_exact(&meta.resolution),
        format_exact(&meta.origin[0]),
        format_exact(&meta.origin[1]),
    );
    Ok(Imported {
        map: map.with_name(name).with_source(source),
        meta,
        report,
    })
}

fn read_prefix(path: &Path, len: usize) -> std::io::Result<Vec<u8>> {
    use std::io::Read;
    let mut buf = vec![0; len];
    let mut f = std::fs::File::open(path)?;
    f.read_exact(&mut buf)?;
    Ok(buf)
}

/// [`import`] of metadata and an image already read.
pub fn import_parts(
    meta: &GridMeta,
    image: &Image,
    options: &ImportOptions,
) -> Result<(Map, Report), GridError> {
    let (w, h) = (image.width, image.height);
    let free = occupancy::free_cells(meta, image);
    let res = &meta.resolution;
    let choice = match &options.at {
        None => Choice::Largest,
        Some((x, y)) => {
            let shown = || (format_exact(x), format_exact(y));
            let cell =
                |v: &Rational, o: &Rational| (Rational::from(v - o) / res).floor().numer().to_i64();
            let (c, r) = (cell(x, &meta.origin[0]), cell(y, &meta.origin[1]));
            match (c, r) {
                (Some(c), Some(r)) if (0..w as i64).contains(&c) && (0..h as i64).contains(&r) => {
                    if !free[r as usize * w + c as usize] {
                        let (x, y) = shown();
                        return Err(GridError::StartNotFree {
                            x,
                            y,
                            reason: format!(
                                "lies in cell (column {c}, row {} from the top), which is not free (occupied or unknown)",
                                h as i64 - 1 - r
                            ),
                        });
                    }
                    Choice::Containing(c as usize, r as usize)
                }
                _ => {
                    let (x, y) = shown();
                    return Err(GridError::StartNotFree {
                        x,
                        y,
                        reason: "lies outside the grid".into(),
                    });
                }
            }
        }
    };
    let cell_area = Rational::from(res * res);
    let min_hole_cells = Rational::from(&options.min_hole_area / &cell_area)
        .ceil()
        .numer()
        .to_u64()
        .unwrap_or(u64::MAX);
    let (mask, region) =
        trace::region(&free, w, h, choice, min_hole_cells).ok_or(GridError::NoFreeCell)?;
    drop(free);
    let mut rings = trace::rings(&mask, w, h);
    drop(mask);
    let traced_vertices = rings.iter().map(Vec::len).sum();
    if let Some(t) = &options.simplify {
        let t_cells = Rational::from(t / res);
        let t2 = Rational::from(&t_cells * &t_cells);
        rings = simplify::rings(&rings, &t2);
    }
    let kept: usize = rings.iter().map(Vec::len).sum();
    // Grid corner (c, r) is at origin + res · (c, r): integers over the
    // least common denominator of the origin and the resolution.
    let mut den = Integer::from(res.denom());
    den.lcm_mut(meta.origin[0].denom());
    den.lcm_mut(meta.origin[1].denom());
    // v · den is an integer: den is a multiple of v's denominator.
    let int = |v: &Rational| Rational::from(v * &den).numer().to_i128();
    let too_large = || {
        GridError::Map(wai_map::MapErrors::one(
            wai_map::MapError::CoordinateTooLarge {
                path: "origin and resolution".into(),
                bits: u64::from(den.significant_bits()),
                max: wai_exact::MAX_COORD_BITS,
            },
        ))
    };
    let (x0, y0, step) = match (int(&meta.origin[0]), int(&meta.origin[1]), int(res)) {
        (Some(a), Some(b), Some(c)) => (a, b, c),
        _ => return Err(too_large()),
    };
    let to_points = |ring: &[(i64, i64)]| -> Vec<Point> {
        ring.iter()
            .map(|&(c, r)| Point::new(x0 + step * i128::from(c), y0 + step * i128::from(r)))
            .collect()
    };
    // The one counter-clockwise ring bounds the region; the others are its
    // holes.
    let outer_at = rings
        .iter()
        .position(|r| trace::area_twice(r) > 0)
        .expect("a non-empty region has an outer ring");
    let outer = to_points(&rings[outer_at]);
    let holes: Vec<Vec<Point>> = rings
        .iter()
        .enumerate()
        .filter(|&(k, _)| k != outer_at)
        .map(|(_, r)| to_points(r))
        .collect();
    let (map, _) = Map::from_scaled_rings(outer, holes, den).map_err(GridError::Map)?;
    let map = map.with_units(wai_map::Units::Metres);
    Ok((
        map,
        Report {
            width: w,
            height: h,
            region,
            traced_vertices,
            simplified_away: traced_vertices - kept,
        },
    ))
}
