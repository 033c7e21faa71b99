#!/usr/bin/env python3
"""Write the seed inputs of fuzz/corpus: the findings of issue 12, encoded in the
harness's input format (fuzz.h) by mirroring each ENTRY's decode order in
entries.def. `make check` replays the corpus; a finding of the fuzzer is added
by copying its saved input (build/fuzz/findings/*.bin) into fuzz/corpus.

    python3 fuzz/seeds.py            (rewrites fuzz/corpus/issue12-*.bin)
"""
import math
import struct
from pathlib import Path

HUGE = {"SIZE_MAX": 0, "2^62-1": 1, "2^61-1": 2, "SIZE_MAX/2": 3}   # fz_request's table


def entry_id(name: str) -> bytes:
    h = 2166136261
    for c in name.encode():
        h = ((h ^ c) * 16777619) & 0xFFFFFFFF
    return struct.pack(">H", (h ^ (h >> 16)) & 0xFFFF)


def nulls() -> bytes:               # fz_nulls: no NULL pointers
    return bytes(4)


def double(x: float) -> bytes:      # fz_double, any bit pattern (tag >= 230)
    return b"\xff" + struct.pack(">d", x)


def rng(x: float) -> bytes:         # fz_range outside its [lo, hi] path: tag >= 200, then fz_double
    return b"\xff" + double(x)


def count(n: int) -> bytes:         # fz_count: tag >= 240, then 2 bytes (n <= max)
    return b"\xf0" + struct.pack(">H", n)


def request(name: str) -> bytes:    # fz_request: one of the huge values
    return bytes([232 + HUGE[name]])
# (fz_request of an ordinary count: a tag byte < 232, then fz_count's bytes)


def small_int(v: int) -> bytes:     # fz_int in -3..40
    return bytes([v + 3])


def points(pts, dim: int) -> bytes:     # fz_points, pattern 0 (each coordinate a fz_double)
    out = bytes([0, 4, 0, 0, 0, 0, 1])  # pattern, no scale, k, L (unused), no noise
    for p in pts:
        for j in range(min(dim, 3)):
            out += double(p[j])
    return out + b"\x01"                # no bad coordinate


def pattern(how: int, scale: int = 4) -> bytes:   # fz_points, a built-in shape
    return bytes([how, scale, 0x80, 0, 0x80, 0, 1, 1])


def smooth(x0=0.0, y0=0.0, phi=0.0, mu=1.0, k=0.5, q=0.0, length=1.0) -> bytes:
    return b"".join(rng(v) for v in (x0, y0, phi, mu, k, q, length))


def affine_polyline(n_request: str) -> bytes:
    arc = [(math.cos(t), math.sin(t)) for t in (2.5 * i / 199 for i in range(200))]
    return (entry_id("el_affine_polyline") + nulls() + count(200) + request(n_request) + count(0)
            + points(arc, 2) + bytes([0, 1, 1, 1, 1, 1, 1, 1]))


def smooth_to_bspline(tol: float, **p) -> bytes:
    return entry_id("el_smooth_to_bspline") + nulls() + smooth(**p) + b"\x00" + double(tol) + b"\x01\x00"


SEEDS = {
    # heap overflow: 2 (n + 1) sizeof(double) wrapped; n = SIZE_MAX looped forever
    "affine-polyline-n-2^61-1": affine_polyline("2^61-1"),
    "affine-polyline-n-SIZE_MAX": affine_polyline("SIZE_MAX"),
    # dim * npoles wrapped: EL_OK with a 0-byte array
    "bspline-alloc-wraps": entry_id("el_bspline_alloc") + nulls() + small_int(3) + small_int(2)
    + request("SIZE_MAX/2") + b"\x00" + count(2),
    # degree + 1 overflowed in el_bspline_check (degree = INT_MAX: fz_int's odd value 1)
    "bspline-check-degree-INT_MAX": entry_id("el_bspline_check") + nulls() + b"\x01" + b"\x02"
    + count(4) + pattern(6) + rng(0.0) + rng(1.0) + bytes([3, 225]),
    # resampling: a 1000-long segment at r = 1e-5 stopped at 524 (EL_OK), r = 1e-9 on an arc
    "resample-segment-1000-r-1e-5": entry_id("el_resample_equilateral") + nulls() + count(2)
    + points([(0, 0), (1000, 0)], 2) + double(1e-5),
    "resample-arc-r-1e-9": entry_id("el_resample_equilateral") + nulls() + count(3000)
    + pattern(3) + double(1e-9),
    # el_smooth_to_bspline: 1e5 poles for seconds, EL_EMAXITER without writing out
    "smooth-to-bspline-k-1e8": smooth_to_bspline(1e-6, k=1e8),
    "smooth-to-bspline-mu-1e8": smooth_to_bspline(1e-6, mu=1e8, k=0.9),
    "smooth-to-bspline-length-1e8": smooth_to_bspline(1e-6, k=0.9, length=1e8),
    "smooth-to-bspline-tol-1e-300": smooth_to_bspline(1e-300, k=0.9, length=5.0),
    # coincident points: EL_OK with NaN
    "affine-elements-nd-coincident": entry_id("el_affine_elements_nd") + nulls() + b"\x00\x01"
    + count(6) + pattern(1),
    # the singular neighbourhood of K = 2: m = 0.6438 gave a basis reaching -221, no status
    "blend-elliptic-m-0.6438": entry_id("el_blend_init_elliptic") + nulls() + b"\x01"
    + rng(math.sqrt(0.6438)) + double(2.0),
    # found by the fuzzer while it was built: -DBL_MAX averaged to -inf (EL_OK);
    # c = 1e-310 and d = 5e-324 gave EL_OK with NaN in Minv; control points near 1e15 with
    # tol 7.5e-4 ran every fit up to 256 spans (now refused: below what they resolve)
    "lane-riesenfeld-minus-DBL_MAX": entry_id("el_affine_lane_riesenfeld") + nulls() + b"\x00"
    + small_int(2) + b"\x01" + count(3) + points([(0,), (-1.7976931348623157e308,), (1,)], 1),
    "blend-mq-c-denormal": entry_id("el_blend_init_mq") + nulls() + double(1e-310) + double(8.95),
    "blend-elliptic-d-denormal": entry_id("el_blend_init_elliptic") + nulls() + b"\x01"
    + rng(0.478) + double(5e-324),
    # issue 12, core's: k = 1 on the equally spaced path returned NaN with EL_OK
    "smooth-eval-k-1-equally-spaced": entry_id("el_smooth_eval") + nulls()
    + smooth(mu=1.0, k=1.0, length=50.0) + count(32) + b"\x01" + double(0.0) + double(50.0 / 31),
}


def main() -> None:
    out = Path(__file__).resolve().parent / "corpus"
    out.mkdir(exist_ok=True)
    for name, data in SEEDS.items():
        (out / f"issue12-{name}.bin").write_bytes(data)
    print(f"wrote {len(SEEDS)} seeds into {out}")


if __name__ == "__main__":
    main()
