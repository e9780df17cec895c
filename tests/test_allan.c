/* Tests of the streaming Allan estimator (src/fnav_allan.c) and of the
 * harness identification (harness/hx_allan_ident.c).
 *
 * References: NIST SP 1065 NBS14 sets and Stable32 results on PHASE.DAT
 * (../shared/data/allan_reference), a numpy extended-precision vector
 * (vectors/allan/gen_allan.py), analytic results. */
#include <float.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "footnav/fnav_allan.h"
#include "footnav/fnav_profile.h"
#include "support/fnav_testdata.h"
#include "hx_allan_ident.h"
#include "hx_devs.h"
#include "hx_log.h"
#include "hx_profile.h"

/* Reference tables of NIST SP 1065 / Stable32 are published to 1e-4
 * relative (and Stable32 prints 5 digits). */
#define REF_TOL 1e-4

/* Stable32's confidence factor "0.683": one sigma, erf(1 / sqrt(2)) */
#define S32_CONF 0.682689492137086

/* The confidence of Stable32's printed limits: S32_CONF up to 100 degrees
 * of freedom, 0.68 above. Of the 73 PHASE.DAT octave rows with limits, the
 * 33 above 100 EDF (119 to 1,502) match 0.68 within 6.8e-5 and miss one
 * sigma by 1.1-4.2e-4; the 40 below (2.9 to 94) match one sigma within
 * 1.6e-4 and miss 0.68 by 4.1e-4 to 3.3e-3 (docs/allan.md, "Confidence
 * intervals"). */
static double s32_conf(double edf)
{
    return edf > 100.0 ? 0.68 : S32_CONF;
}

/* Stable32's limits against ours from its printed sigma, both printed to 5
 * digits (up to 5e-5 each): the worst row is 1.6e-4 (HDEV, m = 128, 2.9
 * degrees of freedom, where the EDF its two limits imply is 0.1-0.3 % above
 * Greenhall's: scripts/stable32_conf.py): hence 2e-4, not a blanket 5e-4
 * at one sigma. */
#define S32_CI_TOL 2e-4

/* The larger relative miss of the limits at confidence conf against
 * Stable32's printed ones. */
static double s32_ci_miss(double dev, double edf, double conf, double lo_ref, double hi_ref)
{
    double lo, hi;
    assert_int_equal(hx_allan_ci(dev, edf, conf, &lo, &hi), 0);
    return fmax(fabs(lo / lo_ref - 1.0), fabs(hi / hi_ref - 1.0));
}

/* Over every Stable32 row checked so far: [0] above 100 EDF, [1] at or
 * below; count, EDF range, worst miss, and the range of misses at the other
 * confidence. */
static struct {
    unsigned n;
    double edf_lo, edf_hi, miss, other_lo, other_hi;
} s32_stat[2];

/* Stable32's limits at row edf: within S32_CI_TOL at s32_conf(edf), and
 * nearer than at the other confidence (0.68 against 0.682689), so that the
 * switch at 100 degrees of freedom is tested, not assumed. */
static void s32_check_ci(double dev, double edf, double lo_ref, double hi_ref)
{
    const double conf = s32_conf(edf);
    const int k = conf == S32_CONF ? 1 : 0;
    const double miss = s32_ci_miss(dev, edf, conf, lo_ref, hi_ref);
    const double other = s32_ci_miss(dev, edf, k == 0 ? S32_CONF : 0.68, lo_ref, hi_ref);
    FNAV_ASSERT_CLOSE(miss, 0.0, S32_CI_TOL, 0.0);
    assert_true(miss < other);
    if (s32_stat[k].n++ == 0u) {
        s32_stat[k].edf_lo = s32_stat[k].edf_hi = edf;
        s32_stat[k].miss = miss;
        s32_stat[k].other_lo = s32_stat[k].other_hi = other;
    }
    s32_stat[k].edf_lo = fmin(s32_stat[k].edf_lo, edf);
    s32_stat[k].edf_hi = fmax(s32_stat[k].edf_hi, edf);
    s32_stat[k].miss = fmax(s32_stat[k].miss, miss);
    s32_stat[k].other_lo = fmin(s32_stat[k].other_lo, other);
    s32_stat[k].other_hi = fmax(s32_stat[k].other_hi, other);
}

/* The figures docs/allan.md quotes, over the tables checked so far (all
 * PHASE.DAT octave tables once the last of the three tests has run). */
static void s32_print_stat(void)
{
    print_message("[  INFO    ] Stable32 limits so far: %u rows above 100 EDF (%.0f-%.0f) within %.1e at 0.68, "
                  "%.1e-%.1e at one sigma; %u rows at or below (%.1f-%.1f) within %.1e at one sigma, %.1e-%.1e at "
                  "0.68\n",
                  s32_stat[0].n, s32_stat[0].edf_lo, s32_stat[0].edf_hi, s32_stat[0].miss, s32_stat[0].other_lo,
                  s32_stat[0].other_hi, s32_stat[1].n, s32_stat[1].edf_lo, s32_stat[1].edf_hi, s32_stat[1].miss,
                  s32_stat[1].other_lo, s32_stat[1].other_hi);
}

/* ------------------------------------------------------------ helpers */

/* Read numbers from a text file (one per line, '#' comments); returns count. */
static size_t read_numbers(const char *path, double *out, size_t max)
{
    FILE *f = fopen(path, "r");
    char line[256];
    size_t n = 0;
    if (f == NULL) {
        return 0;
    }
    while (fgets(line, sizeof line, f) != NULL && n < max) {
        char *end;
        double v;
        if (line[0] == '#') {
            continue;
        }
        v = strtod(line, &end);
        if (end != line) {
            out[n++] = v;
        }
    }
    fclose(f);
    return n;
}

typedef struct {
    uint32_t tau;
    uint32_t terms;
    int alpha;
    double lo, dev, hi;
} s32_row_t;

/* Stable32 result file: AF Tau # Alpha MinSigma Sigma MaxSigma */
static size_t read_stable32(const char *rel, s32_row_t *rows, size_t max)
{
    char path[512], line[256];
    FILE *f;
    size_t n = 0;
    if (fnav_testdata_path(rel, path, sizeof path) != 0 || (f = fopen(path, "r")) == NULL) {
        return 0;
    }
    while (fgets(line, sizeof line, f) != NULL && n < max) {
        unsigned af, terms;
        int alpha;
        double tau, lo, s, hi;
        if (line[0] == '#') {
            continue;
        }
        if (sscanf(line, "%u %lf %u %d %lf %lf %lf", &af, &tau, &terms, &alpha, &lo, &s, &hi) == 7) {
            rows[n].tau = af;
            rows[n].terms = terms;
            rows[n].alpha = alpha;
            rows[n].lo = lo;
            rows[n].dev = s;
            rows[n].hi = hi;
            n++;
        }
    }
    fclose(f);
    return n;
}

/* PHASE.DAT as frequency data: y_i = x_{i+1} - x_i (tau0 = 1 s). */
static size_t phasedat_freq(double *y, size_t max)
{
    static double x[1100];
    char path[512];
    size_t n, i;
    if (fnav_testdata_path("allan_reference/phasedat/PHASE.DAT", path, sizeof path) != 0) {
        return 0;
    }
    n = read_numbers(path, x, sizeof x / sizeof x[0]);
    for (i = 0; i + 1 < n && i < max; i++) {
        y[i] = x[i + 1] - x[i];
    }
    return n > 0 ? n - 1 : 0;
}

/* Run a series through estimators covering the tau list (chunks of
 * FNAV_ALLAN_MAX_POINTS); results in the order of the list. */
static void run_series(const double *y, size_t n, const uint32_t *tau, size_t ntau, fnav_allan_result_t *res)
{
    static fnav_allan_t a;
    size_t c, i, k;
    for (c = 0; c < ntau; c += FNAV_ALLAN_MAX_POINTS) {
        const size_t cnt = ntau - c < FNAV_ALLAN_MAX_POINTS ? ntau - c : FNAV_ALLAN_MAX_POINTS;
        const fnav_allan_config_t cfg = { tau + c, cnt };
        assert_int_equal(fnav_allan_init(&a, &cfg), FNAV_OK);
        for (i = 0; i < n; i++) {
            assert_int_equal(fnav_allan_push(&a, (fnav_real_t)y[i]), FNAV_OK);
        }
        for (k = 0; k < cnt; k++) {
            assert_int_equal(fnav_allan_get(&a, k, &res[c + k]), FNAV_OK);
            assert_int_equal(res[c + k].tau, tau[c + k]);
        }
    }
}

static int skip_without(const char *rel)
{
    char path[512];
    if (fnav_testdata_path(rel, path, sizeof path) != 0) {
        fnav_test_skip_notice(rel);
        return 1;
    }
    return 0;
}

/* ------------------------------------------------------------ NBS14 */

static void test_nbs14_1000(void **state)
{
    static double y[1000];
    static const uint32_t tau[3] = { 1, 10, 100 };
    /* NIST SP 1065 p. 108 (nbs14_1000pt_expected.csv) */
    static const double adev[3] = { 2.922319e-01, 9.965736e-02, 3.897804e-02 };
    static const double oadev[3] = { 2.922319e-01, 9.159953e-02, 3.241343e-02 };
    fnav_allan_result_t r[3];
    char path[512];
    int k;
    (void)state;
    if (fnav_testdata_path("allan_reference/nbs14/nbs14_1000pt_frequency.txt", path, sizeof path) != 0) {
        fnav_test_skip_notice("NBS14 1000-point set");
        skip();
    }
    assert_int_equal(read_numbers(path, y, 1000), 1000);
    run_series(y, 1000, tau, 3, r);
    for (k = 0; k < 3; k++) {
        FNAV_ASSERT_CLOSE(sqrt((double)r[k].avar), oadev[k], 0.0, REF_TOL);
        FNAV_ASSERT_CLOSE(sqrt((double)r[k].avar_nonoverlap), adev[k], 0.0, REF_TOL);
        assert_int_equal(r[k].terms, 1001u - 2u * tau[k]);
        assert_int_equal(r[k].terms_nonoverlap, 1000u / tau[k] - 1u);
        assert_int_equal(r[k].level, 0);
    }
}

static void test_nbs14_10(void **state)
{
    /* NIST SP 1065 p. 107: the 9 frequency values */
    static const double y[9] = { 892.0, 809.0, 823.0, 798.0, 671.0, 644.0, 883.0, 903.0, 677.0 };
    static const uint32_t tau[2] = { 1, 2 };
    fnav_allan_result_t r[2];
    (void)state;
    run_series(y, 9, tau, 2, r);
    FNAV_ASSERT_CLOSE(sqrt((double)r[0].avar), 91.22945, 0.0, REF_TOL);
    FNAV_ASSERT_CLOSE(sqrt((double)r[0].avar_nonoverlap), 91.22945, 0.0, REF_TOL);
    FNAV_ASSERT_CLOSE(sqrt((double)r[1].avar), 85.95287, 0.0, REF_TOL);
    FNAV_ASSERT_CLOSE(sqrt((double)r[1].avar_nonoverlap), 115.8082, 0.0, REF_TOL);
    assert_int_equal(r[1].terms, 6);
    assert_int_equal(r[1].terms_nonoverlap, 3);
}

/* ------------------------------------------------------------ PHASE.DAT */

static void check_every_tau(const char *rel, int overlapping)
{
    static s32_row_t rows[200];
    static double y[1100];
    static uint32_t tau[200];
    static fnav_allan_result_t r[200];
    size_t n, ny, i;
    if (skip_without(rel)) {
        skip();
    }
    n = read_stable32(rel, rows, 200);
    ny = phasedat_freq(y, 1100);
    assert_true(n > 100);
    assert_int_equal(ny, 1000);
    for (i = 0; i < n; i++) {
        tau[i] = rows[i].tau;
        assert_true(fnav_allan_tau_valid(tau[i]));
    }
    run_series(y, ny, tau, n, r);
    for (i = 0; i < n; i++) {
        const double dev = sqrt((double)(overlapping ? r[i].avar : r[i].avar_nonoverlap));
        assert_int_equal(r[i].level, 0); /* every tau here is fully overlapping */
        assert_int_equal(overlapping ? r[i].terms : r[i].terms_nonoverlap, rows[i].terms);
        FNAV_ASSERT_CLOSE(dev, rows[i].dev, 0.0, REF_TOL);
    }
}

static void test_phasedat_oadev_every_tau(void **state)
{
    (void)state;
    check_every_tau("allan_reference/phasedat/phase_dat_oadev.txt", 1);
}

static void test_phasedat_adev_every_tau(void **state)
{
    (void)state;
    check_every_tau("allan_reference/phasedat/phase_dat_adev.txt", 0);
}

/* Octave tau with Stable32's confidence limits (Greenhall EDF, white FM as
 * Stable32 identified, alpha column 0). Stable32's "0.683" is the
 * one-sigma probability erf(1 / sqrt(2)) = 0.682689 (S32_CONF): at its
 * few-term points only that value makes both printed limits agree with
 * one EDF (HDEV, m = 128, 5 terms); above 100 degrees of freedom its limits
 * are those of 0.68 (s32_conf()). */
static void check_octave(const char *rel, int overlapping)
{
    static s32_row_t rows[32];
    static double y[1100];
    static uint32_t tau[32];
    fnav_allan_result_t r[32];
    size_t n, ny, i;
    if (skip_without(rel)) {
        skip();
    }
    n = read_stable32(rel, rows, 32);
    ny = phasedat_freq(y, 1100);
    assert_int_equal(n, 8);
    for (i = 0; i < n; i++) {
        tau[i] = rows[i].tau;
    }
    run_series(y, ny, tau, n, r);
    for (i = 0; i < n; i++) {
        const double dev = sqrt((double)(overlapping ? r[i].avar : r[i].avar_nonoverlap));
        const double edf = hx_allan_point_edf(&r[i], FNAV_ALLAN_NOISE_WHITE, overlapping);
        assert_int_equal(overlapping ? r[i].terms : r[i].terms_nonoverlap, rows[i].terms);
        FNAV_ASSERT_CLOSE(dev, rows[i].dev, 0.0, REF_TOL);
        s32_check_ci(rows[i].dev, edf, rows[i].lo, rows[i].hi);
    }
    s32_print_stat();
}

static void test_phasedat_oadev_octave_ci(void **state)
{
    (void)state;
    check_octave("allan_reference/phasedat/phase_dat_oadev_octave.txt", 1);
}

static void test_phasedat_adev_octave_ci(void **state)
{
    (void)state;
    check_octave("allan_reference/phasedat/phase_dat_adev_octave.txt", 0);
}

/* ------------------------------------------------------------ other deviations */

/* PHASE.DAT's phase record relative to its first value (the x of hx_devs.h). */
static size_t phasedat_phase(double *x, size_t max)
{
    static double y[1100];
    const size_t ny = phasedat_freq(y, 1100);
    size_t i;
    assert_true(ny + 1u <= max);
    x[0] = 0.0;
    for (i = 0; i < ny; i++) {
        x[i + 1u] = x[i] + y[i];
    }
    return ny + 1u;
}

/* Every tau of a Stable32 table of deviation k: value and term count; where
 * Stable32 printed limits (the octave runs), the limits from hx_dev_edf()
 * with Stable32's own alpha, so that the EDF is checked apart from the
 * noise identification. */
static void check_dev_table(const char *rel, hx_dev_t k, int octave)
{
    static s32_row_t rows[200];
    static double x[1100];
    size_t n, nx, i, nlim = 0;
    if (skip_without(rel)) {
        skip();
    }
    n = read_stable32(rel, rows, 200);
    nx = phasedat_phase(x, 1100);
    assert_true(n >= 8u);
    assert_int_equal(nx, 1001);
    for (i = 0; i < n; i++) {
        uint32_t terms;
        const double v = hx_dev_var_record(k, x, nx, rows[i].tau, &terms);
        const double dev = sqrt(v) * hx_dev_scale(k, rows[i].tau, 1.0);
        assert_int_equal(terms, rows[i].terms);
        FNAV_ASSERT_CLOSE(dev, rows[i].dev, 0.0, REF_TOL);
        if (rows[i].lo > 0.0) {
            s32_check_ci(rows[i].dev, hx_dev_edf(k, rows[i].alpha, rows[i].tau, nx), rows[i].lo, rows[i].hi);
            nlim++;
        }
    }
    /* the octave files carry limits on every row, the all-tau files none
     * (an octave table read without its limits would skip every CI check) */
    assert_int_equal(nlim, octave ? n : 0u);
}

static void test_phasedat_other_deviations(void **state)
{
    static const struct {
        const char *name;
        hx_dev_t k;
    } t[] = {
        { "mdev", HX_DEV_MDEV }, { "tdev", HX_DEV_TDEV }, { "hdev", HX_DEV_HDEV }, { "ohdev", HX_DEV_OHDEV },
        { "totdev", HX_DEV_TOTDEV }, { "adev", HX_DEV_ADEV }, { "oadev", HX_DEV_OADEV },
    };
    size_t i;
    char rel[128];
    (void)state;
    for (i = 0; i < sizeof t / sizeof t[0]; i++) {
        snprintf(rel, sizeof rel, "allan_reference/phasedat/phase_dat_%s.txt", t[i].name);
        check_dev_table(rel, t[i].k, 0);
        snprintf(rel, sizeof rel, "allan_reference/phasedat/phase_dat_%s_octave.txt", t[i].name);
        check_dev_table(rel, t[i].k, 1);
    }
    s32_print_stat();
}

/* NIST SP 1065 p. 107: every deviation of the 10-point NBS14 set at
 * tau 1 and 2 s (nbs14_10pt_expected.csv). Published to 7 digits: 1e-6.
 * PDEV has no published value there. MTOTDEV and TTOTDEV are Stable32's
 * 5 digits (1e-5); HTOTDEV at tau 2 is published with the white-FM bias
 * correction (HTOTVAR / 0.995), which footnav does not apply, so the value
 * expected is the published one times sqrt(0.995) (1e-5: the factor is
 * itself rounded; the 1000-point set agrees to 1e-7, test_totdev_nbs14). */
static void test_nbs14_10_other_deviations(void **state)
{
    static const double y[9] = { 892.0, 809.0, 823.0, 798.0, 671.0, 644.0, 883.0, 903.0, 677.0 };
    static const double want[HX_DEV_COUNT][2] = {
        { 91.22945, 115.8082 }, { 91.22945, 85.95287 }, { 91.22945, 74.78849 }, { 52.67135, 86.35831 },
        { 70.80608, 116.7980 }, { 70.80607, 85.61487 }, { 91.22945, 93.90379 },
        { 91.22945, 87.60538 }, /* PDEV: OADEV at m = 1; m = 2 from the definition (scripts/pvar_edf.py --nbs14-10) */
        { 64.509, 64.794 },     { 37.244, 74.818 }, { 70.80607, 91.16396 * 0.99749686716300 /* sqrt(0.995) */ },
    };
    double x[10];
    unsigned k, m;
    (void)state;
    x[0] = 0.0;
    for (m = 0; m < 9u; m++) {
        x[m + 1u] = x[m] + y[m];
    }
    for (k = 0; k < HX_DEV_COUNT; k++) {
        for (m = 1; m <= 2u; m++) {
            uint32_t terms;
            const double dev = sqrt(hx_dev_var_record((hx_dev_t)k, x, 10u, m, &terms)) *
                               hx_dev_scale((hx_dev_t)k, m, 1.0);
            FNAV_ASSERT_CLOSE(dev, want[k][m - 1u], 0.0, k >= HX_DEV_MTOTDEV ? 1e-5 : 1e-6);
            assert_true(terms > 0u);
        }
    }
    /* too long an averaging factor: no term, NaN */
    for (k = 0; k < HX_DEV_COUNT; k++) {
        uint32_t terms = 7u;
        assert_true(isnan(hx_dev_var_record((hx_dev_t)k, x, 10u, 5u, &terms)));
        assert_int_equal(terms, 0u);
    }
}

