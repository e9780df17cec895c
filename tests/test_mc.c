/* Tests of the Monte Carlo engine (harness/hx_mc.h) with oracle navigators
 * whose errors are drawn from the covariance they report: the average NEES
 * must sit in its chi-square band, the RMS error must match the predicted
 * standard deviation; an over-confident oracle (covariance / 4) must be
 * flagged. Also the frame convention (origin and x axis where the sensor is
 * at the alignment)
 * and the pairing of estimates with the truth through the sample counter. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "hx_mc.h"
#include "support/fnav_testdata.h"

#define MAX_RUNS 64
#define MAX_SECONDS 64

typedef struct {
    const hx_motion_t *m;
    double scale;        /* reported covariance = true covariance * scale */
    uint32_t nan_seq;    /* a NaN in P of the estimate of this sample (0: none) */
    fnav_rng_t rng;
    double align_s;      /* no valid estimate before this time, s */
    double yaw0, p0[3];  /* the frame: heading and position at the alignment */
    int aligned;
    hx_mc_est_t pending[4];
    int npending;
    int started;
    double bias_true[6]; /* the simulated bias (a constant offset effect) */
    int negate_q;        /* report -q_est: the same attitude */
    double frame_yaw;    /* report in a frame turned by this yaw about n's z, rad (0: the truth's heading) */
    /* what the oracle reported, per run (the engine's figures are checked
     * against these): run, rate, every valid estimate's horizontal error
     * squared, the last one's errors, the errors at whole seconds (the ends
     * of 1 s bins) and one measured sample */
    int run;
    double rate;
    double sum_h2[MAX_RUNS], last_h[MAX_RUNS], last_v[MAX_RUNS], last_pred_h[MAX_RUNS];
    long nest[MAX_RUNS];
    double at_s_h2[MAX_RUNS][MAX_SECONDS], at_s_v2[MAX_RUNS][MAX_SECONDS];
    double probe_ax[MAX_RUNS];
} oracle_t;

static void qmul(const double a[4], const double b[4], double r[4])
{
    r[0] = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
    r[1] = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
    r[2] = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
    r[3] = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
}

static int o_start(void *ctx, double rate, int run)
{
    oracle_t *o = (oracle_t *)ctx;
    o->run = run;
    o->rate = rate;
    if (run < MAX_RUNS) {
        o->sum_h2[run] = 0.0;
        o->nest[run] = 0;
    }
    /* the same error draws for both oracles of a run: paired variants */
    fnav_rng_seed(&o->rng, 1000u + (uint32_t)run, 7u);
    o->aligned = 0;
    o->npending = 0;
    o->started = 1;
    return 0;
}

/* Lower-triangular factor A of the true covariance at time t (position
 * sd grows with time and is correlated between x and y). */
static void factor(double t, double A[15][15])
{
    double sp = 0.02 + 0.01 * t;
    int i;
    memset(A, 0, sizeof(double) * 225);
    for (i = 0; i < 3; i++) {
        A[i][i] = 0.01;       /* attitude, rad */
        A[3 + i][3 + i] = 0.05; /* velocity */
        A[6 + i][6 + i] = sp;
        A[9 + i][9 + i] = 1e-3;
        A[12 + i][12 + i] = 2e-2;
    }
    A[7][6] = 0.8 * sp; /* correlated horizontal position */
    /* Attitude errors drive velocity and position errors, as in a filter
     * (a tilt makes a velocity error, a heading error a cross-track one):
     * cross-covariances the joint ("all") NEES reads with their sign. */
    for (i = 0; i < 3; i++) {
        A[3 + i][i] = 0.04;
    }
    A[6][2] = 0.5 * sp;
    A[7][2] = -0.5 * sp;
}

