/*
 * The fuzzing harness shared by the adversarial driver (driver.c) and the
 * libFuzzer target (libfuzzer.c): a byte reader that turns any input into
 * adversarial arguments, the checks every call must pass, and the table of
 * entry points (entries.def, one ENTRY per public function of elastica.h).
 *
 * An input is [2 bytes: entry id][payload]; the id is a 16-bit hash of the
 * function's name (fz_entry_id), so adding entries never changes what an old
 * input means. The payload is read front to back by the fz_* decoders; a
 * decoder past the end reads zeros, so every byte string is a valid input.
 */
#ifndef EL_FUZZ_H
#define EL_FUZZ_H

#include <stddef.h>
#include <stdint.h>
#include "elastica.h"

typedef struct fz_in {
    const uint8_t *data;
    size_t size, pos;
} fz_in;

/* ---------------------------------------------------------------- decoders */

uint8_t fz_byte(fz_in *in);
/* A double: ~40 % adversarial (NaN, +-inf, +-0, 1e+-300, denormals, DBL_MAX,
 * 1 +- 1e-15, the blend's K = 2 modulus, ...), ~50 % moderate (|x| <= 10),
 * ~10 % any bit pattern. */
double fz_double(fz_in *in);
/* A value in [lo, hi] most of the time, else fz_double (the adversarial ones). */
double fz_range(fz_in *in, double lo, double hi);
/* An int: small (-3..40) mostly, sometimes INT_MIN / INT_MAX / -1 / huge. */
int fz_int(fz_in *in);
/* An array length the caller really holds: 0..5 (often), up to max. */
size_t fz_count(fz_in *in, size_t max);
/* A requested size (not an array the caller holds): as fz_count, or huge
 * (SIZE_MAX, 2^62 - 1, 2^61 - 1, 1e7, ...). */
size_t fz_request(fz_in *in, size_t max);
/* n points of dim coordinates (malloc'ed, freed by fz_free_all): random,
 * all equal, collinear, an elastica sample with noise, a circle arc, a
 * zigzag, extreme scales, one NaN/inf... */
double *fz_points(fz_in *in, size_t n, int dim);
/* n doubles, each fz_double (or sorted, or equally spaced). */
double *fz_values(fz_in *in, size_t n);
/* zeroed scratch memory (freed by fz_free_all). */
void *fz_alloc(size_t bytes);
/* Which of up to 8 pointer arguments are NULL (bit i set once in 16 inputs):
 * NUL(i, p) is p or NULL by bit i of the mask `nul`. */
unsigned fz_nulls(fz_in *in);
#define NUL(i, p) (((nul >> (i)) & 1u) ? NULL : (p))

/* A modulus k: 0, +-1, 1 +- 1e-15, +-1e4, moderate, or adversarial. */
double fz_modulus(fz_in *in);
/* Fit options from the input: fixed parameters, bounds, tol, counts. */
el_fit_options fz_fit_options(fz_in *in);
/* Hermite options from the input: either mode, sigma and length in range mostly,
 * sometimes a bad mode, tol, samples, grid or max_solutions. */
el_hermite_options fz_hermite_options(fz_in *in);
el_smooth_params fz_smooth(fz_in *in);
el_discrete_params fz_discrete(fz_in *in);
/* A B-spline built from the input: usually valid (clamped, degree 1..7),
 * sometimes with broken knots / mults / counts (el_bspline_check must catch
 * them). Arrays from fz_alloc. */
el_bspline fz_bspline(fz_in *in, int dim);
/* Spline options as a user sets them (mode, tension, length, ends, closed),
 * sometimes absurd; and the finiteness checks of a spline result. */
el_spline_options fz_spline_options(fz_in *in);
void fz_check_spline(const el_spline_result *r);
/* An initialised basis (MQ or elliptic); EL_OK or the init status. */
int fz_blend_basis(fz_in *in, el_blend_basis *b);

/* ---------------------------------------------------------------- checks */

/* The documented statuses of an entry: ST(EL_OK) | ST(EL_EINVAL) | ... */
#define ST(s) (1u << (s))
#define ST_FIT (ST(EL_OK) | ST(EL_EINVAL) | ST(EL_ESINGULAR) | ST(EL_ENOMEM) | ST(EL_EINTERNAL) | \
                ST(EL_ENOCONV) | ST(EL_EMAXITER))

/* Record a finding of the current call (kind: "non-finite", "untouched", ...). */
void fz_finding(const char *kind, const char *fmt, ...);
/* Every one of the n values is finite, else a "non-finite" finding naming what. */
void fz_check_finite(const double *v, size_t n, const char *what);
#define FZ_FINITE(v, n) fz_check_finite((v), (n), #v)

/* Every solution's parameters and scalars finite, npieces 1..3 and its pieces finite. */
void fz_check_hermite_solutions(const el_hermite_solution *s, size_t n);

/* Canary bytes for outputs documented as untouched on error. */
void fz_canary(void *p, size_t bytes);
int fz_canary_intact(const void *p, size_t bytes);
/* n doubles of scratch output filled with the canary. */
double *fz_out(size_t n);
#define FZ_UNTOUCHED(p, bytes) do { if (!fz_canary_intact((p), (bytes))) \
    fz_finding("untouched", "%s written on an error status", #p); } while (0)

/* ---------------------------------------------------------------- entries */

typedef int (*fz_fn)(fz_in *in);

typedef struct fz_entry {
    const char *name;
    unsigned statuses;   /* documented statuses (ST bits) */
    int cost;            /* 1 cheap .. 100 (fits): the driver gives cheap entries more cases */
    fz_fn fn;
    uint16_t id;         /* fz_entry_id(name), filled by fz_entries() */
} fz_entry;

/* The table (entries.def) and its length. */
const fz_entry *fz_entries(size_t *count);
uint16_t fz_entry_id(const char *name);
/* The entry an input selects: the one with its id, else id modulo the count
 * (so libFuzzer's mutations still reach every entry). */
const fz_entry *fz_select(const uint8_t *data, size_t size);

/*
 * Run one input: decode, call, check (status documented, outputs), free.
 * Returns the number of findings it made (each also passed to the sink).
 */
typedef void (*fz_sink)(const fz_entry *e, const char *kind, const char *msg);
int fz_run(const uint8_t *data, size_t size, fz_sink sink);

/* Free everything fz_alloc / fz_points / ... handed out for the current input. */
void fz_free_all(void);

/* 1: print every decoded argument on stderr (driver --trace). */
extern int fz_trace;
/* The largest count or request the current input made (the slow-call limit
 * applies to n <= 1e4 only). */
extern size_t fz_large;

/* The tolerated findings (fuzz/known-findings: "ENTRY KIND" per line, # comments). */
void fz_read_known(const char *path);
int fz_is_known(const char *entry, const char *kind);

/* Once per process, before fz_run: installs a GSL error handler after the
 * library's first GSL call, as a caller would; every call of it is a finding
 * (kind "gsl-error"). */
void fz_init(void);

#endif
