/* Status codes, messages, and the shared argument checks. */
#include "internal.h"
#include <gsl/gsl_errno.h>

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
    default:           return "unknown status";
    }
}

const char *el_version(void) { return "0.1.0"; }

void el__gsl_quiet(void) { gsl_set_error_handler_off(); }

int el__all_finite(const double *v, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (!isfinite(v[i])) return EL_EINVAL;
    return EL_OK;
}
