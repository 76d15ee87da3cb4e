//! Gaps between consecutive candidate edges as chains of the map's
//! boundary (Def 5.5), and when two of them are nested or interweaved
//! (Def 5.6).
//!
//! The edges of one set C_{i,j} lie on the line h_j(l_i) and face the
//! embedding, so the map's interior lies on the same side of each and the
//! boundary runs along all of them in one direction. The gap g(s, e) of
//! two consecutive ones is the boundary chain from s forward to e,
//! `s, s+1, …, e` (indices mod n), s being the one first along that
//! direction: the chain "s₁s₂, …, e₂e₁" of Def 5.5, which leaves the line
//! behind s and comes back to it at e. [`GapChain::holds_own_set`] tells
//! when that chain passes another edge of its own set, which the reading
//! excludes (counted by the checkers, never seen on the stress corpus).
//!
//! # "Part of the polygonal chain" (Def 5.6)
//! Read literally with closed chains, two gaps g(a₁, a₂) and g(a₂, a₃) of
//! one set would be interweaved (a₂ is in both), yet Lemma 5.5 says two
//! gaps of one embedding never are, and its proof leans on consecutive
//! edges. So: g₁ is **nested** into g₂ when s₁ and e₁ lie on the closed
//! chain g₂; the two are **interweaved** when neither is nested into the
//! other and an end of each lies strictly inside the other (on the chain,
//! not its end edges). Two gaps that only share an end edge are neither.

use wai_map::Map;

/// One gap of one set C_{i,j}: the map edges s and e, the set it is
/// consecutive in, and its chain on the boundary.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct GapChain {
    /// The first and last edge of the chain (s first along the boundary).
    pub s: usize,
    pub e: usize,
    /// The embedding's position j and the artificial edge's position i in
    /// [`crate::CandidateSets`].
    pub j: usize,
    pub i: usize,
    /// The number of boundary steps from s to e: the chain is the edges
    /// s + k mod n for k in 0..=len.
    pub len: usize,
    n: usize,
}

/// How two gaps lie on the boundary (Def 5.6, as the module doc reads it).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum GapRelation {
    /// The first gap's ends lie on the second's chain.
    NestedInto,
    /// The second gap's ends lie on the first's chain.
    Holds,
    Interweaved,
    Apart,
}

impl GapRelation {
    pub fn is_nested(self) -> bool {
        matches!(self, GapRelation::NestedInto | GapRelation::Holds)
    }
}

impl GapChain {
    /// The chain of gap (s, e) of C_{i,j} on a boundary of `n` edges, from
    /// s forward to e (tests plant chains here; maps use [`gap_chains`]).
    pub fn new(s: usize, e: usize, j: usize, i: usize, n: usize) -> GapChain {
        GapChain {
            s,
            e,
            j,
            i,
            len: (e + n - s) % n,
            n,
        }
    }

    /// The steps from this chain's first edge to map edge `x`.
    fn offset(&self, x: usize) -> usize {
        (x + self.n - self.s) % self.n
    }

    /// Whether map edge `x` is on the closed chain.
    pub fn holds(&self, x: usize) -> bool {
        self.offset(x) <= self.len
    }

    /// Whether map edge `x` is on the chain but not one of its end edges.
    pub fn holds_inside(&self, x: usize) -> bool {
        (1..self.len).contains(&self.offset(x))
    }

    /// The map edges of the chain, from s to e.
    pub fn edges(&self) -> impl Iterator<Item = usize> + '_ {
        (0..=self.len).map(|k| (self.s + k) % self.n)
    }

    /// Whether the chain passes an edge of its own set other than its ends.
    pub fn holds_own_set(&self, set: &[usize]) -> bool {
        set.iter().any(|&x| self.holds_inside(x))
    }

    /// Def 5.6 for two different gaps (different pairs of map edges).
    pub fn relation(&self, other: &GapChain) -> GapRelation {
        if other.holds(self.s) && other.holds(self.e) {
            GapRelation::NestedInto
        } else if self.holds(other.s) && self.holds(other.e) {
            GapRelation::Holds
        } else if (other.holds_inside(self.s) || other.holds_inside(self.e))
            && (self.holds_inside(other.s) || self.holds_inside(other.e))
        {
            GapRelation::Interweaved
        } else {
            GapRelation::Apart
        }
    }

    /// Whether the two are the same gap: the same pair of map edges.
    pub fn same_edges(&self, other: &GapChain) -> bool {
        (self.s, self.e) == (other.s, other.e)
    }
}

