/**
 * @file hx_allan_ident.h
 * @brief Sensor-noise models and their identification from an Allan
 *        deviation table (harness side; docs/allan.md "Identification").
 *
 * The model of one channel is white noise plus a first-order Gauss-Markov
 * (AR(1)) bias, the paper's eqs. (1)-(4), optionally with quantisation and
 * rate random walk terms. Two identifications are offered:
 *
 * - hx_allan_identify() "paper": section III.C as written (eqs. 5-6) through
 *   fnav_allan_identify_paper(), read with eq. (4), i.e. sigma_bias is the
 *   stationary standard deviation of the AR(1) bias;
 * - "fit": a weighted least-squares fit of the model's exact discrete-time
 *   Allan variance to the measured one (log ADEV residuals weighted by the
 *   equivalent degrees of freedom), which reproduces the measured curve.
 *
 * Also: the exact Allan variance of the model at any tau, a streaming
 * simulator of the model (paper Fig. 7 check) and confidence intervals.
 * Used by `harness allan` and meant for reuse (sim-to-real, issue #6).
 * All quantities are doubles in the unit of the channel (u): u is m/s^2 or
 * rad/s in SI, or whatever the series is in.
 */
#ifndef HX_ALLAN_IDENT_H
#define HX_ALLAN_IDENT_H

#include <stddef.h>
#include <stdint.h>
#include "footnav/fnav_allan.h"

/** Noise model of one channel. A zero coefficient switches a term off. */
typedef struct {
    double white;     /**< N: white-noise density = ADEV at 1 s, u/sqrt(Hz); sample std N sqrt(f_s) */
    double gm_sigma;  /**< AR(1) bias stationary standard deviation, u (paper sigma_bias, eq. 4) */
    double gm_tau_s;  /**< AR(1) correlation time, s (paper tau / f_s, eq. 5) */
    double quant;     /**< Q: quantisation / white phase, u s; AVAR 3 Q^2 / tau^2 */
    double rrw;       /**< K: rate random walk, u/sqrt(s); AVAR K^2 tau / 3 */
} hx_noise_model_t;

/** Quality of a model against a measured table. */
typedef struct {
    double rms_log10;  /**< RMS of log10(ADEV_model / ADEV_measured) over the points used */
    double max_ratio;  /**< largest max(model/measured, measured/model) over them */
    double ratio_at_min; /**< model / measured ADEV at the measured minimum (bias instability) */
    int npoints;       /**< points used */
    int iterations;    /**< least-squares iterations (fit only) */
} hx_allan_quality_t;

/** Options of the fit. */
typedef struct {
    int with_quant;      /**< also fit Q */
    int with_rrw;        /**< also fit K */
    double tau_max_s;    /**< use points with tau <= this (s); 0: all with terms */
    double model_floor;  /**< relative model-error floor in the weights (default 0.05) */
} hx_allan_fit_opts_t;

/** Defaults: white + AR(1) only, tau_max 0, floor 0.05. */
extern const hx_allan_fit_opts_t hx_allan_fit_opts_default;

/** Everything identified for one channel. */
typedef struct {
    fnav_allan_paper_id_t paper;      /**< the paper's numbers (eqs. 5-6) */
    int paper_ok;                     /**< 0 when the table does not allow it (e.g. 1 s not covered) */
    hx_noise_model_t paper_model;     /**< white = sigma_v, AR(1) sigma = sigma_bias, T = tau / f_s */
    hx_allan_quality_t paper_quality; /**< how well the paper's model reproduces the table */
    hx_noise_model_t paper_drive_model;     /**< other reading: sigma_bias = std of the driving noise n_k */
    hx_allan_quality_t paper_drive_quality; /**< its quality */
    hx_allan_quality_t paper_sample_quality; /**< eq. 4 reading with sigma_v taken as the per-sample std */
    hx_noise_model_t fit;             /**< corrected identification */
    int fit_ok;                       /**< 0 when the fit failed */
    hx_allan_quality_t fit_quality;
} hx_allan_ident_t;

