/* Status codes, messages, and the shared argument checks. */
#define _POSIX_C_SOURCE 200112L /* pthread_once */
#include "internal.h"
#include <gsl/gsl_errno.h>
#include <pthread.h>
#include <stdlib.h>

const char *el_strerror(int status)
{
    switch (status) {
    case EL_OK:        return "success";
    case EL_EINVAL:    return "invalid argument (NULL, NaN/inf, out of range or too few points)";
    case EL_ENOMEM:    return "out of memory";
    case EL_EDOM:      return "input outside the domain the method covers";
    case EL_ENOCONV:   return "did not converge (best result seen returned)";
    case EL_ESINGULAR: return "singular or degenerate input";
    case EL_EMAXITER:  return "iteration limit reached (best result seen returned)";
    case EL_EINTERNAL: return "internal numerical routine failed";
    case EL_ERANGE:    return "target beyond the range of solutions reached";
    default:           return "unknown status";
    }
}

const char *el_version(void) { return EL_VERSION_STRING; }

static pthread_once_t gsl_quiet_once = PTHREAD_ONCE_INIT;

/* GSL has no getter for its handler: switching it off returns the one in place,
 * and a program's own (non-NULL) handler goes back at once. */
static void gsl_handler_off(void)
{
    gsl_error_handler_t *callers = gsl_set_error_handler_off();
    if (callers) gsl_set_error_handler(callers);
}

/* GSL's error handler is process-wide and aborts by default (NULL): switch it
 * off once, race-free, before the library's first GSL call, unless the program
 * installed its own; every GSL status is then mapped to an EL_ code by the caller. */
void el__gsl_quiet(void) { pthread_once(&gsl_quiet_once, gsl_handler_off); }

int el__all_finite(const double *v, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (!isfinite(v[i])) return EL_EINVAL;
    return EL_OK;
}

void *el__alloc(size_t count, size_t per, size_t elem)
{
    size_t bytes;
    if (el__size_mul(count, per, &bytes) || el__size_mul(bytes, elem, &bytes)) return NULL;
    return malloc(bytes ? bytes : 1);
}

void *el__realloc(void *p, size_t count, size_t per, size_t elem)
{
    size_t bytes;
    if (el__size_mul(count, per, &bytes) || el__size_mul(bytes, elem, &bytes)) return NULL;
    return realloc(p, bytes ? bytes : 1);
}
