"""freecadcmd -t tests: the G2 quadratic's searches for a count that builds or covers the
source (g2quad_core, _more_edges: el.covering_edges, every count n+1 .. 4n, each sampled anew
and built) stop after SEARCH_SAMPLES samples of the source and say so, the feature made in
error with its Edges to edit: a recompute of a hand-drawn source ran past 500 s (revR). The
work is counted (samples taken), not timed; the limit is lowered here so QA gui F2's
jittered oval, which builds from Edges = 25 on, stops first."""
import elastica_samples as S
from freecad.elastica import g2quad as Q
from test_elastica_g2quad_more_edges import jittered_spline


class _Sampled:
    """The samples g2quad takes (sources.sample_chain's n) while active."""

    def __enter__(self):
        self.taken, self.saved = 0, Q.sample_chain

        def sample(edges, n):
            self.taken += n
            return self.saved(edges, n)
        Q.sample_chain = sample
        return self

    def __exit__(self, *exc):
        Q.sample_chain = self.saved


class G2QuadSearchBoundTest(S.DocTest):
    doc_name = "ElasticaG2QuadSearchBound"

    def test_a_search_past_its_samples_stops_and_says_so(self):
        s = jittered_spline(self)
        q = Q.make(self.doc, [(s, [])], Edges=24)
        saved = Q.SEARCH_SAMPLES
        Q.SEARCH_SAMPLES = Q.SAMPLES_PER_VERTEX * 24      # less than Edges = 25 takes
        try:
            with _Sampled() as work:
                self.doc.recompute()
        finally:
            Q.SEARCH_SAMPLES = saved
        self.assertIn("Invalid", q.State)
        self.assertIn("the search stopped at Edges = 25 (", q.Status)
        self.assertTrue(q.Status.endswith("type Edges = 25 or more"), q.Status)
        self.assertNotIn("no count from", q.Status)   # none tried
        # the build at 24 and the top count's (96), nothing of the search
        self.assertLessEqual(work.taken, Q.SAMPLES_PER_VERTEX * (24 + 96) + 2)
        q.touch()
        with _Sampled() as work:      # the search as before, within its samples
            self.doc.recompute()
        self.assertRegex(q.Status, r"Edges = \d+ builds it$")
        self.assertLessEqual(work.taken, Q.SAMPLES_PER_VERTEX * (24 + 96) + Q.SEARCH_SAMPLES + 2)


if __name__ == "__main__":
    import unittest
    unittest.main()
