/* The harness's decoders, checks and runner (see fuzz.h). */
#include "fuzz.h"

#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* ---------------------------------------------------------------- memory */

static void **allocs;
static size_t nalloc, capalloc;

void *fz_alloc(size_t bytes)
{
    void *p = calloc(1, bytes ? bytes : 1);
    if (!p) abort();   /* the harness's own memory: not a finding */
    if (nalloc == capalloc) {
        capalloc = capalloc ? 2 * capalloc : 64;
        allocs = realloc(allocs, capalloc * sizeof *allocs);
        if (!allocs) abort();
    }
    allocs[nalloc++] = p;
    return p;
}

void fz_free_all(void)
{
    for (size_t i = 0; i < nalloc; i++) free(allocs[i]);
    nalloc = 0;
}

/* ---------------------------------------------------------------- decoders */

int fz_trace;

/* --trace: every decoded argument on stderr, to read a reproducer. */
static double traced(const char *what, double v)
{
    if (fz_trace) fprintf(stderr, "  %s %.17g\n", what, v);
    return v;
}

uint8_t fz_byte(fz_in *in) { return in->pos < in->size ? in->data[in->pos++] : 0; }

/* Big-endian; one byte per statement (C leaves the order within an expression open). */
static unsigned fz_u16(fz_in *in)
{
    unsigned hi = fz_byte(in);
    return hi << 8 | fz_byte(in);
}

static uint64_t fz_u64(fz_in *in)
{
    uint64_t v = 0;
    for (int i = 0; i < 8; i++) v = (v << 8) | fz_byte(in);
    return v;
}

static const double SPECIAL[] = {
    NAN, INFINITY, -INFINITY, 0.0, -0.0, 1e300, -1e300, 1e-300, -1e-300,
    4.9406564584124654e-324, 1e-310, -1e-310, DBL_MAX, -DBL_MAX, DBL_MIN, 1.0, -1.0,
    1.0 + 1e-15, 1.0 - 1e-15, -1.0 - 1e-15, -1.0 + 1e-15, 0.5, 2.0, 1e8, -1e8, 1e-8,
    0.80241, 0.6438, 0.8024, 1e15, 1e-15, M_PI, -M_PI, 2 * M_PI, 1e154, 1e-154, 3.0, 1e4,
};
enum { NSPECIAL = sizeof SPECIAL / sizeof *SPECIAL };

double fz_double(fz_in *in)
{
    uint8_t tag = fz_byte(in);
    if (tag < 100) return traced("double", SPECIAL[tag % NSPECIAL]);
    if (tag < 230) {   /* moderate: |x| <= 10, 16 bits of resolution */
        unsigned v = fz_u16(in);
        return traced("double", -10.0 + 20.0 * v / 65535.0);
    }
    uint64_t bits = fz_u64(in);
    double x;
    memcpy(&x, &bits, sizeof x);
    return traced("double", x);
}

double fz_range(fz_in *in, double lo, double hi)
{
    uint8_t tag = fz_byte(in);
    if (tag < 200) {
        unsigned v = fz_u16(in);
        return traced("range", lo + (hi - lo) * v / 65535.0);
    }
    return fz_double(in);
}

int fz_int(fz_in *in)
{
    static const int odd[] = {INT_MIN, INT_MAX, -1, 0, 1, 1000000, -1000000, INT_MAX - 1};
    uint8_t tag = fz_byte(in);
    return (int)traced("int", tag < 224 ? (int)(tag % 44) - 3 : odd[tag % 8]);
}

size_t fz_count(fz_in *in, size_t max)
{
    uint8_t tag = fz_byte(in);
    size_t n;
    if (tag < 96) n = tag % 6;
    else if (tag < 240) n = 6 + ((size_t)tag << 8 | fz_byte(in)) % 60;
    else n = fz_u16(in) % (max + 1);
    n = n <= max ? n : max;
    if (fz_large < n) fz_large = n;
    traced("count", (double)n);
    return n;
}

size_t fz_request(fz_in *in, size_t max)
{
    static const size_t huge[] = {(size_t)-1, ((size_t)1 << 62) - 1, ((size_t)1 << 61) - 1,
                                  (size_t)-1 / 2, 10000000, 1000001, (size_t)1 << 32, 100000};
    uint8_t tag = fz_byte(in);
    if (tag >= 232) {
        fz_large = huge[tag % 8];
        traced("request", (double)huge[tag % 8]);
        return huge[tag % 8];
    }
    return fz_count(in, max);
}

