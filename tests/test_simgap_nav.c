/* Tests of the walk domain's building blocks of the sim-to-real gap
 * diagnosis (harness/hx_simgap_nav.h, docs/simgap.md "Walks"): the sensor's
 * linear error from the one fitted on the filter's trajectory, the
 * matching of real and twin stances, and the navigation points of a run. End-to-end walk diagnoses are in
 * tests/cli/test_simgap.sh. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include <cjson/cJSON.h>

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

/* A fitted value beyond the catalogue's range is set to the bound and
 * flagged, never reported as a fit (analytic): a scale b on the trajectory
 * is the sensor's b / (1 - b), so b = 0.95 is 19, past sf's upper bound 10;
 * b = 1 (I - B singular) is past it too; a misalignment whose trajectory
 * value was already clamped to -1 stays flagged; jointly, scale gx 0.5 with
 * misalign gx.from_z 0.6 on the trajectory are the sensor's 1.0 and 1.2
 * (the (3, 5) block of B (I - B)^-1: [0.5 0.6; 0 0] [2 1.2; 0 1]), the
 * second past misalign's bound 1. A clamped value reported as a fit with
 * no flag fails. */
static void test_sensor_values_at_bound(void **state)
{
    double B[6][6], val[2];
    int ch[2], k[2], at[2], eq_at[2] = { 0, 0 };
    double eq[2];
    (void)state;
    memset(B, 0, sizeof B);
    B[5][5] = 0.95;
    B[0][0] = -0.5;
    ch[0] = 5;
    k[0] = 0;
    eq[0] = 0.95;
    ch[1] = 0;
    k[1] = 0;
    eq[1] = -0.5;
    assert_int_equal(sg_nav_sensor_values((const double(*)[6])B, FNAV_EFFECT_SCALE, 2, ch, k, eq, NULL, val, at), 1);
    FNAV_ASSERT_CLOSE(val[0], 10.0, 0.0, 0.0);
    assert_int_equal(at[0], 1);
    FNAV_ASSERT_CLOSE(val[1], -0.5 / 1.5, 1e-12, 0.0);
    assert_int_equal(at[1], 0);
    /* singular */
    B[5][5] = 1.0;
    eq[0] = 1.0;
    assert_int_equal(sg_nav_sensor_values((const double(*)[6])B, FNAV_EFFECT_SCALE, 1, ch, k, eq, NULL, val, at), 1);
    FNAV_ASSERT_CLOSE(val[0], 10.0, 0.0, 0.0);
    assert_int_equal(at[0], 1);
    /* a trajectory value clamped already: misalign gx.from_z (column gz) */
    memset(B, 0, sizeof B);
    B[3][5] = -1.0;
    ch[0] = 3;
    k[0] = 2;
    eq[0] = -1.0;
    eq_at[0] = -1;
    assert_int_equal(
        sg_nav_sensor_values((const double(*)[6])B, FNAV_EFFECT_MISALIGN, 1, ch, k, eq, eq_at, val, at), 1);
    FNAV_ASSERT_CLOSE(val[0], -1.0, 0.0, 0.0);
    assert_int_equal(at[0], -1);
    eq_at[0] = 0;
    B[3][5] = eq[0] = 0.02;
    assert_int_equal(
        sg_nav_sensor_values((const double(*)[6])B, FNAV_EFFECT_MISALIGN, 1, ch, k, eq, eq_at, val, at), 0);
    FNAV_ASSERT_CLOSE(val[0], 0.02, 1e-15, 0.0);
    assert_int_equal(at[0], 0);
    /* jointly: the misalignment past its bound */
    B[3][3] = 0.5;
    B[3][5] = eq[0] = 0.6;
    assert_int_equal(
        sg_nav_sensor_values((const double(*)[6])B, FNAV_EFFECT_MISALIGN, 1, ch, k, eq, eq_at, val, at), 1);
    FNAV_ASSERT_CLOSE(val[0], 1.0, 0.0, 0.0);
    assert_int_equal(at[0], 1);
    ch[0] = 3;
    k[0] = 0;
    eq[0] = 0.5;
    assert_int_equal(sg_nav_sensor_values((const double(*)[6])B, FNAV_EFFECT_SCALE, 1, ch, k, eq, NULL, val, at), 0);
    FNAV_ASSERT_CLOSE(val[0], 1.0, 1e-12, 0.0);
    assert_int_equal(at[0], 0);
    /* a bad index */
    k[0] = 3;
    assert_int_equal(sg_nav_sensor_values((const double(*)[6])B, FNAV_EFFECT_MISALIGN, 1, ch, k, eq, NULL, val, at),
                     -1);
}

