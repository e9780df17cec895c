/* Tests of the IMU error model and effect catalogue (fnav_imuerr.h).
 *
 * Statistical acceptance: simulated noise must have the intended Allan curve
 * (each check: the overlapping Allan variance estimate lies inside the
 * chi-square interval, z = 4, of the exact analytic value for the simulated
 * discrete process, with the equivalent degrees of freedom of NIST SP 1065
 * Table 5), and each effect leaves its documented signature
 * (docs/simulator.md). Seeds are fixed: the tests are deterministic. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "footnav/fnav_imuerr.h"
#include "support/fnav_testdata.h"

#define PI 3.14159265358979323846
#define Z_CI 4.0 /* two-sided z of every statistical check (p ~ 6e-5 each) */

/* ------------------------------------------------------------ helpers */

/* Exact overlapping Allan variance of y[0..n) at averaging factor m
 * (Howe, Allan & Barnes 1981), via the cumulative sum ("phase"). */
static double oavar(const double *y, size_t n, size_t m)
{
    double *x = (double *)malloc((n + 1) * sizeof *x);
    double s = 0.0;
    size_t i;
    assert_non_null(x);
    x[0] = 0.0;
    for (i = 0; i < n; i++) {
        x[i + 1] = x[i] + y[i];
    }
    assert_true(2 * m <= n);
    for (i = 0; i + 2 * m <= n; i++) {
        double d = x[i + 2 * m] - 2.0 * x[i + m] + x[i];
        s += d * d;
    }
    free(x);
    return s / (2.0 * (double)m * (double)m * (double)(n - 2 * m + 1));
}

/* Allan variance of a stationary discrete process with autocovariance
 * R(k) = var c^|k| (AR(1), eq. 3) at averaging factor m:
 * AVAR = (Var(S_m) - Cov(S_m, S_m')) / m^2 for adjacent block sums. */
static double avar_ar1(size_t m, double var, double c)
{
    double vs = (double)m, cv = 0.0, ck = 1.0;
    size_t k;
    for (k = 1; k < 2 * m; k++) {
        ck *= c;
        if (k < m) {
            vs += 2.0 * (double)(m - k) * ck;
        }
        cv += (double)(m - (k > m ? k - m : m - k)) * ck;
    }
    return var * (vs - cv) / ((double)m * (double)m);
}

/* Allan variance of a discrete random walk with increment variance q. */
static double avar_rw(size_t m, double q)
{
    return q * (2.0 * (double)m * (double)m + 1.0) / (6.0 * (double)m);
}

/* Allan variance of a sampled sinusoid of amplitude a and angular
 * frequency w rad/sample, averaged over phase. */
static double avar_sine(size_t m, double a, double w)
{
    double s = sin(0.5 * w * (double)m), d = sin(0.5 * w);
    return a * a * s * s * s * s / ((double)m * (double)m * d * d);
}

/* Equivalent degrees of freedom of the overlapping Allan variance, NIST SP
 * 1065 Table 5, with N phase points (n samples + 1). */
static double edf_white(double N, double m)
{
    return (3.0 * (N - 1.0) / (2.0 * m) - 2.0 * (N - 2.0) / N) * 4.0 * m * m / (4.0 * m * m + 5.0);
}
static double edf_flicker(double N, double m)
{
    return m < 1.5 ? 2.0 * (N - 2.0) * (N - 2.0) / (2.3 * N - 4.9) : 5.0 * N * N / (4.0 * m * (N + 3.0 * m));
}
static double edf_rw(double N, double m)
{
    return (N - 2.0) / m * ((N - 1.0) * (N - 1.0) - 3.0 * m * (N - 1.0) + 4.0 * m * m) / ((N - 3.0) * (N - 3.0));
}

/* Chi-square quantile (Wilson-Hilferty) at standard normal z. */
static double chi2_q(double nu, double z)
{
    double a = 2.0 / (9.0 * nu);
    double t = 1.0 - a + z * sqrt(a);
    return nu * t * t * t;
}

/* Fail unless est is inside the chi-square interval of truth with edf. */
static void check_avar(double est, double truth, double edf, const char *what, size_t m)
{
    double lo = truth * chi2_q(edf, -Z_CI) / edf;
    double hi = truth * chi2_q(edf, Z_CI) / edf;
    if (!(est >= lo && est <= hi)) {
        fprintf(stderr, "%s: m=%zu AVAR %.6g outside [%.6g, %.6g] (analytic %.6g, edf %.1f)\n", what, m, est, lo,
                hi, truth, edf);
        fail();
    }
}

/* Run n sensor steps on a constant true signal; store channel ch. */
static void run_const(fnav_imuerr_t *e, size_t n, int ch, double *out, double *bias_out)
{
    size_t i;
    for (i = 0; i < n; i++) {
        fnav_real_t f[3] = { FNAV_R(0.0), FNAV_R(0.0), FNAV_R(-9.80665) };
        fnav_real_t w[3] = { FNAV_R(0.0), FNAV_R(0.0), FNAV_R(0.0) };
        fnav_real_t y[6], b[6];
        fnav_imuerr_signal(e, f, w, y);
        fnav_imuerr_sensor(e, y);
        out[i] = (double)y[ch] - (ch == 2 ? -9.80665 : 0.0);
        if (bias_out != NULL) {
            fnav_imuerr_bias(e, b);
            bias_out[i] = (double)b[ch];
        }
    }
}

static fnav_imuerr_config_t base_cfg(double rate)
{
    fnav_imuerr_config_t c = fnav_imuerr_config_default;
    const char *env = getenv("FNAV_TEST_SEED"); /* to re-run the suite on other seeds */
    c.rate_hz = (fnav_real_t)rate;
    c.seed = (env != NULL) ? (uint32_t)strtoul(env, NULL, 10) : 12345u;
    return c;
}

static double mean_of(const double *y, size_t n)
{
    double s = 0.0;
    size_t i;
    for (i = 0; i < n; i++) {
        s += y[i];
    }
    return s / (double)n;
}

static double var_of(const double *y, size_t n)
{
    double mu = mean_of(y, n), s = 0.0;
    size_t i;
    for (i = 0; i < n; i++) {
        s += (y[i] - mu) * (y[i] - mu);
    }
    return s / (double)(n - 1);
}

/* ------------------------------------------------------------ RNG */

static void test_rng_deterministic_and_normal(void **state)
{
    fnav_rng_t a, b, c;
    size_t i, n = 1000000;
    double s1 = 0.0, s2 = 0.0, s4 = 0.0, su = 0.0;
    int differ = 0;
    (void)state;
    fnav_rng_seed(&a, 7u, 1u);
    fnav_rng_seed(&b, 7u, 1u);
    fnav_rng_seed(&c, 7u, 2u);
    for (i = 0; i < 1000; i++) {
        uint32_t x = fnav_rng_u32(&a), y = fnav_rng_u32(&b), z = fnav_rng_u32(&c);
        assert_int_equal(x, y);
        differ += (x != z);
    }
    assert_true(differ > 990);
    for (i = 0; i < n; i++) {
        double g = (double)fnav_rng_gauss(&a);
        double u = (double)fnav_rng_uniform(&b);
        assert_true(u >= 0.0 && u < 1.0);
        su += u;
        s1 += g;
        s2 += g * g;
        s4 += g * g * g * g;
    }
    /* mean 0 (se 1/sqrt(n)), variance 1 (se sqrt(2/n)), kurtosis 3 (se sqrt(96/n)) */
    FNAV_ASSERT_CLOSE(s1 / (double)n, 0.0, Z_CI / sqrt((double)n), 0.0);
    FNAV_ASSERT_CLOSE(s2 / (double)n, 1.0, Z_CI * sqrt(2.0 / (double)n), 0.0);
    FNAV_ASSERT_CLOSE(s4 / (double)n, 3.0, Z_CI * sqrt(96.0 / (double)n), 0.0);
    FNAV_ASSERT_CLOSE(su / (double)n, 0.5, Z_CI * sqrt(1.0 / 12.0 / (double)n), 0.0);
}

/* ------------------------------------------------------------ catalogue */

