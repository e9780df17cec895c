/* Monte Carlo engine (see hx_mc.h). */
#include "hx_mc.h"

#include "hx_allan_ident.h"
#include "hx_motion.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

const int hx_nees_dim[HX_NEES_COUNT] = { 3, 3, 3, 6, 15 };
const char *const hx_nees_name[HX_NEES_COUNT] = { "pos", "vel", "att", "bias", "all" };

/* first index and size of each NEES group in the 15-state error order */
static const int k_first[HX_NEES_COUNT] = { 6, 3, 0, 9, 0 };

void hx_nees_band(int n, int d, double alpha, double *lo, double *hi)
{
    double nu = (double)n * (double)d;
    *lo = hx_chi2_quantile(nu, 0.5 * alpha) / (double)n;
    *hi = hx_chi2_quantile(nu, 1.0 - 0.5 * alpha) / (double)n;
}

/* ------------------------------------------------------------ buffers */

typedef struct {
    uint32_t count;
    fnav_sample_t meas;
    double pos[3], vel[3], q[4], bias[6], odo;
} mc_tick_t;

typedef struct {
    mc_tick_t *t;
    size_t n, cap;
    int oom;
} mc_buf_t;

static int mc_sink(void *ctx, const hx_sim_tick_t *tk)
{
    mc_buf_t *b = (mc_buf_t *)ctx;
    mc_tick_t *x;
    if (b->n == b->cap) {
        size_t cap = b->cap ? 2 * b->cap : 8192;
        mc_tick_t *nt = (mc_tick_t *)realloc(b->t, cap * sizeof *nt);
        if (nt == NULL) {
            b->oom = 1;
            return 1;
        }
        b->t = nt;
        b->cap = cap;
    }
    x = &b->t[b->n++];
    x->count = tk->count;
    x->meas = tk->meas;
    memcpy(x->pos, tk->truth.pos_m, sizeof x->pos);
    memcpy(x->vel, tk->truth.vel_mps, sizeof x->vel);
    memcpy(x->q, tk->truth.q_nb, sizeof x->q);
    memcpy(x->bias, tk->bias, sizeof x->bias);
    x->odo = tk->truth.odo_m;
    return 0;
}

/* per run, per bin: the last estimate in the bin */
typedef struct {
    int valid;
    double eh2, ev2, eyaw2, ph2, pv2;
    double nees[HX_NEES_COUNT];
} mc_slot_t;

/* ------------------------------------------------------------ math */

