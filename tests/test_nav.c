/* fnav_nav: configuration, timing (duplicates, gaps, jumps, time going
 * backwards), NaN rejection, the push/pop/step/run contracts, the landing
 * settling state's start at every stance onset, the alignment's renewal
 * before the first stride, object sizes,
 * the golden replays of vectors/nav/golden (any change fails), and the
 * float32-versus-float64 agreement on every real walk of the shared data
 * (vectors/nav/double_reference.csv, from gen_double_reference.py). */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>
#include <cjson/cJSON.h>

#include "footnav/fnav_nav.h"
#include "fnav_testdata.h"
#include "hx_nav.h"

static const double k_g = 9.80665;

/* A still foot (level, tiny deterministic wobble) sampled at 200 Hz. */
static fnav_sample_t still(long k)
{
    fnav_sample_t s;
    memset(&s, 0, sizeof s);
    s.t_ns = (int64_t)k * 5000000;
    s.seq = (uint32_t)k;
    s.accel_mps2[0] = (fnav_real_t)(0.001 * ((k % 3) - 1));
    s.accel_mps2[2] = (fnav_real_t)(-k_g + 0.001 * ((k % 5) - 2));
    s.gyro_rps[1] = (fnav_real_t)(0.0002 * ((k % 7) - 3));
    return s;
}

/* A sample of the synthetic swing: 2 rad/s of pitch rate, 1 m/s^2 forward. */
static void swing(fnav_sample_t *s)
{
    s->gyro_rps[1] = FNAV_R(2.0);
    s->accel_mps2[0] = FNAV_R(1.0);
}

/* The navigator's default detector is the detector's default: one
 * initializer (FNAV_STANCE_CONFIG_DEFAULT_INIT) for both: were
 * fnav_nav_config_default to hold a copy of the values, a default changed
 * in one would not reach the other. Compared field by field (the
 * padding of a struct is not part of its value). */
static void test_default_stance_is_detector_default(void **state)
{
    const fnav_stance_config_t *a = &fnav_nav_config_default.stance, *b = &fnav_stance_config_default;
    (void)state;
    assert_int_equal(a->detector, b->detector);
    assert_true(a->rate_hz == b->rate_hz && a->window_s == b->window_s);
    assert_true(a->sigma_a_mps2 == b->sigma_a_mps2 && a->sigma_g_rps == b->sigma_g_rps && a->gamma == b->gamma);
    assert_true(a->gyro_thresh_rps == b->gyro_thresh_rps && a->accel_thresh_mps2 == b->accel_thresh_mps2);
    assert_true(a->gravity_mps2 == b->gravity_mps2);
    assert_int_equal(a->adaptive, b->adaptive);
    assert_true(a->floor_window_s == b->floor_window_s && a->margin_dec == b->margin_dec &&
                a->adapt_max_ratio == b->adapt_max_ratio);
    assert_true(a->min_zupt_s == b->min_zupt_s && a->min_stance_s == b->min_stance_s &&
                a->min_swing_s == b->min_swing_s && a->event_window_s == b->event_window_s);
    assert_true(a->min_zupt_cycle == b->min_zupt_cycle);
}

/* The valid range of every field of fnav_nav_config_t, as docs/navigation.md
 * ("Configuration", "What fnav_nav_init accepts") states it: for each real
 * field the last value accepted and the first refused at the boundary (the
 * defaults elsewhere: lever and settling on), and NaN and +-Inf refused. */
typedef struct {
    const char *name;
    size_t off;
    fnav_real_t ok, bad;
} cfg_range_t;

#define CFG_RANGE(f, ok, bad) { #f, offsetof(fnav_nav_config_t, f), FNAV_R(ok), FNAV_R(bad) }

/* Either side of where an sd's square stops being a positive finite real:
 * float squares 1e-18 to 1e-36 (above FLT_MIN), 1e-23 to 1e-46 (below half
 * the least subnormal, 1.4e-45: 0), 1e18 to 1e36, 1e20 to 1e40 (above
 * FLT_MAX, 3.4e38: inf); double 1e-150, 1e-170 (1e-340 below 4.9e-324),
 * 1e150, 1e160 (1e320 above 1.8e308). */
#if FNAV_USE_DOUBLE
#define SQ_TINY_OK 1e-150
#define SQ_TINY_BAD 1e-170
#define SQ_HUGE_OK 1e150
#define SQ_HUGE_BAD 1e160
#else
#define SQ_TINY_OK 1e-18f
#define SQ_TINY_BAD 1e-23f
#define SQ_HUGE_OK 1e18f
#define SQ_HUGE_BAD 1e20f
#endif

/* With the rate estimated (stance.rate_hz 0) the first frame waits for
 * the 33rd sample (32 intervals) or for its own latency, h + lag samples,
 * whichever is later, and that sample releases every frame then due: the
 * figures fnav_nav.h and docs/navigation.md ("Data flow and latency") give. A standing
 * sensor at exact rates; counted by push and pop. */
static int first_release(double rate_hz, float min_zupt_cycle, int *released)
{
    static fnav_nav_t nav;
    fnav_nav_config_t c = fnav_nav_config_default;
    fnav_nav_frame_t f;
    fnav_sample_t s;
    int i;
    c.stance.min_zupt_cycle = (fnav_real_t)min_zupt_cycle;
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    for (i = 1; i <= 200; i++) {
        memset(&s, 0, sizeof s);
        s.t_ns = (int64_t)((double)(i - 1) * 1e9 / rate_hz + 0.5);
        s.accel_mps2[2] = FNAV_R(-9.80665);
        assert_int_equal(fnav_nav_push(&nav, &s), FNAV_OK);
        *released = 0;
        while (fnav_nav_pop(&nav, &f) == FNAV_OK) {
            ++*released;
        }
        if (*released > 0) {
            return i;
        }
    }
    return -1;
}

static void test_first_frames(void **state)
{
    int n = 0;
    (void)state;
    assert_true(fnav_nav_config_default.stance.rate_hz == FNAV_R(0.0)); /* estimated */
    /* defaults: 200 Hz latency 16 samples, 33 - 16 = 17 frames at sample 33 */
    assert_int_equal(first_release(200.0, fnav_nav_config_default.stance.min_zupt_cycle, &n), 33);
    assert_int_equal(n, 17);
    /* 400 Hz: latency 34 samples, past the 33rd: one frame a sample from 35 */
    assert_int_equal(first_release(400.0, fnav_nav_config_default.stance.min_zupt_cycle, &n), 35);
    assert_int_equal(n, 1);
    /* 820 Hz: latency 62 (the ring's cap) */
    assert_int_equal(first_release(820.0, fnav_nav_config_default.stance.min_zupt_cycle, &n), 63);
    assert_int_equal(n, 1);
    /* min_zupt_cycle 0: latency 5 at 200 Hz, 12 at 400 Hz */
    assert_int_equal(first_release(200.0, 0.0f, &n), 33);
    assert_int_equal(n, 28);
    assert_int_equal(first_release(400.0, 0.0f, &n), 33);
    assert_int_equal(n, 21);
}

static void test_config_ranges(void **state)
{
    static fnav_nav_t nav;
    static const cfg_range_t reals[] = {
        CFG_RANGE(gravity_mps2, 1e-3, 0.0),
        CFG_RANGE(accel_motion_noise_mps2_rthz, 0.0, -1e-6),
        CFG_RANGE(gyro_motion_noise_rps_rthz, 0.0, -1e-6),
        CFG_RANGE(zupt_sigma_mps, 1e-6, 0.0),
        CFG_RANGE(lever_sd_m, 1e-6, 0.0),
        CFG_RANGE(lever_rw_m_rts, 0.0, -1e-6),
        CFG_RANGE(settle_sd_mps, 1e-6, 0.0),
        CFG_RANGE(settle_tau_s, 1e-6, 0.0),
        CFG_RANGE(zaru_sigma_rps, 1e-6, 0.0),
        CFG_RANGE(zaru_gate, 0.0, -1e-6),
        CFG_RANGE(zaru_after_s, 0.0, -1e-6),
        CFG_RANGE(realign_min_s, 5.0, 5.001), /* at most align.max_still_s (5) */
        CFG_RANGE(realign_min_s, 0.0, -1e-6),
        CFG_RANGE(tilt_sd_rad, 1e-6, 0.0),
        CFG_RANGE(yaw_sd_rad, 1e-6, 0.0),
        CFG_RANGE(gyro_bias_sd_rps, 1e-6, 0.0),
        CFG_RANGE(accel_bias_sd_mps2, 1e-6, 0.0),
        CFG_RANGE(max_gap_s, 1e-6, 0.0),
        CFG_RANGE(diverge_speed_mps, 1e-6, 0.0),
        CFG_RANGE(stance.rate_hz, 0.0, -1e-6),
        CFG_RANGE(stance.window_s, 1e-6, 0.0),
        CFG_RANGE(stance.sigma_a_mps2, 1e-6, 0.0),
        CFG_RANGE(stance.sigma_g_rps, 1e-6, 0.0),
        CFG_RANGE(stance.gamma, 1e-6, 0.0),
        CFG_RANGE(stance.gyro_thresh_rps, 1e-6, 0.0),
        CFG_RANGE(stance.accel_thresh_mps2, 1e-6, 0.0),
        CFG_RANGE(stance.floor_window_s, 1e-6, 0.0),
        CFG_RANGE(stance.margin_dec, 0.0, -1e-6),
        CFG_RANGE(stance.adapt_max_ratio, 1.0, 0.999),
        CFG_RANGE(stance.min_zupt_s, 0.0, -1e-6),
        CFG_RANGE(stance.min_stance_s, 0.0, -1e-6),
        CFG_RANGE(stance.min_swing_s, 0.0, -1e-6),
        CFG_RANGE(stance.event_window_s, 1e-6, 0.0),
        CFG_RANGE(stance.min_zupt_cycle, 1.0, 1.001),
        CFG_RANGE(stance.min_zupt_cycle, 0.0, -1e-6),
        CFG_RANGE(align.min_still_s, 0.2, 0.0), /* at least short_still_s (0.2) */
        CFG_RANGE(align.max_still_s, 3.0, 2.999), /* at least realign_min_s (3) and min_still_s (0.5) */
        CFG_RANGE(align.short_still_s, 0.5, 0.501), /* in (0, min_still_s] */
        CFG_RANGE(align.short_still_s, 1e-6, 0.0),
        CFG_RANGE(align.still_ratio, 1.001, 1.0),
        CFG_RANGE(align.gyro_bias_prior_sd_rps, 0.0, -1e-6),
        CFG_RANGE(profile.rate_hz, 1e-6, 0.0),
        CFG_RANGE(profile.accel_noise_mps2_rthz[0], 1e-6, 0.0),
        CFG_RANGE(profile.gyro_tau_s[2], 1e-6, 0.0),
        CFG_RANGE(profile.gyro_bias_sigma_rps[1], 1e-6, 0.0),
    };
    static const struct {
        const char *name;
        size_t off;
        int upper; /* 1: no other upper bound, the square's overflow tested */
    } sq_fields[] = {
        { "zupt_sigma_mps", offsetof(fnav_nav_config_t, zupt_sigma_mps), 1 },
        { "zaru_sigma_rps", offsetof(fnav_nav_config_t, zaru_sigma_rps), 1 },
        { "gyro_bias_sd_rps", offsetof(fnav_nav_config_t, gyro_bias_sd_rps), 1 },
        { "accel_bias_sd_mps2", offsetof(fnav_nav_config_t, accel_bias_sd_mps2), 1 },
        { "lever_sd_m", offsetof(fnav_nav_config_t, lever_sd_m), 1 },
        { "settle_sd_mps", offsetof(fnav_nav_config_t, settle_sd_mps), 1 },
        { "tilt_sd_rad", offsetof(fnav_nav_config_t, tilt_sd_rad), 0 },
        { "yaw_sd_rad", offsetof(fnav_nav_config_t, yaw_sd_rad), 0 },
    };
    const fnav_real_t nonfinite[3] = { (fnav_real_t)NAN, (fnav_real_t)INFINITY, -(fnav_real_t)INFINITY };
    size_t i, k;
    fnav_nav_config_t c;
    (void)state;
    assert_int_equal(fnav_nav_config_default.lever, 1);
    assert_int_equal(fnav_nav_config_default.settle, 1);
    for (i = 0; i < sizeof reals / sizeof reals[0]; i++) {
        fnav_real_t *f = (fnav_real_t *)(void *)((unsigned char *)&c + reals[i].off);
        c = fnav_nav_config_default;
        *f = reals[i].ok;
        if (fnav_nav_init(&nav, &c) != FNAV_OK) {
            fail_msg("%s = %g refused", reals[i].name, (double)reals[i].ok);
        }
        *f = reals[i].bad;
        if (fnav_nav_init(&nav, &c) != FNAV_E_CONFIG) {
            fail_msg("%s = %g not refused", reals[i].name, (double)reals[i].bad);
        }
        for (k = 0; k < 3; k++) {
            *f = nonfinite[k];
            if (fnav_nav_init(&nav, &c) != FNAV_E_CONFIG) {
                fail_msg("%s = %g not refused", reals[i].name, (double)nonfinite[k]);
            }
        }
    }
    c = fnav_nav_config_default;
    c.realign_min_s = FNAV_R(0.0);
    c.align.max_still_s = FNAV_R(0.5);
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    c.align.max_still_s = FNAV_R(0.499);
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
    /* the sds whose square the filter takes: a square neither 0 nor
     * infinite. SQ_* lie either side of where the real type's square
     * underflows to 0 (below the least subnormal) or overflows; tilt and
     * yaw are bounded above by fnav_nav_att_sd_max_rad instead */
    for (i = 0; i < sizeof sq_fields / sizeof sq_fields[0]; i++) {
        fnav_real_t *f = (fnav_real_t *)(void *)((unsigned char *)&c + sq_fields[i].off);
        const fnav_real_t vals[4] = { SQ_TINY_OK, SQ_TINY_BAD, SQ_HUGE_OK, SQ_HUGE_BAD };
        for (k = 0; k < (sq_fields[i].upper ? 4u : 2u); k++) {
            c = fnav_nav_config_default;
            *f = vals[k];
            if (fnav_nav_init(&nav, &c) != (k % 2u == 0u ? FNAV_OK : FNAV_E_CONFIG)) {
                fail_msg("%s = %g %s", sq_fields[i].name, (double)vals[k], k % 2u == 0u ? "refused" : "not refused");
            }
        }
    }
    /* tilt and yaw: at most fnav_nav_att_sd_max_rad (0.707 rad, 18 states) */
    for (k = 0; k < 2; k++) {
        c = fnav_nav_config_default;
        *(k == 0 ? &c.tilt_sd_rad : &c.yaw_sd_rad) = fnav_nav_att_sd_max_rad(&c) * FNAV_R(0.999);
        assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
        *(k == 0 ? &c.tilt_sd_rad : &c.yaw_sd_rad) = fnav_nav_att_sd_max_rad(&c) * FNAV_R(1.001);
        assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
    }
    /* every value of the profile: > 0 and finite (fnav_profile_validate) */
    for (i = 0; i < 18; i++) {
        fnav_real_t *arrs[6];
        fnav_real_t *f;
        c = fnav_nav_config_default;
        arrs[0] = c.profile.accel_noise_mps2_rthz;
        arrs[1] = c.profile.accel_tau_s;
        arrs[2] = c.profile.accel_bias_sigma_mps2;
        arrs[3] = c.profile.gyro_noise_rps_rthz;
        arrs[4] = c.profile.gyro_tau_s;
        arrs[5] = c.profile.gyro_bias_sigma_rps;
        f = &arrs[i / 3][i % 3];
        *f = FNAV_R(1e-6);
        if (fnav_nav_init(&nav, &c) != FNAV_OK) {
            fail_msg("profile value %zu = 1e-6 refused", i);
        }
        *f = FNAV_R(0.0);
        if (fnav_nav_init(&nav, &c) != FNAV_E_CONFIG) {
            fail_msg("profile value %zu = 0 not refused", i);
        }
        for (k = 0; k < 3; k++) {
            *f = nonfinite[k];
            if (fnav_nav_init(&nav, &c) != FNAV_E_CONFIG) {
                fail_msg("profile value %zu = %g not refused", i, (double)nonfinite[k]);
            }
        }
    }
    /* with the detector's rate given, a time jump must be longer than a gap */
    c = fnav_nav_config_default;
    c.stance.rate_hz = FNAV_R(100.0);
    c.max_gap_s = FNAV_R(0.016);
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    c.max_gap_s = FNAV_R(0.015);
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
    /* the switches: 0 or 1; the counts and enumerations */
    c = fnav_nav_config_default;
    for (k = 0; k < 2; k++) {
        int bad = k == 0 ? -1 : 2;
        c = fnav_nav_config_default;
        c.lever = bad;
        assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
        c = fnav_nav_config_default;
        c.settle = bad;
        assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
        c = fnav_nav_config_default;
        c.zaru = bad;
        assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
        c = fnav_nav_config_default;
        c.closed_form = bad;
        assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
        c = fnav_nav_config_default;
        c.stance.adaptive = bad;
        assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
    }
    c = fnav_nav_config_default;
    c.diverge_undone = 1u;
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    c.diverge_undone = 0u;
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
    c = fnav_nav_config_default;
    c.sample_type = (fnav_sample_type_t)7;
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
    c = fnav_nav_config_default;
    c.bias_model = (fnav_bias_model_t)7;
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
    c = fnav_nav_config_default;
    c.stance.detector = (fnav_detector_t)7;
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
    /* the lever's and the settling's values are not read when they are off */
    c = fnav_nav_config_default;
    c.lever = 0;
    c.lever_sd_m = FNAV_R(0.0);
    c.settle = 0;
    c.settle_tau_s = FNAV_R(0.0);
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
}

