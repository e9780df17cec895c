/* Endurance of the float32 UKF: two measurements of what rounding does on
 * long runs (docs/navigation.md, "Long runs in float32: what rounding did and
 * does to the covariance"; docs/frames.md, "Frames"). Not a suite: it prints its table
 * and exits 0 (non-zero only when a step fails). Build it in the float and
 * the double build and compare:
 *
 *   make build/host/tests/endure_ukf && build/host/tests/endure_ukf far
 *   make BUILD=build/double FNAV_DEFS=-DFNAV_USE_DOUBLE=1 build/double/tests/endure_ukf
 *
 * far [STEPS]: a walk-like motion at 200 Hz (stance 0.4 s with a ZUPT per
 *   sample, swing 0.6 s pitching at up to 3 rad/s, turning a little),
 *   STEPS predictions (24,000: two minutes), run from the origin and from
 *   (D, -D, 0) for D from 30 m to 10 km. The flat-earth strapdown does not
 *   read the position, so in exact arithmetic the two runs carry the same
 *   covariance and the same displacement. Printed: the largest difference of
 *   a covariance entry with a position row (in units of the two states'
 *   sds), the ratio of the x position sds, and the difference of the
 *   displacements. The control row starts at the origin with 1e-6 m/s more
 *   velocity, to show how much the filter amplifies a tiny perturbation.
 *
 * stand RATE_HZ HOURS P0_RAD2 [GYRO_NOISE]: a level stand with a ZUPT per
 *   sample from a yaw variance P0; the yaw variance every 10 minutes and
 *   its growth after the first 10 minutes (the bias's transient) against
 *   GYRO_NOISE^2 t, the gyro white noise's random walk (rad/s/sqrt(Hz);
 *   0 or left out: the UKF's default; a negative one, or one the UKF
 *   refuses, is an error), and the share each prediction adds,
 *   GYRO_NOISE^2 dt, in units of the variance's spacing (ulp: nextafter,
 *   in the build's fnav_real_t).
 *
 * budget RATE_HZ HOURS P0_RAD2 [GYRO_NOISE]: the stand above (GYRO_NOISE
 *   as there), then one more
 *   prediction and ZUPT, printing where the yaw variance's share of the
 *   noise goes (docs/navigation.md, "The heading's variance stops
 *   growing"), in ulps of the yaw variance P0 before that prediction:
 *   the factor's U_yy^2 - P0 (P0 -> Cholesky factor), the re-formed
 *   2 Wi (gamma U_yy)^2 - P0 (gamma U_yy as the sigma points' offset, in
 *   fnav_real_t), the two yaw sigma points' differences D from the centre
 *   against +-gamma U_yy (in ulps of gamma U_yy) with Wi (D+^2 + D-^2) - P0
 *   (summed in double), the same offset's round trip through the
 *   attitude parameters alone (fnav_ukf_grp_to_quat, fnav_ukf_quat_to_grp),
 *   and the variance after the prediction and after the ZUPT. It reads the
 *   UKF's scratch as fnav_ukf_predict leaves it (fnav_ukf.c, sigma_att):
 *   U's column n-1 (the yaw's, yaw packed last) still holds the factor, its
 *   columns 4 and 5 the yaw points' differences D (the closed form, the
 *   default). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "footnav/footnav.h"
#include "fnav_testukf.h"

static const double k_g = 9.80665;


static fnav_ukf_t g_a, g_b;

/* one run of "far": 0 on success */
static int far_run(int cf, double dist_m, int control, long steps)
{
    fnav_ukf_config_t c = fnav_ukf_config_default;
    const fnav_ukf_init_sd_t sd = fnav_test_ukf_sd_default();
    const fnav_vec3_t far = fnav_vec3((fnav_real_t)dist_m, (fnav_real_t)-dist_m, FNAV_R(0.0));
    double worst = 0.0, dmax = 0.0, sdr;
    long k;
    int i, j;
    c.closed_form = cf;
    if (fnav_ukf_init(&g_a, &c) != FNAV_OK || fnav_ukf_init(&g_b, &c) != FNAV_OK ||
        fnav_ukf_start(&g_a, fnav_quat_identity(), fnav_vec3_zero(), fnav_vec3_zero(), &sd) != FNAV_OK ||
        fnav_ukf_start(&g_b, fnav_quat_identity(), fnav_vec3_zero(), fnav_vec3_zero(), &sd) != FNAV_OK) {
        return 1;
    }
    if (control) {
        g_b.vel_mps.v[0] = FNAV_R(1.0e-6);
    } else {
        g_b.pos_m = far;
    }
    for (k = 0; k < steps; k++) {
        fnav_vec3_t w, fb;
        const int still = fnav_test_walk_step(k, &w, &fb);
        if (fnav_ukf_predict(&g_a, w, fb, FNAV_R(0.005)) != FNAV_OK ||
            fnav_ukf_predict(&g_b, w, fb, FNAV_R(0.005)) != FNAV_OK) {
            return 2;
        }
        if (still && (fnav_ukf_zupt(&g_a, w) != FNAV_OK || fnav_ukf_zupt(&g_b, w) != FNAV_OK)) {
            return 3;
        }
    }
    for (i = 0; i < 3; i++) {
        const double d = ((double)g_b.pos_m.v[i] - (control ? 0.0 : (double)far.v[i])) - (double)g_a.pos_m.v[i];
        dmax = fabs(d) > dmax ? fabs(d) : dmax;
        for (j = 0; j < FNAV_UKF_NMAX; j++) { /* internal indices: 0-17 */
            const double pa = (double)fnav_ukf_cov(&g_a, FNAV_UKF_P + i, j);
            const double pb = (double)fnav_ukf_cov(&g_b, FNAV_UKF_P + i, j);
            double s;
            if (fnav_ukf_cov(&g_a, j, j) == FNAV_R(0.0)) {
                continue; /* a state switched off: its row is 0 and sd x sd would be 0 (0/0) */
            }
            s = sqrt((double)fnav_ukf_cov(&g_a, FNAV_UKF_P + i, FNAV_UKF_P + i) * (double)fnav_ukf_cov(&g_a, j, j));
            worst = fabs(pb - pa) / s > worst ? fabs(pb - pa) / s : worst;
        }
    }
    sdr = sqrt((double)fnav_ukf_cov(&g_b, FNAV_UKF_P, FNAV_UKF_P) /
               (double)fnav_ukf_cov(&g_a, FNAV_UKF_P, FNAV_UKF_P));
    if (control) {
        printf("%d  control  %8.3g  %6.3f  %8.4f  %6.2f\n", cf, worst, sdr, dmax,
               hypot((double)g_a.pos_m.v[0], (double)g_a.pos_m.v[1]));
    } else {
        printf("%d  %7.0f  %8.3g  %6.3f  %8.4f  %6.2f\n", cf, dist_m, worst, sdr, dmax,
               hypot((double)g_a.pos_m.v[0], (double)g_a.pos_m.v[1]));
    }
    return 0;
}

