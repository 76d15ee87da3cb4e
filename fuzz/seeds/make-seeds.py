#!/usr/bin/env python3
"""Writes the seed corpora of the structure-aware targets, deterministically.

Each target gets one file per shape of `wai_gen::bytes::SHAPES` (the first
byte picks the shape: byte % 8, in the order of SHAPES), followed by bytes
from Python's `random.Random` seeded with the target and shape, so running
this again writes the same files. Run from `fuzz/`: `python3 seeds/make-seeds.py`.
"""
import os
import random

SHAPES = ["ring", "star", "polyomino", "chamfer", "comb", "corridor", "rooms", "family"]
# The viewpoint target reads up to six viewpoints after the map: more bytes.
TARGETS = {
    "claims_ch3": 64,
    "claims_ch4": 64,
    "claims_ch5": 64,
    "visibility": 160,
    "decompose": 64,
}

here = os.path.dirname(os.path.abspath(__file__))
for target, length in TARGETS.items():
    out = os.path.join(here, target)
    os.makedirs(out, exist_ok=True)
    for i, shape in enumerate(SHAPES):
        rnd = random.Random(f"{target}-{shape}")
        data = bytes([i]) + bytes(rnd.randrange(256) for _ in range(length))
        with open(os.path.join(out, f"shape-{shape}"), "wb") as f:
            f.write(data)

# The holes target reads a kind (byte % 2), n, the holes and a seed: one
# file per kind.
out = os.path.join(here, "holes")
os.makedirs(out, exist_ok=True)
for i, kind in enumerate(["orthogonal-pillars", "simple-holes"]):
    rnd = random.Random(f"holes-{kind}")
    data = bytes([i]) + bytes(rnd.randrange(256) for _ in range(11))
    with open(os.path.join(out, f"kind-{kind}"), "wb") as f:
        f.write(data)
