/* fnav_math.h: vectors, quaternions, DCMs and Euler angles against analytic
 * answers. Tolerances: float32 build 2e-6, double build 1e-12. */
#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "footnav/fnav_math.h"
#include "fnav_testdata.h"

#if FNAV_USE_DOUBLE
#define TOL 1e-12
#else
#define TOL 2e-6
#endif

static const double k_pi = 3.14159265358979323846;

static void assert_vec(fnav_vec3_t v, double x, double y, double z, double tol)
{
    FNAV_ASSERT_CLOSE(v.v[0], x, tol, 0.0);
    FNAV_ASSERT_CLOSE(v.v[1], y, tol, 0.0);
    FNAV_ASSERT_CLOSE(v.v[2], z, tol, 0.0);
}

static void test_vec3(void **state)
{
    fnav_vec3_t a = fnav_vec3(FNAV_R(1.0), FNAV_R(2.0), FNAV_R(3.0));
    fnav_vec3_t b = fnav_vec3(FNAV_R(-4.0), FNAV_R(0.5), FNAV_R(2.0));
    (void)state;
    assert_vec(fnav_vec3_add(a, b), -3.0, 2.5, 5.0, TOL);
    assert_vec(fnav_vec3_sub(a, b), 5.0, 1.5, 1.0, TOL);
    FNAV_ASSERT_CLOSE(fnav_vec3_dot(a, b), -4.0 + 1.0 + 6.0, TOL, 0.0);
    assert_vec(fnav_vec3_cross(a, b), 2.0 * 2.0 - 3.0 * 0.5, 3.0 * -4.0 - 1.0 * 2.0, 1.0 * 0.5 - 2.0 * -4.0, TOL);
    FNAV_ASSERT_CLOSE(fnav_vec3_norm(a), sqrt(14.0), TOL, 0.0);
    FNAV_ASSERT_CLOSE(fnav_vec3_norm(fnav_vec3_normalize(b)), 1.0, TOL, 0.0);
    assert_vec(fnav_vec3_normalize(fnav_vec3_zero()), 0.0, 0.0, 0.0, 0.0);
    /* [a x] b == a x b */
    {
        fnav_vec3_t c = fnav_mat3_mul_vec3(fnav_mat3_skew(a), b);
        fnav_vec3_t d = fnav_vec3_cross(a, b);
        assert_vec(c, d.v[0], d.v[1], d.v[2], TOL);
    }
}

/* A rotation of +90 deg about z takes x to y (right hand). */
static void test_quat_rotvec_axis(void **state)
{
    fnav_quat_t q = fnav_quat_from_rotvec(fnav_vec3(FNAV_R(0.0), FNAV_R(0.0), (fnav_real_t)(k_pi / 2.0)));
    fnav_vec3_t r = fnav_quat_rotate(q, fnav_vec3(FNAV_R(1.0), FNAV_R(0.0), FNAV_R(0.0)));
    fnav_mat3_t c = fnav_quat_to_dcm(q);
    fnav_vec3_t r2 = fnav_mat3_mul_vec3(c, fnav_vec3(FNAV_R(1.0), FNAV_R(0.0), FNAV_R(0.0)));
    (void)state;
    assert_vec(r, 0.0, 1.0, 0.0, TOL);
    assert_vec(r2, 0.0, 1.0, 0.0, TOL);
    FNAV_ASSERT_CLOSE(q.q[0], cos(k_pi / 4.0), TOL, 0.0);
    FNAV_ASSERT_CLOSE(q.q[3], sin(k_pi / 4.0), TOL, 0.0);
}

/* rotvec -> quat -> rotvec is the identity, across both branches of the
 * small-angle series (1e-4 rad) and up to almost pi. */
