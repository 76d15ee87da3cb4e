//! Family `window-grid` (claim T5.17t, the Ω(r²) half with n = Θ(r)):
//! one room with two windows, each onto a wall broken into c collinear
//! pieces — Fig 5.2's rectangular skeleton with two artificial edges, each
//! cell in one visibility wedge of each (Lemma 5.2), grown until the
//! wedges of the two windows cut the room into a c × c grid.
//!
//! The room is `[0, S]²`. A short tunnel in its north wall near the west
//! corner (x in `[2, 4]`) opens into chamber A, whose ceiling is broken by
//! c − 1 notches; one in its east wall near the south corner (y in
//! `[2, 4]`) opens into chamber B, whose far wall is broken the same way.
//! A robot at `(2 + u, 2 + v)` sees through each tunnel a narrow cone, like
//! a pinhole camera: it lands on A's ceiling about `L·u / (S − 2 − v)` west
//! of the tunnel and on B's wall about `L·v / (S − 2 − u)` south of it, L
//! the chamber's depth. Where each cone lands on one piece, seeing no
//! vertex behind the windows, the view's skeleton is the room with its two
//! windows as artificial edges, whichever pieces they are: one class, with
//! a cell for every pair (piece of A, piece of B) — c² cells — while the
//! map has n = 8c + 12 vertices and r = 4c + 4 reflex ones. So its largest
//! class grows as r², a factor c/8 beyond n.
//!
//! The walls of A run west of the room and B's south of it, so the two
//! chambers never meet; the map is a tree of room and chambers, simple.

use crate::families::check_size;
use crate::ring::into_map;
use crate::GenError;
use wai_exact::Point;
use wai_map::Map;

/// The pitch of the broken walls: a piece of 14 and a notch of 2.
const P: i128 = 16;
/// Notch width and depth.
const NOTCH: i128 = 2;
/// The tunnels: width and length, and their offset from the room's corner.
const DOOR: i128 = 2;
const TUNNEL: i128 = 1;
const OFF: i128 = 2;

fn p(x: i128, y: i128) -> Point {
    Point::new(x, y)
}

/// Family `window-grid` with `c ≥ 1` pieces per broken wall: n = 8c + 12,
/// r = 4c + 4 (module doc).
pub fn window_grid(c: u32) -> Result<Map, GenError> {
    const F: &str = "window-grid";
    if c < 1 {
        return Err(GenError::ParamTooSmall {
            family: F,
            param: "c",
            value: c,
            min: 1,
        });
    }
    check_size(F, 8 * u64::from(c) + 12)?;
    let k = i128::from(c);
    // Chamber depth L (tunnel included) and room side S: the cones reach
    // c·P along the walls for robot offsets up to about a third of S.
    let l = 2 * k * P;
    let s = OFF + l;
    let (a, b) = (OFF, OFF);
    // Chamber A spans x from `a - (c + 1)P` to `a + DOOR + P/2`, chamber B
    // y from `b - (c + 1)P` to `b + DOOR + P/2`.
    let far = (k + 1) * P;
    let near = DOOR + P / 2;
    let (ya, xb) = (s + TUNNEL, s + TUNNEL); // chamber floors / near walls
    let (yc, xf) = (s + l, s + l); // A's ceiling, B's far wall
    let mut ring = vec![p(0, 0), p(s, 0)];
    // East wall up to tunnel B, chamber B, back.
    ring.extend([p(s, b), p(xb, b), p(xb, b - far), p(xf, b - far)]);
    // B's far wall northwards, notches recessed east at offsets jP below
    // the tunnel (j = c − 1 … 1).
    for j in (1..k).rev() {
        let y = b - j * P;
        ring.extend([
            p(xf, y),
            p(xf + NOTCH, y),
            p(xf + NOTCH, y + NOTCH),
            p(xf, y + NOTCH),
        ]);
    }
    ring.extend([
        p(xf, b + near),
        p(xb, b + near),
        p(xb, b + DOOR),
        p(s, b + DOOR),
    ]);
    // North-east corner, north wall west to tunnel A, chamber A, back.
    ring.extend([
        p(s, s),
        p(a + DOOR, s),
        p(a + DOOR, ya),
        p(a + near, ya),
        p(a + near, yc),
    ]);
    // A's ceiling westwards, notches recessed north at offsets jP west of
    // the tunnel (j = 1 … c − 1).
    for j in 1..k {
        let x = a - j * P;
        ring.extend([
            p(x + NOTCH, yc),
            p(x + NOTCH, yc + NOTCH),
            p(x, yc + NOTCH),
            p(x, yc),
        ]);
    }
    ring.extend([p(a - far, yc), p(a - far, ya), p(a, ya), p(a, s), p(0, s)]);
    Ok(into_map(ring, format!("{F}/c={c}")))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes() {
        for c in 1..=12 {
            let m = window_grid(c).unwrap();
            assert_eq!(m.n(), 8 * c as usize + 12, "c = {c}");
            assert_eq!(m.r(), 4 * c as usize + 4, "c = {c}");
        }
        assert!(window_grid(0).is_err());
    }
}
