//! The run record: what one checker run found, kept as JSON so that a fresh
//! clone can show it (`wai claims`, the claims table of `README.md`) without
//! running the checkers again.
//!
//! A [`RunRecord`] says which run it was (command line, commit, date, wall
//! time, maps per kind) and, per claim the run covered, a [`ClaimRecord`]:
//! instances examined, violations (the checker's known failures counted
//! apart), the instances per case of the claim (every declared case, hit or
//! not), the largest ratio measured with the name of its map, and the
//! checker's further named counts. It is built from a driver [`Summary`] by
//! [`RunRecord::from_summary`] and stored in `lemmas/last-run.json` by
//! [`RunRecord::write`].
//!
//! # The format
//!
//! ```json
//! {
//!   "version": 2,
//!   "command": "wai check --budget 10m",
//!   "commit": "a338b73",
//!   "date": "2025-01-31",
//!   "seconds": 600,
//!   "maps": 60,
//!   "map_kinds": [{"kind": "random-simple-star", "maps": 10}],
//!   "claims": [{"id": "T5.17", "examined": 60, "violations": 0,
//!               "known_failures": 0, "max_ratio": "80/41",
//!               "max_ratio_approx": 1.951219512195122,
//!               "max_ratio_map": "random-simple-star n=8 seed=0",
//!               "cases": {"convex map": 12}, "counts": {}}]
//! }
//! ```
//!
//! `max_ratio` is exact (a rational as a string, `null` when the claim
//! measures no ratio); `max_ratio_approx` is written beside it for readers
//! and ignored when read back. Three fields are optional, written when
//! known and absent from older records: a kind's `first` (the stream index
//! of its first map) and a claim's `max_ratio_map_index` (the stream index
//! of the ratio's map), which let a merge of shards order kinds and break
//! ties between equal ratios as the unsharded run does; and `shards`, the
//! shards of a run that a shard's record or a merge holds
//! ([`crate::shard::Shards`]). `digest` (not shown above) seals the
//! record: the SHA-256 of its other fields as written; a record whose
//! content no longer matches it (edited by hand) is refused.
//!
//! # Edge cases
//!
//! A claim the run covered but whose checker examined nothing has
//! `examined: 0`: the run did not test it, and readers must say so. A claim
//! absent from `claims` was not covered by the run at all. Reading checks
//! the shape and the arithmetic (violations and known failures never exceed
//! `examined`, no claim twice) and says what is wrong and where; it never
//! panics.
//!
//! ```
//! use wai_hunt::record::RunRecord;
//! let text = r#"{"version": 2, "command": "c", "commit": "x", "date": "2025-01-31",
//!   "seconds": 1, "maps": 0, "map_kinds": [],
//!   "claims": [{"id": "T5.17", "examined": 0, "violations": 0, "known_failures": 0,
//!               "max_ratio": null, "max_ratio_map": null, "cases": {}, "counts": {}}]}"#;
//! // Not written by `wai check`: no digest.
//! let err = RunRecord::from_json(&serde_json::from_str(text).unwrap()).unwrap_err();
//! assert!(err.starts_with("digest: missing"), "{err}");
//! let bad = text.replace(r#""examined": 0"#, r#""examined": -1"#);
//! let err = RunRecord::from_json(&serde_json::from_str(&bad).unwrap()).unwrap_err();
//! assert!(err.contains("claims[0].examined"), "{err}");
//! ```

use std::collections::BTreeMap;
use std::path::Path;

use rug::Rational;
use serde_json::{json, Map as Object, Value};

use crate::json_read::{array, field, kind_of, object, optional_uint, string, uint};
use crate::shard::Shards;
use crate::summary::Summary;

/// The version written in `"version"`; reading refuses any other.
pub const FORMAT_VERSION: u64 = 2;