/* The summary and the JSON say so: the text names the bound and what the
 * value is, the JSON's `bounds` gives the range and which bound (null
 * inside; `bounds` null for an effect with no range searched). */
static void test_param_at_bound_outputs(void **state)
{
    char b[160];
    cJSON *p = cJSON_CreateObject(), *bd;
    (void)state;
    sg_nav_param_text(b, sizeof b, FNAV_EFFECT_SCALE, 5, 0, 10.0, 1);
    assert_string_equal(b, "gz.sf=10 at the catalogue's bound: only a lower limit");
    sg_nav_param_text(b, sizeof b, FNAV_EFFECT_MISALIGN, 3, 2, -1.0, -1);
    assert_string_equal(b, "gx.from_z=-1 at the catalogue's bound: only an upper limit");
    sg_nav_param_text(b, sizeof b, FNAV_EFFECT_SCALE, 5, 0, 0.25, 0);
    assert_string_equal(b, "gz.sf=0.25");
    sg_nav_bounds_json(p, FNAV_EFFECT_SCALE, 0, 1);
    bd = cJSON_GetObjectItem(p, "bounds");
    assert_non_null(bd);
    FNAV_ASSERT_CLOSE(cJSON_GetObjectItem(bd, "lo")->valuedouble, -0.9, 0.0, 0.0);
    FNAV_ASSERT_CLOSE(cJSON_GetObjectItem(bd, "hi")->valuedouble, 10.0, 0.0, 0.0);
    assert_string_equal(cJSON_GetObjectItem(bd, "at_bound")->valuestring, "upper");
    cJSON_Delete(p);
    p = cJSON_CreateObject();
    sg_nav_bounds_json(p, FNAV_EFFECT_GSENS, 1, 0);
    assert_true(cJSON_IsNull(cJSON_GetObjectItem(cJSON_GetObjectItem(p, "bounds"), "at_bound")));
    cJSON_Delete(p);
    p = cJSON_CreateObject();
    sg_nav_bounds_json(p, FNAV_EFFECT_QUANT, 0, 0);
    assert_true(cJSON_IsNull(cJSON_GetObjectItem(p, "bounds")));
    cJSON_Delete(p);
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
    assert_int_equal(sg_nav_draw_case(&o, t, 0u, &rng, &cs, &cfg, script, sizeof script, why, sizeof why), -1);
    assert_non_null(strstr(why, "zero-velocity updates of the simulated walk could be matched, 5 needed"));
}

