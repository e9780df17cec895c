/**
 * @file fnav_ukf.h
 * @brief 15-state unscented Kalman filter of foot-mounted inertial
 *        navigation (paper IV): attitude, velocity, position, gyroscope and
 *        accelerometer biases; unscented prediction through the strapdown,
 *        zero-velocity (ZUPT) and zero-angular-rate (ZARU) updates, AR(1)
 *        bias model (paper eqs. (3), (4)).
 *
 * Attitude. The paper's three Euler-angle states are carried the way the
 * attitude-estimation literature does it (Crassidis & Markley 2003, USQUE):
 * a nominal quaternion q_nb plus a three-parameter attitude error in the
 * navigation frame, q_true = dq(a) * q_nb, where a are the generalised
 * Rodrigues parameters with a = 1, f = 4 (a = 4 tan(angle/4) along the axis:
 * the rotation vector up to second order, angle + angle^3/48 + ..., trig-free
 * both ways, singular only at 360 degrees). After each prediction and update the error mean is
 * folded into q_nb and reset to zero. Roll, pitch and yaw (ZYX) are derived
 * from q_nb for output only, so the filter has no Euler singularity at
 * +-90 degrees of pitch. The covariance of the attitude error is what the
 * output reports as the attitude variances (rad^2, about the n axes).
 *
 * Lever (optional, docs/navigation.md). A foot does not stand still in
 * stance: it rolls over the heel and then over the forefoot, so the IMU
 * moves with v = C_nb (w x r) about the contact point, r the lever from that
 * pivot to the IMU in the body frame. A plain ZUPT (v = 0) removes that
 * motion every stride and the error accumulates, mostly vertically. With
 * config.lever = 1 the filter carries r as three more states (constant, with
 * a small random walk) and the zero-velocity update measures
 * v - C_nb (w x r) = 0, the velocity of the pivot; with lever = 0 it is the
 * paper's 15-state filter with v = 0.
 *
 * Landing settling (optional, docs/navigation.md, "The landing"). When the
 * foot lands it is not yet still: for a few tens of milliseconds after the
 * stance begins the IMU still moves vertically (the sole settles, the
 * forefoot comes down), a few cm/s that decay, and the lever above does not
 * explain it. A ZUPT that takes this motion for INS error corrects the
 * position as if the error had grown over the whole swing (by about half a
 * swing times the velocity) and the height climbs at every stride. With
 * config.settle = 1 the vertical settling velocity s (along the n frame's
 * z) is a coloured error of the ZUPT (Bryson & Henrikson's state
 * augmentation for coloured measurement noise): the ZUPT measures
 * v - C_nb (w x r) - s e_z = 0, s starts at each stance onset at 0 with
 * standard deviation settle_sd_mps (fnav_ukf_settle_start()) and decays as
 * s' = c s, c = exp(-dt/settle_tau_s), without driving noise. The filter
 * then attributes to s the part of the onset velocity that decays, and to
 * the INS the part that persists. s never enters the strapdown, so it is
 * kept outside the sigma points: its variance Pss and its cross-covariance
 * Pxs with the packed states are propagated as Pss' = c^2 Pss and
 * Pxs' = c F Pxs, with F the strapdown's error-state map (exact in the
 * lever, velocity, position and biases, first order in the attitude error,
 * as the closed form's gyro-bias terms), and every update is the exact
 * Kalman update of the augmented state. Once Pss has decayed below
 * 1e-4 settle_sd_mps^2 (4.6 settle_tau_s) s is dropped (marginalised: the
 * other states' covariance is unchanged).
 *
 * Internal state indices (FNAV_UKF_R .. FNAV_UKF_BA), FNAV_UKF_NMAX = 18:
 *   0-2 lever, 3-5 velocity, 6-8 position, 9-11 attitude error, 12-14 gyro
 *   bias, 15-17 accelerometer bias. The covariance fnav_ukf_t.P holds only
 *   the active states (lever without config.lever and the biases with the
 *   bias model off take no room and no time), packed in the order lever,
 *   velocity, position, accelerometer bias, gyro bias, attitude error
 *   (fnav_ukf_t.act, .pos; read it with fnav_ukf_cov()).
 * The attitude comes last so that, with an upper-triangular Cholesky factor
 * (P = U U^T, column j non-zero in rows 0..j only), the sigma-point pairs
 * along every other column leave the attitude at its centre. The strapdown
 * maps lever, velocity, position and accelerometer bias exactly linearly
 * (r' = r, v' = v + dv, p' = p + dp + dv dt, the accelerometer bias through
 * the velocity increment) and the gyro bias to first order (its sigma
 * spread rotates the increment by gamma sigma_bg dt, a few 1e-6 rad): those
 * pairs are propagated in closed form, and only the 6 attitude points go
 * through the full strapdown, in every configuration (the linear
 * substructure of a partially linear model, as in "Exploiting linear
 * substructure in LRKFs", arXiv:2009.07571, extended to the gyro bias by
 * linearisation). Running
 * every point through the strapdown (config.closed_form = 0) gives the same
 * result up to rounding with the bias model off, and up to the first-order
 * terms' relative error gamma sigma_bg dt with it (tested).
 * The output order (fnav_nav_frame_t.p_diag) is the paper's: attitude,
 * velocity, position, gyro bias, accelerometer bias.
 *
 * Numerics (float32): P is kept symmetric (only the upper triangle is
 * computed, then mirrored); the predicted covariance, referenced to the
 * propagated centre, is S + (beta - alpha^2) m m^T + Q with S = sum_i Wi D_i
 * D_i^T (fnav_ukf.c): every term is positive semi-definite for every
 * configuration init accepts (n + lambda > 0, so Wi > 0, and beta >=
 * alpha^2; the defaults alpha = 1, beta = 2, kappa = 0 among them), whatever
 * kappa and the sign of W0c, which this form never multiplies (W0c is about
 * -1e6 at alpha = 1e-3, tested). A small alpha keeps the signs; it puts
 * the sigma points at gamma = alpha sqrt(n + kappa) standard deviations,
 * so the rounding of each point's image weighs more (in the mean by Wi =
 * 1 / (2 alpha^2 (n + kappa))). n + lambda is formed as alpha^2 (n + kappa),
 * so gamma and the weights hold to rounding down to alpha = 1e-4 and below
 * (the scaled UT's usual range is 1e-4 to 1); an alpha whose W0m
 * overflows (float: about 3e-20) is refused, FNAV_E_CONFIG; updates use
 * the Joseph form, expanded as P - K H P - P H^T K^T + K S K^T (valid for any
 * gain, symmetric term by term). A Cholesky pivot that is not positive triggers the defined
 * recovery: add jitter (1e-6 of each variance) and retry; if that also fails,
 * reset P to its own diagonal (cross-covariances dropped), count it, and
 * return FNAV_E_DECOMP after completing the step with the reset covariance.
 * Non-finite inputs return FNAV_E_NANINF and leave the filter unchanged but
 * for its health.nan_inputs counter; a
 * step that would produce a non-finite state is undone (FNAV_E_DIVERGED).
 * After every prediction and update a guard keeps the diagonal finite,
 * positive and below a generous maximum per state kind (standard deviation
 * 1 m lever, 100 m/s, 10 km, pi rad, 1 rad/s, 10 m/s^2): a variance that is
 * not finite or not positive resets its row and column to zero and itself to
 * the maximum; a larger one is clamped with its row and column scaled alike
 * (health.cov_guard counts both). Long stretches without any stance (no
 * update for minutes) otherwise let float32 rounding drive variances
 * negative. An update's posterior variance that rounding takes to zero or
 * below (float32, a prior variance more than 1 / FLT_EPSILON times the
 * measurement's: the first ZUPT after minutes of swing) is instead set to
 * its exact lower bound (K R K^T)_ii, its row and column cleared (counted
 * in health.cov_guard too): the maximum would be what the next update
 * rounds to zero again, for ever.
 */
