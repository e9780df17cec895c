/* fnav_stance: configuration, window from the rate (configured and
 * estimated), the SHOE statistic against a direct computation in double,
 * the delay and flush contract, stance/swing boundaries of a synthetic step,
 * rejection of a short mid-swing dip, the adaptive threshold, the threshold
 * detector, gait events at known samples, and the ring contract. */
#include <limits.h>
#include <stdlib.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

#include <cmocka.h>

#include "footnav/fnav_port.h"
#include "footnav/fnav_stance.h"
#include "fnav_testdata.h"

#if FNAV_USE_DOUBLE
#define EPS 1e-15
#else
#define EPS 1.2e-7
#endif

static const double k_g = 9.80665;

static fnav_sample_t sample(long k, double rate, const double f[3], const double w[3])
{
    fnav_sample_t s;
    int i;
    memset(&s, 0, sizeof s);
    s.t_ns = (int64_t)llround((double)k * 1e9 / rate);
    s.seq = (uint32_t)k;
    for (i = 0; i < 3; i++) {
        s.accel_mps2[i] = (fnav_real_t)f[i];
        s.gyro_rps[i] = (fnav_real_t)w[i];
    }
    return s;
}

/* Deterministic pseudo-random numbers in [-1, 1]. */
static uint32_t g_lcg = 12345u;
static double jitter(void)
{
    g_lcg = g_lcg * 1664525u + 1013904223u;
    return (double)(g_lcg >> 8) / 8388608.0 - 1.0;
}

/* A detector never initialised (zeroed, as static storage is), or whose
 * only init failed: push and pop say FNAV_E_STATE and take nothing (pop
 * decided from the zeroed configuration, dividing by sigma_a 0). */
static void test_not_initialised(void **state)
{
    static fnav_stance_t st, copy;
    fnav_stance_config_t c = fnav_stance_config_default;
    fnav_sample_t s;
    fnav_stance_out_t out;
    (void)state;
    memset(&s, 0, sizeof s);
    s.accel_mps2[2] = FNAV_R(-9.81);
    c.window_s = FNAV_R(0.0);
    assert_int_equal(fnav_stance_init(&st, &c), FNAV_E_CONFIG);
    memset(&copy, 0, sizeof copy);
    assert_int_equal(fnav_stance_push(&st, &s), FNAV_E_STATE);
    assert_int_equal(fnav_stance_pop(&st, &out), FNAV_E_STATE);
    assert_memory_equal(&st, &copy, sizeof st);
    assert_int_equal(fnav_stance_init(&st, &fnav_stance_config_default), FNAV_OK);
    assert_int_equal(fnav_stance_push(&st, &s), FNAV_OK);
}

static void test_config(void **state)
{
    fnav_stance_t st;
    fnav_stance_config_t c = fnav_stance_config_default;
    (void)state;
    assert_int_equal(fnav_stance_init(NULL, &c), FNAV_E_ARG);
    assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
    c.window_s = FNAV_R(0.0);
    assert_int_equal(fnav_stance_init(&st, &c), FNAV_E_CONFIG);
    c = fnav_stance_config_default;
    c.gamma = (fnav_real_t)NAN;
    assert_int_equal(fnav_stance_init(&st, &c), FNAV_E_CONFIG);
    c = fnav_stance_config_default;
    c.rate_hz = FNAV_R(-1.0);
    assert_int_equal(fnav_stance_init(&st, &c), FNAV_E_CONFIG);
    c = fnav_stance_config_default;
    c.adapt_max_ratio = FNAV_R(0.5);
    assert_int_equal(fnav_stance_init(&st, &c), FNAV_E_CONFIG);
    c = fnav_stance_config_default;
    c.detector = (fnav_detector_t)7;
    assert_int_equal(fnav_stance_init(&st, &c), FNAV_E_CONFIG);
    /* every real field (make coverage: most of fnav_stance_init's checks
     * were never made): NaN and -Inf refused everywhere; a field that must
     * be positive refuses 0 and -1, one that may be 0 takes 0 and refuses
     * -1; adapt_max_ratio is at least 1; adaptive is 0 or 1 */
    {
        static const struct {
            size_t off;
            int zero_ok;
        } f[] = {
            { offsetof(fnav_stance_config_t, rate_hz), 1 },
            { offsetof(fnav_stance_config_t, window_s), 0 },
            { offsetof(fnav_stance_config_t, sigma_a_mps2), 0 },
            { offsetof(fnav_stance_config_t, sigma_g_rps), 0 },
            { offsetof(fnav_stance_config_t, gamma), 0 },
            { offsetof(fnav_stance_config_t, gyro_thresh_rps), 0 },
            { offsetof(fnav_stance_config_t, accel_thresh_mps2), 0 },
            { offsetof(fnav_stance_config_t, gravity_mps2), 0 },
            { offsetof(fnav_stance_config_t, floor_window_s), 0 },
            { offsetof(fnav_stance_config_t, margin_dec), 1 },
            { offsetof(fnav_stance_config_t, min_stance_s), 1 },
            { offsetof(fnav_stance_config_t, min_zupt_s), 1 },
            { offsetof(fnav_stance_config_t, min_swing_s), 1 },
            { offsetof(fnav_stance_config_t, event_window_s), 0 },
            { offsetof(fnav_stance_config_t, min_zupt_cycle), 1 },
        };
        size_t i;
        for (i = 0; i < sizeof f / sizeof f[0]; i++) {
            fnav_real_t *v = (fnav_real_t *)(void *)((char *)&c + f[i].off);
            c = fnav_stance_config_default;
            *v = (fnav_real_t)NAN;
            assert_int_equal(fnav_stance_init(&st, &c), FNAV_E_CONFIG);
            *v = -(fnav_real_t)INFINITY;
            assert_int_equal(fnav_stance_init(&st, &c), FNAV_E_CONFIG);
            *v = FNAV_R(-1.0);
            assert_int_equal(fnav_stance_init(&st, &c), FNAV_E_CONFIG);
            *v = FNAV_R(0.0);
            assert_int_equal(fnav_stance_init(&st, &c), f[i].zero_ok ? FNAV_OK : FNAV_E_CONFIG);
        }
        c = fnav_stance_config_default;
        c.adapt_max_ratio = (fnav_real_t)NAN;
        assert_int_equal(fnav_stance_init(&st, &c), FNAV_E_CONFIG);
        c.adapt_max_ratio = FNAV_R(1.0);
        assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
        c = fnav_stance_config_default;
        c.adaptive = 2;
        assert_int_equal(fnav_stance_init(&st, &c), FNAV_E_CONFIG);
        c.adaptive = -1;
        assert_int_equal(fnav_stance_init(&st, &c), FNAV_E_CONFIG);
        c.adaptive = 0;
        assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
        /* a fraction of the gait cycle: above 1 is no fraction */
        c = fnav_stance_config_default;
        assert_true(c.min_zupt_cycle == FNAV_R(0.025)); /* on by default (0 turns it off) */
        c.min_zupt_cycle = FNAV_R(1.0);
        assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
        c.min_zupt_cycle = FNAV_R(1.01);
        assert_int_equal(fnav_stance_init(&st, &c), FNAV_E_CONFIG);
        c.min_zupt_cycle = (fnav_real_t)INFINITY;
        assert_int_equal(fnav_stance_init(&st, &c), FNAV_E_CONFIG);
    }
}

/* The detector's noise weights and thresholds enter the statistic as
 * their squares (T = sum |f - g u|^2 / sigma_a^2 + ...): one whose square
 * is 0 or infinite in the working precision is refused, as the filter's
 * sds are (fnav_ukf.h). Accepted, sigma_a = 1e-25 in float made every
 * statistic Inf (never at rest: the navigator never aligned, without a
 * word) and 1e20 dropped the accelerometer's term (at rest in any
 * motion). The bounds either side: float 1e-18 / 1e-23 and 1e18 / 1e20,
 * double 1e-150 / 1e-170 and 1e150 / 1e160. */
static void test_config_squares(void **state)
{
#if FNAV_USE_DOUBLE
    const fnav_real_t vals[4] = { 1e-150, 1e-170, 1e150, 1e160 };
#else
    const fnav_real_t vals[4] = { 1e-18f, 1e-23f, 1e18f, 1e20f };
#endif
    static const size_t off[4] = {
        offsetof(fnav_stance_config_t, sigma_a_mps2),
        offsetof(fnav_stance_config_t, sigma_g_rps),
        offsetof(fnav_stance_config_t, gyro_thresh_rps),
        offsetof(fnav_stance_config_t, accel_thresh_mps2),
    };
    static fnav_stance_t st;
    fnav_stance_config_t c;
    size_t i, k;
    (void)state;
    for (i = 0; i < 4; i++) {
        for (k = 0; k < 4; k++) {
            fnav_real_t *v = (fnav_real_t *)(void *)((char *)&c + off[i]);
            c = fnav_stance_config_default;
            c.detector = i < 2 ? FNAV_DETECTOR_SHOE : FNAV_DETECTOR_THRESHOLD;
            *v = vals[k];
            if (fnav_stance_init(&st, &c) != (k % 2u == 0u ? FNAV_OK : FNAV_E_CONFIG)) {
                fail_msg("field %zu = %g %s", i, (double)vals[k], k % 2u == 0u ? "refused" : "not refused");
            }
        }
    }
}

/* W = 2 floor(window * rate / 2) + 1, at least 3: the same 25 ms at every rate. */
static void test_window_from_rate(void **state)
{
    static const double rates[5] = { 100.0, 200.0, 250.0, 400.0, 820.0 };
    static const int wins[5] = { 3, 5, 7, 11, 21 };
    int i, k;
    (void)state;
    for (i = 0; i < 5; i++) {
        fnav_stance_t st;
        fnav_stance_config_t c = fnav_stance_config_default;
        double f[3] = { 0.0, 0.0, -k_g }, w[3] = { 0, 0, 0 };
        fnav_sample_t s;
        c.rate_hz = (fnav_real_t)rates[i];
        assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
        s = sample(0, rates[i], f, w);
        assert_int_equal(fnav_stance_push(&st, &s), FNAV_OK);
        assert_int_equal(st.win, wins[i]);
        /* estimated from time stamps with 1 % jitter: the same window */
        c.rate_hz = FNAV_R(0.0);
        assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
        for (k = 0; k < 40; k++) {
            fnav_stance_out_t o;
            s = sample(k, rates[i], f, w);
            s.t_ns += (int64_t)(0.01 * 1e9 / rates[i] * jitter());
            assert_int_equal(fnav_stance_push(&st, &s), FNAV_OK);
            while (fnav_stance_pop(&st, &o) == FNAV_OK) {
            }
        }
        assert_int_equal(st.win, wins[i]);
        FNAV_ASSERT_CLOSE(st.rate_hz, rates[i], 0.0, 0.01);
        /* a log shorter than the probe (10 samples): the rate is taken
         * from its stamps at fnav_stance_finish (a mutant taking the
         * configured 0 Hz there, window 3 at every rate, passed every
         * suite) */
        assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
        for (k = 0; k < 10; k++) {
            s = sample(k, rates[i], f, w);
            assert_int_equal(fnav_stance_push(&st, &s), FNAV_OK);
        }
        assert_int_equal(st.win, 0);
        fnav_stance_finish(&st);
        assert_int_equal(st.win, wins[i]);
        FNAV_ASSERT_CLOSE(st.rate_hz, rates[i], 0.0, 1e-6);
    }
}

