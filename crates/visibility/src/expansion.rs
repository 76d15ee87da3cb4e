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
use crate::map_skeleton::{from_leaves, MapSkeleton, SkeletonAtError};
use crate::polygon::{VisibilityError, VisibilityPolygon};
use crate::skeleton::Skeleton;
use crate::triangulation::{Across, Triangulation};
use rug::Integer;
use std::cmp::Ordering;
use wai_exact::{BigVector, Point, RatPoint, Vector};
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
}

/// Directions from p to map vertices, compared exactly.
///
/// Implementation note: with `p = (X, Y) / W` the direction to vertex `v`
/// is `W·v − (X, Y)`. If `|W|·|v| < 2^61` and `|X|, |Y| < 2^61`, every
/// direction is below `2^62` per coordinate, a cross product of two
/// directions is below `2 · 2^124 = 2^125` and fits an `i128`: the fast
/// path. Otherwise the same formula runs on GMP integers.
enum Frame<'a> {
    Fast {
        x: i128,
        y: i128,
        w: i128,
        v: &'a [Point],
    },
    Exact {
        x: Integer,
        y: Integer,
        w: Integer,
        v: &'a [Point],
    },
}

impl<'a> Frame<'a> {
    fn new(p: &RatPoint, v: &'a [Point], coord_bits: u32) -> Frame<'a> {
        if fits_fast(p, coord_bits) {
            Frame::Fast {
                x: p.hx().to_i128().expect("fits"),
                y: p.hy().to_i128().expect("fits"),
                w: p.hw().to_i128().expect("fits"),
                v,
            }
        } else {
            Frame::Exact {
                x: p.hx().clone(),
                y: p.hy().clone(),
                w: p.hw().clone(),
                v,
            }
        }
    }

    /// The sign of `dir(i) × dir(j)`: `Greater` if vertex j is
    /// counter-clockwise from vertex i as seen from p. Equivalently the
    /// orientation of `(v_i, v_j, p)`.
    #[inline]
    fn turn(&self, i: usize, j: usize) -> Ordering {
        match self {
            Frame::Fast { x, y, w, v } => {
                // Directions below 2^62 (the note above): the differences
                // fit, and the cross sign takes its i128 path. Nothing
                // wraps below the bound; the wrapping operations spare
                // fuzzing builds' redundant overflow checks.
                let c = |a: i128, b: i128| w.wrapping_mul(a).wrapping_sub(b);
                let d = |k: usize| Vector::new(c(v[k].x, *x), c(v[k].y, *y));
                d(i).cross_sign(d(j))
            }
            Frame::Exact { x, y, w, v } => {
                let d = |k: usize| {
                    BigVector::new(Integer::from(w * v[k].x) - x, Integer::from(w * v[k].y) - y)
                };
                d(i).cross_sign(&d(j))
            }
        }
    }
}

/// A step of the expansion, with its cone: open between the directions of
/// vertices `lo` and `hi`, counter-clockwise.
enum Step {
    /// Leave triangle `tri` through its side `side` (corner `side` to
    /// corner `side + 1`).
    Leave {
        tri: u32,
        side: u8,
        lo: u32,
        hi: u32,
    },
    /// Enter triangle `tri` through its side `side`.
    Enter {
        tri: u32,
        side: u8,
        lo: u32,
        hi: u32,
    },
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
        let leaves = self.leaves_at(p)?;
        if let Some(sk) = from_leaves(self.map, p, self.coord_bits, &leaves) {
            return Ok(sk?);
        }
        let vp = assemble(self.map, p, self.coord_bits, &leaves);
        Ok(MapSkeleton::of(&Skeleton::of(self.map, &vp)?))
    }