static void test_config(void **state)
{
    static fnav_nav_t nav;
    fnav_nav_config_t c = fnav_nav_config_default;
    (void)state;
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    assert_int_equal(fnav_nav_init(NULL, &c), FNAV_E_ARG);
    c.gravity_mps2 = FNAV_R(0.0);
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
    c = fnav_nav_config_default;
    c.profile.gyro_tau_s[0] = FNAV_R(-1.0);
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
    c = fnav_nav_config_default;
    c.stance.window_s = FNAV_R(-0.1);
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
    c = fnav_nav_config_default;
    c.zupt_sigma_mps = FNAV_R(0.0);
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
    {
        /* initial sds whose variance is 0 or infinite in this build: were
         * they accepted, the filter would start with that variance (the
         * guard then makes it the maximum: a tilt sd of 1e-25 rad becomes
         * pi rad); fnav_ukf_start refuses them, and start_filter asserts
         * that it starts */
#if FNAV_USE_DOUBLE
        const fnav_real_t bad[2] = { 1.0e-170, 1.0e160 };
#else
        const fnav_real_t bad[2] = { 1.0e-25f, 1.0e20f };
#endif
        int k, b;
        for (k = 0; k < 5; k++) {
            for (b = 0; b < 2; b++) {
                fnav_real_t *x[5] = { &c.tilt_sd_rad, &c.yaw_sd_rad, &c.gyro_bias_sd_rps, &c.accel_bias_sd_mps2,
                                      &c.zupt_sigma_mps };
                c = fnav_nav_config_default;
                *x[k] = bad[b];
                if (fnav_nav_init(&nav, &c) != FNAV_E_CONFIG) {
                    fail_msg("initial sd %d = %g accepted", k, (double)bad[b]);
                }
            }
        }
    }
    /* the ZARU's gate reaches the filter; a negative one is refused */
    c = fnav_nav_config_default;
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    assert_true(nav.ukf.cfg.zaru_gate == fnav_ukf_config_default.zaru_gate);
    c.zaru_gate = FNAV_R(5.0);
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    assert_true(nav.ukf.cfg.zaru_gate == FNAV_R(5.0));
    c.zaru_gate = FNAV_R(-1.0);
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
    /* the flags zaru and closed_form are 0 or 1, as lever and settle (2
     * and -1 are not taken for 1) */
    c = fnav_nav_config_default;
    c.zaru = 2;
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
    c.zaru = -1;
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
    c = fnav_nav_config_default;
    c.closed_form = 2;
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
    /* an initial tilt or yaw sd the UKF's sigma points cannot represent
     * (fnav_nav_att_sd_max_rad: 3 / sqrt(18) rad with the default 18
     * states, the lever's included): a yaw sd of 90 deg, if taken, reads
     * 32.4 deg a sample later */
    c = fnav_nav_config_default;
    assert_true(fabs((double)fnav_nav_att_sd_max_rad(&c) - 3.0 / sqrt(18.0)) < 1.0e-6);
    assert_true(fnav_nav_att_sd_max_rad(NULL) == FNAV_R(0.0));
    c.yaw_sd_rad = FNAV_R(1.5707963);
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
    c.yaw_sd_rad = fnav_nav_att_sd_max_rad(&c) * FNAV_R(1.001);
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
    c.yaw_sd_rad = fnav_nav_att_sd_max_rad(&c) * FNAV_R(0.999);
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    c = fnav_nav_config_default;
    c.tilt_sd_rad = fnav_nav_att_sd_max_rad(&c) * FNAV_R(1.001);
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
    c.tilt_sd_rad = FNAV_R(0.72); /* above 3 / sqrt(18) = 0.707, below 3 / sqrt(15) = 0.775 */
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
    c.lever = 0; /* 15 states: a larger limit */
    assert_true(fabs((double)fnav_nav_att_sd_max_rad(&c) - 3.0 / sqrt(15.0)) < 1.0e-6);
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    /* the divergence limits and the longest gap: positive and finite, a
     * run of at least one undone step (none was tested: a mutant accepting
     * a speed limit of 0, which resets at every step, passed every suite) */
    {
        const fnav_real_t bad[4] = { FNAV_R(0.0), -FNAV_R(1.0), (fnav_real_t)INFINITY, (fnav_real_t)NAN };
        int k;
        for (k = 0; k < 4; k++) {
            c = fnav_nav_config_default;
            c.diverge_speed_mps = bad[k];
            assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
            c = fnav_nav_config_default;
            c.max_gap_s = bad[k];
            assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
        }
        c = fnav_nav_config_default;
        c.diverge_undone = 0u;
        assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
        c.diverge_undone = 1u;
        c.diverge_speed_mps = FNAV_R(1e-3);
        c.max_gap_s = FNAV_R(1e-3);
        assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
        /* with a configured rate the longest gap must be above 1.5
         * intervals (a gap): 1.5 / 128 s at 128 Hz, exactly 1.5 intervals
         * in binary, is refused, 1.6 intervals accepted (a mutant accepting
         * 1.5 passed every suite) */
        c = fnav_nav_config_default;
        c.stance.rate_hz = FNAV_R(128.0);
        c.max_gap_s = FNAV_R(0.01171875);
        assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
        c.max_gap_s = FNAV_R(0.0125);
        assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    }
    /* a renewal minimum longer than a still period can last (the
     * alignment's max_still_s ends it) would never renew: refused */
    c = fnav_nav_config_default;
    c.realign_min_s = c.align.max_still_s;
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    c.realign_min_s = c.align.max_still_s + FNAV_R(0.5);
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
    /* the ZARU's standstill time: 0 or more, finite */
    c = fnav_nav_config_default;
    assert_true(c.zaru_after_s == FNAV_R(0.0));
    c.zaru_after_s = FNAV_R(-0.1);
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
    c.zaru_after_s = (fnav_real_t)INFINITY;
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
    /* the alignment's gyro-bias prior: one whose square overflows was
     * accepted, made the bias NaN and the start of the filter on it failed
     * its assert, an abort (test_align test_prior_square) */
    c = fnav_nav_config_default;
    c.align.gyro_bias_prior_sd_rps = SQ_HUGE_BAD;
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
    c.align.gyro_bias_prior_sd_rps = SQ_HUGE_OK;
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    /* the checks of nav_init no suite made (make coverage): gravity not
     * finite; a motion noise not finite or negative; an initial sd of 0,
     * negative, or whose square is 0 or infinite in the working precision
     * (fnav_ukf_start would refuse it); zaru neither 0 nor 1; a renewal
     * minimum negative or NaN */
    {
        const fnav_real_t huge = (fnav_real_t)(FNAV_USE_DOUBLE ? 1e200 : 1e30);
        const fnav_real_t tiny = (fnav_real_t)(FNAV_USE_DOUBLE ? 1e-200 : 1e-30);
        const fnav_real_t bad_sd[4] = { FNAV_R(0.0), FNAV_R(-0.1), huge, tiny };
        int k;
        c = fnav_nav_config_default;
        c.gravity_mps2 = (fnav_real_t)NAN;
        assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
        c = fnav_nav_config_default;
        c.accel_motion_noise_mps2_rthz = (fnav_real_t)INFINITY;
        assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
        c.accel_motion_noise_mps2_rthz = FNAV_R(-0.1);
        assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
        c.accel_motion_noise_mps2_rthz = FNAV_R(0.0); /* none: accepted */
        assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
        c = fnav_nav_config_default;
        c.gyro_motion_noise_rps_rthz = (fnav_real_t)NAN;
        assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
        c.gyro_motion_noise_rps_rthz = FNAV_R(-0.1);
        assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
        c.gyro_motion_noise_rps_rthz = FNAV_R(0.0);
        assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
        for (k = 0; k < 4; k++) {
            c = fnav_nav_config_default;
            c.tilt_sd_rad = bad_sd[k];
            assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
            c = fnav_nav_config_default;
            c.yaw_sd_rad = bad_sd[k];
            assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
            c = fnav_nav_config_default;
            c.gyro_bias_sd_rps = bad_sd[k];
            assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
            c = fnav_nav_config_default;
            c.accel_bias_sd_mps2 = bad_sd[k];
            assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
        }
        c = fnav_nav_config_default;
        c.zaru = 2;
        assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
        c.zaru = -1;
        assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
        c = fnav_nav_config_default;
        c.realign_min_s = FNAV_R(-0.1);
        assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
        c.realign_min_s = (fnav_real_t)NAN;
        assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
        c.realign_min_s = FNAV_R(0.0);
        assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    }
}

/* One frame per accepted sample, in order; rejected samples change nothing;
 * alignment after the still period; position stays at the origin at rest. */
static void test_stream_contract(void **state)
{
    static fnav_nav_t nav, copy;
    fnav_nav_config_t c = fnav_nav_config_default;
    fnav_nav_frame_t fr;
    long k, frames = 0, n = 600;
    uint32_t next = 0;
    (void)state;
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    for (k = 0; k < n; k++) {
        fnav_sample_t s = still(k);
        assert_int_equal(fnav_nav_push(&nav, &s), FNAV_OK);
        while (fnav_nav_pop(&nav, &fr) == FNAV_OK) {
            assert_int_equal(fr.seq, next);
            next++;
            frames++;
        }
        if (k == 300) {
            /* NaN, a value or a stamp out of range (a glitch; a
             * stamp whose difference with the last would overflow) and a
             * time going backwards: rejected, nothing changes */
            fnav_sample_t bad = still(301);
            copy = nav;
            bad.gyro_rps[2] = (fnav_real_t)NAN;
            assert_int_equal(fnav_nav_push(&nav, &bad), FNAV_E_NANINF);
            bad = still(301);
            bad.accel_mps2[1] = FNAV_R(-2.0e6);
            assert_int_equal(fnav_nav_push(&nav, &bad), FNAV_E_RANGE);
            bad = still(301);
            bad.t_ns = FNAV_T_NS_MAX + 1;
            assert_int_equal(fnav_nav_push(&nav, &bad), FNAV_E_RANGE);
            bad = still(299);
            assert_int_equal(fnav_nav_push(&nav, &bad), FNAV_E_TIME);
            assert_int_equal(nav.stats.nan_inputs, 1);
            assert_int_equal(nav.stats.range_inputs, 2);
            assert_int_equal(nav.stats.time_back, 1);
            assert_true((nav.health & FNAV_HEALTH_RANGE) != 0u);
            nav.stats.nan_inputs = copy.stats.nan_inputs;
            nav.stats.range_inputs = copy.stats.range_inputs;
            nav.stats.time_back = copy.stats.time_back;
            nav.health = copy.health;
            assert_int_equal(nav.back_run, 1u); /* the run behind, toward FNAV_NAV_TIME_RESYNC */
            nav.back_run = copy.back_run;
            assert_memory_equal(&nav, &copy, sizeof nav);
            nav.stats.nan_inputs = 1;
            nav.stats.range_inputs = 2;
            nav.stats.time_back = 1;
            nav.back_run = 1u; /* the next accepted sample ends the run */
            nav.health |= FNAV_HEALTH_NANINF | FNAV_HEALTH_RANGE | FNAV_HEALTH_TIME_BACK;
        }
    }
    fnav_nav_finish(&nav);
    while (fnav_nav_pop(&nav, &fr) == FNAV_OK) {
        assert_int_equal(fr.seq, next);
        next++;
        frames++;
    }
    assert_int_equal(fnav_nav_pop(&nav, &fr), FNAV_END);
    assert_int_equal(frames, n);
    assert_int_equal(nav.stats.frames, n);
    assert_true(nav.aligned);
    assert_true(fr.flags & FNAV_FRAME_ALIGNED);
    assert_true(fr.flags & FNAV_FRAME_ZUPT);
    assert_true(fr.health & FNAV_HEALTH_NANINF);
    assert_true(fr.health & FNAV_HEALTH_TIME_BACK);
    /* at rest the position stays at the origin (ZUPTs every sample) */
    assert_true(fabs((double)fr.pos_m[0]) < 1e-3 && fabs((double)fr.pos_m[1]) < 1e-3 && fabs((double)fr.pos_m[2]) < 1e-3);
    assert_true(fabs((double)fr.euler_rad[0]) < 1e-3 && fabs((double)fr.euler_rad[1]) < 1e-3);
}

/* After fnav_nav_finish a push is a call in the wrong state, whatever the
 * sample: FNAV_E_STATE for a good sample and equally for a NaN, an
 * out-of-range value or stamp and a stamp going backwards, with nothing
 * counted and the navigator unchanged byte for byte (fnav_nav.h): the bad
 * samples must not return their own rejection status nor be counted in
 * stats and health after the end. */
static void test_push_after_finish(void **state)
{
    static fnav_nav_t nav, copy;
    fnav_nav_config_t c = fnav_nav_config_default;
    fnav_nav_frame_t fr;
    fnav_sample_t s;
    long k;
    (void)state;
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    for (k = 0; k < 100; k++) {
        s = still(k);
        assert_int_equal(fnav_nav_push(&nav, &s), FNAV_OK);
        while (fnav_nav_pop(&nav, &fr) == FNAV_OK) {
        }
    }
    fnav_nav_finish(&nav);
    copy = nav;
    s = still(100);
    assert_int_equal(fnav_nav_push(&nav, &s), FNAV_E_STATE);
    s.gyro_rps[0] = (fnav_real_t)NAN;
    assert_int_equal(fnav_nav_push(&nav, &s), FNAV_E_STATE);
    s = still(100);
    s.accel_mps2[2] = FNAV_R(2.0e6);
    assert_int_equal(fnav_nav_push(&nav, &s), FNAV_E_STATE);
    s = still(100);
    s.t_ns = FNAV_T_NS_MAX + 1;
    assert_int_equal(fnav_nav_push(&nav, &s), FNAV_E_STATE);
    s = still(10); /* backwards */
    assert_int_equal(fnav_nav_push(&nav, &s), FNAV_E_STATE);
    s.accel_mps2[0] = (fnav_real_t)INFINITY;
    assert_int_equal(fnav_nav_step(&nav, &s, &fr), FNAV_E_STATE);
    assert_int_equal(nav.stats.nan_inputs, 0);
    assert_int_equal(nav.stats.range_inputs, 0);
    assert_int_equal(nav.stats.time_back, 0);
    assert_int_equal(nav.health & (FNAV_HEALTH_NANINF | FNAV_HEALTH_RANGE | FNAV_HEALTH_TIME_BACK), 0u);
    assert_memory_equal(&nav, &copy, sizeof nav);
    /* the frames held back by the detector are still all there: h 2 + lag
     * 14 at 200 Hz (fnav_nav.h, "Latency"; 5 with min_zupt_cycle 0, the
     * scaling off) */
    k = 0;
    while (fnav_nav_pop(&nav, &fr) == FNAV_OK) {
        k++;
    }
    assert_int_equal(k, 16);
    assert_int_equal(nav.stats.frames, 100);
}

/* Duplicates (dt = 0), gaps (> 1.5 intervals), time jumps (> max_gap_s).
 * The motion inside a time jump is unknown: its frame is propagated over
 * the nominal interval 1 / rate, not over the 1.005 s of the stamps. The
 * filter's cached AR(1) interval (fnav_ukf_t.ar1_dt_s, the dt of the last
 * prediction whose interval changed) shows which interval was used at the
 * jump's frame. */