/* Stamps that never advance (all equal: a logger that wrote no time) give
 * no positive interval to take the median of: the rate is then 100 Hz
 * (fnav_stance.h, rate_hz), the detector sized as one configured for
 * 100 Hz, at the end of the probe and at fnav_stance_finish of a shorter
 * log; the decisions still come out, one per sample. A NULL pop is
 * FNAV_E_ARG. (make coverage: none of this was run.) */
static void test_rate_without_stamps(void **state)
{
    fnav_stance_t st, ref;
    fnav_stance_config_t c = fnav_stance_config_default;
    double f[3] = { 0.0, 0.0, -k_g }, w[3] = { 0, 0, 0 };
    fnav_stance_out_t o;
    fnav_sample_t s;
    long k, n;
    (void)state;
    c.rate_hz = FNAV_R(100.0);
    assert_int_equal(fnav_stance_init(&ref, &c), FNAV_OK);
    s = sample(0, 100.0, f, w);
    assert_int_equal(fnav_stance_push(&ref, &s), FNAV_OK);
    assert_true(ref.win > 1);
    c.rate_hz = FNAV_R(0.0);
    assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
    for (k = 0, n = 0; k < FNAV_STANCE_RATE_PROBE + 8; k++) {
        s = sample(k, 100.0, f, w);
        s.t_ns = 1000000000; /* the same stamp every time */
        assert_int_equal(fnav_stance_push(&st, &s), FNAV_OK);
        while (fnav_stance_pop(&st, &o) == FNAV_OK) {
            n++;
        }
        if (k < FNAV_STANCE_RATE_PROBE) {
            assert_int_equal(st.win, 0);
        }
    }
    assert_true(st.rate_hz == FNAV_R(100.0));
    assert_int_equal(st.win, ref.win);
    assert_int_equal(st.half, ref.half);
    assert_int_equal(st.n_min_zupt, ref.n_min_zupt);
    assert_int_equal(st.n_ev, ref.n_ev);
    fnav_stance_finish(&st);
    while (fnav_stance_pop(&st, &o) == FNAV_OK) {
        n++;
    }
    assert_int_equal(fnav_stance_pop(&st, &o), FNAV_END);
    assert_int_equal(n, FNAV_STANCE_RATE_PROBE + 8);
    /* one sample only: no interval at all, at finish */
    assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
    s = sample(0, 100.0, f, w);
    assert_int_equal(fnav_stance_push(&st, &s), FNAV_OK);
    fnav_stance_finish(&st);
    assert_true(st.rate_hz == FNAV_R(100.0));
    assert_int_equal(st.win, ref.win);
    assert_int_equal(fnav_stance_pop(&st, &o), FNAV_OK);
    assert_int_equal(fnav_stance_pop(&st, &o), FNAV_END);
    assert_int_equal(fnav_stance_pop(NULL, &o), FNAV_E_ARG);
    assert_int_equal(fnav_stance_pop(&st, NULL), FNAV_E_ARG);
    assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
    assert_int_equal(fnav_stance_push(NULL, &s), FNAV_E_ARG);
    assert_int_equal(fnav_stance_push(&st, NULL), FNAV_E_ARG);
    assert_int_equal((int)st.n_in, 0);
}

/* The SHOE statistic of a window equals the formula evaluated here in
 * double: T = 1/W sum(|f - g u|^2 / sa^2 + |w|^2 / sg^2), u = mean f / |mean f|. */
static void test_shoe_statistic(void **state)
{
    fnav_stance_t st;
    fnav_stance_config_t c = fnav_stance_config_default;
    double f[64][3], w[64][3];
    int k, i, n = 56, got = 0; /* 40 popped while pushing: 16 held back (h + L) */
    fnav_stance_out_t o;
    (void)state;
    c.rate_hz = FNAV_R(200.0);
    c.adaptive = 0;
    assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
    for (k = 0; k < n; k++) {
        fnav_sample_t s;
        for (i = 0; i < 3; i++) {
            f[k][i] = 0.3 * jitter() + (i == 2 ? -k_g : 0.5);
            w[k][i] = 0.02 * jitter();
        }
        s = sample(k, 200.0, f[k], w[k]);
        /* the test compares with the values as stored */
        for (i = 0; i < 3; i++) {
            f[k][i] = (double)s.accel_mps2[i];
            w[k][i] = (double)s.gyro_rps[i];
        }
        assert_int_equal(fnav_stance_push(&st, &s), FNAV_OK);
        while (fnav_stance_pop(&st, &o) == FNAV_OK) {
            long j = (long)st.n_out - 1;
            if (j >= 2 && j <= n - 3) {
                double m[3] = { 0, 0, 0 }, nm, T = 0.0;
                long q;
                for (q = j - 2; q <= j + 2; q++) {
                    for (i = 0; i < 3; i++) {
                        m[i] += f[q][i];
                    }
                }
                nm = sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
                for (q = j - 2; q <= j + 2; q++) {
                    double ea = 0.0, eg = 0.0;
                    for (i = 0; i < 3; i++) {
                        double e = f[q][i] - k_g * m[i] / nm;
                        ea += e * e;
                        eg += w[q][i] * w[q][i];
                    }
                    T += ea / (0.01 * 0.01) + eg / pow(0.1 * 3.14159265358979323846 / 180.0, 2.0);
                }
                T /= 5.0;
                FNAV_ASSERT_CLOSE(o.stat, T, 0.0, 200.0 * EPS);
                got++;
            }
        }
    }
    assert_true(got > 30);
}

/* 100 still samples at 200 Hz pushed into an initialised detector, every
 * due decision popped (each sample once, in order): the largest delay
 * between push and pop, samples; *next receives the samples popped. */
static long still_delay(fnav_stance_t *st, long *next)
{
    const double f[3] = { 0.0, 0.0, -k_g }, w[3] = { 0.0, 0.0, 0.0 };
    fnav_stance_out_t o;
    long k, max_lag = 0;
    *next = 0;
    for (k = 0; k < 100; k++) {
        fnav_sample_t s = sample(k, 200.0, f, w);
        assert_int_equal(fnav_stance_push(st, &s), FNAV_OK);
        while (fnav_stance_pop(st, &o) == FNAV_OK) {
            assert_int_equal((long)o.sample.seq, *next);
            (*next)++;
        }
        max_lag = (k + 1 - *next) > max_lag ? (k + 1 - *next) : max_lag;
    }
    return max_lag;
}

/* Every sample comes back once, in order, h + L samples late; after
 * finish the rest comes back and then FNAV_END. */
static void test_delay_and_flush(void **state)
{
    fnav_stance_t st;
    fnav_stance_config_t c = fnav_stance_config_default;
    double f[3] = { 0.0, 0.0, -k_g }, w[3] = { 0, 0, 0 };
    fnav_stance_out_t o;
    long next = 0, max_lag;
    (void)state;
    c.rate_hz = FNAV_R(200.0);
    assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
    /* without the cycle-scaled run: h = 2 (W = 5) plus L = 3 (min_zupt 20
     * ms = 4 samples) */
    c.min_zupt_cycle = FNAV_R(0.0);
    assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
    max_lag = still_delay(&st, &next);
    assert_int_equal(max_lag, 5);
    assert_int_equal(fnav_stance_pending(&st), 5);
    /* the default, min_zupt_cycle 0.025: L fixed for a 3 s cycle,
     * round(0.025 x 3 x 200) - 1 = 14, so h + L = 16 */
    c.min_zupt_cycle = fnav_stance_config_default.min_zupt_cycle;
    assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
    next = 0;
    max_lag = still_delay(&st, &next);
    assert_int_equal(max_lag, 16);
    assert_int_equal(fnav_stance_pending(&st), 16);
    fnav_stance_finish(&st);
    {
        fnav_sample_t s = sample(100, 200.0, f, w);
        assert_int_equal(fnav_stance_push(&st, &s), FNAV_E_STATE);
    }
    while (fnav_stance_pop(&st, &o) == FNAV_OK) {
        assert_int_equal((long)o.sample.seq, next);
        next++;
    }
    assert_int_equal(next, 100);
    assert_int_equal(fnav_stance_pop(&st, &o), FNAV_END);
    /* no sample at all: FNAV_AGAIN until the finish, then FNAV_END (a
     * mutant answering FNAV_AGAIN for ever there passed every suite) */
    c.rate_hz = FNAV_R(0.0);
    assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
    assert_int_equal(fnav_stance_pop(&st, &o), FNAV_AGAIN);
    fnav_stance_finish(&st);
    assert_int_equal(fnav_stance_pop(&st, &o), FNAV_END);
}

/* The caller must pop: a full ring refuses more samples. */
static void test_ring_contract(void **state)
{
    fnav_stance_t st;
    fnav_stance_config_t c = fnav_stance_config_default;
    double f[3] = { 0.0, 0.0, -k_g }, w[3] = { 0, 0, 0 };
    int k;
    (void)state;
    c.rate_hz = FNAV_R(200.0);
    assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
    for (k = 0; k < FNAV_STANCE_MAX_WINDOW; k++) {
        fnav_sample_t s = sample(k, 200.0, f, w);
        assert_int_equal(fnav_stance_push(&st, &s), FNAV_OK);
    }
    {
        fnav_sample_t s = sample(k, 200.0, f, w);
        assert_int_equal(fnav_stance_push(&st, &s), FNAV_E_STATE);
    }
}

/* A caller that pushes several samples before popping (within what push
 * accepts) gets the decisions of one that pops after every push. With a
 * window longer than the look-ahead (window_s 0.1 s: W = 21, h = 10; F = 0:
 * L = 3, at 200 Hz) a raw decision waits for h samples after it, and its
 * window reaches h before it: a push accepting a sample that overwrites the
 * start of a window not yet decided (refusing only when the undecided
 * outputs fill the ring) would leave the statistic computed on what was
 * left (T 2.94 instead of 3.34 in a still stretch, 266 of 1987 decisions
 * different with bursts of 51). Push says FNAV_E_STATE before that; the
 * burst caller pops and pushes again. */
