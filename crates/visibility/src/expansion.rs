//! The production algorithm for V_p: triangular expansion over a
//! triangulation of the map (as in CGAL's `Triangular_expansion_visibility_2`).
//!
//! Preprocess once per map ([`VisibilityIndex::new`]); per query, find the
//! triangle holding p and push the view cone through every triangle side
//! that is not a map edge, narrowing it at each third vertex strictly inside
//! it. Every map edge the cone reaches is the nearest edge on that cone,
//! which is what [`crate::assemble`] needs.

use crate::assemble::{assemble, fits_fast};
use crate::locate::Grid;
use crate::map_skeleton::{from_leaves, MapSkeleton, SkeletonAtError, SkeletonScratch};
use crate::polygon::{VisibilityError, VisibilityPolygon};
use crate::skeleton::Skeleton;
use crate::triangulation::{Across, Triangulation};
use rug::Integer;
use std::cell::RefCell;
use std::cmp::Ordering;
use wai_exact::{BigVector, Point, RatPoint};
use wai_map::Map;

/// A map prepared for many visibility queries.
#[derive(Debug)]
pub struct VisibilityIndex<'m> {
    map: &'m Map,
    triangulation: Triangulation,
    grid: Grid,
    /// Bits of the largest map coordinate (for the fast path).
    coord_bits: u32,
    /// By map vertex: the triangles with a corner there.
    fans: Vec<Vec<u32>>,
    /// By map vertex: reflex in the map.
    pub(crate) reflex: Vec<bool>,
}

/// Directions from p to map vertices, compared exactly.
///
/// Implementation note: with `p = (X, Y) / W` the direction to vertex `v`
/// is `W·v − (X, Y)`. If `|W|·|v| < 2^61` and `|X|, |Y| < 2^61`
/// ([`fits_fast`]), `W`, `X`, `Y` and every map coordinate fit an `i64`,
/// `W·v` is one widening `i64` product, and every direction is below
/// `2^62` per coordinate: it fits an `i64` too ([`Fast`]). A cross product
/// of two such directions is a difference of two widening products below
/// `2^124`, below `2^125` in all, and fits an `i128`. Otherwise the same
/// formula runs on GMP integers ([`Exact`]).
trait Frame {
    /// What a cone carries for each of its two bounding directions.
    type Dir: Copy;
    /// The direction from p to map vertex `k`.
    fn dir(&self, k: usize) -> Self::Dir;
    /// The sign of `a × b`: `Greater` if `b` is counter-clockwise from `a`
    /// as seen from p.
    fn turn(&self, a: Self::Dir, b: Self::Dir) -> Ordering;
    /// The expansion stack of this frame's kind in `scratch`.
    fn stack(scratch: &mut Scratch) -> &mut Vec<Step<Self::Dir>>;
}

/// Buffers a query reuses from the last one on the same thread: a checker
/// asks for thousands of skeletons, each of which would otherwise allocate
/// its leaves, its stack and the fast path's working lists anew.
#[derive(Default)]
pub(crate) struct Scratch {
    leaves: Vec<(usize, usize)>,
    fast: Vec<Step<(i64, i64)>>,
    exact: Vec<Step<u32>>,
    skeleton: SkeletonScratch,
}

thread_local! {
    static SCRATCH: RefCell<Scratch> = RefCell::new(Scratch::default());
}

/// Run `f` with this thread's scratch buffers (fresh ones if they are in
/// use further up the stack).
fn with_scratch<T>(f: impl FnOnce(&mut Scratch) -> T) -> T {
    SCRATCH.with(|s| match s.try_borrow_mut() {
        Ok(mut s) => f(&mut s),
        Err(_) => f(&mut Scratch::default()),
    })
}

/// The `i64` frame of [`Frame`]'s note: directions are computed once per
/// cone bound and carried along, a turn is two widening products.
struct Fast<'a> {
    x: i64,
    y: i64,
    w: i64,
    v: &'a [Point],
}

