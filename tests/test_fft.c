/* Tests of the radix-2 FFT (src/fnav_fft.c) against a direct DFT computed
 * in long double (an independent double-precision reference). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include <cmocka.h>

#include "footnav/fnav_fft.h"
#include "support/fnav_testdata.h"

/* Error bound relative to the largest bin: radix-2 rounding grows as
 * eps log2(N); measured worst 4.8e-8 (float) and 1.5e-16 (double) on the
 * real transforms of random data with a DC part, N = 4..4096 (printed by
 * test_real_vs_dft). */
#if FNAV_USE_DOUBLE
#define FFT_TOL 1e-14
#else
#define FFT_TOL 1e-6
#endif

static double lcg(uint64_t *s)
{
    *s = 6364136223846793005u * *s + 1442695040888963407u;
    return (double)(*s >> 11) / 9007199254740992.0 - 0.5;
}

static void dft(const double *xr, const double *xi, size_t n, long double *yr, long double *yi)
{
    size_t k, t;
    const long double tw = 6.283185307179586476925286766559L / (long double)n;
    for (k = 0; k < n; k++) {
        long double sr = 0.0L, si = 0.0L;
        for (t = 0; t < n; t++) {
            const long double a = tw * (long double)((k * t) % n);
            sr += (long double)xr[t] * cosl(a) + (long double)xi[t] * sinl(a);
            si += (long double)xi[t] * cosl(a) - (long double)xr[t] * sinl(a);
        }
        yr[k] = sr;
        yi[k] = si;
    }
}

static void test_complex_vs_dft(void **state)
{
    static fnav_fft_t f;
    static double xr[512], xi[512];
    static long double yr[512], yi[512];
    static fnav_real_t re[512], im[512];
    uint64_t s = 99;
    uint32_t m;
    (void)state;
    assert_int_equal(fnav_fft_init(&f, FNAV_FFT_MAX_N), FNAV_OK);
    for (m = 2; m <= FNAV_FFT_MAX_N / 2 && m <= 512; m *= 2) {
        size_t k;
        double peak = 0.0, err = 0.0;
        for (k = 0; k < m; k++) {
            xr[k] = (double)(fnav_real_t)lcg(&s);
            xi[k] = (double)(fnav_real_t)lcg(&s);
            re[k] = (fnav_real_t)xr[k];
            im[k] = (fnav_real_t)xi[k];
        }
        /* a table for a longer transform serves shorter ones (stride) */
        assert_int_equal(fnav_fft_complex(&f, re, im, m), FNAV_OK);
        dft(xr, xi, m, yr, yi);
        for (k = 0; k < m; k++) {
            const double mag = (double)sqrtl(yr[k] * yr[k] + yi[k] * yi[k]);
            peak = mag > peak ? mag : peak;
        }
        for (k = 0; k < m; k++) {
            const double e = fabs((double)re[k] - (double)yr[k]) + fabs((double)im[k] - (double)yi[k]);
            err = e > err ? e : err;
        }
        assert_true(err <= FFT_TOL * peak);
    }
}

