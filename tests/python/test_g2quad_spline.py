"""G2 quadratic B-splines of an elastic spline (QA23 F10): g2_quadratic(ElasticSpline) and
`elastica g2quad spline.json` build from its pieces; a closed one closes G2 (QA25 F3)."""
import json
import warnings

import numpy as np
import pytest

import libelastica as el
from libelastica.cli import main

# a batten through 7 ducks: convex, and an S (one inflection inside a piece)
CONVEX = np.array([(0, 0), (20, 9), (45, 15), (70, 16), (95, 12), (120, 4), (135, -3)], float)
S = np.array([(0, 0), (20, 10), (40, 12), (60, 6), (80, -4), (100, -10), (120, -8)], float)


def _within(g, sp):
    """Largest distance of the G2 quadratic's splines (2000 points each) from the spline
    (a polyline of 20001 of its points, segment projection)."""
    from libelastica.report import closest_points
    src = sp.points(20001)
    worst = 0.0
    for b in g.bsplines:
        p = b(np.linspace(*b.domain, 2000))
        worst = max(worst, float(np.max(np.linalg.norm(closest_points(p, src) - p, axis=1))))
    return worst


@pytest.mark.parametrize("ducks", [CONVEX, S], ids=["convex", "S"])
def test_g2_quadratic_of_an_elastic_spline(ducks):
    """It raised "elastica_inflections: curve.k must be a real number, got None" (QA23 F10).
    Now the splines run from the spline's start to its end, split at its inflections, G2
    inside, and lie within the deviation they report of it."""
    sp = el.elastic_spline(ducks, tension=0.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", el.EndTangentWarning)
        g = el.g2_quadratic(sp, 48)
    k = sp.curvature(20001)
    flips = int(np.count_nonzero(np.diff(np.sign(k[np.abs(k) > 1e-9 * np.abs(k).max()])) != 0))
    assert len(g.bsplines) == flips + 1 and len(sp.inflections()) == flips
    assert g.covers_source and g.curvature_jump < 1e-9
    assert np.allclose(g.ends[0], sp.points(0.0), atol=1e-9 * sp.length)
    assert np.allclose(g.ends[-1], sp.points(sp.length), atol=1e-9 * sp.length)
    own = _within(g, sp)
    assert own <= 1.01 * g.deviation + 1e-9 * sp.length and g.deviation < 0.01 * sp.length


# QA25 F3's 'o' of 8 ducks, UPM 1000 (font units)
O_DUCKS = np.array([(500, 720), (680, 620), (730, 360), (640, 110), (500, 40), (330, 110),
                    (250, 360), (320, 620)], float)


def _seam(g):
    """(angle in degrees, |curvature jump| relative, gap) where the last spline's end meets
    the first's start, measured on the B-splines themselves."""
    b0, b1 = g.bsplines[0], g.bsplines[-1]
    d0, d1 = b0.derivative(b0.knots[:1])[0], b1.derivative(b1.knots[-1:])[0]
    ang = np.degrees(abs(np.arctan2(d1[0] * d0[1] - d1[1] * d0[0], d0 @ d1)))
    k0, k1 = b0.curvature(b0.knots[:1])[0], b1.curvature(b1.knots[-1:])[0]
    gap = np.linalg.norm(b0(b0.knots[:1])[0] - b1(b1.knots[-1:])[0])
    return ang, abs(k0 - k1) / abs(k0), gap


@pytest.mark.parametrize("n", [24, 32, 64, 128])
@pytest.mark.parametrize("ducks", [O_DUCKS, O_DUCKS[::-1], np.roll(O_DUCKS, 3, axis=0)],
                         ids=["o", "o reversed", "o from duck 3"])
def test_a_closed_spline_closes_g2(ducks, n):
    """QA25 F3: a closed spline was refused ("pass an open one, or its samples from a point
    of your choice"), and its samples' splines closed at a corner (4.8 deg at 24 edges, 0.62
    at 128), silently. Now it is opened at its point 0 and both ends held to the spline's
    tangent and curvature there: the outline closes on itself, to the bit, with one tangent
    and one curvature (G2), the source's, and says so (seam_angle, seam_curvature_jump)."""
    ring = el.elastic_spline(ducks, closed=True)
    with warnings.catch_warnings():
        warnings.simplefilter("error")          # nothing to warn of
        g = el.g2_quadratic(ring, n)
    ang, jump, gap = _seam(g)
    assert gap == 0.0 and np.array_equal(g.ends[0], ducks[0])
    assert ang < 1e-9 and jump < 1e-9
    assert g.seam_angle < 1e-9 and g.seam_curvature_jump < 1e-9
    k_src = ring.curvature(np.array([0.0]))[0]
    assert abs(g.bsplines[0].curvature(g.bsplines[0].knots[:1])[0] - k_src) < 1e-9 * abs(k_src)
    assert g.covers_source and g.curvature_jump < 1e-9
    assert _within(g, ring) <= 1.01 * g.deviation + 1e-9 * ring.length
    assert "where the outline closes (point 0)" in g.g2_summary() and "(G2)" in g.g2_summary()
    # open sources have no seam
    assert el.g2_quadratic(el.elastic_spline(CONVEX, tension=0.1), 24).seam_angle is None


def test_a_closed_splines_seam_corner_is_warned():
    """Where the seam cannot be held (24 edges round a 12-duck bean, inflections: its end
    pieces too short for the hold), the corner is said, with its angle: EndTangentWarning
    naming the seam, and seam_angle. (A held seam straying farther from the source is no
    longer given up: 8 edges round a 5-duck ring close G2, test_g2quad_seam.py.)"""
    t = np.linspace(0, 2 * np.pi, 13)[:-1]
    r = 20 + 7 * np.cos(2 * t)
    ring = el.elastic_spline(np.c_[r * np.cos(t), 0.7 * r * np.sin(t) + 4 * np.cos(t) ** 2],
                             closed=True)
    with pytest.warns(el.EndTangentWarning, match="where the outline closes are .* deg apart") as rec:
        g = el.g2_quadratic(ring, 24)
    seam = [m for w in rec if isinstance(w.message, el.EndTangentWarning)
            for m in w.message.misses if m[0] == "seam"]
    assert seam and seam[0][1] == g.seam_angle and np.degrees(g.seam_angle) > 1.0
    assert abs(np.degrees(g.seam_angle) - _seam(g)[0]) < 1e-9
    assert "(not G2)" in g.g2_summary()


def test_elastica_g2quad_of_a_closed_splines_json(capsys, tmp_path):
    """`elastica g2quad` of an open spline's JSON builds (it said "no elastica curve"), of
    a closed one's too (QA25 F3: it exited 2, "a closed spline has no ends"), closing G2."""
    ring = el.elastic_spline(O_DUCKS, closed=True, tension=0.0)
    for ducks, closed, said in ((CONVEX, False, "G2 quadratic B-spline: 1 inflection-free"),
                                (ring.data, True, "where the outline closes (point 0)")):
        f = tmp_path / "ducks.csv"
        np.savetxt(f, ducks, delimiter=",")
        extra = ["--closed"] if closed else []
        extra += ["--tension", "0"]
        assert main(["spline", str(f), *extra, "--json", str(tmp_path / "sp.json")]) == 0
        capsys.readouterr()
        rc = main(["g2quad", str(tmp_path / "sp.json"), "--edges", "48", "--json",
                   str(tmp_path / "g.json")])
        out, err = capsys.readouterr()
        assert rc == 0 and said in out and "warning" not in err, (out, err)
        rec = json.loads((tmp_path / "g.json").read_text())
        assert rec["covers_source"] and rec["pieces"] == 1
        if closed:
            assert rec["seam_angle_rad"] < 1e-9 and rec["seam_curvature_jump"] < 1e-9
            assert rec["ends"][0] == rec["ends"][-1]
        else:
            assert rec["seam_angle_rad"] is None


def test_repeated_points_are_named_as_the_cause():
    """Every point doubled: the DomainError listed "a straight piece, an inflection where
    none is allowed, or too few edges" (none the cause); one doubled point gave a
    CoverageError of a false inflection (QA23 F9). Now the repeats are named."""
    c = el.SmoothElastica(x0=0, y0=0, phi=0.2, mu=1.0, k=0.6, q=0.4, length=1.5)
    pts = c.points(400)
    for doubled, named in ((np.repeat(pts, 2, axis=0), "400 point(s) repeat the one before (points 1, 3, 5"),
                           (np.insert(pts, 100, pts[100], axis=0), "1 point(s) repeat the one before (points 101,")):
        with pytest.raises(el.DomainError, match=r"drop the repeats") as e:
            el.g2_quadratic(doubled, 12)
        assert named in str(e.value)


def test_exact_samples_of_a_straight_span_are_not_called_noisy():
    """Samples (1000 a piece) of a batten with a straight middle span: "the points are too
    noisy ... 848 sign changes" (QA23 F9); they change sign where the batten runs straight
    (8.5e-9 rad a step), their evaluation's rounding above its bend. Now that is said."""
    from pathlib import Path
    ducks = np.loadtxt(Path(__file__).parent.parent / "data" / "waterline_midbody40.csv",
                       delimiter=",", skiprows=1)
    sp = el.elastic_spline(ducks, tension=0.0)
    q = np.vstack([c.points(np.linspace(0, c.length, 1001))[:-1] for c in sp.pieces]
                  + [sp.points(np.array([sp.length]))])
    with pytest.raises(el.DomainError) as e:
        el.g2_quadratic(q, 96)
    said = str(e.value)
    assert "too noisy" not in said and "run (nearly) straight from point" in said
    a = int(said.split("straight from point ")[1].split()[0])
    b = int(said.split("straight from point ")[1].split()[2])
    s = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(q, axis=0).T))])
    flat = sp.curvature(s[a:b + 1])
    assert np.max(np.abs(flat)) < 1e-3 * np.max(np.abs(sp.curvature(2001)))


