/**
 * @file fnav_types.h
 * @brief Scalar type, literals, math mapping, the one status enum and the
 *        IMU sample shared by every footnav module.
 */
#ifndef FNAV_TYPES_H
#define FNAV_TYPES_H

#include <stdint.h>
#include <stddef.h>
#include <math.h>
#include <float.h>
#include <string.h>

#include "fnav_config.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ------------------------------------------------------------------------ */
/* Scalar type                                                               */
/* ------------------------------------------------------------------------ */

#if FNAV_USE_DOUBLE
/** Real scalar of the core: double in the reference build. */
typedef double fnav_real_t;
/** Literal of type fnav_real_t: always write a decimal point, FNAV_R(1.0). */
#define FNAV_R(x) (x)
#define FNAV_REAL_EPSILON DBL_EPSILON
#define FNAV_REAL_MAX DBL_MAX
#else
/** Real scalar of the core: float (the firmware default). */
typedef float fnav_real_t;
/** Literal of type fnav_real_t: always write a decimal point, FNAV_R(1.0). */
#define FNAV_R(x) (x##f)
#define FNAV_REAL_EPSILON FLT_EPSILON
#define FNAV_REAL_MAX FLT_MAX
#endif

#define FNAV_PI FNAV_R(3.14159265358979323846)
/** Degrees to radians. */
#define FNAV_DEG2RAD (FNAV_PI / FNAV_R(180.0))
/** Standard gravity, m/s^2 (CGPM 1901), used to convert g to m/s^2. */
#define FNAV_G0_MPS2 FNAV_R(9.80665)

/* Keep a function out of line (its stack frame then does not add to its
 * caller's deeper calls), or always inline a tiny one that -Os would
 * otherwise call (a per-element check in the filter's loops); no-ops for
 * compilers without the attributes. */
#if defined(__GNUC__)
#define FNAV_NOINLINE __attribute__((noinline))
#define FNAV_ALWAYS_INLINE __attribute__((always_inline))
#else
#define FNAV_NOINLINE
#define FNAV_ALWAYS_INLINE
#endif

/* Math functions, mapped once (STYLE 5). static inline so that no argument
 * is evaluated twice. */
#if FNAV_USE_DOUBLE
static inline fnav_real_t fnav_sqrt(fnav_real_t x) { return sqrt(x); }
static inline fnav_real_t fnav_fabs(fnav_real_t x) { return fabs(x); }
static inline fnav_real_t fnav_sin(fnav_real_t x) { return sin(x); }
static inline fnav_real_t fnav_cos(fnav_real_t x) { return cos(x); }
static inline fnav_real_t fnav_tan(fnav_real_t x) { return tan(x); }
static inline fnav_real_t fnav_asin(fnav_real_t x) { return asin(x); }
static inline fnav_real_t fnav_acos(fnav_real_t x) { return acos(x); }
static inline fnav_real_t fnav_atan2(fnav_real_t y, fnav_real_t x) { return atan2(y, x); }
static inline fnav_real_t fnav_exp(fnav_real_t x) { return exp(x); }
static inline fnav_real_t fnav_log(fnav_real_t x) { return log(x); }
static inline fnav_real_t fnav_log10(fnav_real_t x) { return log10(x); }
static inline fnav_real_t fnav_pow(fnav_real_t x, fnav_real_t y) { return pow(x, y); }
static inline fnav_real_t fnav_floor(fnav_real_t x) { return floor(x); }
static inline fnav_real_t fnav_ceil(fnav_real_t x) { return ceil(x); }
static inline fnav_real_t fnav_fmod(fnav_real_t x, fnav_real_t y) { return fmod(x, y); }
#else
static inline fnav_real_t fnav_sqrt(fnav_real_t x) { return sqrtf(x); }
static inline fnav_real_t fnav_fabs(fnav_real_t x) { return fabsf(x); }
static inline fnav_real_t fnav_sin(fnav_real_t x) { return sinf(x); }
static inline fnav_real_t fnav_cos(fnav_real_t x) { return cosf(x); }
static inline fnav_real_t fnav_tan(fnav_real_t x) { return tanf(x); }
static inline fnav_real_t fnav_asin(fnav_real_t x) { return asinf(x); }
static inline fnav_real_t fnav_acos(fnav_real_t x) { return acosf(x); }
static inline fnav_real_t fnav_atan2(fnav_real_t y, fnav_real_t x) { return atan2f(y, x); }
static inline fnav_real_t fnav_exp(fnav_real_t x) { return expf(x); }
static inline fnav_real_t fnav_log(fnav_real_t x) { return logf(x); }
static inline fnav_real_t fnav_log10(fnav_real_t x) { return log10f(x); }
static inline fnav_real_t fnav_pow(fnav_real_t x, fnav_real_t y) { return powf(x, y); }
static inline fnav_real_t fnav_floor(fnav_real_t x) { return floorf(x); }
static inline fnav_real_t fnav_ceil(fnav_real_t x) { return ceilf(x); }
static inline fnav_real_t fnav_fmod(fnav_real_t x, fnav_real_t y) { return fmodf(x, y); }
#endif

