#!/usr/bin/env python3
"""karto-scanmatcher as a side-by-side peer: JSON lines on stdin/stdout.

karto-scanmatcher (PyPI, GPL-3) is run only in this separate process, from
its own virtual environment (scripts/install-karto); the Rust side talks to
it through pipes and never links or vendors it. This file only imports it.

Protocol (one JSON object per line, one answer line per message):

  {"walls": [[x1, y1, x2, y2], ...], "config": {...}}
      -> {"ready": true, "ms": build_ms, "settings": {...}}
  {"angles": [...], "ranges": [r | null, ...], "max_range": r | null}
      -> {"x": .., "y": .., "heading": .., "response": .., "ms": match_ms,
          "covariance": [[..3..], ..]}
  anything wrong -> {"error": "..."}; the process keeps serving
      (with "not_installed": true when karto_scanmatcher does not import).
  EOF on stdin -> exit 0.

Units: metres and radians, headings counter-clockwise from the x axis,
scan angles relative to the robot's heading (equal steps), all in the map
frame.

How the map is given to karto. Karto's matcher knows a map only as a list
of "base" scans whose points it rasterises (and smears) into its
correlation grid at every match. A known floor plan is therefore handed
over as one synthetic base scan per wall: a scan whose beams all point
along the wall (angular step 0) from its first end, with ranges 0, s, 2s,
.., the wall's length, so its points sample the wall every s metres
(s = resolution / 2 by default; every grid cell a wall crosses is hit).
Karto drops base-scan points that do not run counter-clockwise around the
search centre (its "viewpoint" filter, meant for local matching); each
wall's points are ordered counter-clockwise around that centre so that
every wall is kept.

Global search. The search centre is the middle of the walls' bounding box;
karto's window is square, with side `search_size`, so it is set to the
longer side of the bounding box (rounded up to whole coarse steps), and
the angular window to +-pi around heading 0: every position in the map and
every heading is tried on the coarse grid (2 cells, coarse angle step),
then refined around the best (1 cell, fine angle step). No odometry
penalty (a global search has no prior).
"""

import json
import math
import sys
import time

try:
    import karto_scanmatcher as karto
except ImportError as e:  # reported as an answer, so the caller sees why
    karto = None
    IMPORT_ERROR = str(e)

# Defaults: what a fair user would choose for global localization on an
# indoor floor of tens of metres (see peers/karto/README.md).
DEFAULTS = {
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


class Peer:
    def __init__(self, walls, config):
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
        res = float(cfg["resolution"])
        if not res > 0:
            raise ValueError("resolution must be > 0")
        xs = [v for s in segs for v in (s[0], s[2])]
        ys = [v for s in segs for v in (s[1], s[3])]
        self.centre = ((min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2)
        w, h = max(xs) - min(xs), max(ys) - min(ys)
        # A whole number of coarse steps (2 cells) per side keeps karto's
        # grids odd-sized and its search lattice symmetric about the centre.
        coarse = 2 * res
        search = math.ceil(max(w, h) / coarse - 1e-9) * coarse
        thr = cfg["range_threshold"] or math.hypot(w, h)
        step = cfg["wall_step"] or res / 2

        c = karto.ScanMatcherConfig()
        c.resolution = res
        c.search_size = search
        c.smear_deviation = float(cfg["smear_deviation"])
        c.range_threshold = float(thr)
        c.coarse_angle_resolution = math.radians(cfg["coarse_angle_deg"])
        c.coarse_search_angle_offset = math.pi
        c.fine_search_angle_resolution = math.radians(cfg["fine_angle_deg"])
        c.use_response_expansion = False
        self.matcher = karto.Wrapper(c)
        self.refine = bool(cfg["refine"])
        self.base = [self._wall_scan(s, step, thr, i) for i, s in enumerate(segs)]
        self.settings = {
            "resolution": res,
            "search_size": search,
            "search_centre": list(self.centre),
            "smear_deviation": c.smear_deviation,
            "range_threshold": thr,
            "coarse_angle_deg": cfg["coarse_angle_deg"],
            "fine_angle_deg": cfg["fine_angle_deg"],
            "refine": self.refine,
            "wall_step": step,
            "wall_points": sum(len(b.ranges) for b in self.base),
        }

    def _wall_scan(self, seg, step, thr, i):
        """One wall as a base scan: beams along it, points every `step`."""
        cx, cy = self.centre
        x1, y1, x2, y2 = seg
        # Counter-clockwise around the centre, or karto's viewpoint filter
        # drops the wall (collinear with the centre: kept either way).
        if (x1 - cx) * (y2 - cy) - (y1 - cy) * (x2 - cx) < 0:
            x1, y1, x2, y2 = x2, y2, x1, y1
        length = math.hypot(x2 - x1, y2 - y1)
        n = max(1, math.ceil(length / step))
        ranges = [length * k / n for k in range(n + 1)]
        # Ranges reach past the threshold only on walls longer than the
        # diagonal, which cannot happen; the scan's own threshold is moot
        # (karto rasterises base scans' unfiltered points).
        conf = karto.LaserScanConfig(0.0, 0.0, 0.0, 0.0, max(length, thr) + 1, max(length, thr) + 1, "wall%d" % i)
        pose = karto.Pose2(x1, y1, math.atan2(y2 - y1, x2 - x1))
        return karto.LocalizedRangeScan(conf, ranges, pose, pose, i, 0.0)

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
        limit = float(max_range) if max_range is not None else self.settings["range_threshold"]
        # A lost return is NaN: karto skips it in the match (its own rule).
        rs = [float(r) if r is not None and 0 < float(r) <= limit else math.nan for r in ranges]
        if all(math.isnan(r) for r in rs):
            raise ValueError("the scan has no returns")
        big = max(limit, self.settings["range_threshold"]) + 1
        conf = karto.LaserScanConfig(angles[0], angles[-1], d, 0.0, big, big, "query")
        cx, cy = self.centre
        guess = karto.Pose2(cx, cy, 0.0)
        scan = karto.LocalizedRangeScan(conf, rs, guess, guess, 0, 0.0)
        t = time.perf_counter()
        result = self.matcher.match_scan(scan, self.base, False, self.refine)
        ms = (time.perf_counter() - t) * 1000
        p = result.best_pose
        return {
            "x": p.x,
            "y": p.y,
            "heading": p.yaw,
            "response": result.response,
            "ms": ms,
            "covariance": result.covariance,
        }


def main():
    peer = None
    out = sys.stdout
    for line in sys.stdin:
        if not line.strip():
            continue
        try:
            msg = json.loads(line)
            if not isinstance(msg, dict):
                raise ValueError("a message must be a JSON object")
            if "walls" in msg:
                t = time.perf_counter()
                peer = Peer(msg["walls"], msg.get("config") or {})
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
        out.write(json.dumps(answer, allow_nan=False) + "\n")
        out.flush()


if __name__ == "__main__":
    main()