/* Greenhall's EDF for the variance family: one difference term (M = 1)
 * is one degree of freedom for every d, filter and stride; undefined where
 * the variance diverges (alpha + 2 d <= 1) or no term exists; and the
 * Allan case is fnav_allan_edf(). */
/* Greenhall & Riley's case 4 (unmodified, white PM, alpha = +2) has two
 * forms: with K = ceil(r) <= d the terms share no phase sample and 1/edf =
 * (1/M) sum over |k| < K of (1 - |k|/r) (C(2d, d+k) / C(2d, d))^2, the
 * table's (1/M)(a0 - a1/r) only for K > d. On 3,000 phase values, OADEV
 * (d = 2, S = m): m = 1024 gives M = 952, r = 0.93, K = 1, edf = M (a
 * 20,000-record Monte Carlo gave 951.3; the table's form 1,096); m = 1280,
 * M = 440 (Monte Carlo 432.4; the table's form gave -1, no interval);
 * m = 768, M = 1464, r = 1.906, K = 2: 1464 / (1 + 2 (1 - 1/r) (4/6)^2). */
static void test_edf_white_pm_few_terms(void **state)
{
    const double r768 = 1464.0 / 768.0;
    (void)state;
    FNAV_ASSERT_CLOSE(fnav_allan_edf_var(2, 2, 0, 1024u, 3000u, 1), 952.0, 1e-9, 0.0);
    FNAV_ASSERT_CLOSE(fnav_allan_edf_var(2, 2, 0, 1280u, 3000u, 1), 440.0, 1e-9, 0.0);
    FNAV_ASSERT_CLOSE(fnav_allan_edf_var(2, 2, 0, 768u, 3000u, 1),
                      1464.0 / (1.0 + 2.0 * (1.0 - 1.0 / r768) * (4.0 / 6.0) * (4.0 / 6.0)), 1e-9, 0.0);
}

/* Greenhall's EDF where it has more than EDF_JMAX = 100 terms (J > 100):
 * none of these branches was run by a suite (make coverage). The reference
 * is the exact EDF of the overlapping estimator, written here from its
 * definition: a term is z_i = sum_n w_n e_(i+n) over a white sequence e (y
 * for white FM, alpha = 0: the second difference of the phase x = cumsum
 * y at stride m, averaged over m starts when modified; x itself for white
 * PM, alpha = +2), its covariance c_k = sum_n w_n w_(n+k), and the mean of
 * M such squares has, Gaussian, edf = 2 E^2 / var = M c0^2 / (c0^2 + 2
 * sum_(k=1..M-1) (1 - k/M) c_k^2). (1) J > 100 with r = M/S <= d + 1:
 * the basic sum cut to 100 terms; unmodified (r = 0.51, 1.00, 2.51) and
 * modified (r = 0.505, 1.51), white FM, within 1 % (the order of a cut
 * at 100 terms; 8e-4 at most measured). At r = 0.51 the
 * table form (1/r)(a0 - a1/r) would give 39 against 1.69, at r = 1 3.0
 * against 2.68. (2) Case 4 (white PM, unmodified) with K = ceil(r) > d and
 * J > 100: the table's (1/M)(a0 - a1/r) is exact there (the terms
 * correlate at lags 0, m, 2m only). */
static double edf_w[1024];

static double edf_exact(int alpha, int modified, long m, long n_phase)
{
    const long lw = modified ? 3 * m : (alpha == 0 ? 2 * m : 2 * m + 1);
    const long M = n_phase - (modified ? 3 * m - 1 : 2 * m);
    double c0 = 0.0, s = 0.0;
    long j, n, k;
    assert_true(lw <= (long)(sizeof edf_w / sizeof edf_w[0]));
    memset(edf_w, 0, sizeof edf_w);
    for (j = 0; j < (modified ? m : 1); j++) {
        if (alpha == 0) {
            for (n = 0; n < m; n++) {
                edf_w[j + n] -= 1.0;
                edf_w[j + m + n] += 1.0;
            }
        } else {
            edf_w[j] += 1.0;
            edf_w[j + m] -= 2.0;
            edf_w[j + 2 * m] += 1.0;
        }
    }
    for (n = 0; n < lw; n++) {
        c0 += edf_w[n] * edf_w[n];
    }
    for (k = 1; k < M && k < lw; k++) {
        double c = 0.0;
        for (n = 0; n + k < lw; n++) {
            c += edf_w[n] * edf_w[n + k];
        }
        s += (1.0 - (double)k / (double)M) * c * c;
    }
    return (double)M * c0 * c0 / (c0 * c0 + 2.0 * s);
}

static void test_edf_many_terms(void **state)
{
    static const struct {
        int alpha, modified;
        long m, n;
        double rel;
    } t[] = {
        { 0, 0, 200, 501, 0.01 }, { 0, 0, 200, 601, 0.01 }, { 0, 0, 100, 451, 0.01 },
        { 0, 1, 200, 701, 0.01 }, { 0, 1, 100, 451, 0.01 },
        { 2, 0, 200, 1151, 1e-9 }, { 2, 0, 100, 651, 1e-9 },
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof t / sizeof t[0]; i++) {
        const double want = edf_exact(t[i].alpha, t[i].modified, t[i].m, t[i].n);
        const double got = fnav_allan_edf_var(t[i].alpha, 2, t[i].modified, (uint32_t)t[i].m, (uint32_t)t[i].n, 1);
        FNAV_ASSERT_CLOSE(got, want, 0.0, t[i].rel);
    }
    /* the reference itself: one term is one degree of freedom */
    FNAV_ASSERT_CLOSE(edf_exact(0, 0, 50, 101), 1.0, 1e-12, 0.0);
}

static void test_edf_var_edges(void **state)
{
    int alpha, d;
    (void)state;
    for (d = 1; d <= 3; d++) {
        for (alpha = 2; alpha + 2 * d > 1; alpha--) {
            const uint32_t m = 4u;
            /* a term spans L = m / F + m d phase values: 1 + m d unmodified (F = m), m + m d modified */
            assert_true(fabs(fnav_allan_edf_var(alpha, d, 0, m, 1u + m * (uint32_t)d, 1) - 1.0) < 1e-12);
            assert_true(fabs(fnav_allan_edf_var(alpha, d, 0, m, 1u + m * (uint32_t)d, 0) - 1.0) < 1e-12);
            assert_true(fabs(fnav_allan_edf_var(alpha, d, 1, m, m + m * (uint32_t)d, 1) - 1.0) < 1e-12);
            assert_true(fnav_allan_edf_var(alpha, d, 0, m, m * (uint32_t)d, 1) < 0.0);
            assert_true(fnav_allan_edf_var(alpha, d, 1, m, m + m * (uint32_t)d - 1u, 1) < 0.0);
        }
        assert_true(fnav_allan_edf_var(alpha, d, 0, 4u, 1000u, 1) < 0.0); /* alpha + 2 d = 1 */
    }
    assert_true(fnav_allan_edf_var(0, 0, 0, 4u, 1000u, 1) < 0.0);
    assert_true(fnav_allan_edf_var(0, 4, 0, 4u, 1000u, 1) < 0.0);
    assert_true(fnav_allan_edf_var(3, 2, 0, 4u, 1000u, 1) < 0.0);
    for (alpha = -2; alpha <= 2; alpha++) {
        assert_true(fnav_allan_edf_var(alpha, 2, 0, 16u, 1001u, 1) == fnav_allan_edf(alpha, 16u, 1001u, 1));
    }
    /* Stable32's PHASE.DAT HDEV octave limits at m = 128 (5 terms, white FM)
     * imply an EDF of 2.8664 (lower limit) and 2.8672 (upper) at the
     * one-sigma confidence (scripts/stable32_conf.py; their 5 printed digits
     * move it by about 0.002): Greenhall's d = 3, non-overlapping value */
    {
        const double e = fnav_allan_edf_var(0, 3, 0, 128u, 1001u, 0);
        assert_true(e > 2.862 && e < 2.871);
    }
    /* the Hadamard variance converges for alpha down to -4 */
    assert_true(fnav_allan_edf_var(-4, 3, 0, 16u, 1001u, 1) > 0.0);
    assert_true(fnav_allan_edf_var(-4, 3, 1, 16u, 1001u, 1) > 0.0);
}

/* The NBS14 1000-point frequency set as its phase record x_0 .. x_1000
 * (x_0 = 0). @return 0, or -1 (with the skip notice) when the shared data
 * are not found. */
static int nbs14_1000_phase(double *x)
{
    static double y[1000];
    char path[512];
    size_t i;
    if (fnav_testdata_path("allan_reference/nbs14/nbs14_1000pt_frequency.txt", path, sizeof path) != 0) {
        fnav_test_skip_notice("NBS14 1000-point set");
        return -1;
    }
    assert_int_equal(read_numbers(path, y, 1000), 1000);
    x[0] = 0.0;
    for (i = 0; i < 1000u; i++) {
        x[i + 1u] = x[i] + y[i];
    }
    return 0;
}

/* PDEV of the NBS14 1000-point set against SigmaTheta's values (17 digits,
 * nbs14_1000pt_pdev_expected.csv, octaves m = 1 .. 256), with the term
 * count n - 2m of SigmaTheta and allantools. */
static void test_pdev_nbs14(void **state)
{
    static double x[1001];
    char path[512], line[256];
    FILE *f;
    int rows = 0;
    (void)state;
    if (nbs14_1000_phase(x) != 0) {
        skip();
    }
    assert_int_equal(fnav_testdata_path("allan_reference/nbs14/nbs14_1000pt_pdev_expected.csv", path, sizeof path), 0);
    f = fopen(path, "r");
    assert_non_null(f);
    while (fgets(line, sizeof line, f) != NULL) {
        unsigned m;
        double want;
        uint32_t terms;
        if (sscanf(line, "%u,%lf", &m, &want) == 2) {
            const double dev = sqrt(hx_dev_var_record(HX_DEV_PDEV, x, 1001u, m, &terms));
            FNAV_ASSERT_CLOSE(dev, want, 0.0, 1e-9);
            assert_int_equal(terms, 1001u - 2u * m);
            rows++;
        }
    }
    fclose(f);
    assert_int_equal(rows, 9);
    /* the longest averaging factor with a term (one), and the first without */
    {
        uint32_t terms;
        assert_true(isfinite(hx_dev_var_record(HX_DEV_PDEV, x, 1001u, 500u, &terms)));
        assert_int_equal(terms, 1u);
        assert_true(isnan(hx_dev_var_record(HX_DEV_PDEV, x, 1001u, 501u, &terms)));
        assert_int_equal(terms, 0u);
    }
}

/* MTOTDEV, TTOTDEV and HTOTDEV of the NBS14 1000-point set:
 * - against scripts/totdev_ref.py, an independent numpy computation of SP
 *   1065's definitions on whole arrays (the C code slides prefix sums), to
 *   1e-9 at m = 1 .. 333, with the term counts n - 3m + 1 and n - 3m;
 * - against Stable32 (nbs14_1000pt_expected.csv) at tau 1, 10, 100 s:
 *   MTOTDEV and TTOTDEV to their 5 printed digits (5e-5), HTOTDEV to 1e-6
 *   once the published white-FM bias correction (1 / 0.995) is undone;
 * - the work counts of the O(n m) forms (hx_dev_work()), and NaN beyond the
 *   longest m. */
static void test_totdev_nbs14(void **state)
{
    static const struct {
        unsigned m;
        double mtot, htot;
    } gold[] = { /* /usr/bin/python3 scripts/totdev_ref.py */
        { 1u, 0.20663914268817099, 0.29438832912413193 },    { 2u, 0.14337124709598123, 0.20246625949942573 },
        { 3u, 0.1085139467408664, 0.15732448599500104 },     { 5u, 0.085082085328324591, 0.12943173266433511 },
        { 8u, 0.065721368838037073, 0.10795284739233242 },   { 10u, 0.055528859768678669, 0.095907204106474783 },
        { 16u, 0.037135008950817248, 0.065102045841168021 }, { 33u, 0.028788891939666265, 0.044175585921787039 },
        { 64u, 0.023606398236653562, 0.033492208585093636 }, { 100u, 0.019546751292673557, 0.030504478811998598 },
        { 128u, 0.016668312513796264, 0.028789940479667309 }, { 256u, 0.005960743187606617, 0.014773396838998608 },
        { 333u, 0.0039410738720929367, 0.0099545270480502126 },
    };
    static const double s32_mtot[3] = { 2.0664e-01, 5.5529e-02, 1.9547e-02 };
    static const double s32_ttot[3] = { 1.1930e-01, 3.2060e-01, 1.1285e+00 };
    static const double s32_htot[3] = { 2.943883e-01, 9.614787e-02, 3.058103e-02 };
    static const unsigned s32_m[3] = { 1u, 10u, 100u };
    static double x[1001];
    size_t i;
    uint32_t terms;
    (void)state;
    if (nbs14_1000_phase(x) != 0) {
        skip();
    }
    for (i = 0; i < sizeof gold / sizeof gold[0]; i++) {
        const unsigned m = gold[i].m;
        FNAV_ASSERT_CLOSE(sqrt(hx_dev_var_record(HX_DEV_MTOTDEV, x, 1001u, m, &terms)), gold[i].mtot, 0.0, 1e-9);
        assert_int_equal(terms, 1001u - 3u * m + 1u);
        assert_true(hx_dev_work(HX_DEV_MTOTDEV, 1001u, m) == (uint64_t)terms * 6u * m);
        FNAV_ASSERT_CLOSE(sqrt(hx_dev_var_record(HX_DEV_TTOTDEV, x, 1001u, m, &terms)) *
                              hx_dev_scale(HX_DEV_TTOTDEV, m, 1.0),
                          gold[i].mtot * (double)m / sqrt(3.0), 0.0, 1e-9);
        FNAV_ASSERT_CLOSE(sqrt(hx_dev_var_record(HX_DEV_HTOTDEV, x, 1001u, m, &terms)), gold[i].htot, 0.0, 1e-9);
        assert_int_equal(terms, m == 1u ? 1001u - 3u : 1001u - 3u * m);
        assert_true(hx_dev_work(HX_DEV_HTOTDEV, 1001u, m) == (m == 1u ? 0u : (uint64_t)terms * 6u * m));
    }
    for (i = 0; i < 3u; i++) {
        const unsigned m = s32_m[i];
        const double mt = sqrt(hx_dev_var_record(HX_DEV_MTOTDEV, x, 1001u, m, &terms));
        const double ht = sqrt(hx_dev_var_record(HX_DEV_HTOTDEV, x, 1001u, m, &terms) / (m > 1u ? 0.995 : 1.0));
        FNAV_ASSERT_CLOSE(mt, s32_mtot[i], 0.0, 5e-5);
        FNAV_ASSERT_CLOSE(mt * hx_dev_scale(HX_DEV_TTOTDEV, m, 1.0), s32_ttot[i], 0.0, 5e-5);
        FNAV_ASSERT_CLOSE(ht, s32_htot[i], 0.0, 1e-6);
    }
    /* the longest m with a term: 3m <= n (MTOT), 3m <= n - 1 (HTOT, frequency windows) */
    assert_true(isfinite(hx_dev_var_record(HX_DEV_MTOTDEV, x, 1001u, 333u, &terms)));
    assert_int_equal(terms, 3u);
    assert_true(isnan(hx_dev_var_record(HX_DEV_MTOTDEV, x, 999u, 334u, &terms)));
    assert_int_equal(terms, 0u);
    assert_true(isfinite(hx_dev_var_record(HX_DEV_HTOTDEV, x, 1000u, 333u, &terms)));
    assert_int_equal(terms, 1u);
    assert_true(isnan(hx_dev_var_record(HX_DEV_HTOTDEV, x, 999u, 333u, &terms)));
    assert_true(hx_dev_work(HX_DEV_HTOTDEV, 999u, 333u) == 0u && hx_dev_work(HX_DEV_OADEV, 1001u, 8u) == 0u);
}

/* Chi-square quantiles at large EDF, where GSL's gsl_cdf_chisq_Pinv() fails
 * at some nu (81,000 and 243,000 at the lower one-sigma point; 6,561,000 at
 * the upper): scipy.stats.chi2.ppf values to 1e-6 (GSL's other tail is
 * itself 2e-7 off at 6.5e6); and the one-sigma interval of a deviation is
 * finite and as wide as the asymptotic +-1 / sqrt(2 nu) (within 2 %) from
 * nu = 1e3 to 1e8: an exact OADEV at m = 1 on 1,000,000 samples had no
 * upper limit before. */
static void test_chi2_quantile_large(void **state)
{
    static const double ref[6][3] = { /* nu, P, chi2.ppf(P, nu) */
        { 81000.0, 0.15865525393145702, 80597.509420763541 },
        { 81000.0, 0.84134474606854304, 81402.490579968056 },
        { 243000.0, 0.15865525393145702, 242302.86395409697 },
        { 243000.0, 0.84134474606854304, 243697.13604614689 },
        { 6561000.0, 0.15865525393145702, 6557377.5700604934 },
        { 6561000.0, 0.84134474606854304, 6564622.4299395159 },
    };
    double nu;
    size_t i;
    (void)state;
    for (i = 0; i < 6u; i++) {
        FNAV_ASSERT_CLOSE(hx_chi2_quantile(ref[i][0], ref[i][1]), ref[i][2], 0.0, 1e-6);
    }
    for (nu = 1e3; nu < 1e8; nu *= 1.37) {
        double lo, hi;
        assert_int_equal(hx_allan_ci(1.0, nu, 0.682689492137086, &lo, &hi), 0);
        assert_true(isfinite(lo) && isfinite(hi) && lo < 1.0 && hi > 1.0);
        FNAV_ASSERT_CLOSE(0.5 * (hi - lo), 1.0 / sqrt(2.0 * nu), 0.0, 0.02);
    }
}

/* The intervals of the total forms: MTOTDEV and TTOTDEV take SP 1065's
 * Table 8 (edf = b n / m - c, alpha +2 .. -2; undefined outside), HTOTDEV the
 * overlapping Hadamard variance's EDF (conservative: docs/allan.md, checked
 * by scripts/totdev_ref.py --mc). */