#ifndef FNAV_UKF_H
#define FNAV_UKF_H

#include "fnav_strapdown.h"

/** 1: the prediction forms the yaw variance as its change with the rounding remainder carried
 *  (fnav_ukf.c, yaw_change; docs/navigation.md, "The heading's variance stops growing"). It
 *  compensates float32 rounding, so it is on in the float build only: in double the round trip it
 *  replaces loses some 1e-16 of the variance, and the double build stays the exact reference. */
#define FNAV_UKF_YAW_CARRY (!FNAV_USE_DOUBLE)

#ifdef __cplusplus
extern "C" {
#endif

#define FNAV_UKF_N 15    /**< the paper's state dimension (output order) */
#define FNAV_UKF_NMAX 18 /**< with the optional lever states */

/** Internal covariance indices (see file comment). */
enum {
    FNAV_UKF_R = 0,
    FNAV_UKF_V = 3,
    FNAV_UKF_P = 6,
    FNAV_UKF_A = 9,
    FNAV_UKF_BG = 12,
    FNAV_UKF_BA = 15
};

/** Bias model (paper IV.A/IV.B). */
typedef enum {
    FNAV_BIAS_AR1 = 0, /**< AR(1)/Gauss-Markov biases about the alignment values (default) */
    FNAV_BIAS_OFF = 1  /**< biases fixed at the alignment values; no bias process noise */
} fnav_bias_model_t;

/** Filter configuration; SI units, per axis of the body frame. */
typedef struct {
    fnav_real_t gyro_noise_rps_rthz[3];   /**< gyro white noise density, rad/s/sqrt(Hz) */
    fnav_real_t accel_noise_mps2_rthz[3]; /**< accel white noise density, m/s^2/sqrt(Hz) */
    fnav_bias_model_t bias_model;         /**< AR1 (default) or OFF */
    fnav_real_t gyro_tau_s[3];            /**< gyro bias correlation time, s */
    fnav_real_t accel_tau_s[3];           /**< accel bias correlation time, s */
    fnav_real_t gyro_bias_sigma_rps[3];   /**< gyro bias stationary std (paper sigma_bias), rad/s */
    fnav_real_t accel_bias_sigma_mps2[3]; /**< accel bias stationary std, m/s^2 */
    fnav_strapdown_config_t strapdown;    /**< gravity, coning, sample type */
    fnav_real_t alpha, beta, kappa;       /**< unscented transform (default 1, 2, 0; beta >= alpha^2) */
    fnav_real_t zupt_sigma_mps;           /**< ZUPT measurement noise, m/s (default 0.01) */
    fnav_real_t zaru_sigma_rps;           /**< ZARU measurement noise, rad/s (default 0.01) */
    int closed_form;                      /**< 1 (default): closed-form linear sigma points; 0: all
                                               through the strapdown (other values refused) */
    int lever;                            /**< 1: estimate the pivot-to-IMU lever (default 0) */
    fnav_real_t lever_sd_m;               /**< initial lever sd per axis, m (default 0.1) */
    fnav_real_t lever_rw_m_rts;           /**< lever random walk, m/sqrt(s) (default 0.002) */
    int settle;                           /**< 1: landing settling state (file comment; default 0) */
    fnav_real_t settle_sd_mps;            /**< settling sd at stance onset, m/s (default 0.025) */
    fnav_real_t settle_tau_s;             /**< settling time constant, s (default 0.03) */
    fnav_real_t zaru_gate;                /**< ZARU validation gate on the innovation's NIS (chi-square,
                                               3 dof); 0: none (default 11.34, the 99 % point) */
} fnav_ukf_config_t;

/** Defaults: NavChip-like noise (paper Table IV), AR(1) model, 9.80665 m/s^2. */
extern const fnav_ukf_config_t fnav_ukf_config_default;

/** Initial standard deviations (after alignment), in the output order. */
typedef struct {
    fnav_real_t att_rad[3];   /**< attitude error about n x, y, z, rad */
    fnav_real_t vel_mps;      /**< per axis, m/s */
    fnav_real_t pos_m;        /**< per axis, m */
    fnav_real_t gyro_bias_rps[3];   /**< rad/s */
    fnav_real_t accel_bias_mps2[3]; /**< m/s^2 */
} fnav_ukf_init_sd_t;

/** Health counters of the filter. */
typedef struct {
    uint32_t predicts;      /**< predictions done */
    uint32_t zupts;         /**< ZUPT updates applied */
    uint32_t zarus;         /**< ZARU updates applied */
    uint32_t zaru_gated;    /**< ZARU updates skipped: NIS beyond config.zaru_gate (the foot turns) */
    uint32_t chol_jitter;   /**< factorisations that needed jitter */
    uint32_t chol_reset;    /**< covariance resets to the diagonal */
    uint32_t nan_inputs;    /**< inputs rejected as NaN/Inf */
    uint32_t diverged;      /**< steps undone because the result was not finite */
    uint32_t update_reject; /**< updates skipped (innovation covariance not positive) */
    uint32_t cov_guard;     /**< covariance entries reset or clamped by the guard (file comment) */
} fnav_ukf_health_t;

/** The filter (caller-owned, fixed size: 3 matrices of 18 x 18). */
typedef struct {
    fnav_ukf_config_t cfg;
    int started;               /**< fnav_ukf_start() was called */
    int n_act;                 /**< active states (9, 12, 15 or 18) */
    int n_lin;                 /**< leading packed states propagated in closed form (all but the attitude) */
    unsigned char act[FNAV_UKF_NMAX]; /**< internal indices of the active states, in packing order */
    int16_t pos[FNAV_UKF_NMAX];       /**< packed index of each internal state, -1 if inactive */
    fnav_real_t gamma;         /**< sigma-point scale sqrt(n + lambda) */
    fnav_real_t w0m, w0c, wi;  /**< weights */
    /* nominal state */
    fnav_quat_t q_nb;          /**< attitude */
    fnav_vec3_t vel_mps;       /**< velocity in n, m/s */
    fnav_vec3_t pos_m;         /**< position in n, m */
    fnav_vec3_t bg_rps;        /**< gyro bias, rad/s */
    fnav_vec3_t ba_mps2;       /**< accel bias, m/s^2 */
    fnav_vec3_t bg0_rps;       /**< alignment gyro bias (AR(1) mean), rad/s */
    fnav_vec3_t ba0_mps2;      /**< alignment accel bias (AR(1) mean), m/s^2 */
    fnav_vec3_t lever_m;       /**< pivot-to-IMU lever in b, m (0 without config.lever) */
    fnav_strapdown_hist_t hist;/**< previous increments (coning, sculling) */
    fnav_real_t ar1_dt_s;      /**< interval of the cached AR(1) terms, s (0: none) */
    fnav_real_t ar1_c[6];      /**< cached exp(-dt/tau), gyro then accel */
    fnav_real_t ar1_q[6];      /**< cached sigma^2 (1 - c^2) */
    int settle_on;             /**< the settling state is active (since the last stance onset) */
    fnav_real_t settle_mps;    /**< settling velocity along n z, m/s (0 when not active) */
    fnav_real_t settle_var;    /**< its variance Pss, (m/s)^2 */
    fnav_real_t settle_dt_s;   /**< interval of the cached decay (0: none) */
    fnav_real_t settle_c;      /**< cached exp(-dt/settle_tau_s) */
#if FNAV_UKF_YAW_CARRY
    fnav_real_t p_yaw_carry_rad2; /**< yaw variance's rounding remainder, rad^2: the part of the last
                                       prediction's change of P's yaw entry that rounding left out, added
                                       to the next one (fnav_ukf.c, yaw_change); 0 whenever P is set */
#endif
    fnav_real_t Pxs[FNAV_UKF_NMAX]; /**< cross-covariance of the packed states with the settling */
    fnav_real_t P[FNAV_UKF_NMAX][FNAV_UKF_NMAX];  /**< covariance of the active states, packed in the
                                                       order of act[] (use fnav_ukf_cov()) */
    fnav_real_t U[FNAV_UKF_NMAX][FNAV_UKF_NMAX];  /**< scratch: Cholesky factor */
    fnav_real_t S[FNAV_UKF_NMAX][FNAV_UKF_NMAX];  /**< scratch: new covariance */
    fnav_real_t Hm[3][FNAV_UKF_NMAX];             /**< scratch: measurement matrix */
    fnav_real_t K[FNAV_UKF_NMAX][3];              /**< scratch: gain (update); bias maps (prediction) */
    fnav_real_t PHt[FNAV_UKF_NMAX][3];            /**< scratch: P H^T */
    fnav_real_t APHt[FNAV_UKF_NMAX][3];           /**< scratch: K S */
    fnav_ukf_health_t health;
} fnav_ukf_t;

/** fnav_ukf_init() with the caller's FNAV_BUILD_TAG, sizeof(fnav_ukf_t) and sizeof(fnav_ukf_config_t)
 *  (call fnav_ukf_init(), which passes them): FNAV_E_BUILD, *f not written, when one is not
 *  the library's. */
FNAV_WARN_UNUSED fnav_status_t fnav_ukf_init_tagged(fnav_ukf_t *f, const fnav_ukf_config_t *cfg,
                                                    uint64_t build_tag, size_t obj_size, size_t cfg_size);

/**
 * Initialise (validates the configuration; the filter waits for
 * fnav_ukf_start()), or start over: every earlier state and counter is
 * dropped. *cfg is copied; it may be the filter's own, &f->cfg, to start
 * over with the same configuration. On a refused configuration *f is left
 * as it was.
 * @return FNAV_OK, FNAV_E_ARG on NULL, FNAV_E_CONFIG on a bad value
 *         (negative or non-finite noise, or a noise density or lever
 *         random walk whose square is not finite (float32: above about
 *         1.8e19), non-positive tau/sigma with AR1,
 *         alpha <= 0, n + lambda <= 0, beta < alpha^2 (a predicted
 *         covariance term that is not positive semi-definite), non-positive
 *         measurement noise,
 *         lever, settle or closed_form other than 0 or 1; a
 *         standard deviation, measurement or bias sigma, lever or settling
 *         sd, whose square is 0 or not finite: in float32 below about
 *         2.6e-23 or above 1.8e19).
 *         FNAV_E_BUILD when this file was compiled with other layout options or layout-changing flags
 *         than the library (FNAV_BUILD_TAG and the struct sizes, fnav_types.h; an inline function passes
 *         them): nothing written.
 */
static inline FNAV_WARN_UNUSED fnav_status_t fnav_ukf_init(fnav_ukf_t *f, const fnav_ukf_config_t *cfg)
{
    return fnav_ukf_init_tagged(f, cfg, FNAV_BUILD_TAG, sizeof(fnav_ukf_t), sizeof(fnav_ukf_config_t));
}

/** A sigma point's attitude error, a GRP (a = 1, f = 4: magnitude 4
 *  tan(angle / 4)), is at most this large at the start: 3 is a rotation of
 *  4 atan(3/4) = 147 deg, 33 deg short of the 180 deg (magnitude 4) beyond
 *  which the prediction reads it back as the shorter rotation the other
 *  way and shrinks the covariance without information
 *  (docs/navigation.md, "States"). */
#define FNAV_UKF_ATT_GRP_MAX FNAV_R(3.0)

/**
 * The largest initial attitude-error standard deviation per axis, rad,
 * that fnav_ukf_start() takes with a configuration:
 * FNAV_UKF_ATT_GRP_MAX / gamma, gamma = alpha sqrt(n + kappa) (0.775 rad =
 * 44.4 deg with fnav_ukf_config_default's 15 states, 0.707 rad = 40.5 deg
 * with the lever's 18, the navigator's default).
 * @return that sd, or 0 for a NULL configuration or one whose n + lambda is
 *         not positive and finite.
 */
fnav_real_t fnav_ukf_att_sd_max(const fnav_ukf_config_t *cfg);

/**
 * Start navigating from an aligned state at the origin at rest.
 * @param q_nb     initial attitude, any non-zero scale (normalised)
 * @param bg_rps   gyro bias from the alignment, rad/s
 * @param ba_mps2  accel bias from the alignment, m/s^2
 * @param sd       initial standard deviations, every one finite and > 0 with
 *                 a finite positive square (the bias ones are checked, then
 *                 unused, with the model off)
 * @return FNAV_OK, FNAV_E_ARG (a NULL pointer, an sd not finite and
 *         positive or whose square is not, an attitude sd whose sigma
 *         points pass FNAV_UKF_ATT_GRP_MAX: sd gamma above it, see
 *         fnav_ukf_att_sd_max(); the zero quaternion),
 *         FNAV_E_NANINF on non-finite values, FNAV_E_STATE for a filter
 *         not initialised (all bytes 0, as in static storage; an automatic
 *         object never initialised holds whatever was on the stack: not
 *         detectable); the filter unchanged on a failure.
 */
FNAV_WARN_UNUSED fnav_status_t fnav_ukf_start(fnav_ukf_t *f, fnav_quat_t q_nb, fnav_vec3_t bg_rps,
                                              fnav_vec3_t ba_mps2, const fnav_ukf_init_sd_t *sd);

/**
 * Unscented prediction over one interval with raw readings.
 * @param gyro_rps    angular rate (body, bias not removed), rad/s
 * @param accel_mps2  specific force (body, bias not removed), m/s^2
 * @param dt_s        interval, s; 0 does nothing
 * @return FNAV_OK; FNAV_E_ARG for a NULL filter; FNAV_E_NANINF (input
 *         ignored); FNAV_E_TIME on dt < 0; FNAV_E_STATE before start; FNAV_E_DECOMP when the covariance had
 *         to be reset (step completed); FNAV_E_DIVERGED (step undone: the
 *         state as before it; the covariance too, but for a jitter or reset
 *         its factorisation needed before the step, which is kept and
 *         counted in health.chol_jitter / chol_reset).
 */
FNAV_WARN_UNUSED fnav_status_t fnav_ukf_predict(fnav_ukf_t *f, fnav_vec3_t gyro_rps, fnav_vec3_t accel_mps2,
                                                fnav_real_t dt_s);

/**
 * Zero-velocity update with standard deviation zupt_sigma_mps per axis:
 * v = 0, or with config.lever v - C_nb (w x r) = 0 for the bias-corrected
 * rate w of this sample; minus s e_z while the settling state is active. The measurement is linear in the error states (the
 * lever term to first order), so the exact Kalman update is used: it is what
 * the unscented update reduces to for a linear measurement.
 * @param gyro_rps  raw angular rate of the sample (body), rad/s (used with the lever)
 * @return FNAV_OK; FNAV_E_ARG for a NULL filter; FNAV_E_STATE before start;
 *         FNAV_E_NANINF on a non-finite rate; FNAV_E_DECOMP when the innovation covariance is not positive
 *         (update skipped, counted in health.update_reject); FNAV_E_DIVERGED
 *         when the correction or the new covariance would not be finite
 *         (update undone, counted in health.diverged).
 */
FNAV_WARN_UNUSED fnav_status_t fnav_ukf_zupt(fnav_ukf_t *f, fnav_vec3_t gyro_rps);

/**
 * Start the landing settling state (config.settle): s = 0 with variance
 * settle_sd_mps^2, uncorrelated with the other states. The navigator calls
 * it when a stance begins, before its first ZUPT. Nothing happens with
 * config.settle = 0.
 * @return FNAV_OK; FNAV_E_ARG; FNAV_E_STATE before start.
 */
FNAV_WARN_UNUSED fnav_status_t fnav_ukf_settle_start(fnav_ukf_t *f);

/**
 * Zero-angular-rate update: the raw gyro reading equals the gyro bias
 * (the foot does not rotate), standard deviation zaru_sigma_rps. A
 * validation gate skips it when the foot does turn: with the innovation
 * y = gyro - b_g and S = P_bg + zaru_sigma^2 I, the update is made only
 * when y^T S^-1 y <= config.zaru_gate (0: always).
 * @return as fnav_ukf_zupt(); FNAV_E_NANINF on a non-finite reading;
 *         FNAV_E_RANGE without effect when the gate rejects the reading
 *         (counted in health.zaru_gated); FNAV_OK without effect when the
 *         bias model is off.
 */
FNAV_WARN_UNUSED fnav_status_t fnav_ukf_zaru(fnav_ukf_t *f, fnav_vec3_t gyro_rps);

/** Covariance element of the internal states i, j (FNAV_UKF_V + k etc.);
 *  0 for a state that is switched off. */
fnav_real_t fnav_ukf_cov(const fnav_ukf_t *f, int i, int j);

/** Set a covariance element (and its mirror) of two active internal states
 *  (for tests and for callers that seed correlations). */
void fnav_ukf_set_cov(fnav_ukf_t *f, int i, int j, fnav_real_t v);

/** Roll, pitch, yaw (ZYX) of the nominal attitude, rad. */
fnav_vec3_t fnav_ukf_euler(const fnav_ukf_t *f);

/** Covariance diagonal in the output order (att, vel, pos, bg, ba). */
void fnav_ukf_p_diag(const fnav_ukf_t *f, fnav_real_t out[FNAV_UKF_N]);

/** Quaternion of generalised Rodrigues parameters (a = 1, f = 4). */
fnav_quat_t fnav_ukf_grp_to_quat(fnav_vec3_t p);

/** Generalised Rodrigues parameters (a = 1, f = 4) of a unit quaternion
 *  (the sign is chosen so that the scalar part is non-negative). */
fnav_vec3_t fnav_ukf_quat_to_grp(fnav_quat_t q);

#ifdef __cplusplus
}
#endif

#endif /* FNAV_UKF_H */