/**
 * Exact Allan variance of the model sampled at rate_hz, averaged over m
 * samples (tau = m / rate_hz): white N^2 f_s / m; AR(1)
 * (s^2/m^2)[m + 2c(m(1-c) - (1-c^m))/(1-c)^2 - c(1-c^m)^2/(1-c)^2],
 * c = exp(-1/(T f_s)); quantisation 3 Q^2 / tau^2; random walk
 * (K^2/f_s)(2 m^2 + 1)/(6 m). Unit u^2.
 */
double hx_noise_model_avar(const hx_noise_model_t *mdl, double rate_hz, double m);

/**
 * Weighted least-squares fit of the model to a measured table (overlapping
 * ADEV). Stage 1: for correlation times on a log grid, unconstrained
 * linear least squares for the squared amplitudes (a T whose solution has
 * an amplitude <= 0 is discarded; when every T is, the fit fails); stage
 * 2: Levenberg-Marquardt
 * (GSL) on log ADEV over log parameters from the best stage-1 point.
 * Weight of a point 1/sqrt(1/(2 EDF) + floor^2), EDF by Greenhall with the
 * noise type from the local slope. A set of terms is tried only with more
 * points than parameters (its amplitudes and T): 4 points fit white + AR(1)
 * only, 5 add Q or K, 6 both.
 * @return 0, or -1 when fewer than 4 usable points or the fit fails.
 */
int hx_allan_fit(const fnav_allan_result_t *r, size_t n, double rate_hz, const hx_allan_fit_opts_t *opts,
                 hx_noise_model_t *out, hx_allan_quality_t *q);

/** Quality of any model against a table (same points as the fit uses). */
void hx_allan_quality(const fnav_allan_result_t *r, size_t n, double rate_hz, double tau_max_s,
                      const hx_noise_model_t *mdl, hx_allan_quality_t *q);

/**
 * Both identifications of one channel.
 * @param r        table, ascending tau
 * @param n        points
 * @param rate_hz  sample rate
 * @param opts     fit options (NULL: defaults); tau_max_s also bounds the
 *                 paper's search for the minimum
 * @param out      results
 * @return 0 when at least one identification worked, -1 otherwise.
 */
int hx_allan_identify(const fnav_allan_result_t *r, size_t n, double rate_hz, const hx_allan_fit_opts_t *opts,
                      hx_allan_ident_t *out);

/** Readings of the paper's parameters (docs/allan.md, "The paper's identification"). */
typedef enum {
    HX_PAPER_EQ4 = 0,    /**< sigma_bias is the stationary std of b (eq. 4); sigma_v a density (III.C.1) */
    HX_PAPER_DRIVE = 1,  /**< sigma_bias is the std of the driving noise n_k (Fig. 7 text) */
    HX_PAPER_SAMPLE = 2  /**< as EQ4, but sigma_v drawn as the per-sample std (Fig. 7 text) */
} hx_paper_reading_t;

/** Model of the paper's identification under one reading. */
void hx_noise_model_paper_reading(const fnav_allan_paper_id_t *id, double rate_hz, hx_paper_reading_t reading,
                                  hx_noise_model_t *mdl);

/** Model of the paper's identification as eq. (4) defines sigma_bias (HX_PAPER_EQ4). */
void hx_noise_model_from_paper(const fnav_allan_paper_id_t *id, double rate_hz, hx_noise_model_t *mdl);

/** ADEV peak of a Gauss-Markov bias alone relative to its stationary std
 *  sigma, and where it lies: max ADEV = 0.6174 sigma at tau = 1.893 T
 *  (maximum of (2 sigma^2 T / tau)[1 - T/(2 tau)(3 - 4 e^(-tau/T) + e^(-2 tau/T))];
 *  the often quoted 0.437 is the same peak per q_c sqrt(T), q_c^2 = 2 sigma^2 / T). */
#define HX_GM_PEAK_RATIO 0.6174
#define HX_GM_PEAK_TAU 1.893

