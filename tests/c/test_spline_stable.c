/* The free batten (tension 0) that is an equilibrium but no minimum (spline_stable.c):
 * EL_EDOM with el_spline_result's slides and the span that slides; stable ones as before. */
#include "spline_check.h"
#include <gsl/gsl_eigen.h>
#include <stdint.h>
#include <stdio.h>

/* 5 ducks: two along +x, a tip at (10, 0), then two going back at deg degrees from the
 * incoming direction (QA19's sweep) */
static void turn(double deg, double xy[10])
{
    const double t = deg * M_PI / 180.0, d[2] = {cos(t), sin(t)};
    const double p[10] = {0, 0, 5, 0, 10, 0, 10 + 4.5 * d[0], 4.5 * d[1], 10 + 9.5 * d[0], 9.5 * d[1] + 0.5};
    memcpy(xy, p, sizeof p);
}

static el_spline_options free_batten(void)
{
    el_spline_options o;
    el_spline_options_defaults(&o);
    o.sigma = 0.0;
    return o;
}

/* QA19 W2: 5 ducks turning 170 deg were returned EL_OK (E 2.2926, length 21.99), an
 * unstable equilibrium: a polyline of 40 edges per span, Newton-solved beside it, has one
 * negative eigenvalue of its reduced Hessian (-0.0233) and a minimiser from it slides the
 * span from the tip (point 2) to point 3 off to length 1.2e7; likewise the same layout
 * turning 160 .. 172 deg (163 .. 172 returned EL_OK before). */
START_TEST(unstable_free_batten_slides_off)
{
    const double sharp[10] = {0, 0, 5, 0, 10, 0.3, 5.5, 1.2, 0.5, 1.6};
    const double deg[] = {160, 163, 165, 167, 169, 170, 172};
    el_spline_options o = free_batten();
    for (int c = 0; c < 8; c++) {
        double xy[10];
        if (c == 0) memcpy(xy, sharp, sizeof xy); else turn(deg[c - 1], xy);
        el_spline_result r;
        ck_assert_msg(el_spline_solve(xy, 5, &o, &r) == EL_EDOM, "case %d", c);
        ck_assert_int_eq(r.slides, 1);
        ck_assert_uint_eq(r.slide_span, 2);
        ck_assert_uint_eq(r.npieces, 0);
        ck_assert_ptr_null(r.pieces);
        el_spline_result_free(&r);
    }
}
END_TEST

/* QA19's controls, whose polylines have no negative eigenvalue (smallest 0.124, 0.090,
 * 0.043, 0.053, 0.25): solved, G2 at every duck, slides 0 */
START_TEST(stable_free_battens_are_solved)
{
    const double irregular[10] = {0, 0, 3.1, 1.2, 7.9, 1.6, 10.2, 0.4, 15.0, -1.9};
    const double t120[10] = {0, 0, 5, 0, 9, 1.5, 8, 5, 6, 9};
    const double t150[10] = {0, 0, 5, 0, 9.5, 1.0, 6.5, 3.5, 2.5, 5.5};
    const double zigzag[12] = {0, 0, 1, 1, 2, 0, 3, 1, 4, 0, 5, 1};
    const double *xy[4] = {irregular, t120, t150, zigzag};
    const size_t n[4] = {5, 5, 5, 6};
    el_spline_options o = free_batten();
    for (int c = 0; c < 4; c++) {
        el_spline_result r;
        ck_assert_msg(el_spline_solve(xy[c], n[c], &o, &r) == EL_OK, "case %d", c);
        ck_assert_int_eq(r.slides, 0);
        ck_assert_int_eq(r.loops, 0);
        check_spline(xy[c], n[c], &o, &r, 1e-9);
        el_spline_result_free(&r);
    }
}
END_TEST

/* A tension > 0 is not judged (the message's advice): the 170-deg ducks solve at sigma 0.3,
 * slides 0 (a minimum there: its reduced Hessian positive definite, by spline_stable.c's
 * test run at that tension) */