/* The navigation points of a hand-made filter run (sg_nav_stance_points),
 * against values worked out by hand from docs/simgap.md's definitions.
 * 60 samples at 100 Hz; updates at 5, 6, 7, 9 (one stance: gaps of up to 2
 * samples join), 20-22 and 40-41: three stances, nine updates. The
 * innovations' covariance is diag(1, 4, 9) except at sample 5, S = L L^T
 * with L = [2 0 0; 1 2 0; 1 1 3], y = L (1, 1, 1), so that every normalised
 * innovation e = L^-1 y is a vector of small integers:
 *   stance 1: e (1,1,1) (1,0,0) (0,1,0) (1,1,1), sum e_k.e_k+1 2, sum |e|^2 8
 *   stance 2: e (2,0,0) (2,1,0) (0,0,1):               4, 10
 *   stance 3: e (0,1,1) (0,-1,-1):                     -2, 4
 * whiteness 4/22; NIS of the first updates 3, 2, 5 (mean 10/3), of all
 * 18/9 = 2; first innovation squared over its variance per axis: x
 * (1 + 4 + 0)/3, y (9/5 + 0 + 1)/3, z (25/11 + 0 + 1)/3; speeds at
 * mid-stance (samples 7, 21, 40) 0.1, 0.2, 0.3, RMS sqrt(0.14/3); two
 * windows of 0.295 s: first NIS 3 and 2 in the first, 5 in the second;
 * the drift from mid-stance 7 to 40 (3, 4, 2): horizontal 5, vertical 2.
 * Without this test, a whiteness without the z component, the residual
 * velocity's ln without the 1/2 of the RMS, stances split at a gap of 2
 * samples, the wrong sign in the whitening, the off-diagonal covariance
 * read as the y and z variances, the mean NIS over stances instead of
 * updates, the drift's vertical from the y axis and the residual speed at
 * the stance's first sample (hand-made mutants) would be caught, if at
 * all, only by the 4-minute CLI walk tests. */
static void test_stance_points(void **state)
{
    enum { N = 60 };
    static int64_t t[N];
    static unsigned char zupt[N];
    static double y[N][3], S[N][6], nis[N], v[N][3], p[N][3];
    static const int upd[] = { 5, 6, 7, 9, 20, 21, 22, 40, 41 };
    static const double ey[9][3] = { { 2, 3, 5 }, { 1, 0, 0 }, { 0, 2, 0 }, { 1, 2, 3 }, { 2, 0, 0 },
                                     { 2, 2, 0 }, { 0, 0, 3 }, { 0, 2, 3 }, { 0, -2, -3 } };
    static const double en[9] = { 3, 1, 1, 3, 2, 1, 1, 5, 1 };
    double vals[16];
    sg_plist_t pl;
    long cnt;
    int i, k;
    (void)state;
    memset(&pl, 0, sizeof pl);
    for (k = 0; k < N; k++) {
        t[k] = (int64_t)k * 10000000;
    }
    for (i = 0; i < 9; i++) {
        k = upd[i];
        zupt[k] = 1;
        memcpy(y[k], ey[i], sizeof y[k]);
        S[k][0] = 1.0;
        S[k][3] = 4.0;
        S[k][5] = 9.0;
        nis[k] = en[i];
    }
    /* L = [2 0 0; 1 2 0; 1 1 3]: S = L L^T = [4 2 2; 2 5 3; 2 3 11] */
    S[5][0] = 4.0;
    S[5][1] = 2.0;
    S[5][2] = 2.0;
    S[5][3] = 5.0;
    S[5][4] = 3.0;
    S[5][5] = 11.0;
    v[7][0] = 0.1;
    v[21][1] = 0.2;
    v[40][2] = 0.3;
    p[7][0] = p[7][1] = p[7][2] = 1.0;
    p[40][0] = 4.0;
    p[40][1] = 5.0;
    p[40][2] = 3.0;
    cnt = sg_nav_stance_points(N, t, zupt, (const double(*)[3])y, (const double(*)[6])S, nis,
                               (const double(*)[3])v, (const double(*)[3])p, 2, 1, vals, &pl);
    assert_int_equal(cnt, 11);
    assert_int_equal((int)pl.n, 11);
    FNAV_ASSERT_CLOSE(vals[0], log(10.0 / 3.0), 1e-12, 0.0);
    FNAV_ASSERT_CLOSE(vals[1], log(2.0), 1e-12, 0.0);
    FNAV_ASSERT_CLOSE(vals[2], log(5.0 / 3.0), 1e-12, 0.0);
    FNAV_ASSERT_CLOSE(vals[3], log(2.8 / 3.0), 1e-12, 0.0);
    FNAV_ASSERT_CLOSE(vals[4], log(12.0 / 11.0), 1e-12, 0.0);
    FNAV_ASSERT_CLOSE(vals[5], 4.0 / 22.0, 1e-12, 0.0);
    FNAV_ASSERT_CLOSE(vals[6], 0.5 * log(0.14 / 3.0), 1e-12, 0.0);
    FNAV_ASSERT_CLOSE(vals[7], log(2.5), 1e-12, 0.0);
    FNAV_ASSERT_CLOSE(vals[8], log(5.0), 1e-12, 0.0);
    FNAV_ASSERT_CLOSE(vals[9], log(5.0), 1e-12, 0.0);
    FNAV_ASSERT_CLOSE(vals[10], log(2.0), 1e-12, 0.0);
    for (i = 0; i < 11; i++) {
        static const int kind[11] = { SG_NAV_NIS_FIRST, SG_NAV_NIS_ALL, SG_NAV_AXIS, SG_NAV_AXIS, SG_NAV_AXIS,
                                      SG_NAV_WHITE, SG_NAV_RESID, SG_NAV_WIN, SG_NAV_WIN, SG_NAV_DRIFT_H,
                                      SG_NAV_DRIFT_V };
        assert_int_equal(pl.p[i].dom, SG_NAV);
        assert_int_equal(pl.p[i].kind, kind[i]);
        assert_int_equal(pl.p[i].empty, 0);
    }
    /* the windows: [0, 0.295) and [0.295, 0.59) s */
    FNAV_ASSERT_CLOSE(pl.p[7].x_hi, 0.295, 1e-12, 0.0);
    FNAV_ASSERT_CLOSE(pl.p[8].x_lo, 0.295, 1e-12, 0.0);
    sg_plist_free(&pl);
}