unsigned fz_nulls(fz_in *in)
{
    unsigned mask = 0;
    for (int i = 0; i < 4; i++) {
        const uint8_t b = fz_byte(in);
        if ((b & 15) == 15) mask |= 1u << (2 * i);
        if ((b >> 4) == 15) mask |= 1u << (2 * i + 1);
    }
    return mask;
}

/* One moderate random number from the input, in [lo, hi] (never adversarial). */
static double fz_moderate(fz_in *in, double lo, double hi)
{
    unsigned v = fz_u16(in);
    return lo + (hi - lo) * v / 65535.0;
}

double *fz_values(fz_in *in, size_t n)
{
    double *v = fz_alloc((n ? n : 1) * sizeof *v);
    uint8_t how = fz_byte(in) % 4;
    double a = fz_double(in), h = fz_double(in);
    for (size_t i = 0; i < n; i++) {
        if (how == 0) v[i] = fz_double(in);
        else if (how == 1) v[i] = a + h * (double)i;                 /* equally spaced */
        else if (how == 2) v[i] = fz_moderate(in, 0.0, 1.0);         /* unit interval */
        else v[i] = (i ? v[i - 1] : 0.0) + fz_moderate(in, 0.0, 2.0); /* sorted, uneven */
    }
    return v;
}

double *fz_points(fz_in *in, size_t n, int dim)
{
    double *p = fz_alloc((n ? n : 1) * (size_t)dim * sizeof *p);
    uint8_t how = fz_byte(in) % 12;
    double scale = 1.0, shift = 0.0;
    switch (fz_byte(in) % 8) {   /* an overall scale and offset, often extreme */
    case 0: scale = 1e-300; break;
    case 1: scale = 1e300; break;
    case 2: scale = 1e-310; break;
    case 3: shift = 1e15; break;
    default: break;
    }
    const double k = fz_moderate(in, 0.05, 0.99), L = fz_moderate(in, 0.5, 30.0),
                 noise = fz_byte(in) % 3 ? 0.0 : fz_moderate(in, 0.0, 0.05);
    for (size_t i = 0; i < n; i++) {
        double t = n > 1 ? (double)i / (double)(n - 1) : 0.0, c[3] = {0, 0, 0};
        switch (how) {
        case 0: for (int j = 0; j < dim && j < 3; j++) c[j] = fz_double(in); break;
        case 1: c[0] = c[1] = c[2] = 1.0; break;                          /* all equal */
        case 2: c[0] = t; c[1] = 2 * t; c[2] = -t; break;                 /* collinear */
        case 3: c[0] = cos(3 * t); c[1] = sin(3 * t); c[2] = 0.1 * t; break;   /* arc */
        case 4: c[0] = t; c[1] = (i % 2) ? 0.1 : -0.1; break;            /* zigzag */
        case 5: c[0] = (double)(i / 2); c[1] = 0.0; break;               /* repeated points */
        case 6: c[0] = t; c[1] = t * t * t - 0.5 * t; c[2] = t * t; break;   /* an S, inflection */
        default: {   /* an elastica sample: the shape users fit */
            el_smooth_params q = {0, 0, 0, 1.0, k * (how == 7 ? 1.5 : 1.0), 0.3, L};
            double s = t * L, xy[2];
            if (el_smooth_eval(&q, 1, &s, xy, NULL, NULL) != EL_OK) xy[0] = xy[1] = 0.0;
            c[0] = xy[0];
            c[1] = xy[1];
            c[2] = 0.05 * xy[0];
            break;
        }
        }
        for (int j = 0; j < dim; j++) {
            double v = j < 3 ? c[j] : (double)j * t;
            if (noise > 0.0) v += noise * fz_moderate(in, -1.0, 1.0);
            p[i * (size_t)dim + (size_t)j] = v * scale + shift;
        }
        if (how == 11 && i > 0 && i % 3 == 0)   /* duplicate points */
            memcpy(p + i * (size_t)dim, p + (i - 1) * (size_t)dim, (size_t)dim * sizeof *p);
    }
    if (n > 0 && fz_byte(in) % 16 == 0) {   /* one bad coordinate */
        const size_t i = fz_byte(in) % n;
        p[i * (size_t)dim] = fz_double(in);
    }
    if (fz_trace) {
        fprintf(stderr, "  points n=%zu dim=%d pattern %d scale %g shift %g:", n, dim, how, scale, shift);
        for (size_t i = 0; i < n * (size_t)dim && i < 24; i++) fprintf(stderr, " %.6g", p[i]);
        fprintf(stderr, n * (size_t)dim > 24 ? " ...\n" : "\n");
    }
    return p;
}