static void test_timing(void **state)
{
    static fnav_nav_t nav;
    fnav_nav_config_t c = fnav_nav_config_default;
    fnav_nav_frame_t fr;
    long k, n = 1400, frames = 0;
    int64_t shift = 0;
    int jump_seen = 0;
    (void)state;
    c.stance.rate_hz = FNAV_R(200.0);
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    for (k = 0; k < n; k++) {
        fnav_sample_t s = still(k);
        if (k == 400) {
            shift += 10000000; /* a 15 ms interval: gap */
        }
        if (k == 600) {
            /* an 8 ms interval, 1.6 nominal ones: a gap (above 1.5,
             * docs/navigation.md "Timing") */
            shift += 3000000;
        }
        if (k == 800) {
            shift += 2000000; /* a 7 ms interval, 1.4 nominal ones: no gap */
        }
        if (k == 1200) {
            /* a 1 s interval: time jump, after the alignment (5 s of the
             * still foot: the alignment's max_still_s) */
            shift += 1000000000;
        }
        if (k == 1300) {
            /* a 0.305 s interval: a time jump by default (max_gap_s 0.2 s;
             * at 0.5 s such an interval mid-swing would be integrated with
             * one sample's rates: scripts/max_gap_sweep.py) */
            shift += 300000000;
        }
        if (k == 1350) {
            shift += 145000000; /* a 0.15 s interval: a gap, integrated */
        }
        s.t_ns += shift;
        assert_int_equal(fnav_nav_push(&nav, &s), FNAV_OK);
        if (k == 300 || k == 301) {
            assert_int_equal(fnav_nav_push(&nav, &s), FNAV_OK); /* exact duplicate */
        }
        while (fnav_nav_pop(&nav, &fr) == FNAV_OK) {
            frames++;
            if (fr.seq == 1200u) {
                /* the jump's frame: aligned and predicted (the still foot
                 * is stance: a ZUPT follows), over the nominal 5 ms. The
                 * two ways of forming 5 ms in fnav_real_t (5e6 ns * 1e-9
                 * and 1 / 200) differ by a rounding at most: 2 eps
                 * relative; a 1.005 s interval differs by a factor 201 */
                jump_seen = 1;
                assert_true(fr.flags & FNAV_FRAME_ALIGNED);
                assert_true(fr.flags & FNAV_FRAME_ZUPT);
                assert_true(fr.health & FNAV_HEALTH_TIME_JUMP);
                FNAV_ASSERT_CLOSE(nav.ukf.ar1_dt_s, 1.0 / 200.0, 0.0, 2.0 * (double)FNAV_REAL_EPSILON);
            }
        }
    }
    fnav_nav_finish(&nav);
    while (fnav_nav_pop(&nav, &fr) == FNAV_OK) {
        frames++;
    }
    assert_true(jump_seen);
    assert_int_equal(frames, n + 2);
    assert_int_equal(nav.stats.duplicates, 2);
    assert_int_equal(nav.stats.gaps, 3);
    assert_int_equal(nav.stats.time_jumps, 2);
    assert_true(fr.health & FNAV_HEALTH_DUPLICATE);
    assert_true(fr.health & FNAV_HEALTH_GAP);
    assert_true(fr.health & FNAV_HEALTH_TIME_JUMP);
    FNAV_ASSERT_CLOSE(nav.stats.max_gap_seen_s, 1.005, 1e-6, 0.0);
}

/* fnav_nav_step returns the newest frame and processes every due one. */
static void test_step(void **state)
{
    static fnav_nav_t nav;
    fnav_nav_config_t c = fnav_nav_config_default;
    fnav_nav_frame_t fr;
    long k, ok = 0;
    (void)state;
    c.stance.rate_hz = FNAV_R(200.0);
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    for (k = 0; k < 100; k++) {
        fnav_sample_t s = still(k);
        fnav_status_t st = fnav_nav_step(&nav, &s, &fr);
        if (st == FNAV_OK) {
            ok++;
            /* latency: W = 5 (h = 2) plus the confirmation look-ahead,
             * fixed by min_zupt_cycle 0.025 for a 3 s cycle: L =
             * round(0.025 x 3 x 200) - 1 = 14 (fnav_stance.h) */
            assert_int_equal((long)fr.seq, k - 16);
        } else {
            assert_int_equal(st, FNAV_AGAIN);
        }
    }
    assert_int_equal(ok, 84);
}

/* The port loop produces the same frames as push/pop by hand. */
typedef struct {
    long i, n;
    fnav_nav_frame_t *out;
    long nout;
} mem_port_t;

static fnav_status_t mem_read(void *ctx, fnav_sample_t *s)
{
    mem_port_t *m = (mem_port_t *)ctx;
    if (m->i >= m->n) {
        return FNAV_END;
    }
    *s = still(m->i);
    if (m->i > 250 && m->i < 330) {
        swing(s); /* some motion */
    }
    m->i++;
    return FNAV_OK;
}

static fnav_status_t mem_write(void *ctx, const fnav_nav_frame_t *f)
{
    mem_port_t *m = (mem_port_t *)ctx;
    m->out[m->nout++] = *f;
    return FNAV_OK;
}

static void test_run_port(void **state)
{
    static fnav_nav_t a, b;
    static fnav_nav_frame_t fa[500], fb[500];
    fnav_nav_config_t c = fnav_nav_config_default;
    mem_port_t m = { 0, 500, fa, 0 }, m2 = { 0, 500, fb, 0 };
    fnav_port_t port;
    fnav_sample_t s;
    (void)state;
    memset(&port, 0, sizeof port);
    port.ctx = &m;
    port.read_sample = mem_read;
    port.write_nav = mem_write;
    assert_int_equal(fnav_nav_init(&a, &c), FNAV_OK);
    assert_int_equal(fnav_nav_run(&a, &port, 0), FNAV_OK);
    assert_int_equal(m.nout, 500);
    assert_int_equal(fnav_nav_init(&b, &c), FNAV_OK);
    while (mem_read(&m2, &s) == FNAV_OK) {
        assert_int_equal(fnav_nav_push(&b, &s), FNAV_OK);
        while (fnav_nav_pop(&b, &fb[m2.nout]) == FNAV_OK) {
            m2.nout++;
        }
    }
    fnav_nav_finish(&b);
    while (fnav_nav_pop(&b, &fb[m2.nout]) == FNAV_OK) {
        m2.nout++;
    }
    assert_int_equal(m2.nout, 500);
    assert_memory_equal(fa, fb, sizeof fa);
}

/* Misuse by an integrator (docs/robustness.md, "Bad-input catalogue: core entry points"): a
 * navigator never initialised (static storage is zeroed), or whose init
 * failed, is refused with FNAV_E_STATE by every call that returns a status,
 * and finish / reset leave it alone: a push, pop or step on it must not
 * return FNAV_OK or FNAV_AGAIN and step a detector with a zeroed
 * configuration, nor fnav_nav_run read the whole source. */
static long g_reads;
static fnav_status_t counting_read(void *ctx, fnav_sample_t *s)
{
    (void)ctx;
    if (g_reads >= 50) {
        return FNAV_END;
    }
    *s = still(g_reads);
    g_reads++;
    return FNAV_OK;
}

static void check_refused(fnav_nav_t *nav)
{
    static fnav_nav_t copy;
    fnav_nav_frame_t fr;
    fnav_sample_t s = still(0);
    fnav_port_t port;
    memset(&port, 0, sizeof port);
    port.read_sample = counting_read;
    copy = *nav;
    assert_int_equal(fnav_nav_push(nav, &s), FNAV_E_STATE);
    assert_int_equal(fnav_nav_pop(nav, &fr), FNAV_E_STATE);
    assert_int_equal(fnav_nav_step(nav, &s, &fr), FNAV_E_STATE);
    g_reads = 0;
    assert_int_equal(fnav_nav_run(nav, &port, 0), FNAV_E_STATE);
    assert_int_equal(g_reads, 0); /* nothing read from the source */
    fnav_nav_finish(nav);
    fnav_nav_reset(nav);
    assert_memory_equal(nav, &copy, sizeof copy);
    assert_int_equal(fnav_nav_push(nav, &s), FNAV_E_STATE);
}

static void test_not_initialised(void **state)
{
    static fnav_nav_t nav; /* zeroed, as static storage is */
    fnav_nav_config_t c = fnav_nav_config_default;
    fnav_sample_t s = still(0);
    (void)state;
    check_refused(&nav);
    /* a failed init leaves it not initialised: a configuration the
     * navigator refuses itself, and one a module refuses (the detector) */
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    assert_int_equal(fnav_nav_push(&nav, &s), FNAV_OK);
    c.gravity_mps2 = FNAV_R(0.0);
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
    check_refused(&nav);
    c = fnav_nav_config_default;
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    c.stance.window_s = FNAV_R(-0.1);
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
    check_refused(&nav);
    /* and a good init after it starts over */
    c = fnav_nav_config_default;
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    assert_int_equal(fnav_nav_push(&nav, &s), FNAV_OK);
    assert_int_equal(nav.stats.samples, 1u);
    /* NULL arguments: FNAV_E_ARG, nothing counted (make coverage: push
     * and pop were not tried with them) */
    {
        fnav_nav_frame_t fr;
        assert_int_equal(fnav_nav_push(NULL, &s), FNAV_E_ARG);
        assert_int_equal(fnav_nav_push(&nav, NULL), FNAV_E_ARG);
        assert_int_equal(fnav_nav_pop(NULL, &fr), FNAV_E_ARG);
        assert_int_equal(fnav_nav_pop(&nav, NULL), FNAV_E_ARG);
        assert_int_equal(fnav_sample_check(NULL), FNAV_E_ARG);
        assert_int_equal(nav.stats.samples, 1u);
    }
}

/* The navigator's configuration reaches its parts (fnav_nav.h): the UKF's
 * noises are the profile's and the motion noise added in quadrature
 * (computed here in double), every other filter option as given, and the
 * gravity that of the detector and the alignment too. Each value differs
 * from both defaults; deleting the copy of lever_rw_m_rts (the defaults
 * of the navigator and the UKF agree, 0.002) passed every suite. */
static void test_config_reaches_parts(void **state)
{
    static fnav_nav_t nav;
    fnav_nav_config_t c = fnav_nav_config_default;
    const fnav_ukf_config_t *u = &nav.ukf.cfg;
    int i;
    (void)state;
    for (i = 0; i < 3; i++) {
        c.profile.gyro_noise_rps_rthz[i] = (fnav_real_t)(0.003 + 0.001 * i);
        c.profile.accel_noise_mps2_rthz[i] = (fnav_real_t)(0.04 + 0.01 * i);
        c.profile.gyro_tau_s[i] = (fnav_real_t)(101.0 + i);
        c.profile.accel_tau_s[i] = (fnav_real_t)(201.0 + i);
        c.profile.gyro_bias_sigma_rps[i] = (fnav_real_t)(0.0011 + 0.0001 * i);
        c.profile.accel_bias_sigma_mps2[i] = (fnav_real_t)(0.011 + 0.001 * i);
    }
    c.gyro_motion_noise_rps_rthz = FNAV_R(0.004);
    c.accel_motion_noise_mps2_rthz = FNAV_R(0.03);
    c.bias_model = FNAV_BIAS_OFF;
    c.gravity_mps2 = FNAV_R(9.79);
    c.sample_type = FNAV_SAMPLE_MEAN;
    c.zupt_sigma_mps = FNAV_R(0.013);
    c.zaru_sigma_rps = FNAV_R(0.017);
    c.zaru_gate = FNAV_R(7.81);
    c.closed_form = 0;
    c.lever = 1;
    c.lever_sd_m = FNAV_R(0.07);
    c.lever_rw_m_rts = FNAV_R(0.005);
    c.settle = 0;
    c.settle_sd_mps = FNAV_R(0.021);
    c.settle_tau_s = FNAV_R(0.04);
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    for (i = 0; i < 3; i++) {
        /* of the values as stored; a few roundings of the build's type */
        const double gn = (double)c.profile.gyro_noise_rps_rthz[i], an = (double)c.profile.accel_noise_mps2_rthz[i];
        const double gm = (double)c.gyro_motion_noise_rps_rthz, am = (double)c.accel_motion_noise_mps2_rthz;
        const double rel = FNAV_USE_DOUBLE ? 1e-15 : 5e-7;
        FNAV_ASSERT_CLOSE(u->gyro_noise_rps_rthz[i], sqrt(gn * gn + gm * gm), 0.0, rel);
        FNAV_ASSERT_CLOSE(u->accel_noise_mps2_rthz[i], sqrt(an * an + am * am), 0.0, rel);
        assert_true(u->gyro_tau_s[i] == c.profile.gyro_tau_s[i]);
        assert_true(u->accel_tau_s[i] == c.profile.accel_tau_s[i]);
        assert_true(u->gyro_bias_sigma_rps[i] == c.profile.gyro_bias_sigma_rps[i]);
        assert_true(u->accel_bias_sigma_mps2[i] == c.profile.accel_bias_sigma_mps2[i]);
    }
    assert_int_equal(u->bias_model, FNAV_BIAS_OFF);
    assert_true(u->strapdown.gravity_mps2 == FNAV_R(9.79));
    assert_int_equal(u->strapdown.sample_type, FNAV_SAMPLE_MEAN);
    assert_true(u->zupt_sigma_mps == FNAV_R(0.013));
    assert_true(u->zaru_sigma_rps == FNAV_R(0.017));
    assert_true(u->zaru_gate == FNAV_R(7.81));
    assert_int_equal(u->closed_form, 0);
    assert_int_equal(u->lever, 1);
    assert_true(u->lever_sd_m == FNAV_R(0.07));
    assert_true(u->lever_rw_m_rts == FNAV_R(0.005));
    assert_int_equal(u->settle, 0);
    assert_true(u->settle_sd_mps == FNAV_R(0.021));
    assert_true(u->settle_tau_s == FNAV_R(0.04));
    assert_true(nav.stance.cfg.gravity_mps2 == FNAV_R(9.79));
    assert_true(nav.align.cfg.gravity_mps2 == FNAV_R(9.79));
    /* and the switches the other way */
    c.lever = 0;
    c.settle = 1;
    c.closed_form = 1;
    c.bias_model = FNAV_BIAS_AR1;
    c.sample_type = FNAV_SAMPLE_INSTANT;
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    assert_int_equal(u->lever, 0);
    assert_int_equal(u->settle, 1);
    assert_int_equal(u->closed_form, 1);
    assert_int_equal(u->bias_model, FNAV_BIAS_AR1);
    assert_int_equal(u->strapdown.sample_type, FNAV_SAMPLE_INSTANT);
}

/* A second fnav_nav_init starts over (fnav_nav.h), also with the
 * navigator's own configuration, fnav_nav_init(&nav, &nav.cfg), the way to
 * restart with the same one: zeroing the navigator, its configuration
 * with it, before copying *cfg would return FNAV_E_CONFIG for a valid
 * configuration, the navigator left not initialised. The restarted
 * navigator makes the frames of a fresh one. */
static void test_reinit_own_config(void **state)
{
    static fnav_nav_t nav, fresh;
    fnav_nav_config_t c = fnav_nav_config_default;
    fnav_nav_frame_t fa, fb;
    long k;
    (void)state;
    c.stance.rate_hz = FNAV_R(200.0);
    c.max_gap_s = FNAV_R(0.25);
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    for (k = 0; k < 300; k++) {
        fnav_sample_t s = still(k);
        fnav_status_t st = fnav_nav_step(&nav, &s, &fa);
        assert_true(st == FNAV_OK || st == FNAV_AGAIN);
    }
    assert_int_equal(fnav_nav_init(&nav, &nav.cfg), FNAV_OK);
    assert_int_equal(nav.stats.samples, 0u);
    assert_true(nav.cfg.stance.rate_hz == FNAV_R(200.0) && nav.cfg.max_gap_s == FNAV_R(0.25));
    assert_int_equal(fnav_nav_init(&fresh, &c), FNAV_OK);
    for (k = 0; k < 600; k++) {
        fnav_sample_t s = still(k);
        fnav_status_t sa = fnav_nav_push(&nav, &s), sb = fnav_nav_push(&fresh, &s);
        assert_int_equal(sa, FNAV_OK);
        assert_int_equal(sb, FNAV_OK);
        for (;;) {
            memset(&fa, 0, sizeof fa);
            memset(&fb, 0, sizeof fb);
            sa = fnav_nav_pop(&nav, &fa);
            sb = fnav_nav_pop(&fresh, &fb);
            assert_int_equal(sa, sb);
            if (sa != FNAV_OK) {
                break;
            }
            assert_memory_equal(&fa, &fb, sizeof fa);
        }
    }
    assert_int_equal(nav.stats.frames, fresh.stats.frames);
    assert_true(nav.stats.frames > 500u);
}

/* Before the alignment a frame has no estimate (fnav_port.h): the ALIGNED
 * flag clear and every real field 0; the first aligned frame has the
 * alignment's attitude and variances. */
static void test_frames_before_alignment(void **state)
{
    static fnav_nav_t nav;
    fnav_nav_config_t c = fnav_nav_config_default;
    fnav_nav_frame_t fr;
    long k, before = 0;
    int aligned = 0;
    (void)state;
    c.stance.rate_hz = FNAV_R(200.0);
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    for (k = 0; k < 2000 && !aligned; k++) { /* the still period completes it at align.max_still_s */
        fnav_sample_t s = still(k);
        assert_int_equal(fnav_nav_push(&nav, &s), FNAV_OK);
        while (!aligned && fnav_nav_pop(&nav, &fr) == FNAV_OK) {
            int i;
            if (fr.flags & FNAV_FRAME_ALIGNED) {
                aligned = 1;
                assert_true(fr.p_diag[0] > FNAV_R(0.0));
                break;
            }
            before++;
            for (i = 0; i < 3; i++) {
                assert_true(fr.pos_m[i] == FNAV_R(0.0) && fr.vel_mps[i] == FNAV_R(0.0));
                assert_true(fr.euler_rad[i] == FNAV_R(0.0) && fr.lever_m[i] == FNAV_R(0.0));
                assert_true(fr.gyro_bias_rps[i] == FNAV_R(0.0) && fr.accel_bias_mps2[i] == FNAV_R(0.0));
            }
            for (i = 0; i < FNAV_UKF_N; i++) {
                assert_true(fr.p_diag[i] == FNAV_R(0.0));
            }
        }
    }
    assert_true(aligned);
    assert_true(before > 50); /* the alignment takes its still period first */
}

/* fnav_nav_step without a frame to write: FNAV_E_ARG, the sample not taken.
 * Not FNAV_AGAIN, taking each sample until the detector's ring is full of
 * frames it cannot pop, then FNAV_E_STATE for ever. */
