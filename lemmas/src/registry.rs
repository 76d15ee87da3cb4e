//! The claims registry: every claim of the catalogue `CLAIMS.md` as data,
//! one [`Claim`] row per id, with its checker where it has one. The top of
//! the crate: it reads every chapter's checkers and nothing reads it but
//! the crate's users.

use crate::framework::Checker;
use crate::{ch3, ch4, ch5};

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
    /// Its checker, if it has one yet.
    pub checker: Option<Checker>,
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
pub fn checkers_of_chapter(chapter: u8) -> Vec<Checker> {
    checkers()
        .filter(|c| chapter_of(c.id) == Some(chapter))
        .collect()
}

/// Every claim's checker, in catalogue order.
pub fn checkers() -> impl Iterator<Item = Checker> {
    CLAIMS.iter().filter_map(|c| c.checker)
}

/// The checker of claim `id`, if the claim has one.
pub fn checker(id: &str) -> Option<Checker> {
    claim(id).and_then(|c| c.checker)
}

/// The ids of the claims that have no checker yet, in catalogue order.
pub fn claims_without_checker() -> Vec<&'static str> {
    CLAIMS
        .iter()
        .filter(|c| c.checker.is_none())
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
        checker: None,
    }
}

impl Claim {
    /// The same row with its checker.
    const fn checked(self, checker: Checker) -> Claim {
        Claim {
            checker: Some(checker),
            ..self
        }
    }
}

use Kind::{Bound, Exact, ExactTight, Example, Tight};