/// What one checker run found.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct RunRecord {
    /// The command line that produced it.
    pub command: String,
    /// The commit of the binary (may end in `+dirty`).
    pub commit: String,
    /// The day of the run, `YYYY-MM-DD` (UTC).
    pub date: String,
    /// Wall time of the run, in seconds.
    pub seconds: u64,
    /// Maps examined.
    pub maps: u64,
    /// Maps per kind (random kind, family, layout…), in the order of their
    /// first map in the stream.
    pub map_kinds: Vec<KindCount>,
    /// One record per claim the run covered, in the order of the run.
    pub claims: Vec<ClaimRecord>,
    /// For a shard's record or a merge of shards: which shards of which
    /// run it holds ([`crate::merge`]); `None` for an unsharded run.
    pub shards: Option<Shards>,
}

/// How many maps of one kind a run saw.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct KindCount {
    pub kind: String,
    pub maps: u64,
    /// The stream index of the kind's first map (which orders the kinds
    /// of a merge as in the unsharded run); `None` in older records.
    pub first: Option<u64>,
}

impl KindCount {
    /// `maps` maps of `kind`, first index unknown.
    pub fn new(kind: impl Into<String>, maps: u64) -> KindCount {
        KindCount {
            kind: kind.into(),
            maps,
            first: None,
        }
    }
}

/// What one run found about one claim.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ClaimRecord {
    /// The claim's id in [`wai_lemmas::CLAIMS`].
    pub id: String,
    /// Instances examined over the run; 0 means the run did not test it.
    pub examined: u64,
    /// Violations other than the known failures.
    pub violations: u64,
    /// Violations that are the checker's known failures, counted apart.
    pub known_failures: u64,
    /// The run's largest [`wai_lemmas::Report::largest`] ratio, exact.
    pub max_ratio: Option<Rational>,
    /// The name of the map of `max_ratio` (`map #i` for an unnamed map).
    pub max_ratio_map: Option<String>,
    /// That map's index in the stream: of two maps with the same ratio,
    /// a run keeps the first, and so does a merge of shards. `None` in
    /// older records.
    pub max_ratio_index: Option<u64>,
    /// Instances per case of the claim ([`wai_lemmas::Report::cases`]):
    /// every case the checker declares, 0 where the run never hit it.
    pub cases: BTreeMap<String, u64>,
    /// The checkers' further named counts ([`wai_lemmas::Report::counts`]), summed.
    pub counts: BTreeMap<String, u64>,
}

impl RunRecord {
    /// The record of a driver run: one [`ClaimRecord`] per tally of
    /// `summary`, in its order, with the violations split by
    /// the checkers' known failures. The rest says which run it was.
    pub fn from_summary(
        summary: &Summary,
        command: String,
        commit: String,
        date: String,
        seconds: u64,
        map_kinds: Vec<KindCount>,
    ) -> RunRecord {
        let claims = summary
            .tallies
            .iter()
            .map(|t| {
                let known = t.violations.iter().filter(|v| v.known).count() as u64;
                ClaimRecord {
                    id: t.claim.to_owned(),
                    examined: t.examined,
                    violations: t.violations.len() as u64 - known,
                    known_failures: known,
                    max_ratio: t.largest.as_ref().map(|l| l.largest.ratio.clone()),
                    max_ratio_map: t.largest.as_ref().map(|l| {
                        l.map_name
                            .clone()
                            .unwrap_or_else(|| format!("map #{}", l.map_index))
                    }),
                    max_ratio_index: t.largest.as_ref().map(|l| l.map_index as u64),
                    cases: t.cases.iter().map(|(k, v)| ((*k).to_owned(), *v)).collect(),
                    counts: t
                        .counts
                        .iter()
                        .map(|(k, v)| ((*k).to_owned(), *v))
                        .collect(),
                }
            })
            .collect();
        RunRecord {
            command,
            commit,
            date,
            seconds,
            maps: summary.maps as u64,
            map_kinds,
            claims,
            shards: None,
        }
    }

    /// True if the record holds some shards of a run but not all: a
    /// partial merge, or one shard's record.
    pub fn is_partial(&self) -> bool {
        self.shards
            .as_ref()
            .is_some_and(|s| !s.missing().is_empty())
    }

    /// The record of claim `id`, if the run covered it.
    pub fn claim(&self, id: &str) -> Option<&ClaimRecord> {
        self.claims.iter().find(|c| c.id == id)
    }

