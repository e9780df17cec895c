/**
 * @file fnav_welch.h
 * @brief Streaming Welch power spectral density of one channel and the
 *        paper's lowest usable sampling frequency (section II.B).
 *
 * Welch's method (P. D. Welch, IEEE Trans. Audio Electroacoust. 15(2), 1967):
 * segments of nfft samples, hop nfft - overlap, each detrended and windowed,
 * its periodogram |FFT|^2 averaged; one-sided density scaling
 * 2 |X_k|^2 / (f_s sum w^2) (DC and Nyquist not doubled), exactly as
 * scipy.signal.welch. Defaults are the paper's: Hamming window of 64
 * samples, 50 % overlap, and scipy's per-segment mean removal (the paper
 * does not say how it treated DC; see docs/psd.md).
 *
 * Memory: fixed by FNAV_WELCH_MAX_NFFT (fnav_config.h), independent of the
 * log length; sizeof(fnav_welch_t) is about 5 * MAX_NFFT reals (float:
 * about 82 KB for the default 4096, 20.6 KB for 1024, 5.2 KB for 256; set MAX_NFFT 64 on a
 * sensor that only needs the paper's 64-sample segments: 1.4 KB). Push costs O(1); every
 * hop samples one real FFT of nfft points (no allocation, no recursion).
 *
 * Context: no shared state; not reentrant per object. fnav_welch_push() may
 * run in an interrupt handler for objects no other context uses: bounded
 * time (at most one nfft-point real FFT, and with FNAV_DETREND_GLOBAL one
 * pass over the ring at the first segment; on the Cortex-M4F at 64 points
 * at most 19,185 instructions for a push to each of 3 channels, `make
 * firmware-bench FW_ICOUNT_SHIFT=6`, docs/firmware.md) and 144 bytes of
 * stack (push 24, segment 40, fnav_fft_real_packed 24, fnav_fft_complex 56:
 * `/usr/bin/python3 tests/support/stack_usage.py build/arm/obj/src
 * fnav_welch_push` after `make firmware`). fnav_welch_init() (the window
 * and the FFT table, sinf/cosf) belongs in thread context.
 */
#ifndef FNAV_WELCH_H
#define FNAV_WELCH_H

#include "fnav_fft.h"
#include "fnav_types.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Largest number of one-sided bins. */
#define FNAV_WELCH_MAX_BINS (FNAV_WELCH_MAX_NFFT / 2 + 1)

/** Window of each segment. */
typedef enum {
    FNAV_WINDOW_HAMMING = 0, /**< 0.54 - 0.46 cos(2 pi n / L) (the paper's) */
    FNAV_WINDOW_HANN = 1,    /**< 0.5 - 0.5 cos(2 pi n / L) */
    FNAV_WINDOW_RECT = 2     /**< all ones (plain periodogram segments) */
} fnav_window_t;

/** Trend removed from each segment before windowing. */
typedef enum {
    FNAV_DETREND_NONE = 0,     /**< nothing (DC, e.g. gravity, stays in) */
    FNAV_DETREND_CONSTANT = 1, /**< the segment mean (scipy's default) */
    FNAV_DETREND_LINEAR = 2,   /**< the least-squares line through the segment */
    FNAV_DETREND_GLOBAL = 3    /**< the mean of the whole record, removed exactly at the end in one
                                    pass (periodic windows only: their DFT is zero beyond bin 1, so
                                    only bins 0 and 1 change; docs/psd.md) */
} fnav_detrend_t;

/** Scaling of the result. */
typedef enum {
    FNAV_SCALING_DENSITY = 0,  /**< power spectral density, unit^2/Hz */
    FNAV_SCALING_SPECTRUM = 1  /**< power spectrum, unit^2 */
} fnav_scaling_t;

/** Configuration. */
typedef struct {
    uint32_t nfft;           /**< segment length, power of two, 8..FNAV_WELCH_MAX_NFFT (default 64) */
    uint32_t overlap;        /**< samples shared by consecutive segments, < nfft (default 32) */
    fnav_window_t window;    /**< default Hamming */
    int symmetric;           /**< 0 (default): periodic window, L = nfft (scipy's get_window);
                                  1: symmetric, L = nfft - 1 (MATLAB's hamming(nfft)) */
    fnav_detrend_t detrend;  /**< default CONSTANT */
    fnav_scaling_t scaling;  /**< default DENSITY */
    fnav_real_t rate_hz;     /**< sample rate, Hz (default 1) */
    fnav_real_t offset;      /**< subtracted from every sample first, in the sample's unit
                                  (default 0; e.g. a whole-log mean or gravity at rest) */
} fnav_welch_config_t;

