//! CGAL as an independent oracle and speed peer for visibility polygons.
//!
//! [`CgalPeer`] drives `target/peers/cgal_visibility` (built by
//! `benches/peers/build.sh`; protocol, regularization choice and CGAL's
//! observed output conventions in `benches/peers/README.md`): CGAL 5.5's
//! `Triangular_expansion_visibility_2<Arrangement_2, Tag_true>` on the
//! exact kernel `Epeck`. One child process is kept alive across queries; the
//! protocol is one command written and flushed, one reply line read.
//!
//! # Frame
//! The map is sent with its **integer** coordinates (those of
//! [`wai_map::Map::vertices`]), not divided by the scale: visibility commutes
//! with a uniform scaling, and integers keep CGAL's exact arithmetic as cheap
//! as ours. So query points and output vertices are in that same integer
//! frame, the frame of every `wai_exact` predicate ([`wai_exact::locate_rat`],
//! [`wai_exact::sees`]); divide by [`CgalPeer::scale`] for input units.
//!
//! # CGAL's output conventions (observed, see the README)
//! Counter-clockwise, no repeated vertex, no needles; but **collinear
//! consecutive vertices do occur** (every map vertex CGAL meets on a
//! straight stretch of the boundary is reported, e.g. when the viewpoint is
//! on the line of a map edge). [`drop_collinear`] removes them.

use rug::{Integer, Rational};
use std::io::{BufRead, BufReader, Write};
use std::path::{Path, PathBuf};
use std::process::{Child, ChildStdin, ChildStdout, Command, Stdio};
use wai_exact::{orientation_rat, Orientation, Point, RatPoint};

/// The environment variable naming the peer binary.
pub const BIN_ENV: &str = "WAI_CGAL_BIN";

/// The peer binary: `$WAI_CGAL_BIN`, else `<repo>/target/peers/cgal_visibility`.
pub fn binary_path() -> PathBuf {
    match std::env::var_os(BIN_ENV) {
        Some(p) if !p.is_empty() => PathBuf::from(p),
        _ => Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("..")
            .join("target")
            .join("peers")
            .join("cgal_visibility"),
    }
}

/// Whether the peer binary exists (run `benches/peers/build.sh` if not).
pub fn available() -> bool {
    binary_path().is_file()
}

/// A running `cgal_visibility` process.
#[derive(Debug)]
pub struct CgalPeer {
    child: Child,
    stdin: Option<ChildStdin>,
    stdout: BufReader<ChildStdout>,
    scale: Option<Integer>,
}

impl CgalPeer {
    /// Start the peer binary of [`binary_path`].
    pub fn spawn() -> Result<CgalPeer, String> {
        let path = binary_path();
        let mut child = Command::new(&path)
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::inherit())
            .spawn()
            .map_err(|e| {
                format!(
                    "cannot start {}: {e} (run benches/peers/build.sh)",
                    path.display()
                )
            })?;
        let stdin = child.stdin.take().ok_or("no stdin pipe")?;
        let stdout = child.stdout.take().ok_or("no stdout pipe")?;
        Ok(CgalPeer {
            child,
            stdin: Some(stdin),
            stdout: BufReader::new(stdout),
            scale: None,
        })
    }

    /// The scale of the current polygon (coordinates are integers over it).
    pub fn scale(&self) -> Option<&Integer> {
        self.scale.as_ref()
    }

    /// Send a simple counter-clockwise ring (a map's vertices) and build
    /// CGAL's arrangement and triangulation. The integer coordinates are sent
    /// as they are; `scale` is only remembered (see the module's "Frame").
    pub fn set_polygon(&mut self, ring: &[Point], scale: &Integer) -> Result<(), String> {
        let mut cmd = format!("polygon {}", ring.len());
        for p in ring {
            cmd.push_str(&format!(" {} {}", p.x, p.y));
        }
        self.scale = None;
        let reply = self.call(&cmd)?;
        match reply.strip_prefix("ok ") {
            Some(n) if n.trim() == ring.len().to_string() => {
                self.scale = Some(scale.clone());
                Ok(())
            }
            _ => Err(format!("unexpected reply to polygon: {reply}")),
        }
    }

    /// Send a map, holes and all (`holed`; `polygon` without holes), and
    /// build CGAL's arrangement and triangulation.
    pub fn set_map(&mut self, map: &wai_map::Map) -> Result<(), String> {
        if !map.has_holes() {
            return self.set_polygon(map.vertices(), map.scale());
        }
        let ring = |cmd: &mut String, pts: &[Point]| {
            cmd.push_str(&format!(" {}", pts.len()));
            for p in pts {
                cmd.push_str(&format!(" {} {}", p.x, p.y));
            }
        };
        let mut cmd = String::from("holed");
        ring(&mut cmd, map.outer());
        cmd.push_str(&format!(" {}", map.hole_count()));
        for hole in map.holes() {
            ring(&mut cmd, hole);
        }
        self.scale = None;
        let reply = self.call(&cmd)?;
        match reply.strip_prefix("ok ") {
            Some(n) if n.trim() == map.n().to_string() => {
                self.scale = Some(map.scale().clone());
                Ok(())
            }
            _ => Err(format!("unexpected reply to holed: {reply}")),
        }
    }

    /// The visibility polygon of `q` (strictly inside the polygon), exactly:
    /// counter-clockwise from the lexicographically smallest vertex, in the
    /// integer frame, as CGAL reports it (see [`drop_collinear`]).
    pub fn visibility(&mut self, q: &RatPoint) -> Result<Vec<RatPoint>, String> {
        let reply = self.call(&format!("query {}", point_text(q)))?;
        parse_vis(&reply)
    }

    /// The median time in ns of `reps` runs of CGAL's `compute_visibility`
    /// for `q` (no preprocessing, no point location, constructed
    /// coordinates left as Epeck's lazy approximations).
    pub fn bench(&mut self, q: &RatPoint, reps: u32) -> Result<u64, String> {
        self.timed("bench", q, reps)
    }

    /// As [`CgalPeer::bench`], but each run also walks the output and
    /// forces the exact rational value of every vertex coordinate.
    pub fn bench_exact(&mut self, q: &RatPoint, reps: u32) -> Result<u64, String> {
        self.timed("bench_exact", q, reps)
    }

    fn timed(&mut self, cmd: &str, q: &RatPoint, reps: u32) -> Result<u64, String> {
        let reply = self.call(&format!("{cmd} {reps} {}", point_text(q)))?;
        reply
            .strip_prefix("time_ns ")
            .and_then(|t| t.trim().parse().ok())
            .ok_or_else(|| format!("unexpected reply to {cmd}: {reply}"))
    }

    /// Write one command, read one reply line; `error ...` becomes `Err`.
    fn call(&mut self, cmd: &str) -> Result<String, String> {
        let stdin = self.stdin.as_mut().ok_or("cgal peer: stdin closed")?;
        stdin
            .write_all(cmd.as_bytes())
            .and_then(|()| stdin.write_all(b"\n"))
            .and_then(|()| stdin.flush())
            .map_err(|e| format!("cgal peer: write failed: {e}"))?;
        let mut line = String::new();
        let read = self
            .stdout
            .read_line(&mut line)
            .map_err(|e| format!("cgal peer: read failed: {e}"))?;
        if read == 0 {
            return Err("cgal peer exited".to_owned());
        }
        let line = line.trim_end().to_owned();
        match line.strip_prefix("error ") {
            Some(msg) => Err(format!("cgal: {msg}")),
            None => Ok(line),
        }
    }
}

