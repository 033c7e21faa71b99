/*
 * Continuation along a one-parameter family of elastic splines (spline_path.c,
 * spline_bracket.c, ...): snapshots of a chain's state, the secant predictor, and the
 * stepping with Newton (el__spline_continuation).
 */
#include "internal.h"
#include <string.h>

/* Snapshots: to restore after a failed step, and the two last ones for the
 * secant predictor. */
void el__snap_save(const el__spchain *w, el__spsnap *s)
{
    memcpy(s->x, w->x, w->n * sizeof *w->x);
    for (size_t j = 0; j < w->m; j++) {
        memcpy(s->v + j * EL__NV, w->pc[j].v, sizeof w->pc[j].v);
        memcpy(s->st + j * EL__NV, w->pc[j].st, sizeof w->pc[j].st);
    }
    s->sigma = w->sigma;
}

void el__snap_load(el__spchain *w, const el__spsnap *s)
{
    memcpy(w->x, s->x, w->n * sizeof *w->x);
    for (size_t j = 0; j < w->m; j++) memcpy(w->pc[j].v, s->v + j * EL__NV, sizeof w->pc[j].v);
    w->sigma = s->sigma;
}

/* el__snap_load, and each piece's el__spiece state from the snapshot */
void el__snap_load_states(el__spchain *w, const el__spsnap *s)
{
    el__snap_load(w, s);
    for (size_t j = 0; j < w->m; j++) memcpy(w->pc[j].st, s->st + j * EL__NV, sizeof w->pc[j].st);
}

/* The state at f = (t - tb)/(tb - ta) beyond b on the line through a and b
 * (knot values, sigma, el__spiece states); b itself if a piece state is invalid. */
static void predict(el__spchain *w, const el__spsnap *a, const el__spsnap *b, double f)
{
    for (size_t i = 0; i < w->n; i++) w->x[i] = b->x[i] + f * (b->x[i] - a->x[i]);
    w->sigma = b->sigma + f * (b->sigma - a->sigma);
    for (size_t j = 0; j < w->m; j++) {
        double st[EL__NV];
        for (int i = 0; i < EL__NV; i++) st[i] = b->st[j * EL__NV + i] + f * (b->st[j * EL__NV + i] - a->st[j * EL__NV + i]);
        if (el__spiece_set_state(&w->pc[j], st)) { el__snap_load(w, b); return; }
    }
}

void el__snap_predict(el__spchain *w, const el__spsnap *a, const el__spsnap *b, double f)
{
    predict(w, a, b, f);
}

/*
 * Follow a one-parameter family from t = 0 (solved, in w) to t = 1: set(w, t)
 * moves the target (sigma or length); each step starts from the secant
 * predictor of the last two solutions and is corrected by Newton to EL__SP_NEAR
 * (the last one to aim, accepted at accept). The first step is dt; it doubles
 * after an easy success, grows by 1.3 after a slow one and halves after a
 * failure (state restored); at most max_steps steps, giving up below 1e-3.
 * A step whose Newton needs more than EL__SP_STEP_HALVINGS halvings fails: a
 * shorter step serves better, and where none does (a fold in t: the free
 * batten that does not exist) the path ends sooner (a 1000-point zigzag says
 * EL_EDOM in ~1 s, was ~5 s; the results elsewhere are the same).
 * Where a continuation ran out of steps after a step that succeeded (el__cont_rest), it
 * goes on from there (spline_path.c's LONG_PATH), the same steps as taking them all again
 * (the predictor rebuilds the chain from the snapshots).
 */
static void snap_copy(const el__spchain *w, el__spsnap *d, const el__spsnap *s)
{
    memcpy(d->x, s->x, w->n * sizeof *d->x);
    memcpy(d->v, s->v, EL__NV * w->m * sizeof *d->v);
    memcpy(d->st, s->st, EL__NV * w->m * sizeof *d->st);
    d->sigma = s->sigma;
}

int el__spline_follow(el__spchain *w, el__spsnap sv[2], int max_steps, double dt,
                      void (*set)(el__spchain *, double, const double *), const double *par,
                      double aim, double accept, el__cont_rest *rest)
{
    double t = 0.0, tp = -1.0;
    el__spsnap *cur = &sv[0], *prev = &sv[1];
    int step = 0;
    if (rest && rest->valid) {
        snap_copy(w, cur, &rest->cur);
        snap_copy(w, prev, &rest->prev);
        t = rest->t; tp = rest->tp; dt = rest->dt; step = rest->steps;
        rest->valid = 0;
        el__snap_load(w, cur);
        set(w, t, par);
    } else {
        el__snap_save(w, cur);
    }
    for (; step < max_steps; step++) {
        const double tn = fmin(1.0, t + dt);
        const int last = tn >= 1.0;
        if (tp >= 0.0) predict(w, prev, cur, (tn - t) / (t - tp));
        set(w, tn, par);
        const int it0 = w->iterations;
        w->halvings = EL__SP_STEP_HALVINGS;
        const int st = last ? el__chain_newton(w, EL__SP_STEP_ITER, aim, accept)
                            : el__chain_newton(w, EL__SP_STEP_ITER, 1e-3 * EL__SP_NEAR, EL__SP_NEAR);
        w->halvings = EL__SP_HALVINGS;
        if (st == EL_OK) {
            if (last) return EL_OK;
            el__spsnap *tmp = prev; prev = cur; cur = tmp;
            el__snap_save(w, cur);
            tp = t;
            t = tn;
            dt *= w->iterations - it0 <= 3 ? 2.0 : 1.3;
            continue;
        }
        if (last && w->resid <= EL__SP_NEAR) { w->near = 1; return EL_ENOCONV; }
        el__snap_load(w, cur);
        set(w, t, par);
        dt *= 0.5;
        if (dt < 1e-3) break;
    }
    if (rest && step == max_steps && tp >= 0.0) {
        snap_copy(w, &rest->cur, cur);
        snap_copy(w, &rest->prev, prev);
        rest->t = t; rest->tp = tp; rest->dt = dt; rest->steps = step;
        rest->valid = 1;
    }
    el__snap_load(w, cur);
    return EL_ENOCONV;
}

int el__spline_continuation(el__spchain *w, el__spsnap sv[2], int max_steps, double dt,
                            void (*set)(el__spchain *, double, const double *), const double *par,
                            double aim, double accept)
{
    return el__spline_follow(w, sv, max_steps, dt, set, par, aim, accept, NULL);
}
