/* Tests of the streaming Welch PSD and the bandwidth rule (src/fnav_welch.c)
 * against scipy.signal.welch vectors (vectors/welch/gen_welch.py), the last
 * segment's spectrum with the global-mean detrending against
 * scipy.signal.periodogram, and analytic cases. */
#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "footnav/fnav_welch.h"
#include "support/fnav_testdata.h"

/* Per-bin relative tolerance against scipy: 1e-11 in double, measured
 * 3.7e-14 (printed by test_against_scipy), 270 times that left for another
 * libm's sin and cos; the requirement, 1e-6, is 2.7e7 times the
 * error and let a Hamming coefficient 2e-9 off (0.460000001: 1e-8 per bin)
 * pass. Float: the
 * input itself is rounded to 24 bits and a 9.81 offset sits under 0.3 of
 * signal; measured worst 1.4e-5 relative to its bin and 4.2e-7 relative to
 * the largest bin (2.0e-4 and 5.2e-7 before the segment's mean was summed
 * about its first sample); asserted per bin at 1e-3 relative to the bin or
 * 1e-6 of the largest bin, whichever is larger. */
#if FNAV_USE_DOUBLE
#define BIN_REL 1e-11
#define PEAK_REL 0.0
#define BAND_REL 1e-9
#else
#define BIN_REL 1e-3
#define PEAK_REL 1e-6
#define BAND_REL 1e-4
#endif

static size_t read_series(const char *rel, double *x, size_t max)
{
    char path[512], line[128];
    FILE *f;
    size_t n = 0;
    if (fnav_vector_path(rel, path, sizeof path) != 0 || (f = fopen(path, "r")) == NULL) {
        return 0;
    }
    while (fgets(line, sizeof line, f) != NULL && n < max) {
        if (line[0] != '#') {
            x[n++] = strtod(line, NULL);
        }
    }
    fclose(f);
    return n;
}

typedef struct {
    char name[64], input[16], window[16], detrend[16], scaling[16];
    double fs;
    unsigned nfft, overlap, nbins;
    int sym;
} vcase_t;

static int parse_case(const char *line, vcase_t *c)
{
    return sscanf(line, "case,%63[^,],%15[^,],%lf,%u,%u,%15[^,],%d,%15[^,],%15[^,],%u", c->name, c->input, &c->fs,
                  &c->nfft, &c->overlap, c->window, &c->sym, c->detrend, c->scaling, &c->nbins) == 10;
}

static void config_of(const vcase_t *c, fnav_welch_config_t *cfg)
{
    *cfg = fnav_welch_config_default;
    cfg->nfft = c->nfft;
    cfg->overlap = c->overlap;
    cfg->window = strcmp(c->window, "hamming") == 0 ? FNAV_WINDOW_HAMMING
                  : strcmp(c->window, "hann") == 0  ? FNAV_WINDOW_HANN
                                                    : FNAV_WINDOW_RECT;
    cfg->symmetric = c->sym;
    cfg->detrend = strcmp(c->detrend, "none") == 0       ? FNAV_DETREND_NONE
                   : strcmp(c->detrend, "constant") == 0 ? FNAV_DETREND_CONSTANT
                   : strcmp(c->detrend, "global") == 0   ? FNAV_DETREND_GLOBAL
                                                         : FNAV_DETREND_LINEAR;
    cfg->scaling = strcmp(c->scaling, "density") == 0 ? FNAV_SCALING_DENSITY : FNAV_SCALING_SPECTRUM;
    cfg->rate_hz = (fnav_real_t)c->fs;
}

/* The two input series of the vectors (read once), and a case's input. */
static double g_synth[6000], g_os820[9000];
static size_t g_nsyn, g_nos;

static void load_inputs(void)
{
    if (g_nsyn == 0u) {
        g_nsyn = read_series("welch/welch_input_synth.txt", g_synth, 6000);
        g_nos = read_series("welch/welch_input_os820.txt", g_os820, 9000);
    }
    assert_int_equal(g_nsyn, 5000);
    assert_int_equal(g_nos, 8192);
}

/* A vector file of vectors/, opened for reading. */
static FILE *open_vector(const char *rel)
{
    char path[512];
    FILE *f;
    assert_int_equal(fnav_vector_path(rel, path, sizeof path), 0);
    f = fopen(path, "r");
    assert_non_null(f);
    return f;
}

/* Push case c's input through w (its segment count and bins checked) and
 * read the average (fnav_welch_get) or, with last, the last segment's
 * periodogram (fnav_welch_last) into psd. */
static void run_case(fnav_welch_t *w, const vcase_t *c, int last, fnav_real_t *psd)
{
    fnav_welch_config_t cfg;
    const int syn = strcmp(c->input, "synth") == 0;
    const double *x = syn ? g_synth : g_os820;
    const size_t n = syn ? g_nsyn : g_nos;
    size_t i;
    config_of(c, &cfg);
    assert_int_equal(fnav_welch_init(w, &cfg), FNAV_OK);
    for (i = 0; i < n; i++) {
        assert_int_equal(fnav_welch_push(w, (fnav_real_t)x[i]), FNAV_OK);
    }
    assert_int_equal(fnav_welch_segments(w), (n - c->nfft) / (c->nfft - c->overlap) + 1u);
    assert_int_equal(fnav_welch_bins(w), c->nbins);
    if (last) {
        assert_int_equal(fnav_welch_last(w, psd, FNAV_WELCH_MAX_BINS), FNAV_OK);
    } else {
        assert_int_equal(fnav_welch_get(w, psd, FNAV_WELCH_MAX_BINS), FNAV_OK);
    }
}