static void test_totdev_edf(void **state)
{
    (void)state;
    FNAV_ASSERT_CLOSE(hx_dev_edf(HX_DEV_MTOTDEV, 2, 10u, 1001u), 1.90 * 100.1 - 2.10, 0.0, 1e-12);
    FNAV_ASSERT_CLOSE(hx_dev_edf(HX_DEV_MTOTDEV, 0, 10u, 1001u), 1.10 * 100.1 - 1.20, 0.0, 1e-12);
    FNAV_ASSERT_CLOSE(hx_dev_edf(HX_DEV_TTOTDEV, -2, 10u, 1001u), 0.75 * 100.1 - 0.31, 0.0, 1e-12);
    assert_true(hx_dev_edf(HX_DEV_MTOTDEV, -3, 10u, 1001u) < 0.0);
    /* TOTDEV: SP 1065 Table 7, edf = b n / m - c for white, flicker and
     * random-walk FM (b, c = 1.50, 0; 1.17, 0.22; 0.93, 0.36); above alpha 0
     * the overlapping AVAR's. A hand-made mutant dropping the flicker row's
     * c passed every suite (fails here, checked) */
    FNAV_ASSERT_CLOSE(hx_dev_edf(HX_DEV_TOTDEV, 0, 10u, 1001u), 1.50 * 100.1, 0.0, 1e-12);
    FNAV_ASSERT_CLOSE(hx_dev_edf(HX_DEV_TOTDEV, -1, 10u, 1001u), 1.17 * 100.1 - 0.22, 0.0, 1e-12);
    FNAV_ASSERT_CLOSE(hx_dev_edf(HX_DEV_TOTDEV, -2, 10u, 1001u), 0.93 * 100.1 - 0.36, 0.0, 1e-12);
    assert_true(hx_dev_edf(HX_DEV_TOTDEV, 1, 10u, 1001u) == fnav_allan_edf_var(1, 2, 0, 10u, 1001u, 1));
    assert_true(hx_dev_edf(HX_DEV_TOTDEV, -3, 10u, 1001u) < 0.0);
    assert_true(hx_dev_edf(HX_DEV_MTOTDEV, 0, 0u, 1001u) < 0.0);
    assert_true(hx_dev_edf(HX_DEV_HTOTDEV, -4, 16u, 1001u) == hx_dev_edf(HX_DEV_OHDEV, -4, 16u, 1001u));
    assert_true(hx_dev_edf(HX_DEV_HTOTDEV, 0, 16u, 1001u) == hx_dev_edf(HX_DEV_OHDEV, 0, 16u, 1001u));
}

/* fnav_allan_slopes (fnav_allan.h): the least-squares slope of log ADEV
 * over the point and its neighbours, 3 inside and 2 at the ends. With tau
 * doubling (log tau equally spaced) that is (y[i+1] - y[i-1]) / (x[i+1] -
 * x[i-1]) inside and the two-point slope at the ends: ADEV 1, 1/2, 1/2, 1, 4
 * at tau 1..16 (log2: 0, -1, -1, 0, 2) gives -1, -1/2, 1/2, 3/2, 2. An
 * unusable point (avar 0) has a NaN slope and is left out of its
 * neighbours'. Taking the next-to-last point's slope from two points (a
 * mutant of the upper neighbour's bound) passed every suite. */
static void test_slopes_three_points(void **state)
{
    static const double adev[5] = { 1.0, 0.5, 0.5, 1.0, 4.0 }, want[5] = { -1.0, -0.5, 0.5, 1.5, 2.0 };
    fnav_allan_result_t r[5];
    fnav_real_t slope[5];
    int i;
    (void)state;
    memset(r, 0, sizeof r);
    for (i = 0; i < 5; i++) {
        r[i].tau = 1u << i;
        r[i].terms = 100u;
        r[i].avar = (fnav_real_t)(adev[i] * adev[i]);
    }
    fnav_allan_slopes(r, 5, slope);
    for (i = 0; i < 5; i++) {
        FNAV_ASSERT_CLOSE(slope[i], want[i], 1e-5, 0.0);
    }
    /* point 2 unusable: its slope NaN, points 1 and 3 from their other two */
    r[2].avar = FNAV_R(0.0);
    fnav_allan_slopes(r, 5, slope);
    assert_true(slope[2] != slope[2]);
    FNAV_ASSERT_CLOSE(slope[1], -1.0, 1e-5, 0.0);
    FNAV_ASSERT_CLOSE(slope[3], 2.0, 1e-5, 0.0);
}

/* The slopes at long tau, on the default 4-per-octave grid from 2^15 to
 * 2^20 samples, of an ADEV that is an exact power law (tau^s, s = -1/2 then
 * +1/2 from 2^17 on: each point's three-point slope is s, or at the bend
 * the least-squares line through the corner, computed here in long double).
 * The inputs carry their float rounding: each log ADEV and log tau
 * difference errs by at most about 2u (u = FNAV_REAL_EPSILON / 2), which
 * a least-squares line over neighbours at least h apart in log tau turns
 * into (2 + 2 |s|) u / h; the bound is 8 u / h, h = ln(8/7) (3.6e-6 in
 * float, 6.6e-15 in double). The slopes summed the uncentred logs (ln tau
 * up to 13.9, their squares 193) and lost 3.1e-4 here in float (1.1e-12
 * in double) to the cancellation of cnt sxx - sx^2; on the ADIS16405 logs
 * (`bin/harness allan LOG --json`) up to 6.6e-3 against numpy
 * (scripts/check_allan_psd_real.py; 8.4e-4 within the identified range,
 * the audit's own comparison). */
static void test_slopes_long_tau(void **state)
{
    static const uint32_t tau[21] = { 32768u,  40960u,  49152u,  57344u,  65536u,  81920u,  98304u,
                                      114688u, 131072u, 163840u, 196608u, 229376u, 262144u, 327680u,
                                      393216u, 458752u, 524288u, 655360u, 786432u, 917504u, 1048576u };
    const double u = (double)FNAV_REAL_EPSILON / 2.0, tol = 8.0 * u / log(8.0 / 7.0);
    fnav_allan_result_t r[21];
    fnav_real_t slope[21];
    long double lx[21], ly[21]; /* the reference in long double: its own rounding far below the bound */
    int i, k;
    (void)state;
    memset(r, 0, sizeof r);
    for (i = 0; i < 21; i++) {
        /* ADEV 0.01 (tau / 2^17)^s: continuous at the bend */
        const double s = tau[i] < 131072u ? -0.5 : 0.5;
        r[i].tau = tau[i];
        r[i].terms = 100u;
        r[i].avar = (fnav_real_t)(1e-4 * pow((double)tau[i] / 131072.0, 2.0 * s));
        lx[i] = logl((long double)tau[i]);
        ly[i] = 0.5L * logl((long double)r[i].avar); /* the rounded input's own line */
    }
    fnav_allan_slopes(r, 21, slope);
    for (i = 0; i < 21; i++) {
        const int lo = i > 0 ? i - 1 : 0, hi = i < 20 ? i + 1 : 20;
        long double sx = 0.0L, sy = 0.0L, sxx = 0.0L, sxy = 0.0L, mx, my;
        double want;
        for (k = lo; k <= hi; k++) {
            sx += lx[k];
            sy += ly[k];
        }
        mx = sx / (long double)(hi - lo + 1);
        my = sy / (long double)(hi - lo + 1);
        for (k = lo; k <= hi; k++) {
            sxx += (lx[k] - mx) * (lx[k] - mx);
            sxy += (lx[k] - mx) * (ly[k] - my);
        }
        want = (double)(sxy / sxx);
        if (getenv("ALLAN_PER_TAU") != NULL) {
            printf("slope tau %7u: %.9g want %.9g, |diff| %.2e (bound %.2e)\n", (unsigned)tau[i], (double)slope[i],
                   want, fabs((double)slope[i] - want), tol);
        }
        FNAV_ASSERT_CLOSE(slope[i], want, tol, 0.0);
    }
}

/* The paper's BS and t_BS at a minimum on the table's last point: no
 * parabola (it needs a neighbour on each side), BS the last ADEV and t_BS
 * its tau exactly. The entry after the n given is a usable point above the
 * minimum: reading it (a mutant of the bound, imin + 1 <= n) drew a
 * parabola through it and passed every suite. */
static void test_paper_min_at_end(void **state)
{
    static const double adev[5] = { 4.0, 2.0, 1.0, 0.5, 2.0 };
    fnav_allan_result_t r[5];
    fnav_allan_paper_id_t id;
    int i;
    (void)state;
    memset(r, 0, sizeof r);
    for (i = 0; i < 5; i++) {
        r[i].tau = 100u << i; /* 100 .. 1600 samples at 100 Hz: 1 s is the first */
        r[i].terms = 100u;
        r[i].avar = (fnav_real_t)(adev[i] * adev[i]);
    }
    assert_int_equal(fnav_allan_identify_paper(r, 4, FNAV_R(100.0), 0u, &id), FNAV_OK);
    assert_int_equal((int)id.i_min, 3);
    FNAV_ASSERT_CLOSE(id.bs, 0.5, 0.0, 1e-6);
    FNAV_ASSERT_CLOSE(id.tau_samples, 800.0, 0.0, 1e-6);
    FNAV_ASSERT_CLOSE(id.t_bs_s, 8.0, 0.0, 1e-6);
    FNAV_ASSERT_CLOSE(id.sigma_v, 4.0, 0.0, 1e-6);
}

/* tau_max (fnav_allan.h; `harness allan` passes 10 % of the record; no
 * suite passed anything but 0, make coverage): on the table of
 * test_paper_min_at_end, the minimum over tau <= 400 is the 400-sample
 * point and over tau <= 800 the 800 one, each exactly (the neighbour
 * above is past tau_max: no parabola); with 0 the parabola in log-log
 * through 400, 800, 1600 refines it, below the grid minimum. And
 * FNAV_E_RANGE when 1 s is below the table (at 50 Hz, 50 samples), when
 * tau_max is below every point, or fewer than 2 points are usable. */
static void test_paper_tau_max(void **state)
{
    static const double adev[5] = { 4.0, 2.0, 1.0, 0.5, 2.0 };
    fnav_allan_result_t r[5];
    fnav_allan_paper_id_t id;
    int i;
    (void)state;
    memset(r, 0, sizeof r);
    for (i = 0; i < 5; i++) {
        r[i].tau = 100u << i;
        r[i].terms = 100u;
        r[i].avar = (fnav_real_t)(adev[i] * adev[i]);
    }
    assert_int_equal(fnav_allan_identify_paper(r, 5, FNAV_R(100.0), 400u, &id), FNAV_OK);
    assert_int_equal((int)id.i_min, 2);
    FNAV_ASSERT_CLOSE(id.bs, 1.0, 0.0, 1e-6);
    FNAV_ASSERT_CLOSE(id.tau_samples, 400.0, 0.0, 1e-6);
    assert_int_equal(fnav_allan_identify_paper(r, 5, FNAV_R(100.0), 800u, &id), FNAV_OK);
    assert_int_equal((int)id.i_min, 3);
    FNAV_ASSERT_CLOSE(id.bs, 0.5, 0.0, 1e-6);
    FNAV_ASSERT_CLOSE(id.tau_samples, 800.0, 0.0, 1e-6);
    assert_int_equal(fnav_allan_identify_paper(r, 5, FNAV_R(100.0), 0u, &id), FNAV_OK);
    assert_int_equal((int)id.i_min, 3);
    {
        /* the vertex of the parabola through (ln tau, ln adev) of the three
         * points, computed here in double */
        const double x0 = log(400.0), x1 = log(800.0), x2 = log(1600.0);
        const double y0 = log(1.0), y1 = log(0.5), y2 = log(2.0);
        const double d1 = (y1 - y0) / (x1 - x0), d2 = (y2 - y1) / (x2 - x1), c2 = (d2 - d1) / (x2 - x0);
        const double xv = 0.5 * (x0 + x1) - d1 / (2.0 * c2);
        const double yv = y0 + d1 * (xv - x0) + c2 * (xv - x0) * (xv - x1);
        assert_true(xv > x0 && xv < x2);
        FNAV_ASSERT_CLOSE(id.tau_samples, exp(xv), 0.0, 1e-5);
        FNAV_ASSERT_CLOSE(id.bs, exp(yv), 0.0, 1e-5);
        assert_true(id.bs < FNAV_R(0.5));
    }
    assert_int_equal(fnav_allan_identify_paper(r, 5, FNAV_R(50.0), 0u, &id), FNAV_E_RANGE);
    /* tau_max below every point: no point to take the minimum of */
    assert_int_equal(fnav_allan_identify_paper(r, 5, FNAV_R(100.0), 50u, &id), FNAV_E_RANGE);
    for (i = 1; i < 5; i++) {
        r[i].terms = 0u; /* no term: not usable */
    }
    assert_int_equal(fnav_allan_identify_paper(r, 5, FNAV_R(100.0), 0u, &id), FNAV_E_RANGE);
}

/* Flicker phase noise (alpha = 1) with more than 100 lags: Greenhall &
 * Riley's algorithm switches from the exact basic sum to their case-3
 * approximation 1/edf = (a0 - a1/r) / (b^2 r), b = b0 + b1 ln m. It must
 * stay near the exact sum over all J = min(M, 3m) lags, which
 * scripts/pvar_edf.py --greenhall-table computes in double from the
 * filter's taps (no code shared with the C). The approximation is 1.9 %,
 * 1.2 % and 0.6 % below it at these points; 3 % bounds that. A b with
 * log10 m in place of ln m gives EDFs a third of these. A short record
 * (r = M/m <= 3 with J > 100 lags) takes the basic sum to 100 lags with m
 * scaled to 100 / r, divided by b^2 100: 0.7, 1.3, 0.5 and 1.1 % above the
 * exact sum at the last four points (the script's second line), inside the
 * same 3 %; a mutant dividing by b / b there (EDFs of 0.004) passed every
 * suite. */
static void test_edf_flicker_pm_table(void **state)
{
    static const uint32_t pt[7][2] = { { 40u, 1001u }, { 64u, 3001u }, { 128u, 4001u }, { 64u, 278u },
                                       { 128u, 556u },  { 40u, 200u },  { 100u, 450u } };
    static const double exact[7] = { 107.5620414, 246.8457145, 204.7103324, 16.36843715,
                                     20.69725378, 16.56890687, 20.00896318 };
    int i;
    (void)state;
    for (i = 0; i < 7; i++) {
        FNAV_ASSERT_CLOSE(fnav_allan_edf_var(1, 2, 0, pt[i][0], pt[i][1], 1), exact[i], 0.0, 0.03);
    }
}

/* Greenhall & Riley's case 2 (unmodified, alpha <= 0, J > 100 lags, r =
 * M/m > d + 1): 1/edf = (a0 - a1/r) / r from their table 2, against the exact
 * basic sum over all lags that scripts/pvar_edf.py --greenhall-fm-table
 * computes from the filter's taps (no code shared with the C), at r just
 * above d + 1 where a1 weighs most. Flicker FM with the Allan filter (d = 2):
 * the table is 0.13 % from the sum at most here, asserted at 1 %; white FM
 * with the overlapping Hadamard filter (d = 3): 2.7 %, 1.7 %, 0.9 %,
 * asserted at 4 %. A hand-made mutant of the flicker FM row (a1 0.375 ->
 * 0.575: +9.5 %) passed every suite and fails here (checked); one of the
 * white FM d = 3 row (a1 0.5 -> 0.05: -11 %) fails here and in Stable32's
 * HDEV intervals (test_phasedat_other_deviations). */
static void test_edf_case2_table(void **state)
{
    static const uint32_t fm[4][2] = { { 40u, 206u }, { 64u, 332u }, { 128u, 648u }, { 40u, 600u } };
    static const double fm_exact[4] = { 4.292301738, 4.337218509, 4.195650285, 15.77540115 };
    static const uint32_t hd[3][2] = { { 40u, 330u }, { 64u, 527u }, { 128u, 1050u } };
    static const double hd_exact[3] = { 7.48648413, 7.542237221, 7.567343772 };
    int i;
    (void)state;
    for (i = 0; i < 4; i++) {
        FNAV_ASSERT_CLOSE(fnav_allan_edf_var(-1, 2, 0, fm[i][0], fm[i][1], 1), fm_exact[i], 0.0, 0.01);
    }
    for (i = 0; i < 3; i++) {
        FNAV_ASSERT_CLOSE(fnav_allan_edf_var(0, 3, 0, hd[i][0], hd[i][1], 1), hd_exact[i], 0.0, 0.04);
    }
}

/* Greenhall & Riley's case 1 (modified: MDEV, TDEV) above 100 lags with
 * r = M/m > 3: 1/edf = (a0 - a1/r) / r from their table 1, against the
 * exact basic sum for the modified Allan filter (the Allan taps convolved
 * with m ones) from scripts/pvar_edf.py --greenhall-mod-table. The table is
 * within 0.1 % of it here (measured), asserted at 1 %. Hand-made mutants of
 * a1 (white PM 0.5 -> 0.05: +18 %; random-walk FM 0.535 -> 0.353: -4.6 %)
 * passed every suite and fail here (checked). */
static void test_edf_modified_table(void **state)
{
    static const uint32_t pt[3][2] = { { 40u, 250u }, { 64u, 400u }, { 128u, 800u } };
    static const double exact[3][3] = { { 5.23380511, 5.225709189, 5.217823017 },
                                        { 3.862128278, 3.853579243, 3.846426253 },
                                        { 2.875951018, 2.868949704, 2.863098798 } };
    int a, i;
    (void)state;
    for (a = 0; a < 3; a++) {
        for (i = 0; i < 3; i++) {
            FNAV_ASSERT_CLOSE(fnav_allan_edf_var(2 - 2 * a, 2, 1, pt[i][0], pt[i][1], 1), exact[a][i], 0.0, 0.01);
        }
    }
}

/* fnav_allan_edf_pvar() against scripts/pvar_edf.py (an independent double
 * computation at the full m): exact to m = 64, within 1e-3 above, where the
 * C code scales the filter of m = 64 (measured: 3.4e-4 at most). And the
 * same script's overlapping Allan filter reproduces Greenhall & Riley's
 * algorithm (fnav_allan_edf_var()) to 1e-9: the computation that the PVAR
 * EDF rests on is theirs. */