# QA23 F10's batten: 12 convex stations of a 100 m waterline (mm), free ends (tension 0:
# curvature 0 at both ends, a corner in its derivative at every duck)
SHIP12 = np.array([(0, 0), (7026, 2968), (14707, 4594), (23492, 5916), (33477, 6919),
                   (44378, 7474), (55622, 7474), (66523, 6919), (76508, 5916), (85293, 4594),
                   (92974, 2968), (100000, 0)], float)


@pytest.mark.parametrize("n", [24, 48, 96, 192, 250])
def test_g2_quadratic_of_a_battens_exact_samples_lands_its_end(n):
    """2001 exact samples of the batten: 24 and 192 edges raised DomainError "edges are too
    few for the points' turning" (48, 96, 250 built): psi(t1) has several near-equal minima,
    fit_ends' secant on A saw the landing miss jump over 0 as the global one changed. Now
    fit_ends follows one minimum to the landing. The splines build, end on the samples' ends,
    and lie within the deviation they report of the samples (own evaluation: 4000 points a
    spline against the sample polyline)."""
    from libelastica.report import closest_points
    sp = el.elastic_spline(SHIP12, tension=0.0)
    assert np.allclose(sp.curvature(np.array([0.0, sp.length])), 0.0, atol=1e-12)
    x = sp.points(2001)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", el.EndTangentWarning)
        g = el.g2_quadratic(x, n)
    assert g.covers_source and g.curvature_jump < 1e-9
    assert np.allclose(g.ends[0], x[0], atol=1e-9 * sp.length)
    assert np.allclose(g.ends[-1], x[-1], atol=1e-9 * sp.length)
    own = 0.0
    for b in g.bsplines:
        p = b(np.linspace(*b.domain, 4000))
        own = max(own, float(np.max(np.linalg.norm(closest_points(p, x) - p, axis=1))))
    assert own <= 1.05 * g.deviation
    # a quadratic's error falls like 1/n^2: 1e-3 of the length at 24 edges is ample
    assert g.deviation < 1e-3 * sp.length * (24.0 / n) ** 2


