//! The claims registry and the checker driver.
//!
//! Every claim of chapters 3–5 of the thesis "Where am I? Indoor Localization
//! Based on Range Measurements" that a program can test has an id in
//! `shared/CLAIMS.md` (`L3.1a`, `T4.2`, `T5.17`, …). This crate holds that
//! catalogue as data, [`CLAIMS`], one [`Claim`] row per id, and the machinery
//! that runs checkers of those claims over maps: the [`Checker`] trait, the
//! [`Report`] every checker returns and the driver [`run`], which sums the
//! reports into a [`Summary`].
//!
//! # Architecture
//!
//! - `lib.rs` (this file): the [`CLAIMS`] table, [`Kind`], [`Status`].
//! - [`driver`]: [`Checker`], [`Report`], [`Violation`], [`run`], [`Summary`].
//! - [`sample`]: the viewpoints and visibility polygons the chapter 3
//!   checkers examine, and Def 3.4 read off a polygon's geometry. Like
//!   `driver`, not a claim's module; nor are [`ratio`] (the bound checkers'
//!   ratios), [`study`] (the structures built once per map), [`wedge_counts`]
//!   (kernel and wedge edges counted per class and embedding) and [`family`]
//!   (which maps are a thesis family, for the `tight` checkers).
//! - [`record`]: [`record::RunRecord`], what a run found, stored in
//!   `lemmas/last-run.json` for `wai claims` and the claims table of
//!   `README.md`.
//! - One module per claim, named after the claim's id in lower case with `.`
//!   replaced by `_` ([`Claim::module_name`]): [`l3_1a`], [`l3_1b`],
//!   [`l3_1c`], [`d3_5`], [`t3_2`], [`t3_3a`], [`t3_3b`], [`a3_6`], [`l3_5`],
//!   [`l3_7`], [`l3_7t`], [`t3_9a`], [`t3_9b`], [`t3_10`], [`l4_1`],
//!   [`l4_5`], [`l4_6`], [`l4_7`], [`l4_8`], [`l4_9`], [`c4_10`], [`c4_15`],
//!   [`c4_16`], [`l4_17`], [`l4_18`], [`t4_19`], [`c4_20`], [`t4_2`],
//!   [`t4_3`], [`o5_3`], [`l5_1`], [`l5_2`], [`l5_3`], [`l5_4`], [`t5_12`],
//!   [`t5_16`], [`t5_17`] so far; the rest of
//!   chapter 5 to come.
//!   Each module
//!   - opens with a doc comment that states the claim in our own words and
//!     cites the thesis (`/// Claim T4.2 (Theorem 4.2).`),
//!   - has a `## Trust` paragraph: exhaustive or sampled, and what the verdict
//!     rests on (STYLE.md 15),
//!   - exports one type implementing [`Checker`] whose `check` returns the
//!     number of instances examined and every violation with the data needed
//!     to replay it,
//!   - has a planted-violation test proving the checker can fail (STYLE.md 6).
//!
//!   When a module lands, its row in [`CLAIMS`] changes from
//!   [`Status::NoCheckerYet`] to [`Status::Checker`].
//!
//! **Invariant:** a checker never mutates what it checks; it reads a
//! `wai_map::Map` (and, later, the stage structures built from it).
//!
//! **Invariant:** nothing passes vacuously. A report always carries
//! `examined`; a claim whose count stays 0 over a run is named in
//! [`Summary::untested`], and a claim no checker of the run covers is named by
//! [`Summary::not_run`]. The integration tests fail if this table and
//! `shared/CLAIMS.md` disagree, in either direction.

pub mod a3_6;
pub mod c4_10;
pub mod c4_15;
pub mod c4_16;
pub mod c4_20;
pub mod check;
pub mod corpus;
pub mod counterexample;
pub mod d3_5;
pub mod driver;
pub mod edge_pairs;
pub mod family;
pub mod l3_1a;
pub mod l3_1b;
pub mod l3_1c;
pub mod l3_5;
pub mod l3_7;
pub mod l3_7t;
pub mod l4_1;
pub mod l4_17;
pub mod l4_18;
pub mod l4_5;
pub mod l4_6;
pub mod l4_7;
pub mod l4_8;
pub mod l4_9;
pub mod l5_1;
pub mod l5_13;
pub mod l5_14;
pub mod l5_2;
pub mod l5_3;
pub mod l5_4;
pub mod l5_5;
pub mod l5_6;
pub mod l5_7;
pub mod l5_8;
pub mod l5_9;
pub mod o5_3;
pub mod planted;
pub mod provenance;
pub mod ratio;
pub mod record;
pub mod sample;
pub mod shrink;
pub mod study;
pub mod t3_10;
pub mod t3_2;
pub mod t3_3a;
pub mod t3_3b;
pub mod t3_9a;
pub mod t3_9b;
pub mod t4_19;
pub mod t4_2;
pub mod t4_3;
pub mod t5_12;
pub mod t5_15;
pub mod t5_16;
pub mod t5_17;
pub mod t5_17t;
pub mod wedge_counts;

