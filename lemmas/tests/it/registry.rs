//! The `CLAIMS` table against the catalogue `data/CLAIMS.md` and the
//! statements of the thesis (`data/thesis-statements.txt`); both copies
//! against the team's sources while those sit beside the checkout.

use std::collections::{BTreeMap, BTreeSet};

use wai_lemmas::{claim, claims_without_checker, Kind, CLAIMS};

/// Claims whose checker module has landed. Add an id here when its row in
/// `CLAIMS` gets its checker.
const WITH_CHECKER: &[&str] = &[
    "L3.1a", "L3.1b", "L3.1c", "D3.5", "T3.2", "T3.3a", "T3.3b", "A3.6", "L3.5", "L3.7", "C3.8",
    "L3.7t", "T3.9a", "T3.9b", "T3.9c", "T3.10", "R3.4", "E4.1", "L4.1", "T4.2", "T4.3", "L4.5",
    "L4.6", "L4.7", "L4.8", "L4.9", "C4.10", "E4.10", "C4.15", "C4.16", "E4.28", "L4.17", "L4.18",
    "T4.19", "C4.20", "O5.3", "L5.1", "L5.2", "L5.3", "L5.4", "L5.5", "L5.6", "L5.7", "L5.8",
    "L5.9", "T5.12", "L5.13", "L5.14", "T5.15", "T5.16", "T5.17", "T5.17t", "C5.18",
];

/// The (id, kind) of every row of every table of `CLAIMS.md` whose header's
/// first cell is `id`, in file order.
fn catalogue() -> Vec<(String, String)> {
    let text = crate::read_repo("data/CLAIMS.md");
    let mut rows = Vec::new();
    let mut in_claims_table = false;
    for line in text.lines() {
        let line = line.trim();
        if !line.starts_with('|') {
            in_claims_table = false;
            continue;
        }
        let cells: Vec<&str> = line.trim_matches('|').split('|').map(str::trim).collect();
        if cells
            .iter()
            .all(|c| !c.is_empty() && c.chars().all(|ch| "-: ".contains(ch)))
        {
            continue; // the separator row
        }
        if cells.first() == Some(&"id") {
            assert_eq!(cells.get(1), Some(&"kind"), "claims table header: {line}");
            in_claims_table = true;
            continue;
        }
        assert!(
            in_claims_table,
            "a table row outside a claims table: {line}"
        );
        assert!(
            cells.len() >= 2,
            "a claims row with fewer than 2 cells: {line}"
        );
        rows.push((cells[0].to_owned(), cells[1].to_owned()));
    }
    rows
}

#[test]
fn claims_md_has_the_expected_tables() {
    let rows = catalogue();
    // 16 claims in chapter 3, 18 in chapter 4, 18 in chapter 5 when this was
    // written; the exact set is compared below, this only guards the parser.
    assert!(
        rows.len() >= 50,
        "parsed only {} rows of CLAIMS.md",
        rows.len()
    );
    for (id, _) in &rows {
        assert!(
            id.len() >= 3 && id.starts_with(|c: char| c.is_ascii_uppercase()),
            "not an id: {id:?}"
        );
    }
}

#[test]
fn claims_md_ids_are_unique() {
    let mut seen = BTreeSet::new();
    for (id, _) in catalogue() {
        assert!(seen.insert(id.clone()), "{id} appears twice in CLAIMS.md");
    }
}

#[test]
fn registry_ids_are_unique() {
    let mut seen = BTreeSet::new();
    for c in CLAIMS {
        assert!(seen.insert(c.id), "{} appears twice in CLAIMS", c.id);
    }
}

#[test]
fn registry_and_claims_md_have_the_same_ids_and_kinds() {
    let md: BTreeMap<String, String> = catalogue().into_iter().collect();
    let missing: Vec<&String> = md.keys().filter(|id| claim(id).is_none()).collect();
    let extra: Vec<&str> = CLAIMS
        .iter()
        .map(|c| c.id)
        .filter(|id| !md.contains_key(*id))
        .collect();
    assert!(
        missing.is_empty(),
        "ids of CLAIMS.md missing from CLAIMS: {missing:?}"
    );
    assert!(
        extra.is_empty(),
        "ids of CLAIMS not in CLAIMS.md: {extra:?}"
    );
    for (id, kind) in &md {
        let parsed = Kind::from_catalogue_str(kind)
            .unwrap_or_else(|| panic!("{id}: unknown kind {kind:?} in CLAIMS.md"));
        let row = claim(id).expect("checked above");
        assert_eq!(
            row.kind, parsed,
            "{id}: CLAIMS says {}, CLAIMS.md says {kind}",
            row.kind
        );
    }
}

#[test]
fn registry_follows_the_order_of_claims_md() {
    let md: Vec<String> = catalogue().into_iter().map(|(id, _)| id).collect();
    let ours: Vec<&str> = CLAIMS.iter().map(|c| c.id).collect();
    assert_eq!(ours, md);
}

