/* The simulator's ideal samples through the project's own strapdown
 * (src/fnav_strapdown.c): the motion truth and the strapdown agree.
 * Interval-mean samples (--decimation mean, the strapdown's convention) of
 * an ideal sensor, integrated by fnav_strapdown_step from the true initial
 * state, return the true trajectory within the strapdown's own
 * discretisation error: stated tolerance 15 cm after a 20 m walk with a 90
 * degree turn at 200 Hz and 4 cm at 400 Hz (no zero-velocity updates: pure
 * integration of 14 strides, pitch rates up to 10 rad/s), and the error
 * falls as the square of the interval (a second-order algorithm: at least
 * 3x per doubling of the rate). Measured: 9.5 cm at 200 Hz in float and
 * double; 2.0 cm (float) and 2.1 cm (double) at 400 Hz. The same with
 * instantaneous samples (--decimation fir, a rate-output sensor)
 * integrated with FNAV_SAMPLE_INSTANT; and the mismatch
 * (instantaneous samples taken for interval means) is worse at both rates.
 * The 15 and 4 cm are stated, not derived (about 1.5 and 2 times the
 * errors). In the double build each error is also held to twice its
 * Richardson estimate from the two rates (|p_200 - p_400| / 3 at 400 Hz,
 * 4 times that at 200 Hz; exact up to the next order, the errors
 * measured 0.82 to 1.18 of them: means 10.1 / 2.5 cm estimated for
 * 9.5 / 2.1 cm, instantaneous 10.0 / 2.5 cm for 10.0 / 3.0 cm), which an error that does
 * not fall with the interval (a truth inconsistent with its samples, a
 * sample-time offset) fails. The float build's own rounding (0.4 mm at
 * 400 Hz against double) has no derived bound here, so it keeps the
 * stated ones. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "hx_sim.h"
#include "support/fnav_testdata.h"

#include "footnav/fnav_strapdown.h"

typedef struct {
    fnav_strapdown_config_t cfg;
    fnav_strapdown_state_t x;
    fnav_strapdown_hist_t h;
    double rate;
    int started;
    int bad;
    hx_truth_t last;
} sd_t;

static int sd_sink(void *ctx, const hx_sim_tick_t *tk)
{
    sd_t *s = (sd_t *)ctx;
    fnav_vec3_t w, f;
    int c;
    if (!s->started) {
        /* the true state at the first stamp */
        s->started = 1;
        for (c = 0; c < 4; c++) {
            s->x.q_nb.q[c] = (fnav_real_t)tk->truth.q_nb[c];
        }
        for (c = 0; c < 3; c++) {
            s->x.vel_mps.v[c] = (fnav_real_t)tk->truth.vel_mps[c];
            s->x.pos_m.v[c] = (fnav_real_t)tk->truth.pos_m[c];
        }
        memset(&s->h, 0, sizeof s->h);
        return 0;
    }
    for (c = 0; c < 3; c++) {
        w.v[c] = tk->meas.gyro_rps[c];
        f.v[c] = tk->meas.accel_mps2[c];
    }
    if (fnav_strapdown_step(&s->cfg, &s->x, &s->h, w, f, (fnav_real_t)(1.0 / s->rate)) !=
        FNAV_OK) {
        s->bad++;
    }
    s->last = tk->truth;
    return 0;
}

static double final_error(const hx_motion_t *m, double rate, hx_decim_t decim, fnav_sample_type_t type,
                          double pos_m[3])
{
    hx_sim_config_t c;
    sd_t s;
    char err[256];
    double d2 = 0.0;
    int k;
    memset(&s, 0, sizeof s);
    s.cfg = fnav_strapdown_config_default;
    s.cfg.sample_type = type;
    s.rate = rate;
    c.motion = m;
    c.err = fnav_imuerr_config_default; /* every effect off: an ideal sensor */
    c.err.rate_hz = (fnav_real_t)rate;
    c.err.oversample = (uint32_t)ceil(8000.0 / rate);
    c.duration_s = 0.0;
    c.decim = decim;
    assert_int_equal(hx_sim_run(&c, sd_sink, &s, err, sizeof err), 0);
    assert_int_equal(s.bad, 0);
    for (k = 0; k < 3; k++) {
        double e = (double)s.x.pos_m.v[k] - s.last.pos_m[k];
        d2 += e * e;
        pos_m[k] = (double)s.x.pos_m.v[k];
    }
    fprintf(stderr, "fnav_strapdown at %g Hz, %s samples integrated as %s: %.4f m from the truth after %.1f m\n",
            rate, decim == HX_DECIM_MEAN ? "interval-mean" : "instantaneous",
            type == FNAV_SAMPLE_MEAN ? "means" : "instantaneous", sqrt(d2), s.last.odo_m);
    return sqrt(d2);
}

/* Richardson's estimate of the 400 Hz error of a second-order algorithm
 * from its 200 and 400 Hz final positions: |p_200 - p_400| / 3 (the 200 Hz
 * error is 4 times it). */
static double richardson(const double p200[3], const double p400[3])
{
    double r = 0.0;
    int k;
    for (k = 0; k < 3; k++) {
        r += (p200[k] - p400[k]) * (p200[k] - p400[k]);
    }
    return sqrt(r) / 3.0;
}

static void test_project_strapdown(void **state)
{
    char err[256];
    hx_motion_config_t mc = hx_motion_config_default();
    hx_motion_t *m = hx_motion_create(&mc, "stand:1,walk:20:90,stand:1", 0.0, err, sizeof err);
    double e200, e400, i200, i400, x200, x400, p200[3], p400[3], q200[3], q400[3], re, ri;
    (void)state;
    assert_non_null(m);
    e200 = final_error(m, 200.0, HX_DECIM_MEAN, FNAV_SAMPLE_MEAN, p200);
    e400 = final_error(m, 400.0, HX_DECIM_MEAN, FNAV_SAMPLE_MEAN, p400);
    re = richardson(p200, p400);
    assert_true(e200 < 0.15);
    assert_true(e400 < 0.04);
    assert_true(e200 / e400 > 3.0);
    i200 = final_error(m, 200.0, HX_DECIM_FIR, FNAV_SAMPLE_INSTANT, q200);
    i400 = final_error(m, 400.0, HX_DECIM_FIR, FNAV_SAMPLE_INSTANT, q400);
    ri = richardson(q200, q400);
    fprintf(stderr, "Richardson's estimates: means %.4f m at 200 Hz, %.4f m at 400 Hz; instantaneous %.4f m, %.4f m\n",
            4.0 * re, re, 4.0 * ri, ri);
    x200 = final_error(m, 200.0, HX_DECIM_FIR, FNAV_SAMPLE_MEAN, q200);
    x400 = final_error(m, 400.0, HX_DECIM_FIR, FNAV_SAMPLE_MEAN, q400);
    assert_true(i200 < 0.15);
    assert_true(i400 < 0.04);
    assert_true(x200 > i200 && x400 > i400);
#if FNAV_USE_DOUBLE
    /* the error is the strapdown's discretisation: within twice Richardson's
     * estimate of it (the comment at the top) */
    assert_true(e200 <= 2.0 * 4.0 * re && e400 <= 2.0 * re);
    assert_true(i200 <= 2.0 * 4.0 * ri && i400 <= 2.0 * ri);
#endif
    hx_motion_free(m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_project_strapdown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