pub use driver::{
    run, Checker, ClaimTally, FoundLargest, FoundViolation, Largest, Report, Summary, Violation,
};
pub use study::Study;

/// What kind of statement a claim is (the "kind" column of `CLAIMS.md`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Kind {
    /// A yes/no statement about one map; one violation is a counterexample
    /// to the thesis or a bug in our code.
    Exact,
    /// An asymptotic upper bound, measured as a ratio on every map and by a
    /// growth fit on the scaling families.
    Bound,
    /// A worst-case construction that a generator family must reproduce.
    Tight,
    /// A figure showing that a surprising configuration exists; its map lives
    /// in `counterexamples/`.
    Example,
    /// `exact+tight`: an exact statement whose bound is also shown tight.
    ExactTight,
}

impl Kind {
    /// The spelling used in the kind column of `CLAIMS.md`.
    pub const fn as_catalogue_str(self) -> &'static str {
        match self {
            Kind::Exact => "exact",
            Kind::Bound => "bound",
            Kind::Tight => "tight",
            Kind::Example => "example",
            Kind::ExactTight => "exact+tight",
        }
    }

    /// Parses the spelling used in the kind column of `CLAIMS.md`.
    pub fn from_catalogue_str(s: &str) -> Option<Kind> {
        [
            Kind::Exact,
            Kind::Bound,
            Kind::Tight,
            Kind::Example,
            Kind::ExactTight,
        ]
        .into_iter()
        .find(|k| k.as_catalogue_str() == s)
    }
}

impl std::fmt::Display for Kind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.as_catalogue_str())
    }
}

/// Whether a claim has a checker yet.
#[derive(Debug, Clone, Copy)]
pub enum Status {
    /// No module checks this claim yet; every run names it as untested.
    NoCheckerYet,
    /// The claim's checker, built by this constructor.
    Checker(fn() -> Box<dyn Checker>),
}

impl Status {
    /// True if the claim has a checker.
    pub const fn has_checker(&self) -> bool {
        matches!(self, Status::Checker(_))
    }
}

/// One row of the claims catalogue.
#[derive(Debug, Clone, Copy)]
pub struct Claim {
    /// The project's id, as in the first column of `CLAIMS.md` (`"T4.2"`).
    pub id: &'static str,
    /// Exact, bound, tight, example or exact+tight.
    pub kind: Kind,
    /// Where the thesis states it (`"Theorem 4.2"`, `"Lemma 3.1(a)"`).
    pub reference: &'static str,
    /// The claim in one line, in our own words.
    pub statement: &'static str,
    /// Whether a checker exists.
    pub status: Status,
}

impl Claim {
    /// The name of the module that will check this claim: the id in lower
    /// case with `.` replaced by `_` (`"T4.2"` → `"t4_2"`, `"L3.7t"` →
    /// `"l3_7t"`).
    pub fn module_name(&self) -> String {
        self.id.to_ascii_lowercase().replace('.', "_")
    }
}

/// The row of `id`, if the catalogue has one.
pub fn claim(id: &str) -> Option<&'static Claim> {
    CLAIMS.iter().find(|c| c.id == id)
}

/// The chapter of a claim id: the digit after its leading letters (`"T4.2"`
/// → 4, `"L3.1a"` → 3).
pub fn chapter_of(id: &str) -> Option<u8> {
    let digit = id.trim_start_matches(|c: char| c.is_ascii_alphabetic());
    digit.chars().next()?.to_digit(10).map(|d| d as u8)
}

/// The checkers of every claim of chapter `chapter` (3, 4 or 5) that has
/// one, in catalogue order; empty for a chapter without claims.
pub fn checkers_of_chapter(chapter: u8) -> Vec<Box<dyn Checker>> {
    makers()
        .filter(|(id, _)| chapter_of(id) == Some(chapter))
        .map(|(_, make)| make())
        .collect()
}

/// Every claim that has a checker, with the checker's constructor, in
/// catalogue order.
pub fn makers() -> impl Iterator<Item = (&'static str, check::Maker)> {
    CLAIMS.iter().filter_map(|c| match c.status {
        Status::Checker(make) => Some((c.id, make)),
        Status::NoCheckerYet => None,
    })
}