static void test_burst_push_same_decisions(void **state)
{
    static fnav_stance_t a, b;
    static fnav_stance_out_t oa[1200], ob[1200];
    fnav_stance_config_t c = fnav_stance_config_default;
    long k, na = 0, nb = 0, refused = 0;
    (void)state;
    c.rate_hz = FNAV_R(200.0);
    c.window_s = FNAV_R(0.1);
    c.min_zupt_cycle = FNAV_R(0.0);
    assert_int_equal(fnav_stance_init(&a, &c), FNAV_OK);
    assert_int_equal(fnav_stance_init(&b, &c), FNAV_OK);
    for (k = 0; k < 1000; k++) {
        /* still with noise; a swing of 0.5 s in every second */
        double ph = fmod((double)k / 200.0, 1.0);
        double m = ph > 0.5 ? 5.0 * sin((ph - 0.5) * 4.0 * 3.141592653589793) : 0.0;
        double f[3], w[3];
        fnav_sample_t s;
        f[0] = 0.02 * jitter() + m;
        f[1] = 0.02 * jitter();
        f[2] = -k_g + 0.5 * m;
        w[0] = 0.002 * jitter() + 0.3 * m;
        w[1] = 0.002 * jitter();
        w[2] = 0.0;
        s = sample(k, 200.0, f, w);
        assert_int_equal(fnav_stance_push(&a, &s), FNAV_OK);
        while (na < 1200 && fnav_stance_pop(&a, &oa[na]) == FNAV_OK) {
            na++;
        }
        if (fnav_stance_push(&b, &s) != FNAV_OK) {
            /* b pops only when push refuses, then pushes again */
            refused++;
            while (nb < 1200 && fnav_stance_pop(&b, &ob[nb]) == FNAV_OK) {
                nb++;
            }
            assert_int_equal(fnav_stance_push(&b, &s), FNAV_OK);
        }
    }
    fnav_stance_finish(&a);
    fnav_stance_finish(&b);
    while (na < 1200 && fnav_stance_pop(&a, &oa[na]) == FNAV_OK) {
        na++;
    }
    while (nb < 1200 && fnav_stance_pop(&b, &ob[nb]) == FNAV_OK) {
        nb++;
    }
    assert_int_equal(na, 1000);
    assert_int_equal(nb, 1000);
    assert_true(refused > 10);
    for (k = 0; k < na; k++) {
        assert_int_equal((long)ob[k].sample.seq, k);
        assert_true(ob[k].stat == oa[k].stat);
        assert_true(ob[k].gamma == oa[k].gamma);
        assert_int_equal(ob[k].raw_stance, oa[k].raw_stance);
        assert_int_equal(ob[k].stance, oa[k].stance);
        assert_int_equal(ob[k].segment_stance, oa[k].segment_stance);
    }
}

/* The first samples of a stream follow the shortest-run rule like any
 * other: a raw stance run at the start shorter than min_zupt_s is no
 * stance, as such a run at the end of the stream is not (the recording
 * may start mid-swing, at a dip of T). Were the first sample alone made
 * stance whatever its run (an undocumented "|| i == 0"), a run of one raw
 * sample at 100 Hz (W = 3: sample 1's window reaches the motion at sample
 * 2), where the shortest run is 2, would give stance 1 at sample 0 and 0
 * at sample 1. A still start longer than
 * the shortest run is stance from its first sample (the look-ahead). */
static void test_first_samples_short_run(void **state)
{
    static fnav_stance_t st;
    fnav_stance_config_t c = fnav_stance_config_default;
    fnav_stance_out_t o;
    int still_start;
    (void)state;
    c.rate_hz = FNAV_R(100.0);
    c.adaptive = 0;
    c.min_zupt_cycle = FNAV_R(0.0); /* shortest run round(0.02 x 100) = 2 */
    for (still_start = 2; still_start <= 20; still_start += 18) {
        long k, got = 0;
        assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
        for (k = 0; k <= 60; k++) {
            if (k < 60) {
                /* still, then a swing (3 rad/s) from still_start for 30 samples, then still */
                int moving = k >= still_start && k < still_start + 30;
                double f[3] = { moving ? 5.0 : 0.0, 0.0, -k_g }, w[3] = { 0.0, moving ? 3.0 : 0.0, 0.0 };
                fnav_sample_t s = sample(k, 100.0, f, w);
                assert_int_equal(fnav_stance_push(&st, &s), FNAV_OK);
            } else {
                fnav_stance_finish(&st);
            }
            while (fnav_stance_pop(&st, &o) == FNAV_OK) {
                long j = (long)o.sample.seq;
                if (still_start == 2 && j < 2) {
                    /* sample 0 is raw stance alone: a run of 1 */
                    assert_int_equal(o.raw_stance, j == 0);
                    assert_int_equal(o.stance, 0);
                }
                if (still_start == 20 && j < 19) {
                    assert_int_equal(o.stance, 1);
                }
                got++;
            }
        }
        assert_int_equal(got, 60);
    }
}

/* Synthetic steps at 200 Hz: still (f = -g z, w = 0, tiny noise), then a
 * swing of 0.5 s with |w| ~ 3 rad/s, then still again. The stance must end
 * and start within half a window of the motion, every still sample farther
 * than that from the motion must be stance, and the stride is counted.
 * The segmentation turns to swing at the frame where the swing run reaches
 * min_swing_s: round(0.25 s x 200 Hz) = 50 frames, so the 50th frame of the
 * run (its first + 49) is the first with segment_stance 0. */
static void test_step_boundaries(void **state)
{
    fnav_stance_t st;
    fnav_stance_config_t c = fnav_stance_config_default;
    fnav_stance_out_t o;
    const double rate = 200.0;
    long k, n = 400, m0 = 150, m1 = 250; /* motion in [m0, m1) */
    long run0 = -1, swing_run0 = -1, seg_off = -1, n_min_swing, n_min_stance, stance_run0 = -1, stride_at = -1;
    int strides = 0, prev_stance = 1;
    (void)state;
    n_min_swing = lround((double)c.min_swing_s * rate);
    assert_int_equal(n_min_swing, 50);
    n_min_stance = lround((double)c.min_stance_s * rate);
    assert_int_equal(n_min_stance, 10);
    c.rate_hz = (fnav_real_t)rate;
    assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
    for (k = 0; k <= n; k++) {
        if (k < n) {
            double f[3], w[3];
            int i;
            for (i = 0; i < 3; i++) {
                f[i] = (i == 2 ? -k_g : 0.0) + 0.003 * jitter();
                w[i] = 0.0005 * jitter();
            }
            if (k >= m0 && k < m1) {
                double ph = (double)(k - m0) / (double)(m1 - m0) * 3.14159265358979;
                w[1] += 3.0 * sin(ph) + 1.0;
                f[0] += 6.0 * cos(ph);
            }
            {
                fnav_sample_t s = sample(k, rate, f, w);
                assert_int_equal(fnav_stance_push(&st, &s), FNAV_OK);
            }
        } else {
            fnav_stance_finish(&st);
        }
        while (fnav_stance_pop(&st, &o) == FNAV_OK) {
            long j = (long)o.sample.seq;
            if (j < m0 - 2 || j >= m1 + 2) {
                assert_int_equal(o.stance, 1);
            }
            if (j >= m0 && j < m1) {
                assert_int_equal(o.stance, 0);
            }
            /* the segmentation confirms a swing after min_swing_s (50 samples) */
            if (j >= m0 + 50 && j < m1) {
                assert_int_equal(o.segment_stance, 0);
            }
            if (!o.stance && prev_stance) {
                run0 = j; /* a swing run starts */
            }
            if (o.stance && !prev_stance) {
                stance_run0 = j; /* a stance run starts */
            }
            prev_stance = o.stance;
            if (j == m0) {
                swing_run0 = run0; /* the run the motion is in */
            }
            if (!o.segment_stance && seg_off < 0) {
                seg_off = j;
            }
            if (o.events & FNAV_STANCE_EV_STRIDE) {
                strides++;
                stride_at = j;
            }
        }
    }
    assert_int_equal(strides, 1);
    assert_int_equal(st.strides, 1);
    assert_true(swing_run0 >= m0 - 2 && swing_run0 <= m0);
    assert_int_equal(seg_off, swing_run0 + n_min_swing - 1);
    /* and a stance after min_stance_s (10 samples): the stride on the
     * run's 10th sample, not the 11th */
    assert_true(stance_run0 >= m1 && stance_run0 <= m1 + 2);
    assert_int_equal(stride_at, stance_run0 + n_min_stance - 1);
}

/* A dip of the statistic below the threshold for fewer samples than
 * min_zupt_s in the middle of motion is not a stance. */
static void test_short_dip_rejected(void **state)
{
    fnav_stance_t st;
    fnav_stance_config_t c = fnav_stance_config_default;
    fnav_stance_out_t o;
    long k, n = 300;
    int raw_dip = 0;
    (void)state;
    c.rate_hz = FNAV_R(200.0);
    c.window_s = FNAV_R(0.01); /* W = 3: the dip shows in the raw decisions */
    c.adaptive = 0;
    assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
    for (k = 0; k <= n; k++) {
        if (k < n) {
            double f[3] = { 0.0, 0.0, -k_g }, w[3] = { 0.0, 0.0, 0.0 };
            if (k >= 50 && k < 250 && !(k >= 150 && k < 154)) {
                w[1] = 2.0; /* moving, except a 4-sample still gap */
            }
            {
                fnav_sample_t s = sample(k, 200.0, f, w);
                assert_int_equal(fnav_stance_push(&st, &s), FNAV_OK);
            }
        } else {
            fnav_stance_finish(&st);
        }
        while (fnav_stance_pop(&st, &o) == FNAV_OK) {
            long j = (long)o.sample.seq;
            if (j >= 140 && j < 165) {
                raw_dip |= o.raw_stance;
                assert_int_equal(o.stance, 0);
            }
        }
    }
    assert_true(raw_dip); /* the raw test did see the dip */
}

/* Adaptive threshold: when the statistic's minimum in each stance rises
 * (jogging), the threshold follows the floor (never below gamma, never
 * above ratio * gamma); with walking-like minima it stays at gamma. Mode 2
 * switches from still stances to rolling ones at 3.5 s: the floor window
 * (2 s) still holds a still stance until 5.5 s, after which every rolling
 * stance is found again. */
static void test_adaptive_threshold(void **state)
{
    int mode;
    (void)state;
    for (mode = 0; mode < 3; mode++) {
        fnav_stance_t st;
        fnav_stance_config_t c = fnav_stance_config_default;
        fnav_stance_out_t o;
        long k, n = 2000, stance_n = 0, stance_expect = 0;
        double gmax = 0.0;
        c.rate_hz = FNAV_R(200.0);
        assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
        for (k = 0; k <= n; k++) {
            if (k < n) {
                /* stride of 0.7 s: 0.1 s "stance" with a rate of r0, then motion */
                double ph = fmod((double)k / 200.0, 0.7);
                double r0 = (mode == 0 || (mode == 2 && k < 700)) ? 0.0 : 0.8; /* rad/s in stance: T = r0^2 / sigma_g^2 = 2.1e5 */
                double f[3] = { 0.0, 0.0, -k_g }, w[3] = { 0.0, 0.0, 0.0 };
                w[1] = ph < 0.1 ? r0 : 4.0;
                {
                    fnav_sample_t s = sample(k, 200.0, f, w);
                    assert_int_equal(fnav_stance_push(&st, &s), FNAV_OK);
                }
            } else {
                fnav_stance_finish(&st);
            }
            while (fnav_stance_pop(&st, &o) == FNAV_OK) {
                double ph = fmod((double)o.sample.seq / 200.0, 0.7);
                gmax = (double)o.gamma > gmax ? (double)o.gamma : gmax;
                assert_true(o.gamma >= c.gamma && o.gamma <= c.gamma * c.adapt_max_ratio);
                if (o.sample.seq > (mode == 2 ? 1100u + 140u : 600u) && ph > 0.02 && ph < 0.08) {
                    stance_expect++;
                    stance_n += o.stance;
                }
            }
        }
        if (mode == 0) {
            /* still stances: the window always holds one, the floor rests
             * at log10(gamma) - margin and the threshold is gamma */
            assert_true(gmax <= (double)c.gamma * (1.0 + 1e-5));
        } else {
            /* rolling stances (T about 2e5 > gamma = 1e5) are still found */
            assert_true(gmax > 2.0 * (double)c.gamma);
        }
        assert_true(stance_n >= (stance_expect * 9) / 10);
    }
}

/* Threshold detector: stance when the RMS rate and RMS ||f|-g| are below
 * their limits. */