/* rotation vector of a unit quaternion, angle in [0, pi] */
static void rotvec(const double q[4], double v[3])
{
    double w = q[0], s = 1.0, sn, a;
    int i;
    if (w < 0.0) {
        w = -w;
        s = -1.0;
    }
    sn = sqrt(q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    a = (sn < 1e-12) ? 2.0 : 2.0 * atan2(sn, w) / sn;
    for (i = 0; i < 3; i++) {
        v[i] = s * a * q[1 + i];
    }
}

/* e^T P^-1 e for the d x d block of P starting at (k, k), by Cholesky;
 * -1 when the block is not positive definite or not finite. */
static double nees_block(double P[15][15], const double e[15], int k, int d)
{
    double L[15][15], y[15], s = 0.0;
    int i, j, m;
    for (i = 0; i < d; i++) {
        for (j = 0; j <= i; j++) {
            double v = 0.5 * (P[k + i][k + j] + P[k + j][k + i]);
            for (m = 0; m < j; m++) {
                v -= L[i][m] * L[j][m];
            }
            if (i == j) {
                if (!(v > 0.0) || !isfinite(v)) {
                    return -1.0;
                }
                L[i][i] = sqrt(v);
            } else {
                L[i][j] = v / L[j][j];
            }
        }
    }
    for (i = 0; i < d; i++) {
        double v = e[k + i];
        for (m = 0; m < i; m++) {
            v -= L[i][m] * y[m];
        }
        y[i] = v / L[i][i];
        s += y[i] * y[i];
    }
    return s;
}

/* ------------------------------------------------------------ engine */

static void free_var(hx_mc_var_t *v)
{
    free(v->bins);
    free(v->final_h_m);
    free(v->final_v_m);
    free(v->final_pred_h_m);
    free(v->final_nees_pos);
    free(v->rms_h_m);
    memset(v, 0, sizeof *v);
}

void hx_mc_result_free(hx_mc_result_t *res)
{
    int i;
    for (i = 0; i < HX_MC_MAX_VARIANTS; i++) {
        free_var(&res->var[i]);
    }
}

typedef struct {
    double sum_eh2, sum_ev2, sum_eyaw2, sum_ph2, sum_pv2;
    double sum_nees[HX_NEES_COUNT];
    int n_nees[HX_NEES_COUNT];
    int n;
} mc_acc_t;

/* The share of a run's time its simulation takes, for the progress (the
 * rest is the variants' replays; about a fifth with one variant). */
#define MC_SIM_SHARE 0.2

/* The memory this run may take: MemAvailable of /proc/meminfo (what can be
 * had without swapping: the free memory and the caches the kernel can
 * drop), else, where it cannot be read, the machine's physical memory;
 * *what says which. 0 when neither is known. */
static double mc_memory_available(const char **what, double *total)
{
    long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
    double avail = 0.0;
    char line[128];
    FILE *f = fopen("/proc/meminfo", "r");
    *total = (pages > 0 && page > 0) ? (double)pages * (double)page : 0.0;
    if (f != NULL) {
        while (fgets(line, sizeof line, f) != NULL) {
            double kb;
            if (sscanf(line, "MemAvailable: %lf kB", &kb) == 1 && kb > 0.0) {
                avail = kb * 1024.0;
                break;
            }
        }
        fclose(f);
    }
    if (avail > 0.0) {
        *what = "available";
        return avail;
    }
    *what = "in this machine";
    return *total;
}

/* A run's samples are held for the pairing with the truth, and every
 * growth bin has its accumulators, its result and the caller's output of it
 * (montecarlo's JSON, about 1.7 KB a bin and variant): refuse, before
 * simulating anything, what cannot fit in the memory available. Standing
 * 1e6 s at 200 Hz (38 GB of samples) would simulate for minutes and grow to
 * about 16 GB before "out of memory"; an hour's walk at --bin 0.01 with
 * --json peaked at 774 MB uncounted, 1e6 s at 240 GB after the runs. Until
 * 2026-12-07 the check took the machine's total memory: a run of 25.2 GB
 * on a machine of 25.3 GB passed, and swapped or was killed. */
static int mc_memory_check(const hx_mc_config_t *cfg, size_t nt, int nbins, int nvar, double duration_s, char *err,
                           size_t err_size)
{
    const double per_bin = (double)sizeof(mc_slot_t) +
                           nvar * ((double)sizeof(mc_acc_t) + (double)sizeof(hx_mc_bin_t) + cfg->out_bytes_per_bin);
    const double ticks = (double)nt * (double)sizeof(mc_tick_t), bins = (double)nbins * per_bin;
    const double rate = (double)cfg->sim.err.rate_hz;
    const char *what = "";
    double total = 0.0, have = mc_memory_available(&what, &total);
    char mem[96];
    if (!((have > 0.0 && ticks + bins > have) || ticks + bins > (double)SIZE_MAX)) {
        return 0;
    }
    if (have < total) {
        snprintf(mem, sizeof mem, "the %.1f GB of memory available (of %.1f GB)", have / 1e9, total / 1e9);
    } else {
        snprintf(mem, sizeof mem, "the %.1f GB of memory %s", have / 1e9, what);
    }
    if (ticks >= bins || !(have > ticks)) {
        snprintf(err, err_size,
                 "%.0f samples (%.6g s at %.6g Hz) are %.1f GB of samples and truth to hold (and %.1f GB of growth "
                 "bins), more than %s: shorten --duration or lower --rate (--seeds does not matter: one run is "
                 "held at a time)",
                 (double)nt, duration_s, rate, ticks / 1e9, bins / 1e9, mem);
    } else {
        /* the bins that fit beside the samples, and the --bin that makes
         * no more of them */
        const double fit = floor((have - ticks) / per_bin);
        snprintf(err, err_size,
                 "--bin %g s makes %d growth bins over %.6g s, %.1f GB to hold (%.0f bytes a bin for %d variant%s%s) "
                 "beside %.1f GB of samples and truth, more than %s: a larger --bin (%.3g s or more)",
                 cfg->bin_s, nbins, duration_s, bins / 1e9, per_bin, nvar, nvar == 1 ? "" : "s",
                 cfg->out_bytes_per_bin > 0.0 ? ", the JSON's included" : "", ticks / 1e9, mem,
                 fit >= 1.0 ? duration_s / fit : duration_s);
    }
    return -1;
}

int hx_mc_run(const hx_mc_config_t *cfg, hx_mc_nav_t *navs, int nvar, hx_mc_result_t *res,
              hx_mc_progress_fn progress, void *progress_ctx, char *err, size_t err_size)
{
    mc_buf_t buf;
    mc_slot_t *slots = NULL;
    mc_acc_t *acc = NULL;
    hx_sim_config_t sc;
    double rate, bin_s = cfg->bin_s > 0.0 ? cfg->bin_s : 1.0;
    int nbins, r, v, b, status = -1;
    size_t nt;
    memset(res, 0, sizeof *res);
    memset(&buf, 0, sizeof buf);
    if (cfg->runs < 1 || nvar < 1 || nvar > HX_MC_MAX_VARIANTS) {
        snprintf(err, err_size, "montecarlo: need at least one run and 1..%d variants", HX_MC_MAX_VARIANTS);
        return -1;
    }
    rate = (double)cfg->sim.err.rate_hz;
    nt = hx_sim_ticks(&cfg->sim);
    nbins = (int)ceil(((double)(nt - 1) / rate) / bin_s - 1e-9);
    if (nbins < 1) {
        nbins = 1;
    }
    res->runs = cfg->runs;
    res->nvar = nvar;
    res->bin_s = bin_s;
    res->duration_s = (double)(nt - 1) / rate;
    if (mc_memory_check(cfg, nt, nbins, nvar, res->duration_s, err, err_size) != 0) {
        goto out;
    }
    slots = (mc_slot_t *)calloc((size_t)nbins, sizeof *slots);
    acc = (mc_acc_t *)calloc((size_t)nbins * (size_t)nvar, sizeof *acc);
    if (slots == NULL || acc == NULL) {
        snprintf(err, err_size, "out of memory");
        goto out;
    }
    for (v = 0; v < nvar; v++) {
        hx_mc_var_t *x = &res->var[v];
        x->name = navs[v].name;
        x->nbins = nbins;
        x->bins = (hx_mc_bin_t *)calloc((size_t)nbins, sizeof *x->bins);
        x->final_h_m = (double *)calloc((size_t)cfg->runs, sizeof(double));
        x->final_v_m = (double *)calloc((size_t)cfg->runs, sizeof(double));
        x->final_pred_h_m = (double *)calloc((size_t)cfg->runs, sizeof(double));
        x->final_nees_pos = (double *)calloc((size_t)cfg->runs, sizeof(double));
        x->rms_h_m = (double *)calloc((size_t)cfg->runs, sizeof(double));
        if (x->bins == NULL || x->final_h_m == NULL || x->final_v_m == NULL || x->final_pred_h_m == NULL ||
            x->final_nees_pos == NULL || x->rms_h_m == NULL) {
            snprintf(err, err_size, "out of memory");
            goto out;
        }
    }
    buf.t = (mc_tick_t *)malloc((size_t)nt * sizeof *buf.t);
    if (buf.t == NULL) {
        snprintf(err, err_size, "out of memory: %.0f samples are %.1f GB of samples and truth to hold", (double)nt,
                 (double)nt * (double)sizeof(mc_tick_t) / 1e9);
        goto out;
    }
    buf.cap = nt;
    for (r = 0; r < cfg->runs; r++) {
        if (cfg->stop != NULL && *cfg->stop) {
            /* stopped (Ctrl-C): the runs done are the result */
            if (r == 0) {
                snprintf(err, err_size, "stopped before the first run was done");
                goto out;
            }
            res->runs = r;
            break;
        }
        sc = cfg->sim;
        sc.err.seed = cfg->sim.err.seed + (uint32_t)r;
        buf.n = 0;
        if (hx_sim_run(&sc, mc_sink, &buf, err, err_size) != 0 || buf.oom) {
            if (buf.oom) {
                snprintf(err, err_size, "out of memory");
            }
            goto out;
        }
        if (progress != NULL) {
            progress(progress_ctx, r + MC_SIM_SHARE, cfg->runs);
        }
        if (r == 0) {
            res->distance_m = buf.t[buf.n - 1].odo;
            for (b = 0; b < nbins; b++) {
                /* a bin ends where the run ends: the last one's estimates
                 * are of that time (not 4 s for a 3.5 s run's last bin, nor
                 * 100 s for the one --bin 100 of a 3 s run) */
                const double t_end = fmin((double)(b + 1) * bin_s, res->duration_s);
                size_t i = (size_t)llround(t_end * rate);
                for (v = 0; v < nvar; v++) {
                    res->var[v].bins[b].t_s = t_end;
                    res->var[v].bins[b].odo_m = buf.t[i < buf.n ? i : buf.n - 1].odo;
                }
            }
        }
        for (v = 0; v < nvar; v++) {
            hx_mc_nav_t *nav = &navs[v];
            hx_mc_var_t *x = &res->var[v];
            hx_mc_est_t est;
            size_t i;
            uint32_t k;
            double sum_h2 = 0.0, p0[3] = { 0.0, 0.0, 0.0 }, cz = 1.0, sz = 0.0, qz[4] = { 1.0, 0.0, 0.0, 0.0 };
            long nest = 0;
            int have_final = 0, finishing = 0, have_frame = 0;
            memset(slots, 0, (size_t)nbins * sizeof *slots);
            if (nav->start(nav->ctx, rate, r) != 0) {
                snprintf(err, err_size, "montecarlo: navigator %s failed to start", nav->name);
                goto out;
            }
            for (i = 0; i <= buf.n; i++) {
                if (progress != NULL && (i & 4095u) == 4095u) {
                    progress(progress_ctx,
                             r + MC_SIM_SHARE + (1.0 - MC_SIM_SHARE) * (v + (double)i / (double)(buf.n + 1)) / nvar,
                             cfg->runs);
                }
                if (i < buf.n) {
                    for (k = 0; k < buf.t[i].count; k++) {
                        if (nav->push(nav->ctx, &buf.t[i].meas) != 0) {
                            snprintf(err, err_size, "montecarlo: navigator %s failed on sample %zu", nav->name, i);
                            goto out;
                        }
                    }
                } else {
                    nav->finish(nav->ctx);
                    finishing = 1;
                }
                while (nav->pop(nav->ctx, &est) == 1) {
                    const mc_tick_t *tk;
                    double e[15], pt[3], vt[3], qt[4], qc[4], dq[4], eh2, ev2;
                    int g, j, ok = 1;
                    (void)finishing;
                    if (!est.valid || est.seq >= buf.n) {
                        continue;
                    }
                    tk = &buf.t[est.seq];
                    if (!have_frame) {
                        /* The filter's frame: origin where the sensor was at
                         * the alignment, x along its heading then (yaw 0 at
                         * the alignment), i.e. at the navigator's first
                         * aligned estimate. Not the truth's first tick: a
                         * motion that starts walking aligns at a later
                         * stance (walk:20, 1.43 m on), and every error
                         * would carry that offset. */
                        /* The heading between the two frames: the yaw of
                         * q_est (x) q_true^-1 (truth n to filter n), not the
                         * truth's Euler yaw, which a mounting at pitch +-90
                         * deg leaves undefined (the filter's yaw 0 there is
                         * split from roll by the noise: 35 m of false error
                         * at --mount 0,90,0). Elsewhere the same up to the
                         * alignment's tilt error. */
                        double qi[4], d[4], yaw0;
                        qi[0] = tk->q[0];
                        qi[1] = -tk->q[1];
                        qi[2] = -tk->q[2];
                        qi[3] = -tk->q[3];
                        hx_quat_mul(est.q_nb, qi, d);
                        yaw0 = -atan2(2.0 * (d[0] * d[3] + d[1] * d[2]), 1.0 - 2.0 * (d[2] * d[2] + d[3] * d[3]));
                        cz = cos(yaw0);
                        sz = sin(yaw0);
                        qz[0] = cos(0.5 * yaw0);
                        qz[3] = -sin(0.5 * yaw0);
                        memcpy(p0, tk->pos, sizeof p0);
                        have_frame = 1;
                    }
                    pt[0] = cz * (tk->pos[0] - p0[0]) + sz * (tk->pos[1] - p0[1]);
                    pt[1] = -sz * (tk->pos[0] - p0[0]) + cz * (tk->pos[1] - p0[1]);
                    pt[2] = tk->pos[2] - p0[2];
                    vt[0] = cz * tk->vel[0] + sz * tk->vel[1];
                    vt[1] = -sz * tk->vel[0] + cz * tk->vel[1];
                    vt[2] = tk->vel[2];
                    hx_quat_mul(qz, tk->q, qt);
                    /* Every error is estimate minus truth, the attitude's
                     * too: q_est = dq (x) q_true, dq = exp(e_att) about the
                     * n axes. The filter perturbs its sigma points as
                     * truth = dq(a) (x) estimate and v + dv alike, so P holds
                     * the covariance of one sign for all states; an attitude
                     * error of the other sign would flip every attitude
                     * cross-covariance in the joint NEES. */
                    qc[0] = qt[0];
                    qc[1] = -qt[1];
                    qc[2] = -qt[2];
                    qc[3] = -qt[3];
                    hx_quat_mul(est.q_nb, qc, dq);
                    rotvec(dq, e);
                    for (j = 0; j < 3; j++) {
                        e[3 + j] = est.vel_mps[j] - vt[j];
                        e[6 + j] = est.pos_m[j] - pt[j];
                        e[9 + j] = est.gyro_bias_rps[j] - tk->bias[3 + j];
                        e[12 + j] = est.accel_bias_mps2[j] - tk->bias[j];
                    }
                    /* a non-finite covariance is skipped too (hx_mc.h): it
                     * made the bin's predicted sd NaN for every run */
                    for (j = 0; j < 15; j++) {
                        ok = ok && isfinite(e[j]);
                        for (g = 0; g < 15; g++) {
                            ok = ok && isfinite(est.P[j][g]);
                        }
                    }
                    if (!ok) {
                        x->nonfinite++;
                        continue;
                    }
                    eh2 = e[6] * e[6] + e[7] * e[7];
                    ev2 = e[8] * e[8];
                    b = (int)ceil((double)est.seq / rate / bin_s - 1e-9) - 1;
                    if (b < 0) {
                        b = 0;
                    }
                    if (b >= nbins) {
                        b = nbins - 1;
                    }
                    {
                        mc_slot_t s;
                        s.valid = 1;
                        s.eh2 = eh2;
                        s.ev2 = ev2;
                        s.eyaw2 = e[2] * e[2];
                        s.ph2 = est.P[6][6] + est.P[7][7];
                        s.pv2 = est.P[8][8];
                        /* a group whose covariance is not positive definite
                         * (states switched off, e.g. the biases without the
                         * bias model) has no NEES */
                        for (g = 0; g < HX_NEES_COUNT; g++) {
                            s.nees[g] = nees_block(est.P, e, k_first[g], hx_nees_dim[g]);
                            if (s.nees[g] < 0.0) {
                                s.nees[g] = (double)NAN;
                            }
                        }
                        slots[b] = s;
                        x->final_h_m[r] = sqrt(eh2);
                        x->final_v_m[r] = sqrt(ev2);
                        x->final_pred_h_m[r] = sqrt(s.ph2);
                        x->final_nees_pos[r] = s.nees[HX_NEES_POS];
                        have_final = 1;
                    }
                    sum_h2 += eh2;
                    nest++;
                    x->estimates++;
                }
            }
            x->rms_h_m[r] = nest > 0 ? sqrt(sum_h2 / (double)nest) : (double)NAN;
            if (!have_final) {
                x->final_h_m[r] = x->final_v_m[r] = x->final_pred_h_m[r] = x->final_nees_pos[r] = (double)NAN;
            }
            for (b = 0; b < nbins; b++) {
                mc_acc_t *a = &acc[(size_t)v * (size_t)nbins + (size_t)b];
                int g;
                if (!slots[b].valid) {
                    continue;
                }
                a->n++;
                a->sum_eh2 += slots[b].eh2;
                a->sum_ev2 += slots[b].ev2;
                a->sum_eyaw2 += slots[b].eyaw2;
                a->sum_ph2 += slots[b].ph2;
                a->sum_pv2 += slots[b].pv2;
                for (g = 0; g < HX_NEES_COUNT; g++) {
                    if (isfinite(slots[b].nees[g])) {
                        a->sum_nees[g] += slots[b].nees[g];
                        a->n_nees[g]++;
                    }
                }
            }
        }
        if (progress != NULL) {
            progress(progress_ctx, r + 1, cfg->runs);
        }
    }
    for (v = 0; v < nvar; v++) {
        for (b = 0; b < nbins; b++) {
            const mc_acc_t *a = &acc[(size_t)v * (size_t)nbins + (size_t)b];
            hx_mc_bin_t *o = &res->var[v].bins[b];
            int g;
            o->n = a->n;
            if (a->n == 0) {
                o->rms_h_m = o->rms_v_m = o->rms_yaw_rad = o->pred_h_m = o->pred_v_m = (double)NAN;
                for (g = 0; g < HX_NEES_COUNT; g++) {
                    o->nees[g] = (double)NAN;
                }
                continue;
            }
            o->rms_h_m = sqrt(a->sum_eh2 / a->n);
            o->rms_v_m = sqrt(a->sum_ev2 / a->n);
            o->rms_yaw_rad = sqrt(a->sum_eyaw2 / a->n);
            o->pred_h_m = sqrt(a->sum_ph2 / a->n);
            o->pred_v_m = sqrt(a->sum_pv2 / a->n);
            for (g = 0; g < HX_NEES_COUNT; g++) {
                o->n_nees[g] = a->n_nees[g];
                o->nees[g] = a->n_nees[g] > 0 ? a->sum_nees[g] / a->n_nees[g] : (double)NAN;
            }
        }
    }
    status = 0;
out:
    free(buf.t);
    free(slots);
    free(acc);
    if (status != 0) {
        hx_mc_result_free(res);
    }
    return status;
}