/* Compare a case's spectrum with scipy's, bin by bin: within BIN_REL of the
 * bin or PEAK_REL of the largest bin. The worst relative errors found are
 * raised into *worst and *worst_peak. */
static void compare_bins(const char *what, const vcase_t *c, const fnav_real_t *psd, const double *expect,
                         double *worst, double *worst_peak)
{
    double peak = 0.0;
    size_t i;
    for (i = 0; i < c->nbins; i++) {
        peak = expect[i] > peak ? expect[i] : peak;
    }
    for (i = 0; i < c->nbins; i++) {
        const double e = fabs((double)psd[i] - expect[i]);
        if (e / expect[i] > *worst) {
            *worst = e / expect[i];
        }
        if (e / peak > *worst_peak) {
            *worst_peak = e / peak;
        }
        if (!(e <= BIN_REL * expect[i] || e <= PEAK_REL * peak)) {
            fprintf(stderr, "%scase %s bin %zu: %.9g vs %.9g\n", what, c->name, i, (double)psd[i], expect[i]);
            fail();
        }
    }
}

/* A "k,value" line of the current case into expect[k]. */
static void read_bin(const char *line, const vcase_t *c, double *expect)
{
    unsigned k;
    double v;
    assert_int_equal(sscanf(line, "%u,%lf", &k, &v), 2);
    assert_true(k < c->nbins);
    expect[k] = v;
}

static void test_against_scipy(void **state)
{
    static fnav_welch_t w;
    static fnav_real_t psd[FNAV_WELCH_MAX_BINS];
    static double expect[FNAV_WELCH_MAX_BINS];
    char line[256];
    FILE *f;
    int ncases = 0, nbands = 0;
    double worst = 0.0, worst_peak = 0.0;
    vcase_t c, cur;
    (void)state;
    load_inputs();
    f = open_vector("welch/welch_expected.csv");
    memset(&cur, 0, sizeof cur);
    while (1) {
        char *got = fgets(line, sizeof line, f);
        int is_case = got != NULL && parse_case(line, &c);
        if ((got == NULL || is_case || strncmp(line, "band,", 5) == 0) && cur.nbins > 0) {
            /* run the previous case */
            run_case(&w, &cur, 0, psd);
            compare_bins("", &cur, psd, expect, &worst, &worst_peak);
            ncases++;
            cur.nbins = 0;
        }
        if (got == NULL) {
            break;
        }
        if (is_case) {
            cur = c;
            continue;
        }
        if (strncmp(line, "band,", 5) == 0) {
            /* band,case,threshold,round,exclude_dc,bandwidth,fs_rounded: re-run that case */
            char name[64];
            double thr, rnd, bw, fsr;
            int ex;
            fnav_bandwidth_config_t bc;
            fnav_bandwidth_t out;
            vcase_t bcase;
            FILE *g;
            char l2[256];
            int found = 0;
            assert_int_equal(sscanf(line, "band,%63[^,],%lf,%lf,%d,%lf,%lf", name, &thr, &rnd, &ex, &bw, &fsr), 6);
            g = open_vector("welch/welch_expected.csv");
            while (fgets(l2, sizeof l2, g) != NULL) {
                if (parse_case(l2, &bcase) && strcmp(bcase.name, name) == 0) {
                    found = 1;
                    break;
                }
            }
            fclose(g);
            assert_true(found);
            run_case(&w, &bcase, 0, psd);
            bc.threshold = (fnav_real_t)thr;
            bc.round_hz = (fnav_real_t)rnd;
            bc.exclude_dc = ex;
            assert_int_equal(fnav_welch_bandwidth(psd, bcase.nbins, (fnav_real_t)(bcase.fs / bcase.nfft), &bc, &out,
                                                  NULL),
                             FNAV_OK);
            FNAV_ASSERT_CLOSE(out.bandwidth_hz, bw, 0.0, BAND_REL);
            FNAV_ASSERT_CLOSE(out.fs_rounded_hz, fsr, 0.0, 0.0);
            nbands++;
            continue;
        }
        if (line[0] != '#' && cur.nbins > 0) {
            read_bin(line, &cur, expect);
        }
    }
    fclose(f);
    assert_int_equal(ncases, 12);
    assert_int_equal(nbands, 6);
    fprintf(stderr, "[  INFO    ] %s build: worst per-bin error vs scipy %.2g relative to the bin, %.2g relative "
                    "to the largest bin\n",
            FNAV_USE_DOUBLE ? "double" : "float", worst, worst_peak);
}

/* fnav_welch_last with the global-mean detrending against scipy
 * (vectors/welch/welch_last_expected.csv, gen_welch.py): after the whole
 * input is pushed, the last segment's spectrum is that of the segment less
 * the mean of every sample pushed, scipy.signal.periodogram(seg - x.mean(),
 * detrend=False). Bins 0 and 1 are the ones the mean correction changes
 * (the periodic window's DFT is zero beyond bin 1). The tolerances of
 * test_against_scipy apply: the same input rounding and offset, one
 * segment's arithmetic instead of an average of several. */
