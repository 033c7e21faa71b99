"""Points end where they start (a closed wire's, a closed sketch's) when their last lies
within FreeCAD's Precision.confusion() (1e-7 mm) of their first, as Part closes a wire
through them (plus 1e-9 of their extent, never less than before): one rule (geometry.ends_meet) for the Elastic spline's Closed, the elliptic
blend's repeated first point and a CSV file's closed curve. (Before, 1e-9 of the extent
(plus 1e-9 mm) for the first two, 1e-9 mm for a CSV: a square of 10 mm whose ends met to
5e-8 mm, closed for Part, was open for all three.) Run with
`freecadcmd -t test_elastica_ends_meet`."""
import os
import tempfile
import unittest

import FreeCAD as App
import Part

from freecad.elastica import ellblend as Eb
from freecad.elastica import sources as So
from freecad.elastica import spline as Sp
from freecad.elastica.geometry import ends_meet

V = App.Vector
CONFUSION = Part.Precision.confusion()


def square(size, gap):
    """A square of side ``size`` (mm) drawn back to its first corner, its last point ``gap``
    (mm) off it."""
    return [V(0, 0, 0), V(size, 0, 0), V(size, size, 0), V(0, size, 0), V(0, gap, 0)]


class EndsMeetTest(unittest.TestCase):

    def test_ends_meet_where_part_closes_the_wire(self):
        for gap in (0.0, 0.5 * CONFUSION, 0.9 * CONFUSION):
            pts = square(10.0, gap)
            self.assertTrue(Part.makePolygon(pts).isClosed(), gap)
            self.assertTrue(ends_meet(pts), gap)
        pts = square(10.0, 3 * CONFUSION)
        self.assertFalse(Part.makePolygon(pts).isClosed())
        self.assertFalse(ends_meet(pts))
        # never less than the 1e-9 of the extent two points coincide to (the blend's pairs):
        # a 2 m square's ends 1.5e-6 mm apart meet, as they did before
        self.assertTrue(ends_meet(square(2000.0, 1.5e-6)))
        self.assertFalse(ends_meet(square(2000.0, 1e-5)))
        self.assertFalse(ends_meet([V(1, 2, 3), V(1, 2, 3)]))      # two points: no curve

    def test_the_spline_blend_and_csv_close_within_confusion(self):
        pts = square(10.0, 0.5 * CONFUSION)
        self.assertTrue(Sp.ends_at_start(pts))
        r = Sp.spline_core(pts, closed=True)
        self.assertEqual(len(r["spline"].pieces), 4)       # the repeated first point dropped
        self.assertEqual(len(Eb._check_points(pts, "interpolate", True)), 4)
        fd, path = tempfile.mkstemp(suffix=".csv")
        try:
            with os.fdopen(fd, "w") as f:
                f.write("x,y,z\n" + "".join(f"{p.x!r},{p.y!r},{p.z!r}\n" for p in pts))
            closed = So.gather_points([], path)[3]
        finally:
            os.remove(path)
        self.assertTrue(closed)


if __name__ == "__main__":
    unittest.main()
