//! `wai claims`: every claim of the registry (`wai_lemmas::CLAIMS`, in
//! catalogue order) with its kind, its checker and what the last recorded
//! run found about it — instances examined, violations, known failures, the
//! largest ratio, the instances per case of its proof and the cases never
//! hit — read from a run record (`lemmas/last-run.json`, a [`RunRecord`]),
//! so that a fresh clone shows it without running anything.
//!
//! `--markdown` prints the same as the Markdown table of `README.md`, and
//! `--write-readme FILE` rewrites the part of FILE between
//! [`TABLE_START`] and [`TABLE_END`] with it; a test fails when README.md's
//! table differs from what this command generates.
//!
//! # Edge cases
//!
//! Nothing passes silently: a claim with a checker that the
//! record does not cover is shown as "not run", one the run covered but
//! examined 0 times as "0 — NOT TESTED"; a claim without a checker says
//! "none yet". A record naming a claim the registry does not have gets a
//! note on standard error. A missing or malformed record is an error (exit
//! 3) naming the file and the field.

use std::path::{Path, PathBuf};

use rug::Rational;
use serde_json::{json, Value};
use wai_hunt::record::{ClaimRecord, RunRecord};
use wai_lemmas::{Claim, CLAIMS};

use crate::Failure;

/// The run record read when `--record` is not given, under the root of the
/// repository the command is run in ([`wai_hunt::repository`]).
pub const DEFAULT_RECORD: &str = "lemmas/last-run.json";

/// The line before the generated table in `README.md`.
pub const TABLE_START: &str = "<!-- claims-table:start -->";
/// The line after the generated table in `README.md`.
pub const TABLE_END: &str = "<!-- claims-table:end -->";

/// The command that regenerates README.md's claims table.
const REGENERATE: &str =
    "cargo run --release -p wai-cli -- claims --markdown --write-readme README.md";

#[derive(clap::Args, Debug)]
pub struct Args {
    /// Print JSON: {"run": {...}, "claims": [{"id", "kind", "checker",
    /// "examined", "violations", "known_failures", "max_ratio",
    /// "max_ratio_approx", "max_ratio_map", "cases": {case: instances},
    /// "cases_never_hit", ...}]}.
    #[arg(long, conflicts_with = "markdown")]
    pub json: bool,
    /// Read this run record instead of lemmas/last-run.json of the
    /// repository the command is run in.
    #[arg(long, value_name = "FILE")]
    pub record: Option<PathBuf>,
    /// Print the claims table as Markdown (the table of README.md).
    #[arg(long)]
    pub markdown: bool,
    /// With --markdown: instead of printing, rewrite the part of FILE
    /// between the lines `<!-- claims-table:start -->` and
    /// `<!-- claims-table:end -->`.
    #[arg(long, value_name = "FILE", requires = "markdown")]
    pub write_readme: Option<PathBuf>,
}

/// Where a claim stands in the record.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum State {
    /// No checker, and the record does not cover it.
    NoChecker,
    /// A checker exists but the recorded run did not cover the claim.
    NotRun,
    /// The run covered it and examined nothing.
    NotTested,
    /// Examined, no violation other than known failures.
    Clean,
    /// Examined, with violations other than known failures.
    Violated,
}

impl State {
    fn as_str(self) -> &'static str {
        match self {
            State::NoChecker => "no checker",
            State::NotRun => "not run",
            State::NotTested => "not tested",
            State::Clean => "clean",
            State::Violated => "violated",
        }
    }
}

/// One claim of the registry beside its record.
struct Row<'a> {
    claim: &'static Claim,
    checker: Option<String>,
    record: Option<&'a ClaimRecord>,
}