@pytest.mark.parametrize("nst, B2, p, M, offset, n", [
    (30, 6430.606123439048, 0.7401605542428256, 3001, (0.0, 0.0), 271),
    (40, 7389.256974654896, 0.6576043538975658, 800, (2.5e5, -1.3e5), 208)])
def test_g2_quadratic_of_a_ship_lines_samples_lands_its_end(nst, B2, p, M, offset, n):
    """A naval architect's waterline: stations of a 100 m convex line (mm, denser at the
    ends, y = B2 sin(pi x / L)^p), a batten through them (tension 0), its samples (the second
    at a big offset). g2_quadratic raised DomainError ("271 edges are too few for the points'
    turning", "208 edges, 1.09e+03 a turn ...") before fit_ends followed psi's minima through
    A (two of 4c16a92's sweep of realistic inputs, /tmp/g2land/sweep/real500.py 151, 193).
    The splines build, end on the samples' ends, lie within their reported deviation."""
    from libelastica.report import closest_points
    u = np.linspace(0.0, 1.0, nst)
    x = 1e5 * (u - 0.24 * np.sin(2 * np.pi * u) / (2 * np.pi))
    sp = el.elastic_spline(np.column_stack([x, B2 * np.sin(np.pi * x / 1e5) ** p]), tension=0.0)
    X = sp.points(M) + np.array(offset)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", el.EndTangentWarning)
        g = el.g2_quadratic(X, n)
    # relative jump: 2.5e5 mm of offset round the vertices' second differences (4.5e-9)
    assert g.covers_source and g.curvature_jump < (1e-9 if offset[0] == 0.0 else 1e-8)
    assert np.allclose(g.ends[0], X[0], rtol=0, atol=1e-9 * sp.length)
    assert np.allclose(g.ends[-1], X[-1], rtol=0, atol=1e-9 * sp.length)
    own = 0.0
    for b in g.bsplines:
        q = b(np.linspace(*b.domain, 4000))
        own = max(own, float(np.max(np.linalg.norm(closest_points(q, X) - q, axis=1))))
    assert own <= 1.05 * g.deviation
    # 1/n^2 as the batten's, 2e-3: 800 samples of 40 stations give 4 samples an edge at 208
    assert g.deviation < 2e-3 * sp.length * (24.0 / n) ** 2