static void test_quat_rotvec_roundtrip(void **state)
{
    static const double angles[] = { 0.0, 1e-9, 3e-5, 9.9e-5, 1.01e-4, 1e-3, 0.3, 1.7, 3.0 };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof angles / sizeof angles[0]; i++) {
        double a = angles[i];
        double ax[3] = { 0.48, -0.6, 0.64 }; /* unit */
        fnav_vec3_t phi = fnav_vec3((fnav_real_t)(a * ax[0]), (fnav_real_t)(a * ax[1]), (fnav_real_t)(a * ax[2]));
        fnav_quat_t q = fnav_quat_from_rotvec(phi);
        fnav_vec3_t back = fnav_quat_to_rotvec(q);
        double qn = sqrt((double)(q.q[0] * q.q[0] + q.q[1] * q.q[1] + q.q[2] * q.q[2] + q.q[3] * q.q[3]));
        FNAV_ASSERT_CLOSE(qn, 1.0, TOL, 0.0);
        /* relative to the angle (measured below 1e-7 in float: the input's
         * rounding): an absolute TOL let anything below 2e-6 rad pass, so
         * at 1e-9 rad, the only angle here in fnav_quat_to_rotvec's
         * small-angle branch, half or twice the vector passed */
        assert_vec(back, a * ax[0], a * ax[1], a * ax[2], TOL * a);
        FNAV_ASSERT_CLOSE(q.q[0], cos(a / 2.0), TOL, 0.0);
    }
}

/* Hamilton product composes rotations: rotating by q1 then q2 equals
 * rotating by q2*q1; conj inverts. */
static void test_quat_compose(void **state)
{
    fnav_quat_t q1 = fnav_quat_from_rotvec(fnav_vec3(FNAV_R(0.3), FNAV_R(-0.2), FNAV_R(0.9)));
    fnav_quat_t q2 = fnav_quat_from_rotvec(fnav_vec3(FNAV_R(-1.1), FNAV_R(0.4), FNAV_R(0.1)));
    fnav_vec3_t v = fnav_vec3(FNAV_R(0.7), FNAV_R(-1.3), FNAV_R(2.2));
    fnav_vec3_t a = fnav_quat_rotate(q2, fnav_quat_rotate(q1, v));
    fnav_vec3_t b = fnav_quat_rotate(fnav_quat_mul(q2, q1), v);
    fnav_vec3_t c = fnav_quat_rotate(fnav_quat_conj(q1), fnav_quat_rotate(q1, v));
    fnav_mat3_t m = fnav_mat3_mul(fnav_quat_to_dcm(q2), fnav_quat_to_dcm(q1));
    fnav_vec3_t d = fnav_mat3_mul_vec3(m, v);
    fnav_mat3_t mt = fnav_mat3_mul(fnav_quat_to_dcm(q1), fnav_mat3_transpose(fnav_quat_to_dcm(q1)));
    int i, j;
    (void)state;
    assert_vec(a, b.v[0], b.v[1], b.v[2], 4 * TOL);
    assert_vec(c, v.v[0], v.v[1], v.v[2], 4 * TOL);
    assert_vec(d, b.v[0], b.v[1], b.v[2], 4 * TOL);
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            FNAV_ASSERT_CLOSE(mt.m[i][j], i == j ? 1.0 : 0.0, 2 * TOL, 0.0);
        }
    }
}

/* ZYX Euler: C_nb = Rz(yaw) Ry(pitch) Rx(roll), checked element by element
 * against the closed form (Titterton & Weston eq. 3.47), and round trips. */