/** Shortest AR(1) bump (1.89 T), in samples, that `harness allan` takes as a
 *  bias: two decades above the shortest tau (one sample). A correlation time
 *  of a few samples is the shape of the sensor's own filtering (anti-alias
 *  low-pass, decimation averaging: white noise through it falls below the
 *  white line over the first decade of tau), which white + AR(1) fits as a
 *  "bias" of T = 1-3 samples that takes part of the white noise; a bump must
 *  clear that decade by another to be told from it (docs/allan.md, "When the
 *  AR(1) part is not identifiable"). T >= 100 / 1.89 = 53 samples. */
#define HX_ALLAN_AR1_MIN_BUMP_SAMPLES 100.0

/**
 * Confidence interval of a deviation with edf degrees of freedom (chi-square,
 * NIST SP 1065 eq. 45). conf e.g. 0.683. @return 0, or -1 when edf <= 0.
 */
int hx_allan_ci(double dev, double edf, double conf, double *lo, double *hi);

/** Chi-square quantile: the P-quantile of chi^2 with nu degrees of freedom
 *  (GSL's gsl_cdf_chisq_Pinv up to nu = 1e4; above, where GSL's search
 *  fails at some nu, the Wilson-Hilferty approximation, within 2.6e-7).
 *  NaN when GSL fails. */
double hx_chi2_quantile(double nu, double p);

/**
 * EDF of a table entry: Greenhall with alpha from the noise type.
 * @param overlapping 1 for the overlapping estimate, 0 for the non-overlapping one
 */
double hx_allan_point_edf(const fnav_allan_result_t *r, fnav_allan_noise_t type, int overlapping);

/**
 * Allan variance at averaging factor m from a whole phase record x_0..x_{n-1}
 * (x_k = sum of the first k samples, any constant removed), offline and in
 * double: the fully overlapping estimator (stride 1, NIST SP 1065 eq. 11,
 * n - 2m terms: the numbers and term counts Stable32 prints at every tau)
 * or the non-overlapping one (stride m, eq. 7, floor((n - 1)/m) - 1 terms).
 * The core's streaming estimator gives the same at tau <= 255 samples and
 * a stride-2^j estimate beyond (docs/allan.md, "Cascade beyond").
 * @param terms  out: the number of terms (0: none, and the result is NaN)
 */
double hx_allan_avar_record(const double *x, size_t n, uint32_t m, int overlapping, uint32_t *terms);

/** Fewest averaged values the lag-1 autocorrelation noise identification uses. */
#define HX_ACF_MIN_POINTS 30u
/** Fewest averaged values the B1-ratio identification (below HX_ACF_MIN_POINTS) uses. */
#define HX_B1_MIN_POINTS 4u

/** How a noise exponent was identified (hx_allan_noise_id_acf()). */
typedef enum {
    HX_NOISE_ID_SLOPE = 0, /**< from the slope of log ADEV (no identification from the data) */
    HX_NOISE_ID_ACF,       /**< lag-1 autocorrelation */
    HX_NOISE_ID_B1,        /**< Barnes' B1 ratio */
    HX_NOISE_ID_B1_RN,     /**< B1, then MVAR / AVAR to tell white from flicker phase noise */
    HX_NOISE_ID_HELD       /**< the slope's at the tau before: this tau's slope is a periodic term's fall */
} hx_noise_id_t;

/** "slope", "acf", "b1", "b1+rn" or "held". */
const char *hx_noise_id_name(hx_noise_id_t how);

/**
 * Marks the tau where the slope of log ADEV reads phase noise (slope about
 * -1, FNAV_ALLAN_NOISE_QUANT) after a shorter tau read frequency noise
 * (white, flicker, rate random walk or ramp). Power-law noises add in Allan
 * variance and phase noise falls fastest with tau (as 1/tau), so where it
 * does not dominate a tau it cannot dominate any longer one: a fall that
 * steep there is a periodic term's past its peak (IEEE Std 952-1997, annex
 * C: sinusoidal noise, ADEV ~ sin^2(pi f0 tau) / (pi f0 tau)), not
 * quantisation, and an EDF of phase noise there is far too large.
 *
 * @param noise     the slope's noise type per tau, shortest tau first
 * @param n         number of tau
 * @param periodic  out: 1 at a marked tau, else 0
 */
