/**
 * @file fnav_math.h
 * @brief Small value types (3-vector, 3x3 matrix, quaternion) with
 *        static inline helpers that take and return values, so that
 *        formulas read like the textbook (x-io Fusion style).
 *
 * Conventions (docs/frames.md):
 * - Quaternion q = [w, x, y, z], Hamilton product, unit norm, q_nb rotates
 *   body-frame vectors into the navigation frame: v_n = q_nb * v_b * q_nb^-1.
 * - C_nb is the matching direction cosine matrix, v_n = C_nb v_b.
 * - Euler angles are ZYX (yaw psi, pitch theta, roll phi):
 *   C_nb = Rz(psi) Ry(theta) Rx(phi)  (Titterton & Weston, eq. 3.47).
 */
#ifndef FNAV_MATH_H
#define FNAV_MATH_H

#include "fnav_types.h"

#ifdef __cplusplus
extern "C" {
#endif

/** 3-vector: element array or named axes. */
typedef union {
    fnav_real_t v[3];
    struct {
        fnav_real_t x, y, z;
    } axis;
} fnav_vec3_t;

/** 3x3 matrix, row major: m[row][col]. */
typedef struct {
    fnav_real_t m[3][3];
} fnav_mat3_t;

/** Quaternion [w, x, y, z]. */
typedef union {
    fnav_real_t q[4];
    struct {
        fnav_real_t w, x, y, z;
    } e;
} fnav_quat_t;

/* ---------------------------------------------------------------- vec3 */

/**
 * exp(-x) for x >= 0 from additions, multiplications and comparisons only,
 * so that the float build gives the same bits on every IEEE-754 target: the
 * filter's decay factors exp(-dt/tau) must not depend on the C library
 * (newlib's and glibc's expf differ in the last bit for some arguments, and
 * one ulp in one decay factor moves a 77 m walk's yaw by about 1e-4 rad:
 * docs/firmware.md, "Host and target agree"). x is halved k times until it
 * is at most 1/16, exp(-y) is its Taylor polynomial of degree 6 there (the
 * first omitted term below 1e-12), and the result is squared k times
 * (each squaring doubles the relative rounding error). In float the
 * relative error is at most 1.1e-6 for x <= 1, 3.4e-5 for x <= 20 and
 * 1.4e-4 up to 80 (the maxima over every float in [1e-7, 80]:
 * `/usr/bin/python3 vectors/math/gen_exp_neg.py --exhaustive`); 0 above 100.
 * The double build uses the C library's exp (it is the host's accuracy
 * reference).
 * @param x  non-negative; x <= 0 (or NaN) gives 1
 */
static inline fnav_real_t fnav_exp_neg(fnav_real_t x)
{
#if FNAV_USE_DOUBLE
    return x > 0.0 ? exp(-x) : 1.0;
#else
    int k = 0;
    fnav_real_t y = x, p;
    if (!(x > FNAV_R(0.0))) {
        return FNAV_R(1.0);
    }
    if (x > FNAV_R(100.0)) {
        return FNAV_R(0.0); /* below the smallest float, and no halving loop for an infinity */
    }
    while (y > FNAV_R(0.0625)) {
        y *= FNAV_R(0.5);
        k++;
    }
    /* 1 - y + y^2/2 - y^3/6 + y^4/24 - y^5/120 + y^6/720, Horner */
    p = FNAV_R(1.0) - y * (FNAV_R(1.0) - y * (FNAV_R(0.5) - y * (FNAV_R(1.0) / FNAV_R(6.0) -
        y * (FNAV_R(1.0) / FNAV_R(24.0) - y * (FNAV_R(1.0) / FNAV_R(120.0) - y * (FNAV_R(1.0) / FNAV_R(720.0)))))));
    while (k > 0) {
        p *= p;
        k--;
    }
    return p;
#endif
}

/**
 * 1 - exp(-x) for x >= 0 without the cancellation of 1 - fnav_exp_neg(x)
 * at small x: the AR(1) driving variance sigma^2 (1 - c^2) = sigma^2 (1 -
 * exp(-2 dt/tau)) has dt/tau of 1e-6 and below, where 1 - c*c in float
 * keeps a few bits (c's rounding, up to 6e-8, against 2 dt/tau: up to
 * 0.4 % at 5 ms with tau 720 s, 11 % at 1 ms with tau 3600 s). Below
 * x = 1/16 the Taylor series x (1 - x/2 (1 - x/3 (...))) to degree 6
 * (first omitted term x^7/5040: relative 1.2e-11), above it 1 -
 * fnav_exp_neg(x), which loses nothing there. Same operations on every
 * target, as fnav_exp_neg; the double build uses expm1.
 * @param x  non-negative; x <= 0 (or NaN) gives 0
 */
static inline fnav_real_t fnav_one_minus_exp_neg(fnav_real_t x)
{
#if FNAV_USE_DOUBLE
    return x > 0.0 ? -expm1(-x) : 0.0;
#else
    if (!(x > FNAV_R(0.0))) {
        return FNAV_R(0.0);
    }
    if (x > FNAV_R(0.0625)) {
        return FNAV_R(1.0) - fnav_exp_neg(x);
    }
    return x * (FNAV_R(1.0) - x * FNAV_R(0.5) * (FNAV_R(1.0) - x * (FNAV_R(1.0) / FNAV_R(3.0)) *
                (FNAV_R(1.0) - x * FNAV_R(0.25) * (FNAV_R(1.0) - x * FNAV_R(0.2) *
                (FNAV_R(1.0) - x * (FNAV_R(1.0) / FNAV_R(6.0)))))));
#endif
}

static inline fnav_vec3_t fnav_vec3(fnav_real_t x, fnav_real_t y, fnav_real_t z)
{
    fnav_vec3_t r;
    r.v[0] = x;
    r.v[1] = y;
    r.v[2] = z;
    return r;
}

static inline fnav_vec3_t fnav_vec3_from(const fnav_real_t a[3])
{
    return fnav_vec3(a[0], a[1], a[2]);
}

static inline fnav_vec3_t fnav_vec3_zero(void)
{
    return fnav_vec3(FNAV_R(0.0), FNAV_R(0.0), FNAV_R(0.0));
}

static inline fnav_vec3_t fnav_vec3_add(fnav_vec3_t a, fnav_vec3_t b)
{
    return fnav_vec3(a.v[0] + b.v[0], a.v[1] + b.v[1], a.v[2] + b.v[2]);
}

static inline fnav_vec3_t fnav_vec3_sub(fnav_vec3_t a, fnav_vec3_t b)
{
    return fnav_vec3(a.v[0] - b.v[0], a.v[1] - b.v[1], a.v[2] - b.v[2]);
}

static inline fnav_vec3_t fnav_vec3_scale(fnav_vec3_t a, fnav_real_t s)
{
    return fnav_vec3(a.v[0] * s, a.v[1] * s, a.v[2] * s);
}

static inline fnav_real_t fnav_vec3_dot(fnav_vec3_t a, fnav_vec3_t b)
{
    return a.v[0] * b.v[0] + a.v[1] * b.v[1] + a.v[2] * b.v[2];
}

static inline fnav_vec3_t fnav_vec3_cross(fnav_vec3_t a, fnav_vec3_t b)
{
    return fnav_vec3(a.v[1] * b.v[2] - a.v[2] * b.v[1],
                     a.v[2] * b.v[0] - a.v[0] * b.v[2],
                     a.v[0] * b.v[1] - a.v[1] * b.v[0]);
}

static inline fnav_real_t fnav_vec3_norm(fnav_vec3_t a)
{
    return fnav_sqrt(fnav_vec3_dot(a, a));
}

/** Unit vector along a; the zero vector is returned unchanged. */
static inline fnav_vec3_t fnav_vec3_normalize(fnav_vec3_t a)
{
    fnav_real_t n = fnav_vec3_norm(a);
    return (n > FNAV_R(0.0)) ? fnav_vec3_scale(a, FNAV_R(1.0) / n) : a;
}

static inline FNAV_ALWAYS_INLINE int fnav_vec3_isfinite(fnav_vec3_t a)
{
    return fnav_isfinite(a.v[0]) && fnav_isfinite(a.v[1]) && fnav_isfinite(a.v[2]);
}

/* ---------------------------------------------------------------- mat3 */

static inline fnav_mat3_t fnav_mat3_identity(void)
{
    fnav_mat3_t r;
    int i, j;
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            r.m[i][j] = (i == j) ? FNAV_R(1.0) : FNAV_R(0.0);
        }
    }
    return r;
}

