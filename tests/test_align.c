/* fnav_align: roll, pitch and biases from known means (exact), the still
 * period logic (restart on early motion, completion on motion or after
 * max_still_s, the noise-floor ratio test), configuration checks. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

#include <cmocka.h>

#include "footnav/fnav_align.h"
#include "footnav/fnav_port.h"
#include "fnav_testdata.h"

#if FNAV_USE_DOUBLE
#define EPS 1e-15
#else
#define EPS 1.2e-7
#endif

static const double k_g = 9.80665;

static void test_config(void **state)
{
    fnav_align_t al;
    fnav_align_config_t c = fnav_align_config_default;
    (void)state;
    assert_int_equal(fnav_align_init(&al, &c), FNAV_OK);
    assert_int_equal(fnav_align_init(NULL, &c), FNAV_E_ARG);
    c.max_still_s = FNAV_R(0.1); /* below min */
    assert_int_equal(fnav_align_init(&al, &c), FNAV_E_CONFIG);
    c = fnav_align_config_default;
    c.still_ratio = FNAV_R(1.0);
    assert_int_equal(fnav_align_init(&al, &c), FNAV_E_CONFIG);
    c = fnav_align_config_default;
    c.gravity_mps2 = (fnav_real_t)NAN;
    assert_int_equal(fnav_align_init(&al, &c), FNAV_E_CONFIG);
}

/* For a body at rest with attitude (roll, pitch, yaw) and an accelerometer
 * bias b along gravity, f = C_bn (0, 0, -g) + b: the alignment returns the
 * roll and pitch exactly, yaw 0, and b. */
static void test_from_means(void **state)
{
    static const double att[4][2] = { { 0.0, 0.0 }, { 0.3, -0.2 }, { -2.9, 0.6 }, { 1.2, -1.3 } };
    int i;
    (void)state;
    for (i = 0; i < 4; i++) {
        fnav_quat_t q = fnav_quat_from_euler((fnav_real_t)att[i][0], (fnav_real_t)att[i][1], FNAV_R(0.7));
        fnav_vec3_t up_b = fnav_quat_rotate(fnav_quat_conj(q), fnav_vec3(FNAV_R(0.0), FNAV_R(0.0), -FNAV_R(1.0)));
        fnav_vec3_t f = fnav_vec3_scale(up_b, (fnav_real_t)(k_g + 0.05)); /* |f| = g + 0.05 */
        fnav_vec3_t w = fnav_vec3(FNAV_R(0.001), FNAV_R(-0.002), FNAV_R(0.003));
        fnav_align_result_t r;
        assert_int_equal(fnav_align_from_means(f, w, (fnav_real_t)k_g, &r), FNAV_OK);
        FNAV_ASSERT_CLOSE(r.euler_rad.v[0], att[i][0], 20.0 * EPS, 0.0);
        FNAV_ASSERT_CLOSE(r.euler_rad.v[1], att[i][1], 20.0 * EPS, 0.0);
        FNAV_ASSERT_CLOSE(r.euler_rad.v[2], 0.0, 0.0, 0.0);
        FNAV_ASSERT_CLOSE(fnav_vec3_norm(r.accel_bias_mps2), 0.05, 40.0 * EPS * k_g, 0.0);
        FNAV_ASSERT_CLOSE(fnav_vec3_dot(r.accel_bias_mps2, up_b), 0.05, 40.0 * EPS * k_g, 0.0);
        FNAV_ASSERT_CLOSE(r.gyro_bias_rps.v[2], 0.003, 0.0, EPS);
        /* the aligned attitude maps the measured gravity to (0, 0, -|f|) */
        {
            fnav_vec3_t fn = fnav_quat_rotate(r.q_nb, f);
            FNAV_ASSERT_CLOSE(fn.v[0], 0.0, 40.0 * EPS * k_g, 0.0);
            FNAV_ASSERT_CLOSE(fn.v[1], 0.0, 40.0 * EPS * k_g, 0.0);
        }
    }
    {
        fnav_align_result_t r;
        assert_int_equal(fnav_align_from_means(fnav_vec3_zero(), fnav_vec3_zero(), (fnav_real_t)k_g, &r), FNAV_E_RANGE);
    }
}

static fnav_sample_t still_sample(long k, double rate, double wobble)
{
    fnav_sample_t s;
    memset(&s, 0, sizeof s);
    s.t_ns = (int64_t)llround((double)k * 1e9 / rate);
    s.accel_mps2[0] = (fnav_real_t)(0.1 + wobble * ((k % 3) - 1));
    s.accel_mps2[1] = (fnav_real_t)(-0.2);
    s.accel_mps2[2] = (fnav_real_t)(-9.81 + wobble * ((k % 5) - 2));
    s.gyro_rps[0] = (fnav_real_t)(0.004 + 0.001 * ((k % 7) - 3));
    s.gyro_rps[1] = FNAV_R(-0.002);
    s.gyro_rps[2] = FNAV_R(0.001);
    return s;
}

/* Motion before min_still_s restarts the average; motion after it
 * completes the alignment with the mean of the still samples. */
