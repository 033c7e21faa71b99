/* The README's C example, built by `make check` against the installed library. */
#include <elastica.h>
#include <elastica_abi.h> /* EL_ABI_DIGEST: the installed header's */
#include <stdio.h>

int main(void)
{
    if (el_abi_digest() != EL_ABI_DIGEST) { /* a library built from another elastica.h */
        fprintf(stderr, "libelastica %s was built from another elastica.h: rebuild this program\n", el_version());
        return 1;
    }
    el_smooth_params p = {.x0 = 0, .y0 = 0, .phi = 0, .mu = 1.0, .k = 0.8, .q = 0, .length = 5};
    double s[100], xy[200], jac[100 * 2 * 7], energy;
    for (int i = 0; i < 100; i++) s[i] = p.length * i / 99.0;
    int st = el_smooth_eval(&p, 100, s, xy, NULL, NULL);
    if (st == EL_OK) st = el_smooth_jacobian(&p, 100, s, NULL, jac);
    if (st == EL_OK) st = el_smooth_energy(&p, &energy);
    if (st != EL_OK) {
        fprintf(stderr, "%s\n", el_strerror(st));
        return 1;
    }
    el_bspline b = {0};          /* certified B-spline (EL_EMAXITER: the best one, honest) */
    st = el_smooth_to_bspline(&p, 1e-6, 3, &b);
    const size_t npoles = b.npoles;
    el_bspline_free(&b);                                   /* whatever the status: b was zeroed */
    if (st != EL_OK) return 1;
    el_discrete_params d = {.x0 = 0, .y0 = 0, .h = 0.1, .phi = 0, .z = 0.1, .q = 0, .k = 0.8};
    double v[100];
    if ((st = el_discrete_eval(&d, 50, v)) != EL_OK) return 1;
    printf("libelastica %s: end point (%.6f, %.6f), energy %.6f, B-spline of %zu poles, last vertex (%.6f, %.6f)\n",
           el_version(), xy[198], xy[199], energy, npoles, v[98], v[99]);
    return 0;
}
