/* Experiment (not a suite, not built by make): the float spread of test_ukf
 * test_closed_form_equivalence's settling case (closed_vs_full: settling on,
 * AR(1), gyro bias sd 1e-3 rad/s), started from 21 accelerometer biases
 * scaled by 1 + k 1e-4, k = 0..20, against that test's bound 2e3 EPS + e.
 * docs/navigation.md, "Long runs in float32", "The heading's variance stops
 * growing", quotes its output, on the current code and with
 * scripts/experiments/ukf_yaw_carry.patch applied:
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
/* closed_vs_full of test_ukf (settling on, AR(1), 1e-3 bias sd), with the start's accelerometer bias x scaled by
 * (1 + k 1e-4): the spread of the float difference */
static double run(double pert)
{
    fnav_ukf_config_t c = fnav_ukf_config_default;
    fnav_ukf_init_sd_t sd = fnav_test_ukf_sd_default();
    fnav_quat_t q0 = fnav_quat_from_euler(FNAV_R(0.2), FNAV_R(-0.3), FNAV_R(0.5));
    fnav_vec3_t ba = fnav_vec3((fnav_real_t)(0.01 * (1.0 + pert)), FNAV_R(0.0), FNAV_R(0.0));
    int k, i, j, r = 0;
    double dc = 0.0;
    c.lever = 1; c.bias_model = FNAV_BIAS_AR1; c.settle = 1;
    for (i = 0; i < 3; i++) sd.gyro_bias_rps[i] = FNAV_R(1e-3);
    r |= fnav_ukf_init(&a, &c);
    c.closed_form = 0;
    r |= fnav_ukf_init(&b, &c);
    r |= fnav_ukf_start(&a, q0, fnav_vec3(FNAV_R(0.001), FNAV_R(0.0), FNAV_R(-0.002)), ba, &sd);
    r |= fnav_ukf_start(&b, q0, fnav_vec3(FNAV_R(0.001), FNAV_R(0.0), FNAV_R(-0.002)), ba, &sd);
    for (k = 0; k < 200; k++) {
        fnav_real_t t = (fnav_real_t)k * FNAV_R(0.005);
        fnav_vec3_t w = fnav_vec3(FNAV_R(2.0) * fnav_sin(FNAV_R(3.0) * t), FNAV_R(1.0), FNAV_R(-0.5) * fnav_cos(t));
        fnav_vec3_t f = fnav_vec3(FNAV_R(3.0) * fnav_cos(FNAV_R(5.0) * t), FNAV_R(1.0), FNAV_R(-9.0));
        r |= fnav_ukf_predict(&a, w, f, FNAV_R(0.005));
        r |= fnav_ukf_predict(&b, w, f, FNAV_R(0.005));
        if (k % 50 == 49) { r |= fnav_ukf_zupt(&a, w); r |= fnav_ukf_zupt(&b, w); }
        if (k % 50 == 39) { r |= fnav_ukf_settle_start(&a); r |= fnav_ukf_settle_start(&b); }
    }
    if (r) { printf("status\n"); exit(1); }
    for (i = 0; i < 18; i++) for (j = 0; j < 18; j++) {
        double sc = sqrt(fabs((double)fnav_ukf_cov(&b, i, i) * (double)fnav_ukf_cov(&b, j, j))) + 1e-30;
        double d = fabs((double)fnav_ukf_cov(&a, i, j) - (double)fnav_ukf_cov(&b, i, j)) / sc;
        dc = d > dc ? d : dc;
    }
    return dc;
}
int main(void)
{
    int k, over = 0;
    double mx = 0.0, sum = 0.0;
    for (k = 0; k < 21; k++) {
        double d = run(1e-4 * k);
        printf("%.3g ", d);
        mx = d > mx ? d : mx; sum += d; over += d > 2e3 * 1.2e-7 + 4.24264 * 1e-3 * 0.005;
    }
    printf("\nmean %.3g max %.3g, over the bound %d of 21\n", sum / 21.0, mx, over);
    return 0;
}
