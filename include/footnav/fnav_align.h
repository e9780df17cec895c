/**
 * @file fnav_align.h
 * @brief Initial alignment from the first still seconds (paper IV.A): roll
 *        and pitch from gravity, gyro bias from the mean angular rate,
 *        accelerometer bias along gravity, yaw 0.
 *
 * The walker stands still for a couple of seconds before walking. Every
 * sample the stance detector marks as still is averaged while its detector
 * statistic also stays below still_ratio times the geometric mean of the
 * statistic over the period so far: the zero-velocity threshold accepts the
 * slow weight shift before the first step, which would bias the gyro mean,
 * but that shift raises the statistic by a decade above the sensor's noise
 * floor (docs/navigation.md). A period that ends (motion, or the ratio test)
 * after at least min_still_s completes the alignment, as does max_still_s of
 * stillness. A shorter period restarts the average, but the quietest such
 * period (lowest mean log10 of the statistic) of at least short_still_s is
 * kept: when the detector reports motion before any period reached
 * min_still_s (a recording that starts a fraction of a second before the
 * first step), the alignment completes on it instead of waiting for a later
 * stance and losing the start of the walk.
 *
 * Gyro bias. A foot standing "still" sways and twists by a degree or two
 * (weight shifts), so the mean rate over a short period carries a rotation
 * rate of the order of the sway angle over the period (up to 2 deg/s on the
 * footprint walks, docs/navigation.md). The standard error of the mean is
 * therefore estimated from batch means (FNAV_ALIGN_BLOCKS blocks whose
 * length doubles as the period grows), which sees that correlated motion,
 * not from the white-noise formula sd / sqrt(n); the bias is the posterior
 * mean of a zero-mean prior of sd gyro_bias_prior_sd_rps (the spread of a
 * MEMS gyro's turn-on bias) updated with that mean:
 *   b_g = w k,  k = s0^2 / (s0^2 + se^2),  sd(b_g) = s0 se / sqrt(s0^2 + se^2).
 * A clean still period (se << s0) gives the mean; a swaying one is shrunk
 * towards zero. A period shorter than min_still_s (the short-period
 * fallback above) gives roll and pitch only: its gyro bias is the prior's,
 * 0 with sd s0, since the foot's smooth turn before its first step is a
 * constant rate over so short a window, which no statistic of it tells
 * from a bias (docs/navigation.md, "Short start"); with s0 = 0 (no prior)
 * it is the plain mean, as for every period.
 *
 * With the mean specific force f and the mean rate w over the still period
 * (navigation frame z down, f_b = C_bn (0, 0, -g) at rest):
 *   roll  = atan2(-f_y, -f_z),  pitch = atan2(f_x, sqrt(f_y^2 + f_z^2)),
 *   yaw   = 0 (the navigation frame's x axis is the initial heading),
 *   b_g   = w k (above; Earth rate, 7.3e-5 rad/s at most, is absorbed in the bias),
 *   b_a   = f - C_bn (0, 0, -g) = (|f| - g) f / |f|.
 * Only the component of the accelerometer bias along gravity is observable
 * at rest; its horizontal components are indistinguishable from tilt and are
 * left at zero (the tilt absorbs them).
 */
#ifndef FNAV_ALIGN_H
#define FNAV_ALIGN_H

#include "fnav_math.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Alignment configuration. */
typedef struct {
    fnav_real_t min_still_s;  /**< still period that completes the alignment at the first motion, s (default 0.5) */
    fnav_real_t max_still_s;  /**< alignment ends after this much stillness, s (default 5) */
    fnav_real_t gravity_mps2; /**< local gravity, m/s^2 (default 9.80665) */
    fnav_real_t still_ratio;  /**< statistic limit over its running geometric mean (default 10) */
    fnav_real_t short_still_s; /**< shortest period accepted when the walk starts before min_still_s
                                    of clean stillness, s (default 0.2) */
    fnav_real_t gyro_bias_prior_sd_rps; /**< prior sd of the gyro turn-on bias, rad/s; 0: no prior,
                                             the plain mean (default 0.5 deg/s) */
} fnav_align_config_t;

extern const fnav_align_config_t fnav_align_config_default;