static void test_catalogue_names_and_params(void **state)
{
    int id, i;
    fnav_imuerr_config_t c = fnav_imuerr_config_default;
    (void)state;
    for (id = 0; id < (int)FNAV_EFFECT_COUNT; id++) {
        const fnav_effect_info_t *info = fnav_imuerr_effect_info((fnav_effect_id_t)id);
        assert_non_null(info);
        assert_int_equal(fnav_imuerr_effect_find(info->name), id);
        assert_true(info->nparams >= 1);
        for (i = 0; i < info->nparams; i++) {
            const fnav_effect_param_t *p = &info->params[i];
            size_t width = (p->flags & FNAV_PARAM_PER_CHANNEL) ? 6 * sizeof(fnav_real_t) : sizeof(fnav_real_t);
            assert_true(p->offset + width <= sizeof(fnav_imuerr_config_t));
            assert_int_equal(fnav_imuerr_param_find((fnav_effect_id_t)id, p->name), i);
            assert_true(p->lo <= p->hi);
        }
        /* the default parameters of every effect are valid when switched on */
        {
            fnav_imuerr_config_t one = fnav_imuerr_config_default;
            fnav_imuerr_t e;
            assert_int_equal(fnav_imuerr_enable(&one, (fnav_effect_id_t)id, FNAV_CH_ALL), FNAV_OK);
            assert_int_equal(fnav_imuerr_init(&e, &one), FNAV_OK);
        }
    }
    assert_int_equal(fnav_imuerr_effect_find("nonsense"), FNAV_EFFECT_COUNT);
    assert_int_equal(fnav_imuerr_param_find(FNAV_EFFECT_QUANT, "nonsense"), -1);
    assert_null(fnav_imuerr_effect_info(FNAV_EFFECT_COUNT));

    /* set / get / reset by name */
    i = fnav_imuerr_param_find(FNAV_EFFECT_QUANT, "lsb");
    assert_int_equal(fnav_imuerr_param_set(&c, FNAV_EFFECT_QUANT, i, FNAV_CH_GZ, FNAV_R(0.25)), FNAV_OK);
    FNAV_ASSERT_CLOSE(fnav_imuerr_param_get(&c, FNAV_EFFECT_QUANT, i, 5), 0.25, 0.0, 1e-7);
    FNAV_ASSERT_CLOSE(fnav_imuerr_param_get(&c, FNAV_EFFECT_QUANT, i, 4), (double)fnav_imuerr_config_default.quant.lsb[4],
                      0.0, 1e-7);
    assert_int_equal(fnav_imuerr_param_set(&c, FNAV_EFFECT_QUANT, i, FNAV_CH_GZ, FNAV_R(-1.0)), FNAV_E_RANGE);
    assert_int_equal(fnav_imuerr_param_set(&c, FNAV_EFFECT_QUANT, 9, FNAV_CH_GZ, FNAV_R(1.0)), FNAV_E_ARG);
    assert_int_equal(fnav_imuerr_param_set(&c, FNAV_EFFECT_QUANT, i, FNAV_CH_GZ, (fnav_real_t)NAN), FNAV_E_RANGE);
    fnav_imuerr_effect_reset(&c, FNAV_EFFECT_QUANT);
    FNAV_ASSERT_CLOSE(c.quant.lsb[5], fnav_imuerr_config_default.quant.lsb[5], 0.0, 0.0);
    /* scalar parameter ignores the channel mask */
    i = fnav_imuerr_param_find(FNAV_EFFECT_DROPOUT, "prob");
    assert_int_equal(fnav_imuerr_param_set(&c, FNAV_EFFECT_DROPOUT, i, 0u, FNAV_R(0.5)), FNAV_OK);
    FNAV_ASSERT_CLOSE(c.dropout.prob, 0.5, 0.0, 0.0);

    /* enable respects the allowed channels */
    c = fnav_imuerr_config_default;
    assert_int_equal(fnav_imuerr_enable(&c, FNAV_EFFECT_GSENS, FNAV_CH_ACC), FNAV_E_ARG);
    assert_int_equal(fnav_imuerr_enable(&c, FNAV_EFFECT_GSENS, FNAV_CH_ALL), FNAV_OK);
    assert_int_equal(c.mask[FNAV_EFFECT_GSENS], FNAV_CH_GYRO);
    assert_int_equal(fnav_imuerr_enable(&c, FNAV_EFFECT_JITTER, FNAV_CH_AX), FNAV_OK);
    assert_int_equal(c.mask[FNAV_EFFECT_JITTER], FNAV_CH_ALL);
    fnav_imuerr_disable(&c, FNAV_EFFECT_JITTER);
    assert_int_equal(c.mask[FNAV_EFFECT_JITTER], 0);
    assert_int_equal(fnav_imuerr_enable(NULL, FNAV_EFFECT_JITTER, FNAV_CH_AX), FNAV_E_ARG);

    /* bad names, ids and channels (fnav_imuerr.h; make coverage: not run):
     * no effect, index -1, a get of 0, a reset that changes nothing */
    assert_int_equal(fnav_imuerr_effect_find(NULL), FNAV_EFFECT_COUNT);
    assert_int_equal(fnav_imuerr_param_find(FNAV_EFFECT_QUANT, NULL), -1);
    assert_int_equal(fnav_imuerr_param_find(FNAV_EFFECT_COUNT, "lsb"), -1);
    i = fnav_imuerr_param_find(FNAV_EFFECT_QUANT, "lsb");
    assert_true(fnav_imuerr_param_get(&c, FNAV_EFFECT_QUANT, i, 6) == FNAV_R(0.0));
    assert_true(fnav_imuerr_param_get(&c, FNAV_EFFECT_QUANT, i, -1) == FNAV_R(0.0));
    assert_true(fnav_imuerr_param_get(&c, FNAV_EFFECT_COUNT, 0, 0) == FNAV_R(0.0));
    assert_true(fnav_imuerr_param_get(NULL, FNAV_EFFECT_QUANT, i, 0) == FNAV_R(0.0));
    /* a scalar parameter ignores the channel, whatever it is */
    i = fnav_imuerr_param_find(FNAV_EFFECT_DROPOUT, "prob");
    c.dropout.prob = FNAV_R(0.125);
    assert_true(fnav_imuerr_param_get(&c, FNAV_EFFECT_DROPOUT, i, 17) == FNAV_R(0.125));
    {
        fnav_imuerr_config_t before = c;
        fnav_imuerr_effect_reset(&c, FNAV_EFFECT_COUNT);
        assert_memory_equal(&c, &before, sizeof c);
    }
    fnav_imuerr_effect_reset(NULL, FNAV_EFFECT_QUANT);
    assert_int_equal(fnav_imuerr_internal_factor(NULL), 1u);
    /* a configuration fnav_imuerr_init refuses: the alias factor converted
     * to uint32_t whatever it held would be undefined behaviour for NaN, a
     * negative value or one above 2^32 (x86 gives 0x80000000 or 0), and
     * oversample 0 coming back as 0 would be a factor a caller divides by;
     * it is 1, as for NULL */
    {
        const fnav_real_t zero = FNAV_R(0.0);
        const fnav_real_t bad[5] = { zero / zero, FNAV_R(-5.0), FNAV_R(1e20), FNAV_R(1.0) / zero, FNAV_R(1.0) };
        int k;
        c = fnav_imuerr_config_default;
        c.mask[FNAV_EFFECT_ALIAS] = FNAV_CH_ALL;
        for (k = 0; k < 5; k++) {
            c.alias.factor = bad[k];
            assert_int_equal(fnav_imuerr_internal_factor(&c), 1u);
        }
        c.alias.factor = FNAV_R(1024.0);
        assert_int_equal(fnav_imuerr_internal_factor(&c), 1024u);
        c = fnav_imuerr_config_default;
        c.oversample = 0u;
        assert_int_equal(fnav_imuerr_internal_factor(&c), 1u);
        c.oversample = 1025u;
        assert_int_equal(fnav_imuerr_internal_factor(&c), 1u);
        c.oversample = 1024u;
        assert_int_equal(fnav_imuerr_internal_factor(&c), 1024u);
    }
}

/* A whole-number parameter given a non-whole value: param_set refuses it
 * with init's status (FNAV_E_CONFIG) and leaves the parameter as it was,
 * rather than take it and leave fnav_imuerr_init to refuse the
 * configuration later without naming it; whole values are taken. */