double fz_modulus(fz_in *in)
{
    static const double ks[] = {0.0, 1.0, -1.0, 1.0 + 1e-15, 1.0 - 1e-15, -1.0 - 1e-15, 0.5,
                                0.8, 0.99, 1.5, -2.0, 1e4, -1e4, 1e-8, 0.999999, 3.0};
    uint8_t tag = fz_byte(in);
    if (tag < 64) return ks[tag % 16];
    if (tag < 224) return fz_moderate(in, -3.0, 3.0);
    return fz_double(in);
}

el_smooth_params fz_smooth(fz_in *in)
{
    el_smooth_params p;
    p.x0 = fz_range(in, -10, 10);
    p.y0 = fz_range(in, -10, 10);
    p.phi = fz_range(in, -7, 7);
    p.mu = fz_range(in, 0.01, 100);
    p.k = fz_modulus(in);
    p.q = fz_range(in, -20, 20);
    p.length = fz_range(in, 0, 20);
    return p;
}

el_discrete_params fz_discrete(fz_in *in)
{
    el_discrete_params p;
    p.x0 = fz_range(in, -10, 10);
    p.y0 = fz_range(in, -10, 10);
    p.h = fz_range(in, 0.01, 2);
    p.phi = fz_range(in, -7, 7);
    p.z = fz_range(in, -1, 1);
    p.q = fz_range(in, -20, 20);
    p.k = fabs(fz_modulus(in));
    if (fz_byte(in) % 16 == 0) p.k = -p.k;
    return p;
}

el_bspline fz_bspline(fz_in *in, int dim)
{
    el_bspline b;
    memset(&b, 0, sizeof b);
    int p = 1 + fz_byte(in) % 7;
    size_t n = (size_t)p + 1 + fz_count(in, 60);
    size_t nint = n - (size_t)p - 1;   /* interior knots, simple */
    b.degree = p;
    b.dim = dim;
    b.npoles = n;
    b.nknots = nint + 2;
    b.poles = fz_points(in, n, dim);
    b.knots = fz_alloc(b.nknots * sizeof *b.knots);
    b.mults = fz_alloc(b.nknots * sizeof *b.mults);
    const double a = fz_range(in, -5, 5), span = fz_range(in, 0.1, 10);
    for (size_t i = 0; i < b.nknots; i++) {
        b.knots[i] = a + span * (double)i / (double)(b.nknots - 1);
        b.mults[i] = (i == 0 || i + 1 == b.nknots) ? p + 1 : 1;
    }
    /* sometimes broken in one way; the counts only shrink (a caller claiming more
     * than its arrays hold is its own bug, not the library's) */
    switch (fz_byte(in) % 24) {
    case 0: { const size_t i = fz_byte(in) % b.nknots; b.knots[i] = fz_double(in); break; }
    case 1: { const size_t i = fz_byte(in) % b.nknots; b.mults[i] = fz_int(in); break; }
    case 2: b.npoles = fz_count(in, n); break;
    case 3: b.degree = fz_int(in); break;
    case 4: b.dim = fz_int(in) % (dim + 1); break;
    case 5: b.nknots = fz_count(in, b.nknots); break;
    case 6: b.poles = NULL; break;
    default: break;
    }
    return b;
}

el_hermite_options fz_hermite_options(fz_in *in)
{
    el_hermite_options o;
    el_hermite_options_defaults(&o);
    if (fz_byte(in) % 2) o.mode = EL_HERMITE_LENGTH;
    if (fz_byte(in) % 4 == 0) o.mode = fz_int(in);
    o.sigma = fz_range(in, -20, 60);
    o.length = fz_range(in, 0.5, 10);
    if (fz_byte(in) % 4 == 0) o.tol = fz_double(in);
    if (fz_byte(in) % 4 == 0) o.samples = fz_int(in);
    if (fz_byte(in) % 4 == 0) o.grid = fz_int(in);
    if (fz_byte(in) % 4 == 0) o.max_solutions = fz_request(in, 100);
    return o;
}

