//! [`merge`]: the records of a run's shards added up into the record of
//! the whole run.
//!
//! A run split with `wai check --shard I/N` ([`crate::shard`]) leaves N
//! records. Each carries, besides the counts of its maps, a `shards`
//! object: N, the run's arguments (the same in every shard), and one entry
//! for itself — its index, maps, wall time, start and end (UTC), the
//! SHA-256 of the binary that ran it and the counterexample files it
//! wrote. [`merge`] sums examined, violations, known failures, cases,
//! counts and maps; keeps per claim the largest ratio with its map (of
//! equal ratios, the one earliest in the stream, as the unsharded run
//! does); and unions the shard entries. A merge of every shard equals the
//! unsharded run's record in everything but the wall time and the command
//! line; a merge of some shards is **partial**: it lists the missing ones
//! ([`Shards::missing`]), and [`RunRecord::is_partial`] says so to every
//! reader. Merges merge again (the shards of a long run can be merged as
//! they finish).
//!
//! # Refused
//!
//! Records of different commits, runs (arguments) or shard counts; a shard
//! present twice (the same shard run twice, or two merges that overlap); a
//! record that is not a shard's (no `shards`); claims that differ; and for
//! a commit with uncommitted changes (`+dirty`), different binaries.

use crate::record::{ClaimRecord, RunRecord};
use crate::shard::Shards;

/// The records of shards (each with a label for messages, such as its
/// path) merged into the record of their run: whole if every shard is
/// there, else partial ([`RunRecord::is_partial`]). The error says which
/// records disagree and how.
pub fn merge(records: &[(String, RunRecord)]) -> Result<RunRecord, String> {
    let Some((first_label, first)) = records.first() else {
        return Err("no record to merge".to_owned());
    };
    let shards_of = |label: &str, r: &RunRecord| -> Result<Shards, String> {
        r.shards.clone().ok_or_else(|| {
            format!(
                "{label} is not a shard's record (it has no \"shards\"): a merge takes the \
                 records of `wai check --shard I/N --record …`, or merges of them"
            )
        })
    };
    let mut shards = shards_of(first_label, first)?;
    // Which record holds each shard, for the message on an overlap.
    let mut holder: Vec<(u64, &str)> = shards
        .present
        .iter()
        .map(|s| (s.index, first_label.as_str()))
        .collect();
    let mut merged = first.clone();
    for (label, r) in &records[1..] {
        let theirs = shards_of(label, r)?;
        let differ = |what: &str, a: &str, b: &str| {
            format!(
                "{label} and {first_label} are not of one run: {what} {b:?} and {a:?}; a merge \
                 takes the shards of one `wai check` command at one commit"
            )
        };
        if r.commit != first.commit {
            return Err(differ("commits", &first.commit, &r.commit));
        }
        if theirs.run != shards.run {
            return Err(differ("runs", &shards.run, &theirs.run));
        }
        if theirs.count != shards.count {
            return Err(differ(
                "shard counts",
                &shards.count.to_string(),
                &theirs.count.to_string(),
            ));
        }
        let ids = |r: &RunRecord| r.claims.iter().map(|c| c.id.clone()).collect::<Vec<_>>();
        if ids(r) != ids(first) {
            return Err(differ("claims", &ids(first).join(","), &ids(r).join(",")));
        }
        if first.commit.ends_with("+dirty") {
            let binaries = |s: &Shards| {
                s.present
                    .iter()
                    .map(|p| p.binary.clone())
                    .collect::<Vec<_>>()
            };
            let (a, b) = (binaries(&shards), binaries(&theirs));
            if let Some(other) = b.iter().find(|x| !a.contains(x)) {
                return Err(format!(
                    "{label} was run by another binary ({other}) than {first_label} ({}), at \
                     commit {} with uncommitted changes: the code that ran may differ; run every \
                     shard from one build",
                    a.first().map_or("", String::as_str),
                    first.commit
                ));
            }
        }
        for s in &theirs.present {
            if let Some((_, other)) = holder.iter().find(|(i, _)| *i == s.index) {
                return Err(format!(
                    "shard {}/{} is in both {other} and {label}: each shard may be merged once \
                     (a shard run twice, or two merges that overlap)",
                    s.index, shards.count
                ));
            }
        }
        holder.extend(theirs.present.iter().map(|s| (s.index, label.as_str())));
        shards.present.extend(theirs.present);
        absorb(&mut merged, r);
    }
    shards.present.sort_by_key(|s| s.index);
    merged.command = shards.run.clone();
    merged.shards = Some(shards);
    Ok(merged)
}