START_TEST(a_tension_is_not_judged)
{
    const double sharp[10] = {0, 0, 5, 0, 10, 0.3, 5.5, 1.2, 0.5, 1.6};
    el_spline_options o = free_batten();
    o.sigma = 0.3;
    el_spline_result r;
    ck_assert_int_eq(el_spline_solve(sharp, 5, &o, &r), EL_OK);
    ck_assert_int_eq(r.slides, 0);
    check_spline(sharp, 5, &o, &r, 1e-9);
    el_spline_result_free(&r);
}
END_TEST

/* The open chain through the n <= 8 points xy at tension sigma (internal units, the mean
 * chord 1), natural ends, solved (as test_spline_g2's bend_parameter_column test builds one) */
static void solved_chain(el__spchain *w, const double *xy, size_t n, double sigma)
{
    const size_t m = n - 1;
    memset(w, 0, sizeof *w);
    ck_assert_int_eq(el__chain_alloc(w, n, m), EL_OK);
    const double S = polygon_length(xy, n) / (double)m;
    w->tol = 1e-12; w->max_iter = 200; w->aim = 1e-14; w->sigma = sigma;
    for (size_t j = 0; j < m; j++) {
        el__spiece *pc = &w->pc[j];
        pc->dx = (xy[2 * j + 2] - xy[2 * j]) / S;
        pc->dy = (xy[2 * j + 3] - xy[2 * j + 1]) / S;
        pc->h = hypot(pc->dx, pc->dy);
    }
    for (size_t i = 0; i < n; i++) {
        w->ell[i] = 0.5 * (w->pc[i > 0 ? i - 1 : 0].h + w->pc[i < m ? i : m - 1].h);
        w->slot[i] = EL__SLOT_ANGLE;
    }
    el__chain_start_angles(w);
    ck_assert_int_eq(el__chain_start_pieces(w), EL_OK);
    ck_assert_int_eq(el__chain_newton(w, 200, w->aim, w->tol), EL_OK);
}

/* E(theta) = sum_j E_j + sigma L_j, each piece re-solved for the knot angles x */
static double chain_energy_at(el__spchain *w, const double *x, const double *v0)
{
    double E = 0.0;
    memcpy(w->x, x, w->n * sizeof *x);
    for (size_t j = 0; j < w->m; j++) {
        el__spiece *pc = &w->pc[j];
        memcpy(pc->v, v0 + EL__NV * j, sizeof pc->v);
        el__sptargets t;
        el__chain_targets(w, j, &t);
        ck_assert_int_eq(el__spiece_newton(pc, &t, 1e-14), EL_OK);
        E += pc->energy + w->sigma * pc->v[EL__SP_L];
    }
    return E;
}

/*
 * el__spline_hessian is the Hessian of E(theta) = sum_j integral kappa^2 + sigma ds of the
 * spans' Hermite elasticae in the knot angles: against its central second differences at
 * step e = 1e-4 (each span re-solved by el__spiece_newton to 1e-14), whose truncation
 * (e^2 E^(4) / 6 ~ 1e-8 |H|) and rounding (eps E / e^2 ~ 1e-7) errors lie far below
 * 1e-5 max |H| (measured: 4e-8 of it). The 150-deg turn and the irregular ducks (stable) and
 * the sharp 170-deg ducks (unstable, QA19 W2) at tension 0, the sharp ones at sigma 0.3 too.
 * The least eigenvalue (GSL's symmetric eigensolver on the dense H): negative for the sharp
 * free batten only.
 */