/** A still period whose mean |f| is off gravity by more than this fraction
 *  is refused (FNAV_E_RANGE): no accelerometer at rest on the Earth reads
 *  that (bias and scale errors of any MEMS part are a few %). It is zeros
 *  from a sensor not yet running, a stuck channel, such samples averaged
 *  with real ones, or a log not in m/s^2. The harness's units check uses
 *  the same tolerance. */
#define FNAV_ALIGN_GRAVITY_TOL FNAV_R(0.25)

/** Blocks of the batch-means estimate of the gyro mean's uncertainty. */
#define FNAV_ALIGN_BLOCKS 8
/** Samples after which a still period starts again (its stamps cannot have
 *  advanced: 2^30 samples are 74 h at 4 kHz, and max_still_s ends a period
 *  long before); keeps the period's longs inside 32 bits. */
#define FNAV_ALIGN_PERIOD_MAX (1L << 30)

/** Result of an alignment. */
typedef struct {
    fnav_quat_t q_nb;          /**< initial attitude (yaw 0) */
    fnav_vec3_t euler_rad;     /**< roll, pitch, yaw = 0, rad */
    fnav_vec3_t gyro_bias_rps; /**< rad/s (posterior mean, see the file comment) */
    fnav_vec3_t accel_bias_mps2; /**< m/s^2, along gravity only */
    fnav_vec3_t accel_mean_mps2; /**< mean specific force, m/s^2 */
    fnav_vec3_t gyro_sd_rps;   /**< per-axis sample standard deviation of the rate, rad/s */
    fnav_vec3_t accel_sd_mps2; /**< per-axis sample standard deviation of f, m/s^2 */
    fnav_vec3_t gyro_mean_rps; /**< mean rate over the still period, rad/s */
    fnav_vec3_t gyro_mean_se_rps; /**< standard error of that mean (batch means), rad/s */
    fnav_vec3_t gyro_bias_sd_rps; /**< standard deviation of gyro_bias_rps, rad/s */
    fnav_real_t duration_s;    /**< still time used, s */
    long samples;              /**< samples used */
} fnav_align_result_t;

/** One still period being accumulated. Sums are kept relative to the first
 *  sample of the period so that float32 variances do not cancel. */
typedef struct {
    fnav_vec3_t a_ref, g_ref;        /**< first sample of the period */
    fnav_vec3_t sa, sg, sa2, sg2;    /**< sums of deviations and squares */
    long n;                          /**< samples in the period */
    fnav_real_t sum_log_stat;        /**< sum of log10 of the detector statistic */
    fnav_vec3_t blk[FNAV_ALIGN_BLOCKS]; /**< gyro sums of completed blocks (relative to g_ref) */
    fnav_vec3_t blk_cur;             /**< gyro sum of the block being filled */
    long blk_len;                    /**< samples per block (doubles when the blocks are full) */
    long blk_fill;                   /**< samples in the current block */
    int nblk;                        /**< completed blocks */
    int64_t t0_ns, t_last_ns;        /**< period start, last sample */
} fnav_align_period_t;

/** Accumulator (caller-owned, about 0.4 KB in float). */
typedef struct {
    fnav_align_config_t cfg;
    fnav_align_period_t cur;         /**< the period being accumulated */
    int done;
    int have_best;                   /**< result holds the quietest earlier short period */
    fnav_real_t best_log_stat;       /**< its mean log10 statistic */
    fnav_align_result_t result;      /**< the alignment (with done), or the short-period candidate */
    fnav_real_t refused_f_mps2;      /**< mean |f| of the last period refused for it (FNAV_ALIGN_GRAVITY_TOL), m/s^2; 0: none */
} fnav_align_t;

/** fnav_align_init() with the caller's FNAV_BUILD_TAG, sizeof(fnav_align_t) and sizeof(fnav_align_config_t)
 *  (call fnav_align_init(), which passes them): FNAV_E_BUILD, *al not written, when one is not
 *  the library's. */
FNAV_WARN_UNUSED fnav_status_t fnav_align_init_tagged(fnav_align_t *al, const fnav_align_config_t *cfg,
                                                      uint64_t build_tag, size_t obj_size, size_t cfg_size);

