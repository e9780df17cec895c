/* fnav_align: roll, pitch and biases from known means (exact), the still
 * period logic (restart on early motion, completion on motion or after
 * max_still_s, the noise-floor ratio test, the short-period fallback), the
 * gyro bias posterior (batch-means standard error, prior shrinkage),
 * configuration checks. */
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

/* An alignment never initialised (zeroed): push and finish say
 * FNAV_E_STATE, as the other modules do (push said FNAV_E_ARG, from the
 * zero gravity of the empty configuration, or averaged the samples). */
static void test_not_initialised(void **state)
{
    static fnav_align_t al, copy;
    fnav_sample_t s;
    (void)state;
    memset(&s, 0, sizeof s);
    s.accel_mps2[2] = FNAV_R(-9.81);
    memset(&copy, 0, sizeof copy);
    assert_int_equal(fnav_align_push(&al, &s, 1, FNAV_R(1.0)), FNAV_E_STATE);
    assert_int_equal(fnav_align_finish(&al), FNAV_E_STATE);
    assert_memory_equal(&al, &copy, sizeof al);
    assert_int_equal(fnav_align_init(&al, &fnav_align_config_default), FNAV_OK);
    assert_int_equal(fnav_align_push(&al, &s, 1, FNAV_R(1.0)), FNAV_AGAIN);
}

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
    c = fnav_align_config_default;
    c.short_still_s = c.min_still_s + FNAV_R(0.1); /* above min */
    assert_int_equal(fnav_align_init(&al, &c), FNAV_E_CONFIG);
    c = fnav_align_config_default;
    c.short_still_s = FNAV_R(0.0);
    assert_int_equal(fnav_align_init(&al, &c), FNAV_E_CONFIG);
    c = fnav_align_config_default;
    c.gyro_bias_prior_sd_rps = -FNAV_R(0.01);
    assert_int_equal(fnav_align_init(&al, &c), FNAV_E_CONFIG);
    c.gyro_bias_prior_sd_rps = FNAV_R(0.0); /* no prior: allowed */
    assert_int_equal(fnav_align_init(&al, &c), FNAV_OK);
    /* the checks no suite made (make coverage): NULL configuration; every
     * real field NaN; min_still_s 0; gravity 0; max_still_s = min_still_s
     * and short_still_s = min_still_s accepted (the bounds are inclusive) */
    assert_int_equal(fnav_align_init(&al, NULL), FNAV_E_ARG);
    {
        fnav_real_t *const fields[6] = { &c.min_still_s, &c.max_still_s, &c.short_still_s, &c.gravity_mps2,
                                         &c.still_ratio, &c.gyro_bias_prior_sd_rps };
        int i;
        for (i = 0; i < 6; i++) {
            c = fnav_align_config_default;
            *fields[i] = (fnav_real_t)NAN;
            assert_int_equal(fnav_align_init(&al, &c), FNAV_E_CONFIG);
        }
    }
    c = fnav_align_config_default;
    c.min_still_s = FNAV_R(0.0);
    c.short_still_s = FNAV_R(0.0);
    assert_int_equal(fnav_align_init(&al, &c), FNAV_E_CONFIG);
    c = fnav_align_config_default;
    c.gravity_mps2 = FNAV_R(0.0);
    assert_int_equal(fnav_align_init(&al, &c), FNAV_E_CONFIG);
    c = fnav_align_config_default;
    c.max_still_s = c.min_still_s;
    c.short_still_s = c.min_still_s;
    assert_int_equal(fnav_align_init(&al, &c), FNAV_OK);
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
        /* the means themselves, as given (the harness prints |f| from
         * accel_mean_mps2; a mutant leaving it unset passed every suite) */
        assert_memory_equal(&r.accel_mean_mps2, &f, sizeof f);
        assert_memory_equal(&r.gyro_mean_rps, &w, sizeof w);
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

/* Bad arguments of fnav_align_from_means, a public function (the harness's
 * axes check calls it directly): a NULL result is FNAV_E_ARG, not a crash;
 * a gravity that is 0, negative, NaN or infinite is FNAV_E_ARG (otherwise
 * 0 with a zero force would pass the |f| test, 0 <= 0.25 * 0, and return OK
 * with an accelerometer bias of 0 / 0 = NaN, and +Inf would pass it,
 * Inf <= Inf, with an infinite bias); a non-finite mean rate is
 * FNAV_E_NANINF (not returned as the gyro bias with OK). Nothing is
 * written on an error. */
