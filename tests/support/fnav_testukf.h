/**
 * @file fnav_testukf.h
 * @brief Test helpers shared by tests/test_ukf.c and tests/endure_ukf.c:
 *        the initial standard deviations the UKF tests start from, and the
 *        walk-like motion of the far-from-origin runs (docs/navigation.md,
 *        "Long runs in float32: what rounding did and does to the
 *        covariance").
 */
#ifndef FNAV_TESTUKF_H
#define FNAV_TESTUKF_H

#include "footnav/footnav.h"

/** Standard gravity, m/s^2, the walk's specific force at rest. */
#define FNAV_TEST_G_MPS2 9.80665

/** Rate of fnav_test_walk_step(), Hz (dt = 5 ms). */
#define FNAV_TEST_WALK_RATE_HZ 200.0

/** The UKF tests' initial sds: attitude 0.01 rad, gyro bias 0.001 rad/s,
 *  accelerometer bias 0.02 m/s^2 per axis, velocity 0.01 m/s, position
 *  0.001 m. */
fnav_ukf_init_sd_t fnav_test_ukf_sd_default(void);

/** Sample k of a walk-like motion at FNAV_TEST_WALK_RATE_HZ, strides of
 *  1 s: stance 0.4 s at rest (returns 1: a ZUPT is due), then swing 0.6 s
 *  pitching at up to 3 rad/s, turning at up to 0.2 rad/s (the heading
 *  couples in) and accelerating at up to 8 m/s^2 along x (returns 0). */
int fnav_test_walk_step(long k, fnav_vec3_t *w_rps, fnav_vec3_t *f_mps2);

#endif /* FNAV_TESTUKF_H */