impl Row<'_> {
    fn state(&self) -> State {
        match (self.record, &self.checker) {
            (Some(r), _) if r.examined == 0 => State::NotTested,
            (Some(r), _) if r.violations > 0 => State::Violated,
            (Some(_), _) => State::Clean,
            (None, Some(_)) => State::NotRun,
            (None, None) => State::NoChecker,
        }
    }

    fn checker_text(&self) -> &str {
        self.checker.as_deref().unwrap_or("none yet")
    }

    fn examined_text(&self) -> String {
        match (self.state(), self.record) {
            (State::NotTested, _) => "0 — NOT TESTED".to_owned(),
            (State::NotRun, _) => "not run".to_owned(),
            (_, Some(r)) => r.examined.to_string(),
            (_, None) => "—".to_owned(),
        }
    }

    fn number(&self, get: fn(&ClaimRecord) -> u64) -> String {
        self.record
            .map_or_else(|| "—".to_owned(), |r| get(r).to_string())
    }

    /// `80/41 ≈ 1.9512`, or `—`.
    fn ratio_text(&self) -> String {
        match self.record.and_then(|r| r.max_ratio.as_ref()) {
            Some(q) => format!("{q} ≈ {}", approx(q)),
            None => "—".to_owned(),
        }
    }

    /// The claim's declared cases with the run's instances of each (0 for a
    /// case the record lacks).
    fn cases(&self) -> Vec<(&'static str, u64)> {
        let declared = self.claim.checker.map_or(&[][..], |c| c.cases);
        declared
            .iter()
            .map(|c| {
                let n = self.record.and_then(|r| r.cases.get(c.name)).copied();
                (c.name, n.unwrap_or(0))
            })
            .collect()
    }

    /// `3 of 5`, or `—` for a claim without cases.
    fn cases_text(&self) -> String {
        let cases = self.cases();
        if cases.is_empty() || self.record.is_none() {
            return "—".to_owned();
        }
        let hit = cases.iter().filter(|(_, n)| *n > 0).count();
        format!("{hit} of {}", cases.len())
    }

    /// The declared cases the run never hit.
    fn never_hit(&self) -> Vec<&'static str> {
        if self.record.is_none() {
            return Vec::new();
        }
        self.cases()
            .into_iter()
            .filter(|(_, n)| *n == 0)
            .map(|(c, _)| c)
            .collect()
    }

    fn ratio_map(&self) -> Option<&str> {
        self.record
            .filter(|r| r.max_ratio.is_some())
            .and_then(|r| r.max_ratio_map.as_deref())
    }
}

/// `1.9512` of an exact ratio, for people only.
fn approx(q: &Rational) -> String {
    format!("{:.4}", q.to_f64())
}

fn rows(record: &RunRecord) -> Vec<Row<'_>> {
    CLAIMS
        .iter()
        .map(|claim| Row {
            claim,
            checker: claim.checker.map(|_| {
                let chapter = wai_lemmas::chapter_of(claim.id).unwrap_or(0);
                format!("wai_lemmas::ch{chapter}::{}", claim.module_name())
            }),
            record: record.claim(claim.id),
        })
        .collect()
}

/// `random-simple-star 10, orth 10`.
fn kinds_text(record: &RunRecord) -> String {
    let kinds: Vec<String> = record
        .map_kinds
        .iter()
        .map(|k| format!("{} {}", k.kind, k.maps))
        .collect();
    kinds.join(", ")
}

/// What a sharded record holds: `, merged from 32 shards`, or for a
/// partial one the shards it lacks; empty for an unsharded run.
fn shards_text(record: &RunRecord) -> String {
    let Some(shards) = &record.shards else {
        return String::new();
    };
    let missing = shards.missing();
    if missing.is_empty() {
        return format!(
            " (the shards' wall times added), merged from {} shards",
            shards.count
        );
    }
    let list: Vec<String> = missing.iter().take(12).map(u64::to_string).collect();
    format!(
        ", PARTIAL: {} of {} shards missing ({}{})",
        missing.len(),
        shards.count,
        list.join(", "),
        if missing.len() > 12 { ", …" } else { "" }
    )
}

