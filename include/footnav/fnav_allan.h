/**
 * @file fnav_allan.h
 * @brief Streaming, fixed-memory Allan deviation of one sensor channel
 *        (overlapping and non-overlapping), noise identification from the
 *        local slope, equivalent degrees of freedom, and the paper's
 *        bias-model identification (section III.C, eqs. (5)-(6)).
 *
 * One fnav_allan_t per channel; fnav_allan_push() once per sample. Memory is
 * fixed at compile time (fnav_config.h) and never grows with the log:
 * sizeof(fnav_allan_t) is 3,948 bytes in the float build with the default
 * options (7,880 in the double build). Method (docs/allan.md):
 *
 * - The samples y_k (a rate, "frequency" in time-and-frequency terms) are
 *   summed into a phase x_k = sum_{i<=k} (y_i - y_0) kept as a Kahan pair, so
 *   that the phase is effectively double length in the float build; y_0, the
 *   first sample, is removed only to keep the phase small (the Allan variance
 *   is invariant to a constant in y).
 * - A ring of the last 2^FNAV_ALLAN_RING0_LOG2 phase values gives the fully
 *   overlapping estimator for every tau <= 2^(RING0_LOG2 - 1) - 1 samples:
 *   AVAR(tau) = sum (x_{i+2m} - 2 x_{i+m} + x_i)^2 / (2 m^2 (N + 1 - 2m))
 *   (NIST SP 1065 eq. 11, N samples, m = tau), the same numbers as Stable32.
 * - Beyond it, cascade level j keeps 2 L + 1 phase values 2^j samples apart
 *   (L = 2^FNAV_ALLAN_CASCADE_LAG_LOG2) and serves tau = m 2^j, m <= L, with
 *   the same second differences taken every 2^j samples: an overlapping
 *   estimator with stride tau / m instead of 1 (term count floor(N/2^j) + 1 - 2m).
 * - Every tau also gets the non-overlapping estimator (stride tau, SP 1065
 *   eq. 7), from the same second differences, taken every m-th term.
 * - Level-0 terms are not formed at every push: when a block of
 *   FNAV_ALLAN_BLOCK samples completes, each tau point sums the block's 32
 *   second differences from contiguous ring reads (4 independent partial
 *   sums, which the compiler vectorises) and folds that block sum into a
 *   Kahan-compensated total, so 10^7 float additions lose nothing measurable
 *   (docs/allan.md, float error). A push is then a few operations, the
 *   block costs about 3 per sample and point.
 *
 * Push cost: the phase update and ring write; every 32 samples one pass over
 * the level-0 points (15 with the default grid); every 2^j samples the
 * points of cascade level j.
 * No allocation, no recursion; not reentrant per object. fnav_allan_push()
 * may run in an interrupt handler (bounded time: the ring re-basing every
 * 2^RING0_LOG2 samples costs one pass over the ring).
 */
#ifndef FNAV_ALLAN_H
#define FNAV_ALLAN_H

#include "fnav_types.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Phase values in the full-rate ring. */
#define FNAV_ALLAN_RING0 (1u << FNAV_ALLAN_RING0_LOG2)
/** Largest tau (samples) estimated fully overlapping (level 0). */
#define FNAV_ALLAN_TAU_FULL_MAX ((FNAV_ALLAN_RING0 / 2u) - 1u)
/** Largest lag m of a cascade level. */
#define FNAV_ALLAN_CASCADE_LAG (1u << FNAV_ALLAN_CASCADE_LAG_LOG2)
/** Phase values kept per cascade level. */
#define FNAV_ALLAN_CASCADE_RING (2u * FNAV_ALLAN_CASCADE_LAG + 1u)
/** First cascade level: the one whose largest tau no longer fits level 0. */
#define FNAV_ALLAN_LEVEL_FIRST (FNAV_ALLAN_RING0_LOG2 - FNAV_ALLAN_CASCADE_LAG_LOG2 - 1)
/** Last cascade level: its largest tau is 2^(FNAV_ALLAN_MAX_LEVELS - 1). */
#define FNAV_ALLAN_LEVEL_LAST (FNAV_ALLAN_MAX_LEVELS - 1 - FNAV_ALLAN_CASCADE_LAG_LOG2)
/** Number of cascade levels (0 when every tau fits level 0). */
#define FNAV_ALLAN_NLEVELS \
    ((FNAV_ALLAN_LEVEL_LAST >= FNAV_ALLAN_LEVEL_FIRST) ? (FNAV_ALLAN_LEVEL_LAST - FNAV_ALLAN_LEVEL_FIRST + 1) : 0)
