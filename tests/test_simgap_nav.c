/* Tests of the walk domain's building blocks of the sim-to-real gap
 * diagnosis (harness/hx_simgap_nav.h, docs/simgap.md "Walks"): the sensor's
 * linear error from the one fitted on the filter's trajectory, and the
 * matching of real and twin stances. End-to-end walk diagnoses are in
 * tests/cli/test_simgap.sh. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "hx_simgap_nav.h"
#include "support/fnav_testdata.h"

/* A scale factor b fitted on the trajectory is the sensor's b / (1 - b)
 * (analytic: x_t = (1 + s) x, b x_t = s x); g-sensitivity alone (gyro rows,
 * accelerometer columns: B B = 0) is unchanged. */
static void test_lin_to_sensor_analytic(void **state)
{
    double B[6][6], A[6][6];
    int i, j;
    (void)state;
    memset(B, 0, sizeof B);
    B[5][5] = 0.2;
    B[2][2] = -0.03;
    assert_int_equal(sg_nav_lin_to_sensor((const double(*)[6])B, A), 0);
    FNAV_ASSERT_CLOSE(A[5][5], 0.25, 1e-12, 0.0);
    FNAV_ASSERT_CLOSE(A[2][2], -0.03 / 1.03, 1e-12, 0.0);
    /* a sensor scale of 0.3 seen through the trajectory: b = 0.3 / 1.3 */
    B[5][5] = 0.3 / 1.3;
    assert_int_equal(sg_nav_lin_to_sensor((const double(*)[6])B, A), 0);
    FNAV_ASSERT_CLOSE(A[5][5], 0.3, 1e-12, 0.0);
    memset(B, 0, sizeof B);
    B[5][2] = 2.3e-3;
    B[3][1] = -1.1e-2;
    assert_int_equal(sg_nav_lin_to_sensor((const double(*)[6])B, A), 0);
    for (i = 0; i < 6; i++) {
        for (j = 0; j < 6; j++) {
            FNAV_ASSERT_CLOSE(A[i][j], B[i][j], 1e-15, 0.0);
        }
    }
}

/* For a full B, A satisfies its definition (I + A)(I - B) = I, and a
 * singular I - B is reported. */
static void test_lin_to_sensor_inverse(void **state)
{
    double B[6][6], A[6][6];
    int i, j, k;
    (void)state;
    for (i = 0; i < 6; i++) {
        for (j = 0; j < 6; j++) {
            B[i][j] = 0.05 * sin(1.0 + 3.0 * (double)i + 7.0 * (double)j);
        }
    }
    assert_int_equal(sg_nav_lin_to_sensor((const double(*)[6])B, A), 0);
    for (i = 0; i < 6; i++) {
        for (j = 0; j < 6; j++) {
            double s = 0.0;
            for (k = 0; k < 6; k++) {
                s += ((i == k ? 1.0 : 0.0) + A[i][k]) * ((k == j ? 1.0 : 0.0) - B[k][j]);
            }
            FNAV_ASSERT_CLOSE(s, i == j ? 1.0 : 0.0, 1e-12, 0.0);
        }
    }
    memset(B, 0, sizeof B);
    B[1][1] = 1.0;
    A[0][0] = 42.0;
    assert_int_equal(sg_nav_lin_to_sensor((const double(*)[6])B, A), -1);
    assert_true(A[0][0] == 42.0);
}

/* Stances are matched one to one after a swing of the same duration: a lag
 * of a few samples is the same stance; a stance the detector split in one
 * run (a second "first update" 0.1 s after the first) or started after a
 * different swing is not compared with another swing's innovation. */
static void test_match_swing(void **state)
{
    /* real: regular strides every 1.1 s (swing 0.6 s), stance at 4.4 split
     * into 4.4 and 4.5 (the second after a 0.05 s gap) */
    const double ta[] = { 1.1, 2.2, 3.3, 4.4, 4.5, 5.6 };
    const double sa[] = { 0.6, 0.6, 0.6, 0.6, 0.05, 0.6 };
    /* twin: 15 ms later; the stance at 4.4 starts at 4.515 after a longer
     * swing; 3.3 is missing */
    const double tb[] = { 1.115, 2.215, 4.515, 5.615 };
    const double sb[] = { 0.6, 0.6, 0.72, 0.6 };
    (void)state;
    assert_int_equal(sg_nav_match_swing(ta, sa, 6, 0, tb, sb, 4), 0);
    assert_int_equal(sg_nav_match_swing(ta, sa, 6, 1, tb, sb, 4), 1);
    assert_int_equal(sg_nav_match_swing(ta, sa, 6, 2, tb, sb, 4), -1); /* nothing within 0.15 s */
    assert_int_equal(sg_nav_match_swing(ta, sa, 6, 3, tb, sb, 4), -1); /* twin 4.515 is nearer to 4.5 */
    assert_int_equal(sg_nav_match_swing(ta, sa, 6, 4, tb, sb, 4), -1); /* swings 0.05 vs 0.72 s */
    assert_int_equal(sg_nav_match_swing(ta, sa, 6, 5, tb, sb, 4), 3);
    /* the plain nearest-in-time rule would have paired 4.4 and 4.5 with 4.515 */
}

/* A walk case that cannot be drawn says why: the validation stopped with
 * "case N: cannot draw a walk case" and nothing more. A walk at 1 Hz has
 * too few zero-velocity updates to size an effect on. */
static void test_draw_case_reason(void **state)
{
    sgv_opts_t o = sgv_opts_default();
    int n, t;
    const sgv_effect_t *E = sgv_effects(&n);
    fnav_rng_t rng;
    sgv_case_t cs;
    fnav_imuerr_config_t cfg;
    char script[1024], why[256] = "";
    (void)state;
    for (t = 0; t < n && E[t].cls != SGV_MOTION; t++) {
    }
    assert_true(t < n);
    o.walk_duration_s = 20.0;
    o.walk_rate_hz = 1.0;
    fnav_rng_seed(&rng, 1u, 7u);
    memset(&cs, 0, sizeof cs);
    assert_int_equal(sg_nav_draw_case(&o, t, &rng, &cs, &cfg, script, sizeof script, why, sizeof why), -1);
    assert_non_null(strstr(why, "zero-velocity updates of the simulated walk could be matched, 5 needed"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lin_to_sensor_analytic),
        cmocka_unit_test(test_lin_to_sensor_inverse),
        cmocka_unit_test(test_match_swing),
        cmocka_unit_test(test_draw_case_reason),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