static void test_step_null_frame(void **state)
{
    static fnav_nav_t nav, copy;
    fnav_nav_config_t c = fnav_nav_config_default;
    long k;
    (void)state;
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    copy = nav;
    for (k = 0; k < 100; k++) {
        fnav_sample_t s = still(k);
        assert_int_equal(fnav_nav_step(&nav, &s, NULL), FNAV_E_ARG);
    }
    assert_memory_equal(&nav, &copy, sizeof nav);
}

/* fnav_nav_run on a navigator whose input has ended (a second run without
 * a new init): FNAV_E_STATE before reading anything, not the whole source
 * read, every push refused and ignored, and FNAV_OK with no frame
 * written. */
static void test_run_after_finish(void **state)
{
    static fnav_nav_t nav;
    fnav_nav_config_t c = fnav_nav_config_default;
    fnav_port_t port;
    (void)state;
    memset(&port, 0, sizeof port);
    port.read_sample = counting_read;
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    g_reads = 0;
    assert_int_equal(fnav_nav_run(&nav, &port, 0), FNAV_OK);
    assert_int_equal(g_reads, 50);
    assert_int_equal(nav.stats.frames, 50u);
    g_reads = 0;
    assert_int_equal(fnav_nav_run(&nav, &port, 0), FNAV_E_STATE);
    assert_int_equal(g_reads, 0);
    assert_int_equal(nav.stats.frames, 50u);
}

/* fnav_nav_run's other exits (fnav_nav.h; make coverage shows no other
 * suite runs them): the max_samples limit (exactly that many samples
 * read, then the frames flushed as at the end of the source); FNAV_AGAIN
 * from a non-blocking source (called again, not counted against the
 * limit, the frames those of a source without it); a read error (its
 * status returned after every frame of the samples read was written); a
 * sink failing inside the loop or in the final flush (FNAV_E_IO, nothing
 * more read or written); NULL arguments (FNAV_E_ARG). */
typedef struct {
    long n;        /**< samples the source holds */
    fnav_status_t end; /**< returned after them: FNAV_END or an error */
    int again;     /**< FNAV_AGAIN before every sample */
    long fail_at;  /**< the sink fails on this frame (0-based), -1: never */
    long reads, calls, writes;
    fnav_nav_frame_t *out;
} script_port_t;

static fnav_status_t script_read(void *ctx, fnav_sample_t *s)
{
    script_port_t *m = (script_port_t *)ctx;
    m->calls++;
    if (m->again && m->calls % 2 == 1) {
        return FNAV_AGAIN;
    }
    if (m->reads >= m->n) {
        return m->end;
    }
    *s = still(m->reads);
    m->reads++;
    return FNAV_OK;
}

static fnav_status_t script_write(void *ctx, const fnav_nav_frame_t *f)
{
    script_port_t *m = (script_port_t *)ctx;
    if (m->writes == m->fail_at) {
        return FNAV_E_IO;
    }
    if (m->out != NULL) {
        m->out[m->writes] = *f;
    }
    m->writes++;
    return FNAV_OK;
}

static fnav_status_t script_run(script_port_t *m, long max_samples)
{
    static fnav_nav_t nav;
    fnav_nav_config_t c = fnav_nav_config_default;
    fnav_port_t port;
    memset(&port, 0, sizeof port);
    port.ctx = m;
    port.read_sample = script_read;
    port.write_nav = script_write;
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    return fnav_nav_run(&nav, &port, max_samples);
}

static void test_run_exits(void **state)
{
    static fnav_nav_t nav;
    static fnav_nav_frame_t fa[200], fb[200];
    fnav_nav_config_t c = fnav_nav_config_default;
    fnav_port_t port;
    script_port_t m;
    (void)state;
    /* reference: 200 samples, plain source */
    memset(&m, 0, sizeof m);
    m.n = 200, m.end = FNAV_END, m.fail_at = -1, m.out = fa;
    assert_int_equal(script_run(&m, 0), FNAV_OK);
    assert_int_equal(m.reads, 200);
    assert_int_equal(m.writes, 200);
    /* FNAV_AGAIN before every sample: the same frames */
    memset(&m, 0, sizeof m);
    m.n = 200, m.end = FNAV_END, m.again = 1, m.fail_at = -1, m.out = fb;
    assert_int_equal(script_run(&m, 0), FNAV_OK);
    assert_int_equal(m.writes, 200);
    assert_memory_equal(fa, fb, sizeof fa);
    /* max_samples = 120 on that source: 120 samples read (in 240 calls:
     * the FNAV_AGAINs are not counted) and the frames of a source of 120
     * samples, those held back flushed as at its end */
    memset(&m, 0, sizeof m);
    m.n = 120, m.end = FNAV_END, m.fail_at = -1, m.out = fa;
    assert_int_equal(script_run(&m, 0), FNAV_OK);
    assert_int_equal(m.writes, 120);
    memset(&m, 0, sizeof m);
    m.n = 200, m.end = FNAV_END, m.again = 1, m.fail_at = -1, m.out = fb;
    assert_int_equal(script_run(&m, 120), FNAV_OK);
    assert_int_equal(m.reads, 120);
    assert_int_equal(m.calls, 240);
    assert_int_equal(m.writes, 120);
    assert_memory_equal(fa, fb, 120 * sizeof fa[0]);
    /* a read error after 60 samples: its status, after the 60 frames */
    memset(&m, 0, sizeof m);
    m.n = 60, m.end = FNAV_E_IO, m.fail_at = -1;
    assert_int_equal(script_run(&m, 0), FNAV_E_IO);
    assert_int_equal(m.reads, 60);
    assert_int_equal(m.writes, 60);
    memset(&m, 0, sizeof m);
    m.n = 60, m.end = FNAV_E_TRUNCATED, m.fail_at = -1;
    assert_int_equal(script_run(&m, 0), FNAV_E_TRUNCATED);
    assert_int_equal(m.writes, 60);
    /* the sink fails on frame 10 (in the loop): nothing more read */
    memset(&m, 0, sizeof m);
    m.n = 200, m.end = FNAV_END, m.fail_at = 10;
    assert_int_equal(script_run(&m, 0), FNAV_E_IO);
    assert_int_equal(m.writes, 10);
    assert_true(m.reads < 200);
    assert_true(m.reads > 10);
    /* the sink fails on the last frame, one held back until the end of
     * the source (the frames lag the samples): in the flush */
    memset(&m, 0, sizeof m);
    m.n = 200, m.end = FNAV_END, m.fail_at = 199;
    assert_int_equal(script_run(&m, 0), FNAV_E_IO);
    assert_int_equal(m.reads, 200);
    assert_int_equal(m.writes, 199);
    /* NULL */
    memset(&port, 0, sizeof port);
    port.read_sample = script_read;
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    assert_int_equal(fnav_nav_run(NULL, &port, 0), FNAV_E_ARG);
    assert_int_equal(fnav_nav_run(&nav, NULL, 0), FNAV_E_ARG);
}

/* What fnav_nav.h says of input in the wrong units, which the core does not
 * check: the bundled walk (vectors/walk.bin, 398 Hz) with its
 * accelerations in g never aligns and the alignment holds the |f| of about
 * 1 it refused; with its rates in deg/s it aligns but diverges (resets);
 * with its stamps in ms the estimated rate is 1000 times too low. In SI it
 * aligns and nothing of that happens. And the profile's rate_hz (the rate
 * its values were identified at) does not enter the navigation: the same
 * frames with any. The test pins what the header says. */
typedef struct {
    int aligned;          /**< the last frame is aligned */
    uint32_t resets;      /**< divergence resets */
    uint32_t range_inputs; /**< samples refused as past any sensor's range */
    double refused_f, rate_hz;
    uint32_t crc;         /**< of every frame's bytes */
} units_run_t;

static units_run_t units_replay(const hx_log_t *log, double acc_k, double gyr_k, double t_k, fnav_real_t profile_hz)
{
    static fnav_nav_t nav;
    fnav_nav_config_t c = fnav_nav_config_default;
    fnav_nav_frame_t fr;
    units_run_t r;
    size_t i;
    int k;
    memset(&r, 0, sizeof r);
    memset(&fr, 0, sizeof fr);
    c.profile.rate_hz = profile_hz;
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    r.crc = 2166136261u;
    for (i = 0; i <= log->n; i++) {
        fnav_status_t st;
        if (i < log->n) {
            fnav_sample_t s;
            hx_log_sample(log, i, &s);
            s.t_ns = (int64_t)((double)s.t_ns * t_k);
            for (k = 0; k < 3; k++) {
                s.accel_mps2[k] = (fnav_real_t)((double)s.accel_mps2[k] * acc_k);
                s.gyro_rps[k] = (fnav_real_t)((double)s.gyro_rps[k] * gyr_k);
            }
            st = fnav_nav_push(&nav, &s);
            /* past the widest gyro range (deg/s read as rad/s): refused */
            assert_true(st == FNAV_OK || st == FNAV_E_RANGE);
        } else {
            fnav_nav_finish(&nav);
        }
        while ((st = fnav_nav_pop(&nav, &fr)) == FNAV_OK) {
            const unsigned char *b = (const unsigned char *)&fr;
            size_t j;
            for (j = 0; j < sizeof fr; j++) {
                r.crc = (r.crc ^ b[j]) * 16777619u; /* FNV-1a */
            }
        }
        assert_int_equal(st, i < log->n ? FNAV_AGAIN : FNAV_END);
    }
    r.aligned = (fr.flags & FNAV_FRAME_ALIGNED) != 0u;
    r.resets = nav.stats.resets;
    r.range_inputs = nav.stats.range_inputs;
    r.refused_f = (double)nav.align.refused_f_mps2;
    r.rate_hz = (double)nav.stance.rate_hz;
    return r;
}

static void test_units_not_checked(void **state)
{
    hx_log_t log;
    char err[256];
    units_run_t si, g, deg, ms, other_rate;
    (void)state;
    assert_int_equal(hx_log_load(&log, "vectors/walk.bin", HX_FMT_AUTO, 0.0, err, sizeof err), 0);
    si = units_replay(&log, 1.0, 1.0, 1.0, FNAV_R(200.0));
    assert_true(si.aligned);
    assert_int_equal(si.resets, 0u);
    assert_true(si.rate_hz > 390.0 && si.rate_hz < 410.0);
    g = units_replay(&log, 1.0 / k_g, 1.0, 1.0, FNAV_R(200.0));
    assert_false(g.aligned);
    assert_true(fabs(g.refused_f - 1.0) < 0.05);
    deg = units_replay(&log, 1.0, 57.29577951308232, 1.0, FNAV_R(200.0)); /* 180 / pi */
    /* the swings' rates past FNAV_NAV_GYRO_MAX_RPS refused, the rest
     * navigated 57 times too fast */
    assert_true(deg.range_inputs > 0u);
    assert_true(deg.resets > 0u);
    assert_int_equal(si.range_inputs, 0u);
    ms = units_replay(&log, 1.0, 1.0, 1000.0, FNAV_R(200.0));
    assert_true(fabs(ms.rate_hz * 1000.0 / si.rate_hz - 1.0) < 0.01);
    other_rate = units_replay(&log, 1.0, 1.0, 1.0, FNAV_R(1000.0));
    assert_int_equal(other_rate.crc, si.crc);
    hx_log_free(&log);
}

/* The landing settling state (fnav_ukf.h) starts at the first ZUPT of every
 * stance. A synthetic walk: still 2 s, then three 0.4 s bursts of motion,
 * each followed by 0.6 s still, at 200 Hz. A first pass finds the sample the
 * detector calls the first of the third stance; the second pass gives it
 * the previous sample's time stamp (dt = 0, a duplicate: that frame has no
 * ZUPT, and the start waits for the next one).
 * A start sets the settling variance back to settle_sd^2, so each shows as
 * a rise of it: one per stance. */
static fnav_sample_t settle_walk(long k)
{
    fnav_sample_t s = still(k);
    long ph = k - 400;
    if (ph >= 0 && ph % 200 < 80) {
        swing(&s);
    }
    return s;
}

/* zaru_after_s: with the ZARU on, a stance gets zero-angular-rate updates
 * only once it has lasted that long. Walking stances of 0.6 s get none at
 * 1 s and every sample at 0; the closing stand gets them from 1 s into
 * its stance, on every later sample. */
static void test_zaru_after(void **state)
{
    static fnav_nav_t nav;
    fnav_nav_config_t c = fnav_nav_config_default;
    fnav_nav_frame_t fr;
    const long n = 400 + 4 * 200 + 600;
    const fnav_real_t after[2] = { FNAV_R(1.0), FNAV_R(0.0) };
    long k;
    int pass;
    (void)state;
    c.stance.rate_hz = FNAV_R(200.0);
    c.zaru = 1;
    for (pass = 0; pass < 2; pass++) {
        uint32_t prev_count = 0u;
        int64_t t_prev = 0;
        double stance_s = 0.0, first_s = -1.0;
        long walking_zarus = 0, final_zarus = 0, final_frames = 0;
        c.zaru_after_s = after[pass];
        assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
        for (k = 0; k < n; k++) {
            fnav_sample_t s = still(k);
            long ph = k - 400;
            if (ph >= 0 && ph < 4 * 200 && ph % 200 < 80) {
                swing(&s);
            }
            assert_int_equal(fnav_nav_push(&nav, &s), FNAV_OK);
            while (fnav_nav_pop(&nav, &fr) == FNAV_OK) {
                const uint32_t count = nav.stats.zarus + nav.stats.zaru_gated;
                const int stance = (fr.flags & FNAV_FRAME_STANCE) != 0u;
                const int aligned = (fr.flags & FNAV_FRAME_ALIGNED) != 0u;
                const int zaru = count != prev_count;
                if (aligned && nav.stats.strides > 0u) {
                    stance_s = stance ? stance_s + (double)(fr.t_ns - t_prev) * 1e-9 : 0.0;
                    if ((long)fr.seq < 400 + 4 * 200) {
                        walking_zarus += zaru;
                    } else if (stance) {
                        final_frames++;
                        final_zarus += zaru;
                        if (zaru && first_s < 0.0) {
                            first_s = stance_s;
                        }
                    }
                }
                prev_count = count;
                t_prev = fr.t_ns;
            }
        }
        if (pass == 0) {
            assert_int_equal(walking_zarus, 0);
            /* from 1 s into the stand on (the stance's first frame counts
             * no time of its own, hence a sample's tolerance) */
            assert_true(first_s >= 1.0 - 0.0051 && first_s <= 1.0 + 0.0051);
            /* the stand's stance began with the last stride's, 0.6 s
             * (120 frames) before the frames counted here, so its first
             * 0.4 s (about 80 frames) lack the ZARU */
            assert_true(final_frames > 500);
            assert_true(final_zarus >= final_frames - 85 && final_zarus <= final_frames - 75);
        } else {
            assert_true(walking_zarus > 100);
            assert_int_equal(final_zarus, final_frames);
        }
    }
}

static void test_settle_onsets(void **state)
{
    static fnav_nav_t nav;
    fnav_nav_config_t c = fnav_nav_config_default;
    fnav_nav_frame_t fr;
    const long n = 400 + 3 * 200;
    long k, third = -1;
    int pass;
    (void)state;
    c.stance.rate_hz = FNAV_R(200.0);
    assert_int_equal(c.settle, 1);
    for (pass = 0; pass < 2; pass++) {
        int prev_stance = 1, onsets = 0, starts = 0, first_zupts = 0, dup_frames = 0;
        fnav_real_t prev_var = FNAV_R(0.0);
        assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
        for (k = 0; k < n; k++) {
            fnav_sample_t s = settle_walk(k);
            if (pass == 1 && k == third) {
                s.t_ns = settle_walk(k - 1).t_ns; /* the previous stamp again: dt = 0 */
            }
            assert_int_equal(fnav_nav_push(&nav, &s), FNAV_OK);
            while (fnav_nav_pop(&nav, &fr) == FNAV_OK) {
                int stance = (fr.flags & FNAV_FRAME_STANCE) != 0u;
                if ((fr.flags & FNAV_FRAME_ALIGNED) != 0u) {
                    if (stance && !prev_stance) {
                        onsets++;
                        if (onsets == 3 && pass == 0) {
                            third = (long)fr.seq;
                        }
                        if (pass == 1 && (long)fr.seq == third) {
                            /* the onset's first frame: no ZUPT yet, pending */
                            assert_true((fr.flags & FNAV_FRAME_ZUPT) == 0u);
                            assert_true(nav.settle_pending);
                            assert_false(nav.ukf.settle_on);
                            dup_frames++;
                        }
                    }
                    if (nav.ukf.settle_var > prev_var) {
                        /* a start: at a stance's first ZUPT */
                        starts++;
                        assert_true(stance && (fr.flags & FNAV_FRAME_ZUPT) != 0u);
                        assert_true(nav.ukf.settle_on);
                        assert_false(nav.settle_pending);
                        first_zupts++;
                    }
                }
                prev_stance = stance;
                prev_var = nav.ukf.settle_var;
            }
        }
        assert_int_equal(onsets, 3);
        assert_int_equal(starts, 3);
        assert_int_equal(first_zupts, 3);
        assert_true(third > 400);
        assert_int_equal(dup_frames, pass == 1 ? 1 : 0);
        assert_int_equal(nav.stats.duplicates, pass == 1 ? 1u : 0u);
    }
}

