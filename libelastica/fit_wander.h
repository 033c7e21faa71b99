/* fit_wander.h: whether a fit follows its points (fit_wander.c): the length of curve no point
 * accounts for (strays), the swing between two points (gap sag), crossings where the points'
 * polygon has none (loops), the gap the report names (el__fit_wander_gap). Split from
 * fit_internal.h; fit_seen, which fit_out holds, stays there. */
#ifndef EL_FIT_WANDER_H
#define EL_FIT_WANDER_H

#include "fit_internal.h"

/* fit_wander.c: how far a fit by distance to the curve strays from its points: the
 * length of curve (total L, input units like the rest) that no point accounts for, the
 * arc between feet fs adjacent along the curve beyond 1.6 times their points' chord (an
 * arc turning by pi) and beyond the first and last foot, each less 4 noise levels, over
 * the length of the points' polygon: a loop or a pass where there is no point, or the
 * points' order run backwards (a point whose foot lies on another pass of a loop, where
 * the passes cross, adds nothing). Above FIT_STRAY the fit does not follow its points;
 * -1 when out of memory. scale: the data's size (the fit's normalisation, el__fit_normalisation). */
#define FIT_STRAY 0.1
/* Above FIT_COIL a fit coils: one loop round all its points adds at most pi x their enclosing
 * circle's diameter, <= pi 2/sqrt(3) = 3.63 x their polygon's length, so more curve unaccounted
 * for passes them again and again (fit_follow.c's lowest_that_follows). */
#define FIT_COIL 4.0
/* A coiling fit gives way to one within FIT_COIL_TOL of the data's size above it that does not
 * coil, even one that swings in a gap (lowest_that_follows); not to a stub far from the points. */
#define FIT_COIL_TOL 0.1
double el__fit_stray(const double *xy, size_t n, const double *fs, double L, double noise, double scale);
/* fit_wander.c: el__fit_stray's length of curve no point accounts for over the length of
 * the curve they do account for where that is shorter than their polygon: noisy points'
 * polygon runs several times the curve's length (QA21's hand-drawn stroke, 400 points 1.6
 * apart at noise 1: polygon 711 for a stroke of 115), so a 130-long loop through empty space
 * beyond its last point (62 unaccounted for: 0.087 of the polygon) passed el__fit_stray's
 * FIT_STRAY; 0.33 of the curve. Above FIT_STRAY such a fit does not follow its points
 * either; -1 when out of memory. *stray (may be NULL): el__fit_stray's figure, of the same pass. */
double el__fit_stray_curve(const double *xy, size_t n, const double *fs, double L, double noise, double scale,
                           double *stray);
/* fit_wander.c: el__fit_stray of a fit whose start or end point is held (ends: the start and
 * end points, input units, NaN where not held; NULL: none): the curve from a held end to the
 * nearest foot is allowed 1.6 times the chord from that end to its point, as between
 * adjacent feet, instead of none (the constraints' curve there, not the fit's stray). */
double el__fit_stray_held(const double *xy, size_t n, const double *fs, double L, double noise,
                          double scale, const double ends[4]);
/* fit_wander.c: how far a smooth fit (p: its parameters, fs: its feet, input units) swings
 * from its points' polygon where there is no point: over each gap between feet adjacent
 * along the curve where it turns by more than FIT_GAP_TURN beyond the polygon's turns at the
 * gap's two points (the sum of |turn|s: a wave, or a bulge out and back), the curve's
 * farthest distance from the chord of their two points, less 4 noise levels, over that chord;
 * the largest (0 where the curve cannot be evaluated), -1 when out of memory. Above
 * FIT_GAP_SAG the fit swings between two points. A fair curve through a gap stays near the
 * chord and turns there about as its points' polygon does: on sketches of 6-9 points along
 * cubic paths, noise 0.3 % of their length, their curves' sag at most 0.087 over 2200 of
 * them; the fits 7-19 mm off a 57 mm gap, 0.12-0.44, turning by 2.6-5.2 rad where the
 * polygon turned by 0.2-0.8 (2.1-4.4 rad beyond it). The turn spares the curves of few
 * exact points, which bend by up to 0.2 of a chord where there is no point, as their polygon
 * does (tests/c/test_fit_basin.c's 6 exact points, a cluster of 5 and one far: sag 0.22,
 * turning 1.3 rad beyond the polygon's: at FIT_GAP_TURN 1 its fit gave way, rms 1e-16 ->
 * 2.3e-3). */