static void test_euler(void **state)
{
    static const double cases[][3] = {
        { 0.1, 0.2, 0.3 }, { -2.5, 1.2, -3.0 }, { 3.1, -0.7, 1.5 }, { 0.0, 0.0, 0.0 }, { -0.4, 1.5, 2.9 },
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        double r = cases[i][0], p = cases[i][1], y = cases[i][2];
        fnav_quat_t q = fnav_quat_from_euler((fnav_real_t)r, (fnav_real_t)p, (fnav_real_t)y);
        fnav_mat3_t c = fnav_quat_to_dcm(q);
        fnav_vec3_t e = fnav_quat_to_euler(q);
        double cr = cos(r), sr = sin(r), cp = cos(p), sp = sin(p), cy = cos(y), sy = sin(y);
        double tol = TOL * (1.0 / cp);
        FNAV_ASSERT_CLOSE(c.m[0][0], cp * cy, TOL, 0.0);
        FNAV_ASSERT_CLOSE(c.m[0][1], -cr * sy + sr * sp * cy, TOL, 0.0);
        FNAV_ASSERT_CLOSE(c.m[0][2], sr * sy + cr * sp * cy, TOL, 0.0);
        FNAV_ASSERT_CLOSE(c.m[1][0], cp * sy, TOL, 0.0);
        FNAV_ASSERT_CLOSE(c.m[1][1], cr * cy + sr * sp * sy, TOL, 0.0);
        FNAV_ASSERT_CLOSE(c.m[1][2], -sr * cy + cr * sp * sy, TOL, 0.0);
        FNAV_ASSERT_CLOSE(c.m[2][0], -sp, TOL, 0.0);
        FNAV_ASSERT_CLOSE(c.m[2][1], sr * cp, TOL, 0.0);
        FNAV_ASSERT_CLOSE(c.m[2][2], cr * cp, TOL, 0.0);
        FNAV_ASSERT_CLOSE(e.v[0], r, tol, 0.0);
        FNAV_ASSERT_CLOSE(e.v[1], p, tol, 0.0);
        FNAV_ASSERT_CLOSE(e.v[2], y, tol, 0.0);
    }
}

/* At pitch = +-90 deg the Euler extraction stays finite (clamped asin). */
static void test_euler_gimbal(void **state)
{
    fnav_quat_t q = fnav_quat_from_euler(FNAV_R(0.2), (fnav_real_t)(k_pi / 2.0), FNAV_R(0.5));
    fnav_vec3_t e;
    (void)state;
    q.q[0] *= FNAV_R(1.0000001); /* push |sin(pitch)| past 1 */
    q.q[2] *= FNAV_R(1.0000001);
    e = fnav_quat_to_euler(q);
    assert_true(fnav_vec3_isfinite(e));
    FNAV_ASSERT_CLOSE(e.v[1], k_pi / 2.0, 1e-3, 0.0);
}

/* At and near pitch = +-90 deg, roll and yaw are not defined one by one
 * (only yaw - roll at +90 deg, yaw + roll at -90 deg), but the three angles
 * returned must still describe the quaternion's rotation: the DCM rebuilt
 * from them equals the quaternion's. The pitch is then known to about
 * sqrt(eps) rad (asin near 1), so the tolerance is 8 sqrt(eps); a wrong pair
 * is off by O(1) (from_euler(-pi, pi/2, 0) came back as (0, pi/2, 0), which
 * maps body y to -y). */
static void test_euler_gimbal_rotation(void **state)
{
    static const double cases[][3] = {
        { -3.14159265358979, 1.57079632679490, 0.0 }, { 0.2, 1.57079632679490, 0.5 },
        { 2.9, 1.57079632679490, -2.8 },              { -3.0, -1.57079632679490, 0.1 },
        { 0.7, -1.57079632679490, 3.1 },              { 1.0, 1.57079632679490 - 2e-4, -1.0 },
        { -2.0, -1.57079632679490 + 2e-4, 2.5 },     { 3.0, 1.57079632679490 - 1e-6, -3.0 },
    };
    const double tol = 8.0 * sqrt((double)FNAV_REAL_EPSILON);
    size_t i;
    int r, c;
    (void)state;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        fnav_quat_t q = fnav_quat_from_euler((fnav_real_t)cases[i][0], (fnav_real_t)cases[i][1],
                                             (fnav_real_t)cases[i][2]);
        fnav_vec3_t e = fnav_quat_to_euler(q);
        fnav_mat3_t want = fnav_quat_to_dcm(q);
        fnav_mat3_t got = fnav_quat_to_dcm(fnav_quat_from_euler(e.v[0], e.v[1], e.v[2]));
        assert_true(fnav_vec3_isfinite(e));
        assert_true((double)e.v[0] > -k_pi - 1e-6 && (double)e.v[0] <= k_pi + 1e-6);
        assert_true((double)e.v[2] > -k_pi - 1e-6 && (double)e.v[2] <= k_pi + 1e-6);
        for (r = 0; r < 3; r++) {
            for (c = 0; c < 3; c++) {
                FNAV_ASSERT_CLOSE(got.m[r][c], want.m[r][c], tol, 0.0);
            }
        }
    }
}