impl Frame for Fast<'_> {
    type Dir = (i64, i64);

    #[inline]
    fn dir(&self, k: usize) -> (i64, i64) {
        // |W·v| < 2^61 and |X| < 2^61 ([`Frame`]'s note): the map
        // coordinate fits an `i64` and the difference is below 2^62.
        let c =
            |a: i128, b: i64| (i128::from(self.w) * i128::from(a as i64) - i128::from(b)) as i64;
        (c(self.v[k].x, self.x), c(self.v[k].y, self.y))
    }

    #[inline]
    fn turn(&self, a: (i64, i64), b: (i64, i64)) -> Ordering {
        // Each product below 2^124 ([`Frame`]'s note): nothing wraps.
        let p = i128::from(a.0) * i128::from(b.1);
        let q = i128::from(a.1) * i128::from(b.0);
        p.cmp(&q)
    }

    #[inline]
    fn stack(scratch: &mut Scratch) -> &mut Vec<Step<(i64, i64)>> {
        &mut scratch.fast
    }
}

/// The GMP frame of [`Frame`]'s note: a cone carries its vertices, whose
/// directions are built again at each turn.
struct Exact<'a> {
    x: Integer,
    y: Integer,
    w: Integer,
    v: &'a [Point],
}

impl Frame for Exact<'_> {
    type Dir = u32;

    #[inline]
    fn dir(&self, k: usize) -> u32 {
        k as u32
    }

    fn turn(&self, i: u32, j: u32) -> Ordering {
        let (w, x, y, v) = (&self.w, &self.x, &self.y, self.v);
        let d = |k: u32| {
            let k = k as usize;
            BigVector::new(Integer::from(w * v[k].x) - x, Integer::from(w * v[k].y) - y)
        };
        d(i).cross_sign(&d(j))
    }

    #[inline]
    fn stack(scratch: &mut Scratch) -> &mut Vec<Step<u32>> {
        &mut scratch.exact
    }
}

/// The frame of viewpoint `p` (`None`: the GMP one).
fn fast_frame<'a>(p: &RatPoint, v: &'a [Point], coord_bits: u32) -> Option<Fast<'a>> {
    if !fits_fast(p, coord_bits) {
        return None;
    }
    Some(Fast {
        x: p.hx().to_i64()?,
        y: p.hy().to_i64()?,
        w: p.hw().to_i64()?,
        v,
    })
}

fn exact_frame<'a>(p: &RatPoint, v: &'a [Point]) -> Exact<'a> {
    Exact {
        x: p.hx().clone(),
        y: p.hy().clone(),
        w: p.hw().clone(),
        v,
    }
}

/// A step of the expansion: leave triangle `tri` through its side `side`
/// (corner `side` to corner `side + 1`) with the cone open between the
/// directions of vertices `lo` and `hi` (`dlo`, `dhi`: as the frame
/// carries them), counter-clockwise.
pub(crate) struct Step<D> {
    tri: u32,
    side: u8,
    lo: u32,
    hi: u32,
    dlo: D,
    dhi: D,
}

impl<'m> VisibilityIndex<'m> {
    /// Triangulate `map` for queries.
    pub fn new(map: &'m Map) -> VisibilityIndex<'m> {
        let coord_bits = map
            .vertices()
            .iter()
            .map(Point::magnitude_bits)
            .max()
            .unwrap_or(0);
        let triangulation = Triangulation::new(map);
        let grid = Grid::new(map, &triangulation);
        let mut fans = vec![Vec::new(); map.n()];
        for t in 0..triangulation.len() {
            for c in triangulation.triangle(t) {
                fans[c].push(t as u32);
            }
        }
        VisibilityIndex {
            map,
            triangulation,
            grid,
            coord_bits,
            fans,
            reflex: (0..map.n()).map(|i| map.is_reflex(i)).collect(),
        }
    }

    pub fn map(&self) -> &'m Map {
        self.map
    }

    /// Bits of the largest map coordinate.
    #[cfg(test)]
    pub(crate) fn coord_bits(&self) -> u32 {
        self.coord_bits
    }

    pub fn triangulation(&self) -> &Triangulation {
        &self.triangulation
    }