# QA25 F4's S stroke of a type designer (font units), free ends: curvature 0 there
S_STROKE = np.array([(520, 700), (380, 640), (330, 520), (450, 420), (580, 320), (560, 180),
                     (420, 120), (300, 170)], float)


@pytest.mark.parametrize("n", [24, 96, 400])
def test_a_free_ends_tangent_is_held_without_a_warning(n):
    """QA25 F4: every free (natural-end) spline warned EndTangentWarning, its ends 0.147 deg
    off the source's at 24 edges (0.0022 at 400): its end curvature, 0, evaluated as
    -2.6e-18, was taken as a curvature to hold, which no G2 quadratic end meets (a straight
    end parabola makes every one straight). Now a zero end holds the tangent alone: exact
    (~1e-14 rad), no warning, G2 inside, the curvature at the ends still small."""
    sp = el.elastic_spline(S_STROKE, tension=0.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        g = el.g2_quadratic(sp, n)
    assert g.source_end_tangent_error < 1e-12 and g.curvature_jump < 1e-9
    assert g.end_curvature_error < 0.2 and g.covers_source
    th = sp.angle(np.array([0.0, sp.length]))
    for b, j, a in ((g.bsplines[0], 0, th[0]), (g.bsplines[-1], -1, th[1])):
        d = b.derivative(b.knots[[j]])[0]
        assert abs(np.angle(np.exp(1j * (np.arctan2(d[1], d[0]) - a)))) < 1e-12


@pytest.mark.parametrize("n", [24, 32, 64, 128])
def test_samples_of_a_closed_outline_close_g2(n):
    """QA25 F3: the 'o''s 321 samples (the last the first), no tangents, closed at a corner,
    unsaid: 4.8 deg at 24 edges, 0.62 at 128. Now both ends hold the samples' own tangent
    and curvature across the seam (cubics through the 8 samples either side): the splines
    close G2, along the source's tangent there to its estimate's accuracy."""
    ring = el.elastic_spline(O_DUCKS, closed=True)
    S = np.vstack([p.points(np.linspace(0, p.length, 41))[:-1] for p in ring.pieces] + [O_DUCKS[:1]])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        g = el.g2_quadratic(S, n)
    ang, jump, gap = _seam(g)
    assert gap == 0.0 and ang < 1e-9 and jump < 1e-9
    assert g.seam_angle < 1e-9 and g.seam_curvature_jump < 1e-9 and g.end_tangent_error is None
    d = g.bsplines[0].derivative(g.bsplines[0].knots[:1])[0]
    th = ring.angle(np.array([0.0]))[0]
    assert abs(np.degrees(np.angle(np.exp(1j * (np.arctan2(d[1], d[0]) - th))))) < 1e-3
    k = ring.curvature(np.array([0.0]))[0]
    assert abs(g.bsplines[0].curvature(g.bsplines[0].knots[:1])[0] - k) < 0.02 * abs(k)
