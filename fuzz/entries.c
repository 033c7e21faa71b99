/* The table of fuzzed entry points, expanded from entries.def. */
#include "fuzz.h"

#include <math.h>
#include <string.h>

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