static void test_last_global_against_scipy(void **state)
{
    static fnav_welch_t w;
    static fnav_real_t psd[FNAV_WELCH_MAX_BINS];
    static double expect[FNAV_WELCH_MAX_BINS];
    char line[256];
    FILE *f;
    int ncases = 0;
    vcase_t c, cur;
    (void)state;
    load_inputs();
    f = open_vector("welch/welch_last_expected.csv");
    memset(&cur, 0, sizeof cur);
    while (1) {
        char *got = fgets(line, sizeof line, f);
        int is_case = got != NULL && parse_case(line, &c);
        if ((got == NULL || is_case) && cur.nbins > 0) {
            double worst = 0.0, worst_peak = 0.0;
            assert_string_equal(cur.detrend, "global");
            run_case(&w, &cur, 1, psd);
            compare_bins("last segment, ", &cur, psd, expect, &worst, &worst_peak);
            ncases++;
            cur.nbins = 0;
        }
        if (got == NULL) {
            break;
        }
        if (is_case) {
            cur = c;
            continue;
        }
        if (line[0] != '#' && cur.nbins > 0) {
            read_bin(line, &cur, expect);
        }
    }
    fclose(f);
    assert_int_equal(ncases, 3);
}

/* The mean of the per-segment spectra (fnav_welch_last) is the Welch average.
 * Rounding (u = FNAV_REAL_EPSILON / 2): each segment's power r^2 + i^2 is
 * the same rounded value in fnav_welch_last and in the running sum, which
 * scales it once more (u); the compensated sum is within 2 u of the exact
 * sum of its terms, and the average's a - c, 1 / n, product and scaling
 * round 4 times: 7 u, within 4 FNAV_REAL_EPSILON relative. The reference
 * sums in long double (seen LDBL_EPSILON / 2 for that sum). Measured 0.9
 * and 2.7 epsilon (float, double). (It was 1e-5 relative in float, 1e-12
 * in double: 80 and 4500 epsilon.) */
static void test_last_segment_average(void **state)
{
    static fnav_welch_t w;
    static fnav_real_t one[FNAV_WELCH_MAX_BINS], avg[FNAV_WELCH_MAX_BINS];
    static long double sum[FNAV_WELCH_MAX_BINS];
    fnav_welch_config_t cfg = fnav_welch_config_default;
    uint32_t k, seen = 0;
    int i;
    (void)state;
    cfg.rate_hz = FNAV_R(100.0);
    assert_int_equal(fnav_welch_init(&w, &cfg), FNAV_OK);
    assert_int_equal(fnav_welch_last(&w, one, FNAV_WELCH_MAX_BINS), FNAV_E_STATE);
    assert_int_equal(fnav_welch_get(&w, avg, FNAV_WELCH_MAX_BINS), FNAV_E_STATE);
    memset(sum, 0, sizeof sum);
    for (i = 0; i < 3000; i++) {
        assert_int_equal(fnav_welch_push(&w, (fnav_real_t)(sin(0.3 * i) + 0.01 * (i % 17))), FNAV_OK);
        if (fnav_welch_segments(&w) > seen) {
            seen = fnav_welch_segments(&w);
            assert_int_equal(fnav_welch_last(&w, one, FNAV_WELCH_MAX_BINS), FNAV_OK);
            for (k = 0; k < fnav_welch_bins(&w); k++) {
                sum[k] += (long double)one[k];
            }
        }
    }
    assert_int_equal(fnav_welch_get(&w, avg, FNAV_WELCH_MAX_BINS), FNAV_OK);
    for (k = 0; k < fnav_welch_bins(&w); k++) {
        FNAV_ASSERT_CLOSE(avg[k], (double)(sum[k] / seen), 0.0,
                          4.0 * (double)FNAV_REAL_EPSILON + 0.5 * (double)seen * (double)LDBL_EPSILON);
    }
    assert_int_equal(fnav_welch_get(&w, avg, 10), FNAV_E_SIZE);
    /* fnav_welch_last too refuses a buffer shorter than the bins, and
     * writes nothing into it; NULL is FNAV_E_ARG (make coverage: neither
     * was run) */
    one[0] = FNAV_R(-1.0);
    assert_int_equal(fnav_welch_last(&w, one, fnav_welch_bins(&w) - 1u), FNAV_E_SIZE);
    assert_true(one[0] == FNAV_R(-1.0));
    assert_int_equal(fnav_welch_last(&w, one, fnav_welch_bins(&w)), FNAV_OK);
    assert_true(one[0] >= FNAV_R(0.0));
    assert_int_equal(fnav_welch_last(NULL, one, FNAV_WELCH_MAX_BINS), FNAV_E_ARG);
    assert_int_equal(fnav_welch_last(&w, NULL, FNAV_WELCH_MAX_BINS), FNAV_E_ARG);
    assert_int_equal(fnav_welch_get(NULL, avg, FNAV_WELCH_MAX_BINS), FNAV_E_ARG);
    assert_int_equal(fnav_welch_get(&w, NULL, FNAV_WELCH_MAX_BINS), FNAV_E_ARG);
}

/* Parseval: with a rectangular window and no detrending, the one-sided
 * density integrates to the mean square of the segments (analytic). */
static void test_parseval(void **state)
{
    static fnav_welch_t w;
    static fnav_real_t p[FNAV_WELCH_MAX_BINS];
    fnav_welch_config_t cfg = fnav_welch_config_default;
    double ms = 0.0, integral = 0.0;
    uint32_t k;
    int i;
    (void)state;
    cfg.window = FNAV_WINDOW_RECT;
    cfg.detrend = FNAV_DETREND_NONE;
    cfg.overlap = 0;
    cfg.nfft = 128;
    cfg.rate_hz = FNAV_R(50.0);
    assert_int_equal(fnav_welch_init(&w, &cfg), FNAV_OK);
    for (i = 0; i < 1280; i++) {
        const double v = 2.0 + cos(0.05 * i * i); /* chirp with an offset */
        ms += v * v;
        assert_int_equal(fnav_welch_push(&w, (fnav_real_t)v), FNAV_OK);
    }
    assert_int_equal(fnav_welch_get(&w, p, FNAV_WELCH_MAX_BINS), FNAV_OK);
    for (k = 0; k < fnav_welch_bins(&w); k++) {
        integral += (double)p[k] * 50.0 / 128.0;
    }
    FNAV_ASSERT_CLOSE(integral, ms / 1280.0, 0.0, FNAV_USE_DOUBLE ? 1e-12 : 1e-5);
    FNAV_ASSERT_CLOSE(fnav_welch_freq(&w, 64), 25.0, 0.0, 1e-7);
}

