/*
 * A fit objective's state saved and put back (fit_candidate.c): its struct, its feet's two
 * arrays and its rest arrays, so that a run that is not kept leaves the later steps seeing
 * exactly what they saw before it (not installed).
 */
#ifndef EL_FIT_OBSTATE_H
#define EL_FIT_OBSTATE_H

#include "fit_internal.h"

typedef struct fit_ob_state {
    fit_objective ob;
    double *buf;          /* the feet's two arrays, then rest and rest_foot (n each) */
} fit_ob_state;

/* *ob saved into *k (k->buf allocated: free it); EL_OK or EL_ENOMEM. */
int el__fit_ob_save(const fit_objective *ob, fit_ob_state *k);
/* *ob put back as el__fit_ob_save found it. */
void el__fit_ob_restore(fit_objective *ob, const fit_ob_state *k);

#endif