#define FIT_GAP_SAG 0.1
#define FIT_GAP_TURN 1.8
double el__fit_gap_sag(const double *xy, size_t n, const double *fs, const double *p, double noise);
/* fit_wander.c: the gap between points i and i + 1 (i in 0..n-2; where the curve passes its
 * points out of order, the gap between two feet adjacent along it, of points a < b, is the
 * gap b - 1: the curve comes to b from a) that the kept fit (p: its parameters of model,
 * fs: its feet, rms: its rms, ends: as el__fit_stray_held's; input units) wanders in, by
 * the tests of the sketch rules
 * (result_wanders, fit_follow.c), in their order: it strays (el__fit_stray_held above
 * FIT_STRAY, at the noise level fmin(noise, rms) of fewer than FIT_SKETCH_POINTS points,
 * else the data's noise): the gap holding the most curve no point accounts for (the ends'
 * share: the gap next to that end's point); then, fewer than FIT_SKETCH_POINTS points (more:
 * the stray test alone), it passes point i + 1 before point i and not after it as well
 * (passed_back: the first such i), it crosses itself where its points' polygon does not
 * (el__fit_loops): the gap of its loop's middle, or it swings between two of them (el__fit_gap_sag above FIT_GAP_SAG; the discrete model's
 * polygon judged at its vertices): the first such gap. -1 where it does none of these (or
 * out of memory). Reporting only (el_fit_*_result.wander_gap): no fit depends on it. seen
 * (may be NULL): what the fit computed of these points and this fit, not computed again. */
long el__fit_wander_gap(int model, const double *xy, size_t n, const double *p, const double *fs, double rms,
                        const double ends[4], const fit_seen *seen);
/* fit_wander.c: whether the fit by distance at x (ob's map) strays from its points
 * (el__fit_stray > FIT_STRAY; noise: el__fit_noise_rms, normalised); d, fs (n each: ob's
 * rest arrays, or the caller's) overwritten with its distances and feet (input units). */
int el__fit_strays_at(fit_objective *ob, const double *x, double noise, double *d, double *fs, double *tmp);
/* fit_wander.c: whether the curve at x (ob's map, one curve) crosses itself: the smooth
 * curve's polygon of 256 chords, the discrete polygon's chords through every
 * ceil((n - 1) / 256)-th vertex (its own segments up to 257 vertices); a loop narrower
 * than ~1/256 of its length is missed. 0 where it cannot be evaluated (or allocated). */
int el__fit_crosses_itself(const fit_objective *ob, const double *x);
/* fit_wander.c: whether the curve at x crosses itself (el__fit_crosses_itself) where the
 * points' own polygon (as el__fit_wanders) does not. */
int el__fit_loops(fit_objective *ob, const double *x);
/* fit_wander.c: whether the fit at x crosses itself where the points' own polygon (its
 * chords through every ceil((n - 1) / 64)-th point: the noise of dense points does not
 * cross) does not, or strays from its points (*strays: el__fit_strays_at's answer, -1
 * until computed, then kept; d, fs as its). */
int el__fit_wanders(fit_objective *ob, const double *x, int *strays, double noise, double *d, double *fs, double *tmp);
/* fit_wander.c: whether the fit at x (objective f) replaces the kept fit at best_x (best_f)
 * that crosses itself (el__fit_loops; *best_loops its answer, -1 until computed, then kept):
 * when x neither crosses itself nor strays (el__fit_wanders, *strays as there) and f is
 * below 4 x best_f. Ipopt ends on a chain of loops in a straight gap between the points,
 * below the fair fit (31 points sketched along 82 mm between nearly collinear G1 joins:
 * 10 loops at rms 0.476, the fair fit 0.490 and certified, QA). */
int el__fit_fair_over_loop(fit_objective *ob, const double *x, double f, int *strays,
                           const double *best_x, double best_f, int *best_loops, double noise,
                           double *d, double *fs, double *tmp);

#endif
