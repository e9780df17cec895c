/* Long-run numerical health (make longrun): ten hours of simulated walking
 * at 200 Hz (harness/hx_sim: exact foot motion, the paper's NavChip error
 * model, anti-alias filter) streamed through the float32 navigator. Every
 * 2,000 frames: every output finite, the active covariance symmetric and
 * positive definite (Cholesky in double), the estimate bounded (speed below
 * 10 m/s, distance from the start within twice the truth's farthest
 * distance plus 100 m: heading drifts without a magnetometer, so position
 * error grows, but it may not run away). No divergence reset may occur on
 * valid data. Prints progress and a summary; exits non-zero on any failure.
 *
 *   make longrun [LONGRUN_HOURS=10]
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "footnav/fnav_nav.h"
#include "footnav/fnav_imuerr.h"
#include "fnav_testcov.h"
#include "hx_motion.h"
#include "hx_sim.h"

typedef struct {
    fnav_nav_t nav;
    long frames, checks, failures;
    double max_speed, max_pos, min_pivot, max_truth;
    double t0;
    hx_truth_t last_truth;
    double first_truth_pos[3];
    double truth_return_m;
    fnav_nav_frame_t last;
    long ticks, total_ticks;
} run_t;

static run_t g_run;

static int fail(run_t *r, const char *what, double v)
{
    if (r->failures < 10) {
        fprintf(stderr, "longrun: FAIL at frame %ld: %s (%g)\n", r->frames, what, v);
    }
    r->failures++;
    return 0;
}


static void check_frame(run_t *r, const fnav_nav_frame_t *f)
{
    int i;
    double v2 = 0.0, p2 = 0.0;
    for (i = 0; i < 3; i++) {
        if (!fnav_isfinite(f->pos_m[i]) || !fnav_isfinite(f->vel_mps[i]) || !fnav_isfinite(f->euler_rad[i])) {
            fail(r, "non-finite output", (double)i);
        }
        v2 += (double)f->vel_mps[i] * (double)f->vel_mps[i];
        p2 += (double)f->pos_m[i] * (double)f->pos_m[i];
    }
    r->max_speed = fmax(r->max_speed, sqrt(v2));
    r->max_pos = fmax(r->max_pos, sqrt(p2));
    if (sqrt(v2) > 10.0) {
        fail(r, "speed above 10 m/s", sqrt(v2));
    }
    if (sqrt(p2) > 2.0 * r->max_truth + 100.0) {
        fail(r, "position runs away (beyond twice the truth's extent + 100 m)", sqrt(p2));
    }
}

static int sink(void *ctx, const hx_sim_tick_t *tick)
{
    run_t *r = (run_t *)ctx;
    fnav_nav_frame_t f;
    unsigned c;
    if (r->ticks == 0) {
        memcpy(r->first_truth_pos, tick->truth.pos_m, sizeof r->first_truth_pos);
    }
    r->ticks++;
    r->last_truth = tick->truth;
    {
        double d0 = tick->truth.pos_m[0] - r->first_truth_pos[0], d1 = tick->truth.pos_m[1] - r->first_truth_pos[1],
               d2 = tick->truth.pos_m[2] - r->first_truth_pos[2];
        r->max_truth = fmax(r->max_truth, sqrt(d0 * d0 + d1 * d1 + d2 * d2));
    }
    for (c = 0; c < tick->count; c++) {
        if (fnav_nav_push(&r->nav, &tick->meas) != FNAV_OK) {
            continue; /* rejected samples are counted by the navigator */
        }
        while (fnav_nav_pop(&r->nav, &f) == FNAV_OK) {
            r->frames++;
            check_frame(r, &f);
            r->last = f;
            if (r->frames % 2000 == 0 && r->nav.ukf.started) {
                double asym, piv = fnav_test_cov_spd(&r->nav.ukf, &asym);
                r->checks++;
                if (!(asym <= 1e-6)) {
                    fail(r, "covariance not finite or not symmetric", asym);
                }
                if (!(piv > 0.0)) {
                    fail(r, "covariance not positive definite", piv);
                }
                r->min_pivot = fmin(r->min_pivot, piv);
            }
        }
    }
    if (r->ticks % (r->total_ticks / 20 + 1) == 0) {
        fprintf(stderr, "longrun: %3.0f %% (%.1f h simulated)\n", 100.0 * (double)r->ticks / (double)r->total_ticks,
                tick->t_s / 3600.0);
    }
    return 0;
}