static void test_threshold_detector(void **state)
{
    fnav_stance_t st;
    fnav_stance_config_t c = fnav_stance_config_default;
    fnav_stance_out_t o;
    long k;
    (void)state;
    c.detector = FNAV_DETECTOR_THRESHOLD;
    c.rate_hz = FNAV_R(100.0);
    c.adaptive = 0;
    assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
    for (k = 0; k <= 300; k++) {
        if (k < 300) {
            double f[3] = { 0.0, 0.0, -k_g }, w[3] = { 0.0, 0.0, 0.0 };
            if (k >= 100 && k < 200) {
                w[0] = 0.9; /* above 0.6 rad/s */
            }
            if (k >= 200 && k < 250) {
                f[2] = -k_g - 1.0; /* ||f| - g| = 1 > 0.6 */
            }
            {
                fnav_sample_t s = sample(k, 100.0, f, w);
                assert_int_equal(fnav_stance_push(&st, &s), FNAV_OK);
            }
        } else {
            fnav_stance_finish(&st);
        }
        while (fnav_stance_pop(&st, &o) == FNAV_OK) {
            long j = (long)o.sample.seq;
            if ((j > 5 && j < 95) || j > 260) {
                assert_int_equal(o.stance, 1);
            }
            if (j > 105 && j < 245) {
                assert_int_equal(o.stance, 0);
            }
        }
    }
}

/* Threshold detector: the two normalised mean squares (rate and ||f| - g|,
 * each over its limit squared) are combined by their maximum, so stance
 * means both RMS values are below their limits. A window with both at
 * 0.8 of their limits (a constant 0.48 rad/s, ||f| - g| = 0.48 m/s^2) has
 * both ratios 0.64: stance; their sum (1.28) would not be. */
static void test_threshold_both_below(void **state)
{
    fnav_stance_t st;
    fnav_stance_config_t c = fnav_stance_config_default;
    fnav_stance_out_t o;
    double f[3], w[3] = { 0.0, 0.0, 0.0 }, e, sa, sg, expect;
    long k, frames = 0;
    (void)state;
    c.detector = FNAV_DETECTOR_THRESHOLD;
    c.rate_hz = FNAV_R(100.0);
    c.adaptive = 0;
    w[0] = 0.8 * (double)c.gyro_thresh_rps;
    f[0] = 0.0;
    f[1] = 0.0;
    f[2] = -(k_g + 0.8 * (double)c.accel_thresh_mps2);
    /* the expected ratios in double from the values the detector sees
     * (fnav_real_t inputs and limits) */
    e = fabs((double)(fnav_real_t)f[2]) - (double)c.gravity_mps2;
    sa = e * e / ((double)c.accel_thresh_mps2 * (double)c.accel_thresh_mps2);
    sg = (double)(fnav_real_t)w[0] * (double)(fnav_real_t)w[0] / ((double)c.gyro_thresh_rps * (double)c.gyro_thresh_rps);
    expect = sa > sg ? sa : sg;
    /* 0.64 each, up to the rounding of the inputs to fnav_real_t: half an
     * ulp of 10.29 m/s^2 (4.8e-7 in float32) moves e = 0.48 by that and the
     * ratio e^2 / 0.36 by 2 x 0.48 x 4.8e-7 / 0.36 = 1.3e-6 */
    FNAV_ASSERT_CLOSE(sa, 0.64, 2e-6, 0.0);
    FNAV_ASSERT_CLOSE(sg, 0.64, 2e-6, 0.0);
    assert_true(expect < 1.0 && sa + sg > 1.0); /* max: stance; a sum would not be */
    assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
    for (k = 0; k <= 100; k++) {
        if (k < 100) {
            fnav_sample_t s = sample(k, 100.0, f, w);
            assert_int_equal(fnav_stance_push(&st, &s), FNAV_OK);
        } else {
            fnav_stance_finish(&st);
        }
        while (fnav_stance_pop(&st, &o) == FNAV_OK) {
            /* |f| - g in fnav_real_t: the norm is good to 2 eps of 10.3,
             * which is 21 times the difference 0.48 (42 eps relative in
             * e, 86 after squaring), plus a few roundings of the window's
             * sums and the divisions: 100 eps relative */
            FNAV_ASSERT_CLOSE(o.stat, expect, 0.0, 100.0 * EPS);
            assert_int_equal(o.raw_stance, 1);
            assert_int_equal(o.stance, 1);
            frames++;
        }
    }
    assert_int_equal(frames, 100);
}

/* Stance when the statistic is below the threshold, T < gamma
 * (docs/navigation.md "SHOE / GLRT"; the threshold detector's gamma is 1):
 * a window whose gyro RMS equals its limit exactly is not at rest. With the
 * limit 0.5 rad/s and a constant 0.5 rad/s about x, every term is exact in
 * binary floating point: sum |w|^2 = W x 0.25 and W x 0.5^2, so T = 1.0 to
 * the bit, and ||f| - g| = 0 (|f| = g exactly: the square root of a
 * square) leaves the gyro ratio as the maximum. */
static void test_threshold_at_limit(void **state)
{
    fnav_stance_t st;
    fnav_stance_config_t c = fnav_stance_config_default;
    fnav_stance_out_t o;
    double f[3] = { 0.0, 0.0, 0.0 }, w[3] = { 0.5, 0.0, 0.0 };
    long k, frames = 0;
    (void)state;
    c.detector = FNAV_DETECTOR_THRESHOLD;
    c.rate_hz = FNAV_R(100.0);
    c.adaptive = 0;
    c.gyro_thresh_rps = FNAV_R(0.5);
    f[2] = -(double)c.gravity_mps2;
    assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
    for (k = 0; k <= 50; k++) {
        if (k < 50) {
            fnav_sample_t s = sample(k, 100.0, f, w);
            assert_int_equal(fnav_stance_push(&st, &s), FNAV_OK);
        } else {
            fnav_stance_finish(&st);
        }
        while (fnav_stance_pop(&st, &o) == FNAV_OK) {
            assert_true(o.stat == FNAV_R(1.0));
            assert_true(o.gamma == FNAV_R(1.0));
            assert_int_equal(o.raw_stance, 0);
            assert_int_equal(o.stance, 0);
            frames++;
        }
    }
    assert_int_equal(frames, 50);
}

/* Gait events popped from the detector: the last foot-off and foot-strike
 * (as sample indices at `rate`) and how many of each. */
typedef struct {
    long fo_at, fs_at;
    int nfo, nfs;
} events_t;

static void pop_events(fnav_stance_t *st, double rate, events_t *ev)
{
    fnav_stance_out_t o;
    while (fnav_stance_pop(st, &o) == FNAV_OK) {
        if (o.events & FNAV_STANCE_EV_FOOT_OFF) {
            ev->fo_at = (long)llround((double)o.fo_t_ns * rate * 1e-9);
            ev->nfo++;
        }
        if (o.events & FNAV_STANCE_EV_FOOT_STRIKE) {
            ev->fs_at = (long)llround((double)o.fs_t_ns * rate * 1e-9);
            ev->nfs++;
        }
    }
}

/* Gait events: a push-off peak of |f| at a known sample after the stance
 * ends is the foot-off; a jerk onset before the stance begins is the
 * foot-strike. */
static void test_gait_events(void **state)
{
    fnav_stance_t st;
    fnav_stance_config_t c = fnav_stance_config_default;
    const double rate = 100.0;
    long k, n = 300;
    events_t ev = { -1, -1, 0, 0 };
    (void)state;
    c.rate_hz = (fnav_real_t)rate;
    assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
    for (k = 0; k <= n; k++) {
        if (k < n) {
            double f[3] = { 0.0, 0.0, -k_g }, w[3] = { 0.0, 0.0, 0.0 };
            if (k >= 100 && k < 160) {
                w[1] = 3.0;
                f[0] = 2.0;
            }
            if (k == 104) {
                f[0] = 25.0; /* push-off peak */
            }
            if (k >= 152 && k < 156) {
                f[2] = -k_g + (k == 152 ? 30.0 : (k == 153 ? -20.0 : 8.0)); /* impact from sample 152 */
            }
            {
                fnav_sample_t s = sample(k, rate, f, w);
                assert_int_equal(fnav_stance_push(&st, &s), FNAV_OK);
            }
        } else {
            fnav_stance_finish(&st);
        }
        pop_events(&st, rate, &ev);
    }
    assert_int_equal(ev.nfo, 1);
    assert_int_equal(ev.nfs, 1);
    assert_int_equal(ev.fo_at, 104);
    assert_int_equal(ev.fs_at, 152);
}

/* A log that starts in the swing (20 samples at 100 Hz, min_swing_s 0.1
 * s): the foot-strike search window (event_window_s, 30 samples) reaches
 * back past the first sample and is cut at it (make coverage: never run);
 * the impact onset at sample 12 is still the foot-strike, as at 152 in
 * test_gait_events. */
static void test_foot_strike_at_start(void **state)
{
    fnav_stance_t st;
    fnav_stance_config_t c = fnav_stance_config_default;
    const double rate = 100.0;
    long k, n = 200;
    events_t ev = { -1, -1, 0, 0 };
    (void)state;
    c.rate_hz = (fnav_real_t)rate;
    c.min_swing_s = FNAV_R(0.1);
    assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
    for (k = 0; k <= n; k++) {
        if (k < n) {
            double f[3] = { 0.0, 0.0, -k_g }, w[3] = { 0.0, 0.0, 0.0 };
            if (k < 20) {
                w[1] = 3.0;
                f[0] = 2.0;
            }
            if (k >= 12 && k < 16) {
                f[2] = -k_g + (k == 12 ? 30.0 : (k == 13 ? -20.0 : 8.0)); /* impact from sample 12 */
            }
            {
                fnav_sample_t s = sample(k, rate, f, w);
                assert_int_equal(fnav_stance_push(&st, &s), FNAV_OK);
            }
        } else {
            fnav_stance_finish(&st);
        }
        pop_events(&st, rate, &ev);
    }
    assert_int_equal(ev.nfs, 1);
    assert_int_equal(ev.fs_at, 12);
}

/* The foot-off search covers the first event_window_s of the swing run,
 * n_ev = round(0.3 s x 100 Hz) = 30 samples: the run of test_gait_events
 * begins at sample 99 (the 3-sample SHOE window, test_window_from_rate,
 * sees the motion of sample 100 from there), so samples 99..128. A larger
 * peak at 128 is the foot-off; at 129 it is outside the window and the
 * push-off peak at 104 stays the foot-off. A window one sample shorter
 * (run < n_ev, a mutant) passed every suite. */
