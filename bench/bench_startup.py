"""Start-up of the command line: `python -m libelastica --help` in a fresh process,
as a Makefile or a shell loop running `elastica` pays it on every call. Against the
same with the header parsed at start (the library seen through a folder without the
build's pre-parsed declarations, libelastica/_cdef.py) and against numpy's import
alone (the floor: the binding needs numpy). The three are run in turn, ROUNDS times,
so machine load hits them alike; wall time of the whole process, medians and ranges.
Byte code is cached (in a temporary folder) as an installed package's is.
One JSON line; "readme"/"value" mark the README's figure."""
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROUNDS = 15


def wall_ms(cmd, env) -> float:
    t = time.perf_counter()
    subprocess.run(cmd, env=env, check=True, stdout=subprocess.DEVNULL)
    return 1e3 * (time.perf_counter() - t)


def main() -> None:
    from libelastica import _ffi          # the library make bench names, as the CLI finds it
    if _ffi._LIBRARY is None:
        sys.exit("bench_startup: name the library's file (LIBELASTICA_PATH, as make bench does)")
    with tempfile.TemporaryDirectory(prefix="bench-startup-") as tmp:
        bare = Path(tmp) / "bare"
        bare.mkdir()
        (bare / "libelastica.so").symlink_to(Path(_ffi._LIBRARY).resolve())
        env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
        env.update(PYTHONPYCACHEPREFIX=str(Path(tmp) / "pyc"), LIBELASTICA_PATH=_ffi._LIBRARY)
        cli = [sys.executable, "-m", "libelastica", "--help"]
        runs = {"cli": (cli, env), "parsed": (cli, dict(env, LIBELASTICA_PATH=str(bare / "libelastica.so"))),
                "numpy": ([sys.executable, "-c", "import numpy"], env)}
        times = {k: [] for k in runs}
        for k, (cmd, e) in runs.items():          # warm-up: byte code written
            wall_ms(cmd, e)
        for r in range(ROUNDS):
            keys = list(runs)[r % 3:] + list(runs)[:r % 3]
            for k in keys:
                times[k].append(wall_ms(*runs[k]))
    med = {k: statistics.median(v) for k, v in times.items()}
    rng = {k: [round(min(v), 1), round(max(v), 1)] for k, v in times.items()}
    print(json.dumps({"bench": "cli_startup", "rounds": ROUNDS, "median_ms": round(med["cli"], 1),
                      "range_ms": rng["cli"], "parsed_median_ms": round(med["parsed"], 1),
                      "parsed_range_ms": rng["parsed"], "numpy_median_ms": round(med["numpy"], 1),
                      "numpy_range_ms": rng["numpy"],
                      "readme": "start-up of `elastica --help` (`python -m libelastica`, a fresh process)",
                      "value": f"{med['cli']:.0f} ms ({rng['cli'][0]:.0f}-{rng['cli'][1]:.0f}; header "
                               f"parsed at start {med['parsed']:.0f} ms, numpy's import alone "
                               f"{med['numpy']:.0f} ms; medians of {ROUNDS})"}))


if __name__ == "__main__":
    main()
