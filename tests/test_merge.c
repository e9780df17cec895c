/* One sensor's file of `harness merge` (harness/hx_merge.h): the columns
 * and units read from a header, and the value at another file's stamps,
 * against values worked out by hand. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

/* CMocka 1.1.5's assert_float_equal compares floats: doubles here */
#define assert_near(a, b, eps) assert_true(fabs((double)(a) - (double)(b)) <= (eps))

#include "hx_merge.h"

static const char *write_file(const char *text)
{
    static char path[64];
    FILE *f;
    snprintf(path, sizeof path, "/tmp/fnav_test_merge_%d.csv", (int)getpid());
    f = fopen(path, "w");
    assert_non_null(f);
    assert_int_equal(fputs(text, f) >= 0, 1);
    assert_int_equal(fclose(f), 0);
    return path;
}

static int load(hx_tri_t *f, const char *text, hx_tri_kind_t kind, const char *units, char *err, size_t size)
{
    hx_csv_layout_t l;
    const char *path = write_file(text);
    int rc;
    hx_csv_layout_default(&l);
    if (units != NULL) {
        assert_int_equal(hx_csv_units_parse(&l, units, err, size), 0);
    }
    rc = hx_tri_load(f, path, kind, &l, err, size);
    unlink(path);
    return rc;
}

/* MetaWear's accelerometer: the epoch taken, the logger's clock (not
 * elapsed (s), from the file's first sample, nor the date beside it, in
 * MetaBase's dotted spelling), the axes in g to m/s^2; without the epoch,
 * a date (ISO's or MetaBase's) before elapsed (s) */
static void test_metawear_columns(void **state)
{
    hx_tri_t f;
    char err[HX_ERR_SIZE];
    (void)state;
    assert_int_equal(load(&f,
                          "epoch (ms),time (-13:00),elapsed (s),x-axis (g),y-axis (g),z-axis (g)\n"
                          "1700000000000,2023-11-14T22.13.20.000,0.000,0.5,-1,2\n"
                          "1700000000010,2023-11-14T22.13.20.010,0.010,1,0,0\n",
                          HX_TRI_ACC, NULL, err, sizeof err),
                     0);
    assert_int_equal((int)f.n, 2);
    assert_string_equal(f.cols[0], "epoch (ms)");
    assert_string_equal(f.time_unit, "ms");
    assert_int_equal(f.t_from_start, 0);
    assert_string_equal(f.cols[3], "z-axis (g)");
    assert_string_equal(f.unit, "g");
    assert_true(f.t_ns[0] == 1700000000000000000LL && f.t_ns[1] == 1700000000010000000LL);
    assert_near(f.v[0][0], 0.5 * 9.80665, 1e-12);
    assert_near(f.v[0][1], -9.80665, 1e-12);
    assert_near(f.v[0][2], 2.0 * 9.80665, 1e-12);
    hx_tri_free(&f);
    {
        /* without the epoch: an ISO date before elapsed (s) (read as it is
         * written, the zone in the name is not added), and MetaBase's
         * dotted one (before 2026-12-05 not read: elapsed (s) was) */
        static const struct {
            const char *text, *col;
            int from_start;
            int64_t t0_ns;
            const char *time_unit; /* NULL: dates and times, whatever the name says */
        } k[] = {
            { "elapsed (s),time (-13:00),x-axis (g),y-axis (g),z-axis (g)\n"
              "0.000,2023-11-14T09:13:20.000,0.5,-1,2\n0.010,2023-11-14T09:13:20.010,1,0,0\n",
              "time (-13:00)", 0, 1699953200000000000LL, NULL },
            { "time (-13:00),elapsed (s),x-axis (g),y-axis (g),z-axis (g)\n"
              "2023-11-14T22.13.20.000,0.000,0.5,-1,2\n2023-11-14T22.13.20.010,0.010,1,0,0\n",
              "time (-13:00)", 0, 1700000000000000000LL, NULL },
            { "time (-13:00),x-axis (g),y-axis (g),z-axis (g)\n"
              "2023-11-14T22.13.20.000,0.5,-1,2\n2023-11-14T22.13.20.010,1,0,0\n",
              "time (-13:00)", 0, 1700000000000000000LL, NULL },
            { "elapsed (s),x-axis (g),y-axis (g),z-axis (g)\n0.000,0.5,-1,2\n0.010,1,0,0\n", "elapsed (s)", 1, 0,
              "s" },
        };
        size_t i;
        for (i = 0; i < sizeof k / sizeof k[0]; i++) {
            assert_int_equal(load(&f, k[i].text, HX_TRI_ACC, NULL, err, sizeof err), 0);
            assert_string_equal(f.cols[0], k[i].col);
            assert_int_equal(f.t_from_start, k[i].from_start);
            if (k[i].time_unit == NULL) {
                assert_null(f.time_unit);
            } else {
                assert_string_equal(f.time_unit, k[i].time_unit);
            }
            assert_true(f.t_ns[0] == k[i].t0_ns && f.t_ns[1] - f.t_ns[0] == 10000000);
            hx_tri_free(&f);
        }
        /* a dotted time after a blank is no date and time: refused */
        assert_int_equal(load(&f,
                              "time (-13:00),x-axis (g),y-axis (g),z-axis (g)\n"
                              "2023-11-14 22.13.20.000,0.5,-1,2\n2023-11-14 22.13.20.010,1,0,0\n",
                              HX_TRI_ACC, NULL, err, sizeof err),
                         -1);
        assert_non_null(strstr(err, "the time column ('time (-13:00)') holds no number in the first row"));
    }
}

