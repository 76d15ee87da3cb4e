//! SVG pictures of a scan localization: the map's walls, the scan points
//! placed at the best pose, every pose of the answer set (an arrow for
//! the heading) and, when known, the true pose.

use std::fmt::Write as _;

use crate::walls::Walls;
use crate::{Pose, Scan, ScanAnswer};

/// The picture of `answer` to `scan` on `walls`, `size` pixels wide.
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
    let (w, h) = (
        (hi.0 - lo.0) * k + 2.0 * margin,
        (hi.1 - lo.1) * k + 2.0 * margin,
    );
    // y up in the map, down on screen.
    let tx = |p: (f64, f64)| (margin + (p.0 - lo.0) * k, margin + (hi.1 - p.1) * k);
    let mut s = String::new();
    let _ = write!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w:.0}" height="{h:.0}"><rect width="{w:.0}" height="{h:.0}" fill="white"/>"#
    );
    for seg in segs {
        let (a, b) = (tx(seg[0]), tx(seg[1]));
        let _ = write!(
            s,
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
    if let Some(best) = &answer.best {
        let (c, sn) = (best.pose.heading.cos(), best.pose.heading.sin());
        for (x, y) in scan.points() {
            let p = tx((best.pose.x + c * x - sn * y, best.pose.y + sn * x + c * y));
            let _ = write!(
                s,
                r##"<circle cx="{:.2}" cy="{:.2}" r="1.2" fill="#d62728"/>"##,
                p.0, p.1
            );
        }
    }
    for (i, hyp) in answer.answer_set.iter().enumerate() {
        let colour = if i == 0 { "#d62728" } else { "#ff7f0e" };
        arrow(
            &mut s,
            &hyp.pose,
            colour,
            &format!("answer {i}, score {:.5}", hyp.score),
        );
    }
    if let Some(t) = truth {
        arrow(&mut s, t, "#2ca02c", "true pose");
    }
    s.push_str("</svg>\n");
    s
}