static inline fnav_vec3_t fnav_mat3_mul_vec3(fnav_mat3_t a, fnav_vec3_t x)
{
    return fnav_vec3(a.m[0][0] * x.v[0] + a.m[0][1] * x.v[1] + a.m[0][2] * x.v[2],
                     a.m[1][0] * x.v[0] + a.m[1][1] * x.v[1] + a.m[1][2] * x.v[2],
                     a.m[2][0] * x.v[0] + a.m[2][1] * x.v[1] + a.m[2][2] * x.v[2]);
}

static inline fnav_mat3_t fnav_mat3_transpose(fnav_mat3_t a)
{
    fnav_mat3_t r;
    int i, j;
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            r.m[i][j] = a.m[j][i];
        }
    }
    return r;
}

static inline fnav_mat3_t fnav_mat3_mul(fnav_mat3_t a, fnav_mat3_t b)
{
    fnav_mat3_t r;
    int i, j;
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            r.m[i][j] = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j];
        }
    }
    return r;
}

/** Skew-symmetric matrix [a x], so that [a x] b = a x b. */
static inline fnav_mat3_t fnav_mat3_skew(fnav_vec3_t a)
{
    fnav_mat3_t r;
    r.m[0][0] = FNAV_R(0.0);
    r.m[0][1] = -a.v[2];
    r.m[0][2] = a.v[1];
    r.m[1][0] = a.v[2];
    r.m[1][1] = FNAV_R(0.0);
    r.m[1][2] = -a.v[0];
    r.m[2][0] = -a.v[1];
    r.m[2][1] = a.v[0];
    r.m[2][2] = FNAV_R(0.0);
    return r;
}

