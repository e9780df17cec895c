/**
 * @file fnav_profile.h
 * @brief Sensor error profiles: white noise plus an AR(1) / Gauss-Markov bias
 *        per axis (paper eqs. (1)-(4)), with the paper's Tables IV-VI built in.
 *
 * Units are SI and rate-independent:
 * - noise density N (white noise; the Allan deviation at tau = 1 s):
 *   m/s^2/sqrt(Hz) and rad/s/sqrt(Hz). A sample taken at rate f_s has standard
 *   deviation N * sqrt(f_s).
 * - correlation time tau_s in seconds. The paper gives tau in samples at its
 *   identification rate (eq. 5: tau = t_BS * f_s); tau_s = tau / f_s. The AR(1)
 *   coefficient for a step dt is c = exp(-dt / tau_s) (eq. 3 with
 *   c = e^(-1/tau) when dt = 1 / f_s).
 * - bias sigma: the stationary standard deviation of the AR(1) bias, the
 *   paper's sigma_bias, so that the driving noise over dt has variance
 *   sigma_bias^2 (1 - exp(-2 dt / tau_s)) (eq. 4).
 */
#ifndef FNAV_PROFILE_H
#define FNAV_PROFILE_H

#include "fnav_types.h"

#ifdef __cplusplus
extern "C" {
#endif

#define FNAV_PROFILE_NAME_MAX 32

/** One sensor's error model. */
typedef struct {
    char name[FNAV_PROFILE_NAME_MAX];       /**< e.g. "navchip" */
    fnav_real_t rate_hz;                    /**< rate the parameters were identified at, Hz */
    fnav_real_t accel_noise_mps2_rthz[3];   /**< accel white noise density, m/s^2/sqrt(Hz) */
    fnav_real_t accel_tau_s[3];             /**< accel bias correlation time, s */
    fnav_real_t accel_bias_sigma_mps2[3];   /**< accel bias stationary std, m/s^2 */
    fnav_real_t gyro_noise_rps_rthz[3];     /**< gyro white noise density, rad/s/sqrt(Hz) */
    fnav_real_t gyro_tau_s[3];              /**< gyro bias correlation time, s */
    fnav_real_t gyro_bias_sigma_rps[3];     /**< gyro bias stationary std, rad/s */
} fnav_profile_t;

/** Built-in profiles, in the paper's units as printed (see fnav_profile.c). */
typedef enum {
    FNAV_PROFILE_NAVCHIP = 0, /**< InterSense NavChip, paper Table IV (200 Hz) */
    FNAV_PROFILE_MTX = 1,     /**< Xsens MTx, paper Table V (200 Hz) */
    FNAV_PROFILE_SHIMMER = 2, /**< Shimmer, paper Table VI (200 Hz) */
    FNAV_PROFILE_COUNT
} fnav_profile_id_t;

/** One row of a paper table, in the paper's units: accel noise
 *  m/s^2/sqrt(Hz), gyro noise deg/s/sqrt(Hz), tau in samples at rate_hz,
 *  sigma_bias in m/s^2 or deg/s. Order: acc x, y, z, gyr x, y, z. */
typedef struct {
    double noise;
    double tau_samples;
    double sigma_bias;
} fnav_profile_paper_row_t;

/**
 * A generic industrial MEMS IMU (3DM-GX5 / MTi class), the navigation's
 * default (docs/navigation.md, "Bias model"): white noise as the NavChip's
 * (Table IV, rounded), each bias's stationary sd the bias instability itself
 * (gyro 10 deg/h = 4.8e-5 rad/s, accelerometer 50 ug = 4.9e-4 m/s^2) with a
 * correlation time of 100 s. Datasheet-class values, not identified from
 * the data in ../shared/data; the same as docs/profiles/generic-mems.profile
 * (tested). Built in as "generic-mems" (fnav_profile_by_name).
 */
#define FNAV_PROFILE_GENERIC_MEMS_INIT                                                                            \
    {                                                                                                             \
        "generic-mems", FNAV_R(200.0), { FNAV_R(7.4e-4), FNAV_R(6.4e-4), FNAV_R(5.0e-4) },                        \
            { FNAV_R(100.0), FNAV_R(100.0), FNAV_R(100.0) }, { FNAV_R(4.9e-4), FNAV_R(4.9e-4), FNAV_R(4.9e-4) },  \
            { FNAV_R(5.8e-5), FNAV_R(6.5e-5), FNAV_R(7.3e-5) }, { FNAV_R(100.0), FNAV_R(100.0), FNAV_R(100.0) }, \
        {                                                                                                         \
            FNAV_R(4.8e-5), FNAV_R(4.8e-5), FNAV_R(4.8e-5)                                                        \
        }                                                                                                         \
    }

/** The paper's table of a built-in profile (6 rows), or NULL. */
const fnav_profile_paper_row_t *fnav_profile_paper_table(fnav_profile_id_t id);

/**
 * Fill a profile from six paper-unit rows (acc x..z, gyr x..z), converted
 * in double (on a Cortex-M4F: soft-float code; fnav_profile_builtin is not).
 * @return FNAV_OK, or FNAV_E_ARG on NULL / non-positive values, and when
 *         the converted profile fails fnav_profile_validate (e.g. an
 *         infinite rate makes every tau 0); *p is written only on FNAV_OK.
 */
FNAV_WARN_UNUSED fnav_status_t fnav_profile_from_paper(fnav_profile_t *p, const char *name, double rate_hz,
                                                       const fnav_profile_paper_row_t rows[6]);

/** A built-in profile. @return FNAV_OK, or FNAV_E_ARG for NULL or an unknown id.
 *  A copy of the paper's table converted by the compiler, bit for bit what
 *  fnav_profile_from_paper(p, name, 200.0, table) gives: no double
 *  arithmetic at run time, so on a single-precision FPU (Cortex-M4F) no
 *  soft-float double helper is linked (docs/firmware.md, "Another sensor
 *  model"). */
FNAV_WARN_UNUSED fnav_status_t fnav_profile_builtin(fnav_profile_t *p, fnav_profile_id_t id);

/** Built-in profile by name ("navchip", "mtx", "shimmer", "generic-mems"); FNAV_E_ARG if unknown. */
FNAV_WARN_UNUSED fnav_status_t fnav_profile_by_name(fnav_profile_t *p, const char *name);

/** FNAV_OK when every value is finite and positive (rate_hz, noise, tau, sigma); else FNAV_E_CONFIG
 *  (FNAV_E_ARG for NULL). */
FNAV_WARN_UNUSED fnav_status_t fnav_profile_validate(const fnav_profile_t *p);

#ifdef __cplusplus
}
#endif

#endif /* FNAV_PROFILE_H */
