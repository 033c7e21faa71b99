/* Not public: the Python binding's own entry (python/libelastica/_fit_call.py), declared
 * here and not in elastica.h (C programs call the public functions it is made of). The
 * binding's cdef reads this header after elastica.h (python/libelastica/_cdef.py); its
 * declarations take the public types only, so el_abi_digest (elastica.h's) covers their
 * layout, and el_binding_digest tells which of this header's versions the library was built
 * from. The library exports both (exports.map names them): the binding's entry, not an API
 * (no promise to C programs; fuzzed all the same, fuzz/entries.def). A binding that does not
 * find them (an installed elastica.h without this header, an older library) or whose
 * binding.h is another (el_binding_digest not its digest: the arguments would be passed
 * otherwise than the library reads them) takes the plain path, the same calls one by one. */
#ifndef EL_BINDING_H
#define EL_BINDING_H

#include <stddef.h>

/* The CRC-32 of this header's declarations as the binding's cdef takes them
 * (python/libelastica/_cdef.py --binding-abi, binding_abi.h): el_abi_digest's twin for
 * this header, which _fit_call.py compares with its own before it calls el_binding_fit. */
unsigned long el_binding_digest(void);

/*
 * el.fit's work before and after its C fit in one crossing: in turn, what el.fit checks
 * and computes through separate calls, each as that call does:
 *   - el_order_screen(xy, n, screen_step, screen_turn, screen): its EL_EINVAL (a NaN or
 *     inf, n = 0) returns -1 at once;
 *   - the rounding test of el.fit's require_distinct (fit_input.py): n >= 4 and the first
 *     4 points pairwise more than rounding_ulps x spacing(max(max xy, -min xy)) apart in x
 *     or in y (numpy's spacing: the gap to the next double away from 0), else -1 (the
 *     binding names the repeats); -1 also where that maximum is 0;
 *   - the fit: el_fit_discrete (discrete != NULL) or el_fit_smooth (smooth != NULL; the
 *     other NULL), opt as given, no initial curve; its status is returned;
 *   - figures[0]: el_fit_noise_quick's figure of xy, NaN where it fails;
 *   - figures[1], [2]: where the fit returned EL_OK, EL_ENOCONV or EL_EMAXITER, the
 *     median of |distances| (the mean of the two middle values for even n, (0 + lo + hi) / 2:
 *     libelastica/_median.py's) and their maximum; NaN where a distance is no finite number,
 *     the mean overflows, or the n doubles for the median cannot be allocated.
 * -1 (nothing fitted, res untouched, figures NaN) where a check refuses or an argument is
 * NULL: the binding then takes its plain path, which says why.
 */
int el_binding_fit(const double *xy, size_t n, const el_fit_options *opt,
                   el_fit_discrete_result *discrete, el_fit_smooth_result *smooth,
                   double *distances, double *foot_s, double rounding_ulps,
                   size_t screen_step, int screen_turn, el_order_screen_result *screen,
                   double *figures);

#endif
