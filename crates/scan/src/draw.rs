//! SVG pictures of a scan localization: the map's walls, the scan points
//! placed at the best pose, every pose of the answer set (an arrow for
//! the heading) and, when known, the true pose; a legend of every kind
//! of mark to the right of the drawing and a scale bar in metres below.
//! The helpers here (legend, round numbers, ticks) serve the error CDF
//! of [`crate::eval::cdf_svg`] too.

use std::fmt::Write as _;

use crate::walls::Walls;
use crate::{Pose, Scan, ScanAnswer};

/// One kind of mark as its legend entry shows it.
#[derive(Debug, Clone, PartialEq)]
pub enum Mark {
    /// A line of this colour, width and dash array ("" for solid).
    Line(String, f64, String),
    /// A dot of this colour and radius.
    Dot(String, f64),
    /// A pose: a dot with a heading arrow, in this colour.
    Pose(String),
}

/// Average width of a 12 px sans-serif character, pixels (generous).
pub(crate) const CHAR_PX: f64 = 6.8;

/// A legend box at (`x`, `y`) (top left) of `entries`; its SVG, width and
/// height. Each entry is a `<g class="legend-entry">`.
pub(crate) fn legend(x: f64, y: f64, entries: &[(Mark, String)]) -> (String, f64, f64) {
    let widest = entries
        .iter()
        .map(|(_, l)| l.chars().count())
        .max()
        .unwrap_or(0)
        .max(6);
    let (w, h) = (
        widest as f64 * CHAR_PX + 56.0,
        26.0 + 20.0 * entries.len() as f64,
    );
    let mut s = format!(
        r##"<g class="legend" font-family="sans-serif" font-size="12" fill="#222"><rect x="{x:.1}" y="{y:.1}" width="{w:.1}" height="{h:.1}" fill="white" stroke="#bbb"/><text x="{:.1}" y="{:.1}" font-weight="bold">Legend</text>"##,
        x + 8.0,
        y + 16.0
    );
    for (i, (mark, label)) in entries.iter().enumerate() {
        let (mx, my) = (x + 8.0, y + 32.0 + 20.0 * i as f64);
        s.push_str(r#"<g class="legend-entry">"#);
        match mark {
            Mark::Line(c, width, dash) => {
                let _ = write!(
                    s,
                    r#"<line x1="{mx:.1}" y1="{my:.1}" x2="{:.1}" y2="{my:.1}" stroke="{c}" stroke-width="{width}" stroke-dasharray="{dash}"/>"#,
                    mx + 28.0
                );
            }
            Mark::Dot(c, r) => {
                let _ = write!(
                    s,
                    r#"<circle cx="{:.1}" cy="{my:.1}" r="{r}" fill="{c}"/>"#,
                    mx + 14.0
                );
            }
            Mark::Pose(c) => {
                let _ = write!(
                    s,
                    r#"<circle cx="{:.1}" cy="{my:.1}" r="4" fill="{c}"/><line x1="{:.1}" y1="{my:.1}" x2="{:.1}" y2="{my:.1}" stroke="{c}" stroke-width="2"/>"#,
                    mx + 6.0,
                    mx + 6.0,
                    mx + 28.0
                );
            }
        }
        let _ = write!(
            s,
            r#"<text x="{:.1}" y="{:.1}">{}</text></g>"#,
            mx + 36.0,
            my + 4.0,
            xml(label)
        );
    }
    s.push_str("</g>\n");
    (s, w, h)
}

/// The smallest 1, 2 or 5 × 10^k not below `x` (> 0).
pub(crate) fn nice_ceil(x: f64) -> f64 {
    let p = 10f64.powf(x.log10().floor());
    [1.0, 2.0, 5.0, 10.0]
        .into_iter()
        .map(|m| m * p)
        .find(|v| *v >= x * (1.0 - 1e-9))
        .unwrap_or(10.0 * p)
}

/// `v`, a multiple of `step` (a 1, 2 or 5 × 10^k), with as many decimals
/// as `step` needs.
pub(crate) fn tick_text(v: f64, step: f64) -> String {
    let decimals = (-step.log10().floor()).max(0.0) as usize;
    format!("{v:.decimals$}")
}

/// A tick step for an axis from 0 to `max` drawn `px` pixels long whose
/// labels need `label_px` pixels each: the smallest round step whose
/// ticks are at least `label_px` + 12 pixels apart.
pub(crate) fn tick_step(max: f64, px: f64, label_px: f64) -> f64 {
    let min_gap = (label_px + 12.0) / px * max;
    nice_ceil(min_gap.max(max * 1e-9))
}

pub(crate) fn xml(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// A scale bar `bar` pixels long, labelled `text`, its left end at `at`
/// (the bar's baseline).
fn scale_bar(s: &mut String, (bx, by): (f64, f64), bar: f64, text: &str) {
    let _ = write!(
        s,
        r##"<g class="scale-bar"><title>scale bar: {text}</title><rect x="{bx:.1}" y="{:.1}" width="{:.2}" height="5" fill="#222"/><rect x="{:.2}" y="{:.1}" width="{:.2}" height="5" fill="white" stroke="#222"/><text x="{:.1}" y="{:.1}" font-size="12" font-family="sans-serif" fill="#222">{text}</text></g>"##,
        by - 5.0,
        bar / 2.0,
        bx + bar / 2.0,
        by - 5.0,
        bar / 2.0,
        bx + bar + 8.0,
        by + 1.0
    );
}

/// The picture of `answer` to `scan` on `walls` (metres), the drawing
/// `size` pixels along its longer side.
pub fn answer_svg(
    walls: &Walls,
    scan: &Scan,
    answer: &ScanAnswer,
    truth: Option<&Pose>,
    size: f64,
) -> String {
    let segs = walls.segments();
    let (lo, hi) = walls.bounds();
    let span = (hi.0 - lo.0).max(hi.1 - lo.1).max(1e-9);
    let k = size / span;
    let margin = 10.0;
    let (dw, dh) = (
        (hi.0 - lo.0) * k + 2.0 * margin,
        (hi.1 - lo.1) * k + 2.0 * margin,
    );
    // y up in the map, down on screen.
    let tx = |p: (f64, f64)| (margin + (p.0 - lo.0) * k, margin + (hi.1 - p.1) * k);
    let mut body = String::new();
    for seg in segs {
        let (a, b) = (tx(seg[0]), tx(seg[1]));
        let _ = write!(
            body,
            r#"<line x1="{:.2}" y1="{:.2}" x2="{:.2}" y2="{:.2}" stroke="black" stroke-width="1.5"/>"#,
            a.0, a.1, b.0, b.1
        );
    }
    let arrow = |s: &mut String, p: &Pose, colour: &str, title: &str| {
        let a = tx((p.x, p.y));
        let len = 0.6 * k;
        let b = (a.0 + len * p.heading.cos(), a.1 - len * p.heading.sin());
        let _ = write!(
            s,
            r#"<g><title>{title} ({:.3}, {:.3}, {:.1}°)</title><circle cx="{:.2}" cy="{:.2}" r="4" fill="{colour}"/><line x1="{:.2}" y1="{:.2}" x2="{:.2}" y2="{:.2}" stroke="{colour}" stroke-width="2"/></g>"#,
            p.x,
            p.y,
            p.heading.to_degrees(),
            a.0,
            a.1,
            a.0,
            a.1,
            b.0,
            b.1
        );
    };
    let mut entries = vec![(
        Mark::Line("black".into(), 1.5, String::new()),
        "map walls".to_string(),
    )];
    if let Some(best) = &answer.best {
        let (c, sn) = (best.pose.heading.cos(), best.pose.heading.sin());
        let points = scan.points();
        let count = points.len();
        for (x, y) in points {
            let p = tx((best.pose.x + c * x - sn * y, best.pose.y + sn * x + c * y));
            let _ = write!(
                body,
                r##"<circle cx="{:.2}" cy="{:.2}" r="1.2" fill="#1f77b4"/>"##,
                p.0, p.1
            );
        }
        entries.push((
            Mark::Dot("#1f77b4".into(), 2.0),
            format!("scan return placed at the best pose ({count})"),
        ));
    }
    for (i, hyp) in answer.answer_set.iter().enumerate() {
        let colour = if i == 0 { "#d62728" } else { "#ff7f0e" };
        arrow(
            &mut body,
            &hyp.pose,
            colour,
            &format!("answer {i}, score {:.5}", hyp.score),
        );
    }
    if !answer.answer_set.is_empty() {
        entries.push((
            Mark::Pose("#d62728".into()),
            "best pose (arrow: heading, 0.6 m)".into(),
        ));
    }
    if answer.answer_set.len() > 1 {
        entries.push((
            Mark::Pose("#ff7f0e".into()),
            format!(
                "other pose of the answer set ({})",
                answer.answer_set.len() - 1
            ),
        ));
    }
    if let Some(t) = truth {
        arrow(&mut body, t, "#2ca02c", "true pose");
        entries.push((Mark::Pose("#2ca02c".into()), "true pose".into()));
    }
    let (legend_svg, lw, lh) = legend(dw + 8.0, margin, &entries);
    // The scale bar: about a fifth of the drawing, a round length.
    let metres = wai_render::nice_floor(0.2 * (dw - 2.0 * margin) / k);
    let bar = metres * k;
    let top = dh.max(lh + margin + 10.0);
    let (w, h) = ((dw + lw + 16.0).max(320.0), top + 30.0);
    let (bx, by) = (margin, top + 14.0);
    let text = format!("{} m", tick_text(metres, metres));
    let mut s = String::new();
    let _ = write!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w:.0}" height="{h:.0}" viewBox="0 0 {w:.2} {h:.2}"><rect width="{w:.0}" height="{h:.0}" fill="white"/>"#
    );
    s.push_str(&body);
    s.push_str(&legend_svg);
    scale_bar(&mut s, (bx, by), bar, &text);
    s.push_str("</svg>\n");
    s
}

