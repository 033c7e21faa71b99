/*
 * Carlson's series for R_F and R_D after the duplications (ellint.c), defined once for
 * every lane width that uses them: the scalar el__carlson_fd, the two lanes of
 * el__carlson_fd2 and the four of el__carlson_fd4 (carlson_lanes.h) do the same
 * operations on the same text of the coefficients.
 */
#ifndef EL_ELLINT_SERIES_H
#define EL_ELLINT_SERIES_H

/* The series of DLMF 19.36.1 (R_F) and 19.36.2 (R_D) to seventh order, in the
 * deviations of the arguments from their means AF, AD after the duplications (kept
 * unscaled: 4^steps times Carlson's, f2 = 2^steps), plus the duplication sum of R_D,
 * num / den. (sqrt and division dominate the cost here: one division per mean.) Defined
 * for a type T, double, el_d2 (two lanes, el__carlson_fd2) and el_d4 (four lanes, AVX2:
 * el__carlson_fd4, hermite_lanes_avx2.c), with its square root: one text of the
 * coefficients, the same operations in each. */
#define DEFINE_RF_SERIES(name, T, SQRT)                                                                       \
    static T name(T AF0, T x0, T y0, T f2, T AF)                                                              \
    {                                                                                                         \
        const T iA = 1.0 / AF, X = (AF0 - x0) * iA, Y = (AF0 - y0) * iA, Z = -X - Y;                          \
        const T E2 = X * Y - Z * Z, E3 = X * Y * Z;                                                           \
        /* the coefficients' quotients are folded by the compiler: multiplications, not the                  \
         * divisions (~4 cycles each, not pipelined) that dividing by them would cost */                      \
        return (1.0 + E2 * (-1.0 / 10.0 + E2 * (1.0 / 24.0 - 5.0 / 208.0 * E2) +                              \
                            E3 * (-3.0 / 44.0 + 1.0 / 16.0 * E2)) +                                           \
                E3 * (1.0 / 14.0 + 3.0 / 104.0 * E3)) * (f2 * SQRT(iA));                                      \
    }

#define DEFINE_RD_SERIES(name, T, SQRT)                                                                       \
    static T name(T AD0, T x0, T y0, T f2, T AD, T num, T den)                                                \
    {                                                                                                         \
        const T iA = 1.0 / AD, X = (AD0 - x0) * iA, Y = (AD0 - y0) * iA, Z = -(X + Y) / 3.0;                  \
        const T XY = X * Y, Z2 = Z * Z;                                                                       \
        const T E2 = XY - 6.0 * Z2, E3 = (3.0 * XY - 8.0 * Z2) * Z;                                           \
        const T E4 = 3.0 * (XY - Z2) * Z2, E5 = XY * Z2 * Z;                                                  \
        return iA * (f2 * SQRT(iA)) *                                                                         \
                   (1.0 + E2 * (-3.0 / 14.0 + E2 * (9.0 / 88.0 - 1.0 / 16.0 * E2 + 45.0 / 272.0 * E3) +       \
                                E3 * (-9.0 / 52.0) + E4 * (3.0 / 20.0) + E5 * (-9.0 / 68.0)) +                \
                    E3 * (1.0 / 6.0 + E3 * (3.0 / 40.0) + E4 * (-9.0 / 68.0)) + E4 * (-3.0 / 22.0) +          \
                    E5 * (3.0 / 26.0)) +                                                                      \
               3.0 * num / den;                                                                               \
    }

#endif
