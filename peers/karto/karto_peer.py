#!/usr/bin/env python3
"""karto-scanmatcher as a side-by-side peer: JSON lines on stdin/stdout.

karto-scanmatcher (PyPI, GPL-3) is run only in this separate process, from
its own virtual environment (scripts/install-karto); the Rust side talks to
it through pipes and never links or vendors it. This file only imports it.

Protocol (one JSON object per line, one answer line per message):

  {"walls": [[x1, y1, x2, y2], ...], "free": [[x, y], ...] (optional),
   "config": {...}}
      -> {"ready": true, "ms": build_ms, "settings": {...}}
  {"angles": [...], "ranges": [r | null, ...], "max_range": r | null}
      -> {"x": .., "y": .., "heading": .., "response": .., "ms": match_ms,
          "cpu_ms": match_cpu_ms, "covariance": [[..3..], ..],
          "windows": n_searched}
  anything wrong -> {"error": "..."}; the process keeps serving
      (with "not_installed": true when karto_scanmatcher does not import).
  EOF on stdin -> exit 0.

The answer's "ms" is wall-clock time; "cpu_ms" is this process's CPU
time for the same match, steadier on a loaded machine.

"free" is the map's boundary ring (the free space is its inside, even-odd
rule); without it every window of the walls' bounding box is searched.

Units: metres and radians, headings counter-clockwise from the x axis,
scan angles relative to the robot's heading (equal steps), all in the map
frame.

How the map is given to karto. Karto's matcher knows a map only as a list
of "base" scans whose points it rasterises (and smears) into its
correlation grid at every match. A known floor plan is therefore handed
over as one synthetic base scan per wall: a scan whose beams all point
along the wall (angular step 0) from one end, with ranges 0, s, 2s, ..,
the wall's length, so its points sample the wall every s metres
(s = resolution / 2 by default; every grid cell a wall crosses is hit).
Karto drops base-scan points that do not run counter-clockwise around the
search centre (its "viewpoint" filter, meant for local matching); each
wall is kept in both directions and the one running counter-clockwise
around the window's centre is given, so that every wall is kept.

Global search, windowed (config "window": a tile's side in metres,
rounded up to whole coarse steps). Karto's search window is a square of
side `search_size` around the query's pose, searched at every heading of
+-pi (coarse: every 2 cells and every coarse angle step; then refined
around the best: 1 cell, fine angle step). The walls' bounding box is
tiled with square tiles of side `window`, centred on the box, and each
tile is searched as a karto window one coarse step wider, so adjacent
windows overlap by one coarse step: every position is on some window's
coarse lattice, and one lattice runs through them all. Only windows
meeting the free space are kept. Each query is matched in every window,
each time with the walls within reach of that window (the range
threshold, or the query's range limit) as base scans, each wall's points
counter-clockwise around that window's centre; the best response over
the windows is the answer. Karto's grid is the window plus a margin on
each side for the scan's points: the range threshold, capped at the
bounding box's longer side. No odometry penalty (a global search has no
prior).

"window": null is the whole-map single window: centred on the bounding
box, side = the box's longer side. On a long map its candidate list
(every position times every heading) runs to gigabytes.
"""

import json
import math
import os
import sys
import time

try:
    import karto_scanmatcher as karto
except ImportError as e:  # reported as an answer, so the caller sees why
    karto = None
    IMPORT_ERROR = str(e)

# Defaults: karto's fastest settings that keep its success rate on the
# evaluation maps and a long corridor (measured: peers/karto/README.md).
DEFAULTS = {
    "window": 8.0,  # search tile side (m); None: one window, the whole map
    "resolution": 0.05,  # correlation grid cell (m); coarse step is 2 cells
    "smear_deviation": 0.05,  # Gaussian smear of map points (m)
    "coarse_angle_deg": 2.0,  # coarse heading step over the full circle
    "fine_angle_deg": 0.2,  # fine heading step within +- coarse/2
    "refine": True,  # karto's fine search around the coarse best
    "range_threshold": None,  # None: the walls' bounding-box diagonal
    "wall_step": None,  # None: resolution / 2
}


