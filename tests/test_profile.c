/* fnav_profile: the paper's Tables IV-VI as printed, converted to SI
 * (tau in samples at 200 Hz -> s, deg -> rad) and checked here against the
 * tables with the conversions redone in double; the AR(1) coefficient of the
 * paper (c = e^(-1/tau), tau in samples) equals footnav's exp(-dt / tau_s) at
 * the identification rate; lookup by name; validation; the profile file
 * (written by `harness allan`) round trip and `--profile FILE` loading. */
#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "footnav/fnav_imuerr.h"
#include "footnav/fnav_nav.h"
#include "footnav/fnav_profile.h"
#include "fnav_testdata.h"
#include "hx_profile.h"

#if FNAV_USE_DOUBLE
#define REL 1e-15
#else
#define REL 1.2e-7
#endif

static const double k_deg = 3.14159265358979323846 / 180.0;

/* The tables as printed in the paper: noise (m/s^2/sqrt(Hz) or
 * deg/s/sqrt(Hz)), tau (samples at 200 Hz), sigma_bias (m/s^2 or deg/s);
 * rows acc x, y, z, gyr x, y, z. Table IV is the NavChip, V the MTx, VI the
 * Shimmer (the captions; see fnav_profile.c for the text's inconsistency). */
static const double k_tables[3][6][3] = {
    { { 7.4e-4, 2000, 1.3e-5 }, { 6.4e-4, 2000, 9.7e-6 }, { 5.0e-4, 2000, 7.3e-6 },
      { 3.3e-3, 1000, 8.5e-5 }, { 3.7e-3, 1000, 6.4e-5 }, { 4.2e-3, 10000, 3.4e-5 } },
    { { 8.9e-4, 2600, 7.9e-6 }, { 8.4e-4, 2600, 8.1e-6 }, { 8.4e-4, 11000, 2.5e-6 },
      { 2.6e-2, 42000, 1.8e-5 }, { 2.5e-2, 56000, 1.6e-5 }, { 2.9e-2, 144000, 8.4e-6 } },
    { { 6.0e-3, 14600, 8.7e-6 }, { 5.9e-3, 36000, 5.3e-6 }, { 6.5e-3, 9400, 1.4e-5 },
      { 1.9e-2, 4200, 1.0e-4 }, { 1.7e-2, 800, 5.3e-4 }, { 1.9e-2, 2800, 2.2e-4 } },
};
static const char *const k_names[3] = { "navchip", "mtx", "shimmer" };

static void check_profile(const fnav_profile_t *p, int t)
{
    int i;
    assert_string_equal(p->name, k_names[t]);
    FNAV_ASSERT_CLOSE(p->rate_hz, 200.0, 0.0, REL);
    for (i = 0; i < 3; i++) {
        FNAV_ASSERT_CLOSE(p->accel_noise_mps2_rthz[i], k_tables[t][i][0], 0.0, REL);
        FNAV_ASSERT_CLOSE(p->accel_tau_s[i], k_tables[t][i][1] / 200.0, 0.0, REL);
        FNAV_ASSERT_CLOSE(p->accel_bias_sigma_mps2[i], k_tables[t][i][2], 0.0, REL);
        FNAV_ASSERT_CLOSE(p->gyro_noise_rps_rthz[i], k_tables[t][3 + i][0] * k_deg, 0.0, 2.0 * REL);
        FNAV_ASSERT_CLOSE(p->gyro_tau_s[i], k_tables[t][3 + i][1] / 200.0, 0.0, REL);
        FNAV_ASSERT_CLOSE(p->gyro_bias_sigma_rps[i], k_tables[t][3 + i][2] * k_deg, 0.0, 2.0 * REL);
    }
}

static void test_builtin_tables(void **state)
{
    int t;
    (void)state;
    for (t = 0; t < 3; t++) {
        fnav_profile_t p;
        const fnav_profile_paper_row_t *rows = fnav_profile_paper_table((fnav_profile_id_t)t);
        int i;
        assert_non_null(rows);
        for (i = 0; i < 6; i++) {
            assert_true(rows[i].noise == k_tables[t][i][0]);
            assert_true(rows[i].tau_samples == k_tables[t][i][1]);
            assert_true(rows[i].sigma_bias == k_tables[t][i][2]);
        }
        assert_int_equal(fnav_profile_builtin(&p, (fnav_profile_id_t)t), FNAV_OK);
        check_profile(&p, t);
        assert_int_equal(fnav_profile_validate(&p), FNAV_OK);
        memset(&p, 0, sizeof p);
        assert_int_equal(fnav_profile_by_name(&p, k_names[t]), FNAV_OK);
        check_profile(&p, t);
    }
    {
        fnav_profile_t p;
        assert_null(fnav_profile_paper_table(FNAV_PROFILE_COUNT));
        assert_int_equal(fnav_profile_builtin(&p, FNAV_PROFILE_COUNT), FNAV_E_ARG);
        assert_int_equal(fnav_profile_by_name(&p, "navchip2"), FNAV_E_ARG);
        assert_int_equal(fnav_profile_by_name(&p, "nav"), FNAV_E_ARG);
        assert_int_equal(fnav_profile_by_name(NULL, "mtx"), FNAV_E_ARG);
    }
}

/* The built-ins hold exactly what fnav_profile_from_paper makes of the
 * paper's tables: each value converted in double (tau / 200 Hz, gyro x
 * pi/180) and rounded once to fnav_real_t, redone here; and byte for byte
 * fnav_profile_from_paper's profile (the name's padding too). The
 * built-ins are converted by the compiler, so that no double arithmetic is
 * linked with them on the Cortex-M4F (tests/cli/test_profile_fw.sh); not one
 * ulp may move (docs/firmware.md, "Another sensor model"). */
