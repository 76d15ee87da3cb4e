//! The candidate edges of one skeleton over all its valid embeddings
//! (thesis sec. 5.3–5.4): the sets C_{i,j}, single and multiple candidate
//! edges (Def 5.4) and the gaps between consecutive candidate edges
//! (Def 5.5).
//!
//! For a skeleton V* with s artificial edges a_1, …, a_s and t valid
//! embeddings h_1, …, h_t, C_{i,j} is the set of valid candidate edges
//! (Def 4.1) of a_i in h_j; they all lie on the line h_j(l_i), and here
//! they are kept in their order along it. A candidate edge is **multiple**
//! if some C_{i,j} holding it has more than one element, **single**
//! otherwise. Two candidate edges consecutive in some C_{i,j} (no other
//! of its edges between them on the line) bound a **gap**; a gap is the
//! pair of map edges, however many sets it is consecutive in.

use std::collections::{BTreeMap, BTreeSet};
use wai_map::Map;

/// C_{i,j} for one skeleton and what Defs 5.4 and 5.5 derive from them.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct CandidateSets {
    /// The artificial edges a_1, …, a_s: skeleton edge indices.
    pub artificial: Vec<usize>,
    /// The valid embeddings h_1, …, h_t: their indices among the
    /// skeleton's embeddings.
    pub embeddings: Vec<usize>,
    /// By valid embedding j, by artificial edge i: C_{i,j}, map edge ids
    /// in their order along the line h_j(l_i).
    pub sets: Vec<Vec<Vec<usize>>>,
    /// C_all: every valid candidate edge.
    pub all: BTreeSet<usize>,
    /// C_mult (Def 5.4).
    pub multiple: BTreeSet<usize>,
    /// The gaps (Def 5.5): pairs of map edges (as ordered along the line)
    /// consecutive in some C_{i,j}, each with the first (i, j) it is
    /// consecutive in.
    pub gaps: BTreeMap<(usize, usize), (usize, usize)>,
}

impl CandidateSets {
    /// From the valid candidate edges of each valid embedding (its index,
    /// and by skeleton edge the valid candidates, empty for full edges, as
    /// `wai_embed::valid_candidate_edges` gives them) and the skeleton's
    /// artificial edges. The edges of each set are ordered along their
    /// common line by their lexicographically least endpoint, which orders
    /// points on one line exactly.
    pub fn new(
        map: &Map,
        artificial: Vec<usize>,
        valid: impl IntoIterator<Item = (usize, Vec<Vec<usize>>)>,
    ) -> CandidateSets {
        let v = map.vertices();
        let least = |e: usize| {
            let (a, b) = (v[e], v[map.next(e)]);
            (a.x, a.y).min((b.x, b.y))
        };
        let mut embeddings = Vec::new();
        let mut sets = Vec::new();
        for (j, by_edge) in valid {
            embeddings.push(j);
            sets.push(
                artificial
                    .iter()
                    .map(|&i| {
                        let mut c = by_edge[i].clone();
                        c.sort_by_key(|&e| least(e));
                        c
                    })
                    .collect(),
            );
        }
        CandidateSets::from_sets(artificial, embeddings, sets)
    }

    /// From sets already ordered along their lines (tests plant sets here).
    pub fn from_sets(
        artificial: Vec<usize>,
        embeddings: Vec<usize>,
        sets: Vec<Vec<Vec<usize>>>,
    ) -> CandidateSets {
        let mut all = BTreeSet::new();
        let mut multiple = BTreeSet::new();
        let mut gaps = BTreeMap::new();
        for (j, by_edge) in sets.iter().enumerate() {
            for (i, c) in by_edge.iter().enumerate() {
                all.extend(c.iter().copied());
                if c.len() > 1 {
                    multiple.extend(c.iter().copied());
                }
                for w in c.windows(2) {
                    gaps.entry((w[0], w[1])).or_insert((i, j));
                }
            }
        }
        CandidateSets {
            artificial,
            embeddings,
            sets,
            all,
            multiple,
            gaps,
        }
    }

    /// s: the number of artificial edges.
    pub fn s(&self) -> usize {
        self.artificial.len()
    }

    /// t: the number of valid embeddings.
    pub fn t(&self) -> usize {
        self.embeddings.len()
    }

    /// c_{i,j} = |C_{i,j}|.
    pub fn c(&self, i: usize, j: usize) -> usize {
        self.sets[j][i].len()
    }

    /// C_sing = C_all \ C_mult (Def 5.4).
    pub fn single(&self) -> BTreeSet<usize> {
        self.all.difference(&self.multiple).copied().collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn single_multiple_and_gaps_of_the_thesis_example() {
        // Fig 3.9's V2*: one artificial edge a_1 and three embeddings with
        // C_{1,1} = {e1, e2}, C_{1,2} = {e1, e2, e3}, C_{1,3} = {e2, e3}.
        let c = CandidateSets::from_sets(
            vec![0],
            vec![0, 1, 2],
            vec![vec![vec![1, 2]], vec![vec![1, 2, 3]], vec![vec![2, 3]]],
        );
        assert_eq!((c.s(), c.t(), c.c(0, 1)), (1, 3, 3));
        assert_eq!(c.multiple, BTreeSet::from([1, 2, 3]));
        assert!(c.single().is_empty());
        // Gaps (e1, e2) and (e2, e3), each consecutive in two sets.
        assert_eq!(c.gaps.len(), 2);
        assert_eq!(c.gaps[&(1, 2)], (0, 0));
        assert_eq!(c.gaps[&(2, 3)], (0, 1));
        // One candidate per set: every edge single, no gap.
        let c = CandidateSets::from_sets(vec![0, 3], vec![4], vec![vec![vec![7], vec![9]]]);
        assert_eq!(c.single(), BTreeSet::from([7, 9]));
        assert!(c.gaps.is_empty());
    }
}
