//! The interweavement graph of a skeleton (Defs 5.7–5.9): its valid
//! embeddings as nodes, joined through special nodes for the equivalence
//! classes of overlapping embeddings (Def 5.7) and of interweaved
//! (embedding, artificial edge) pairs (Def 5.8).
//!
//! Two embeddings are interweaved through artificial edges a₁, a₂ when a
//! gap of C_{a₁,h₁} and a gap of C_{a₂,h₂} are interweaved (Def 5.6,
//! [`crate::GapRelation`]); the pairs are given, and this module only
//! builds the graph and answers questions about its shape.

use std::collections::{BTreeMap, BTreeSet};

/// A node: an embedding (its position j) or a special node.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Node {
    Embedding(usize),
    /// An equivalence class of overlapping embeddings, E^ov_k.
    Overlap(usize),
    /// An equivalence class of interweaved (embedding, artificial edge)
    /// pairs, E^iw_k.
    Interweave(usize),
}

/// An embedding (its position j) with one of its artificial edges
/// (position i): the elements of Def 5.8's classes.
pub type EmbeddedEdge = (usize, usize);

/// The interweavement graph IG of Def 5.9.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Interweavement {
    /// t: the embedding nodes are `Embedding(0..t)`.
    pub embeddings: usize,
    /// E^ov: the classes of more than one embedding, each sorted.
    pub overlap_classes: Vec<Vec<usize>>,
    /// E^iw: the classes of more than one (j, i) pair, each sorted.
    pub interweave_classes: Vec<Vec<EmbeddedEdge>>,
    /// The edges, each from an embedding node to a special node, once.
    pub edges: BTreeSet<(Node, Node)>,
}

/// Union–find over `0..n` with path halving.
struct Classes(Vec<usize>);

impl Classes {
    fn find(&mut self, mut x: usize) -> usize {
        while self.0[x] != x {
            self.0[x] = self.0[self.0[x]];
            x = self.0[x];
        }
        x
    }

    fn union(&mut self, a: usize, b: usize) {
        let (a, b) = (self.find(a), self.find(b));
        self.0[a] = b;
    }

    /// The classes of more than one element, each in increasing order,
    /// ordered by their least element.
    fn groups(mut self) -> Vec<Vec<usize>> {
        let n = self.0.len();
        let mut by_root: BTreeMap<usize, Vec<usize>> = BTreeMap::new();
        for x in 0..n {
            let r = self.find(x);
            by_root.entry(r).or_default().push(x);
        }
        let mut out: Vec<Vec<usize>> = by_root.into_values().filter(|g| g.len() > 1).collect();
        out.sort();
        out
    }
}

impl Interweavement {
    /// The graph of `t` valid embeddings, the pairs of them that overlap,
    /// and the interweaved pairs ((j₁, i₁), (j₂, i₂)) of embedding and
    /// artificial edge.
    pub fn new(
        t: usize,
        overlapping: &[(usize, usize)],
        interweaved: &[(EmbeddedEdge, EmbeddedEdge)],
    ) -> Interweavement {
        let mut ov = Classes((0..t).collect());
        for &(a, b) in overlapping {
            ov.union(a, b);
        }
        let overlap_classes = ov.groups();
        let pairs: BTreeSet<(usize, usize)> =
            interweaved.iter().flat_map(|&(a, b)| [a, b]).collect();
        let pairs: Vec<(usize, usize)> = pairs.into_iter().collect();
        let at = |p: &(usize, usize)| pairs.binary_search(p).expect("listed");
        let mut iw = Classes((0..pairs.len()).collect());
        for (a, b) in interweaved {
            iw.union(at(a), at(b));
        }
        let interweave_classes: Vec<Vec<(usize, usize)>> = iw
            .groups()
            .into_iter()
            .map(|g| g.into_iter().map(|k| pairs[k]).collect())
            .collect();
        let mut edges = BTreeSet::new();
        for (k, class) in overlap_classes.iter().enumerate() {
            for &j in class {
                edges.insert((Node::Embedding(j), Node::Overlap(k)));
            }
        }
        for (k, class) in interweave_classes.iter().enumerate() {
            for &(j, _) in class {
                edges.insert((Node::Embedding(j), Node::Interweave(k)));
            }
        }
        Interweavement {
            embeddings: t,
            overlap_classes,
            interweave_classes,
            edges,
        }
    }

    /// Every node: the t embedding nodes, then the special nodes.
    pub fn nodes(&self) -> Vec<Node> {
        (0..self.embeddings)
            .map(Node::Embedding)
            .chain((0..self.overlap_classes.len()).map(Node::Overlap))
            .chain((0..self.interweave_classes.len()).map(Node::Interweave))
            .collect()
    }

    /// The number of special nodes, |E^ov| + |E^iw|.
    pub fn special_nodes(&self) -> usize {
        self.overlap_classes.len() + self.interweave_classes.len()
    }

    /// The degree of every node.
    pub fn degrees(&self) -> BTreeMap<Node, usize> {
        let mut d: BTreeMap<Node, usize> = self.nodes().into_iter().map(|x| (x, 0)).collect();
        for (a, b) in &self.edges {
            *d.entry(*a).or_default() += 1;
            *d.entry(*b).or_default() += 1;
        }
        d
    }