static void test_builtin_exact(void **state)
{
    int t, i;
    (void)state;
    for (t = 0; t < 3; t++) {
        const fnav_profile_paper_row_t *rows = fnav_profile_paper_table((fnav_profile_id_t)t);
        fnav_profile_t p, q;
        memset(&q, 0xa5, sizeof q);
        assert_int_equal(fnav_profile_builtin(&p, (fnav_profile_id_t)t), FNAV_OK);
        assert_int_equal(fnav_profile_from_paper(&q, k_names[t], 200.0, rows), FNAV_OK);
        assert_memory_equal(&p, &q, sizeof p);
        assert_true(p.rate_hz == (fnav_real_t)200.0);
        for (i = 0; i < 3; i++) {
            assert_true(p.accel_noise_mps2_rthz[i] == (fnav_real_t)k_tables[t][i][0]);
            assert_true(p.accel_tau_s[i] == (fnav_real_t)(k_tables[t][i][1] / 200.0));
            assert_true(p.accel_bias_sigma_mps2[i] == (fnav_real_t)k_tables[t][i][2]);
            assert_true(p.gyro_noise_rps_rthz[i] == (fnav_real_t)(k_tables[t][3 + i][0] * k_deg));
            assert_true(p.gyro_tau_s[i] == (fnav_real_t)(k_tables[t][3 + i][1] / 200.0));
            assert_true(p.gyro_bias_sigma_rps[i] == (fnav_real_t)(k_tables[t][3 + i][2] * k_deg));
        }
    }
    {
        fnav_profile_t p;
        assert_int_equal(fnav_profile_builtin(NULL, FNAV_PROFILE_NAVCHIP), FNAV_E_ARG);
        assert_int_equal(fnav_profile_builtin(&p, (fnav_profile_id_t)-1), FNAV_E_ARG);
    }
}

/* The paper's AR(1) coefficient c = e^(-1/tau) per sample (tau in samples)
 * and eq. (4)'s driving variance sigma^2 (1 - e^(-2/tau)) are what the
 * filter uses at the identification rate: the navigator configured with
 * the Shimmer profile, one prediction at dt = 1/200 s, and the filter's
 * cached coefficients (fnav_ukf_t.ar1_c, ar1_q: gyro x, y, z, then
 * accelerometer x, y, z) compared with the paper's tables, converted here
 * in double. Rounding: c = 1 - d with d = 1 - exp(-dt/tau) good to about
 * 5.5 EPS relative (dt / tau rounded 1.5 EPS, fnav_one_minus_exp_neg's
 * series 4 EPS), which is d < 1.3e-3 times that relative to c, plus c's own
 * rounding EPS / 2: 2 REL. q = sigma^2 d (2 - d): sigma^2 within 4 EPS
 * (the profile's sigma within 2 EPS, test_builtin_tables), d within
 * 5.5 EPS, three products: 16 REL. */
static void test_ar1_units(void **state)
{
    static fnav_nav_t nav;
    fnav_nav_config_t c = fnav_nav_config_default;
    fnav_ukf_init_sd_t sd;
    int i;
    (void)state;
    assert_int_equal(fnav_profile_builtin(&c.profile, FNAV_PROFILE_SHIMMER), FNAV_OK);
    assert_int_equal(c.bias_model, FNAV_BIAS_AR1);
    assert_int_equal(fnav_nav_init(&nav, &c), FNAV_OK);
    for (i = 0; i < 3; i++) {
        sd.att_rad[i] = FNAV_R(0.01);
        sd.gyro_bias_rps[i] = FNAV_R(1.0e-4);
        sd.accel_bias_mps2[i] = FNAV_R(1.0e-3);
    }
    sd.vel_mps = FNAV_R(0.01);
    sd.pos_m = FNAV_R(0.001);
    assert_int_equal(fnav_ukf_start(&nav.ukf, fnav_quat_identity(), fnav_vec3_zero(), fnav_vec3_zero(), &sd), FNAV_OK);
    assert_int_equal(fnav_ukf_predict(&nav.ukf, fnav_vec3_zero(), fnav_vec3(FNAV_R(0.0), FNAV_R(0.0), -FNAV_R(9.80665)),
                                      FNAV_R(1.0) / FNAV_R(200.0)),
                     FNAV_OK);
    for (i = 0; i < 3; i++) {
        const double tg = k_tables[2][3 + i][1], ta = k_tables[2][i][1];
        const double sg = k_tables[2][3 + i][2] * k_deg, sa = k_tables[2][i][2];
        FNAV_ASSERT_CLOSE(nav.ukf.ar1_c[i], exp(-1.0 / tg), 0.0, 2.0 * REL);
        FNAV_ASSERT_CLOSE(nav.ukf.ar1_c[3 + i], exp(-1.0 / ta), 0.0, 2.0 * REL);
        /* 1 - e^(-2/tau) as -expm1(-2/tau): 1 - exp() would lose 2/tau's
         * ratio of digits (exp's last bit against 5e-4 here) */
        FNAV_ASSERT_CLOSE(nav.ukf.ar1_q[i], sg * sg * -expm1(-2.0 / tg), 0.0, 16.0 * REL);
        FNAV_ASSERT_CLOSE(nav.ukf.ar1_q[3 + i], sa * sa * -expm1(-2.0 / ta), 0.0, 16.0 * REL);
    }
}

