//! SVG pictures (output only).
//!
//! The principal type is [`Canvas`]: it maps the exact integer coordinates
//! of a map onto an SVG view box (y up, as in the thesis's figures),
//! collects layers, and finishes the picture with a legend of every kind
//! of mark it drew (in a band to the right of the drawing, so never
//! clipped), a scale bar in the map's units and a wrapped caption below.
//! A map in longitude/latitude ([`MapUnits::LonLat`]) is drawn in a local
//! equirectangular projection (x scaled by the cosine of its mean
//! latitude) with the scale bar in metres.
//!
//! [`map_svg`], [`visibility_svg`], [`cells_svg`] and [`embeddings_svg`]
//! draw the workspace's pictures; [`class_colours`] gives the cells of
//! adjacent classes different colours however many classes there are.
//!
//! # Invariant
//! Floating point appears only here, in the pixel coordinates written to
//! the SVG text; nothing read back from a picture decides anything. The
//! same input gives the same bytes.
#![allow(
    clippy::float_arithmetic,
    reason = "pixel coordinates of pictures are output only"
)]

use rug::Integer;
use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write;
use wai_exact::{Point, RatPoint};
use wai_map::Map;

/// The mean Earth radius (IUGG), metres, as `wai_scan::units` uses it.
const EARTH_RADIUS: f64 = 6_371_008.8;

/// Metres per degree of latitude (and of longitude at the equator).
fn metres_per_degree() -> f64 {
    EARTH_RADIUS * std::f64::consts::PI / 180.0
}

/// What a map's input coordinates measure, for the scale bar and the
/// projection. [`MapUnits::guess`] takes the units a map states, else
/// applies the rule of the scan commands' `--units auto`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MapUnits {
    /// Unknown: the scale bar says "map units".
    Plain,
    /// Metres.
    Metres,
    /// Longitude, latitude in degrees (WGS 84): drawn in a local
    /// equirectangular projection, the scale bar in metres.
    LonLat,
}

impl MapUnits {
    /// The units the map's file states, else [`MapUnits::LonLat`] if it
    /// looks like longitude/latitude ([`Map::looks_lonlat`]: within ±180
    /// and ±90, spanning less than 0.1 in both), else [`MapUnits::Plain`].
    pub fn guess(map: &Map) -> MapUnits {
        match map.units() {
            Some(wai_map::Units::Metres) => MapUnits::Metres,
            Some(wai_map::Units::LonLat) => MapUnits::LonLat,
            Some(wai_map::Units::Scale(_)) => MapUnits::Plain,
            None if map.looks_lonlat() => MapUnits::LonLat,
            None => MapUnits::Plain,
        }
    }
}

/// One kind of mark, as its legend entry shows it.
#[derive(Clone, Debug, PartialEq)]
pub enum Mark {
    /// A filled area: a swatch with this fill, fill opacity and outline.
    Area {
        fill: String,
        opacity: f64,
        stroke: String,
    },
    /// A line of this colour, width and SVG dash array ("" for solid).
    Line {
        stroke: String,
        width: f64,
        dash: String,
    },
    /// A dot of this fill and radius, outlined in `stroke` ("none" for no
    /// outline).
    Dot {
        fill: String,
        r: f64,
        stroke: String,
    },
    /// Several filled swatches side by side (areas coloured per class).
    Swatches(Vec<String>),
    /// A text label, shown by an example.
    Text(String),
}

impl Mark {
    /// A filled area.
    pub fn area(fill: &str, opacity: f64, stroke: &str) -> Mark {
        Mark::Area {
            fill: fill.to_string(),
            opacity,
            stroke: stroke.to_string(),
        }
    }

    /// A line.
    pub fn line(stroke: &str, width: f64, dash: &str) -> Mark {
        Mark::Line {
            stroke: stroke.to_string(),
            width,
            dash: dash.to_string(),
        }
    }

    /// A dot without outline.
    pub fn dot(fill: &str, r: f64) -> Mark {
        Mark::Dot {
            fill: fill.to_string(),
            r,
            stroke: "none".to_string(),
        }
    }

    /// The SVG of this mark's sample in a 28 × 14 box at (`x`, `y`) (top
    /// left).
    fn sample(&self, x: f64, y: f64) -> String {
        match self {
            Mark::Area {
                fill,
                opacity,
                stroke,
            } => format!(
                r#"<rect x="{x:.1}" y="{:.1}" width="28" height="12" fill="{fill}" fill-opacity="{opacity}" stroke="{stroke}" stroke-width="1"/>"#,
                y + 1.0
            ),
            Mark::Line {
                stroke,
                width,
                dash,
            } => format!(
                r#"<line x1="{x:.1}" y1="{yy:.1}" x2="{:.1}" y2="{yy:.1}" stroke="{stroke}" stroke-width="{width}" stroke-dasharray="{dash}"/>"#,
                x + 28.0,
                yy = y + 7.0
            ),
            Mark::Dot { fill, r, stroke } => format!(
                r#"<circle cx="{:.1}" cy="{:.1}" r="{r:.1}" fill="{fill}" stroke="{stroke}" stroke-width="1.5"/>"#,
                x + 14.0,
                y + 7.0
            ),
            Mark::Swatches(fills) => {
                let k = fills.len().max(1) as f64;
                let w = 28.0 / k;
                fills
                    .iter()
                    .enumerate()
                    .map(|(i, f)| {
                        format!(
                            r##"<rect x="{:.2}" y="{:.1}" width="{w:.2}" height="12" fill="{f}" stroke="#555" stroke-width="0.3"/>"##,
                            x + w * i as f64,
                            y + 1.0
                        )
                    })
                    .collect()
            }
            Mark::Text(example) => format!(
                r##"<text x="{:.1}" y="{:.1}" font-size="10" fill="#333">{}</text>"##,
                x + 4.0,
                y + 11.0,
                escape(example)
            ),
        }
    }
}