/* ---------------------------------------------------------------- quat */

static inline fnav_quat_t fnav_quat(fnav_real_t w, fnav_real_t x, fnav_real_t y, fnav_real_t z)
{
    fnav_quat_t r;
    r.q[0] = w;
    r.q[1] = x;
    r.q[2] = y;
    r.q[3] = z;
    return r;
}

static inline fnav_quat_t fnav_quat_identity(void)
{
    return fnav_quat(FNAV_R(1.0), FNAV_R(0.0), FNAV_R(0.0), FNAV_R(0.0));
}

/** Hamilton product a * b. */
static inline fnav_quat_t fnav_quat_mul(fnav_quat_t a, fnav_quat_t b)
{
    return fnav_quat(a.q[0] * b.q[0] - a.q[1] * b.q[1] - a.q[2] * b.q[2] - a.q[3] * b.q[3],
                     a.q[0] * b.q[1] + a.q[1] * b.q[0] + a.q[2] * b.q[3] - a.q[3] * b.q[2],
                     a.q[0] * b.q[2] - a.q[1] * b.q[3] + a.q[2] * b.q[0] + a.q[3] * b.q[1],
                     a.q[0] * b.q[3] + a.q[1] * b.q[2] - a.q[2] * b.q[1] + a.q[3] * b.q[0]);
}

static inline fnav_quat_t fnav_quat_conj(fnav_quat_t a)
{
    return fnav_quat(a.q[0], -a.q[1], -a.q[2], -a.q[3]);
}

/** Unit quaternion along a, with the scalar part made non-negative;
 *  a zero quaternion becomes the identity. */