/// Every gap of every set C_{i,j} of `sets` (as [`crate::CandidateSets`]
/// holds them: by j, by i, ordered along their line), as chains of `map`.
pub fn gap_chains(map: &Map, sets: &[Vec<Vec<usize>>]) -> Vec<GapChain> {
    let v = map.vertices();
    let n = v.len();
    let mut out = Vec::new();
    for (j, by_edge) in sets.iter().enumerate() {
        for (i, set) in by_edge.iter().enumerate() {
            for w in set.windows(2) {
                // The sets are ordered by least endpoint, lexicographically;
                // the boundary runs along them lexicographically forward iff
                // an edge's direction is lexicographically positive.
                let (a, b) = (v[w[0]], v[(w[0] + 1) % n]);
                let forward = (b.x, b.y) > (a.x, a.y);
                let (s, e) = if forward { (w[0], w[1]) } else { (w[1], w[0]) };
                out.push(GapChain::new(s, e, j, i, n));
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use wai_exact::Point;

    fn map_of(pts: &[(i128, i128)]) -> Map {
        Map::from_ring(pts.iter().map(|&(x, y)| Point::new(x, y)).collect())
            .unwrap()
            .0
    }

    fn chain(s: usize, e: usize, n: usize) -> GapChain {
        GapChain::new(s, e, 0, 0, n)
    }

    #[test]
    fn relations_on_a_cycle_of_twenty_edges() {
        let n = 20;
        let g = |s, e| chain(s, e, n);
        // Consecutive gaps of one set share an end edge: apart.
        assert_eq!(g(1, 5).relation(&g(5, 9)), GapRelation::Apart);
        assert_eq!(g(1, 9).relation(&g(3, 6)), GapRelation::Holds);
        assert_eq!(g(3, 6).relation(&g(1, 9)), GapRelation::NestedInto);
        // A shared end edge and the other end inside: nested.
        assert_eq!(g(1, 5).relation(&g(1, 9)), GapRelation::NestedInto);
        assert_eq!(g(1, 6).relation(&g(4, 9)), GapRelation::Interweaved);
        assert_eq!(g(4, 9).relation(&g(1, 6)), GapRelation::Interweaved);
        // Around the end of the numbering.
        assert_eq!(g(17, 3).relation(&g(1, 8)), GapRelation::Interweaved);
        assert_eq!(g(17, 3).relation(&g(18, 2)), GapRelation::Holds);
        assert_eq!(g(10, 12).relation(&g(17, 3)), GapRelation::Apart);
        assert!(g(17, 3).holds(0) && g(17, 3).holds_inside(19) && !g(17, 3).holds_inside(3));
        assert_eq!(
            g(17, 3).edges().collect::<Vec<_>>(),
            [17, 18, 19, 0, 1, 2, 3]
        );
    }

    #[test]
    fn the_chain_of_a_niche_runs_behind_the_line() {
        // A room with a notch in its floor: edges 0 and 4 lie on y = 0, the
        // notch (edges 1–3) below; both edges run in +x.
        let map = map_of(&[
            (0, 0),
            (2, 0),
            (2, -1),
            (3, -1),
            (3, 0),
            (5, 0),
            (5, 4),
            (0, 4),
        ]);
        let gaps = gap_chains(&map, &[vec![vec![0, 4]]]);
        assert_eq!(gaps.len(), 1);
        assert_eq!(gaps[0].edges().collect::<Vec<_>>(), [0, 1, 2, 3, 4]);
        // Reversed orientation: the same room traversed clockwise is not a
        // map, so flip the notch to the ceiling, where edges run in -x.
        let map = map_of(&[
            (0, 0),
            (5, 0),
            (5, 4),
            (3, 4),
            (3, 5),
            (2, 5),
            (2, 4),
            (0, 4),
        ]);
        // Edges 2 ((5,4)→(3,4)) and 6 ((2,4)→(0,4)), ordered by least
        // endpoint: 6 first, but the boundary runs from 2 to 6.
        let gaps = gap_chains(&map, &[vec![vec![6, 2]]]);
        assert_eq!((gaps[0].s, gaps[0].e, gaps[0].len), (2, 6, 4));
        assert!(!gaps[0].holds_own_set(&[6, 2]));
    }
}