static void test_still_period(void **state)
{
    fnav_align_t al;
    fnav_align_config_t c = fnav_align_config_default;
    long k;
    fnav_status_t st = FNAV_AGAIN;
    (void)state;
    assert_int_equal(fnav_align_init(&al, &c), FNAV_OK);
    /* 0.3 s still, then a moving sample: too short, restart */
    for (k = 0; k < 30; k++) {
        fnav_sample_t s = still_sample(k, 100.0, 0.0);
        assert_int_equal(fnav_align_push(&al, &s, 1, FNAV_R(100.0)), FNAV_AGAIN);
    }
    {
        fnav_sample_t s = still_sample(30, 100.0, 0.0);
        assert_int_equal(fnav_align_push(&al, &s, 0, FNAV_R(1e7)), FNAV_AGAIN);
    }
    assert_int_equal((int)al.n, 0);
    /* 1 s still, then motion: complete */
    for (k = 31; k < 132 && st == FNAV_AGAIN; k++) {
        fnav_sample_t s = still_sample(k, 100.0, 0.0);
        st = fnav_align_push(&al, &s, 1, FNAV_R(100.0));
    }
    assert_int_equal(st, FNAV_AGAIN);
    {
        fnav_sample_t s = still_sample(132, 100.0, 0.0);
        assert_int_equal(fnav_align_push(&al, &s, 0, FNAV_R(1e7)), FNAV_OK);
    }
    assert_int_equal((int)al.result.samples, 101);
    FNAV_ASSERT_CLOSE(al.result.duration_s, 1.0, 1e-6, 0.0);
    /* mean of 0.004 + 0.001 ((k % 7) - 3) over k = 31..131 */
    {
        double m = 0.0;
        for (k = 31; k < 132; k++) {
            m += 0.004 + 0.001 * ((k % 7) - 3);
        }
        FNAV_ASSERT_CLOSE(al.result.gyro_bias_rps.v[0], m / 101.0, 1e4 * EPS * 0.004, 0.0);
    }
    {
        fnav_sample_t s = still_sample(133, 100.0, 0.0);
        assert_int_equal(fnav_align_push(&al, &s, 1, FNAV_R(100.0)), FNAV_E_STATE);
    }
}

/* A long still period completes after max_still_s. */
static void test_max_duration(void **state)
{
    fnav_align_t al;
    fnav_align_config_t c = fnav_align_config_default;
    long k;
    fnav_status_t st = FNAV_AGAIN;
    (void)state;
    c.max_still_s = FNAV_R(2.0);
    assert_int_equal(fnav_align_init(&al, &c), FNAV_OK);
    for (k = 0; k < 1000 && st == FNAV_AGAIN; k++) {
        fnav_sample_t s = still_sample(k, 200.0, 0.002);
        st = fnav_align_push(&al, &s, 1, FNAV_R(100.0));
    }
    assert_int_equal(st, FNAV_OK);
    assert_int_equal((int)k, 401);
    /* sample standard deviation of the wobble pattern (0.002 x {-2..2}) */
    FNAV_ASSERT_CLOSE(al.result.accel_sd_mps2.v[2], 0.002 * sqrt(2.0), 0.0, 0.02);
}

/* The detector statistic rising a decade above its running geometric
 * mean ends the still period even while the zero-velocity test passes. */
static void test_ratio_ends_period(void **state)
{
    fnav_align_t al;
    fnav_align_config_t c = fnav_align_config_default;
    long k;
    fnav_status_t st = FNAV_AGAIN;
    (void)state;
    assert_int_equal(fnav_align_init(&al, &c), FNAV_OK);
    for (k = 0; k < 300 && st == FNAV_AGAIN; k++) {
        fnav_sample_t s = still_sample(k, 100.0, 0.0);
        fnav_real_t stat = k < 100 ? FNAV_R(100.0) : FNAV_R(100.0) * fnav_pow(FNAV_R(10.0), (fnav_real_t)(k - 100) / FNAV_R(20.0));
        st = fnav_align_push(&al, &s, 1, stat);
    }
    assert_int_equal(st, FNAV_OK);
    /* log10 T = 2 + m/20 at m = k - 100 (2 before); at sample k the mean of
     * log10 T over samples 0..k-1 is (2 k + (m - 1) m / 40) / k, and
     * 2 + m/20 exceeds it by more than 1 first at m = 22 (k = 122: 3.1 >
     * 3.0947), so the period holds the 122 samples 0..121 */
    assert_int_equal((int)k, 123);
    assert_int_equal((int)al.result.samples, 122);
}

/* finish: aligns on what was collected if it is long enough. */
static void test_finish(void **state)
{
    fnav_align_t al;
    fnav_align_config_t c = fnav_align_config_default;
    long k;
    (void)state;
    assert_int_equal(fnav_align_init(&al, &c), FNAV_OK);
    for (k = 0; k < 20; k++) {
        fnav_sample_t s = still_sample(k, 100.0, 0.0);
        assert_int_equal(fnav_align_push(&al, &s, 1, FNAV_R(100.0)), FNAV_AGAIN);
    }
    assert_int_equal(fnav_align_finish(&al), FNAV_E_STATE);
    for (; k < 80; k++) {
        fnav_sample_t s = still_sample(k, 100.0, 0.0);
        assert_int_equal(fnav_align_push(&al, &s, 1, FNAV_R(100.0)), FNAV_AGAIN);
    }
    assert_int_equal(fnav_align_finish(&al), FNAV_OK);
    assert_int_equal((int)al.result.samples, 80);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_config),
        cmocka_unit_test(test_from_means),
        cmocka_unit_test(test_still_period),
        cmocka_unit_test(test_max_duration),
        cmocka_unit_test(test_ratio_ends_period),
        cmocka_unit_test(test_finish),
    };
    return cmocka_run_group_tests_name("align", tests, NULL, NULL);
}