static inline fnav_quat_t fnav_quat_normalize(fnav_quat_t a)
{
    fnav_real_t n = fnav_sqrt(a.q[0] * a.q[0] + a.q[1] * a.q[1] + a.q[2] * a.q[2] + a.q[3] * a.q[3]);
    fnav_real_t s;
    if (!(n > FNAV_R(0.0))) {
        return fnav_quat_identity();
    }
    s = (a.q[0] < FNAV_R(0.0)) ? -FNAV_R(1.0) / n : FNAV_R(1.0) / n;
    return fnav_quat(a.q[0] * s, a.q[1] * s, a.q[2] * s, a.q[3] * s);
}

/** Exact quaternion of the rotation vector phi (axis * angle, rad):
 *  q = [cos(|phi|/2), sin(|phi|/2) phi/|phi|] (Titterton & Weston eq. 11.33);
 *  a Taylor series below 1e-4 rad keeps float32 accurate. */
static inline fnav_quat_t fnav_quat_from_rotvec(fnav_vec3_t phi)
{
    fnav_real_t a2 = fnav_vec3_dot(phi, phi);
    fnav_real_t a = fnav_sqrt(a2);
    fnav_real_t c, s;
    if (a < FNAV_R(1.0e-4)) {
        c = FNAV_R(1.0) - a2 / FNAV_R(8.0);
        s = FNAV_R(0.5) - a2 / FNAV_R(48.0);
    } else {
        c = fnav_cos(FNAV_R(0.5) * a);
        s = fnav_sin(FNAV_R(0.5) * a) / a;
    }
    return fnav_quat(c, s * phi.v[0], s * phi.v[1], s * phi.v[2]);
}

/** Rotation vector of a unit quaternion (inverse of fnav_quat_from_rotvec),
 *  angle in [0, pi]. */
static inline fnav_vec3_t fnav_quat_to_rotvec(fnav_quat_t q)
{
    fnav_real_t w = q.q[0];
    fnav_real_t sn, a, k;
    fnav_vec3_t u = fnav_vec3(q.q[1], q.q[2], q.q[3]);
    if (w < FNAV_R(0.0)) {
        w = -w;
        u = fnav_vec3_scale(u, -FNAV_R(1.0));
    }
    sn = fnav_vec3_norm(u);
    if (sn < FNAV_R(1.0e-6)) {
        k = FNAV_R(2.0) / ((w > FNAV_R(0.0)) ? w : FNAV_R(1.0));
    } else {
        a = FNAV_R(2.0) * fnav_atan2(sn, w);
        k = a / sn;
    }
    return fnav_vec3_scale(u, k);
}

/** Rotate v by q: q * [0 v] * q^-1. */
static inline fnav_vec3_t fnav_quat_rotate(fnav_quat_t q, fnav_vec3_t v)
{
    /* v' = v + 2 w (u x v) + 2 u x (u x v), u = vector part */
    fnav_vec3_t u = fnav_vec3(q.q[1], q.q[2], q.q[3]);
    fnav_vec3_t t = fnav_vec3_scale(fnav_vec3_cross(u, v), FNAV_R(2.0));
    return fnav_vec3_add(fnav_vec3_add(v, fnav_vec3_scale(t, q.q[0])), fnav_vec3_cross(u, t));
}

/** DCM C_nb of the unit quaternion q_nb (Titterton & Weston eq. 3.63). */
static inline fnav_mat3_t fnav_quat_to_dcm(fnav_quat_t q)
{
    fnav_mat3_t c;
    fnav_real_t w = q.q[0], x = q.q[1], y = q.q[2], z = q.q[3];
    c.m[0][0] = w * w + x * x - y * y - z * z;
    c.m[0][1] = FNAV_R(2.0) * (x * y - w * z);
    c.m[0][2] = FNAV_R(2.0) * (x * z + w * y);
    c.m[1][0] = FNAV_R(2.0) * (x * y + w * z);
    c.m[1][1] = w * w - x * x + y * y - z * z;
    c.m[1][2] = FNAV_R(2.0) * (y * z - w * x);
    c.m[2][0] = FNAV_R(2.0) * (x * z - w * y);
    c.m[2][1] = FNAV_R(2.0) * (y * z + w * x);
    c.m[2][2] = w * w - x * x - y * y + z * z;
    return c;
}

