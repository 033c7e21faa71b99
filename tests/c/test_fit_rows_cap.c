/* Held fits' runs held to the kept fit's objective (el_fit_options.exhaustive = 0, the
 * default: fit_choose.c's rows_capped, fit_candidate.c's rows_halfway, fit_ipopt.c's rate
 * test at iterates near the rows) against the plain path that runs every start to its end
 * (exhaustive = 1): the same fit or a lower one, meeting the same constraints, never a
 * status the plain path does not reach. Kinds: joined G1 at both ends (smooth, discrete), G2
 * at the start and G1 at the end (smooth), pinned at both ends, the natural batten
 * (discrete); data: a noisy sine-like scan with 2-3 inflections (no elastica: the held fit
 * well above the free one, where the later starts crept), a noisy elastica scan (k 0.8,
 * inflectional) and a sparse uneven sketch of a non-inflectional one (k 1.3); at the scale
 * of the points and at 1e-6 and 1e6 of it. */
#include "testutil.h"
#include "sine_scan_held.h"
#include "hand_sketch_held.h"
#include <math.h>
#include <stdio.h>
#include <string.h>

enum { NSCAN = SINE_SCAN_N > 150 ? SINE_SCAN_N : 150, NSKETCH = 12 };

typedef struct held_data {
    double xy[2 * NSCAN];
    size_t n;
    double p0[2], p1[2], t0, t1, k0, k1;     /* the end conditions the kinds hold */
} held_data;

/* A sine-like scan: y = a sin(3 pi t + 0.2)(1 + 0.2 t) over x = 100 t, t uneven, noise
 * 0.3 (deterministic), its ends' own points, tangents and curvatures (of the sine). */
static void sine_scan(held_data *D)
{
    const double a = 12.0, w = 3.0 * M_PI, ph = 0.2;
    D->n = NSCAN;
    for (size_t i = 0; i < NSCAN; i++) {
        const double t = pow((double)i / (NSCAN - 1), 1.2);
        D->xy[2 * i] = 100.0 * t + 0.3 * sin(12.9898 * (double)i);
        D->xy[2 * i + 1] = a * sin(w * t + ph) * (1.0 + 0.2 * t) + 0.3 * cos(78.233 * (double)i);
    }
    for (int e = 0; e < 2; e++) {
        const double t = e, y = a * sin(w * t + ph) * (1.0 + 0.2 * t);
        const double dy = a * (w * cos(w * t + ph) * (1.0 + 0.2 * t) + 0.2 * sin(w * t + ph));
        const double ddy = a * (-w * w * sin(w * t + ph) * (1.0 + 0.2 * t) + 0.4 * w * cos(w * t + ph));
        double *p = e ? D->p1 : D->p0;
        p[0] = 100.0 * t;
        p[1] = y;
        *(e ? &D->t1 : &D->t0) = atan2(dy, 100.0);
        *(e ? &D->k1 : &D->k0) = 100.0 * ddy / pow(100.0 * 100.0 + dy * dy, 1.5);
    }
}

/* n points of the smooth curve c at uneven arc lengths (the ends included), noise amp
 * (deterministic); the curve's own end conditions. */
static void elastica_scan(held_data *D, const el_smooth_params *c, size_t n, double amp)
{
    double s[NSCAN] = {0.0}, th[2], ka[2], e[4];   /* (zeroed: gcc -O1 -fsanitize read n = 0 as possible) */
    D->n = n;
    for (size_t i = 0; i < n; i++) s[i] = c->length * pow((double)i / (double)(n - 1), 1.3);
    ck_assert_int_eq(el_smooth_eval(c, n, s, D->xy, NULL, NULL), EL_OK);
    for (size_t i = 1; i + 1 < n; i++) {
        D->xy[2 * i] += amp * sin(12.9898 * (double)i);
        D->xy[2 * i + 1] += amp * cos(78.233 * (double)i);
    }
    const double se[2] = {0.0, c->length};
    ck_assert_int_eq(el_smooth_eval(c, 2, se, e, th, ka), EL_OK);
    memcpy(D->p0, e, sizeof D->p0);
    memcpy(D->p1, e + 2, sizeof D->p1);
    D->t0 = th[0]; D->t1 = th[1]; D->k0 = ka[0]; D->k1 = ka[1];
}

/* D scaled by f about the origin. */
static void scaled(held_data *D, double f)
{
    for (size_t i = 0; i < 2 * D->n; i++) D->xy[i] *= f;
    for (int c = 0; c < 2; c++) { D->p0[c] *= f; D->p1[c] *= f; }
    D->k0 /= f;
    D->k1 /= f;
}

enum { G1_ENDS, G2_G1, PINNED, NATURAL };