START_TEST(hessian_is_the_second_difference_of_the_energy)
{
    const double sharp[10] = {0, 0, 5, 0, 10, 0.3, 5.5, 1.2, 0.5, 1.6};
    const double t150[10] = {0, 0, 5, 0, 9.5, 1.0, 6.5, 3.5, 2.5, 5.5};
    const double irregular[10] = {0, 0, 3.1, 1.2, 7.9, 1.6, 10.2, 0.4, 15.0, -1.9};
    const double *xy[4] = {t150, irregular, sharp, sharp};
    const double sigma[4] = {0.0, 0.0, 0.0, 0.3};
    const int unstable[4] = {0, 0, 1, 0};
    const size_t n = 5;
    for (int c = 0; c < 4; c++) {
        el__spchain w;
        solved_chain(&w, xy[c], n, sigma[c]);
        ck_assert(isfinite(el__chain_eval(&w, 1)));
        el__spline_hessian(&w);
        double x0[5], v0[EL__NV * 4], H[25];
        memcpy(x0, w.x, sizeof x0);
        for (size_t j = 0; j < w.m; j++) memcpy(v0 + EL__NV * j, w.pc[j].v, sizeof w.pc[j].v);
        for (size_t i = 0; i < n; i++)
            for (size_t k = 0; k < n; k++)
                H[i * n + k] = i == k ? w.dg[i] : k == i + 1 ? w.up[i] : i == k + 1 ? w.up[k] : 0.0;
        const double e = 1e-4, hmax = el__max_abs(H, n * n);
        double worst = 0.0;
        for (size_t i = 0; i < n; i++)
            for (size_t k = 0; k < n; k++) {
                double f[4], x[5];
                for (int a = 0; a < 4; a++) {
                    memcpy(x, x0, sizeof x);
                    x[i] += a & 1 ? e : -e;
                    x[k] += a & 2 ? e : -e;
                    f[a] = chain_energy_at(&w, x, v0);
                }
                const double fd = (f[3] - f[2] - f[1] + f[0]) / (4.0 * e * e);
                worst = fmax(worst, fabs(fd - H[i * n + k]));
            }
        ck_assert_msg(worst <= 1e-5 * hmax, "case %d: |H - fd| %g of %g", c, worst, hmax);
        gsl_eigen_symm_workspace *ws = gsl_eigen_symm_alloc(n);
        gsl_vector *ev = gsl_vector_alloc(n);
        gsl_matrix_view Hm = gsl_matrix_view_array(H, n, n);
        ck_assert_int_eq(gsl_eigen_symm(&Hm.matrix, ev, ws), 0);
        const double lmin = gsl_vector_min(ev);
        ck_assert_msg(unstable[c] ? lmin < 0.0 : lmin > 0.0, "case %d: least eigenvalue %g", c, lmin);
        gsl_vector_free(ev);
        gsl_eigen_symm_free(ws);
        el__chain_free(&w);
    }
}
END_TEST

/*
 * el__spline_unstable reads the pieces' c0, c1, cL as the solver's last step left them
 * where they belong to the pieces' current parameters (el__chain_jac_current), and
 * evaluates the chain again where not. Solved by el__chain_newton they are current; moved
 * by each piece's own Newton to other end angles (which recomputes them there) and put back
 * as a snapshot restores them (v copied, as el__snap_load does; the knot residuals by an
 * evaluation without Jacobians), they are not, and the verdict, the span and the least
 * eigenvalue's vector are bit for bit those of a chain solved afresh: the 170-deg ducks
 * stay unstable (QA19 W2), the 150-deg turn stable.
 */
