//! A side-by-side peer: karto-scanmatcher's correlative scan matcher run on
//! the same maps and the same scans as [`crate::ScanLocalizer`], for
//! comparison.
//!
//! # Licence boundary
//! karto-scanmatcher (PyPI, OpenKarto's matcher with Python bindings) is
//! GPL-3. It is never vendored, linked or imported here: `scripts/install-karto`
//! installs the pinned wheel into its own virtual environment
//! (`target/peers/karto-venv`), and [`KartoPeer`] runs
//! `peers/karto/karto_peer.py` with that environment's Python as a separate
//! process, exchanging one JSON object per line over its stdin and stdout.
//! Nothing of karto's crosses the pipe but numbers.
//!
//! # What the peer does
//! The map's walls (not the obstacles: the robot does not know them) become
//! karto's correlation grid at [`KartoConfig::resolution`]; each query is a
//! full-circle exhaustive search over the map: the walls' bounding box is
//! tiled with square windows of side [`KartoConfig::window`] (only those
//! meeting the free space are kept), and in each karto runs its coarse
//! search over every position and heading, then its fine search around
//! the best; the best response over the windows is the answer. No odometry
//! prior. See `peers/karto/README.md` for the settings and the measured
//! figures.

use std::io::{BufRead, BufReader, Read, Write};
use std::path::{Path, PathBuf};
use std::process::{Child, ChildStdin, ChildStdout, Command, Stdio};
use std::sync::{Arc, Mutex};

use serde_json::{json, Value};
use wai_map::Map;

use crate::{Pose, Scan};

/// A wall segment in metres, as the peer receives it.
pub type Wall = [(f64, f64); 2];

/// How to install the peer, said by every "not installed" error.
pub const INSTALL_HINT: &str = "run scripts/install-karto";

/// The environment variable naming the Python interpreter to run the peer
/// with, instead of the repository's `target/peers/karto-venv/bin/python`.
pub const PYTHON_ENV: &str = "WAI_KARTO_PYTHON";

/// The walls of `map` in metres, for [`KartoPeer::spawn`]. Obstacles are
/// not walls: the peer, like our localizer, does not know them.
pub fn map_walls(map: &Map) -> Vec<Wall> {
    crate::walls(map)
}

/// The map's outer ring in metres, for [`KartoPeer::spawn_map`]: the free
/// space lies inside it (less the holes, which the walls bring), so the
/// peer searches only windows meeting it.
pub fn map_free(map: &Map) -> Vec<(f64, f64)> {
    let outer = map.outer().len();
    crate::walls(map)
        .into_iter()
        .take(outer)
        .map(|[a, _]| a)
        .collect()
}

/// The peer's settings, sent with the walls.
#[derive(Debug, Clone, PartialEq)]
pub struct KartoConfig {
    /// The side in metres of the square tiles the map's bounding box is
    /// cut into, each searched as a karto window one coarse step wider (so
    /// adjacent ones overlap); `None` searches the whole bounding box as
    /// one window (slow, and on long maps gigabytes).
    pub window: Option<f64>,
    /// The correlation grid's cell in metres; karto's coarse search steps
    /// two cells, its fine search one.
    pub resolution: f64,
    /// The standard deviation (m) of the Gaussian karto smears each map
    /// point with.
    pub smear_deviation: f64,
    /// The coarse heading step over the full circle, in degrees.
    pub coarse_angle_deg: f64,
    /// The fine heading step within ± half a coarse step, in degrees.
    pub fine_angle_deg: f64,
    /// Whether karto refines the coarse best (its `doRefineMatch`).
    pub refine: bool,
}

impl Default for KartoConfig {
    /// karto's fastest settings that keep its success rate on the
    /// evaluation maps and a corridor (peers/karto/README.md gives the
    /// measurements): 8 m windows, karto's 0.05 m grid and 2° step. The peer's `DEFAULTS` agree (a test checks).
    fn default() -> Self {
        KartoConfig {
            window: Some(8.0),
            resolution: 0.05,
            smear_deviation: 0.05,
            coarse_angle_deg: 2.0,
            fine_angle_deg: 0.2,
            refine: true,
        }
    }
}

