//! One shard of a run: `wai check --shard I/N` sees the maps of the
//! unsharded run with the same arguments whose position is I modulo N, so
//! that N shards, run anywhere and in any order, see each map of the run
//! exactly once ([`crate::merge`] adds their records up again).
//!
//! The position is taken within each lane of the search
//! ([`crate::stream::Lane`]): with a count, the run has one lane (stream
//! indices 0..count), so shard I holds the indices ≡ I (mod N); with a time
//! budget, every lane (each kind, the fixed maps) is split the same way,
//! so each shard goes through every kind, and the budget is split evenly
//! (each shard runs for budget / N).
//!
//! A shard's record says which shard it is ([`Shards`]): N, the run's
//! arguments, and one [`ShardRun`] entry for itself — its index, maps,
//! wall time, start and end (UTC), the SHA-256 of the binary that ran it
//! and the counterexample files it wrote. A merge ([`crate::merge`])
//! holds the entries of every shard it merged.

use std::fmt;

use serde_json::{json, Value};

use crate::json_read::{array, object, string, uint};
use crate::stream::Lane;

/// Shard `index` of `count` (0 ≤ index < count); `0/1` is the whole run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Shard {
    pub index: u64,
    pub count: u64,
}

impl Shard {
    /// The whole run, unsharded.
    pub const WHOLE: Shard = Shard { index: 0, count: 1 };

    /// Shard `index` of `count`; `None` unless `index < count`.
    pub fn new(index: u64, count: u64) -> Option<Shard> {
        (index < count).then_some(Shard { index, count })
    }

    /// True for [`Shard::WHOLE`].
    pub fn is_whole(&self) -> bool {
        self.count == 1
    }

    /// This shard's part of `lane`: its maps at positions ≡ index (mod
    /// count), in order.
    pub fn of_lane(&self, lane: &Lane) -> Lane {
        let (i, n) = (self.index, self.count);
        Lane {
            name: lane.name.clone(),
            start: lane.start + i * lane.step,
            step: lane.step * n,
            // Positions i, i + n, … below len.
            len: lane.len.map(|len| len.saturating_sub(i).div_ceil(n)),
        }
    }
}

impl fmt::Display for Shard {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}/{}", self.index, self.count)
    }
}

impl std::str::FromStr for Shard {
    type Err = String;

    /// `I/N`, shards numbered from 0 (as Slurm's `--array=0-N-1` and GNU
    /// parallel's `{%}`-free `seq 0 N-1` give them).
    fn from_str(s: &str) -> Result<Shard, String> {
        let (i, n) = s
            .split_once('/')
            .ok_or_else(|| format!("{s:?} is not I/N (shard I of N, from 0)"))?;
        let num = |t: &str| {
            t.trim()
                .parse::<u64>()
                .map_err(|_| format!("{s:?}: {t:?} is not a whole number"))
        };
        let (i, n) = (num(i)?, num(n)?);
        if n == 0 {
            return Err(format!("{s:?}: a run has at least one shard"));
        }
        Shard::new(i, n).ok_or_else(|| {
            format!(
                "{s:?}: shards are numbered from 0 to {}, so {i} is not one of {n}",
                n - 1
            )
        })
    }
}

/// The shards a record holds, of a run split into `count`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Shards {
    /// N: how many shards the run was split into.
    pub count: u64,
    /// The run: the `wai check` command line without `--shard` and the
    /// options that only say where output goes; the same in every shard.
    pub run: String,
    /// The shards held, by increasing index, each once.
    pub present: Vec<ShardRun>,
}

/// One shard's run.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ShardRun {
    /// I, from 0 to N − 1.
    pub index: u64,
    /// Maps the shard checked.
    pub maps: u64,
    /// Its wall time, in seconds.
    pub seconds: u64,
    /// Start and end, UTC, `YYYY-MM-DDTHH:MM:SSZ`.
    pub started: String,
    pub ended: String,
    /// The SHA-256 of the `wai` binary that ran it.
    pub binary: String,
    /// The counterexample files it wrote (paths as it wrote them).
    pub counterexamples: Vec<String>,
}

impl Shards {
    /// The shard indices of the run that this record does not hold.
    pub fn missing(&self) -> Vec<u64> {
        let mut have = self.present.iter().map(|s| s.index).peekable();
        (0..self.count)
            .filter(|i| {
                if have.peek() == Some(i) {
                    have.next();
                    false
                } else {
                    true
                }
            })
            .collect()
    }