static int far_table(long steps)
{
    static const double dist_m[7] = { 30.0, 100.0, 300.0, 500.0, 1000.0, 3000.0, 10000.0 };
    int cf, d;
    printf("%s build, %ld steps at 200 Hz\n", sizeof(fnav_real_t) == sizeof(float) ? "float" : "double", steps);
    printf("closed_form  distance_m  cov_diff_sdsd  pos_x_sd_ratio  displacement_diff_m  displacement_m\n");
    for (cf = 1; cf >= 0; cf--) {
        for (d = 0; d < 7; d++) {
            if (far_run(cf, dist_m[d], 0, steps) != 0) {
                return 1;
            }
        }
        if (far_run(cf, 0.0, 1, steps) != 0) {
            return 1;
        }
    }
    return 0;
}

/* the spacing of fnav_real_t at x > 0 (float or double, as built) */
static double real_ulp(double x)
{
    if (sizeof(fnav_real_t) == sizeof(float)) {
        const float f = (float)x;
        return (double)(nextafterf(f, HUGE_VALF) - f);
    }
    return nextafter(x, HUGE_VAL) - x;
}

/* one prediction and ZUPT of a level stand: 0 on success */
static int stand_step(fnav_ukf_t *f, fnav_real_t dt)
{
    const fnav_vec3_t fz = fnav_vec3(FNAV_R(0.0), FNAV_R(0.0), (fnav_real_t)-k_g);
    if (fnav_ukf_predict(f, fnav_vec3_zero(), fz, dt) != FNAV_OK) {
        return 2;
    }
    return fnav_ukf_zupt(f, fnav_vec3_zero()) != FNAV_OK ? 2 : 0;
}