impl KartoConfig {
    /// The settings as the peer's `config` object.
    pub fn to_json(&self) -> Value {
        json!({
            "window": self.window,
            "resolution": self.resolution,
            "smear_deviation": self.smear_deviation,
            "coarse_angle_deg": self.coarse_angle_deg,
            "fine_angle_deg": self.fine_angle_deg,
            "refine": self.refine,
        })
    }
}

/// What went wrong with the peer.
#[derive(Debug, thiserror::Error)]
pub enum PeerError {
    /// The peer's Python, or karto-scanmatcher in it, is missing.
    #[error("the karto peer is not installed ({why}): {hint}")]
    NotInstalled { why: String, hint: &'static str },
    /// The process could not be started.
    #[error("cannot start the karto peer {python}: {source}")]
    Spawn {
        python: PathBuf,
        source: std::io::Error,
    },
    /// The process ended (or closed its pipes) before answering.
    #[error("the karto peer died ({status}); its stderr ends with:\n{stderr}")]
    Died { status: String, stderr: String },
    /// An answer that is not the JSON the protocol promises.
    #[error("the karto peer answered bad JSON ({why}): {line}")]
    BadAnswer { why: String, line: String },
    /// The peer understood the message and refused it.
    #[error("the karto peer refused: {0}")]
    Refused(String),
    /// A message this side will not send (a raw line with a newline).
    #[error("cannot send {0}")]
    BadRequest(String),
}

/// The peer's answer to one scan.
#[derive(Debug, Clone, PartialEq)]
pub struct PeerAnswer {
    /// The best pose, in the map frame (metres, radians CCW from x).
    pub pose: Pose,
    /// karto's response at that pose, in [0, 1]: the smeared grid's mean
    /// value under the scan's points.
    pub response: f64,
    /// The match's time in milliseconds, measured inside the peer (karto's
    /// `match_scan` only: no JSON, no pipes).
    pub ms: f64,
}

/// A running karto peer holding one map; killed on drop.
#[derive(Debug)]
pub struct KartoPeer {
    child: Child,
    stdin: ChildStdin,
    stdout: BufReader<ChildStdout>,
    stderr: Arc<Mutex<String>>,
    drain: Option<std::thread::JoinHandle<()>>,
    build_ms: f64,
    settings: Value,
}

/// How much of the peer's stderr is kept for error messages.
const STDERR_TAIL: usize = 4096;

impl KartoPeer {
    /// The interpreter [`KartoPeer::spawn`] uses: `$WAI_KARTO_PYTHON`, or
    /// the venv that `scripts/install-karto` makes under the repository's
    /// `target/`.
    pub fn default_python() -> PathBuf {
        match std::env::var_os(PYTHON_ENV) {
            Some(p) if !p.is_empty() => PathBuf::from(p),
            _ => repo_root().join("target/peers/karto-venv/bin/python"),
        }
    }

    /// The peer script, `peers/karto/karto_peer.py` in the repository.
    pub fn script() -> PathBuf {
        repo_root().join("peers/karto/karto_peer.py")
    }

    /// Starts the peer with [`KartoPeer::default_python`] and gives it the
    /// map's `walls`; returns once karto's map is built.
    pub fn spawn(walls: &[Wall], config: &KartoConfig) -> Result<KartoPeer, PeerError> {
        Self::spawn_with(&Self::default_python(), walls, config)
    }

    /// Starts the peer on `map`: its walls, and its boundary as the free
    /// space, so that only windows meeting the map are searched.
    pub fn spawn_map(map: &Map, config: &KartoConfig) -> Result<KartoPeer, PeerError> {
        Self::spawn_full(
            &Self::default_python(),
            &map_walls(map),
            Some(&map_free(map)),
            config,
        )
    }