/* A reset between a stance onset and its first ZUPT (a caller's
 * fnav_nav_reset after the onset's frame, whose duplicated stamp postponed
 * the ZUPT, as in test_settle_onsets) drops the pending settling start: the
 * landing belongs to the filter that was reset, and the re-aligned filter's
 * first ZUPT is a still period's, not a landing's: a pending start that
 * survived the reset and the re-alignment would start the settling state at
 * the re-aligned filter's first ZUPT. */
static void test_settle_pending_reset(void **state)
{
    static fnav_nav_t nav;
    fnav_nav_config_t c = fnav_nav_config_default;
    fnav_nav_frame_t fr;
    long k, third = -1, realigned_frames = 0;
    int pass, onsets, prev_stance, reset_done = 0;
    (void)state;
    c.stance.rate_hz = FNAV_R(200.0);
    for (pass = 0; pass < 2; pass++) {
        assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
        onsets = 0;
        prev_stance = 1;
        for (k = 0; k < 1000 + 1400; k++) {
            fnav_sample_t s = k < 1000 ? settle_walk(k) : still(k);
            if (pass == 1 && k == third) {
                s.t_ns = settle_walk(k - 1).t_ns; /* dt = 0: the onset's ZUPT waits */
            }
            assert_int_equal(fnav_nav_push(&nav, &s), FNAV_OK);
            while (fnav_nav_pop(&nav, &fr) == FNAV_OK) {
                int stance = (fr.flags & FNAV_FRAME_STANCE) != 0u;
                if (pass == 0 && (fr.flags & FNAV_FRAME_ALIGNED) != 0u && stance && !prev_stance && ++onsets == 3) {
                    third = (long)fr.seq;
                }
                if (pass == 1 && (long)fr.seq == third) {
                    assert_true(nav.settle_pending);
                    fnav_nav_reset(&nav);
                    reset_done = 1;
                }
                if (pass == 1 && reset_done && (fr.flags & FNAV_FRAME_ALIGNED) != 0u) {
                    realigned_frames++;
                    assert_false(nav.ukf.settle_on);
                }
                prev_stance = stance;
            }
        }
        assert_true(third > 800);
    }
    assert_int_equal(nav.stats.resets, 1u);
    assert_true(realigned_frames > 100);
}

/* An alignment that ends while the foot still stands (7 s still against the
 * alignment's 5 s at most) starts no settling state: the first one starts
 * at the landing after the following swing. */
static void test_settle_not_at_alignment(void **state)
{
    static fnav_nav_t nav;
    fnav_nav_config_t c = fnav_nav_config_default;
    fnav_nav_frame_t fr;
    long k, aligned_still = 0;
    int starts = 0, moved = 0;
    fnav_real_t prev_var = FNAV_R(0.0);
    (void)state;
    c.stance.rate_hz = FNAV_R(200.0);
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    for (k = 0; k < 1400 + 80 + 200; k++) {
        fnav_sample_t s = still(k);
        if (k >= 1400 && k < 1480) {
            swing(&s);
        }
        assert_int_equal(fnav_nav_push(&nav, &s), FNAV_OK);
        while (fnav_nav_pop(&nav, &fr) == FNAV_OK) {
            if ((fr.flags & FNAV_FRAME_ALIGNED) != 0u && (fr.flags & FNAV_FRAME_STANCE) == 0u) {
                moved = 1;
            }
            if ((fr.flags & FNAV_FRAME_ALIGNED) != 0u && !moved) {
                aligned_still++; /* standing after the alignment: no settling */
                assert_false(nav.ukf.settle_on);
            }
            if (nav.ukf.settle_var > prev_var) {
                starts++;
                assert_true(moved);
            }
            prev_var = nav.ukf.settle_var;
        }
    }
    assert_true(aligned_still > 100);
    assert_int_equal(starts, 1);
}

/* The renewal of the alignment before the first stride: a foot that stands
 * 10 s whose gyro z bias steps from 0.002 to 0.004 rad/s at 5 s (a power-on
 * drift, which the AR(1) states cannot follow and no ZUPT observes), then
 * two strides and 7 s of standing. The alignment completes at 5 s on the
 * first bias; the still period 5-10 s ends at the first swing and renews
 * it (bias 0.004, position and heading held); after the first stride the
 * long stillness renews nothing. With realign_min_s = 0 the first bias
 * stays. */
static fnav_sample_t renew_walk(long k)
{
    fnav_sample_t s = still(k);
    s.gyro_rps[2] = (fnav_real_t)(k < 1000 ? 0.002 : 0.004);
    if ((k >= 2000 && k < 2080) || (k >= 2400 && k < 2480)) {
        swing(&s);
    }
    return s;
}

static void test_realign(void **state)
{
    static fnav_nav_t nav;
    fnav_nav_config_t c = fnav_nav_config_default;
    fnav_nav_frame_t fr;
    int pass;
    (void)state;
    c.stance.rate_hz = FNAV_R(200.0);
    assert_true(c.realign_min_s > FNAV_R(0.0));
    for (pass = 0; pass < 2; pass++) {
        long k;
        double bz_before = 0.0, bz_after = 0.0, pos_at = 1.0, yaw_before = 0.0, yaw_at = 1.0;
        uint32_t renewed_at_stride = 99u;
        if (pass == 1) {
            c.realign_min_s = FNAV_R(0.0);
        }
        assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
        for (k = 0; k < 2480 + 1400; k++) {
            fnav_sample_t s = renew_walk(k);
            assert_int_equal(fnav_nav_push(&nav, &s), FNAV_OK);
            while (fnav_nav_pop(&nav, &fr) == FNAV_OK) {
                if ((long)fr.seq == 1990) {
                    bz_before = (double)fr.gyro_bias_rps[2];
                    yaw_before = (double)fr.euler_rad[2];
                }
                if ((long)fr.seq == 2000) {
                    bz_after = (double)fr.gyro_bias_rps[2];
                    yaw_at = (double)fr.euler_rad[2];
                    double x = (double)fr.pos_m[0], y = (double)fr.pos_m[1], z = (double)fr.pos_m[2];
                    pos_at = sqrt(x * x + y * y + z * z);
                }
                if ((fr.flags & FNAV_FRAME_STRIDE) != 0u && renewed_at_stride == 99u) {
                    renewed_at_stride = nav.stats.realigned;
                }
            }
        }
        /* the first alignment's bias, 0.002 rad/s, up to the first swing */
        assert_true(fabs(bz_before - 0.002) < 2.0e-4);
        assert_true(pos_at < 1.0e-3);
        assert_true(fabs(yaw_at - yaw_before) < 1.0e-3);
        assert_int_equal(renewed_at_stride, pass == 0 ? 1u : 0u);
        assert_int_equal(nav.stats.realigned, pass == 0 ? 1u : 0u); /* none after the stride */
        if (pass == 0) {
            assert_true(fabs(bz_after - 0.004) < 2.0e-4);
            /* the renewed alignment: 5-10 s less the detector's window at the swing */
            assert_true((double)nav.align.result.duration_s > 4.9 && (double)nav.align.result.duration_s <= 5.0);
        } else {
            assert_true(fabs(bz_after - 0.002) < 2.0e-4);
        }
    }
}

/* The heading held over a renewal with b's x axis vertical (a sensor
 * mounted upright on the heel or the side of the shoe: pitch 90 deg, where
 * ZYX yaw and roll split by the noise). The foot stands with x up, tilted
 * by 0.05 deg, first towards y, from 5 s towards z (a sway of 0.07 deg);
 * the renewal at the first swing must keep the heading of a level body
 * axis (b's z) within 0.01 rad. Holding the ZYX yaw would turn it by
 * 0.09 rad here, and by 87 and 110 deg on the xio short walk turned
 * upright: the split of the tilt into yaw and
 * roll turns with the tilt's direction. */
static double g_upright_tilt_deg = 0.05, g_upright_noise = 0.001;
static fnav_sample_t upright(long k)
{
    const double e = g_upright_tilt_deg * 3.14159265358979 / 180.0, a = k < 1000 ? 0.0 : 0.5 * 3.14159265358979;
    fnav_sample_t s = still(k);
    s.accel_mps2[0] = (fnav_real_t)(k_g * cos(e) + g_upright_noise * ((k % 5) - 2));
    s.accel_mps2[1] = (fnav_real_t)(k_g * sin(e) * cos(a) + g_upright_noise * ((k % 3) - 1));
    s.accel_mps2[2] = (fnav_real_t)(k_g * sin(e) * sin(a));
    s.gyro_rps[0] = (fnav_real_t)(k < 1000 ? 0.002 : 0.004);
    if ((k >= 2000 && k < 2080) || (k >= 2400 && k < 2480)) {
        s.gyro_rps[1] = FNAV_R(2.0);
        s.accel_mps2[2] = FNAV_R(1.0);
    }
    return s;
}

static double level_axis_heading(const fnav_nav_frame_t *fr)
{
    fnav_mat3_t c = fnav_quat_to_dcm(fnav_quat_from_euler(fr->euler_rad[0], fr->euler_rad[1], fr->euler_rad[2]));
    return atan2((double)c.m[1][2], (double)c.m[0][2]);
}

static void test_realign_x_vertical(void **state)
{
    static fnav_nav_t nav;
    fnav_nav_config_t c = fnav_nav_config_default;
    fnav_nav_frame_t fr;
    double h_before = 0.0, h_at = 10.0, pitch_before = 0.0, d;
    long k;
    (void)state;
    c.stance.rate_hz = FNAV_R(200.0);
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    for (k = 0; k < 2200; k++) {
        fnav_sample_t s = upright(k);
        assert_int_equal(fnav_nav_push(&nav, &s), FNAV_OK);
        while (fnav_nav_pop(&nav, &fr) == FNAV_OK) {
            if ((long)fr.seq == 1990) {
                h_before = level_axis_heading(&fr);
                pitch_before = (double)fr.euler_rad[1];
            }
            if ((long)fr.seq == 2000) {
                h_at = level_axis_heading(&fr);
            }
        }
    }
    assert_int_equal(nav.stats.realigned, 1u);
    assert_true(pitch_before > 1.56); /* within 0.6 deg of 90 */
    d = fmod(h_at - h_before + 3.0 * 3.14159265358979, 2.0 * 3.14159265358979) - 3.14159265358979;
    fprintf(stderr, "x vertical: pitch %.3f deg, level axis heading %.4f -> %.4f rad over the renewal\n",
            pitch_before * 57.29577951308232, h_before, h_at);
    assert_true(fabs(d) < 0.01);
}

/* The same renewal closer to the lock: tilted by 1e-4 deg, without noise.
 * The heading held is the filter's own attitude (its level axis, from
 * q_nb, not from the frame's Euler angles, which lose it there: in float32
 * the ZYX angles of a pose 1e-4 deg from pitch 90 deg give back an attitude
 * 10 deg off, and holding that would turn the heading by 0.0046 rad here;
 * 7e-5 rad with the filter's attitude). */
static void test_realign_near_lock(void **state)
{
    static fnav_nav_t nav;
    fnav_nav_config_t c = fnav_nav_config_default;
    fnav_nav_frame_t fr;
    double h_before = 0.0, h_at = 10.0, d;
    fnav_mat3_t m;
    long k;
    (void)state;
    g_upright_tilt_deg = -1.0e-4;
    g_upright_noise = 0.0;
    c.stance.rate_hz = FNAV_R(200.0);
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    for (k = 0; k < 2200; k++) {
        fnav_sample_t s = upright(k);
        assert_int_equal(fnav_nav_push(&nav, &s), FNAV_OK);
        while (fnav_nav_pop(&nav, &fr) == FNAV_OK) {
            if ((long)fr.seq == 1990 || (long)fr.seq == 2000) {
                m = fnav_quat_to_dcm(nav.ukf.q_nb); /* the state of this frame */
                *((long)fr.seq == 1990 ? &h_before : &h_at) = atan2((double)m.m[1][2], (double)m.m[0][2]);
            }
        }
    }
    g_upright_tilt_deg = 0.05;
    g_upright_noise = 0.001;
    assert_int_equal(nav.stats.realigned, 1u);
    d = fmod(h_at - h_before + 3.0 * 3.14159265358979, 2.0 * 3.14159265358979) - 3.14159265358979;
    fprintf(stderr, "x vertical 1e-4 deg from the lock: level axis heading %.5f -> %.5f rad over the renewal\n", h_before,
            h_at);
    assert_true(fabs(d) < 1.0e-3);
}

/* A time jump inside a still period ends it: the motion, and so the
 * stillness, inside the jump is unknown. 0.3 s still, a 6 s jump, then 6 s
 * still at 200 Hz: the alignment is the 5 s (max_still_s) after the jump,
 * not 6.3 s "still" completed at the first sample after it from 61
 * samples. */
static void test_align_time_jump(void **state)
{
    static fnav_nav_t nav;
    fnav_nav_config_t c = fnav_nav_config_default;
    fnav_nav_frame_t fr;
    double first_aligned_s = -1.0;
    long k;
    (void)state;
    c.stance.rate_hz = FNAV_R(200.0);
    c.realign_min_s = FNAV_R(0.0);
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    for (k = 0; k < 60 + 1200; k++) {
        fnav_sample_t s = still(k);
        if (k >= 60) {
            s.t_ns += (int64_t)6000000000; /* the jump, between samples 59 and 60 */
        }
        assert_int_equal(fnav_nav_push(&nav, &s), FNAV_OK);
        while (fnav_nav_pop(&nav, &fr) == FNAV_OK) {
            if ((fr.flags & FNAV_FRAME_ALIGNED) != 0u && first_aligned_s < 0.0) {
                first_aligned_s = 1e-9 * (double)fr.t_ns;
            }
        }
    }
    fnav_nav_finish(&nav);
    while (fnav_nav_pop(&nav, &fr) == FNAV_OK) {
        if ((fr.flags & FNAV_FRAME_ALIGNED) != 0u && first_aligned_s < 0.0) {
            first_aligned_s = 1e-9 * (double)fr.t_ns;
        }
    }
    assert_true(nav.aligned);
    assert_int_equal(nav.stats.time_jumps, 1u);
    assert_true((double)nav.align.result.duration_s > 4.9 && (double)nav.align.result.duration_s <= 5.0 + 1e-6);
    assert_true(first_aligned_s > 6.3 + 4.9);
}

/* One corrupted time stamp far ahead (a bit flip in a sensor's own timer,
 * here +1 h at sample 300 of a still foot at 200 Hz) must not end the run
 * (every later sample "going backwards" against it, rejected with
 * FNAV_E_TIME, and no frame for the rest of the run: 299 of 299
 * rejected). FNAV_NAV_TIME_RESYNC consecutive samples behind the last accepted one
 * are a new timeline: the first FNAV_NAV_TIME_RESYNC - 1 are rejected and
 * counted, the next is accepted, and the interval back to it is a time jump
 * (integrated as one nominal interval), as the glitch's own is. A single
 * sample behind is still rejected (test_stream_contract). */
/* A log whose only still period is at its very end: 1 s of swing, then a
 * still tail of n samples at 200 Hz. Run to FNAV_END; *pre is the length of
 * the trailing still run (the detector's stance frames) popped before
 * fnav_nav_finish, *run its whole length, *first_aligned its position (0
 * based) of the first aligned frame (-1: none), *zupts the aligned frames
 * with a ZUPT; returns the last frame. */
static fnav_nav_frame_t end_still_run(fnav_nav_t *nav, long n, long *pre, long *run, long *first_aligned,
                                      long *zupts)
{
    fnav_nav_config_t c = fnav_nav_config_default;
    fnav_nav_frame_t fr;
    long k;
    int finished = 0;
    memset(&fr, 0, sizeof fr);
    c.stance.rate_hz = FNAV_R(200.0);
    assert_int_equal(fnav_nav_init(nav, &c), FNAV_OK);
    *pre = *run = *zupts = 0;
    *first_aligned = -1;
    for (k = 0; k <= 200 + n; k++) {
        fnav_status_t st;
        if (k < 200 + n) {
            fnav_sample_t s = still(k);
            if (k < 200) {
                swing(&s);
            }
            assert_int_equal(fnav_nav_push(nav, &s), FNAV_OK);
        } else {
            fnav_nav_finish(nav);
            finished = 1;
        }
        while ((st = fnav_nav_pop(nav, &fr)) == FNAV_OK) {
            *run = (fr.flags & FNAV_FRAME_STANCE) ? *run + 1 : 0;
            *pre = finished ? *pre : *run;
            if ((fr.flags & FNAV_FRAME_ALIGNED) && *first_aligned < 0) {
                *first_aligned = *run - 1;
            }
            *zupts += (fr.flags & FNAV_FRAME_ZUPT) != 0u;
        }
        assert_int_equal(st, finished ? FNAV_END : FNAV_AGAIN);
    }
    return fr;
}

/* The end of the input completes the alignment on the still period it ends
 * in (fnav_nav_finish). Done before the samples the detector holds back
 * (h + lag = 5 at 200 Hz) reach the alignment, a log ending with 44 still
 * samples (0.215 s, align_short_s is 0.2 s), the only still period, would
 * not align, its alignment having seen 40 of them (0.195 s). The held-back
 * samples go on to the alignment,
 * which completes at the first with which its still period qualifies (the
 * frames after it are navigated, as after an alignment at max_still_s).
 * With enough stillness before the held-back samples (43 + held) the
 * alignment is as it was: on the samples before them, all held-back frames
 * navigated; with 38 (0.185 s) nothing aligns. (With min_zupt_cycle 0,
 * the scaling off, 5 are held back: 44 and 48.) */