static void test_param_set_whole(void **state)
{
    fnav_imuerr_config_t c = fnav_imuerr_config_default;
    fnav_imuerr_t e;
    const int sh = fnav_imuerr_param_find(FNAV_EFFECT_QUANT, "shaped");
    const int fa = fnav_imuerr_param_find(FNAV_EFFECT_ALIAS, "factor");
    const fnav_real_t fa0 = c.alias.factor;
    (void)state;
    assert_true(sh >= 0 && fa >= 0);
    /* init's status for such a value, set behind param_set's back */
    c.quant.shaped[5] = FNAV_R(0.5);
    assert_int_equal(fnav_imuerr_enable(&c, FNAV_EFFECT_QUANT, FNAV_CH_GZ), FNAV_OK);
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_E_CONFIG);
    c = fnav_imuerr_config_default;
    /* per-channel (quant.shaped, 0/1): refused, no channel changed */
    assert_int_equal(fnav_imuerr_param_set(&c, FNAV_EFFECT_QUANT, sh, FNAV_CH_ALL, FNAV_R(0.5)), FNAV_E_CONFIG);
    assert_true(c.quant.shaped[0] == fnav_imuerr_config_default.quant.shaped[0]);
    assert_true(c.quant.shaped[5] == fnav_imuerr_config_default.quant.shaped[5]);
    assert_int_equal(fnav_imuerr_param_set(&c, FNAV_EFFECT_QUANT, sh, FNAV_CH_GZ, FNAV_R(1.0)), FNAV_OK);
    assert_true(c.quant.shaped[5] == FNAV_R(1.0));
    /* scalar (alias.factor, 2 .. 1024): refused just above and below a whole number */
    assert_int_equal(fnav_imuerr_param_set(&c, FNAV_EFFECT_ALIAS, fa, 0u, FNAV_R(2.5)), FNAV_E_CONFIG);
    assert_int_equal(fnav_imuerr_param_set(&c, FNAV_EFFECT_ALIAS, fa, 0u, FNAV_R(3.0) + FNAV_R(0.0009765625)),
                     FNAV_E_CONFIG);
    assert_int_equal(fnav_imuerr_param_set(&c, FNAV_EFFECT_ALIAS, fa, 0u, FNAV_R(1023.75)), FNAV_E_CONFIG);
    assert_true(c.alias.factor == fa0);
    assert_int_equal(fnav_imuerr_param_set(&c, FNAV_EFFECT_ALIAS, fa, 0u, FNAV_R(3.0)), FNAV_OK);
    assert_true(c.alias.factor == FNAV_R(3.0));
    /* out of range is still FNAV_E_RANGE, as before */
    assert_int_equal(fnav_imuerr_param_set(&c, FNAV_EFFECT_ALIAS, fa, 0u, FNAV_R(1.5)), FNAV_E_RANGE);
    /* what param_set takes, init takes */
    assert_int_equal(fnav_imuerr_enable(&c, FNAV_EFFECT_QUANT, FNAV_CH_GZ), FNAV_OK);
    assert_int_equal(fnav_imuerr_enable(&c, FNAV_EFFECT_ALIAS, FNAV_CH_ALL), FNAV_OK);
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_OK);
}

static void test_config_validation(void **state)
{
    fnav_imuerr_config_t c;
    fnav_imuerr_t e;
    (void)state;
    memset(&e, 0x5A, sizeof e);
    assert_int_equal(fnav_imuerr_init(NULL, &fnav_imuerr_config_default), FNAV_E_ARG);
    assert_int_equal(fnav_imuerr_init(&e, NULL), FNAV_E_ARG);

    c = fnav_imuerr_config_default;
    c.rate_hz = FNAV_R(0.0);
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_E_CONFIG);
    assert_int_equal(((unsigned char *)&e)[0], 0x5A); /* untouched */

    c = fnav_imuerr_config_default;
    c.oversample = 0u;
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_E_CONFIG);

    /* own-axis misalignment belongs to the scale factor */
    c = fnav_imuerr_config_default;
    c.mask[FNAV_EFFECT_MISALIGN] = FNAV_CH_AY;
    c.misalign.from_y[1] = FNAV_R(0.01);
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_E_CONFIG);
    c.mask[FNAV_EFFECT_MISALIGN] = FNAV_CH_AX; /* only channels switched on are checked */
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_OK);

    /* g-sensitivity on an accelerometer channel */
    c = fnav_imuerr_config_default;
    c.mask[FNAV_EFFECT_GSENS] = FNAV_CH_AX;
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_E_CONFIG);

    /* parameter outside its range on an enabled channel */
    c = fnav_imuerr_config_default;
    c.mask[FNAV_EFFECT_QUANT] = FNAV_CH_GX;
    c.quant.lsb[3] = FNAV_R(0.0);
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_E_CONFIG);
    c.quant.lsb[3] = FNAV_R(1e-3);
    c.quant.shaped[3] = FNAV_R(0.5); /* a switch is 0 or 1 */
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_E_CONFIG);

    c = fnav_imuerr_config_default;
    c.mask[FNAV_EFFECT_FLICKER] = FNAV_CH_ALL;
    c.flicker.tau_lo_s = FNAV_R(100.0);
    c.flicker.tau_hi_s = FNAV_R(10.0);
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_E_CONFIG);
    /* an empty band too: ln r = 0 made every pole's variance B^2 ln r / pi
     * zero, a flicker effect that adds nothing (a hand-made mutant accepted
     * tau_lo_s == tau_hi_s and no test saw it) */
    c.flicker.tau_hi_s = FNAV_R(100.0);
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_E_CONFIG);
    c.flicker.tau_hi_s = FNAV_R(100.5);
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_OK);

    c = fnav_imuerr_config_default;
    c.mask[FNAV_EFFECT_ALIAS] = FNAV_CH_ALL;
    c.alias.factor = FNAV_R(2.5);
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_E_CONFIG);
    c.alias.factor = FNAV_R(8.0);
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_OK);
    assert_int_equal(fnav_imuerr_internal_factor(&c), 8);
    /* a scalar parameter outside its range [2, 1024] (make coverage: only
     * per-channel ones were tried) */
    c.alias.factor = FNAV_R(1.0);
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_E_CONFIG);
    c.alias.factor = FNAV_R(2048.0);
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_E_CONFIG);
    c.alias.factor = FNAV_R(1024.0);
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_OK);
    /* the rate finite and positive, oversample 1 .. 1024 */
    c = fnav_imuerr_config_default;
    c.rate_hz = (fnav_real_t)NAN;
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_E_CONFIG);
    c = fnav_imuerr_config_default;
    c.oversample = 1025u;
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_E_CONFIG);
    c.oversample = 1024u;
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_OK);
    /* a rate so small that its period 1 / rate_hz overflows (a subnormal
     * float): was accepted with dt_s = Inf, and the first sensor step's
     * time 0 * Inf made a ramp's or thermal drift's bias NaN, every output
     * of fnav_imuerr_apply NaN with FNAV_OK; refused, *e untouched. The
     * smallest rate with a finite period is accepted. */
    {
#if FNAV_USE_DOUBLE
        const fnav_real_t bad = 1e-310, ok = 1e-300;
#else
        const fnav_real_t bad = 1e-40f, ok = 1e-38f;
#endif
        c = fnav_imuerr_config_default;
        c.mask[FNAV_EFFECT_RAMP] = FNAV_CH_ALL;
        c.rate_hz = bad;
        memset(&e, 0x5A, sizeof e);
        assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_E_CONFIG);
        assert_int_equal(((unsigned char *)&e)[0], 0x5A);
        c.rate_hz = ok;
        assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_OK);
        assert_true(fnav_isfinite(e.dt_s));
        {
            fnav_sample_t s;
            int i;
            memset(&s, 0, sizeof s);
            s.accel_mps2[2] = -FNAV_G0_MPS2;
            assert_int_equal(fnav_imuerr_apply(&e, &s), FNAV_OK);
            for (i = 0; i < 3; i++) {
                assert_true(fnav_isfinite(s.accel_mps2[i]) && fnav_isfinite(s.gyro_rps[i]));
            }
        }
    }

    c = fnav_imuerr_config_default;
    c.mask[FNAV_EFFECT_JUMPS] = FNAV_CH_AX;
    c.jumps.rate_hz[0] = FNAV_R(1000.0); /* more than one per sample at 100 Hz */
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_E_CONFIG);
}

