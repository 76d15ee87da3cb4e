//! The additional coarsening step of thesis sec. 6.10.4: neighbouring
//! cells whose skeletons differ by a small distance `D` are combined into
//! one bigger cell, so that the Monotonous Bisector Tree (sec. 6.4;
//! Noltemeier, Verbarg and Zirkelbach 1992/93) is built over fewer items.
//!
//! [`coarsen`] works on items `0..n`, a neighbour graph on them and `D` as
//! a closure. It visits the neighbour pairs in ascending order of their
//! `D` and merges the two groups of a pair if one group's representative
//! is within the threshold of every member of the other group; the merged
//! group keeps that representative.
//!
//! # Guarantee
//! - Every member `m` of a group with representative `r` has
//!   `dist(r, m) ≤ threshold` (evaluated in that argument order, exactly as
//!   the merge checked it; `m = r` is not evaluated, its distance being 0
//!   for a pseudo-metric). So a group is a ball of radius `threshold`
//!   around its representative, which stands for the whole group.
//! - Every group is connected in the neighbour graph: groups only merge
//!   along a neighbour pair.
//!
//! # Edge cases
//! - Threshold 0 merges only items at distance 0 (identical skeletons);
//!   a negative or `NaN` threshold merges nothing.
//! - A threshold no smaller than every distance (`f64::INFINITY`, say)
//!   merges each connected component of the neighbour graph into one
//!   group.
//! - Pairs `(i, i)` are ignored; `(i, j)` and `(j, i)` are the same pair,
//!   listed once or many times. Pairs with equal `D` are taken in
//!   ascending `(min, max)` order, so the result does not depend on the
//!   order of `neighbours`.
//! - When both representatives qualify, the representative of the larger
//!   group is kept (of equal sizes, the one with the smaller index); if
//!   only the other one does, it is kept.
//!
//! # Cost
//! `D` once per pair for the sort, then per merge attempt one evaluation
//! per member of the group that is checked. Successful merges move the
//! smaller group's labels (`O(n log n)` relabellings in all); a pair whose
//! merge fails is not retried, but a large group may be checked again for
//! other pairs, so the worst case is `O(pairs · n)` evaluations.

use std::cmp::Ordering;

/// The groups found by [`coarsen`]. Groups are numbered in the order of
/// their smallest item.
#[derive(Debug, Clone, PartialEq)]
pub struct Coarsening {
    /// The group of each item.
    pub group_of: Vec<usize>,
    /// The representative of each group, one of its members.
    pub representatives: Vec<usize>,
}

impl Coarsening {
    /// The number of groups.
    pub fn len(&self) -> usize {
        self.representatives.len()
    }

    /// True when there are no groups (no items).
    pub fn is_empty(&self) -> bool {
        self.representatives.is_empty()
    }

    /// The members of each group, ascending.
    pub fn groups(&self) -> Vec<Vec<usize>> {
        let mut groups = vec![Vec::new(); self.len()];
        for (item, &g) in self.group_of.iter().enumerate() {
            groups[g].push(item);
        }
        groups
    }
}

/// Merges neighbouring items into groups (module docs): the pairs of
/// `neighbours` in ascending order of `dist`, each merge keeping every
/// member within `threshold` of its group's representative. Deterministic.
///
/// # Panics
/// If a pair names an item `≥ n`.
pub fn coarsen(
    n: usize,
    neighbours: &[(usize, usize)],
    dist: impl Fn(usize, usize) -> f64,
    threshold: f64,
) -> Coarsening {
    let mut groups = Groups::singletons(n);
    for (_, i, j) in sorted_pairs(n, neighbours, &dist) {
        groups.try_merge(i, j, &dist, threshold);
    }
    groups.finish()
}

/// The distinct pairs `(min, max)` with their `D`, ascending by
/// `(D, min, max)`.
fn sorted_pairs(
    n: usize,
    neighbours: &[(usize, usize)],
    dist: &impl Fn(usize, usize) -> f64,
) -> Vec<(f64, usize, usize)> {
    let mut pairs: Vec<(usize, usize)> = neighbours
        .iter()
        .filter(|(i, j)| i != j)
        .map(|&(i, j)| {
            assert!(
                i < n && j < n,
                "neighbour pair ({i}, {j}) names an item ≥ {n}"
            );
            (i.min(j), i.max(j))
        })
        .collect();
    pairs.sort_unstable();
    pairs.dedup();
    let mut weighted: Vec<(f64, usize, usize)> =
        pairs.into_iter().map(|(i, j)| (dist(i, j), i, j)).collect();
    weighted.sort_by(|a, b| a.0.total_cmp(&b.0).then((a.1, a.2).cmp(&(b.1, b.2))));
    weighted
}

/// Groups under construction, labelled by an arbitrary member's index.
struct Groups {
    label: Vec<usize>,
    members: Vec<Vec<usize>>,
    representative: Vec<usize>,
}

impl Groups {
    fn singletons(n: usize) -> Groups {
        Groups {
            label: (0..n).collect(),
            members: (0..n).map(|i| vec![i]).collect(),
            representative: (0..n).collect(),
        }
    }

    /// Merges the groups of `i` and `j` if a representative of one covers
    /// the other (the larger group's first); does nothing otherwise.
    fn try_merge(
        &mut self,
        i: usize,
        j: usize,
        dist: &impl Fn(usize, usize) -> f64,
        threshold: f64,
    ) {
        let (a, b) = (self.label[i], self.label[j]);
        if a == b {
            return;
        }
        let (big, small) = match self.size_order(a, b) {
            Ordering::Less => (b, a),
            _ => (a, b),
        };
        if self.covers(big, small, dist, threshold) {
            self.absorb(big, small, self.representative[big]);
        } else if self.covers(small, big, dist, threshold) {
            self.absorb(big, small, self.representative[small]);
        }
    }

    /// Bigger groups first; of equal sizes, the smaller representative.
    fn size_order(&self, a: usize, b: usize) -> Ordering {
        let key = |g: usize| {
            (
                self.members[g].len(),
                std::cmp::Reverse(self.representative[g]),
            )
        };
        key(a).cmp(&key(b))
    }

    /// True if the representative of `by` is within `threshold` of every
    /// member of `group`, checked from the other representative outwards
    /// (the cheapest refusal first).
    fn covers(
        &self,
        by: usize,
        group: usize,
        dist: &impl Fn(usize, usize) -> f64,
        threshold: f64,
    ) -> bool {
        let r = self.representative[by];
        let first = self.representative[group];
        dist(r, first) <= threshold
            && self.members[group]
                .iter()
                .filter(|&&m| m != first)
                .all(|&m| dist(r, m) <= threshold)
    }

    /// Moves the members of `small` into `big`, which gets `representative`.
    fn absorb(&mut self, big: usize, small: usize, representative: usize) {
        let moved = std::mem::take(&mut self.members[small]);
        for &m in &moved {
            self.label[m] = big;
        }
        self.members[big].extend(moved);
        self.representative[big] = representative;
    }

    /// Numbers the groups by their smallest item.
    fn finish(self) -> Coarsening {
        let mut number = vec![usize::MAX; self.label.len()];
        let mut representatives = Vec::new();
        let mut group_of = Vec::with_capacity(self.label.len());
        for &l in &self.label {
            if number[l] == usize::MAX {
                number[l] = representatives.len();
                representatives.push(self.representative[l]);
            }
            group_of.push(number[l]);
        }
        Coarsening {
            group_of,
            representatives,
        }
    }
}