static void test_align_at_end(void **state)
{
    static fnav_nav_t nav;
    fnav_nav_frame_t fr;
    long pre, run, first, zupts;
    /* h 2 + lag 14 with the defaults at 200 Hz (fnav_nav.h, "Latency") */
    const long held = 16;
    (void)state;
    fr = end_still_run(&nav, 39 + held, &pre, &run, &first, &zupts);
    assert_int_equal(run - pre, held);
    assert_true(nav.aligned);
    assert_int_equal(nav.health & FNAV_HEALTH_NOT_ALIGNED, 0u);
    assert_true(fr.flags & FNAV_FRAME_ALIGNED);
    /* completed at the first sample at which the period reached
     * align_short_s, a held-back one, which it took in: that frame is
     * neither predicted nor updated, the later ones are. The period's
     * duration as fnav_align.c forms it, with one sample fewer, falls short
     * (41 samples, 0.2 s, in float64; in float32 40 intervals of 5 ms come
     * out below 0.2f, and it takes 42) */
    assert_true(first >= pre && first < run);
    assert_int_equal(nav.align.result.samples, first + 1);
    assert_true(nav.align.result.duration_s >= nav.cfg.align.short_still_s);
    assert_true((fnav_real_t)((int64_t)(first - 1) * 5000000) * FNAV_R(1.0e-9) < nav.cfg.align.short_still_s);
    assert_int_equal(zupts, run - first - 1);
    assert_true(zupts > 0);
    /* aligned on the still tail (with the swing's last sample, which the
     * detector's window marks as stance: a mean ax of about 1/42 m/s^2,
     * pitch 0.0024 rad), not on the swing (ax 1 m/s^2, pitch 0.1 rad) */
    assert_true(fabs((double)nav.align.result.euler_rad.v[0]) < 1e-3 &&
                fabs((double)nav.align.result.euler_rad.v[1]) < 0.01);

    /* enough before the held-back samples: aligned at fnav_nav_finish on
     * those popped before it, every held-back frame navigated */
    fr = end_still_run(&nav, 43 + held, &pre, &run, &first, &zupts);
    assert_int_equal(run - pre, held);
    assert_true(nav.aligned);
    assert_int_equal(nav.align.result.samples, pre);
    assert_int_equal(first, pre);
    assert_int_equal(zupts, held);

    /* too short even with the held-back samples: not aligned */
    fr = end_still_run(&nav, 38, &pre, &run, &first, &zupts);
    assert_int_equal(run - pre, held);
    assert_false(nav.aligned);
    assert_true(nav.health & FNAV_HEALTH_NOT_ALIGNED);
    assert_int_equal(first, -1);
    assert_false(fr.flags & FNAV_FRAME_ALIGNED);
}

static void test_time_glitch_forward(void **state)
{
    static fnav_nav_t nav;
    fnav_nav_config_t c = fnav_nav_config_default;
    fnav_nav_frame_t fr;
    long k, n = 1200, rejected = 0, frames = 0;
    int64_t t_last = -1;
    (void)state;
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    for (k = 0; k < n; k++) {
        fnav_sample_t s = still(k);
        fnav_status_t st;
        if (k == 300) {
            s.t_ns += (int64_t)3600 * 1000000000;
        }
        st = fnav_nav_push(&nav, &s);
        if (st == FNAV_E_TIME) {
            rejected++;
        } else {
            assert_int_equal(st, FNAV_OK);
        }
        while (fnav_nav_pop(&nav, &fr) == FNAV_OK) {
            frames++;
            t_last = fr.t_ns;
        }
    }
    fnav_nav_finish(&nav);
    while (fnav_nav_pop(&nav, &fr) == FNAV_OK) {
        frames++;
        t_last = fr.t_ns;
    }
    assert_int_equal(rejected, (long)FNAV_NAV_TIME_RESYNC - 1);
    assert_int_equal(nav.stats.time_back, FNAV_NAV_TIME_RESYNC - 1u);
    assert_int_equal(frames, n - rejected);
    assert_int_equal(nav.stats.frames, (uint32_t)(n - rejected));
    assert_true(t_last == still(n - 1).t_ns);
    assert_int_equal(nav.stats.time_jumps, 2u); /* forward to the glitch, back from it */
    assert_true((nav.health & (FNAV_HEALTH_TIME_BACK | FNAV_HEALTH_TIME_JUMP)) ==
                (FNAV_HEALTH_TIME_BACK | FNAV_HEALTH_TIME_JUMP));
    /* the foot stood still throughout: aligned and at the origin */
    assert_true(nav.aligned);
    assert_true((fr.flags & FNAV_FRAME_ZUPT) != 0u);
    assert_true(fabs((double)fr.pos_m[0]) < 1e-3 && fabs((double)fr.pos_m[1]) < 1e-3 &&
                fabs((double)fr.pos_m[2]) < 1e-3);
}

/* A renewal on a still frame: a foot that stands 11 s. The alignment
 * completes at 5 s (max_still_s) and the renewal's still period, starting
 * at the next sample, reaches max_still_s about 5 s later while the foot
 * still stands: the filter restarts at that stance frame on the still
 * samples before it, as at the first alignment, so that frame is neither
 * predicted nor updated. Its position variance is exactly the start value,
 * max(held variance, 0.001^2 m^2) (fnav_nav.c start_filter): a prediction
 * over the frame's interval would add to it. */
static void test_realign_still_frame(void **state)
{
    static fnav_nav_t nav;
    fnav_nav_config_t c = fnav_nav_config_default;
    fnav_nav_frame_t fr, prev;
    const fnav_real_t start_var = FNAV_R(0.001) * FNAV_R(0.001); /* start_filter's sd.pos_m^2 */
    long k;
    int renewals = 0, have_prev = 0;
    (void)state;
    c.stance.rate_hz = FNAV_R(200.0);
    assert_true(c.realign_min_s > FNAV_R(0.0) && c.realign_min_s <= c.align.max_still_s);
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    memset(&prev, 0, sizeof prev);
    for (k = 0; k < 2200; k++) {
        fnav_sample_t s = renew_walk(k); /* still up to 10 s (sample 2000) */
        if (k >= 2000) {
            s = still(k);
            s.gyro_rps[2] = FNAV_R(0.004);
        }
        assert_int_equal(fnav_nav_push(&nav, &s), FNAV_OK);
        while (fnav_nav_pop(&nav, &fr) == FNAV_OK) {
            if ((int)nav.stats.realigned > renewals) {
                int i;
                renewals = (int)nav.stats.realigned;
                assert_true(have_prev && (prev.flags & FNAV_FRAME_ALIGNED) != 0u);
                assert_true(fr.flags & FNAV_FRAME_STANCE);
                assert_false(fr.flags & FNAV_FRAME_ZUPT);
                for (i = 0; i < 3; i++) {
                    fnav_real_t held = prev.p_diag[6 + i];
                    fnav_real_t expect = held > start_var ? held : start_var;
                    assert_true(fr.p_diag[6 + i] == expect);
                }
            }
            prev = fr;
            have_prev = 1;
        }
    }
    assert_int_equal(renewals, 1);
    assert_true(nav.stats.strides == 0u);
}

/* Memory: the filter object within 8 KB in float32 (the issue's limit). */
static void test_sizes(void **state)
{
    (void)state;
    fprintf(stderr, "sizeof: fnav_nav_t %zu, fnav_ukf_t %zu, fnav_stance_t %zu, fnav_align_t %zu bytes\n",
            sizeof(fnav_nav_t), sizeof(fnav_ukf_t), sizeof(fnav_stance_t), sizeof(fnav_align_t));
#if !FNAV_USE_DOUBLE
    assert_true(sizeof(fnav_ukf_t) <= 8192);
#endif
}

/* ------------------------------------------------------------ resampler */

/* The --rate resampler: a 10 Hz sine at 400 Hz passes to 100 Hz with its
 * amplitude (within 1 %), an 80 Hz sine (above the new Nyquist rate, it
 * would alias to 20 Hz) is removed (below 1 %), duplicates are dropped and
 * counted, and upsampling is refused. */
/* An input log of n zeroed samples for the resampler's tests. */
static void log_alloc(hx_log_t *in, size_t n)
{
    memset(in, 0, sizeof *in);
    in->t_ns = (int64_t *)calloc(n, sizeof *in->t_ns);
    in->seq = (uint32_t *)calloc(n, sizeof *in->seq);
    in->acc = (double(*)[3])calloc(n, sizeof *in->acc);
    in->gyr = (double(*)[3])calloc(n, sizeof *in->gyr);
    in->temp = (double *)calloc(n, sizeof *in->temp);
    assert_true(in->t_ns && in->seq && in->acc && in->gyr && in->temp);
}

/* The summary's stance mid-points: the middle of the detector's stance in
 * each segmented phase, not of the segmented phase (which lags the detector
 * by the segmentation's hysteresis) and not before the alignment. */
static void test_stance_mids(void **state)
{
    static fnav_nav_frame_t fr[400];
    hx_traj_t t;
    size_t mid[4], n, i;
    (void)state;
    memset(fr, 0, sizeof fr);
    memset(&t, 0, sizeof t);
    for (i = 0; i < 400; i++) {
        fr[i].t_ns = (int64_t)i * 5000000;
        fr[i].flags |= (i < 100 || (i >= 200 && i < 300)) ? FNAV_FRAME_STANCE : 0u; /* detector */
        fr[i].flags |= ((i >= 10 && i < 150) || (i >= 210 && i < 350)) ? FNAV_FRAME_SEG_STANCE : 0u;
        fr[i].flags |= i >= 90 ? FNAV_FRAME_ALIGNED : 0u;
    }
    fr[250].flags &= ~FNAV_FRAME_STANCE; /* a one-frame flicker inside a stance changes nothing */
    t.n = 400;
    t.f = fr;
    n = hx_nav_stance_mids(&t, mid, 4);
    assert_int_equal(n, 2);
    /* first phase: aligned from 90, the detector's stance ends at 99; the
     * segmented phase's middle, (90 + 149) / 2 = 119, lies in the swing */
    assert_int_equal(mid[0], 94);
    /* second: the detector's run 200..299 (the phase began at 210) */
    assert_int_equal(mid[1], 249);
}

static void test_resampler(void **state)
{
    hx_log_t in, out;
    size_t n = 4000, i;
    long dups = 0;
    double fs = 0.0, a10 = 0.0, a80 = 0.0;
    char err[320];
    (void)state;
    log_alloc(&in, n + 1);
    for (i = 0; i < n; i++) {
        double t = (double)i / 400.0;
        in.t_ns[i] = (int64_t)llround(t * 1e9);
        in.acc[i][0] = sin(2.0 * 3.14159265358979 * 10.0 * t);
        in.gyr[i][0] = sin(2.0 * 3.14159265358979 * 80.0 * t);
    }
    /* one exact duplicate */
    memmove(&in.t_ns[1001], &in.t_ns[1000], (n - 1000) * sizeof *in.t_ns);
    memmove(&in.acc[1001], &in.acc[1000], (n - 1000) * sizeof *in.acc);
    memmove(&in.gyr[1001], &in.gyr[1000], (n - 1000) * sizeof *in.gyr);
    in.n = n + 1;
    assert_int_equal(hx_nav_resample(&in, 100.0, 0.5, &out, &dups, &fs, err, sizeof err), 0);
    assert_int_equal(dups, 1);
    FNAV_ASSERT_CLOSE(fs, 400.0, 0.0, 1e-9);
    FNAV_ASSERT_CLOSE((double)out.n, 1000.0, 1.0, 0.0);
    FNAV_ASSERT_CLOSE((double)(out.t_ns[1] - out.t_ns[0]), 1e7, 1.0, 0.0);
    /* amplitudes sqrt(2) x RMS over 800 output samples (80 cycles of 10 Hz)
     * away from the edges (the filter is 161 input samples long) */
    for (i = 100; i < 900; i++) {
        a10 += out.acc[i][0] * out.acc[i][0];
        a80 += out.gyr[i][0] * out.gyr[i][0];
    }
    a10 = sqrt(2.0 * a10 / 800.0);
    a80 = sqrt(2.0 * a80 / 800.0);
    /* the Blackman window's pass-band ripple and stop-band leakage are about
     * 2e-4 (-74 dB); measured 2.0e-6 off at 10 Hz and 6.3e-6 left of 80 Hz
     * (the tolerances were 1 %: 5000 and 1600 times what it does) */
    FNAV_ASSERT_CLOSE(a10, 1.0, 1e-3, 0.0);
    assert_true(a80 < 1e-3);
    hx_log_free(&out);
    assert_int_equal(hx_nav_resample(&in, 500.0, 0.5, &out, &dups, &fs, err, sizeof err), -1);
    assert_non_null(strstr(err, "only downsampling"));
    hx_log_free(&in);
}

/* A time jump in the input (100 s without samples, above max_gap_s)
 * splits the resampled log: no output instant falls inside it, the filter
 * does not reach across it (a constant on each side comes out exactly), and
 * the grid starts again at the first sample after it, so the navigator
 * still sees one interval above max_gap_s. A gap of lost samples below
 * max_gap_s (4 samples) is closed up: the grid runs through it. A grid
 * run through the jump too would make up 10,000 samples here, and 8.6
 * million for a day's pause. */
static void test_resampler_time_jump(void **state)
{
    hx_log_t in, out;
    size_t n = 4000, i, inside = 0;
    long dups = 0;
    double fs = 0.0;
    int64_t t_after = 0, longest = 0;
    char err[320];
    (void)state;
    log_alloc(&in, n);
    for (i = 0; i < n; i++) {
        /* 400 Hz; samples 1000-1003 lost; 100 s pause after sample 2000 */
        const size_t k = i < 1000 ? i : i + 4;
        in.t_ns[i] = (int64_t)k * 2500000 + (i > 2000 ? (int64_t)100000000000 : 0);
        in.acc[i][2] = i > 2000 ? -2.0 : -1.0;
    }
    t_after = in.t_ns[2001];
    in.n = n;
    assert_int_equal(hx_nav_resample(&in, 100.0, 0.5, &out, &dups, &fs, err, sizeof err), 0);
    FNAV_ASSERT_CLOSE(fs, 400.0, 0.0, 1e-9);
    /* 2001 samples and the 4 lost ones at 400 Hz, 0 .. 5.01 s: 502
     * instants; then 1999 samples, 4.995 s: 500 instants from t_after */
    assert_int_equal(out.n, 1002);
    for (i = 0; i < out.n; i++) {
        if (out.t_ns[i] > in.t_ns[2000] && out.t_ns[i] < t_after) {
            inside++;
        }
        if (i > 0 && out.t_ns[i] - out.t_ns[i - 1] > longest) {
            longest = out.t_ns[i] - out.t_ns[i - 1];
        }
        FNAV_ASSERT_CLOSE(out.acc[i][2], out.t_ns[i] >= t_after ? -2.0 : -1.0, 1e-12, 0.0);
    }
    assert_int_equal(inside, 0);
    assert_true(out.t_ns[502] == t_after);
    assert_true(longest > (int64_t)100000000000 - 10000000);
    for (i = 1; i <= 501; i++) {
        assert_true(out.t_ns[i] - out.t_ns[i - 1] == 10000000); /* the lost samples' gap closed up */
    }
    hx_log_free(&out);
    hx_log_free(&in);
}

/* The walk test of the units check, fed two ways: by stamps
 * (hx_walk_push, replay, info, simgap) and by a caller's own windows of
 * samples (hx_walk_window, allan's one-second windows): the same count.
 * 100 Hz: 5 s of swinging |f| (5 and 15 m/s^2 in turn: sd 5, every sample
 * off gravity), 5 s at rest, 5 s at rest with one tap a second (3 samples
 * of 25 m/s^2: sd 2.7, but 3 % of the samples off gravity, below the
 * tenth a walk needs). */
static void test_walk_window(void **state)
{
    hx_walk_t by_stamp, by_window;
    double s = 0.0, s2 = 0.0;
    long n = 0, off = 0;
    int i;
    (void)state;
    memset(&by_stamp, 0, sizeof by_stamp);
    memset(&by_window, 0, sizeof by_window);
    for (i = 0; i < 1501; i++) {
        const double f = i < 500 ? (i % 2 ? 15.0 : 5.0) : i >= 1000 && i % 100 < 3 ? 25.0 : 9.80665 + 0.001 * (i % 3);
        hx_walk_push(&by_stamp, (int64_t)i * 10000000, f); /* the 1501st sample closes the 15th second */
        if (i == 1500) {
            break;
        }
        s += f;
        s2 += f * f;
        off += hx_walk_off(f);
        if (++n == 100) {
            hx_walk_window(&by_window, n, s, s2, off);
            s = s2 = 0.0;
            n = off = 0;
        }
    }
    assert_int_equal(by_stamp.windows, 5);
    assert_int_equal(by_window.windows, 5);
    assert_true(hx_walk_seen(&by_window));
    assert_true(hx_walk_off(11.81) && !hx_walk_off(11.8) && hx_walk_off(7.8) && !hx_walk_off(9.8));
    /* fewer than 10 samples: no window counts */
    memset(&by_window, 0, sizeof by_window);
    hx_walk_window(&by_window, 9, 9.0 * 10.0, 9.0 * 125.0, 9);
    assert_int_equal(by_window.windows, 0);
}