static void test_real_vs_dft(void **state)
{
    static fnav_fft_t f;
    static double x[FNAV_FFT_MAX_N], z[FNAV_FFT_MAX_N];
    static long double yr[FNAV_FFT_MAX_N], yi[FNAV_FFT_MAX_N];
    static fnav_real_t re[FNAV_FFT_MAX_N / 2 + 1], im[FNAV_FFT_MAX_N / 2 + 1];
    uint64_t s = 7;
    uint32_t n;
    double worst = 0.0;
    (void)state;
    for (n = 4; n <= FNAV_FFT_MAX_N; n *= 2) {
        size_t k;
        double peak = 0.0, err = 0.0;
        assert_int_equal(fnav_fft_init(&f, n), FNAV_OK);
        for (k = 0; k < n; k++) {
            x[k] = (double)(fnav_real_t)(lcg(&s) + 3.0); /* with a DC part */
            z[k] = 0.0;
        }
        for (k = 0; k < n / 2; k++) {
            re[k] = (fnav_real_t)x[2 * k];
            im[k] = (fnav_real_t)x[2 * k + 1];
        }
        /* entry n/2 is output only (fnav_fft.h): what it held before must
         * not show (a mutant leaving im[n/2] as it was passed every suite:
         * it held the 0 of the previous transform) */
        re[n / 2] = FNAV_R(7.0);
        im[n / 2] = FNAV_R(7.0);
        assert_int_equal(fnav_fft_real_packed(&f, re, im), FNAV_OK);
        dft(x, z, n, yr, yi);
        for (k = 0; k <= n / 2; k++) {
            const double mag = (double)sqrtl(yr[k] * yr[k] + yi[k] * yi[k]);
            peak = mag > peak ? mag : peak;
        }
        for (k = 0; k <= n / 2; k++) {
            const double e = fabs((double)re[k] - (double)yr[k]) + fabs((double)im[k] - (double)yi[k]);
            err = e > err ? e : err;
        }
        assert_true(err <= FFT_TOL * peak);
        assert_true(im[0] == FNAV_R(0.0) && im[n / 2] == FNAV_R(0.0));
        worst = err / peak > worst ? err / peak : worst;
    }
    /* the figure docs/psd.md quotes */
    fprintf(stderr, "[  INFO    ] %s build: worst real-transform error %.2g of the largest bin, N = 4..%u\n",
            FNAV_USE_DOUBLE ? "double" : "float", worst, (unsigned)FNAV_FFT_MAX_N);
}

/* A pure tone lands in one bin (analytic): the real transform of
 * cos(2 pi b t / n) is n/2 at bin b with phase 0 (re = n/2, im = 0) and 0
 * in every other bin. Each part is checked, not the magnitude alone (a
 * magnitude check let a tone come out as a sine, or with its sign
 * flipped, pass; and its 1e-4 absolute held the double build to 3e11
 * times its rounding). Tolerance: the transform's bound, FFT_TOL of the
 * largest bin (n/2), plus the inputs' rounding to fnav_real_t, half an
 * epsilon of each |x| <= 1, summed over the n samples into any bin. */
static void test_real_tone(void **state)
{
    static fnav_fft_t f;
    static fnav_real_t re[33], im[33];
    const uint32_t n = 64, bin = 5;
    const double tol = FFT_TOL * (n / 2.0) + 0.5 * (double)FNAV_REAL_EPSILON * n;
    uint32_t k;
    (void)state;
    assert_int_equal(fnav_fft_init(&f, n), FNAV_OK);
    for (k = 0; k < n / 2; k++) {
        re[k] = (fnav_real_t)cos(6.283185307179586 * bin * (2.0 * k) / n);
        im[k] = (fnav_real_t)cos(6.283185307179586 * bin * (2.0 * k + 1.0) / n);
    }
    assert_int_equal(fnav_fft_real_packed(&f, re, im), FNAV_OK);
    for (k = 0; k <= n / 2; k++) {
        FNAV_ASSERT_CLOSE(re[k], k == bin ? n / 2.0 : 0.0, tol, 0.0);
        FNAV_ASSERT_CLOSE(im[k], 0.0, tol, 0.0);
    }
}

/* fnav_fft_cos_sin_2pi against long double, every k of n = 1..600 and of
 * the largest transform lengths and their windows' (1023 .. 4097):
 * the twiddles (8 | n, reduced to [0, pi/4]) and the symmetric window
 * (n = nfft - 1, odd: reduced to [0, pi] only). Absolute error in units
 * of the working precision's epsilon; the exact values at multiples of
 * pi/2 are exact when 8 divides n (cos 0 = 1, sin 0 = 0 after the
 * reduction). The worst errors are printed (the figures fnav_fft.h
 * quotes). */