    /// The expansion's leaves for p: counter-clockwise, the map vertex
    /// whose direction starts each angular interval and the nearest map
    /// edge on it.
    pub(crate) fn leaves_at(&self, p: &RatPoint) -> Result<Vec<(usize, usize)>, VisibilityError> {
        let v = self.map.vertices();
        let frame = Frame::new(p, v, self.coord_bits);
        let tri = &self.triangulation;
        // Locate p: a triangle with p in its closed interior.
        let mut start = None;
        'search: for &t in self.grid.candidates(p) {
            let c = tri.triangle(t as usize);
            let mut s = [Ordering::Equal; 3];
            for k in 0..3 {
                s[k] = frame.turn(c[k], c[(k + 1) % 3]);
                if s[k] == Ordering::Less {
                    continue 'search;
                }
            }
            start = Some((t as usize, s));
            break;
        }
        let Some((t0, signs)) = start else {
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
        let stack: Vec<Step> = (0..3)
            .rev()
            .map(|k| Step::Leave {
                tri: t0 as u32,
                side: k as u8,
                lo: c0[k] as u32,
                hi: c0[(k + 1) % 3] as u32,
            })
            .collect();
        Ok(self.expand(&frame, stack))
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
        let n = self.map.n();
        let frame = Frame::new(
            &RatPoint::from(self.map.vertices()[x]),
            self.map.vertices(),
            self.coord_bits,
        );
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
        let mut at = (x + 1) % n;
        while let Some(&f) = fan.iter().find(|f| f.2 == at) {
            ordered.push(f);
            at = f.3;
            if at == (x + n - 1) % n {
                break;
            }
        }
        debug_assert_eq!(ordered.len(), fan.len(), "the fan at {x} is one chain");
        let stack: Vec<Step> = ordered
            .iter()
            .rev()
            .map(|&(t, k, lo, hi)| Step::Leave {
                tri: t,
                side: ((k + 1) % 3) as u8,
                lo: lo as u32,
                hi: hi as u32,
            })
            .collect();
        let mut leaves = self.expand(&frame, stack);
        leaves.dedup();
        leaves
    }

    /// Push the cones of `stack` through the triangulation: the leaves
    /// `(lo, e)`, in the order popped, say that the cone starting at the
    /// direction of vertex `lo` reaches map edge `e`.
    fn expand(&self, frame: &Frame, mut stack: Vec<Step>) -> Vec<(usize, usize)> {
        let tri = &self.triangulation;
        let mut leaves: Vec<(usize, usize)> = Vec::new();
        while let Some(step) = stack.pop() {
            match step {
                Step::Leave {
                    tri: t,
                    side: k,
                    lo,
                    hi,
                } => match tri.across(t as usize, k as usize) {
                    Across::MapEdge(e) => leaves.push((lo as usize, e as usize)),
                    Across::Triangle(u) => {
                        let c = tri.triangle(t as usize);
                        let (a, b) = (c[k as usize], c[(k as usize + 1) % 3]);
                        let cu = tri.triangle(u as usize);
                        let j = (0..3)
                            .find(|&j| cu[j] == b && cu[(j + 1) % 3] == a)
                            .expect("symmetric adjacency");
                        stack.push(Step::Enter {
                            tri: u,
                            side: j as u8,
                            lo,
                            hi,
                        });
                    }
                },
                Step::Enter {
                    tri: t,
                    side: k,
                    lo,
                    hi,
                } => {
                    // Entered through side k: corner k is the hi end, corner
                    // k + 1 the lo end, and the third corner may split the cone.
                    let k = k as usize;
                    let third = tri.triangle(t as usize)[(k + 2) % 3];
                    let after_lo = frame.turn(lo as usize, third) == Ordering::Greater;
                    let before_hi = frame.turn(third, hi as usize) == Ordering::Greater;
                    let (side_lo, side_hi) = (((k + 1) % 3) as u8, ((k + 2) % 3) as u8);
                    if after_lo && before_hi {
                        let c = third as u32;
                        stack.push(Step::Leave {
                            tri: t,
                            side: side_hi,
                            lo: c,
                            hi,
                        });
                        stack.push(Step::Leave {
                            tri: t,
                            side: side_lo,
                            lo,
                            hi: c,
                        });
                    } else if after_lo {
                        stack.push(Step::Leave {
                            tri: t,
                            side: side_lo,
                            lo,
                            hi,
                        });
                    } else {
                        stack.push(Step::Leave {
                            tri: t,
                            side: side_hi,
                            lo,
                            hi,
                        });
                    }
                }
            }
        }
        leaves
    }
}
