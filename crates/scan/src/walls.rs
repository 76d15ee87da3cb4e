//! The map's walls as `f64` segments in a uniform grid: the two geometric
//! queries the scan localizer makes thousands of times per query — the
//! range along a beam ([`Walls::cast`]) and the nearest wall to a point
//! ([`Walls::nearest`], the correspondence of point-to-line ICP).
//!
//! Both are exact copies of a brute-force loop over all walls, only faster:
//! a test compares them on random queries.

use crate::Pose;

/// A wall segment `[a, b]` in input units.
pub type Segment = [(f64, f64); 2];

/// The nearest point of a wall to a query point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Nearest {
    /// The distance from the query point.
    pub distance: f64,
    /// The closest point on the wall.
    pub point: (f64, f64),
    /// The unit normal of the wall's line (either side).
    pub normal: (f64, f64),
}

/// Walls bucketed in a uniform grid of square cells.
#[derive(Debug, Clone)]
pub struct Walls {
    segments: Vec<Segment>,
    /// The lower left corner of the walls' bounding box: the grid's origin.
    origin: (f64, f64),
    /// The upper right corner of the walls' bounding box.
    top: (f64, f64),
    cell: f64,
    cols: usize,
    rows: usize,
    /// Per grid cell, the walls whose bounding box meets it.
    buckets: Vec<Vec<u32>>,
}

impl Walls {
    /// Buckets `segments` in a grid of about 4 cells per segment.
    pub fn new(segments: Vec<Segment>) -> Walls {
        let (mut lo, mut hi) = (
            (f64::INFINITY, f64::INFINITY),
            (f64::NEG_INFINITY, f64::NEG_INFINITY),
        );
        for s in &segments {
            for p in s {
                lo = (lo.0.min(p.0), lo.1.min(p.1));
                hi = (hi.0.max(p.0), hi.1.max(p.1));
            }
        }
        if segments.is_empty() {
            lo = (0.0, 0.0);
            hi = (1.0, 1.0);
        }
        let (w, h) = ((hi.0 - lo.0).max(1e-9), (hi.1 - lo.1).max(1e-9));
        let target = (4 * segments.len()).max(1) as f64;
        let cell = (w * h / target).sqrt().max(w.max(h) / 512.0);
        let cols = ((w / cell).ceil() as usize).max(1);
        let rows = ((h / cell).ceil() as usize).max(1);
        let mut walls = Walls {
            segments,
            origin: lo,
            top: hi,
            cell,
            cols,
            rows,
            buckets: vec![Vec::new(); cols * rows],
        };
        for (k, s) in walls.segments.iter().enumerate() {
            let (c0, r0) = walls.cell_of((s[0].0.min(s[1].0), s[0].1.min(s[1].1)));
            let (c1, r1) = walls.cell_of((s[0].0.max(s[1].0), s[0].1.max(s[1].1)));
            for r in r0..=r1 {
                for c in c0..=c1 {
                    walls.buckets[r * cols + c].push(k as u32);
                }
            }
        }
        walls
    }

    /// The walls, in the order given.
    pub fn segments(&self) -> &[Segment] {
        &self.segments
    }

    /// The walls' bounding box, lower left and upper right corners (the
    /// unit square when there are none).
    pub fn bounds(&self) -> ((f64, f64), (f64, f64)) {
        (self.origin, self.top)
    }

    fn cell_of(&self, p: (f64, f64)) -> (usize, usize) {
        let c = ((p.0 - self.origin.0) / self.cell).floor();
        let r = ((p.1 - self.origin.1) / self.cell).floor();
        (
            (c.max(0.0) as usize).min(self.cols - 1),
            (r.max(0.0) as usize).min(self.rows - 1),
        )
    }

    /// The range from `o` along the unit direction `d` to the first wall
    /// crossed ahead, or infinity. Walls collinear with the beam are
    /// ignored (a sensor does not see a wall edge-on).
    pub fn cast(&self, o: (f64, f64), d: (f64, f64)) -> f64 {
        // Amanatides–Woo traversal of the grid cells the beam passes; a hit
        // found in a cell is final once it lies before the cell's exit.
        let (mut c, mut r) = self.cell_of(o);
        let step_c: isize = if d.0 > 0.0 { 1 } else { -1 };
        let step_r: isize = if d.1 > 0.0 { 1 } else { -1 };
        let border = |i: usize, step: isize, o: f64, base: f64| {
            base + (i as f64 + if step > 0 { 1.0 } else { 0.0 }) * self.cell - o
        };
        let mut t_c = if d.0 != 0.0 {
            border(c, step_c, o.0, self.origin.0) / d.0
        } else {
            f64::INFINITY
        };
        let mut t_r = if d.1 != 0.0 {
            border(r, step_r, o.1, self.origin.1) / d.1
        } else {
            f64::INFINITY
        };
        let dt_c = if d.0 != 0.0 {
            self.cell / d.0.abs()
        } else {
            f64::INFINITY
        };
        let dt_r = if d.1 != 0.0 {
            self.cell / d.1.abs()
        } else {
            f64::INFINITY
        };
        let mut best = f64::INFINITY;
        loop {
            for &k in &self.buckets[r * self.cols + c] {
                if let Some(t) = hit(o, d, &self.segments[k as usize]) {
                    best = best.min(t);
                }
            }
            let exit = t_c.min(t_r);
            if best <= exit {
                return best;
            }
            if t_c < t_r {
                let next = c as isize + step_c;
                if next < 0 || next >= self.cols as isize {
                    return best;
                }
                c = next as usize;
                t_c += dt_c;
            } else {
                let next = r as isize + step_r;
                if next < 0 || next >= self.rows as isize {
                    return best;
                }
                r = next as usize;
                t_r += dt_r;
            }
        }
    }