static void test_pdev_edf(void **state)
{
    static const uint32_t pt[8][2] = { { 2, 40 },   { 4, 60 },    { 8, 50 },    { 16, 200 },
                                       { 64, 1001 }, { 100, 260 }, { 128, 1001 }, { 256, 1001 } };
    /* scripts/pvar_edf.py: rows alpha = 2 .. -2 */
    static const double pv[5][8] = {
        { 21.07317073, 19.0744921, 7.220970441, 16.73028462, 21.57632536, 2.234819055, 9.728350216, 3.998883816 },
        { 22.66517674, 17.16582649, 6.099108925, 13.98547604, 17.96213693, 1.734472353, 8.068559079, 3.261914387 },
        { 23.51020408, 16.93541551, 5.955197884, 13.72800162, 17.64503866, 1.533581752, 7.895373891, 3.136357433 },
        { 23.59715853, 16.83778542, 5.860544076, 13.63409334, 17.54765765, 1.363734368, 7.803178333, 3.006947262 },
        { 19.38505583, 13.79038036, 4.719117611, 11.13907963, 14.36698672, 1.186584269, 6.324756511, 2.341091802 },
    };
    /* scripts/pvar_edf.py --greenhall: the overlapping Allan filter, first four points */
    static const double av[5][4] = {
        { 19.05882353, 27.84439359, 19.89292543, 90.84978541 }, { 19.73310042, 21.15435496, 10.87489701, 34.46970977 },
        { 20.01830664, 16.62619559, 6.463806933, 15.59265899 }, { 19.88019553, 15.26729478, 5.494300393, 12.8087277 },
        { 16.10001608, 12.19088568, 4.266009197, 10.05142385 },
    };
    int a, i;
    double worst_scaled = 0.0;
    (void)state;
    for (a = 0; a < 5; a++) {
        for (i = 0; i < 8; i++) {
            const double e = fnav_allan_edf_pvar(2 - a, pt[i][0], pt[i][1]);
            FNAV_ASSERT_CLOSE(e, pv[a][i], 0.0, pt[i][0] <= 64u ? 1e-9 : 1e-3);
            if (pt[i][0] > 64u && fabs(e / pv[a][i] - 1.0) > worst_scaled) {
                worst_scaled = fabs(e / pv[a][i] - 1.0);
            }
        }
        for (i = 0; i < 4; i++) {
            FNAV_ASSERT_CLOSE(fnav_allan_edf_var(2 - a, 2, 0, pt[i][0], pt[i][1], 1), av[a][i], 0.0, 1e-9);
        }
        /* m = 1: PVAR is the overlapping Allan variance */
        assert_true(fnav_allan_edf_pvar(2 - a, 1u, 500u) == fnav_allan_edf_var(2 - a, 2, 0, 1u, 500u, 1));
    }
    printf("PVAR EDF above m = 64 (scaled filter) against the full computation: worst %.1e\n", worst_scaled);
    /* one term (n = 2m + 1) is one degree of freedom; none, or a divergent noise, is undefined */
    assert_true(fabs(fnav_allan_edf_pvar(0, 8u, 17u) - 1.0) < 1e-12);
    assert_true(fnav_allan_edf_pvar(0, 8u, 16u) < 0.0);
    assert_true(fnav_allan_edf_pvar(-3, 8u, 1001u) < 0.0);
    assert_true(fnav_allan_edf_pvar(3, 8u, 1001u) < 0.0);
    assert_true(fnav_allan_edf_pvar(0, 0u, 1001u) < 0.0);
}

/* The PVAR EDF against simulation: 2000 records of white phase, white FM and
 * random-walk FM noise, the PDEV of each (hx_dev_var_record()), and the
 * EDF 2 mean^2 / var of the estimates, within 15 % of fnav_allan_edf_pvar()
 * (the simulated EDF's standard error is about 3.5 %: sqrt(2.4 / 2000)). */
static void test_pdev_edf_simulated(void **state)
{
    static double x[257];
    const hx_noise_model_t white = { 1.0, 0.0, 0.0, 0.0, 0.0 };
    static const int alphas[3] = { 2, 0, -2 };
    static const uint32_t ms[2] = { 4, 16 };
    int a, im;
    (void)state;
    for (a = 0; a < 3; a++) {
        for (im = 0; im < 2; im++) {
            hx_noise_sim_t sim;
            double s1 = 0.0, s2 = 0.0, mean, var, edf;
            const int reps = 2000;
            int r;
            assert_int_equal(hx_noise_sim_init(&sim, &white, 1.0, 11u + (unsigned long)(a * 2 + im)), 0);
            for (r = 0; r < reps; r++) {
                double y = 0.0, v;
                uint32_t terms;
                size_t k;
                x[0] = 0.0;
                for (k = 1; k < 257u; k++) {
                    const double e = hx_noise_sim_next(&sim);
                    if (alphas[a] == 2) {
                        x[k] = e;
                    } else if (alphas[a] == 0) {
                        x[k] = x[k - 1u] + e;
                    } else {
                        y += e;
                        x[k] = x[k - 1u] + y;
                    }
                }
                v = hx_dev_var_record(HX_DEV_PDEV, x, 257u, ms[im], &terms);
                s1 += v;
                s2 += v * v;
            }
            hx_noise_sim_free(&sim);
            mean = s1 / reps;
            var = s2 / reps - mean * mean;
            edf = fnav_allan_edf_pvar(alphas[a], ms[im], 257u);
            FNAV_ASSERT_CLOSE(2.0 * mean * mean / var, edf, 0.0, 0.15);
        }
    }
}

/* ------------------------------------------------------------ cascade, float error */

/* The test signal of vectors/allan/gen_allan.py, bit-exact. */
static double *synthetic_signal(size_t n)
{
    double *y = (double *)malloc(n * sizeof *y);
    uint64_t s = 20240601u;
    double r = 0.0;
    const double inv = 1.0 / 4294967296.0;
    size_t k;
    int i;
    assert_non_null(y);
    for (k = 0; k < n; k++) {
        double u[4], w;
        for (i = 0; i < 4; i++) {
            s = 6364136223846793005u * s + 1442695040888963407u;
            u[i] = (double)(s >> 32) * inv;
        }
        w = ((u[0] + u[1]) + u[2]) - 1.5;
        r = r + 2e-4 * (u[3] - 0.5);
        y[k] = ((9.80665 + 0.02 * w) + r) + 1e-7 * (double)k;
    }
    return y;
}

/* Largest relative error of the float build against the extended-precision
 * reference on 1.1e6 samples (docs/allan.md, "Precision (float32 error)"): measured
 * 7.0e-7 (overlapping) and 1.0e-6 (non-overlapping), asserted at 1e-5 (the
 * input itself is rounded to float: 9.8 carries 24 bits). */
#if FNAV_USE_DOUBLE
#define SYN_TOL 1e-9
#else
#define SYN_TOL 1e-5
#endif

static void test_synthetic_every_level(void **state)
{
    const size_t n = 1100000;
    static fnav_allan_t a;
    char path[512], line[256];
    FILE *f;
    double *y, worst = 0.0, worst_n = 0.0;
    size_t i, rows = 0, levels_seen = 0;
    uint32_t last_level = 0;
    (void)state;
    assert_int_equal(fnav_vector_path("allan/allan_synthetic.csv", path, sizeof path), 0);
    y = synthetic_signal(n);
    assert_int_equal(fnav_allan_init(&a, NULL), FNAV_OK);
    for (i = 0; i < n; i++) {
        assert_int_equal(fnav_allan_push(&a, (fnav_real_t)y[i]), FNAV_OK);
    }
    free(y);
    f = fopen(path, "r");
    assert_non_null(f);
    while (fgets(line, sizeof line, f) != NULL) {
        unsigned tau, level, terms, terms_n;
        double avar, avar_n;
        fnav_allan_result_t r;
        if (sscanf(line, "%u,%u,%u,%u,%lf,%lf", &tau, &level, &terms, &terms_n, &avar, &avar_n) != 6) {
            continue;
        }
        assert_int_equal(fnav_allan_get(&a, rows, &r), FNAV_OK);
        assert_int_equal(r.tau, tau);
        assert_int_equal(r.level, level);
        assert_int_equal(r.terms, terms);
        assert_int_equal(r.terms_nonoverlap, terms_n);
        FNAV_ASSERT_CLOSE(r.avar, avar, 0.0, SYN_TOL);
        FNAV_ASSERT_CLOSE(r.avar_nonoverlap, avar_n, 0.0, SYN_TOL);
        if (fabs((double)r.avar / avar - 1.0) > worst) {
            worst = fabs((double)r.avar / avar - 1.0);
        }
        if (fabs((double)r.avar_nonoverlap / avar_n - 1.0) > worst_n) {
            worst_n = fabs((double)r.avar_nonoverlap / avar_n - 1.0);
        }
        if (level != last_level) {
            levels_seen++;
            last_level = level;
        }
        rows++;
    }
    fclose(f);
    assert_true(rows >= 38);       /* tau up to 2^19 */
    assert_true(levels_seen >= 10); /* the cascade is exercised */
    fprintf(stderr, "[  INFO    ] %s build: largest relative AVAR error %.2g (overlapping), %.2g (non-overlapping)\n",
            FNAV_USE_DOUBLE ? "double" : "float", worst, worst_n);
}

/* A first sample far from the mean (a start-up zero before 2^20 samples of
 * 9.81 + white noise): the estimator re-centres its input on the running
 * mean (docs/allan.md, "Phase"), so the phase does not grow by 9.81 per
 * sample and the cascade rings keep their precision. Reference: the same
 * estimator terms (every sample at level 0, every 2^level-th phase value in
 * the cascade) summed directly on a long double phase. Measured: float 1.5e-4
 * relative at most (at tau 65536; 0.12 of the tolerance below at most, at
 * tau 384), 1.1e-2 before the re-centring.
 *
 * Tolerance, derived per tau (not a fixed 2e-3 in float, 1e-9 in
 * double), first order in u = FNAV_REAL_EPSILON / 2, worst case (no
 * cancellation assumed). Each term d = (x_e + x_{e-2m}) - 2 x_{e-m} uses
 * three stored phase values; a stored value is relative to its ring's base
 * and in the frame of the current y_0, so its magnitude is at most
 * X = R + |y_0 - mean| 2S: R the range of the reference phase over the
 * 2S samples before e (S: the ring's span, 512 + 32 samples at level 0,
 * 17 stride in the cascade; the base is a phase of that ring), the line
 * of the y_0 offset over them (y_0 read after every push; the reference
 * phase is relative to the input's mean 9.81); both taken over the (at
 * most 3) blocks of S samples that hold the window. A stored value has been
 * rounded when written ((ph - base) - pc: 2 u X), at each of at most two
 * re-basings (u X; the shift's own rounding is common to the ring and
 * cancels in d) and at each re-centring in the window (the line's product
 * and the subtraction: u (2 |dy_0| S + X), |dy_0| <= 2 of the largest
 * offset): with weights 1, 2, 1 that is 4 u (4 X + n_rc (4 off S + X));
 * d's own two roundings add u (2 X + |d|). The offset is that after the
 * first re-centring (r1, index 511): a term using a value written before
 * it (y_0 = 0, the phase 9.81 per sample) adds 4 u (4 X' + 9.83 r1 + X'),
 * X' = 9.81 r1 + R (its write and the correcting line's product and
 * subtraction). The Kahan phase pair errs by at
 * most u (|y - y_0| + u |ph|) per sample (the compensation captures the
 * sum's rounding exactly; (y - y_0) - pc rounds once), so a second
 * difference by u sum_{(e-2m, e]} |y - y_0| + 2m u^2 |ph|max. With Delta_e
 * that bound, sum d^2 errs by at most sum (2 |d| Delta_e + Delta_e^2),
 * relative to sum d^2 from the reference; the sums add 70 u + 2 T u^2
 * (d^2: u; level 0's plain block sums of 32 terms and the pending ones:
 * 2 x 31 u; the Kahan sum: 2 u + 2 T u^2; so - co, the divisor 2 tau^2 T
 * and the division: 3 u). The reference, in long double, is exact to this
 * order.
 *
 * For a term whose values were all written after the first re-centring
 * (the other terms keep the bound above and its pre-re-centring addition),
 * X is taken per term (not R + the largest offset in the 3 blocks x 2S,
 * the coarse X): a stored value is ph_q - base, the base the phase at
 * the ring's last re-basing, and the estimator's phase steps by y - y_0
 * where the reference's steps by y - 9.81 (the phase itself is never
 * re-centred, only the stored values), so X = R + sum |y_0 - 9.81| over the
 * pushes from the earliest base of the oldest value (the last re-basing
 * before it was written: ring0 at n = 511 mod 512, a cascade ring at every
 * 17th write, else 0) to e, + 2S |dy_0| for each re-centring at or after the
 * oldest value's write (its line); each such re-centring's rounding is
 * u (2 |dy_0| S + X) per value. The coarse X leaves out the phase from before
 * the first re-centring (y_0 = 0: 9.81 per sample, 5013 over its 511)
 * that a cascade value written after it carries until its ring first
 * re-bases, and takes the 0.019 offset between the first and second
 * re-centrings over all 2S samples of every window that held it. Float, per
 * tau (ALLAN_PER_TAU=1 build/host/tests/test_allan): the bound is the coarse
 * one to 1 % up to tau 256, 3-9 % above it from 384 to 16384 (the left-out
 * phase: 1.06e-3 at 384 where 1.03e-3, 1.12e-3 at 4096 where 1.03e-3), and
 * below it from 24576 (2.14e-3 where 2.49e-3; 3.37e-3 at 65536 where
 * 4.85e-3; 6.17e-3 at 98304 where 1.25e-2); measured 1.9e-7 to 1.5e-4, at
 * most 0.12 of it. It stays above the fixed 2e-3 from tau 24576:
 * there the top levels' values written before their ring first re-bases
 * (17 x 4096 samples and more) carry the 5013 of the first 511 samples, a
 * rounding of u 5013 = 3e-4 on second differences of 0.6-0.9. Double:
 * 3.8e-13 to 1.1e-11 (2.3e-11 with the coarse X), measured 2.4e-13. */
static void test_unrepresentative_first_sample(void **state)
{
    const size_t n = (size_t)1 << 20;
    const double u = (double)FNAV_REAL_EPSILON / 2.0;
    static fnav_allan_t a;
    long double *x = (long double *)malloc((n + 1u) * sizeof *x);
    double *off = (double *)malloc((n + 1u) * sizeof *off);   /* |y_0 - 9.81| after push k */
    double *pinc = (double *)malloc((n + 1u) * sizeof *pinc); /* prefix sums of |y - y_0| */
    uint32_t *prc = (uint32_t *)malloc((n + 1u) * sizeof *prc); /* prefix counts of y_0 changes */
    double *poff = (double *)malloc((n + 1u) * sizeof *poff); /* prefix sums of |y_0 - 9.81| as pushed */
    size_t rc_at[16];                                          /* the phase index of each y_0 change */
    double rc_dy[16];                                          /* |the change of y_0| there */
    size_t nrc_all = 0;
    static long double bmin[((size_t)1 << 20) / FNAV_ALLAN_RING0 + 2u], bmax[((size_t)1 << 20) / FNAV_ALLAN_RING0 + 2u];
    static double boff[((size_t)1 << 20) / FNAV_ALLAN_RING0 + 2u];
    uint64_t s = 12345u;
    size_t k, i, r1, checked = 0;
    double worst = 0.0, worst_frac = 0.0, phmax, tol_at_worst = 0.0, tol_min = 1.0, tol_max = 0.0;
    (void)state;
    assert_non_null(x);
    assert_non_null(off);
    assert_non_null(pinc);
    assert_non_null(prc);
    assert_non_null(poff);
    assert_int_equal(fnav_allan_init(&a, NULL), FNAV_OK);
    x[0] = 0.0L;
    pinc[0] = 0.0;
    prc[0] = 0u;
    off[0] = 0.0;
    poff[0] = 0.0;
    for (k = 0; k < n; k++) {
        double uu = 0.0, y, y0_before;
        for (i = 0; i < 12u; i++) {
            s = 6364136223846793005u * s + 1442695040888963407u;
            uu += (double)(s >> 32) / 4294967296.0;
        }
        y = k == 0u ? 0.0 : 9.81 + 2e-3 * (uu - 6.0);
        y = (double)(fnav_real_t)y; /* what the estimator sees */
        y0_before = k == 0u ? y : (double)a.y0;
        assert_int_equal(fnav_allan_push(&a, (fnav_real_t)y), FNAV_OK);
        x[k + 1u] = x[k] + ((long double)y - 9.81L);
        pinc[k + 1u] = pinc[k] + fabs(y - y0_before);
        prc[k + 1u] = prc[k] + ((double)a.y0 != y0_before ? 1u : 0u);
        /* the estimator's phase steps by y - y_0, the reference's by
         * y - 9.81: they part by |y_0 - 9.81| at this push */
        poff[k + 1u] = poff[k] + fabs((k == 0u ? y : y0_before) - 9.81);
        if (prc[k + 1u] != prc[k]) {
            assert_true(nrc_all < 16u);
            rc_at[nrc_all] = k + 1u;
            rc_dy[nrc_all] = fabs((double)a.y0 - y0_before);
            nrc_all++;
        }
        off[k + 1u] = fabs((double)a.y0 - 9.81);
        if (k == 0u) {
            off[0] = off[1]; /* y_0 = the first sample, 0, from the start */
        }
    }
    phmax = pinc[n];
    for (r1 = 1; r1 <= n && prc[r1] == 0u; r1++) {
    }
    assert_true(r1 <= FNAV_ALLAN_RING0); /* the first re-centring, when ring0 first wraps */
    for (i = 0; i < fnav_allan_count(&a); i++) {
        fnav_allan_result_t r;
        long double so = 0.0L, sn = 0.0L;
        double bo = 0.0, bn = 0.0, rel_o, rel_n;
        size_t st, m, e, j, terms = 0, terms_n = 0, span;
        assert_int_equal(fnav_allan_get(&a, i, &r), FNAV_OK);
        if ((size_t)r.tau * 10u > n) {
            break;
        }
        st = r.stride;
        m = r.tau;
        span = st == 1u ? FNAV_ALLAN_RING0 + FNAV_ALLAN_BLOCK : FNAV_ALLAN_CASCADE_RING * st;
        /* the reference phase's range and the largest offset per block of
         * span samples: the 2 span before e lie in at most 3 blocks */
        for (j = 0; j * span <= n; j++) {
            size_t q;
            bmin[j] = x[j * span];
            bmax[j] = x[j * span];
            boff[j] = 0.0;
            for (q = j * span; q < (j + 1u) * span && q <= n; q++) {
                bmin[j] = x[q] < bmin[j] ? x[q] : bmin[j];
                bmax[j] = x[q] > bmax[j] ? x[q] : bmax[j];
                if (q >= r1) {
                    boff[j] = off[q] > boff[j] ? off[q] : boff[j];
                }
            }
        }
        for (e = 2u * m; e <= n; e += st) {
            const long double d = (x[e] - 2.0L * x[e - m]) + x[e - 2u * m];
            const size_t lo = e > 2u * span ? e - 2u * span : 0u;
            long double xmin = bmin[lo / span], xmax = bmax[lo / span];
            double offm = 0.0, bigx, delta;
            const uint32_t nrc = prc[e] - prc[lo];
            for (j = lo / span; j <= e / span; j++) {
                xmin = bmin[j] < xmin ? bmin[j] : xmin;
                xmax = bmax[j] > xmax ? bmax[j] : xmax;
                offm = boff[j] > offm ? boff[j] : offm;
            }
            if (e - 2u * m >= r1) {
                /* every value of the term written after the first
                 * re-centring: see the comment above, X from the window's
                 * own offsets and re-centrings */
                const size_t q0 = e - 2u * m, per = st == 1u ? FNAV_ALLAN_RING0 : FNAV_ALLAN_CASCADE_RING * st;
                /* the earliest base of the oldest value: the last re-basing
                 * before it was written (ring0 at n = 511 mod 512, a
                 * cascade ring after its 17th, 34th ... write), else 0 */
                const size_t nb = st == 1u ? (q0 > per - 1u ? (q0 - per) / per * per + per - 1u : 0u)
                                           : (q0 > per ? (q0 - 1u) / per * per : 0u);
                double rcs = 0.0;
                size_t c;
                bigx = (double)(xmax - xmin) + (poff[e] - poff[nb]);
                for (c = 0; c < nrc_all; c++) {
                    if (rc_at[c] >= e - 2u * m && rc_at[c] <= e) {
                        bigx += rc_dy[c] * 2.0 * (double)span;
                    }
                }
                for (c = 0; c < nrc_all; c++) {
                    if (rc_at[c] >= e - 2u * m && rc_at[c] <= e) {
                        rcs += 2.0 * rc_dy[c] * (double)span + bigx;
                    }
                }
                delta = u * (4.0 * (4.0 * bigx + rcs) + 2.0 * bigx + fabs((double)d));
            } else {
                bigx = (double)(xmax - xmin) + offm * 2.0 * (double)span;
                delta = u * (4.0 * (4.0 * bigx + (double)nrc * (4.0 * offm * (double)span + bigx)) + 2.0 * bigx +
                             fabs((double)d));
            }
            delta += u * (pinc[e] - pinc[e - 2u * m]) + 2.0 * (double)m * u * u * phmax;
            if (e - 2u * m < r1) {
                /* a value written before the first re-centring: in the frame
                 * y_0 = 0, up to 9.81 r1 from its base, moved at r1 by a line
                 * of slope |dy_0| <= 9.83 over at most r1 samples */
                const double xpre = 9.81 * (double)r1 + (double)(xmax - xmin);
                delta += u * 4.0 * (4.0 * xpre + 9.83 * (double)r1 + xpre);
            }
            so += d * d;
            bo += 2.0 * fabs((double)d) * delta + delta * delta;
            terms++;
            if (e % m == 0u) {
                sn += d * d;
                bn += 2.0 * fabs((double)d) * delta + delta * delta;
                terms_n++;
            }
        }
        assert_int_equal(r.terms, terms);
        assert_int_equal(r.terms_nonoverlap, terms_n);
        rel_o = bo / (double)so + 70.0 * u + 2.0 * (double)terms * u * u;
        rel_n = bn / (double)sn + 70.0 * u + 2.0 * (double)terms_n * u * u;
        so /= 2.0L * (long double)m * (long double)m * (long double)terms;
        sn /= 2.0L * (long double)m * (long double)m * (long double)terms_n;
        if (getenv("ALLAN_PER_TAU") != NULL) {
            fprintf(stderr,
                    "[  INFO    ] tau %6zu: relative AVAR error %.3g, derived tolerance %.3g (non-overlapping %.3g, "
                    "%.3g)\n",
                    m, fabs((double)r.avar / (double)so - 1.0), rel_o,
                    fabs((double)r.avar_nonoverlap / (double)sn - 1.0), rel_n);
        }
        tol_min = rel_o < tol_min ? rel_o : tol_min;
        tol_max = rel_o > tol_max ? rel_o : tol_max;
        FNAV_ASSERT_CLOSE(r.avar, (double)so, 0.0, rel_o);
        FNAV_ASSERT_CLOSE(r.avar_nonoverlap, (double)sn, 0.0, rel_n);
        if (fabs((double)r.avar / (double)so - 1.0) > worst) {
            worst = fabs((double)r.avar / (double)so - 1.0);
            tol_at_worst = rel_o;
        }
        if (fabs((double)r.avar / (double)so - 1.0) / rel_o > worst_frac) {
            worst_frac = fabs((double)r.avar / (double)so - 1.0) / rel_o;
        }
        checked++;
    }
    free(x);
    free(off);
    free(pinc);
    free(prc);
    free(poff);
    assert_true(checked >= 30u); /* tau up to 2^16 samples: cascade levels 5..13 */
    fprintf(stderr, "[  INFO    ] %s build, first sample 0: largest relative AVAR error %.2g (derived tolerance "
                    "there %.2g; %.2g to %.2g over tau); at most %.2g of the derived tolerance\n",
            FNAV_USE_DOUBLE ? "double" : "float", worst, tol_at_worst, tol_min, tol_max, worst_frac);
}

