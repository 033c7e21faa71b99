/*
 * One inflection-free piece of seed 002 §4.1-4.3 (affine_polyline.c builds and optimises it;
 * affine_landing.c lands its last vertex at the piece end for fit_ends, §4.4).
 */
#ifndef EL_AFFINE_PIECE_H
#define EL_AFFINE_PIECE_H
#include "affine_internal.h"

typedef struct arc arc;     /* an arc of the parabolic replacement f~ (affine_polyline.c) */

typedef struct piece {
    const arc *arcs;
    size_t Ta, Tb;      /* parameter range [Ta, Tb] of f~ (arcs Ta..Tb-1) */
    int sigma;          /* turning sense */
    double A;           /* signed area constant */
    size_t m;           /* edges: local vertices 0..m */
    double x0[2];       /* fixed first vertex */
    int skip_lo, skip_hi;
    double *xy, *t;     /* workspace m+1 points / parameters */
    double *r;          /* workspace 3 (m+1) residuals: psi's, then polish's r(t +- d) */
} piece;

/* The polyline of P at t1 from P->x0, vertex by vertex (§4.3) into P->xy, P->t. EL_EDOM:
 * no next vertex (an edge of length 0, or none within bounds beyond Tb). */
int el__piece_build(piece *P, double t1);
/* psi = sum r_j^2 (4) of the polyline built in P, its residuals in P->r. */
double el__piece_psi_built(piece *P);
/* psi at t1 (a gsl_function: 1e300 where the build fails); P->r must be allocated. */
double el__piece_psi(double t1, void *params);
/* Gauss-Newton polish of a minimiser t of psi, steps within w; P->r must be allocated. */
double el__piece_polish(piece *P, double t, double w);
/* t1 from the affine length cbrt|A| along f~. */
double el__piece_t1_start(const piece *P);
/* P at its A: t1 from el__piece_t1_start, optimised (§4.2); P left built, *psi its psi. */
int el__piece_solve(piece *P, const el_affine_options *o, double *psi);
/* fit_ends (§4.4): A adjusted so that P's last vertex lands at its end Tb (affine_landing.c);
 * `last`: the polyline's last piece. P left built, *psi its psi; EL_EDOM: no A found lands it. */
int el__piece_fit_ends(piece *P, const el_affine_options *o, int last, double *psi);

#endif