/** Non-zero when x is neither NaN nor infinite: its IEEE-754 exponent field
 *  is not all ones. A test of the bits, not comparisons: it holds under any
 *  floating-point flags (-ffinite-math-only folds x == x and x <= MAX), and
 *  on the Cortex-M4F it is an integer AND and compare where x == x and the
 *  two range comparisons were three VCMPs with their VMRS: 1,952 bytes less
 *  flash for the firmware image, the same worst-case stack (docs/firmware.md,
 *  "Budget"; tests/test_math.c test_isfinite). */
/* the bits through memcpy; GCC's and Clang's builtin also in a program
 * built -ffreestanding or -fno-builtin, where memcpy is a call at every
 * check (tests/cli/test_install.sh) */
#if defined(__GNUC__) || defined(__clang__)
#define FNAV_BITS_COPY(dst, src, n) __builtin_memcpy(dst, src, n)
#else
#define FNAV_BITS_COPY(dst, src, n) memcpy(dst, src, n)
#endif
#if FNAV_USE_DOUBLE
#if DBL_MANT_DIG != 53 || DBL_MAX_EXP != 1024
#error "fnav_isfinite expects IEEE-754 binary64 double"
#endif
static inline FNAV_ALWAYS_INLINE int fnav_isfinite(fnav_real_t x)
{
    uint64_t u;
    FNAV_BITS_COPY(&u, &x, sizeof u);
    return (u & UINT64_C(0x7ff0000000000000)) != UINT64_C(0x7ff0000000000000);
}
#else
#if FLT_MANT_DIG != 24 || FLT_MAX_EXP != 128
#error "fnav_isfinite expects IEEE-754 binary32 float"
#endif
static inline FNAV_ALWAYS_INLINE int fnav_isfinite(fnav_real_t x)
{
    uint32_t u;
    FNAV_BITS_COPY(&u, &x, sizeof u);
    return (u & 0x7f800000u) != 0x7f800000u;
}
#endif

/** Clamp x to [lo, hi] (x is evaluated once). */
static inline fnav_real_t fnav_clamp(fnav_real_t x, fnav_real_t lo, fnav_real_t hi)
{
    return (x < lo) ? lo : ((x > hi) ? hi : x);
}

/* ------------------------------------------------------------------------ */
/* Status                                                                    */
/* ------------------------------------------------------------------------ */

/** The one status enum of footnav: 0 is success, negative is failure,
 *  positive values are non-failure conditions a caller may act on. */