static void kind_options(const held_data *D, int kind, int exhaustive, el_fit_options *o)
{
    el_fit_options_defaults(o);
    o->exhaustive = exhaustive;
    o->constraints = EL_CONSTRAIN_START_POINT | EL_CONSTRAIN_END_POINT;
    memcpy(o->start_point, D->p0, sizeof o->start_point);
    memcpy(o->end_point, D->p1, sizeof o->end_point);
    if (kind == G1_ENDS || kind == G2_G1) {
        o->constraints |= EL_CONSTRAIN_START_TANGENT | EL_CONSTRAIN_END_TANGENT;
        o->start_tangent = D->t0;
        o->end_tangent = D->t1;
    }
    if (kind == G2_G1) {
        o->constraints |= EL_CONSTRAIN_START_CURVATURE;
        o->start_curvature = D->k0;
    }
    if (kind == NATURAL) {
        o->constraints |= EL_CONSTRAIN_START_CURVATURE | EL_CONSTRAIN_END_CURVATURE;
        o->start_curvature = o->end_curvature = 0.0;
    }
}

/* One fit of a kind: status, rms, the constraint named, iterations. */
typedef struct fit_out { int status, constraint, iterations; double rms; } fit_out;

static fit_out fit_kind(const held_data *D, int model, int kind, int exhaustive)
{
    el_fit_options o;
    kind_options(D, kind, exhaustive, &o);
    fit_out r;
    if (model == 0) {
        el_fit_smooth_result a;
        memset(&a, 0, sizeof a);
        r.status = el_fit_smooth(D->xy, D->n, &o, NULL, &a, NULL, NULL);
        r.rms = a.rms; r.constraint = a.constraint; r.iterations = a.iterations;
    } else {
        el_fit_discrete_result a;
        memset(&a, 0, sizeof a);
        r.status = el_fit_discrete(D->xy, D->n, &o, NULL, &a, NULL, NULL);
        r.rms = a.rms; r.constraint = a.constraint; r.iterations = a.iterations;
    }
    return r;
}

/* The held fit f against the plain path's p, p's rms in the held fit's units (scale: the
 * plain fit ran on the points scaled by 1/scale): f's rms at most p's (to 1e-9 of it), its
 * status EL_OK wherever p's is, the same constraint named where neither meets them. */
static void judge(fit_out f, fit_out p, double scale, const char *what)
{
    const double rp = p.rms * scale;
    if (p.status == EL_OK) {
        ck_assert_msg(f.status == EL_OK, "%s: status %d where the plain path's is EL_OK", what, f.status);
        ck_assert_msg(f.rms <= rp * (1.0 + 1e-9), "%s: rms %.17g above the plain path's %.17g", what, f.rms, rp);
    } else if (f.status != EL_OK) {
        ck_assert_msg(f.status == p.status && f.constraint == p.constraint,
                      "%s: status %d (constraint %d), plain %d (%d)", what, f.status, f.constraint,
                      p.status, p.constraint);
    }
}

/* One kind fitted both ways at D's scale; the iterations of both into its (NULL: not asked). */
static void compare_its(const held_data *D, int model, int kind, const char *what, int *its)
{
    const fit_out f = fit_kind(D, model, kind, 0), p = fit_kind(D, model, kind, 1);
    judge(f, p, 1.0, what);
    if (its) { its[0] = f.iterations; its[1] = p.iterations; }
}

enum { NSCALES = 3 };
static const double scales[NSCALES] = {1.0, 1e-6, 1e6};

/* One kind of the data D0: the plain path's fit at D0's scale, the held fit at D0's scale and
 * at 1e-6 and 1e6 of it, each judged against the plain fit's rms scaled with the points (the
 * fit is the same at every scale: test_fit's scale cases; the plain path is not run again at
 * 1e-6 and 1e6, two thirds of its fits); the held fits' iterations into its (NULL: not asked). */
static void compare_scaled(const held_data *D0, int model, int kind, const char *what,
                           int its[NSCALES][2])
{
    const fit_out p = fit_kind(D0, model, kind, 1);
    for (int a = 0; a < NSCALES; a++) {
        held_data D = *D0;
        scaled(&D, scales[a]);
        char at[128];
        snprintf(at, sizeof at, "%s x %g", what, scales[a]);
        const fit_out f = fit_kind(&D, model, kind, 0);
        judge(f, p, scales[a], at);
        if (its) { its[a][0] = f.iterations; its[a][1] = p.iterations; }
    }
}

