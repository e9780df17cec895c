/**
 * @file fnav_strapdown.h
 * @brief Strapdown inertial navigation in a local-level frame: attitude,
 *        velocity and position from raw specific force and angular rate.
 *
 * Frames (docs/frames.md): n is local level, z down, x along the initial
 * heading; b is the sensor frame. Gravity in n is g_n = (0, 0, +g), so the
 * specific force at rest is f_n = (0, 0, -g). Earth rate and transport rate
 * are neglected (a walker moves a few hundred metres; Earth rate, 15 deg/h,
 * is far below the gyro noise of the sensors footnav targets; docs/frames.md).
 *
 * The algorithm (Titterton & Weston 2004, ch. 11; Savage 1998) for one
 * sample interval dt (from the previous sample's time to this sample's):
 *  - increments theta (rotation) and dv (velocity) over the interval and the
 *    coning and sculling terms, formed according to what a sample is
 *    (config.sample_type):
 *    - FNAV_SAMPLE_INSTANT (default): the readings are the instantaneous rate
 *      and specific force at the sample's time (rate-output MEMS: NGIMU,
 *      MicroStrain, Xsens rate outputs). theta and dv are the integrals over
 *      the interval of the quadratic through the last three readings
 *      (uniform steps: dt/12 (-w_k-2 + 8 w_k-1 + 5 w_k), third order; the
 *      trapezoid (w_k-1 + w_k) dt / 2 when only two readings exist or the
 *      two intervals differ by more than a factor 2), and the coning and
 *      sculling terms of the linear profile between the last two readings
 *      (derivation in fnav_strapdown.c): coning = (1/12) (w_k-1 dt) x (w_k dt),
 *      sculling = (1/12)((w_k-1 dt) x (f_k dt) + (f_k-1 dt) x (w_k dt));
 *    - FNAV_SAMPLE_MEAN: the readings are the mean rate and specific force
 *      over the interval (an integrating sensor's delta-angle and
 *      delta-velocity divided by dt): theta = w dt, dv = f dt, two-sample
 *      coning (1/12) theta_prev x theta and sculling
 *      (1/12)(theta_prev x dv + dv_prev x theta) (Savage 1998).
 *    Taking instantaneous samples for interval means runs the integration
 *    half a sample ahead of the motion (docs/navigation.md);
 *  - attitude: q_nb(k) = q_nb(k-1) * q(theta + coning), exact quaternion;
 *  - velocity: rotation compensation 0.5 theta x dv plus sculling, then
 *    v(k) = v(k-1) + C_nb(k-1) dv' + g_n dt;
 *  - position: trapezoidal, p(k) = p(k-1) + 0.5 (v(k-1) + v(k)) dt, exact for
 *    constant acceleration.
 * All functions are reentrant and may run in an interrupt (no shared state).
 */
#ifndef FNAV_STRAPDOWN_H
#define FNAV_STRAPDOWN_H

#include "fnav_math.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Kinematic state propagated by the strapdown. */
typedef struct {
    fnav_quat_t q_nb;    /**< attitude, body to navigation frame (unit, w >= 0 not required) */
    fnav_vec3_t vel_mps; /**< velocity in n, m/s */
    fnav_vec3_t pos_m;   /**< position in n, m */
} fnav_strapdown_state_t;

/** Readings of the previous samples, for the next interval. */
typedef struct {
    fnav_vec3_t w_rps;     /**< newest (bias-corrected) rate reading, rad/s */
    fnav_vec3_t f_mps2;    /**< newest (bias-corrected) specific-force reading, m/s^2 */
    fnav_vec3_t w2_rps;    /**< the reading before it, rad/s */
    fnav_vec3_t f2_mps2;   /**< the reading before it, m/s^2 */
    fnav_real_t dt_prev_s; /**< interval that ended at the newest reading, s */
    int have_sample;       /**< readings stored: 0, 1 (w_rps, f_mps2) or 2 (also w2, f2) */
    int valid;             /**< 1 once an interval was integrated (dt_prev_s valid) */
} fnav_strapdown_hist_t;

/** What a sample's readings are (fnav_strapdown.h file comment). */
typedef enum {
    FNAV_SAMPLE_INSTANT = 0, /**< instantaneous values at the sample's time (default) */
    FNAV_SAMPLE_MEAN = 1     /**< means over the interval ending at the sample's time */
} fnav_sample_type_t;

/** Configuration of the strapdown. */
typedef struct {
    fnav_real_t gravity_mps2; /**< magnitude of local gravity, m/s^2 (default 9.80665) */
    int coning;               /**< 1 (default): coning and sculling terms */
    fnav_sample_type_t sample_type; /**< FNAV_SAMPLE_INSTANT (default) or FNAV_SAMPLE_MEAN */
} fnav_strapdown_config_t;