impl Drop for CgalPeer {
    fn drop(&mut self) {
        // Closing stdin ends the peer's input loop.
        drop(self.stdin.take());
        let _ = self.child.wait();
    }
}

/// `x y` of a rational point, as `p/q` texts.
fn point_text(q: &RatPoint) -> String {
    let x = Rational::from((q.hx().clone(), q.hw().clone()));
    let y = Rational::from((q.hy().clone(), q.hw().clone()));
    format!("{x} {y}")
}

/// Parse `vis K x1 y1 ... xK yK`.
fn parse_vis(reply: &str) -> Result<Vec<RatPoint>, String> {
    let mut tok = reply.split_ascii_whitespace();
    if tok.next() != Some("vis") {
        return Err(format!("unexpected reply to query: {reply}"));
    }
    let k: usize = tok
        .next()
        .and_then(|t| t.parse().ok())
        .ok_or_else(|| format!("bad vertex count in: {reply}"))?;
    let mut rational = || -> Result<Rational, String> {
        let t = tok.next().ok_or("vis: too few coordinates")?;
        t.parse::<Rational>()
            .map_err(|e| format!("vis: bad rational {t:?}: {e}"))
    };
    let mut out = Vec::with_capacity(k);
    for _ in 0..k {
        let (x, y) = (rational()?, rational()?);
        out.push(rat_point(x, y));
    }
    if tok.next().is_some() {
        return Err("vis: too many coordinates".to_owned());
    }
    Ok(out)
}

/// The homogeneous point `(x, y)` over the common denominator.
pub fn rat_point(x: Rational, y: Rational) -> RatPoint {
    RatPoint::from_rationals(x, y)
}

/// `poly` without repeated consecutive vertices and without vertices in the
/// middle of a straight stretch (collinear with both neighbours), keeping
/// the order; CGAL reports such vertices. A vertex is dropped when it is
/// collinear with its two neighbours in the deduplicated ring; on a
/// polygon without spikes (CGAL's regularized output has none) this keeps
/// exactly the corners. Fewer than three corners (a degenerate input) give
/// the deduplicated ring back.
pub fn drop_collinear(poly: &[RatPoint]) -> Vec<RatPoint> {
    let mut ring: Vec<RatPoint> = Vec::with_capacity(poly.len());
    for p in poly {
        if ring.last() != Some(p) {
            ring.push(p.clone());
        }
    }
    while ring.len() > 1 && ring.first() == ring.last() {
        ring.pop();
    }
    let n = ring.len();
    if n < 3 {
        return ring;
    }
    let corners: Vec<RatPoint> = (0..n)
        .filter(|&i| {
            orientation_rat(&ring[(i + n - 1) % n], &ring[i], &ring[(i + 1) % n])
                != Orientation::Collinear
        })
        .map(|i| ring[i].clone())
        .collect();
    if corners.len() < 3 {
        ring
    } else {
        corners
    }
}