/** Largest tau (samples) the estimator can be configured for. */
#define FNAV_ALLAN_TAU_MAX (1ul << (FNAV_ALLAN_MAX_LEVELS - 1))

/** Configuration: the averaging times to track. */
typedef struct {
    /** Averaging factors m = tau / tau0 in samples, strictly ascending, each
     *  either <= FNAV_ALLAN_TAU_FULL_MAX or m' 2^j with m' <= FNAV_ALLAN_CASCADE_LAG
     *  and m' 2^j <= FNAV_ALLAN_TAU_MAX (fnav_allan_tau_valid()).
     *  NULL: the default grid (fnav_allan_grid() with 2 points per octave). */
    const uint32_t *tau;
    /** Entries in tau, 1..FNAV_ALLAN_MAX_POINTS (ignored when tau is NULL). */
    size_t n_tau;
} fnav_allan_config_t;

/** Default: 2 points per octave, tau = 1, 2, 3, 4, 6, 8, ... 2^20 samples. */
extern const fnav_allan_config_t fnav_allan_config_default;

/** Full-rate samples per block: level-0 terms are summed a block at a time
 *  (contiguous, vectorisable loads from the ring) when the block completes. */
#define FNAV_ALLAN_BLOCK 32u

/** One tau point's accumulators (internal; read through fnav_allan_get()). */
typedef struct {
    fnav_real_t so, co;   /**< overlapping sum of squared second differences + Kahan compensation */
    fnav_real_t sn, cn;   /**< non-overlapping sum + compensation */
    uint16_t lag;         /**< lag at the point's level (tau / 2^level) */
    uint8_t level;        /**< 0: full rate; else cascade level (stride 2^level) */
    uint8_t late;         /**< level 0 with 2 lag + BLOCK > ring: terms taken at every push */
} fnav_allan_point_t;

/** The estimator of one channel. Caller-owned; fields are internal. */
typedef struct {
    /** phase, full rate, relative to base0; the first BLOCK entries are
     *  repeated at the end so that a block's lagged reads are contiguous */
    fnav_real_t ring0[FNAV_ALLAN_RING0 + FNAV_ALLAN_BLOCK];
    fnav_real_t ringc[FNAV_ALLAN_NLEVELS > 0 ? FNAV_ALLAN_NLEVELS : 1][FNAV_ALLAN_CASCADE_RING];
    fnav_real_t basec[FNAV_ALLAN_NLEVELS > 0 ? FNAV_ALLAN_NLEVELS : 1]; /**< phase base per level */
    fnav_allan_point_t pt[FNAV_ALLAN_MAX_POINTS];
    fnav_real_t y0;        /**< first sample, removed from every sample */
    fnav_real_t ph, pc;    /**< phase: Kahan sum and compensation */
    fnav_real_t base0;     /**< phase base of ring0 */
    uint32_t n;            /**< samples pushed */
    uint8_t wc[FNAV_ALLAN_NLEVELS > 0 ? FNAV_ALLAN_NLEVELS : 1]; /**< cascade ring indices */
    uint8_t npt;           /**< tau points */
    uint8_t npt0;          /**< of which at level 0 (the first npt0) */
    uint8_t nlate0;        /**< first level-0 point with .late set (npt0 if none) */
} fnav_allan_t;