static void test_validate(void **state)
{
    fnav_profile_t p;
    fnav_profile_paper_row_t rows[6];
    (void)state;
    assert_int_equal(fnav_profile_builtin(&p, FNAV_PROFILE_MTX), FNAV_OK);
    p.gyro_tau_s[1] = FNAV_R(0.0);
    assert_int_equal(fnav_profile_validate(&p), FNAV_E_CONFIG);
    assert_int_equal(fnav_profile_builtin(&p, FNAV_PROFILE_MTX), FNAV_OK);
    p.accel_noise_mps2_rthz[2] = (fnav_real_t)NAN;
    assert_int_equal(fnav_profile_validate(&p), FNAV_E_CONFIG);
    assert_int_equal(fnav_profile_builtin(&p, FNAV_PROFILE_MTX), FNAV_OK);
    p.rate_hz = FNAV_R(-200.0);
    assert_int_equal(fnav_profile_validate(&p), FNAV_E_CONFIG);
    assert_int_equal(fnav_profile_validate(NULL), FNAV_E_ARG);
    memcpy(rows, fnav_profile_paper_table(FNAV_PROFILE_NAVCHIP), sizeof rows);
    rows[4].sigma_bias = -1.0;
    assert_int_equal(fnav_profile_from_paper(&p, "x", 200.0, rows), FNAV_E_ARG);
    /* the null arguments (by_name with a null name, from_paper with null
     * rows: mutants without those checks passed every suite) */
    {
        memcpy(rows, fnav_profile_paper_table(FNAV_PROFILE_NAVCHIP), sizeof rows);
        assert_int_equal(fnav_profile_from_paper(&p, "x", 200.0, rows), FNAV_OK);
        assert_int_equal(fnav_profile_from_paper(NULL, "x", 200.0, rows), FNAV_E_ARG);
        assert_int_equal(fnav_profile_from_paper(&p, NULL, 200.0, rows), FNAV_E_ARG);
        assert_int_equal(fnav_profile_from_paper(&p, "x", 200.0, NULL), FNAV_E_ARG);
        assert_int_equal(fnav_profile_by_name(&p, NULL), FNAV_E_ARG);
    }
    memcpy(rows, fnav_profile_paper_table(FNAV_PROFILE_NAVCHIP), sizeof rows);
    assert_int_equal(fnav_profile_from_paper(&p, "x", 0.0, rows), FNAV_E_ARG);
    assert_int_equal(fnav_profile_from_paper(&p, "x", (double)INFINITY, rows), FNAV_E_ARG);
    /* a conversion that leaves the working precision's range (an infinite
     * rate makes every tau 0; in float 1e39 Hz is an infinite rate and
     * 1e-46 Hz a zero one) is refused and leaves the profile as it was
     * (CONTRIBUTING: bad data leaves the object unchanged; not half
     * converted: name, rate and every value overwritten) */
    {
        static const double bad_rates[3] = { (double)INFINITY, FNAV_USE_DOUBLE ? (double)INFINITY : 1.0e39,
                                             FNAV_USE_DOUBLE ? (double)INFINITY : 1.0e-46 };
        int r;
        for (r = 0; r < 3; r++) {
            fnav_profile_t before;
            assert_int_equal(fnav_profile_builtin(&p, FNAV_PROFILE_MTX), FNAV_OK);
            before = p;
            assert_int_equal(fnav_profile_from_paper(&p, "x", bad_rates[r], rows), FNAV_E_ARG);
            assert_memory_equal(&p, &before, sizeof p);
        }
    }
    /* another identification rate: tau in samples scales with it */
    assert_int_equal(fnav_profile_from_paper(&p, "at100", 100.0, rows), FNAV_OK);
    FNAV_ASSERT_CLOSE(p.accel_tau_s[0], 2000.0 / 100.0, 0.0, REL);
    /* (make coverage: not run) a zero or NaN noise and a zero or NaN tau
     * in a row are refused like a negative sigma, the profile unchanged;
     * a name longer than FNAV_PROFILE_NAME_MAX - 1 characters is cut
     * there, NUL-terminated */
    {
        static const char long_name[] = "a-profile-name-of-more-than-thirty-one-characters";
        fnav_profile_t before = p;
        rows[1].noise = 0.0;
        assert_int_equal(fnav_profile_from_paper(&p, "x", 200.0, rows), FNAV_E_ARG);
        rows[1].noise = (double)NAN;
        assert_int_equal(fnav_profile_from_paper(&p, "x", 200.0, rows), FNAV_E_ARG);
        memcpy(rows, fnav_profile_paper_table(FNAV_PROFILE_NAVCHIP), sizeof rows);
        rows[5].tau_samples = 0.0;
        assert_int_equal(fnav_profile_from_paper(&p, "x", 200.0, rows), FNAV_E_ARG);
        rows[5].tau_samples = (double)NAN;
        assert_int_equal(fnav_profile_from_paper(&p, "x", 200.0, rows), FNAV_E_ARG);
        assert_memory_equal(&p, &before, sizeof p);
        memcpy(rows, fnav_profile_paper_table(FNAV_PROFILE_NAVCHIP), sizeof rows);
        assert_true(strlen(long_name) > FNAV_PROFILE_NAME_MAX);
        assert_int_equal(fnav_profile_from_paper(&p, long_name, 200.0, rows), FNAV_OK);
        assert_int_equal((int)strlen(p.name), FNAV_PROFILE_NAME_MAX - 1);
        assert_memory_equal(p.name, long_name, FNAV_PROFILE_NAME_MAX - 1);
    }
}

/* A profile file (the format `harness allan --profile` writes) survives a
 * write/read round trip, and hx_profile_load takes names and files. */