/* Every kind of the data D0 (compare_scaled). */
static void all_kinds_scaled(const held_data *D0, const char *data, int sparse)
{
    char what[96];
    static const char *kinds[] = {"G1 ends", "G2 start G1 end", "pinned", "natural"};
    for (int kind = G1_ENDS; kind <= NATURAL; kind++)
        for (int model = 0; model < 2; model++) {
            /* the discrete start curvature other than 0 is a row of its own; the natural
             * batten's smooth fit searches its family whole (no rows): discrete only */
            if ((kind == G2_G1 && model == 1) || (kind == NATURAL && model == 0)) continue;
            if (!sparse && kind == PINNED) continue;      /* no rows: nothing held */
            snprintf(what, sizeof what, "%s, %s, %s", data, kinds[kind], model ? "discrete" : "smooth");
            compare_scaled(D0, model, kind, what, NULL);
        }
}

START_TEST(test_sine_scan)
{
    held_data D;
    sine_scan(&D);
    all_kinds_scaled(&D, "sine scan", 0);
}
END_TEST

/* The sweep's scan (sine_scan_held.h), G1 at both ends: the smooth fit's runs the kept fit
 * holds stop early (fewer iterations in all, the kept fit the same: main's rms 1.28601 smooth,
 * 1.28661 discrete), at its scale and at 1e-6 and 1e6 of it. */
START_TEST(test_sweep_scan)
{
    held_data D;
    D.n = SINE_SCAN_N;
    memcpy(D.xy, SINE_SCAN_XY, sizeof SINE_SCAN_XY);
    memcpy(D.p0, SINE_SCAN_P0, sizeof D.p0);
    memcpy(D.p1, SINE_SCAN_P1, sizeof D.p1);
    D.t0 = SINE_SCAN_T0;
    D.t1 = SINE_SCAN_T1;
    D.k0 = D.k1 = 0.0;
    for (int model = 0; model < 2; model++) {
        char what[64];
        int its[NSCALES][2];
        snprintf(what, sizeof what, "sweep's scan, G1 ends, %s", model ? "discrete" : "smooth");
        compare_scaled(&D, model, G1_ENDS, what, its);
        /* smooth: its later guesses' runs stopped (the discrete fit's ran as before) */
        if (model == 0)
            for (int a = 0; a < NSCALES; a++)
                ck_assert_msg(its[a][0] < its[a][1], "%s x %g: %d iterations, the plain path %d", what,
                              scales[a], its[a][0], its[a][1]);
    }
}
END_TEST

START_TEST(test_elastica_scan)
{
    const double L = 100.0, w = 5.0 * 1.995 / L;       /* k 0.8: K(0.8) = 1.995, 2.5 waves */
    const el_smooth_params c = {0.0, 0.0, 0.3, w * w, 0.8, -0.4, L};
    held_data D;
    elastica_scan(&D, &c, NSCAN, 0.4);
    all_kinds_scaled(&D, "elastica scan", 0);
}
END_TEST

START_TEST(test_sparse_sketch)
{
    const el_smooth_params c = {1.0, -2.0, -0.7, 4.0, 1.3, 0.2, 1.0};     /* k 1.3: no inflection */
    held_data D;
    elastica_scan(&D, &c, NSKETCH, 0.004);
    all_kinds_scaled(&D, "sparse sketch", 1);
}
END_TEST

/* A noisy hand sketch (hand_sketch_held.h), G1 at both ends, the end tangent 0.3 off its
 * last chord: a run the kept fit's cap stops counts as a run to max_iter (stop_rule), as the
 * plain path's ran there. Counted as none, every further guess ran (each stopped): 13585
 * iterations against the plain path's 7771, the same fit. */
START_TEST(test_hand_sketch)
{
    held_data D;
    const size_t n = HAND_SKETCH_N;
    D.n = n;
    memcpy(D.xy, HAND_SKETCH_XY, sizeof HAND_SKETCH_XY);
    memcpy(D.p0, D.xy, sizeof D.p0);
    memcpy(D.p1, D.xy + 2 * n - 2, sizeof D.p1);
    D.t0 = atan2(D.xy[3] - D.xy[1], D.xy[2] - D.xy[0]);
    D.t1 = atan2(D.xy[2 * n - 1] - D.xy[2 * n - 3], D.xy[2 * n - 2] - D.xy[2 * n - 4]) + 0.3;
    D.k0 = D.k1 = 0.0;
    int its[2];
    compare_its(&D, 0, G1_ENDS, "hand sketch, G1 ends, smooth", its);
    ck_assert_msg(its[0] <= its[1], "hand sketch: %d iterations, the plain path %d", its[0], its[1]);
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("fit rows cap");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 300);
    tcase_add_test(tc, test_sine_scan);
    tcase_add_test(tc, test_sweep_scan);
    tcase_add_test(tc, test_elastica_scan);
    tcase_add_test(tc, test_sparse_sketch);
    tcase_add_test(tc, test_hand_sketch);
    suite_add_tcase(s, tc);
    return s;
}

int main(void) { return test_run_suite(suite()); }