/// Every claim of `data/CLAIMS.md`, in its order. A test checks this table
/// against the file, id by id and kind by kind.
pub static CLAIMS: &[Claim] = &[
    // Chapter 3 — the Guibas–Motwani–Raghavan scheme.
    c(
        "L3.1a",
        Exact,
        "Lemma 3.1(a)",
        "A reflex vertex of a visibility polygon is never spurious.",
    )
    .checked(ch3::l3_1a::CHECKER),
    c(
        "L3.1b",
        Exact,
        "Lemma 3.1(b)",
        "Two spurious edges of a visibility polygon are never adjacent.",
    )
    .checked(ch3::l3_1b::CHECKER),
    c(
        "L3.1c",
        Exact,
        "Lemma 3.1(c)",
        "A non-spurious edge of V_p is all of its supporting map edge that p sees.",
    )
    .checked(ch3::l3_1c::CHECKER),
    c(
        "D3.5",
        Exact,
        "Definitions 3.5 and 3.6",
        "Non-spurious edges are exactly one of full/half/partial; spurious vertices of half edges lie on spurious edges; blocking vertices are reflex map vertices.",
    )
    .checked(ch3::d3_5::CHECKER),
    c(
        "T3.2",
        Exact,
        "Theorem 3.2",
        "With the viewpoint fixed relative to the skeleton origin, equal visibility polygons and equal skeletons imply each other.",
    )
    .checked(ch3::t3_2::CHECKER),
    c(
        "T3.3a",
        Exact,
        "Theorem 3.3(1)",
        "Every visibility cell is convex.",
    )
    .checked(ch3::t3_3a::CHECKER),
    c(
        "T3.3b",
        Exact,
        "Theorem 3.3(2)",
        "Every interior point has the skeleton of the cell (open face, edge or vertex of the arrangement) that contains it.",
    )
    .checked(ch3::t3_3b::CHECKER),
    c(
        "A3.6",
        Exact,
        "Section 3.6 (boundary assignment)",
        "A point of a visibility ray, given to the cell on its anchor's side, has that cell's skeleton; known false on 1-cells and 0-cells.",
    )
    .checked(ch3::a3_6::CHECKER),
    c(
        "L3.5",
        Exact,
        "Lemma 3.5",
        "A point with skeleton V* lies in the kernel of exactly one embedding of V*.",
    )
    .checked(ch3::l3_5::CHECKER),
    c(
        "L3.7",
        Exact,
        "Lemma 3.7",
        "A skeleton has at most r embeddings, valid or not.",
    )
    .checked(ch3::l3_7::CHECKER),
    c(
        "C3.8",
        Exact,
        "Corollary 3.8",
        "A localization query has at most r answers.",
    )
    .checked(ch3::c3_8::CHECKER),
    c(
        "T3.9a",
        Exact,
        "Theorem 3.9 (proof)",
        "At most 2n decomposition vertices lie on any one visibility ray.",
    )
    .checked(ch3::t3_9a::CHECKER),
    c(
        "T3.9b",
        Bound,
        "Theorem 3.9",
        "The number of cells and their total complexity N is O(n^2 r).",
    )
    .checked(ch3::t3_9b::CHECKER),
    c(
        "T3.9c",
        Tight,
        "Theorem 3.9 (tightness), Fig 3.15",
        "A corridor with r niches opposite a convex chain has Omega(n^2 r) cells.",
    )
    .checked(ch3::t3_9c::CHECKER),
    c(
        "L3.7t",
        Tight,
        "Lemma 3.7 (tightness), Fig 3.12",
        "A corridor of niches gives one skeleton Omega(r) embeddings.",
    )
    .checked(ch3::l3_7t::CHECKER),
    c(
        "T3.10",
        Bound,
        "Theorem 3.10",
        "An equivalence class has total complexity O(n^2).",
    )
    .checked(ch3::t3_10::CHECKER),
    c(
        "R3.4",
        Example,
        "Remark 3.4, Fig 3.10",
        "An embedding can have no witness when its candidate edge is shorter than the artificial edge.",
    )
    .checked(ch3::r3_4::CHECKER),
    // Chapter 4 — overlapping embeddings.
    c(
        "E4.1",
        Example,
        "Examples 4.1 and 4.2, Figs 4.1 and 4.2",
        "Two valid embeddings of one skeleton can have overlapping skeletons and kernels, even with strictly crossing artificial edges.",
    )
    .checked(ch4::e4_1::CHECKER),
    c(
        "L4.1",
        Tight,
        "Lemma 4.1",
        "Omega(r) embeddings of one skeleton can all overlap in one point.",
    )
    .checked(ch4::l4_1::CHECKER),
    c(
        "T4.2",
        Exact,
        "Theorem 4.2",
        "Witnesses of two different valid embeddings of one skeleton whose skeleton polygons overlap never see each other.",
    )
    .checked(ch4::t4_2::CHECKER),
    c(
        "T4.3",
        Exact,
        "Theorem 4.3",
        "Witnesses of two different valid embeddings of one skeleton whose kernels overlap never see each other.",
    )
    .checked(ch4::t4_3::CHECKER),
    c(
        "L4.5",
        Exact,
        "Lemma 4.5",
        "An embedded artificial edge meets at most two artificial edges of another valid embedding, and its part on the intersection boundary is one segment.",
    )
    .checked(ch4::l4_5::CHECKER),
    c(
        "L4.6",
        Exact,
        "Lemma 4.6",
        "Two overlapping valid embeddings intersect in one connected polygon.",
    )
    .checked(ch4::l4_6::CHECKER),
    c(
        "L4.7",
        Exact,
        "Lemma 4.7",
        "Every edge of the intersection polygon of two overlapping valid embeddings is of type 1 to 5.",
    )
    .checked(ch4::l4_7::CHECKER),
    c(
        "L4.8",
        Exact,
        "Lemma 4.8",
        "An artificial edge crossing two artificial edges of the other embedding is LR to both or RL to both.",
    )
    .checked(ch4::l4_8::CHECKER),
    c(
        "L4.9",
        Exact,
        "Lemma 4.9",
        "At most one LR/LR and one RL/RL intersection, and min{x, y} <= 1 for the mixed counts.",
    )
    .checked(ch4::l4_9::CHECKER),
    c(
        "C4.10",
        Exact,
        "Corollary 4.10",
        "An intersection polygon has at most four type-5 edges.",
    )
    .checked(ch4::c4_10::CHECKER),
    c(
        "E4.10",
        Example,
        "Corollary 4.10, Fig 4.16",
        "Four type-5 edges occur, with no map vertex in the intersection polygon.",
    )
    .checked(ch4::e4_10::CHECKER),
    c(
        "C4.15",
        Exact,
        "Corollary 4.15",
        "The intersection of two overlapping valid embeddings of one skeleton lies on one side of the line through any witness pair.",
    )
    .checked(ch4::c4_15::CHECKER),
    c(
        "C4.16",
        Exact,
        "Corollary 4.16",
        "Every line parallel to the translation between the embeddings that crosses their intersection has both witnesses on one side.",
    )
    .checked(ch4::c4_16::CHECKER),
    c(
        "E4.28",
        Example,
        "Section 4.6, Fig 4.28",
        "Embeddings that intersect without overlapping can have mutually visible witnesses.",
    )
    .checked(ch4::e4_28::CHECKER),
    c(
        "L4.17",
        Exact,
        "Lemma 4.17",
        "Lines of sight from one embedded skeleton polygon to candidate edges of two different artificial edges never cross outside it.",
    )
    .checked(ch4::l4_17::CHECKER),
    c(
        "L4.18",
        Exact,
        "Lemma 4.18",
        "For crossing candidate edges c of h and c' of h' with h, h' overlapping, h(a) meets h'(V<>) or h'(a') meets h(V<>).",
    )
    .checked(ch4::l4_18::CHECKER),
    c(
        "T4.19",
        Exact,
        "Theorem 4.19",
        "A candidate edge of an overlapping embedding crossing two candidate edges c1, c2 of one artificial edge is not between them on the boundary.",
    )
    .checked(ch4::t4_19::CHECKER),
    c(
        "C4.20",
        Exact,
        "Corollary 4.20",
        "Mutually crossing candidate edge pairs appear on the boundary as c1, c2, c1', c2' or c1', c2', c1, c2.",
    )
    .checked(ch4::c4_20::CHECKER),
    // Chapter 5 — the complexity of an equivalence class.
    c(
        "O5.3",
        Exact,
        "Observation 5.3",
        "Every edge of every cell of an equivalence class is a kernel edge or a wedge edge.",
    )
    .checked(ch5::o5_3::CHECKER),
    c(
        "L5.1",
        Bound,
        "Lemma 5.1",
        "An equivalence class has O(n + r^2 + W) kernel edges, W its wedge edges.",
    )
    .checked(ch5::l5_1::CHECKER),
    c(
        "L5.2",
        Bound,
        "Lemma 5.2",
        "Wedge edges in one embedding are O(r + (sum of (c_ij - 1))^2 - sum of (c_ij - 1)^2).",
    )
    .checked(ch5::l5_2::CHECKER),
    c(
        "L5.3",
        ExactTight,
        "Lemma 5.3, Fig 5.4",
        "There are at most s*t single candidate edges, so O(min{n, r^2}), and Omega(r^2) is reached.",
    )
    .checked(ch5::l5_3::CHECKER),
    c(
        "L5.4",
        Exact,
        "Lemma 5.4",
        "The number of gaps and the number of multiple candidate edges are within a factor 2 of each other.",
    )
    .checked(ch5::l5_4::CHECKER),
    c(
        "L5.5",
        Exact,
        "Lemma 5.5",
        "Nested or interweaved gaps belong to different embeddings.",
    )
    .checked(ch5::l5_5::CHECKER),
    c(
        "L5.6",
        Exact,
        "Lemma 5.6",
        "The embeddings of two interweaved gaps do not overlap.",
    )
    .checked(ch5::l5_6::CHECKER),
    c(
        "L5.7",
        Exact,
        "Lemma 5.7",
        "All interweaved gap pairs of two embeddings use the same pair of artificial edges.",
    )
    .checked(ch5::l5_7::CHECKER),
    c(
        "L5.8",
        Exact,
        "Lemma 5.8",
        "The interweavement graph has no cycle.",
    )
    .checked(ch5::l5_8::CHECKER),
    c(
        "L5.9",
        Exact,
        "Lemma 5.9",
        "The interweavement graph is a forest with embedding nodes as leaves, special nodes of degree >= 2, and at most twice as many edges as embedding nodes.",
    )
    .checked(ch5::l5_9::CHECKER),
    c(
        "T5.12",
        Bound,
        "Theorem 5.12",
        "A skeleton has O(r) multiple candidate edges.",
    )
    .checked(ch5::t5_12::CHECKER),
    c(
        "L5.13",
        Exact,
        "Lemma 5.13",
        "If map edges e, f are candidate edges of different artificial edges in k >= 2 embeddings, all sight lines to e cross one common embedded artificial edge, and likewise for f.",
    )
    .checked(ch5::l5_13::CHECKER),
    c(
        "L5.14",
        Exact,
        "Lemma 5.14",
        "With k >= 4 such embeddings, at least ceil(k/3) of them pairwise overlap.",
    )
    .checked(ch5::l5_14::CHECKER),
    c(
        "T5.15",
        Exact,
        "Theorem 5.15",
        "A valid candidate edge and a valid multiple candidate edge of different artificial edges share at most 6 embeddings.",
    )
    .checked(ch5::t5_15::CHECKER),
    c(
        "T5.16",
        Bound,
        "Theorem 5.16",
        "An equivalence class has O(r^2) wedge edges.",
    )
    .checked(ch5::t5_16::CHECKER),
    c(
        "T5.17",
        Bound,
        "Theorem 5.17",
        "An equivalence class has O(n + r^2) cells and total complexity.",
    )
    .checked(ch5::t5_17::CHECKER),
    c(
        "T5.17t",
        Tight,
        "Theorem 5.17 (tightness), chapter 5 introduction",
        "Some maps have one equivalence class of complexity Omega(n), others Omega(r^2).",
    )
    .checked(ch5::t5_17t::CHECKER),
    c(
        "C5.18",
        Bound,
        "Corollary 5.18",
        "Algorithm 3.14 preprocesses a map in O(N(n + r^2)) time and space.",
    )
    .checked(ch5::c5_18::CHECKER),
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