static int o_push(void *ctx, const fnav_sample_t *s)
{
    oracle_t *o = (oracle_t *)ctx;
    hx_mc_est_t *e;
    hx_truth_t t;
    double A[15][15], z[15], d[15], ang, dq[4], qf[4], qz[4], cz, sz;
    int i, j, first;
    if (o->npending >= 4) {
        return -1;
    }
    e = &o->pending[o->npending++];
    memset(e, 0, sizeof *e);
    e->seq = s->seq;
    if (s->seq == 10u && o->run < MAX_RUNS) {
        o->probe_ax[o->run] = (double)s->accel_mps2[0];
    }
    hx_motion_eval(o->m, (double)s->t_ns * 1e-9, &t);
    if (t.t_s < o->align_s) {
        e->valid = 0; /* not aligned yet */
        return 0;
    }
    e->valid = 1;
    first = !o->aligned;
    if (!o->aligned) {
        /* as the filter: origin where the sensor is at the alignment, x
         * along its heading then */
        o->yaw0 = t.euler_rad[2];
        memcpy(o->p0, t.pos_m, sizeof o->p0);
        o->aligned = 1;
    }
    factor(t.t_s, A);
    for (i = 0; i < 15; i++) {
        z[i] = (double)fnav_rng_gauss(&o->rng);
    }
    for (i = 0; i < 15; i++) {
        d[i] = 0.0;
        for (j = 0; j < 15; j++) {
            d[i] += A[i][j] * z[j];
        }
    }
    if (first) {
        /* the first estimate's attitude is the frame's own, as the
         * filter's alignment defines it (yaw 0, sd 1 mrad): hx_mc anchors
         * the frame to it (the yaw of q_est (x) q_true^-1), which a drawn
         * yaw error would turn, and a drawn tilt error too, at second order
         * (zeroing the yaw alone fails test_engine_figures_exact). A first
         * estimate whose yaw is not the truth's is tested with the whole
         * output turned (frame_yaw, test_frame_from_first_estimate) */
        d[0] = d[1] = d[2] = 0.0;
    }
    for (i = 0; i < 15; i++) {
        for (j = 0; j < 15; j++) {
            int k;
            double v = 0.0;
            for (k = 0; k < 15; k++) {
                v += A[i][k] * A[j][k];
            }
            e->P[i][j] = v * o->scale;
        }
    }
    if (o->nan_seq != 0u && s->seq == o->nan_seq) {
        e->P[6][6] = (double)NAN;
    }
    /* The estimate is the truth in the filter frame (rotated by -yaw0) less
     * the error d, drawn as the filter's sigma points perturb its state:
     * truth = exp(d_att) (x) q_est, v_true = v_est + d_v, ... (fnav_ukf.c,
     * apply_att). One sign for every state, so the cross-covariances of P
     * hold; hx_mc must recover them as such. */
    cz = cos(o->yaw0);
    sz = sin(o->yaw0);
    qz[0] = cos(0.5 * o->yaw0);
    qz[1] = qz[2] = 0.0;
    qz[3] = -sin(0.5 * o->yaw0);
    qmul(qz, t.q_nb, qf);
    e->pos_m[0] = cz * (t.pos_m[0] - o->p0[0]) + sz * (t.pos_m[1] - o->p0[1]) - d[6];
    e->pos_m[1] = -sz * (t.pos_m[0] - o->p0[0]) + cz * (t.pos_m[1] - o->p0[1]) - d[7];
    e->pos_m[2] = t.pos_m[2] - o->p0[2] - d[8];
    e->vel_mps[0] = cz * t.vel_mps[0] + sz * t.vel_mps[1] - d[3];
    e->vel_mps[1] = -sz * t.vel_mps[0] + cz * t.vel_mps[1] - d[4];
    e->vel_mps[2] = t.vel_mps[2] - d[5];
    for (i = 0; i < 3; i++) {
        e->gyro_bias_rps[i] = o->bias_true[3 + i] - d[9 + i];
        e->accel_bias_mps2[i] = o->bias_true[i] - d[12 + i];
    }
    /* q_est = exp(-d_att) (x) q_true */
    ang = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    dq[0] = cos(0.5 * ang);
    for (i = 0; i < 3; i++) {
        dq[1 + i] = -(ang > 0.0 ? sin(0.5 * ang) / ang : 0.5) * d[i];
    }
    qmul(dq, qf, e->q_nb);
    if (o->frame_yaw != 0.0) {
        /* a navigator whose alignment put yaw 0 elsewhere: the whole
         * output turned by frame_yaw (its first estimate's yaw included) */
        const double c = cos(o->frame_yaw), sn = sin(o->frame_yaw), x = e->pos_m[0], vx = e->vel_mps[0];
        double qt[4], q[4];
        e->pos_m[0] = c * x - sn * e->pos_m[1];
        e->pos_m[1] = sn * x + c * e->pos_m[1];
        e->vel_mps[0] = c * vx - sn * e->vel_mps[1];
        e->vel_mps[1] = sn * vx + c * e->vel_mps[1];
        qt[0] = cos(0.5 * o->frame_yaw);
        qt[1] = qt[2] = 0.0;
        qt[3] = sin(0.5 * o->frame_yaw);
        memcpy(q, e->q_nb, sizeof q);
        qmul(qt, q, e->q_nb);
    }
    if (o->negate_q) {
        for (i = 0; i < 4; i++) {
            e->q_nb[i] = -e->q_nb[i];
        }
    }
    if (o->run < MAX_RUNS && !(o->nan_seq != 0u && s->seq == o->nan_seq)) {
        /* estimate minus truth is -d: horizontal d6, d7, vertical d8 */
        double h2 = d[6] * d[6] + d[7] * d[7], k = t.t_s;
        o->sum_h2[o->run] += h2;
        o->nest[o->run]++;
        o->last_h[o->run] = sqrt(h2);
        o->last_v[o->run] = fabs(d[8]);
        o->last_pred_h[o->run] = sqrt(e->P[6][6] + e->P[7][7]);
        if (k >= 1.0 && fabs(k - floor(k + 0.5)) < 1e-9 && floor(k + 0.5) <= MAX_SECONDS) {
            int b = (int)floor(k + 0.5) - 1; /* the 1 s bin that ends at t */
            o->at_s_h2[o->run][b] = h2;
            o->at_s_v2[o->run][b] = d[8] * d[8];
        }
    }
    return 0;
}

