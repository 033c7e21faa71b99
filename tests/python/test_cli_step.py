"""`elastica fit FILE --step S` is judged by the file's points, not by its resampled
polygon's vertices (el.fit_resampled): the rms, max error and distances it prints and
writes are the points' distances to the curve drawn, and a step that fits them far worse
than their own fit says so (el.ResampleWarning's text)."""
from __future__ import annotations

import json

import numpy as np
import pytest

import libelastica as el
from libelastica.io import bspline_from_dict

from cli_run import cli
from near_segments import candidate_segments

REF = el.SmoothElastica(x0=0, y0=0, phi=0.25, mu=1.2e-6, k=0.6, q=0.3, length=4000.0)
N = 300                 # unevenly spaced, mean spacing 13.3, noise 4


@pytest.fixture(scope="module")
def scan(tmp_path_factory):
    rng = np.random.default_rng(5)
    s = np.sort(rng.uniform(0.0, REF.length, N))
    xy = REF.points(s) + rng.normal(0.0, 4.0, (N, 2))
    path = tmp_path_factory.mktemp("step") / "scan.csv"
    np.savetxt(path, xy, delimiter=",", header="x,y", comments="")
    return path, xy


def distances_to(bspline, xy, samples=40_000):
    """Each point's distance to a B-spline, measured here: the nearest of its dense chord
    polygon (segments 0.1 long), not the library's feet (a smooth fit's own spline, which
    the CLI measures to, lies within 1e-6 of this 1e-9 one). The segments looked at are those
    that can hold the nearest point (near_segments: the same minimum as over all 40 000)."""
    t = np.linspace(*bspline.domain, samples)
    P = bspline.evaluate(t)
    A, D = P[:-1], np.diff(P, axis=0)
    dd = np.sum(D * D, axis=1)
    out = np.empty(len(xy))
    for i, (p, j) in enumerate(zip(xy, candidate_segments(xy, P))):
        a, d = A[j], D[j]
        u = np.clip(np.sum((p - a) * d, axis=1) / dd[j], 0.0, 1.0)
        out[i] = np.sqrt(np.min(np.sum((a + u[:, None] * d - p) ** 2, axis=1)))
    return out


@pytest.mark.parametrize("model", ["discrete", "smooth"])
@pytest.mark.parametrize("step", ["5", "60"])       # below the spacing, 4.5 times it
def test_step_reports_the_files_points(scan, tmp_path, capsys, model, step):
    path, xy = scan
    out = tmp_path / "fit.json"
    code, text, err = cli(capsys, "fit", path, "--step", step, "--model", model,
                          "--bspline-tol", "1e-9", "--json", out)
    assert code == 0, err
    rec = json.loads(out.read_text())
    # the curve drawn: the JSON's B-spline (a discrete fit's C2 cubic through its vertices)
    d = distances_to(bspline_from_dict(rec["bspline"]), xy)
    own_rms = float(np.sqrt(np.mean(d ** 2)))
    assert rec["rms"] == pytest.approx(own_rms, rel=1e-5)
    assert rec["max_error"] == pytest.approx(float(d.max()), rel=1e-5)
    assert len(rec["distances"]) == N and rec["n_points"] == N
    np.testing.assert_allclose(np.abs(rec["distances"]), d, rtol=1e-5, atol=1e-5)
    assert len(rec["foot_s"]) == N and "file's points" in rec["distances_of"]
    # not the polygon's vertices' (main reported those: 3.36 to 3.40 against 4.03 to 4.05)
    poly = el.resampled_polygon(xy, float(step))
    assert rec["fitted_points"] == len(poly) != N
    poly_rms = float(np.sqrt(np.mean(distances_to(bspline_from_dict(rec["bspline"]), poly) ** 2)))
    assert abs(rec["polygon_rms"] - own_rms) > 0.1 * own_rms
    assert abs(poly_rms - own_rms) > 0.1 * own_rms
    # the text says the same figure
    code, text, err = cli(capsys, "fit", path, "--step", step, "--model", model)
    line = next(ln for ln in text.splitlines() if ln.startswith("rms "))
    assert float(line.split()[1]) == pytest.approx(own_rms, rel=1e-5), text
    # and says what it is (QA13: "(point-to-curve; fitted paired distances)" at 5 and 60)
    assert "(point-to-curve: the file's points to the curve drawn)" in line, line
    assert "paired" not in line, line


def test_a_coarse_step_says_its_points_lie_far(scan, tmp_path, capsys):
    """At 600 (8 vertices) the discrete fit's cubic lies 24 from the points, 6 x their own
    smooth fit's 4.0; its polygon's vertices lie 2.9 from it (what main reported)."""
    path, xy = scan
    out = tmp_path / "fit.json"
    code, text, err = cli(capsys, "fit", path, "--step", "600", "--json", out)
    assert code == 0, err
    rec = json.loads(out.read_text())
    assert rec["rms"] > 4 * rec["resample_reference_rms"] > 4 * 3.5, rec["rms"]
    assert "resampled at 600 lies" in err and "a shorter step, or none, fits them closer" in err
    assert f"{rec['rms']:.3g} from them (rms)" in err, err
    line = next(ln for ln in cli(capsys, "fit", path, "--step", "600")[1].splitlines()
                if ln.startswith("rms "))
    assert "(point-to-curve: the file's points to the curve drawn)" in line, line