static void test_cos_sin_2pi(void **state)
{
    static const uint32_t big[] = { 1023, 1024, 2047, 2048, 4095, 4096, 4097 };
    uint32_t n, k, i;
    double worst8 = 0.0, worst_other = 0.0, worst8_ulp = 0.0;
    (void)state;
    for (i = 0; i < 600u + sizeof big / sizeof big[0]; i++) {
        n = i < 600u ? i + 1u : big[i - 600u];
        for (k = 0; k < n; k++) {
            fnav_real_t c, s;
            const long double a = 6.283185307179586476925286766559L * (long double)k / (long double)n;
            long double tc = cosl(a), ts = sinl(a);
            double e;
            if (4u * k == n || 4u * k == 3u * n) {
                tc = 0.0L;
            }
            if (2u * k == n || k == 0u) {
                ts = 0.0L;
            }
            assert_int_equal(fnav_fft_cos_sin_2pi(k, n, &c, &s), FNAV_OK);
            e = fmax(fabs((double)c - (double)tc), fabs((double)s - (double)ts)) / (double)FNAV_REAL_EPSILON;
            if (n % 8u == 0u) {
                /* ulp of a value in [2^e, 2^(e+1)): epsilon 2^e */
                const double uc = (double)tc == 0.0 ? 0.0
                                                    : fabs((double)c - (double)tc) /
                                                          ((double)FNAV_REAL_EPSILON * ldexp(1.0, ilogb((double)tc)));
                const double us = (double)ts == 0.0 ? 0.0
                                                    : fabs((double)s - (double)ts) /
                                                          ((double)FNAV_REAL_EPSILON * ldexp(1.0, ilogb((double)ts)));
                worst8 = fmax(worst8, e);
                worst8_ulp = fmax(worst8_ulp, fmax(uc, us));
                if (4u * k % n == 0u) { /* a multiple of pi/2: exact */
                    assert_true(c == (fnav_real_t)tc && s == (fnav_real_t)ts);
                }
            } else {
                worst_other = fmax(worst_other, e);
            }
        }
    }
    fprintf(stderr, "[  INFO    ] %s build: cos/sin(2 pi k / n) worst error %.2f eps (8 | n; %.2f ulp), %.2f eps (other n), n = 1..600, 1023..4097\n",
            FNAV_USE_DOUBLE ? "double" : "float", worst8, worst8_ulp, worst_other);
    assert_true(worst8 <= 1.0);
    assert_true(worst_other <= 4.0);
}

static void test_init_errors(void **state)
{
    static fnav_fft_t f;
    (void)state;
    assert_int_equal(fnav_fft_init(NULL, 64), FNAV_E_ARG);
    assert_int_equal(fnav_fft_init(&f, 48), FNAV_E_CONFIG);
    assert_int_equal(fnav_fft_init(&f, 2), FNAV_E_CONFIG);
    assert_int_equal(fnav_fft_init(&f, FNAV_FFT_MAX_N * 2u), FNAV_E_CONFIG);
    assert_int_equal(fnav_fft_init(&f, FNAV_FFT_MAX_N), FNAV_OK);
}

/* Argument checks: fnav_fft_complex checks m and the table,
 * fnav_fft_real_packed the table, fnav_fft_cos_sin_2pi n. Unchecked, an m
 * that is not a power of two would run its butterflies past the m entries
 * (m = 6: re[6], re[7]: ASan, heap-buffer-overflow); m = 128 on a table of
 * 64 would take the last stage's twiddles as 1 (X_1 of a unit impulse at
 * sample 1 would come out 1 + 0i, numpy.fft.fft 0.9988 - 0.0491i); a table
 * never initialised (n = 0, zeroed as static storage is) would send
 * fnav_fft_real_packed's split loop to k < 0 - k, past every array; n = 0
 * would divide by zero in fnav_fft_cos_sin_2pi. Each is refused with a
 * status, writing nothing. */