/* Bandwidth on spectra whose answer is known. */
static void test_bandwidth_analytic(void **state)
{
    fnav_real_t p[33], ccdf[33];
    fnav_bandwidth_t out;
    fnav_bandwidth_config_t c = fnav_bandwidth_config_default;
    const fnav_real_t df = FNAV_R(12.8125); /* 820 Hz / 64 */
    int k;
    (void)state;
    /* one tone in bin 9: 95 % of it is reached 95 % across the bin */
    for (k = 0; k < 33; k++) {
        p[k] = k == 9 ? FNAV_R(4.0) : FNAV_R(0.0);
    }
    assert_int_equal(fnav_welch_bandwidth(p, 33, df, &c, &out, ccdf), FNAV_OK);
    FNAV_ASSERT_CLOSE(out.bandwidth_hz, (9.0 - 0.5 + 0.95) * 12.8125, 0.0, 1e-6);
    FNAV_ASSERT_CLOSE(out.fs_hz, 2.0 * (9.0 - 0.5 + 0.95) * 12.8125, 0.0, 1e-6);
    FNAV_ASSERT_CLOSE(out.fs_rounded_hz, 250.0, 0.0, 0.0);
    FNAV_ASSERT_CLOSE(out.total, 4.0 * 12.8125, 0.0, 1e-6);
    FNAV_ASSERT_CLOSE(ccdf[8], 1.0, 0.0, 1e-6);
    FNAV_ASSERT_CLOSE(ccdf[9], 0.0, 1e-6, 0.0);
    /* a tone in the Nyquist bin: that bin ends at fmax (31.5 df .. 32 df),
     * so 95 % of it is reached at 31.5 df + 0.95 * df / 2. A hand-made
     * mutant giving the last bin a whole width (to 32.5 df, beyond fmax)
     * passed every suite (fails here, checked) */
    p[9] = FNAV_R(0.0);
    p[32] = FNAV_R(4.0);
    assert_int_equal(fnav_welch_bandwidth(p, 33, df, &c, &out, NULL), FNAV_OK);
    FNAV_ASSERT_CLOSE(out.bandwidth_hz, (31.5 + 0.95 * 0.5) * 12.8125, 0.0, 1e-6);
    p[32] = FNAV_R(0.0);
    /* equal tones in bins 2 and 20: the crossing is 90 % into bin 20 */
    p[9] = FNAV_R(0.0);
    p[2] = FNAV_R(1.0);
    p[20] = FNAV_R(1.0);
    assert_int_equal(fnav_welch_bandwidth(p, 33, df, &c, &out, NULL), FNAV_OK);
    FNAV_ASSERT_CLOSE(out.bandwidth_hz, (20.0 - 0.5 + 0.9) * 12.8125, 0.0, 1e-6);
    /* a huge DC bin decides the answer unless it is excluded */
    p[0] = FNAV_R(1000.0);
    assert_int_equal(fnav_welch_bandwidth(p, 33, df, &c, &out, NULL), FNAV_OK);
    assert_true(out.bandwidth_hz < df * FNAV_R(0.5));
    c.exclude_dc = 1;
    assert_int_equal(fnav_welch_bandwidth(p, 33, df, &c, &out, NULL), FNAV_OK);
    FNAV_ASSERT_CLOSE(out.bandwidth_hz, (20.0 - 0.5 + 0.9) * 12.8125, 0.0, 1e-5);
    /* errors */
    for (k = 0; k < 33; k++) {
        p[k] = FNAV_R(0.0);
    }
    assert_int_equal(fnav_welch_bandwidth(p, 33, df, &c, &out, NULL), FNAV_E_RANGE);
    c.threshold = FNAV_R(1.5);
    assert_int_equal(fnav_welch_bandwidth(p, 33, df, &c, &out, NULL), FNAV_E_ARG);
    assert_int_equal(fnav_welch_bandwidth(NULL, 33, df, NULL, &out, NULL), FNAV_E_ARG);
    /* a rounding step that is not finite (a review, 2026-11-29): +Inf passed
     * the check (>= 0) and the rounded frequency came out NaN with FNAV_OK */
    p[5] = FNAV_R(1.0);
    c = fnav_bandwidth_config_default;
    c.round_hz = (fnav_real_t)INFINITY;
    assert_int_equal(fnav_welch_bandwidth(p, 33, df, &c, &out, NULL), FNAV_E_ARG);
    c.round_hz = (fnav_real_t)NAN;
    assert_int_equal(fnav_welch_bandwidth(p, 33, df, &c, &out, NULL), FNAV_E_ARG);
    c.round_hz = FNAV_R(50.0);
    assert_int_equal(fnav_welch_bandwidth(p, 33, df, &c, &out, NULL), FNAV_OK);
    /* rounded up to a multiple of 50 Hz; with round_hz = 0 not rounded,
     * fs itself (fnav_welch.h; make coverage: 0 was never tried) */
    {
        const double fs = (double)out.fs_hz, up = (double)out.fs_rounded_hz;
        FNAV_ASSERT_CLOSE(up, 50.0 * ceil(fs / 50.0), 1e-9, 0.0);
        assert_true(up > fs + 1.0); /* the case rounds something */
        c.round_hz = FNAV_R(0.0);
        assert_int_equal(fnav_welch_bandwidth(p, 33, df, &c, &out, NULL), FNAV_OK);
        assert_true(out.fs_rounded_hz == out.fs_hz);
        FNAV_ASSERT_CLOSE(out.fs_hz, fs, 0.0, 0.0);
    }
    /* a step so fine that fs / step overflows float (harness psd --round
     * 1e-40 printed fs_Hz inf): a step that small rounds nothing */
    c.round_hz = (fnav_real_t)1e-37;
    assert_int_equal(fnav_welch_bandwidth(p, 33, df, &c, &out, NULL), FNAV_OK);
    assert_true(fnav_isfinite(out.fs_rounded_hz));
    FNAV_ASSERT_CLOSE(out.fs_rounded_hz, out.fs_hz, 0.0, 1e-6);
}