    /// The connected components with at least one edge, as (embedding
    /// nodes, special nodes) each, ordered by their least node.
    pub fn components(&self) -> Vec<(usize, usize)> {
        let nodes = self.nodes();
        let at = |x: &Node| nodes.binary_search(x).expect("a node of the graph");
        let mut c = Classes((0..nodes.len()).collect());
        for (a, b) in &self.edges {
            c.union(at(a), at(b));
        }
        c.groups()
            .into_iter()
            .map(|g| {
                let embeddings = g
                    .iter()
                    .filter(|&&k| matches!(nodes[k], Node::Embedding(_)))
                    .count();
                (embeddings, g.len() - embeddings)
            })
            .collect()
    }

    /// A cycle, as the nodes along it, if the graph has one (Lemma 5.8
    /// says it has none). The graph is simple, so a cycle has at least
    /// four nodes.
    pub fn cycle(&self) -> Option<Vec<Node>> {
        let mut adj: BTreeMap<Node, Vec<Node>> = BTreeMap::new();
        for &(a, b) in &self.edges {
            adj.entry(a).or_default().push(b);
            adj.entry(b).or_default().push(a);
        }
        let mut parent: BTreeMap<Node, Option<Node>> = BTreeMap::new();
        for &root in adj.keys() {
            if parent.contains_key(&root) {
                continue;
            }
            parent.insert(root, None);
            let mut stack = vec![root];
            while let Some(x) = stack.pop() {
                for &y in &adj[&x] {
                    if parent[&x] == Some(y) {
                        continue;
                    }
                    if parent.contains_key(&y) {
                        // A non-tree edge x–y closes a cycle through their
                        // common ancestor.
                        return Some(close_cycle(&parent, x, y));
                    }
                    parent.insert(y, Some(x));
                    stack.push(y);
                }
            }
        }
        None
    }
}

/// The cycle a non-tree edge x–y closes in a DFS forest given by `parent`.
fn close_cycle(parent: &BTreeMap<Node, Option<Node>>, x: Node, y: Node) -> Vec<Node> {
    let path = |mut a: Node| {
        let mut p = vec![a];
        while let Some(b) = parent[&a] {
            p.push(b);
            a = b;
        }
        p
    };
    let (px, py) = (path(x), path(y));
    let on_y: BTreeSet<Node> = py.iter().copied().collect();
    let meet = *px.iter().find(|a| on_y.contains(a)).expect("one tree");
    let mut cycle: Vec<Node> = px.iter().copied().take_while(|&a| a != meet).collect();
    cycle.push(meet);
    let back: Vec<Node> = py.iter().copied().take_while(|&a| a != meet).collect();
    cycle.extend(back.into_iter().rev());
    cycle
}

#[cfg(test)]
mod tests {
    use super::*;
    use Node::*;

    #[test]
    fn the_graph_of_example_5_2() {
        // Fig 5.8 (0-based): h1–h2–h3 interweaved through a1; h2 with h6
        // (a3, a2) and with h7 (a2, a2); h4–h5 through a1; h3, h4 overlap.
        let iw = [
            ((0, 0), (1, 0)),
            ((1, 0), (2, 0)),
            ((1, 2), (5, 1)),
            ((1, 1), (6, 1)),
            ((3, 0), (4, 0)),
        ];
        let g = Interweavement::new(7, &[(2, 3)], &iw);
        assert_eq!(g.overlap_classes, vec![vec![2, 3]]);
        assert_eq!(g.interweave_classes.len(), 4);
        assert_eq!(g.special_nodes(), 5);
        // 3 + 2 + 2 + 2 edges to interweavements, 2 to the overlap class.
        assert_eq!(g.edges.len(), 11);
        assert_eq!(g.cycle(), None);
        let d = g.degrees();
        assert_eq!(d[&Embedding(1)], 3);
        assert_eq!(d[&Overlap(0)], 2);
        // One tree of all seven embeddings and the five special nodes.
        assert_eq!(g.components(), vec![(7, 5)]);
        // Two trees apart, and an embedding on no edge in none.
        let g = Interweavement::new(5, &[(0, 1)], &[((2, 0), (3, 0))]);
        assert_eq!(g.components(), vec![(2, 1), (2, 1)]);
    }

    #[test]
    fn a_circle_of_interweavements_is_found() {
        // h0–h1, h1–h2, h2–h0, each through its own pair of artificial
        // edges: three special nodes and a cycle of six nodes.
        let iw = [((0, 0), (1, 0)), ((1, 1), (2, 1)), ((2, 2), (0, 2))];
        let g = Interweavement::new(3, &[], &iw);
        let cycle = g.cycle().expect("a cycle");
        assert_eq!(cycle.len(), 6);
        assert!(cycle.contains(&Interweave(0)) && cycle.contains(&Embedding(2)));
        // Overlapping and interweaved at once: a cycle of four.
        let g = Interweavement::new(2, &[(0, 1)], &[((0, 0), (1, 0))]);
        assert_eq!(g.cycle().map(|c| c.len()), Some(4));
    }
}