/// The reference names the statement the id's letter stands for and
/// contains the id's number, and that statement exists in the thesis.
#[test]
fn references_match_the_ids_and_the_thesis() {
    let statements: BTreeSet<String> = crate::read_repo("data/thesis-statements.txt")
        .lines()
        .map(str::to_owned)
        .collect();
    for c in CLAIMS {
        assert!(!c.statement.trim().is_empty(), "{}: empty statement", c.id);
        let number: String = c.id[1..]
            .trim_end_matches(|ch: char| ch.is_ascii_lowercase())
            .to_owned();
        assert!(
            c.reference.contains(&number),
            "{}: reference {:?} does not contain {number}",
            c.id,
            c.reference
        );
        let word = match &c.id[..1] {
            "L" => "Lemma",
            "T" => "Theorem",
            "C" => "Corollary",
            "D" => "Definition",
            "R" => "Remark",
            "O" => "Observation",
            "E" => "Fig",
            "A" => "Section",
            other => panic!("{}: unknown id prefix {other}", c.id),
        };
        assert!(
            c.reference.contains(word),
            "{}: reference {:?} does not name a {word}",
            c.id,
            c.reference
        );
        if word == "Section" {
            // A rule of a section (A3.6): the section's heading exists.
            assert!(
                statements.contains(&format!("Section {number}")),
                "{}: the thesis has no section {number}",
                c.id
            );
        } else if word != "Fig" {
            let heading = format!("{word} {number}");
            assert!(
                statements.contains(&heading),
                "{}: the thesis has no {heading:?}",
                c.id
            );
        }
    }
}

#[test]
fn statuses_match_the_list_of_landed_checkers() {
    for c in CLAIMS {
        let listed = WITH_CHECKER.contains(&c.id);
        assert_eq!(
            c.checker.is_some(),
            listed,
            "{}: status and WITH_CHECKER disagree",
            c.id
        );
        if let Some(checker) = c.checker {
            assert_eq!(checker.id, c.id, "the checker of {} has another id", c.id);
        }
    }
}

/// Names every claim that no checker tests yet; the list shrinks as claim
/// modules land.
#[test]
fn untested_claims_are_named() {
    let untested = claims_without_checker();
    println!(
        "claims without a checker ({} of {}): {}",
        untested.len(),
        CLAIMS.len(),
        untested.join(", ")
    );
    let expected: Vec<&str> = CLAIMS
        .iter()
        .map(|c| c.id)
        .filter(|id| !WITH_CHECKER.contains(id))
        .collect();
    assert_eq!(untested, expected);
    assert_eq!(untested.len(), CLAIMS.len() - WITH_CHECKER.len());
}

/// The files of `lemmas/src` that are not a claim's module: the crate
/// root, the registry, the planted bugs, the unit tests' fixtures, and the
/// framework's folder; and of each chapter's folder: its `mod.rs`. Nothing
/// else may be there.
const NOT_CLAIMS: &[&str] = &["lib", "registry", "planted", "fixtures"];

/// The `.rs` files and folders of `dir` (stems for files).
fn entries(dir: &std::path::Path) -> Vec<(String, bool)> {
    let mut out: Vec<(String, bool)> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{} is not readable: {e}", dir.display()))
        .map(|e| e.expect("directory entry").path())
        .filter_map(|p| {
            if p.is_dir() {
                p.file_name()
                    .map(|s| (s.to_string_lossy().into_owned(), true))
            } else if p.extension().is_some_and(|x| x == "rs") {
                p.file_stem()
                    .map(|s| (s.to_string_lossy().into_owned(), false))
            } else {
                None
            }
        })
        .collect();
    out.sort();
    out
}

/// What is out of place in a `lemmas/src` laid out as `src`: a file at the
/// top other than [`NOT_CLAIMS`], a folder other than `framework` and
/// `ch3`–`ch5`, and in a chapter's folder a file that is not `mod.rs` or
/// the module of a claim of that chapter.
fn stray_modules(src: &std::path::Path) -> Vec<String> {
    let mut stray = Vec::new();
    for (name, is_dir) in entries(src) {
        match (is_dir, name.as_str()) {
            (false, m) if NOT_CLAIMS.contains(&m) => {}
            (true, "framework") => {}
            (true, ch) if ["ch3", "ch4", "ch5"].contains(&ch) => {
                let chapter = ch[2..].parse::<u8>().expect("a digit");
                let names: BTreeSet<String> = CLAIMS
                    .iter()
                    .filter(|c| wai_lemmas::chapter_of(c.id) == Some(chapter))
                    .map(|c| c.module_name())
                    .collect();
                for (m, sub) in entries(&src.join(ch)) {
                    if sub || (m != "mod" && !names.contains(&m)) {
                        stray.push(format!("{ch}/{m}"));
                    }
                }
            }
            _ => stray.push(name),
        }
    }
    stray
}