int main(int argc, char **argv)
{
    double hours = (argc > 1) ? atof(argv[1]) : 10.0;
    hx_motion_config_t mc = hx_motion_config_default();
    hx_sim_config_t sc;
    hx_motion_t *motion;
    fnav_profile_t prof;
    char err[320];
    run_t *r = &g_run;
    fnav_nav_config_t nc = fnav_nav_config_default;
    double dx, dy, dz;
    if (!(hours > 0.0 && hours <= 48.0)) {
        fprintf(stderr, "usage: longrun_nav [HOURS in (0, 48]]\n");
        return 2;
    }
    motion = hx_motion_create(&mc, "loop", hours * 3600.0, err, sizeof err);
    if (motion == NULL) {
        fprintf(stderr, "longrun: %s\n", err);
        return 2;
    }
    if (fnav_profile_by_name(&prof, "navchip") != FNAV_OK) {
        return 2;
    }
    memset(&sc, 0, sizeof sc);
    sc.motion = motion;
    if (fnav_imuerr_config_from_profile(&sc.err, &prof) != FNAV_OK) {
        fprintf(stderr, "longrun: error model from the profile failed\n");
        return 2;
    }
    sc.err.rate_hz = FNAV_R(200.0);
    sc.err.oversample = 10u; /* internal 2 kHz before the anti-alias filter, as harness sim */
    sc.err.seed = 20261122u;
    sc.duration_s = hx_motion_duration(motion);
    sc.decim = HX_DECIM_FIR;
    memset(r, 0, sizeof *r);
    r->min_pivot = INFINITY;
    r->total_ticks = (long)hx_sim_ticks(&sc);
    if (fnav_nav_init(&r->nav, &nc) != FNAV_OK) {
        fprintf(stderr, "longrun: fnav_nav_init failed\n");
        return 2;
    }
    fprintf(stderr, "longrun: %.1f h of a closed-loop walk at 200 Hz (%ld samples, %d strides), NavChip errors, "
                    "float32 navigator\n",
            sc.duration_s / 3600.0, r->total_ticks, hx_motion_strides(motion));
    if (hx_sim_run(&sc, sink, r, err, sizeof err) < 0) {
        fprintf(stderr, "longrun: %s\n", err);
        return 2;
    }
    fnav_nav_finish(&r->nav);
    {
        fnav_nav_frame_t f;
        while (fnav_nav_pop(&r->nav, &f) == FNAV_OK) {
            r->frames++;
            check_frame(r, &f);
            r->last = f;
        }
    }
    if (r->nav.stats.resets != 0u) {
        fail(r, "divergence reset on valid data", (double)r->nav.stats.resets);
    }
    if (r->checks == 0) {
        fail(r, "no covariance check ran", 0.0);
    }
    /* the loop ends where it began: the end position is the return-to-start
     * error, whatever the heading of the frame (the truth's end is the
     * truth's start to within the motion's rounding) */
    dx = (double)r->last.pos_m[0] - (r->last_truth.pos_m[0] - r->first_truth_pos[0]);
    dy = (double)r->last.pos_m[1] - (r->last_truth.pos_m[1] - r->first_truth_pos[1]);
    dz = (double)r->last.pos_m[2] - (r->last_truth.pos_m[2] - r->first_truth_pos[2]);
    printf("longrun: %.1f h, %ld frames, %ld covariance checks (symmetric positive definite; smallest relative "
           "Cholesky pivot %.3g), max speed %.2f m/s, max |position| %.1f m (truth %.1f m), final error %.2f m (%.2f m vertical), "
           "covariance guard %u, Cholesky jitter %u / resets %u, divergence resets %u: %s\n"
           "longrun: (final error = end position minus the truth's displacement, the loop's return-to-start error)\n",
           sc.duration_s / 3600.0, r->frames, r->checks, r->min_pivot, r->max_speed, r->max_pos, r->max_truth,
           sqrt(dx * dx + dy * dy + dz * dz), fabs(dz), r->nav.stats.cov_guard, r->nav.stats.chol_jitter,
           r->nav.stats.chol_reset, r->nav.stats.resets, r->failures == 0 ? "ok" : "FAILED");
    hx_motion_free(motion);
    return r->failures == 0 ? 0 : 1;
}