static void test_file_round_trip(void **state)
{
    fnav_profile_t a, b;
    char path[] = "/tmp/fnav_profile_XXXXXX", err[320];
    int fd, i;
    FILE *f;
    (void)state;
    fd = mkstemp(path);
    assert_true(fd >= 0);
    close(fd);
    assert_int_equal(fnav_profile_builtin(&a, FNAV_PROFILE_SHIMMER), FNAV_OK);
    a.accel_bias_sigma_mps2[1] = FNAV_R(0.0071); /* an Allan-style value */
    assert_int_equal(hx_profile_write(path, &a, "test_profile round trip", err, sizeof err), 0);
    assert_int_equal(hx_profile_read(path, &b, err, sizeof err), 0);
    assert_int_equal(hx_profile_load(path, &b, err, sizeof err), 0);
    assert_int_equal(fnav_profile_validate(&b), FNAV_OK);
    for (i = 0; i < 3; i++) {
        FNAV_ASSERT_CLOSE(b.accel_noise_mps2_rthz[i], a.accel_noise_mps2_rthz[i], 0.0, 1e-6);
        FNAV_ASSERT_CLOSE(b.accel_tau_s[i], a.accel_tau_s[i], 0.0, 1e-6);
        FNAV_ASSERT_CLOSE(b.accel_bias_sigma_mps2[i], a.accel_bias_sigma_mps2[i], 0.0, 1e-6);
        FNAV_ASSERT_CLOSE(b.gyro_noise_rps_rthz[i], a.gyro_noise_rps_rthz[i], 0.0, 1e-6);
        FNAV_ASSERT_CLOSE(b.gyro_tau_s[i], a.gyro_tau_s[i], 0.0, 1e-6);
        FNAV_ASSERT_CLOSE(b.gyro_bias_sigma_rps[i], a.gyro_bias_sigma_rps[i], 0.0, 1e-6);
    }
    FNAV_ASSERT_CLOSE(b.rate_hz, 200.0, 0.0, 1e-6);
    assert_int_equal(hx_profile_load("mtx", &b, err, sizeof err), 0);
    assert_string_equal(b.name, "mtx");
    /* a broken file: one line error with its line number */
    f = fopen(path, "w");
    assert_non_null(f);
    fputs("format = footnav-profile 1\nrate_hz = 200\naccel_tau_s = 1 2\n", f);
    fclose(f);
    assert_int_equal(hx_profile_read(path, &b, err, sizeof err), -1);
    assert_non_null(strstr(err, ":3:"));
    /* a required key given twice is refused (rate_hz and format are not
     * taken from their last line) */
    assert_int_equal(hx_profile_write(path, &a, "twice", err, sizeof err), 0);
    f = fopen(path, "a");
    assert_non_null(f);
    fputs("rate_hz = 100\n", f);
    fclose(f);
    assert_int_equal(hx_profile_read(path, &b, err, sizeof err), -1);
    assert_non_null(strstr(err, "rate_hz given twice"));
    /* a noise key given twice too, and rate_hz above 1e6 Hz
     * (profile-format.md: [1, 1e6]); 1e6 itself is taken. A rate written
     * at full float precision reads back exactly (%.9g: 9 digits carry any
     * float). Hand-made mutants dropping the twice check for noise keys, the
     * 1e6 bound or writing rate_hz with 4 digits passed every suite (fail
     * here, checked) */
    assert_int_equal(hx_profile_write(path, &a, "twice", err, sizeof err), 0);
    f = fopen(path, "a");
    assert_non_null(f);
    fputs("gyro_tau_s = 1 1 1\n", f);
    fclose(f);
    assert_int_equal(hx_profile_read(path, &b, err, sizeof err), -1);
    assert_non_null(strstr(err, "gyro_tau_s given twice"));
    /* a UTF-8 byte order mark at the start (a profile written by hand in
     * an editor that saves one) is skipped, as the CSV reader does: the
     * file is not "not a footnav profile" nor ":1: expected 'key = value'";
     * one elsewhere is still text of its line */
    {
        static const char *const first[2] = { "format = footnav-profile 1\n", "# a comment\nformat = footnav-profile 1\n" };
        int v;
        for (v = 0; v < 2; v++) {
            f = fopen(path, "w");
            assert_non_null(f);
            fprintf(f, "\xef\xbb\xbf%srate_hz = 200\n", first[v]);
            for (i = 0; i < 6; i++) {
                static const char *const all[6] = { "accel_noise_mps2_rthz", "accel_tau_s", "accel_bias_sigma_mps2",
                                                     "gyro_noise_rps_rthz", "gyro_tau_s", "gyro_bias_sigma_rps" };
                fprintf(f, "%s = 1e-3 1e-3 1e-3\n", all[i]);
            }
            fclose(f);
            assert_int_equal(hx_profile_read(path, &b, err, sizeof err), 0);
            FNAV_ASSERT_CLOSE(b.rate_hz, 200.0, 0.0, 1e-7);
        }
        f = fopen(path, "w");
        assert_non_null(f);
        fputs("format = footnav-profile 1\n\xef\xbb\xbfrate_hz = 200\n", f);
        fclose(f);
        assert_int_equal(hx_profile_read(path, &b, err, sizeof err), -1);
    }
    /* name too: the last one is not taken without a word; its line is
     * named */
    assert_int_equal(hx_profile_write(path, &a, NULL, err, sizeof err), 0);
    f = fopen(path, "a");
    assert_non_null(f);
    fputs("name = other\n", f);
    fclose(f);
    assert_int_equal(hx_profile_read(path, &b, err, sizeof err), -1);
    assert_non_null(strstr(err, ":11: name given twice"));
    {
        static const double rates[3] = { 1e6, 1.0000001e6, 2e6 };
        int k;
        for (k = 0; k < 3; k++) {
            fnav_profile_t c = a;
            c.rate_hz = (fnav_real_t)rates[k];
            assert_int_equal(hx_profile_write(path, &c, "rate", err, sizeof err), 0);
            assert_int_equal(hx_profile_read(path, &b, err, sizeof err), k == 0 ? 0 : -1);
        }
        assert_non_null(strstr(err, "rate_hz"));
        a.rate_hz = FNAV_R(199.123459);
        assert_int_equal(hx_profile_write(path, &a, "rate", err, sizeof err), 0);
        assert_int_equal(hx_profile_read(path, &b, err, sizeof err), 0);
        assert_true(b.rate_hz == a.rate_hz);
        a.rate_hz = FNAV_R(200.0);
    }
    /* a line of 511 characters is allowed (profile-format.md), also with
     * CR LF; 512 is too long (not 510 as the most) */
    {
        int len;
        for (len = 511; len <= 512; len++) {
            int crlf;
            for (crlf = 0; crlf < 2; crlf++) {
                int k;
                assert_int_equal(hx_profile_write(path, &a, "long line", err, sizeof err), 0);
                f = fopen(path, "a");
                assert_non_null(f);
                fputc('#', f);
                for (k = 1; k < len; k++) {
                    fputc('x', f);
                }
                fputs(crlf ? "\r\n" : "\n", f);
                fclose(f);
                assert_int_equal(hx_profile_read(path, &b, err, sizeof err), len <= 511 ? 0 : -1);
            }
        }
        assert_non_null(strstr(err, "line too long"));
    }
    /* a NUL byte (a binary file given as the profile, e.g. a .bin log)
     * says so; it is not reported as "line too long" */
    f = fopen(path, "wb");
    assert_non_null(f);
    fputs("format = footnav-profile 1\nrate_hz = 200\n", f);
    fputc('\0', f);
    fputs("accel_tau_s = 1 1 1\n", f);
    fclose(f);
    assert_int_equal(hx_profile_read(path, &b, err, sizeof err), -1);
    assert_non_null(strstr(err, ":3: NUL byte"));
    assert_null(strstr(err, "too long"));
    remove(path);
    assert_int_equal(hx_profile_load("/nonexistent/dir/p.profile", &b, err, sizeof err), -1);
    /* a directory opens but cannot be read: a read error, not "not a
     * footnav profile (no 'format' line)" */
    assert_int_equal(hx_profile_read("/tmp/", &b, err, sizeof err), -1);
    assert_non_null(strstr(err, "cannot read profile"));
    assert_null(strstr(err, "not a footnav profile"));
}