/** Result at one tau. Variances in the unit of the samples squared. */
typedef struct {
    uint32_t tau;             /**< averaging factor m, samples (tau = m / f_s) */
    uint32_t level;           /**< 0: fully overlapping; j: stride 2^j (cascade) */
    uint32_t stride;          /**< samples between overlapping terms (2^level) */
    uint32_t n_phase;         /**< phase values at the point's level (for fnav_allan_edf) */
    uint32_t lag;             /**< lag at that level (tau / stride) */
    uint32_t terms;           /**< overlapping terms (second differences) */
    uint32_t terms_nonoverlap;/**< non-overlapping terms */
    fnav_real_t avar;         /**< overlapping Allan variance (NaN when terms == 0) */
    fnav_real_t avar_nonoverlap; /**< non-overlapping Allan variance (NaN when no term) */
} fnav_allan_result_t;

/** Noise type of a region of the Allan deviation curve, from the slope of
 *  log ADEV against log tau (IEEE Std 952-1997, annex C). */
typedef enum {
    FNAV_ALLAN_NOISE_UNKNOWN = 0,  /**< slope not available */
    FNAV_ALLAN_NOISE_QUANT = 1,    /**< slope -1: quantisation (white phase) */
    FNAV_ALLAN_NOISE_WHITE = 2,    /**< slope -1/2: white rate noise (angle/velocity random walk) */
    FNAV_ALLAN_NOISE_FLICKER = 3,  /**< slope 0: flicker (bias instability) */
    FNAV_ALLAN_NOISE_RRW = 4,      /**< slope +1/2: rate random walk */
    FNAV_ALLAN_NOISE_RAMP = 5      /**< slope +1: rate ramp (drift) */
} fnav_allan_noise_t;

/** Parameters identified as in the paper, section III.C. Units: those of the
 *  samples (sigma_v per sqrt(Hz)). */
typedef struct {
    fnav_real_t sigma_v;        /**< ADEV at tau = 1 s ("sensor noise"), unit/sqrt(Hz) */
    fnav_real_t bs;             /**< bias stability: the minimum of ADEV, unit */
    fnav_real_t t_bs_s;         /**< averaging time of the minimum, s */
    fnav_real_t tau_samples;    /**< correlation "coefficient" tau = t_BS f_s, samples (eq. 5) */
    fnav_real_t sigma_bias;     /**< sigma_bias = BS / sqrt(tau), unit (eq. 6) */
    uint32_t i_min;             /**< index of the grid point nearest the minimum */
} fnav_allan_paper_id_t;

/** fnav_allan_init() with the caller's FNAV_BUILD_TAG, sizeof(fnav_allan_t) and sizeof(fnav_allan_config_t)
 *  (call fnav_allan_init(), which passes them): FNAV_E_BUILD, *a not written, when one is not
 *  the library's. */
FNAV_WARN_UNUSED fnav_status_t fnav_allan_init_tagged(fnav_allan_t *a, const fnav_allan_config_t *cfg,
                                                      uint64_t build_tag, size_t obj_size, size_t cfg_size);

/**
 * Initialise an estimator.
 * @param a    estimator (caller-owned)
 * @param cfg  configuration, or NULL for fnav_allan_config_default; *cfg
 *             and its tau array are read only during the call (the grid is
 *             kept in a's tau points): neither need outlive it
 * @return FNAV_OK; FNAV_E_ARG when a is NULL; FNAV_E_CONFIG when the grid is
 *         empty, too long, not strictly ascending or has a tau that
 *         fnav_allan_tau_valid() rejects (a is then left zeroed).
 *         FNAV_E_BUILD when this file was compiled with other layout options or layout-changing flags
 *         than the library (FNAV_BUILD_TAG and the struct sizes, fnav_types.h; an inline function passes
 *         them): nothing written.
 */
static inline FNAV_WARN_UNUSED fnav_status_t fnav_allan_init(fnav_allan_t *a, const fnav_allan_config_t *cfg)
{
    return fnav_allan_init_tagged(a, cfg, FNAV_BUILD_TAG, sizeof(fnav_allan_t), sizeof(fnav_allan_config_t));
}