static int o_pop(void *ctx, hx_mc_est_t *est)
{
    oracle_t *o = (oracle_t *)ctx;
    if (o->npending == 0) {
        return 0;
    }
    *est = o->pending[0];
    memmove(&o->pending[0], &o->pending[1], (size_t)(o->npending - 1) * sizeof o->pending[0]);
    o->npending--;
    return 1;
}

static void o_finish(void *ctx)
{
    (void)ctx;
}

/* The runs' common simulation: the motion at 50 Hz, point samples, seed 5,
 * 1 s bins. */
static void mc_config_50hz(hx_mc_config_t *cfg, hx_motion_t *m, int runs)
{
    memset(cfg, 0, sizeof *cfg);
    cfg->sim.motion = m;
    cfg->sim.err = fnav_imuerr_config_default;
    cfg->sim.err.rate_hz = (fnav_real_t)50.0;
    cfg->sim.err.oversample = 1u;
    cfg->sim.err.seed = 5u;
    cfg->sim.decim = HX_DECIM_FIR;
    cfg->runs = runs;
    cfg->bin_s = 1.0;
}

static hx_mc_nav_t make_nav(const char *name, oracle_t *o)
{
    hx_mc_nav_t n;
    n.name = name;
    n.ctx = o;
    n.start = o_start;
    n.push = o_push;
    n.pop = o_pop;
    n.finish = o_finish;
    return n;
}