    /// [`KartoPeer::spawn`] with the given interpreter.
    pub fn spawn_with(
        python: &Path,
        walls: &[Wall],
        config: &KartoConfig,
    ) -> Result<KartoPeer, PeerError> {
        Self::spawn_full(python, walls, None, config)
    }

    /// The peer with the given interpreter, walls and (if any) free-space
    /// ring.
    pub fn spawn_full(
        python: &Path,
        walls: &[Wall],
        free: Option<&[(f64, f64)]>,
        config: &KartoConfig,
    ) -> Result<KartoPeer, PeerError> {
        if !python.exists() {
            return Err(PeerError::NotInstalled {
                why: format!("{} does not exist", python.display()),
                hint: INSTALL_HINT,
            });
        }
        let mut child = Command::new(python)
            // -B: no bytecode files written into the repository.
            .arg("-B")
            .arg(Self::script())
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .map_err(|source| PeerError::Spawn {
                python: python.to_path_buf(),
                source,
            })?;
        let (Some(stdin), Some(stdout), Some(mut err)) =
            (child.stdin.take(), child.stdout.take(), child.stderr.take())
        else {
            unreachable!("all three pipes were requested");
        };
        // Drained on a thread so a chatty peer never blocks on a full pipe;
        // the tail explains a death.
        let stderr = Arc::new(Mutex::new(String::new()));
        let sink = Arc::clone(&stderr);
        let drain = std::thread::spawn(move || {
            let mut buf = [0u8; 1024];
            while let Ok(n @ 1..) = err.read(&mut buf) {
                let mut s = sink.lock().unwrap_or_else(|p| p.into_inner());
                s.push_str(&String::from_utf8_lossy(&buf[..n]));
                if s.len() > 2 * STDERR_TAIL {
                    let cut = s.len() - STDERR_TAIL;
                    let cut = (cut..s.len()).find(|&i| s.is_char_boundary(i)).unwrap_or(0);
                    s.drain(..cut);
                }
            }
        });
        let mut peer = KartoPeer {
            child,
            stdin,
            stdout: BufReader::new(stdout),
            stderr,
            drain: Some(drain),
            build_ms: 0.0,
            settings: Value::Null,
        };
        let walls: Vec<[f64; 4]> = walls.iter().map(|[a, b]| [a.0, a.1, b.0, b.1]).collect();
        let mut first = json!({ "walls": walls, "config": config.to_json() });
        if let Some(ring) = free {
            let ring: Vec<[f64; 2]> = ring.iter().map(|&(x, y)| [x, y]).collect();
            first["free"] = json!(ring);
        }
        let answer = peer.request(&first)?;
        if answer.get("not_installed").and_then(Value::as_bool) == Some(true) {
            return Err(PeerError::NotInstalled {
                why: error_text(&answer).unwrap_or_default(),
                hint: INSTALL_HINT,
            });
        }
        if let Some(e) = error_text(&answer) {
            return Err(PeerError::Refused(e));
        }
        if answer.get("ready").and_then(Value::as_bool) != Some(true) {
            return Err(bad(&answer, "no \"ready\": true"));
        }
        peer.build_ms = number(&answer, "ms")?;
        peer.settings = answer.get("settings").cloned().unwrap_or(Value::Null);
        Ok(peer)
    }

    /// The time karto's map took to build, in milliseconds (in the peer).
    pub fn build_ms(&self) -> f64 {
        self.build_ms
    }

    /// The settings the peer ran with, as it reported them: those sent and
    /// those it derived (windows, search size, range threshold, wall
    /// points).
    pub fn settings(&self) -> &Value {
        &self.settings
    }