/** Quaternion q_nb of ZYX Euler angles (rad): roll phi, pitch theta, yaw psi. */
static inline fnav_quat_t fnav_quat_from_euler(fnav_real_t roll, fnav_real_t pitch, fnav_real_t yaw)
{
    fnav_real_t cr = fnav_cos(FNAV_R(0.5) * roll), sr = fnav_sin(FNAV_R(0.5) * roll);
    fnav_real_t cp = fnav_cos(FNAV_R(0.5) * pitch), sp = fnav_sin(FNAV_R(0.5) * pitch);
    fnav_real_t cy = fnav_cos(FNAV_R(0.5) * yaw), sy = fnav_sin(FNAV_R(0.5) * yaw);
    return fnav_quat(cr * cp * cy + sr * sp * sy,
                     sr * cp * cy - cr * sp * sy,
                     cr * sp * cy + sr * cp * sy,
                     cr * cp * sy - sr * sp * cy);
}

/** ZYX Euler angles (rad) of q_nb: out = (roll, pitch, yaw), with
 *  sin(pitch) = 2 (w y - x z) clamped to [-1, 1] before asin so that
 *  rounding never yields NaN. Within sqrt(8 eps) rad of pitch +-90 deg
 *  (|sin(pitch)| >= 1 - 4 eps: 0.056 deg in float) roll and yaw's atan2
 *  arguments are of the size of their rounding, and only yaw - roll (pitch
 *  +90 deg) or yaw + roll (-90 deg) is defined: roll is then 0 and yaw that
 *  sum or difference, 2 atan2(z -+ x, w +- y), so the three angles still
 *  give q's rotation (the convention of PX4's matrix::Euler). */
static inline fnav_vec3_t fnav_quat_to_euler(fnav_quat_t q)
{
    fnav_real_t w = q.q[0], x = q.q[1], y = q.q[2], z = q.q[3];
    fnav_real_t sp = fnav_clamp(FNAV_R(2.0) * (w * y - x * z), -FNAV_R(1.0), FNAV_R(1.0));
    if (fnav_fabs(sp) >= FNAV_R(1.0) - FNAV_R(4.0) * FNAV_REAL_EPSILON) {
        fnav_real_t s = sp > FNAV_R(0.0) ? FNAV_R(1.0) : -FNAV_R(1.0);
        fnav_real_t yaw = FNAV_R(2.0) * fnav_atan2(z - s * x, w + s * y); /* (-2 pi, 2 pi] */
        if (yaw > FNAV_PI) {
            yaw -= FNAV_R(2.0) * FNAV_PI;
        } else if (yaw <= -FNAV_PI) {
            yaw += FNAV_R(2.0) * FNAV_PI;
        }
        return fnav_vec3(FNAV_R(0.0), s * FNAV_R(0.5) * FNAV_PI, yaw);
    }
    return fnav_vec3(fnav_atan2(FNAV_R(2.0) * (w * x + y * z), FNAV_R(1.0) - FNAV_R(2.0) * (x * x + y * y)),
                     fnav_asin(sp),
                     fnav_atan2(FNAV_R(2.0) * (w * z + x * y), FNAV_R(1.0) - FNAV_R(2.0) * (y * y + z * z)));
}

/** Wrap an angle to (-pi, pi]. fmod is exact, so the result stays in range
 *  for any finite input (an angle of 1e30 rad has no meaningful phase left,
 *  but it never escapes the range). */