static void test_profile_baseline(void **state)
{
    fnav_profile_t p;
    fnav_imuerr_config_t c = fnav_imuerr_config_default;
    fnav_imuerr_t e;
    size_t n = 400000, ch;
    double *y = (double *)malloc(n * sizeof *y);
    (void)state;
    assert_non_null(y);
    assert_int_equal(fnav_profile_by_name(&p, "navchip"), FNAV_OK);
    assert_int_equal(fnav_imuerr_config_from_profile(&c, &p), FNAV_OK);
    assert_int_equal(c.mask[FNAV_EFFECT_WHITE], FNAV_CH_ALL);
    assert_int_equal(c.mask[FNAV_EFFECT_AR1], FNAV_CH_ALL);
    FNAV_ASSERT_CLOSE(c.ar1.tau_s[5], 10000.0 / 200.0, 0.0, 1e-6);               /* Table IV gyr z */
    FNAV_ASSERT_CLOSE(c.white.density[3], 3.3e-3 * PI / 180.0, 0.0, 1e-6);
    c.rate_hz = FNAV_R(200.0);
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_OK);
    /* per-sample std = N sqrt(f_s); at tau = 1 s the Allan deviation is N
     * (the paper reads sigma_v there); the AR(1) part is far below it */
    for (ch = 0; ch < 6; ch++) {
        fnav_imuerr_t e2;
        size_t m = 200;
        double N = (double)c.white.density[ch], var_b = (double)c.ar1.sigma[ch] * (double)c.ar1.sigma[ch];
        double cc = exp(-1.0 / (200.0 * (double)c.ar1.tau_s[ch]));
        double truth = N * N * 200.0 / (double)m + avar_ar1(m, var_b, cc);
        assert_int_equal(fnav_imuerr_init(&e2, &c), FNAV_OK);
        run_const(&e2, n, (int)ch, y, NULL);
        check_avar(oavar(y, n, 1), N * N * 200.0 + avar_ar1(1, var_b, cc), edf_white((double)n + 1.0, 1.0),
                   "navchip tau0", 1);
        check_avar(oavar(y, n, m), truth, edf_white((double)n + 1.0, (double)m), "navchip tau=1s", m);
    }
    assert_int_equal(fnav_imuerr_config_from_profile(NULL, &p), FNAV_E_ARG);
    p.gyro_tau_s[0] = FNAV_R(-1.0);
    assert_int_equal(fnav_imuerr_config_from_profile(&c, &p), FNAV_E_CONFIG);
    /* each of the six figures outside the catalogue's range (density and
     * sigma up to 1e3, tau from 1e-3 s) is refused, on the second axis: a
     * mutant leaving the gyro density out of the range check passed every
     * suite */
    {
        int k;
        for (k = 0; k < 6; k++) {
            fnav_real_t *x[6];
            assert_int_equal(fnav_profile_builtin(&p, FNAV_PROFILE_NAVCHIP), FNAV_OK);
            assert_int_equal(fnav_imuerr_config_from_profile(&c, &p), FNAV_OK);
            x[0] = &p.accel_noise_mps2_rthz[1];
            x[1] = &p.gyro_noise_rps_rthz[1];
            x[2] = &p.accel_tau_s[1];
            x[3] = &p.gyro_tau_s[1];
            x[4] = &p.accel_bias_sigma_mps2[1];
            x[5] = &p.gyro_bias_sigma_rps[1];
            *x[k] = (k == 2 || k == 3) ? FNAV_R(5e-4) : FNAV_R(2e3);
            assert_int_equal(fnav_imuerr_config_from_profile(&c, &p), FNAV_E_CONFIG);
        }
    }
    free(y);
}

/* White + AR(1) with both parts visible: the estimate follows the exact
 * analytic curve at every octave. */
static void test_allan_white_plus_ar1(void **state)
{
    const double rate = 100.0, N = 0.01, tau = 20.0, sig = 0.005;
    fnav_imuerr_config_t c = base_cfg(rate);
    fnav_imuerr_t e;
    size_t n = (size_t)1 << 20, m;
    double *y = (double *)malloc(n * sizeof *y);
    double cc = exp(-1.0 / (rate * tau));
    int ch;
    (void)state;
    assert_non_null(y);
    for (ch = 0; ch < 6; ch++) {
        c.white.density[ch] = (fnav_real_t)N;
        c.ar1.tau_s[ch] = (fnav_real_t)tau;
        c.ar1.sigma[ch] = (fnav_real_t)sig;
    }
    c.mask[FNAV_EFFECT_WHITE] = FNAV_CH_ALL;
    c.mask[FNAV_EFFECT_AR1] = FNAV_CH_ALL;
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_OK);
    run_const(&e, n, 3, y, NULL);
    for (m = 1; m <= n / 32; m *= 2) {
        double truth = N * N * rate / (double)m + avar_ar1(m, sig * sig, cc);
        double Np = (double)n + 1.0;
        double edf = fmin(edf_white(Np, (double)m), edf_rw(Np, (double)m));
        check_avar(oavar(y, n, m), truth, edf, "white+AR(1)", m);
    }
    /* the AR(1) bump is really there: at tau ~ 2 T_c it is 2x the white part */
    m = (size_t)(2.0 * tau * rate);
    assert_true(avar_ar1(m, sig * sig, cc) > 2.0 * N * N * rate / (double)m);
    free(y);
}

/* Eqs. (3), (4) directly: the driving noise n_k = b_k - c b_(k-1) has
 * variance sigma^2 (1 - c^2) and the regression of b_k on b_(k-1) is c. */
static void test_ar1_equations(void **state)
{
    const double rate = 200.0, tau = 5.0, sig = 0.02;
    fnav_imuerr_config_t c = base_cfg(rate);
    fnav_imuerr_t e;
    size_t n = 1000000, i;
    double *y = (double *)malloc(n * sizeof *y), *b = (double *)malloc(n * sizeof *b);
    double cc = exp(-1.0 / (rate * tau)), sxy = 0.0, sxx = 0.0, sn2 = 0.0, chat, se;
    (void)state;
    assert_non_null(y);
    assert_non_null(b);
    for (i = 0; i < 6; i++) {
        c.ar1.tau_s[i] = (fnav_real_t)tau;
        c.ar1.sigma[i] = (fnav_real_t)sig;
    }
    c.mask[FNAV_EFFECT_AR1] = FNAV_CH_ALL;
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_OK);
    run_const(&e, n, 1, y, b);
    for (i = 1; i < n; i++) {
        double d = b[i] - cc * b[i - 1];
        sn2 += d * d;
        sxy += b[i] * b[i - 1];
        sxx += b[i - 1] * b[i - 1];
        assert_true(fabs(y[i] - b[i]) < 1e-6); /* no white noise: output = bias */
    }
    /* eq. (4) */
    FNAV_ASSERT_CLOSE(sn2 / (double)(n - 1), sig * sig * (1.0 - cc * cc), 0.0, Z_CI * sqrt(2.0 / (double)n));
    /* eq. (3): least-squares c, se = sqrt(var(n) / sum b^2) */
    chat = sxy / sxx;
    se = sqrt(sig * sig * (1.0 - cc * cc) / sxx);
    FNAV_ASSERT_CLOSE(chat, cc, Z_CI * se, 0.0);
    /* stationary: the variance of b stays sigma^2 (start drawn stationary);
     * n samples hold n / (2 tau rate) independent ones */
    FNAV_ASSERT_CLOSE(var_of(b, n), sig * sig, 0.0, Z_CI * sqrt(2.0 * 2.0 * tau * rate / (double)n));
    free(y);
    free(b);
}

/* The AR(1) state starts stationary, b_0 ~ N(0, sigma^2) (fnav_imuerr_init):
 * across seeds the first output bias b_1 = c b_0 + n_1 has variance
 * c^2 sigma^2 + sigma^2 (1 - c^2) = sigma^2. A start at b_0 = 0 (a hand-made
 * mutant, the long single-seed runs above did not see it: n / (2 tau f_s)
 * independent samples dilute a transient of one correlation time) gives
 * sigma^2 (1 - c^2), 2e-4 sigma^2 here. 2000 seeds x 6 independent channels:
 * the sample variance of 12000 zero-mean normals has relative se
 * sqrt(2 / 12000) = 1.3 %, z = 4 gives 5.2 %. */