typedef enum {
    FNAV_OK = 0,             /**< success */
    FNAV_END = 1,            /**< a source has no more samples */
    FNAV_AGAIN = 2,          /**< nothing available yet (non-blocking source) */
    FNAV_E_ARG = -1,         /**< invalid argument (NULL, out of domain) */
    FNAV_E_CONFIG = -2,      /**< configuration rejected by an _init */
    FNAV_E_NANINF = -3,      /**< NaN or Inf in an input; input ignored */
    FNAV_E_RANGE = -4,       /**< value outside its physical range */
    FNAV_E_DECOMP = -5,      /**< matrix factorisation failed (not positive definite) */
    FNAV_E_STATE = -6,       /**< call not valid in the object's current state */
    FNAV_E_TIME = -7,        /**< timestamp went backwards or jumped too far */
    FNAV_E_SIZE = -8,        /**< buffer too small or size mismatch */
    FNAV_E_IO = -9,          /**< port I/O failed */
    FNAV_E_FORMAT = -10,     /**< malformed input format */
    FNAV_E_CRC = -11,        /**< integrity check failed */
    FNAV_E_TRUNCATED = -12,  /**< input ends inside a record */
    FNAV_E_UNSUPPORTED = -13,/**< feature or version not supported */
    FNAV_E_DIVERGED = -14,   /**< estimator diverged; reset required */
    FNAV_E_BUILD = -15       /**< caller compiled with other layout options or flags than the library
                                  (FNAV_BUILD_TAG, or a struct's size) */
} fnav_status_t;

#if defined(__GNUC__) || defined(__clang__)
#define FNAV_WARN_UNUSED __attribute__((warn_unused_result))
#else
#define FNAV_WARN_UNUSED
#endif

/** A function that never returns to its caller (fnav_port_assert_failed).
 *  C99 has no keyword for it: GCC's and clang's attribute, C11's _Noreturn,
 *  else nothing. The compiler may then drop the code after a call (the
 *  core's FNAV_ASSERT costs less flash) and warns about a definition that
 *  can return (an error with -Werror); a definition that returns anyway is
 *  undefined behaviour. */
#if defined(__GNUC__) || defined(__clang__)
#define FNAV_NORETURN __attribute__((noreturn))
#elif defined(__STDC_VERSION__) && (__STDC_VERSION__ >= 201112L)
#define FNAV_NORETURN _Noreturn
#else
#define FNAV_NORETURN
#endif

/** Short constant English text of a status (never NULL). */
const char *fnav_status_str(fnav_status_t status);

/* ------------------------------------------------------------------------ */
/* Build tag                                                                 */
/* ------------------------------------------------------------------------ */

/** log2 of FNAV_WELCH_MAX_NFFT (a power of two in 8..65536,
 *  fnav_config_check.h), as a constant expression. */
#define FNAV_BUILD_NFFT_LOG2                                                                             \
    (3 + (FNAV_WELCH_MAX_NFFT >= 16) + (FNAV_WELCH_MAX_NFFT >= 32) + (FNAV_WELCH_MAX_NFFT >= 64) +       \
     (FNAV_WELCH_MAX_NFFT >= 128) + (FNAV_WELCH_MAX_NFFT >= 256) + (FNAV_WELCH_MAX_NFFT >= 512) +        \
     (FNAV_WELCH_MAX_NFFT >= 1024) + (FNAV_WELCH_MAX_NFFT >= 2048) + (FNAV_WELCH_MAX_NFFT >= 4096) +     \
     (FNAV_WELCH_MAX_NFFT >= 8192) + (FNAV_WELCH_MAX_NFFT >= 16384) + (FNAV_WELCH_MAX_NFFT >= 32768) +   \
     (FNAV_WELCH_MAX_NFFT >= 65536))