/** Paper settings: Hamming 64, 50 % overlap, constant detrend, density, 1 Hz. */
extern const fnav_welch_config_t fnav_welch_config_default;

/** The estimator of one channel. Caller-owned; fields are internal. */
typedef struct {
    fnav_welch_config_t cfg;
    fnav_fft_t fft;
    fnav_real_t win[FNAV_WELCH_MAX_NFFT];      /**< window */
    fnav_real_t ring[FNAV_WELCH_MAX_NFFT];     /**< last nfft samples (offset removed) */
    fnav_real_t re[FNAV_WELCH_MAX_BINS];       /**< FFT of the last segment */
    fnav_real_t im[FNAV_WELCH_MAX_BINS];
    fnav_real_t acc[FNAV_WELCH_MAX_BINS];      /**< sum of |X_k|^2 over segments (Kahan) */
    fnav_real_t accc[FNAV_WELCH_MAX_BINS];     /**< Kahan compensation */
    fnav_real_t s2;                            /**< sum of w^2 */
    fnav_real_t s1;                            /**< sum of w (= W_0, the window's DFT at bin 0) */
    fnav_real_t w1r, w1i;                      /**< W_1, the window's DFT at bin 1 */
    fnav_real_t shift;                         /**< GLOBAL: removed to keep sums small: the first sample,
                                                    then the first segment's mean */
    fnav_real_t gs, gc;                        /**< GLOBAL: sum of samples (Kahan) */
    fnav_real_t x0, x1r, x1i;                  /**< GLOBAL: sums of X_0, X_1 over segments (Kahan) */
    fnav_real_t x0c, x1rc, x1ic;               /**< their Kahan compensations */
    uint32_t pos;                              /**< ring index of the next sample */
    uint32_t fill;                             /**< samples in the ring (<= nfft) */
    uint32_t since;                            /**< samples since the last segment */
    uint32_t nseg;                             /**< segments averaged */
    uint32_t nsamples;                         /**< samples pushed (at most 2^32 - 1) */
} fnav_welch_t;

/** fnav_welch_init() with the caller's FNAV_BUILD_TAG, sizeof(fnav_welch_t) and sizeof(fnav_welch_config_t)
 *  (call fnav_welch_init(), which passes them): FNAV_E_BUILD, *w not written, when one is not
 *  the library's. */
FNAV_WARN_UNUSED fnav_status_t fnav_welch_init_tagged(fnav_welch_t *w, const fnav_welch_config_t *cfg,
                                                      uint64_t build_tag, size_t obj_size, size_t cfg_size);

/**
 * Initialise.
 * @param w    estimator (caller-owned)
 * @param cfg  configuration, or NULL for fnav_welch_config_default; may be
 *             w's own (&w->cfg: a reset with the same settings)
 * @return FNAV_OK; FNAV_E_ARG for NULL w; FNAV_E_CONFIG for a bad nfft,
 *         overlap >= nfft, unknown window/detrend/scaling, a rate not
 *         positive and finite or one whose density scale
 *         1 / (rate_hz sum w^2) or rate_hz nfft is not finite (float32
 *         at nfft 64: below about 2e-40 or above about 5e36 Hz), an offset not finite or beyond
 *         FNAV_INPUT_MAX_ABS, or FNAV_DETREND_GLOBAL with a symmetric window;
 *         *w is then not changed (one initialised before keeps its
 *         configuration and data; one never initialised stays zeroed).
 *         FNAV_E_BUILD when this file was compiled with other layout options or layout-changing flags
 *         than the library (FNAV_BUILD_TAG and the struct sizes, fnav_types.h; an inline function passes
 *         them): nothing written.
 */
static inline FNAV_WARN_UNUSED fnav_status_t fnav_welch_init(fnav_welch_t *w, const fnav_welch_config_t *cfg)
{
    return fnav_welch_init_tagged(w, cfg, FNAV_BUILD_TAG, sizeof(fnav_welch_t), sizeof(fnav_welch_config_t));
}

