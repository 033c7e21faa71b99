#!/usr/bin/env python3
"""Generate examples/keyline_3d.csv: a realistic scanned roof-tile keyline.

A pantile (S-shaped roof tile) is pressed from clay on a form; its keyline, the
intersection of the tile's upper surface with a plane across it, is close to an
elastica with one inflection (seed 000 §5). A 3D scanner sees that line as a
noisy, unevenly spaced polyline in some tilted plane of its own coordinate
system. This script makes such a polyline, deterministically:

1. the true keyline is a smooth elastica (libelastica.SmoothElastica) with
   k = 0.65 whose parameter range u = sqrt(mu) s + q in [0.25, 3.39] crosses
   K(k) ~ 1.8 once (3K ~ 5.4 lies beyond), so the curvature 2 k sqrt(mu) cn(u)
   changes sign exactly once: one inflection, 330 mm of arc, a 311 mm chord,
   ~47 mm from trough to crest, as a pantile;
2. it is sampled at jittered arc-length steps of about 2 mm (a line scanner
   sweeping at uneven speed), with a few short gaps;
3. it is placed in 3D: the tile lies on a roof of 32 degrees pitch, turned
   by 17 degrees about the vertical in the scanner frame, offset from the origin;
4. isotropic Gaussian measurement noise of sigma = 0.15 mm is added, plus a
   small out-of-plane sag (the tile's warp, 0.3 mm at mid-length).

Run from the source tree after `make lib`:
    LIBELASTICA_PATH=build/libelastica.so PYTHONPATH=python python3 examples/make_keyline.py
The output is committed, so `make demo` does not need to regenerate it.
"""
from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "python"))

import libelastica as el  # noqa: E402


def true_keyline() -> el.SmoothElastica:
    """The noiseless keyline, in mm, in its own plane."""
    return el.SmoothElastica(x0=0.0, y0=0.0, phi=-1.028, mu=(1.0 / 105.0) ** 2, k=0.65,
                             q=0.25, length=330.0)


def rotation(axis, angle: float) -> np.ndarray:
    """Rotation matrix about a unit axis (Rodrigues)."""
    a = np.asarray(axis, dtype=float)
    a = a / np.linalg.norm(a)
    K = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + math.sin(angle) * K + (1 - math.cos(angle)) * K @ K


def make(seed: int = 20240605) -> np.ndarray:
    rng = np.random.default_rng(seed)
    curve = true_keyline()
    # 2. jittered arc-length sampling with two short scanner gaps
    steps = rng.uniform(1.4, 2.6, size=400)
    s = np.concatenate([[0.0], np.cumsum(steps)])
    s = s[s <= curve.length]
    gaps = ((s > 101.0) & (s < 108.0)) | ((s > 247.0) & (s < 252.0))
    s = s[~gaps]
    xy = curve.points(s)
    # out-of-plane warp of the tile
    sag = 0.3 * np.sin(math.pi * s / curve.length)
    local = np.column_stack([xy, sag])
    # 3. place the keyline plane in the scanner frame
    R = rotation([0, 0, 1], math.radians(17.0)) @ rotation([1, 0, 0], math.radians(32.0))
    xyz = local @ R.T + np.array([412.0, -138.5, 96.25])
    # 4. measurement noise
    xyz += rng.normal(0.0, 0.15, size=xyz.shape)
    return xyz


def main() -> None:
    xyz = make()
    out = HERE / "keyline_3d.csv"
    with open(out, "w") as f:
        f.write("# scanned pantile keyline (synthetic, examples/make_keyline.py): "
                "x,y,z in mm, scanner frame, sigma 0.15 mm noise\n")
        f.write("x,y,z\n")
        for p in xyz:
            f.write(f"{p[0]:.3f},{p[1]:.3f},{p[2]:.3f}\n")
    kappa = true_keyline().curvature(np.linspace(0, true_keyline().length, 2001))
    changes = int(np.sum(np.sign(kappa[1:]) != np.sign(kappa[:-1])))
    print(f"wrote {out} ({len(xyz)} points, {changes} inflection(s) in the true curve)")


if __name__ == "__main__":
    main()