/// The totals line: how many claims have a checker, were tested, were not.
fn totals(rows: &[Row<'_>]) -> String {
    let ids = |s: State| -> Vec<&str> {
        rows.iter()
            .filter(|r| r.state() == s)
            .map(|r| r.claim.id)
            .collect()
    };
    let with_checker = rows.iter().filter(|r| r.checker.is_some()).count();
    let tested = rows
        .iter()
        .filter(|r| matches!(r.state(), State::Clean | State::Violated))
        .count();
    let mut parts = vec![
        format!("{} claims", rows.len()),
        format!("{with_checker} with a checker"),
        format!("{tested} tested by the run"),
    ];
    for (state, what) in [
        (State::Violated, "with violations"),
        (State::NotTested, "NOT TESTED (0 examined)"),
        (State::NotRun, "not run"),
    ] {
        let list = ids(state);
        if !list.is_empty() {
            parts.push(format!("{} {what}: {}", list.len(), list.join(", ")));
        }
    }
    parts.push(format!(
        "{} without a checker yet",
        ids(State::NoChecker).len()
    ));
    let cased: Vec<&Row<'_>> = rows.iter().filter(|r| !r.cases().is_empty()).collect();
    let all_cases: usize = cased.iter().map(|r| r.cases().len()).sum();
    let never: usize = cased.iter().map(|r| r.never_hit().len()).sum();
    parts.push(format!(
        "{} claims name {all_cases} cases, {never} never hit by the run",
        cased.len()
    ));
    format!("{}.", parts.join("; "))
}

/// The lines naming, per claim, the cases the run never hit.
fn never_hit_lines(rows: &[Row<'_>], bullet: &str) -> String {
    let mut out = String::new();
    for r in rows {
        let never = r.never_hit();
        if !never.is_empty() {
            out.push_str(&format!("{bullet}{}: {}\n", r.claim.id, never.join(", ")));
        }
    }
    out
}

/// The plain-text table.
fn text(record: &RunRecord, path: &Path, rows: &[Row<'_>]) -> String {
    let mut out = format!(
        "last recorded run ({}):\n  command  {}\n  commit   {}, {}, {} maps in {} s{}\n",
        path.display(),
        record.command,
        record.commit,
        record.date,
        record.maps,
        record.seconds,
        shards_text(record)
    );
    if !record.map_kinds.is_empty() {
        out.push_str(&format!("  maps     {}\n", kinds_text(record)));
    }
    out.push('\n');
    let header = [
        "id",
        "kind",
        "checker",
        "examined",
        "violations",
        "known failures",
        "cases hit",
        "largest ratio",
    ];
    let cells: Vec<[String; 8]> = rows
        .iter()
        .map(|r| {
            let ratio = match r.ratio_map() {
                Some(m) => format!("{} on {m}", r.ratio_text()),
                None => r.ratio_text(),
            };
            [
                r.claim.id.to_owned(),
                r.claim.kind.to_string(),
                r.checker_text().to_owned(),
                r.examined_text(),
                r.number(|c| c.violations),
                r.number(|c| c.known_failures),
                r.cases_text(),
                ratio,
            ]
        })
        .collect();
    let mut widths = header.map(|h| h.chars().count());
    for row in &cells {
        for (w, c) in widths.iter_mut().zip(row) {
            *w = (*w).max(c.chars().count());
        }
    }
    let line = |row: &[&str]| -> String {
        let padded: Vec<String> = row
            .iter()
            .zip(widths)
            .enumerate()
            .map(|(i, (c, w))| {
                if i + 1 == row.len() {
                    (*c).to_owned()
                } else {
                    format!("{c:<w$}")
                }
            })
            .collect();
        format!("{}\n", padded.join("  ").trim_end())
    };
    out.push_str(&line(&header));
    for row in &cells {
        let refs: Vec<&str> = row.iter().map(String::as_str).collect();
        out.push_str(&line(&refs));
    }
    out.push('\n');
    out.push_str(&totals(rows));
    out.push('\n');
    let never = never_hit_lines(rows, "  ");
    if !never.is_empty() {
        out.push_str(
            "\ncases never hit by the run (`wai check --target CLAIM:CASE` searches for one):\n",
        );
        out.push_str(&never);
    }
    out
}

/// The run's command without the options that only say where it wrote its
/// files (`--record`, `--out`, `--largest`): what was examined, not the
/// folders of the machine it ran on.
fn what_was_run(command: &str) -> String {
    const WHERE: [&str; 3] = ["--record", "--out", "--largest"];
    let mut words = command.split_whitespace();
    let mut kept = Vec::new();
    while let Some(w) = words.next() {
        if WHERE.contains(&w) {
            words.next();
        } else if !WHERE.iter().any(|o| w.starts_with(&format!("{o}="))) {
            kept.push(w);
        }
    }
    kept.join(" ")
}

/// A table cell's text with `|` escaped.
fn cell(s: &str) -> String {
    s.replace('|', "\\|")
}

/// The Markdown table of README.md, ending with a newline.
fn markdown(record: &RunRecord, rows: &[Row<'_>]) -> String {
    let code = |s: &str| format!("`{}`", s.replace('`', "'"));
    let mut out = format!(
        "Last recorded run: {} at commit {}, {}: {} maps{} in {} s{}.\n\n",
        code(&what_was_run(&record.command)),
        code(&record.commit),
        record.date,
        record.maps,
        if record.map_kinds.is_empty() {
            String::new()
        } else {
            format!(" ({})", kinds_text(record))
        },
        record.seconds,
        shards_text(record)
    );
    out.push_str("| id | thesis | kind | checker | examined | violations | known failures | cases hit | largest ratio |\n");
    out.push_str("|---|---|---|---|--:|--:|--:|--:|---|\n");
    for r in rows {
        let checker = match &r.checker {
            Some(c) => code(c),
            None => "none yet".to_owned(),
        };
        let examined = match r.state() {
            State::NotTested => "0 — **NOT TESTED**".to_owned(),
            _ => r.examined_text(),
        };
        let ratio = match r.ratio_map() {
            Some(m) => format!("{} ({})", r.ratio_text(), code(m)),
            None => r.ratio_text(),
        };
        out.push_str(&format!(
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
            r.claim.id,
            cell(r.claim.reference),
            r.claim.kind,
            cell(&checker),
            examined,
            r.number(|c| c.violations),
            r.number(|c| c.known_failures),
            r.cases_text(),
            cell(&ratio),
        ));
    }
    out.push('\n');
    out.push_str(&totals(rows));
    out.push('\n');
    let never = never_hit_lines(rows, "- ");
    if !never.is_empty() {
        out.push_str("\nCases never hit by the run:\n\n");
        out.push_str(&never);
    }
    out
}

/// The JSON of `--json`.
fn to_json(record: &RunRecord, path: &Path, rows: &[Row<'_>]) -> Value {
    let mut run = record.to_json();
    if let Some(o) = run.as_object_mut() {
        o.remove("claims");
        o.insert("record_file".to_owned(), json!(path.display().to_string()));
        // A merge lacking shards (or one shard's record) is not the run.
        o.insert("partial".to_owned(), json!(record.is_partial()));
    }
    let claims: Vec<Value> = rows
        .iter()
        .map(|r| {
            let rec = r.record;
            let ratio = rec.and_then(|c| c.max_ratio.as_ref());
            json!({
                "id": r.claim.id,
                "kind": r.claim.kind.as_catalogue_str(),
                "reference": r.claim.reference,
                "checker": r.checker,
                "status": r.state().as_str(),
                "examined": rec.map(|c| c.examined),
                "violations": rec.map(|c| c.violations),
                "known_failures": rec.map(|c| c.known_failures),
                "max_ratio": ratio.map(Rational::to_string),
                "max_ratio_approx": ratio.and_then(|q| serde_json::Number::from_f64(q.to_f64())),
                "max_ratio_map": r.ratio_map(),
                "cases": r.cases().into_iter().collect::<std::collections::BTreeMap<_, _>>(),
                "cases_never_hit": r.never_hit(),
                "counts": rec.map(|c| &c.counts),
            })
        })
        .collect();
    json!({"run": run, "claims": claims})
}

/// `text` with the lines between [`TABLE_START`] and [`TABLE_END`]
/// replaced by `table`; each marker must be on a line of its own, once.
fn replace_table(text: &str, table: &str) -> Result<String, String> {
    let once = |marker: &str| -> Result<usize, String> {
        let at: Vec<usize> = text.match_indices(marker).map(|(i, _)| i).collect();
        match at[..] {
            [i] if i == 0 || text[..i].ends_with('\n') => Ok(i),
            [_] => Err(format!("{marker} must start a line")),
            [] => Err(format!("no line {marker}")),
            _ => Err(format!("{marker} appears {} times", at.len())),
        }
    };
    let (start, end) = (once(TABLE_START)?, once(TABLE_END)?);
    let body = start + TABLE_START.len();
    if !text[body..].starts_with('\n') || end < body + 1 {
        return Err(format!(
            "{TABLE_START} must stand alone on a line before {TABLE_END}"
        ));
    }
    Ok(format!("{}{table}{}", &text[..=body], &text[end..]))
}

pub fn run(args: &Args) -> Result<(), Failure> {
    let path = match &args.record {
        Some(path) => path.clone(),
        None => wai_hunt::repository::path(DEFAULT_RECORD)
            .map_err(|e| Failure::io(format!("no run record: {e}, or give --record FILE")))?,
    };
    let record = RunRecord::read(&path).map_err(Failure::io)?;
    // Shown as an absolute path, whatever `--record` was given as.
    let path = std::fs::canonicalize(&path).unwrap_or(path);
    for c in &record.claims {
        if wai_lemmas::claim(&c.id).is_none() {
            eprintln!(
                "note: {}: claim {} is not in the registry; not shown",
                path.display(),
                c.id
            );
        }
    }
    let rows = rows(&record);
    if args.json {
        let v = to_json(&record, &path, &rows);
        outln!(
            "{}",
            serde_json::to_string_pretty(&v).map_err(|e| Failure::io(e.to_string()))?
        );
    } else if args.markdown {
        let table = markdown(&record, &rows);
        match &args.write_readme {
            None => out!("{table}"),
            Some(readme) => {
                let shown = readme.display();
                let old = std::fs::read_to_string(readme)
                    .map_err(|e| Failure::io(format!("{shown}: {e}")))?;
                let new = replace_table(&old, &table)
                    .map_err(|e| Failure::io(format!("{shown}: {e}")))?;
                if new == old {
                    eprintln!("{shown}: the claims table is up to date");
                } else {
                    std::fs::write(readme, new)
                        .map_err(|e| Failure::io(format!("{shown}: {e}")))?;
                    eprintln!("{shown}: claims table rewritten (`{REGENERATE}`)");
                }
            }
        }
    } else {
        out!("{}", text(&record, &path, &rows));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table_shows_what_was_run_not_where_it_wrote() {
        assert_eq!(
            what_was_run(
                "wai check --maps all --record lemmas/last-run.json --out /tmp/a \
                 --largest=/tmp/b --seed 1"
            ),
            "wai check --maps all --seed 1"
        );
    }

    #[test]
    fn the_table_is_replaced_between_the_markers_only() {
        let readme = format!("# T\n\n{TABLE_START}\nold\nrows\n{TABLE_END}\nafter\n");
        let new = replace_table(&readme, "new\n").unwrap();
        assert_eq!(
            new,
            format!("# T\n\n{TABLE_START}\nnew\n{TABLE_END}\nafter\n")
        );
        assert_eq!(replace_table(&new, "new\n").unwrap(), new);
        let empty = format!("{TABLE_START}\n{TABLE_END}\n");
        assert_eq!(
            replace_table(&empty, "x\n").unwrap(),
            format!("{TABLE_START}\nx\n{TABLE_END}\n")
        );
    }

    #[test]
    fn bad_markers_are_errors() {
        for (readme, needle) in [
            (
                format!("{TABLE_START}\n"),
                "no line <!-- claims-table:end -->",
            ),
            ("nothing".to_owned(), "no line <!-- claims-table:start -->"),
            (format!("{TABLE_END}\n{TABLE_START}\n"), "must stand alone"),
            (
                format!("{TABLE_START}\n{TABLE_END}\n{TABLE_END}\n"),
                "appears 2 times",
            ),
            (
                format!("{TABLE_START} x\n{TABLE_END}\n"),
                "must stand alone",
            ),
            (
                format!("a {TABLE_START}\n{TABLE_END}\n"),
                "must start a line",
            ),
        ] {
            let err = replace_table(&readme, "t\n").unwrap_err();
            assert!(err.contains(needle), "{needle:?} missing from {err:?}");
        }
    }
}