static void test_wrap_and_normalize(void **state)
{
    fnav_quat_t z = fnav_quat(FNAV_R(0.0), FNAV_R(0.0), FNAV_R(0.0), FNAV_R(0.0));
    fnav_quat_t n = fnav_quat_normalize(fnav_quat(FNAV_R(-2.0), FNAV_R(0.0), FNAV_R(0.0), FNAV_R(0.0)));
    (void)state;
    FNAV_ASSERT_CLOSE(fnav_wrap_pi(FNAV_R(0.5)), 0.5, TOL, 0.0);
    FNAV_ASSERT_CLOSE(fnav_wrap_pi((fnav_real_t)(k_pi + 0.25)), -k_pi + 0.25, 4 * TOL, 0.0);
    FNAV_ASSERT_CLOSE(fnav_wrap_pi((fnav_real_t)(-k_pi - 0.25)), k_pi - 0.25, 4 * TOL, 0.0);
    FNAV_ASSERT_CLOSE(fnav_wrap_pi((fnav_real_t)(-k_pi)), k_pi, 4 * TOL, 0.0);
    FNAV_ASSERT_CLOSE(fnav_wrap_pi((fnav_real_t)(20.0 * k_pi + 1.0)), 1.0, 1e-5, 0.0);
    /* bounded work and a result in range for huge finite angles */
    {
        fnav_real_t w = fnav_wrap_pi(FNAV_R(1.0e30));
        assert_true(w <= FNAV_PI && w >= -FNAV_PI);
    }
    /* zero quaternion -> identity; negative scalar part flipped */
    assert_true(fnav_quat_normalize(z).q[0] == FNAV_R(1.0));
    assert_true(n.q[0] == FNAV_R(1.0));
    assert_true(fnav_isfinite(FNAV_R(1.0)) && !fnav_isfinite((fnav_real_t)NAN) && !fnav_isfinite((fnav_real_t)INFINITY));
    FNAV_ASSERT_CLOSE(fnav_clamp(FNAV_R(2.0), FNAV_R(-1.0), FNAV_R(1.0)), 1.0, 0.0, 0.0);
}

/* fnav_isfinite on every class of value, against the C library's isfinite:
 * NaN of either sign, +-Inf, +-the largest finite value, the smallest and
 * the largest denormal of either sign, +-0 and 1. The values go through a
 * volatile so the inlined code is what is tested, not a constant folded by
 * the compiler. */