    /// The record as JSON (the format of the module doc), sealed with its
    /// `digest`.
    pub fn to_json(&self) -> Value {
        let mut v = self.body();
        v["digest"] = json!(digest_of(&v));
        v
    }

    /// The record without its digest.
    fn body(&self) -> Value {
        let kinds: Vec<Value> = self
            .map_kinds
            .iter()
            .map(|k| {
                let mut v = json!({"kind": k.kind, "maps": k.maps});
                if let Some(first) = k.first {
                    v["first"] = json!(first);
                }
                v
            })
            .collect();
        let claims: Vec<Value> = self.claims.iter().map(ClaimRecord::to_json).collect();
        let mut body = json!({
            "version": FORMAT_VERSION,
            "command": self.command,
            "commit": self.commit,
            "date": self.date,
            "seconds": self.seconds,
            "maps": self.maps,
            "map_kinds": kinds,
            "claims": claims,
        });
        // Optional fields are written only when present, so older records
        // keep their digests.
        if let Some(shards) = &self.shards {
            body["shards"] = shards.to_json();
        }
        body
    }

    /// Reads a record written by [`RunRecord::to_json`]; the error names the
    /// field (`claims[3].examined`) and what is wrong with it. The record
    /// read must have the `digest` it was written with: a record edited
    /// by hand is refused.
    pub fn from_json(v: &Value) -> Result<RunRecord, String> {
        let record = RunRecord::from_json_unsealed(v)?;
        let stored = match object(v, "the record")?.get("digest") {
            Some(Value::String(d)) => d.clone(),
            Some(other) => return Err(format!("digest: expected a string, found {}", kind_of(other))),
            None => {
                return Err(
                    "digest: missing; a run record is written by `wai check --record`, sealed with the digest of its content"
                        .to_string(),
                )
            }
        };
        let expected = digest_of(&record.body());
        if stored != expected {
            return Err(format!(
                "digest: the content was changed after `wai check` wrote it (the file says {stored}, its content has {expected}); re-run the recorded command to get a true record"
            ));
        }
        Ok(record)
    }

    /// [`RunRecord::from_json`] without the digest check: for records made
    /// by hand (tests, examples), which [`RunRecord::to_json`] then seals;
    /// never for a stored record.
    pub fn from_json_unsealed(v: &Value) -> Result<RunRecord, String> {
        let top = object(v, "the record")?;
        let version = uint(top, "version", "")?;
        if version != FORMAT_VERSION {
            return Err(format!(
                "version: this build reads run records of version {FORMAT_VERSION}, not {version}"
            ));
        }
        let date = string(top, "date", "")?;
        if !is_date(&date) {
            return Err(format!("date: expected YYYY-MM-DD, found {date:?}"));
        }
        let map_kinds = array(top, "map_kinds", "")?
            .iter()
            .enumerate()
            .map(|(i, k)| {
                let at = format!("map_kinds[{i}].");
                let k = object(k, &at[..at.len() - 1])?;
                Ok(KindCount {
                    kind: string(k, "kind", &at)?,
                    maps: uint(k, "maps", &at)?,
                    first: optional_uint(k, "first", &at)?,
                })
            })
            .collect::<Result<Vec<_>, String>>()?;
        let mut claims: Vec<ClaimRecord> = Vec::new();
        for (i, c) in array(top, "claims", "")?.iter().enumerate() {
            let claim = ClaimRecord::from_json(c, &format!("claims[{i}]"))?;
            if claims.iter().any(|d| d.id == claim.id) {
                return Err(format!("claims[{i}].id: claim {} appears twice", claim.id));
            }
            claims.push(claim);
        }
        Ok(RunRecord {
            command: string(top, "command", "")?,
            commit: string(top, "commit", "")?,
            date,
            seconds: uint(top, "seconds", "")?,
            maps: uint(top, "maps", "")?,
            map_kinds,
            claims,
            shards: match top.get("shards") {
                None => None,
                Some(v) => Some(Shards::from_json(v, "shards")?),
            },
        })
    }