    /// As JSON; `missing` is written for readers and checked when read.
    pub fn to_json(&self) -> Value {
        let present: Vec<Value> = self
            .present
            .iter()
            .map(|s| {
                json!({
                    "index": s.index,
                    "maps": s.maps,
                    "seconds": s.seconds,
                    "started": s.started,
                    "ended": s.ended,
                    "binary": s.binary,
                    "counterexamples": s.counterexamples,
                })
            })
            .collect();
        json!({
            "count": self.count,
            "run": self.run,
            "missing": self.missing(),
            "present": present,
        })
    }

    /// Reads the `shards` object at `at`.
    pub fn from_json(v: &Value, at: &str) -> Result<Shards, String> {
        let o = object(v, at)?;
        let at = format!("{at}.");
        let count = uint(o, "count", &at)?;
        if count == 0 {
            return Err(format!("{at}count: a run has at least one shard"));
        }
        let mut present: Vec<ShardRun> = Vec::new();
        for (k, s) in array(o, "present", &at)?.iter().enumerate() {
            let here = format!("{at}present[{k}]");
            let s = object(s, &here)?;
            let here = format!("{here}.");
            let files = array(s, "counterexamples", &here)?
                .iter()
                .map(|f| {
                    f.as_str().map(str::to_owned).ok_or_else(|| {
                        format!("{here}counterexamples: expected file names, found {f}")
                    })
                })
                .collect::<Result<Vec<_>, String>>()?;
            let run = ShardRun {
                index: uint(s, "index", &here)?,
                maps: uint(s, "maps", &here)?,
                seconds: uint(s, "seconds", &here)?,
                started: string(s, "started", &here)?,
                ended: string(s, "ended", &here)?,
                binary: string(s, "binary", &here)?,
                counterexamples: files,
            };
            if run.index >= count {
                return Err(format!(
                    "{here}index: shard {} of a run of {count} shards (numbered from 0)",
                    run.index
                ));
            }
            if present.last().is_some_and(|p| p.index >= run.index) {
                return Err(format!(
                    "{here}index: shards are listed once each by increasing index, and {} is not",
                    run.index
                ));
            }
            present.push(run);
        }
        let shards = Shards {
            count,
            run: string(o, "run", &at)?,
            present,
        };
        let written: Vec<u64> = array(o, "missing", &at)?
            .iter()
            .map(|m| m.as_u64().unwrap_or(u64::MAX))
            .collect();
        if written != shards.missing() {
            return Err(format!(
                "{at}missing: says {written:?}, but the shards present leave {:?} missing",
                shards.missing()
            ));
        }
        Ok(shards)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_and_refuses_clearly() {
        assert_eq!("2/4".parse::<Shard>(), Ok(Shard { index: 2, count: 4 }));
        assert_eq!("0/1".parse::<Shard>(), Ok(Shard::WHOLE));
        for (bad, needle) in [
            ("4/4", "from 0 to 3"),
            ("1/0", "at least one"),
            ("x/2", "not a whole number"),
            ("3", "not I/N"),
            ("-1/2", "not a whole number"),
        ] {
            let err = bad.parse::<Shard>().unwrap_err();
            assert!(err.contains(needle), "{bad}: {err}");
        }
        assert_eq!(Shard::new(2, 4).unwrap().to_string(), "2/4");
    }

    #[test]
    fn the_shards_of_a_lane_partition_it() {
        for (len, step, start) in [
            (Some(10), 1, 0),
            (Some(7), 3, 2),
            (Some(0), 1, 0),
            (None, 4, 1),
        ] {
            let lane = Lane {
                name: "k".into(),
                start,
                step,
                len,
            };
            for n in 1..=5u64 {
                let mut seen: Vec<u64> = Vec::new();
                for i in 0..n {
                    let part = Shard::new(i, n).unwrap().of_lane(&lane);
                    // Up to 40 positions of endless lanes.
                    let mut j = 0;
                    while let Some(index) = part.index(j) {
                        if len.is_none() && index >= start + 40 * step {
                            break;
                        }
                        seen.push(index);
                        j += 1;
                    }
                }
                seen.sort_unstable();
                let whole: Vec<u64> = (0..len.unwrap_or(40)).map(|j| start + j * step).collect();
                assert_eq!(seen, whole, "len {len:?} step {step} into {n}");
            }
        }
    }
}