static void test_argument_checks(void **state)
{
    static fnav_fft_t f, zero;
    /* the m entries a call may use, and a guard beyond that must not move */
    static fnav_real_t re[FNAV_FFT_MAX_N + 8], im[FNAV_FFT_MAX_N + 8];
    static const uint32_t bad_m[] = { 0u, 1u, 3u, 6u, 12u, 48u, 128u };
    fnav_real_t c = FNAV_R(7.0), s = FNAV_R(7.0);
    size_t i, k;
    (void)state;
    assert_int_equal(fnav_fft_init(&f, 64u), FNAV_OK);
    for (i = 0; i < sizeof bad_m / sizeof bad_m[0] + 2u; i++) {
        /* the bad sizes, then 64 (above the 64 / 2 fnav_fft.h allows this
         * table) and FNAV_FFT_MAX_N (above the compiled maximum's half) */
        const size_t nb = sizeof bad_m / sizeof bad_m[0];
        const uint32_t m = i < nb ? bad_m[i] : (i == nb ? 64u : FNAV_FFT_MAX_N);
        for (k = 0; k < FNAV_FFT_MAX_N + 8u; k++) {
            re[k] = (fnav_real_t)k;
            im[k] = -(fnav_real_t)k;
        }
        assert_int_equal(fnav_fft_complex(&f, re, im, m), FNAV_E_SIZE);
        for (k = 0; k < FNAV_FFT_MAX_N + 8u; k++) {
            assert_true(re[k] == (fnav_real_t)k && im[k] == -(fnav_real_t)k);
        }
    }
    /* the largest m the table serves, and the smallest */
    assert_int_equal(fnav_fft_complex(&f, re, im, 32u), FNAV_OK);
    assert_int_equal(fnav_fft_complex(&f, re, im, 2u), FNAV_OK);
    assert_int_equal(fnav_fft_complex(NULL, re, im, 32u), FNAV_E_ARG);
    assert_int_equal(fnav_fft_complex(&f, NULL, im, 32u), FNAV_E_ARG);
    assert_int_equal(fnav_fft_complex(&f, re, NULL, 32u), FNAV_E_ARG);
    assert_int_equal(fnav_fft_real_packed(NULL, re, im), FNAV_E_ARG);
    assert_int_equal(fnav_fft_real_packed(&f, NULL, im), FNAV_E_ARG);
    assert_int_equal(fnav_fft_real_packed(&f, re, NULL), FNAV_E_ARG);
    /* a table never initialised, or whose init failed: nothing written */
    assert_int_equal(fnav_fft_init(&zero, 48u), FNAV_E_CONFIG);
    for (k = 0; k < FNAV_FFT_MAX_N + 8u; k++) {
        re[k] = (fnav_real_t)k;
        im[k] = -(fnav_real_t)k;
    }
    assert_int_equal(fnav_fft_real_packed(&zero, re, im), FNAV_E_STATE);
    assert_int_equal(fnav_fft_complex(&zero, re, im, 2u), FNAV_E_STATE);
    for (k = 0; k < FNAV_FFT_MAX_N + 8u; k++) {
        assert_true(re[k] == (fnav_real_t)k && im[k] == -(fnav_real_t)k);
    }
    assert_int_equal(fnav_fft_real_packed(&f, re, im), FNAV_OK);
    /* cos and sin of 2 pi k / n: n = 0 and NULL outputs refused, nothing written */
    assert_int_equal(fnav_fft_cos_sin_2pi(3u, 0u, &c, &s), FNAV_E_ARG);
    assert_true(c == FNAV_R(7.0) && s == FNAV_R(7.0));
    assert_int_equal(fnav_fft_cos_sin_2pi(3u, 8u, NULL, &s), FNAV_E_ARG);
    assert_int_equal(fnav_fft_cos_sin_2pi(3u, 8u, &c, NULL), FNAV_E_ARG);
    assert_true(c == FNAV_R(7.0) && s == FNAV_R(7.0));
    assert_int_equal(fnav_fft_cos_sin_2pi(2u, 8u, &c, &s), FNAV_OK); /* pi / 2, exact when 8 | n */
    assert_true(c == FNAV_R(0.0) && s == FNAV_R(1.0));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_complex_vs_dft),
        cmocka_unit_test(test_real_vs_dft),
        cmocka_unit_test(test_real_tone),
        cmocka_unit_test(test_cos_sin_2pi),
        cmocka_unit_test(test_init_errors),
        cmocka_unit_test(test_argument_checks),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