/* A value positive and finite as read (double) but not in the working
 * precision (float: 1e39 is infinite, 1e-50 zero) is refused at its line,
 * naming the key, not only "a value is zero, negative or not finite in the
 * float build", without line or key. The double build refuses both too,
 * as outside the key's limits (a file valid for one build is for both). */
static void test_file_out_of_float_range(void **state)
{
    static const char *const lines[4] = { "gyro_tau_s = 100 100 1e39\n", "accel_noise_mps2_rthz = 1e-4 1e-50 1e-4\n",
                                          "rate_hz = 1e-50\n", "rate_hz = 1e-50\r\n" };
    static const char *const keys[4] = { "gyro_tau_s", "accel_noise_mps2_rthz", "rate_hz", "rate_hz" };
    char path[] = "/tmp/fnav_profile_XXXXXX", err[320];
    fnav_profile_t b;
    int fd, k;
    (void)state;
    fd = mkstemp(path);
    assert_true(fd >= 0);
    close(fd);
    for (k = 0; k < 4; k++) {
        FILE *f = fopen(path, "w");
        int i;
        assert_non_null(f);
        fputs("format = footnav-profile 1\n", f);
        if (k < 2) {
            fputs("rate_hz = 200\n", f);
        }
        fputs(lines[k], f);
        for (i = 0; i < 6; i++) {
            static const char *const all[6] = { "accel_noise_mps2_rthz", "accel_tau_s", "accel_bias_sigma_mps2",
                                                 "gyro_noise_rps_rthz", "gyro_tau_s", "gyro_bias_sigma_rps" };
            if (strcmp(all[i], keys[k]) != 0) {
                fprintf(f, "%s = 1e-3 1e-3 1e-3\n", all[i]);
            }
        }
        fclose(f);
        err[0] = '\0';
        assert_int_equal(hx_profile_read(path, &b, err, sizeof err), -1);
        assert_non_null(strstr(err, k < 2 ? ":3:" : ":2:"));
        assert_non_null(strstr(err, keys[k]));
        assert_non_null(strstr(err, FNAV_USE_DOUBLE ? "outside [" : "float"));
    }
    remove(path);
}

/* A profile file of the seven required keys, 1e-3 each and rate_hz 200,
 * with `edit` (one "key = value" line, may be "") replacing its key's line
 * or, a key of no line here, after them; `extra` lines after all. */
static void write_file(const char *path, const char *edit, const char *extra)
{
    static const char *const all[7] = { "rate_hz", "accel_noise_mps2_rthz", "accel_tau_s", "accel_bias_sigma_mps2",
                                        "gyro_noise_rps_rthz", "gyro_tau_s", "gyro_bias_sigma_rps" };
    const size_t ek = strcspn(edit, " =");
    FILE *f = fopen(path, "w");
    int i, used = 0;
    assert_non_null(f);
    fputs("format = footnav-profile 1\n", f);
    for (i = 0; i < 7; i++) {
        if (ek > 0u && strlen(all[i]) == ek && strncmp(all[i], edit, ek) == 0) {
            fprintf(f, "%s\n", edit);
            used = 1;
        } else {
            fprintf(f, "%s = %s\n", all[i], i == 0 ? "200" : "1e-3 1e-3 1e-3");
        }
    }
    if (!used && edit[0] != '\0') {
        fprintf(f, "%s\n", edit);
    }
    fputs(extra, f);
    fclose(f);
}

/* Each value is checked against the strictest of its consumers' limits
 * at its line (hx_profile.h): the filter took gyro_bias_sigma_rps = 1e-25
 * and then refused its configuration naming no key, sim refused
 * accel_noise 1e20 and a correlation time of 0.0005 s or 1e10 s after the
 * load, simgap blamed the log; rate_hz 1e-40 zeroed eq6's bias sd. The
 * limits themselves are taken. */
static void test_value_limits(void **state)
{
    static const struct {
        const char *line, *want;
    } bad[] = {
        { "gyro_bias_sigma_rps = 1e-5 1e-25 1e-5", ":8: gyro_bias_sigma_rps value 2 '1e-25' outside [1.0842e-19, 1000]" },
        { "accel_bias_sigma_mps2 = 1e-3 1e-3 1001", ":5: accel_bias_sigma_mps2 value 3 '1001' outside [" },
        { "accel_noise_mps2_rthz = 1e20 1e-3 1e-3", ":3: accel_noise_mps2_rthz value 1 '1e20' outside [" },
        { "gyro_noise_rps_rthz = 1e-3 1e-3 1e-39", ":6: gyro_noise_rps_rthz value 3 '1e-39' " },
        { "accel_tau_s = 0.0005 1 1", ":4: accel_tau_s value 1 '0.0005' outside [0.001, 1e+09]" },
        { "gyro_tau_s = 1 1e10 1", ":7: gyro_tau_s value 2 '1e10' outside [0.001, 1e+09]" },
        { "rate_hz = 1e-40", ":2: rate_hz '1e-40' outside [1, 1e+06]" },
        { "rate_hz = 0.5", ":2: rate_hz '0.5' outside [1, 1e+06]" },
    };
    static const char *const good[] = {
        "gyro_bias_sigma_rps = 1.0842022e-19 1e3 1e-5", "accel_noise_mps2_rthz = 1.2e-38 1e3 1e-3",
        "accel_tau_s = 0.001 1e9 1", "rate_hz = 1", "rate_hz = 1e6",
    };
    char path[] = "/tmp/fnav_profile_XXXXXX", err[320];
    fnav_profile_t b;
    size_t k;
    int fd;
    (void)state;
    fd = mkstemp(path);
    assert_true(fd >= 0);
    close(fd);
    for (k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        write_file(path, bad[k].line, "");
        err[0] = '\0';
        if (hx_profile_read(path, &b, err, sizeof err) != -1 || strstr(err, bad[k].want) == NULL) {
            fail_msg("'%s': '%s', expected '%s'", bad[k].line, err, bad[k].want);
        }
    }
    for (k = 0; k < sizeof good / sizeof good[0]; k++) {
        write_file(path, good[k], "");
        if (hx_profile_read(path, &b, err, sizeof err) != 0) {
            fail_msg("'%s' refused: %s", good[k], err);
        }
        assert_int_equal(fnav_profile_validate(&b), FNAV_OK);
    }
    remove(path);
}

