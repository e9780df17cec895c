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
        fnav_fft_complex(&f, re, im, m);
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
        fnav_fft_real_packed(&f, re, im);
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

/* A pure tone lands in one bin with amplitude n/2 (analytic). */
static void test_real_tone(void **state)
{
    static fnav_fft_t f;
    static fnav_real_t re[33], im[33];
    const uint32_t n = 64, bin = 5;
    uint32_t k;
    (void)state;
    assert_int_equal(fnav_fft_init(&f, n), FNAV_OK);
    for (k = 0; k < n / 2; k++) {
        re[k] = (fnav_real_t)cos(6.283185307179586 * bin * (2.0 * k) / n);
        im[k] = (fnav_real_t)cos(6.283185307179586 * bin * (2.0 * k + 1.0) / n);
    }
    fnav_fft_real_packed(&f, re, im);
    for (k = 0; k <= n / 2; k++) {
        const double mag = sqrt((double)(re[k] * re[k] + im[k] * im[k]));
        FNAV_ASSERT_CLOSE(mag, k == bin ? n / 2.0 : 0.0, 1e-4, 0.0);
    }
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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_complex_vs_dft),
        cmocka_unit_test(test_real_vs_dft),
        cmocka_unit_test(test_real_tone),
        cmocka_unit_test(test_init_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
