/* The fit's first-order certificates (fit_lm.c): el__fit_first_order, and
 * el__fit_first_order_rows on the tangent space of met constraint rows, against a linear
 * least-squares problem whose constrained minimum GSL computes independently (null space of
 * the rows by QR, the reduced problem by gsl_multifit_linear): certified there, and not
 * certified where a step along the rows' tangent space would still lower f by 1e-10 of itself
 * (the certificate's measure: twice that decrease, against tol 2f). */
#include "testutil.h"
#include "fit_internal.h"
#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_multifit.h>
#include <string.h>

enum { NR = 20, NX = 5 };

/* f, g and H (fit_value's scaling: f = |r|^2 / 2n, g = J^T r / n, H = J^T J / n) of the
 * residuals r = J x - b at x. */
static void value_at(const double *J, const double *b, const double *x, fit_value *v)
{
    double r[NR];
    memset(v, 0, sizeof *v);
    for (int i = 0; i < NR; i++) {
        r[i] = -b[i];
        for (int j = 0; j < NX; j++) r[i] += J[i * NX + j] * x[j];
        v->f += r[i] * r[i] / (2.0 * NR);
    }
    for (int j = 0; j < NX; j++)
        for (int i = 0; i < NR; i++) {
            v->g[j] += J[i * NX + j] * r[i] / NR;
            for (int l = 0; l <= j; l++) v->H[j * NX + l] += J[i * NX + j] * J[i * NX + l] / NR;
        }
}

START_TEST(test_certificate_on_the_rows_tangent_space)
{
    gsl_set_error_handler_off();
    unsigned long long st = 11;
    for (int trial = 0; trial < 50; trial++) {
        const int m = trial % 4;     /* 0 rows: el__fit_first_order's verdict too */
        double J[NR * NX], b[NR], A[FIT_NCON * NX], c[FIT_NCON];
        for (int i = 0; i < NR * NX; i++) J[i] = test_normal(&st);
        for (int i = 0; i < NR; i++) b[i] = test_normal(&st);
        for (int i = 0; i < m * NX; i++) A[i] = test_normal(&st);
        for (int i = 0; i < m; i++) c[i] = test_normal(&st);
        /* A^T = Q R: the last NX - m columns of Q span the null space Z of A; the particular
         * solution x_p = Q1 R1^-T c */
        gsl_matrix *At = gsl_matrix_alloc(NX, m ? m : 1), *Q = gsl_matrix_alloc(NX, NX), *R = gsl_matrix_alloc(NX, m ? m : 1);
        gsl_vector *tau = gsl_vector_alloc(m ? m : 1);
        double xp[NX] = {0};
        gsl_matrix_set_identity(Q);
        if (m) {
            for (int i = 0; i < m; i++)
                for (int j = 0; j < NX; j++) gsl_matrix_set(At, j, i, A[i * NX + j]);
            ck_assert_int_eq(gsl_linalg_QR_decomp(At, tau), GSL_SUCCESS);
            ck_assert_int_eq(gsl_linalg_QR_unpack(At, tau, Q, R), GSL_SUCCESS);
            double w[FIT_NCON];
            for (int i = 0; i < m; i++) {        /* R1^T w = c, forward */
                double s = c[i];
                for (int l = 0; l < i; l++) s -= gsl_matrix_get(R, l, i) * w[l];
                w[i] = s / gsl_matrix_get(R, i, i);
            }
            for (int j = 0; j < NX; j++)
                for (int i = 0; i < m; i++) xp[j] += gsl_matrix_get(Q, j, i) * w[i];
        }
        const int nz = NX - m;
        /* min |J (x_p + Z y) - b| over y */
        gsl_matrix *JZ = gsl_matrix_alloc(NR, nz), *cov = gsl_matrix_alloc(nz, nz);
        gsl_vector *rhs = gsl_vector_alloc(NR), *y = gsl_vector_alloc(nz);
        gsl_multifit_linear_workspace *ws = gsl_multifit_linear_alloc(NR, nz);
        for (int i = 0; i < NR; i++) {
            double jx = 0.0;
            for (int j = 0; j < NX; j++) jx += J[i * NX + j] * xp[j];
            gsl_vector_set(rhs, i, b[i] - jx);
            for (int k = 0; k < nz; k++) {
                double s = 0.0;
                for (int j = 0; j < NX; j++) s += J[i * NX + j] * gsl_matrix_get(Q, j, m + k);
                gsl_matrix_set(JZ, i, k, s);
            }
        }
        double chisq;
        ck_assert_int_eq(gsl_multifit_linear(JZ, rhs, y, cov, &chisq, ws), GSL_SUCCESS);
        double x[NX], z[NX], w[NX];
        for (int k = 0; k < nz; k++) w[k] = test_normal(&st);
        for (int j = 0; j < NX; j++) {
            x[j] = xp[j];
            z[j] = 0.0;
            for (int k = 0; k < nz; k++) {
                x[j] += gsl_matrix_get(Q, j, m + k) * gsl_vector_get(y, k);
                z[j] += gsl_matrix_get(Q, j, m + k) * w[k];   /* a tangent direction, A z = 0 */
            }
        }
        fit_value v;
        value_at(J, b, x, &v);
        ck_assert_msg(el__fit_first_order_rows(&v, A, m, NX, 1e-13), "trial %d m %d: minimum not certified", trial, m);
        if (m == 0) ck_assert(el__fit_first_order(&v, NX, 1e-13));
        /* x + t z: reduced gradient t Z^T H z, so twice the decrease of the tangent step is
         * t^2 z^T H z (H's quadratic form, the reduced Hessian's on Z's coordinates) */
        double zHz = 0.0;
        for (int j = 0; j < NX; j++)
            for (int l = 0; l < NX; l++) zHz += z[j] * v.H[j >= l ? j * NX + l : l * NX + j] * z[l];
        const double t = sqrt(1e-10 * 2.0 * v.f / zHz);
        double xt[NX];
        for (int j = 0; j < NX; j++) xt[j] = x[j] + t * z[j];
        value_at(J, b, xt, &v);
        ck_assert_msg(!el__fit_first_order_rows(&v, A, m, NX, 1e-13), "trial %d m %d: a 1e-10 decrease certified", trial, m);
        ck_assert_msg(el__fit_first_order_rows(&v, A, m, NX, 1.01e-10) &&
                      !el__fit_first_order_rows(&v, A, m, NX, 1e-10 * 0.99),
                      "trial %d m %d: the measure is not twice the tangent step's decrease", trial, m);
        if (m == 0) ck_assert(!el__fit_first_order(&v, NX, 1e-13) && el__fit_first_order(&v, NX, 1.01e-10));
        gsl_multifit_linear_free(ws);
        gsl_vector_free(y); gsl_vector_free(rhs); gsl_vector_free(tau);
        gsl_matrix_free(JZ); gsl_matrix_free(cov); gsl_matrix_free(At); gsl_matrix_free(Q); gsl_matrix_free(R);
    }
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("fit_certificate");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, test_certificate_on_the_rows_tangent_space);
    suite_add_tcase(s, tc);
    return s;
}

int main(void) { return test_run_suite(suite()); }