START_TEST(stale_jacobians_are_evaluated_again)
{
    const double sharp[10] = {0, 0, 5, 0, 10, 0.3, 5.5, 1.2, 0.5, 1.6};
    const double t150[10] = {0, 0, 5, 0, 9.5, 1.0, 6.5, 3.5, 2.5, 5.5};
    const double *xy[2] = {sharp, t150};
    const int unstable[2] = {1, 0};
    for (int c = 0; c < 2; c++) {
        el__spchain fresh, w;
        solved_chain(&fresh, xy[c], 5, 0.0);
        solved_chain(&w, xy[c], 5, 0.0);
        ck_assert_int_eq(el__chain_jac_current(&fresh), 1);
        size_t span0 = 99, span1 = 98;
        const int neg0 = el__spline_unstable(&fresh, &span0);
        ck_assert_int_eq(neg0 > 0, unstable[c]);
        double x0[5], v0[EL__NV * 4];
        memcpy(x0, w.x, sizeof x0);
        for (size_t j = 0; j < w.m; j++) memcpy(v0 + EL__NV * j, w.pc[j].v, sizeof w.pc[j].v);
        for (size_t i = 0; i < w.n; i++) w.x[i] += 0.05 * (double)(i + 1);
        for (size_t j = 0; j < w.m; j++) {
            el__sptargets t;
            el__chain_targets(&w, j, &t);
            ck_assert_int_eq(el__spiece_newton(&w.pc[j], &t, 1e-13), EL_OK);
        }
        memcpy(w.x, x0, sizeof x0);
        for (size_t j = 0; j < w.m; j++) memcpy(w.pc[j].v, v0 + EL__NV * j, sizeof w.pc[j].v);
        ck_assert(isfinite(el__chain_eval(&w, 0)));
        ck_assert_int_eq(el__chain_jac_current(&w), 0);
        const int neg1 = el__spline_unstable(&w, &span1);
        ck_assert_int_eq(neg1, neg0);
        if (neg0) {
            ck_assert_uint_eq(span1, span0);
            ck_assert_uint_eq(span1, 2);
            ck_assert_mem_eq(w.z, fresh.z, w.n * sizeof *w.z);
        }
        el__chain_free(&fresh);
        el__chain_free(&w);
    }
}
END_TEST

/* uniform in [0, 1) (an LCG: the same draws on every machine) */
static double ck_urand(uint64_t *r)
{
    *r = *r * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*r >> 11) / 9007199254740992.0;
}

/* The count on the length constraint (spline_stable.c's file comment) against the bordered
 * matrix K = [H 0 g; 0 C 1; g^T 1^T 0], C = diag(1 / gamma_j), by its eigenvalues (GSL's
 * dense symmetric solver): neg(K) - 1. */
static int bordered_negatives(const double *dg, const double *up, const double *g, size_t k,
                              const double *gam, size_t m)
{
    const size_t N = k + m + 1;
    gsl_matrix *K = gsl_matrix_calloc(N, N);
    gsl_vector *ev = gsl_vector_alloc(N);
    gsl_eigen_symm_workspace *ws = gsl_eigen_symm_alloc(N);
    for (size_t i = 0; i < k; i++) {
        gsl_matrix_set(K, i, i, dg[i]);
        if (i + 1 < k) { gsl_matrix_set(K, i, i + 1, up[i]); gsl_matrix_set(K, i + 1, i, up[i]); }
        gsl_matrix_set(K, i, N - 1, g[i]);
        gsl_matrix_set(K, N - 1, i, g[i]);
    }
    for (size_t j = 0; j < m; j++) {
        gsl_matrix_set(K, k + j, k + j, 1.0 / gam[j]);
        gsl_matrix_set(K, k + j, N - 1, 1.0);
        gsl_matrix_set(K, N - 1, k + j, 1.0);
    }
    ck_assert_int_eq(gsl_eigen_symm(K, ev, ws), 0);
    int neg = 0;
    for (size_t i = 0; i < N; i++) neg += gsl_vector_get(ev, i) < 0.0;
    gsl_eigen_symm_free(ws);
    gsl_vector_free(ev);
    gsl_matrix_free(K);
    return neg - 1;
}

/* H with a tiny leading pivot (the review's H: well conditioned, det -0.91, one negative
 * eigenvalue), g = e0, spans' gamma_j 0.2 + 0.3 > 0: g^T H^{-1} g = -0.91, so gamma + g^T
 * H^{-1} g = -0.41 < 0 and the constraint lifts H's negative eigenvalue: stable. GSL's
 * non-pivoting gsl_linalg_solve_symm_tridiag (de127fd's solve) returns x = (0, 1, -0.3) with
 * status 0 (g^T x = 0: "unstable"). Then random H (leading blocks near singular among
 * them), g and gamma_j of either sign (spans past their force-free length: gamma_j < 0),
 * each count against K's. */