void hx_allan_mark_periodic(const fnav_allan_noise_t *noise, size_t n, unsigned char *periodic);

/**
 * Power-law noise exponent alpha (S_y(f) ~ f^alpha) at averaging factor m
 * by the lag-1 autocorrelation method (W. J. Riley and C. A. Greenhall,
 * "Power law noise identification using the lag 1 autocorrelation", 18th
 * EFTF, 2004; the method Stable32 uses): the frequency averaged over m
 * (non-overlapping) and detrended (least-squares line) is differenced d
 * times until delta = r1 / (1 + r1) < 0.25 (r1: its lag-1 autocorrelation)
 * or d = 2; alpha = -round(2 delta) - 2 d, limited to -2..+2. Unlike the
 * slope of ADEV it tells flicker phase (+1) from white phase (+2) noise.
 * With fewer than HX_ACF_MIN_POINTS averages (but HX_B1_MIN_POINTS or more)
 * it uses Barnes' B1 ratio (standard over Allan variance of the averages)
 * against its expected value for alpha = -2, -1, 0 and phase noise, nearest
 * on a log scale. B1 cannot tell white from flicker phase noise; there, as
 * Stable32 does, the ratio R(m) = MVAR / AVAR of the record decides: 1 / m
 * for white phase noise, 3 ln(256/27) / (2 (1.038 + 3 ln(pi m))) for
 * flicker phase noise with the bandwidth at the Nyquist frequency (NIST
 * SP 1065 sec. 5.6), split at their geometric mean.
 * @param x      phase record x_0..x_{n-1} (hx_allan_avar_record())
 * @param alpha  out: the integer exponent
 * @param how    out (may be NULL): the method that gave it
 * @return 0, or -1 when fewer than HX_B1_MIN_POINTS averages exist or out of memory
 */
int hx_allan_noise_id_acf(const double *x, size_t n, uint32_t m, int *alpha, hx_noise_id_t *how);

/**
 * EDF of a table entry for a given alpha (Greenhall; fnav_allan_edf()).
 * @param overlapping 1 for the overlapping estimate, 0 for the non-overlapping one
 */
double hx_allan_point_edf_alpha(const fnav_allan_result_t *r, int alpha, int overlapping);

/* ------------------------------------------------------------ simulation */

/** Streaming simulator of a noise model: e_k = b_k + v_k (+ quantisation,
 *  + random walk), the paper's eqs. (2)-(4). */
typedef struct {
    void *rng;          /**< gsl_rng * */
    double c;           /**< AR(1) coefficient exp(-1 / (T f_s)) */
    double sd_drive;    /**< AR(1) driving noise std sigma sqrt(1 - c^2) (eq. 4) */
    double sd_white;    /**< white sample std N sqrt(f_s) */
    double sd_quant;    /**< phase noise std Q (u s) */
    double sd_rw;       /**< random-walk step std K / sqrt(f_s) */
    double rate_hz;
    double b, rw, xq;   /**< AR(1) state, random-walk state, last phase noise */
} hx_noise_sim_t;

/** Start a simulator (the AR(1) starts in its stationary distribution).
 *  @return 0, -1 on a bad model or rate. */
int hx_noise_sim_init(hx_noise_sim_t *s, const hx_noise_model_t *mdl, double rate_hz, unsigned long seed);
/** Next sample, u. */
double hx_noise_sim_next(hx_noise_sim_t *s);
void hx_noise_sim_free(hx_noise_sim_t *s);

/**
 * Allan table of n simulated samples of a model, through the same streaming
 * estimator and grid as a measurement (the paper's Fig. 7 check).
 * @param out  at least fnav_allan_count() entries for cfg
 * @return number of points, or 0 on failure.
 */
size_t hx_allan_simulate(const hx_noise_model_t *mdl, double rate_hz, uint32_t n, unsigned long seed,
                         const fnav_allan_config_t *cfg, fnav_allan_result_t *out);

#endif /* HX_ALLAN_IDENT_H */