/* The limits are the simulator's effect ranges where it is the strictest
 * (src/fnav_imuerr.c's catalogue: a change there shows here), the built-in
 * profiles are within them, and hx_profile_check says a value outside
 * (sim --bias-sigma eq6's rescaled sd) with its key. */
static void test_limits_named(void **state)
{
    const fnav_effect_info_t *w = fnav_imuerr_effect_info(FNAV_EFFECT_WHITE);
    const fnav_effect_info_t *a = fnav_imuerr_effect_info(FNAV_EFFECT_AR1);
    fnav_profile_t p;
    char err[320];
    int t;
    (void)state;
    assert_non_null(w);
    assert_non_null(a);
    assert_true(w->params[0].hi == HX_PROFILE_NOISE_MAX && w->params[0].lo <= HX_PROFILE_NOISE_MIN);
    assert_true(a->params[0].lo == HX_PROFILE_TAU_MIN_S && a->params[0].hi == HX_PROFILE_TAU_MAX_S);
    assert_true(a->params[1].hi == HX_PROFILE_SIGMA_MAX && a->params[1].lo <= HX_PROFILE_SIGMA_MIN);
    /* the filter's sd_ok: the smallest sd's square is a normal float */
    assert_true((float)(HX_PROFILE_SIGMA_MIN * HX_PROFILE_SIGMA_MIN) >= FLT_MIN);
    for (t = 0; t < FNAV_PROFILE_COUNT; t++) {
        assert_int_equal(fnav_profile_builtin(&p, (fnav_profile_id_t)t), FNAV_OK);
        assert_int_equal(hx_profile_check(&p, err, sizeof err), 0);
    }
    assert_int_equal(fnav_profile_by_name(&p, "generic-mems"), FNAV_OK);
    assert_int_equal(hx_profile_check(&p, err, sizeof err), 0);
    p.gyro_bias_sigma_rps[1] = FNAV_R(2e3);
    assert_int_equal(hx_profile_check(&p, err, sizeof err), -1);
    assert_non_null(strstr(err, "gyro_bias_sigma_rps value 2 2000 outside [1.0842e-19, 1000]"));
    assert_int_equal(fnav_profile_by_name(&p, "generic-mems"), FNAV_OK);
    p.rate_hz = FNAV_R(0.5);
    assert_int_equal(hx_profile_check(&p, err, sizeof err), -1);
    assert_non_null(strstr(err, "rate_hz 0.5 outside [1, 1e+06]"));
}

/* A profile's numbers are decimal, as the options' are: strtod read 0x10
 * as 16 and 0x1p-3 as 0.125 */
static void test_hex_refused(void **state)
{
    static const struct {
        const char *line, *want;
    } bad[] = {
        { "gyro_tau_s = 0x10 1 1", ":7: gyro_tau_s value 1 '0x10' is not a decimal number" },
        { "accel_tau_s = 1 0x1p-3 1", ":4: accel_tau_s value 2 '0x1p-3' is not a decimal number" },
        { "gyro_tau_s = 1 1 1p3", ":7: gyro_tau_s value 3 '1p3' is not a decimal number" },
        { "rate_hz = 0xC8", ":2: rate_hz '0xC8' is not a decimal number" },
    };
    char path[] = "/tmp/fnav_profile_XXXXXX", err[320];
    fnav_profile_t b;
    size_t k;
    int fd;
    (void)state;
    fd = mkstemp(path);
    assert_true(fd >= 0);
    close(fd);
    for (k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        write_file(path, bad[k].line, "");
        err[0] = '\0';
        if (hx_profile_read(path, &b, err, sizeof err) != -1 || strstr(err, bad[k].want) == NULL) {
            fail_msg("'%s': '%s', expected '%s'", bad[k].line, err, bad[k].want);
        }
    }
    write_file(path, "gyro_tau_s = 16 1.25e+1 +3", "");
    assert_int_equal(hx_profile_read(path, &b, err, sizeof err), 0);
    remove(path);
}

/* A name is printed (sim's effect lines, replay's summary): a control
 * character in it (an ESC, a C1 CSI in UTF-8) is refused at its line, a
 * printable UTF-8 name is taken */
static void test_name_printable(void **state)
{
    static const char *const bad[] = { "name = a\033[2Jb", "name = a\tb", "name = a\302\233b", "name = a\177" };
    char path[] = "/tmp/fnav_profile_XXXXXX", err[320];
    fnav_profile_t b;
    size_t k;
    int fd;
    (void)state;
    fd = mkstemp(path);
    assert_true(fd >= 0);
    close(fd);
    for (k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        write_file(path, bad[k], "");
        err[0] = '\0';
        if (hx_profile_read(path, &b, err, sizeof err) != -1 || strstr(err, ":9: name has a control character") == NULL) {
            fail_msg("case %zu: '%s'", k, err);
        }
    }
    write_file(path, "name = caf\303\251 200 Hz", "");
    assert_int_equal(hx_profile_read(path, &b, err, sizeof err), 0);
    assert_string_equal(b.name, "caf\303\251 200 Hz");
    remove(path);
}

/* A missing key has no line: the message says so, not "FILE: rate_hz
 * missing" under a FILE:LINE promise, and names the line of an unknown key
 * that may spell it */
static void test_missing_key_message(void **state)
{
    char path[] = "/tmp/fnav_profile_XXXXXX", err[320], want[400];
    fnav_profile_t b;
    FILE *f;
    int fd;
    (void)state;
    fd = mkstemp(path);
    assert_true(fd >= 0);
    close(fd);
    f = fopen(path, "w");
    assert_non_null(f);
    fputs("format = footnav-profile 1\n", f);
    fclose(f);
    assert_int_equal(hx_profile_read(path, &b, err, sizeof err), -1);
    snprintf(want, sizeof want, "%s: no line gives rate_hz (a required key)", path);
    assert_string_equal(err, want);
    f = fopen(path, "w");
    assert_non_null(f);
    fputs("format = footnav-profile 1\nrate_hz = 100\naccel_noise_mps2_rthz = 1 1 1\naccel_tau_s = 1 1 1\n"
          "accel_bias_sigma_mps2 = 1 1 1\n# a comment\ngyro_nosie_rps_rthz = 1 1 1\n",
          f);
    fclose(f);
    assert_int_equal(hx_profile_read(path, &b, err, sizeof err), -1);
    snprintf(want, sizeof want,
             "%s: no line gives gyro_noise_rps_rthz (a required key; line 7 has 'gyro_nosie_rps_rthz', unknown: "
             "misspelt?)",
             path);
    assert_string_equal(err, want);
    f = fopen(path, "w");
    assert_non_null(f);
    fputs("fromat = footnav-profile 1\nrate_hz = 100\n", f);
    fclose(f);
    assert_int_equal(hx_profile_read(path, &b, err, sizeof err), -1);
    assert_non_null(strstr(err, "not a footnav profile (no 'format = footnav-profile 1' line; line 1 has 'fromat'"));
    remove(path);
}