/* Stamps in bursts: the filter takes the input as uniform at its median
 * rate, which is no sampling period here. 400 Hz in packets of 4 samples
 * stamped 5 us apart every 10 ms (200 kHz from the median interval), or
 * sharing one stamp (100 Hz from the distinct stamps): refused, naming the
 * rate over the span for --input-rate. Resampled (exit 0), the first would
 * smear seconds into each output, the second keep one sample of four. A
 * log that loses a third of its samples
 * in small gaps, or repeats a quarter of its stamps, is still resampled. */
static void test_resampler_bursts(void **state)
{
    hx_log_t in, out;
    size_t n = 4000, i;
    long dups = 0;
    double fs = 0.0;
    char err[512];
    int kind;
    (void)state;
    log_alloc(&in, n);
    in.n = n;
    for (kind = 0; kind < 4; kind++) {
        for (i = 0; i < n; i++) {
            switch (kind) {
            case 0: /* 4 samples 5 us apart every 10 ms */
                in.t_ns[i] = (int64_t)(i / 4u) * 10000000 + (int64_t)(i % 4u) * 5000;
                break;
            case 1: /* 4 samples to a stamp every 10 ms */
                in.t_ns[i] = (int64_t)(i / 4u) * 10000000;
                break;
            case 2: /* 400 Hz, one sample of three lost (gaps closed up) */
                in.t_ns[i] = (int64_t)(i + i / 2u) * 2500000;
                break;
            default: /* 400 Hz, one stamp of four repeated */
                in.t_ns[i] = (int64_t)(i - i / 4u) * 2500000;
                break;
            }
            in.acc[i][2] = -9.8;
        }
        err[0] = '\0';
        if (kind < 2) {
            assert_int_equal(hx_nav_resample(&in, 100.0, 0.5, &out, &dups, &fs, err, sizeof err), -1);
            assert_non_null(strstr(err, "--rate: the time stamps come in bursts"));
            assert_non_null(strstr(err, kind == 0 ? "gives 200000 Hz" : "gives 100 Hz"));
            assert_non_null(strstr(err, kind == 0 ? "stamped close together" : "share one stamp"));
            /* the rate of the whole packets (2 to 1000: 3992 samples over
             * 9.98 s), not the samples over the span (400.3) */
            assert_non_null(strstr(err, "4000 samples span 9.99 s, 400 Hz"));
            assert_non_null(strstr(err, "give --input-rate 400 ("));
        } else {
            assert_int_equal(hx_nav_resample(&in, 100.0, 0.5, &out, &dups, &fs, err, sizeof err), 0);
            FNAV_ASSERT_CLOSE(fs, 400.0, 0.0, 1e-9);
            hx_log_free(&out);
        }
    }
    hx_log_free(&in);
}

/* A rate that is no integer fraction of the input's (250 -> 100 Hz, like
 * openshoe_gx2 in the rate experiment): the output instants fall between
 * input samples. A 30 Hz tone, inside the pass band, keeps its amplitude
 * and phase: the error against the tone at the output instants is below
 * 0.1 % of the amplitude (RMS). The filtered signal interpolated linearly
 * between the input samples would be 3.4 % off the amplitude, 5 % error
 * (40 Hz: 7 % and 9 %). */
static void test_resampler_fractional(void **state)
{
    hx_log_t in, out;
    size_t n = 5000, i;
    long dups = 0;
    double fs = 0.0, a = 0.0, e = 0.0;
    const double w = 2.0 * 3.14159265358979 * 30.0;
    char err[320];
    (void)state;
    log_alloc(&in, n);
    for (i = 0; i < n; i++) {
        double t = (double)i / 250.0;
        in.t_ns[i] = (int64_t)llround(t * 1e9);
        in.acc[i][2] = sin(w * t + 0.3);
        in.gyr[i][1] = 1.0; /* DC: unit gain */
    }
    in.n = n;
    assert_int_equal(hx_nav_resample(&in, 100.0, 0.5, &out, &dups, &fs, err, sizeof err), 0);
    assert_int_equal(dups, 0);
    FNAV_ASSERT_CLOSE((double)out.n, 2000.0, 1.0, 0.0);
    /* away from the edges (the filter spans 101 input samples, 41 output) */
    for (i = 100; i < 1900; i++) {
        double t = 1e-9 * (double)(out.t_ns[i] - out.t_ns[0]);
        double d = out.acc[i][2] - sin(w * t + 0.3);
        a += out.acc[i][2] * out.acc[i][2];
        e += d * d;
        FNAV_ASSERT_CLOSE(out.gyr[i][1], 1.0, 1e-9, 0.0);
    }
    a = sqrt(2.0 * a / 1800.0);
    e = sqrt(2.0 * e / 1800.0);
    /* 30 Hz lies in the pass band (edge ~0.385 x 100 Hz): measured 6.5e-5 off
     * in amplitude and RMS error; 1e-3, the window's ripple with margin (the
     * tolerances were 0.5 %, 77 times the error) */
    FNAV_ASSERT_CLOSE(a, 1.0, 1e-3, 0.0);
    assert_true(e < 1e-3);
    /* the edges too keep unit DC gain (renormalised partial window) */
    FNAV_ASSERT_CLOSE(out.gyr[0][1], 1.0, 1e-9, 0.0);
    FNAV_ASSERT_CLOSE(out.gyr[out.n - 1][1], 1.0, 1e-9, 0.0);
    hx_log_free(&out);
    hx_log_free(&in);
}

/* ------------------------------------------------------------ golden */

/* One trajectory row against its golden row: fields printed as %.6f must
 * agree to 2e-6, fields printed as %.4e to 2e-4 relative. */
static int compare_fields(const char *lg, const char *lr, long row, char *why, size_t why_size)
{
    const char *pg = lg, *pr = lr;
    int col = 0;
    while (*pr != '\0' && *pr != '\n') {
        char *eg, *er;
        double vg = strtod(pg, &eg), vr = strtod(pr, &er);
        int sci = memchr(pr, 'e', (size_t)(er - pr)) != NULL;
        double tol = sci ? 2e-4 * fabs(vr) + 1e-30 : 2e-6;
        if (eg == pg || er == pr || fabs(vg - vr) > tol) {
            snprintf(why, why_size, "row %ld (t = %.6f) column %d: %.9g vs golden %.9g", row, atof(lr), col + 1, vg,
                     vr);
            return -1;
        }
        pg = (*eg == ',') ? eg + 1 : eg;
        pr = (*er == ',') ? er + 1 : er;
        col++;
    }
    return 0;
}

/* Compare a replay's trajectory CSV with its golden file, which keeps rows
 * 0, 25, 50, ... and the last one (make_golden.sh): those rows field by
 * field, and the row count (a frame added or lost anywhere moves the rows
 * kept, and rows after the golden last one or a golden row past the
 * replay's end are changes too): any change of the computation shows. */
static int compare_rows(const char *got_path, const char *ref_path, char *why, size_t why_size)
{
    FILE *g = fopen(got_path, "r"), *r = fopen(ref_path, "r");
    static char lg[2048], lr[2048], tail[2048];
    long matched = 0, k = 0, tail_row = -1;
    int rc = 0;
    if (g == NULL || r == NULL) {
        snprintf(why, why_size, "cannot open %s or %s", got_path, ref_path);
        if (g) fclose(g);
        if (r) fclose(r);
        return -1;
    }
    if (fgets(lg, sizeof lg, g) == NULL || fgets(lr, sizeof lr, r) == NULL || strcmp(lg, lr) != 0) {
        snprintf(why, why_size, "header differs");
        fclose(g);
        fclose(r);
        return -1;
    }
    while (rc == 0 && fgets(lg, sizeof lg, g) != NULL) {
        if (k % 25 == 0) {
            if (fgets(lr, sizeof lr, r) == NULL) {
                snprintf(why, why_size, "the replay goes on after the last golden row (row %ld, t = %.6f)", k,
                         atof(lg));
                rc = -1;
            } else {
                rc = compare_fields(lg, lr, k, why, why_size);
                matched++;
                tail_row = -1;
            }
        } else {
            memcpy(tail, lg, sizeof tail);
            tail_row = k;
        }
        k++;
    }
    if (rc == 0 && tail_row >= 0) { /* the last row, kept apart */
        if (fgets(lr, sizeof lr, r) == NULL) {
            snprintf(why, why_size, "the replay goes on after the last golden row (row %ld, t = %.6f)", tail_row,
                     atof(tail));
            rc = -1;
        } else {
            rc = compare_fields(tail, lr, tail_row, why, why_size);
            matched++;
        }
    }
    if (rc == 0 && fgets(lr, sizeof lr, r) != NULL) {
        snprintf(why, why_size, "the replay ends (%ld rows) before the golden row at t = %.6f", k, atof(lr));
        rc = -1;
    }
    fclose(g);
    fclose(r);
    if (rc == 0 && matched < 10) {
        snprintf(why, why_size, "only %ld rows compared", matched);
        rc = -1;
    }
    return rc;
}

static void test_golden_replays(void **state)
{
    static const char *const names[3] = { "gx2_walk2", "xio_short", "square2" };
    int i;
    (void)state;
    for (i = 0; i < 3; i++) {
        char in[256], ref[256], rel[128], err[400], why[300], out[] = "/tmp/fnav_golden_XXXXXX";
        fnav_nav_config_t c = fnav_nav_config_default;
        FILE *f;
        int fd, rc;
        snprintf(rel, sizeof rel, "nav/golden/%s.csv", names[i]);
        if (fnav_vector_path(rel, in, sizeof in) != 0) {
            fail_msg("golden input %s missing (run from the repository root)", rel);
        }
        snprintf(rel, sizeof rel, "nav/golden/%s_traj_%s.csv", names[i], FNAV_USE_DOUBLE ? "double" : "float");
        assert_int_equal(fnav_vector_path(rel, ref, sizeof ref), 0);
        fd = mkstemp(out);
        assert_true(fd >= 0);
        f = fdopen(fd, "w");
        assert_non_null(f);
        rc = hx_nav_replay("test", in, HX_FMT_AUTO, 0.0, &c, 0.0, f, NULL, 0, err, sizeof err);
        fclose(f);
        assert_int_equal(rc, 0);
        if (compare_rows(out, ref, why, sizeof why) != 0) {
            remove(out);
            fail_msg("golden replay %s changed: %s (if intended: sh vectors/nav/make_golden.sh and commit the "
                     "reason)",
                     names[i], why);
        }
        remove(out);
    }
}

/* ------------------------------------------------------------ float vs double */

static void test_float_vs_double(void **state)
{
    char ref[256], line[512], path[600], err[400];
    FILE *f;
    int n = 0, skipped = 0;
    double worst = 0.0;
    (void)state;
    assert_int_equal(fnav_vector_path("nav/double_reference.csv", ref, sizeof ref), 0);
    f = fopen(ref, "r");
    assert_non_null(f);
    while (fgets(line, sizeof line, f) != NULL) {
        char walk[300];
        double dist, ex, ey, ez, tol, d;
        hx_traj_t t;
        hx_nav_summary_t s;
        fnav_nav_config_t c = fnav_nav_config_default;
        int rc;
        if (line[0] == '#' || strncmp(line, "walk,", 5) == 0) {
            continue;
        }
        if (sscanf(line, "%299[^,],%lf,%lf,%lf,%lf", walk, &dist, &ex, &ey, &ez) != 5) {
            /* a row this test cannot read was left out without a word (a
             * changed reference format passed with no walk compared) */
            fail_msg("double_reference.csv: unreadable row: %s", line);
        }
        if (fnav_testdata_path(walk, path, sizeof path) != 0) {
            fnav_test_skip_notice(walk); /* each missing walk named (they were left out without a word) */
            skipped++;
            continue;
        }
        rc = hx_nav_replay("test", path, HX_FMT_AUTO, 0.0, &c, 0.0, NULL, &t, 0, err, sizeof err);
        assert_true(rc == 0 || rc == 1); /* 1: a truncated last line */
        hx_nav_summarize(&t, &s);
        d = sqrt((s.end_pos_m[0] - ex) * (s.end_pos_m[0] - ex) + (s.end_pos_m[1] - ey) * (s.end_pos_m[1] - ey) +
                 (s.end_pos_m[2] - ez) * (s.end_pos_m[2] - ez));
        /* float32: 0.1 % of the distance travelled (1 cm for a walk whose
         * detector finds no steps); float64: the same code, 1e-9 relative */
#if FNAV_USE_DOUBLE
        tol = 1e-9 * (dist + 1.0);
#else
        tol = 0.001 * (dist > 10.0 ? dist : 10.0);
#endif
        if (!(d <= tol)) {
            fail_msg("%s: final position differs from the float64 reference by %.4f m (limit %.4f m, distance %.1f m)",
                     walk, d, tol, dist);
        }
        if (dist > 0.0 && d / dist > worst) {
            worst = d / dist;
        }
        hx_traj_free(&t);
        n++;
    }
    fclose(f);
    assert_true(n + skipped > 0); /* a reference without rows compares nothing */
    if (skipped > 0 && n == 0) {
        fnav_test_skip_notice("float vs double on the real walks");
        skip();
    }
    fprintf(stderr, "float%s vs float64 reference: %d walks, worst final-position difference %.4f %% of distance\n",
            FNAV_USE_DOUBLE ? "64" : "32", n, 100.0 * worst);
}

/* A time jump must be longer than a gap: with max_gap_s below the sample
 * interval every interval would be a time jump, integrated as one nominal
 * interval and restarting the alignment's still period, so the navigator
 * would never align (a 20 Hz still log, max_gap_s 0.04: 0 of 400 frames
 * aligned). Refused at init with a configured rate; with
 * an estimated one an interval is a jump only beyond 1.5 nominal intervals
 * too. */
/* The stamps' range ends: -FNAV_T_NS_MAX and +FNAV_T_NS_MAX are both
 * accepted, so their difference must fit int64_t (with 2^62 it would be
 * 2^63: signed overflow in the navigator, the detector and the alignment,
 * and the jump read as a negative interval, neither counted nor seen). The
 * interval between them is one time jump of
 * 2 FNAV_T_NS_MAX ns; one nanosecond beyond either end is refused. */
static void test_stamp_range_ends(void **state)
{
    static fnav_nav_t nav;
    fnav_nav_frame_t fr;
    fnav_sample_t s;
    int frames = 0;
    fnav_nav_config_t c = fnav_nav_config_default;
    (void)state;
    c.stance.rate_hz = FNAV_R(200.0); /* a gap is judged against the rate */
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    s = still(0);
    s.t_ns = -FNAV_T_NS_MAX - 1;
    assert_int_equal(fnav_nav_push(&nav, &s), FNAV_E_RANGE);
    s.t_ns = -FNAV_T_NS_MAX; /* the two ends, one after the other */
    assert_int_equal(fnav_nav_push(&nav, &s), FNAV_OK);
    s = still(1);
    s.t_ns = FNAV_T_NS_MAX;
    assert_int_equal(fnav_nav_push(&nav, &s), FNAV_OK);
    s = still(2);
    s.t_ns = FNAV_T_NS_MAX;
    s.t_ns++;
    assert_int_equal(fnav_nav_push(&nav, &s), FNAV_E_RANGE);
    fnav_nav_finish(&nav);
    while (fnav_nav_pop(&nav, &fr) == FNAV_OK) {
        frames++;
    }
    assert_int_equal(frames, 2);
    assert_int_equal(nav.stats.time_jumps, 1);
    assert_true((double)nav.stats.max_gap_seen_s > 9.2e9); /* 2 (2^62 - 1) ns = 9.22e9 s */
    assert_int_equal(nav.stats.range_inputs, 2);
}

static void test_max_gap_below_interval(void **state)
{
    static fnav_nav_t nav;
    fnav_nav_config_t c = fnav_nav_config_default;
    fnav_nav_frame_t fr;
    long k, aligned = 0;
    (void)state;
    c.max_gap_s = FNAV_R(0.04);
    c.stance.rate_hz = FNAV_R(20.0);
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_E_CONFIG);
    c.stance.rate_hz = FNAV_R(40.0); /* 1.5 intervals: 0.0375 s */
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    c.stance.rate_hz = FNAV_R(0.0);
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    for (k = 0; k < 400; k++) {
        fnav_sample_t s = still(k);
        s.t_ns = (int64_t)k * 50000000; /* 20 Hz */
        assert_int_equal(fnav_nav_push(&nav, &s), FNAV_OK);
        while (fnav_nav_pop(&nav, &fr) == FNAV_OK) {
            aligned += (fr.flags & FNAV_FRAME_ALIGNED) != 0u;
        }
    }
    assert_int_equal(nav.stats.time_jumps, 0u);
    assert_int_equal(nav.stats.gaps, 0u);
    assert_true(aligned > 250);
    /* a real jump is still one */
    {
        fnav_sample_t s = still(400);
        s.t_ns = (int64_t)399 * 50000000 + (int64_t)2000000000;
        assert_int_equal(fnav_nav_push(&nav, &s), FNAV_OK);
        fnav_nav_finish(&nav);
        while (fnav_nav_pop(&nav, &fr) == FNAV_OK) {
        }
        assert_int_equal(nav.stats.time_jumps, 1u);
    }
}

/* ------------------------------------------------------------ summary notes */

