//! The Monotonous Bisector Tree (thesis sec. 6.4, after Noltemeier,
//! Verbarg and Zirkelbach 1992/93): a nearest-neighbour index over items
//! compared by a distance `D` that is only known through a closure.
//!
//! Every node is a *cluster*: a centre (one of its items) and a radius, the
//! largest `D(centre, member)` over its members. A cluster with more than
//! `leaf_size` members is split by the bisector between two centres: the
//! parent's centre, which the first child keeps, and the member farthest
//! from it, which becomes the second child's centre; every other member
//! joins the nearer centre. Keeping the parent's centre is what makes the
//! radii *monotonously* decreasing: the first child is a subset of the
//! parent around the same centre, and a member joins the second child only
//! if it is strictly nearer to the new centre than to the parent's, whose
//! distance was at most the parent's radius.
//!
//! A query gives the query distance `d(S, item)` as a closure. The tree is
//! correct for it when `d` and `D` satisfy eq. 6.1 of the thesis,
//! `d(S, V1) + D(V1, V2) ≥ d(S, V2)`: then every member `m` of a cluster
//! with centre `c` and radius `r` has `d(S, m) ≥ d(S, c) − r`, and a
//! cluster whose lower bound exceeds the best distance found so far holds
//! no better item and is skipped. `D` a metric or pseudo-metric (symmetric,
//! `D(i, i) = 0`, triangle inequality) and `d` the same metric measured
//! from an outside point satisfy eq. 6.1.
//!
//! # Edge cases
//! - Ties between distances are broken by the item index, everywhere: the
//!   farthest member is the one with the smallest index among the farthest,
//!   a member at equal distance from both centres joins the parent's
//!   centre, and query results are ordered by `(distance, item)` with
//!   [`f64::total_cmp`], exactly like the linear scans [`linear_nearest`],
//!   [`linear_k_nearest`] and [`linear_within`]. The tree returns the same
//!   items with the same (bit-identical) distances in the same order.
//! - A cluster of radius 0 (its members all at distance 0 from the centre:
//!   duplicates, or one shift class of a pseudo-metric) is a leaf whatever
//!   its size, since no bisector separates it.
//! - `n = 0` gives an empty tree: queries find nothing and evaluate nothing.
//! - A `NaN` distance never prunes (every comparison with it is false), so
//!   it costs evaluations but never a wrong answer.
//!
//! # Rounding and the pruning slack
//! In `f64` the triangle inequality can fail by a few ulps even for an
//! exact metric, and the lower bound `d(S, c) − r` is itself rounded. A
//! cluster is therefore pruned only if its lower bound exceeds the bound
//! by more than [`PRUNE_SLACK`] times `d(S, c) + r`: every value in the
//! inequality that could be violated is at most that large, so the slack
//! dominates their rounding errors (a few ulps, about `1e-16` relative,
//! per operation) by many orders of magnitude. The slack only costs
//! evaluations, never correctness.
//!
//! # Cost
//! Building evaluates `D` once per member of each split cluster (the
//! distance to the new centre; the distance to the kept centre is carried
//! down), so `n − 1` plus the summed sizes of the split clusters: about
//! `n log n` on data that splits evenly. The worst case is quadratic: on
//! points `0, 1, 2, 4, …, 2^k` of a line every split cuts off only the
//! farthest point, the tree has depth `n − leaf_size` and building costs
//! about `n²/2` evaluations. A query evaluates `d` at most once per item
//! (a centre's distance is passed down to the child that keeps it).

use std::cmp::Ordering;
use std::collections::BinaryHeap;

/// The relative slack of the pruning test: a cluster is skipped only if
/// `d(S, c) − r > bound + PRUNE_SLACK · (|d(S, c)| + r)` (see the module's
/// "Rounding" section).
pub const PRUNE_SLACK: f64 = 1e-9;

/// An item found by a query and its query distance `d(S, item)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Neighbour {
    pub item: usize,
    pub distance: f64,
}

impl Neighbour {
    /// The order of query results: by distance ([`f64::total_cmp`]), then
    /// by item index, so that ties are broken the same way everywhere.
    pub fn rank_cmp(&self, other: &Neighbour) -> Ordering {
        self.distance
            .total_cmp(&other.distance)
            .then(self.item.cmp(&other.item))
    }
}

/// What a query cost: how many times it called the query distance.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct QueryStats {
    pub evaluations: usize,
}

/// One cluster of the tree.
#[derive(Debug, Clone, PartialEq)]
pub struct Node {
    centre: usize,
    radius: f64,
    kind: Kind,
}