/** @return FNAV_OK, FNAV_E_ARG, FNAV_E_CONFIG (non-positive or non-finite
 *          values, max < min, short > min, still_ratio <= 1, negative prior,
 *          a positive prior whose square is 0 or not finite: in float32
 *          below about 2.6e-23 or above 1.8e19).
 *  FNAV_E_BUILD when this file was compiled with other layout options or layout-changing flags
 *  than the library (FNAV_BUILD_TAG and the struct sizes, fnav_types.h; an inline function passes
 *  them): nothing written. */
static inline FNAV_WARN_UNUSED fnav_status_t fnav_align_init(fnav_align_t *al, const fnav_align_config_t *cfg)
{
    return fnav_align_init_tagged(al, cfg, FNAV_BUILD_TAG, sizeof(fnav_align_t), sizeof(fnav_align_config_t));
}

/**
 * Feed one sample with the detector's decision.
 * @param sample  the sample (finite, checked by the caller)
 * @param still   1 when the detector marks the foot at rest
 * @param stat    the detector's test statistic (> 0), or 0 to skip the ratio test
 * @return FNAV_AGAIN while aligning, FNAV_OK when the alignment completed
 *         with this call (result valid), FNAV_E_STATE once already done
 *         or for an alignment never initialised (zeroed, as static storage is),
 *         FNAV_E_RANGE when the period that would have completed has a mean
 *         specific force off gravity by more than FNAV_ALIGN_GRAVITY_TOL
 *         (zero: no gravity direction, a sensor that outputs zeros; or
 *         zeros averaged with real samples; or not m/s^2); that period is
 *         discarded (its |f| in refused_f_mps2) and the next still sample
 *         starts a new one; FNAV_E_ARG for a NULL alignment or sample.
 */
FNAV_WARN_UNUSED fnav_status_t fnav_align_push(fnav_align_t *al, const fnav_sample_t *sample, int still,
                                                fnav_real_t stat);

/**
 * Complete the alignment with what was collected (e.g. at the end of the
 * input, or when a caller knows the period is over): the current period
 * when it has at least min_still_s, else the quietest period of at least
 * short_still_s seen (the current one included), as fnav_align_push does
 * at the first motion.
 * @return FNAV_OK with the result (also when already done), FNAV_E_STATE
 *         when no period qualifies (a current period whose mean |f| is off
 *         gravity by more than FNAV_ALIGN_GRAVITY_TOL does not) or for an
 *         alignment never initialised, FNAV_E_ARG for NULL.
 */
FNAV_WARN_UNUSED fnav_status_t fnav_align_finish(fnav_align_t *al);

/** Start measuring again: after the alignment (the renewal, below), or
 *  when a time jump interrupts a still period before it (fnav_nav). The
 *  alignment result, if any, is kept. */
void fnav_align_renew_start(fnav_align_t *al);

/**
 * Renewal: after the alignment, while the foot has not walked yet, the
 * still periods go on being measured with the same rules (the ratio test,
 * max_still_s). When a period ends with at least min_s of clean stillness,
 * its alignment is written to *out, which is not touched otherwise (out
 * may be &al->result).
 * @return 1 with *out, 0 otherwise (also for NULL arguments).
 */
int fnav_align_renew(fnav_align_t *al, const fnav_sample_t *s, int still, fnav_real_t stat, fnav_real_t min_s,
                     fnav_align_result_t *out);

/** Compute an alignment from a mean specific force, mean rate and gravity
 *  (the formulas of the file comment). FNAV_E_RANGE if |f| is not finite or
 *  off gravity by more than FNAV_ALIGN_GRAVITY_TOL (zero among them);
 *  FNAV_E_ARG for a NULL out or a gravity that is not finite and positive;
 *  FNAV_E_NANINF for a non-finite rate. *out is written only on FNAV_OK. */
FNAV_WARN_UNUSED fnav_status_t fnav_align_from_means(fnav_vec3_t f_mean, fnav_vec3_t w_mean, fnav_real_t gravity_mps2,
                                                     fnav_align_result_t *out);

#ifdef __cplusplus
}
#endif

#endif /* FNAV_ALIGN_H */