/* allantools (third party, full overlap at every tau) on ADIS16405 log 1:
 * identical estimator for tau <= 255 samples; beyond, the cascade uses a
 * stride of tau/m (m 5..8), a statistically equivalent estimate: it must
 * stay within half a standard error of the full-overlap value, the standard
 * error of the deviation being 1/sqrt(2 EDF) relative (measured: at most
 * 0.34 standard errors, at tau = 26 % of the record; below 0.11 up to 10 %). */
static void test_allantools_adis(void **state)
{
    static const char *const cols[6] = { "gx", "gy", "gz", "ax", "ay", "az" };
    char path[512], ref[512], line[512];
    hx_log_t log;
    FILE *f;
    static double y[1000000];
    static uint32_t tau[32];
    static double refv[32][6];
    static fnav_allan_result_t r[32];
    fnav_real_t slope[32];
    size_t nt = 0, i;
    int c;
    char err[320];
    (void)state;
    if (fnav_testdata_path("adis16405_static/adis16405_imu1_100Hz.csv.gz", path, sizeof path) != 0 ||
        fnav_testdata_path("allan_reference/derived_thirdparty/adis16405_imu1_oadev_allantools.csv", ref,
                           sizeof ref) != 0) {
        fnav_test_skip_notice("ADIS16405 log 1 / allantools cross-check");
        skip();
    }
    f = fopen(ref, "r");
    assert_non_null(f);
    while (fgets(line, sizeof line, f) != NULL && nt < 32) {
        double t, m, v[6];
        if (sscanf(line, "%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf", &t, &m, &v[0], &v[1], &v[2], &v[3], &v[4], &v[5]) == 8) {
            tau[nt] = (uint32_t)m;
            for (c = 0; c < 6; c++) {
                refv[nt][c] = v[c];
            }
            nt++;
        }
    }
    fclose(f);
    assert_true(nt >= 15);
    assert_int_equal(hx_log_load(&log, path, HX_FMT_AUTO, 0.0, err, sizeof err), 0);
    assert_int_equal(log.n, 1000000);
    for (c = 0; c < 6; c++) {
        /* allantools columns: gyro deg/s, accel g */
        for (i = 0; i < log.n; i++) {
            y[i] = c < 3 ? log.gyr[i][c] * 57.29577951308232 : log.acc[i][c - 3] / 9.80665;
        }
        run_series(y, log.n, tau, nt, r);
        fnav_allan_slopes(r, nt, slope);
        for (i = 0; i < nt; i++) {
            const double dev = sqrt((double)r[i].avar);
            if (tau[i] <= FNAV_ALLAN_TAU_FULL_MAX) {
                FNAV_ASSERT_CLOSE(dev, refv[i][c], 0.0, FNAV_USE_DOUBLE ? 1e-6 : 1e-5);
            } else {
                const double edf = hx_allan_point_edf(&r[i], fnav_allan_noise_from_slope(slope[i]), 1);
                assert_true(edf > 0.0);
                FNAV_ASSERT_CLOSE(dev, refv[i][c], 0.0, 0.5 / sqrt(2.0 * edf));
            }
        }
        (void)cols;
    }
    hx_log_free(&log);
}

/* ------------------------------------------------------------ API */

static void test_memory_bound(void **state)
{
    (void)state;
#if !FNAV_USE_DOUBLE
    assert_true(sizeof(fnav_allan_t) <= 4096u);
#endif
    assert_true(FNAV_ALLAN_TAU_MAX >= 864000ul); /* 10 % of 12 h at 200 Hz */
    assert_true(fnav_allan_tau_valid((uint32_t)FNAV_ALLAN_TAU_MAX));
}

static void test_config_errors(void **state)
{
    static fnav_allan_t a;
    static const uint32_t bad_order[3] = { 1, 4, 2 };
    static const uint32_t not_representable[2] = { 1, 257 }; /* odd beyond the full-rate ring */
    static const uint32_t too_big[1] = { 1u << 22 };
    static const uint32_t zero[1] = { 0 };
    uint32_t many[FNAV_ALLAN_MAX_POINTS + 1];
    fnav_allan_config_t cfg;
    size_t i;
    (void)state;
    for (i = 0; i < FNAV_ALLAN_MAX_POINTS + 1u; i++) {
        many[i] = (uint32_t)i + 1u;
    }
    assert_int_equal(fnav_allan_init(NULL, NULL), FNAV_E_ARG);
    cfg.tau = bad_order;
    cfg.n_tau = 3;
    assert_int_equal(fnav_allan_init(&a, &cfg), FNAV_E_CONFIG);
    cfg.tau = not_representable;
    cfg.n_tau = 2;
    assert_int_equal(fnav_allan_init(&a, &cfg), FNAV_E_CONFIG);
    cfg.tau = too_big;
    cfg.n_tau = 1;
    assert_int_equal(fnav_allan_init(&a, &cfg), FNAV_E_CONFIG);
    cfg.tau = zero;
    assert_int_equal(fnav_allan_init(&a, &cfg), FNAV_E_CONFIG);
    cfg.tau = many;
    cfg.n_tau = 0;
    assert_int_equal(fnav_allan_init(&a, &cfg), FNAV_E_CONFIG);
    cfg.n_tau = FNAV_ALLAN_MAX_POINTS + 1u;
    assert_int_equal(fnav_allan_init(&a, &cfg), FNAV_E_CONFIG);
    cfg.n_tau = FNAV_ALLAN_MAX_POINTS;
    assert_int_equal(fnav_allan_init(&a, &cfg), FNAV_OK);
    assert_int_equal(fnav_allan_count(&a), FNAV_ALLAN_MAX_POINTS);
    assert_false(fnav_allan_tau_valid(9u << 6));
    assert_true(fnav_allan_tau_valid(7u << 10));
}

static void test_bad_samples_leave_state(void **state)
{
    static fnav_allan_t a, copy;
    fnav_allan_result_t r;
    int i;
    (void)state;
    assert_int_equal(fnav_allan_init(&a, NULL), FNAV_OK);
    for (i = 0; i < 100; i++) {
        assert_int_equal(fnav_allan_push(&a, (fnav_real_t)(i % 7)), FNAV_OK);
    }
    copy = a;
    assert_int_equal(fnav_allan_push(&a, (fnav_real_t)NAN), FNAV_E_NANINF);
    assert_int_equal(fnav_allan_push(&a, (fnav_real_t)INFINITY), FNAV_E_NANINF);
    /* finite but beyond FNAV_INPUT_MAX_ABS: its squares would overflow the
     * float sums into Inf/NaN (found by fuzzing) */
    assert_int_equal(fnav_allan_push(&a, FNAV_R(1.0e30)), FNAV_E_RANGE);
    assert_int_equal(fnav_allan_push(&a, (fnav_real_t)(-2.0 * FNAV_INPUT_MAX_ABS)), FNAV_E_RANGE);
    assert_memory_equal(&a, &copy, sizeof a);
    assert_int_equal(fnav_allan_push(&a, (fnav_real_t)FNAV_INPUT_MAX_ABS), FNAV_OK);
    a = copy;
    a.n = UINT32_MAX;
    assert_int_equal(fnav_allan_push(&a, FNAV_R(1.0)), FNAV_E_RANGE);
    assert_int_equal(fnav_allan_get(&copy, 1000, &r), FNAV_E_ARG);
    assert_int_equal(fnav_allan_get(&copy, 0, NULL), FNAV_E_ARG);
    /* no term yet: NaN, zero counts */
    assert_int_equal(fnav_allan_init(&a, NULL), FNAV_OK);
    assert_int_equal(fnav_allan_push(&a, FNAV_R(1.0)), FNAV_OK);
    assert_int_equal(fnav_allan_get(&a, 0, &r), FNAV_OK);
    assert_int_equal(r.terms, 0);
    assert_true(isnan((double)r.avar));
}

/* An estimator never initialised (zeroed, as static storage is) or whose
 * fnav_allan_init failed (it is then left zeroed) refuses samples with
 * FNAV_E_STATE, as fnav_welch_push and fnav_nav_push do: it took them with
 * FNAV_OK, tracked no tau and every fnav_allan_get said FNAV_E_ARG, so a
 * failed init went unnoticed. NULL is FNAV_E_ARG (an FNAV_ASSERT before). */
static void test_not_initialised(void **state)
{
    static fnav_allan_t a, zero;
    static const uint32_t bad_order[] = { 4, 2 };
    fnav_allan_config_t cfg;
    fnav_allan_result_t r;
    (void)state;
    assert_int_equal(fnav_allan_push(NULL, FNAV_R(1.0)), FNAV_E_ARG);
    assert_int_equal(fnav_allan_push(&a, FNAV_R(1.0)), FNAV_E_STATE);
    assert_int_equal(fnav_allan_push(&a, FNAV_R(2.0)), FNAV_E_STATE);
    assert_memory_equal(&a, &zero, sizeof a); /* nothing taken */
    assert_int_equal(fnav_allan_samples(&a), 0u);
    assert_int_equal(fnav_allan_get(&a, 0, &r), FNAV_E_STATE);
    /* a sample it would reject anyway is refused as such first */
    assert_int_equal(fnav_allan_push(&a, (fnav_real_t)NAN), FNAV_E_NANINF);
    /* a failed init leaves it zeroed: refused the same way */
    assert_int_equal(fnav_allan_init(&a, NULL), FNAV_OK);
    assert_int_equal(fnav_allan_push(&a, FNAV_R(1.0)), FNAV_OK);
    cfg.tau = bad_order;
    cfg.n_tau = 2;
    assert_int_equal(fnav_allan_init(&a, &cfg), FNAV_E_CONFIG);
    assert_int_equal(fnav_allan_push(&a, FNAV_R(1.0)), FNAV_E_STATE);
    assert_int_equal(fnav_allan_get(&a, 0, &r), FNAV_E_STATE);
    /* initialised: taken, and a bad index stays FNAV_E_ARG */
    assert_int_equal(fnav_allan_init(&a, NULL), FNAV_OK);
    assert_int_equal(fnav_allan_push(&a, FNAV_R(1.0)), FNAV_OK);
    assert_int_equal(fnav_allan_samples(&a), 1u);
    assert_int_equal(fnav_allan_get(&a, fnav_allan_count(&a), &r), FNAV_E_ARG);
    assert_int_equal(fnav_allan_get(&a, 0, &r), FNAV_OK);
}

/* fnav_allan_init reads the configuration and its tau array only during the
 * call (fnav_allan.h): the caller's array may be reused at once. */
static void test_grid_copied(void **state)
{
    static fnav_allan_t a;
    uint32_t tau[3] = { 1u, 2u, 4u };
    fnav_allan_config_t cfg;
    fnav_allan_result_t r;
    size_t i;
    int k;
    (void)state;
    cfg.tau = tau;
    cfg.n_tau = 3;
    assert_int_equal(fnav_allan_init(&a, &cfg), FNAV_OK);
    tau[0] = 0u; /* the caller's array reused: invalid values now */
    tau[1] = 0u;
    tau[2] = 0u;
    cfg.n_tau = 0;
    for (k = 0; k < 100; k++) {
        assert_int_equal(fnav_allan_push(&a, (fnav_real_t)(k % 5)), FNAV_OK);
    }
    assert_int_equal(fnav_allan_count(&a), 3u);
    for (i = 0; i < 3; i++) {
        assert_int_equal(fnav_allan_get(&a, i, &r), FNAV_OK);
        assert_int_equal(r.tau, 1u << i);
        assert_true(r.terms > 0u);
    }
}

static void test_grid(void **state)
{
    uint32_t g[128];
    size_t n, i;
    (void)state;
    n = fnav_allan_grid(g, 128, 1u << 20, 1);
    assert_int_equal(n, 21);
    for (i = 0; i < n; i++) {
        assert_int_equal(g[i], 1u << i);
    }
    n = fnav_allan_grid(g, 128, 1000, 2);
    assert_int_equal(g[0], 1);
    assert_int_equal(g[1], 2);
    assert_int_equal(g[2], 3);
    assert_int_equal(g[n - 1], 768);
    n = fnav_allan_grid(g, 128, 1u << 20, 4);
    for (i = 0; i < n; i++) {
        assert_true(fnav_allan_tau_valid(g[i]));
        if (i > 0) {
            assert_true(g[i] > g[i - 1]);
        }
    }
    assert_int_equal(g[n - 1], 1u << 20);
    assert_int_equal(fnav_allan_grid(g, 3, 1u << 20, 4), 3);
    /* a tau_max past FNAV_ALLAN_TAU_MAX is capped there (fnav_allan.h):
     * the octaves 1 .. FNAV_ALLAN_TAU_MAX, every one valid, and NULL gives
     * no point (make coverage: neither was run) */
    n = fnav_allan_grid(g, 128, UINT32_MAX, 1);
    assert_int_equal(n, FNAV_ALLAN_MAX_LEVELS);
    assert_int_equal((unsigned long)g[n - 1], FNAV_ALLAN_TAU_MAX);
    for (i = 0; i < n; i++) {
        assert_int_equal(g[i], 1u << i);
        assert_true(fnav_allan_tau_valid(g[i]));
    }
    assert_false(fnav_allan_tau_valid((uint32_t)(FNAV_ALLAN_TAU_MAX + 1ul)));
    assert_int_equal(fnav_allan_grid(NULL, 128, 1000, 1), 0);
}

/* ------------------------------------------------------------ noise types */