static void test_isfinite(void **state)
{
    static const int expect[] = {0, 0, 0, 0, 1, 1, 1, 1, 1, 1, 1, 1, 1};
    volatile fnav_real_t v[13];
    fnav_vec3_t a;
    size_t i;
    (void)state;
    v[0] = (fnav_real_t)NAN;
    v[1] = -(fnav_real_t)NAN;
    v[2] = (fnav_real_t)INFINITY;
    v[3] = -(fnav_real_t)INFINITY;
    v[4] = FNAV_REAL_MAX;
    v[5] = -FNAV_REAL_MAX;
#if FNAV_USE_DOUBLE
    v[6] = ldexp(1.0, -1074);          /* smallest denormal */
    v[7] = DBL_MIN - ldexp(1.0, -1074); /* largest denormal */
#else
    v[6] = ldexpf(1.0f, -149);
    v[7] = FLT_MIN - ldexpf(1.0f, -149);
#endif
    v[8] = -v[6];
    v[9] = -v[7];
    v[10] = FNAV_R(0.0);
    v[11] = -FNAV_R(0.0);
    v[12] = FNAV_R(1.0);
    /* the denormals are denormals (not flushed to zero, below the smallest normal) */
#if FNAV_USE_DOUBLE
    assert_true(v[6] > 0.0 && v[7] > v[6] && v[7] < DBL_MIN);
#else
    assert_true(v[6] > 0.0f && v[7] > v[6] && v[7] < FLT_MIN);
#endif
    for (i = 0; i < sizeof expect / sizeof expect[0]; i++) {
        fnav_real_t x = v[i];
        assert_int_equal(isfinite(x) != 0, expect[i]);
        assert_int_equal(fnav_isfinite(x) != 0, expect[i]);
    }
    a = fnav_vec3(FNAV_REAL_MAX, -FNAV_R(0.0), v[6]);
    assert_true(fnav_vec3_isfinite(a));
    a.v[2] = v[1];
    assert_false(fnav_vec3_isfinite(a));
}

/* fnav_one_minus_exp_neg against the C library's expm1 in double (an
 * independent computation): relative error within 2e-6 in float from x =
 * 1e-12 (an AR(1) at 1 kHz with tau of hours has 2 dt/tau near 1e-7) to 80,
 * where 1 - c*c had errors of per cent; 0 for x <= 0 and NaN. */
static void test_one_minus_exp_neg(void **state)
{
    double x, worst = 0.0;
    (void)state;
    assert_true(fnav_one_minus_exp_neg(FNAV_R(0.0)) == FNAV_R(0.0));
    assert_true(fnav_one_minus_exp_neg(FNAV_R(-1.0)) == FNAV_R(0.0));
    assert_true(fnav_one_minus_exp_neg((fnav_real_t)NAN) == FNAV_R(0.0));
    for (x = 1e-12; x <= 80.0; x *= 1.01) {
        const fnav_real_t xr = (fnav_real_t)x;
        const double ref = -expm1(-(double)xr), rel = fabs((double)fnav_one_minus_exp_neg(xr) - ref) / ref;
        worst = rel > worst ? rel : worst;
        assert_true(rel <= (FNAV_USE_DOUBLE ? 1e-15 : 2e-6));
    }
    fprintf(stderr, "one_minus_exp_neg: worst relative error %.3g\n", worst);
}

/* fnav_exp_neg: in the float build exactly the bits of the same algorithm
 * run in numpy float32 (vectors/math/gen_exp_neg.py); in both builds within
 * its documented relative error of exp(-x); the edge values. */