class NotInstalled(Exception):
    """karto_scanmatcher does not import in this interpreter."""


def _inside(x, y, ring):
    """Whether (x, y) is inside the ring (even-odd rule)."""
    inside = False
    n = len(ring)
    for i in range(n):
        (x1, y1), (x2, y2) = ring[i], ring[(i + 1) % n]
        if (y1 > y) != (y2 > y) and x < x1 + (y - y1) * (x2 - x1) / (y2 - y1):
            inside = not inside
    return inside


def _segment_meets_box(seg, x0, y0, x1, y1):
    """Whether the segment meets the closed box [x0, x1] x [y0, y1]
    (Liang-Barsky clipping)."""
    ax, ay, bx, by = seg
    dx, dy = bx - ax, by - ay
    lo, hi = 0.0, 1.0
    for p, q in ((-dx, ax - x0), (dx, x1 - ax), (-dy, ay - y0), (dy, y1 - ay)):
        if p == 0:
            if q < 0:
                return False
        else:
            t = q / p
            if p < 0:
                lo = max(lo, t)
            else:
                hi = min(hi, t)
            if lo > hi:
                return False
    return True


def _segment_box_distance(seg, x0, y0, x1, y1):
    """The distance between a segment and the box [x0, x1] x [y0, y1]."""
    if _segment_meets_box(seg, x0, y0, x1, y1):
        return 0.0
    ax, ay, bx, by = seg

    def point_box(px, py):
        return math.hypot(max(x0 - px, 0.0, px - x1), max(y0 - py, 0.0, py - y1))

    def point_segment(px, py):
        dx, dy = bx - ax, by - ay
        ll = dx * dx + dy * dy
        t = 0.0 if ll == 0 else max(0.0, min(1.0, ((px - ax) * dx + (py - ay) * dy) / ll))
        return math.hypot(px - ax - t * dx, py - ay - t * dy)

    corners = ((x0, y0), (x1, y0), (x1, y1), (x0, y1))
    return min([point_box(ax, ay), point_box(bx, by)] + [point_segment(cx, cy) for cx, cy in corners])