/* The level stand of "stand" and "budget": f initialised with the gyro
 * white noise (0: the UKF's default), started at rest and level with the
 * yaw variance p0. Returns 0, or 1 after saying why on stderr. */
static int stand_setup(fnav_ukf_t *f, fnav_ukf_config_t *c, double p0, double noise)
{
    const fnav_ukf_init_sd_t sd = fnav_test_ukf_sd_default();
    fnav_status_t st;
    int i;
    *c = fnav_ukf_config_default;
    if (!(noise >= 0.0)) {
        fprintf(stderr, "endure_ukf: GYRO_NOISE %g: not a density >= 0 (0: the UKF's default)\n", noise);
        return 1;
    }
    if (noise > 0.0) {
        for (i = 0; i < 3; i++) {
            c->gyro_noise_rps_rthz[i] = (fnav_real_t)noise;
        }
    }
    st = fnav_ukf_init(f, c);
    if (st != FNAV_OK) {
        fprintf(stderr, "endure_ukf: fnav_ukf_init with gyro noise %g rad/s/sqrt(Hz): %s\n",
                (double)c->gyro_noise_rps_rthz[2], fnav_status_str(st));
        return 1;
    }
    st = fnav_ukf_start(f, fnav_quat_identity(), fnav_vec3_zero(), fnav_vec3_zero(), &sd);
    if (st != FNAV_OK) {
        fprintf(stderr, "endure_ukf: fnav_ukf_start: %s\n", fnav_status_str(st));
        return 1;
    }
    fnav_ukf_set_cov(f, FNAV_UKF_A + 2, FNAV_UKF_A + 2, (fnav_real_t)p0);
    return 0;
}

static int stand(double rate_hz, double hours, double p0, double noise)
{
    static fnav_ukf_t f;
    fnav_ukf_config_t c;
    const long n = (long)(rate_hz * hours * 3600.0 + 0.5), every = (long)(rate_hz * 600.0 + 0.5);
    const fnav_real_t dt = (fnav_real_t)(1.0 / rate_hz);
    double p10 = 0.0;
    long k;
    if (stand_setup(&f, &c, p0, noise) != 0) {
        return 1;
    }
    noise = (double)c.gyro_noise_rps_rthz[2];
    printf("%s build, %.0f Hz, yaw variance from %.3g rad^2, gyro noise z %.4g rad/s/sqrt(Hz)\n",
           sizeof(fnav_real_t) == sizeof(float) ? "float" : "double", rate_hz, p0, noise);
    for (k = 1; k <= n; k++) {
        if (stand_step(&f, dt) != 0) {
            return 2;
        }
        if (k % every == 0) {
            const double p = (double)fnav_ukf_cov(&f, FNAV_UKF_A + 2, FNAV_UKF_A + 2), t = (double)k / rate_hz;
            if (k == every) {
                p10 = p;
            }
            printf("%7.0f s  yaw variance %.7e rad^2  growth since 600 s %.4g of noise^2 t  "
                   "share noise^2 dt %.3g ulps of it\n",
                   t, p, t > 600.0 ? (p - p10) / (noise * noise * (t - 600.0)) : 0.0,
                   noise * noise * (double)dt / real_ulp(p));
        }
    }
    return 0;
}