static void test_exp_neg(void **state)
{
    char path[512], line[256];
    FILE *f;
    int rows = 0;
    double x, worst1 = 0.0, worst20 = 0.0;
    (void)state;
    assert_true(fnav_exp_neg(FNAV_R(0.0)) == FNAV_R(1.0));
    assert_true(fnav_exp_neg(FNAV_R(-3.0)) == FNAV_R(1.0));
    assert_true(fnav_exp_neg((fnav_real_t)NAN) == FNAV_R(1.0));
#if !FNAV_USE_DOUBLE
    assert_true(fnav_exp_neg(FNAV_R(150.0)) == FNAV_R(0.0));
    assert_true(fnav_exp_neg((fnav_real_t)INFINITY) == FNAV_R(0.0));
#endif
    for (x = 1e-7; x <= 80.0; x *= 1.01) {
        const fnav_real_t xr = (fnav_real_t)x;
        const double ref = exp(-(double)xr), rel = fabs((double)fnav_exp_neg(xr) - ref) / ref;
        if (x <= 1.0 && rel > worst1) {
            worst1 = rel;
        } else if (x <= 20.0 && rel > worst20) {
            worst20 = rel;
        }
        assert_true(rel <= (x <= 1.0 ? 1.1e-6 : x <= 20.0 ? 3.4e-5 : 1.4e-4));
    }
    fprintf(stderr, "exp_neg: worst relative error %.3g (x <= 1), %.3g (x <= 20)\n", worst1, worst20);
    assert_int_equal(fnav_vector_path("math/exp_neg.csv", path, sizeof path), 0);
    f = fopen(path, "r");
    assert_non_null(f);
    assert_non_null(fgets(line, sizeof line, f)); /* header */
    while (fgets(line, sizeof line, f) != NULL) {
        unsigned long xb, rb;
        assert_int_equal(sscanf(line, "%lx,%lx", &xb, &rb), 2);
#if !FNAV_USE_DOUBLE
        {
            uint32_t xu = (uint32_t)xb, ru;
            float xf, r;
            memcpy(&xf, &xu, sizeof xf);
            r = fnav_exp_neg(xf);
            memcpy(&ru, &r, sizeof ru);
            if (ru != (uint32_t)rb) {
                fprintf(stderr, "exp_neg(%.9g) = 0x%08lx, expected 0x%08lx\n", (double)xf, (unsigned long)ru, rb);
            }
            assert_true(ru == (uint32_t)rb);
        }
#endif
        rows++;
    }
    fclose(f);
    assert_true(rows > 400);
}

/* fnav_ns_to_us_u32 against the formula it replaced in the stance detector,
 * (uint32_t)(uint64_t)(t_ns / 1000) (C99: the quotient truncated toward
 * zero; a 64-bit division, a call to __aeabi_ldivmod on the Cortex-M4F):
 * the same bits for every int64_t. The edge cases: 0, the signs, each side
 * of every multiple of 1000 near 0, the quotient's wraps of 2^32 (t_ns near
 * k 2^32 1000 for k = +-1, +-2 and the largest k), the bits 2^32 and 2^48
 * of t_ns, INT64_MIN and INT64_MAX and near them; then a 400 Hz walk of 2.5 ms steps
 * across the first wrap and through zero, and 2,000,000 pseudo-random
 * values spread over the whole range (xorshift64, every magnitude). */
static uint32_t us_reference(int64_t t_ns)
{
    return (uint32_t)((uint64_t)(t_ns / 1000));
}

static void check_i64(int64_t x)
{
    const fnav_real_t a = fnav_i64_to_real(x), b = (fnav_real_t)x;
    if (memcmp(&a, &b, sizeof a) != 0) {
        fail_msg("fnav_i64_to_real(%lld) = %.17g, (fnav_real_t)x = %.17g", (long long)x, (double)a, (double)b);
    }
}

/* fnav_i64_to_real() (fnav_math.h): the bits of (fnav_real_t)x for every
 * int64_t, through int32_t or not: around 0, 2^24 (float's last exact
 * integer), 2^31 (the int32 bounds: both paths either side), 2^53, the
 * int64 bounds, halfway cases of float and random values of every
 * magnitude, either sign. */