/* hx_profile_load of `path` with stderr captured into out[size] */
static int load_captured(const char *path, char *out, size_t size)
{
    fnav_profile_t p;
    char err[320];
    FILE *cap = tmpfile();
    int fd = dup(2), rc;
    size_t n;
    assert_non_null(cap);
    assert_true(fd >= 0);
    fflush(stderr);
    assert_true(dup2(fileno(cap), 2) >= 0);
    rc = hx_profile_load(path, &p, err, sizeof err);
    fflush(stderr);
    assert_true(dup2(fd, 2) >= 0);
    close(fd);
    rewind(cap);
    n = fread(out, 1, size - 1u, cap);
    out[n] = '\0';
    fclose(cap);
    return rc;
}

/* A key neither read nor documented is ignored with a warning at its line
 * (gyro_nosie left the default noise in place without a word), naming
 * the key it most likely meant; the optional keys `allan --profile` writes
 * and x_* keys are not warned about */
static void test_unknown_key_warned(void **state)
{
    static const struct {
        const char *extra, *want;
    } cases[] = {
        { "gyro_nosie = 1 1 1\n", ":9: unknown key 'gyro_nosie' ignored (did you mean gyro_noise_rps_rthz?)" },
        { "Name = t\n", ":9: unknown key 'Name' ignored (did you mean name?)" },
        { "rate = 100\n", ":9: unknown key 'rate' ignored (did you mean rate_hz?)" },
        { "gyro_tua_s = 1 1 1\n", "(did you mean gyro_tau_s?)" },
        { "colour = red\n", ":9: unknown key 'colour' ignored (a key of your own starts with x_)" },
        { "x_colour = red\nident_method = allan-lsq-white-ar1\nident_samples = 10\ngyro_quant_rad = 1 1 1\n"
          "accel_rrw_mps2_rts = 1 1 1\nident_bound_gyro = 1 0 0\nallan_fit_rms_log10_accel = nan nan nan\n"
          "paper_gyro_tau_s = 1 1 1\nident_future = 1\n",
          NULL },
    };
    char path[64], out[2048];
    size_t k;
    (void)state;
    for (k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        /* a file each: the loader warns once per file */
        int fd;
        snprintf(path, sizeof path, "/tmp/fnav_profile_u%zu_XXXXXX", k);
        fd = mkstemp(path);
        assert_true(fd >= 0);
        close(fd);
        write_file(path, "", cases[k].extra);
        assert_int_equal(load_captured(path, out, sizeof out), 0);
        if (cases[k].want != NULL ? strstr(out, cases[k].want) == NULL || strstr(out, path) == NULL
                                  : out[0] != '\0') {
            fail_msg("case %zu: '%s'", k, out);
        }
        unlink(path);
    }
}

/* The units check's advice (hx_profile_implausible): a value flagged in
 * its key's unit names the units it was most likely written in, with the
 * value converted from each. Datasheets give a gyro's bias instability in
 * deg/h, its angle random walk in deg/sqrt(h) and an accelerometer's noise
 * and bias in ug: advice naming only deg/s, deg/s/sqrt(Hz) and mg, once
 * followed (10 deg/h written as 10 -> 0.175 rad/s, 50 ug as 50 -> 0.49
 * m/s^2), would give a value 3600 or 1000 times too large that is no
 * longer flagged. */
static void test_units_advice(void **state)
{
    static const struct {
        int which; /* 0 gyro noise, 1 accel noise, 2 gyro bias, 3 accel bias */
        double v;
        const char *want[2], *not_want;
    } cases[] = {
        { 2, 10.0, { "deg/h", "4.85e-05" }, NULL },            /* generic-mems' 10 deg/h, as written */
        { 0, 0.3, { "deg/sqrt(h)", "8.73e-05" }, NULL },       /* an ARW of 0.3 deg/sqrt(h) */
        { 1, 70.0, { "ug/sqrt(Hz)", "0.000686" }, "in mg" },   /* the ICM-42688-P's 70 ug/sqrt(Hz) */
        { 3, 50.0, { " ug", "0.00049" }, NULL },                /* generic-mems' 50 ug */
        { 0, 0.0396, { "deg/s/sqrt(Hz)", "0.000691" }, NULL }, /* still said: the ADIS16405's deg/s/sqrt(Hz) */
        { 3, 5.0, { "mg", "0.049" }, NULL },                   /* still said: 5 mg */
    };
    size_t k;
    (void)state;
    for (k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        fnav_profile_t p;
        char msg[320];
        fnav_real_t *v;
        assert_int_equal(fnav_profile_by_name(&p, "generic-mems"), FNAV_OK);
        assert_int_equal(hx_profile_implausible(&p, msg, sizeof msg), 0);
        v = cases[k].which == 0   ? p.gyro_noise_rps_rthz
            : cases[k].which == 1 ? p.accel_noise_mps2_rthz
            : cases[k].which == 2 ? p.gyro_bias_sigma_rps
                                  : p.accel_bias_sigma_mps2;
        v[0] = v[1] = v[2] = (fnav_real_t)cases[k].v;
        assert_int_equal(hx_profile_implausible(&p, msg, sizeof msg), 1);
        if (strstr(msg, cases[k].want[0]) == NULL || strstr(msg, cases[k].want[1]) == NULL ||
            (cases[k].not_want != NULL && strstr(msg, cases[k].not_want) != NULL)) {
            fail_msg("case %zu: '%s'", k, msg);
        }
    }
}

/* The built-in generic MEMS profile (the navigation's default) is the file
 * docs/profiles/generic-mems.profile, value for value (the evidence runs
 * of docs/navigation.md load the file), and the default configuration's
 * profile is it. */