static inline fnav_real_t fnav_wrap_pi(fnav_real_t a)
{
    const fnav_real_t two_pi = FNAV_R(2.0) * FNAV_PI;
    if (a > FNAV_PI || a <= -FNAV_PI) {
        a = fnav_fmod(a, two_pi); /* (-2 pi, 2 pi), exact */
        if (a > FNAV_PI) {
            a -= two_pi;
        } else if (a <= -FNAV_PI) {
            a += two_pi;
        }
    }
    return a;
}

/** (uint32_t)(t / (2^shift c)), C99's division (truncated toward zero)
 *  modulo 2^32, the same bits for every int64_t, with three 32-bit
 *  divisions by c instead of a 64-bit division (a call to __aeabi_ldivmod
 *  on the Cortex-M4F). Requires c < 2^16 and shift < 64; with constant
 *  arguments (the wrappers below) the divisions are by a constant. For
 *  m = |t| >> shift, floor(m / c) = floor(|t| / (2^shift c)); long division
 *  of m by c: its high word (the quotient's bits above 32 are not needed,
 *  only the remainder), then the low word in two 16-bit digits, each step
 *  below c 2^16 < 2^32; a negative time's quotient is the negated one,
 *  modulo 2^32. Always inlined: at -Os a call cost 7 more instructions and
 *  8 more bytes than the copy in the stance detector (make firmware-bench). */
static inline FNAV_ALWAYS_INLINE uint32_t fnav_div_i64_u32(int64_t t, unsigned shift, uint32_t c)
{
    const uint64_t m = (t < 0 ? 0u - (uint64_t)t : (uint64_t)t) >> shift; /* |t|, INT64_MIN too */
    const uint32_t hi = (uint32_t)(m >> 32), lo = (uint32_t)m;
    uint32_t x = ((hi % c) << 16) | (lo >> 16);
    const uint32_t q1 = x / c;
    uint32_t q;
    x = ((x - q1 * c) << 16) | (lo & 0xffffu);
    q = (q1 << 16) | (x / c); /* m / c modulo 2^32 */
    return t < 0 ? 0u - q : q;
}

/** Microseconds of a time in ns modulo 2^32: (uint32_t)(t_ns / 1000), once
 *  per sample in the stance detector (tests/test_math.c, test_ns_to_us_u32). */
static inline FNAV_ALWAYS_INLINE uint32_t fnav_ns_to_us_u32(int64_t t_ns)
{
    return fnav_div_i64_u32(t_ns, 0u, 1000u);
}

/** Milliseconds of a time in ns modulo 2^32: (uint32_t)(t_ns / 1000000),
 *  10^6 = 2^6 15625 (the Cortex-M port's STATUS uptime; tests/test_math.c,
 *  test_ns_to_ms_u32). */
static inline FNAV_ALWAYS_INLINE uint32_t fnav_ns_to_ms_u32(int64_t t_ns)
{
    return fnav_div_i64_u32(t_ns, 6u, 15625u);
}

/** (fnav_real_t)x, the same bits for every int64_t, through int32_t when x
 *  fits (-2^31 <= x < 2^31: a time difference in ns under 2.1 s): on the
 *  Cortex-M4F an int32 -> float conversion is one VCVT, an int64 -> float a
 *  call to __aeabi_l2f, once per sample in the navigator and the stance
 *  detector. Same bits: for x in [INT32_MIN, INT32_MAX] the conversion to
 *  int32_t keeps the value (C99 6.3.1.3p1), and both conversions to
 *  fnav_real_t then round that same integer in the same way (6.3.1.4p2: the
 *  value itself when representable, else the nearest above or below by
 *  the current rounding mode: IEEE 754 round to nearest even on both
 *  targets); in double every int32 is exact. tests/test_math.c
 *  test_i64_to_real (edge and random values, float and double builds). */
static inline FNAV_ALWAYS_INLINE fnav_real_t fnav_i64_to_real(int64_t x)
{
    if (x >= INT32_MIN && x <= INT32_MAX) {
        return (fnav_real_t)(int32_t)x;
    }
    return (fnav_real_t)x;
}

#ifdef __cplusplus
}
#endif

#endif /* FNAV_MATH_H */