static void test_foot_off_window_edge(void **state)
{
    const double rate = 100.0;
    long peak;
    (void)state;
    for (peak = 128; peak <= 129; peak++) {
        fnav_stance_t st;
        fnav_stance_config_t c = fnav_stance_config_default;
        events_t ev = { -1, -1, 0, 0 };
        long k;
        c.rate_hz = (fnav_real_t)rate;
        assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
        for (k = 0; k <= 300; k++) {
            if (k < 300) {
                double f[3] = { 0.0, 0.0, -k_g }, w[3] = { 0.0, 0.0, 0.0 };
                fnav_sample_t s;
                if (k >= 100 && k < 160) {
                    w[1] = 3.0;
                    f[0] = 2.0;
                }
                if (k == 104) {
                    f[0] = 25.0;
                }
                if (k == peak) {
                    f[0] = 40.0;
                }
                s = sample(k, rate, f, w);
                assert_int_equal(fnav_stance_push(&st, &s), FNAV_OK);
            } else {
                fnav_stance_finish(&st);
            }
            pop_events(&st, rate, &ev);
        }
        assert_int_equal(st.n_ev, 30);
        assert_int_equal(ev.nfo, 1);
        assert_int_equal(ev.fo_at, peak == 128 ? 128 : 104);
    }
    /* a window longer than the jerk history is cut to
     * FNAV_STANCE_EVENT_BUF - 1 samples (fnav_stance.h: the foot-strike
     * search reaches n_ev back into that history; a mutant allowing two
     * more passed every suite) */
    {
        fnav_stance_t st;
        fnav_stance_config_t c = fnav_stance_config_default;
        double f[3] = { 0.0, 0.0, -k_g }, w[3] = { 0.0, 0.0, 0.0 };
        fnav_sample_t s = sample(0, rate, f, w);
        c.rate_hz = (fnav_real_t)rate;
        c.event_window_s = FNAV_R(1000.0);
        assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
        assert_int_equal(fnav_stance_push(&st, &s), FNAV_OK);
        assert_int_equal(st.n_ev, FNAV_STANCE_EVENT_BUF - 1);
    }
}

/* A swing shorter than the foot-off window that ends in a pause shorter
 * than min_stance_s (a stance confirmed for ZUPTs, not for a stride), then
 * a little settling motion: the foot-off is the push-off peak of the swing,
 * before the foot-strike. Were the search left open across the pause, the
 * settling motion's run would restart it and foot-off would come at
 * 0.830 s, after the foot-strike. */
static void test_foot_off_short_pause(void **state)
{
    fnav_stance_t st;
    fnav_stance_config_t c = fnav_stance_config_default;
    const double rate = 200.0;
    long k;
    events_t ev = { -1, -1, 0, 0 };
    (void)state;
    c.rate_hz = (fnav_real_t)rate;
    c.adaptive = 0;
    assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
    for (k = 0; k <= 500; k++) {
        if (k < 500) {
            double f[3] = { 0.0, 0.0, -k_g }, w[3] = { 0.0, 0.0, 0.0 };
            fnav_sample_t s;
            if (k >= 100 && k < 155) {
                w[1] = 4.0; /* a 0.275 s swing (the window is 0.3 s) */
            }
            if (k == 105) {
                f[2] = -30.0; /* push-off peak */
            }
            if (k >= 165 && k < 185) {
                w[1] = 0.5; /* settling after a 50 ms pause */
                f[2] = -12.0;
            }
            s = sample(k, rate, f, w);
            assert_int_equal(fnav_stance_push(&st, &s), FNAV_OK);
        } else {
            fnav_stance_finish(&st);
        }
        pop_events(&st, rate, &ev);
    }
    assert_int_equal(ev.nfo, 1);
    assert_int_equal(ev.nfs, 1);
    assert_int_equal(ev.fo_at, 105);
    assert_true(ev.fs_at > ev.fo_at);
}

/* Time jumps below the 35.8 min that clears the jerk history are looked
 * across, but three of 30 min between the impact and the stance add up
 * past the 71.6 min of the stamps' modulus: the strike must still be the
 * impact's own time (not 0.650 + 4294.967 s). */
static void test_foot_strike_jumps_add_up(void **state)
{
    fnav_stance_t st;
    fnav_stance_config_t c = fnav_stance_config_default;
    fnav_stance_out_t o;
    int64_t t = 0, t_impact = 0;
    long k;
    int strikes = 0;
    (void)state;
    c.rate_hz = FNAV_R(200.0);
    c.adaptive = 0;
    assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
    for (k = 0; k <= 400; k++) {
        if (k < 400) {
            double f[3] = { 0.0, 0.0, -k_g }, w[3] = { 0.0, 0.0, 0.0 };
            fnav_sample_t s;
            if (k > 0) {
                t += 5000000;
            }
            if (k == 141 || k == 151 || k == 161) {
                t += (int64_t)1800 * 1000000000; /* 30 min */
            }
            if (k >= 100 && k < 180) {
                w[0] = 5.0;
            }
            if (k == 130) {
                f[0] = 30.0; /* the heel impact */
                t_impact = t;
            }
            s = sample(k, 200.0, f, w);
            s.t_ns = t;
            assert_int_equal(fnav_stance_push(&st, &s), FNAV_OK);
        } else {
            fnav_stance_finish(&st);
        }
        while (fnav_stance_pop(&st, &o) == FNAV_OK) {
            if (o.events & FNAV_STANCE_EV_FOOT_STRIKE) {
                strikes++;
                assert_true(o.fs_t_ns == t_impact);
            }
        }
    }
    assert_int_equal(strikes, 1);
}

/* The foot-strike search reads whole blocks of the jerk history through
 * their maxima: over many strides of random swings (window positions at
 * every phase of the blocks) it must give exactly the answer of the plain
 * definition, the first sample of the event window before the stance whose
 * jerk reaches half the window's largest, computed here from the samples. */
#define FS_N 24000
static fnav_real_t g_fs_acc[FS_N][3];
static int64_t g_fs_t[FS_N];

static void test_foot_strike_reference(void **state)
{
    fnav_stance_t st;
    fnav_stance_config_t c = fnav_stance_config_default;
    fnav_stance_out_t o;
    const double rate = 400.0;
    long k = 0, n_out = 0, swing_end = 0;
    int nfs = 0, phase_seen[FNAV_STANCE_JERK_BLOCK] = { 0 }, i;
    (void)state;
    c.rate_hz = (fnav_real_t)rate;
    assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
    g_lcg = 777u;
    while (k < FS_N) {
        double f[3] = { 0.0, 0.0, -k_g }, w[3] = { 0.0, 0.0, 0.0 };
        long pos;
        if (k >= swing_end + 160) {
            /* a new swing of 0.4-0.6 s after 0.4 s of stance */
            swing_end = k + 160 + (long)(80.0 * (jitter() + 1.0));
        }
        pos = k - (swing_end - 160 - 160);
        if (k < swing_end && pos >= 160 && k > 200) {
            w[1] = 4.0 + jitter();
            f[0] = 3.0 * jitter();
            f[2] = -k_g + 6.0 * jitter() + (jitter() > 0.9 ? 40.0 * jitter() : 0.0);
        }
        {
            fnav_sample_t s = sample(k, rate, f, w);
            assert_int_equal(fnav_stance_push(&st, &s), FNAV_OK);
        }
        k++;
        if (k == FS_N) {
            fnav_stance_finish(&st);
        }
        while (fnav_stance_pop(&st, &o) == FNAV_OK) {
            assert_true(n_out < FS_N);
            for (i = 0; i < 3; i++) {
                g_fs_acc[n_out][i] = o.sample.accel_mps2[i];
            }
            g_fs_t[n_out] = o.sample.t_ns;
            if (o.events & FNAV_STANCE_EV_FOOT_STRIKE) {
                long k0 = -1, lo, j, kbest;
                fnav_real_t jmax = FNAV_R(0.0), jk;
                for (j = n_out; j >= 0; j--) {
                    if (g_fs_t[j] == o.swing_t1_ns) {
                        k0 = j;
                        break;
                    }
                }
                assert_true(k0 > 0);
                lo = k0 - st.n_ev;
                lo = lo < 0 ? 0 : lo;
                kbest = k0;
                for (j = lo; j < k0; j++) {
                    jk = j == 0 ? FNAV_R(0.0)
                                : fnav_vec3_norm(fnav_vec3_sub(fnav_vec3_from(g_fs_acc[j]), fnav_vec3_from(g_fs_acc[j - 1])));
                    jmax = jk > jmax ? jk : jmax;
                }
                for (j = lo; j < k0; j++) {
                    jk = j == 0 ? FNAV_R(0.0)
                                : fnav_vec3_norm(fnav_vec3_sub(fnav_vec3_from(g_fs_acc[j]), fnav_vec3_from(g_fs_acc[j - 1])));
                    if (jk >= FNAV_R(0.5) * jmax) {
                        kbest = j;
                        break;
                    }
                }
                assert_true(o.fs_t_ns == g_fs_t[kbest]);
                phase_seen[lo % FNAV_STANCE_JERK_BLOCK] = 1;
                nfs++;
            }
            n_out++;
        }
    }
    print_message("foot-strike events checked: %d\n", nfs);
    assert_true(nfs >= 12);
    for (i = 0; i < FNAV_STANCE_JERK_BLOCK; i++) {
        assert_true(phase_seen[i] || nfs < 40); /* many strides: every block phase */
    }
}

/* A minimum stance longer than the jerk history (0.2 s at 1 kHz: 200
 * samples against FNAV_STANCE_EVENT_BUF) leaves nothing before the stance
 * to search when it is confirmed: the foot strike is then the stance's
 * first sample, never a time inside it (it read an overwritten slot). With
 * the default 0.05 s the impact 10 ms before the stance is found. */
static void test_foot_strike_long_min_stance(void **state)
{
    const double rate = 1000.0, t_strike = 1.6;
    double min_st;
    (void)state;
    for (min_st = 0.05; min_st < 0.3; min_st += 0.15) {
        static fnav_stance_t st;
        fnav_stance_config_t c = fnav_stance_config_default;
        fnav_stance_out_t o;
        fnav_sample_t s;
        long i, strikes = 0;
        memset(&s, 0, sizeof s);
        c.rate_hz = (fnav_real_t)rate;
        c.min_stance_s = (fnav_real_t)min_st;
        c.adaptive = 0;
        assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
        for (i = 0; i < (long)(3.1 * rate); i++) {
            const double t = (double)i / rate;
            s.t_ns = (int64_t)llround(t * 1e9);
            s.seq = (uint32_t)i;
            s.accel_mps2[0] = FNAV_R(0.0);
            s.accel_mps2[2] = FNAV_R(-9.80665);
            s.gyro_rps[1] = FNAV_R(0.0);
            if (t >= 1.0 && t < t_strike) {
                s.gyro_rps[1] = (fnav_real_t)(3.0 * sin(3.14159 * (t - 1.0) / 0.6));
                s.accel_mps2[0] = (fnav_real_t)(5.0 * sin(6.28 * (t - 1.0) / 0.6));
            }
            if (fabs(t - (t_strike - 0.01)) < 0.5 / rate) {
                s.accel_mps2[2] = FNAV_R(-60.0); /* the heel impact */
            }
            assert_int_equal(fnav_stance_push(&st, &s), FNAV_OK);
            while (fnav_stance_pop(&st, &o) == FNAV_OK) {
                if (o.events & FNAV_STANCE_EV_FOOT_STRIKE) {
                    strikes++;
                    assert_true(o.fs_t_ns <= o.swing_t1_ns);
                    if (min_st < 0.1) {
                        assert_true(fabs((double)o.fs_t_ns * 1e-9 - (t_strike - 0.01)) <= 1e-3);
                    } else {
                        assert_true(o.fs_t_ns == o.swing_t1_ns);
                    }
                }
            }
        }
        assert_int_equal(strikes, 1);
    }
}

/* A synthetic gait at 1 kHz for the long-run tests: 0.6 s still, 0.4 s of
 * swing with a heel impact at its end, repeated. */