/**
 * Add one sample.
 * @param a  initialised estimator
 * @param y  the sample (any unit; rate, specific force, ...)
 * @return FNAV_OK; FNAV_E_ARG for NULL a; FNAV_E_NANINF for a NaN/Inf
 *         sample and FNAV_E_RANGE for |y| > FNAV_INPUT_MAX_ABS (both
 *         ignored, state unchanged), and FNAV_E_RANGE when 2^32 - 2 samples
 *         were already pushed (their 2^32 - 1 phase values are what
 *         fnav_allan_result_t.n_phase holds); FNAV_E_STATE for an estimator
 *         never initialised (zeroed, as static storage is) or whose
 *         fnav_allan_init failed (nothing taken; a sample the checks above
 *         reject is refused as such first).
 * ISR-safe for distinct objects; bounded time: on the Cortex-M4F with the
 * firmware's options at most 22,064 instructions for a push to each of 6
 * channels (`make firmware-bench FW_ICOUNT_SHIFT=6`, docs/firmware.md), and
 * 144 bytes of stack at most (push 8, push_rare 72, memcpy counted as 64:
 * `/usr/bin/python3 tests/support/stack_usage.py build/arm/obj/src
 * fnav_allan_push` after `make firmware`).
 */
FNAV_WARN_UNUSED fnav_status_t fnav_allan_push(fnav_allan_t *a, fnav_real_t y);

/** Number of tau points (the grid size). */
size_t fnav_allan_count(const fnav_allan_t *a);

/** Samples pushed so far. */
uint32_t fnav_allan_samples(const fnav_allan_t *a);

/**
 * Result at grid point i (0 .. fnav_allan_count() - 1, ascending tau).
 * @return FNAV_OK; FNAV_E_ARG for a bad index / NULL; FNAV_E_STATE for an
 *         estimator never initialised or whose fnav_allan_init failed.
 */
FNAV_WARN_UNUSED fnav_status_t fnav_allan_get(const fnav_allan_t *a, size_t i, fnav_allan_result_t *out);

/** Non-zero when tau (samples) can be tracked with the compile-time options. */
int fnav_allan_tau_valid(uint32_t tau);

/**
 * Fill a log-spaced grid: per_octave points in each octave [2^k, 2^(k+1)),
 * at m 2^j with m in (L/2, L] (L = FNAV_ALLAN_CASCADE_LAG), so every point is
 * valid; small tau are rounded and deduplicated; 2^k always included.
 * per_octave 1 gives octaves only; 2 adds 3 * 2^(k-1); 4 adds 5, 6, 7 * 2^(k-2).
 * @param tau        output array
 * @param max        its capacity
 * @param tau_max    largest tau wanted (samples; capped at FNAV_ALLAN_TAU_MAX)
 * @param per_octave 1, 2 or 4 (other values are treated as 4 when > 2)
 * @return number of entries written (stops at max).
 */
size_t fnav_allan_grid(uint32_t *tau, size_t max, uint32_t tau_max, unsigned per_octave);

/**
 * Noise type from a slope of log ADEV over log tau: the nearest of
 * -1, -1/2, 0, +1/2, +1 (boundaries half way, so |slope - k/2| < 1/4).
 */
fnav_allan_noise_t fnav_allan_noise_from_slope(fnav_real_t slope);

/** Short English name of a noise type ("white", "flicker", ...). */
const char *fnav_allan_noise_name(fnav_allan_noise_t t);

/** Power-law exponent alpha of S_y(f) ~ f^alpha for a noise type, as used
 *  by fnav_allan_edf(): quantisation +2, white 0, flicker -1, rate random
 *  walk -2; ramp (not a power law) is mapped to -2. */
int fnav_allan_noise_alpha(fnav_allan_noise_t t);

/**
 * Local slope of log ADEV against log tau at each of n points: the
 * least-squares slope over the point and its valid neighbours (3 points
 * inside, 2 at the ends). Points with avar not finite and positive are
 * skipped; their slope is NaN.
 * @param r      results (ascending tau)
 * @param n      number of results
 * @param slope  output, n entries
 */
void fnav_allan_slopes(const fnav_allan_result_t *r, size_t n, fnav_real_t *slope);

