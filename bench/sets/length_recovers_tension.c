/* The length mode against the tension mode (issue 16): every tension-mode solution of random
 * problems (sigma |p1 - p0|^2 uniform in [-10, 40] or log-uniform in [1, 1000]) whose length
 * lies in [1.01, 3] |p1 - p0| solved again by that length; prints those the length mode misses
 * (the same sigma and kappa0) and their count. A second check beside make hermite-sets: a
 * looser trace corrector kept every solution of the sets but missed 4 more of the 138 304
 * solutions of seeds 31337, 777 and 4242 (main misses 2, problems 2947 and 9031 of seed 777).
 * make length-recovers runs it on those three seeds; by hand: build/length-recovers GRID PROBLEMS
 * [SEED] (6 20000 31337: about 25 s). */
#include "elastica.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
static double uni(unsigned long long *s, double lo, double hi)
{
    unsigned long long x = *s; x ^= x << 13; x ^= x >> 7; x ^= x << 17; *s = x;
    return lo + (hi - lo) * (double)(x >> 11) / 9007199254740992.0;
}
int main(int argc, char **argv)
{
    const int g = atoi(argv[1]), N = atoi(argv[2]);
    unsigned long long s = argc > 3 ? strtoull(argv[3], 0, 10) : 31337;
    size_t n = 0, miss = 0;
    const double pi = 3.14159265358979324;
    for (int i = 0; i < N; i++) {
        const double p0[2] = {0, 0}, c = uni(&s, -pi, pi), p1[2] = {cos(c), sin(c)};
        const double a = uni(&s, -pi, pi), b = uni(&s, -pi, pi);
        const double t0[2] = {cos(a), sin(a)}, t1[2] = {cos(b), sin(b)};
        el_hermite_options o; el_hermite_options_defaults(&o);
        o.sigma = i % 2 ? uni(&s, -10, 40) : pow(10.0, uni(&s, 0, 3));
        el_hermite_result r;
        if (el_hermite_solve(p0, t0, p1, t1, &o, &r)) continue;
        for (size_t j = 0; j < r.count; j++) {
            const el_hermite_solution *q = &r.solutions[j];
            if (!(q->length >= 1.01 && q->length <= 3.0)) continue;
            n++;
            el_hermite_options ol; el_hermite_options_defaults(&ol);
            ol.mode = EL_HERMITE_LENGTH; ol.length = q->length; ol.grid = g;
            el_hermite_result rl;
            int found = 0;
            if (el_hermite_solve(p0, t0, p1, t1, &ol, &rl) == EL_OK) {
                for (size_t k = 0; k < rl.count; k++)
                    found |= fabs(rl.solutions[k].sigma - q->sigma) <= 1e-6 * (1 + fabs(q->sigma)) &&
                             fabs(rl.solutions[k].kappa0 - q->kappa0) <= 1e-5 * (1 + fabs(q->kappa0));
                el_hermite_result_free(&rl);
            }
            if (!found) { miss++; printf("miss: problem %d c %.17g a %.17g b %.17g L %.17g sigma %.17g kappa0 %.17g\n", i, c, a, b, q->length, q->sigma, q->kappa0); }
        }
        el_hermite_result_free(&r);
    }
    printf("grid %d: %zu tension solutions, %zu missed by length\n", g, n, miss);
    return 0;
}