static void test_ar1_stationary_start(void **state)
{
    const double rate = 100.0, tau = 100.0, sig = 0.01;
    fnav_imuerr_config_t c = base_cfg(rate);
    fnav_imuerr_t e;
    const uint32_t nseed = 2000u;
    uint32_t s;
    double s2 = 0.0, n = 0.0;
    int ch;
    (void)state;
    for (ch = 0; ch < 6; ch++) {
        c.ar1.tau_s[ch] = (fnav_real_t)tau;
        c.ar1.sigma[ch] = (fnav_real_t)sig;
    }
    c.mask[FNAV_EFFECT_AR1] = FNAV_CH_ALL;
    for (s = 0; s < nseed; s++) {
        fnav_real_t f[3] = { FNAV_R(0.0), FNAV_R(0.0), FNAV_R(0.0) }, y[6], b[6];
        c.seed = 7000u + s;
        assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_OK);
        fnav_imuerr_signal(&e, f, f, y);
        fnav_imuerr_sensor(&e, y);
        fnav_imuerr_bias(&e, b);
        for (ch = 0; ch < 6; ch++) {
            FNAV_ASSERT_CLOSE(y[ch], b[ch], 0.0, 0.0); /* no white noise: output = bias */
            s2 += (double)b[ch] * (double)b[ch];
            n += 1.0;
        }
    }
    FNAV_ASSERT_CLOSE(s2 / n, sig * sig, 0.0, Z_CI * sqrt(2.0 / n));
}

/* ------------------------------------------------------------ effects */

static void test_determinism_and_stream_independence(void **state)
{
    fnav_imuerr_config_t c = base_cfg(100.0);
    fnav_imuerr_t a, b;
    size_t n = 5000, i;
    double *y1 = (double *)malloc(n * sizeof *y1), *y2 = (double *)malloc(n * sizeof *y2);
    (void)state;
    assert_non_null(y1);
    assert_non_null(y2);
    c.mask[FNAV_EFFECT_WHITE] = FNAV_CH_ALL;
    assert_int_equal(fnav_imuerr_init(&a, &c), FNAV_OK);
    assert_int_equal(fnav_imuerr_init(&b, &c), FNAV_OK);
    run_const(&a, n, 4, y1, NULL);
    run_const(&b, n, 4, y2, NULL);
    for (i = 0; i < n; i++) {
        assert_true(y1[i] == y2[i]);
    }
    /* switching other effects on (on other channels, or additive ones) does
     * not change the white-noise draws */
    c.mask[FNAV_EFFECT_OFFSET] = FNAV_CH_GY;
    c.mask[FNAV_EFFECT_FLICKER] = FNAV_CH_ACC;
    c.mask[FNAV_EFFECT_JUMPS] = FNAV_CH_GX;
    c.mask[FNAV_EFFECT_DROPOUT] = FNAV_CH_ALL;
    assert_int_equal(fnav_imuerr_init(&b, &c), FNAV_OK);
    run_const(&b, n, 4, y2, NULL);
    for (i = 0; i < n; i++) {
        FNAV_ASSERT_CLOSE(y2[i] - y1[i], (double)c.offset.value[4], 1e-6, 0.0);
    }
    /* nor does the mask of another channel of the same effect: white noise
     * on gy alone draws what gy draws with every channel on (the draws are
     * made for every channel of an enabled effect; a hand-made mutant that
     * drew only for the channels switched on passed every suite) */
    c = base_cfg(100.0);
    c.mask[FNAV_EFFECT_WHITE] = FNAV_CH_GY;
    assert_int_equal(fnav_imuerr_init(&b, &c), FNAV_OK);
    run_const(&b, n, 4, y2, NULL);
    for (i = 0; i < n; i++) {
        assert_true(y2[i] == y1[i]);
    }
    c.mask[FNAV_EFFECT_WHITE] = FNAV_CH_ALL;
    /* another seed gives another sequence */
    c.seed = 99u;
    assert_int_equal(fnav_imuerr_init(&b, &c), FNAV_OK);
    run_const(&b, n, 4, y2, NULL);
    assert_true(fabs(y2[10] - y1[10]) > 0.0);
    free(y1);
    free(y2);
}

static void test_quantisation(void **state)
{
    const double rate = 100.0, lsb = 0.01;
    fnav_imuerr_config_t c = base_cfg(rate);
    fnav_imuerr_t a, b;
    size_t n = 500000, i, m;
    double *yq = (double *)malloc(n * sizeof *yq), *y0 = (double *)malloc(n * sizeof *y0);
    double *err = (double *)malloc(n * sizeof *err);
    (void)state;
    assert_non_null(yq);
    assert_non_null(y0);
    assert_non_null(err);
    c.white.density[3] = (fnav_real_t)(3.0 * lsb / sqrt(rate)); /* 3 LSB per sample: dithered */
    c.mask[FNAV_EFFECT_WHITE] = FNAV_CH_ALL;
    assert_int_equal(fnav_imuerr_init(&a, &c), FNAV_OK);
    run_const(&a, n, 3, y0, NULL);
    c.mask[FNAV_EFFECT_QUANT] = FNAV_CH_GX;
    c.quant.lsb[3] = (fnav_real_t)lsb;
    assert_int_equal(fnav_imuerr_init(&b, &c), FNAV_OK);
    run_const(&b, n, 3, yq, NULL);
    /* time-domain trace: every value on the lattice; error within LSB/2 */
    for (i = 0; i < n; i++) {
        double k = yq[i] / lsb;
        assert_true(fabs(k - floor(k + 0.5)) < 1e-3);
        err[i] = yq[i] - y0[i];
        assert_true(fabs(err[i]) <= 0.5 * lsb * (1.0 + 1e-4));
    }
    /* plain rounding: white error, variance LSB^2/12, Allan slope -1/2 */
    FNAV_ASSERT_CLOSE(var_of(err, n), lsb * lsb / 12.0, 0.0, Z_CI * sqrt(0.8 / (double)n));
    for (m = 1; m <= 64; m *= 4) {
        check_avar(oavar(err, n, m), lsb * lsb / 12.0 / (double)m, edf_white((double)n + 1.0, (double)m),
                   "quant plain", m);
    }

    /* noise-shaped (integrating sensor): error of the sum bounded by LSB,
     * Allan variance LSB^2 / (4 m^2): slope -1 */
    c.quant.shaped[3] = FNAV_R(1.0);
    assert_int_equal(fnav_imuerr_init(&b, &c), FNAV_OK);
    run_const(&b, n, 3, yq, NULL);
    {
        double sum = 0.0;
        for (i = 0; i < n; i++) {
            err[i] = yq[i] - y0[i];
            sum += err[i];
            assert_true(fabs(sum) <= lsb * (0.5 + 1e-3) + 1e-9 * (double)i);
        }
    }
    for (m = 1; m <= 256; m *= 4) {
        /* residuals are close to iid uniform: 3 per Allan term, white-like edf */
        check_avar(oavar(err, n, m), lsb * lsb / (4.0 * (double)m * (double)m),
                   edf_white((double)n + 1.0, 1.0) / 3.0, "quant shaped", m);
    }
    free(yq);
    free(y0);
    free(err);
}

static void test_flicker(void **state)
{
    const double rate = 4.0, B = 1e-3, lo = 2.0, hi = 2e4;
    fnav_imuerr_config_t c = base_cfg(rate);
    fnav_imuerr_t e;
    size_t n = (size_t)1 << 21, m;
    double *y = (double *)malloc(n * sizeof *y);
    double lnr = log(hi / lo) / (FNAV_IMUERR_FLICKER_POLES - 1);
    double v = B * B * lnr / PI; /* variance per pole */
    int ch;
    (void)state;
    assert_non_null(y);
    for (ch = 0; ch < 6; ch++) {
        c.flicker.b[ch] = (fnav_real_t)B;
    }
    c.flicker.tau_lo_s = (fnav_real_t)lo;
    c.flicker.tau_hi_s = (fnav_real_t)hi;
    c.mask[FNAV_EFFECT_FLICKER] = FNAV_CH_ALL;
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_OK);
    run_const(&e, n, 5, y, NULL);
    for (m = 8; m <= n / 64; m *= 2) {
        double truth = 0.0, Np = (double)n + 1.0, edf;
        int i;
        for (i = 0; i < FNAV_IMUERR_FLICKER_POLES; i++) {
            double tau_i = lo * exp(lnr * i);
            truth += avar_ar1(m, v, exp(-1.0 / (rate * tau_i)));
        }
        edf = fmin(edf_flicker(Np, (double)m), edf_rw(Np, (double)m));
        check_avar(oavar(y, n, m), truth, edf, "flicker", m);
        /* the pole sum is 1/f: flat at 0.664 B inside the band (design
         * check of the weights, ripple and edge roll-off within 12 %) */
        if ((double)m / rate >= 4.0 * lo && (double)m / rate <= hi / 20.0) {
            FNAV_ASSERT_CLOSE(sqrt(truth), sqrt(2.0 * log(2.0) / PI) * B, 0.0, 0.12);
        }
    }
    free(y);
}