static void test_noise_from_slope(void **state)
{
    (void)state;
    assert_int_equal(fnav_allan_noise_from_slope(FNAV_R(-1.0)), FNAV_ALLAN_NOISE_QUANT);
    assert_int_equal(fnav_allan_noise_from_slope(FNAV_R(-0.5)), FNAV_ALLAN_NOISE_WHITE);
    assert_int_equal(fnav_allan_noise_from_slope(FNAV_R(0.1)), FNAV_ALLAN_NOISE_FLICKER);
    assert_int_equal(fnav_allan_noise_from_slope(FNAV_R(0.5)), FNAV_ALLAN_NOISE_RRW);
    assert_int_equal(fnav_allan_noise_from_slope(FNAV_R(1.1)), FNAV_ALLAN_NOISE_RAMP);
    assert_int_equal(fnav_allan_noise_from_slope((fnav_real_t)NAN), FNAV_ALLAN_NOISE_UNKNOWN);
    assert_int_equal(fnav_allan_noise_alpha(FNAV_ALLAN_NOISE_FLICKER), -1);
    /* the nearest of the power-law slopes -1, -1/2, 0, +1/2 (docs/allan.md):
     * the boundaries sit half way, at -3/4, -1/4, +1/4 and +3/4. A hand-made
     * mutant moving -1/4 to -0.35 passed every suite (fails here, checked) */
    assert_int_equal(fnav_allan_noise_from_slope(FNAV_R(-0.8)), FNAV_ALLAN_NOISE_QUANT);
    assert_int_equal(fnav_allan_noise_from_slope(FNAV_R(-0.7)), FNAV_ALLAN_NOISE_WHITE);
    assert_int_equal(fnav_allan_noise_from_slope(FNAV_R(-0.3)), FNAV_ALLAN_NOISE_WHITE);
    assert_int_equal(fnav_allan_noise_from_slope(FNAV_R(-0.2)), FNAV_ALLAN_NOISE_FLICKER);
    assert_int_equal(fnav_allan_noise_from_slope(FNAV_R(0.2)), FNAV_ALLAN_NOISE_FLICKER);
    assert_int_equal(fnav_allan_noise_from_slope(FNAV_R(0.3)), FNAV_ALLAN_NOISE_RRW);
    assert_int_equal(fnav_allan_noise_from_slope(FNAV_R(0.7)), FNAV_ALLAN_NOISE_RRW);
    assert_int_equal(fnav_allan_noise_from_slope(FNAV_R(0.8)), FNAV_ALLAN_NOISE_RAMP);
    /* S_y ~ f^alpha (SP 1065 table 1): white phase +2, white FM 0, flicker
     * FM -1, random-walk FM -2; a mutant giving quantisation alpha = 1
     * passed every suite (fails here, checked) */
    assert_int_equal(fnav_allan_noise_alpha(FNAV_ALLAN_NOISE_QUANT), 2);
    assert_int_equal(fnav_allan_noise_alpha(FNAV_ALLAN_NOISE_WHITE), 0);
    assert_int_equal(fnav_allan_noise_alpha(FNAV_ALLAN_NOISE_RRW), -2);
    assert_string_equal(fnav_allan_noise_name(FNAV_ALLAN_NOISE_RRW), "rate-random-walk");
    /* the other names (harness allan prints them; make coverage: never
     * asked), and "unknown" for UNKNOWN and a value outside the enum */
    assert_string_equal(fnav_allan_noise_name(FNAV_ALLAN_NOISE_QUANT), "quantisation");
    assert_string_equal(fnav_allan_noise_name(FNAV_ALLAN_NOISE_WHITE), "white");
    assert_string_equal(fnav_allan_noise_name(FNAV_ALLAN_NOISE_FLICKER), "flicker");
    assert_string_equal(fnav_allan_noise_name(FNAV_ALLAN_NOISE_RAMP), "ramp");
    assert_string_equal(fnav_allan_noise_name(FNAV_ALLAN_NOISE_UNKNOWN), "unknown");
    assert_string_equal(fnav_allan_noise_name((fnav_allan_noise_t)99), "unknown");
}

/* Simulated pure white noise and pure random walk: the local slopes and
 * noise types of the streaming estimate. */
static void test_noise_types_simulated(void **state)
{
    static fnav_allan_t a, b;
    static fnav_allan_result_t ra[FNAV_ALLAN_MAX_POINTS], rb[FNAV_ALLAN_MAX_POINTS];
    fnav_real_t sa[FNAV_ALLAN_MAX_POINTS], sb[FNAV_ALLAN_MAX_POINTS];
    hx_noise_model_t white = { 1.0, 0.0, 0.0, 0.0, 0.0 }, rw = { 0.0, 0.0, 0.0, 0.0, 1.0 };
    hx_noise_sim_t s1, s2;
    size_t i, n;
    uint32_t k;
    (void)state;
    assert_int_equal(fnav_allan_init(&a, NULL), FNAV_OK);
    assert_int_equal(fnav_allan_init(&b, NULL), FNAV_OK);
    assert_int_equal(hx_noise_sim_init(&s1, &white, 100.0, 7), 0);
    assert_int_equal(hx_noise_sim_init(&s2, &rw, 100.0, 8), 0);
    for (k = 0; k < 200000u; k++) {
        assert_int_equal(fnav_allan_push(&a, (fnav_real_t)hx_noise_sim_next(&s1)), FNAV_OK);
        assert_int_equal(fnav_allan_push(&b, (fnav_real_t)hx_noise_sim_next(&s2)), FNAV_OK);
    }
    hx_noise_sim_free(&s1);
    hx_noise_sim_free(&s2);
    n = fnav_allan_count(&a);
    for (i = 0; i < n; i++) {
        assert_int_equal(fnav_allan_get(&a, i, &ra[i]), FNAV_OK);
        assert_int_equal(fnav_allan_get(&b, i, &rb[i]), FNAV_OK);
    }
    fnav_allan_slopes(ra, n, sa);
    fnav_allan_slopes(rb, n, sb);
    for (i = 0; i < n; i++) {
        if (ra[i].tau > 2000u) {
            break; /* enough terms for a clear slope below 1 % of the record */
        }
        assert_int_equal(fnav_allan_noise_from_slope(sa[i]), FNAV_ALLAN_NOISE_WHITE);
        assert_int_equal(fnav_allan_noise_from_slope(sb[i]), FNAV_ALLAN_NOISE_RRW);
        /* white: ADEV(tau) = N / sqrt(tau_s) within 3 standard errors (1/sqrt(2 EDF)) */
        FNAV_ASSERT_CLOSE(sqrt((double)ra[i].avar), 1.0 / sqrt((double)ra[i].tau / 100.0), 0.0,
                          3.0 / sqrt(2.0 * hx_allan_point_edf(&ra[i], FNAV_ALLAN_NOISE_WHITE, 1)));
    }
}

/* ------------------------------------------------------------ identification */

/* A table from an analytic model on the default grid, with term counts of
 * a record of n samples (the model values are exact). */
static size_t analytic_table(const hx_noise_model_t *m, double fs, uint32_t n, fnav_allan_result_t *r)
{
    static fnav_allan_t a;
    size_t i, cnt;
    assert_int_equal(fnav_allan_init(&a, NULL), FNAV_OK);
    a.n = n; /* only the term counts are taken from the estimator */
    cnt = fnav_allan_count(&a);
    for (i = 0; i < cnt; i++) {
        assert_int_equal(fnav_allan_get(&a, i, &r[i]), FNAV_OK);
        r[i].avar = (fnav_real_t)hx_noise_model_avar(m, fs, (double)r[i].tau);
    }
    return cnt;
}

static void test_paper_identification_arithmetic(void **state)
{
    /* white N = 0.01 u/sqrt(Hz) plus a flicker floor 1e-3 u: ADEV^2 = N^2/tau + B^2
     * has no minimum; add a rate random walk so that it turns up */
    hx_noise_model_t m = { 0.01, 0.0, 0.0, 0.0, 2e-5 };
    fnav_allan_result_t r[FNAV_ALLAN_MAX_POINTS];
    fnav_allan_paper_id_t id;
    const double fs = 200.0;
    size_t n = analytic_table(&m, fs, 8640000u, r), i, imin = 0;
    (void)state;
    for (i = 0; i < n; i++) {
        if (r[i].avar < r[imin].avar) {
            imin = i;
        }
    }
    assert_int_equal(fnav_allan_identify_paper(r, n, (fnav_real_t)fs, 0, &id), FNAV_OK);
    /* sigma_v: ADEV at 1 s = sqrt(N^2 + K^2/3) (log-log interpolation between 192 and 256 samples;
     * exact for the white term, which dominates there: measured 2.2e-7 relative in float, 1.5e-8 in
     * double; the tolerance was 2e-3) */
    FNAV_ASSERT_CLOSE(id.sigma_v, sqrt(hx_noise_model_avar(&m, fs, 200.0)), 0.0, 1e-5);
    /* minimum of N^2/t + K^2 t/3 at t = sqrt(3) N / K; located between the points of the
     * 2-per-octave table: 0.09 % off in both builds, B 0.015 % (the tolerances were 5 % and 1 %) */
    FNAV_ASSERT_CLOSE(id.t_bs_s, sqrt(3.0) * 0.01 / 2e-5, 0.0, 5e-3);
    FNAV_ASSERT_CLOSE(id.bs, sqrt(2.0 * 0.01 * 2e-5 / sqrt(3.0)), 0.0, 1e-3);
    FNAV_ASSERT_CLOSE(id.tau_samples, (double)id.t_bs_s * fs, 0.0, 1e-6);                    /* eq. 5 */
    FNAV_ASSERT_CLOSE(id.sigma_bias, (double)id.bs / sqrt((double)id.tau_samples), 0.0, 1e-6); /* eq. 6 */
    assert_int_equal(id.i_min, imin);
    /* 1 s outside the table */
    assert_int_equal(fnav_allan_identify_paper(r, 3, (fnav_real_t)fs, 0, &id), FNAV_E_RANGE);
    assert_int_equal(fnav_allan_identify_paper(NULL, n, (fnav_real_t)fs, 0, &id), FNAV_E_ARG);
    /* a bad rate is an argument error (fnav_allan.h), not "1 s outside the table" */
    assert_int_equal(fnav_allan_identify_paper(r, n, (fnav_real_t)fs, 0, NULL), FNAV_E_ARG);
    assert_int_equal(fnav_allan_identify_paper(r, n, FNAV_R(0.0), 0, &id), FNAV_E_ARG);
    assert_int_equal(fnav_allan_identify_paper(r, n, FNAV_R(-200.0), 0, &id), FNAV_E_ARG);
    assert_int_equal(fnav_allan_identify_paper(r, n, (fnav_real_t)NAN, 0, &id), FNAV_E_ARG);
    assert_int_equal(fnav_allan_identify_paper(r, n, (fnav_real_t)INFINITY, 0, &id), FNAV_E_ARG);
}

/* The model's Allan variance against the definition: Var(mean) - Cov of
 * adjacent means from the autocovariance, summed directly. */
static void test_model_avar_exact(void **state)
{
    static const double ms[5] = { 1.0, 2.0, 7.0, 64.0, 300.0 };
    static const double Ts[3] = { 0.05, 2.0, 500.0 };
    const double fs = 100.0;
    int i, j;
    (void)state;
    for (j = 0; j < 3; j++) {
        const double c = exp(-1.0 / (Ts[j] * fs));
        hx_noise_model_t m = { 0.0, 1.0, 0.0, 0.0, 0.0 };
        m.gm_tau_s = Ts[j];
        for (i = 0; i < 5; i++) {
            const int mm = (int)ms[i];
            long double var = 0.0L, cov = 0.0L;
            int p, q;
            for (p = 0; p < mm; p++) {
                for (q = 0; q < mm; q++) {
                    var += powl((long double)c, (long double)abs(p - q));
                    cov += powl((long double)c, (long double)(q + mm - p));
                }
            }
            FNAV_ASSERT_CLOSE(hx_noise_model_avar(&m, fs, ms[i]), (double)((var - cov) / (long double)(mm * mm)),
                              1e-15, 2e-4);
        }
    }
    {
        /* white, quantisation and random walk against their textbook forms */
        hx_noise_model_t w = { 0.3, 0.0, 0.0, 0.0, 0.0 }, q = { 0.0, 0.0, 0.0, 0.2, 0.0 },
                         k = { 0.0, 0.0, 0.0, 0.0, 0.5 };
        FNAV_ASSERT_CLOSE(hx_noise_model_avar(&w, fs, 250.0), 0.09 / 2.5, 0.0, 1e-12);
        FNAV_ASSERT_CLOSE(hx_noise_model_avar(&q, fs, 250.0), 3.0 * 0.04 / 6.25, 0.0, 1e-12);
        FNAV_ASSERT_CLOSE(hx_noise_model_avar(&k, fs, 250000.0), 0.25 * 2500.0 / 3.0, 0.0, 1e-6);
    }
}

/* The AR(1) ADEV peak: 0.6174 sigma at 1.893 T (hx_allan_ident.h). */
static void test_gm_peak(void **state)
{
    hx_noise_model_t m = { 0.0, 2.0, 50.0, 0.0, 0.0 };
    const double fs = 100.0;
    double best = 0.0, best_tau = 0.0, t;
    (void)state;
    for (t = 10.0; t < 1000.0; t *= 1.001) {
        const double v = sqrt(hx_noise_model_avar(&m, fs, t * fs));
        if (v > best) {
            best = v;
            best_tau = t;
        }
    }
    FNAV_ASSERT_CLOSE(best, HX_GM_PEAK_RATIO * 2.0, 0.0, 1e-3);
    FNAV_ASSERT_CLOSE(best_tau, HX_GM_PEAK_TAU * 50.0, 0.0, 0.01);
}

/* The least-squares fit recovers the parameters of an exact table, and the
 * paper's identification of that table does not reproduce it. */
static void test_fit_recovers_model(void **state)
{
    hx_noise_model_t truth = { 0.004, 0.002, 30.0, 0.0, 0.0 }, fit;
    hx_allan_quality_t q;
    hx_allan_ident_t id;
    hx_allan_fit_opts_t o = hx_allan_fit_opts_default;
    fnav_allan_result_t r[FNAV_ALLAN_MAX_POINTS];
    const double fs = 100.0;
    size_t n = analytic_table(&truth, fs, 2000000u, r);
    (void)state;
    o.tau_max_s = 2000.0;
    assert_int_equal(hx_allan_fit(r, n, fs, &o, &fit, &q), 0);
    /* an exact table: the fit lands within 6e-9 relative in the float build (the table's
     * float32 values), 1e-14 in double; 1e-5 (was 1e-3) keeps a wide margin over float */
    FNAV_ASSERT_CLOSE(fit.white, truth.white, 0.0, 1e-5);
    FNAV_ASSERT_CLOSE(fit.gm_sigma, truth.gm_sigma, 0.0, 1e-5);
    FNAV_ASSERT_CLOSE(fit.gm_tau_s, truth.gm_tau_s, 0.0, 1e-5);
    assert_true(q.rms_log10 < 1e-4);
    assert_int_equal(hx_allan_identify(r, n, fs, &o, &id), 0);
    assert_true(id.paper_ok && id.fit_ok);
    /* eq. 4 reading: the AR(1) bump is far too small */
    assert_true(id.paper_quality.rms_log10 > 0.1);
    assert_true(id.fit_quality.rms_log10 < 1e-4);
    /* extra terms when asked */
    {
        hx_noise_model_t t2 = { 0.004, 0.002, 30.0, 0.0, 1e-4 };
        n = analytic_table(&t2, fs, 2000000u, r);
        o.with_rrw = 1;
        assert_int_equal(hx_allan_fit(r, n, fs, &o, &fit, &q), 0);
        /* exact table again: 2e-8 relative in float, 1e-14 in double (the tolerance was 2 %) */
        FNAV_ASSERT_CLOSE(fit.rrw, 1e-4, 0.0, 1e-5);
        FNAV_ASSERT_CLOSE(fit.gm_sigma, 0.002, 0.0, 1e-5);
    }
    /* too few points */
    assert_int_equal(hx_allan_fit(r, 3, fs, &o, &fit, &q), -1);
}

/* More parameters than points: with the quantisation and random-walk terms
 * (four amplitudes and T) a table of 4 usable points took the four-term
 * stage-1 solve, exact and with RMS 0, and then asked GSL's Levenberg-
 * Marquardt for 5 parameters from 4 residuals, which calls the GSL error
 * handler (abort() unless a caller turned it off; the harness had, so it
 * silently kept the stage-1 solve: 5 parameters of 4 points). A subset is
 * now fitted only with more points than parameters; here white + AR(1). */
static void test_fit_more_params_than_points(void **state)
{
    hx_noise_model_t truth = { 0.01, 0.05, 0.02, 2e-4, 1.0 }, fit;
    hx_allan_quality_t q;
    hx_allan_fit_opts_t o = hx_allan_fit_opts_default;
    fnav_allan_result_t r[FNAV_ALLAN_MAX_POINTS];
    const double fs = 100.0;
    size_t n = analytic_table(&truth, fs, 100000u, r), k;
    int nterms;
    (void)state;
    assert_true(n > 6);
    o.with_quant = 1;
    o.with_rrw = 1;
    for (k = 4; k <= 6; k++) {
        const int rc = hx_allan_fit(r, k, fs, &o, &fit, &q);
        if (rc != 0) {
            continue;
        }
        nterms = (fit.white > 0.0) + (fit.gm_sigma > 0.0) + (fit.quant > 0.0) + (fit.rrw > 0.0);
        /* amplitudes and T: fewer than the points */
        assert_true((size_t)nterms + 1u < k);
        assert_int_equal(q.npoints, (int)k);
    }
}

/* A fit reported as done must be finite: white noise at 100 Hz with one
 * wild point (m = 8, 900x its neighbours) and the extra terms drove
 * can drive Levenberg-Marquardt to log parameters whose exp() overflows: Q
 * and sigma infinite, T infinite, RMS NaN, and a return of 0 (a randomised
 * table driver finds it). A non-finite step result keeps the stage-1
 * solution. */
static void test_fit_finite(void **state)
{
    static const uint32_t taus[7] = { 1, 2, 3, 4, 6, 8, 12 };
    static const double avars[7] = { 0.0100000082, 0.005000012, 0.00333335018, 0.00250002206, 0.00166669907,
                                     1.10629368, 0.000833397266 };
    static fnav_allan_t a;
    fnav_allan_result_t r[7];
    hx_noise_model_t fit;
    hx_allan_quality_t q;
    hx_allan_fit_opts_t o = hx_allan_fit_opts_default;
    size_t i, j, n = 0;
    (void)state;
    assert_int_equal(fnav_allan_init(&a, NULL), FNAV_OK);
    a.n = 1000000u; /* term counts of 10^6 samples */
    for (i = 0; i < fnav_allan_count(&a) && n < 7; i++) {
        fnav_allan_result_t e;
        assert_int_equal(fnav_allan_get(&a, i, &e), FNAV_OK);
        for (j = 0; j < 7; j++) {
            if (e.tau == taus[j]) {
                e.avar = (fnav_real_t)avars[j];
                r[n++] = e;
            }
        }
    }
    assert_int_equal(n, 7);
    o.with_quant = o.with_rrw = 1;
    o.tau_max_s = 300.0;
    if (hx_allan_fit(r, n, 100.0, &o, &fit, &q) == 0) {
        assert_true(isfinite(fit.white) && isfinite(fit.gm_sigma) && isfinite(fit.gm_tau_s));
        assert_true(isfinite(fit.quant) && isfinite(fit.rrw) && isfinite(q.rms_log10));
    }
}

/* A limit of the analysed tau under one sample is no paper identification,
 * not "no limit"; `harness allan` refuses such a
 * record before identifying (too few samples for any Allan point), so the
 * guard is checked here. */
static void test_identify_limit_below_one_sample(void **state)
{
    hx_noise_model_t truth = { 0.004, 0.002, 30.0, 0.0, 0.0 };
    hx_allan_ident_t id;
    hx_allan_fit_opts_t o = hx_allan_fit_opts_default;
    fnav_allan_result_t r[FNAV_ALLAN_MAX_POINTS];
    const double fs = 100.0;
    size_t n = analytic_table(&truth, fs, 2000000u, r);
    (void)state;
    o.tau_max_s = 0.5 / fs;
    (void)hx_allan_identify(r, n, fs, &o, &id);
    assert_false(id.paper_ok);
    assert_false(id.fit_ok);
    o.tau_max_s = 2000.0;
    assert_int_equal(hx_allan_identify(r, n, fs, &o, &id), 0);
    assert_true(id.paper_ok);
}