START_TEST(length_count_is_the_bordered_inertia)
{
    const double dg[3] = {1e-17, 1.0, 1.0}, up[2] = {1.0, 0.3}, g[3] = {1.0, 0.0, 0.0};
    const double gam[2] = {0.2, 0.3};
    ck_assert_int_eq(el__tridiag_negatives(dg, up, 0, 2, 0.0), 1);
    ck_assert_int_eq(bordered_negatives(dg, up, g, 3, gam, 2), 0);
    ck_assert_int_eq(el__spline_length_negatives(dg, up, g, 3, 1, gam, 2), 0);
    /* one span past its force-free length, H positive definite, gamma > 0: unstable by moving
     * length between the spans at fixed angles (H alone says stable) */
    const double dp[2] = {2.0, 3.0}, upp[1] = {0.5}, gp[2] = {0.3, -0.2}, gm[3] = {1.0, -0.4, 0.6};
    ck_assert_int_eq(bordered_negatives(dp, upp, gp, 2, gm, 3), 1);
    ck_assert_int_eq(el__spline_length_negatives(dp, upp, gp, 2, 0, gm, 3), 1);
    uint64_t r = 12345;
    int seen[4] = {0, 0, 0, 0};
    for (int t = 0; t < 4000; t++) {
        const size_t k = 1 + t % 9, m = k + 1;
        double d[10], u[10], b[10], c[11];
        for (size_t i = 0; i < k; i++) {
            d[i] = 4.0 * ck_urand(&r) - 1.0;
            u[i] = 2.0 * ck_urand(&r) - 1.0;
            b[i] = 2.0 * ck_urand(&r) - 1.0;
        }
        if (t % 3 == 0) d[0] = 1e-15 * (ck_urand(&r) - 0.5);   /* a tiny leading pivot */
        for (size_t j = 0; j < m; j++) c[j] = (ck_urand(&r) < 0.15 ? -1.0 : 1.0) * (0.05 + ck_urand(&r));
        const int negH = el__tridiag_negatives(d, u, 0, k - 1, 0.0);
        const int want = bordered_negatives(d, u, b, k, c, m);
        const int got = el__spline_length_negatives(d, u, b, k, negH, c, m);
        ck_assert_msg(got == want, "trial %d (k %zu): %d for %d", t, k, got, want);
        seen[want < 3 ? want : 3]++;
    }
    for (int i = 0; i < 4; i++) ck_assert_int_gt(seen[i], 0);
}
END_TEST

/* A result of another piece count than the chain's is not judged (0): w, a chain of its
 * own (the sharp free batten of 5 ducks, unstable by H), was judged in its place before. */
START_TEST(another_chains_result_is_not_judged)
{
    const double sharp[10] = {0, 0, 5, 0, 10, 0.3, 5.5, 1.2, 0.5, 1.6};
    el__spchain w;
    solved_chain(&w, sharp, 5, 0.0);
    size_t span = 99;
    ck_assert_int_gt(el__spline_unstable(&w, &span), 0);
    el_spline_options o;
    el_spline_options_defaults(&o);
    o.sigma = 1.0;
    el_spline_result r;
    ck_assert_int_eq(el_spline_solve(sharp, 4, &o, &r), EL_OK);
    ck_assert_uint_eq(r.npieces, 3);
    for (int held = 0; held < 2; held++) {
        span = 99;
        ck_assert_int_eq(el__spline_unstable_result(&w, &r, 1.0, held, &span), 0);
    }
    el_spline_result_free(&r);
    el__chain_free(&w);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("spline_stable");
    TCase *tc = tcase_create("spline_stable");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, unstable_free_batten_slides_off);
    tcase_add_test(tc, stable_free_battens_are_solved);
    tcase_add_test(tc, a_tension_is_not_judged);
    tcase_add_test(tc, hessian_is_the_second_difference_of_the_energy);
    tcase_add_test(tc, stale_jacobians_are_evaluated_again);
    tcase_add_test(tc, length_count_is_the_bordered_inertia);
    tcase_add_test(tc, another_chains_result_is_not_judged);
    suite_add_tcase(s, tc);
    return test_run_suite(s);
}