    /// V_p of an interior point p.
    ///
    /// # Edge cases
    /// p may lie on lines through map vertices, on diagonals of the
    /// triangulation, on the extension of a map edge: all decisions are exact
    /// and cones are split only at vertices strictly inside them, so the
    /// result equals [`crate::reference::visibility_polygon`]'s.
    pub fn visibility_polygon(&self, p: &RatPoint) -> Result<VisibilityPolygon, VisibilityError> {
        let leaves = self.leaves_at(p)?;
        Ok(assemble(self.map, p, self.coord_bits, &leaves))
    }

    /// V*_p of an interior point p in map terms (Def 3.7): read off the
    /// expansion without V_p's points when p's coordinates are small
    /// ([`crate::map_skeleton`]), else from V_p and [`Skeleton::of`].
    ///
    /// # Edge cases
    /// The same as [`VisibilityIndex::visibility_polygon`]'s; the result
    /// equals `MapSkeleton::of(&Skeleton::of(map, &V_p)?)` for every p.
    pub fn skeleton_at(&self, p: &RatPoint) -> Result<MapSkeleton, SkeletonAtError> {
        with_scratch(|scratch| {
            self.leaves_into(p, scratch)?;
            let Scratch {
                leaves, skeleton, ..
            } = scratch;
            if let Some(sk) =
                from_leaves(self.map, &self.reflex, p, self.coord_bits, leaves, skeleton)
            {
                return Ok(sk?);
            }
            let vp = assemble(self.map, p, self.coord_bits, leaves);
            Ok(MapSkeleton::of(&Skeleton::of(self.map, &vp)?))
        })
    }

    /// The expansion's leaves for p: counter-clockwise, the map vertex
    /// whose direction starts each angular interval and the nearest map
    /// edge on it.
    pub(crate) fn leaves_at(&self, p: &RatPoint) -> Result<Vec<(usize, usize)>, VisibilityError> {
        let mut scratch = Scratch::default();
        self.leaves_into(p, &mut scratch)?;
        Ok(scratch.leaves)
    }

    /// [`VisibilityIndex::leaves_at`] into `scratch.leaves`.
    fn leaves_into(&self, p: &RatPoint, scratch: &mut Scratch) -> Result<(), VisibilityError> {
        let v = self.map.vertices();
        match fast_frame(p, v, self.coord_bits) {
            Some(frame) => self.leaves_in_scratch(&frame, p, scratch),
            None => self.leaves_in_scratch(&exact_frame(p, v), p, scratch),
        }
    }

    /// [`VisibilityIndex::leaves_at`] in `frame`, the frame of `p`.
    #[cfg(test)]
    fn leaves_in<F: Frame>(
        &self,
        frame: &F,
        p: &RatPoint,
    ) -> Result<Vec<(usize, usize)>, VisibilityError> {
        let mut scratch = Scratch::default();
        self.leaves_in_scratch(frame, p, &mut scratch)?;
        Ok(scratch.leaves)
    }