static void test_i64_to_real(void **state)
{
    const int64_t centres[] = { 0, (int64_t)1 << 24, (int64_t)1 << 25, 2147483647, (int64_t)1 << 31, (int64_t)1 << 32,
                                (int64_t)1 << 53, INT64_MAX - 3000, 2500000, 1000000000, 2100000000,
                                (int64_t)16777217 * 128 };
    uint64_t x = 0x9e3779b97f4a7c15u;
    size_t c;
    int64_t d;
    long i;
    (void)state;
    assert_true(fnav_i64_to_real(0) == FNAV_R(0.0));
    assert_true(fnav_i64_to_real(-1) == FNAV_R(-1.0));
    assert_true(fnav_i64_to_real(2500000) == FNAV_R(2500000.0));
    check_i64(INT32_MAX);
    check_i64(INT32_MIN);
    check_i64((int64_t)INT32_MIN - 1);
    check_i64((int64_t)INT32_MAX + 1);
    check_i64(INT64_MAX);
    check_i64(INT64_MIN);
    check_i64(INT64_MIN + 1);
    check_i64(16777217);  /* 2^24 + 1: not a float, rounds to even */
    check_i64(16777219);  /* 2^24 + 3: rounds up */
    check_i64(-16777217);
    check_i64(2147483520);  /* INT32_MAX - 127: the largest float below 2^31 (exact) */
    check_i64(2147483584);  /* halfway between the last two floats under 2^31 */
    check_i64(-2147483584);
    for (c = 0; c < sizeof centres / sizeof centres[0]; c++) {
        for (d = -2001; d <= 2001; d++) {
            check_i64(centres[c] + d);
            check_i64(-(centres[c] + d));
        }
    }
    for (i = 0; i < 2000000; i++) {
        int64_t v;
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        /* every magnitude: the draw shifted right by 1..63 bits, either sign */
        v = (int64_t)(x >> (1u + (unsigned)(i % 63)));
        check_i64((i & 64) ? -v : v);
    }
}

static void check_us(int64_t t_ns)
{
    if (fnav_ns_to_us_u32(t_ns) != us_reference(t_ns)) {
        fail_msg("fnav_ns_to_us_u32(%lld) = %lu, (uint32_t)(t_ns / 1000) = %lu", (long long)t_ns,
                 (unsigned long)fnav_ns_to_us_u32(t_ns), (unsigned long)us_reference(t_ns));
    }
}

static void test_ns_to_us_u32(void **state)
{
    const int64_t wrap_ns = (int64_t)4294967296 * 1000; /* the quotient reaches 2^32 */
    const int64_t centres[] = { 0, 1000, 999999, 1000000000, wrap_ns, 2 * wrap_ns, wrap_ns / 2,
                                (int64_t)4294967296, (int64_t)1 << 48, (INT64_MAX / wrap_ns) * wrap_ns,
                                INT64_MAX - 3000, INT64_MIN + 3000 };
    uint64_t x = 0x9e3779b97f4a7c15u;
    size_t c;
    int64_t d, t;
    long i;
    (void)state;
    assert_int_equal(fnav_ns_to_us_u32(0), 0);
    assert_int_equal(fnav_ns_to_us_u32(999), 0);
    assert_int_equal(fnav_ns_to_us_u32(-999), 0);           /* truncated toward zero */
    assert_int_equal(fnav_ns_to_us_u32(1000), 1);
    assert_true(fnav_ns_to_us_u32(-1000) == 0xffffffffu);    /* -1 modulo 2^32 */
    assert_true(fnav_ns_to_us_u32(wrap_ns - 1) == 0xffffffffu);
    assert_true(fnav_ns_to_us_u32(wrap_ns) == 0u);
    check_us(INT64_MAX);
    check_us(INT64_MIN);
    check_us(INT64_MIN + 1);
    for (c = 0; c < sizeof centres / sizeof centres[0]; c++) {
        for (d = -2001; d <= 2001; d++) {
            check_us(centres[c] + d);
            check_us(-(centres[c] + d));
        }
    }
    for (t = -wrap_ns - 25000000, i = 0; i < 200000; i++, t += 2500000) {
        check_us(t); /* a walk at 400 Hz across the wrap at -2^32 us */
    }
    for (t = wrap_ns - 250000000, i = 0; i < 200000; i++, t += 2500000) {
        check_us(t); /* and at +2^32 us */
    }
    for (t = -250000000, i = 0; i < 200; i++, t += 2500000) {
        check_us(t); /* and through 0 */
    }
    for (i = 0; i < 2000000; i++) {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        /* every magnitude: the draw shifted right by 1..63 bits, either sign;
         * and the draw itself, any int64_t */
        check_us((int64_t)(x >> ((x & 63u) | 1u)) * ((x & 64u) ? -1 : 1));
        check_us((int64_t)x);
    }
}

