/*
 * One text for every lane width: the code of carlson_lanes.h and hermite_lanes_body.h
 * is written in these names, and the file that includes it sets LANES_W (2: lanes.h's
 * el_d2, SSE2; 4: el_d4, AVX, in an object compiled for it) first. LN(f) names the
 * width's function (f2, f4).
 */
#if LANES_W == 2
#define LV el_d2
#define LM el_m2
#define lv_sel el_d2_sel
#define lv_sqrt el_d2_sqrt
#define lv_and el_d2_and
#define lv_abs el_d2_abs
#define lv_finite el_d2_finite
#define lm_or el_m2_or
#define lm_and el_m2_and
#define lm_andnot el_m2_andnot
#define lm_any el_m2_any
#define LV1(c) ((el_d2){(c), (c)})
#define LM_ALL ((el_m2){-1, -1})
#define LM_NONE ((el_m2){0, 0})
#define LN(f) f##2
#elif LANES_W == 4
#define LV el_d4
#define LM el_m4
#define lv_sel el_d4_sel
#define lv_sqrt el_d4_sqrt
#define lv_and el_d4_and
#define lv_abs el_d4_abs
#define lv_finite el_d4_finite
#define lm_or el_m4_or
#define lm_and el_m4_and
#define lm_andnot el_m4_andnot
#define lm_any el_m4_any
#define LV1(c) ((el_d4){(c), (c), (c), (c)})
#define LM_ALL ((el_m4){-1, -1, -1, -1})
#define LM_NONE ((el_m4){0, 0, 0, 0})
#define LN(f) f##4
#else
#error "LANES_W is 2 or 4"
#endif