class Peer:
    def __init__(self, walls, config, free=None):
        if karto is None:
            raise NotInstalled("cannot import karto_scanmatcher: " + IMPORT_ERROR)
        unknown = set(config) - set(DEFAULTS)
        if unknown:
            raise ValueError("unknown config keys: %s" % sorted(unknown))
        cfg = dict(DEFAULTS)
        cfg.update(config)
        segs = [tuple(float(v) for v in w) for w in walls]
        if not segs or any(len(s) != 4 or not all(map(math.isfinite, s)) for s in segs):
            raise ValueError("walls must be a non-empty list of [x1, y1, x2, y2] of finite numbers")
        ring = None
        if free is not None:
            ring = [tuple(float(v) for v in p) for p in free]
            if len(ring) < 3 or any(len(p) != 2 or not all(map(math.isfinite, p)) for p in ring):
                raise ValueError("free must be a ring of at least 3 [x, y] of finite numbers")
        res = float(cfg["resolution"])
        if not res > 0:
            raise ValueError("resolution must be > 0")
        xs = [v for s in segs for v in (s[0], s[2])]
        ys = [v for s in segs for v in (s[1], s[3])]
        x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)
        cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
        w, h = x1 - x0, y1 - y0
        # A whole number of coarse steps (2 cells) per side keeps karto's
        # grids odd-sized and its search lattice symmetric about the centre.
        coarse = 2 * res

        def steps(length):
            return max(1, math.ceil(length / coarse - 1e-9))

        thr = float(cfg["range_threshold"] or math.hypot(w, h))
        if not thr > 0:
            raise ValueError("range_threshold must be > 0")
        step = float(cfg["wall_step"] or res / 2)
        window = cfg["window"]
        if window is None:
            search = steps(max(w, h)) * coarse
            centres = [(cx, cy)]
            margin = thr
            overlap = None
        else:
            window = float(window)
            if not window > 0:
                raise ValueError("window must be > 0 (or null)")
            # Tiles of k coarse steps, each searched with one coarse step
            # more (karto's window): adjacent windows overlap by one step,
            # sharing two lattice lines, and one lattice runs through them
            # all, centred on the bounding box.
            k = steps(window)
            stride = k * coarse
            search = (k + 1) * coarse
            overlap = coarse
            # Karto centres its grid's cells on the window's centre, so the
            # centres are put on multiples of the resolution: walls on
            # round coordinates then run along cell centres, not cell
            # borders (which would cost a 0.1 m grid a tenth of its
            # response and some answers). One cell more of span covers the
            # shift.
            cx, cy = round(cx / res) * res, round(cy / res) * res
            nx = max(1, math.ceil((w + res - search) / stride - 1e-9) + 1)
            ny = max(1, math.ceil((h + res - search) / stride - 1e-9) + 1)
            half = search / 2
            centres = []
            for j in range(ny):
                for i in range(nx):
                    wx = cx + (i - (nx - 1) / 2) * stride
                    wy = cy + (j - (ny - 1) / 2) * stride
                    box = (wx - half, wy - half, wx + half, wy + half)
                    if ring is None or _inside(wx, wy, ring) or any(
                        _segment_meets_box(s, *box) for s in segs
                    ):
                        centres.append((wx, wy))
            # Karto's grid: the window plus the points a scan from it can
            # reach, which all lie within the bounding box.
            margin = min(thr, max(w, h))
        self.search = search
        self.thr = thr
        c = karto.ScanMatcherConfig()
        c.resolution = res
        c.search_size = search
        c.smear_deviation = float(cfg["smear_deviation"])
        c.range_threshold = float(margin)
        c.coarse_angle_resolution = math.radians(cfg["coarse_angle_deg"])
        c.coarse_search_angle_offset = math.pi
        c.fine_search_angle_resolution = math.radians(cfg["fine_angle_deg"])
        c.use_response_expansion = False
        self.matcher = karto.Wrapper(c)
        self.refine = bool(cfg["refine"])
        # Each wall in both directions; a window takes the one running
        # counter-clockwise around its centre.
        self.segs = segs
        self.scans = [
            (self._wall_scan(s, step, thr, 2 * i), self._wall_scan(s[2:] + s[:2], step, thr, 2 * i + 1))
            for i, s in enumerate(segs)
        ]
        self.windows = centres
        self.bases = {}
        self.settings = {
            "window": window,
            "windows": len(centres),
            "window_overlap": overlap,
            "resolution": res,
            "search_size": search,
            "search_centre": [cx, cy] if window is None else None,
            "smear_deviation": c.smear_deviation,
            "range_threshold": thr,
            "coarse_angle_deg": cfg["coarse_angle_deg"],
            "fine_angle_deg": cfg["fine_angle_deg"],
            "refine": self.refine,
            "wall_step": step,
            "wall_points": sum(len(a.ranges) for a, _ in self.scans),
            "free_space_given": ring is not None,
        }

    def _wall_scan(self, seg, step, thr, i):
        """One wall as a base scan: beams along it from its first end,
        points every `step`."""
        x1, y1, x2, y2 = seg
        length = math.hypot(x2 - x1, y2 - y1)
        n = max(1, math.ceil(length / step))
        ranges = [length * k / n for k in range(n + 1)]
        # The scan's own range limit is moot: karto rasterises base scans'
        # unfiltered points.
        big = max(length, thr) + 1
        conf = karto.LaserScanConfig(0.0, 0.0, 0.0, 0.0, big, big, "wall%d" % i)
        pose = karto.Pose2(x1, y1, math.atan2(y2 - y1, x2 - x1))
        return karto.LocalizedRangeScan(conf, ranges, pose, pose, i, 0.0)

    def _base(self, k, reach):
        """The base scans of window k: the walls within `reach` of it,
        each counter-clockwise around the window's centre (karto's
        viewpoint filter; collinear with the centre: kept either way)."""
        key = (k, reach)
        if key not in self.bases:
            wx, wy = self.windows[k]
            half = self.search / 2
            box = (wx - half, wy - half, wx + half, wy + half)
            base = []
            for s, (fwd, back) in zip(self.segs, self.scans):
                if _segment_box_distance(s, *box) > reach:
                    continue
                ccw = (s[0] - wx) * (s[3] - wy) - (s[1] - wy) * (s[2] - wx) >= 0
                base.append(fwd if ccw else back)
            self.bases[key] = base
        return self.bases[key]

    def localize(self, msg):
        angles = msg.get("angles")
        ranges = msg.get("ranges")
        if not isinstance(angles, list) or not isinstance(ranges, list):
            raise ValueError("a query needs lists 'angles' and 'ranges'")
        if len(angles) != len(ranges) or len(angles) < 2:
            raise ValueError("angles and ranges must have the same length >= 2")
        angles = [float(a) for a in angles]
        d = (angles[-1] - angles[0]) / (len(angles) - 1)
        if not d > 0 or any(abs(angles[i] - (angles[0] + i * d)) > 1e-6 for i in range(len(angles))):
            raise ValueError("karto needs beams at equal increasing angles")
        max_range = msg.get("max_range")
        limit = min(float(max_range), self.thr) if max_range is not None else self.thr
        # A lost return is NaN: karto skips it in the match (its own rule).
        rs = [float(r) if r is not None and 0 < float(r) <= limit else math.nan for r in ranges]
        if all(math.isnan(r) for r in rs):
            raise ValueError("the scan has no returns")
        big = self.thr + 1
        conf = karto.LaserScanConfig(angles[0], angles[-1], d, 0.0, big, big, "query")
        best = None
        t, cpu = time.perf_counter(), time.process_time()
        for k, (wx, wy) in enumerate(self.windows):
            # The query's pose is karto's search centre.
            guess = karto.Pose2(wx, wy, 0.0)
            scan = karto.LocalizedRangeScan(conf, rs, guess, guess, 0, 0.0)
            base = self._base(k, limit)
            if not base:
                continue
            result = self.matcher.match_scan(scan, base, False, self.refine)
            if best is None or result.response > best.response:
                best = result
        ms = (time.perf_counter() - t) * 1000
        cpu_ms = (time.process_time() - cpu) * 1000
        if best is None:
            raise ValueError("no window has a wall within reach")
        p = best.best_pose
        return {
            "x": p.x,
            "y": p.y,
            "heading": p.yaw,
            "response": best.response,
            "ms": ms,
            "cpu_ms": cpu_ms,
            "covariance": best.covariance,
            "windows": len(self.windows),
        }