/* The flicker poles start stationary too: each pole's state b_i,0 ~ N(0, v),
 * v = B^2 ln r / pi, so that the first output's flicker bias, the sum of
 * P independent poles, has variance P v over seeds. A start at 0 (a
 * hand-made mutant that test_flicker's single long run did not see) gives
 * about P v (1 - c_i^2), under 2 % of it here. 2000 seeds x 6 channels:
 * relative se of the sample variance sqrt(2 / 12000) = 1.3 %, z = 4. */
static void test_flicker_stationary_start(void **state)
{
    const double rate = 100.0, B = 1e-3, lo = 1.0, hi = 1e4;
    fnav_imuerr_config_t c = base_cfg(rate);
    fnav_imuerr_t e;
    const double lnr = log(hi / lo) / (FNAV_IMUERR_FLICKER_POLES - 1);
    const double var = FNAV_IMUERR_FLICKER_POLES * B * B * lnr / PI;
    uint32_t s;
    double s2 = 0.0, n = 0.0;
    int ch;
    (void)state;
    for (ch = 0; ch < 6; ch++) {
        c.flicker.b[ch] = (fnav_real_t)B;
    }
    c.flicker.tau_lo_s = (fnav_real_t)lo;
    c.flicker.tau_hi_s = (fnav_real_t)hi;
    c.mask[FNAV_EFFECT_FLICKER] = FNAV_CH_ALL;
    for (s = 0; s < 2000u; s++) {
        fnav_real_t f[3] = { FNAV_R(0.0), FNAV_R(0.0), FNAV_R(0.0) }, y[6], b[6];
        c.seed = 9000u + s;
        assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_OK);
        fnav_imuerr_signal(&e, f, f, y);
        fnav_imuerr_sensor(&e, y);
        fnav_imuerr_bias(&e, b);
        for (ch = 0; ch < 6; ch++) {
            s2 += (double)b[ch] * (double)b[ch];
            n += 1.0;
        }
    }
    FNAV_ASSERT_CLOSE(s2 / n, var, 0.0, Z_CI * sqrt(2.0 / n));
}

static void test_rate_random_walk(void **state)
{
    const double rate = 10.0, K = 2e-4;
    fnav_imuerr_config_t c = base_cfg(rate);
    fnav_imuerr_t e;
    size_t n = (size_t)1 << 20, m;
    double *y = (double *)malloc(n * sizeof *y);
    (void)state;
    assert_non_null(y);
    c.rrw.k[0] = (fnav_real_t)K;
    c.mask[FNAV_EFFECT_RRW] = FNAV_CH_AX;
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_OK);
    run_const(&e, n, 0, y, NULL);
    for (m = 1; m <= n / 64; m *= 4) {
        double q = K * K / rate;
        check_avar(oavar(y, n, m), avar_rw(m, q), edf_rw((double)n + 1.0, (double)m), "rrw", m);
        /* continuous limit K^2 tau / 3 (slope +1/2) */
        if (m >= 64) {
            FNAV_ASSERT_CLOSE(avar_rw(m, q), K * K * ((double)m / rate) / 3.0, 0.0, 1e-3);
        }
    }
    free(y);
}

static void test_ramp_and_thermal(void **state)
{
    const double rate = 50.0, R = 1e-3;
    fnav_imuerr_config_t c = base_cfg(rate);
    fnav_imuerr_t e;
    size_t n = 100000, m, i;
    double *y = (double *)malloc(n * sizeof *y), *b = (double *)malloc(n * sizeof *b);
    (void)state;
    assert_non_null(y);
    assert_non_null(b);
    c.ramp.rate[4] = (fnav_real_t)R;
    c.mask[FNAV_EFFECT_RAMP] = FNAV_CH_GY;
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_OK);
    run_const(&e, n, 4, y, NULL);
    for (i = 0; i < n; i += 997) {
        FNAV_ASSERT_CLOSE(y[i], R * (double)i / rate, 1e-9, 1e-5); /* b = R t, t = 0 at the first sample */
    }
    /* Allan: R tau / sqrt(2), slope +1, exactly */
    for (m = 1; m <= n / 4; m *= 4) {
        double t = (double)m / rate;
        FNAV_ASSERT_CLOSE(oavar(y, n, m), R * R * t * t / 2.0, 0.0, 2e-3);
    }

    /* thermal: bias = coef (T - t0), T = t0 + rise (1 - exp(-t / tau)) */
    c = base_cfg(rate);
    c.mask[FNAV_EFFECT_THERMAL] = FNAV_CH_AZ;
    c.thermal.coef[2] = FNAV_R(0.01);
    c.thermal.rise_c = FNAV_R(12.0);
    c.thermal.tau_s = FNAV_R(300.0);
    c.thermal.t0_c = FNAV_R(20.0);
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_OK);
    for (i = 0; i < n; i++) {
        fnav_sample_t s;
        double t = (double)i / rate, T = 20.0 + 12.0 * (1.0 - exp(-t / 300.0));
        memset(&s, 0, sizeof s);
        s.accel_mps2[2] = FNAV_R(-9.80665);
        assert_int_equal(fnav_imuerr_apply(&e, &s), FNAV_OK);
        if (i % 1009 == 0) {
            assert_true((s.flags & FNAV_SAMPLE_HAS_TEMP) != 0u);
            FNAV_ASSERT_CLOSE(s.temp_c, T, 1e-4, 1e-5);
            FNAV_ASSERT_CLOSE((double)s.accel_mps2[2] + 9.80665, 0.01 * (T - 20.0), 1e-5, 1e-4);
            FNAV_ASSERT_CLOSE(s.accel_mps2[0], 0.0, 0.0, 0.0);
        }
    }
    free(y);
    free(b);
}

/* Goertzel amplitude of a real signal at f (Hz) for rate fs. */
static double tone_amp(const double *y, size_t n, double f, double fs)
{
    double w = 2.0 * PI * f / fs, cw = 2.0 * cos(w), s0, s1 = 0.0, s2 = 0.0, re, im;
    size_t i;
    for (i = 0; i < n; i++) {
        s0 = y[i] + cw * s1 - s2;
        s2 = s1;
        s1 = s0;
    }
    re = s1 - s2 * cos(w);
    im = s2 * sin(w);
    return 2.0 * sqrt(re * re + im * im) / (double)n;
}

static void test_vibration(void **state)
{
    const double rate = 100.0, A = 0.05, f = 13.0, N = 2e-3;
    fnav_imuerr_config_t c = base_cfg(rate);
    fnav_imuerr_t e;
    size_t n = 200000, m;
    double *y = (double *)malloc(n * sizeof *y);
    double floor_amp;
    (void)state;
    assert_non_null(y);
    c.white.density[2] = (fnav_real_t)N;
    c.mask[FNAV_EFFECT_WHITE] = FNAV_CH_ALL;
    c.vibration.amp[2] = (fnav_real_t)A;
    c.vibration.freq_hz[2] = (fnav_real_t)f;
    c.vibration.phase_rad[2] = FNAV_R(0.3);
    c.mask[FNAV_EFFECT_VIBRATION] = FNAV_CH_AZ;
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_OK);
    run_const(&e, n, 2, y, NULL);
    /* spectral line of amplitude A at f; noise amplitude in a bin is
     * ~ 2 sigma / sqrt(n) */
    FNAV_ASSERT_CLOSE(tone_amp(y, n, f, rate), A, Z_CI * 2.0 * N * sqrt(rate) / sqrt((double)n), 0.0);
    floor_amp = tone_amp(y, n, 21.7, rate);
    assert_true(floor_amp < Z_CI * 2.0 * N * sqrt(rate) / sqrt((double)n));
    /* Allan bump: white + sampled-sine term, nulls at tau = k / f */
    for (m = 1; m <= 64; m++) {
        double truth = N * N * rate / (double)m + avar_sine(m, A, 2.0 * PI * f / rate);
        check_avar(oavar(y, n, m), truth, edf_white((double)n + 1.0, (double)m) / 4.0, "vibration", m);
    }
    free(y);
}