/* bare axes in another order (Sensor Logger's z,y,x), ns since the epoch
 * exact with --units time=ns, a repeated stamp dropped */
static void test_bare_axes_ns(void **state)
{
    hx_tri_t f;
    char err[HX_ERR_SIZE];
    (void)state;
    assert_int_equal(load(&f,
                          "time,seconds_elapsed,z,y,x\n"
                          "1733300000000000001,0,3,2,1\n"
                          "1733300000000000001,0,9,9,9\n"
                          "1733300000002500003,0.0025,6,5,4\n",
                          HX_TRI_GYR, "time=ns", err, sizeof err),
                     0);
    assert_int_equal((int)f.n, 2);
    assert_int_equal((int)f.steps_back, 1);
    assert_true(f.t_ns[0] == INT64_C(1733300000000000001) && f.t_ns[1] == INT64_C(1733300000002500003));
    assert_near(f.v[0][0], 1.0, 0.0);
    assert_near(f.v[0][2], 3.0, 0.0);
    assert_near(f.v[1][1], 5.0, 0.0);
    assert_string_equal(f.unit_from, "default");
    hx_tri_free(&f);
}

/* refusals: swapped files, both sensors, a unitless time that reads as no
 * IMU's rate (with the unit it looks like), axes in two units */
static void test_refusals(void **state)
{
    hx_tri_t f;
    char err[HX_ERR_SIZE];
    (void)state;
    assert_int_equal(load(&f, "t,gyr_x,gyr_y,gyr_z\n0,1,2,3\n", HX_TRI_ACC, NULL, err, sizeof err), -1);
    assert_non_null(strstr(err, "the files swapped?"));
    assert_int_equal(load(&f, "t,ax,ay,az,gx,gy,gz\n0,1,2,3,4,5,6\n", HX_TRI_GYR, NULL, err, sizeof err), -1);
    assert_non_null(strstr(err, "names the accelerometer and the gyroscope"));
    assert_int_equal(load(&f, "time,x,y,z\n0,1,2,3\n10,1,2,3\n20,1,2,3\n", HX_TRI_ACC, NULL, err, sizeof err), -1);
    assert_non_null(strstr(err, "they look like milliseconds, a 100 Hz log (give --units time=ms)"));
    assert_int_equal(load(&f, "t,x [g],y [mg],z [g]\n0,1,2,3\n", HX_TRI_ACC, NULL, err, sizeof err), -1);
    assert_non_null(strstr(err, "the axes name different units"));
    assert_int_equal(load(&f, "t,x (deg/s),y (deg/s),z (deg/s)\n0,1,2,3\n", HX_TRI_ACC, NULL, err, sizeof err), -1);
    assert_non_null(strstr(err, "names deg/s, not the accelerometer's unit"));
}