static void run_oracles_on(const char *script, double dist_m, double align_s, double mount_yaw_deg,
                           const char *effect)
{
    char err[256];
    hx_motion_config_t mc = hx_motion_config_default();
    hx_motion_t *m;
    hx_mc_config_t cfg;
    hx_mc_result_t res;
    oracle_t good, over;
    hx_mc_nav_t navs[2];
    double lo, hi;
    int b, in_good = 0, in_over = 0, nb, nb_aligned = 0, g;
    mc.mount_deg[2] = mount_yaw_deg;
    m = hx_motion_create(&mc, script, 0.0, err, sizeof err);
    assert_non_null(m);
    memset(&good, 0, sizeof good);
    memset(&over, 0, sizeof over);
    good.m = over.m = m;
    good.scale = 1.0;
    over.scale = 0.25;
    good.align_s = over.align_s = align_s;
    navs[0] = make_nav("consistent", &good);
    navs[1] = make_nav("overconfident", &over);
    mc_config_50hz(&cfg, m, 50);
    if (effect != NULL) {
        int c;
        assert_int_equal(hx_effect_parse(&cfg.sim.err, effect, err, sizeof err), 0);
        for (c = 0; c < 6; c++) {
            if (cfg.sim.err.mask[FNAV_EFFECT_OFFSET] & (1u << c)) {
                /* the oracles estimate the simulated bias */
                good.bias_true[c] = over.bias_true[c] = (double)cfg.sim.err.offset.value[c];
            }
        }
    }
    assert_int_equal(hx_mc_run(&cfg, navs, 2, &res, NULL, NULL, err, sizeof err), 0);
    assert_int_equal(res.nvar, 2);
    assert_int_equal(res.runs, 50);
    assert_int_equal(res.var[0].nonfinite, 0);
    nb = res.var[0].nbins;
    assert_true(nb >= 25);
    FNAV_ASSERT_CLOSE(res.distance_m, dist_m, 1e-6, 0.0);
    for (b = 0; b < nb; b++) {
        /* the bins that end after the alignment have every run */
        if (res.var[0].bins[b].t_s > align_s + 1.0) {
            assert_int_equal(res.var[0].bins[b].n, 50);
        }
        nb_aligned += res.var[0].bins[b].n > 0;
    }
    assert_true(nb_aligned >= 20);
    for (g = 0; g < HX_NEES_COUNT; g++) {
        in_good = 0;
        in_over = 0;
        for (b = 0; b < nb; b++) {
            const hx_mc_bin_t *x = &res.var[0].bins[b], *y = &res.var[1].bins[b];
            assert_int_equal(x->n_nees[g], x->n);
            if (x->n == 0) {
                continue; /* before the alignment */
            }
            hx_nees_band(x->n_nees[g], hx_nees_dim[g], 0.05, &lo, &hi);
            in_good += x->nees[g] >= lo && x->nees[g] <= hi;
            in_over += y->nees[g] >= lo && y->nees[g] <= hi;
            /* the over-confident oracle reports a quarter of the covariance */
            FNAV_ASSERT_CLOSE(y->nees[g], 4.0 * x->nees[g], 0.0, 1e-9);
        }
        /* 95 % bands: expect ~95 % of the bins inside for the consistent one */
        if (in_good < (int)(0.85 * nb_aligned) || in_over > 0) {
            fprintf(stderr, "NEES %s: %d / %d bins in band (consistent), %d (over-confident)\n", hx_nees_name[g],
                    in_good, nb_aligned, in_over);
            fail();
        }
    }
    for (b = 0; b < nb; b++) {
        const hx_mc_bin_t *x = &res.var[0].bins[b];
        if (x->n < 50) {
            continue; /* the bin of the alignment */
        }
        /* RMS horizontal error matches the predicted sd (100 dof: ~7 %) */
        FNAV_ASSERT_CLOSE(x->rms_h_m, x->pred_h_m, 0.0, 0.3);
        FNAV_ASSERT_CLOSE(res.var[1].bins[b].rms_h_m, x->rms_h_m, 0.0, 1e-12); /* same errors */
    }
    hx_mc_result_free(&res);
    hx_motion_free(m);
}

static void run_oracles(double mount_yaw_deg, const char *effect)
{
    run_oracles_on("stand:2,walk:30:90,stand:1", 30.0, 0.0, mount_yaw_deg, effect);
}

static void test_consistent_and_overconfident(void **state)
{
    (void)state;
    run_oracles(0.0, NULL);
}

/* The sensor mounted at 30 degrees of yaw: the filter's frame is the
 * sensor's initial heading, the engine rotates the truth into it. */