/* A density is never negative (a review, 2026-12-01): a spectrum with a
 * negative bin was taken, its total the sum of the positive and negative
 * parts: {0, 4, -3, 0, 1} (df 1 Hz) gave FNAV_OK, a total of 2, a
 * "95 %" band of 0.975 Hz and a CCDF rising from 0 to 0.5. A negative or
 * NaN bin is now FNAV_E_RANGE, the DC bin too when it is left out of the
 * total, with nothing written. */
static void test_bandwidth_bad_bins(void **state)
{
    fnav_real_t p[5] = { FNAV_R(0.0), FNAV_R(4.0), FNAV_R(-3.0), FNAV_R(0.0), FNAV_R(1.0) }, ccdf[5];
    fnav_bandwidth_t out, copy;
    fnav_bandwidth_config_t c = fnav_bandwidth_config_default;
    int k;
    (void)state;
    memset(&out, 0x5a, sizeof out);
    copy = out;
    for (k = 0; k < 5; k++) {
        ccdf[k] = FNAV_R(7.0);
    }
    assert_int_equal(fnav_welch_bandwidth(p, 5, FNAV_R(1.0), &c, &out, ccdf), FNAV_E_RANGE);
    p[2] = (fnav_real_t)NAN;
    assert_int_equal(fnav_welch_bandwidth(p, 5, FNAV_R(1.0), &c, &out, ccdf), FNAV_E_RANGE);
    p[2] = FNAV_R(0.0);
    p[0] = FNAV_R(-1.0);
    c.exclude_dc = 1;
    assert_int_equal(fnav_welch_bandwidth(p, 5, FNAV_R(1.0), &c, &out, ccdf), FNAV_E_RANGE);
    p[0] = (fnav_real_t)NAN;
    assert_int_equal(fnav_welch_bandwidth(p, 5, FNAV_R(1.0), &c, &out, ccdf), FNAV_E_RANGE);
    assert_memory_equal(&out, &copy, sizeof out);
    for (k = 0; k < 5; k++) {
        assert_true(ccdf[k] == FNAV_R(7.0));
    }
    /* the same spectrum without them: 4 and 1 in bins 1 and 4 */
    p[0] = FNAV_R(0.0);
    c.exclude_dc = 0;
    assert_int_equal(fnav_welch_bandwidth(p, 5, FNAV_R(1.0), &c, &out, ccdf), FNAV_OK);
    FNAV_ASSERT_CLOSE(out.total, 5.0, 0.0, 1e-6);
    /* 4.75 of 5: 0.75 of bin 4's power, bin 4 spanning [3.5, 4] (the last, clipped) */
    FNAV_ASSERT_CLOSE(out.bandwidth_hz, 3.5 + 0.75 * 0.5, 0.0, 1e-6);
}

static void test_config_and_bad_input(void **state)
{
    static fnav_welch_t w, copy;
    fnav_welch_config_t c = fnav_welch_config_default;
    int i;
    (void)state;
    assert_int_equal(fnav_welch_init(NULL, NULL), FNAV_E_ARG);
    /* push was the one welch entry point that dereferenced a NULL w (a core
     * review, 2026-11-29): every other one returns FNAV_E_ARG */
    assert_int_equal(fnav_welch_push(NULL, FNAV_R(1.0)), FNAV_E_ARG);
    c.nfft = 48;
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_E_CONFIG);
    c.nfft = FNAV_WELCH_MAX_NFFT * 2u;
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_E_CONFIG);
    c.nfft = 64;
    c.overlap = 64;
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_E_CONFIG);
    c.overlap = 32;
    c.rate_hz = FNAV_R(0.0);
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_E_CONFIG);
    c.rate_hz = FNAV_R(1.0);
    c.window = (fnav_window_t)7;
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_E_CONFIG);
    assert_int_equal(fnav_welch_init(&w, NULL), FNAV_OK);
    for (i = 0; i < 100; i++) {
        assert_int_equal(fnav_welch_push(&w, (fnav_real_t)i), FNAV_OK);
    }
    copy = w;
    assert_int_equal(fnav_welch_push(&w, (fnav_real_t)NAN), FNAV_E_NANINF);
    assert_int_equal(fnav_welch_push(&w, FNAV_R(1.0e30)), FNAV_E_RANGE); /* found by fuzzing */
    assert_memory_equal(&w, &copy, sizeof w);
    c = fnav_welch_config_default;
    c.offset = FNAV_R(1.0e30);
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_E_CONFIG);
    /* checks no suite made (make coverage): a power of two below 8 (8 and
     * FNAV_WELCH_MAX_NFFT accepted), a detrending or scaling outside the
     * enum, the global mean with a symmetric window, a rate not finite */
    c = fnav_welch_config_default;
    c.overlap = 0;
    c.nfft = 4;
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_E_CONFIG);
    c.nfft = 8;
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_OK);
    c.nfft = FNAV_WELCH_MAX_NFFT;
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_OK);
    c = fnav_welch_config_default;
    c.detrend = (fnav_detrend_t)9;
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_E_CONFIG);
    c = fnav_welch_config_default;
    c.scaling = (fnav_scaling_t)9;
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_E_CONFIG);
    c = fnav_welch_config_default;
    c.detrend = FNAV_DETREND_GLOBAL;
    c.symmetric = 1;
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_E_CONFIG);
    c.symmetric = 0;
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_OK);
    c = fnav_welch_config_default;
    c.rate_hz = (fnav_real_t)INFINITY;
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_E_CONFIG);
    c.rate_hz = (fnav_real_t)NAN;
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_E_CONFIG);
}