/* Simulated white + AR(1): the fit of the streaming table lands close to the
 * simulated parameters (statistical tolerance). The spread of the fit's
 * relative errors over 30 seeds (1..29 and 42), which
 * test_fit_simulated_seeds measures and prints (build/host/tests/test_allan):
 * white sd 0.0027 (max 0.0065), gm_sigma sd 0.042 (max 0.091), gm_tau sd
 * 0.17 (max 0.47), rms_log10 mean 0.020, sd 0.009, at most 0.043; seed 42:
 * +0.12 %, -6.3 %, -6.6 %, rms_log10 0.020. The tolerances are 4 of those
 * sd (white 0.011, gm_sigma 0.17; 0.02 and 0.25, 7.4 and 6 sd, would let
 * a fit biased by 1.5 % in the white noise pass), gm_tau's 0.5
 * (2.9 sd) kept, and rms_log10's 0.05 (the mean + 3.3 sd) kept. The
 * simulator's own statistics are checked tightly by test_sim_statistics. */
static void test_fit_simulated(void **state)
{
    hx_noise_model_t truth = { 0.01, 0.004, 20.0, 0.0, 0.0 };
    hx_allan_ident_t id;
    hx_allan_fit_opts_t o = hx_allan_fit_opts_default;
    fnav_allan_result_t r[FNAV_ALLAN_MAX_POINTS];
    const double fs = 100.0;
    size_t n = hx_allan_simulate(&truth, fs, 1000000u, 42, NULL, r);
    (void)state;
    assert_true(n > 30);
    o.tau_max_s = 1000.0;
    assert_int_equal(hx_allan_identify(r, n, fs, &o, &id), 0);
    assert_true(id.fit_ok);
    FNAV_ASSERT_CLOSE(id.fit.white, truth.white, 0.0, 4.0 * 0.0027);
    FNAV_ASSERT_CLOSE(id.fit.gm_sigma, truth.gm_sigma, 0.0, 4.0 * 0.042);
    FNAV_ASSERT_CLOSE(id.fit.gm_tau_s, truth.gm_tau_s, 0.0, 0.5);
    assert_true(id.fit_quality.rms_log10 < 0.05);
}

/* The same fit over the 30 seeds: no bias. The mean relative error of each
 * parameter is within 4 standard errors of the mean (sd / sqrt(30), the sd
 * measured over the same seeds: a t statistic of 29 degrees of freedom,
 * beyond 4 in 1 of 2,500 draws) of zero: a systematic error of the white
 * noise's fit of 0.3 %, which the single seed above cannot tell from its
 * scatter, fails here. Measured (float): white mean -0.0005, sd 0.0027;
 * gm_sigma +0.0001, 0.042; gm_tau -0.046, 0.17 (1.5 standard errors). */
static void test_fit_simulated_seeds(void **state)
{
    enum { NS = 30 };
    static fnav_allan_result_t r[FNAV_ALLAN_MAX_POINTS];
    static const char *const name[4] = { "white", "gm_sigma", "gm_tau", "rms_log10" };
    hx_noise_model_t truth = { 0.01, 0.004, 20.0, 0.0, 0.0 };
    double s1[4] = { 0.0, 0.0, 0.0, 0.0 }, s2[4] = { 0.0, 0.0, 0.0, 0.0 }, mx[4] = { 0.0, 0.0, 0.0, 0.0 };
    int k, j;
    (void)state;
    for (k = 0; k < NS; k++) {
        hx_allan_ident_t id;
        hx_allan_fit_opts_t o = hx_allan_fit_opts_default;
        size_t n = hx_allan_simulate(&truth, 100.0, 1000000u, k < NS - 1 ? (unsigned long)k + 1ul : 42ul, NULL, r);
        double e[4];
        o.tau_max_s = 1000.0;
        assert_int_equal(hx_allan_identify(r, n, 100.0, &o, &id), 0);
        assert_true(id.fit_ok);
        e[0] = id.fit.white / truth.white - 1.0;
        e[1] = id.fit.gm_sigma / truth.gm_sigma - 1.0;
        e[2] = id.fit.gm_tau_s / truth.gm_tau_s - 1.0;
        e[3] = id.fit_quality.rms_log10;
        for (j = 0; j < 4; j++) {
            s1[j] += e[j];
            s2[j] += e[j] * e[j];
            mx[j] = fmax(mx[j], fabs(e[j]));
        }
    }
    for (j = 0; j < 4; j++) {
        const double m = s1[j] / NS, sd = sqrt((s2[j] - NS * m * m) / (NS - 1));
        fprintf(stderr, "fit over %d seeds, %s%s: mean %+.4f, sd %.4f, largest %.4f\n", NS, name[j],
                j < 3 ? " (relative error)" : "", m, sd, mx[j]);
        if (j < 3) {
            assert_true(fabs(m) <= 4.0 * sd / sqrt((double)NS));
        }
    }
}

static void test_sim_statistics(void **state)
{
    hx_noise_model_t m = { 0.02, 0.5, 0.1, 0.0, 0.0 };
    hx_noise_sim_t s;
    double sum = 0.0, sum2 = 0.0;
    const int n = 400000;
    int k;
    (void)state;
    assert_int_equal(hx_noise_sim_init(&s, &m, 100.0, 3), 0);
    for (k = 0; k < n; k++) {
        const double v = hx_noise_sim_next(&s);
        sum += v;
        sum2 += v * v;
    }
    hx_noise_sim_free(&s);
    /* variance = sigma_b^2 + N^2 f_s = 0.25 + 0.04 */
    FNAV_ASSERT_CLOSE(sum2 / n - (sum / n) * (sum / n), 0.29, 0.0, 0.03);
    m.gm_tau_s = 0.0;
    assert_int_equal(hx_noise_sim_init(&s, &m, 100.0, 3), -1);
}

/* The simulator's quantisation and rate-random-walk terms against the model
 * they simulate (docs/allan.md, "Corrected identification"): AVAR = 3 Q^2 f_s^2 / m^2 and
 * K^2 (2 m^2 + 1) / (6 m f_s), exact for the discrete processes (e_k =
 * (x_k - x_{k-1}) f_s with x_k ~ N(0, Q^2); a walk of step K / sqrt(f_s)).
 * Overlapping AVAR of 400,000 samples: measured +0.20 %, +0.40 %
 * (quantisation, m = 1, 4) and +0.03 % (RRW, m = 10); asserted at 5 %. Hand-made
 * mutants scaling either step by f_s (off by 1e4) passed every suite (only
 * white + AR(1) was simulated here) and fail now (checked). */
static void test_sim_quant_rrw(void **state)
{
    const double fs = 100.0, Q = 1e-3, K = 1e-2;
    const size_t n = 400000;
    double *x = (double *)malloc((n + 1u) * sizeof *x);
    int kind;
    (void)state;
    assert_non_null(x);
    for (kind = 0; kind < 2; kind++) {
        hx_noise_model_t m = { 0.0, 0.0, 0.0, 0.0, 0.0 };
        hx_noise_sim_t s;
        uint32_t terms;
        size_t k;
        if (kind == 0) {
            m.quant = Q;
        } else {
            m.rrw = K;
        }
        assert_int_equal(hx_noise_sim_init(&s, &m, fs, 11u + (unsigned long)kind), 0);
        x[0] = 0.0;
        for (k = 0; k < n; k++) {
            x[k + 1u] = x[k] + hx_noise_sim_next(&s);
        }
        hx_noise_sim_free(&s);
        if (kind == 0) {
            FNAV_ASSERT_CLOSE(hx_allan_avar_record(x, n + 1u, 1u, 1, &terms), 3.0 * Q * Q * fs * fs, 0.0, 0.05);
            FNAV_ASSERT_CLOSE(hx_allan_avar_record(x, n + 1u, 4u, 1, &terms), 3.0 * Q * Q * fs * fs / 16.0, 0.0, 0.05);
        } else {
            FNAV_ASSERT_CLOSE(hx_allan_avar_record(x, n + 1u, 10u, 1, &terms), K * K * 201.0 / (60.0 * fs), 0.0, 0.05);
        }
    }
    free(x);
}

/* ------------------------------------------------------------ paper tables, profiles */

/* The built-in profiles are the paper's Tables IV-VI (a few cells checked
 * against the printed tables, all in the paper's units). */
static void test_paper_tables_builtin(void **state)
{
    fnav_profile_t p;
    const fnav_profile_paper_row_t *t;
    const double d2r = 3.14159265358979323846 / 180.0;
    (void)state;
    t = fnav_profile_paper_table(FNAV_PROFILE_NAVCHIP);
    assert_non_null(t);
    FNAV_ASSERT_CLOSE(t[0].noise, 7.4e-4, 0.0, 1e-12);
    FNAV_ASSERT_CLOSE(t[5].tau_samples, 10000.0, 0.0, 0.0);
    FNAV_ASSERT_CLOSE(t[3].sigma_bias, 8.5e-5, 0.0, 1e-12);
    t = fnav_profile_paper_table(FNAV_PROFILE_MTX);
    FNAV_ASSERT_CLOSE(t[5].tau_samples, 144000.0, 0.0, 0.0);
    FNAV_ASSERT_CLOSE(t[2].sigma_bias, 2.5e-6, 0.0, 1e-12);
    t = fnav_profile_paper_table(FNAV_PROFILE_SHIMMER);
    FNAV_ASSERT_CLOSE(t[4].sigma_bias, 5.3e-4, 0.0, 1e-12);
    assert_int_equal(fnav_profile_builtin(&p, FNAV_PROFILE_SHIMMER), FNAV_OK);
    FNAV_ASSERT_CLOSE(p.gyro_tau_s[1], 800.0 / 200.0, 0.0, 1e-6);
    FNAV_ASSERT_CLOSE(p.gyro_noise_rps_rthz[0], 1.9e-2 * d2r, 0.0, 1e-6);
}

/* The paper's own rows, read through eqs. (4) and (6): the AR(1) bump the
 * model produces is 0.6174 / sqrt(tau) of the bias stability the row encodes. */
static void test_paper_tables_inconsistent(void **state)
{
    int t, k;
    (void)state;
    for (t = 0; t < FNAV_PROFILE_COUNT; t++) {
        const fnav_profile_paper_row_t *row = fnav_profile_paper_table((fnav_profile_id_t)t);
        for (k = 0; k < 6; k++) {
            fnav_allan_paper_id_t id;
            hx_noise_model_t m;
            const double bs = row[k].sigma_bias * sqrt(row[k].tau_samples);
            double peak = 0.0, tt;
            memset(&id, 0, sizeof id);
            id.sigma_v = (fnav_real_t)row[k].noise;
            id.sigma_bias = (fnav_real_t)row[k].sigma_bias;
            id.tau_samples = (fnav_real_t)row[k].tau_samples;
            hx_noise_model_paper_reading(&id, 200.0, HX_PAPER_EQ4, &m);
            m.white = 0.0;
            for (tt = 1.0; tt < 1e7; tt *= 1.05) {
                const double v = sqrt(hx_noise_model_avar(&m, 200.0, tt));
                peak = v > peak ? v : peak;
            }
            assert_true(peak < 0.03 * bs); /* the bump is 30x to 600x below the bias stability */
        }
    }
}

/* The three readings of the paper's identification (hx_allan_ident.h), each
 * from its definition: EQ4 takes sigma_v as the density (ADEV at 1 s) and
 * sigma_bias as the stationary sd; SAMPLE draws sigma_v as the per-sample
 * std, density sigma_v / sqrt(f_s) (2e-2 / sqrt(200) = 1.41421e-3); DRIVE
 * takes sigma_bias as the driving sd of eq. (4), stationary sd
 * sigma_bias / sqrt(1 - c^2), c = e^(-1/tau): 1e-4 / sqrt(1 - e^(-2/400))
 * = 1.41598e-3 (numpy). The SAMPLE density multiplied by sqrt(f_s) instead
 * would pass every test but this one. The expected values
 * are these formulas, evaluated here in double on the fnav_real_t inputs
 * (not the printed 1.41421356e-3 and 1.41598e-3 and the unrounded
 * 2e-2 and 1e-4, to 1e-6 and 1e-5 relative): the readings that pass a value
 * through exactly, the SAMPLE density to 4 DBL_EPSILON (a square root and a
 * division), the DRIVE sd to 4 DBL_EPSILON / (1 - c^2) (1 - c^2 = 5e-3
 * formed here as 1 - exp, which cancels: the code uses expm1). */
static void test_paper_readings(void **state)
{
    fnav_allan_paper_id_t id;
    hx_noise_model_t m;
    (void)state;
    memset(&id, 0, sizeof id);
    id.sigma_v = (fnav_real_t)2e-2;
    id.sigma_bias = (fnav_real_t)1e-4;
    id.tau_samples = (fnav_real_t)400.0;
    {
        const double sv = (double)id.sigma_v, sb = (double)id.sigma_bias, one_c2 = 1.0 - exp(-2.0 / 400.0);
        hx_noise_model_paper_reading(&id, 200.0, HX_PAPER_EQ4, &m);
        FNAV_ASSERT_CLOSE(m.white, sv, 0.0, 0.0);
        FNAV_ASSERT_CLOSE(m.gm_sigma, sb, 0.0, 0.0);
        FNAV_ASSERT_CLOSE(m.gm_tau_s, 2.0, 0.0, 0.0);
        hx_noise_model_paper_reading(&id, 200.0, HX_PAPER_SAMPLE, &m);
        FNAV_ASSERT_CLOSE(m.white, sv / sqrt(200.0), 0.0, 4.0 * DBL_EPSILON);
        FNAV_ASSERT_CLOSE(m.gm_sigma, sb, 0.0, 0.0);
        FNAV_ASSERT_CLOSE(m.gm_tau_s, 2.0, 0.0, 0.0);
        hx_noise_model_paper_reading(&id, 200.0, HX_PAPER_DRIVE, &m);
        FNAV_ASSERT_CLOSE(m.white, sv, 0.0, 0.0);
        FNAV_ASSERT_CLOSE(m.gm_sigma, sb / sqrt(one_c2), 0.0, 4.0 * DBL_EPSILON / one_c2);
        FNAV_ASSERT_CLOSE(m.gm_tau_s, 2.0, 0.0, 0.0);
        /* the figures the comment quotes */
        FNAV_ASSERT_CLOSE(sv / sqrt(200.0), 1.41421e-3, 0.0, 5e-6);
        FNAV_ASSERT_CLOSE(sb / sqrt(one_c2), 1.41598e-3, 0.0, 5e-6);
    }
}

static void test_profile_roundtrip(void **state)
{
    fnav_profile_t p, q;
    char err[320];
    const char *path = "build/test_allan_roundtrip.profile";
    (void)state;
    assert_int_equal(fnav_profile_builtin(&p, FNAV_PROFILE_MTX), FNAV_OK);
    assert_int_equal(hx_profile_write_extra(path, &p, "test", "gyro_rrw_rps_rts = 1e-5 2e-5 3e-5\nident_samples = 5\n",
                                            err, sizeof err),
                     0);
    assert_int_equal(hx_profile_read(path, &q, err, sizeof err), 0);
    FNAV_ASSERT_CLOSE(q.gyro_tau_s[2], p.gyro_tau_s[2], 0.0, 1e-6);
    FNAV_ASSERT_CLOSE(q.accel_bias_sigma_mps2[0], p.accel_bias_sigma_mps2[0], 0.0, 1e-6);
    remove(path);
}

/* One second difference (N = L = 2m + 1 phase values) is one chi-square
 * degree of freedom for every noise type (Greenhall and Riley's M = 1); one
 * value fewer has no difference and no EDF. */
static void test_edf_single_term(void **state)
{
    int alpha;
    (void)state;
    for (alpha = -2; alpha <= 2; alpha++) {
        assert_true(fabs(fnav_allan_edf(alpha, 1u, 3u, 1) - 1.0) < 1e-12);
        assert_true(fabs(fnav_allan_edf(alpha, 4u, 9u, 0) - 1.0) < 1e-12);
        assert_true(fnav_allan_edf(alpha, 1u, 2u, 1) < 0.0);
        assert_true(fnav_allan_edf(alpha, 4u, 8u, 0) < 0.0);
    }
    assert_true(fnav_allan_edf(3, 1u, 100u, 1) < 0.0);
}

/* hx_allan_avar_record() and hx_dev_var_record() on a frequency ramp y_k = a k: the phase
 * x_n = a n (n - 1) / 2 has every second difference at lag m equal to a m^2,
 * so AVAR(m) = a^2 m^2 / 2 exactly, for both estimators; term counts
 * n - 2m (stride 1) and floor((n - 1) / m) - 1 (stride m). */
static void test_avar_record_ramp(void **state)
{
    static double x[1001];
    const double a = 0.125;
    uint32_t m, terms;
    size_t n;
    (void)state;
    for (n = 0; n < 1001u; n++) {
        x[n] = a * (double)n * ((double)n - 1.0) / 2.0;
    }
    for (m = 1; m <= 500u; m += 37u) {
        const double want = a * a * (double)m * (double)m / 2.0;
        assert_true(fabs(hx_allan_avar_record(x, 1001u, m, 1, &terms) / want - 1.0) < 1e-12);
        assert_int_equal(terms, 1001u - 2u * m);
        assert_true(fabs(hx_allan_avar_record(x, 1001u, m, 0, &terms) / want - 1.0) < 1e-12);
        assert_int_equal(terms, 1000u / m - 1u);
    }
    /* the other deviations (hx_devs.h): MVAR sums m second differences, all
     * a m^2, so MVAR = AVAR = a^2 m^2 / 2; the third differences vanish, so
     * HVAR = OHVAR = 0 (the Hadamard variance ignores a drift) */
    for (m = 1; m <= 333u; m += 23u) {
        const double want = a * a * (double)m * (double)m / 2.0;
        assert_true(fabs(hx_dev_var_record(HX_DEV_MDEV, x, 1001u, m, &terms) / want - 1.0) < 1e-9);
        assert_int_equal(terms, 1001u - 3u * m + 1u);
        assert_true(hx_dev_var_record(HX_DEV_HDEV, x, 1001u, m, &terms) < 1e-18 * want);
        assert_true(hx_dev_var_record(HX_DEV_OHDEV, x, 1001u, m, &terms) < 1e-18 * want);
        assert_int_equal(terms, 1001u - 3u * m);
    }
    /* n = 2m phase values: no second difference */
    assert_true(isnan(hx_allan_avar_record(x, 10u, 5u, 1, &terms)));
    assert_int_equal(terms, 0u);
    assert_true(isnan(hx_allan_avar_record(x, 10u, 0u, 1, &terms)));
}

/* The data's noise identification at its edges: a strictly alternating
 * frequency (lag-1 autocorrelation -1: the strongest phase noise), a
 * constant, and too few averages. */
