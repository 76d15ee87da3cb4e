//! Pairs of map edges that are candidate edges of *different* artificial
//! edges in one embedding: the premise shared by Lemma 5.13, Lemma 5.14
//! and Theorem 5.15 (sec. 5.5).
//!
//! For map edges e, f and a valid embedding h_j of a skeleton, (e, f) is
//! such a pair in h_j when e ∈ C_{i,j} and f ∈ C_{ĩ,j} for artificial
//! edges a_i ≠ a_ĩ. By Lemma 4.17 the sets of one embedding are disjoint,
//! so each of e and f has at most one artificial edge in h_j (a violation
//! of that is L4.17's to report; here the first set holding an edge is
//! taken).

use wai_embed::CandidateSets;

/// One embedding in which a pair of map edges are candidate edges of
/// different artificial edges.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shared {
    /// The embedding's position j in [`CandidateSets::embeddings`].
    pub j: usize,
    /// The position i of e's artificial edge in [`CandidateSets::artificial`].
    pub i: usize,
    /// The same of f's, ĩ ≠ i.
    pub i_tilde: usize,
    /// Whether f is a multiple candidate edge *in that set*: |C_{ĩ,j}| > 1.
    /// Theorem 5.15's proof and eq. (5.9) use multiplicity in this sense
    /// (f shares C_{ĩ,j} with another candidate edge f_u).
    pub f_multiple: bool,
}

/// By ordered pair (e, f) of map edges, e ≠ f, ascending: the embeddings
/// that share it ([`shared_embeddings`]), each pair's in increasing j.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct SharedPairs {
    /// The pairs, ascending.
    pairs: Vec<(usize, usize)>,
    /// Pair k's embeddings are `shared[starts[k]..starts[k + 1]]`.
    starts: Vec<usize>,
    shared: Vec<Shared>,
}

impl SharedPairs {
    /// Every pair with its embeddings, pairs ascending.
    pub fn iter(&self) -> impl Iterator<Item = ((usize, usize), &[Shared])> + '_ {
        (0..self.pairs.len()).map(|k| (self.pairs[k], self.of(k)))
    }

    /// The embeddings that share (e, f), if any.
    pub fn get(&self, pair: (usize, usize)) -> Option<&[Shared]> {
        let k = self.pairs.binary_search(&pair).ok()?;
        Some(self.of(k))
    }

    /// The number of pairs.
    pub fn len(&self) -> usize {
        self.pairs.len()
    }

    /// Whether no pair is shared.
    pub fn is_empty(&self) -> bool {
        self.pairs.is_empty()
    }

    fn of(&self, k: usize) -> &[Shared] {
        &self.shared[self.starts[k]..self.starts[k + 1]]
    }
}

/// By ordered pair (e, f) of map edges, e ≠ f: every valid embedding in
/// which e and f are candidate edges of different artificial edges, in
/// increasing j. [`crate::Study::edge_pairs`] keeps them per class.
pub fn shared_embeddings(c: &CandidateSets) -> SharedPairs {
    let mut entries: Vec<((usize, usize), Shared)> = Vec::new();
    let mut owner: Vec<(usize, usize)> = Vec::new();
    for (j, by_edge) in c.sets.iter().enumerate() {
        // Map edge -> the first artificial edge holding it (Lemma 4.17).
        owner.clear();
        for (i, set) in by_edge.iter().enumerate() {
            owner.extend(set.iter().map(|&e| (e, i)));
        }
        owner.sort_by_key(|&(e, _)| e); // stable: the first i first
        owner.dedup_by_key(|&mut (e, _)| e);
        for &(e, i) in &owner {
            for &(f, i_tilde) in &owner {
                if i != i_tilde {
                    let s = Shared {
                        j,
                        i,
                        i_tilde,
                        f_multiple: by_edge[i_tilde].len() > 1,
                    };
                    entries.push(((e, f), s));
                }
            }
        }
    }
    // By pair, then j (each embedding gives a pair once).
    entries.sort_unstable_by_key(|&(pair, s)| (pair, s.j));
    let mut out = SharedPairs {
        pairs: Vec::new(),
        starts: Vec::new(),
        shared: Vec::with_capacity(entries.len()),
    };
    for (pair, s) in entries {
        if out.pairs.last() != Some(&pair) {
            out.pairs.push(pair);
            out.starts.push(out.shared.len());
        }
        out.shared.push(s);
    }
    out.starts.push(out.shared.len());
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pairs_of_different_artificial_edges_only() {
        // Two embeddings; in the first a_0 holds {1, 2} and a_1 holds {3};
        // in the second a_0 holds {1} and a_1 holds {3, 4}.
        let c = CandidateSets::from_sets(
            vec![0, 1],
            vec![0, 1],
            vec![vec![vec![1, 2], vec![3]], vec![vec![1], vec![3, 4]]],
        );
        let pairs = shared_embeddings(&c);
        // 1 and 2 share a_0 in the first embedding: never a pair.
        assert!(pairs.get((1, 2)).is_none());
        let p13 = pairs.get((1, 3)).unwrap();
        assert_eq!(p13.len(), 2);
        assert_eq!((p13[0].f_multiple, p13[1].f_multiple), (false, true));
        let p31 = pairs.get((3, 1)).unwrap();
        assert_eq!((p31[0].f_multiple, p31[1].f_multiple), (true, false));
        assert_eq!(pairs.get((4, 1)).unwrap().len(), 1);
        // (1, 3), (1, 4), (2, 3), (3, 1), (3, 2), (4, 1), in order.
        let all: Vec<(usize, usize)> = pairs.iter().map(|(p, _)| p).collect();
        assert_eq!(all, [(1, 3), (1, 4), (2, 3), (3, 1), (3, 2), (4, 1)]);
    }
}