static void test_filter_frame(void **state)
{
    (void)state;
    run_oracles(30.0, NULL);
}

/* A navigator that aligns late, in the middle of a walk that starts at
 * once and turns: its frame is where the sensor is then (origin and
 * heading), not at the truth's first tick (there, every error would carry
 * the offset, 1.43 m for the filter on walk:20). */
static void test_late_alignment(void **state)
{
    (void)state;
    run_oracles_on("walk:30:90,stand:3", 30.0, 6.0, 0.0, NULL);
}

/* Dropped and duplicated samples: estimates are matched by the counter. */
static void test_drops_and_duplicates(void **state)
{
    (void)state;
    run_oracles(0.0, "dropout:prob=0.1");
    run_oracles(0.0, "duplicate:prob=0.1");
}

/* The bias errors are taken against the simulated bias of each sensor: a
 * constant offset, 0.05 m/s^2 on the accelerometers and 0.005 rad/s on the
 * gyros (the defaults), estimated by the oracles. Against the other
 * sensor's bias (a hand-made mutant of hx_mc.c: the gyro error less the
 * accelerometer bias) the gyro errors are 45 sd off and no bin of the bias
 * NEES is in its band; without any bias in the simulation (the other tests)
 * the two cannot be told apart. */
static void test_bias_against_simulated_bias(void **state)
{
    (void)state;
    run_oracles(0.0, "offset");
}

/* Oracle a and its variant b (the caller's field set on b) run side by side
 * on a short walk with a turn, 5 runs: *res is the engine's result, *m the
 * motion (the caller frees both). */
static void run_variant(oracle_t *a, oracle_t *b, hx_mc_result_t *res, hx_motion_t **m)
{
    char err[256];
    hx_motion_config_t mc = hx_motion_config_default();
    hx_mc_config_t cfg;
    hx_mc_nav_t navs[2];
    *m = hx_motion_create(&mc, "stand:2,walk:10:90,stand:1", 0.0, err, sizeof err);
    assert_non_null(*m);
    a->m = b->m = *m;
    a->scale = b->scale = 1.0;
    navs[0] = make_nav("a", a);
    navs[1] = make_nav("b", b);
    mc_config_50hz(&cfg, *m, 5);
    assert_int_equal(hx_mc_run(&cfg, navs, 2, res, NULL, NULL, err, sizeof err), 0);
}

/* q and -q are one attitude: an oracle that reports -q_est (the scalar part
 * negative) has the attitude error, and so every NEES, of the one that
 * reports q_est (rotvec's sign fold; removed by a hand-made mutant, the
 * negated oracle's attitude error was ~2 pi and nothing noticed). */
static void test_negated_quaternion(void **state)
{
    hx_motion_t *m;
    hx_mc_result_t res;
    oracle_t a, b;
    int k, g, nb = 0;
    (void)state;
    memset(&a, 0, sizeof a);
    memset(&b, 0, sizeof b);
    b.negate_q = 1;
    run_variant(&a, &b, &res, &m);
    for (k = 0; k < res.var[0].nbins; k++) {
        const hx_mc_bin_t *x = &res.var[0].bins[k], *y = &res.var[1].bins[k];
        if (x->n == 0) {
            continue;
        }
        nb++;
        FNAV_ASSERT_CLOSE(y->rms_yaw_rad, x->rms_yaw_rad, 1e-12, 1e-9);
        assert_true(x->rms_yaw_rad < 0.1); /* sd 0.01 rad: not a wrapped angle */
        for (g = 0; g < HX_NEES_COUNT; g++) {
            assert_true(isfinite(x->nees[g]));
            FNAV_ASSERT_CLOSE(y->nees[g], x->nees[g], 1e-12, 1e-9);
        }
    }
    assert_true(nb >= 10);
    hx_mc_result_free(&res);
    hx_motion_free(m);
}