#[derive(Debug, Clone, PartialEq)]
enum Kind {
    /// The members, ascending, with `D(centre, member)` for each, which
    /// lets a query skip single members as well as whole clusters.
    Leaf {
        items: Vec<usize>,
        to_centre: Vec<f64>,
    },
    /// The child that keeps this node's centre, then the other one.
    Split([usize; 2]),
}

impl Node {
    /// The cluster's centre, one of its members.
    pub fn centre(&self) -> usize {
        self.centre
    }

    /// The largest `D(centre, member)` over the cluster's members.
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// The two children of a split cluster (indices into [`Mbt::nodes`]):
    /// first the one that keeps this centre, then the one around the
    /// farthest member. `None` for a leaf.
    pub fn children(&self) -> Option<[usize; 2]> {
        match self.kind {
            Kind::Split(children) => Some(children),
            Kind::Leaf { .. } => None,
        }
    }

    /// A leaf's members in ascending order, its centre among them; empty
    /// for a split cluster.
    pub fn items(&self) -> &[usize] {
        match &self.kind {
            Kind::Leaf { items, .. } => items,
            Kind::Split(_) => &[],
        }
    }
}

/// A Monotonous Bisector Tree over the items `0..n` (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct Mbt {
    /// The root is `nodes[0]` when `n > 0`.
    nodes: Vec<Node>,
    len: usize,
    build_evaluations: usize,
    /// The relative pruning slack ([`PRUNE_SLACK`] unless set).
    slack: f64,
}

/// A cluster's members with `D(centre, member)`, in ascending item order.
type Members = Vec<(usize, f64)>;

/// A cluster waiting to be built.
struct Pending {
    node: usize,
    centre: usize,
    members: Members,
}

impl Mbt {
    /// Builds the tree over `0..n` top-down. The root's centre is item 0;
    /// clusters of at most `leaf_size` members (0 counts as 1) or of radius
    /// 0 become leaves. `dist(a, b)` is `D`; the tree only ever asks for
    /// `dist(centre, member)`. Deterministic: the same `D` gives the same
    /// tree.
    pub fn build(n: usize, leaf_size: usize, dist: impl Fn(usize, usize) -> f64) -> Mbt {
        let leaf_size = leaf_size.max(1);
        let mut tree = Mbt {
            nodes: Vec::new(),
            len: n,
            build_evaluations: 0,
            slack: PRUNE_SLACK,
        };
        if n == 0 {
            return tree;
        }
        let members = (0..n)
            .map(|m| (m, if m == 0 { 0.0 } else { dist(0, m) }))
            .collect();
        tree.build_evaluations = n - 1;
        tree.nodes.push(Node::leaf(0, 0.0, Vec::new()));
        // An explicit stack: a degenerate tree may be n deep.
        let mut pending = vec![Pending {
            node: 0,
            centre: 0,
            members,
        }];
        while let Some(cluster) = pending.pop() {
            pending.extend(tree.settle(cluster, leaf_size, &dist));
        }
        tree
    }

    /// Makes `cluster` a leaf, or splits it and returns its two children.
    fn settle(
        &mut self,
        cluster: Pending,
        leaf_size: usize,
        dist: &impl Fn(usize, usize) -> f64,
    ) -> Vec<Pending> {
        let Pending {
            node,
            centre,
            members,
        } = cluster;
        let (far, radius) = farthest(&members);
        if members.len() <= leaf_size || radius <= 0.0 {
            self.nodes[node] = Node::leaf(centre, radius, members);
            return Vec::new();
        }
        let (keep, other) = bisect(centre, far, members, dist);
        // `bisect` evaluates D for every member but the two centres.
        self.build_evaluations += keep.len() + other.len() - 2;
        let ids = [self.nodes.len(), self.nodes.len() + 1];
        for id in ids {
            self.nodes.push(Node::leaf(id, 0.0, Vec::new()));
        }
        self.nodes[node] = Node {
            centre,
            radius,
            kind: Kind::Split(ids),
        };
        vec![
            Pending {
                node: ids[1],
                centre: far,
                members: other,
            },
            Pending {
                node: ids[0],
                centre,
                members: keep,
            },
        ]
    }

    /// The number of items, `n`.
    pub fn len(&self) -> usize {
        self.len
    }

    /// True for the tree over no items.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The clusters; the root is `nodes()[0]` unless the tree is empty.
    pub fn nodes(&self) -> &[Node] {
        &self.nodes
    }

    /// The tree with a wider relative pruning slack, for a query distance
    /// that is itself computed with a known relative error (the localizer's
    /// FFT rotation search in `f32`).
    pub fn with_slack(mut self, slack: f64) -> Mbt {
        self.slack = slack.max(PRUNE_SLACK);
        self
    }

    /// How many times building called `D`.
    pub fn build_evaluations(&self) -> usize {
        self.build_evaluations
    }