/* a bad row stops the reading with the rows before it kept (1) */
static void test_bad_row(void **state)
{
    hx_tri_t f;
    char err[HX_ERR_SIZE];
    (void)state;
    assert_int_equal(load(&f, "t;x;y;z\n0,00;1,5;2;3\n0,01;1;2;3\n0,02;x;2;3\n", HX_TRI_ACC, NULL, err, sizeof err), 1);
    assert_int_equal((int)f.n, 2);
    assert_near(f.v[0][0], 1.5, 0.0); /* a decimal comma beside semicolons */
    assert_non_null(strstr(f.error, ":4: column 2 ('x') is not a number: 'x'"));
    hx_tri_free(&f);
}

/* the value at a stamp: its own at its stamps, linear between, none before
 * the first, after the last or across a gap; the cursor starts over for
 * an earlier stamp */
static void test_at(void **state)
{
    int64_t t[4] = { 0, 10, 20, 60 };
    double v[4][3] = { { 0, 1, 2 }, { 10, -1, 2 }, { 20, 3, 2 }, { 60, 3, 2 } }, out[3];
    hx_tri_t f;
    size_t j = 0;
    (void)state;
    memset(&f, 0, sizeof f);
    f.n = 4;
    f.t_ns = t;
    f.v = v;
    assert_int_equal(hx_tri_at(&f, -1, &j, 15, out), HX_TRI_BEFORE);
    assert_int_equal(hx_tri_at(&f, 0, &j, 15, out), HX_TRI_IN);
    assert_near(out[1], 1.0, 0.0);
    assert_int_equal(hx_tri_at(&f, 5, &j, 15, out), HX_TRI_IN);
    assert_near(out[0], 5.0, 1e-12);
    assert_near(out[1], 0.0, 1e-12);
    assert_near(out[2], 2.0, 0.0);
    assert_int_equal(hx_tri_at(&f, 13, &j, 15, out), HX_TRI_IN);
    assert_near(out[1], -1.0 + 0.3 * 4.0, 1e-12);
    assert_int_equal((int)j, 1);
    assert_int_equal(hx_tri_at(&f, 20, &j, 15, out), HX_TRI_IN); /* a stamp of its own: no gap to judge */
    assert_near(out[0], 20.0, 0.0);
    assert_int_equal(hx_tri_at(&f, 21, &j, 15, out), HX_TRI_GAP); /* 20 to 60: 40 > 15 */
    assert_int_equal(hx_tri_at(&f, 21, &j, 40, out), HX_TRI_IN);  /* 40 is no gap at 40 */
    assert_near(out[0], 21.0, 1e-12);
    assert_int_equal(hx_tri_at(&f, 60, &j, 15, out), HX_TRI_IN);
    assert_int_equal(hx_tri_at(&f, 61, &j, 15, out), HX_TRI_AFTER);
    assert_int_equal(hx_tri_at(&f, 2, &j, 15, out), HX_TRI_IN); /* back before the cursor */
    assert_near(out[0], 2.0, 1e-12);
    assert_int_equal((int)j, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_metawear_columns),
        cmocka_unit_test(test_bare_axes_ns),
        cmocka_unit_test(test_refusals),
        cmocka_unit_test(test_bad_row),
        cmocka_unit_test(test_at),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