/* hx_sat: a channel is saturated with at least two runs of two or more
 * samples at its extreme (hx_nav.h, docs/harness.md "info"); one run is a
 * natural maximum. After a still second (HX_SAT_BLOCK samples alternating
 * +-0.001: the noise at rest 0.001), a run of two at +5 and another: 4
 * samples at the maximum and 1 at the minimum (-1), the count of both
 * extremes (hx_sat_count) 5, counted by hand; without the second run, 0. */
/* hx_sat_count of channel ax after n_still samples alternating +-0.001,
 * then the values v, at 1 ms steps */
static long sat_count_of(size_t n_still, const double *v, size_t n)
{
    hx_sat_t st;
    fnav_sample_t s;
    size_t k;
    memset(&st, 0, sizeof st);
    memset(&s, 0, sizeof s);
    for (k = 0; k < n_still + n; k++) {
        s.t_ns = (int64_t)k * 1000000;
        s.accel_mps2[0] = (fnav_real_t)(k < n_still ? (k % 2 == 0 ? 0.001 : -0.001) : v[k - n_still]);
        hx_sat_push(&st, &s);
    }
    return hx_sat_count(&st, 0);
}

static void test_sat_two_runs(void **state)
{
    static const double k_one[] = { -1.0, 5.0, 5.0, 1.0, 2.0, 1.0, 0.0 };
    static const double k_two[] = { -1.0, 5.0, 5.0, 1.0, 2.0, 5.0, 5.0, 0.0 };
    (void)state;
    assert_int_equal(sat_count_of(HX_SAT_BLOCK, k_one, sizeof k_one / sizeof k_one[0]), 0);
    assert_int_equal(sat_count_of(HX_SAT_BLOCK, k_two, sizeof k_two / sizeof k_two[0]), 5);
}

/* A still, quantised channel is not clipped: values of 0.001 steps within
 * +-2 steps, with a run of two at +3 and one at -3 steps, span 6 steps,
 * within HX_SAT_SPAN_NOISE times the noise at rest (at least the step): 0,
 * where the flat tops alone said 4. The same runs at +-0.5, 500 steps
 * apart, are clipping: 4. */
static void test_sat_still_quantised(void **state)
{
    double v[200];
    size_t k;
    (void)state;
    for (k = 0; k < 200; k++) {
        v[k] = 0.001 * (double)((long)((k * 7u) % 5u) - 2);
    }
    v[50] = v[51] = 0.003;
    v[150] = v[151] = -0.003;
    assert_int_equal(sat_count_of(0, v, 200), 0);
    v[50] = v[51] = 0.5;
    v[150] = v[151] = -0.5;
    assert_int_equal(sat_count_of(0, v, 200), 4);
    /* fewer samples than a block: the noise of those there (the +-0.5
     * runs put back to the still values first) */
    v[50] = v[51] = 0.0;
    v[45] = v[46] = 0.003;
    v[55] = v[56] = -0.003;
    assert_int_equal(sat_count_of(0, v + 40, 20), 0);
}

/* A channel that never rests (no block of HX_SAT_BLOCK samples within
 * HX_SAT_REST_SD_ACCEL): its flat tops are judged alone, its motion taken
 * for no noise. A swing of +-30 m/s^2 clipped at +-20: runs of two at each
 * extreme in every period, 40 samples at them; the same swing with its
 * first 64 samples still (a block at rest) is clipped too; fewer samples
 * than a block, moving: clipped. */
static void test_sat_never_rests(void **state)
{
    double v[256];
    size_t k;
    (void)state;
    for (k = 0; k < 256; k++) {
        v[k] = 30.0 * sin(2.0 * 3.14159265358979 * (double)k / 25.6);
        v[k] = v[k] > 20.0 ? 20.0 : v[k] < -20.0 ? -20.0 : v[k];
    }
    assert_true(sat_count_of(0, v, 256) > 0);
    assert_true(sat_count_of(HX_SAT_BLOCK, v, 256) > 0);
    assert_true(sat_count_of(0, v, 40) > 0);
}

/* The notes' thresholds at their edges as hx_nav.h words them: "little
 * motion" is more than 10 s, over 90 % in stance and fewer than three
 * strides; "gappy" is a loss that reaches 1 % of the motion time (1 s of
 * 100 s exactly: 0.01 x 100.0 rounds to 1.0). */
static void test_note_thresholds(void **state)
{
    hx_nav_summary_t s;
    (void)state;
    memset(&s, 0, sizeof s);
    s.duration_s = 60.0;
    s.stance_fraction = 0.95;
    s.strides = 2;
    assert_true(hx_nav_little_motion(&s));
    s.strides = 3;
    assert_false(hx_nav_little_motion(&s));
    s.strides = 2;
    s.duration_s = 10.0;
    assert_false(hx_nav_little_motion(&s));
    s.duration_s = 60.0;
    s.stance_fraction = 0.9;
    assert_false(hx_nav_little_motion(&s));
    s.motion_s = 100.0;
    s.gap_lost_s = 1.0;
    assert_true(hx_nav_gappy(&s));
    s.gap_lost_s = 0.999;
    assert_false(hx_nav_gappy(&s));
    s.motion_s = 0.0;
    s.gap_lost_s = 1.0;
    assert_false(hx_nav_gappy(&s));
}

/* The whole of a file into a NUL-terminated buffer (free it), NULL if unreadable. */
static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    char *buf = NULL;
    long n;
    if (f == NULL) {
        return NULL;
    }
    if (fseek(f, 0, SEEK_END) == 0 && (n = ftell(f)) >= 0 && fseek(f, 0, SEEK_SET) == 0 &&
        (buf = (char *)malloc((size_t)n + 1)) != NULL) {
        buf[fread(buf, 1, (size_t)n, f)] = '\0';
    }
    fclose(f);
    return buf;
}

/* The health counters of replay's and eval's JSON and summary, each under
 * its own name: one NaN and two out-of-range samples (a value, a stamp)
 * pushed into a still run give nan_rejected 1 and range_rejected 2. No log
 * brings a NaN to the navigator (each reader refuses NaN and out-of-range
 * values and stamps, and live's receiver skips them), and an out-of-range
 * value only through replay --rate, whose low-pass overshoots a swing
 * between -1e6 and 1e6: the two keys swapped pass every other test (a
 * mutation round). */
static void test_health_keys(void **state)
{
    static fnav_nav_t nav;
    fnav_nav_config_t c = fnav_nav_config_default;
    fnav_nav_frame_t fr;
    hx_traj_t t;
    hx_nav_summary_t s;
    fnav_sample_t bad;
    char json_path[] = "/tmp/fnav_health_XXXXXX", txt_path[] = "/tmp/fnav_health_txt_XXXXXX", err[256];
    char *text;
    cJSON *root, *h;
    FILE *f;
    long k;
    int fd;
    (void)state;
    memset(&t, 0, sizeof t);
    t.input_complete = -1; /* not said: no complete/error keys */
    t.cap = 400;
    t.f = (fnav_nav_frame_t *)malloc(t.cap * sizeof *t.f);
    assert_non_null(t.f);
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    for (k = 0; k < 300; k++) {
        fnav_sample_t smp = still(k);
        if (k == 150) {
            bad = still(k);
            bad.gyro_rps[0] = (fnav_real_t)NAN;
            assert_int_equal(fnav_nav_push(&nav, &bad), FNAV_E_NANINF);
            bad = still(k);
            bad.accel_mps2[2] = FNAV_R(2.0e6);
            assert_int_equal(fnav_nav_push(&nav, &bad), FNAV_E_RANGE);
            bad = still(k);
            bad.t_ns = FNAV_T_NS_MAX + 1;
            assert_int_equal(fnav_nav_push(&nav, &bad), FNAV_E_RANGE);
        }
        assert_int_equal(fnav_nav_push(&nav, &smp), FNAV_OK);
        while (fnav_nav_pop(&nav, &fr) == FNAV_OK) {
            assert_true(t.n < t.cap);
            t.f[t.n++] = fr;
        }
    }
    fnav_nav_finish(&nav);
    while (fnav_nav_pop(&nav, &fr) == FNAV_OK) {
        assert_true(t.n < t.cap);
        t.f[t.n++] = fr;
    }
    t.stats = nav.stats;
    t.rate_hz = (double)nav.stance.rate_hz;
    t.aligned = nav.aligned;
    hx_nav_summarize(&t, &s);

    fd = mkstemp(json_path);
    assert_true(fd >= 0);
    f = fdopen(fd, "w"); /* hx_nav_write_json writes it by name */
    assert_non_null(f);
    fclose(f);
    assert_int_equal(hx_nav_write_json(json_path, "still.csv", "test", &t, &s, NULL, err, sizeof err), 0);
    text = slurp(json_path);
    remove(json_path);
    assert_non_null(text);
    root = cJSON_Parse(text);
    free(text);
    assert_non_null(root);
    h = cJSON_GetObjectItemCaseSensitive(root, "health");
    assert_non_null(h);
    assert_true(cJSON_IsNumber(cJSON_GetObjectItemCaseSensitive(h, "nan_rejected")));
    assert_true(cJSON_IsNumber(cJSON_GetObjectItemCaseSensitive(h, "range_rejected")));
    assert_int_equal(cJSON_GetObjectItemCaseSensitive(h, "nan_rejected")->valueint, 1);
    assert_int_equal(cJSON_GetObjectItemCaseSensitive(h, "range_rejected")->valueint, 2);
    cJSON_Delete(root);

    fd = mkstemp(txt_path);
    assert_true(fd >= 0);
    f = fdopen(fd, "w");
    assert_non_null(f);
    hx_nav_print_summary(f, "still.csv", &t, &s);
    fclose(f);
    text = slurp(txt_path);
    remove(txt_path);
    assert_non_null(text);
    if (strstr(text, "1 NaN/Inf rejected, 2 out of range rejected") == NULL) {
        fail_msg("the summary's health line does not say 1 NaN/Inf and 2 out of range rejected:\n%s", text);
    }
    free(text);
    hx_traj_free(&t);
}

/* A long gap in motion is one longer than HX_NAV_LONG_GAP_S (docs/harness.md,
 * "replay": "gaps longer than 20 ms"): an interval of exactly 20 ms is not
 * one, 1 ns more is. The stamps are whole nanoseconds and 1e-9 x 20,000,000
 * is 0.020 exactly in double, so the edge is sharp. Frames at 400 Hz, all
 * aligned and in motion, with one interval of 20 ms or 20 ms + 1 ns among
 * them (>= in place of > passes every other test: a mutation round). */
static void test_long_gap_edge(void **state)
{
    static const int64_t k_gap_ns[2] = { 20000000, 20000001 };
    int g;
    (void)state;
    for (g = 0; g < 2; g++) {
        hx_traj_t t;
        hx_nav_summary_t s;
        size_t i;
        int64_t tn = 0;
        memset(&t, 0, sizeof t);
        t.n = t.cap = 800;
        t.f = (fnav_nav_frame_t *)calloc(t.cap, sizeof *t.f);
        assert_non_null(t.f);
        t.rate_hz = 400.0;
        t.max_gap_s = 0.5;
        t.aligned = 1;
        for (i = 0; i < t.n; i++) {
            t.f[i].t_ns = tn;
            t.f[i].seq = (uint32_t)i;
            t.f[i].flags = FNAV_FRAME_ALIGNED; /* no stance: every interval is motion */
            tn += i == 400 ? k_gap_ns[g] : 2500000;
        }
        hx_nav_summarize(&t, &s);
        assert_true(fabs(s.motion_s - (798 * 0.0025 + 1e-9 * (double)k_gap_ns[g])) < 1e-12);
        if (g == 0) {
            assert_int_equal(s.long_gaps, 0);
            assert_true(s.gap_lost_s == 0.0);
            assert_true(s.longest_motion_gap_s == 0.0);
        } else {
            assert_int_equal(s.long_gaps, 1);
            assert_true(fabs(s.gap_lost_s - (0.020000001 - 0.0025)) < 1e-12);
            assert_true(s.longest_motion_gap_s == 1e-9 * 20000001.0);
        }
        hx_traj_free(&t);
    }
}

/* The gait cycle behind the summary's "the gait cycles last" note
 * (hx_nav_strides_too_short): from one onset of the foot's motion to the
 * next. Frames at 200 Hz, the detector's stance flag in a pattern per
 * cycle: a slow walk (60 steps/min, `harness sim --motion walk --cadence
 * 60 --speed 0.5`: stance 0.72 s, then a swing the detector breaks with a
 * 15 ms stance in its middle) has 2 s cycles; were the blip to split each
 * cycle in two, the median would read 0.39 s and a normal slow walk be told
 * its time axis was compressed. A stance shorter than
 * HX_NAV_CYCLE_MOTION_S ends no motion; a compressed walk (0.25 s
 * cycles, stance 0.10 s) and a normal one (1.1 s) are judged as usual. */
static void test_gait_cycles(void **state)
{
    static const struct {
        int stance, motion, blip, motion2; /* frames at 200 Hz, in this order, per cycle */
        double cycle_s;
        int too_short;
    } k_cases[] = {
        { 143, 73, 3, 181, 2.0, 0 },  /* slow walk, a 15 ms stance blip mid-swing */
        { 120, 98, 0, 0, 1.09, 0 },   /* normal walk */
        { 20, 30, 0, 0, 0.25, 1 },    /* a compressed time axis */
        { 20, 14, 2, 14, 0.25, 1 },   /* compressed, with a blip in the swing */
    };
    size_t c;
    (void)state;
    for (c = 0; c < sizeof k_cases / sizeof k_cases[0]; c++) {
        const int per = k_cases[c].stance + k_cases[c].motion + k_cases[c].blip + k_cases[c].motion2;
        hx_traj_t t;
        hx_nav_summary_t s;
        size_t i;
        memset(&t, 0, sizeof t);
        t.n = t.cap = (size_t)(25 * per);
        t.f = (fnav_nav_frame_t *)calloc(t.cap, sizeof *t.f);
        assert_non_null(t.f);
        t.rate_hz = 200.0;
        t.max_gap_s = 0.5;
        t.aligned = 1;
        for (i = 0; i < t.n; i++) {
            const int k = (int)(i % (size_t)per);
            const int still = k < k_cases[c].stance ||
                              (k >= k_cases[c].stance + k_cases[c].motion &&
                               k < k_cases[c].stance + k_cases[c].motion + k_cases[c].blip);
            t.f[i].t_ns = (int64_t)i * 5000000;
            t.f[i].seq = (uint32_t)i;
            t.f[i].flags = FNAV_FRAME_ALIGNED | (still ? FNAV_FRAME_STANCE : 0u);
        }
        hx_nav_summarize(&t, &s);
        if (s.stride_intervals != 24 || fabs(s.median_stride_s - k_cases[c].cycle_s) > 1e-9 ||
            hx_nav_strides_too_short(&s) != k_cases[c].too_short) {
            fail_msg("case %zu: %ld cycles, median %.4f s (expected 24 of %.4f s), too short %d", c,
                     s.stride_intervals, s.median_stride_s, k_cases[c].cycle_s, hx_nav_strides_too_short(&s));
        }
        hx_traj_free(&t);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_default_stance_is_detector_default),
        cmocka_unit_test(test_config),
        cmocka_unit_test(test_config_ranges),
        cmocka_unit_test(test_first_frames),
        cmocka_unit_test(test_config_reaches_parts),
        cmocka_unit_test(test_stream_contract),
        cmocka_unit_test(test_push_after_finish),
        cmocka_unit_test(test_timing),
        cmocka_unit_test(test_step),
        cmocka_unit_test(test_run_port),
        cmocka_unit_test(test_not_initialised),
        cmocka_unit_test(test_reinit_own_config),
        cmocka_unit_test(test_frames_before_alignment),
        cmocka_unit_test(test_step_null_frame),
        cmocka_unit_test(test_run_after_finish),
        cmocka_unit_test(test_run_exits),
        cmocka_unit_test(test_units_not_checked),
        cmocka_unit_test(test_zaru_after),
        cmocka_unit_test(test_max_gap_below_interval),
        cmocka_unit_test(test_stamp_range_ends),
        cmocka_unit_test(test_settle_onsets),
        cmocka_unit_test(test_settle_not_at_alignment),
        cmocka_unit_test(test_settle_pending_reset),
        cmocka_unit_test(test_realign),
        cmocka_unit_test(test_realign_x_vertical),
        cmocka_unit_test(test_realign_near_lock),
        cmocka_unit_test(test_align_time_jump),
        cmocka_unit_test(test_align_at_end),
        cmocka_unit_test(test_time_glitch_forward),
        cmocka_unit_test(test_realign_still_frame),
        cmocka_unit_test(test_sizes),
        cmocka_unit_test(test_stance_mids),
        cmocka_unit_test(test_resampler),
        cmocka_unit_test(test_resampler_fractional),
        cmocka_unit_test(test_resampler_time_jump),
        cmocka_unit_test(test_resampler_bursts),
        cmocka_unit_test(test_walk_window),
        cmocka_unit_test(test_sat_two_runs),
        cmocka_unit_test(test_sat_still_quantised),
        cmocka_unit_test(test_sat_never_rests),
        cmocka_unit_test(test_note_thresholds),
        cmocka_unit_test(test_health_keys),
        cmocka_unit_test(test_long_gap_edge),
        cmocka_unit_test(test_gait_cycles),
        cmocka_unit_test(test_golden_replays),
        cmocka_unit_test(test_float_vs_double),
    };
    return cmocka_run_group_tests_name("nav", tests, NULL, NULL);
}