/// The map's walls (metres) with a dot at each of `points`, coloured by its
/// kind: `kinds[k]` is the colour and legend label of kind `k` (the legend
/// counts each kind's dots). For the query poses of an evaluation
/// coloured by outcome.
pub fn points_svg(
    walls: &Walls,
    title: &str,
    points: &[((f64, f64), usize)],
    kinds: &[(&str, &str)],
    size: f64,
) -> String {
    let segs = walls.segments();
    let (lo, hi) = walls.bounds();
    let span = (hi.0 - lo.0).max(hi.1 - lo.1).max(1e-9);
    let k = size / span;
    let margin = 10.0;
    let top_text = 24.0;
    let (dw, dh) = (
        (hi.0 - lo.0) * k + 2.0 * margin,
        (hi.1 - lo.1) * k + 2.0 * margin + top_text,
    );
    let tx = |p: (f64, f64)| {
        (
            margin + (p.0 - lo.0) * k,
            top_text + margin + (hi.1 - p.1) * k,
        )
    };
    let mut body = String::new();
    for seg in segs {
        let (a, b) = (tx(seg[0]), tx(seg[1]));
        let _ = write!(
            body,
            r#"<line x1="{:.2}" y1="{:.2}" x2="{:.2}" y2="{:.2}" stroke="black" stroke-width="1"/>"#,
            a.0, a.1, b.0, b.1
        );
    }
    let mut counts = vec![0usize; kinds.len()];
    for &(p, kind) in points {
        counts[kind] += 1;
        let a = tx(p);
        let _ = write!(
            body,
            r#"<circle cx="{:.2}" cy="{:.2}" r="2.2" fill="{}"/>"#,
            a.0, a.1, kinds[kind].0
        );
    }
    let mut entries = vec![(
        Mark::Line("black".into(), 1.0, String::new()),
        "map walls".to_string(),
    )];
    entries.extend(
        kinds
            .iter()
            .zip(&counts)
            .map(|((c, l), n)| (Mark::Dot((*c).into(), 3.0), format!("{l} ({n})"))),
    );
    let (legend_svg, lw, lh) = legend(dw + 8.0, top_text + margin, &entries);
    let metres = wai_render::nice_floor(0.2 * (dw - 2.0 * margin) / k);
    let bar = metres * k;
    let top = dh.max(lh + top_text + margin + 10.0);
    let (w, h) = ((dw + lw + 16.0).max(320.0), top + 30.0);
    let (bx, by) = (margin, top + 14.0);
    let text = format!("{} m", tick_text(metres, metres));
    let mut s = String::new();
    let _ = write!(
        s,
        r##"<svg xmlns="http://www.w3.org/2000/svg" width="{w:.0}" height="{h:.0}" viewBox="0 0 {w:.2} {h:.2}"><rect width="{w:.0}" height="{h:.0}" fill="white"/><text x="{margin:.1}" y="16" font-size="14" font-family="sans-serif" fill="#222">{}</text>"##,
        xml(title)
    );
    s.push_str(&body);
    s.push_str(&legend_svg);
    scale_bar(&mut s, (bx, by), bar, &text);
    s.push_str("</svg>\n");
    s
}
