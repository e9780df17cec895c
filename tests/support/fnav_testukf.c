/* Test helpers shared by the UKF's suite and its endurance measurement
 * (fnav_testukf.h). */
#include "fnav_testukf.h"

#include <math.h>

fnav_ukf_init_sd_t fnav_test_ukf_sd_default(void)
{
    fnav_ukf_init_sd_t sd;
    int i;
    for (i = 0; i < 3; i++) {
        sd.att_rad[i] = FNAV_R(0.01);
        sd.gyro_bias_rps[i] = FNAV_R(0.001);
        sd.accel_bias_mps2[i] = FNAV_R(0.02);
    }
    sd.vel_mps = FNAV_R(0.01);
    sd.pos_m = FNAV_R(0.001);
    return sd;
}

int fnav_test_walk_step(long k, fnav_vec3_t *w_rps, fnav_vec3_t *f_mps2)
{
    const double t = (double)k / FNAV_TEST_WALK_RATE_HZ, ph = fmod(t, 1.0);
    *w_rps = fnav_vec3_zero();
    *f_mps2 = fnav_vec3(FNAV_R(0.0), FNAV_R(0.0), (fnav_real_t)-FNAV_TEST_G_MPS2);
    if (ph >= 0.4) {
        const double u = (ph - 0.4) / 0.6;
        w_rps->v[1] = (fnav_real_t)(3.0 * sin(6.28318530717959 * u));
        w_rps->v[2] = (fnav_real_t)(0.2 * sin(3.14159265358979 * u)); /* a turn: heading couples in */
        f_mps2->v[0] = (fnav_real_t)(8.0 * sin(6.28318530717959 * u));
        return 0;
    }
    return 1;
}