    /// Reads the record stored at `path`; the error starts with the path.
    pub fn read(path: &Path) -> Result<RunRecord, String> {
        let shown = path.display();
        let text = std::fs::read_to_string(path)
            .map_err(|e| format!("{shown}: cannot read the run record: {e}"))?;
        let v: Value = serde_json::from_str(&text)
            .map_err(|e| format!("{shown}: malformed JSON in the run record: {e}"))?;
        RunRecord::from_json(&v).map_err(|e| format!("{shown}: not a run record: {e}"))
    }

    /// Writes the record to `path` as pretty JSON with a trailing newline
    /// (keys in a fixed order, so equal records give equal files), through
    /// a temporary file beside it so a failed write leaves the old one.
    pub fn write(&self, path: &Path) -> Result<(), String> {
        let mut text = serde_json::to_string_pretty(&self.to_json())
            .map_err(|e| format!("{}: cannot serialise the run record: {e}", path.display()))?;
        text.push('\n');
        write_whole(path, text.as_bytes())
            .map_err(|e| format!("{}: cannot write the run record: {e}", path.display()))
    }
}

impl ClaimRecord {
    /// The claim as JSON.
    fn to_json(&self) -> Value {
        let mut v = json!({
            "id": self.id,
            "examined": self.examined,
            "violations": self.violations,
            "known_failures": self.known_failures,
            "max_ratio": self.max_ratio.as_ref().map(Rational::to_string),
            "max_ratio_approx": self.max_ratio.as_ref().and_then(ratio_approx),
            "max_ratio_map": self.max_ratio_map,
            "cases": self.cases,
            "counts": self.counts,
        });
        if let Some(i) = self.max_ratio_index {
            v["max_ratio_map_index"] = json!(i);
        }
        v
    }

    /// Reads one entry of `claims`; `at` is its place (`claims[3]`).
    fn from_json(v: &Value, at: &str) -> Result<ClaimRecord, String> {
        let c = object(v, at)?;
        let at = format!("{at}.");
        let max_ratio = match field(c, "max_ratio", &at)? {
            Value::Null => None,
            Value::String(s) => Some(s.parse::<Rational>().map_err(|e| {
                format!("{at}max_ratio: {s:?} is not an exact rational like \"80/41\": {e}")
            })?),
            other => {
                return Err(format!(
                    "{at}max_ratio: expected a string like \"80/41\" or null, found {other}"
                ))
            }
        };
        let max_ratio_map = match field(c, "max_ratio_map", &at)? {
            Value::Null => None,
            Value::String(s) => Some(s.clone()),
            other => {
                return Err(format!(
                    "{at}max_ratio_map: expected a string or null, found {other}"
                ))
            }
        };
        let counts = named_counts(c, "counts", &at)?;
        let cases = named_counts(c, "cases", &at)?;
        let record = ClaimRecord {
            id: string(c, "id", &at)?,
            examined: uint(c, "examined", &at)?,
            violations: uint(c, "violations", &at)?,
            known_failures: uint(c, "known_failures", &at)?,
            max_ratio,
            max_ratio_map,
            max_ratio_index: optional_uint(c, "max_ratio_map_index", &at)?,
            cases,
            counts,
        };
        if record.id.is_empty() {
            return Err(format!("{at}id: empty"));
        }
        let found = u128::from(record.violations) + u128::from(record.known_failures);
        if found > u128::from(record.examined) {
            return Err(format!(
                "{at}examined: claim {} has {} violations and {} known failures but only {} instances examined",
                record.id, record.violations, record.known_failures, record.examined
            ));
        }
        Ok(record)
    }
}

/// An object of named counts (`counts`, `cases`) of a claim at `at`.
fn named_counts(
    c: &Object<String, Value>,
    key: &str,
    at: &str,
) -> Result<BTreeMap<String, u64>, String> {
    match field(c, key, at)? {
        Value::Object(o) => o
            .keys()
            .map(|k| Ok((k.clone(), uint(o, k, &format!("{at}{key}."))?)))
            .collect(),
        other => Err(format!("{at}{key}: expected an object, found {other}")),
    }
}