/**
 * Equivalent degrees of freedom of an Allan variance estimate, by the
 * algorithm of C. A. Greenhall and W. J. Riley, "Uncertainty of stability
 * variances based on finite differences", Proc. 35th PTTI, 2003 (the one
 * Stable32 uses). Computed in double arithmetic (not for an ISR).
 * @param alpha    power-law noise exponent, -2..+2 (fnav_allan_noise_alpha())
 * @param m        averaging factor in phase samples of the series used
 *                 (fnav_allan_result_t.lag for the overlapping estimate,
 *                 .tau with n_phase = samples + 1 for the non-overlapping one)
 * @param n_phase  phase values of that series (fnav_allan_result_t.n_phase)
 * @param overlapping 1: stride 1 (fully overlapping), 0: stride m
 * @return the EDF, or a negative value when it is undefined (no term, or
 *         alpha outside -2..+2).
 */
double fnav_allan_edf(int alpha, uint32_t m, uint32_t n_phase, int overlapping);

/**
 * The same algorithm for the family of difference variances (Greenhall &
 * Riley's d, filter factor F and stride factor S): d = 2 is the Allan
 * variance, d = 3 the Hadamard variance; modified (F = 1) gives the
 * modified Allan (and time) variance with d = 2. fnav_allan_edf() is the
 * case d = 2, unmodified.
 * @param alpha    power-law noise exponent, -4..+2, with alpha + 2 d > 1
 * @param d        order of the phase difference, 1..3
 * @param modified 1: the modified variance (phase averaged over m), 0: not
 * @param m        averaging factor in phase samples
 * @param n_phase  phase values of the series
 * @param overlapping 1: stride 1 (fully overlapping), 0: stride m
 * @return the EDF, or a negative value when it is undefined.
 */
double fnav_allan_edf_var(int alpha, int d, int modified, uint32_t m, uint32_t n_phase, int overlapping);

/**
 * EDF of the parabolic variance (PVAR, Vernotte, Lenczner, Bourgeois &
 * Rubiola, IEEE TUFFC 63(4), 2016), fully overlapping, M = n_phase - 2m
 * terms (SigmaTheta's and allantools' count), for power-law noise. The
 * same quantity as Greenhall & Riley's, computed the same way (the
 * filter's output autocovariance under the sample-averaged power law,
 * their basic sum to J = min(M, 3m) lags) for the PVAR filter, whose taps
 * (m - 1) / 2 - k, k < m, and their negatives are not in their family.
 * Exact up to m = 64; above, the filter of m = 64 with lags scaled by
 * 64 / m (the large-m limit). m = 1: PVAR is the overlapping Allan variance
 * and so is the EDF. Checked against simulation (docs/allan.md). Double
 * arithmetic and 1.1 KB of stack (the taps' autocorrelation): for the
 * host, not for an ISR; the firmware does not link it.
 * @param alpha   power-law noise exponent, -2..+2
 * @return the EDF, or a negative value when it is undefined.
 */
double fnav_allan_edf_pvar(int alpha, uint32_t m, uint32_t n_phase);

/**
 * The paper's identification (section III.C) from an Allan deviation table:
 * sigma_v = ADEV at 1 s (log-log interpolation between grid points), BS =
 * the minimum of ADEV over points with tau <= tau_max (refined by a parabola
 * through the minimum and its neighbours in log-log), tau = t_BS f_s (eq. 5),
 * sigma_bias = BS / sqrt(tau) (eq. 6). The overlapping ADEV is used.
 * @param r        results, ascending tau
 * @param n        number of results
 * @param rate_hz  sample rate, Hz
 * @param tau_max  largest tau (samples) considered for the minimum (0: all;
 *                 `harness allan` passes 10 % of the record, docs/allan.md)
 * @param id       output
 * @return FNAV_OK; FNAV_E_ARG on NULL / bad rate; FNAV_E_RANGE when 1 s is
 *         outside the tau range with data, fewer than 2 valid points, or
 *         tau_max below every valid point (no point to take the minimum of).
 */
FNAV_WARN_UNUSED fnav_status_t fnav_allan_identify_paper(const fnav_allan_result_t *r, size_t n, fnav_real_t rate_hz,
                                                         uint32_t tau_max, fnav_allan_paper_id_t *id);

#ifdef __cplusplus
}
#endif

#endif /* FNAV_ALLAN_H */
