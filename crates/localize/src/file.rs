//! A preprocessed map on disk: versioned JSON, every number an exact
//! decimal string, so that a user preprocesses once (`wai preprocess`) and
//! localizes many times. The file holds the map itself (scaled integer
//! vertices and the scale), each class's skeleton key, and each class's
//! overlay with its slabs, so loading does no geometry beyond validating
//! the map and the structure.
//!
//! # Invariant
//! A file that was edited or damaged is refused, never read as if it were
//! whole: it carries SHA-256 digests of its map (`digest.map`: the scale and
//! the vertices, and where each hole starts) and of its whole content (`digest.content`: every field
//! but the digests, as written), and loading recomputes both; then it
//! checks the structure against the map — every index in range, each
//! class's skeleton embedded at each item's origin onto map vertices, every
//! item's points in the closed map.

use crate::overlay::{CellSite, ClassOverlay, Item, Line, Shape, Slab};
use crate::Localizer;
use rug::{Integer, Rational};
use serde::{Deserialize, Serialize};
use wai_exact::{Containment, Point, RatPoint};
use wai_map::digest::sha256;
use wai_map::Map;
use wai_visibility::{LineLabel, SkeletonKey};

/// The `format` field of every file.
pub const FORMAT: &str = "wai-localizer";
/// The version this build writes and reads (2: with digests).
pub const VERSION: u32 = 2;

/// Why a file could not be read back.
#[derive(Debug, thiserror::Error)]
pub enum FileError {
    #[error("not JSON or not a preprocessed map: {0}")]
    Json(#[from] serde_json::Error),
    #[error("the file's format is {0:?}, not {FORMAT:?}")]
    Format(String),
    #[error(
        "the file has version {0}; this build reads version {VERSION} (preprocess the map again)"
    )]
    Version(u32),
    #[error("{0:?} is not an integer")]
    Number(String),
    #[error("the stored map is invalid: {0}")]
    Map(String),
    #[error("the stored structure is inconsistent: {0}")]
    Structure(String),
    #[error(
        "the {what} digest does not match (stored {stored}, computed {computed}): the file was \
         edited or damaged after `wai preprocess` wrote it; preprocess the map again"
    )]
    Digest {
        what: &'static str,
        stored: String,
        computed: String,
    },
}

#[derive(Serialize, Deserialize)]
struct FileDto {
    format: String,
    version: u32,
    digest: Digests,
    #[serde(flatten)]
    body: Body,
}

#[derive(Serialize, Deserialize)]
struct Digests {
    map: String,
    content: String,
}

/// What the content digest covers: every field but the header.
#[derive(Serialize, Deserialize)]
struct Body {
    name: Option<String>,
    scale: String,
    vertices: Vec<[String; 2]>,
    /// Where each hole's ring starts in `vertices` (absent for a map
    /// without holes, so such files are as before).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    hole_starts: Vec<usize>,
    classes: Vec<ClassDto>,
}

impl Digests {
    /// The digests of `body`, as the writer seals it.
    fn of(body: &Body) -> Digests {
        Digests {
            map: map_digest(&body.scale, &body.vertices, &body.hole_starts),
            content: content_digest(body),
        }
    }
}

/// The map's digest: its scale and vertices, one per line, then where
/// each hole starts (nothing for a map without holes).
fn map_digest(scale: &str, vertices: &[[String; 2]], hole_starts: &[usize]) -> String {
    let mut text = format!("{scale}\n");
    for [x, y] in vertices {
        text.push_str(&format!("{x} {y}\n"));
    }
    for s in hole_starts {
        text.push_str(&format!("hole at {s}\n"));
    }
    sha256(text.as_bytes())
}

/// The content's digest: the body as this build writes it.
fn content_digest(body: &Body) -> String {
    sha256(
        serde_json::to_string(body)
            .expect("plain data serializes")
            .as_bytes(),
    )
}

#[derive(Serialize, Deserialize)]
struct ClassDto {
    offsets: Vec<[String; 2]>,
    labels: Vec<Option<[String; 3]>>,
    /// Items: origin vertex, "f<face>" or "l<lower cell>", and points as
    /// homogeneous [x, y, w].
    items: Vec<ItemDto>,
    xs: Vec<String>,
    lines: Vec<[String; 3]>,
    slabs: Vec<SlabDto>,
}