/* The engine anchors the filter's frame on the first estimate (the yaw
 * of q_est (x) q_true^-1, and its position): a navigator whose whole output
 * is turned by a yaw, its first estimate's attitude included, as an
 * alignment that puts yaw 0 elsewhere does, has the errors of one that is
 * not. The anchor was otherwise tested only on first estimates with the
 * truth's attitude (test_filter_frame turns the truth, not the estimate).
 * The covariances are not turned with it, so the NEES are not compared:
 * the horizontal, vertical and heading errors are invariant. */
static void test_frame_from_first_estimate(void **state)
{
    hx_motion_t *m;
    hx_mc_result_t res;
    oracle_t a, b;
    int k, nb = 0;
    (void)state;
    memset(&a, 0, sizeof a);
    memset(&b, 0, sizeof b);
    b.frame_yaw = 2.0; /* 115 deg: past any small-angle shortcut */
    run_variant(&a, &b, &res, &m);
    for (k = 0; k < res.var[0].nbins; k++) {
        const hx_mc_bin_t *x = &res.var[0].bins[k], *y = &res.var[1].bins[k];
        if (x->n == 0) {
            continue;
        }
        nb++;
        assert_int_equal(y->n, x->n);
        assert_true(x->rms_h_m > 0.0);
        FNAV_ASSERT_CLOSE(y->rms_h_m, x->rms_h_m, 1e-12, 1e-9);
        FNAV_ASSERT_CLOSE(y->rms_v_m, x->rms_v_m, 1e-12, 1e-9);
        FNAV_ASSERT_CLOSE(y->rms_yaw_rad, x->rms_yaw_rad, 1e-12, 1e-9);
        assert_true(x->rms_yaw_rad < 0.1);
    }
    assert_true(nb >= 10);
    hx_mc_result_free(&res);
    hx_motion_free(m);
}

/* Sample seq 10's x acceleration of a plain simulation. */
typedef struct {
    double ax;
} probe_t;

static int probe_sink(void *ctx, const hx_sim_tick_t *tk)
{
    if (tk->seq == 10u) {
        ((probe_t *)ctx)->ax = (double)tk->meas.accel_mps2[0];
    }
    return 0;
}

/* The engine's figures against what the oracle reported, computed on the
 * oracle's side from its own error draws d (estimate - truth = -d) and its
 * covariance, not by the engine's arithmetic:
 * - per run: the RMS horizontal error over every estimate, the last
 *   estimate's horizontal and vertical errors and predicted sd;
 * - per 1 s bin (t_s = (b + 1) s, hx_mc.h: the last estimate in the bin):
 *   the RMS over runs of the errors at t_s exactly, and the predicted sd
 *   there, analytic from factor(): P66 + P77 = (1 + 0.25 + 0.64 + 1 + 0.25)
 *   sp^2 = 3.14 sp^2, P88 = sp^2, sp = 0.02 + 0.01 t;
 * - run r simulates seed + r (hx_mc.h): its samples are those of a plain
 *   simulation with that seed, and differ from run to run.
 * Hand-made mutants of hx_mc.c that passed the statistical checks (RMS
 * error within 30 % of the predicted sd): the vertical error in the
 * horizontal one (+17 %), a per-run RMS over n + 1 estimates, bins one
 * sample early (the estimate at t - 1/f_s), the predicted vertical sd from
 * the horizontal one, and every run on the same seed. */