static void test_noise_id_edges(void **state)
{
    static double x[4001];
    size_t n;
    int alpha = 99;
    hx_noise_id_t how = HX_NOISE_ID_SLOPE;
    (void)state;
    x[0] = 0.0;
    for (n = 1; n < 4001u; n++) {
        x[n] = x[n - 1u] + ((n % 2u) ? 1.0 : -1.0); /* y = +1, -1, +1, ... */
    }
    assert_int_equal(hx_allan_noise_id_acf(x, 4001u, 1u, &alpha, NULL), 0);
    assert_int_equal(alpha, 2);
    for (n = 0; n < 4001u; n++) {
        x[n] = 0.0;
    }
    alpha = 99;
    assert_int_equal(hx_allan_noise_id_acf(x, 4001u, 1u, &alpha, NULL), 0);
    assert_true(alpha >= -2 && alpha <= 2);
    /* 4000 samples: 30 averages up to m = 133 (autocorrelation), 4 up to
     * m = 1000 (B1; a constant has no Allan variance: no answer), none beyond */
    assert_int_equal(hx_allan_noise_id_acf(x, 4001u, 200u, &alpha, NULL), -1);
    assert_int_equal(hx_allan_noise_id_acf(x, 4001u, 1001u, &alpha, NULL), -1);
    for (n = 1; n < 4001u; n++) {
        x[n] = x[n - 1u] + (double)((n * 2654435761u) % 1000u) / 1000.0 - 0.5; /* scrambled: white FM */
    }
    assert_int_equal(hx_allan_noise_id_acf(x, 4001u, 200u, &alpha, &how), 0); /* 20 averages: B1 */
    assert_true(alpha >= -2 && alpha <= 2);
    assert_int_equal(how, HX_NOISE_ID_B1);
    assert_int_equal(hx_allan_noise_id_acf(x, 4001u, 1001u, &alpha, NULL), -1);
    /* a white phase: B1 says phase noise, and MVAR / AVAR (about 1 / m =
     * 0.005 against 0.11 for flicker) says white: +2 */
    {
        uint64_t r = 88172645463325252ull; /* xorshift64 (Marsaglia 2003): uniform phase, white */
        for (n = 1; n < 4001u; n++) {
            r ^= r << 13;
            r ^= r >> 7;
            r ^= r << 17;
            x[n] = (double)(r >> 11) / 9007199254740992.0 - 0.5;
        }
    }
    alpha = 99;
    assert_int_equal(hx_allan_noise_id_acf(x, 4001u, 200u, &alpha, &how), 0);
    assert_int_equal(alpha, 2);
    assert_int_equal(how, HX_NOISE_ID_B1_RN);
    alpha = 99;
    assert_int_equal(hx_allan_noise_id_acf(x, 4001u, 1u, &alpha, &how), 0);
    assert_int_equal(how, HX_NOISE_ID_ACF);
    assert_int_equal(alpha, 2); /* the lag-1 ACF method names white phase too */
    assert_string_equal(hx_noise_id_name(HX_NOISE_ID_B1_RN), "b1+rn");
}

/* R(m) = MVAR / AVAR at m = 1: the two are the same estimate there, so R
 * is 1 whatever the noise, exactly white phase noise's expected 1 / m and
 * above flicker phase noise's 0.75 (the formula's, for larger m). The
 * split at the geometric mean put +2 below it and +1 above, which holds
 * only while 1 / m < the flicker value (m >= 2): at m = 1 every record that
 * B1 called phase noise was named flicker phase noise (+1), a white phase
 * of 21 samples too (400 white phases of 20 averages: all 344 of B1's
 * phase answers +1; `harness allan --series` of 25 samples printed alpha 1
 * b1+rn at tau 1). The nearer expected value on a log scale (the same split
 * for m >= 2) gives +2. */
static void test_noise_id_rn_at_one_sample(void **state)
{
    static double x[21];
    uint64_t r = 88172645463325252ull; /* xorshift64, as test_noise_id_edges: uniform white phase */
    size_t n;
    int alpha = 99;
    hx_noise_id_t how = HX_NOISE_ID_SLOPE;
    (void)state;
    for (n = 0; n < 21u; n++) {
        r ^= r << 13;
        r ^= r >> 7;
        r ^= r << 17;
        x[n] = (double)(r >> 11) / 9007199254740992.0 - 0.5;
    }
    assert_int_equal(hx_allan_noise_id_acf(x, 21u, 1u, &alpha, &how), 0); /* 20 averages: B1 */
    assert_int_equal(how, HX_NOISE_ID_B1_RN);
    assert_int_equal(alpha, 2);
}

/* The sample count's end: 2^32 - 1 samples give 2^32 phase values, which
 * n_phase (uint32_t) cannot hold: it would read 0, and fnav_allan_edf()
 * would then call every estimate undefined. 12.4 days at
 * 4 kHz. The count is moved to its end here (the ring contents do not
 * matter for the counts); the push that would make it 2^32 - 1 is refused. */
static void test_sample_count_end(void **state)
{
    static fnav_allan_t a;
    fnav_allan_result_t r;
    int i;
    (void)state;
    assert_int_equal(fnav_allan_init(&a, NULL), FNAV_OK);
    for (i = 0; i < 100; i++) {
        assert_int_equal(fnav_allan_push(&a, (fnav_real_t)(0.01 * (double)(i % 7))), FNAV_OK);
    }
    a.n = UINT32_MAX - 3u;
    assert_int_equal(fnav_allan_push(&a, FNAV_R(0.02)), FNAV_OK);
    assert_int_equal(fnav_allan_push(&a, FNAV_R(0.03)), FNAV_OK);
    assert_int_equal(fnav_allan_push(&a, FNAV_R(0.04)), FNAV_E_RANGE);
    assert_int_equal(fnav_allan_samples(&a), UINT32_MAX - 1u);
    assert_int_equal(fnav_allan_get(&a, 0, &r), FNAV_OK);
    assert_int_equal(r.tau, 1u);
    assert_int_equal(r.n_phase, UINT32_MAX); /* samples + 1 */
    assert_int_equal(r.terms, UINT32_MAX - 2u);
    assert_true(fnav_allan_edf(0, r.lag, r.n_phase, 1) > 0.0);
}

/* The non-overlapping sums near the count's end (2^32 - 2 samples): the
 * next multiple of m above a block start must not wrap past 2^32 to a
 * small number, or fnav_allan_get would add about 2^32 / m stale ring
 * terms, and within m samples of the end its loop would step past 2^32 and
 * never end. The count is moved to the end as in
 * test_sample_count_end (in the ring's phase, so the ring stays
 * consistent); the last pushes may add at most a term or two per point. */
static uint64_t g_xs = 88172645463325252ull;
static double xs_uniform(void)
{
    g_xs ^= g_xs << 13;
    g_xs ^= g_xs >> 7;
    g_xs ^= g_xs << 17;
    return (double)(g_xs >> 11) * (1.0 / 9007199254740992.0) - 0.5;
}

static void test_nonoverlap_count_end(void **state)
{
    static const uint32_t tau[2] = { 40u, 100u };
    static fnav_allan_t a;
    const fnav_allan_config_t cfg = { tau, 2 };
    const uint32_t target = UINT32_MAX - 33u;
    fnav_real_t sn0[2];
    size_t i;
    (void)state;
    assert_int_equal(fnav_allan_init(&a, &cfg), FNAV_OK);
    while (a.n < 100000u || (a.n & (FNAV_ALLAN_RING0 - 1u)) != (target & (FNAV_ALLAN_RING0 - 1u))) {
        assert_int_equal(fnav_allan_push(&a, (fnav_real_t)xs_uniform()), FNAV_OK);
    }
    a.n = target;
    for (i = 0; i < 2; i++) {
        fnav_allan_result_t r;
        assert_int_equal(fnav_allan_get(&a, i, &r), FNAV_OK);
        sn0[i] = r.avar_nonoverlap * FNAV_R(2.0) * (fnav_real_t)(r.tau * r.tau) * (fnav_real_t)r.terms_nonoverlap;
    }
    while (a.n < UINT32_MAX - 7u) {
        assert_int_equal(fnav_allan_push(&a, (fnav_real_t)xs_uniform()), FNAV_OK);
    }
    for (i = 0; i < 2; i++) {
        fnav_allan_result_t r;
        double sn;
        assert_int_equal(fnav_allan_get(&a, i, &r), FNAV_OK);
        sn = (double)r.avar_nonoverlap * 2.0 * (double)r.tau * (double)r.tau * (double)r.terms_nonoverlap;
        /* each term is (m (ybar2 - ybar1))^2 <= m^2 with |y| < 0.5; the 26
         * pushes complete at most one new non-overlapping term */
        assert_true(isfinite(sn));
        assert_true(sn - (double)sn0[i] <= 1.0 * (double)r.tau * (double)r.tau * (1.0 + 1e-3) + 1e-3 * (double)sn0[i]);
    }
}

/* Level-0 tau of 241 .. 255 samples (2 tau + FNAV_ALLAN_BLOCK > RING0: too
 * long for the block sums, so push_rare() adds their terms one push at a
 * time) against the textbook sums on a long double phase: the default grid
 * has no such tau, and a hand-made mutant taking the non-overlapping terms at
 * end indices n % m == 1 instead of 0 for them passed every suite (fails
 * here, checked). */
#if FNAV_USE_DOUBLE
#define LATE_TOL 1e-9
#else
#define LATE_TOL 1e-4
#endif

static void test_late_level0_points(void **state)
{
    static const uint32_t tau[4] = { 100u, 241u, 250u, 255u };
    static fnav_allan_t a;
    static long double x[3001];
    const fnav_allan_config_t cfg = { tau, 4 };
    const size_t n = 3000;
    size_t i, k;
    (void)state;
    assert_true(2u * tau[1] + FNAV_ALLAN_BLOCK > FNAV_ALLAN_RING0); /* the late case */
    assert_true(2u * tau[0] + FNAV_ALLAN_BLOCK <= FNAV_ALLAN_RING0);
    assert_int_equal(fnav_allan_init(&a, &cfg), FNAV_OK);
    g_xs = 88172645463325252ull;
    x[0] = 0.0L;
    for (i = 0; i < n; i++) {
        const fnav_real_t y = (fnav_real_t)xs_uniform();
        assert_int_equal(fnav_allan_push(&a, y), FNAV_OK);
        x[i + 1u] = x[i] + (long double)y;
    }
    for (k = 0; k < 4; k++) {
        const size_t m = tau[k];
        long double so = 0.0L, sn = 0.0L;
        size_t to = 0, tn = 0;
        fnav_allan_result_t r;
        for (i = 0; i + 2u * m <= n; i++) {
            const long double d = x[i + 2u * m] - 2.0L * x[i + m] + x[i];
            so += d * d;
            to++;
            if (i % m == 0u) {
                sn += d * d;
                tn++;
            }
        }
        assert_int_equal(fnav_allan_get(&a, k, &r), FNAV_OK);
        assert_int_equal(r.level, 0);
        assert_int_equal(r.terms, to);
        assert_int_equal(r.terms_nonoverlap, tn);
        FNAV_ASSERT_CLOSE(r.avar, (double)(so / (2.0L * (long double)(m * m) * (long double)to)), 0.0, LATE_TOL);
        FNAV_ASSERT_CLOSE(r.avar_nonoverlap, (double)(sn / (2.0L * (long double)(m * m) * (long double)tn)), 0.0,
                          LATE_TOL);
    }
}

/* Every result after every push, against the same terms summed on a long
 * double phase (docs/allan.md, "Streaming estimator"). Every other test reads
 * the estimator once, at the end of its record, so a fault at some phases
 * of the count only (the block in progress in fnav_allan_get, the first
 * block with terms, a cascade level's first terms, the pushes just after a
 * re-centring) could hide. The grid covers block points (m = 1, m not
 * dividing the block, m > block, m = 240), push-at-a-time points (241,
 * 255) and cascade levels 5 to 8; the input starts with an unrepresentative
 * 0 and steps by 20 half-way, so the re-centring runs twice (at n = 511 and
 * after the step). Measured: 3.2e-12 relative in double; 8.5e-4 in float,
 * the first term of tau 240 at n = 480, before the first re-centring, when
 * the phase has grown by the offset of the first sample to about 1,700
 * (ulp 1.2e-4) against a second difference of about 6 (the cost named in
 * docs/allan.md, "Phase"; test_unrepresentative_first_sample's 2e-3). No
 * mutant of fnav_allan.c tried passed the rest of this file and failed
 * here: it pins the per-push behaviour, not a fix. */
#if FNAV_USE_DOUBLE
#define EVERY_TOL 1e-9
#else
#define EVERY_TOL 2e-3
#endif

static void test_every_push(void **state)
{
    static const uint32_t tau[] = { 1u, 2u, 3u, 7u, 16u, 17u, 31u, 100u, 240u, 241u, 255u,
                                    256u, 384u, 448u, 640u, 1280u };
    enum { NPT = sizeof tau / sizeof tau[0], N = 2700 };
    static fnav_allan_t a;
    static long double x[N + 1];
    long double so[NPT] = { 0.0L }, sn[NPT] = { 0.0L };
    uint32_t to[NPT] = { 0u }, tn[NPT] = { 0u };
    const fnav_allan_config_t cfg = { tau, NPT };
    double worst = 0.0;
    size_t k, i, compared = 0, recentred = 0;
    fnav_real_t y0_prev;
    (void)state;
    assert_int_equal(fnav_allan_init(&a, &cfg), FNAV_OK);
    g_xs = 88172645463325252ull;
    x[0] = 0.0L;
    y0_prev = FNAV_R(0.0);
    for (k = 1; k <= N; k++) {
        const double u = xs_uniform();
        const fnav_real_t y = k == 1u ? FNAV_R(0.0) : (fnav_real_t)(3.0 + u + (k > N / 2u ? 20.0 : 0.0));
        assert_int_equal(fnav_allan_push(&a, y), FNAV_OK);
        if (k > 1u && a.y0 != y0_prev) {
            recentred++;
        }
        y0_prev = a.y0;
        x[k] = x[k - 1u] + (long double)y;
        for (i = 0; i < NPT; i++) {
            const uint32_t m = tau[i];
            fnav_allan_result_t r;
            assert_int_equal(fnav_allan_get(&a, i, &r), FNAV_OK);
            /* the reference's terms end at k: every stride-th sample */
            if (k >= 2u * m && k % r.stride == 0u) {
                const long double d = (x[k] - 2.0L * x[k - m]) + x[k - 2u * m];
                so[i] += d * d;
                to[i]++;
                if (k % m == 0u) {
                    sn[i] += d * d;
                    tn[i]++;
                }
            }
            assert_int_equal(r.tau, m);
            assert_int_equal(r.n_phase, k / r.stride + 1u);
            assert_int_equal(r.terms, to[i]);
            assert_int_equal(r.terms_nonoverlap, tn[i]);
            if (to[i] == 0u) {
                assert_true(isnan((double)r.avar));
            } else {
                const double ref = (double)(so[i] / (2.0L * (long double)m * (long double)m * (long double)to[i]));
                FNAV_ASSERT_CLOSE(r.avar, ref, 0.0, EVERY_TOL);
                if (fabs((double)r.avar / ref - 1.0) > worst) {
                    worst = fabs((double)r.avar / ref - 1.0);
                }
                compared++;
            }
            if (tn[i] == 0u) {
                assert_true(isnan((double)r.avar_nonoverlap));
            } else {
                const double ref = (double)(sn[i] / (2.0L * (long double)m * (long double)m * (long double)tn[i]));
                FNAV_ASSERT_CLOSE(r.avar_nonoverlap, ref, 0.0, EVERY_TOL);
                if (fabs((double)r.avar_nonoverlap / ref - 1.0) > worst) {
                    worst = fabs((double)r.avar_nonoverlap / ref - 1.0);
                }
            }
        }
    }
    assert_true(recentred >= 2u);
    assert_int_equal(a.pt[NPT - 1u].level, 8); /* tau 1280 = 5 x 2^8 */
    assert_true(to[NPT - 1u] > 0u);
    fprintf(stderr, "[  INFO    ] %s build: %zu results after every push, %zu re-centrings, largest relative error %.2g\n",
            FNAV_USE_DOUBLE ? "double" : "float", compared, recentred, worst);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_nbs14_1000),
        cmocka_unit_test(test_nbs14_10),
        cmocka_unit_test(test_nbs14_10_other_deviations),
        cmocka_unit_test(test_phasedat_other_deviations),
        cmocka_unit_test(test_edf_var_edges),
        cmocka_unit_test(test_edf_white_pm_few_terms),
        cmocka_unit_test(test_edf_many_terms),
        cmocka_unit_test(test_pdev_nbs14),
        cmocka_unit_test(test_totdev_nbs14),
        cmocka_unit_test(test_totdev_edf),
        cmocka_unit_test(test_chi2_quantile_large),
        cmocka_unit_test(test_edf_flicker_pm_table),
        cmocka_unit_test(test_slopes_three_points),
        cmocka_unit_test(test_slopes_long_tau),
        cmocka_unit_test(test_paper_min_at_end),
        cmocka_unit_test(test_paper_tau_max),
        cmocka_unit_test(test_pdev_edf),
        cmocka_unit_test(test_pdev_edf_simulated),
        cmocka_unit_test(test_phasedat_oadev_every_tau),
        cmocka_unit_test(test_phasedat_adev_every_tau),
        cmocka_unit_test(test_phasedat_oadev_octave_ci),
        cmocka_unit_test(test_phasedat_adev_octave_ci),
        cmocka_unit_test(test_synthetic_every_level),
        cmocka_unit_test(test_unrepresentative_first_sample),
        cmocka_unit_test(test_allantools_adis),
        cmocka_unit_test(test_memory_bound),
        cmocka_unit_test(test_config_errors),
        cmocka_unit_test(test_bad_samples_leave_state),
        cmocka_unit_test(test_not_initialised),
        cmocka_unit_test(test_grid_copied),
        cmocka_unit_test(test_grid),
        cmocka_unit_test(test_edf_case2_table),
        cmocka_unit_test(test_edf_modified_table),
        cmocka_unit_test(test_sim_quant_rrw),
        cmocka_unit_test(test_noise_from_slope),
        cmocka_unit_test(test_late_level0_points),
        cmocka_unit_test(test_every_push),
        cmocka_unit_test(test_noise_types_simulated),
        cmocka_unit_test(test_paper_identification_arithmetic),
        cmocka_unit_test(test_model_avar_exact),
        cmocka_unit_test(test_gm_peak),
        cmocka_unit_test(test_fit_recovers_model),
        cmocka_unit_test(test_identify_limit_below_one_sample),
        cmocka_unit_test(test_fit_more_params_than_points),
        cmocka_unit_test(test_fit_finite),
        cmocka_unit_test(test_fit_simulated),
        cmocka_unit_test(test_fit_simulated_seeds),
        cmocka_unit_test(test_sim_statistics),
        cmocka_unit_test(test_paper_tables_builtin),
        cmocka_unit_test(test_paper_tables_inconsistent),
        cmocka_unit_test(test_profile_roundtrip),
        cmocka_unit_test(test_edf_single_term),
        cmocka_unit_test(test_avar_record_ramp),
        cmocka_unit_test(test_noise_id_edges),
        cmocka_unit_test(test_noise_id_rn_at_one_sample),
        cmocka_unit_test(test_sample_count_end),
        cmocka_unit_test(test_nonoverlap_count_end),
        cmocka_unit_test(test_paper_readings),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
