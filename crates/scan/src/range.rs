//! The sensing range a scan is read with (the scan model of the crate's
//! docs, sec. 6.1 and eq. 6.8).
//!
//! A lost return — a beam with no range — says only that nothing stood
//! within the sensor's range R along that beam: the wall is *beyond R*,
//! never "at infinity". Every stage reads it so: the scan's polygon V_S
//! and the map's PCFs are both capped at one range C (eq. 6.8), so that a
//! lost beam reads C on both sides at the true pose, and the pose score
//! charges a lost beam only by how far the map's range there falls short
//! of C. That is sound for every C ≤ R, and sharpest at C = R.
//!
//! R is what the scan's source states (`sensor.max_range`, ROS
//! `range_max`) when it states one. When it does not, the data give a
//! lower bound: every return lies within R, so R is at least the longest
//! return L, and C = L is read — sound whatever R is, but blind to walls
//! between L and R, so the answer set may widen; [`SensingRange::warnings`]
//! says so. A stated range can also be loose (ROS drivers state the
//! sensor's nominal range, not where returns really stop): when the map
//! at the best pose puts walls within the stated range along lost beams,
//! the localizer reads the scan again with C = L
//! ([`SensingRange::loosened`]) and says why.
//!
//! When every beam returned, no range is needed: nothing is capped.

use serde_json::{json, Value};

use crate::Scan;

/// Lost beams that must face a wall well within the stated range at the
/// best pose before the statement is called loose: at least this many, and
/// at least [`LOOSE_SHARE`] of the lost beams.
pub const LOOSE_MIN_BEAMS: usize = 3;
pub const LOOSE_SHARE: f64 = 0.05;

/// Where the range C that lost beams are read against comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RangeBasis {
    /// Every beam returned: no range is needed, nothing is capped.
    NotNeeded,
    /// The range the scan's source states.
    Stated,
    /// No range stated: the longest return, a lower bound of the sensor's.
    LongestReturn,
    /// A range was stated, but the map at the best pose contradicted it
    /// (walls within it along lost beams): the longest return instead.
    LooseStatement,
}

impl RangeBasis {
    pub fn label(self) -> &'static str {
        match self {
            RangeBasis::NotNeeded => "not needed",
            RangeBasis::Stated => "stated",
            RangeBasis::LongestReturn => "longest return",
            RangeBasis::LooseStatement => "longest return (stated range loose)",
        }
    }
}

/// The sensing range of one scan: what was stated, what the data show,
/// and the range C that lost beams were read against.
#[derive(Debug, Clone, PartialEq)]
pub struct SensingRange {
    /// The maximum range the scan's source states.
    pub stated: Option<f64>,
    /// The longest return: a lower bound of the sensor's range.
    pub longest_return: Option<f64>,
    /// Beams without a return.
    pub lost: usize,
    pub beams: usize,
    /// C: lost beams read as "beyond C", PCFs capped at C (∞: uncapped).
    pub cap: f64,
    pub basis: RangeBasis,
    /// For [`RangeBasis::LooseStatement`]: how many lost beams faced a wall
    /// within the stated range at the best pose.
    pub contradicted: usize,
}

impl SensingRange {
    /// The range `scan` is read with before any pose is known: its stated
    /// range if it has lost beams and states one, else its longest return
    /// if it has lost beams, else none.
    pub fn of(scan: &Scan) -> SensingRange {
        let stated = scan.max_range.filter(|r| r.is_finite() && *r > 0.0);
        let longest_return = scan
            .ranges
            .iter()
            .flatten()
            .copied()
            .filter(|r| r.is_finite())
            .fold(None, |m: Option<f64>, r| Some(m.map_or(r, |m| m.max(r))));
        let lost = scan.ranges.iter().filter(|r| r.is_none()).count();
        let (cap, basis) = match (lost, stated, longest_return) {
            (0, _, _) => (f64::INFINITY, RangeBasis::NotNeeded),
            (_, Some(r), _) => (r, RangeBasis::Stated),
            (_, None, Some(l)) if l > 0.0 => (l, RangeBasis::LongestReturn),
            // No usable return at all: such a scan is not localizable
            // (`Scan::localizable`); nothing can be read against a range.
            _ => (f64::INFINITY, RangeBasis::LongestReturn),
        };
        SensingRange {
            stated,
            longest_return,
            lost,
            beams: scan.ranges.len(),
            cap,
            basis,
            contradicted: 0,
        }
    }

    /// This range read as loose: `contradicted` lost beams faced a wall
    /// within the stated range at the best pose, so C becomes the longest
    /// return. `None` when that would not lower C.
    pub fn loosened(&self, contradicted: usize) -> Option<SensingRange> {
        let l = self.longest_return.filter(|l| *l > 0.0)?;
        (l < self.cap).then(|| SensingRange {
            cap: l,
            basis: RangeBasis::LooseStatement,
            contradicted,
            ..self.clone()
        })
    }

    /// Whether `contradicted` of this scan's lost beams facing a wall
    /// within the stated range is enough to call the statement loose.
    pub fn is_contradicted_by(&self, contradicted: usize) -> bool {
        contradicted >= LOOSE_MIN_BEAMS && contradicted as f64 >= LOOSE_SHARE * self.lost as f64
    }

    /// What the reader of an answer must know: the range was not stated
    /// and only bounded, it was loose, or returns lie beyond it.
    pub fn warnings(&self) -> Vec<String> {
        let mut out = Vec::new();
        match self.basis {
            RangeBasis::LongestReturn if self.cap.is_finite() => out.push(format!(
                "the scan states no maximum range; its {} beams without a return were read \
                 as \"beyond {:.3} m\", the longest return, which is only a lower bound of \
                 the sensor's range: places that differ only beyond it look alike, and the \
                 answer set may be wider than a stated range would give (state it: \
                 sensor.max_range, range_max, or --max-range)",
                self.lost, self.cap
            )),
            RangeBasis::LooseStatement => out.push(format!(
                "the stated maximum range {:.3} m looks loose: at the best pose {} of the {} \
                 beams without a return face a wall within it; the scan was read again with \
                 the longest return, {:.3} m, as its range",
                self.stated.unwrap_or(f64::NAN),
                self.contradicted,
                self.lost,
                self.cap
            )),
            _ => {}
        }
        if let (Some(r), Some(l)) = (self.stated, self.longest_return) {
            if l > r * 1.05 {
                out.push(format!(
                    "the longest return, {l:.3} m, lies beyond the stated maximum range \
                     {r:.3} m: returns were capped at the stated range"
                ));
            }
        }
        out
    }

    /// One line for a text answer.
    pub fn describe(&self) -> String {
        let stated = self
            .stated
            .map_or("not stated".to_owned(), |r| format!("{r} m stated"));
        let longest = self
            .longest_return
            .map_or(String::new(), |l| format!(", longest return {l:.3} m"));
        let read = match self.basis {
            RangeBasis::NotNeeded => "every beam returned, nothing capped".to_owned(),
            _ => format!(
                "{} beams without a return read as beyond {:.3} m ({})",
                self.lost,
                self.cap,
                self.basis.label()
            ),
        };
        format!("sensing range: {stated}{longest}; {read}")
    }

    pub fn to_json(&self) -> Value {
        json!({
            "stated_max_range": self.stated,
            "longest_return": self.longest_return,
            "beams": self.beams,
            "beams_without_return": self.lost,
            "read_as_beyond": self.cap.is_finite().then_some(self.cap),
            "basis": self.basis.label(),
            "contradicted_beams": self.contradicted,
        })
    }
}