static void test_jumps(void **state)
{
    const double rate = 100.0, lam = 0.5, amp = 0.03;
    fnav_imuerr_config_t c = base_cfg(rate);
    fnav_imuerr_t e;
    size_t n = 1000000, i, m;
    double *y = (double *)malloc(n * sizeof *y), *b = (double *)malloc(n * sizeof *b);
    double steps = 0.0, s2 = 0.0, expect = lam * (double)n / rate;
    (void)state;
    assert_non_null(y);
    assert_non_null(b);
    c.jumps.rate_hz[1] = (fnav_real_t)lam;
    c.jumps.amp[1] = (fnav_real_t)amp;
    c.mask[FNAV_EFFECT_JUMPS] = FNAV_CH_AY;
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_OK);
    run_const(&e, n, 1, y, b);
    /* time-domain trace: piecewise constant with Poisson(lambda T) steps of
     * Gaussian size amp */
    for (i = 1; i < n; i++) {
        double d = b[i] - b[i - 1];
        if (d != 0.0) {
            steps += 1.0;
            s2 += d * d;
        }
    }
    FNAV_ASSERT_CLOSE(steps, expect, Z_CI * sqrt(expect), 0.0);
    FNAV_ASSERT_CLOSE(sqrt(s2 / steps), amp, 0.0, Z_CI / sqrt(2.0 * steps));
    /* Allan: a random walk with increment variance p amp^2 (slope +1/2);
     * the increments are sparse, so the interval is widened 3x */
    for (m = 100; m <= n / 100; m *= 10) {
        double q = (1.0 - exp(-lam / rate)) * amp * amp;
        check_avar(oavar(y, n, m), avar_rw(m, q), edf_rw((double)n + 1.0, (double)m) / 9.0, "jumps", m);
    }
    /* the steps are drawn once per output sample, at the output rate,
     * whatever the internal rate of the signal stage: with oversample 10 a
     * hand-made mutant drawing with the internal period (p = 1 - exp(-lambda
     * dt / 10)) made a tenth of the steps, unseen at oversample 1. Poisson
     * count of lambda T = 2000 steps in 1000 s, z = 4 bound. */
    c.oversample = 10u;
    c.jumps.rate_hz[1] = FNAV_R(2.0);
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_OK);
    run_const(&e, 100000, 1, y, b);
    steps = 0.0;
    for (i = 1; i < 100000; i++) {
        steps += b[i] != b[i - 1];
    }
    FNAV_ASSERT_CLOSE(steps, 2000.0, Z_CI * sqrt(2000.0), 0.0);
    /* at most one step per sample: lambda up to the rate (p = 1 - 1/e) */
    c.oversample = 1u;
    c.jumps.rate_hz[1] = (fnav_real_t)rate;
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_OK);
    c.jumps.rate_hz[1] = (fnav_real_t)(1.5 * rate);
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_E_CONFIG);
    free(y);
    free(b);
}

static void test_deterministic_signal_effects(void **state)
{
    fnav_imuerr_config_t c = base_cfg(100.0);
    fnav_imuerr_t e;
    fnav_real_t f[3] = { FNAV_R(1.0), FNAV_R(-2.0), FNAV_R(-9.0) };
    fnav_real_t w[3] = { FNAV_R(0.5), FNAV_R(0.25), FNAV_R(-1.5) };
    fnav_real_t y[6];
    int i;
    (void)state;
    /* scale factor */
    c.mask[FNAV_EFFECT_SCALE] = FNAV_CH_AX | FNAV_CH_GZ;
    c.scale.sf[0] = FNAV_R(0.02);
    c.scale.sf[5] = FNAV_R(-0.01);
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_OK);
    fnav_imuerr_signal(&e, f, w, y);
    FNAV_ASSERT_CLOSE(y[0], 1.02, 1e-6, 0.0);
    FNAV_ASSERT_CLOSE(y[1], -2.0, 0.0, 0.0);
    FNAV_ASSERT_CLOSE(y[5], -1.5 * 0.99, 1e-6, 0.0);
    /* misalignment: y_i += sum_j m_ij x_j over the same sensor */
    c = base_cfg(100.0);
    c.mask[FNAV_EFFECT_MISALIGN] = FNAV_CH_AY | FNAV_CH_GX;
    c.misalign.from_x[1] = FNAV_R(0.01);
    c.misalign.from_z[1] = FNAV_R(-0.02);
    c.misalign.from_x[3] = FNAV_R(0.0);
    c.misalign.from_y[3] = FNAV_R(0.03);
    c.misalign.from_z[3] = FNAV_R(0.0);
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_OK);
    fnav_imuerr_signal(&e, f, w, y);
    FNAV_ASSERT_CLOSE(y[1], -2.0 + 0.01 * 1.0 - 0.02 * -9.0, 1e-6, 0.0);
    FNAV_ASSERT_CLOSE(y[3], 0.5 + 0.03 * 0.25, 1e-6, 0.0);
    FNAV_ASSERT_CLOSE(y[0], 1.0, 0.0, 0.0);
    /* g-sensitivity: gyro error G f */
    c = base_cfg(100.0);
    c.mask[FNAV_EFFECT_GSENS] = FNAV_CH_GZ;
    c.gsens.from_x[5] = FNAV_R(1e-3);
    c.gsens.from_y[5] = FNAV_R(0.0);
    c.gsens.from_z[5] = FNAV_R(2e-4);
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_OK);
    fnav_imuerr_signal(&e, f, w, y);
    FNAV_ASSERT_CLOSE(y[5], -1.5 + 1e-3 * 1.0 + 2e-4 * -9.0, 1e-7, 0.0);
    FNAV_ASSERT_CLOSE(y[4], 0.25, 0.0, 0.0);
    /* saturation: flat top at exactly the range, in both stages; with
     * quantisation the top is the last lattice point inside the range */
    c = base_cfg(100.0);
    c.mask[FNAV_EFFECT_SATURATION] = FNAV_CH_ALL;
    c.saturation.range[2] = FNAV_R(5.0);
    c.saturation.range[3] = FNAV_R(0.3);
    c.mask[FNAV_EFFECT_OFFSET] = FNAV_CH_GY;
    c.offset.value[4] = FNAV_R(1.0);
    c.saturation.range[4] = FNAV_R(1.2);
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_OK);
    for (i = 0; i < 3; i++) {
        fnav_imuerr_signal(&e, f, w, y);
        fnav_imuerr_sensor(&e, y);
        FNAV_ASSERT_CLOSE(y[2], -(double)c.saturation.range[2], 0.0, 0.0);
        FNAV_ASSERT_CLOSE(y[3], (double)c.saturation.range[3], 0.0, 0.0);
        FNAV_ASSERT_CLOSE(y[4], (double)c.saturation.range[4], 0.0, 0.0); /* 0.25 + 1.0 clipped at the output */
        FNAV_ASSERT_CLOSE(y[5], -1.5, 0.0, 0.0);
    }
    c.mask[FNAV_EFFECT_QUANT] = FNAV_CH_AZ | FNAV_CH_GX;
    c.quant.lsb[2] = FNAV_R(0.3);
    c.quant.lsb[3] = FNAV_R(0.18);
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_OK);
    fnav_imuerr_signal(&e, f, w, y);
    fnav_imuerr_sensor(&e, y);
    FNAV_ASSERT_CLOSE(y[2], -4.8, 1e-6, 0.0);
    /* and on the positive side (make coverage: never run): 0.3 rounds to
     * 2 lsb = 0.36, past the range; the top is 1 lsb, 0.18 */
    FNAV_ASSERT_CLOSE(y[3], 0.18, 1e-7, 0.0);
    /* offset */
    c = base_cfg(100.0);
    c.mask[FNAV_EFFECT_OFFSET] = FNAV_CH_AX;
    c.offset.value[0] = FNAV_R(0.125);
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_OK);
    fnav_imuerr_signal(&e, f, w, y);
    fnav_imuerr_sensor(&e, y);
    FNAV_ASSERT_CLOSE(y[0], 1.125, 1e-7, 0.0);
    {
        fnav_real_t bias[6];
        fnav_imuerr_bias(&e, bias);
        FNAV_ASSERT_CLOSE(bias[0], 0.125, 0.0, 0.0);
        FNAV_ASSERT_CLOSE(bias[1], 0.0, 0.0, 0.0);
    }
}