/// The digest of a record's body: of its compact JSON as this build
/// writes it from what it read (so layout and the ignored
/// `max_ratio_approx` do not count; every field that is read does).
fn digest_of(body: &Value) -> String {
    wai_map::digest::sha256(body.to_string().as_bytes())
}

/// The ratio as a JSON number, for readers only (`null` beyond `f64`).
fn ratio_approx(r: &Rational) -> Option<Value> {
    serde_json::Number::from_f64(r.to_f64()).map(Value::Number)
}

/// True if `s` has the shape `YYYY-MM-DD` with a month 01–12 and a day 01–31.
fn is_date(s: &str) -> bool {
    let b = s.as_bytes();
    let digits = |r: std::ops::Range<usize>| b[r].iter().all(u8::is_ascii_digit);
    if b.len() != 10 || b[4] != b'-' || b[7] != b'-' || !digits(0..4) {
        return false;
    }
    if !digits(5..7) || !digits(8..10) {
        return false;
    }
    let month = (b[5] - b'0') * 10 + (b[6] - b'0');
    let day = (b[8] - b'0') * 10 + (b[9] - b'0');
    (1..=12).contains(&month) && (1..=31).contains(&day)
}

/// Writes `bytes` to `path` whole or not at all: to `PATH.tmp` beside it,
/// then renamed over it, so a process killed while writing (a cancelled
/// shard) leaves the old file or none, never half of one.
pub fn write_whole(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let mut tmp = path.as_os_str().to_owned();
    tmp.push(".tmp");
    let tmp = std::path::PathBuf::from(tmp);
    std::fs::write(&tmp, bytes).and_then(|()| std::fs::rename(&tmp, path))
}

#[cfg(test)]
mod tests {
    use super::*;
    use wai_exact::Point;
    use wai_lemmas::{Checker, Report, Violation};
    use wai_map::Map;

    fn map(ring: &[(i128, i128)]) -> Map {
        let ring = ring.iter().map(|&(x, y)| Point::new(x, y)).collect();
        Map::from_ring(ring).expect("test map is valid").0
    }

    fn sample() -> RunRecord {
        RunRecord {
            command: "stress --maps 2".to_owned(),
            commit: "a338b73+dirty".to_owned(),
            date: "2025-01-31".to_owned(),
            seconds: 12,
            maps: 2,
            map_kinds: vec![
                KindCount::new("random-simple-star", 1),
                KindCount {
                    first: Some(1),
                    ..KindCount::new("orth", 1)
                },
            ],
            claims: vec![
                ClaimRecord {
                    id: "T5.17".to_owned(),
                    examined: 2,
                    violations: 0,
                    known_failures: 0,
                    max_ratio: Some(Rational::from((80, 41))),
                    max_ratio_map: Some("orth n=8 seed=1".to_owned()),
                    max_ratio_index: Some(1),
                    cases: BTreeMap::from([("convex".to_owned(), 1), ("other".to_owned(), 0)]),
                    counts: BTreeMap::from([("largest".to_owned(), 3)]),
                },
                ClaimRecord {
                    id: "A3.6".to_owned(),
                    examined: 10,
                    violations: 1,
                    known_failures: 4,
                    max_ratio: None,
                    max_ratio_map: None,
                    max_ratio_index: None,
                    cases: BTreeMap::new(),
                    counts: BTreeMap::new(),
                },
                ClaimRecord {
                    id: "L4.6".to_owned(),
                    examined: 0,
                    violations: 0,
                    known_failures: 0,
                    max_ratio: None,
                    max_ratio_map: None,
                    max_ratio_index: None,
                    cases: BTreeMap::new(),
                    counts: BTreeMap::new(),
                },
            ],
            shards: None,
        }
    }

    #[test]
    fn json_round_trip_is_exact() {
        let r = sample();
        let v = r.to_json();
        assert_eq!(v["claims"][0]["max_ratio"], "80/41");
        let approx = v["claims"][0]["max_ratio_approx"]
            .as_f64()
            .expect("a number");
        assert!(approx > 1.95 && approx < 1.952, "{approx}");
        assert!(v["claims"][1]["max_ratio"].is_null());
        assert_eq!(RunRecord::from_json(&v), Ok(r.clone()));
        assert_eq!(r.claim("A3.6").map(|c| c.known_failures), Some(4));
        assert!(r.claim("T4.2").is_none());
    }