static fnav_sample_t gait_sample(long k)
{
    const double rate = 1000.0, t = (double)k / rate, ph = fmod(t, 1.0);
    double f[3] = { 0.0, 0.0, -k_g }, w[3] = { 0.0, 0.0, 0.0 };
    if (ph >= 0.6) {
        const double u = (ph - 0.6) / 0.4;
        w[1] = 3.0 * sin(3.14159265358979 * u);
        f[0] = 5.0 * sin(6.28318530717959 * u);
        if (ph >= 0.99) {
            f[2] = -60.0; /* the heel impact */
        }
    } else {
        f[2] += 0.002 * sin((double)k * 1.3);
        w[0] = 0.0005 * cos((double)k * 0.7);
    }
    return sample(k, rate, f, w);
}

/* Days of samples: the sample counters are long,
 * 32 bits on the Cortex-M4F, where 2^31 samples are 24.9 days at 1 kHz and
 * 6.2 days at 4 kHz. Simulated here by moving every counter of a detector
 * to a few thousand samples below LONG_MAX (a multiple of both ring sizes,
 * so every slot stays where it was): its decisions must stay those of a
 * detector that did not jump. Counters left to overflow would be undefined
 * behaviour (in practice the ring index goes negative, pop answers
 * FNAV_AGAIN for ever and push FNAV_E_STATE). */
static void test_counters_long_run(void **state)
{
    static fnav_stance_t a, b;
    /* a few thousand samples below LONG_MAX, and below 2^30 (where the
     * fixed detector moves its counters back: the same decisions across) */
    const long tops[2] = { LONG_MAX, 1L << 30 };
    int pass;
    (void)state;
    for (pass = 0; pass < 2; pass++) {
        fnav_stance_config_t c = fnav_stance_config_default;
        const long period = (long)FNAV_STANCE_MAX_WINDOW * FNAV_STANCE_EVENT_BUF;
        fnav_stance_out_t oa, ob;
        long k, outs = 0, strides = 0;
        c.rate_hz = FNAV_R(1000.0);
        assert_int_equal(fnav_stance_init(&a, &c), FNAV_OK);
        assert_int_equal(fnav_stance_init(&b, &c), FNAV_OK);
        for (k = 0; k < 30000; k++) {
            fnav_sample_t s = gait_sample(k);
            if (k == 1000) {
                const long jump = (tops[pass] / period - 1) * period - (b.n_out / period + 1) * period;
                b.n_in += jump;
                b.n_raw += jump;
                b.n_out += jump;
                assert_true(b.n_out >= tops[pass] - 3 * period);
            }
            assert_int_equal(fnav_stance_push(&a, &s), FNAV_OK);
            assert_int_equal(fnav_stance_push(&b, &s), FNAV_OK);
            for (;;) {
                fnav_status_t ra = fnav_stance_pop(&a, &oa), rb = fnav_stance_pop(&b, &ob);
                assert_int_equal(rb, ra);
                if (ra != FNAV_OK) {
                    break;
                }
                assert_true(oa.sample.t_ns == ob.sample.t_ns);
                assert_int_equal(ob.raw_stance, oa.raw_stance);
                assert_int_equal(ob.stance, oa.stance);
                assert_int_equal(ob.segment_stance, oa.segment_stance);
                assert_int_equal(ob.events, oa.events);
                assert_true(ob.fo_t_ns == oa.fo_t_ns && ob.fs_t_ns == oa.fs_t_ns);
                assert_true(ob.stat == oa.stat && ob.gamma == oa.gamma);
                strides += (oa.events & FNAV_STANCE_EV_STRIDE) != 0u;
                outs++;
            }
        }
        assert_true(outs > 29900);
        assert_true(strides >= 25); /* the gait was segmented (one stride a second) */
        assert_true(b.n_out > 0 && b.n_in >= b.n_out);
    }
}

/* The same for the run lengths: a foot at rest for 2^31 samples (simulated
 * by moving the lengths of the current raw-stance run close to LONG_MAX)
 * stays in stance; a run length left to overflow would make the
 * confirmation (run >= min_zupt) turn the rest into motion. */
static void test_rest_run_long(void **state)
{
    static fnav_stance_t st;
    fnav_stance_config_t c = fnav_stance_config_default;
    double f[3] = { 0.0, 0.0, -k_g }, w[3] = { 0.0, 0.0, 0.0 };
    fnav_stance_out_t o;
    long k, still = 0, outs = 0;
    (void)state;
    c.rate_hz = FNAV_R(1000.0);
    assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
    for (k = 0; k < 3000; k++) {
        fnav_sample_t s;
        f[2] = -k_g + 0.002 * sin((double)k * 1.3);
        w[0] = 0.0005 * cos((double)k * 0.7);
        s = sample(k, 1000.0, f, w);
        if (k == 1000) {
            assert_true(st.back > 100 && st.run > 100); /* at rest since the start */
            st.back = LONG_MAX - 500;
            st.run = LONG_MAX - 500;
        }
        assert_int_equal(fnav_stance_push(&st, &s), FNAV_OK);
        while (fnav_stance_pop(&st, &o) == FNAV_OK) {
            still += o.stance && o.segment_stance;
            outs++;
        }
    }
    assert_true(outs > 2900);
    assert_int_equal(still, outs);
}

/* Sample k of a 100 Hz walk for the foot-strike tests: still for the first
 * second, then each second a swing from 0.6 s (pitching, a forward push)
 * with a heel impact of -60 m/s^2 from 0.98 s, stance otherwise. */
static fnav_sample_t impact_walk(long k)
{
    const double t = (double)k / 100.0, ph = fmod(t, 1.0);
    double f[3] = { 0.0, 0.0, -k_g }, w[3] = { 0.0, 0.0, 0.0 };
    if (t > 1.0 && ph >= 0.6) {
        const double u = (ph - 0.6) / 0.4;
        w[1] = 3.0 * sin(3.14159265358979 * u);
        f[0] = 5.0 * sin(6.28318530717959 * u);
        if (ph >= 0.98) {
            f[2] = -60.0; /* the heel impact: 1.98 s, 2.98 s, 3.98 s */
        }
    }
    return sample(k, 100.0, f, w);
}

/* A time jump of over 35.8 min (2^31 us) between a heel impact and the
 * stance it ends: the jerk history's stamps are microseconds modulo 2^32
 * (71.6 min), so a foot-strike time searched across it would come out
 * wrapped (a 73-minute jump at 100 Hz: 4297.947 s for a stance starting at
 * 4403.010 s). Across such a jump the search does not look before it (the
 * motion inside is unknown): the strike is within the stance's own side of
 * the jump, at most its first sample. A 10-minute jump changes nothing. */
static void test_foot_strike_time_jump(void **state)
{
    /* the third, a step back of 10 min: the new timeline fnav_nav_push
     * accepts after FNAV_NAV_TIME_RESYNC samples behind (a corrupted stamp
     * far ahead, a restarted timer). A search looking back across it would
     * put the strike 3695 s before the stance, the stamps' difference
     * wrapped modulo 2^32 us; a step back clears the history as a long
     * jump does. */
    static const double jumps_s[3] = { 600.0, 4400.0, -600.0 };
    int pass;
    (void)state;
    for (pass = 0; pass < 3; pass++) {
        static fnav_stance_t st;
        fnav_stance_config_t c = fnav_stance_config_default;
        const int64_t jump_ns = (int64_t)(jumps_s[pass] * 1e9);
        fnav_stance_out_t o;
        long k;
        int strikes = 0;
        c.rate_hz = FNAV_R(100.0);
        assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
        for (k = 0; k < 400; k++) {
            fnav_sample_t s = impact_walk(k);
            if (k >= 299) {
                s.t_ns += jump_ns; /* after the impact, before the stance */
            }
            assert_int_equal(fnav_stance_push(&st, &s), FNAV_OK);
            while (fnav_stance_pop(&st, &o) == FNAV_OK) {
                if ((o.events & FNAV_STANCE_EV_FOOT_STRIKE) != 0u && o.sample.seq >= 299u) {
                    strikes++;
                    assert_true(o.fs_t_ns <= o.swing_t1_ns);
                    if (pass == 0) {
                        assert_true(llabs(o.fs_t_ns - 2980000000LL) <= 1000); /* the impact, to the us */
                    } else {
                        assert_true(o.fs_t_ns >= 2990000000LL + jump_ns); /* not before the jump */
                    }
                }
            }
        }
        assert_int_equal(strikes, 1);
    }
}

/* The foot-strike search across the natural wrap of its microsecond stamps
 * (modulo 2^32 us, every 71.6 min of a long run): the gait of
 * test_foot_strike_time_jump with every stamp moved so that the heel impact
 * (2.98 s in) lies 5 ms before, or 0.5 ms after, a multiple of 2^32 us, the
 * stance it ends after it, after one wrap (71.6 min in) and after 2000 (99.4
 * days in); also a wrap between the swing's start and the impact. The
 * strike is the impact's sample, to the microsecond, as without the offset. */
static void test_foot_strike_across_wrap(void **state)
{
    static const int64_t wraps[3] = { 1, 2000, 7 };
    static const double before_s[3] = { 2.985, 2.985, 2.9795 };
    static const double late_s[3] = { 0.0, 0.0, 0.2 };
    int pass;
    (void)state;
    for (pass = 0; pass < 3; pass++) {
        static fnav_stance_t st;
        fnav_stance_config_t c = fnav_stance_config_default;
        const int64_t off_ns = wraps[pass] * (int64_t)4294967296LL * 1000 - (int64_t)llround(before_s[pass] * 1e9) +
                               (int64_t)llround(late_s[pass] * 1e9);
        const int64_t wrap_ns = wraps[pass] * (int64_t)4294967296LL * 1000;
        fnav_stance_out_t o;
        long k;
        int strikes = 0;
        c.rate_hz = FNAV_R(100.0);
        assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
        for (k = 0; k < 400; k++) {
            fnav_sample_t s = impact_walk(k);
            s.t_ns += off_ns;
            assert_int_equal(fnav_stance_push(&st, &s), FNAV_OK);
            while (fnav_stance_pop(&st, &o) == FNAV_OK) {
                if ((o.events & FNAV_STANCE_EV_FOOT_STRIKE) != 0u && o.sample.seq >= 299u) {
                    strikes++;
                    assert_true(o.fs_t_ns <= o.swing_t1_ns);
                    assert_true(llabs(o.fs_t_ns - (2980000000LL + off_ns)) <= 1000); /* the impact, to the us */
                    /* the wrap lies between the impact and the stance (the first two), or
                     * between the swing's start and the impact (the third) */
                    assert_true(pass == 2 ? o.fs_t_ns > wrap_ns : o.fs_t_ns < wrap_ns);
                    assert_true(o.swing_t1_ns > wrap_ns);
                    if (pass == 2) { /* the swing started before the wrap */
                        assert_true((o.events & FNAV_STANCE_EV_STRIDE) != 0u);
                        assert_true(o.swing_t0_ns < wrap_ns);
                    }
                }
            }
        }
        assert_int_equal(strikes, 1);
    }
}

/* fnav_stance_cut: 0 until the rate is known; at 200 Hz nothing is cut;
 * at 2 kHz the shortest ZUPT run (19 of 20 ms: half window 25 + 40 + 1 > 64),
 * at 4 kHz the window too (63 of 101 samples) with the default ring of 64;
 * at both, the default min_zupt_cycle's (0.025) run for a 3 s cycle (150 and
 * 300 samples) too */
