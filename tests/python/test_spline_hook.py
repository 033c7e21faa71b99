"""An elastic spline that hooks (a micro-loop where close points zig-zag) says so: QA gui3 G4,
a closed outline of 30 points round an egg with 0.4 mm jitter bent to radius 0.52 mm between
two points 0.66 mm apart, without crossing itself, so LoopWarning (a self-crossing) stayed
silent and FreeCAD's Elastic spline said nothing."""
import math
import warnings

import numpy as np

import libelastica as el
from libelastica.spline_hook import hook, hook_text


def _outline(jitter):
    rng = np.random.default_rng(11)
    t = np.sort(rng.uniform(0, 2 * math.pi, 30))
    xy = np.c_[150 * np.cos(t) + 0.15 * 150 * np.cos(2 * t), 90 * np.sin(t)]
    xy = xy + jitter * rng.normal(0, 0.4, (30, 2))
    xy[7] += [5, 5]
    return xy + [600, 300]


def _spline(xy):
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        sp = el.elastic_spline(xy, tension=0.0, closed=True)
    return sp, [x for x in w if issubclass(x.category, el.LoopWarning)]


def test_jittered_outline_hooks_and_says_where():
    sp, said = _spline(_outline(1.0))
    assert not sp.loops                      # no self-crossing: the old warning's blind spot
    assert len(said) == 1 and issubclass(said[0].category, el.HookWarning)
    text = str(said[0].message)
    assert "hooks between points 2 and 3" in text and "radius 0.518" in text
    j, radius, spacing = hook(sp)
    assert j == 2 and radius * el.HOOK_RATIO < spacing


def test_outline_without_jitter_does_not_hook():
    sp, said = _spline(_outline(0.0))
    assert said == [] and hook(sp) is None
    assert hook_text(sp) == ""