#[derive(Serialize, Deserialize)]
struct ItemDto {
    origin: usize,
    site: String,
    kind: String,
    points: Vec<[String; 3]>,
}

#[derive(Serialize, Deserialize)]
struct SlabDto {
    pieces: Vec<u32>,
    labels: Vec<Vec<u32>>,
}

fn z(s: &str) -> Result<Integer, FileError> {
    Integer::from_str_radix(s, 10).map_err(|_| FileError::Number(s.to_string()))
}

fn i(s: &str) -> Result<i128, FileError> {
    s.parse().map_err(|_| FileError::Number(s.to_string()))
}

fn q(s: &str) -> Result<Rational, FileError> {
    let (n, d) = s.split_once('/').unwrap_or((s, "1"));
    let d = z(d)?;
    if d <= 0 {
        return Err(FileError::Number(s.to_string()));
    }
    Ok(Rational::from((z(n)?, d)))
}

fn pt(p: &RatPoint) -> [String; 3] {
    [p.hx().to_string(), p.hy().to_string(), p.hw().to_string()]
}

fn unpt(p: &[String; 3]) -> Result<RatPoint, FileError> {
    RatPoint::new(z(&p[0])?, z(&p[1])?, z(&p[2])?)
        .ok_or_else(|| FileError::Structure(format!("point {p:?} has w = 0")))
}

/// Serialize a localizer.
pub fn to_json(loc: &Localizer) -> String {
    let classes = loc
        .keys
        .iter()
        .zip(&loc.overlays)
        .map(|(key, o)| ClassDto {
            offsets: key
                .offsets
                .iter()
                .map(|(x, y)| [x.to_string(), y.to_string()])
                .collect(),
            labels: key
                .labels
                .iter()
                .map(|l| {
                    l.as_ref()
                        .map(|l| [l.a.to_string(), l.b.to_string(), l.c.to_string()])
                })
                .collect(),
            items: o
                .items
                .iter()
                .map(|it| {
                    let site = match it.site {
                        CellSite::Face(f) => format!("f{f}"),
                        CellSite::Lower(l) => format!("l{l}"),
                    };
                    let (kind, points) = match &it.shape {
                        Shape::Polygon(r) => ("polygon", r.iter().map(pt).collect()),
                        Shape::Segment(a, b) => ("segment", vec![pt(a), pt(b)]),
                        Shape::Point(p) => ("point", vec![pt(p)]),
                    };
                    ItemDto {
                        origin: it.origin,
                        site,
                        kind: kind.to_string(),
                        points,
                    }
                })
                .collect(),
            xs: o.xs.iter().map(|x| x.to_string()).collect(),
            lines: o
                .lines
                .iter()
                .map(|l| [l.a.to_string(), l.b.to_string(), l.c.to_string()])
                .collect(),
            slabs: o
                .slabs
                .iter()
                .map(|s| SlabDto {
                    pieces: s.pieces.clone(),
                    labels: s.labels.clone(),
                })
                .collect(),
        })
        .collect();
    let body = Body {
        name: loc.map.name().map(str::to_string),
        scale: loc.map.scale().to_string(),
        vertices: loc
            .map
            .vertices()
            .iter()
            .map(|p| [p.x.to_string(), p.y.to_string()])
            .collect(),
        hole_starts: (1..=loc.map.hole_count())
            .map(|k| loc.map.ring_range(k).start)
            .collect(),
        classes,
    };
    let dto = FileDto {
        format: FORMAT.to_string(),
        version: VERSION,
        digest: Digests::of(&body),
        body,
    };
    serde_json::to_string(&dto).expect("plain data serializes")
}