/* The offset is removed before anything else: with no detrending, a
 * constant offset equal to the signal's mean gives the spectrum of the
 * zero-mean signal. */
static void test_offset(void **state)
{
    static fnav_welch_t a, b;
    static fnav_real_t pa[FNAV_WELCH_MAX_BINS], pb[FNAV_WELCH_MAX_BINS];
    fnav_welch_config_t c = fnav_welch_config_default;
    uint32_t k;
    int i;
    (void)state;
    c.detrend = FNAV_DETREND_NONE;
    assert_int_equal(fnav_welch_init(&a, &c), FNAV_OK);
    c.offset = FNAV_R(9.75);
    assert_int_equal(fnav_welch_init(&b, &c), FNAV_OK);
    for (i = 0; i < 2000; i++) {
        const double v = 0.3 * sin(0.21 * i);
        assert_int_equal(fnav_welch_push(&a, (fnav_real_t)v), FNAV_OK);
        assert_int_equal(fnav_welch_push(&b, (fnav_real_t)(v + 9.75)), FNAV_OK);
    }
    assert_int_equal(fnav_welch_get(&a, pa, FNAV_WELCH_MAX_BINS), FNAV_OK);
    assert_int_equal(fnav_welch_get(&b, pb, FNAV_WELCH_MAX_BINS), FNAV_OK);
    for (k = 0; k < fnav_welch_bins(&a); k++) {
        FNAV_ASSERT_CLOSE(pb[k], pa[k], FNAV_USE_DOUBLE ? 1e-12 : 1e-6, FNAV_USE_DOUBLE ? 1e-9 : 1e-3);
    }
}

/* The per-segment mean and line (CONSTANT, LINEAR) are removed without
 * losing the segment's small signal to a large offset: gravity on an
 * accelerometer axis, 4096-sample segments. The spectrum with the offset
 * must be that without it, bin 0 included, within the float tolerance of
 * docs/psd.md (1e-3 of the bin or 1e-6 of the largest). Summing the raw
 * float samples for the mean put a 1.4 % error into bin 0 of the ADIS16405
 * az spectrum. */
static void test_segment_mean_large_offset(void **state)
{
    static fnav_welch_t a, b;
    static fnav_real_t pa[FNAV_WELCH_MAX_BINS], pb[FNAV_WELCH_MAX_BINS];
    fnav_welch_config_t c = fnav_welch_config_default;
    uint32_t k, seed = 12345u;
    int d, i;
    (void)state;
    for (d = 0; d < 2; d++) {
        double pmax = 0.0;
        c.detrend = d == 0 ? FNAV_DETREND_CONSTANT : FNAV_DETREND_LINEAR;
        c.nfft = 4096u;
        c.window = FNAV_WINDOW_HANN;
        assert_int_equal(fnav_welch_init(&a, &c), FNAV_OK);
        assert_int_equal(fnav_welch_init(&b, &c), FNAV_OK);
        for (i = 0; i < 5 * 4096; i++) {
            double v;
            seed = seed * 1664525u + 1013904223u;
            v = 0.01 * ((double)(seed >> 8) / 16777216.0 - 0.5) + 0.002 * sin(0.003 * i);
            assert_int_equal(fnav_welch_push(&a, (fnav_real_t)v), FNAV_OK);
            assert_int_equal(fnav_welch_push(&b, (fnav_real_t)(v - 9.96)), FNAV_OK);
        }
        assert_int_equal(fnav_welch_get(&a, pa, FNAV_WELCH_MAX_BINS), FNAV_OK);
        assert_int_equal(fnav_welch_get(&b, pb, FNAV_WELCH_MAX_BINS), FNAV_OK);
        for (k = 0; k < fnav_welch_bins(&a); k++) {
            pmax = (double)pa[k] > pmax ? (double)pa[k] : pmax;
        }
        for (k = 0; k < fnav_welch_bins(&a); k++) {
            /* the offset signal's float samples carry their own rounding
             * (about 5e-7 against noise of 3e-3): the same size as the
             * tolerance's absolute part */
            FNAV_ASSERT_CLOSE(pb[k], pa[k], FNAV_USE_DOUBLE ? 1e-15 : 1e-6 * pmax, FNAV_USE_DOUBLE ? 1e-9 : 1e-3);
        }
    }
}

/* GLOBAL on a long record whose first sample is far from the mean: white
 * noise, sd 1 at 1 kHz, so the one-sided density is 2e-3 (1e-3 at DC).
 * Bins 0 and 1 are where global_fix cancels large terms; with the first
 * sample as the only shift and plain float sums this test failed in
 * float32 (a double build was right). 31,249 segments: the estimate's own
 * sd is about 0.6 %, and the 4 % held around the analytic density are
 * that statistic's band, not the arithmetic's. The record is deterministic,
 * so every bin is also checked against scipy.signal.welch of the same
 * record less its mean (vectors/welch/welch_long_offset_expected.csv,
 * gen_welch.py, which writes the generator below in Python) to
 * test_against_scipy's tolerances: 1e-3 of the bin in float (the input
 * rounded to 24 bits), 1e-11 in double. */