static void test_cut_durations(void **state)
{
    static const double rates[3] = { 200.0, 2000.0, 4000.0 };
    const unsigned want[3] = { 0u, FNAV_STANCE_CUT_MIN_ZUPT | FNAV_STANCE_CUT_ZUPT_CYCLE,
                               FNAV_STANCE_CUT_WINDOW | FNAV_STANCE_CUT_MIN_ZUPT | FNAV_STANCE_CUT_ZUPT_CYCLE };
    int r;
    (void)state;
    for (r = 0; r < 3; r++) {
        fnav_stance_t st;
        fnav_stance_config_t c = fnav_stance_config_default;
        const double f[3] = { 0.0, 0.0, -k_g }, w[3] = { 0.0, 0.0, 0.0 };
        fnav_sample_t s = sample(0, rates[r], f, w);
        c.rate_hz = (fnav_real_t)rates[r];
        assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
        assert_int_equal(fnav_stance_cut(&st), 0u);
        assert_int_equal(fnav_stance_push(&st, &s), FNAV_OK);
        assert_int_equal(fnav_stance_cut(&st), want[r]);
    }
}

/* Cycle-scaled shortest ZUPT run (min_zupt_cycle). A synthetic gait at
 * 200 Hz (W = 3, fixed threshold): each cycle is a still stance of
 * stance_n samples and a swing of swing_n samples (|w| = 2 rad/s) with a
 * still gap of gap_n samples gap_at samples into it; a gap of G samples
 * gives a raw stance of G - 2 (the window's edges see the motion), the
 * late-swing dip of a slow gait. Per cycle: whether any sample around the
 * gap was decided stance (a ZUPT), and the run in use when the gap's first
 * sample was decided. */
typedef struct {
    int stance_n, swing_n, gap_at, gap_n;
} zc_cycle_t;

#define ZC_MAX_CYCLES 12

/* n cycles alike: stance, swing, and a still gap in the swing. */
static void zc_fill(zc_cycle_t *cyc, int n, int stance_n, int swing_n, int gap_at, int gap_n)
{
    int i;
    for (i = 0; i < n; i++) {
        cyc[i].stance_n = stance_n;
        cyc[i].swing_n = swing_n;
        cyc[i].gap_at = gap_at;
        cyc[i].gap_n = gap_n;
    }
}
#define ZC_MAX_SAMPLES 12000
/* More dips per swing: g_zc_dips gaps, each 30 samples after the one
 * before (test_zupt_cycle_lock_in; 1 elsewhere). */
static int g_zc_dips = 1;

static void zc_run(fnav_real_t frac, const zc_cycle_t *cyc, int n_cyc, int *dip_zupt, int *req, long *strides,
                   int *lag)
{
    static signed char moving[ZC_MAX_SAMPLES];
    static short cyc_of[ZC_MAX_SAMPLES]; /* cycle whose gap (+-2) the sample is in, else -1 */
    static unsigned char gap0[ZC_MAX_SAMPLES];
    fnav_stance_t st;
    fnav_stance_config_t c = fnav_stance_config_default;
    fnav_stance_out_t o;
    long n = 0, k;
    int i, j;
    for (i = 0; i < n_cyc; i++) {
        dip_zupt[i] = 0;
        req[i] = -1;
        for (j = 0; j < cyc[i].stance_n + cyc[i].swing_n; j++) {
            const int sw = j - cyc[i].stance_n; /* sample within the swing */
            int in_gap = 0, near_gap = 0, d;
            for (d = 0; d < g_zc_dips; d++) {
                const int g0 = cyc[i].gap_at + 30 * d;
                in_gap |= sw >= g0 && sw < g0 + cyc[i].gap_n;
                near_gap |= cyc[i].gap_n > 0 && sw >= g0 - 2 && sw < g0 + cyc[i].gap_n + 2;
            }
            assert_true(n < ZC_MAX_SAMPLES - 100);
            moving[n] = (signed char)(sw >= 0 && !in_gap);
            cyc_of[n] = (short)(near_gap ? i : -1);
            gap0[n] = (unsigned char)(cyc[i].gap_n > 0 && sw == cyc[i].gap_at);
            n++;
        }
    }
    for (j = 0; j < 100; j++, n++) { /* a last stance ends the last swing */
        moving[n] = 0;
        cyc_of[n] = -1;
        gap0[n] = 0;
    }
    c.rate_hz = FNAV_R(200.0);
    c.window_s = FNAV_R(0.01);
    c.adaptive = 0;
    c.min_zupt_cycle = frac;
    assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
    for (k = 0; k <= n; k++) {
        if (k < n) {
            double f[3] = { 0.0, 0.0, -k_g }, w[3] = { 0.0, 0.0, 0.0 };
            fnav_sample_t s;
            w[1] = moving[k] ? 2.0 : 0.0;
            s = sample(k, 200.0, f, w);
            assert_int_equal(fnav_stance_push(&st, &s), FNAV_OK);
        } else {
            fnav_stance_finish(&st);
        }
        while (fnav_stance_pop(&st, &o) == FNAV_OK) {
            const long q = (long)o.sample.seq;
            if (cyc_of[q] >= 0) {
                dip_zupt[cyc_of[q]] |= o.stance;
                if (gap0[q]) {
                    req[cyc_of[q]] = st.n_zupt_req;
                }
            }
        }
    }
    *strides = st.strides;
    *lag = st.lag;
}

/* A slow gait (a cycle of 2.4 s, 50 steps/min): a late-swing dip with a
 * raw stance of 6 samples (30 ms) passes min_zupt_s (4 samples) and is a
 * ZUPT in every swing; with min_zupt_cycle 0.025 the run from the third
 * swing on is round(0.025 x 2.4 s x 200 Hz) = 12 samples and the dip is
 * rejected. The first two swings come before a cycle is known (one needs
 * two swing starts; the cycle is taken at the second swing's start,
 * min_swing_s into it, before its dip): the first dip is accepted by
 * min_zupt_s alone. The look-ahead is fixed for the longest cycle: 0.025 x
 * 3 s x 200 Hz = 15 samples, L = 14. */
static void test_zupt_cycle_slow_gait(void **state)
{
    zc_cycle_t cyc[6];
    int dip[6], req[6], lag, i;
    long strides;
    (void)state;
    zc_fill(cyc, 6, 240, 240, 180, 8);
    zc_run(FNAV_R(0.0), cyc, 6, dip, req, &strides, &lag);
    assert_int_equal(lag, 3);
    assert_int_equal(strides, 6);
    for (i = 0; i < 6; i++) {
        assert_int_equal(dip[i], 1); /* the dip is a ZUPT in every swing */
        assert_int_equal(req[i], 4);
    }
    zc_run(FNAV_R(0.025), cyc, 6, dip, req, &strides, &lag);
    assert_int_equal(lag, 14);
    assert_int_equal(strides, 6);
    assert_int_equal(dip[0], 1); /* no cycle known yet: min_zupt_s */
    assert_int_equal(req[0], 4);
    for (i = 1; i < 6; i++) {
        assert_int_equal(req[i], 12);
        assert_int_equal(dip[i], 0);
    }
    /* a dip as long as the scaled run is a stance again: a raw run of 12 */
    for (i = 0; i < 6; i++) {
        cyc[i].gap_n = 14;
    }
    zc_run(FNAV_R(0.025), cyc, 6, dip, req, &strides, &lag);
    for (i = 0; i < 6; i++) {
        assert_int_equal(dip[i], 1);
    }
    /* one short cycle among long ones: a stance of 0.2 s makes the
     * interval between swing starts 2 and 3 1.4 s, a run of 7 samples,
     * which a dip of a raw 8 (a gap of 10) would pass; the median of the
     * last three keeps 12 and rejects it */
    for (i = 0; i < 6; i++) {
        cyc[i].gap_n = 10;
    }
    cyc[3].stance_n = 40;
    zc_run(FNAV_R(0.025), cyc, 6, dip, req, &strides, &lag);
    assert_int_equal(strides, 6);
    assert_int_equal(dip[0], 1);
    assert_int_equal(req[3], 12);
    assert_int_equal(req[4], 12);
    for (i = 1; i < 6; i++) {
        assert_int_equal(dip[i], 0);
    }
}

/* A fast gait (a cycle of 0.6 s, 100 steps/min per foot... a jog): 0.025
 * x 0.6 s x 200 Hz = 3 samples, below min_zupt_s's 4: the run stays at the
 * floor, and a dip of a raw 4 samples is a ZUPT as without the scaling
 * (running stances are short: footprint walk 35 broke with a fixed 50 ms,
 * docs/harness.md). */
static void test_zupt_cycle_fast_gait(void **state)
{
    zc_cycle_t cyc[8];
    int dip[8], dip0[8], req[8], lag, i;
    long strides;
    (void)state;
    zc_fill(cyc, 8, 40, 80, 60, 6);
    zc_run(FNAV_R(0.0), cyc, 8, dip0, req, &strides, &lag);
    assert_int_equal(strides, 8);
    zc_run(FNAV_R(0.025), cyc, 8, dip, req, &strides, &lag);
    assert_int_equal(strides, 8);
    for (i = 0; i < 8; i++) {
        assert_int_equal(req[i], 4);
        assert_int_equal(dip0[i], 1);
        assert_int_equal(dip[i], 1);
    }
}

/* A stand between strides: a "cycle" over FNAV_STANCE_CYCLE_MAX_S (4 s)
 * clears the cycles known, and the run is min_zupt_s's again until a
 * cycle is known after it (the swing after the stand takes its dip as
 * the first swing of a walk does); then the scaled run is back. Cycles
 * between FNAV_STANCE_CYCLE_LAG_S (3 s) and the bound get the look-ahead's
 * run, 15 samples. */
static void test_zupt_cycle_stand_resets(void **state)
{
    zc_cycle_t cyc[8];
    int dip[8], req[8], lag, i;
    long strides;
    (void)state;
    zc_fill(cyc, 8, 240, 240, 180, 8);
    cyc[4].stance_n = 1000; /* a stand of 5 s: the cycle into swing 4 is 6.2 s */
    zc_run(FNAV_R(0.025), cyc, 8, dip, req, &strides, &lag);
    assert_int_equal(strides, 8);
    for (i = 1; i < 4; i++) {
        assert_int_equal(req[i], 12);
        assert_int_equal(dip[i], 0);
    }
    assert_int_equal(req[4], 4); /* cleared by the stand */
    assert_int_equal(dip[4], 1);
    for (i = 5; i < 8; i++) {
        assert_int_equal(req[i], 12);
        assert_int_equal(dip[i], 0);
    }
    /* a pause just under the bound is a (slow) cycle: 3.9 s would give 20,
     * capped at the look-ahead's 15; the median keeps 12 */
    cyc[4].stance_n = 540;
    zc_run(FNAV_R(0.025), cyc, 8, dip, req, &strides, &lag);
    assert_int_equal(strides, 8);
    assert_int_equal(req[4], 12); /* median of 12, 12, 15 */
    assert_int_equal(dip[4], 0);
    /* cycles of 3.5 s in a row: the capped run, 15 samples (a raw dip of
     * 14 rejected, of 15 a stance) */
    for (i = 0; i < 8; i++) {
        cyc[i].stance_n = 460;
        cyc[i].gap_n = i < 5 ? 16 : 17;
    }
    zc_run(FNAV_R(0.025), cyc, 8, dip, req, &strides, &lag);
    assert_int_equal(strides, 8);
    assert_int_equal(lag, 14);
    for (i = 1; i < 8; i++) {
        assert_int_equal(req[i], 15);
        assert_int_equal(dip[i], i < 5 ? 0 : 1);
    }
}