/** Defaults: standard gravity, coning/sculling on, instantaneous samples. */
extern const fnav_strapdown_config_t fnav_strapdown_config_default;

/**
 * Normal gravity on the WGS-84 ellipsoid (Somigliana's formula, closed form
 * of Moritz 1980) with the free-air height correction -3.086e-6 m/s^2 per m.
 * @param lat_rad  geodetic latitude, rad
 * @param height_m height above the ellipsoid, m
 * @return gravity magnitude, m/s^2
 */
fnav_real_t fnav_gravity_wgs84(fnav_real_t lat_rad, fnav_real_t height_m);

/** Pre-computed increments of one interval (shared by every sigma point). */
typedef struct {
    fnav_vec3_t theta_rad; /**< rotation increment (bias removed), rad */
    fnav_vec3_t dv_mps;    /**< velocity increment (bias removed), m/s */
    fnav_vec3_t coning;    /**< coning term, rad */
    fnav_vec3_t scull;     /**< sculling term, m/s */
    fnav_real_t dt_s;      /**< interval, s */
    fnav_vec3_t w_rps;     /**< this sample's rate reading (bias removed), rad/s */
    fnav_vec3_t f_mps2;    /**< this sample's specific force (bias removed), m/s^2 */
} fnav_strapdown_incr_t;

/**
 * Form the increments of one interval from bias-corrected readings.
 * @param cfg        configuration (coning switch, sample type)
 * @param hist       previous interval (read), may be NULL for none: the first
 *                   interval takes the reading as constant over the interval
 * @param gyro_rps   angular rate reading in b, rad/s
 * @param accel_mps2 specific force reading in b, m/s^2
 * @param dt_s       interval, s (>= 0)
 * @param out        increments
 */
void fnav_strapdown_increments(const fnav_strapdown_config_t *cfg, const fnav_strapdown_hist_t *hist,
                               fnav_vec3_t gyro_rps, fnav_vec3_t accel_mps2, fnav_real_t dt_s,
                               fnav_strapdown_incr_t *out);

/** Remember the readings of this sample and, for dt > 0, the increments of
 *  its interval for the next one. */
void fnav_strapdown_hist_push(fnav_strapdown_hist_t *hist, const fnav_strapdown_incr_t *inc);

/**
 * Propagate a state over one interval with given increments; the corrections
 * d_theta and d_dv (e.g. a sigma point's bias deviation times dt) are added to
 * the increments first. The result's quaternion is renormalised.
 * @param cfg      configuration (gravity)
 * @param x        state, updated in place
 * @param inc      increments of the interval
 * @param d_theta  extra rotation increment, rad (body)
 * @param d_dv     extra velocity increment, m/s (body)
 */
void fnav_strapdown_propagate(const fnav_strapdown_config_t *cfg, fnav_strapdown_state_t *x,
                              const fnav_strapdown_incr_t *inc, fnav_vec3_t d_theta, fnav_vec3_t d_dv);

/**
 * One complete strapdown step from raw (bias-corrected) readings: forms the
 * increments, propagates and updates the history.
 * @param cfg  configuration (gravity finite and positive, a known sample type)
 * @param x    state, updated in place
 * @param hist history, updated; may be NULL (each reading held over its interval)
 * @return FNAV_OK; FNAV_E_ARG for a NULL cfg or x, or a cfg out of its
 *         domain (x and hist unchanged); FNAV_E_NANINF on a non-finite
 *         input or dt (x unchanged); FNAV_E_TIME on dt < 0 (x unchanged);
 *         FNAV_E_RANGE when finite inputs overflow the state (x and hist
 *         unchanged).
 */
FNAV_WARN_UNUSED fnav_status_t fnav_strapdown_step(const fnav_strapdown_config_t *cfg, fnav_strapdown_state_t *x,
                                                   fnav_strapdown_hist_t *hist, fnav_vec3_t gyro_rps,
                                                   fnav_vec3_t accel_mps2, fnav_real_t dt_s);

/** Quaternion of a rotation vector without trigonometric calls: below
 *  0.2 rad a 6th-order series (truncation below 2.5e-13); above, the angle
 *  wrapped to (-pi, pi], halved until below 0.2 rad (at most 4 times), the
 *  series, then squared back. NaN or Inf give the identity. */
fnav_quat_t fnav_strapdown_quat_exp(fnav_vec3_t phi);

#ifdef __cplusplus
}
#endif

#endif /* FNAV_STRAPDOWN_H */
