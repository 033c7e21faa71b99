"""One object of every class of the binding that pickles (test_portable_pickle.py builds
them in this Python; the other Python loads its pickle and writes it back)."""
import numpy as np

import libelastica as el

CURVE = el.SmoothElastica(x0=0, y0=0, phi=0.2, mu=1.0, k=0.8, q=0.0, length=8.0)


def objects():
    P = CURVE.points(60) + np.random.default_rng(3).normal(0, 0.02, (60, 2))
    xyz = np.c_[P, 0.1 * P[:, 0]]
    chain = el.hermite((0, 0), (1, 0), (1, 0.2), (1, 0.1), tension=1500.0)
    # (numpy values in a result's dict too)
    held = el.fit(P, model="smooth", constraints={"start_point": np.zeros(2),
                                                  "start_tangent": np.float64(0.2)})
    corner = np.r_[np.c_[np.linspace(0, 5, 30), np.zeros(30)],
                   np.c_[np.full(30, 5.0), np.linspace(0.2, 5, 30)]]
    return {
        "FitResult": el.fit(P, model="smooth"), "discrete": el.fit(P), "held": held,
        "curve order": el.fit(P[::-1][np.r_[1, 0, 2:60]], order="curve"),
        "SmoothElastica": CURVE, "DiscreteElastica": el.fit(P).curve,
        "ElasticSpline": el.elastic_spline(P[::8], tension=0.5),
        "BSpline": CURVE.to_bspline(), "HermiteSolutions": chain,
        "HermiteChain": next(c for c in chain if isinstance(c, el.HermiteChain)),
        "KeylineFit": el.fit_keyline(np.c_[np.linspace(0, 10, 80),
                                           np.sin(np.linspace(0, 6, 80))]),
        "G2Quadratic": el.g2_quadratic(CURVE, 12),
        "BlendCurve": el.blend_curve([(0, 0), (0.3, 0.8), (0.7, 0.9), (1, 0)]),
        "EllipticBlend": el.EllipticBlend(k=0.3), "MQBlend": el.MQBlend(c=0.5),
        "Ordering": el.out_of_order(P[np.random.default_rng(4).permutation(60)]),
        "Frame": el.plane_fit(xyz)[1], "Frame2D": el.pca_normalize(P)[1],
        "AffinePolyline": el.affine_polyline(CURVE, 30),
        "OsculatingConics": el.osculating_conics(np.c_[2 * np.cos(np.linspace(0, 5, 12)),
                                                       np.sin(np.linspace(0, 5, 12))]),
        "ResampledFit": el.fit_resampled(P, 0.2),
        "Misfit": el.misfit(corner, el.fit(corner, model="smooth", check_misfit=False).distances),
    }
