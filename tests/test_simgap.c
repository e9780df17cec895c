/* Tests of the sim-to-real gap diagnosis's building blocks
 * (harness/hx_simgap.h, hx_simgap_valid.h): the detectable magnitudes
 * against the catalogue's own table, the exact Allan variance of the
 * models against the estimator, the z-scores' calibration, the lattice
 * statistic, the fits, and end-to-end diagnoses of simulated logs. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "footnav/fnav_profile.h"
#include "hx_simgap.h"
#include "hx_simgap_valid.h"
#include "support/fnav_testdata.h"

#define D2R (3.14159265358979323846 / 180.0)

/* ------------------------------------------------------------ thresholds */

/* The detectable magnitudes of vectors/sim/detectable.csv (computed by
 * vectors/sim/gen_detectable.py with numpy, independently) are reproduced
 * by sgv_detect_threshold() for every profile, sensor and effect. */
static void test_thresholds_match_catalogue(void **state)
{
    /* paper Tables IV-VI, x rows, as gen_detectable.py uses them */
    static const struct {
        const char *name;
        double acc[3], gyro[3]; /* noise, tau in samples at 200 Hz, sigma_bias (deg for gyro) */
    } prof[] = {
        { "navchip", { 7.4e-4, 2000.0, 1.3e-5 }, { 3.3e-3, 1000.0, 8.5e-5 } },
        { "mtx", { 8.9e-4, 2600.0, 7.9e-6 }, { 2.6e-2, 42000.0, 1.8e-5 } },
        { "shimmer", { 6.0e-3, 14600.0, 8.7e-6 }, { 1.9e-2, 4200.0, 1.0e-4 } },
    };
    char path[512], line[256];
    FILE *f;
    int rows = 0;
    (void)state;
    assert_int_equal(fnav_vector_path("sim/detectable.csv", path, sizeof path), 0);
    f = fopen(path, "r");
    assert_non_null(f);
    assert_non_null(fgets(line, sizeof line, f)); /* header */
    while (fgets(line, sizeof line, f) != NULL) {
        char pn[32], sens[16], eff[32], par[16], unit[32];
        double thr, tau, N, T, sig, got, tol = 1e-4;
        const double *row;
        sg_effect_t e;
        int p, magp = 0;
        if (sscanf(line, "%31[^,],%15[^,],%31[^,],%15[^,],%31[^,],%lf,%lf", pn, sens, eff, par, unit, &thr, &tau) != 7) {
            continue;
        }
        for (p = 0; p < 3 && strcmp(prof[p].name, pn) != 0; p++) {
        }
        assert_true(p < 3);
        row = strcmp(sens, "acc") == 0 ? prof[p].acc : prof[p].gyro;
        N = row[0] * (row == prof[p].gyro ? D2R : 1.0);
        T = row[1] / 200.0;
        sig = row[2] * (row == prof[p].gyro ? D2R : 1.0);
        memset(&e, 0, sizeof e);
        if (strcmp(eff, "flicker") == 0) {
            e.id = FNAV_EFFECT_FLICKER;
            e.p[1] = 0.5;
            e.p[2] = 5000.0;
        } else if (strcmp(eff, "rrw") == 0) {
            e.id = FNAV_EFFECT_RRW;
        } else if (strcmp(eff, "ramp") == 0) {
            e.id = FNAV_EFFECT_RAMP;
        } else if (strcmp(eff, "thermal") == 0) {
            e.id = FNAV_EFFECT_THERMAL;
            e.p[1] = 10.0;
            e.p[2] = 600.0;
            tol = 2e-3; /* continuous-time warm-up against the sampled one */
        } else if (strcmp(eff, "quant_shaped") == 0) {
            e.id = FNAV_EFFECT_QUANT;
            e.p[1] = 1.0;
        } else if (strcmp(eff, "vibration_37hz") == 0) {
            e.id = FNAV_EFFECT_VIBRATION;
            e.p[1] = 37.0;
        } else if (strcmp(eff, "jumps_1per600s") == 0) {
            e.id = FNAV_EFFECT_JUMPS;
            e.p[0] = 1.0 / 600.0;
            magp = 1;
        } else {
            fail_msg("unknown effect %s", eff);
        }
        got = sgv_detect_threshold(&e, magp, N, sig, T, 200.0, 3600.0);
        FNAV_ASSERT_CLOSE(got, thr, 0.0, tol);
        rows++;
    }
    fclose(f);
    assert_int_equal(rows, 42);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_thresholds_match_catalogue),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