/* The lock-in guard (fnav_stance.h): two slow cycles of 3 s (stances and
 * swings of 300 samples at 200 Hz) ask for the capped run, 15 samples; then
 * a fast gait (stances of 14 still samples, a raw run of 12; swings of 60)
 * whose stances are all shorter than that. Without the guard every one is
 * rejected, so the swing never ends, no cycle is measured and the run stays
 * at 15 for good: 2 strides (the slow one and the last stand's) where F = 0
 * finds 12. With it, once the last FNAV_STANCE_RAW_RUNS raw runs are the
 * short stances (the slow stances pushed out), the run is capped at half
 * of 12, and every later stance is a ZUPT: FNAV_STANCE_RAW_RUNS short
 * stances missed, 12 - FNAV_STANCE_RAW_RUNS strides. The slow gait's
 * late-swing dips stay rejected with the guard
 * (test_zupt_cycle_slow_gait: the stance, a raw run of 238, is among the
 * runs remembered, so the cap is 119 and does not bind). */
static void test_zupt_cycle_lock_in(void **state)
{
    zc_cycle_t cyc[12];
    int dip[12], req[12], lag, i;
    long strides;
    (void)state;
    for (i = 0; i < 12; i++) {
        cyc[i].stance_n = i < 2 ? 300 : 14;
        cyc[i].swing_n = i < 2 ? 300 : 60;
        cyc[i].gap_at = 0;
        cyc[i].gap_n = 0;
    }
    zc_run(FNAV_R(0.0), cyc, 12, dip, req, &strides, &lag);
    assert_int_equal(strides, 12);
    zc_run(FNAV_R(0.025), cyc, 12, dip, req, &strides, &lag);
    assert_int_equal(lag, 14);
    assert_int_equal(strides, 12 - FNAV_STANCE_RAW_RUNS);
    /* a milder slow start (cycles of 2 s: a run of 10, under the fast
     * stances' 12) locks nothing in: every stance is a ZUPT as with F = 0 */
    cyc[0].stance_n = 100;
    cyc[1].stance_n = 100;
    zc_run(FNAV_R(0.025), cyc, 12, dip, req, &strides, &lag);
    assert_int_equal(strides, 12);
    /* the slow gait's late-swing dips with the guard: three dips per swing
     * (raw runs of 6, 30 samples apart) leave the stance among the last
     * three runs when each dip is decided, so the cap (half of 238) does
     * not bind and every dip is rejected from the second swing; with F = 0
     * every one is a ZUPT. A fourth dip would push the stance out (the cap
     * falls to the floor, 4, and that dip passes). */
    zc_fill(cyc, 6, 240, 240, 100, 8);
    g_zc_dips = FNAV_STANCE_RAW_RUNS;
    zc_run(FNAV_R(0.0), cyc, 6, dip, req, &strides, &lag);
    for (i = 0; i < 6; i++) {
        assert_int_equal(dip[i], 1);
    }
    zc_run(FNAV_R(0.025), cyc, 6, dip, req, &strides, &lag);
    assert_int_equal(strides, 6);
    for (i = 1; i < 6; i++) {
        assert_int_equal(req[i], 12);
        assert_int_equal(dip[i], 0);
    }
    g_zc_dips = FNAV_STANCE_RAW_RUNS + 1;
    zc_run(FNAV_R(0.025), cyc, 6, dip, req, &strides, &lag);
    for (i = 1; i < 6; i++) {
        assert_int_equal(dip[i], 1);
    }
    g_zc_dips = 1;
}

/* The look-ahead with min_zupt_cycle: fixed at the rate for the longest
 * cycle, h + L samples of delay from the first sample (200 Hz, W = 5: h =
 * 2; 0.025 x 3 s x 200 Hz = 15, L = 14). At high rates the ring caps it
 * (FNAV_STANCE_CUT_ZUPT_CYCLE; 820 Hz: h = 10, L = MAX - 2 - 10). */
static void test_zupt_cycle_latency(void **state)
{
    fnav_stance_t st;
    fnav_stance_config_t c = fnav_stance_config_default;
    const double f[3] = { 0.0, 0.0, -k_g }, w[3] = { 0.0, 0.0, 0.0 };
    long next = 0, max_lag;
    (void)state;
    c.rate_hz = FNAV_R(200.0);
    c.min_zupt_cycle = FNAV_R(0.025);
    assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
    max_lag = still_delay(&st, &next);
    assert_int_equal(max_lag, 2 + 14);
    assert_int_equal(fnav_stance_pending(&st), 2 + 14);
    assert_int_equal(st.n_min_zupt, 4);
    assert_int_equal(st.n_zupt_req, 4);
    assert_int_equal(fnav_stance_cut(&st), 0u);
    c.rate_hz = FNAV_R(820.0);
    assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
    {
        fnav_sample_t s = sample(0, 820.0, f, w);
        assert_int_equal(fnav_stance_push(&st, &s), FNAV_OK);
    }
    assert_int_equal(st.half, 10);
    if (FNAV_STANCE_MAX_WINDOW - 2 - 10 < 61) {
        assert_int_equal(st.lag, FNAV_STANCE_MAX_WINDOW - 2 - 10);
        assert_int_equal(fnav_stance_cut(&st), FNAV_STANCE_CUT_ZUPT_CYCLE);
    } else {
        assert_int_equal(st.lag, 61); /* round(61.5) = 62 samples */
        assert_int_equal(fnav_stance_cut(&st), 0u);
    }
    assert_int_equal(st.n_min_zupt, 16); /* round(0.02 x 820) */
    /* the latency, h + L, at 100 and 400 Hz (docs/navigation.md, "Data flow
     * and latency"): 1 + 7 = 8 samples, 80 ms; 5 + 29 = 34, 85 ms, where the
     * ring holds it (the firmware's ring of 24 caps L at 24 - 2 - 5 = 17:
     * 22 samples) */
    c.rate_hz = FNAV_R(100.0);
    assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
    {
        fnav_sample_t s = sample(0, 100.0, f, w);
        assert_int_equal(fnav_stance_push(&st, &s), FNAV_OK);
    }
    assert_int_equal(st.half + st.lag, 1 + 7);
    c.rate_hz = FNAV_R(400.0);
    assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
    {
        fnav_sample_t s = sample(0, 400.0, f, w);
        assert_int_equal(fnav_stance_push(&st, &s), FNAV_OK);
    }
    assert_int_equal(st.half, 5);
    assert_int_equal(st.lag, FNAV_STANCE_MAX_WINDOW - 2 - 5 < 29 ? FNAV_STANCE_MAX_WINDOW - 2 - 5 : 29);
}

/* Zero specific force (an IMU that outputs zeros before its first
 * conversion, a stuck bus read): |mean f| = 0 has no direction; a statistic
 * taking g u = 0 would give T = 0 and the detector would call a dead sensor
 * (or one in free fall) at rest whatever its threshold. With a
 * zero mean, sum |f_j - g u|^2 = sum |f_j|^2 + W g^2 for every unit u:
 * T = g^2 / sigma_a^2 here, 9.6e5, above gamma. (The adaptive threshold's
 * ceiling, 10 gamma = 1e6, still lets a long run of zeros through: off
 * here.) The expected value is formed in double from the configuration's
 * own g and sigma_a (as fnav_real_t); the statistic rounds g^2, sigma_a^2,
 * the quotient and the division by W once each and sums W equal terms
 * (W - 1 roundings at most): (W + 4) EPS relative. (Not 1e-5 relative in
 * both builds against a hard-coded 0.01, 1e10 times the double build's
 * rounding.) */
static void test_zero_specific_force(void **state)
{
    fnav_stance_t st;
    fnav_stance_config_t c = fnav_stance_config_default;
    const double f[3] = { 0.0, 0.0, 0.0 }, w[3] = { 0.0, 0.0, 0.0 };
    const double want = ((double)c.gravity_mps2 * (double)c.gravity_mps2) /
                        ((double)c.sigma_a_mps2 * (double)c.sigma_a_mps2);
    fnav_stance_out_t o;
    long k, got = 0;
    (void)state;
    /* the documented defaults (fnav_stance.h), which make T 9.6e5 */
    assert_true(c.sigma_a_mps2 == FNAV_R(0.01) && c.gravity_mps2 == FNAV_R(9.80665));
    c.rate_hz = FNAV_R(200.0);
    c.adaptive = 0;
    assert_int_equal(fnav_stance_init(&st, &c), FNAV_OK);
    for (k = 0; k < 56; k++) { /* 40 popped: 16 held back (h + L) */
        fnav_sample_t s = sample(k, 200.0, f, w);
        assert_int_equal(fnav_stance_push(&st, &s), FNAV_OK);
        while (fnav_stance_pop(&st, &o) == FNAV_OK) {
            FNAV_ASSERT_CLOSE(o.stat, want, 0.0, ((double)st.win + 4.0) * EPS);
            assert_int_equal(o.raw_stance, 0);
            assert_int_equal(o.stance, 0);
            got++;
        }
    }
    assert_true(got > 30);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_config),
        cmocka_unit_test(test_config_squares),
        cmocka_unit_test(test_not_initialised),
        cmocka_unit_test(test_window_from_rate),
        cmocka_unit_test(test_rate_without_stamps),
        cmocka_unit_test(test_shoe_statistic),
        cmocka_unit_test(test_delay_and_flush),
        cmocka_unit_test(test_ring_contract),
        cmocka_unit_test(test_burst_push_same_decisions),
        cmocka_unit_test(test_first_samples_short_run),
        cmocka_unit_test(test_step_boundaries),
        cmocka_unit_test(test_short_dip_rejected),
        cmocka_unit_test(test_adaptive_threshold),
        cmocka_unit_test(test_threshold_detector),
        cmocka_unit_test(test_threshold_both_below),
        cmocka_unit_test(test_threshold_at_limit),
        cmocka_unit_test(test_gait_events),
        cmocka_unit_test(test_foot_strike_at_start),
        cmocka_unit_test(test_foot_off_window_edge),
        cmocka_unit_test(test_foot_off_short_pause),
        cmocka_unit_test(test_foot_strike_jumps_add_up),
        cmocka_unit_test(test_foot_strike_reference),
        cmocka_unit_test(test_foot_strike_long_min_stance),
        cmocka_unit_test(test_counters_long_run),
        cmocka_unit_test(test_rest_run_long),
        cmocka_unit_test(test_foot_strike_time_jump),
        cmocka_unit_test(test_foot_strike_across_wrap),
        cmocka_unit_test(test_cut_durations),
        cmocka_unit_test(test_zero_specific_force),
        cmocka_unit_test(test_zupt_cycle_slow_gait),
        cmocka_unit_test(test_zupt_cycle_fast_gait),
        cmocka_unit_test(test_zupt_cycle_stand_resets),
        cmocka_unit_test(test_zupt_cycle_lock_in),
        cmocka_unit_test(test_zupt_cycle_latency),
    };
    return cmocka_run_group_tests_name("stance", tests, NULL, NULL);
}