static void test_generic_mems(void **state)
{
    fnav_profile_t a, b;
    const fnav_profile_t *d = &fnav_nav_config_default.profile;
    char err[256];
    int i;
    (void)state;
    assert_int_equal(fnav_profile_by_name(&a, "generic-mems"), FNAV_OK);
    assert_int_equal(fnav_profile_validate(&a), FNAV_OK);
    assert_string_equal(a.name, "generic-mems");
    if (access("docs/profiles/generic-mems.profile", R_OK) != 0) {
        fprintf(stderr, "docs/profiles/generic-mems.profile missing (run from the repository root)\n");
        fail();
    }
    assert_int_equal(hx_profile_load("docs/profiles/generic-mems.profile", &b, err, sizeof err), 0);
    assert_true(a.rate_hz == b.rate_hz && a.rate_hz == d->rate_hz);
    for (i = 0; i < 3; i++) {
        assert_true(a.accel_noise_mps2_rthz[i] == b.accel_noise_mps2_rthz[i]);
        assert_true(a.accel_tau_s[i] == b.accel_tau_s[i]);
        assert_true(a.accel_bias_sigma_mps2[i] == b.accel_bias_sigma_mps2[i]);
        assert_true(a.gyro_noise_rps_rthz[i] == b.gyro_noise_rps_rthz[i]);
        assert_true(a.gyro_tau_s[i] == b.gyro_tau_s[i]);
        assert_true(a.gyro_bias_sigma_rps[i] == b.gyro_bias_sigma_rps[i]);
    }
    assert_true(memcmp(&a, d, sizeof a) == 0);
    /* 10 deg/h and 50 ug, as documented */
    FNAV_ASSERT_CLOSE(a.gyro_bias_sigma_rps[0], 10.0 / 3600.0 * 3.14159265358979 / 180.0, 0.0, 0.01);
    FNAV_ASSERT_CLOSE(a.accel_bias_sigma_mps2[0], 50e-6 * 9.80665, 0.0, 0.01);
}

/* Loads `path` with stderr captured: the number of warnings it printed. */
static int load_warnings(const char *path)
{
    fnav_profile_t p;
    char err[320], line[1024];
    FILE *cap = tmpfile();
    int fd = dup(2), n = 0;
    assert_non_null(cap);
    assert_true(fd >= 0);
    fflush(stderr);
    assert_true(dup2(fileno(cap), 2) >= 0);
    assert_int_equal(hx_profile_load(path, &p, err, sizeof err), 0);
    fflush(stderr);
    assert_true(dup2(fd, 2) >= 0);
    close(fd);
    rewind(cap);
    while (fgets(line, sizeof line, cap) != NULL) {
        n += strstr(line, "warning: ") != NULL && strstr(line, "above any IMU's") != NULL;
    }
    fclose(cap);
    return n;
}

/* hx_profile_load warns once per file about a value no IMU has in its
 * key's unit: remembering only the file it warned about last, it would
 * warn about A twice when loading A, B, A. */
static void test_load_warns_once_per_file(void **state)
{
    fnav_profile_t a;
    char pa[] = "/tmp/fnav_profile_a_XXXXXX", pb[] = "/tmp/fnav_profile_b_XXXXXX", err[320];
    int fd;
    (void)state;
    assert_int_equal(fnav_profile_builtin(&a, FNAV_PROFILE_SHIMMER), FNAV_OK);
    a.gyro_noise_rps_rthz[0] = FNAV_R(0.0396); /* deg/s/sqrt(Hz) written as rad/s/sqrt(Hz) */
    fd = mkstemp(pa);
    assert_true(fd >= 0);
    close(fd);
    fd = mkstemp(pb);
    assert_true(fd >= 0);
    close(fd);
    assert_int_equal(hx_profile_write(pa, &a, NULL, err, sizeof err), 0);
    assert_int_equal(hx_profile_write(pb, &a, NULL, err, sizeof err), 0);
    assert_int_equal(load_warnings(pa), 1);
    assert_int_equal(load_warnings(pb), 1);
    assert_int_equal(load_warnings(pa), 0);
    assert_int_equal(load_warnings(pb), 0);
    assert_int_equal(load_warnings(pa), 0);
    {
        /* a file is known by its name as given (A as /tmp/./a is another
         * name); the table full, a further name is warned at each load,
         * and those remembered still are not. Only names warned about
         * fill it: the tests before load no implausible file */
        char name[HX_PROFILE_WARNED_MAX * 2 + sizeof pa + 8];
        int k;
        const char *slash = strrchr(pa, '/');
        assert_non_null(slash);
        for (k = 1; k <= HX_PROFILE_WARNED_MAX - 2; k++) {
            int j, m = snprintf(name, sizeof name, "%.*s", (int)(slash - pa), pa);
            for (j = 0; j < k; j++) {
                m += snprintf(name + m, sizeof name - (size_t)m, "/.");
            }
            snprintf(name + m, sizeof name - (size_t)m, "%s", slash);
            assert_int_equal(load_warnings(name), 1);
            assert_int_equal(load_warnings(name), 0);
        }
        snprintf(name, sizeof name, "/tmp/%s", slash);
        assert_int_equal(load_warnings(name), 1);
        assert_int_equal(load_warnings(name), 1);
        assert_int_equal(load_warnings(pa), 0);
        assert_int_equal(load_warnings(pb), 0);
    }
    unlink(pa);
    unlink(pb);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_builtin_tables),
        cmocka_unit_test(test_builtin_exact),
        cmocka_unit_test(test_ar1_units),
        cmocka_unit_test(test_validate),
        cmocka_unit_test(test_file_round_trip),
        cmocka_unit_test(test_load_warns_once_per_file),
        cmocka_unit_test(test_file_out_of_float_range),
        cmocka_unit_test(test_units_advice),
        cmocka_unit_test(test_generic_mems),
        cmocka_unit_test(test_value_limits),
        cmocka_unit_test(test_limits_named),
        cmocka_unit_test(test_hex_refused),
        cmocka_unit_test(test_name_printable),
        cmocka_unit_test(test_missing_key_message),
        /* after test_load_warns_once_per_file: it counts the files
         * warned about before it */
        cmocka_unit_test(test_unknown_key_warned),
    };
    return cmocka_run_group_tests_name("profile", tests, NULL, NULL);
}