/* fnav_ns_to_ms_u32 (the Cortex-M port's STATUS uptime; fnav_div_i64_u32
 * with a shift), against C's 64-bit division modulo 2^32: both sides of
 * each millisecond edge (also past 2^32 ms, where uptime_ms wraps), of
 * every power of two of y = ns >> 6 up to 2^57 (among them the long
 * division's digit edges 2^16 and 2^32), the extremes, and random values
 * of every magnitude and sign */
static void check_ms_of_ns(int64_t ns)
{
    if (fnav_ns_to_ms_u32(ns) != (uint32_t)(ns / 1000000)) {
        fail_msg("ns %lld: %lu, the division %lu", (long long)ns, (unsigned long)fnav_ns_to_ms_u32(ns),
                 (unsigned long)(uint32_t)(ns / 1000000));
    }
}

static void test_ns_to_ms_u32(void **state)
{
    static const int64_t ms[] = {0, 1, 2, 999, 1000, 65535, 65536, 4294967295LL, 4294967296LL, 4294967297LL,
                                 1099511627776LL, 9223372036854LL};
    uint64_t r = UINT64_C(0x9e3779b97f4a7c15);
    size_t i;
    int k, d;
    (void)state;
    for (i = 0; i < sizeof ms / sizeof ms[0]; i++) {
        for (d = -2; d <= 2; d++) {
            const int64_t ns = ms[i] * 1000000 + d;
            check_ms_of_ns(ns);
            check_ms_of_ns(-ns);
        }
    }
    for (k = 0; k < 58; k++) { /* y = 2^k - 1, 2^k, 2^k + 1 (every digit edge among them) */
        for (d = -1; d <= 1; d++) {
            const int64_t y = (int64_t)(UINT64_C(1) << k) + d;
            int e;
            for (e = 0; e < 64 && y >= 0 && y < (INT64_C(1) << 57); e += 21) { /* shifted out: none, some, all */
                check_ms_of_ns(y * 64 + e); /* y < 2^57: no overflow */
                check_ms_of_ns(-(y * 64 + e));
            }
        }
    }
    check_ms_of_ns(INT64_MAX);
    check_ms_of_ns(INT64_MIN);
    check_ms_of_ns(INT64_MIN + 1);
    assert_true(fnav_ns_to_ms_u32(INT64_MIN) == (uint32_t)(INT64_MIN / 1000000));
    assert_int_equal(fnav_ns_to_ms_u32(INT64_C(4294967296000000)), 0u); /* 2^32 ms: uptime_ms wraps */
    for (i = 0; i < 2000000u; i++) {
        uint64_t v;
        r ^= r << 13; /* xorshift64 (Marsaglia 2003) */
        r ^= r >> 7;
        r ^= r << 17;
        v = r >> (r % 61u); /* every magnitude, 2^3 .. 2^64 */
        check_ms_of_ns((int64_t)v);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_vec3),
        cmocka_unit_test(test_quat_rotvec_axis),
        cmocka_unit_test(test_quat_rotvec_roundtrip),
        cmocka_unit_test(test_quat_compose),
        cmocka_unit_test(test_euler),
        cmocka_unit_test(test_euler_gimbal),
        cmocka_unit_test(test_euler_gimbal_rotation),
        cmocka_unit_test(test_wrap_and_normalize),
        cmocka_unit_test(test_exp_neg),
        cmocka_unit_test(test_one_minus_exp_neg),
        cmocka_unit_test(test_isfinite),
        cmocka_unit_test(test_ns_to_us_u32),
        cmocka_unit_test(test_ns_to_ms_u32),
        cmocka_unit_test(test_i64_to_real),
    };
    return cmocka_run_group_tests_name("math", tests, NULL, NULL);
}