    /// The item nearest to the query (smallest `(distance, item)`), or
    /// `None` if there are no items.
    pub fn nearest(&self, q: impl FnMut(usize) -> f64) -> Option<Neighbour> {
        self.nearest_with_stats(q).0
    }

    /// [`Mbt::nearest`] and how many distances it evaluated.
    pub fn nearest_with_stats(
        &self,
        q: impl FnMut(usize) -> f64,
    ) -> (Option<Neighbour>, QueryStats) {
        let mut best = Nearest(None);
        let stats = self.search(q, &mut best);
        (best.0, stats)
    }

    /// The `k` items nearest to the query, ascending by `(distance, item)`;
    /// all items if `k ≥ n`.
    pub fn k_nearest(&self, k: usize, q: impl FnMut(usize) -> f64) -> Vec<Neighbour> {
        self.k_nearest_with_stats(k, q).0
    }

    /// [`Mbt::k_nearest`] and how many distances it evaluated.
    pub fn k_nearest_with_stats(
        &self,
        k: usize,
        q: impl FnMut(usize) -> f64,
    ) -> (Vec<Neighbour>, QueryStats) {
        if k == 0 {
            return (Vec::new(), QueryStats::default());
        }
        let mut best = KNearest {
            k,
            heap: BinaryHeap::with_capacity(k.min(self.len)),
        };
        let stats = self.search(q, &mut best);
        let found = best.heap.into_sorted_vec().into_iter().map(|r| r.0);
        (found.collect(), stats)
    }

    /// Every item with distance `≤ r`, ascending by `(distance, item)`.
    pub fn within(&self, r: f64, q: impl FnMut(usize) -> f64) -> Vec<Neighbour> {
        self.within_with_stats(r, q).0
    }

    /// [`Mbt::within`] and how many distances it evaluated.
    pub fn within_with_stats(
        &self,
        r: f64,
        q: impl FnMut(usize) -> f64,
    ) -> (Vec<Neighbour>, QueryStats) {
        let mut found = Within {
            r,
            found: Vec::new(),
        };
        let stats = self.search(q, &mut found);
        found.found.sort_by(Neighbour::rank_cmp);
        (found.found, stats)
    }

    /// The depth-first branch and bound shared by the queries: offers every
    /// evaluated item to `collector` and skips what its bound excludes.
    fn search(&self, q: impl FnMut(usize) -> f64, collector: &mut impl Collector) -> QueryStats {
        let mut eval = Counted {
            q,
            stats: QueryStats::default(),
        };
        let Some(root) = self.nodes.first() else {
            return eval.stats;
        };
        let d_root = eval.offer(root.centre, collector);
        // Each entry carries d(S, centre), evaluated once by its parent.
        let mut stack = vec![(0, d_root)];
        while let Some((id, d_centre)) = stack.pop() {
            let node = &self.nodes[id];
            if prunable(d_centre, node.radius, collector.bound(), self.slack) {
                continue;
            }
            match &node.kind {
                Kind::Leaf { items, to_centre } => {
                    for (&m, &to_c) in items.iter().zip(to_centre) {
                        // The centre was offered when it was evaluated.
                        if m != node.centre
                            && !prunable(d_centre, to_c, collector.bound(), self.slack)
                        {
                            eval.offer(m, collector);
                        }
                    }
                }
                Kind::Split([keep, other]) => {
                    let d_other = eval.offer(self.nodes[*other].centre, collector);
                    // The nearer child goes on top, so it is searched first.
                    if d_other < d_centre {
                        stack.extend([(*keep, d_centre), (*other, d_other)]);
                    } else {
                        stack.extend([(*other, d_other), (*keep, d_centre)]);
                    }
                }
            }
        }
        eval.stats
    }
}

impl Node {
    fn leaf(centre: usize, radius: f64, members: Members) -> Node {
        let (items, to_centre) = members.into_iter().unzip();
        Node {
            centre,
            radius,
            kind: Kind::Leaf { items, to_centre },
        }
    }
}

/// The member farthest from the centre (the smallest index among equals)
/// and its distance, the cluster's radius. `members` is never empty: it
/// holds at least the centre.
fn farthest(members: &[(usize, f64)]) -> (usize, f64) {
    let mut best = members[0];
    for &(m, d) in &members[1..] {
        if d.total_cmp(&best.1) == Ordering::Greater {
            best = (m, d);
        }
    }
    best
}