    /// karto's best pose for `scan` over the whole map and every heading.
    /// `max_range` is the sensor's range limit, if any.
    pub fn localize(
        &mut self,
        scan: &Scan,
        max_range: Option<f64>,
    ) -> Result<PeerAnswer, PeerError> {
        let answer = self.request(&json!({
            "angles": scan.angles,
            "ranges": scan.ranges,
            "max_range": max_range,
        }))?;
        if let Some(e) = error_text(&answer) {
            return Err(PeerError::Refused(e));
        }
        Ok(PeerAnswer {
            pose: Pose {
                x: number(&answer, "x")?,
                y: number(&answer, "y")?,
                heading: number(&answer, "heading")?,
            },
            response: number(&answer, "response")?,
            ms: number(&answer, "ms")?,
        })
    }

    /// Sends one line as it is and returns the peer's answer, error answers
    /// included: for tests of the protocol itself.
    pub fn raw(&mut self, line: &str) -> Result<Value, PeerError> {
        if line.contains('\n') {
            return Err(PeerError::BadRequest("a line with a newline".into()));
        }
        self.exchange(line)
    }

    fn request(&mut self, message: &Value) -> Result<Value, PeerError> {
        self.exchange(&message.to_string())
    }

    fn exchange(&mut self, line: &str) -> Result<Value, PeerError> {
        let sent = writeln!(self.stdin, "{line}").and_then(|()| self.stdin.flush());
        let mut answer = String::new();
        let read = match sent {
            Ok(()) => self.stdout.read_line(&mut answer),
            Err(e) => Err(e),
        };
        match read {
            Ok(n) if n > 0 => serde_json::from_str(&answer).map_err(|e| PeerError::BadAnswer {
                why: e.to_string(),
                line: answer.trim_end().to_string(),
            }),
            // EOF or a broken pipe: the process is gone (or going).
            _ => Err(self.died()),
        }
    }

    fn died(&mut self) -> PeerError {
        // EOF almost always means it is exiting; one that closed its pipes
        // and lingers is killed after two seconds rather than waited for.
        let mut status = None;
        for _ in 0..40 {
            match self.child.try_wait() {
                Ok(Some(s)) => {
                    status = Some(s.to_string());
                    break;
                }
                Ok(None) => std::thread::sleep(std::time::Duration::from_millis(50)),
                Err(e) => {
                    status = Some(format!("status unknown: {e}"));
                    break;
                }
            }
        }
        let status = status.unwrap_or_else(|| {
            let _ = self.child.kill();
            "alive with its pipes closed; killed".to_string()
        });
        // The drain thread ends at the pipe's EOF, having read the last
        // words; a grandchild holding the pipe open is not waited for.
        for _ in 0..20 {
            match &self.drain {
                Some(d) if !d.is_finished() => {
                    std::thread::sleep(std::time::Duration::from_millis(50))
                }
                _ => break,
            }
        }
        let stderr = self
            .stderr
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .clone();
        PeerError::Died { status, stderr }
    }
}

impl Drop for KartoPeer {
    fn drop(&mut self) {
        // Already exited is fine; the wait reaps it either way.
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// The root of the repository the command is run in: the nearest ancestor
/// of the current directory holding the peer's script, never the path this
/// binary was built at (a binary installed elsewhere uses the peer of the
/// repository the user is in). Outside any, the current directory: the
/// paths under it do not exist and the peer reports itself not installed.
fn repo_root() -> PathBuf {
    let here = std::env::current_dir().unwrap_or_else(|_| PathBuf::from("."));
    here.ancestors()
        .find(|dir| dir.join("peers/karto/karto_peer.py").is_file())
        .map_or(here.clone(), Path::to_path_buf)
}

fn error_text(answer: &Value) -> Option<String> {
    answer.get("error").map(|e| match e.as_str() {
        Some(s) => s.to_string(),
        None => e.to_string(),
    })
}

fn number(answer: &Value, key: &str) -> Result<f64, PeerError> {
    answer
        .get(key)
        .and_then(Value::as_f64)
        .ok_or_else(|| bad(answer, &format!("no number {key:?}")))
}

fn bad(answer: &Value, why: &str) -> PeerError {
    PeerError::BadAnswer {
        why: why.to_string(),
        line: answer.to_string(),
    }
}