static void test_engine_figures_exact(void **state)
{
    char err[256];
    hx_motion_config_t mc = hx_motion_config_default();
    hx_motion_t *m;
    hx_mc_config_t cfg;
    hx_mc_result_t res;
    static oracle_t o; /* large: not on the stack */
    hx_mc_nav_t nav;
    const int runs = 8;
    int r, b, checked = 0;
    (void)state;
    m = hx_motion_create(&mc, "stand:2,walk:30:90,stand:1", 0.0, err, sizeof err);
    assert_non_null(m);
    memset(&o, 0, sizeof o);
    o.m = m;
    o.scale = 1.0;
    nav = make_nav("oracle", &o);
    mc_config_50hz(&cfg, m, runs);
    assert_int_equal(hx_effect_parse(&cfg.sim.err, "white", err, sizeof err), 0);
    assert_int_equal(hx_mc_run(&cfg, &nav, 1, &res, NULL, NULL, err, sizeof err), 0);
    for (r = 0; r < runs; r++) {
        hx_sim_config_t sc = cfg.sim;
        probe_t pr = { (double)NAN };
        assert_true(o.nest[r] > 1000);
        FNAV_ASSERT_CLOSE(res.var[0].rms_h_m[r], sqrt(o.sum_h2[r] / (double)o.nest[r]), 0.0, 1e-9);
        FNAV_ASSERT_CLOSE(res.var[0].final_h_m[r], o.last_h[r], 0.0, 1e-9);
        FNAV_ASSERT_CLOSE(res.var[0].final_v_m[r], o.last_v[r], 0.0, 1e-9);
        FNAV_ASSERT_CLOSE(res.var[0].final_pred_h_m[r], o.last_pred_h[r], 0.0, 1e-12);
        sc.err.seed = cfg.sim.err.seed + (uint32_t)r;
        assert_int_equal(hx_sim_run(&sc, probe_sink, &pr, err, sizeof err), 0);
        assert_true(o.probe_ax[r] == pr.ax);
        if (r > 0) {
            assert_true(o.probe_ax[r] != o.probe_ax[r - 1]);
        }
    }
    for (b = 0; b < res.var[0].nbins && b < MAX_SECONDS; b++) {
        const hx_mc_bin_t *x = &res.var[0].bins[b];
        double t = (double)(b + 1), sp = 0.02 + 0.01 * t, h2 = 0.0, v2 = 0.0;
        if (t > res.duration_s) {
            /* the last bin would end after the run: it ends with the run,
             * at its last estimate (it said (b + 1) s) */
            FNAV_ASSERT_CLOSE(x->t_s, res.duration_s, 1e-12, 0.0);
            assert_int_equal(b, res.var[0].nbins - 1);
            continue;
        }
        FNAV_ASSERT_CLOSE(x->t_s, t, 1e-12, 0.0);
        assert_int_equal(x->n, runs);
        for (r = 0; r < runs; r++) {
            h2 += o.at_s_h2[r][b];
            v2 += o.at_s_v2[r][b];
        }
        FNAV_ASSERT_CLOSE(x->pred_h_m, sqrt(3.14) * sp, 0.0, 1e-9);
        FNAV_ASSERT_CLOSE(x->pred_v_m, sp, 0.0, 1e-9);
        FNAV_ASSERT_CLOSE(x->rms_h_m, sqrt(h2 / runs), 0.0, 1e-9);
        FNAV_ASSERT_CLOSE(x->rms_v_m, sqrt(v2 / runs), 0.0, 1e-9);
        checked++;
    }
    assert_true(checked >= 25);
    hx_mc_result_free(&res);
    hx_motion_free(m);
}

static void test_band(void **state)
{
    double lo, hi;
    (void)state;
    /* one run of dimension 3: the chi-square(3) 95 % interval */
    hx_nees_band(1, 3, 0.05, &lo, &hi);
    FNAV_ASSERT_CLOSE(lo, 0.2157952826, 1e-8, 0.0); /* scipy.stats.chi2.ppf(0.025, 3) */
    FNAV_ASSERT_CLOSE(hi, 9.3484036045, 1e-8, 0.0); /* scipy.stats.chi2.ppf(0.975, 3) */
    /* 50 runs of dimension 3 */
    hx_nees_band(50, 3, 0.05, &lo, &hi);
    FNAV_ASSERT_CLOSE(lo, 2.36, 0.01, 0.0);
    FNAV_ASSERT_CLOSE(hi, 3.72, 0.01, 0.0);
}

/* Progress within a run: its simulation, then each variant's replay every
 * 4,096 samples, increasing, below the next whole run (not one long run
 * reporting nothing until it ends). */
typedef struct {
    int calls, within, order_ok;
    double last;
} prog_rec_t;

static void rec_progress(void *ctx, double done, int total)
{
    prog_rec_t *p = (prog_rec_t *)ctx;
    p->order_ok = p->order_ok && done >= p->last && done <= (double)total;
    p->within += done > 0.0 && done < 1.0;
    p->last = done;
    p->calls++;
}