el_fit_options fz_fit_options(fz_in *in)
{
    el_fit_options o;
    el_fit_options_defaults(&o);
    o.max_iter = 1 + fz_byte(in) % 200;   /* the default at most: work bounded as in use */
    uint8_t what = fz_byte(in);
    if (what & 1) {   /* fixed parameters, sometimes absurd values */
        for (int j = 0; j < 7; j++)
            if (fz_byte(in) % 4 == 0) { o.fixed[j] = 1; o.value[j] = fz_double(in); }
    }
    if (what & 2) {   /* bounds, sometimes inconsistent */
        for (int j = 0; j < 7; j++)
            if (fz_byte(in) % 4 == 0) { o.lower[j] = fz_double(in); o.upper[j] = fz_double(in); }
    }
    if (what & 4) o.tol = fz_double(in);
    if (what & 8) o.limited_memory = fz_int(in);
    if (what & 16) o.max_candidates = fz_int(in) % 8;
    if (what & 32) o.param_mode = fz_int(in) % 4;
    if (what & 64) o.use_initial = 1;
    if (what & 128) o.max_iter = fz_int(in) % 201;
    const uint8_t more = fz_byte(in);
    if (more & 1) o.distance = fz_byte(in) % 8 == 0 ? fz_int(in) : fz_byte(in) % 3;
    if (more & 2) {   /* constraints: the kinds, values moderate or adversarial */
        o.constraints = fz_byte(in) % 8 == 0 ? fz_int(in) : fz_byte(in);
        o.start_point[0] = fz_range(in, -5, 5); o.start_point[1] = fz_range(in, -5, 5);
        o.end_point[0] = fz_range(in, -5, 5);   o.end_point[1] = fz_range(in, -5, 5);
        o.start_tangent = fz_range(in, -4, 4);  o.end_tangent = fz_range(in, -4, 4);
        o.start_curvature = fz_range(in, -1, 1); o.end_curvature = fz_range(in, -1, 1);
        o.length_range[0] = fz_range(in, 0, 10); o.length_range[1] = fz_range(in, 0, 100);
        o.k_range[0] = fz_range(in, -3, 1);      o.k_range[1] = fz_range(in, -1, 3);
    }
    return o;
}

static el_spline_end spline_end(fz_in *in)
{
    el_spline_end e;
    memset(&e, 0, sizeof e);
    e.kind = fz_byte(in) % 8 == 0 ? fz_int(in) : fz_byte(in) % 3;
    e.tangent[0] = fz_range(in, -1, 1);
    e.tangent[1] = fz_range(in, -1, 1);
    e.curvature = fz_range(in, -2, 2);
    return e;
}

/* options as a user sets them (tension, length, ends, closed), sometimes absurd */
el_spline_options fz_spline_options(fz_in *in)
{
    el_spline_options o;
    el_spline_options_defaults(&o);
    if (fz_byte(in) % 2) o.mode = EL_SPLINE_LENGTH;
    if (fz_byte(in) % 8 == 0) o.mode = fz_int(in);
    o.sigma = fz_range(in, 0, 50);
    o.length = fz_range(in, 1, 40);
    o.closed = fz_byte(in) % 4 == 0;
    o.start = spline_end(in);
    o.end = spline_end(in);
    if (fz_byte(in) % 4 == 0) o.tol = fz_double(in);
    if (fz_byte(in) % 4 == 0) o.max_iter = fz_int(in);
    if (fz_byte(in) % 4 == 0) o.max_steps = fz_int(in);
    return o;
}

void fz_check_spline(const el_spline_result *r)
{
    FZ_FINITE(&r->pieces[0].x0, 7 * r->npieces);
    if (r->nguides > 2) fz_finding("output", "more than two guide ducks");
    else {
        FZ_FINITE(r->guides, 2 * r->nguides);
        FZ_FINITE(r->guide_forces, 2 * r->nguides);
        for (size_t g = 0; g < r->nguides; g++)
            if (r->guide_pieces[g] >= r->npieces) fz_finding("output", "guide duck on no piece");
    }
    FZ_FINITE(r->forces, 2 * r->npieces);
    FZ_FINITE(r->angles, r->npoints);
    FZ_FINITE(r->curvatures, r->npoints);
    FZ_FINITE(&r->sigma, 5);
}

int fz_blend_basis(fz_in *in, el_blend_basis *b)
{
    memset(b, 0, sizeof *b);
    if (fz_byte(in) % 3 == 0) {
        double c = fz_range(in, -5, 5), d;
        if (fz_byte(in) % 2 || el_blend_eck_d(c, &d) != EL_OK) d = fz_range(in, 0.1, 10);
        return el_blend_init_mq(b, c, d);
    }
    return el_blend_init_elliptic(b, fz_range(in, 0, 0.999), fz_range(in, 0.1, 10));
}

/* ---------------------------------------------------------------- checks */

size_t fz_large;

static fz_sink cur_sink;
static const fz_entry *cur_entry;
static int cur_findings;