/* The windows cover the segment to its last sample: a stance whose first
 * update is the segment's last sample belongs to the last window. 30
 * samples at 100 Hz (t 0-0.29 s), two windows [0, 0.145) and [0.145,
 * 0.29]; stances at samples 2 (NIS 2) and 29 (NIS 7). Were the last window
 * half-open, the second stance would be in no window (counted in the mean
 * first-update NIS, 4.5, but not in its window) and the window an empty
 * placeholder. */
static void test_stance_points_last_sample(void **state)
{
    enum { N = 30 };
    static int64_t t[N];
    static unsigned char zupt[N];
    static double y[N][3], S[N][6], nis[N], v[N][3], p[N][3];
    double vals[16];
    sg_plist_t pl;
    long cnt;
    int k;
    (void)state;
    memset(&pl, 0, sizeof pl);
    for (k = 0; k < N; k++) {
        t[k] = (int64_t)k * 10000000;
        S[k][0] = S[k][3] = S[k][5] = 1.0;
    }
    zupt[2] = zupt[N - 1] = 1;
    nis[2] = 2.0;
    nis[N - 1] = 7.0;
    cnt = sg_nav_stance_points(N, t, zupt, (const double(*)[3])y, (const double(*)[6])S, nis,
                               (const double(*)[3])v, (const double(*)[3])p, 2, 0, vals, &pl);
    assert_int_equal(cnt, 9);
    FNAV_ASSERT_CLOSE(vals[0], log(4.5), 1e-12, 0.0);
    assert_int_equal(pl.p[7].kind, SG_NAV_WIN);
    assert_int_equal(pl.p[7].empty, 0);
    FNAV_ASSERT_CLOSE(vals[7], log(2.0), 1e-12, 0.0);
    assert_int_equal(pl.p[8].kind, SG_NAV_WIN);
    assert_int_equal(pl.p[8].empty, 0);
    FNAV_ASSERT_CLOSE(vals[8], log(7.0), 1e-12, 0.0);
    sg_plist_free(&pl);
}