/// Average width of a character of the 12 px sans-serif text, pixels (a
/// generous estimate, so that text estimated to fit does fit).
const CHAR_PX: f64 = 6.8;

/// `text` broken at spaces into lines of at most `width` characters (a
/// longer word stays whole).
pub fn wrap(text: &str, width: usize) -> Vec<String> {
    let mut lines = Vec::new();
    let mut line = String::new();
    for word in text.split(' ') {
        if !line.is_empty() && line.chars().count() + 1 + word.chars().count() > width {
            lines.push(std::mem::take(&mut line));
        }
        if !line.is_empty() {
            line.push(' ');
        }
        line.push_str(word);
    }
    if !line.is_empty() || lines.is_empty() {
        lines.push(line);
    }
    lines
}

/// The texts of a picture's legend entries, as this crate draws them
/// (`<g class="legend-entry">`), each entry's lines joined by spaces: for
/// tests and tools that read a picture back.
pub fn legend_texts(svg: &str) -> Vec<String> {
    svg.split(r#"<g class="legend-entry">"#)
        .skip(1)
        .map(|entry| {
            let entry = &entry[..entry.find("</g>").unwrap_or(entry.len())];
            entry
                .split("<text")
                .skip(1)
                .filter_map(|t| {
                    let t = &t[t.find('>')? + 1..];
                    Some(t[..t.find("</text>")?].to_string())
                })
                .collect::<Vec<_>>()
                .join(" ")
        })
        .collect()
}

/// The largest 1, 2 or 5 × 10^k not above `x` (> 0).
pub fn nice_floor(x: f64) -> f64 {
    let p = 10f64.powf(x.log10().floor());
    [5.0, 2.0, 1.0]
        .into_iter()
        .map(|m| m * p)
        .find(|v| *v <= x * (1.0 + 1e-9))
        .unwrap_or(p)
}

/// `v`, a 1, 2 or 5 × 10^k, written without float noise.
pub fn nice_text(v: f64) -> String {
    let decimals = (-v.log10().floor()).max(0.0) as usize;
    format!("{v:.decimals$}")
}

/// Characters per legend line before it wraps.
const LEGEND_CHARS: usize = 34;

/// An SVG drawing in the coordinate frame of one map.
#[derive(Debug)]
pub struct Canvas {
    min: (f64, f64),
    /// Pixels per integer unit along y.
    unit: f64,
    /// The projection's stretch of x (cos of the mean latitude for a
    /// lon/lat map, else 1).
    kx: f64,
    width: f64,
    height: f64,
    margin: f64,
    body: String,
    legend: Vec<(Mark, String)>,
    /// Pixels per unit of the scale bar, the unit's name, and a note on
    /// the projection.
    bar: Option<(f64, String, String)>,
}

/// Convert an integer coordinate to `f64` for drawing.
fn approx(c: i128) -> f64 {
    // i128 -> f64 rounds to nearest; pictures need no more.
    c as f64
}

impl Canvas {
    /// A canvas showing the box `lo`–`hi` (integer map units) scaled to
    /// `size` pixels along its longer side, without projection or scale
    /// bar.
    pub fn new(lo: Point, hi: Point, size: f64) -> Canvas {
        Canvas::projected(lo, hi, size, 1.0)
    }

    fn projected(lo: Point, hi: Point, size: f64, kx: f64) -> Canvas {
        let w = approx(hi.x - lo.x).max(1.0) * kx;
        let h = approx(hi.y - lo.y).max(1.0);
        let unit = size / w.max(h);
        Canvas {
            min: (approx(lo.x), approx(lo.y)),
            unit,
            kx,
            width: w * unit,
            height: h * unit,
            margin: 0.05 * size,
            body: String::new(),
            legend: Vec::new(),
            bar: None,
        }
    }

    /// A canvas fitted to `map`, its units guessed ([`MapUnits::guess`]).
    pub fn for_map(map: &Map, size: f64) -> Canvas {
        Canvas::for_map_in(map, size, MapUnits::guess(map))
    }

    /// A canvas fitted to `map` in `units`: projected if lon/lat, with a
    /// scale bar.
    pub fn for_map_in(map: &Map, size: f64, units: MapUnits) -> Canvas {
        let (lo, hi) = map.bounding_box();
        let scale = map.scale().to_f64();
        let kx = match units {
            MapUnits::LonLat => (approx(lo.y + hi.y) / 2.0 / scale).to_radians().cos(),
            _ => 1.0,
        };
        let mut c = Canvas::projected(lo, hi, size, kx);
        // Pixels per input unit along y (and, projected, along x).
        let per_input = c.unit * scale;
        c.bar = Some(match units {
            MapUnits::Plain => (per_input, "map units".to_string(), String::new()),
            MapUnits::Metres => (per_input, "m".to_string(), String::new()),
            MapUnits::LonLat => {
                let mean = approx(lo.y + hi.y) / 2.0 / scale;
                (
                    per_input / metres_per_degree(),
                    "m".to_string(),
                    format!(
                        "lon/lat drawn in a local equirectangular projection: x × cos {:.2}°",
                        mean
                    ),
                )
            }
        });
        c
    }

    /// Adds a legend entry: `label` for marks drawn like `mark`.
    pub fn legend(&mut self, mark: Mark, label: &str) {
        self.legend.push((mark, label.to_string()));
    }

    fn px(&self, p: Point) -> (f64, f64) {
        self.px_approx(approx(p.x), approx(p.y))
    }

    fn px_approx(&self, x: f64, y: f64) -> (f64, f64) {
        let sx = (x - self.min.0) * self.unit * self.kx + self.margin;
        let sy = self.height - (y - self.min.1) * self.unit + self.margin;
        (sx, sy)
    }

    fn px_rat(&self, p: &RatPoint) -> (f64, f64) {
        let w = p.hw().to_f64();
        self.px_approx(p.hx().to_f64() / w, p.hy().to_f64() / w)
    }

    /// The pixel text of a ring's vertices, as the polygons write them.
    fn ring_text(&self, ring: &[RatPoint]) -> Vec<String> {
        ring.iter()
            .map(|p| {
                let (x, y) = self.px_rat(p);
                format!("{x:.2},{y:.2}")
            })
            .collect()
    }

    /// A closed polygon with exact rational vertices, filled at opacity
    /// 0.55.
    pub fn polygon_rat(&mut self, ring: &[RatPoint], fill: &str, stroke: &str, stroke_width: f64) {
        self.polygon_rat_titled(ring, fill, 0.55, stroke, stroke_width, "");
    }

    /// A closed polygon with exact rational vertices, fill opacity
    /// `opacity`, and a tooltip `title` (none if empty).
    pub fn polygon_rat_titled(
        &mut self,
        ring: &[RatPoint],
        fill: &str,
        opacity: f64,
        stroke: &str,
        stroke_width: f64,
        title: &str,
    ) {
        let pts = self.ring_text(ring).join(" ");
        let _ = write!(
            self.body,
            r#"<polygon points="{pts}" fill="{fill}" fill-opacity="{opacity}" stroke="{stroke}" stroke-width="{stroke_width}""#,
        );
        if title.is_empty() {
            self.body.push_str("/>\n");
        } else {
            let _ = writeln!(self.body, "><title>{}</title></polygon>", escape(title));
        }
    }

    /// A segment between exact points; `dash` is an SVG dash array or "".
    pub fn segment_rat(
        &mut self,
        a: &RatPoint,
        b: &RatPoint,
        stroke: &str,
        width: f64,
        dash: &str,
        title: &str,
    ) {
        let ((x1, y1), (x2, y2)) = (self.px_rat(a), self.px_rat(b));
        let _ = writeln!(
            self.body,
            r#"<line x1="{x1:.2}" y1="{y1:.2}" x2="{x2:.2}" y2="{y2:.2}" stroke="{stroke}" stroke-width="{width}" stroke-dasharray="{dash}"><title>{}</title></line>"#,
            escape(title)
        );
    }

    /// A dot at an exact point.
    pub fn dot_rat(&mut self, p: &RatPoint, r: f64, fill: &str, title: &str) {
        let (x, y) = self.px_rat(p);
        let _ = writeln!(
            self.body,
            r#"<circle cx="{x:.2}" cy="{y:.2}" r="{r}" fill="{fill}"><title>{}</title></circle>"#,
            escape(title)
        );
    }

    /// A closed polygon.
    pub fn polygon(&mut self, ring: &[Point], fill: &str, stroke: &str, stroke_width: f64) {
        let pts: Vec<String> = ring
            .iter()
            .map(|&p| {
                let (x, y) = self.px(p);
                format!("{x:.2},{y:.2}")
            })
            .collect();
        let _ = writeln!(
            self.body,
            r#"<polygon points="{}" fill="{fill}" stroke="{stroke}" stroke-width="{stroke_width}" stroke-linejoin="round"/>"#,
            pts.join(" ")
        );
    }

    /// A dot of radius `r` pixels.
    pub fn dot(&mut self, p: Point, r: f64, fill: &str, title: &str) {
        let (x, y) = self.px(p);
        let _ = writeln!(
            self.body,
            r#"<circle cx="{x:.2}" cy="{y:.2}" r="{r}" fill="{fill}"><title>{}</title></circle>"#,
            escape(title)
        );
    }

    /// A text label at `p`, offset by a few pixels.
    pub fn label(&mut self, p: Point, text: &str, size: f64) {
        let (x, y) = self.px(p);
        let _ = writeln!(
            self.body,
            r##"<text x="{:.2}" y="{:.2}" font-size="{size}" font-family="sans-serif" fill="#333">{}</text>"##,
            x + 3.0,
            y - 3.0,
            escape(text)
        );
    }

    /// The scale bar's SVG at (`x`, `y`) (its left end, the bar's line)
    /// and its height, or nothing without a scale.
    fn scale_bar(&self, x: f64, y: f64) -> Option<String> {
        let (per, name, note) = self.bar.as_ref()?;
        // About a fifth of the drawing, rounded down to 1, 2 or 5 × 10^k.
        let length = nice_floor(0.2 * self.width / per);
        let px = length * per;
        let text = format!("{} {name}", nice_text(length));
        let mut s = format!(
            r##"<g class="scale-bar"><title>scale bar: {text}</title><rect x="{x:.1}" y="{:.1}" width="{:.2}" height="5" fill="#222"/><rect x="{:.2}" y="{:.1}" width="{:.2}" height="5" fill="white" stroke="#222" stroke-width="1"/><text x="{:.1}" y="{:.1}" font-size="12" font-family="sans-serif" fill="#222">{text}</text>"##,
            y - 5.0,
            px / 2.0,
            x + px / 2.0,
            y - 5.0,
            px / 2.0,
            x + px + 8.0,
            y + 1.0,
        );
        if !note.is_empty() {
            let _ = write!(
                s,
                r##"<text x="{x:.1}" y="{:.1}" font-size="11" font-family="sans-serif" fill="#555">{}</text>"##,
                y + 16.0,
                escape(note)
            );
        }
        s.push_str("</g>\n");
        Some(s)
    }

    /// The finished SVG document, with `title`, the legend to the right
    /// of the drawing, the scale bar and the caption (wrapped) below.
    pub fn finish(self, title: &str, caption: &str) -> String {
        let (dw, dh) = (
            self.width + 2.0 * self.margin,
            self.height + 2.0 * self.margin,
        );
        // The legend: one row of 14 px per line, 6 px between entries.
        let entries: Vec<(&Mark, Vec<String>)> = self
            .legend
            .iter()
            .map(|(m, l)| (m, wrap(l, LEGEND_CHARS)))
            .collect();
        let widest = entries
            .iter()
            .flat_map(|(_, ls)| ls.iter().map(|l| l.chars().count()))
            .max()
            .unwrap_or(0);
        let lw = if entries.is_empty() {
            0.0
        } else {
            (widest.max(6) as f64) * CHAR_PX + 60.0
        };
        let lh = 24.0
            + entries
                .iter()
                .map(|(_, ls)| 14.0 * ls.len() as f64 + 6.0)
                .sum::<f64>();
        let w = (dw + lw).max(320.0);
        let top = dh.max(lh + 10.0);
        let bar = self.scale_bar(self.margin, top + 14.0);
        let bar_h = match &self.bar {
            None => 0.0,
            Some((.., note)) if note.is_empty() => 24.0,
            Some(_) => 38.0,
        };
        let lines = wrap(caption, ((w - 8.0) / CHAR_PX) as usize);
        let h = top + bar_h + 15.0 * lines.len() as f64 + 6.0;
        let mut out = format!(
            concat!(
                r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w:.0}" height="{h:.0}" viewBox="0 0 {w:.2} {h:.2}">"#,
                "\n<title>{title}</title>\n",
                r#"<rect width="100%" height="100%" fill="white"/>"#,
                "\n{body}",
            ),
            w = w,
            h = h,
            title = escape(title),
            body = self.body,
        );
        if !entries.is_empty() {
            let x = dw + 8.0;
            let _ = write!(
                out,
                r##"<g class="legend" font-family="sans-serif" font-size="12" fill="#222"><rect x="{x:.1}" y="{:.1}" width="{:.1}" height="{lh:.1}" fill="white" stroke="#bbb"/><text x="{:.1}" y="{:.1}" font-weight="bold">Legend</text>"##,
                self.margin,
                lw - 12.0,
                x + 8.0,
                self.margin + 16.0,
            );
            let mut y = self.margin + 24.0;
            for (mark, ls) in &entries {
                out.push_str(r#"<g class="legend-entry">"#);
                out.push_str(&mark.sample(x + 8.0, y));
                for (i, l) in ls.iter().enumerate() {
                    let _ = write!(
                        out,
                        r#"<text x="{:.1}" y="{:.1}">{}</text>"#,
                        x + 44.0,
                        y + 11.0 + 14.0 * i as f64,
                        escape(l)
                    );
                }
                out.push_str("</g>\n");
                y += 14.0 * ls.len() as f64 + 6.0;
            }
            out.push_str("</g>\n");
        }
        if let Some(b) = bar {
            out.push_str(&b);
        }
        for (i, l) in lines.iter().enumerate() {
            let _ = writeln!(
                out,
                r##"<text x="4" y="{:.2}" font-size="12" font-family="sans-serif" fill="#555">{}</text>"##,
                top + bar_h + 12.0 + 15.0 * i as f64,
                escape(l)
            );
        }
        out.push_str("</svg>\n");
        out
    }
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// What [`map_svg`] and the other map pictures draw.
#[derive(Clone, Debug)]
pub struct MapStyle {
    /// Pixels along the longer side of the map.
    pub size: f64,
    /// Number every vertex.
    pub vertex_labels: bool,
    /// The map's units; `None` guesses ([`MapUnits::guess`]).
    pub units: Option<MapUnits>,
}

impl Default for MapStyle {
    fn default() -> Self {
        MapStyle {
            size: 800.0,
            vertex_labels: false,
            units: None,
        }
    }
}

impl MapStyle {
    fn canvas(&self, map: &Map) -> Canvas {
        Canvas::for_map_in(
            map,
            self.size,
            self.units.unwrap_or_else(|| MapUnits::guess(map)),
        )
    }
}

/// The map's walls as every map picture's legend shows them.
const WALL: &str = "#1f3b73";

fn wall_legend(c: &mut Canvas, inside: &str) {
    c.legend(Mark::area(inside, 1.0, WALL), "map (walls and inside)");
}

/// The map's walls: the outer ring filled with `fill` (`"none"` for an
/// outline), each hole (pillar) over it in grey.
fn map_shape(c: &mut Canvas, map: &Map, fill: &str) {
    c.polygon(map.outer(), fill, WALL, 1.5);
    let hole_fill = if fill == "none" { "none" } else { "#d0d0d0" };
    for hole in map.holes() {
        c.polygon(hole, hole_fill, WALL, 1.5);
    }
}

/// Draw `map`: its polygon, its vertices, its reflex vertices marked in red,
/// a legend, a scale bar, and a caption with n, r and the scale.
pub fn map_svg(map: &Map, style: &MapStyle) -> String {
    let mut c = style.canvas(map);
    map_shape(&mut c, map, "#eef3fb");
    let dot = (style.size / 250.0).clamp(1.5, 4.0);
    for (i, &p) in map.vertices().iter().enumerate() {
        let (fill, kind) = if map.is_reflex(i) {
            ("#d62728", "reflex")
        } else {
            (WALL, "convex")
        };
        let r = if map.is_reflex(i) { dot * 1.6 } else { dot };
        c.dot(
            p,
            r,
            fill,
            &format!("vertex {i} {} ({kind})", coordinate_text(p, map.scale())),
        );
        if style.vertex_labels {
            c.label(p, &i.to_string(), 10.0);
        }
    }
    wall_legend(&mut c, "#eef3fb");
    c.legend(
        Mark::dot(WALL, dot),
        &format!("convex vertex ({})", map.n() - map.r()),
    );
    c.legend(
        Mark::dot("#d62728", dot * 1.6),
        &format!("reflex vertex ({})", map.r()),
    );
    if style.vertex_labels {
        c.legend(Mark::Text("12".into()), "vertex index");
    }
    let name = map.name().unwrap_or("map");
    let caption = format!(
        "{name}: n = {}, r = {}{} (reflex vertices in red){}",
        map.n(),
        map.r(),
        if map.has_holes() {
            format!(", {} hole(s)", map.hole_count())
        } else {
            String::new()
        },
        if *map.scale() == 1 {
            String::new()
        } else {
            format!(", coordinates in units of 1/{}", map.scale())
        }
    );
    c.finish(name, &caption)
}

/// An exact point of the map's integer frame in the map's input units.
fn rat_text(p: &RatPoint, scale: &Integer) -> String {
    let den = Integer::from(p.hw() * scale);
    let q = |v: &Integer| wai_map::format_exact(&rug::Rational::from((v.clone(), den.clone())));
    format!("({}, {})", q(p.hx()), q(p.hy()))
}

fn coordinate_text(p: Point, scale: &Integer) -> String {
    let q =
        |v: i128| wai_map::format_exact(&rug::Rational::from((Integer::from(v), scale.clone())));
    format!("({}, {})", q(p.x), q(p.y))
}

/// Draw V_p over its map: the visible region, its edges by kind (spurious
/// dashed), the skeleton's artificial edges dotted with their label lines
/// faint, the viewpoint, a legend of every kind drawn, a scale bar and a
/// caption with the counts.
pub fn visibility_svg(
    map: &Map,
    vp: &wai_visibility::VisibilityPolygon,
    skeleton: Option<&wai_visibility::Skeleton>,
    style: &MapStyle,
) -> String {
    use wai_visibility::{EdgeKind, SkeletonEdge};
    let mut c = style.canvas(map);
    map_shape(&mut c, map, "#f4f4f4");
    c.polygon_rat(&vp.points(), "#ffe9a8", "none", 0.0);
    let n = vp.len();
    let kind_style = |k: EdgeKind| match k {
        EdgeKind::Spurious => ("#d62728", "5,4", "spurious"),
        EdgeKind::Full => ("#2ca02c", "", "full"),
        EdgeKind::Half => ("#ff7f0e", "", "half"),
        EdgeKind::Partial => ("#9467bd", "", "partial"),
    };
    for (i, e) in vp.edges().iter().enumerate() {
        let (a, b) = (&vp.vertices()[i].point, &vp.vertices()[(i + 1) % n].point);
        let (color, dash, what) = kind_style(e.kind);
        c.segment_rat(a, b, color, 2.5, dash, &format!("V_p edge {i}: {what}"));
    }
    for (i, v) in vp.vertices().iter().enumerate() {
        let fill = if v.spurious { "#d62728" } else { "#111" };
        c.dot_rat(
            &v.point,
            2.5,
            fill,
            &format!(
                "V_p vertex {i}{}",
                if v.spurious { " (spurious)" } else { "" }
            ),
        );
    }
    let mut artificial = 0;
    if let Some(sk) = skeleton {
        let k = sk.vertices().len();
        let (lo, hi) = map.bounding_box();
        for (i, e) in sk.edges().iter().enumerate() {
            if let SkeletonEdge::Artificial { map_edge, .. } = e {
                artificial += 1;
                let (a, b) = (
                    RatPoint::from(sk.vertices()[i]),
                    RatPoint::from(sk.vertices()[(i + 1) % k]),
                );
                c.segment_rat(&a, &b, "#111", 1.5, "2,3", &format!("artificial edge {i}"));
                // The label's line, drawn across the map's box.
                let (p, q) = (
                    map.vertices()[*map_edge],
                    map.vertices()[(*map_edge + 1) % map.n()],
                );
                if let Some((s, t)) = line_across_box(p, q, lo, hi) {
                    c.segment_rat(
                        &s,
                        &t,
                        "#9467bd",
                        0.7,
                        "1,3",
                        &format!("label line of artificial edge {i}"),
                    );
                }
            }
        }
        c.dot(sk.origin(), 4.0, "#1f77b4", "skeleton origin v0");
    }
    c.dot_rat(
        vp.viewpoint(),
        4.0,
        "#000",
        &format!("viewpoint {}", rat_text(vp.viewpoint(), map.scale())),
    );
    let count = |k: EdgeKind| vp.edges().iter().filter(|e| e.kind == k).count();
    wall_legend(&mut c, "#f4f4f4");
    c.legend(
        Mark::area("#ffe9a8", 0.55, "none"),
        "visibility polygon V_p (visible region)",
    );
    for k in [
        EdgeKind::Full,
        EdgeKind::Half,
        EdgeKind::Partial,
        EdgeKind::Spurious,
    ] {
        let (colour, dash, what) = kind_style(k);
        if count(k) > 0 {
            c.legend(
                Mark::line(colour, 2.5, dash),
                &format!("{what} edge of V_p ({})", count(k)),
            );
        }
    }
    c.legend(Mark::dot("#111", 2.5), "vertex of V_p");
    if vp.vertices().iter().any(|v| v.spurious) {
        c.legend(Mark::dot("#d62728", 2.5), "spurious vertex of V_p");
    }
    if skeleton.is_some() {
        if artificial > 0 {
            c.legend(
                Mark::line("#111", 1.5, "2,3"),
                &format!("artificial edge of the skeleton V*_p ({artificial})"),
            );
            c.legend(
                Mark::line("#9467bd", 0.7, "1,3"),
                "label line (map edge) of an artificial edge",
            );
        }
        c.legend(Mark::dot("#1f77b4", 4.0), "skeleton origin v0");
    }
    c.legend(Mark::dot("#000", 4.0), "viewpoint p");
    let caption = format!(
        "V_p of {}: {} vertices; edges {} full, {} half, {} partial, {} spurious (dashed red){}",
        rat_text(vp.viewpoint(), map.scale()),
        n,
        count(EdgeKind::Full),
        count(EdgeKind::Half),
        count(EdgeKind::Partial),
        count(EdgeKind::Spurious),
        skeleton.map_or(String::new(), |s| format!(
            "; skeleton: {} vertices, {} artificial (dotted)",
            s.vertices().len(),
            s.artificial_count()
        )),
    );
    c.finish(map.name().unwrap_or("map"), &caption)
}

/// The part of the line through `p` and `q` inside the box `lo`–`hi`, for
/// drawing (exact clipping against the four box lines).
fn line_across_box(p: Point, q: Point, lo: Point, hi: Point) -> Option<(RatPoint, RatPoint)> {
    use wai_exact::{construct_intersection, Line};
    let l = Line::new(p, q)?;
    let corners = [lo, Point::new(hi.x, lo.y), hi, Point::new(lo.x, hi.y)];
    let inside = |r: &RatPoint| {
        let (x, y, w) = (r.hx(), r.hy(), r.hw());
        Integer::from(w * lo.x) <= *x
            && *x <= Integer::from(w * hi.x)
            && Integer::from(w * lo.y) <= *y
            && *y <= Integer::from(w * hi.y)
    };
    let hits: Vec<RatPoint> = (0..4)
        .filter_map(|k| {
            Line::new(corners[k], corners[(k + 1) % 4])
                .and_then(|side| construct_intersection(&l, &side))
        })
        .filter(inside)
        .collect();
    let a = hits.first()?.clone();
    let b = hits.iter().find(|h| **h != a)?.clone();
    Some((a, b))
}

/// A kept cell of dimension 1 (two points: a segment) or 0 (one point),
/// with its class, for [`cells_svg`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LowerDrawn {
    /// The segment's ends, or the one point.
    pub points: Vec<RatPoint>,
    pub class: usize,
}

/// The palette [`class_colours`] picks from: golden-angle hues, each
/// round of the hue circle at another lightness and saturation, so that
/// colours near in the palette are far apart in hue.
fn palette(k: usize) -> String {
    const LIGHT: [(u32, u32); 4] = [(70, 68), (60, 48), (85, 80), (45, 62)];
    let hue = (k as f64 * 137.508) % 360.0;
    let (s, l) = LIGHT[k % LIGHT.len()];
    format!("hsl({hue:.1}, {s}%, {l}%)")
}

/// How many colours [`class_colours`] uses.
const PALETTE: usize = 40;

/// A colour for every class index below `classes`, such that two classes
/// with 2-cells sharing an edge differ: a greedy colouring of the class
/// adjacency graph, classes in index order, each taking the first palette
/// colour from its own (index mod palette) on that no coloured neighbour
/// has. `adjacent` lists unordered pairs of adjacent classes.
/// Deterministic. With more neighbours than colours, a class takes the
/// colour fewest of its neighbours have.
pub fn class_colours(classes: usize, adjacent: &BTreeSet<(usize, usize)>) -> Vec<String> {
    let mut nbrs: Vec<Vec<usize>> = vec![Vec::new(); classes];
    for &(a, b) in adjacent {
        if a != b && a < classes && b < classes {
            nbrs[a].push(b);
            nbrs[b].push(a);
        }
    }
    let mut pick: Vec<Option<usize>> = vec![None; classes];
    for c in 0..classes {
        let mut used = [0usize; PALETTE];
        for &d in &nbrs[c] {
            if let Some(k) = pick[d] {
                used[k] += 1;
            }
        }
        let start = c % PALETTE;
        let k = (0..PALETTE)
            .map(|i| (start + i) % PALETTE)
            .min_by_key(|&k| used[k])
            .unwrap_or(start);
        pick[c] = Some(k);
    }
    pick.into_iter().map(|k| palette(k.unwrap_or(0))).collect()
}

/// Pairs of classes whose 2-cells share an edge as drawn (both ends at
/// the same pixel text), on `canvas`.
fn drawn_adjacency(canvas: &Canvas, cells: &[(Vec<RatPoint>, usize)]) -> BTreeSet<(usize, usize)> {
    let mut by_edge: BTreeMap<(String, String), BTreeSet<usize>> = BTreeMap::new();
    for (ring, class) in cells {
        let pts = canvas.ring_text(ring);
        for i in 0..pts.len() {
            let (a, b) = (&pts[i], &pts[(i + 1) % pts.len()]);
            if a == b {
                continue;
            }
            let key = if a < b {
                (a.clone(), b.clone())
            } else {
                (b.clone(), a.clone())
            };
            by_edge.entry(key).or_default().insert(*class);
        }
    }
    let mut pairs = BTreeSet::new();
    for classes in by_edge.values() {
        let v: Vec<usize> = classes.iter().copied().collect();
        for i in 0..v.len() {
            for j in i + 1..v.len() {
                pairs.insert((v[i], v[j]));
            }
        }
    }
    pairs
}

/// Draw cells over their map: the 2-cells filled with a colour of their
/// class (adjacent classes differ, [`class_colours`]; each cell's tooltip
/// names its class), and the kept 1-cells (thick segments) and 0-cells
/// (dots) drawn over them in dark outline with their class colour, so
/// that cells of every dimension are visible. With `highlight`, the cells
/// of that class stand out in red and the others fade. A legend, a scale
/// bar and `caption` below.
pub fn cells_svg(
    map: &Map,
    cells: &[(Vec<RatPoint>, usize)],
    lower: &[LowerDrawn],
    highlight: Option<usize>,
    style: &MapStyle,
    caption: &str,
) -> String {
    let mut c = style.canvas(map);
    map_shape(&mut c, map, "#ffffff");
    let classes = cells
        .iter()
        .map(|(_, k)| k + 1)
        .chain(lower.iter().map(|l| l.class + 1))
        .max()
        .unwrap_or(0);
    let colours = class_colours(classes, &drawn_adjacency(&c, cells));
    for (ring, class) in cells {
        let (fill, stroke, width) = match highlight {
            Some(h) if h == *class => ("#d62728", "#7f0000", 1.2),
            Some(_) => ("#e8e8e8", "#bbbbbb", 0.3),
            None => (colours[*class].as_str(), "#555555", 0.3),
        };
        c.polygon_rat_titled(ring, fill, 0.9, stroke, width, &format!("class {class}"));
    }
    for l in lower {
        let colour = match highlight {
            Some(h) if h == l.class => "#d62728",
            Some(_) => "#999999",
            None => colours[l.class].as_str(),
        };
        let title = format!("kept {}-cell, class {}", l.points.len() - 1, l.class);
        match l.points.as_slice() {
            [a, b] => {
                c.segment_rat(a, b, "#000000", 4.0, "", &title);
                c.segment_rat(a, b, colour, 2.0, "", &title);
            }
            [p] => {
                c.dot_rat(p, 4.0, "#000000", &title);
                c.dot_rat(p, 2.5, colour, &title);
            }
            _ => {}
        }
    }
    map_shape(&mut c, map, "none");
    c.legend(Mark::line(WALL, 1.5, ""), "map walls");
    let class_count = cells.iter().map(|(_, k)| *k).collect::<BTreeSet<_>>().len();
    match highlight {
        None => c.legend(
            Mark::Swatches(colours.iter().take(6).cloned().collect()),
            &format!(
                "2-cells ({}) in {class_count} classes, filled by class (adjacent classes differ; tooltip: class id)",
                cells.len()
            ),
        ),
        Some(h) => {
            c.legend(
                Mark::area("#d62728", 0.9, "#7f0000"),
                &format!("2-cells of class {h}"),
            );
            c.legend(
                Mark::area("#e8e8e8", 0.9, "#bbbbbb"),
                "2-cells of the other classes",
            );
        }
    }
    let ones = lower.iter().filter(|l| l.points.len() == 2).count();
    let zeros = lower.iter().filter(|l| l.points.len() == 1).count();
    let kept_colour = if highlight.is_some() {
        "#d62728".to_string()
    } else {
        colours.first().cloned().unwrap_or_else(|| palette(0))
    };
    if ones > 0 {
        c.legend(
            Mark::line(&kept_colour, 3.0, ""),
            &format!("kept 1-cell ({ones}), in its class's colour, outlined black"),
        );
    }
    if zeros > 0 {
        c.legend(
            Mark::Dot {
                fill: kept_colour,
                r: 3.0,
                stroke: "#000".into(),
            },
            &format!("kept 0-cell ({zeros}), in its class's colour, outlined black"),
        );
    }
    c.finish(map.name().unwrap_or("map"), caption)
}

/// One embedding of a skeleton to draw (sec. 3.7, Def 4.1): its embedded
/// skeleton polygon, kernel, witness cells and candidate edges.
#[derive(Clone, Debug)]
pub struct EmbeddingDrawn {
    /// The map vertex h(v0).
    pub origin: usize,
    /// h(V◇), counter-clockwise.
    pub polygon: Vec<Point>,
    /// h(ker V*): empty, a point, a segment or a polygon.
    pub kernel: Vec<RatPoint>,
    /// The witness cells: rings (2-cells), segments (1-cells), points.
    pub witnesses: Vec<Vec<RatPoint>>,
    /// The map edges that are candidate edges of its artificial edges,
    /// with whether each is valid (seen by a witness).
    pub candidate_edges: Vec<(usize, bool)>,
}

/// How many embeddings the legend names one by one; beyond, one entry
/// says the hues tell them apart.
const LEGEND_EMBEDDINGS: usize = 8;

/// Draw the embeddings of one skeleton over its map, one hue each: the
/// skeleton polygons outlined, kernels shaded, witness cells filled
/// darker, candidate edges thick (solid if valid, dashed if not), each
/// origin h(v0) marked; a legend of every kind of mark and of the
/// embeddings' hues, a scale bar and `caption`.
pub fn embeddings_svg(
    map: &Map,
    drawn: &[EmbeddingDrawn],
    style: &MapStyle,
    caption: &str,
) -> String {
    let mut c = style.canvas(map);
    map_shape(&mut c, map, "#ffffff");
    let v = map.vertices();
    let hue = |i: usize| (i as f64 * 137.508 + 200.0) % 360.0;
    for (i, h) in drawn.iter().enumerate() {
        let ring: Vec<RatPoint> = h.polygon.iter().map(|&p| RatPoint::from(p)).collect();
        c.polygon_rat(
            &ring,
            &format!("hsla({:.1}, 60%, 70%, 0.15)", hue(i)),
            &format!("hsl({:.1}, 60%, 40%)", hue(i)),
            1.2,
        );
        if h.kernel.len() >= 3 {
            c.polygon_rat(
                &h.kernel,
                &format!("hsla({:.1}, 60%, 60%, 0.35)", hue(i)),
                "none",
                0.0,
            );
        }
    }
    let (mut witnesses, mut valid_edges, mut other_edges, mut kernels) = (0, 0, 0, 0);
    for (i, h) in drawn.iter().enumerate() {
        let colour = format!("hsl({:.1}, 70%, 35%)", hue(i));
        let title = format!("witness of the embedding at map vertex {}", h.origin);
        kernels += usize::from(h.kernel.len() >= 3);
        for w in &h.witnesses {
            witnesses += 1;
            match w.as_slice() {
                [p] => c.dot_rat(p, 3.0, &colour, &title),
                [a, b] => c.segment_rat(a, b, &colour, 3.0, "", &title),
                ring => c.polygon_rat(ring, &colour, "none", 0.0),
            }
        }
        for &(e, valid) in &h.candidate_edges {
            let (a, b) = (RatPoint::from(v[e]), RatPoint::from(v[(e + 1) % v.len()]));
            let what = if valid {
                valid_edges += 1;
                "valid candidate"
            } else {
                other_edges += 1;
                "candidate"
            };
            c.segment_rat(
                &a,
                &b,
                &colour,
                4.0,
                if valid { "" } else { "6 4" },
                &format!(
                    "{what} edge {e} of the embedding at map vertex {}",
                    h.origin
                ),
            );
        }
        c.dot(
            v[h.origin],
            4.0,
            &colour,
            &format!("h(v0) = map vertex {}", h.origin),
        );
    }
    map_shape(&mut c, map, "none");
    c.legend(Mark::line(WALL, 1.5, ""), "map walls");
    for (i, h) in drawn.iter().enumerate().take(LEGEND_EMBEDDINGS) {
        c.legend(
            Mark::area(
                &format!("hsl({:.1}, 60%, 70%)", hue(i)),
                0.4,
                &format!("hsl({:.1}, 60%, 40%)", hue(i)),
            ),
            &format!("embedding at map vertex {}", h.origin),
        );
    }
    if drawn.len() > LEGEND_EMBEDDINGS {
        c.legend(
            Mark::Swatches(
                (LEGEND_EMBEDDINGS..drawn.len().min(LEGEND_EMBEDDINGS + 6))
                    .map(|i| format!("hsl({:.1}, 60%, 70%)", hue(i)))
                    .collect(),
            ),
            &format!(
                "{} more embeddings, one hue each (tooltips name them)",
                drawn.len() - LEGEND_EMBEDDINGS
            ),
        );
    }
    // The kinds of mark, in a neutral grey; each takes its embedding's hue.
    let grey = "hsl(0, 0%, 35%)";
    c.legend(
        Mark::area("hsl(0, 0%, 70%)", 0.3, grey),
        "embedded skeleton polygon h(V◇), outlined",
    );
    if kernels > 0 {
        c.legend(
            Mark::area("hsl(0, 0%, 60%)", 0.35, "none"),
            "kernel h(ker V*), shaded",
        );
    }
    if witnesses > 0 {
        c.legend(
            Mark::area(grey, 0.55, "none"),
            &format!("witness cell ({witnesses}), filled dark"),
        );
    }
    if valid_edges > 0 {
        c.legend(
            Mark::line(grey, 4.0, ""),
            &format!("valid candidate edge ({valid_edges})"),
        );
    }
    if other_edges > 0 {
        c.legend(
            Mark::line(grey, 4.0, "6 4"),
            &format!("candidate edge, not valid ({other_edges})"),
        );
    }
    c.legend(Mark::dot(grey, 4.0), "origin h(v0), a map vertex");
    c.finish(map.name().unwrap_or("map"), caption)
}