/// Adds `other`'s counts to `into` (same claims in the same order).
fn absorb(into: &mut RunRecord, other: &RunRecord) {
    into.date = into.date.clone().max(other.date.clone());
    into.seconds += other.seconds;
    into.maps += other.maps;
    for k in &other.map_kinds {
        match into.map_kinds.iter_mut().find(|m| m.kind == k.kind) {
            Some(m) => {
                m.maps += k.maps;
                m.first = match (m.first, k.first) {
                    (Some(a), Some(b)) => Some(a.min(b)),
                    (a, b) => a.or(b),
                };
            }
            None => into.map_kinds.push(k.clone()),
        }
    }
    // As the unsharded run: kinds in the order of their first map (kinds
    // of older records, without it, last, in the order met).
    into.map_kinds.sort_by_key(|k| k.first.unwrap_or(u64::MAX));
    for (mine, theirs) in into.claims.iter_mut().zip(&other.claims) {
        absorb_claim(mine, theirs);
    }
}

fn absorb_claim(into: &mut ClaimRecord, other: &ClaimRecord) {
    into.examined += other.examined;
    into.violations += other.violations;
    into.known_failures += other.known_failures;
    for (case, n) in &other.cases {
        *into.cases.entry(case.clone()).or_default() += n;
    }
    for (name, n) in &other.counts {
        *into.counts.entry(name.clone()).or_default() += n;
    }
    if let Some(theirs) = &other.max_ratio {
        let index = |i: Option<u64>| i.unwrap_or(u64::MAX);
        let beats = into.max_ratio.as_ref().is_none_or(|mine| {
            theirs > mine
                || (theirs == mine && index(other.max_ratio_index) < index(into.max_ratio_index))
        });
        if beats {
            into.max_ratio = Some(theirs.clone());
            into.max_ratio_map = other.max_ratio_map.clone();
            into.max_ratio_index = other.max_ratio_index;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::search::{search, Limit};
    use crate::shard::Shard;
    use crate::shard::ShardRun;
    use crate::stream::{parse_kinds, Stream};
    use serde_json::{json, Value};

    /// The record of `shard` of a count run over a few kinds, as `wai
    /// check --shard` makes it.
    fn run(shard: Shard, count: u64) -> RunRecord {
        let stream = Stream::Generated {
            kinds: parse_kinds("random-orthogonal:6-9,random-simple-star:5-8,family:1-2").unwrap(),
            seed: 4,
        };
        let checkers = [
            wai_lemmas::ch3::t3_9a::CHECKER,
            wai_lemmas::ch5::t5_17::CHECKER,
            wai_lemmas::ch3::l3_7::CHECKER,
        ];
        let out = search(
            &checkers,
            &stream,
            Limit::Count(count),
            shard,
            false,
            &|_, _| {},
        );
        let mut r = RunRecord::from_summary(
            &out.summary,
            format!("wai check --count {count} --shard {shard}"),
            "c0ffee".to_owned(),
            "2026-11-28".to_owned(),
            out.elapsed.as_secs(),
            out.map_kinds.clone(),
        );
        if !shard.is_whole() {
            r.shards = Some(Shards {
                count: shard.count,
                run: format!("wai check --count {count}"),
                present: vec![ShardRun {
                    index: shard.index,
                    maps: r.maps,
                    seconds: r.seconds,
                    started: "2026-11-28T00:00:00Z".to_owned(),
                    ended: "2026-11-28T00:00:01Z".to_owned(),
                    binary: "b".to_owned(),
                    counterexamples: Vec::new(),
                }],
            });
        }
        r
    }

    /// Everything but the wall time, the command and the shard entries.
    fn content(r: &RunRecord) -> (u64, Vec<KindCount>, Vec<ClaimRecord>) {
        (r.maps, r.map_kinds.clone(), r.claims.clone())
    }

    fn labelled(records: &[RunRecord]) -> Vec<(String, RunRecord)> {
        records
            .iter()
            .map(|r| {
                let i = r.shards.as_ref().map_or(0, |s| s.present[0].index);
                (format!("shard-{i}.json"), r.clone())
            })
            .collect()
    }

    use crate::record::KindCount;

    #[test]
    fn the_shards_of_a_count_run_merge_into_the_unsharded_record() {
        let whole = run(Shard::WHOLE, 23);
        let shards: Vec<RunRecord> = (0..4).map(|i| run(Shard::new(i, 4).unwrap(), 23)).collect();
        // Every shard sees its own maps: 6, 6, 6 and 5.
        let maps: Vec<u64> = shards.iter().map(|r| r.maps).collect();
        assert_eq!(maps, [6, 6, 6, 5]);
        // In any order.
        let mut order = labelled(&shards);
        order.swap(0, 3);
        order.swap(1, 2);
        let merged = merge(&order).unwrap();
        assert_eq!(content(&merged), content(&whole));
        assert!(!merged.is_partial());
        assert_eq!(merged.command, "wai check --count 23");
        let s = merged.shards.as_ref().unwrap();
        assert_eq!(s.missing(), Vec::<u64>::new());
        assert_eq!(
            s.present.iter().map(|p| p.index).collect::<Vec<_>>(),
            [0, 1, 2, 3]
        );
        // The largest ratios of the whole run come from some shard.
        assert!(whole.claims.iter().any(|c| c.max_ratio.is_some()));
        // Sealed and read back, the merge is the same record.
        assert_eq!(RunRecord::from_json(&merged.to_json()), Ok(merged.clone()));
        // Merges merge again: (0, 2) and (1, 3) give the same.
        let all = labelled(&shards);
        let a = merge(&[all[0].clone(), all[2].clone()]).unwrap();
        let b = merge(&[all[1].clone(), all[3].clone()]).unwrap();
        assert!(a.is_partial() && b.is_partial());
        let again = merge(&[("a".into(), a), ("b".into(), b)]).unwrap();
        assert_eq!(again, merged);
    }

    #[test]
    fn a_missing_shard_makes_a_partial_merge_that_says_which() {
        let shards: Vec<RunRecord> = (0..4).map(|i| run(Shard::new(i, 4).unwrap(), 11)).collect();
        let mut three = labelled(&shards);
        three.remove(2);
        let partial = merge(&three).unwrap();
        assert!(partial.is_partial());
        assert_eq!(partial.shards.as_ref().unwrap().missing(), [2]);
        assert_eq!(partial.maps, 11 - shards[2].maps);
        let v = partial.to_json();
        assert_eq!(v["shards"]["missing"], json!([2]));
        // The repaired shard completes it: the same as all four at once.
        let repaired = merge(&[
            ("partial".into(), partial),
            ("shard-2.json".into(), shards[2].clone()),
        ])
        .unwrap();
        assert_eq!(repaired, merge(&labelled(&shards)).unwrap());
    }

    #[test]
    fn records_of_different_runs_or_overlapping_shards_are_refused() {
        let a = run(Shard::new(0, 2).unwrap(), 8);
        let b = run(Shard::new(1, 2).unwrap(), 8);
        let refused = |records: Vec<(&str, RunRecord)>, needle: &str| {
            let records: Vec<(String, RunRecord)> = records
                .into_iter()
                .map(|(l, r)| (l.to_owned(), r))
                .collect();
            let err = merge(&records).unwrap_err();
            assert!(err.contains(needle), "{needle:?} not in: {err}");
        };
        refused(
            vec![("a", a.clone()), ("a again", a.clone())],
            "shard 0/2 is in both a and a again",
        );
        let mut other_commit = b.clone();
        other_commit.commit = "deadbee".into();
        refused(
            vec![("a", a.clone()), ("b", other_commit)],
            "commits \"deadbee\" and \"c0ffee\"",
        );
        let mut other_run = b.clone();
        other_run.shards.as_mut().unwrap().run = "wai check --count 9".into();
        refused(vec![("a", a.clone()), ("b", other_run)], "runs");
        let mut other_split = b.clone();
        other_split.shards.as_mut().unwrap().count = 3;
        refused(vec![("a", a.clone()), ("b", other_split)], "shard counts");
        let mut fewer_claims = b.clone();
        fewer_claims.claims.pop();
        refused(vec![("a", a.clone()), ("b", fewer_claims)], "claims");
        let whole = run(Shard::WHOLE, 8);
        refused(
            vec![("a", a.clone()), ("whole.json", whole)],
            "whole.json is not a shard's record",
        );
        let (mut da, mut db) = (a.clone(), b.clone());
        da.commit = "c0ffee+dirty".into();
        db.commit = "c0ffee+dirty".into();
        db.shards.as_mut().unwrap().present[0].binary = "other".into();
        refused(vec![("a", da.clone()), ("b", db)], "another binary");
        refused(Vec::new(), "no record");
        // One dirty build merges.
        let mut db = b.clone();
        db.commit = da.commit.clone();
        assert!(merge(&[("a".into(), da), ("b".into(), db)]).is_ok());
    }

    #[test]
    fn shard_lists_that_lie_are_refused_when_read() {
        let a = run(Shard::new(1, 2).unwrap(), 6);
        let sealed = a.to_json();
        assert_eq!(sealed["shards"]["missing"], json!([0]));
        let reread = |edit: &dyn Fn(&mut Value)| {
            let mut v = sealed["shards"].clone();
            edit(&mut v);
            Shards::from_json(&v, "shards")
        };
        assert!(reread(&|_| {}).is_ok());
        let err = reread(&|v| v["missing"] = json!([])).unwrap_err();
        assert!(err.contains("shards.missing: says []"), "{err}");
        let err = reread(&|v| v["present"][0]["index"] = json!(2)).unwrap_err();
        assert!(
            err.contains("shards.present[0].index: shard 2 of a run of 2"),
            "{err}"
        );
        let err = reread(&|v| v["count"] = json!(0)).unwrap_err();
        assert!(err.contains("at least one shard"), "{err}");
    }
}