/// Every module file of `lemmas/src` other than the shared ones is the
/// module of a claim, in its chapter's folder, and every claim with a
/// checker has its module.
#[test]
fn claim_modules_and_ids_correspond() {
    let src = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/src"));
    let stray = stray_modules(src);
    assert!(
        stray.is_empty(),
        "lemmas/src/{{{}}}: not the module of any claim of its chapter",
        stray.join(", ")
    );
    for c in CLAIMS.iter().filter(|c| c.checker.is_some()) {
        let chapter = wai_lemmas::chapter_of(c.id).expect("a chapter");
        let file = src.join(format!("ch{chapter}/{}.rs", c.module_name()));
        assert!(
            file.is_file(),
            "{} has a checker but no module {}",
            c.id,
            file.display()
        );
    }
}

/// The test above can fail: a stray file at the top, a claim module in
/// another chapter's folder and a stray folder are named; the shared files
/// and the claim modules in place are not.
#[test]
fn a_stray_module_is_named() {
    let dir = std::env::temp_dir().join(format!("wai-lemmas-stray-{}", std::process::id()));
    for sub in ["framework", "ch3", "ch4", "extra"] {
        std::fs::create_dir_all(dir.join(sub)).unwrap();
    }
    for f in [
        "lib.rs",
        "registry.rs",
        "helpers.rs",
        "notes.txt",
        "framework/report.rs",
        "ch3/mod.rs",
        "ch3/l3_1a.rs",
        "ch3/t4_2.rs",
        "ch4/t4_2.rs",
    ] {
        std::fs::write(dir.join(f), "").unwrap();
    }
    let stray = stray_modules(&dir);
    std::fs::remove_dir_all(&dir).unwrap();
    assert_eq!(stray, vec!["ch3/t4_2", "extra", "helpers"]);
}

/// Every checker of the registry belongs to exactly one of chapters 3-5, so
/// the per-chapter fuzz targets and `wai check --chapter` cover them all.
#[test]
fn every_checker_is_in_one_chapter() {
    let ids = |ch: u8| -> Vec<&'static str> {
        wai_lemmas::checkers_of_chapter(ch)
            .iter()
            .map(|c| c.id)
            .collect()
    };
    let all: Vec<&str> = (3..=5).flat_map(ids).collect();
    let with_checker: Vec<&str> = wai_lemmas::CLAIMS
        .iter()
        .filter(|c| c.checker.is_some())
        .map(|c| c.id)
        .collect();
    assert_eq!(all, with_checker);
    assert_eq!(wai_lemmas::chapter_of("L3.1a"), Some(3));
    assert_eq!(wai_lemmas::chapter_of("T5.17t"), Some(5));
    assert_eq!(wai_lemmas::chapter_of("x"), None);
    assert!(ids(6).is_empty());
}

/// The numbered statements of the thesis: every `**Lemma 3.1`,
/// `**Theorem 4.2`, … (bold, as the thesis states them) as `Lemma 3.1`,
/// and every numbered section heading `# 3.6 …` as `Section 3.6`, sorted.
fn statements_of(thesis: &str) -> BTreeSet<String> {
    const WORDS: [&str; 6] = [
        "Lemma",
        "Theorem",
        "Corollary",
        "Definition",
        "Remark",
        "Observation",
    ];
    let number = |s: &str| -> String {
        s.chars()
            .take_while(|c| c.is_ascii_digit() || *c == '.')
            .collect::<String>()
            .trim_end_matches('.')
            .to_owned()
    };
    let mut out = BTreeSet::new();
    for word in WORDS {
        let bold = format!("**{word} ");
        for (i, _) in thesis.match_indices(&bold) {
            let n = number(&thesis[i + bold.len()..]);
            if !n.is_empty() {
                out.insert(format!("{word} {n}"));
            }
        }
    }
    for line in thesis.lines() {
        if let Some(rest) = line.strip_prefix('#') {
            let n = number(rest.trim_start_matches('#').trim_start());
            if n.contains('.') {
                out.insert(format!("Section {n}"));
            }
        }
    }
    out
}

/// `data/CLAIMS.md` is the team's catalogue, unchanged.
#[test]
fn the_catalogue_is_the_teams() {
    let Some(theirs) = crate::read_team_source("CLAIMS.md") else {
        return;
    };
    assert!(
        crate::read_repo("data/CLAIMS.md") == theirs,
        "data/CLAIMS.md differs from ../shared/CLAIMS.md: copy it again \
         (cp ../shared/CLAIMS.md data/CLAIMS.md)"
    );
}

/// `data/thesis-statements.txt` lists the thesis's numbered statements.
#[test]
fn the_statements_are_the_theses() {
    let Some(thesis) = crate::read_team_source("thesis.md") else {
        return;
    };
    let want: Vec<String> = statements_of(&thesis).into_iter().collect();
    let have = crate::read_repo("data/thesis-statements.txt");
    assert!(
        have.lines().eq(want.iter().map(String::as_str)),
        "data/thesis-statements.txt is not the list of the thesis's statements; \
         it should read:\n{}",
        want.join("\n")
    );
}
