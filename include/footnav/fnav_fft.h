/**
 * @file fnav_fft.h
 * @brief Fixed-size radix-2 FFT: in-place complex transform and a real
 *        transform of N points through one complex transform of N/2.
 *
 * The twiddle table lives in the object and is sized for the largest real
 * length FNAV_WELCH_MAX_NFFT (fnav_config.h): sizeof(fnav_fft_t) is
 * FNAV_WELCH_MAX_NFFT * sizeof(fnav_real_t) + 8 bytes. Iterative, no
 * recursion, no allocation; the transforms may run in an interrupt handler.
 * Forward transform, no scaling: X_k = sum_n x_n e^(-2 pi i k n / N).
 */
#ifndef FNAV_FFT_H
#define FNAV_FFT_H

#include "fnav_types.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Largest real transform length. */
#define FNAV_FFT_MAX_N FNAV_WELCH_MAX_NFFT

/** Twiddle table for real transforms of length n (complex ones of n/2). */
typedef struct {
    uint32_t n;                              /**< real transform length (power of two) */
    uint32_t reserved;
    fnav_real_t cs[FNAV_FFT_MAX_N / 2];      /**< cos(2 pi k / n), k < n/2 */
    fnav_real_t sn[FNAV_FFT_MAX_N / 2];      /**< sin(2 pi k / n), k < n/2 */
} fnav_fft_t;

/**
 * cos(2 pi k / n) and sin(2 pi k / n) in fnav_real_t without double-precision
 * libm calls (they cost ~7 KB of flash on a Cortex-M4F): the angle is reduced
 * with exact integer arithmetic to [0, pi/4] when 8 divides n (to [0, pi]
 * otherwise) before fnav_cos / fnav_sin. Measured against long double over
 * every k of n = 1..600 and 1023..4097 (tests/test_fft.c, test_cos_sin_2pi,
 * which prints the figures): when 8 divides n (every FFT twiddle) within
 * 0.66 of FNAV_REAL_EPSILON absolute, 2.2 ulp of the value, and exact at
 * multiples of pi/2; otherwise (the symmetric window's odd n = nfft - 1)
 * within 2.94 epsilons absolute, many ulps of a value near a zero crossing
 * (double build: 0.50 and 2.94 epsilons).
 * @param k     numerator (any value; taken modulo n)
 * @param n     denominator, > 0
 * @param c     cosine (output)
 * @param s     sine (output)
 * @return FNAV_OK; FNAV_E_ARG for n = 0 or a NULL output (nothing written).
 */
FNAV_WARN_UNUSED fnav_status_t fnav_fft_cos_sin_2pi(uint32_t k, uint32_t n, fnav_real_t *c, fnav_real_t *s);

/** fnav_fft_init() with the caller's FNAV_BUILD_TAG and sizeof(fnav_fft_t) (call fnav_fft_init(), which
 *  passes them): FNAV_E_BUILD, *f not written, when one is not the library's. */
FNAV_WARN_UNUSED fnav_status_t fnav_fft_init_tagged(fnav_fft_t *f, uint32_t n, uint64_t build_tag, size_t obj_size);

/**
 * Prepare the table for real transforms of n points.
 * @return FNAV_OK; FNAV_E_ARG for NULL; FNAV_E_CONFIG when n is not a power
 *         of two in 4..FNAV_FFT_MAX_N.
 *         FNAV_E_BUILD when this file was compiled with other layout options or layout-changing flags
 *         than the library (FNAV_BUILD_TAG and the struct sizes, fnav_types.h; an inline function passes
 *         them): nothing written.
 */
static inline FNAV_WARN_UNUSED fnav_status_t fnav_fft_init(fnav_fft_t *f, uint32_t n)
{
    return fnav_fft_init_tagged(f, n, FNAV_BUILD_TAG, sizeof(fnav_fft_t));
}

/**
 * In-place forward complex FFT of m points, m a power of two with
 * 2 <= m <= f->n / 2.
 * @param re  real parts, m entries
 * @param im  imaginary parts, m entries
 * @return FNAV_OK; FNAV_E_ARG for a NULL pointer; FNAV_E_STATE for a table
 *         fnav_fft_init never made (zeroed, or its init failed); FNAV_E_SIZE
 *         for an m that is not a power of two in 2..f->n / 2 (so never
 *         above FNAV_FFT_MAX_N / 2). Refused calls write nothing.
 */
FNAV_WARN_UNUSED fnav_status_t fnav_fft_complex(const fnav_fft_t *f, fnav_real_t *re, fnav_real_t *im, uint32_t m);

/**
 * Forward FFT of n = f->n real points, given packed: re[k] = x[2k],
 * im[k] = x[2k+1] for k < n/2. On return re[k], im[k] hold X_k for
 * k = 0 .. n/2 (n/2 + 1 bins; im[0] = im[n/2] = 0).
 * @param re  n/2 + 1 entries
 * @param im  n/2 + 1 entries
 * @return FNAV_OK; FNAV_E_ARG for a NULL pointer; FNAV_E_STATE for a table
 *         fnav_fft_init never made (zeroed, or its init failed). Refused
 *         calls write nothing.
 */
FNAV_WARN_UNUSED fnav_status_t fnav_fft_real_packed(const fnav_fft_t *f, fnav_real_t *re, fnav_real_t *im);

#ifdef __cplusplus
}
#endif

#endif /* FNAV_FFT_H */
