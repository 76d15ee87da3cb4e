//! SVG pictures (output only).
//!
//! The principal type is [`Canvas`]: it maps the exact integer coordinates
//! of a map onto an SVG view box (y up, as in the thesis's figures) and
//! collects layers. [`map_svg`] draws a map with its reflex vertices marked;
//! later issues add layers for visibility polygons, skeletons and cells.
//!
//! # Invariant
//! Floating point appears only here, in the pixel coordinates written to
//! the SVG text; nothing read back from a picture decides anything.
#![allow(
    clippy::float_arithmetic,
    reason = "pixel coordinates of pictures are output only (STYLE.md 1)"
)]

use rug::Integer;
use std::fmt::Write;
use wai_exact::{Point, RatPoint};
use wai_map::Map;

/// An SVG drawing in the coordinate frame of one map.
#[derive(Debug)]
pub struct Canvas {
    min: (f64, f64),
    unit: f64,
    width: f64,
    height: f64,
    margin: f64,
    body: String,
}

/// Convert an integer coordinate to `f64` for drawing.
fn approx(c: i128) -> f64 {
    // i128 -> f64 rounds to nearest; pictures need no more.
    c as f64
}

impl Canvas {
    /// A canvas showing the box `lo`–`hi` (integer map units) scaled to
    /// `size` pixels along its longer side.
    pub fn new(lo: Point, hi: Point, size: f64) -> Canvas {
        let w = approx(hi.x - lo.x).max(1.0);
        let h = approx(hi.y - lo.y).max(1.0);
        let unit = size / w.max(h);
        Canvas {
            min: (approx(lo.x), approx(lo.y)),
            unit,
            width: w * unit,
            height: h * unit,
            margin: 0.05 * size,
            body: String::new(),
        }
    }

    /// A canvas fitted to `map`.
    pub fn for_map(map: &Map, size: f64) -> Canvas {
        let (lo, hi) = map.bounding_box();
        Canvas::new(lo, hi, size)
    }

    fn px(&self, p: Point) -> (f64, f64) {
        self.px_approx(approx(p.x), approx(p.y))
    }

    fn px_approx(&self, x: f64, y: f64) -> (f64, f64) {
        let sx = (x - self.min.0) * self.unit + self.margin;
        let sy = self.height - (y - self.min.1) * self.unit + self.margin;
        (sx, sy)
    }

    fn px_rat(&self, p: &RatPoint) -> (f64, f64) {
        let w = p.hw().to_f64();
        self.px_approx(p.hx().to_f64() / w, p.hy().to_f64() / w)
    }