    /// [`VisibilityIndex::leaves_at`] in `frame`, the frame of `p`, into
    /// `scratch.leaves`.
    fn leaves_in_scratch<F: Frame>(
        &self,
        frame: &F,
        p: &RatPoint,
        scratch: &mut Scratch,
    ) -> Result<(), VisibilityError> {
        let tri = &self.triangulation;
        // Locate p: a triangle with p in its closed interior.
        let mut start = None;
        'search: for &t in self.grid.candidates(p) {
            let c = tri.triangle(t as usize);
            let d = c.map(|k| frame.dir(k));
            let mut s = [Ordering::Equal; 3];
            for k in 0..3 {
                s[k] = frame.turn(d[k], d[(k + 1) % 3]);
                if s[k] == Ordering::Less {
                    continue 'search;
                }
            }
            start = Some((t as usize, s, d));
            break;
        }
        let Some((t0, signs, d0)) = start else {
            return Err(VisibilityError::Outside(p.clone()));
        };
        let c0 = tri.triangle(t0);
        let zeros = signs.iter().filter(|&&o| o == Ordering::Equal).count();
        let on_map_edge = (0..3).any(|k| {
            signs[k] == Ordering::Equal && matches!(tri.across(t0, k), Across::MapEdge(_))
        });
        if zeros >= 2 || on_map_edge {
            return Err(VisibilityError::OnBoundary(p.clone()));
        }
        // Depth first, counter-clockwise: the stack holds later cones below
        // earlier ones, so leaves come out in angular order.
        let stack = F::stack(scratch);
        stack.clear();
        stack.extend((0..3).rev().map(|k| Step {
            tri: t0 as u32,
            side: k as u8,
            lo: c0[k] as u32,
            hi: c0[(k + 1) % 3] as u32,
            dlo: d0[k],
            dhi: d0[(k + 1) % 3],
        }));
        let mut stack = std::mem::take(F::stack(scratch));
        scratch.leaves.clear();
        self.expand_into(frame, &mut stack, &mut scratch.leaves);
        *F::stack(scratch) = stack;
        Ok(())
    }

    /// The view from map vertex `x` (its visibility polygon V_x, as the
    /// triangular expansion sees it): the sectors of x's interior angle,
    /// counter-clockwise from the direction of x + 1 to that of x − 1, each
    /// as `(lo, e)`: the open sector from the direction of map vertex `lo`
    /// up to the next sector's `lo` reaches map edge `e` first.
    ///
    /// The `lo`s, with x − 1, are the vertices x sees strictly (the open
    /// segment in the interior of the map), in angular order; a vertex
    /// behind another in the same direction starts no sector. A direction
    /// equal to a sector's `lo` is taken as just counter-clockwise of it:
    /// what a viewpoint sees just past the ray through `lo` (see
    /// `wai_cells`' incremental skeletons, sec. 3.9.2).
    pub fn vertex_view(&self, x: usize) -> Vec<(usize, usize)> {
        let v = self.map.vertices();
        let p = RatPoint::from(v[x]);
        match fast_frame(&p, v, self.coord_bits) {
            Some(frame) => self.vertex_view_in(&frame, x),
            None => self.vertex_view_in(&exact_frame(&p, v), x),
        }
    }

    /// [`VisibilityIndex::vertex_view`] in `frame`, the frame of vertex `x`.
    fn vertex_view_in<F: Frame>(&self, frame: &F, x: usize) -> Vec<(usize, usize)> {
        let tri = &self.triangulation;
        // The fan at x in counter-clockwise order: each triangle's cone runs
        // from the corner after x to the one before, and the next triangle's
        // cone starts where this one ends.
        let cone = |t: u32| {
            let c = tri.triangle(t as usize);
            let k = (0..3)
                .find(|&k| c[k] == x)
                .expect("fan triangles have x as a corner");
            (t, k, c[(k + 1) % 3], c[(k + 2) % 3])
        };
        let fan: Vec<(u32, usize, usize, usize)> = self.fans[x].iter().map(|&t| cone(t)).collect();
        let mut ordered = Vec::with_capacity(fan.len());
        let mut at = self.map.next(x);
        while let Some(&f) = fan.iter().find(|f| f.2 == at) {
            ordered.push(f);
            at = f.3;
            if at == self.map.prev(x) {
                break;
            }
        }
        debug_assert_eq!(ordered.len(), fan.len(), "the fan at {x} is one chain");
        let stack: Vec<Step<F::Dir>> = ordered
            .iter()
            .rev()
            .map(|&(t, k, lo, hi)| Step {
                tri: t,
                side: ((k + 1) % 3) as u8,
                lo: lo as u32,
                hi: hi as u32,
                dlo: frame.dir(lo),
                dhi: frame.dir(hi),
            })
            .collect();
        let mut leaves = self.expand(frame, stack);
        leaves.dedup();
        leaves
    }

    /// Push the cones of `stack` through the triangulation: the leaves
    /// `(lo, e)`, in the order popped, say that the cone starting at the
    /// direction of vertex `lo` reaches map edge `e`.
    ///
    /// Depth first: a cone that enters a triangle goes on through one side
    /// or splits at the third corner, its first part followed at once and
    /// the second pushed, so the leaves come out counter-clockwise.
    fn expand<F: Frame>(&self, frame: &F, mut stack: Vec<Step<F::Dir>>) -> Vec<(usize, usize)> {
        let mut leaves: Vec<(usize, usize)> = Vec::with_capacity(self.map.n());
        self.expand_into(frame, &mut stack, &mut leaves);
        leaves
    }

    /// [`VisibilityIndex::expand`], appending to `leaves` and leaving
    /// `stack` empty.
    fn expand_into<F: Frame>(
        &self,
        frame: &F,
        stack: &mut Vec<Step<F::Dir>>,
        leaves: &mut Vec<(usize, usize)>,
    ) {
        const NEXT: [usize; 3] = [1, 2, 0];
        const AFTER_NEXT: [usize; 3] = [2, 0, 1];
        let tri = &self.triangulation;
        while let Some(mut step) = stack.pop() {
            loop {
                let (t, k) = (step.tri as usize, step.side as usize);
                let u = match tri.across(t, k) {
                    Across::MapEdge(e) => {
                        leaves.push((step.lo as usize, e as usize));
                        break;
                    }
                    Across::Triangle(u) => u,
                };
                // Entered u through its side j: corner j is the hi end,
                // corner j + 1 the lo end, and the third corner may split
                // the cone.
                let j = tri.entry(t, k);
                let third = tri.triangle(u as usize)[AFTER_NEXT[j]];
                let dthird = frame.dir(third);
                let after_lo = frame.turn(step.dlo, dthird) == Ordering::Greater;
                let before_hi = frame.turn(dthird, step.dhi) == Ordering::Greater;
                let (side_lo, side_hi) = (NEXT[j] as u8, AFTER_NEXT[j] as u8);
                step.tri = u;
                if after_lo && before_hi {
                    let c = third as u32;
                    stack.push(Step {
                        tri: u,
                        side: side_hi,
                        lo: c,
                        hi: step.hi,
                        dlo: dthird,
                        dhi: step.dhi,
                    });
                    step.side = side_lo;
                    step.hi = c;
                    step.dhi = dthird;
                } else if after_lo {
                    step.side = side_lo;
                } else {
                    step.side = side_hi;
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_points::interior_points;

    /// The `i64` frame and the GMP frame give the same leaves and the
    /// same vertex views, on maps small and scaled up to the bound of
    /// [`fits_fast`] (where the fast frame still answers) and beyond.
    #[test]
    fn the_fast_frame_equals_the_exact_frame() {
        let mut maps = Vec::new();
        for kind in wai_gen::RANDOM_KINDS {
            for seed in 0..3 {
                maps.push(wai_gen::random(kind.id, kind.min_n.max(8) + 4, seed).unwrap());
            }
        }
        maps.extend(wai_gen::exhaustive_polyomino_maps(
            4,
            wai_gen::Symmetry::Free,
        ));
        let mut fast = 0;
        for map in &maps {
            for shift in [0u32, 20, 40, 55] {
                let map = map.scaled_up(shift).unwrap();
                let index = VisibilityIndex::new(&map);
                let v = map.vertices();
                for p in interior_points(&map, 7, 3) {
                    let want = index.leaves_in(&exact_frame(&p, v), &p);
                    if let Some(frame) = fast_frame(&p, v, index.coord_bits) {
                        fast += 1;
                        assert_eq!(index.leaves_in(&frame, &p), want, "p = {p}");
                    }
                }
                for x in 0..map.n() {
                    let p = RatPoint::from(v[x]);
                    let want = index.vertex_view_in(&exact_frame(&p, v), x);
                    if let Some(frame) = fast_frame(&p, v, index.coord_bits) {
                        assert_eq!(index.vertex_view_in(&frame, x), want, "vertex {x}");
                    }
                }
            }
        }
        assert!(fast > 1000, "{fast} points on the fast frame");
    }
}