/* A long walk: more stances than 4,096 (a fixed list's size). 5,000
 * one-update stances 5 samples apart at 100 Hz (250 s); every first NIS 1
 * but the last stance's, 1001 (mean 1.2), the last at (3, 4, 0) m from the
 * first (horizontal drift 5 m), ten windows of 25 s. Were the stances
 * after the 4,096th dropped without a word, the mean NIS would read 1, the
 * drift run to stance 4,096 and the last window (stances 4,500 on) be an
 * empty placeholder (a 90-minute walk at a normal cadence has about
 * 4,900). */
static void test_stance_points_many(void **state)
{
    enum { NS = 5000, GAP = 5, N = NS * GAP, NWIN = 10 };
    static int64_t t[N];
    static unsigned char zupt[N];
    static double y[N][3], S[N][6], nis[N], v[N][3], p[N][3];
    double vals[8 + NWIN + 2];
    sg_plist_t pl;
    long cnt;
    int k;
    (void)state;
    memset(&pl, 0, sizeof pl);
    for (k = 0; k < N; k++) {
        t[k] = (int64_t)k * 10000000;
        S[k][0] = S[k][3] = S[k][5] = 1.0;
        if (k % GAP == 0) {
            zupt[k] = 1;
            nis[k] = 1.0;
        }
    }
    nis[(NS - 1) * GAP] = 1001.0;
    p[(NS - 1) * GAP][0] = 3.0;
    p[(NS - 1) * GAP][1] = 4.0;
    cnt = sg_nav_stance_points(N, t, zupt, (const double(*)[3])y, (const double(*)[6])S, nis,
                               (const double(*)[3])v, (const double(*)[3])p, NWIN, 1, vals, &pl);
    assert_int_equal(cnt, 7 + NWIN + 2);
    FNAV_ASSERT_CLOSE(vals[0], log(1.2), 1e-12, 0.0);
    assert_int_equal(pl.p[7 + NWIN - 1].kind, SG_NAV_WIN);
    assert_int_equal(pl.p[7 + NWIN - 1].empty, 0);
    FNAV_ASSERT_CLOSE(vals[7 + NWIN - 1], log((499.0 + 1001.0) / 500.0), 1e-12, 0.0);
    assert_int_equal(pl.p[7 + NWIN].kind, SG_NAV_DRIFT_H);
    FNAV_ASSERT_CLOSE(vals[7 + NWIN], log(5.0), 1e-12, 0.0);
    sg_plist_free(&pl);
}

/* The stances the fit of the motion effects takes (sg_nav_stance_starts)
 * on the 5,000-stance run of test_stance_points_many: every one. With
 * arrays of 4,096 the later stances (on a 90-minute walk a third of the
 * held-out ones) would be left out of the fit and its held-out test
 * without a word. */
static void test_stance_starts_many(void **state)
{
    enum { NS = 5000, GAP = 5, N = NS * GAP };
    static int64_t t[N];
    static unsigned char zupt[N];
    static double ts[NS];
    int k;
    (void)state;
    for (k = 0; k < N; k++) {
        t[k] = (int64_t)k * 10000000;
        zupt[k] = k % GAP == 0;
    }
    assert_int_equal(sg_nav_stance_starts(N, t, zupt, ts, NS), NS);
    FNAV_ASSERT_CLOSE(ts[NS - 1], 0.01 * (NS - 1) * GAP, 1e-9, 0.0);
}