/// True if a violation of `claim` with replay data `data` is one of the
/// known failures that every run counts apart instead of as a
/// counterexample: the sec. 3.6 rule on 1- and 0-cells (A3.6,
/// [`a3_6::is_known_failure`]) and edges on rays from hidden vertices
/// (O5.3, [`o5_3::is_known_failure`]). Their data's `"kind"` names which.
pub fn is_known_failure(claim: &str, data: &serde_json::Value) -> bool {
    match claim {
        "A3.6" => a3_6::is_known_failure(data),
        "O5.3" => o5_3::is_known_failure(data),
        _ => false,
    }
}

/// The ids of the claims that have no checker yet, in catalogue order.
pub fn claims_without_checker() -> Vec<&'static str> {
    CLAIMS
        .iter()
        .filter(|c| !c.status.has_checker())
        .map(|c| c.id)
        .collect()
}

/// Shorthand for the table below.
const fn c(
    id: &'static str,
    kind: Kind,
    reference: &'static str,
    statement: &'static str,
) -> Claim {
    Claim {
        id,
        kind,
        reference,
        statement,
        status: Status::NoCheckerYet,
    }
}

impl Claim {
    /// The same row with a checker.
    const fn checked(self, make: fn() -> Box<dyn Checker>) -> Claim {
        Claim {
            status: Status::Checker(make),
            ..self
        }
    }
}

use Kind::{Bound, Exact, ExactTight, Example, Tight};