def main():
    peer = None
    out = sys.stdout
    # A measuring aid: WAI_KARTO_TIMES names a file each answer (pose,
    # response, times) and the settings are appended to, as JSON lines.
    path = os.environ.get("WAI_KARTO_TIMES")
    times = open(path, "a") if path else None
    for line in sys.stdin:
        if not line.strip():
            continue
        try:
            msg = json.loads(line)
            if not isinstance(msg, dict):
                raise ValueError("a message must be a JSON object")
            if "walls" in msg:
                t = time.perf_counter()
                peer = Peer(msg["walls"], msg.get("config") or {}, msg.get("free"))
                ms = (time.perf_counter() - t) * 1000
                answer = {"ready": True, "ms": ms, "settings": peer.settings}
            elif peer is None:
                raise ValueError("the first message must give the walls")
            else:
                answer = peer.localize(msg)
        except NotInstalled as e:
            answer = {"error": str(e), "not_installed": True}
        except Exception as e:  # noqa: BLE001 - every failure becomes an answer
            answer = {"error": "%s: %s" % (type(e).__name__, e)}
        if times is not None and "cpu_ms" in answer:
            keys = ("x", "y", "heading", "response", "ms", "cpu_ms")
            times.write(json.dumps(dict({k: answer[k] for k in keys}, settings=peer.settings)) + "\n")
            times.flush()
        out.write(json.dumps(answer, allow_nan=False) + "\n")
        out.flush()


if __name__ == "__main__":
    main()