/** The options that set a public struct's layout (fnav_config.h), packed
 *  into 64 bits, each in its own field wide enough for the range
 *  fnav_config_check.h allows, so two option sets never share a tag:
 *  bits 0-3 sizeof(fnav_real_t) (FNAV_USE_DOUBLE: 4 or 8), 4-14
 *  FNAV_STANCE_MAX_WINDOW, 15-27 FNAV_STANCE_EVENT_BUF, 28-32
 *  FNAV_ALLAN_MAX_LEVELS, 33-36 FNAV_ALLAN_RING0_LOG2, 37-39
 *  FNAV_ALLAN_CASCADE_LAG_LOG2, 40-47 FNAV_ALLAN_MAX_POINTS, 48-52
 *  log2 FNAV_WELCH_MAX_NFFT, 53-59 FNAV_IMUERR_FLICKER_POLES, 60-63 the
 *  layout of the tag itself (1). FNAV_ENABLE_ASSERT, FNAV_NAV_TIME_RESYNC
 *  and FNAV_INPUT_MAX_ABS change what the library's code does, not a
 *  layout, and are not in it. A macro: it takes the options of the file it
 *  is expanded in. Every public _init but fnav_wire_decoder_init (void,
 *  its struct moved by no option) passes the caller's to the library, with
 *  the caller's sizeof of the object and of its configuration struct
 *  (which catch a layout flag such as -fpack-struct, or another version's
 *  headers, as far as a size moves), and the library answers FNAV_E_BUILD,
 *  writing nothing, when one is not its own (docs/firmware.md, "A library
 *  and a program built with other options"). */
#define FNAV_BUILD_TAG                                                                                   \
    (((uint64_t)1 << 60) | ((uint64_t)sizeof(fnav_real_t) << 0) |                                        \
     ((uint64_t)(FNAV_STANCE_MAX_WINDOW) << 4) | ((uint64_t)(FNAV_STANCE_EVENT_BUF) << 15) |             \
     ((uint64_t)(FNAV_ALLAN_MAX_LEVELS) << 28) | ((uint64_t)(FNAV_ALLAN_RING0_LOG2) << 33) |             \
     ((uint64_t)(FNAV_ALLAN_CASCADE_LAG_LOG2) << 37) | ((uint64_t)(FNAV_ALLAN_MAX_POINTS) << 40) |       \
     ((uint64_t)(FNAV_BUILD_NFFT_LOG2) << 48) | ((uint64_t)(FNAV_IMUERR_FLICKER_POLES) << 53))

/** The FNAV_BUILD_TAG the library was compiled with: a program that calls
 *  a library function before its first _init (fnav_profile_builtin() on
 *  its configuration, say: the helpers pass no tag or size) compares it
 *  with its own FNAV_BUILD_TAG first; on a mismatch, print both in hex and
 *  compare the fields above. */
uint64_t fnav_build_tag(void);

/* ------------------------------------------------------------------------ */
/* IMU sample                                                                */
/* ------------------------------------------------------------------------ */

/** fnav_sample_t.flags: temp_c holds a measured temperature. */
#define FNAV_SAMPLE_HAS_TEMP 0x1u
/** fnav_sample_t.flags: seq is a counter from the sensor (drops visible). */
#define FNAV_SAMPLE_HAS_SEQ 0x2u

/** Largest |t_ns| a sample may carry: 2^62 - 1 ns (146 years either side
 *  of the epoch), so that the difference of any two stamps fits int64_t
 *  (2 (2^62 - 1) < 2^63; with 2^62 itself, -2^62 then +2^62 overflowed). */
#define FNAV_T_NS_MAX (((int64_t)1 << 62) - 1)

/** One IMU sample in the sensor (body) frame b, SI units. */
typedef struct {
    int64_t t_ns;                 /**< sample time, ns, monotonic non-decreasing, |t_ns| <= FNAV_T_NS_MAX */
    uint32_t seq;                 /**< record counter of the source (wraps at 2^32) */
    uint32_t flags;               /**< FNAV_SAMPLE_* bits */
    fnav_real_t accel_mps2[3];    /**< specific force f_b, m/s^2 */
    fnav_real_t gyro_rps[3];      /**< angular rate w_ib_b, rad/s */
    fnav_real_t temp_c;           /**< temperature, deg C (valid with HAS_TEMP) */
} fnav_sample_t;

#ifdef __cplusplus
}
#endif

#endif /* FNAV_TYPES_H */