static void test_global_long_offset_start(void **state)
{
    static fnav_welch_t w;
    static fnav_real_t p[FNAV_WELCH_MAX_BINS];
    fnav_welch_config_t c = fnav_welch_config_default;
    uint64_t x = 88172645463325252ull;
    long i;
    (void)state;
    c.detrend = FNAV_DETREND_GLOBAL;
    c.rate_hz = FNAV_R(1000.0);
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_OK);
    for (i = 0; i < 1000000L; i++) {
        double u1, u2, g;
        x ^= x << 13; x ^= x >> 7; x ^= x << 17;
        u1 = 1.0 - (double)(x >> 11) * (1.0 / 9007199254740992.0);
        x ^= x << 13; x ^= x >> 7; x ^= x << 17;
        u2 = (double)(x >> 11) * (1.0 / 9007199254740992.0);
        g = sqrt(-2.0 * log(u1)) * cos(6.283185307179586 * u2);
        assert_int_equal(fnav_welch_push(&w, (fnav_real_t)(i == 0 ? 50.0 : g)), FNAV_OK);
    }
    assert_int_equal(fnav_welch_get(&w, p, FNAV_WELCH_MAX_BINS), FNAV_OK);
    assert_true(fabs((double)p[0] / 1.0e-3 - 1.0) < 0.04);
    assert_true(fabs((double)p[1] / 2.0e-3 - 1.0) < 0.04);
    assert_true(fabs((double)p[2] / 2.0e-3 - 1.0) < 0.04);
    {
        static double expect[FNAV_WELCH_MAX_BINS];
        char line[256];
        double worst = 0.0, worst_peak = 0.0;
        unsigned nread = 0;
        vcase_t vc;
        FILE *f = open_vector("welch/welch_long_offset_expected.csv");
        memset(&vc, 0, sizeof vc);
        while (fgets(line, sizeof line, f) != NULL) {
            if (line[0] == '#') {
                continue;
            }
            if (parse_case(line, &vc)) {
                /* the configuration the vector was made with */
                assert_true(vc.fs == 1000.0 && vc.nfft == c.nfft && vc.overlap == c.overlap && vc.sym == 0 &&
                            strcmp(vc.window, "hamming") == 0 && c.window == FNAV_WINDOW_HAMMING &&
                            strcmp(vc.detrend, "global") == 0 && strcmp(vc.scaling, "density") == 0 &&
                            c.scaling == FNAV_SCALING_DENSITY);
                continue;
            }
            assert_true(vc.nbins == fnav_welch_bins(&w));
            read_bin(line, &vc, expect);
            nread++;
        }
        fclose(f);
        assert_int_equal(nread, fnav_welch_bins(&w));
        compare_bins("long offset start: ", &vc, p, expect, &worst, &worst_peak);
        fprintf(stderr, "[  INFO    ] %s build: long record, first sample 50: worst bin %.2g relative to scipy\n",
                FNAV_USE_DOUBLE ? "double" : "float", worst);
    }
}

/* The sample count's end (a review, 2026-11-28): with a hop of one sample
 * the segment count reached 2^32 with the samples and wrapped to 0 (get then
 * answered FNAV_E_STATE, and the GLOBAL mean divided a sum of every sample
 * by a count that had stopped). 12.4 days at 4 kHz. The counts are moved
 * to their end here, consistently (hop 1: nseg = nsamples - nfft + 1); the
 * push that would make the count 2^32 is refused. */
static void test_sample_count_end(void **state)
{
    static fnav_welch_t w;
    fnav_welch_config_t c = fnav_welch_config_default;
    fnav_real_t out[FNAV_WELCH_MAX_BINS];
    int i, refused = 0;
    (void)state;
    c.nfft = 8u;
    c.overlap = 7u;
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_OK);
    for (i = 0; i < 40; i++) {
        assert_int_equal(fnav_welch_push(&w, (fnav_real_t)(0.1 * (double)(i % 5))), FNAV_OK);
    }
    w.nsamples = UINT32_MAX - 20u;
    w.nseg = w.nsamples - c.nfft + 1u;
    for (i = 0; i < 40; i++) {
        fnav_status_t st = fnav_welch_push(&w, (fnav_real_t)(0.1 * (double)(i % 5)));
        if (st == FNAV_E_RANGE) {
            refused++;
        } else {
            assert_int_equal(st, FNAV_OK);
        }
    }
    assert_int_equal(refused, 20);
    assert_int_equal(w.nsamples, UINT32_MAX);
    assert_int_equal(fnav_welch_segments(&w), UINT32_MAX - c.nfft + 1u);
    assert_int_equal(fnav_welch_get(&w, out, FNAV_WELCH_MAX_BINS), FNAV_OK);
    for (i = 0; i < 5; i++) {
        assert_true(fnav_isfinite(out[i]) && out[i] >= FNAV_R(0.0));
    }
}

/* An estimator never initialised (static storage, zeroed) or whose init
 * failed before it ever succeeded: nfft is 0. Push stepped the ring index
 * past the end (pos + 1 == 0 never wrapped it), writing out of bounds from
 * the FNAV_WELCH_MAX_NFFT-th push on (found by a library user's probe,
 * 2026-11-30); now the index stays in the ring, no segment completes and
 * fnav_welch_get says FNAV_E_STATE, as before the first segment. */