/// Every claim of `shared/CLAIMS.md`, in its order. A test checks this table
/// against the file, id by id and kind by kind.
pub static CLAIMS: &[Claim] = &[
    // Chapter 3 — the Guibas–Motwani–Raghavan scheme.
    c(
        "L3.1a",
        Exact,
        "Lemma 3.1(a)",
        "A reflex vertex of a visibility polygon is never spurious.",
    )
    .checked(l3_1a::checker),
    c(
        "L3.1b",
        Exact,
        "Lemma 3.1(b)",
        "Two spurious edges of a visibility polygon are never adjacent.",
    )
    .checked(l3_1b::checker),
    c(
        "L3.1c",
        Exact,
        "Lemma 3.1(c)",
        "A non-spurious edge of V_p is all of its supporting map edge that p sees.",
    )
    .checked(l3_1c::checker),
    c(
        "D3.5",
        Exact,
        "Definitions 3.5 and 3.6",
        "Non-spurious edges are exactly one of full/half/partial; spurious vertices of half edges lie on spurious edges; blocking vertices are reflex map vertices.",
    )
    .checked(d3_5::checker),
    c(
        "T3.2",
        Exact,
        "Theorem 3.2",
        "With the viewpoint fixed relative to the skeleton origin, equal visibility polygons and equal skeletons imply each other.",
    )
    .checked(t3_2::checker),
    c(
        "T3.3a",
        Exact,
        "Theorem 3.3(1)",
        "Every visibility cell is convex.",
    )
    .checked(t3_3a::checker),
    c(
        "T3.3b",
        Exact,
        "Theorem 3.3(2)",
        "Every interior point has the skeleton of the cell (open face, edge or vertex of the arrangement) that contains it.",
    )
    .checked(t3_3b::checker),
    c(
        "A3.6",
        Exact,
        "Section 3.6 (boundary assignment)",
        "A point of a visibility ray, given to the cell on its anchor's side, has that cell's skeleton; known false on 1-cells and 0-cells.",
    )
    .checked(a3_6::checker),
    c(
        "L3.5",
        Exact,
        "Lemma 3.5",
        "A point with skeleton V* lies in the kernel of exactly one embedding of V*.",
    )
    .checked(l3_5::checker),
    c(
        "L3.7",
        Exact,
        "Lemma 3.7",
        "A skeleton has at most r embeddings, valid or not.",
    )
    .checked(l3_7::checker),
    c(
        "C3.8",
        Exact,
        "Corollary 3.8",
        "A localization query has at most r answers.",
    ),
    c(
        "T3.9a",
        Exact,
        "Theorem 3.9 (proof)",
        "At most 2n decomposition vertices lie on any one visibility ray.",
    )
    .checked(t3_9a::checker),
    c(
        "T3.9b",
        Bound,
        "Theorem 3.9",
        "The number of cells and their total complexity N is O(n^2 r).",
    )
    .checked(t3_9b::checker),
    c(
        "T3.9c",
        Tight,
        "Theorem 3.9 (tightness), Fig 3.15",
        "A corridor with r niches opposite a convex chain has Omega(n^2 r) cells.",
    ),
    c(
        "L3.7t",
        Tight,
        "Lemma 3.7 (tightness), Fig 3.12",
        "A corridor of niches gives one skeleton Omega(r) embeddings.",
    )
    .checked(l3_7t::checker),
    c(
        "T3.10",
        Bound,
        "Theorem 3.10",
        "An equivalence class has total complexity O(n^2).",
    )
    .checked(t3_10::checker),
    c(
        "R3.4",
        Example,
        "Remark 3.4, Fig 3.10",
        "An embedding can have no witness when its candidate edge is shorter than the artificial edge.",
    ),
    // Chapter 4 — overlapping embeddings.
    c(
        "E4.1",
        Example,
        "Examples 4.1 and 4.2, Figs 4.1 and 4.2",
        "Two valid embeddings of one skeleton can have overlapping skeletons and kernels, even with strictly crossing artificial edges.",
    ),
    c(
        "L4.1",
        Tight,
        "Lemma 4.1",
        "Omega(r) embeddings of one skeleton can all overlap in one point.",
    )
    .checked(l4_1::checker),
    c(
        "T4.2",
        Exact,
        "Theorem 4.2",
        "Witnesses of two different valid embeddings of one skeleton whose skeleton polygons overlap never see each other.",
    )
    .checked(t4_2::checker),
    c(
        "T4.3",
        Exact,
        "Theorem 4.3",
        "Witnesses of two different valid embeddings of one skeleton whose kernels overlap never see each other.",
    )
    .checked(t4_3::checker),
    c(
        "L4.5",
        Exact,
        "Lemma 4.5",
        "An embedded artificial edge meets at most two artificial edges of another valid embedding, and its part on the intersection boundary is one segment.",
    )
    .checked(l4_5::checker),
    c(
        "L4.6",
        Exact,
        "Lemma 4.6",
        "Two overlapping valid embeddings intersect in one connected polygon.",
    )
    .checked(l4_6::checker),
    c(
        "L4.7",
        Exact,
        "Lemma 4.7",
        "Every edge of the intersection polygon of two overlapping valid embeddings is of type 1 to 5.",
    )
    .checked(l4_7::checker),
    c(
        "L4.8",
        Exact,
        "Lemma 4.8",
        "An artificial edge crossing two artificial edges of the other embedding is LR to both or RL to both.",
    )
    .checked(l4_8::checker),
    c(
        "L4.9",
        Exact,
        "Lemma 4.9",
        "At most one LR/LR and one RL/RL intersection, and min{x, y} <= 1 for the mixed counts.",
    )
    .checked(l4_9::checker),
    c(
        "C4.10",
        Exact,
        "Corollary 4.10",
        "An intersection polygon has at most four type-5 edges.",
    )
    .checked(c4_10::checker),
    c(
        "E4.10",
        Example,
        "Corollary 4.10, Fig 4.16",
        "Four type-5 edges occur, with no map vertex in the intersection polygon.",
    ),
    c(
        "C4.15",
        Exact,
        "Corollary 4.15",
        "The intersection of two overlapping valid embeddings of one skeleton lies on one side of the line through any witness pair.",
    )
    .checked(c4_15::checker),
    c(
        "C4.16",
        Exact,
        "Corollary 4.16",
        "Every line parallel to the translation between the embeddings that crosses their intersection has both witnesses on one side.",
    )
    .checked(c4_16::checker),
    c(
        "E4.28",
        Example,
        "Section 4.6, Fig 4.28",
        "Embeddings that intersect without overlapping can have mutually visible witnesses.",
    ),
    c(
        "L4.17",
        Exact,
        "Lemma 4.17",
        "Lines of sight from one embedded skeleton polygon to candidate edges of two different artificial edges never cross outside it.",
    )
    .checked(l4_17::checker),
    c(
        "L4.18",
        Exact,
        "Lemma 4.18",
        "For crossing candidate edges c of h and c' of h' with h, h' overlapping, h(a) meets h'(V<>) or h'(a') meets h(V<>).",
    )
    .checked(l4_18::checker),
    c(
        "T4.19",
        Exact,
        "Theorem 4.19",
        "A candidate edge of an overlapping embedding crossing two candidate edges c1, c2 of one artificial edge is not between them on the boundary.",
    )
    .checked(t4_19::checker),
    c(
        "C4.20",
        Exact,
        "Corollary 4.20",
        "Mutually crossing candidate edge pairs appear on the boundary as c1, c2, c1', c2' or c1', c2', c1, c2.",
    )
    .checked(c4_20::checker),
    // Chapter 5 — the complexity of an equivalence class.
    c(
        "O5.3",
        Exact,
        "Observation 5.3",
        "Every edge of every cell of an equivalence class is a kernel edge or a wedge edge.",
    )
    .checked(o5_3::checker),
    c(
        "L5.1",
        Bound,
        "Lemma 5.1",
        "An equivalence class has O(n + r^2 + W) kernel edges, W its wedge edges.",
    )
    .checked(l5_1::checker),
    c(
        "L5.2",
        Bound,
        "Lemma 5.2",
        "Wedge edges in one embedding are O(r + (sum of (c_ij - 1))^2 - sum of (c_ij - 1)^2).",
    )
    .checked(l5_2::checker),
    c(
        "L5.3",
        ExactTight,
        "Lemma 5.3, Fig 5.4",
        "There are at most s*t single candidate edges, so O(min{n, r^2}), and Omega(r^2) is reached.",
    )
    .checked(l5_3::checker),
    c(
        "L5.4",
        Exact,
        "Lemma 5.4",
        "The number of gaps and the number of multiple candidate edges are within a factor 2 of each other.",
    )
    .checked(l5_4::checker),
    c(
        "L5.5",
        Exact,
        "Lemma 5.5",
        "Nested or interweaved gaps belong to different embeddings.",
    )
    .checked(l5_5::checker),
    c(
        "L5.6",
        Exact,
        "Lemma 5.6",
        "The embeddings of two interweaved gaps do not overlap.",
    )
    .checked(l5_6::checker),
    c(
        "L5.7",
        Exact,
        "Lemma 5.7",
        "All interweaved gap pairs of two embeddings use the same pair of artificial edges.",
    )
    .checked(l5_7::checker),
    c(
        "L5.8",
        Exact,
        "Lemma 5.8",
        "The interweavement graph has no cycle.",
    )
    .checked(l5_8::checker),
    c(
        "L5.9",
        Exact,
        "Lemma 5.9",
        "The interweavement graph is a forest with embedding nodes as leaves, special nodes of degree >= 2, and at most twice as many edges as embedding nodes.",
    )
    .checked(l5_9::checker),
    c(
        "T5.12",
        Bound,
        "Theorem 5.12",
        "A skeleton has O(r) multiple candidate edges.",
    )
    .checked(t5_12::checker),
    c(
        "L5.13",
        Exact,
        "Lemma 5.13",
        "If map edges e, f are candidate edges of different artificial edges in k >= 2 embeddings, all sight lines to e cross one common embedded artificial edge, and likewise for f.",
    )
    .checked(l5_13::checker),
    c(
        "L5.14",
        Exact,
        "Lemma 5.14",
        "With k >= 4 such embeddings, at least ceil(k/3) of them pairwise overlap.",
    )
    .checked(l5_14::checker),
    c(
        "T5.15",
        Exact,
        "Theorem 5.15",
        "A valid candidate edge and a valid multiple candidate edge of different artificial edges share at most 6 embeddings.",
    )
    .checked(t5_15::checker),
    c(
        "T5.16",
        Bound,
        "Theorem 5.16",
        "An equivalence class has O(r^2) wedge edges.",
    )
    .checked(t5_16::checker),
    c(
        "T5.17",
        Bound,
        "Theorem 5.17",
        "An equivalence class has O(n + r^2) cells and total complexity.",
    )
    .checked(t5_17::checker),
    c(
        "T5.17t",
        Tight,
        "Theorem 5.17 (tightness), chapter 5 introduction",
        "Some maps have one equivalence class of complexity Omega(n), others Omega(r^2).",
    )
    .checked(t5_17t::checker),
    c(
        "C5.18",
        Bound,
        "Corollary 5.18",
        "Algorithm 3.14 preprocesses a map in O(N(n + r^2)) time and space.",
    ),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn kinds_round_trip_through_their_catalogue_spelling() {
        for k in [Exact, Bound, Tight, Example, ExactTight] {
            assert_eq!(Kind::from_catalogue_str(k.as_catalogue_str()), Some(k));
        }
        assert_eq!(Kind::from_catalogue_str("exact + tight"), None);
    }

    #[test]
    fn module_names_follow_the_id() {
        assert_eq!(
            claim("T4.2").map(Claim::module_name).as_deref(),
            Some("t4_2")
        );
        assert_eq!(
            claim("L3.7t").map(Claim::module_name).as_deref(),
            Some("l3_7t")
        );
        assert!(claim("X9.9").is_none());
    }
}