    /// A closed polygon with exact rational vertices.
    pub fn polygon_rat(&mut self, ring: &[RatPoint], fill: &str, stroke: &str, stroke_width: f64) {
        let pts: Vec<String> = ring
            .iter()
            .map(|p| {
                let (x, y) = self.px_rat(p);
                format!("{x:.2},{y:.2}")
            })
            .collect();
        let _ = writeln!(
            self.body,
            r#"<polygon points="{}" fill="{fill}" fill-opacity="0.55" stroke="{stroke}" stroke-width="{stroke_width}"/>"#,
            pts.join(" ")
        );
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

    /// The finished SVG document, with `title` and a caption line.
    pub fn finish(self, title: &str, caption: &str) -> String {
        let (w, h) = (
            self.width + 2.0 * self.margin,
            self.height + 2.0 * self.margin + 18.0,
        );
        format!(
            concat!(
                r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w:.0}" height="{h:.0}" viewBox="0 0 {w:.2} {h:.2}">"#,
                "\n<title>{title}</title>\n",
                r#"<rect width="100%" height="100%" fill="white"/>"#,
                "\n{body}",
                r##"<text x="4" y="{cy:.2}" font-size="12" font-family="sans-serif" fill="#555">{caption}</text>"##,
                "\n</svg>\n"
            ),
            w = w,
            h = h,
            title = escape(title),
            body = self.body,
            cy = h - 5.0,
            caption = escape(caption),
        )
    }
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// What [`map_svg`] draws.
#[derive(Clone, Debug)]
pub struct MapStyle {
    /// Pixels along the longer side of the map.
    pub size: f64,
    /// Number every vertex.
    pub vertex_labels: bool,
}

impl Default for MapStyle {
    fn default() -> Self {
        MapStyle {
            size: 800.0,
            vertex_labels: false,
        }
    }
}

/// Draw `map`: its polygon, its vertices, its reflex vertices marked in red,
/// and a caption with n, r and the scale.
pub fn map_svg(map: &Map, style: &MapStyle) -> String {
    let mut c = Canvas::for_map(map, style.size);
    c.polygon(map.vertices(), "#eef3fb", "#1f3b73", 1.5);
    let dot = (style.size / 250.0).clamp(1.5, 4.0);
    for (i, &p) in map.vertices().iter().enumerate() {
        let (fill, kind) = if map.is_reflex(i) {
            ("#d62728", "reflex")
        } else {
            ("#1f3b73", "convex")
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
    let name = map.name().unwrap_or("map");
    let caption = format!(
        "{name}: n = {}, r = {} (reflex vertices in red){}",
        map.n(),
        map.r(),
        if *map.scale() == 1 {
            String::new()
        } else {
            format!(", coordinates in units of 1/{}", map.scale())
        }
    );
    c.finish(name, &caption)
}

fn coordinate_text(p: Point, scale: &Integer) -> String {
    let q =
        |v: i128| wai_map::format_exact(&rug::Rational::from((Integer::from(v), scale.clone())));
    format!("({}, {})", q(p.x), q(p.y))
}

/// Draw V_p over its map: the visible region, its spurious edges dashed,
/// the skeleton's artificial edges dotted with their label lines faint, the
/// viewpoint, and a caption with the counts.
pub fn visibility_svg(
    map: &Map,
    vp: &wai_visibility::VisibilityPolygon,
    skeleton: Option<&wai_visibility::Skeleton>,
    style: &MapStyle,
) -> String {
    use wai_visibility::{EdgeKind, SkeletonEdge};
    let mut c = Canvas::for_map(map, style.size);
    c.polygon(map.vertices(), "#f4f4f4", "#1f3b73", 1.5);
    c.polygon_rat(&vp.points(), "#ffe9a8", "none", 0.0);
    let n = vp.len();
    for (i, e) in vp.edges().iter().enumerate() {
        let (a, b) = (&vp.vertices()[i].point, &vp.vertices()[(i + 1) % n].point);
        let (color, dash, what) = match e.kind {
            EdgeKind::Spurious => ("#d62728", "5,4", "spurious"),
            EdgeKind::Full => ("#2ca02c", "", "full"),
            EdgeKind::Half => ("#ff7f0e", "", "half"),
            EdgeKind::Partial => ("#9467bd", "", "partial"),
        };
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
    if let Some(sk) = skeleton {
        let k = sk.vertices().len();
        let (lo, hi) = map.bounding_box();
        for (i, e) in sk.edges().iter().enumerate() {
            if let SkeletonEdge::Artificial { map_edge, .. } = e {
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
        &format!("viewpoint {}", vp.viewpoint()),
    );
    let count = |k: EdgeKind| vp.edges().iter().filter(|e| e.kind == k).count();
    let caption = format!(
        "V_p of {}: {} vertices; edges {} full, {} half, {} partial, {} spurious (dashed red){}",
        vp.viewpoint(),
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

/// Draw cells over their map, each filled with a colour of its class;
/// with `highlight`, the cells of that class stand out and the others fade.
/// `cells` holds each cell's exact boundary and its class index.
/// A kept cell of dimension 1 (two points: a segment) or 0 (one point),
/// with its class, for [`cells_svg`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LowerDrawn {
    /// The segment's ends, or the one point.
    pub points: Vec<RatPoint>,
    pub class: usize,
}

/// The 2-cells filled by class, and the kept 1-cells (thick segments) and
/// 0-cells (dots) drawn over them in dark outline with their class colour,
/// so that cells of every dimension are visible.
pub fn cells_svg(
    map: &Map,
    cells: &[(Vec<RatPoint>, usize)],
    lower: &[LowerDrawn],
    highlight: Option<usize>,
    style: &MapStyle,
    caption: &str,
) -> String {
    let mut c = Canvas::for_map(map, style.size);
    c.polygon(map.vertices(), "#ffffff", "#1f3b73", 1.5);
    for (ring, class) in cells {
        let (fill, stroke, width) = match highlight {
            Some(h) if h == *class => ("#d62728".to_string(), "#7f0000", 1.2),
            Some(_) => ("#e8e8e8".to_string(), "#bbbbbb", 0.3),
            None => (class_colour(*class), "#555555", 0.3),
        };
        c.polygon_rat(ring, &fill, stroke, width);
    }
    for l in lower {
        let colour = match highlight {
            Some(h) if h == l.class => "#d62728".to_string(),
            Some(_) => "#999999".to_string(),
            None => class_colour(l.class),
        };
        let title = format!("kept {}-cell, class {}", l.points.len() - 1, l.class);
        match l.points.as_slice() {
            [a, b] => {
                c.segment_rat(a, b, "#000000", 4.0, "", &title);
                c.segment_rat(a, b, &colour, 2.0, "", &title);
            }
            [p] => {
                c.dot_rat(p, 4.0, "#000000", &title);
                c.dot_rat(p, 2.5, &colour, &title);
            }
            _ => {}
        }
    }
    c.polygon(map.vertices(), "none", "#1f3b73", 1.5);
    c.finish(map.name().unwrap_or("map"), caption)
}

/// A stable colour for a class index (golden-angle hues).
fn class_colour(class: usize) -> String {
    let hue = (class as f64 * 137.508) % 360.0;
    format!("hsl({hue:.1}, 65%, 72%)")
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

/// Draw the embeddings of one skeleton over its map, one hue each: the
/// skeleton polygons outlined, kernels shaded, witness cells filled
/// darker, candidate edges thick (solid if valid, dashed if not), each
/// origin h(v0) marked.
pub fn embeddings_svg(
    map: &Map,
    drawn: &[EmbeddingDrawn],
    style: &MapStyle,
    caption: &str,
) -> String {
    let mut c = Canvas::for_map(map, style.size);
    c.polygon(map.vertices(), "#ffffff", "#1f3b73", 1.5);
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
    for (i, h) in drawn.iter().enumerate() {
        let colour = format!("hsl({:.1}, 70%, 35%)", hue(i));
        let title = format!("witness of the embedding at map vertex {}", h.origin);
        for w in &h.witnesses {
            match w.as_slice() {
                [p] => c.dot_rat(p, 3.0, &colour, &title),
                [a, b] => c.segment_rat(a, b, &colour, 3.0, "", &title),
                ring => c.polygon_rat(ring, &colour, "none", 0.0),
            }
        }
        for &(e, valid) in &h.candidate_edges {
            let (a, b) = (RatPoint::from(v[e]), RatPoint::from(v[(e + 1) % v.len()]));
            let what = if valid {
                "valid candidate"
            } else {
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
    c.polygon(map.vertices(), "none", "#1f3b73", 1.5);
    c.finish(map.name().unwrap_or("map"), caption)
}
