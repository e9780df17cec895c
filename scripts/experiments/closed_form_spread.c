/* Experiment (not a suite, not built by make): the figures behind the float
 * bound of test_ukf test_closed_form_equivalence's settling case (the
 * comment there; docs/navigation.md, "Long runs in float32", "The heading's
 * variance stops growing (corrected)"). The test's pair (settling on, AR(1),
 * gyro bias sd 1e-3 rad/s, lever), 200 steps with a ZUPT every 50: each path
 * against itself with filter b's accelerometer bias x moved by k 1e-5
 * (k = 1..40) gives the RMS s_ff (full sigma points) and s_cc (closed form)
 * and s = sqrt((s_ff^2 + s_cc^2) / 2), as the test computes it; then the
 * closed form against the full path, b moved the same way, in units of s
 * (mean, sd, max), and from the same start. Build and run (float build):
 *
 *   make build/host/libfootnav.a
 *   cc -std=c99 -O2 -Iinclude -Itests/support -o /tmp/cf_spread scripts/experiments/closed_form_spread.c \
 *       tests/support/fnav_testukf.c build/host/libfootnav.a -lm && /tmp/cf_spread
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "footnav/footnav.h"
#include "fnav_testukf.h"
static fnav_ukf_t a, b;

/* the core's assert hook (the harness's port is not linked here) */
FNAV_NORETURN void fnav_port_assert_failed(const char *file, int line, const char *expr)
{
    fprintf(stderr, "assertion failed: %s:%d: %s\n", file, line, expr);
    abort();
}

/* test_ukf's run_pair for the settling case: the largest covariance difference relative to sqrt(P_ii P_jj) */
static double run(int a_closed, int b_closed, double rel_b)
{
    fnav_ukf_config_t c = fnav_ukf_config_default;
    fnav_ukf_init_sd_t sd = fnav_test_ukf_sd_default();
    fnav_quat_t q0 = fnav_quat_from_euler(FNAV_R(0.2), FNAV_R(-0.3), FNAV_R(0.5));
    fnav_vec3_t bg = fnav_vec3(FNAV_R(0.001), FNAV_R(0.0), FNAV_R(-0.002));
    int k, i, j, r = 0;
    double dc = 0.0;
    c.lever = 1;
    c.bias_model = FNAV_BIAS_AR1;
    c.settle = 1;
    for (i = 0; i < 3; i++) {
        sd.gyro_bias_rps[i] = FNAV_R(1e-3);
    }
    c.closed_form = a_closed;
    r |= fnav_ukf_init(&a, &c);
    c.closed_form = b_closed;
    r |= fnav_ukf_init(&b, &c);
    r |= fnav_ukf_start(&a, q0, bg, fnav_vec3(FNAV_R(0.01), FNAV_R(0.0), FNAV_R(0.0)), &sd);
    r |= fnav_ukf_start(&b, q0, bg, fnav_vec3((fnav_real_t)(0.01 * (1.0 + rel_b)), FNAV_R(0.0), FNAV_R(0.0)), &sd);
    for (k = 0; k < 200; k++) {
        fnav_real_t t = (fnav_real_t)k * FNAV_R(0.005);
        fnav_vec3_t w = fnav_vec3(FNAV_R(2.0) * fnav_sin(FNAV_R(3.0) * t), FNAV_R(1.0), FNAV_R(-0.5) * fnav_cos(t));
        fnav_vec3_t f = fnav_vec3(FNAV_R(3.0) * fnav_cos(FNAV_R(5.0) * t), FNAV_R(1.0), FNAV_R(-9.0));
        r |= fnav_ukf_predict(&a, w, f, FNAV_R(0.005));
        r |= fnav_ukf_predict(&b, w, f, FNAV_R(0.005));
        if (k % 50 == 49) {
            r |= fnav_ukf_zupt(&a, w);
            r |= fnav_ukf_zupt(&b, w);
        }
        if (k % 50 == 39) {
            r |= fnav_ukf_settle_start(&a);
            r |= fnav_ukf_settle_start(&b);
        }
    }
    if (r) {
        printf("a filter call failed\n");
        exit(1);
    }
    for (i = 0; i < FNAV_UKF_NMAX; i++) {
        for (j = 0; j < FNAV_UKF_NMAX; j++) {
            double sc = sqrt(fabs((double)fnav_ukf_cov(&b, i, i) * (double)fnav_ukf_cov(&b, j, j))) + 1e-30;
            double d = fabs((double)fnav_ukf_cov(&a, i, j) - (double)fnav_ukf_cov(&b, i, j)) / sc;
            dc = d > dc ? d : dc;
        }
    }
    return dc;
}

int main(void)
{
    const int kn = 40;
    const double e = sqrt(18.0) * 1e-3 * 0.005; /* the test's e_big */
    double sff = 0.0, scc = 0.0, s, sum = 0.0, sum2 = 0.0, mx = 0.0, d0, mean;
    int k;
    for (k = 1; k <= kn; k++) {
        double d = run(0, 0, 1e-5 * k);
        sff += d * d;
        d = run(1, 1, 1e-5 * k);
        scc += d * d;
    }
    s = sqrt((sff + scc) / (2.0 * kn));
    for (k = 1; k <= kn; k++) {
        double d = run(1, 0, 1e-5 * k) / s;
        sum += d;
        sum2 += d * d;
        mx = d > mx ? d : mx;
    }
    mean = sum / kn;
    d0 = run(1, 0, 0.0);
    printf("s_ff %.3g s_cc %.3g s %.3g\n", sqrt(sff / kn), sqrt(scc / kn), s);
    printf("closed form vs full, b moved by k 1e-5 (k = 1..%d): mean %.3g s, sd %.3g s, max %.3g s\n", kn, mean,
           sqrt((sum2 - kn * mean * mean) / (kn - 1)), mx);
    printf("closed form vs full, same start: %.3g = %.3g s (e + %.3g s; the test's bound e + 5 s = %.3g)\n", d0, d0 / s,
           (d0 - e) / s, e + 5.0 * s);
    return 0;
}