/**
 * Add one sample; completes a segment every (nfft - overlap) samples once
 * nfft samples were seen.
 * @return FNAV_OK; FNAV_E_ARG for NULL w; FNAV_E_NANINF for NaN/Inf,
 *         FNAV_E_RANGE for |x| > FNAV_INPUT_MAX_ABS and once 2^32 - 1
 *         samples were pushed (ignored, state unchanged); FNAV_E_STATE for
 *         an estimator never initialised (zeroed, as static storage is) or
 *         whose only fnav_welch_init failed, before the sample is looked
 *         at (nothing taken), as fnav_nav_push says.
 */
FNAV_WARN_UNUSED fnav_status_t fnav_welch_push(fnav_welch_t *w, fnav_real_t x);

/** Segments averaged so far (0 for NULL). */
uint32_t fnav_welch_segments(const fnav_welch_t *w);

/** Number of one-sided bins, nfft/2 + 1 (0 for NULL). */
uint32_t fnav_welch_bins(const fnav_welch_t *w);

/** Frequency of bin k, Hz (k f_s / nfft; 0 for NULL or an estimator never
 *  initialised). fnav_welch_freq(w, 1) is the bin spacing, the df_hz of
 *  fnav_welch_bandwidth(). */
fnav_real_t fnav_welch_freq(const fnav_welch_t *w, uint32_t k);

/**
 * The averaged one-sided spectrum.
 * @param out   fnav_welch_bins(w) entries
 * @param n_out capacity of out
 * @return FNAV_OK; FNAV_E_ARG for NULL w or out; FNAV_E_SIZE when n_out is
 *         too small; FNAV_E_STATE before the first segment (or for an
 *         estimator never initialised). Nothing is written unless FNAV_OK.
 */
FNAV_WARN_UNUSED fnav_status_t fnav_welch_get(const fnav_welch_t *w, fnav_real_t *out, size_t n_out);

/**
 * One-sided spectrum of the most recent segment alone (same scaling), for
 * spectrograms: call when fnav_welch_segments() has grown. With
 * FNAV_DETREND_GLOBAL the mean of the samples so far is removed.
 * @return as fnav_welch_get().
 */
FNAV_WARN_UNUSED fnav_status_t fnav_welch_last(const fnav_welch_t *w, fnav_real_t *out, size_t n_out);

/** Lowest-usable-sampling-frequency settings (paper II.B). */
typedef struct {
    fnav_real_t threshold;  /**< fraction of the total power the band must hold (default 0.95) */
    fnav_real_t round_hz;   /**< round the sampling frequency up to a multiple of this (default 50; 0: none) */
    int exclude_dc;         /**< 1: leave bin 0 out of the total (another way to ignore gravity); default 0 */
} fnav_bandwidth_config_t;

/** The paper's settings: 95 %, multiples of 50 Hz, DC bin included. */
extern const fnav_bandwidth_config_t fnav_bandwidth_config_default;

/** Result of fnav_welch_bandwidth(). */
typedef struct {
    fnav_real_t total;          /**< total power, unit^2 (sum of P_k df) */
    fnav_real_t bandwidth_hz;   /**< smallest f with cumulative power >= threshold * total */
    fnav_real_t fs_hz;          /**< 2 * bandwidth (Nyquist) */
    fnav_real_t fs_rounded_hz;  /**< fs rounded up to a multiple of round_hz (fs itself when round_hz is 0,
                                     or so small that fs / round_hz overflows) */
} fnav_bandwidth_t;

/**
 * Cumulative power and the bandwidth holding a fraction of it, from a
 * one-sided density P_k, k = 0..n-1, bins df apart. Bin k holds the power
 * P_k df and spans [(k - 1/2) df, (k + 1/2) df] clipped to [0, (n-1) df];
 * the cumulative power is interpolated linearly inside the bin where it
 * crosses the threshold (docs/psd.md).
 * @param ccdf  optional (may be NULL), n entries: complementary cumulative
 *              fraction 1 - C(f) at the upper edge of each bin
 * @return FNAV_OK; FNAV_E_ARG for NULL / n < 2 / df <= 0 / a threshold
 *         outside (0, 1] / round_hz < 0 or not finite;
 *         FNAV_E_RANGE when a bin is negative or NaN (bin 0 too when
 *         exclude_dc leaves it out) or the total power is not positive and
 *         finite; nothing is written then.
 */
FNAV_WARN_UNUSED fnav_status_t fnav_welch_bandwidth(const fnav_real_t *psd, size_t n, fnav_real_t df_hz,
                                                    const fnav_bandwidth_config_t *cfg, fnav_bandwidth_t *out,
                                                    fnav_real_t *ccdf);

#ifdef __cplusplus
}
#endif

#endif /* FNAV_WELCH_H */