/* The held-out part of a walk split at a sample (docs/simgap.md, section
 * 2) begins with the first stance that begins at or after the split: a
 * stance in progress at the split began in the fit segment and is the
 * fit's. 180 samples at 100 Hz; runs of updates at 10-20, 50-65, 95-105,
 * 110-112 (a piece of the stance 95-105: 0.05 s after it, less than the
 * shortest swing of 0.25 s) and 145-155; first-update NIS 2, 3, 5, 1, 7
 * and 0.5 at sample 60 (mid-stance). Split at 60, inside the second
 * stance: held out from 95, two stances (the third with its piece, the
 * fourth), mean first-update NIS of the runs (5 + 1 + 7) / 3. A held-out
 * part beginning at the split sample would hold out the stance 50-65 too
 * (three stances), with its mid-stance update at 60 as its "first" (mean
 * (0.5 + 5 + 1 + 7) / 4). A split in the gap
 * before the piece (107) holds out from 145; one at a stance's first
 * update (95) from it; one after the last stance none. */
static void test_held_out_whole_stances(void **state)
{
    enum { N = 180 };
    static int64_t t[N];
    static unsigned char zupt[N];
    static double y[N][3], S[N][6], nis[N], v[N][3], p[N][3];
    static const int run[5][2] = { { 10, 20 }, { 50, 65 }, { 95, 105 }, { 110, 112 }, { 145, 155 } };
    static const double first[5] = { 2.0, 3.0, 5.0, 1.0, 7.0 };
    double vals[16];
    sg_plist_t pl;
    long from = -1, cnt;
    int i, k;
    (void)state;
    memset(&pl, 0, sizeof pl);
    for (k = 0; k < N; k++) {
        t[k] = (int64_t)k * 10000000;
        S[k][0] = S[k][3] = S[k][5] = 1.0;
    }
    for (i = 0; i < 5; i++) {
        for (k = run[i][0]; k <= run[i][1]; k++) {
            zupt[k] = 1;
        }
        nis[run[i][0]] = first[i];
    }
    nis[60] = 0.5;
    assert_int_equal(sg_nav_held_out_stances(N, t, zupt, 60, 0.25, &from), 2);
    assert_int_equal(from, 95);
    assert_int_equal(sg_nav_held_out_stances(N, t, zupt, 107, 0.25, &from), 1);
    assert_int_equal(from, 145);
    assert_int_equal(sg_nav_held_out_stances(N, t, zupt, 95, 0.25, &from), 2);
    assert_int_equal(from, 95);
    assert_int_equal(sg_nav_held_out_stances(N, t, zupt, 0, 0.25, &from), 4);
    assert_int_equal(from, 10);
    assert_int_equal(sg_nav_held_out_stances(N, t, zupt, 170, 0.25, &from), 0);
    assert_int_equal(from, N);
    cnt = sg_nav_held_out_points(N, t, zupt, (const double(*)[3])y, (const double(*)[6])S, nis,
                                 (const double(*)[3])v, (const double(*)[3])p, 60, 0.25, 1, vals, &pl);
    assert_int_equal(cnt, 8);
    FNAV_ASSERT_CLOSE(vals[0], log(13.0 / 3.0), 1e-12, 0.0);
    /* the window spans the segment from the split sample: 0.6-1.79 s */
    assert_int_equal(pl.p[7].kind, SG_NAV_WIN);
    FNAV_ASSERT_CLOSE(pl.p[7].x_lo, 0.6, 1e-12, 0.0);
    FNAV_ASSERT_CLOSE(pl.p[7].x_hi, 1.79, 1e-12, 0.0);
    FNAV_ASSERT_CLOSE(vals[7], log(13.0 / 3.0), 1e-12, 0.0);
    sg_plist_free(&pl);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lin_to_sensor_analytic),
        cmocka_unit_test(test_lin_to_sensor_inverse),
        cmocka_unit_test(test_sensor_values_at_bound),
        cmocka_unit_test(test_param_at_bound_outputs),
        cmocka_unit_test(test_match_swing),
        cmocka_unit_test(test_draw_case_reason),
        cmocka_unit_test(test_stance_points),
        cmocka_unit_test(test_stance_points_last_sample),
        cmocka_unit_test(test_stance_points_many),
        cmocka_unit_test(test_stance_starts_many),
        cmocka_unit_test(test_held_out_whole_stances),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