static void test_apply_rejects_nonfinite(void **state)
{
    fnav_imuerr_config_t c = base_cfg(100.0);
    fnav_imuerr_t e;
    fnav_sample_t s;
    (void)state;
    c.mask[FNAV_EFFECT_WHITE] = FNAV_CH_ALL;
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_OK);
    memset(&s, 0, sizeof s);
    s.gyro_rps[1] = (fnav_real_t)NAN;
    assert_int_equal(fnav_imuerr_apply(&e, &s), FNAV_E_NANINF);
    assert_int_equal(e.k, 0);
    assert_true(s.gyro_rps[1] != s.gyro_rps[1]);
    assert_int_equal(fnav_imuerr_apply(NULL, &s), FNAV_E_ARG);
    s.gyro_rps[1] = FNAV_R(0.0);
    assert_int_equal(fnav_imuerr_apply(&e, &s), FNAV_OK);
    assert_int_equal(e.k, 1);
}

static void test_timing(void **state)
{
    const double rate = 200.0, dt = 1.0 / rate;
    fnav_imuerr_config_t c = base_cfg(rate);
    fnav_imuerr_t e;
    size_t n = 200000, i, drops = 0, dups = 0, emitted = 0;
    double s1 = 0.0, s2 = 0.0, q2 = 0.0, last = -1e30;
    (void)state;
    c.mask[FNAV_EFFECT_DROPOUT] = FNAV_CH_ALL;
    c.mask[FNAV_EFFECT_DUPLICATE] = FNAV_CH_ALL;
    c.mask[FNAV_EFFECT_JITTER] = FNAV_CH_ALL;
    c.dropout.prob = FNAV_R(0.02);
    c.duplicate.prob = FNAV_R(0.005);
    c.jitter.stamp_s = (fnav_real_t)(0.05 * dt); /* clamp practically never active */
    c.jitter.sample_s = FNAV_R(1e-4);
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_OK);
    for (i = 0; i < n; i++) {
        fnav_imuerr_tick_t t;
        fnav_imuerr_tick(&e, &t);
        assert_true(t.count <= 2u);
        drops += (t.count == 0u);
        dups += (t.count == 2u);
        if (t.count > 0u) {
            double stamp = (double)i * dt + (double)t.stamp_off_s;
            assert_true(stamp >= last);
            last = stamp;
            emitted++;
            s1 += (double)t.stamp_off_s;
            s2 += (double)t.stamp_off_s * (double)t.stamp_off_s;
        }
        q2 += (double)t.sample_off_s * (double)t.sample_off_s;
    }
    FNAV_ASSERT_CLOSE((double)drops, 0.02 * (double)n, Z_CI * sqrt(0.02 * 0.98 * (double)n), 0.0);
    FNAV_ASSERT_CLOSE((double)dups, 0.005 * 0.98 * (double)n, Z_CI * sqrt(0.005 * (double)n), 0.0);
    FNAV_ASSERT_CLOSE(s1 / (double)emitted, 0.0, Z_CI * 0.05 * dt / sqrt((double)emitted), 0.0);
    FNAV_ASSERT_CLOSE(sqrt(s2 / (double)emitted), 0.05 * dt, 0.0, Z_CI / sqrt(2.0 * (double)emitted));
    FNAV_ASSERT_CLOSE(sqrt(q2 / (double)n), 1e-4, 0.0, Z_CI / sqrt(2.0 * (double)n));

    /* heavy jitter (3 dt): stamps still never go backwards */
    c.jitter.stamp_s = (fnav_real_t)(3.0 * dt);
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_OK);
    last = -1e30;
    for (i = 0; i < 20000; i++) {
        fnav_imuerr_tick_t t;
        fnav_imuerr_tick(&e, &t);
        if (t.count > 0u) {
            double stamp = (double)i * dt + (double)t.stamp_off_s;
            assert_true(stamp >= last - 1e-7); /* float offsets: equal within rounding */
            last = stamp;
        }
    }
    /* no timing effect: one sample per tick, nominal stamps */
    c = base_cfg(rate);
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_OK);
    for (i = 0; i < 100; i++) {
        fnav_imuerr_tick_t t;
        fnav_imuerr_tick(&e, &t);
        assert_int_equal(t.count, 1);
        FNAV_ASSERT_CLOSE(t.stamp_off_s, 0.0, 0.0, 0.0);
    }
}

/* Dropout and duplication on the same tick: a dropped sample is not emitted
 * twice (fnav_imuerr_tick duplicates only a sample that is kept). With both
 * probabilities 0.5 the counts 0, 1, 2 have probabilities 0.5, 0.25, 0.25;
 * duplicating regardless (a hand-made mutant, invisible at the 2 % and
 * 0.5 % of test_timing) gives 0.5, 0.25 -> 0.25 of count 2 from the drops
 * too: P(2) = 0.5. Binomial bounds, z = 4: n = 40000 gives an sd of
 * sqrt(0.25 0.75 / n) = 0.0022 on a proportion. */
static void test_dropout_before_duplicate(void **state)
{
    fnav_imuerr_config_t c = base_cfg(100.0);
    fnav_imuerr_t e;
    const size_t n = 40000;
    size_t i, k[3] = { 0, 0, 0 };
    (void)state;
    c.mask[FNAV_EFFECT_DROPOUT] = FNAV_CH_ALL;
    c.mask[FNAV_EFFECT_DUPLICATE] = FNAV_CH_ALL;
    c.dropout.prob = FNAV_R(0.5);
    c.duplicate.prob = FNAV_R(0.5);
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_OK);
    for (i = 0; i < n; i++) {
        fnav_imuerr_tick_t t;
        fnav_imuerr_tick(&e, &t);
        assert_true(t.count <= 2u);
        k[t.count]++;
    }
    FNAV_ASSERT_CLOSE((double)k[0] / (double)n, 0.5, Z_CI * sqrt(0.25 / (double)n), 0.0);
    FNAV_ASSERT_CLOSE((double)k[1] / (double)n, 0.25, Z_CI * sqrt(0.1875 / (double)n), 0.0);
    FNAV_ASSERT_CLOSE((double)k[2] / (double)n, 0.25, Z_CI * sqrt(0.1875 / (double)n), 0.0);
}

/* Without an anti-alias filter the white noise of M f_s folds into the
 * output band: per-sample variance N^2 M f_s. */
static void test_alias_noise_folding(void **state)
{
    const double rate = 100.0, N = 1e-3;
    fnav_imuerr_config_t c = base_cfg(rate);
    fnav_imuerr_t e;
    size_t n = 200000, m;
    double *y = (double *)malloc(n * sizeof *y);
    (void)state;
    assert_non_null(y);
    c.white.density[0] = (fnav_real_t)N;
    c.mask[FNAV_EFFECT_WHITE] = FNAV_CH_ALL;
    c.mask[FNAV_EFFECT_ALIAS] = FNAV_CH_ALL;
    c.alias.factor = FNAV_R(10.0);
    assert_int_equal(fnav_imuerr_init(&e, &c), FNAV_OK);
    FNAV_ASSERT_CLOSE(e.dt_int_s, 1e-3, 0.0, 1e-6);
    run_const(&e, n, 0, y, NULL);
    for (m = 1; m <= 16; m *= 4) {
        check_avar(oavar(y, n, m), N * N * rate * 10.0 / (double)m, edf_white((double)n + 1.0, (double)m),
                   "alias folding", m);
    }
    free(y);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rng_deterministic_and_normal),
        cmocka_unit_test(test_catalogue_names_and_params),
        cmocka_unit_test(test_param_set_whole),
        cmocka_unit_test(test_config_validation),
        cmocka_unit_test(test_profile_baseline),
        cmocka_unit_test(test_allan_white_plus_ar1),
        cmocka_unit_test(test_ar1_equations),
        cmocka_unit_test(test_ar1_stationary_start),
        cmocka_unit_test(test_determinism_and_stream_independence),
        cmocka_unit_test(test_quantisation),
        cmocka_unit_test(test_flicker),
        cmocka_unit_test(test_flicker_stationary_start),
        cmocka_unit_test(test_rate_random_walk),
        cmocka_unit_test(test_ramp_and_thermal),
        cmocka_unit_test(test_vibration),
        cmocka_unit_test(test_jumps),
        cmocka_unit_test(test_deterministic_signal_effects),
        cmocka_unit_test(test_apply_rejects_nonfinite),
        cmocka_unit_test(test_timing),
        cmocka_unit_test(test_dropout_before_duplicate),
        cmocka_unit_test(test_alias_noise_folding),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