/* one prediction's budget of the yaw variance (the header's "budget"); 0 on success */
static int budget(double rate_hz, double hours, double p0, double noise)
{
    static fnav_ukf_t f;
    fnav_ukf_config_t c;
    const long n = (long)(rate_hz * hours * 3600.0 + 0.5);
    const fnav_real_t dt = (fnav_real_t)(1.0 / rate_hz);
    const fnav_vec3_t fz = fnav_vec3(FNAV_R(0.0), FNAV_R(0.0), (fnav_real_t)-k_g);
    double pa, u, q, uyy, gu, dp, dm, rt;
    fnav_real_t gus;
    long k;
    int y;
    if (stand_setup(&f, &c, p0, noise) != 0) {
        return 1;
    }
    for (k = 1; k <= n; k++) {
        if (stand_step(&f, dt) != 0) {
            return 2;
        }
    }
    y = f.n_act - 1;
    pa = (double)f.P[y][y];
    u = real_ulp(pa);
    q = (double)c.gyro_noise_rps_rthz[2] * (double)c.gyro_noise_rps_rthz[2] * (double)dt;
    if (fnav_ukf_predict(&f, fnav_vec3_zero(), fz, dt) != FNAV_OK) {
        return 2;
    }
    uyy = (double)f.U[y][y];
    gus = f.gamma * f.U[y][y];
    gu = (double)gus;
    dp = (double)f.U[y][4];
    dm = (double)f.U[y][5];
    {
        const fnav_vec3_t a = fnav_ukf_quat_to_grp(fnav_ukf_grp_to_quat(fnav_vec3(FNAV_R(0.0), FNAV_R(0.0), gus)));
        rt = (double)a.v[2];
    }
    printf("%s build, %.0f Hz, after %.3g h: yaw variance P0 %.9e rad^2, its ulp %.3g, share noise^2 dt %.3f ulps\n",
           sizeof(fnav_real_t) == sizeof(float) ? "float" : "double", rate_hz, hours, pa, u, q / u);
    printf("factor U_yy^2 - P0                       %+.3f ulps of P0\n", (uyy * uyy - pa) / u);
    printf("re-formed 2 Wi (gamma U_yy)^2 - P0        %+.3f ulps of P0\n", (2.0 * (double)f.wi * gu * gu - pa) / u);
    printf("yaw points D+ - gamma U_yy, D- + gamma U_yy  %+.3f, %+.3f ulps of gamma U_yy (%.9g rad)\n",
           (dp - gu) / real_ulp(gu), (dm + gu) / real_ulp(gu), gu);
    printf("attitude round trip alone of gamma U_yy   %+.3f ulps of it\n", (rt - gu) / real_ulp(gu));
    printf("Wi (D+^2 + D-^2) - P0                     %+.3f ulps of P0\n",
           ((double)f.wi * (dp * dp + dm * dm) - pa) / u);
    printf("after the prediction (+ noise) - P0       %+.3f ulps of P0 (share %.3f)\n", ((double)f.P[y][y] - pa) / u,
           q / u);
    if (fnav_ukf_zupt(&f, fnav_vec3_zero()) != FNAV_OK) {
        return 2;
    }
    printf("after the ZUPT - P0                       %+.3f ulps of P0\n", ((double)f.P[y][y] - pa) / u);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc >= 2 && strcmp(argv[1], "far") == 0) {
        return far_table(argc >= 3 ? atol(argv[2]) : 24000L);
    }
    if (argc >= 5 && strcmp(argv[1], "stand") == 0) {
        return stand(atof(argv[2]), atof(argv[3]), atof(argv[4]), argc >= 6 ? atof(argv[5]) : 0.0);
    }
    if (argc >= 5 && strcmp(argv[1], "budget") == 0) {
        return budget(atof(argv[2]), atof(argv[3]), atof(argv[4]), argc >= 6 ? atof(argv[5]) : 0.0);
    }
    fprintf(stderr, "usage: endure_ukf far [STEPS] | stand RATE_HZ HOURS P0_RAD2 [GYRO_NOISE_RPS_RTHZ] |\n"
                    "       budget RATE_HZ HOURS P0_RAD2 [GYRO_NOISE_RPS_RTHZ]   (GYRO_NOISE 0: the UKF's default)\n");
    return 2;
}
