/* The table of fuzzed entry points, expanded from entries.def. */
#include "fuzz.h"
#include "../libelastica/binding.h"   /* the binding's entry: exported, fuzzed too */

#include <math.h>
#include <string.h>

/* el_fit_noise and el_fit_noise_quick: the same arguments and promises (a figure >= 0,
 * untouched on error). */
static int fz_noise_figure(fz_in *in, int (*figure)(const double *, size_t, double *))
{
    const unsigned nul = fz_nulls(in);
    size_t n = fz_count(in, 2000);
    double *xy = fz_points(in, n, 2), noise = -7.0;
    int st = figure(NUL(0, xy), n, NUL(1, &noise));
    if (st == EL_OK) {
        FZ_FINITE(&noise, 1);
        if (!(noise >= 0.0)) fz_finding("output", "noise %g", noise);
    } else if (noise != -7.0) {
        fz_finding("output", "noise written on error (%g)", noise);
    }
    return st;
}

#define ENTRY(name, statuses, cost, ...) static int fz_##name(fz_in *in) __VA_ARGS__
#include "entries.def"
#undef ENTRY

static fz_entry table[] = {
#define ENTRY(name, statuses, cost, ...) {#name, statuses, cost, fz_##name, 0},
#include "entries.def"
#undef ENTRY
};

const fz_entry *fz_entries(size_t *count)
{
    *count = sizeof table / sizeof *table;
    if (table[0].id == 0)
        for (size_t i = 0; i < *count; i++) table[i].id = fz_entry_id(table[i].name);
    return table;
}