static void test_progress_within_run(void **state)
{
    char err[256];
    hx_motion_config_t mc = hx_motion_config_default();
    hx_motion_t *m;
    hx_mc_config_t cfg;
    hx_mc_result_t res;
    oracle_t o;
    hx_mc_nav_t navs[2];
    prog_rec_t pr = { 0, 0, 1, 0.0 };
    (void)state;
    m = hx_motion_create(&mc, "stand:2,walk:200:90,stand:1", 0.0, err, sizeof err);
    assert_non_null(m);
    memset(&o, 0, sizeof o);
    o.m = m;
    o.scale = 1.0;
    navs[0] = make_nav("a", &o);
    navs[1] = make_nav("b", &o);
    mc_config_50hz(&cfg, m, 1);
    assert_int_equal(hx_mc_run(&cfg, navs, 2, &res, rec_progress, &pr, err, sizeof err), 0);
    assert_true(pr.order_ok);
    {
        /* the simulation, then one report per 4,096 samples per variant */
        const int per_var = (int)((hx_sim_ticks(&cfg.sim) + 1u) / 4096u);
        assert_true(per_var >= 1);
        assert_int_equal(pr.within, 1 + 2 * per_var);
    }
    assert_true(pr.last == 1.0);
    hx_mc_result_free(&res);
    hx_motion_free(m);
}

/* An estimate whose covariance is not finite is skipped and counted, as
 * one with a non-finite value (a NaN predicted sd made its bin's RMS of
 * the predicted sd NaN, for every run). */
static void test_nonfinite_covariance(void **state)
{
    char err[256];
    hx_motion_config_t mc = hx_motion_config_default();
    hx_motion_t *m;
    hx_mc_config_t cfg;
    hx_mc_result_t res;
    oracle_t o;
    hx_mc_nav_t nav;
    int b;
    (void)state;
    m = hx_motion_create(&mc, "stand:2,walk:10,stand:1", 0.0, err, sizeof err);
    assert_non_null(m);
    memset(&o, 0, sizeof o);
    o.m = m;
    o.scale = 1.0;
    o.nan_seq = 300u; /* 6 s at 50 Hz: the last estimate of the bin ending at 6 s */
    nav = make_nav("nan", &o);
    mc_config_50hz(&cfg, m, 3);
    assert_int_equal(hx_mc_run(&cfg, &nav, 1, &res, NULL, NULL, err, sizeof err), 0);
    assert_int_equal(res.var[0].nonfinite, 3);
    for (b = 0; b < res.var[0].nbins; b++) {
        assert_int_equal(res.var[0].bins[b].n, 3);
        assert_true(isfinite(res.var[0].bins[b].pred_h_m));
        assert_true(isfinite(res.var[0].bins[b].rms_h_m));
    }
    hx_mc_result_free(&res);
    hx_motion_free(m);
}

static void test_bad_config(void **state)
{
    hx_mc_config_t cfg;
    hx_mc_result_t res;
    char err[256];
    oracle_t o;
    hx_mc_nav_t n = make_nav("x", &o);
    (void)state;
    memset(&cfg, 0, sizeof cfg);
    cfg.runs = 0;
    assert_int_equal(hx_mc_run(&cfg, &n, 1, &res, NULL, NULL, err, sizeof err), -1);
    assert_true(strlen(err) > 5);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_band),
        cmocka_unit_test(test_consistent_and_overconfident),
        cmocka_unit_test(test_filter_frame),
        cmocka_unit_test(test_late_alignment),
        cmocka_unit_test(test_drops_and_duplicates),
        cmocka_unit_test(test_nonfinite_covariance),
        cmocka_unit_test(test_bad_config),
        cmocka_unit_test(test_progress_within_run),
        cmocka_unit_test(test_bias_against_simulated_bias),
        cmocka_unit_test(test_negated_quaternion),
        cmocka_unit_test(test_frame_from_first_estimate),
        cmocka_unit_test(test_engine_figures_exact),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