void fz_finding(const char *kind, const char *fmt, ...)
{
    char msg[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    cur_findings++;
    if (cur_sink) cur_sink(cur_entry, kind, msg);
}

void fz_check_finite(const double *v, size_t n, const char *what)
{
    for (size_t i = 0; i < n; i++)
        if (!isfinite(v[i])) {
            fz_finding("non-finite", "EL_OK (or a best result) with %s[%zu] = %g", what, i, v[i]);
            return;
        }
}

void fz_check_hermite_solutions(const el_hermite_solution *s, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        FZ_FINITE(&s[i].curve.x0, 7);
        FZ_FINITE(&s[i].length, 3);
        FZ_FINITE(&s[i].kappa0, 3);
        const int np = s[i].npieces;
        if (np < 1 || np > 3) fz_finding("output", "npieces %d", np);
        else if (np > 1) FZ_FINITE(&s[i].rest[0].x0, 7 * (size_t)(np - 1));
    }
}

static const unsigned char CANARY = 0xA5;

void fz_canary(void *p, size_t bytes) { memset(p, CANARY, bytes); }

double *fz_out(size_t n)
{
    double *v = fz_alloc((n ? n : 1) * sizeof *v);
    fz_canary(v, (n ? n : 1) * sizeof *v);
    return v;
}

int fz_canary_intact(const void *p, size_t bytes)
{
    const unsigned char *c = p;
    for (size_t i = 0; i < bytes; i++)
        if (c[i] != CANARY) return 0;
    return 1;
}

/* ---------------------------------------------------------------- table */

/* ---------------------------------------------------------------- known findings */

static char known[64][160];
static int nknown;

void fz_read_known(const char *path)
{
    FILE *f = fopen(path, "r");
    char line[256], e[120], k[32];
    if (!f) { fprintf(stderr, "fuzz: cannot read %s\n", path); exit(2); }
    while (fgets(line, sizeof line, f) && nknown < 64)
        if (line[0] != '#' && sscanf(line, "%119s %31s", e, k) == 2)
            snprintf(known[nknown++], sizeof known[0], "%s %s", e, k);
    fclose(f);
}

int fz_is_known(const char *entry, const char *kind)
{
    char key[160];
    snprintf(key, sizeof key, "%s %s", entry, kind);
    for (int i = 0; i < nknown; i++)
        if (!strcmp(known[i], key)) return 1;
    return 0;
}

static void gsl_handler(const char *reason, const char *file, int line, int gsl_errno)
{
    fz_finding("gsl-error", "GSL's error handler was called: %s (%s:%d, gsl_errno %d); a caller "
               "whose handler aborts would abort here", reason, file, line, gsl_errno);
}

void fz_init(void)
{
    /* the library turns GSL's handler off on its first GSL call (pthread_once);
     * after that, install one as a caller would: every call of it is a finding */
    el_blend_basis b;
    el_blend_init_elliptic(&b, 0.5, 2.0);
    gsl_set_error_handler(gsl_handler);
}

uint16_t fz_entry_id(const char *name)
{
    uint32_t h = 2166136261u;   /* FNV-1a */
    for (const char *c = name; *c; c++) h = (h ^ (uint8_t)*c) * 16777619u;
    return (uint16_t)(h ^ (h >> 16));
}

const fz_entry *fz_select(const uint8_t *data, size_t size)
{
    size_t n;
    const fz_entry *t = fz_entries(&n);
    uint16_t id = size >= 2 ? (uint16_t)(data[0] << 8 | data[1]) : 0;
    for (size_t i = 0; i < n; i++)
        if (t[i].id == id) return &t[i];
    return &t[id % n];
}

static const char *status_name(int st)
{
    static const char *names[] = {"EL_OK", "EL_EINVAL", "EL_ENOMEM", "EL_EDOM", "EL_ENOCONV",
                                  "EL_ESINGULAR", "EL_EMAXITER", "EL_EINTERNAL"};
    return st >= 0 && st < 8 ? names[st] : "unknown";
}

int fz_run(const uint8_t *data, size_t size, fz_sink sink)
{
    const fz_entry *e = fz_select(data, size);
    fz_in in = {data, size, size >= 2 ? 2 : size};
    cur_sink = sink;
    cur_entry = e;
    cur_findings = 0;
    fz_large = 0;
    if (fz_trace) fprintf(stderr, "%s:\n", e->name);
    int st = e->fn(&in);
    if (fz_trace) fprintf(stderr, "  -> status %d\n", st);
    if (st < 0 || st > 31 || !(e->statuses & ST(st)))
        fz_finding("status", "returned %s (%d), which the header does not list", status_name(st), st);
    fz_free_all();
    return cur_findings;
}