/// Splits `members` by the bisector of `centre` and `far`: a member joins
/// `far` only if strictly nearer to it, so ties stay with `centre`. Both
/// halves stay in ascending item order and carry the distance to their own
/// centre.
fn bisect(
    centre: usize,
    far: usize,
    members: Members,
    dist: &impl Fn(usize, usize) -> f64,
) -> (Members, Members) {
    let mut keep = Vec::new();
    let mut other = Vec::new();
    for (m, to_centre) in members {
        if m == far {
            other.push((m, 0.0));
        } else if m == centre {
            keep.push((m, 0.0));
        } else {
            let to_far = dist(far, m);
            if to_far < to_centre {
                other.push((m, to_far));
            } else {
                keep.push((m, to_centre));
            }
        }
    }
    (keep, other)
}

/// True if a cluster at query distance `d_centre` with radius `radius`
/// certainly holds nothing within `bound` (eq. 6.1, with the slack of the
/// module's "Rounding" section). Infinite or `NaN` values never prune.
fn prunable(d_centre: f64, radius: f64, bound: f64, relative: f64) -> bool {
    let slack = relative * (d_centre.abs() + radius);
    d_centre - radius > bound + slack
}

/// The query distance, counting its calls.
struct Counted<Q> {
    q: Q,
    stats: QueryStats,
}

impl<Q: FnMut(usize) -> f64> Counted<Q> {
    /// Evaluates `d(S, item)` and offers the item to `collector`.
    fn offer(&mut self, item: usize, collector: &mut impl Collector) -> f64 {
        self.stats.evaluations += 1;
        let distance = (self.q)(item);
        collector.offer(Neighbour { item, distance });
        distance
    }
}

/// What a query keeps of the items it sees, and the distance beyond which
/// it wants nothing more.
trait Collector {
    fn bound(&self) -> f64;
    fn offer(&mut self, found: Neighbour);
}

struct Nearest(Option<Neighbour>);

impl Collector for Nearest {
    fn bound(&self) -> f64 {
        self.0.map_or(f64::INFINITY, |n| n.distance)
    }

    fn offer(&mut self, found: Neighbour) {
        let better = match self.0 {
            Some(best) => found.rank_cmp(&best) == Ordering::Less,
            None => true,
        };
        if better {
            self.0 = Some(found);
        }
    }
}

struct KNearest {
    k: usize,
    /// A max-heap: the worst of the `k` best is on top.
    heap: BinaryHeap<Ranked>,
}

impl Collector for KNearest {
    fn bound(&self) -> f64 {
        match self.heap.peek() {
            Some(worst) if self.heap.len() >= self.k => worst.0.distance,
            _ => f64::INFINITY,
        }
    }

    fn offer(&mut self, found: Neighbour) {
        if self.heap.len() < self.k {
            self.heap.push(Ranked(found));
        } else if self
            .heap
            .peek()
            .is_some_and(|worst| found.rank_cmp(&worst.0) == Ordering::Less)
        {
            self.heap.pop();
            self.heap.push(Ranked(found));
        }
    }
}

struct Within {
    r: f64,
    found: Vec<Neighbour>,
}

impl Collector for Within {
    fn bound(&self) -> f64 {
        self.r
    }

    fn offer(&mut self, found: Neighbour) {
        if found.distance <= self.r {
            self.found.push(found);
        }
    }
}

/// A [`Neighbour`] ordered by [`Neighbour::rank_cmp`], for the heap.
struct Ranked(Neighbour);

impl PartialEq for Ranked {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}

impl Eq for Ranked {}

impl PartialOrd for Ranked {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Ranked {
    fn cmp(&self, other: &Self) -> Ordering {
        self.0.rank_cmp(&other.0)
    }
}

/// The reference for [`Mbt::nearest`]: the smallest `(distance, item)`
/// over all of `0..n`.
pub fn linear_nearest(n: usize, mut q: impl FnMut(usize) -> f64) -> Option<Neighbour> {
    (0..n)
        .map(|item| Neighbour {
            item,
            distance: q(item),
        })
        .min_by(Neighbour::rank_cmp)
}

/// The reference for [`Mbt::k_nearest`]: all items sorted by
/// `(distance, item)`, the first `k` kept.
pub fn linear_k_nearest(n: usize, k: usize, q: impl FnMut(usize) -> f64) -> Vec<Neighbour> {
    let mut all = all_sorted(n, q);
    all.truncate(k);
    all
}

/// The reference for [`Mbt::within`]: the items with distance `≤ r`,
/// sorted by `(distance, item)`.
pub fn linear_within(n: usize, r: f64, q: impl FnMut(usize) -> f64) -> Vec<Neighbour> {
    let mut all = all_sorted(n, q);
    all.retain(|found| found.distance <= r);
    all
}

fn all_sorted(n: usize, mut q: impl FnMut(usize) -> f64) -> Vec<Neighbour> {
    let mut all: Vec<Neighbour> = (0..n)
        .map(|item| Neighbour {
            item,
            distance: q(item),
        })
        .collect();
    all.sort_by(Neighbour::rank_cmp);
    all
}