    /// The range seen from `pose` along the beam at `angle` (relative to
    /// the heading).
    pub fn range(&self, pose: &Pose, angle: f64) -> f64 {
        let a = pose.heading + angle;
        self.cast((pose.x, pose.y), (a.cos(), a.sin()))
    }

    /// The nearest wall to `p` within distance `gate`, if any.
    pub fn nearest(&self, p: (f64, f64), gate: f64) -> Option<Nearest> {
        self.nearest_facing(p, gate, None)
    }

    /// [`Walls::nearest`] among the walls whose inner side (the left of a
    /// counter-clockwise ring's edge) faces `viewer`: a beam from the
    /// robot can only hit a wall's face that looks at it, and without this
    /// a point on one face of a thin wall pairs with its other face.
    pub fn nearest_facing(
        &self,
        p: (f64, f64),
        gate: f64,
        viewer: Option<(f64, f64)>,
    ) -> Option<Nearest> {
        let (c0, r0) = self.cell_of((p.0 - gate, p.1 - gate));
        let (c1, r1) = self.cell_of((p.0 + gate, p.1 + gate));
        let mut best: Option<Nearest> = None;
        for r in r0..=r1 {
            for c in c0..=c1 {
                for &k in &self.buckets[r * self.cols + c] {
                    let s = &self.segments[k as usize];
                    if viewer.is_some_and(|v| !faces(s, v)) {
                        continue;
                    }
                    let n = closest(p, s);
                    if n.distance <= gate && best.is_none_or(|b| n.distance < b.distance) {
                        best = Some(n);
                    }
                }
            }
        }
        best
    }

    /// [`Walls::nearest`] by a loop over every wall (the reference).
    pub fn nearest_brute(&self, p: (f64, f64), gate: f64) -> Option<Nearest> {
        self.segments
            .iter()
            .map(|s| closest(p, s))
            .filter(|n| n.distance <= gate)
            .min_by(|a, b| a.distance.total_cmp(&b.distance))
    }

    /// [`Walls::cast`] by a loop over every wall (the reference).
    pub fn cast_brute(&self, o: (f64, f64), d: (f64, f64)) -> f64 {
        self.segments
            .iter()
            .filter_map(|s| hit(o, d, s))
            .fold(f64::INFINITY, f64::min)
    }
}

/// The distance along the ray from `o` in direction `d` (unit) to segment
/// `s`, if the ray crosses it ahead of `o`. Collinear segments are ignored.
pub(crate) fn hit(o: (f64, f64), d: (f64, f64), s: &Segment) -> Option<f64> {
    let e = (s[1].0 - s[0].0, s[1].1 - s[0].1);
    let denom = d.0 * e.1 - d.1 * e.0;
    if denom.abs() <= 1e-15 * (e.0.abs() + e.1.abs()) {
        return None;
    }
    let w = (s[0].0 - o.0, s[0].1 - o.1);
    let t = (w.0 * e.1 - w.1 * e.0) / denom;
    let u = (w.0 * d.1 - w.1 * d.0) / denom;
    (t > 0.0 && (-1e-12..=1.0 + 1e-12).contains(&u)).then_some(t)
}

/// Whether `v` lies strictly left of the directed segment `s`.
fn faces(s: &Segment, v: (f64, f64)) -> bool {
    (s[1].0 - s[0].0) * (v.1 - s[0].1) - (s[1].1 - s[0].1) * (v.0 - s[0].0) > 0.0
}

/// The closest point of segment `s` to `p`.
fn closest(p: (f64, f64), s: &Segment) -> Nearest {
    let e = (s[1].0 - s[0].0, s[1].1 - s[0].1);
    let len2 = e.0 * e.0 + e.1 * e.1;
    let u = if len2 > 0.0 {
        (((p.0 - s[0].0) * e.0 + (p.1 - s[0].1) * e.1) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let q = (s[0].0 + u * e.0, s[0].1 + u * e.1);
    let len = len2.sqrt().max(f64::MIN_POSITIVE);
    Nearest {
        distance: ((p.0 - q.0).powi(2) + (p.1 - q.1).powi(2)).sqrt(),
        point: q,
        normal: (-e.1 / len, e.0 / len),
    }
}
