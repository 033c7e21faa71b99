/* The Hermite solution sets of fixed random problems, for `make hermite-sets OLD=<rev>`
 * (bench/sets/compare_sets.py compares two builds' dumps): every speed change to the
 * Hermite solver must keep every solution (issue 16). Eight sets of 1000 problems, by
 * tension and by length, in the ranges the bench uses and at their edges (low and high
 * tension, nearly collinear tangents, short and long lengths). One line per problem,
 *   P set index rc count unrepresentable
 * then one per solution, in units of |p1 - p0| (d):
 *   S L/d sigma d^2 kappa0 d kappa1 d energy d npieces
 * (a chain's pieces are the same curve however its phases are split). */
#include "elastica.h"
#include <math.h>
#include <stdio.h>

static double uni(unsigned long long *s, double lo, double hi)
{
    unsigned long long x = *s;
    x ^= x << 13; x ^= x >> 7; x ^= x << 17;
    *s = x;
    return lo + (hi - lo) * (double)(x >> 11) / 9007199254740992.0;
}

enum { PER_SET = 1000 };

/* Set `set`'s problem: p1 (|p1| in [0.5, 2]), tangents, mode and sigma or length. */
static void draw(int set, unsigned long long *s, double p1[2], double t0[2], double t1[2],
                 el_hermite_options *o)
{
    const double pi = 3.14159265358979324;
    const double d = uni(s, 0.5, 2.0), c = uni(s, -pi, pi);
    p1[0] = d * cos(c);
    p1[1] = d * sin(c);
    double a = uni(s, -pi, pi), b = uni(s, -pi, pi);
    if (set == 3 || set == 7) {   /* nearly collinear with the chord: aligned or opposite */
        const double off = pow(10.0, uni(s, -8.0, -2.0));
        a = c + off * (uni(s, -1, 1) < 0 ? -1 : 1);
        b = c + (set == 7 && uni(s, -1, 1) < 0 ? pi : 0.0) + off * uni(s, -1, 1);
    }
    t0[0] = cos(a); t0[1] = sin(a);
    t1[0] = cos(b); t1[1] = sin(b);
    el_hermite_options_defaults(o);
    const double d2 = d * d;
    switch (set) {
    case 0: o->sigma = uni(s, -10, 40) / d2; break;                    /* the bench's */
    case 1: o->sigma = uni(s, 0, 5) / d2; break;                       /* low tension */
    case 2: o->sigma = pow(10.0, uni(s, log10(40.0), 4.0)) / d2; break; /* high tension */
    case 3: o->sigma = uni(s, -10, 100) / d2; break;                   /* near collinear */
    default:
        o->mode = EL_HERMITE_LENGTH;
        o->length = d * (set == 4 ? uni(s, 1.05, 3.0) : set == 5 ? 1.0 + pow(10.0, uni(s, -3.0, log10(0.05)))
                         : set == 6 ? uni(s, 3.0, 8.0) : uni(s, 1.01, 3.0));
    }
}

int main(void)
{
    for (int set = 0; set < 8; set++) {
        unsigned long long s = 1000003ULL * (unsigned long long)(set + 1);
        for (int i = 0; i < PER_SET; i++) {
            const double p0[2] = {0, 0};
            double p1[2], t0[2], t1[2];
            el_hermite_options o;
            draw(set, &s, p1, t0, t1, &o);
            const double d = hypot(p1[0], p1[1]);
            el_hermite_result r;
            const int rc = el_hermite_solve(p0, t0, p1, t1, &o, &r);
            printf("P %d %d %d %zu %zu\n", set, i, rc, rc ? (size_t)0 : r.count, rc ? (size_t)0 : r.unrepresentable);
            if (rc) continue;
            for (size_t j = 0; j < r.count; j++) {
                const el_hermite_solution *h = &r.solutions[j];
                printf("S %.17g %.17g %.17g %.17g %.17g %d\n", h->length / d, h->sigma * d * d,
                       h->kappa0 * d, h->kappa1 * d, h->energy * d, h->npieces);
            }
            el_hermite_result_free(&r);
        }
    }
    return 0;
}