/// Read a localizer back; the map is validated again and the structure's
/// indices are checked to be in range, so a damaged file is refused
/// rather than answering wrongly or panicking.
pub fn from_json(bytes: &[u8]) -> Result<Localizer, FileError> {
    // Read the header first, for a clear message on another format.
    let head: serde_json::Value = serde_json::from_slice(bytes)?;
    let format = head.get("format").and_then(|f| f.as_str()).unwrap_or("");
    if format != FORMAT {
        return Err(FileError::Format(format.to_string()));
    }
    let version = head.get("version").and_then(|v| v.as_u64()).unwrap_or(0);
    if version != u64::from(VERSION) {
        return Err(FileError::Version(version as u32));
    }
    let FileDto { digest, body, .. } = serde_json::from_value(head)?;
    let check = |what: &'static str, stored: &str, computed: String| {
        if stored == computed {
            Ok(())
        } else {
            Err(FileError::Digest {
                what,
                stored: stored.to_owned(),
                computed,
            })
        }
    };
    let computed = Digests::of(&body);
    check("map", &digest.map, computed.map)?;
    check("content", &digest.content, computed.content)?;
    let dto = body;
    let ring: Vec<Point> = dto
        .vertices
        .iter()
        .map(|[x, y]| Ok(Point::new(i(x)?, i(y)?)))
        .collect::<Result<_, FileError>>()?;
    let scale = z(&dto.scale)?;
    if scale <= 0 {
        return Err(FileError::Number(dto.scale));
    }
    // The rings: the outer one, then each hole from its start.
    let mut bounds = vec![0];
    bounds.extend(dto.hole_starts.iter().copied());
    bounds.push(ring.len());
    if bounds.windows(2).any(|w| w[0] >= w[1]) {
        return Err(FileError::Structure(
            "hole starts are not ascending positions inside the vertices".into(),
        ));
    }
    let mut rings = bounds.windows(2).map(|w| ring[w[0]..w[1]].to_vec());
    let outer = rings.next().expect("at least one ring");
    let (mut map, norm) = Map::from_scaled_rings(outer, rings.collect(), scale)
        .map_err(|e| FileError::Map(e.to_string()))?;
    if map.vertices() != ring.as_slice() || !norm.is_identity() {
        return Err(FileError::Map(
            "the stored vertices are not in normal form".into(),
        ));
    }
    if let Some(name) = dto.name {
        map = map.with_name(name);
    }
    let n = map.n();
    let v = map.vertices();
    let vertex_set: rustc_hash::FxHashSet<Point> = v.iter().copied().collect();
    let is_vertex = |p: Point| vertex_set.contains(&p);
    let mut keys = Vec::with_capacity(dto.classes.len());
    let mut overlays = Vec::with_capacity(dto.classes.len());
    for (k, c) in dto.classes.into_iter().enumerate() {
        let bad = |what: &str| FileError::Structure(format!("class {k}: {what}"));
        let offsets = c
            .offsets
            .iter()
            .map(|[x, y]| Ok((i(x)?, i(y)?)))
            .collect::<Result<Vec<_>, FileError>>()?;
        let labels = c
            .labels
            .iter()
            .map(|l| match l {
                None => Ok(None),
                Some([a, b, c]) => Ok(Some(LineLabel {
                    a: z(a)?,
                    b: z(b)?,
                    c: z(c)?,
                })),
            })
            .collect::<Result<Vec<_>, FileError>>()?;
        if offsets.len() != labels.len() {
            return Err(bad("offsets and labels differ in length"));
        }
        let mut items = Vec::with_capacity(c.items.len());
        for it in &c.items {
            if it.origin >= n {
                return Err(bad("an item's origin is not a map vertex"));
            }
            // The class's skeleton embedded at the item's origin: every
            // skeleton vertex lands on a map vertex.
            let o = v[it.origin];
            let lands = |dx: i128, dy: i128| match (o.x.checked_add(dx), o.y.checked_add(dy)) {
                (Some(x), Some(y)) => is_vertex(Point::new(x, y)),
                _ => false,
            };
            if let Some((dx, dy)) = offsets.iter().find(|&&(dx, dy)| !lands(dx, dy)) {
                return Err(bad(&format!(
                    "its skeleton at origin {} puts the vertex at offset ({dx}, {dy}) on no \
                     map vertex",
                    it.origin
                )));
            }
            let idx: usize = it.site[1..].parse().map_err(|_| bad("bad site"))?;
            let site = match &it.site[..1] {
                "f" => CellSite::Face(idx),
                "l" => CellSite::Lower(idx),
                _ => return Err(bad("bad site")),
            };
            let pts = it.points.iter().map(unpt).collect::<Result<Vec<_>, _>>()?;
            // Shapes are stored translated by minus their origin vertex:
            // moved back, every point lies in the closed map.
            if let Some(p) = pts
                .iter()
                .find(|p| map.locate(&crate::shifted(p, o, 1)) == Containment::Outside)
            {
                return Err(bad(&format!(
                    "an item's point {p}, at origin {}, lies outside the map",
                    it.origin
                )));
            }
            let shape = match (it.kind.as_str(), pts.len()) {
                ("polygon", m) if m >= 3 => Shape::Polygon(pts),
                ("segment", 2) => {
                    let mut p = pts.into_iter();
                    Shape::Segment(p.next().expect("2"), p.next().expect("2"))
                }
                ("point", 1) => Shape::Point(pts.into_iter().next().expect("1")),
                _ => return Err(bad("bad item shape")),
            };
            items.push(Item {
                origin: it.origin,
                site,
                shape,
            });
        }
        let xs = c.xs.iter().map(|x| q(x)).collect::<Result<Vec<_>, _>>()?;
        if xs.windows(2).any(|w| w[0] >= w[1]) {
            return Err(bad("slab boundaries not ascending"));
        }
        let lines = c
            .lines
            .iter()
            .map(|[a, b, cc]| {
                Ok(Line {
                    a: z(a)?,
                    b: z(b)?,
                    c: z(cc)?,
                })
            })
            .collect::<Result<Vec<_>, FileError>>()?;
        if c.slabs.len() != xs.len().saturating_sub(1) {
            return Err(bad("slab count"));
        }
        let mut slabs = Vec::with_capacity(c.slabs.len());
        for s in c.slabs {
            let ok = s.labels.len() == s.pieces.len() + 1
                && s.pieces.iter().all(|&l| (l as usize) < lines.len())
                && s.labels
                    .iter()
                    .flatten()
                    .all(|&t| (t as usize) < items.len());
            if !ok {
                return Err(bad("a slab's pieces or labels are out of range"));
            }
            slabs.push(Slab {
                pieces: s.pieces,
                labels: s.labels,
            });
        }
        keys.push(SkeletonKey { offsets, labels });
        overlays.push(ClassOverlay::from_parts(items, xs, lines, slabs));
    }
    Ok(Localizer::assemble(map, keys, overlays))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `text` edited by `edit`, with both digests recomputed, as a tool that
    /// rewrites the file would: the structural checks must refuse it.
    fn resealed(text: &str, edit: impl FnOnce(&mut Body)) -> String {
        let mut dto: FileDto = serde_json::from_str(text).unwrap();
        edit(&mut dto.body);
        dto.digest = Digests::of(&dto.body);
        serde_json::to_string(&dto).unwrap()
    }

    fn refused(text: &str) -> String {
        from_json(text.as_bytes()).unwrap_err().to_string()
    }

    #[test]
    fn resealed_edits_fail_the_structural_checks() {
        let loc = Localizer::new(&wai_gen::family("corridor-niches", &[2]).unwrap());
        let text = to_json(&loc);
        // Resealing the untouched file gives it back: the digests are
        // recomputed as the writer computes them.
        assert_eq!(resealed(&text, |_| {}), text);

        let e = refused(&resealed(&text, |b| {
            let c = b
                .classes
                .iter_mut()
                .find(|c| !c.offsets.is_empty())
                .unwrap();
            let last = c.offsets.len() - 1;
            c.offsets[last][0] = "100000".into();
        }));
        assert!(e.contains("on no map vertex"), "{e}");

        let e = refused(&resealed(&text, |b| {
            let c = b.classes.iter_mut().find(|c| !c.items.is_empty()).unwrap();
            c.items[0].points[0] = ["-100000".into(), "0".into(), "1".into()];
        }));
        assert!(e.contains("lies outside the map"), "{e}");

        let e = refused(&resealed(&text, |b| {
            let c = b.classes.iter_mut().find(|c| !c.slabs.is_empty()).unwrap();
            c.slabs[0].labels[0] = vec![999_999];
        }));
        assert!(e.contains("out of range"), "{e}");

        let e = refused(&resealed(&text, |b| {
            b.vertices[1] = ["-5".into(), "7".into()];
            b.vertices[2] = ["5".into(), "-7".into()];
        }));
        assert!(e.contains("map"), "{e}");
    }
}