static void test_from_means_bad_args(void **state)
{
    const fnav_vec3_t f = fnav_vec3(FNAV_R(0.1), FNAV_R(-0.2), FNAV_R(-9.8));
    const fnav_vec3_t w = fnav_vec3(FNAV_R(0.001), FNAV_R(0.0), FNAV_R(0.0));
    const fnav_real_t zero = FNAV_R(0.0);
    const fnav_real_t bad_g[4] = { FNAV_R(0.0), FNAV_R(-9.8), zero / zero, FNAV_R(1.0) / zero };
    fnav_align_result_t r, r0;
    int i;
    (void)state;
    assert_int_equal(fnav_align_from_means(f, w, (fnav_real_t)k_g, NULL), FNAV_E_ARG);
    memset(&r0, 0x5a, sizeof r0);
    for (i = 0; i < 4; i++) {
        r = r0;
        assert_int_equal(fnav_align_from_means(fnav_vec3_zero(), w, bad_g[i], &r), FNAV_E_ARG);
        assert_int_equal(fnav_align_from_means(f, w, bad_g[i], &r), FNAV_E_ARG);
        assert_memory_equal(&r, &r0, sizeof r);
    }
    for (i = 0; i < 3; i++) {
        fnav_vec3_t wb = w;
        wb.v[i] = (i == 1) ? zero / zero : ((i == 0) ? FNAV_R(1.0) / zero : -FNAV_R(1.0) / zero);
        r = r0;
        assert_int_equal(fnav_align_from_means(f, wb, (fnav_real_t)k_g, &r), FNAV_E_NANINF);
        assert_memory_equal(&r, &r0, sizeof r);
    }
    /* the same arguments with a good gravity and rate align */
    assert_int_equal(fnav_align_from_means(f, w, (fnav_real_t)k_g, &r), FNAV_OK);
    assert_true(fnav_isfinite(r.accel_bias_mps2.v[2]));
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

/* The mean specific force of still_sample(k0) .. still_sample(k0 + n - 1),
 * in double from the fnav_real_t values pushed (the wobble's cycles of 3
 * and 5 samples do not divide every n: the mean is not the nominal one). */
static void still_mean_f(long k0, long n, double rate, double wobble, double m[3])
{
    long k;
    int i;
    m[0] = m[1] = m[2] = 0.0;
    for (k = k0; k < k0 + n; k++) {
        fnav_sample_t s = still_sample(k, rate, wobble);
        for (i = 0; i < 3; i++) {
            m[i] += (double)s.accel_mps2[i] / (double)n;
        }
    }
}

/* The accelerometer bias of an alignment on still_sample(k0) ..
 * still_sample(k0 + n - 1) (check_accel_bias: 200 Hz, wobble 0.002):
 * f (|f| - g) / |f|, f the mean specific force (fnav_align_from_means),
 * each component, with f and |f| in double from the samples pushed and g
 * the configuration's.
 * Rounding: the period sums offsets from its first sample (|offset| <=
 * 0.008, partial sums <= 3.3: u of 3.3 in the mean) and adds the mean
 * offset to that sample (u of |f|); |f| and |f| - g then take a few u of
 * |f| more (the difference cancels to 0.004 of |f|, absolutely no worse),
 * the scaling by f / |f| two u of the bias: 10 EPS of |f| absolute (EPS is
 * 2 u) is about twice that. (It compared the norm alone with the nominal
 * sqrt(0.1^2 + 0.2^2 + 9.81^2) - g to 1e-4 in both builds: 8 times the
 * float rounding, 1e10 times the double's, and blind to the direction.) */
static void check_accel_bias_at(const fnav_align_t *al, const fnav_align_config_t *c, long k0, long n, double rate,
                                double wobble)
{
    double m[3], fn;
    int i;
    still_mean_f(k0, n, rate, wobble, m);
    fn = sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
    for (i = 0; i < 3; i++) {
        FNAV_ASSERT_CLOSE(al->result.accel_bias_mps2.v[i], m[i] * (fn - (double)c->gravity_mps2) / fn, 10.0 * EPS * fn,
                          0.0);
    }
}

static void check_accel_bias(const fnav_align_t *al, const fnav_align_config_t *c, long k0, long n)
{
    check_accel_bias_at(al, c, k0, n, 200.0, 0.002);
}

/* Motion before short_still_s restarts the average; motion after
 * min_still_s completes the alignment with the mean of the still samples
 * (no prior here: the plain mean). */
static void test_still_period(void **state)
{
    fnav_align_t al;
    fnav_align_config_t c = fnav_align_config_default;
    long k;
    fnav_status_t st = FNAV_AGAIN;
    (void)state;
    c.gyro_bias_prior_sd_rps = FNAV_R(0.0);
    assert_int_equal(fnav_align_init(&al, &c), FNAV_OK);
    /* 0.15 s still, then a moving sample: too short, restart */
    for (k = 0; k < 16; k++) {
        fnav_sample_t s = still_sample(k, 100.0, 0.0);
        assert_int_equal(fnav_align_push(&al, &s, 1, FNAV_R(100.0)), FNAV_AGAIN);
    }
    for (; k < 31; k++) {
        fnav_sample_t s = still_sample(k, 100.0, 0.0);
        assert_int_equal(fnav_align_push(&al, &s, 0, FNAV_R(1e7)), FNAV_AGAIN);
    }
    assert_int_equal((int)al.cur.n, 0);
    assert_int_equal(al.have_best, 0);
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
    assert_int_equal((int)al.result.samples, 401); /* samples 0..400 (0 to 2 s) */
    /* sample standard deviation of the wobble pattern (0.002 x {-2..2}) */
    FNAV_ASSERT_CLOSE(al.result.accel_sd_mps2.v[2], 0.002 * sqrt(2.0), 0.0, 0.02);
    /* exactly: the sample standard deviation (divisor n - 1) of the values
     * pushed, computed here in double. The running sums of the n = 401
     * offsets from the first sample (sa, sa2) are within n EPS relative
     * each, so sa2 - sa^2 / n is within 3 n EPS of sa2; against the
     * difference that is a factor (mean^2 + var) / var larger, at most
     * 3.25 here (gyro x: offsets 0..6 mrad/s, mean 3, variance 4), so
     * the variance is within 10 n EPS and its square root within 5 n EPS
     * relative. The divisor n instead of n - 1 gives an sd smaller by
     * 1 / (2 (n - 1)) = 1.25e-3, five times that. */
    {
        enum { n = 401 };
        static double v[n][3];
        double sum[3] = { 0.0, 0.0, 0.0 }, ss[3] = { 0.0, 0.0, 0.0 };
        int i;
        for (k = 0; k < n; k++) {
            fnav_sample_t s = still_sample(k, 200.0, 0.002);
            v[k][0] = (double)s.accel_mps2[0];
            v[k][1] = (double)s.accel_mps2[2];
            v[k][2] = (double)s.gyro_rps[0];
            for (i = 0; i < 3; i++) {
                sum[i] += v[k][i];
            }
        }
        for (k = 0; k < n; k++) {
            for (i = 0; i < 3; i++) {
                ss[i] += (v[k][i] - sum[i] / n) * (v[k][i] - sum[i] / n);
            }
        }
        FNAV_ASSERT_CLOSE(al.result.accel_sd_mps2.v[0], sqrt(ss[0] / (double)(n - 1)), 0.0, 5.0 * n * EPS);
        FNAV_ASSERT_CLOSE(al.result.accel_sd_mps2.v[2], sqrt(ss[1] / (double)(n - 1)), 0.0, 5.0 * n * EPS);
        FNAV_ASSERT_CLOSE(al.result.gyro_sd_rps.v[0], sqrt(ss[2] / (double)(n - 1)), 0.0, 5.0 * n * EPS);
    }
}

/* A positive gyro-bias prior sd whose square is 0 or infinite in the
 * working precision is refused, as the filter's sds are (fnav_ukf.h): its
 * square is the posterior's weight. Accepted, 1e20 in float (square Inf)
 * gave a gyro bias of Inf / Inf = NaN, and fnav_nav's start of the filter
 * on it failed its assert (FNAV_ASSERT, an abort, from a configuration
 * fnav_nav_init had accepted); 1e-25 (square 0) took the plain mean, the
 * opposite of what a prior that small means (a bias of 0). 0 (no prior)
 * stays allowed. Either side: float 1e-18 / 1e-23 and 1e18 / 1e20, double
 * 1e-150 / 1e-170 and 1e150 / 1e160; the accepted ones give a finite
 * bias. */
static void test_prior_square(void **state)
{
#if FNAV_USE_DOUBLE
    const fnav_real_t vals[4] = { 1e-150, 1e-170, 1e150, 1e160 };
#else
    const fnav_real_t vals[4] = { 1e-20f, 1e-23f, 1e18f, 1e20f };
#endif
    fnav_align_t al;
    fnav_align_config_t c = fnav_align_config_default;
    int k;
    (void)state;
    c.max_still_s = FNAV_R(2.0);
    for (k = 0; k < 4; k++) {
        long j;
        fnav_status_t st = FNAV_AGAIN;
        c.gyro_bias_prior_sd_rps = vals[k];
        if (fnav_align_init(&al, &c) != (k % 2 == 0 ? FNAV_OK : FNAV_E_CONFIG)) {
            fail_msg("prior sd %g %s", (double)vals[k], k % 2 == 0 ? "refused" : "not refused");
        }
        if (k % 2 != 0) {
            continue;
        }
        for (j = 0; j < 1000 && st == FNAV_AGAIN; j++) {
            fnav_sample_t s = still_sample(j, 200.0, 0.002);
            st = fnav_align_push(&al, &s, 1, FNAV_R(100.0));
        }
        assert_int_equal(st, FNAV_OK);
        assert_true(fnav_vec3_isfinite(al.result.gyro_bias_rps) && fnav_vec3_isfinite(al.result.gyro_bias_sd_rps));
        {
            /* an accepted prior has a posterior: sd positive where the
             * mean's is (an axis without noise has se 0, and so an exact
             * mean), at most the prior's and the mean's (1e-20 in float:
             * s0^2 se^2 underflowed to a posterior sd of 0) */
            int i;
            for (i = 0; i < 3; i++) {
                const fnav_real_t sd = al.result.gyro_bias_sd_rps.v[i];
                const fnav_real_t se = al.result.gyro_mean_se_rps.v[i];
                if (!((se > FNAV_R(0.0) ? sd > FNAV_R(0.0) : sd == FNAV_R(0.0)) && sd <= vals[k] * FNAV_R(1.000001) &&
                      sd <= al.result.gyro_mean_se_rps.v[i] * FNAV_R(1.000001))) {
                    fail_msg("prior sd %g: posterior sd %g (mean se %g)", (double)vals[k], (double)sd,
                             (double)al.result.gyro_mean_se_rps.v[i]);
                }
            }
        }
    }
    c.gyro_bias_prior_sd_rps = FNAV_R(0.0); /* no prior */
    assert_int_equal(fnav_align_init(&al, &c), FNAV_OK);
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

/* A still sample whose statistic is 0 (zero readings, a quantised sensor
 * at rest) has no logarithm: it counts as log10 = 0 (left_floor's
 * "unusable") and neither ends the period nor pulls the noise floor to
 * -inf. With its log10 (-inf) in the running mean, the first positive
 * statistic after it (1e-3 here, 3 decades under the floor of 0) "left
 * the floor" and ended the period at 1 s of 5 (a mutant taking stat >= 0
 * as usable passed every suite). 1 s of zeros then 1e-3 at 200 Hz: the
 * period runs to max_still_s, samples 0..1000 (as test_max_duration). */
static void test_zero_stat(void **state)
{
    fnav_align_t al;
    fnav_align_config_t c = fnav_align_config_default;
    long k;
    fnav_status_t st = FNAV_AGAIN;
    (void)state;
    assert_int_equal(fnav_align_init(&al, &c), FNAV_OK);
    for (k = 0; k < 2000 && st == FNAV_AGAIN; k++) {
        fnav_sample_t s = still_sample(k, 200.0, 0.002);
        st = fnav_align_push(&al, &s, 1, k < 200 ? FNAV_R(0.0) : FNAV_R(1e-3));
    }
    assert_int_equal(st, FNAV_OK);
    assert_int_equal((int)k, 1001);
    assert_int_equal((int)al.result.samples, 1001);
}

/* The variance is clamped at 0 when the running sums' rounding makes it
 * negative: one sample 0.7 m/s^2 off and 10,000 equal ones after it (1 kHz,
 * 10 s) cancel sa2 - sa^2 / n down to its true value (0.7^2 / n, 1 part in
 * 10^4 of sa2), under the float32 sums' rounding (numpy float32 with the
 * same order of operations gives -5.2e-6: tests/align_clamp_ref.py). The
 * standard deviation is a
 * number between 0 and twice the true one (0.7 / sqrt(n) = 7.0e-3,
 * computed here in double), not NaN (a mutant without the clamp passed
 * every suite). */
static void test_rounded_variance_clamped(void **state)
{
    fnav_align_t al;
    fnav_align_config_t c = fnav_align_config_default;
    long k;
    fnav_status_t st = FNAV_AGAIN;
    double d, sum = 0.0, ss = 0.0, sd;
    (void)state;
    c.max_still_s = FNAV_R(10.0);
    assert_int_equal(fnav_align_init(&al, &c), FNAV_OK);
    for (k = 0; k < 20000 && st == FNAV_AGAIN; k++) {
        fnav_sample_t s = still_sample(k, 1000.0, 0.0);
        s.accel_mps2[2] = k == 0 ? (fnav_real_t)-9.81 : (fnav_real_t)(-9.81 + 0.7);
        st = fnav_align_push(&al, &s, 1, FNAV_R(100.0));
    }
    assert_int_equal(st, FNAV_OK);
    assert_int_equal((int)al.result.samples, 10001);
    /* the true sample standard deviation of the values pushed */
    d = (double)(fnav_real_t)(-9.81 + 0.7) - (double)(fnav_real_t)-9.81;
    for (k = 0; k < 10001; k++) {
        sum += k == 0 ? 0.0 : d;
    }
    for (k = 0; k < 10001; k++) {
        const double e = (k == 0 ? 0.0 : d) - sum / 10001.0;
        ss += e * e;
    }
    sd = sqrt(ss / 10000.0);
    FNAV_ASSERT_CLOSE(sd, 0.7 / sqrt(10001.0), 0.0, 1e-5);
    assert_true(fnav_isfinite(al.result.accel_sd_mps2.v[2]));
    assert_true(al.result.accel_sd_mps2.v[2] >= FNAV_R(0.0));
    assert_true((double)al.result.accel_sd_mps2.v[2] <= 2.0 * sd);
#if FNAV_USE_DOUBLE
    /* in double the sums are good enough for the true value: as in
     * test_max_duration, the variance within 10 n EPS relative times
     * (mean^2 + var) / var (10,001 here: the cancellation), its square
     * root half that */
    {
        const double mean = sum / 10001.0, var = ss / 10000.0;
        FNAV_ASSERT_CLOSE(al.result.accel_sd_mps2.v[2], sd, 0.0, 5.0 * 10001.0 * EPS * (mean * mean + var) / var);
    }
#else
    /* in float the variance rounds to -5.2e-6 (tests/align_clamp_ref.py,
     * numpy float32): the clamp is what runs, and the standard deviation is 0
     * (the bounds above alone did not show that the clamp ran; sums that no
     * longer round below 0 need another case for the clamp, not a wider
     * check) */
    assert_true(al.result.accel_sd_mps2.v[2] == FNAV_R(0.0));
#endif
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
    /* on those 80 samples (it checked only their count): the bias of
     * their mean specific force and the mean of their gyro x, 0.004 +
     * 0.001 ((k mod 7) - 3) over k = 0..79 (tolerances as
     * check_accel_bias's and test_stuck_stamp_period's) */
    check_accel_bias_at(&al, &c, 0, 80, 100.0, 0.0);
    {
        double mx = 0.0;
        for (k = 0; k < 80; k++) {
            mx += (double)still_sample(k, 100.0, 0.0).gyro_rps[0] / 80.0;
        }
        FNAV_ASSERT_CLOSE(al.result.gyro_mean_rps.v[0], mx, EPS * (80.0 * 0.006 + 0.01), 0.0);
    }
}

/* A period that ends before min_still_s but after short_still_s is kept;
 * when the foot then moves, the quietest kept period aligns (a walk that
 * starts a fraction of a second after the recording). A noisier one does
 * not replace it. */
static void test_short_period_fallback(void **state)
{
    fnav_align_t al;
    fnav_align_config_t c = fnav_align_config_default;
    long k;
    (void)state;
    c.gyro_bias_prior_sd_rps = FNAV_R(0.0);
    assert_int_equal(fnav_align_init(&al, &c), FNAV_OK);
    /* 0.3 s quiet (T = 100), then the statistic jumps (ratio test) */
    for (k = 0; k < 31; k++) {
        fnav_sample_t s = still_sample(k, 100.0, 0.0);
        assert_int_equal(fnav_align_push(&al, &s, 1, FNAV_R(100.0)), FNAV_AGAIN);
    }
    {
        fnav_sample_t s = still_sample(31, 100.0, 0.0);
        assert_int_equal(fnav_align_push(&al, &s, 1, FNAV_R(1e4)), FNAV_AGAIN);
    }
    assert_int_equal(al.have_best, 1);
    assert_int_equal((int)al.result.samples, 31);
    assert_int_equal((int)al.cur.n, 0);
    /* 0.3 s of sway (T = 1e4), still below the detector threshold */
    for (k = 32; k < 63; k++) {
        fnav_sample_t s = still_sample(k, 100.0, 0.0);
        assert_int_equal(fnav_align_push(&al, &s, 1, FNAV_R(1e4)), FNAV_AGAIN);
    }
    /* the step: completes on the quiet period, samples 0..30 */
    {
        fnav_sample_t s = still_sample(63, 100.0, 0.0);
        assert_int_equal(fnav_align_push(&al, &s, 0, FNAV_R(1e7)), FNAV_OK);
    }
    assert_int_equal((int)al.result.samples, 31);
    FNAV_ASSERT_CLOSE(al.result.duration_s, 0.3, 1e-6, 0.0);
    /* finish on a short period also uses the fallback */
    assert_int_equal(fnav_align_init(&al, &c), FNAV_OK);
    for (k = 0; k < 25; k++) {
        fnav_sample_t s = still_sample(k, 100.0, 0.0);
        assert_int_equal(fnav_align_push(&al, &s, 1, FNAV_R(100.0)), FNAV_AGAIN);
    }
    assert_int_equal(fnav_align_finish(&al), FNAV_OK);
    assert_int_equal((int)al.result.samples, 25);
}

/* The gyro bias of a period shorter than min_still_s (the walk starts
 * early) is the prior's, 0 with sd gyro_bias_prior_sd_rps: a smooth
 * rotation of the foot before its first step reads as a constant rate that
 * no statistic of the window tells from a bias (the batch means agree, so
 * the shrinkage kept it). A period of min_still_s or more keeps the
 * posterior mean; roll and pitch come from both; prior 0 (no prior) keeps
 * the plain mean. Cut shared walks: scripts/cut_still.py. */
static void test_short_period_bias_prior(void **state)
{
    static const long n_of[2] = { 31, 61 }; /* 0.3 s (short) and 0.6 s at 100 Hz */
    fnav_align_config_t c = fnav_align_config_default;
    int q, prior;
    (void)state;
    for (prior = 0; prior < 2; prior++) {
        c.gyro_bias_prior_sd_rps = prior ? fnav_align_config_default.gyro_bias_prior_sd_rps : FNAV_R(0.0);
        for (q = 0; q < 2; q++) {
            fnav_align_t al;
            long k;
            assert_int_equal(fnav_align_init(&al, &c), FNAV_OK);
            for (k = 0; k < n_of[q]; k++) {
                fnav_sample_t s = still_sample(k, 100.0, 0.0);
                s.gyro_rps[2] = FNAV_R(0.035); /* 2 deg/s: a turn of 0.6 deg in 0.3 s */
                assert_int_equal(fnav_align_push(&al, &s, 1, FNAV_R(100.0)), FNAV_AGAIN);
            }
            {
                fnav_sample_t s = still_sample(n_of[q], 100.0, 0.0);
                assert_int_equal(fnav_align_push(&al, &s, 0, FNAV_R(1e7)), FNAV_OK); /* the step */
            }
            assert_int_equal((int)al.result.samples, (int)n_of[q]);
            /* the mean rate is kept as measured, the tilt from the mean f */
            FNAV_ASSERT_CLOSE(al.result.gyro_mean_rps.v[2], 0.035, 1e-6, 0.0);
            FNAV_ASSERT_CLOSE(al.result.euler_rad.v[0], atan2(0.2, 9.81), 1e-5, 0.0);
            if (prior && q == 0) {
                assert_true(al.result.gyro_bias_rps.v[2] == FNAV_R(0.0) && al.result.gyro_bias_rps.v[0] == FNAV_R(0.0));
                assert_true(al.result.gyro_bias_sd_rps.v[2] == c.gyro_bias_prior_sd_rps);
            } else {
                /* a constant rate: the batch means agree (se ~ 0), the mean kept */
                FNAV_ASSERT_CLOSE(al.result.gyro_bias_rps.v[2], 0.035, 1e-4, 0.0);
            }
        }
    }
}

/* finish when a short period was kept and the current one does not
 * qualify (shorter than min_still_s and noisier than the kept one): the
 * kept period aligns, as at the first motion in test_short_period_fallback.
 * A second finish is FNAV_OK and changes nothing; a push after the end is
 * FNAV_E_STATE; NULL is refused (make coverage: none of these was run). */
static void test_finish_keeps_best(void **state)
{
    fnav_align_t al;
    fnav_align_config_t c = fnav_align_config_default;
    fnav_align_result_t r;
    fnav_align_result_t out;
    long k;
    (void)state;
    c.gyro_bias_prior_sd_rps = FNAV_R(0.0);
    assert_int_equal(fnav_align_init(&al, &c), FNAV_OK);
    for (k = 0; k < 31; k++) {
        fnav_sample_t s = still_sample(k, 100.0, 0.0);
        assert_int_equal(fnav_align_push(&al, &s, 1, FNAV_R(100.0)), FNAV_AGAIN);
    }
    for (k = 31; k < 63; k++) { /* the ratio test ends the quiet period at k = 31 */
        fnav_sample_t s = still_sample(k, 100.0, 0.0);
        assert_int_equal(fnav_align_push(&al, &s, 1, FNAV_R(1e4)), FNAV_AGAIN);
    }
    assert_int_equal(al.have_best, 1);
    assert_int_equal((int)al.cur.n, 31);
    assert_int_equal(fnav_align_finish(&al), FNAV_OK);
    assert_int_equal(al.done, 1);
    assert_int_equal((int)al.result.samples, 31);
    FNAV_ASSERT_CLOSE(al.result.duration_s, 0.3, 1e-6, 0.0);
    r = al.result;
    assert_int_equal(fnav_align_finish(&al), FNAV_OK);
    assert_memory_equal(&al.result, &r, sizeof r);
    {
        fnav_sample_t s = still_sample(63, 100.0, 0.0);
        assert_int_equal(fnav_align_push(&al, &s, 1, FNAV_R(100.0)), FNAV_E_STATE);
        assert_int_equal(fnav_align_push(NULL, &s, 1, FNAV_R(100.0)), FNAV_E_ARG);
        assert_int_equal(fnav_align_push(&al, NULL, 1, FNAV_R(100.0)), FNAV_E_ARG);
        assert_int_equal(fnav_align_renew(NULL, &s, 1, FNAV_R(100.0), FNAV_R(0.1), &out), 0);
        assert_int_equal(fnav_align_renew(&al, &s, 1, FNAV_R(100.0), FNAV_R(0.1), NULL), 0);
    }
    assert_int_equal(fnav_align_finish(NULL), FNAV_E_ARG);
}

/* Gyro bias posterior. (1) A clean still period (white noise) keeps almost
 * the whole mean: its standard error is the white-noise value. (2) A foot
 * swaying at 1 Hz by 1 deg over 0.75 s has a mean rate far from the bias;
 * the batch means see the correlated motion and the prior pulls the
 * estimate to (near) zero: the error shrinks. The posterior follows
 * b = w s0^2 / (s0^2 + se^2) exactly. */
static double batch_means_se(const double *x, long n)
{
    long len = 1, nb, b, k;
    double m[FNAV_ALIGN_BLOCKS], mean = 0.0, var = 0.0;
    while (n / len >= FNAV_ALIGN_BLOCKS) { /* a full set of blocks merges into half as many */
        len *= 2;
    }
    nb = n / len;
    for (b = 0; b < nb; b++) {
        m[b] = 0.0;
        for (k = 0; k < len; k++) {
            m[b] += x[b * len + k];
        }
        m[b] /= (double)len;
        mean += m[b] / (double)nb;
    }
    for (b = 0; b < nb; b++) {
        var += (m[b] - mean) * (m[b] - mean) / (double)(nb - 1);
    }
    return sqrt(var / (double)nb);
}

static void test_gyro_bias_posterior(void **state)
{
    static double rates[400];
    fnav_align_t al;
    fnav_align_config_t c = fnav_align_config_default;
    const double rate = 200.0, b_true = 0.002, s0 = (double)c.gyro_bias_prior_sd_rps;
    long k;
    unsigned long seed = 12345u;
    (void)state;
    /* (1) white noise of 0.005 rad/s around the bias, 2 s */
    assert_int_equal(fnav_align_init(&al, &c), FNAV_OK);
    for (k = 0; k < 400; k++) {
        fnav_sample_t s = still_sample(k, rate, 0.0);
        double u = 0.0;
        int j;
        for (j = 0; j < 12; j++) { /* Irwin-Hall approximately normal, sd 1 */
            seed = seed * 1103515245u + 12345u;
            u += (double)((seed >> 16) & 0x7fff) / 32768.0;
        }
        s.gyro_rps[1] = (fnav_real_t)(b_true + 0.005 * (u - 6.0));
        rates[k] = (double)s.gyro_rps[1];
        assert_int_equal(fnav_align_push(&al, &s, 1, FNAV_R(100.0)), FNAV_AGAIN);
    }
    {
        fnav_sample_t s = still_sample(400, rate, 0.0);
        assert_int_equal(fnav_align_push(&al, &s, 0, FNAV_R(1e7)), FNAV_OK);
    }
    {
        double w = (double)al.result.gyro_mean_rps.v[1], se = (double)al.result.gyro_mean_se_rps.v[1];
        double k_shrink = s0 * s0 / (s0 * s0 + se * se);
        /* the standard error is of the white-noise order 0.005 / sqrt(400) */
        assert_true(se > 0.5 * 0.005 / 20.0 && se < 2.5 * 0.005 / 20.0);
        {
            /* and is it, recomputed here in double: the unbiased sample
             * variance (divisor n - 1) over n, or the batch-means value
             * where that is larger. A divisor n - 1 in the second place
             * moves it by 1/(2 x 399) = 1.3e-3 relative; the float sums'
             * rounding is far below 1e-4 */
            double mean = 0.0, var = 0.0, se_white, se_bm;
            for (k = 0; k < 400; k++) {
                mean += rates[k] / 400.0;
            }
            for (k = 0; k < 400; k++) {
                var += (rates[k] - mean) * (rates[k] - mean) / 399.0;
            }
            se_white = sqrt(var / 400.0);
            se_bm = batch_means_se(rates, 400);
            FNAV_ASSERT_CLOSE(se, se_white > se_bm ? se_white : se_bm, 0.0, 1e-4);
        }
        assert_true(k_shrink > 0.99);
        FNAV_ASSERT_CLOSE(al.result.gyro_bias_rps.v[1], w * k_shrink, 0.0, 1e-5);
        FNAV_ASSERT_CLOSE(al.result.gyro_bias_sd_rps.v[1], s0 * se / sqrt(s0 * s0 + se * se), 0.0, 1e-5);
        FNAV_ASSERT_CLOSE(al.result.gyro_bias_rps.v[1], b_true, 3.0 * se, 0.0);
    }
    /* (2) sway: angle 1 deg sin(2 pi t), rate its derivative, over 0.75 s */
    assert_int_equal(fnav_align_init(&al, &c), FNAV_OK);
    for (k = 0; k < 150; k++) {
        fnav_sample_t s = still_sample(k, rate, 0.0);
        double t = (double)k / rate;
        s.gyro_rps[1] = (fnav_real_t)(b_true + 0.0174533 * 6.283185307179586 * cos(6.283185307179586 * t));
        rates[k] = (double)s.gyro_rps[1];
        assert_int_equal(fnav_align_push(&al, &s, 1, FNAV_R(100.0)), FNAV_AGAIN);
    }
    {
        fnav_sample_t s = still_sample(150, rate, 0.0);
        assert_int_equal(fnav_align_push(&al, &s, 0, FNAV_R(1e7)), FNAV_OK);
    }
    {
        double w = (double)al.result.gyro_mean_rps.v[1], se = (double)al.result.gyro_mean_se_rps.v[1];
        double bias_err_mean = fabs(w - b_true), bias_err = fabs((double)al.result.gyro_bias_rps.v[1] - b_true);
        /* the mean is off by the sway (about 0.02 rad/s); the standard
         * error sees it, and the estimate is several times closer */
        assert_true(bias_err_mean > 0.01);
        assert_true(se > 0.3 * bias_err_mean);
        assert_true(bias_err < 0.5 * bias_err_mean);
        FNAV_ASSERT_CLOSE(al.result.gyro_bias_rps.v[1], w * s0 * s0 / (s0 * s0 + se * se), 0.0, 1e-6);
        /* the standard error is the batch-means value, recomputed here in
         * double: the doubling blocks of fnav_align.h end, for 150 samples,
         * as 4 whole blocks of 32 (the 22 samples after them are in no
         * block); the block means' unbiased variance (divisor 3) over 4 */
        FNAV_ASSERT_CLOSE(se, batch_means_se(rates, 150), 0.0, 1e-4);
    }
}

/* A still period whose mean specific force is exactly zero (a sensor that
 * outputs zeros, which the adaptive SHOE threshold accepts as stance) has
 * no gravity direction: FNAV_E_RANGE, and the period is discarded. Kept,
 * the next still sample would complete the alignment on the zeros and the
 * real samples together, an accelerometer bias of -g x (zeros / all) along
 * gravity (9.78 m/s^2 here). */
static void test_zero_mean_period(void **state)
{
    fnav_align_t al;
    fnav_align_config_t c = fnav_align_config_default;
    long k;
    fnav_status_t st = FNAV_AGAIN;
    (void)state;
    c.max_still_s = FNAV_R(2.0);
    assert_int_equal(fnav_align_init(&al, &c), FNAV_OK);
    for (k = 0; k < 401; k++) {
        fnav_sample_t s;
        memset(&s, 0, sizeof s);
        s.t_ns = (int64_t)k * 5000000;
        st = fnav_align_push(&al, &s, 1, FNAV_R(100.0));
        assert_int_equal(st, k < 400 ? FNAV_AGAIN : FNAV_E_RANGE);
    }
    assert_int_equal(al.done, 0);
    st = FNAV_AGAIN;
    for (k = 401; k < 2000 && st == FNAV_AGAIN; k++) {
        fnav_sample_t s = still_sample(k, 200.0, 0.002);
        st = fnav_align_push(&al, &s, 1, FNAV_R(100.0));
    }
    assert_int_equal(st, FNAV_OK);
    assert_int_equal((int)al.result.samples, 401); /* the real samples only */
    check_accel_bias(&al, &c, 401, 401);
}

/* A sensor stuck on one time stamp (frozen, repeating its last sample) in a
 * still period: the period's duration stays 0, so it never ends, and its
 * sample count (a long: 32 bits on the Cortex-M4F) would grow without
 * bound, to a signed overflow after 2^31 samples (24.9 days at 1 kHz). A
 * period restarts at FNAV_ALIGN_PERIOD_MAX samples (the stamps say no
 * time passed), so the count stays far inside
 * 32 bits and the alignment completes on the real stillness that follows.
 * The count is set near the end directly (2^30 pushes would take minutes). */
static void test_stuck_stamp_period(void **state)
{
    fnav_align_t al;
    fnav_align_config_t c = fnav_align_config_default;
    fnav_status_t st = FNAV_AGAIN;
    long k;
    (void)state;
    assert_int_equal(fnav_align_init(&al, &c), FNAV_OK);
    for (k = 0; k < 100; k++) {
        fnav_sample_t s = still_sample(k, 200.0, 0.002);
        s.t_ns = 1000000000; /* stuck */
        assert_int_equal(fnav_align_push(&al, &s, 1, FNAV_R(100.0)), FNAV_AGAIN);
    }
    assert_true(al.cur.n == 100);
    al.cur.n = 2147483647L - 1L; /* a 32-bit long's largest, less one */
    al.cur.sum_log_stat = (fnav_real_t)(2.0 * (double)al.cur.n); /* log10(100) each: no ratio break */
    for (k = 100; k < 102; k++) {
        fnav_sample_t s = still_sample(k, 200.0, 0.002);
        s.t_ns = 1000000000;
        assert_int_equal(fnav_align_push(&al, &s, 1, FNAV_R(100.0)), FNAV_AGAIN);
        assert_true(al.cur.n > 0 && al.cur.n <= 2147483647L);
    }
    assert_true(al.cur.n <= 2);
    /* the restart is at FNAV_ALIGN_PERIOD_MAX samples exactly: a period
     * holding that many takes no more (a mutant restarting one sample
     * later passed every suite) */
    al.cur.n = FNAV_ALIGN_PERIOD_MAX - 1L;
    al.cur.sum_log_stat = (fnav_real_t)(2.0 * (double)al.cur.n);
    {
        fnav_sample_t s = still_sample(102, 200.0, 0.002);
        s.t_ns = 1000000000;
        assert_int_equal(fnav_align_push(&al, &s, 1, FNAV_R(100.0)), FNAV_AGAIN);
        assert_true(al.cur.n == FNAV_ALIGN_PERIOD_MAX);
        assert_int_equal(fnav_align_push(&al, &s, 1, FNAV_R(100.0)), FNAV_AGAIN);
        assert_true(al.cur.n == 1);
    }
    for (k = 102; k < 5000 && st == FNAV_AGAIN; k++) {
        fnav_sample_t s = still_sample(k, 200.0, 0.002);
        s.t_ns += 1000000000 - 510000000; /* on from the stuck stamp, 5 ms apart */
        st = fnav_align_push(&al, &s, 1, FNAV_R(100.0));
    }
    assert_int_equal(st, FNAV_OK);
    /* max_still_s 5 s at 200 Hz: the stuck sample the period restarted
     * with and k = 102 .. 1102 (its stamps 1 s .. 6 s; k = 102's repeats
     * the stuck one) */
    assert_int_equal((int)k, 1103);
    assert_int_equal((int)al.result.samples, 1002);
    /* the gyro means of those samples, in double: gyro x 0.004 + 0.001
     * ((k mod 7) - 3), not a whole number of its 7-sample cycles, so not
     * 0.004 (not held to 0.004 within 1e-4, 16 times the cycles'
     * 6e-6); the period sums offsets from its first sample (|offset| <=
     * 0.006 rad/s, partial sums <= 1002 x 0.006): u of that per addition,
     * over n in the mean, and u of the mean for adding it back: EPS (6 +
     * 0.01) rad/s. Gyro y is constant: exact but for that last u. */
    {
        double mx = (double)still_sample(102, 200.0, 0.002).gyro_rps[0];
        for (k = 102; k <= 1102; k++) {
            mx += (double)still_sample(k, 200.0, 0.002).gyro_rps[0];
        }
        mx /= 1002.0;
        FNAV_ASSERT_CLOSE(al.result.gyro_mean_rps.v[0], mx, EPS * (1002.0 * 0.006 + 0.01), 0.0);
        FNAV_ASSERT_CLOSE(al.result.gyro_mean_rps.v[1], (double)FNAV_R(-0.002), EPS * 0.002, 0.0);
    }
}

/* A still period whose mean |f| is off gravity by more than 25 %
 * (FNAV_ALIGN_GRAVITY_TOL) is refused: 1 s of zeros (a sensor not yet
 * running) and 2 s of real stillness in one period average |f| = 2/3 of
 * the real one, and aligning on it would give an accelerometer bias of
 * 3.3 m/s^2 (2 s of zeros then a still foot through the navigator:
 * 3.91 m/s^2); the period is refused, its |f| kept, and the next
 * one aligns on real samples only. A log in g (|f| = 1) is refused too. */
static void test_implausible_gravity(void **state)
{
    fnav_align_t al;
    fnav_align_config_t c = fnav_align_config_default;
    fnav_align_result_t r;
    fnav_status_t st = FNAV_AGAIN;
    long k;
    (void)state;
    assert_int_equal(fnav_align_from_means(fnav_vec3(FNAV_R(0.0), FNAV_R(0.0), (fnav_real_t)(-1.24 * k_g)),
                                           fnav_vec3_zero(), (fnav_real_t)k_g, &r), FNAV_OK);
    assert_int_equal(fnav_align_from_means(fnav_vec3(FNAV_R(0.0), FNAV_R(0.0), (fnav_real_t)(-0.76 * k_g)),
                                           fnav_vec3_zero(), (fnav_real_t)k_g, &r), FNAV_OK);
    assert_int_equal(fnav_align_from_means(fnav_vec3(FNAV_R(0.0), FNAV_R(0.0), (fnav_real_t)(-1.26 * k_g)),
                                           fnav_vec3_zero(), (fnav_real_t)k_g, &r), FNAV_E_RANGE);
    assert_int_equal(fnav_align_from_means(fnav_vec3(FNAV_R(0.0), FNAV_R(0.0), FNAV_R(-1.0)), fnav_vec3_zero(),
                                           (fnav_real_t)k_g, &r), FNAV_E_RANGE);
    c.max_still_s = FNAV_R(3.0);
    assert_int_equal(fnav_align_init(&al, &c), FNAV_OK);
    assert_true(al.refused_f_mps2 == FNAV_R(0.0));
    for (k = 0; k < 200; k++) {
        fnav_sample_t s;
        memset(&s, 0, sizeof s);
        s.t_ns = (int64_t)k * 5000000;
        assert_int_equal(fnav_align_push(&al, &s, 1, FNAV_R(100.0)), FNAV_AGAIN);
    }
    for (k = 200; k < 3000 && st == FNAV_AGAIN; k++) {
        fnav_sample_t s = still_sample(k, 200.0, 0.002);
        st = fnav_align_push(&al, &s, 1, FNAV_R(100.0));
        if (k == 600) {
            /* 3 s: 200 zeros and 401 real samples, refused */
            assert_int_equal(st, FNAV_E_RANGE);
            /* |f| of the period: the 200 zeros and the 401 real samples
             * (k = 200..600), whose first sample, a zero, is the
             * reference: the real samples' offsets are the full |f|, their
             * k-th partial sum k |f|, each addition rounded by u of it: u
             * |f| 401 x 402 / 2 in the sum, over 601 in the mean; and a few
             * u of |f| for the norm */
            double m[3], fr;
            still_mean_f(200, 401, 200.0, 0.002, m);
            fr = sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]) * 401.0 / 601.0;
            FNAV_ASSERT_CLOSE(al.refused_f_mps2, fr, 0.5 * EPS * fr * (401.0 * 402.0 / 2.0) / 401.0 + 4.0 * EPS * fr,
                              0.0);
            st = FNAV_AGAIN;
        }
    }
    assert_int_equal(st, FNAV_OK);
    assert_int_equal((int)al.result.samples, 601); /* real samples only: 3 s from k = 601 */
    check_accel_bias(&al, &c, 601, 601);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_config),
        cmocka_unit_test(test_prior_square),
        cmocka_unit_test(test_not_initialised),
        cmocka_unit_test(test_from_means),
        cmocka_unit_test(test_from_means_bad_args),
        cmocka_unit_test(test_still_period),
        cmocka_unit_test(test_max_duration),
        cmocka_unit_test(test_ratio_ends_period),
        cmocka_unit_test(test_zero_stat),
        cmocka_unit_test(test_rounded_variance_clamped),
        cmocka_unit_test(test_finish),
        cmocka_unit_test(test_short_period_fallback),
        cmocka_unit_test(test_short_period_bias_prior),
        cmocka_unit_test(test_finish_keeps_best),
        cmocka_unit_test(test_gyro_bias_posterior),
        cmocka_unit_test(test_zero_mean_period),
        cmocka_unit_test(test_stuck_stamp_period),
        cmocka_unit_test(test_implausible_gravity),
    };
    return cmocka_run_group_tests_name("align", tests, NULL, NULL);
}