    #[test]
    fn write_and_read_round_trip_deterministically() {
        let dir = std::env::temp_dir().join(format!("wai-record-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("run.json");
        let r = sample();
        r.write(&path).unwrap();
        let first = std::fs::read_to_string(&path).unwrap();
        assert!(first.ends_with("}\n"), "{first}");
        assert_eq!(RunRecord::read(&path), Ok(r.clone()));
        RunRecord::read(&path).unwrap().write(&path).unwrap();
        assert_eq!(std::fs::read_to_string(&path).unwrap(), first);
        std::fs::remove_dir_all(dir).ok();
    }

    /// `edit` applied to the sample's JSON must be refused with an error
    /// containing `needle`.
    fn check_refused(edit: impl FnOnce(&mut Value), needle: &str) {
        let mut v = sample().to_json();
        edit(&mut v);
        let err = RunRecord::from_json(&v).expect_err("malformed record accepted");
        assert!(err.contains(needle), "{needle:?} missing from: {err}");
    }

    #[test]
    fn edited_records_are_refused() {
        let sealed = sample().to_json();
        assert!(RunRecord::from_json(&sealed).is_ok());
        // A count raised by hand, still consistent in itself.
        let mut more = sealed.clone();
        let examined = more["claims"][0]["examined"].as_u64().unwrap();
        more["claims"][0]["examined"] = json!(examined + 1000);
        let err = RunRecord::from_json(&more).unwrap_err();
        assert!(err.starts_with("digest: the content was changed"), "{err}");
        // Another command line, or the digest gone.
        let mut other = sealed.clone();
        other["command"] = json!("wai check --budget 10h");
        assert!(RunRecord::from_json(&other)
            .unwrap_err()
            .starts_with("digest:"));
        let mut bare = sealed.clone();
        bare.as_object_mut().unwrap().remove("digest");
        let err = RunRecord::from_json(&bare).unwrap_err();
        assert!(err.starts_with("digest: missing"), "{err}");
        // Only what is read counts: the approximation beside a ratio and
        // the layout may change.
        let mut approx = sealed.clone();
        for c in approx["claims"].as_array_mut().unwrap() {
            if c["max_ratio_approx"].is_number() {
                c["max_ratio_approx"] = json!(0.5);
            }
        }
        assert!(RunRecord::from_json(&approx).is_ok());
    }

    #[test]
    fn malformed_records_are_clear_errors() {
        check_refused(
            |v| *v = json!([1, 2]),
            "expected a JSON object, found an array",
        );
        check_refused(|v| v["version"] = json!(1), "version 2, not 1");
        check_refused(
            |v| v["claims"][0]["cases"]["convex"] = json!(-2),
            "claims[0].cases.convex: expected a non-negative integer",
        );
        check_refused(
            |v| {
                v.as_object_mut().unwrap().remove("command");
            },
            "command: missing",
        );
        check_refused(
            |v| v["date"] = json!("31.1.2025"),
            "date: expected YYYY-MM-DD",
        );
        check_refused(
            |v| v["date"] = json!("2025-13-01"),
            "date: expected YYYY-MM-DD",
        );
        check_refused(
            |v| v["maps"] = json!(-1),
            "maps: expected a non-negative integer",
        );
        check_refused(
            |v| v["seconds"] = json!(1.5),
            "seconds: expected a non-negative",
        );
        check_refused(
            |v| v["map_kinds"] = json!({}),
            "map_kinds: expected an array",
        );
        check_refused(
            |v| v["map_kinds"][1] = json!(3),
            "map_kinds[1]: expected a JSON object",
        );
        check_refused(
            |v| v["claims"][1]["examined"] = json!("ten"),
            "claims[1].examined: expected a non-negative integer, found \"ten\"",
        );
        check_refused(
            |v| v["claims"][0]["max_ratio"] = json!("1/0"),
            "claims[0].max_ratio: \"1/0\" is not an exact rational",
        );
        check_refused(
            |v| v["claims"][0]["max_ratio"] = json!(1.95),
            "claims[0].max_ratio: expected a string",
        );
        check_refused(
            |v| v["claims"][2]["counts"] = json!({"x": "y"}),
            "claims[2].counts.x: expected a non-negative integer",
        );
        check_refused(
            |v| v["claims"][1]["violations"] = json!(7),
            "claim A3.6 has 7 violations and 4 known failures but only 10",
        );
        check_refused(
            |v| v["claims"][2]["id"] = json!("T5.17"),
            "claims[2].id: claim T5.17 appears twice",
        );
        check_refused(|v| v["claims"][0]["id"] = json!(""), "claims[0].id: empty");
    }

    #[test]
    fn unreadable_files_are_clear_errors() {
        let err = RunRecord::read(Path::new("/nonexistent/run.json")).unwrap_err();
        assert!(
            err.starts_with("/nonexistent/run.json: cannot read"),
            "{err}"
        );
        let dir = std::env::temp_dir().join(format!("wai-record-bad-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("bad.json");
        std::fs::write(&path, "{\"version\": 2,").unwrap();
        let err = RunRecord::read(&path).unwrap_err();
        assert!(err.contains("malformed JSON"), "{err}");
        std::fs::remove_dir_all(dir).ok();
    }

    #[test]
    fn from_summary_of_a_real_run() {
        let l = map(&[(0, 0), (6, 0), (6, 2), (2, 2), (2, 6), (0, 6)]).with_name("L");
        let square = map(&[(0, 0), (4, 0), (4, 4), (0, 4)]).with_name("square");
        let summary = crate::summary::run(&[wai_lemmas::ch5::t5_17::CHECKER], [l, square]);
        let r = RunRecord::from_summary(
            &summary,
            "test".to_owned(),
            "c0ffee".to_owned(),
            "2025-01-31".to_owned(),
            0,
            vec![KindCount::new("hand-made", 2)],
        );
        assert_eq!(r.maps, 2);
        assert_eq!(r.claims.len(), 1);
        let c = r.claim("T5.17").expect("T5.17 ran");
        assert_eq!((c.examined, c.violations, c.known_failures), (2, 0, 0));
        // A convex map's one cell: |EC| / (n + r²) = 2n / n.
        assert_eq!(c.max_ratio, Some(Rational::from(2)));
        assert_eq!(c.max_ratio_map.as_deref(), Some("square"));
        assert_eq!(RunRecord::from_json(&r.to_json()), Ok(r));
    }

    /// Planted: A3.6 "fails" on every map, once with a known failure (a
    /// 1-cell) and, on triangles, once with a wrong cell.
    const PLANTED_A36: Checker = Checker {
        check: |study| {
            let mut report = Report::new("A3.6");
            let known = json!({"kind": wai_lemmas::ch3::a3_6::FAILS_ON_1_CELL});
            report.record(Some(Violation::with_data("planted: a 1-cell", known)));
            let wrong = json!({"kind": wai_lemmas::ch3::a3_6::WRONG_CELL});
            report.record(
                (study.map().n() == 3).then(|| Violation::with_data("planted: wrong", wrong)),
            );
            report
        },
        ..wai_lemmas::ch3::a3_6::CHECKER
    };

    #[test]
    fn known_failures_are_counted_apart() {
        let triangle = map(&[(0, 0), (4, 0), (0, 4)]);
        let square = map(&[(0, 0), (4, 0), (4, 4), (0, 4)]);
        let summary = crate::summary::run(&[PLANTED_A36], [triangle, square]);
        let r = RunRecord::from_summary(
            &summary,
            "planted".to_owned(),
            "x".to_owned(),
            "2025-01-31".to_owned(),
            0,
            Vec::new(),
        );
        let c = r.claim("A3.6").expect("A3.6 ran");
        assert_eq!((c.examined, c.violations, c.known_failures), (4, 1, 2));
        assert_eq!(
            (c.max_ratio.as_ref(), c.max_ratio_map.as_ref()),
            (None, None)
        );
    }
}
