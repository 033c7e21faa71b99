"""freecadcmd -t tests of a spline the solver's work budget stopped (the binding's
NotConvergedError.stopped, el_spline_result's stopped): the feature makes no further solve
after it (each a call with a budget of its own: G2 hints, the tangent-only retry) and says to
raise MaxIter, not that the G2 end fails (revF 3)."""
import unittest

from freecad.elastica import spline as Sp

# the fuzz's el_spline_to_bspline hang 9291f637 (tests/c/test_spline_work.c's
# one_budget_for_the_whole_call): 7 scattered points, tension 49.5, a G2 start and a tangent
# end; the call stops at its budget, 96 000 evaluations (~1.3 s)
XY = [(-3.1804379339284354, 0.96238651102464345), (8.0825513084611273, 7.2494087129015021),
      (-7.4218356603341729, -1.8420038809568717e-66), (6.2831853071795862, -4.8229190508888378),
      (-2.9130998702983142, -1.0), (4.9406564584124654e-324, 8.9568932631418328),
      (-1.7457109983782794e-143, -6.3640802624551771)]
START = {"tangent": (-0.91366445410849162, 0.99597161821927216), "curvature": 1.2866102082856488}
END = (4.7414358739604783, -0.83196765087357893)


class SplineBudgetTest(unittest.TestCase):
    def test_a_stopped_solve_is_not_retried_and_says_raise_maxiter(self):
        calls = []
        libelastica = Sp.el()
        solve = libelastica.elastic_spline

        def counted(*args, **kwargs):
            calls.append(kwargs)
            return solve(*args, **kwargs)

        libelastica.elastic_spline = counted
        try:
            with self.assertRaises(Sp.NoSpline) as ctx:
                Sp._solve(XY, "tension", 49.549858854047457, False, START, END)
        finally:
            libelastica.elastic_spline = solve
        msg = str(ctx.exception)
        # before: 2 solves more (the tangent-only retry, each with a full budget) and "no
        # equilibrium with this G2 end"
        self.assertEqual(len(calls), 1, calls)
        self.assertIn("work budget", msg)
        self.assertIn("raise MaxIter", msg)
        self.assertNotIn("G2 end", msg)