static void test_not_initialised(void **state)
{
    static fnav_welch_t w, copy;
    fnav_welch_config_t c = fnav_welch_config_default;
    fnav_real_t out[FNAV_WELCH_MAX_BINS];
    uint32_t i;
    (void)state;
    c.nfft = 48; /* refused: w stays zeroed */
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_E_CONFIG);
    /* a push says FNAV_E_STATE, as fnav_nav_push does, before it looks at
     * the sample, and takes nothing (it returned FNAV_OK and counted the
     * sample before 2026-11-30) */
    memset(&copy, 0, sizeof copy);
    for (i = 0; i < FNAV_WELCH_MAX_NFFT + 8u; i++) {
        assert_int_equal(fnav_welch_push(&w, FNAV_R(1.0)), FNAV_E_STATE);
    }
    assert_int_equal(fnav_welch_push(&w, (fnav_real_t)NAN), FNAV_E_STATE);
    assert_memory_equal(&w, &copy, sizeof w);
    assert_int_equal(fnav_welch_segments(&w), 0);
    assert_int_equal(fnav_welch_bins(&w), 1);
    /* the accessors answer 0 rather than read through NULL or divide by
     * nfft 0 (fnav_welch_freq dereferenced NULL and gave NaN here) */
    assert_true(fnav_welch_freq(&w, 1) == FNAV_R(0.0));
    assert_true(fnav_welch_freq(NULL, 1) == FNAV_R(0.0));
    assert_int_equal(fnav_welch_bins(NULL), 0);
    assert_int_equal(fnav_welch_segments(NULL), 0);
    assert_int_equal(fnav_welch_get(&w, out, FNAV_WELCH_MAX_BINS), FNAV_E_STATE);
    assert_int_equal(fnav_welch_last(&w, out, FNAV_WELCH_MAX_BINS), FNAV_E_STATE);
    /* an init that succeeds afterwards starts from scratch */
    assert_int_equal(fnav_welch_init(&w, NULL), FNAV_OK);
    for (i = 0; i < 64u; i++) {
        assert_int_equal(fnav_welch_push(&w, (fnav_real_t)(i % 3u)), FNAV_OK);
    }
    assert_int_equal(fnav_welch_segments(&w), 1);
    assert_int_equal(fnav_welch_get(&w, out, FNAV_WELCH_MAX_BINS), FNAV_OK);
    /* a failed init leaves an initialised estimator as it was (fnav_welch.h) */
    copy = w;
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_E_CONFIG);
    assert_memory_equal(&w, &copy, sizeof w);
}

/* Re-initialising with the estimator's own configuration (a reset,
 * fnav_welch_init(&w, &w.cfg); a review, 2026-12-01): init cleared the
 * estimator, configuration included, before it read the configuration's
 * nfft again, so it returned FNAV_E_CONFIG and left the estimator zeroed
 * (every push then FNAV_E_STATE), where fnav_welch.h says a failed init
 * leaves it as it was. It must reset it: no segment, the same
 * configuration, and the same spectrum as a fresh estimator after the same
 * samples. */
static void test_reinit_own_config(void **state)
{
    static fnav_welch_t w, fresh;
    static fnav_real_t pw[FNAV_WELCH_MAX_BINS], pf[FNAV_WELCH_MAX_BINS];
    fnav_welch_config_t c = fnav_welch_config_default;
    uint32_t k;
    int i;
    (void)state;
    c.nfft = 128u;
    c.overlap = 96u;
    c.window = FNAV_WINDOW_HANN;
    c.detrend = FNAV_DETREND_GLOBAL;
    c.rate_hz = FNAV_R(250.0);
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_OK);
    for (i = 0; i < 700; i++) {
        assert_int_equal(fnav_welch_push(&w, (fnav_real_t)(3.0 + sin(0.7 * i))), FNAV_OK);
    }
    assert_true(fnav_welch_segments(&w) > 0u);
    assert_int_equal(fnav_welch_init(&w, &w.cfg), FNAV_OK);
    assert_memory_equal(&w.cfg, &c, sizeof c);
    assert_int_equal(fnav_welch_segments(&w), 0);
    assert_int_equal(fnav_welch_init(&fresh, &c), FNAV_OK);
    for (i = 0; i < 500; i++) {
        const fnav_real_t v = (fnav_real_t)(0.5 * cos(0.31 * i) + 0.01 * (i % 11));
        assert_int_equal(fnav_welch_push(&w, v), FNAV_OK);
        assert_int_equal(fnav_welch_push(&fresh, v), FNAV_OK);
    }
    assert_int_equal(fnav_welch_get(&w, pw, FNAV_WELCH_MAX_BINS), FNAV_OK);
    assert_int_equal(fnav_welch_get(&fresh, pf, FNAV_WELCH_MAX_BINS), FNAV_OK);
    for (k = 0; k < fnav_welch_bins(&w); k++) {
        assert_true(pw[k] == pf[k]); /* the same arithmetic on the same samples */
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_against_scipy),
        cmocka_unit_test(test_last_segment_average),
        cmocka_unit_test(test_last_global_against_scipy),
        cmocka_unit_test(test_parseval),
        cmocka_unit_test(test_bandwidth_analytic),
        cmocka_unit_test(test_bandwidth_bad_bins),
        cmocka_unit_test(test_config_and_bad_input),
        cmocka_unit_test(test_offset),
        cmocka_unit_test(test_segment_mean_large_offset),
        cmocka_unit_test(test_global_long_offset_start),
        cmocka_unit_test(test_sample_count_end),
        cmocka_unit_test(test_not_initialised),
        cmocka_unit_test(test_reinit_own_config),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
