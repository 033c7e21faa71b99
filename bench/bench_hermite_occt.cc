/* Hermite interpolation against OpenCASCADE's FairCurve_Batten (Debian
 * libocct-modeling-algorithms-dev): one free-sliding batten per problem (the
 * tension-free equilibrium, sigma = 0) against libelastica's all sigma = 0
 * solutions, on the same random problems as bench_hermite.c, timed alternately
 * in the same run. FairCurve_Batten fails by design when an end angle to the
 * chord exceeds pi/2 (its free length becomes infinite), so problems are drawn
 * with both angles within 80 degrees of the chord. The batten's length is
 * compared with libelastica's solutions to show that both solve one problem.
 * FairCurve_Batten runs with its default iteration limit and tolerance (a
 * tolerance of 1e-7 costs it about 30 % more). One JSON line per figure. */
#include "elastica.h"
#include <FairCurve_Batten.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <Geom2dAdaptor_Curve.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Standard_Failure.hxx>
#include <gp_Pnt2d.hxx>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <vector>

static double uni(unsigned long long *s, double lo, double hi)
{
    unsigned long long x = *s;
    x ^= x << 13; x ^= x >> 7; x ^= x << 17;
    *s = x;
    return lo + (hi - lo) * (double)(x >> 11) / 9007199254740992.0;
}

static double now_us()
{
    timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec * 1e6 + t.tv_nsec * 1e-3;
}

static double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return v.empty() ? NAN : v[v.size() / 2];
}

int main()
{
    const int n = 2000;
    const double lim = 80.0 * M_PI / 180.0;
    unsigned long long s = 2024;
    std::vector<double> ours, theirs;
    int converged = 0, agree = 0;
    for (int i = 0; i < n; i++) {
        const double p0[2] = {0, 0}, p1[2] = {uni(&s, -1, 1), uni(&s, -1, 1)};
        const double chord = std::atan2(p1[1], p1[0]);
        const double a1 = uni(&s, -lim, lim), a2 = uni(&s, -lim, lim);
        /* Angle1 from the chord at P1; Angle2 from the chord at P2, sign as OCCT
         * measures it (a symmetric arc has Angle1 = Angle2) */
        const double t0[2] = {std::cos(chord + a1), std::sin(chord + a1)};
        const double t1[2] = {std::cos(chord - a2), std::sin(chord - a2)};
        el_hermite_options o;
        el_hermite_options_defaults(&o);
        o.sigma = 0.0;
        el_hermite_result r;
        double t = now_us();
        const int rc = el_hermite_solve(p0, t0, p1, t1, &o, &r);
        ours.push_back(now_us() - t);

        double length = NAN;
        t = now_us();
        try {
            FairCurve_Batten b(gp_Pnt2d(p0[0], p0[1]), gp_Pnt2d(p1[0], p1[1]), 0.01);
            b.SetFreeSliding(Standard_True);
            b.SetAngle1(a1);
            b.SetAngle2(a2);
            FairCurve_AnalysisCode code;
            if (b.Compute(code) && code == FairCurve_OK) {
                theirs.push_back(now_us() - t);
                converged++;
                Geom2dAdaptor_Curve c(b.Curve());
                length = GCPnts_AbscissaPoint::Length(c);
            }
        } catch (const Standard_Failure &) {
        }
        if (rc == EL_OK) {
            for (size_t j = 0; j < r.count; j++)
                if (std::fabs(r.solutions[j].length - length) <= 1e-3 * length) { agree++; break; }
            el_hermite_result_free(&r);
        }
    }
    const double mo = median(ours), mt = median(theirs);
    std::printf("{\"bench\": \"hermite_sigma0_c\", \"problems\": %d, \"median_us\": %.1f}\n", n, mo);
    std::printf("{\"bench\": \"occt_fair_curve_batten\", \"problems\": %d, \"converged\": %d, "
                "\"length_matches_a_libelastica_solution\": %d, \"median_us\": %.1f}\n",
                n, converged, agree, mt);
    std::printf("{\"bench\": \"hermite_vs_occt_batten_ratio\", \"ratio\": %.3f, "
                "\"readme\": \"one free-sliding OpenCASCADE `FairCurve_Batten` (sigma = 0)\", "
                "\"value\": \"%.1f ms; all sigma = 0 solutions of the same problem: %.0f us, the "
                "batten among them (%d of %d)\"}\n", mo / mt, mt / 1000.0, mo, agree, converged);
    return 0;
}
