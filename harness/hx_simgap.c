/* Sim-to-real gap diagnosis: the pipeline (hx_simgap.h, docs/simgap.md).
 * Static logs: per channel, baseline fit on the fit segment, twins, gap per
 * segment and domain, forward selection of catalogue effects scored on the
 * held-out segment; timing domain from the time stamps. Walks: see
 * hx_simgap_nav.c. */
#include "hx_simgap.h"
#include "hx_simgap_nav.h"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "hx_cli.h"
#include "hx_nav.h"
#include "hx_profile.h"

sg_opts_t sg_opts_default(void)
{
    sg_opts_t o;
    memset(&o, 0, sizeof o);
    o.domain = 0;
    o.seeds = 16;
    o.seeds_cand = 16;
    o.prescreen = 3;
    o.fit_frac = 0.6;
    o.alpha = 0.05;
    o.seed = 1u;
    o.max_steps = 3;
    o.cmd = "simgap";
    return o;
}

double sg_log_rate(const hx_log_t *log)
{
    double r;
    if (log->meta.rate_hz > 0.0 && log->meta.rate_nominal) {
        return log->meta.rate_hz;
    }
    r = hx_stamp_rate_hz(log->t_ns, log->n, NULL);
    return r > 0.0 ? r : log->meta.rate_hz;
}

int sg_stamps_check(const hx_log_t *log, const char *path, int domain, char *err, size_t err_size)
{
    /* a walk stamped in bursts (4 samples 5 us apart every 10 ms) is
     * refused: it would be read at 200 kHz, detected as static and analysed
     * as one, exit 0; one stamp per packet of 4 would be navigated and
     * twinned at 100 Hz (a 400 Hz walk), its answer meaningless */
    const size_t n = log->n < HX_STAMPS_PROBE_N ? log->n : (size_t)HX_STAMPS_PROBE_N;
    const double max_gap_s = (double)fnav_nav_config_default.max_gap_s;
    hx_bursts_t bu;
    char msg[640];
    if (err_size > 0u) {
        err[0] = '\0';
    }
    if (log->t_ns == NULL || log->meta.stamps_made || hx_stamp_bursts(log->t_ns, n, max_gap_s, &bu) <= 0) {
        return 0;
    }
    bu.first = log->n > n;
    bu.format = log->meta.format;
    if (domain == 2 || (domain == 0 && sg_detect_domain(log, bu.rate_hz) == 2)) {
        hx_bursts_text(&bu, "navigation needs each sample's own time", "Time stamps in bursts", err, err_size);
        return -1;
    }
    /* the verdict above, not hx_nav_bursts_warn's second test of the same
     * stamps; its words, with sg_log_rate's rate and its source */
    hx_warn("simgap", "%s: %s", path,
            hx_bursts_rate_text(&bu, "the taus and frequencies are read at", sg_log_rate(log),
                                log->meta.rate_nominal && log->meta.rate_hz > 0.0, msg, sizeof msg));
    return 0;
}

int sg_detect_domain(const hx_log_t *log, double rate_hz)
{
    size_t n = log->n, k, w = (size_t)(rate_hz > 1.0 ? rate_hz : 1.0), nw = 0, moving = 0;
    double gm[3] = { 0, 0, 0 }, fn = 0.0;
    if (n == 0) {
        return 1;
    }
    for (k = 0; k < n; k++) {
        int i;
        for (i = 0; i < 3; i++) {
            gm[i] += log->gyr[k][i];
        }
        fn += sqrt(log->acc[k][0] * log->acc[k][0] + log->acc[k][1] * log->acc[k][1] + log->acc[k][2] * log->acc[k][2]);
    }
    for (k = 0; k < 3; k++) {
        gm[k] /= (double)n;
    }
    fn /= (double)n;
    /* one-second windows: moving when within the window the rate departs
     * from the log's mean by more than 1 rad/s and the specific force from
     * its mean norm by more than 1 m/s^2 (a foot in swing does both many
     * times a second). Both: with either one enough to make a window
     * move, a static log with its gyro in deg/s (noise of tenths of a
     * "rad/s", reaching 1 within every second) would be a walk without a
     * stance, "too short" for its stances (tests/cli/test_simgap.sh); every
     * walk of the shared data has 9-95 % of its windows moving by both */
    for (k = 0; k + w <= n; k += w) {
        size_t i;
        int mg = 0, mf = 0;
        for (i = k; i < k + w && !(mg && mf); i++) {
            double a = log->gyr[i][0] - gm[0], b = log->gyr[i][1] - gm[1], c = log->gyr[i][2] - gm[2];
            double f = sqrt(log->acc[i][0] * log->acc[i][0] + log->acc[i][1] * log->acc[i][1] +
                            log->acc[i][2] * log->acc[i][2]);
            mg |= a * a + b * b + c * c > 1.0;
            mf |= fabs(f - fn) > 1.0;
        }
        moving += (size_t)(mg && mf);
        nw++;
    }
    return (nw > 0 && (double)moving > 0.02 * (double)nw) ? 2 : 1;
}

/* ------------------------------------------------------------ timing */

static double poisson_z(long n, double lam)
{
    double p;
    lam += 0.05; /* the twin's clock is ideal; one stray event is not evidence */
    if (n <= 0) {
        return 0.0;
    }
    p = gsl_cdf_poisson_Q((unsigned)(n - 1), lam); /* P(X >= n) */
    if (!(p > 1e-300)) {
        return SG_ZCAP;
    }
    p = gsl_cdf_ugaussian_Qinv(p);
    /* far fewer events than lam (a jitter's expected tail, below): P(X >= n)
     * rounds to 1, whose normal score is -inf */
    return p > SG_ZCAP ? SG_ZCAP : (p < -SG_ZCAP || p != p ? -SG_ZCAP : p);
}

/* Two-sided score of a count against an expectation (after fitting): the
 * normal score of the Poisson tail on the count's side, capped at SG_ZCAP,
 * so that it is poisson_z's when the count lies above (against a fitted
 * rate of 0 the same number as before fitting). The normal approximation
 * (n - lam) / sqrt(lam), uncapped, would make 500 drops in the held-out
 * part of a log whose fit segment had none "40 sigma" before fitting and
 * "+2235.8 sigma" after a fit that changed nothing. */
static double count_z(long n, double lam)
{
    double p;
    lam += 0.05;
    if ((double)n > lam) {
        p = gsl_cdf_poisson_Q((unsigned)(n - 1), lam); /* P(X >= n) */
        if (!(p > 1e-300)) {
            return SG_ZCAP;
        }
        p = gsl_cdf_ugaussian_Qinv(p);
        return p > SG_ZCAP ? SG_ZCAP : p;
    }
    p = gsl_cdf_poisson_P((unsigned)(n > 0 ? n : 0), lam); /* P(X <= n) */
    if (!(p > 1e-300)) {
        return -SG_ZCAP;
    }
    p = -gsl_cdf_ugaussian_Qinv(p);
    return p < -SG_ZCAP ? -SG_ZCAP : p;
}

/* Standard error of the log of a sample variance of n values whose
 * kurtosis is kurt: Var(s^2) = sigma^4 ((kurt - 1) / n + O(1/n^2)), 2 / (n - 1)
 * for Gaussian values (kurt 3). Clock jitter is heavy-tailed (kurtosis 5
 * to 16 on the shared walks' stamps), where the Gaussian's error is 1.4 to
 * 2.7 times too small and a stationary clock looked non-stationary; never
 * narrower than the Gaussian's (a claim of a difference stays
 * conservative). */
static double logvar_se(double kurt, long n)
{
    if (!(kurt > 3.0)) {
        kurt = 3.0;
    }
    return sqrt((kurt - 1.0) / (double)(n - 1));
}

/* A count n against an expectation lam that was itself estimated with
 * variance var (the jitter's tails, below): the normal score
 * (n - lam -+ 1/2) / sqrt(lam + var), the Poisson spread and the
 * estimate's added (treated as known, the expectation from 11,000
 * intervals made a clean log's z spread 1.2-1.26 times too wide: a
 * review); without an estimated tail, or where both are small, the
 * Poisson tail: count_z (two-sided, `two`) or poisson_z. */
static double tail_z(long n, double lam, double var, int two)
{
    double z;
    if (!(var > 0.0) || !(lam + var >= 1.0)) {
        /* no tail estimated (an exact or a coarse clock): the exact tail */
        return two ? count_z(n, lam) : poisson_z(n, lam);
    }
    z = ((double)n - lam - ((double)n > lam ? 0.5 : -0.5)) / sqrt(lam + var);
    if (!two && n <= 0) {
        return 0.0;
    }
    return z > SG_ZCAP ? SG_ZCAP : (z < -SG_ZCAP ? -SG_ZCAP : z);
}

/* jitter_tails' fixed point: m and s of N(m, s^2) from the quartiles q[]
 * of the intervals kept between the thresholds (x = dt - T, ns), their
 * levels within the kept mass; the expected drops and duplicates of the n
 * kept intervals' population in lam[], the quartiles' normal scores in
 * z[]. Returns s, or 0 where no spread or no clock is left to model. */
static double tails_fit(const double q[3], double T, long n, double lam[2], double z[3])
{
    double m = 0.0, sd = 0.0, hi = 0.0, lo = 0.0;
    int it, i;
    lam[0] = lam[1] = 0.0;
    for (it = 0; it < 100; it++) {
        const double kept = 1.0 - hi - lo;
        double hi2, lo2;
        for (i = 0; i < 3; i++) {
            z[i] = gsl_cdf_ugaussian_Pinv(lo + 0.25 * (i + 1) * kept);
        }
        sd = (q[2] - q[0]) / (z[2] - z[0]);
        m = q[1] - sd * z[1];
        if (!(sd > 0.0)) {
            return 0.0;
        }
        hi2 = gsl_cdf_ugaussian_Q((0.5 * T - m) / sd);
        lo2 = gsl_cdf_ugaussian_P((-0.9 * T - m) / sd);
        if (hi2 + lo2 > 0.5) {
            return 0.0; /* no clock left to model */
        }
        if (fabs(hi2 - hi) < 1e-14 && fabs(lo2 - lo) < 1e-14) {
            break;
        }
        hi = hi2;
        lo = lo2;
    }
    lam[0] = (double)n / (1.0 - hi - lo) * hi;
    lam[1] = (double)n / (1.0 - hi - lo) * lo;
    return sd;
}

/* The drops and duplicates segment g's jitter makes by itself: with
 * Gaussian stamp noise an interval is T + N(m, s^2), and its tails pass the
 * counts' thresholds (over 1.5 T a drop, at most 0.1 T a duplicate): at 200
 * Hz with stamps jittered by 1 ms (intervals' sd 1.41 ms) 3.8 % of the
 * intervals are over 7.5 ms, which were counted as 439 drops on an 11,000
 * sample walk that lost none. m and s come from the quartiles of the
 * regular intervals (those between the thresholds), whose levels are
 * corrected for the tails the thresholds cut off (a fixed point: the cut
 * tails from m and s, the quartiles' levels within the kept mass from the
 * tails), so lost samples, whose merged intervals lie beyond 1.5 T, do not
 * widen them (taken over every interval, 2 % of drops widened the spread
 * enough to fit a third of them away: a review), nor does the cut narrow
 * them (the plain sd and the median absolute deviation of the cut
 * intervals came out 9 % and 7 % short on that walk). Expected counts:
 * the kept intervals' population n_kept / (1 - tails) times each tail,
 * their variances by the delta method through the fixed point (below).
 * Only where the jitter itself is significant (jitter_sig: its z above
 * the timing family's critical value) and resolved by the stamps
 * (resolution under s / 4):
 * intervals on a coarse lattice (stamps in ms at 400 Hz: 2 or 3 ms, never
 * beyond 1.5 T) have quartiles that are the lattice's steps, which read
 * as a spread made thousands of drops "expected" and hid 2 % of lost
 * samples (a review). A Gaussian model: a heavier-tailed jitter still
 * passes the thresholds more often than expected (docs/simgap.md,
 * "Timing domain"). */
static void jitter_tails(const hx_log_t *lg, const sg_segs_t *segs, int g, double T, double res_ns,
                         int jitter_sig, double tail[2], double var[2])
{
    double *x;
    long k, n = 0;
    int blk;
    tail[0] = tail[1] = var[0] = var[1] = 0.0; /* drops, duplicates */
    if (!jitter_sig) {
        return;
    }
    for (blk = 0; blk < segs->nb[g]; blk++) {
        n += segs->n[g][blk];
    }
    x = (double *)malloc((size_t)(n > 0 ? n : 1) * sizeof *x);
    if (x == NULL) {
        return;
    }
    n = 0;
    for (blk = 0; blk < segs->nb[g]; blk++) {
        for (k = segs->start[g][blk] + 1; k < segs->start[g][blk] + segs->n[g][blk]; k++) {
            const double dt = (double)(lg->t_ns[k] - lg->t_ns[k - 1]);
            if (dt > 0.1 * T && dt <= 1.5 * T) {
                x[n++] = dt - T;
            }
        }
    }
    if (n > 8) {
        double q[3], lam[2], sd, gr[2][3], z[3], f[3];
        int i, j, c;
        qsort(x, (size_t)n, sizeof *x, hx_cmp_double);
        for (i = 0; i < 3; i++) {
            q[i] = gsl_stats_quantile_from_sorted_data(x, 1, (size_t)n, 0.25 * (i + 1));
        }
        sd = tails_fit(q, T, n, lam, z);
        if (sd > 0.0 && res_ns <= 0.25 * sd) {
            /* the variance of each expectation by the delta method through
             * the fixed point (a numerical gradient in the three
             * quartiles: the cut's correction feeds a wider spread back
             * into a larger tail, and a gradient of the plain normal tail
             * left 1.7 times the variance out: z's sd 1.17 over 300 clean
             * logs), with the sample quartiles' covariance p_a (1 - p_b) /
             * (n f_a f_b), f the kept intervals' density there */
            const double kept = 1.0 - (lam[0] + lam[1]) / ((double)n + lam[0] + lam[1]);
            tail[0] = lam[0];
            tail[1] = lam[1];
            for (i = 0; i < 3; i++) {
                double qp[3], lp[2], zp[3];
                const double h = 1e-3 * sd;
                memcpy(qp, q, sizeof qp);
                qp[i] += h;
                if (!(tails_fit(qp, T, n, lp, zp) > 0.0)) {
                    var[0] = var[1] = 0.0;
                    tail[0] = tail[1] = 0.0;
                    free(x);
                    return;
                }
                gr[0][i] = (lp[0] - lam[0]) / h;
                gr[1][i] = (lp[1] - lam[1]) / h;
                f[i] = gsl_ran_ugaussian_pdf(z[i]) / (sd * kept);
            }
            for (c = 0; c < 2; c++) {
                for (i = 0; i < 3; i++) {
                    for (j = 0; j < 3; j++) {
                        const int a1 = i < j ? i : j, b1 = i < j ? j : i;
                        const double pa = 0.25 * (a1 + 1), pb = 0.25 * (b1 + 1);
                        var[c] += gr[c][i] * gr[c][j] * pa * (1.0 - pb) / ((double)n * f[i] * f[j]);
                    }
                }
            }
        }
    }
    free(x);
}

void sg_timing_analyse(const hx_log_t *lg, double rate, const sg_segs_t *segs, double alpha, sg_timing_t *t)
{
    const double T = 1e9 / rate;
    int g, d;
    long k;
    double res = 1.0, s0_ns;
    memset(t, 0, sizeof *t);
    t->first_t[SG_TIM_DUP] = t->first_t[SG_TIM_DROP] = (double)NAN;
    if (lg->n < 16 || lg->t_ns == NULL || lg->meta.stamps_made) {
        /* a format without stamps (ADIS16405, OpenShoe 820 Hz): the stamps
         * are index / rate, with nothing to analyse (analysed, they would
         * read as a clean clock with a 0.01 s resolution) */
        return;
    }
    /* resolution: the largest decade of ns that divides every stamp offset */
    for (d = 9; d >= 0; d--) {
        int64_t r = 1;
        int i, ok = 1;
        for (i = 0; i < d; i++) {
            r *= 10;
        }
        for (k = 1; k < (long)lg->n && ok; k++) {
            if ((lg->t_ns[k] - lg->t_ns[0]) % r != 0) {
                ok = 0;
            }
        }
        if (ok) {
            res = (double)r;
            break;
        }
    }
    t->have = 1;
    t->res_s = res * 1e-9;
    /* What rounding an ideal clock's stamps to the resolution leaves in the
     * intervals: each is floor(T/res) or one more resolution step, the
     * longer with the frequency p = frac(T/res), so their spread is
     * res sqrt(p (1 - p)) (T the mean regular interval). res/sqrt(6) is
     * that spread's average over p, not its value at this p: at 300 Hz with
     * stamps in ms (p = 1/3, 0.471 ms against 0.408 ms) it would answer a
     * clean log "jitter" at 38.6 sigma. */
    {
        double s = 0.0, p;
        long nreg = 0;
        for (k = 1; k < (long)lg->n; k++) {
            double dt = (double)(lg->t_ns[k] - lg->t_ns[k - 1]);
            if (dt > 0.1 * T && dt <= 1.5 * T) {
                s += dt;
                nreg++;
            }
        }
        p = nreg > 0 ? s / (double)nreg / res : 0.0;
        p -= floor(p);
        s0_ns = res * sqrt(p * (1.0 - p));
    }
    for (g = 0; g < SG_NSEG; g++) {
        /* moments of x = dt - T about the segment's first regular x (ref):
         * the spread and kurtosis do not depend on it, and with a rate that
         * is not the clock's own (a coarse-stamped CSV with dropped
         * samples, read at 95.4 Hz for 100 Hz) every x is the same
         * -485,000 ns, whose raw moments would cancel to a spread of
         * 0.43 ns: "jitter" against an exact grid's 0
         * (test_timing_jitter_off_rate) */
        double s = 0.0, s2 = 0.0, s3 = 0.0, s4 = 0.0, ref = 0.0;
        long nreg = 0;
        int blk;
        for (blk = 0; blk < segs->nb[g]; blk++)
        for (k = segs->start[g][blk] + 1; k < segs->start[g][blk] + segs->n[g][blk]; k++) {
            double dt = (double)(lg->t_ns[k] - lg->t_ns[k - 1]);
            double tk = (double)(lg->t_ns[k] - lg->t_ns[0]) * 1e-9;
            t->n_int[g]++;
            if (dt <= 0.1 * T) {
                t->n_dup[g]++;
                if (g == SG_FULL && !(t->first_t[SG_TIM_DUP] == t->first_t[SG_TIM_DUP])) {
                    t->first_t[SG_TIM_DUP] = tk;
                }
            } else if (dt > 1.5 * T) {
                t->n_drop[g] += (long)floor(dt / T + 0.5) - 1;
                if (g == SG_FULL && !(t->first_t[SG_TIM_DROP] == t->first_t[SG_TIM_DROP])) {
                    t->first_t[SG_TIM_DROP] = tk;
                }
            } else {
                double x = dt - T;
                if (nreg == 0) {
                    ref = x;
                }
                x -= ref;
                s += x;
                s2 += x * x;
                s3 += x * x * x;
                s4 += x * x * x * x;
                nreg++;
            }
        }
        t->jit_sd[g] = nreg > 1 ? sqrt((s2 - s * s / (double)nreg) / (double)(nreg - 1)) * 1e-9 : 0.0;
        t->jit_kurt[g] = 3.0;
        if (nreg > 3) {
            /* central moments from the raw ones about ref (x in ns: no overflow) */
            const double m = s / (double)nreg, e2 = s2 / (double)nreg, e3 = s3 / (double)nreg,
                         e4 = s4 / (double)nreg;
            const double c2 = e2 - m * m, c4 = e4 - 4.0 * m * e3 + 6.0 * m * m * e2 - 3.0 * m * m * m * m;
            if (c2 > 0.0 && c4 > 0.0) {
                t->jit_kurt[g] = c4 / (c2 * c2);
            }
        }
        {
            /* what rounding to the resolution leaves (above) */
            double s0 = s0_ns * 1e-9, z = 0.0, tail[2], var[2];
            if (nreg > 2 && t->jit_sd[g] > s0) {
                z = (log(t->jit_sd[g] * t->jit_sd[g]) - log(s0 > 1e-12 ? s0 * s0 : 1e-24)) /
                    logvar_se(t->jit_kurt[g], nreg);
            }
            t->z[g][SG_TIM_JITTER] = z > SG_ZCAP ? SG_ZCAP : z;
            jitter_tails(lg, segs, g, T, res, z > gsl_cdf_ugaussian_Qinv(alpha / 3.0), tail, var);
            t->tail_drop[g] = tail[0];
            t->tail_dup[g] = tail[1];
            t->tail_drop_var[g] = var[0];
            t->tail_dup_var[g] = var[1];
        }
        t->z[g][SG_TIM_DUP] = tail_z(t->n_dup[g], t->tail_dup[g], t->tail_dup_var[g], 0);
        t->z[g][SG_TIM_DROP] = tail_z(t->n_drop[g], t->tail_drop[g], t->tail_drop_var[g], 0);
    }
    {
        double zc = gsl_cdf_ugaussian_Qinv(alpha / 3.0);
        long nif = t->n_int[SG_FIT] > 0 ? t->n_int[SG_FIT] : 1;
        double s0 = s0_ns * 1e-9;
        for (d = 0; d < SG_TIM_NKIND; d++) {
            t->sel[d] = t->z[SG_FULL][d] > zc;
            t->significant |= t->sel[d];
        }
        /* the rates beyond what the jitter's tails make */
        const double xdup = fmax(0.0, (double)t->n_dup[SG_FIT] - t->tail_dup[SG_FIT]);
        const double xdrop = fmax(0.0, (double)t->n_drop[SG_FIT] - t->tail_drop[SG_FIT]);
        t->dup_prob = xdup / (double)nif;
        t->drop_prob = xdrop / ((double)nif + xdrop);
        t->stamp_s = t->jit_sd[SG_FIT] > s0 ? sqrt(0.5 * (t->jit_sd[SG_FIT] * t->jit_sd[SG_FIT] - s0 * s0)) : 0.0;
        t->z_after[SG_TIM_DUP] = tail_z(t->n_dup[SG_HOLD], t->dup_prob * (double)t->n_int[SG_HOLD] +
                                                               t->tail_dup[SG_HOLD],
                                        t->tail_dup_var[SG_HOLD], 1);
        /* before each kept sample p / (1 - p) lost ones on average
         * (geometric): the held-out intervals expect the fit's drops per
         * interval, not p per interval (10 % too few at p = 0.1, +4.5 sigma
         * on a clean dropout log; test_timing_dropout_after) */
        t->z_after[SG_TIM_DROP] = tail_z(t->n_drop[SG_HOLD], xdrop / (double)nif * (double)t->n_int[SG_HOLD] +
                                                                  t->tail_drop[SG_HOLD],
                                         t->tail_drop_var[SG_HOLD], 1);
        {
            double ex = 2.0 * t->stamp_s * t->stamp_s + s0 * s0, sd = t->jit_sd[SG_HOLD];
            long nh = t->n_int[SG_HOLD] - t->n_dup[SG_HOLD];
            t->z_after[SG_TIM_JITTER] = (ex > 0.0 && sd > 0.0 && nh > 2)
                                            ? (log(sd * sd) - log(ex)) / logvar_se(t->jit_kurt[SG_HOLD], nh)
                                            : 0.0;
        }
        /* an effect whose fitted rate the held-out segment refutes (either
         * way: two-sided, in the same family of three) leaves a held-out
         * gap: the verdict's "explained" needs every held-out gap within
         * noise */
        t->z_crit = gsl_cdf_ugaussian_Qinv(alpha / 6.0);
        for (d = 0; d < SG_TIM_NKIND; d++) {
            t->open[d] = t->sel[d] && fabs(t->z_after[d]) > t->z_crit;
        }
    }
}

/* ------------------------------------------------------------ static */

typedef struct {
    double *v[SG_NSEG];   /**< S rows of values per segment */
    double *vx[SG_NSEG];  /**< parameter-uncertainty variance per point */
    double *sh[SG_NSEG];  /**< S rows: shift of each point's expectation by the refit to twin s */
} twinset_t;

static void twinset_free(twinset_t *t)
{
    int g;
    for (g = 0; g < SG_NSEG; g++) {
        free(t->v[g]);
        free(t->vx[g]);
        free(t->sh[g]);
        t->v[g] = NULL;
        t->vx[g] = NULL;
        t->sh[g] = NULL;
    }
}

/* The time points of a table weighted by the baseline twins' spread, as
 * their comparison measured it (once it exists: the baseline fit itself
 * has no drift to fit). */
static void table_weights(const sg_result_t *r, int ch, int g, sg_table_t *t)
{
    if (r->ch[ch].cmp[g].twin_sd != NULL) {
        sg_table_time_weights(t, r->ch[ch].cmp[g].twin_sd);
        sg_table_time_base(t, &r->ch[ch].baseline);
    }
}

/* Spread of the model's predictions when it is refitted on each twin's
 * fit segment: the sampling uncertainty of the fitted parameters, carried
 * into every point of every segment (a parametric bootstrap of the fit).
 * se_model (or NULL): the fitted model whose Allan standard errors become
 * the refits' spread of its parameters (sg_se_from_refits; reporting
 * only: the same refits, nothing else changes). */
static int param_var(const sg_result_t *r, int ch, const sg_chmodel_t *gen, const int *with, int nwith,
                     const sg_evidence_t *ev, double tmax, int gfit, twinset_t *t, sg_chmodel_t *se_model)
{
    const int S = r->S;
    const sg_plist_t *pl = r->pl[ch];
    const double fs = r->rate_hz;
    double t0[SG_NSEG][SG_MAX_BLK], t1[SG_NSEG][SG_MAX_BLK], *pred[SG_NSEG];
    int g, s, ok = 0, b;
    size_t j;
    sg_chmodel_t *fits = NULL;
    int *fit_ok = NULL;
    if (se_model != NULL) {
        fits = (sg_chmodel_t *)malloc((size_t)S * sizeof *fits);
        fit_ok = (int *)calloc((size_t)S, sizeof *fit_ok);
        if (fits == NULL || fit_ok == NULL) {
            free(fits);
            free(fit_ok);
            return -1;
        }
    }
    for (g = 0; g < SG_NSEG; g++) {
        for (b = 0; b < r->segs.nb[g]; b++) {
            t0[g][b] = (double)r->segs.start[g][b] / fs;
            t1[g][b] = (double)(r->segs.start[g][b] + r->segs.n[g][b]) / fs;
        }
        t->vx[g] = (double *)calloc(pl[g].n + 1, sizeof(double));
        pred[g] = (double *)malloc(((size_t)S * pl[g].n + 1) * sizeof(double));
        if (t->vx[g] == NULL || pred[g] == NULL) {
            for (; g >= 0; g--) {
                free(pred[g]);
            }
            free(fits);
            free(fit_ok);
            return -1;
        }
    }
    for (s = 0; s < S; s++) {
        sg_table_t tb;
        sg_fit_t f;
        sg_table_from(&pl[gfit], t->v[gfit] + (size_t)s * pl[gfit].n, ch, fs, &r->segs, gfit, &tb);
        table_weights(r, ch, gfit, &tb);
        if (sg_fit_model(&tb, gen->mean, with, nwith, ev, tmax, &f) != 0) {
            for (g = 0; g < SG_NSEG; g++) {
                for (j = 0; j < pl[g].n; j++) {
                    pred[g][(size_t)s * pl[g].n + j] = (double)NAN;
                }
            }
            continue;
        }
        ok++;
        if (fits != NULL) {
            fits[s] = f.model;
            fit_ok[s] = 1;
        }
        for (g = 0; g < SG_NSEG; g++) {
            for (j = 0; j < pl[g].n; j++) {
                pred[g][(size_t)s * pl[g].n + j] =
                    sg_model_lnstat(&f.model, &pl[g].p[j], fs, r->segs.nb[g], t0[g], t1[g]);
            }
        }
    }
    for (g = 0; g < SG_NSEG; g++) {
        for (j = 0; j < pl[g].n && ok >= 3; j++) {
            double m = 0.0, v = 0.0;
            int c = 0;
            for (s = 0; s < S; s++) {
                double x = pred[g][(size_t)s * pl[g].n + j];
                if (x == x) {
                    m += x;
                    c++;
                }
            }
            if (c < 3) {
                /* no analytic expectation (lattice, timing): no shift */
                for (s = 0; s < S; s++) {
                    pred[g][(size_t)s * pl[g].n + j] = 0.0;
                }
                continue;
            }
            m /= (double)c;
            for (s = 0; s < S; s++) {
                double x = pred[g][(size_t)s * pl[g].n + j];
                if (x == x) {
                    v += (x - m) * (x - m);
                }
            }
            t->vx[g][j] = v / (double)(c - 1);
            /* shifts relative to the generating model's expectation: the
             * fit's bias, if any, is part of the null as of the real */
            {
                double m0 = sg_model_lnstat(gen, &pl[g].p[j], fs, r->segs.nb[g], t0[g], t1[g]);
                if (!(m0 == m0)) {
                    m0 = m;
                }
                for (s = 0; s < S; s++) {
                    double x = pred[g][(size_t)s * pl[g].n + j];
                    pred[g][(size_t)s * pl[g].n + j] = (x == x) ? x - m0 : 0.0;
                }
            }
        }
        if (ok < 3) {
            memset(pred[g], 0, (size_t)S * pl[g].n * sizeof(double));
        }
        t->sh[g] = pred[g];
    }
    if (se_model != NULL) {
        sg_se_from_refits(se_model, fits, fit_ok, S);
    }
    free(fits);
    free(fit_ok);
    return 0;
}

static int twinset_run(const sg_chmodel_t *m, int ch, const sg_feat_cfg_t *fc, const sg_segs_t *segs, double q,
                       int S, uint32_t seed, sg_plist_t pl[SG_NSEG], twinset_t *t)
{
    int g;
    memset(t, 0, sizeof *t);
    for (g = 0; g < SG_NSEG; g++) {
        t->v[g] = (double *)calloc((size_t)S * (pl[g].n + 1), sizeof(double));
        if (t->v[g] == NULL) {
            twinset_free(t);
            return -1;
        }
    }
    if (sg_twin_static(m, ch, fc, segs, q, S, seed, pl, t->v) != 0) {
        twinset_free(t);
        return -1;
    }
    return 0;
}

static int cmp_all(const sg_plist_t pl[SG_NSEG], double *const real[SG_NSEG], const twinset_t *t, int S, double alpha,
                   sg_cmp_t cmp[SG_NSEG])
{
    int g;
    for (g = 0; g < SG_NSEG; g++) {
        if (sg_compare(&pl[g], real[g], t->v[g], S, t->vx[g], t->sh[g], alpha, &cmp[g]) != 0) {
            return -1;
        }
    }
    return 0;
}

double sg_fit_explained(double G_before, double null_mean, double G_after)
{
    /* no excess, no fraction of it (NaN: a 0 would read "explains
     * nothing") */
    return (G_before - null_mean) > 0.0 ? (G_before - G_after) / (G_before - null_mean) : (double)NAN;
}

/* Explained fraction of the held-out excess gap by going from twins a to
 * twins b (paired seeds), with a 68 % bootstrap interval (docs/simgap.md,
 * section 4). Each resample draws the twin seeds with replacement from all
 * but one seed r, and replaces the real by real + (b's twin r as a real,
 * minus the mean of b's twins as reals): a fresh realisation of the real
 * log's sampling noise under the model b, whose twins stand for new draws of
 * the real (as in sg_lr_test's null). Without that term the interval carried
 * only the twins' means' uncertainty and held the truth in 39 % of logs
 * (scripts/simgap_explained_coverage.py). The perturbed real carries its
 * noise twice, which biases the resampled fractions, so the interval is the
 * normal-theory one centred on the estimate, f +- se, se the half-distance
 * of the resamples' 16th and 84th percentiles (a robust bootstrap standard
 * error; Efron & Tibshirani 1993, ch. 6 and 12; Davison & Hinkley 1997,
 * sec. 5.2). */
void sg_explained(const sg_plist_t *pl, const double *real, const double *ta, const double *va, const double *sa,
                      const double *tb, const double *vb, const double *sb, int S, double null_mean, double null_sd,
                      double *f, double *lo, double *hi, uint32_t seed)
{
    enum { B = 200 };
    double fb[B], Ga, Gb, se;
    int idx[64], b, k, nb = 0;
    size_t j, n = pl->n;
    uint32_t st = seed * 2654435761u + 12345u;
    double *mb, *pr;
    const int S1 = S < 64 ? S : 64;
    for (k = 0; k < S1; k++) {
        idx[k] = k;
    }
    Ga = sg_gap_resampled(pl, real, ta, S, idx, S, va, sa);
    Gb = sg_gap_resampled(pl, real, tb, S, idx, S, vb, sb);
    /* a fraction of the excess only where there is an excess (two null sd) */
    if (!(Ga - null_mean > 2.0 * null_sd)) {
        *f = *lo = *hi = (double)NAN;
        return;
    }
    *f = (Ga - Gb) / (Ga - null_mean);
    mb = (double *)calloc(n + 1, sizeof *mb);
    pr = (double *)malloc((n + 1) * sizeof *pr);
    if (mb == NULL || pr == NULL || S1 < 3) {
        free(mb);
        free(pr);
        *lo = *hi = *f;
        return;
    }
    /* the mean of b's twins as reals (each minus its refit shift) */
    for (k = 0; k < S1; k++) {
        for (j = 0; j < n; j++) {
            mb[j] += tb[(size_t)k * n + j] - (sb != NULL ? sb[(size_t)k * n + j] : 0.0);
        }
    }
    for (j = 0; j < n; j++) {
        mb[j] /= (double)S1;
    }
    for (b = 0; b < B; b++) {
        double ga, gb;
        int r;
        st = st * 1664525u + 1013904223u;
        r = (int)((st >> 8) % (uint32_t)S1);
        /* the other seeds, with replacement (b's twin r shares a's seed r) */
        for (k = 0; k < S1; k++) {
            int m;
            st = st * 1664525u + 1013904223u;
            m = (int)((st >> 8) % (uint32_t)(S1 - 1));
            idx[k] = m < r ? m : m + 1;
        }
        for (j = 0; j < n; j++) {
            pr[j] = real[j] + tb[(size_t)r * n + j] - (sb != NULL ? sb[(size_t)r * n + j] : 0.0) - mb[j];
        }
        ga = sg_gap_resampled(pl, pr, ta, S, idx, S1, va, sa);
        gb = sg_gap_resampled(pl, pr, tb, S, idx, S1, vb, sb);
        if (ga - null_mean > 0.0) {
            fb[nb++] = (ga - gb) / (ga - null_mean);
        }
    }
    free(mb);
    free(pr);
    if (nb < 10) {
        *lo = *hi = *f;
        return;
    }
    /* sort and take the 16th and 84th percentiles */
    for (b = 1; b < nb; b++) {
        double v = fb[b];
        k = b - 1;
        while (k >= 0 && fb[k] > v) {
            fb[k + 1] = fb[k];
            k--;
        }
        fb[k + 1] = v;
    }
    se = 0.5 * (fb[(int)(0.84 * (double)(nb - 1))] - fb[(int)(0.16 * (double)(nb - 1))]);
    *lo = *f - se;
    *hi = *f + se;
}

/* Score test of adding an effect, on the held-out segment: the deviation
 * of the real from model a's twins projected on the effect's signature
 * (delta_j = twin mean of b - twin mean of a), T = sum_j delta_j d_j / D_j,
 * D_j the noise variance of point j (the matched filter, most powerful for
 * this alternative; linear, so its null is close to Gaussian). Its null
 * distribution comes from the twins of a taken as the real (with their
 * refit shifts), each against the other twins of a and b (its own seed
 * left out of both: b's twin of that seed shares its random numbers).
 * Returns z = (T_real - mean T_s) / sd T_s. */
double sg_score_test(const sg_plist_t *pl, const double *real, const sg_cmp_t *ca, const double *ta,
                         const double *sa, const double *tb, int S, double *t_real, double *t_mean, double *t_sd)
{
    size_t j, n = pl->n;
    int s, r;
    double sum = 0.0, sum2 = 0.0, T = 0.0, sd;
    double *ma = (double *)malloc((n + 1) * sizeof *ma), *mb = (double *)malloc((n + 1) * sizeof *mb);
    double *D = (double *)malloc((n + 1) * sizeof *D);
    if (ma == NULL || mb == NULL || D == NULL || S < 4) {
        free(ma);
        free(mb);
        free(D);
        return 0.0;
    }
    for (j = 0; j < n; j++) {
        ma[j] = mb[j] = 0.0;
        for (r = 0; r < S; r++) {
            ma[j] += ta[(size_t)r * n + j];
            mb[j] += tb[(size_t)r * n + j];
        }
        D[j] = ca->sd_tot[j] * ca->sd_tot[j];
        if (!(D[j] > 1e-24)) {
            D[j] = 1e-24;
        }
        T += (mb[j] - ma[j]) / (double)S * (real[j] - ma[j] / (double)S) / D[j];
    }
    for (s = 0; s < S; s++) {
        double Ts = 0.0;
        for (j = 0; j < n; j++) {
            double a1 = (ma[j] - ta[(size_t)s * n + j]) / (double)(S - 1);
            double b1 = (mb[j] - tb[(size_t)s * n + j]) / (double)(S - 1);
            double ps = ta[(size_t)s * n + j] - (sa != NULL ? sa[(size_t)s * n + j] : 0.0);
            Ts += (b1 - a1) * (ps - a1) / D[j];
        }
        sum += Ts;
        sum2 += Ts * Ts;
    }
    free(ma);
    free(mb);
    free(D);
    *t_real = T;
    *t_mean = sum / (double)S;
    sd = sqrt((sum2 - sum * sum / (double)S) / (double)(S - 1));
    *t_sd = sd;
    /* the real is a new draw against the mean and sd of S: (T - mean) /
     * (sd sqrt(1 + 1/S)) is the statistic that follows Student's t with
     * S - 1 degrees of freedom (without the factor the test would reject
     * 1.27 times as often as its level at S = 16) */
    return sd > 0.0 ? (T - *t_mean) / (sd * sqrt(1.0 + 1.0 / (double)S)) : 0.0;
}

/* An effect's standard errors without twins to refit: the Allan fit's
 * (sg_effect_t.se_allan) are unknown. */
static void se_without_twins(sg_effect_t *e)
{
    int k;
    for (k = 0; k < SG_MAX_PAR; k++) {
        if (e->se_allan[k]) {
            e->se[k] = (double)NAN;
            e->se_allan[k] = 0;
        }
    }
}

/* The static effects the diagnosis can fit. */
static const int k_static_cands[] = { FNAV_EFFECT_QUANT,   FNAV_EFFECT_VIBRATION, FNAV_EFFECT_FLICKER,
                                      FNAV_EFFECT_RRW,     FNAV_EFFECT_RAMP,      FNAV_EFFECT_THERMAL,
                                      FNAV_EFFECT_JUMPS };
#define N_STATIC_CANDS ((int)(sizeof k_static_cands / sizeof k_static_cands[0]))

/* Least improvement of the fit segment's Allan objective for a candidate to
 * be simulated and tested on the held-out segment. */
#define SG_DQ_TEST 6.0

/* Index of an effect's magnitude parameter. */
static int mag_index(int id)
{
    return id == FNAV_EFFECT_JUMPS ? 1 : 0;
}

void sg_prune_zero(sg_chres_t *c)
{
    /* an effect accepted at one step can be refitted to nothing once later
     * effects join (jumps at 0.00875 m/s^2, then 0 beside vibration and
     * flicker): it explains none of the final model's gap and is no
     * answer */
    int j, kept = 0;
    for (j = 0; j < c->nsel; j++) {
        const int m = sg_model_find(&c->final, c->sel_id[j]);
        if (m >= 0 && c->final.e[m].p[mag_index(c->sel_id[j])] == 0.0) {
            c->zero_id[c->nzero++] = c->sel_id[j];
            continue;
        }
        c->sel_id[kept] = c->sel_id[j];
        c->sel_expl[kept] = c->sel_expl[j];
        c->sel_lo[kept] = c->sel_lo[j];
        c->sel_hi[kept] = c->sel_hi[j];
        kept++;
    }
    c->nsel = kept;
}

int sg_ar1_at_max(const sg_chres_t *c)
{
    const int ia = sg_model_find(&c->baseline, FNAV_EFFECT_AR1);
    return c->active && ia >= 0 && c->baseline.e[ia].p[1] > 0.0 && c->ar1_tau_max_s > 0.0 &&
           c->baseline.e[ia].p[0] >= 0.999 * c->ar1_tau_max_s;
}

/* Which candidate effects have the evidence they need. */
static int cand_eligible(int id, const sg_evidence_t *ev, double zc)
{
    switch (id) {
    case FNAV_EFFECT_QUANT: return ev->q > 0.0 && ev->q_z > zc;
    case FNAV_EFFECT_VIBRATION: return ev->tone_score > 3.0 && ev->tone_hz > 0.0;
    case FNAV_EFFECT_JUMPS: return ev->nsteps >= 1;
    default: return 1;
    }
}

/* Longest AR(1) correlation time of the baseline: its Allan bump (at
 * 1.89 T) and the fall after it must lie inside the tau range of both the
 * fit and the held-out analysis; longer correlations are random-walk-like
 * over the record (sigma and T trade off along sigma^2 / T) and belong to
 * the catalogue (rrw, flicker, ramp), where the held-out test judges them. */
static double fit_tmax(const sg_result_t *r, int ch)
{
    int g;
    double t = INFINITY;
    for (g = SG_FIT; g <= SG_HOLD; g++) {
        const sg_plist_t *pl = &r->pl[ch][g];
        const double lim = SG_ID_FRAC * (double)sg_segs_minblock(&r->segs, g) / r->rate_hz * (1.0 + 1e-9);
        size_t j;
        double tmax = 0.0;
        for (j = 0; j < pl->n; j++) {
            if (pl->p[j].dom == SG_ALLAN && pl->p[j].x <= lim && pl->p[j].x > tmax) {
                tmax = pl->p[j].x;
            }
        }
        t = tmax < t ? tmax : t;
    }
    /* the bump at 1.89 T and the fall after it (slope -1/2, what tells a
     * Gauss-Markov bias from a random walk) inside the range: T <= tau_max / 4 */
    return t / 4.0;
}

/* A fold without evidence for the candidate: its scores and gains are 0. */
static int no_evidence(double *z, double *dG, double *zg, double *dL)
{
    *z = 0.0;
    *dG = 0.0;
    *zg = 0.0;
    *dL = 0.0;
    return 0;
}

/* The second fold of a sandwich split: the candidate model (current
 * effects plus one, ids `with`) fitted on the middle (table tm; a walk's K
 * by the likelihood of the middle's samples of x) and tested
 * on the ends, which the first fold fitted on. The reference is the
 * current model's twins (fitted on the ends, their refit shifts on the
 * ends included, so twins taken as the real are treated as the real was);
 * the candidate's twins share their seeds. Gives the score test's z on the
 * ends and the ends' gap reduction. Returns 0, or -1 when the fold could
 * not be computed. */
static int fold_ends(sg_result_t *r, int ch, const double *x, const sg_feat_cfg_t *fc, const sg_table_t *tm,
                     const int *with, int nwith, double tmax, double alpha, uint32_t seed, const twinset_t *cur,
                     const sg_cmp_t ccur[SG_NSEG], const sg_cand_t *cd, double *z, double *dG, double *zg,
                     double *dL)
{
    const sg_chres_t *c = &r->ch[ch];
    const int S = r->opts.seeds;
    sg_fit_t f;
    twinset_t ts;
    sg_cmp_t cc;
    double tr, tmn, tsd;
    int k;
    if (!cand_eligible(cd->id, &c->ev_mid, c->cmp[SG_FULL].z_crit)) {
        /* the middle holds no line, no step or no lattice of its own: no
         * evidence from this fold (its fit must not borrow the ends'
         * evidence, which this fold tests on) */
        return no_evidence(z, dG, zg, dL);
    }
    if (sg_fit_model(tm, c->baseline.mean, with, nwith, &c->ev_mid, tmax, &f) != 0) {
        return -1;
    }
    if (cd->id != FNAV_EFFECT_QUANT && cd->id != FNAV_EFFECT_VIBRATION) {
        /* The first fold chose to simulate the candidate because the ends
         * support it, and this fold tests on the ends: under no effect that
         * choice leans this fold's test towards the candidate. So this fold
         * counts only when the middle supports the candidate by the same
         * rule (objective lower by SG_DQ_TEST; a lattice or a line is
         * simulated on its own evidence, which cand_eligible above took
         * from the middle); then the two folds' choices agree and the lean
         * is confined to candidates both parts favour. */
        sg_fit_t fc0;
        double dq, dq_drift;
        if (sg_fit_model(tm, c->baseline.mean, with, nwith - 1, &c->ev_mid, tmax, &fc0) != 0) {
            return -1;
        }
        dq = (fc0.Q + fc0.Q_time) - (f.Q + f.Q_time);
        dq_drift = (fc0.Q + fc0.Q_time_drift) - (f.Q + f.Q_time_drift);
        if (!((dq_drift > dq ? dq_drift : dq) > SG_DQ_TEST)) {
            return no_evidence(z, dG, zg, dL);
        }
    }
    k = sg_model_find(&f.model, cd->id);
    if (k >= 0 && (cd->id == FNAV_EFFECT_FLICKER || cd->id == FNAV_EFFECT_RRW) && !(f.model.e[k].p[0] > 0.0) &&
        cd->eff.p[0] > 0.0) {
        /* the middle's few long-tau Allan points put a random drift at
         * zero more often than its samples do: its magnitude is then
         * fitted by the middle's likelihood (flicker by its block means, a
         * walk by the exact filter), started from fold 1's; without a
         * likelihood it stays zero */
        double q2;
        f.model.e[k].p[0] = cd->eff.p[0];
        if ((cd->id == FNAV_EFFECT_FLICKER ? sg_bm_fit(x, &r->segs, SG_HOLD, r->rate_hz, &f.model, cd->id, &q2)
                                           : sg_rrw_ml(x, &r->segs, SG_HOLD, r->rate_hz, &f.model)) != 0) {
            f.model.e[k].p[0] = 0.0;
        }
    } else {
        (void)sg_rrw_ml(x, &r->segs, SG_HOLD, r->rate_hz, &f.model);
    }
    if (k < 0 || !(f.model.e[k].p[mag_index(cd->id)] != 0.0)) {
        /* the middle shows none of it: no evidence from this fold */
        return no_evidence(z, dG, zg, dL);
    }
    if (twinset_run(&f.model, ch, fc, &r->segs, c->q_full, S, seed, r->pl[ch], &ts) != 0) {
        return -1;
    }
    if (param_var(r, ch, &f.model, with, nwith, &c->ev_mid, tmax, SG_HOLD, &ts, NULL) != 0) {
        twinset_free(&ts);
        return -1;
    }
    memset(&cc, 0, sizeof cc);
    if (sg_compare(&r->pl[ch][SG_FIT], r->real[ch][SG_FIT], ts.v[SG_FIT], S, ts.vx[SG_FIT], ts.sh[SG_FIT], alpha,
                   &cc) != 0) {
        twinset_free(&ts);
        return -1;
    }
    *dG = ccur[SG_FIT].G - cc.G;
    *z = sg_score_test(&r->pl[ch][SG_FIT], r->real[ch][SG_FIT], &ccur[SG_FIT], cur->v[SG_FIT], cur->sh[SG_FIT],
                       ts.v[SG_FIT], S, &tr, &tmn, &tsd);
    *zg = sg_lr_test(&r->pl[ch][SG_FIT], r->real[ch][SG_FIT], cur->v[SG_FIT], cur->vx[SG_FIT], cur->sh[SG_FIT],
                     ts.v[SG_FIT], ts.vx[SG_FIT], ts.sh[SG_FIT], S, dL);
    sg_cmp_free(&cc);
    twinset_free(&ts);
    return 0;
}

double sg_accept_zcrit(double alpha, int seeds)
{
    /* each simulated candidate is two tests (score and likelihood ratio, either
     * may accept): Bonferroni over the two, the channels and
     * about five candidates each; the null's spread comes from S twins, so
     * the quantile is Student's with S - 1 degrees of freedom */
    return gsl_cdf_tdist_Qinv(alpha / (double)(SG_NCH * 5 * 2), (double)(seeds - 1));
}

int sg_cand_accepted(const sg_cand_t *cd, double zacc)
{
    return (cd->z_delta > zacc || cd->z_gap > zacc) && !(cd->expl_lo <= 0.0);
}

int sg_selection_stops(int step, int held_significant)
{
    return step > 0 && !held_significant;
}

int sg_thermal_nested(double q_ramp, double q_thermal)
{
    const double qr = q_ramp, qt = q_thermal;
    return qr == qr && qt == qt && qr - qt < gsl_cdf_chisq_Qinv(0.01, 1.0);
}

void sg_cand_fold2(sg_cand_t *cd, double zb, double dGb, double zgb, double dLb)
{
    cd->z_ends = zb;
    cd->dG_ends = dGb;
    cd->zg_ends = zgb;
    cd->dL_ends = dLb;
    cd->dL_rank += dLb;
    cd->z_delta = (cd->z_mid + zb) / sqrt(2.0);
    cd->z_gap = (cd->zg_mid + zgb) / sqrt(2.0);
}

/* Forward selection on one channel. */
static int attribute(sg_result_t *r, int ch, const double *x, const sg_feat_cfg_t *fc, const sg_table_t *tab,
                     double alpha, hx_progress_t *prog, double *pdone)
{
    sg_chres_t *c = &r->ch[ch];
    const sg_opts_t *o = &r->opts;
    const int S = o->seeds;
    twinset_t cur;
    sg_cmp_t ccur[SG_NSEG];
    int with[SG_MAX_EFF], nwith = 0, step, g, i;
    double zc = c->cmp[SG_FULL].z_crit;
    const double zacc = sg_accept_zcrit(r->opts.alpha, r->opts.seeds);
    const double tmax = fit_tmax(r, ch);
    uint32_t seed = o->seed + 1000u * (uint32_t)ch;
    memset(&cur, 0, sizeof cur);
    /* the baseline twins are the current ones */
    for (g = 0; g < SG_NSEG; g++) {
        cur.v[g] = (double *)malloc((size_t)S * (r->pl[ch][g].n + 1) * sizeof(double));
        cur.vx[g] = (double *)malloc((r->pl[ch][g].n + 1) * sizeof(double));
        cur.sh[g] = (double *)malloc((size_t)S * (r->pl[ch][g].n + 1) * sizeof(double));
        if (cur.v[g] == NULL || cur.vx[g] == NULL || cur.sh[g] == NULL) {
            twinset_free(&cur);
            return -1;
        }
        memcpy(cur.v[g], r->twin[ch][g], (size_t)S * r->pl[ch][g].n * sizeof(double));
        memcpy(cur.vx[g], r->vx[ch][g], r->pl[ch][g].n * sizeof(double));
        memcpy(cur.sh[g], r->sh[ch][g], (size_t)S * r->pl[ch][g].n * sizeof(double));
        if (sg_compare(&r->pl[ch][g], r->real[ch][g], cur.v[g], S, cur.vx[g], cur.sh[g], alpha, &ccur[g]) != 0) {
            twinset_free(&cur);
            return -1;
        }
    }
    c->final = c->baseline;
    for (step = 0; step < o->max_steps; step++) {
        sg_step_t *st = &c->step[step];
        int order[N_STATIC_CANDS], nord = 0, best = -1, k, th_nested, nskip = 0;
        double bestdL = 0.0;
        twinset_t bestset;
        sg_cmp_t bestcmp[SG_NSEG];
        sg_fit_t curfit;
        sg_table_t tabm;
        memset(st, 0, sizeof *st);
        memset(&bestset, 0, sizeof bestset);
        memset(bestcmp, 0, sizeof bestcmp);
        st->selected = -1;
        st->G_hold_before = ccur[SG_HOLD].G;
        st->G_fit_before = ccur[SG_FIT].G;
        if (sg_selection_stops(step, ccur[SG_HOLD].significant)) {
            break;
        }
        (void)zacc;
        if (r->segs.sandwich) {
            sg_table_from(&r->pl[ch][SG_HOLD], r->real[ch][SG_HOLD], ch, r->rate_hz, &r->segs, SG_HOLD, &tabm);
            table_weights(r, ch, SG_HOLD, &tabm);
        }
        if (sg_fit_model(tab, c->baseline.mean, with, nwith, &c->ev, tmax, &curfit) != 0) {
            break;
        }
        /* parsimony between nested drifts: a warm-up is a ramp plus
         * curvature (a ramp is its long-time-constant limit); when the fit
         * segment's trends, curvatures and level do not need the curvature
         * (the warm-up's fit beats the ramp's by less than chi-square_1 at
         * 1 %), the warm-up is not simulated: the ramp stands for it */
        th_nested = sg_thermal_nested(sg_time_fit_q(tab, 0), sg_time_fit_q(tab, 1));
        /* fit every eligible candidate on the fit segment */
        for (i = 0; i < N_STATIC_CANDS; i++) {
            int id = k_static_cands[i], w2[SG_MAX_EFF];
            sg_fit_t f;
            sg_cand_t *cd;
            if (sg_model_find(&c->final, id) >= 0 || !cand_eligible(id, &c->ev, zc) || nwith + 1 >= SG_MAX_EFF) {
                continue;
            }
            memcpy(w2, with, (size_t)nwith * sizeof *w2);
            w2[nwith] = id;
            if (sg_fit_model(tab, c->baseline.mean, w2, nwith + 1, &c->ev, tmax, &f) != 0) {
                continue;
            }
            cd = &st->cand[st->ncand++];
            memset(cd, 0, sizeof *cd);
            cd->id = id;
            cd->eff = f.model.e[sg_model_find(&f.model, id)];
            /* a candidate gets the standard errors of its Allan-fitted
             * parameters from its twins' refits when it is simulated (below);
             * one that is not has no twins: no standard error (the Allan
             * fit's own is too small, docs/simgap.md, section 3) */
            se_without_twins(&cd->eff);
            /* ranked by the Allan objective; the time points join only
             * the threshold, read two ways, either of which lets a
             * candidate be simulated (the held-out tests judge it): their
             * deviance with the variance the model's slow random parts add
             * (a random walk that tilts the blocks) and their residual in
             * the baseline twins' variances (a drift, also after a random
             * drift has been selected, whose variance the deviance would
             * credit with the trends the drift explains) */
            cd->Q_fit = f.Q;
            cd->dQ_fit = (curfit.Q + curfit.Q_time) - (f.Q + f.Q_time);
            {
                const double dq_drift = (curfit.Q + curfit.Q_time_drift) - (f.Q + f.Q_time_drift);
                cd->dQ_fit = dq_drift > cd->dQ_fit ? dq_drift : cd->dQ_fit;
            }
            cd->nested = id == FNAV_EFFECT_THERMAL && th_nested;
            cd->expl_hold = cd->expl_lo = cd->expl_hi = (double)NAN;
            cd->G_fit = cd->G_hold = (double)NAN;
            order[nord++] = st->ncand - 1;
        }
        /* prescreen: lattice and line candidates always; the others by the
         * improvement of the fit-segment objective */
        for (i = 1; i < nord; i++) {
            int v = order[i];
            k = i - 1;
            while (k >= 0) {
                const sg_cand_t *a = &st->cand[order[k]], *b = &st->cand[v];
                int pa = (a->id == FNAV_EFFECT_QUANT || a->id == FNAV_EFFECT_VIBRATION);
                int pb = (b->id == FNAV_EFFECT_QUANT || b->id == FNAV_EFFECT_VIBRATION);
                if (pa > pb || (pa == pb && a->Q_fit <= b->Q_fit)) {
                    break;
                }
                order[k + 1] = order[k];
                k--;
            }
            order[k + 1] = v;
        }
        for (i = 0; i < nord; i++) {
            sg_cand_t *cd = &st->cand[order[i]];
            int pri = (cd->id == FNAV_EFFECT_QUANT || cd->id == FNAV_EFFECT_VIBRATION);
            int w2[SG_MAX_EFF];
            sg_fit_t f;
            twinset_t ts;
            sg_cmp_t cc[SG_NSEG];
            double dG;
            /* a candidate is tested on the held-out segment when the fit
             * segment supports it (objective lower by SG_DQ_TEST) */
            if (cd->nested) {
                nskip++; /* the ramp stands for it; its prescreen place goes to the next */
                continue;
            }
            if (!pri && (i - nskip >= o->prescreen + (c->ev.q_z > zc) + (c->ev.tone_score > 3.0) ||
                         !(cd->eff.p[mag_index(cd->id)] != 0.0) || !(cd->dQ_fit > SG_DQ_TEST))) {
                continue;
            }
            memcpy(w2, with, (size_t)nwith * sizeof *w2);
            w2[nwith] = cd->id;
            if (sg_fit_model(tab, c->baseline.mean, w2, nwith + 1, &c->ev, tmax, &f) != 0) {
                continue;
            }
            if (sg_rrw_ml(x, &r->segs, SG_FIT, r->rate_hz, &f.model) == 0) {
                cd->eff = f.model.e[sg_model_find(&f.model, cd->id)];
            }
            if (twinset_run(&f.model, ch, fc, &r->segs, c->q_full, S, seed, r->pl[ch], &ts) != 0) {
                continue;
            }
            if (param_var(r, ch, &f.model, w2, nwith + 1, &c->ev, tmax, SG_FIT, &ts, &f.model) != 0) {
                twinset_free(&ts);
                continue;
            }
            /* its standard errors now from its twins' refits */
            cd->eff = f.model.e[sg_model_find(&f.model, cd->id)];
            memset(cc, 0, sizeof cc);
            {
                sg_plist_t *pls = r->pl[ch];
                double **rv = r->real[ch];
                if (cmp_all(pls, rv, &ts, S, alpha, cc) != 0) {
                    twinset_free(&ts);
                    continue;
                }
                cd->simulated = 1;
                cd->G_fit = cc[SG_FIT].G;
                cd->G_hold = cc[SG_HOLD].G;
                sg_explained(&pls[SG_HOLD], rv[SG_HOLD], cur.v[SG_HOLD], cur.vx[SG_HOLD], cur.sh[SG_HOLD], ts.v[SG_HOLD],
                          ts.vx[SG_HOLD], ts.sh[SG_HOLD], S,
                          ccur[SG_HOLD].null_mean, ccur[SG_HOLD].null_sd,
                          &cd->expl_hold, &cd->expl_lo, &cd->expl_hi, seed + (uint32_t)cd->id);
                cd->expl_fit = sg_fit_explained(ccur[SG_FIT].G, ccur[SG_FIT].null_mean, cc[SG_FIT].G);
                cd->z_delta = sg_score_test(&pls[SG_HOLD], rv[SG_HOLD], &ccur[SG_HOLD], cur.v[SG_HOLD], cur.sh[SG_HOLD],
                                         ts.v[SG_HOLD], S, &cd->t_hold, &cd->t_null_mean, &cd->t_null_sd);
                cd->zg_mid = sg_lr_test(&pls[SG_HOLD], rv[SG_HOLD], cur.v[SG_HOLD], cur.vx[SG_HOLD], cur.sh[SG_HOLD],
                                        ts.v[SG_HOLD], ts.vx[SG_HOLD], ts.sh[SG_HOLD], S, &cd->dL_mid);
            }
            dG = ccur[SG_HOLD].G - cd->G_hold;
            cd->dG_hold = dG;
            cd->z_mid = cd->z_delta;
            cd->z_ends = cd->dG_ends = cd->zg_ends = cd->dL_ends = (double)NAN;
            cd->z_gap = cd->zg_mid;
            cd->dL_rank = cd->dL_mid;
            if (r->segs.sandwich) {
                /* second fold: fit on the middle, held out the ends */
                double zb = 0.0, dGb = 0.0, zgb = 0.0, dLb = 0.0;
                if (fold_ends(r, ch, x, fc, &tabm, w2, nwith + 1, tmax, alpha, seed, &cur, ccur, cd, &zb, &dGb, &zgb,
                              &dLb) == 0) {
                    sg_cand_fold2(cd, zb, dGb, zgb, dLb);
                    dG += dGb;
                }
            }
            cd->dG_rank = dG;
            if (prog != NULL) {
                *pdone += cd->z_ends == cd->z_ends ? 2.0 : 1.0;
                hx_progress_update(prog, *pdone);
            }
            /* accepted only with a held-out gain beyond what twins without
             * the effect show (z_delta) and beyond the seed noise */
            if (cd->dL_rank > bestdL && sg_cand_accepted(cd, zacc)) {
                if (best >= 0) {
                    twinset_free(&bestset);
                    for (g = 0; g < SG_NSEG; g++) {
                        sg_cmp_free(&bestcmp[g]);
                    }
                }
                best = order[i];
                bestdL = cd->dL_rank;
                bestset = ts;
                memcpy(bestcmp, cc, sizeof cc);
                c->final = f.model;
            } else {
                twinset_free(&ts);
                for (g = 0; g < SG_NSEG; g++) {
                    sg_cmp_free(&cc[g]);
                }
            }
        }
        c->nsteps = step + 1;
        if (best < 0) {
            break;
        }
        st->selected = best;
        c->sel_id[c->nsel] = st->cand[best].id;
        c->sel_expl[c->nsel] = st->cand[best].expl_hold;
        c->sel_lo[c->nsel] = st->cand[best].expl_lo;
        c->sel_hi[c->nsel] = st->cand[best].expl_hi;
        c->nsel++;
        with[nwith++] = st->cand[best].id;
        twinset_free(&cur);
        cur = bestset;
        for (g = 0; g < SG_NSEG; g++) {
            sg_cmp_free(&ccur[g]);
            ccur[g] = bestcmp[g];
        }
    }
    sg_prune_zero(c);
    c->within_noise = !ccur[SG_HOLD].significant;
    for (g = 0; g < SG_NSEG; g++) {
        c->cmp_final[g] = ccur[g];
        r->twin_final[ch][g] = cur.v[g];
        r->vx_final[ch][g] = cur.vx[g];
        r->sh_final[ch][g] = cur.sh[g];
    }
    return 0;
}

void sg_locate_into(const sg_plist_t *pl, int ch, int seg, const sg_cmp_t *c, sg_loc_t *loc, size_t *nloc,
                    size_t cap, size_t *dropped)
{
    size_t j = 0;
    while (j < pl->n) {
        size_t k = j, best = j;
        double sgn = c->z[j] > 0.0 ? 1.0 : -1.0;
        if (fabs(c->z[j]) <= 2.5) {
            j++;
            continue;
        }
        while (k < pl->n && pl->p[k].dom == pl->p[j].dom && fabs(c->z[k]) > 2.5 && c->z[k] * sgn > 0.0 &&
               (pl->p[k].dom != SG_TIME || pl->p[k].kind == pl->p[j].kind)) {
            if (fabs(c->z[k]) > fabs(c->z[best])) {
                best = k;
            }
            k++;
        }
        if (fabs(c->z[best]) > c->z_crit && *nloc >= cap) {
            ++*dropped;
        } else if (fabs(c->z[best]) > c->z_crit) {
            sg_loc_t *L = &loc[(*nloc)++];
            /* the deviation behind z (after the parameter-uncertainty
             * correction), so that the ratio agrees with z's sign: the raw
             * real - twin mean would print "34.9 sigma below the twin (ADEV
             * x1.11)" on a vibration log */
            double d = c->dev[best];
            L->dom = pl->p[j].dom;
            L->ch = ch;
            L->seg = seg;
            L->kind = pl->p[j].dom == SG_TIME ? pl->p[j].kind : 0;
            L->x_lo = pl->p[j].x_lo;
            L->x_hi = pl->p[k - 1].x_hi;
            if (L->dom == SG_TIME && L->kind == SG_TIME_STEP && pl->p[best].t_peak_hi > pl->p[best].t_peak_lo) {
                /* a step or transient: where in the block it is, not the
                 * block ("t 0-600 s" for 0.5 s at 300 s) */
                L->x_lo = pl->p[best].t_peak_lo;
                L->x_hi = pl->p[best].t_peak_hi;
            }
            L->peak_z = c->z[best];
            /* Allan and PSD values are logs of variances: the ratio of deviations */
            L->ratio = (L->dom == SG_ALLAN || L->dom == SG_PSD) ? exp(0.5 * d) : d;
            L->npts = (int)(k - j);
        }
        j = k > j ? k : j + 1;
    }
}

static void locate(sg_result_t *r, int ch, int seg)
{
    sg_locate_into(&r->pl[ch][seg], ch, seg, &r->ch[ch].cmp[seg], r->loc, &r->nloc, sizeof r->loc / sizeof r->loc[0],
                   &r->nloc_dropped);
}

/* The given profile's white + AR(1) model of channel ch (not fitted). */
static void profile_model(const fnav_profile_t *p, int ch, double mean, sg_chmodel_t *m)
{
    memset(m, 0, sizeof *m);
    m->mean = mean;
    m->n = 2;
    m->e[0].id = FNAV_EFFECT_WHITE;
    m->e[1].id = FNAV_EFFECT_AR1;
    m->e[0].p[0] = ch < 3 ? (double)p->accel_noise_mps2_rthz[ch] : (double)p->gyro_noise_rps_rthz[ch - 3];
    m->e[1].p[0] = ch < 3 ? (double)p->accel_tau_s[ch] : (double)p->gyro_tau_s[ch - 3];
    m->e[1].p[1] = ch < 3 ? (double)p->accel_bias_sigma_mps2[ch] : (double)p->gyro_bias_sigma_rps[ch - 3];
    m->e[0].se[0] = m->e[1].se[0] = m->e[1].se[1] = (double)NAN;
}

/* Real features of the three segments of one channel. */
static int real_features(const double *x, const sg_segs_t *segs, const sg_feat_cfg_t *fc, double q, int ch,
                         sg_plist_t pl[SG_NSEG], double *vals[SG_NSEG])
{
    int g, b;
    for (g = 0; g < SG_NSEG; g++) {
        sg_segacc_t a;
        long k, cnt;
        size_t cap = 512;
        if (sg_segacc_init(&a, fc, segs, g, q) != 0) {
            return -1;
        }
        for (b = 0; b < segs->nb[g]; b++) {
            for (k = 0; k < segs->n[g][b]; k++) {
                sg_segacc_push(&a, b, x[segs->start[g][b] + k]);
            }
        }
        vals[g] = (double *)malloc(cap * sizeof(double));
        if (vals[g] == NULL) {
            sg_segacc_free(&a);
            return -1;
        }
        cnt = sg_segacc_finish(&a, ch, &pl[g], vals[g], cap);
        sg_segacc_free(&a);
        if (cnt < 0) {
            return -1;
        }
    }
    return 0;
}

/* Whether x holds one value over each block of segment g (no Allan point
 * there; *v the first block's value). */
static int seg_one_value(const double *x, const sg_segs_t *segs, int g, double *v)
{
    int b;
    long k;
    if (segs->nb[g] < 1 || segs->n[g][0] < 1) {
        return 0;
    }
    *v = x[segs->start[g][0]];
    for (b = 0; b < segs->nb[g]; b++) {
        for (k = segs->start[g][b] + 1; k < segs->start[g][b] + segs->n[g][b]; k++) {
            if (x[k] != x[segs->start[g][b]]) {
                return 0;
            }
        }
    }
    return 1;
}

static int diagnose_static(const hx_log_t *log, sg_result_t *r, char *err, size_t err_size)
{
    const sg_opts_t *o = &r->opts;
    const int S = o->seeds;
    sg_feat_cfg_t fc = sg_feat_cfg_default(r->rate_hz);
    double *x = NULL;
    /* Bonferroni over the channels and the four tests of each (G and max |z|,
     * whole log and held-out segment) */
    double alpha = o->alpha / (double)(SG_NCH * 4);
    int ch, g, have_prof = 0, nact = 0;
    hx_progress_t progs, *prog = o->quiet ? NULL : &progs;
    double done = 0.0, budget, share;
    fnav_profile_t prof;
    if (o->profile != NULL) {
        char e2[256];
        if (hx_profile_load(o->profile, &prof, e2, sizeof e2) != 0) {
            snprintf(err, err_size, "%s", e2);
            return -1;
        }
        have_prof = 1;
        snprintf(r->prof_name, sizeof r->prof_name, "%s", prof.name[0] != '\0' ? prof.name : o->profile);
    }
    x = (double *)malloc(r->n * sizeof *x);
    if (x == NULL) {
        snprintf(err, err_size, "out of memory");
        return -1;
    }
    /* progress: a unit per channel for its features, then per channel a
     * budget of its baseline and at most lattice + line + the prescreen's
     * candidates per step, each simulated twice with the sandwich split's
     * second fold; a channel that needs less jumps to the end of its share
     * when it is done (an estimate of about four candidates per channel in
     * all reached 100 % a third into a one-hour log's run) */
    for (ch = 0; ch < SG_NCH; ch++) {
        nact += !r->constant[ch];
    }
    budget = 1.0 + (double)o->max_steps * (double)(o->prescreen + 2) * (r->segs.sandwich ? 2.0 : 1.0);
    if (prog != NULL) {
        hx_progress_start(prog, "simgap", (double)nact * (1.0 + budget));
    }
    r->confident = 1;
    /* first every channel's features and whether the log supports a
     * confident answer on it, so that a channel too short for one stops the
     * attribution of every channel, not of those after it only */
    for (ch = 0; ch < SG_NCH; ch++) {
        sg_chres_t *c = &r->ch[ch];
        sg_table_t tfit, thold;
        size_t k;
        if (r->constant[ch]) {
            continue; /* nothing to test: not analysed (constant_channels) */
        }
        for (k = 0; k < (size_t)r->n; k++) {
            x[k] = ch < 3 ? log->acc[k][ch] : log->gyr[k][ch - 3];
        }
        /* one value over the fit or the held-out segment: nothing to fit
         * or to test there, which is not a log too short (as one, it would
         * be answered "fewer than 4 Allan points" or "within +-25 % over
         * only 0 decades", and stop the attribution of every channel) */
        for (g = SG_FIT; g <= SG_HOLD && !r->seg_constant[ch]; g++) {
            if (seg_one_value(x, &r->segs, g, &r->seg_constant_value[ch])) {
                r->seg_constant[ch] = g;
            }
        }
        if (r->seg_constant[ch]) {
            hx_warn("simgap", "%s: channel %s does not vary within the %s segment (%.6g %s at its start): stuck "
                              "there, or its noise is below the output's step; not analysed",
                    r->path, sg_channel_name(ch), r->seg_constant[ch] == SG_FIT ? "fit" : "held-out",
                    r->seg_constant_value[ch], sg_channel_unit(ch));
            done += 1.0 + budget;
            continue;
        }
        c->q_full = sg_lattice_step(x, r->n, &c->q_full_z);
        /* the lattice domain exists only where the values lie on one */
        if (!(c->q_full_z > gsl_cdf_ugaussian_Qinv(0.5 * alpha))) {
            c->q_full = 0.0;
        }
        if (real_features(x, &r->segs, &fc, c->q_full, ch, r->pl[ch], r->real[ch]) != 0) {
            snprintf(err, err_size, "feature extraction failed (memory)");
            free(x);
            return -1;
        }
        sg_table_from(&r->pl[ch][SG_FIT], r->real[ch][SG_FIT], ch, r->rate_hz, &r->segs, SG_FIT, &tfit);
        sg_table_from(&r->pl[ch][SG_HOLD], r->real[ch][SG_HOLD], ch, r->rate_hz, &r->segs, SG_HOLD, &thold);
        /* confident answer: the held-out segment must give tight intervals
         * (ADEV within about +-25 %, i.e. sd(ln AVAR) <= 0.5) over a decade */
        {
            double tlo = INFINITY, thi = 0.0;
            for (k = 0; k < thold.n; k++) {
                double var = 1.0 / thold.w[k] - SG_FIT_FLOOR * SG_FIT_FLOOR;
                if (var <= 0.25) {
                    double tau = thold.m[k] / r->rate_hz;
                    tlo = tau < tlo ? tau : tlo;
                    thi = tau > thi ? tau : thi;
                }
            }
            r->tau_span_dec[ch] = thi > 0.0 ? log10(thi / tlo) : 0.0;
            if (r->tau_span_dec[ch] < 1.0) {
                r->confident = 0;
                snprintf(r->why, sizeof r->why,
                         "the held-out segment (%.1f s) gives Allan deviations within +-25 %% over only %.2f "
                         "decades of tau (a confident answer needs one decade)",
                         (double)r->segs.total[SG_HOLD] / r->rate_hz, r->tau_span_dec[ch]);
            }
        }
        if (tfit.n < 4) {
            r->confident = 0;
            snprintf(r->why, sizeof r->why, "the fit segment (%.1f s) has fewer than 4 Allan points (channel %s)",
                     (double)r->segs.total[SG_FIT] / r->rate_hz, sg_channel_name(ch));
        }
        done += 1.0;
        if (prog != NULL) {
            hx_progress_update(prog, done);
        }
    }
    for (ch = 0; ch < SG_NCH && (r->constant[ch] || r->seg_constant[ch]); ch++) {
    }
    if (ch == SG_NCH) {
        snprintf(err, err_size, "no channel varies over both the fit and the held-out segment (stuck, or noise "
                                "below the output's step): nothing to diagnose");
        free(x);
        return -1;
    }
    for (ch = 0; ch < SG_NCH; ch++) {
        sg_chres_t *c = &r->ch[ch];
        sg_table_t tfit;
        sg_fit_t bf;
        double mean = 0.0, tmax;
        twinset_t ts;
        size_t k;
        if (r->constant[ch] || r->seg_constant[ch]) {
            continue;
        }
        share = done + budget; /* where this channel's share of the progress ends */
        for (k = 0; k < (size_t)r->n; k++) {
            x[k] = ch < 3 ? log->acc[k][ch] : log->gyr[k][ch - 3];
            mean += x[k];
        }
        mean /= (double)r->n;
        sg_table_from(&r->pl[ch][SG_FIT], r->real[ch][SG_FIT], ch, r->rate_hz, &r->segs, SG_FIT, &tfit);
        if (tfit.n < 4) {
            done = share;
            continue; /* not analysed; the log is not confident (above) */
        }
        sg_evidence(x, &r->segs, r->rate_hz, c->q_full, &c->ev);
        if (r->segs.sandwich) {
            sg_evidence_seg(x, &r->segs, SG_HOLD, r->rate_hz, c->q_full, &c->ev_mid);
        }
        tmax = fit_tmax(r, ch);
        c->ar1_tau_max_s = tmax;
        if (sg_fit_model(&tfit, mean, NULL, 0, &c->ev, tmax, &bf) != 0) {
            snprintf(err, err_size, "baseline fit failed on channel %s", sg_channel_name(ch));
            free(x);
            return -1;
        }
        c->baseline = bf.model;
        c->final = bf.model;
        c->active = 1;
        if (twinset_run(&c->baseline, ch, &fc, &r->segs, c->q_full, S, o->seed + 1000u * (uint32_t)ch,
                        r->pl[ch], &ts) != 0) {
            snprintf(err, err_size, "twin simulation failed on channel %s", sg_channel_name(ch));
            free(x);
            return -1;
        }
        if (param_var(r, ch, &c->baseline, NULL, 0, &c->ev, tmax, SG_FIT, &ts, &c->baseline) != 0) {
            snprintf(err, err_size, "out of memory");
            free(x);
            return -1;
        }
        c->final = c->baseline; /* with the standard errors from the twins' refits */
        for (g = 0; g < SG_NSEG; g++) {
            r->twin[ch][g] = ts.v[g];
            r->vx[ch][g] = ts.vx[g];
            r->sh[ch][g] = ts.sh[g];
            if (sg_compare(&r->pl[ch][g], r->real[ch][g], ts.v[g], S, ts.vx[g], ts.sh[g], alpha, &c->cmp[g]) != 0) {
                snprintf(err, err_size, "out of memory");
                free(x);
                return -1;
            }
            if (c->cmp[g].undefined > SG_CMP_EMPTY) {
                /* nothing to test the channel against: said as an input
                 * the diagnosis cannot answer */
                snprintf(err, err_size, "channel %s: the gap of the baseline twin cannot be tested: %s",
                         sg_channel_name(ch), sg_cmp_why(&c->cmp[g]));
                free(x);
                return -1;
            }
        }
        table_weights(r, ch, SG_FIT, &tfit);
        c->gap_full = c->cmp[SG_FULL].significant;
        c->gap_hold = c->cmp[SG_HOLD].significant;
        done += 1.0;
        if (prog != NULL) {
            hx_progress_update(prog, done);
        }
        locate(r, ch, SG_FULL);
        if (have_prof) {
            /* the given parameterisation against the log: its own twins, no
             * parameter uncertainty (nothing was fitted) */
            twinset_t tp;
            profile_model(&prof, ch, mean, &c->prof);
            if (twinset_run(&c->prof, ch, &fc, &r->segs, c->q_full, S, o->seed + 7000u + 1000u * (uint32_t)ch, r->pl[ch],
                            &tp) != 0) {
                snprintf(err, err_size, "profile twin simulation failed on channel %s", sg_channel_name(ch));
                free(x);
                return -1;
            }
            for (g = 0; g < SG_NSEG; g++) {
                if (sg_compare(&r->pl[ch][g], r->real[ch][g], tp.v[g], S, NULL, NULL, alpha, &c->cmp_prof[g]) != 0) {
                    twinset_free(&tp);
                    snprintf(err, err_size, "out of memory");
                    free(x);
                    return -1;
                }
                if (c->cmp_prof[g].undefined > SG_CMP_EMPTY) {
                    twinset_free(&tp);
                    snprintf(err, err_size, "channel %s: the given profile's gap cannot be tested: %s",
                             sg_channel_name(ch), sg_cmp_why(&c->cmp_prof[g]));
                    free(x);
                    return -1;
                }
            }
            twinset_free(&tp);
            c->have_prof = 1;
            sg_locate_into(&r->pl[ch][SG_FULL], ch, SG_FULL, &c->cmp_prof[SG_FULL], r->ploc, &r->nploc,
                           sizeof r->ploc / sizeof r->ploc[0], &r->nloc_dropped);
        }
        /* attribution on every channel: a candidate whose held-out gain is
         * significant reveals a gap the omnibus test is too blunt for */
        if (r->confident) {
            if (attribute(r, ch, x, &fc, &tfit, alpha, prog, &done) != 0) {
                snprintf(err, err_size, "attribution failed on channel %s", sg_channel_name(ch));
                free(x);
                return -1;
            }
        } else {
            c->within_noise = !c->gap_hold;
        }
        c->gap = c->gap_full || c->gap_hold || c->nsel > 0;
        done = share;
        if (prog != NULL) {
            hx_progress_update(prog, done);
        }
    }
    if (prog != NULL) {
        hx_progress_end(prog);
    }
    free(x);
    return 0;
}

/* ------------------------------------------------------------ verdict */

static void verdict(sg_result_t *r)
{
    int ch, gaps = 0, sel = 0, open = 0;
    if (!r->confident) {
        snprintf(r->verdict, sizeof r->verdict, "too-short");
        return;
    }
    for (ch = 0; ch < SG_NCH; ch++) {
        const sg_chres_t *c = &r->ch[ch];
        if (!c->active) {
            /* a channel stuck over one segment only: a gap no twin of the
             * catalogue reproduces */
            gaps += r->seg_constant[ch] != 0;
            open += r->seg_constant[ch] != 0;
            continue;
        }
        if (c->gap) {
            gaps++;
            sel += c->nsel;
            open += !c->within_noise;
        }
    }
    if (r->tim.significant) {
        int d;
        gaps++;
        for (d = 0; d < SG_TIM_NKIND; d++) {
            sel += r->tim.sel[d];
            open += r->tim.open[d];
        }
    }
    if (r->nav != NULL) {
        sg_nav_verdict_counts((const sg_nav_t *)r->nav, &gaps, &sel, &open);
    }
    if (gaps == 0) {
        snprintf(r->verdict, sizeof r->verdict, "none");
    } else if (sel == 0) {
        snprintf(r->verdict, sizeof r->verdict, "unexplained");
    } else if (open > 0) {
        snprintf(r->verdict, sizeof r->verdict, "partly-explained");
    } else {
        snprintf(r->verdict, sizeof r->verdict, "explained");
    }
}

/* The median over the log's one-second windows of the gyro's spread, the
 * RMS of the three rates about their window means (rad/s): hundredths at
 * rest; above SG_STATIC_GYRO_SPREAD_RPS on a static log, a gyro in deg/s,
 * as allan's motion check reads it (HX_ALLAN_MOVING_GYRO_RPS, cmd_allan.c).
 * 0 for a log shorter than a window or out of memory (no verdict). */
#define SG_STATIC_GYRO_SPREAD_RPS 0.25
static double static_gyro_spread_rps(const hx_log_t *log, double rate_hz)
{
    const size_t w = (size_t)(rate_hz > 2.0 ? rate_hz : 2.0), nw = log->n / w;
    double *sp, med;
    size_t b;
    if (nw == 0 || (sp = (double *)malloc(nw * sizeof *sp)) == NULL) {
        return 0.0;
    }
    for (b = 0; b < nw; b++) {
        double m[3] = { 0, 0, 0 }, v = 0.0;
        size_t k;
        int i;
        for (k = b * w; k < (b + 1) * w; k++) {
            for (i = 0; i < 3; i++) {
                m[i] += log->gyr[k][i];
            }
        }
        for (i = 0; i < 3; i++) {
            m[i] /= (double)w;
        }
        for (k = b * w; k < (b + 1) * w; k++) {
            for (i = 0; i < 3; i++) {
                v += (log->gyr[k][i] - m[i]) * (log->gyr[k][i] - m[i]);
            }
        }
        sp[b] = sqrt(v / (double)w);
    }
    med = hx_median(sp, (int)nw);
    free(sp);
    return med;
}

/* Units (docs/harness.md, "Units check"): the rest value of |f| is its
 * median over the tenth of the samples that rotate least (the stances of a
 * walk; any of a static log). A walk in other units would be navigated into
 * nonsense: -1 with err set. A static log's Allan and PSD analysis only
 * carries the wrong unit labels (and a slow rate is no mistake there): a
 * warning, 0. */
static int units_of_log(const hx_log_t *log, const char *path, const sg_result_t *r, char *err, size_t err_size)
{
    double *wm = (double *)malloc(log->n * sizeof *wm), *fm = (double *)malloc(log->n * sizeof *fm);
    double wmax = 0.0, wq;
    char msg[768];
    size_t k, nf = 0;
    int bad;
    /* the remedies name --units for the interchange CSV, as replay's */
    hx_csv_layout_t lay, lay_t, lay_w;
    const hx_csv_layout_t *csv = hx_units_layout(log->meta.format, &lay);
    /* a static log's units warning and time warning each name the items
     * of both, one --units value (a second --units replaces the first) */
    const int slow = r->domain == 1 && !log->meta.rate_nominal;
    /* the rate the time unit is judged at: the log's span too (stamps in
     * bursts are no unit) */
    const double rate_u = hx_log_time_unit_rate(log, r->rate_hz);
    const hx_csv_layout_t *csv_t = slow ? hx_time_unit_layout(rate_u, csv, &lay_t) : csv;
    const hx_csv_layout_t *want = NULL;
    double f_med;
    char give[64];
    hx_walk_t walk;
    if (wm == NULL || fm == NULL) {
        free(wm);
        free(fm);
        snprintf(err, err_size, "out of memory");
        return -1;
    }
    for (k = 0; k < log->n; k++) {
        wm[k] = sqrt(log->gyr[k][0] * log->gyr[k][0] + log->gyr[k][1] * log->gyr[k][1] +
                     log->gyr[k][2] * log->gyr[k][2]);
        wmax = wm[k] > wmax ? wm[k] : wmax;
    }
    memcpy(fm, wm, log->n * sizeof *fm);
    qsort(fm, log->n, sizeof *fm, hx_cmp_double);
    wq = fm[log->n / 10];
    for (k = 0; k < log->n; k++) {
        if (wm[k] <= wq) {
            fm[nf++] = sqrt(log->acc[k][0] * log->acc[k][0] + log->acc[k][1] * log->acc[k][1] +
                            log->acc[k][2] * log->acc[k][2]);
        }
    }
    qsort(fm, nf, sizeof *fm, hx_cmp_double);
    f_med = fm[nf / 2];
    /* the walk replay's gyro mark needs (a gyro in rad/s read as deg/s by
     * --units gyro=deg/s), from the accelerometer as replay's: such a walk
     * is detected as static (its rates stay below 1 rad/s), and would be
     * analysed as one without a word */
    memset(&walk, 0, sizeof walk);
    for (k = 0; k < log->n; k++) {
        hx_walk_push(&walk, log->t_ns[k],
                     sqrt(log->acc[k][0] * log->acc[k][0] + log->acc[k][1] * log->acc[k][1] +
                          log->acc[k][2] * log->acc[k][2]));
    }
    bad = hx_units_problem(f_med, 9.80665, wmax, r->domain == 2 ? rate_u : 0.0, csv_t, hx_walk_seen(&walk), msg,
                           sizeof msg);
    want = hx_units_want(csv, f_med, 9.80665, wmax, &lay_w);
    free(wm);
    free(fm);
    /* not on a walk given --static: its spread is the motion's, and
     * "probably in deg/s (give --units gyro=deg/s)" sent the user to make
     * its rates 57 times too small (the summary says it looks like a walk) */
    if (!bad && r->domain == 1 && r->domain_detected == 1) {
        const double spread = static_gyro_spread_rps(log, r->rate_hz);
        if (spread > SG_STATIC_GYRO_SPREAD_RPS) {
            snprintf(msg, sizeof msg,
                     "the gyroscope spreads by %.3g rad/s RMS within a second (the median one-second window) while "
                     "the log is static, where a gyro at rest spreads by hundredths: the log is not in rad/s but "
                     "probably in deg/s (%s) (docs/log-format.md)",
                     spread, hx_units_fix_dps(csv_t, give, sizeof give));
            bad = 1;
            if (want != NULL && csv->gyr_scale == 1.0) {
                lay_w.gyr_scale = M_PI / 180.0;
            }
        }
    }
    if (bad && r->domain == 2) {
        snprintf(err, err_size, "%s", msg);
        return -1;
    }
    if (bad) {
        /* a warning, shown under --quiet too (it hides the progress
         * only) */
        hx_warn("simgap", "%s: %s", path, msg);
    }
    /* a static log may be slow, but one below 1 Hz that a time column in
     * milliseconds (us, ns) explains is named, as allan and psd name it:
     * the first minute of ADIS16405 log 1 with its time in ms would be
     * analysed at 0.1 Hz without a word (taus 1000 times too long) */
    if (slow && hx_time_unit_hint(rate_u, want, msg, sizeof msg)) {
        hx_warn("simgap", "%s: %s; the taus and frequencies are read at %.3g Hz", path, msg, r->rate_hz);
    }
    return 0;
}

/* A channel that holds one value over the whole log (a stuck output, or
 * noise below the output's step) has no noise to compare with a twin: its
 * Allan variance is zero at every tau. Said as such (a warning; the summary
 * and the JSON's constant_channels[]), rather than as a log too short for
 * its Allan points; a static log's other channels are diagnosed without it.
 * Every channel constant: -1 with err set (nothing to diagnose). */
static int constant_channels(const hx_log_t *log, const char *path, sg_result_t *r, char *err, size_t err_size)
{
    int ch, nconst = 0;
    for (ch = 0; ch < SG_NCH; ch++) {
        const double v0 = ch < 3 ? log->acc[0][ch] : log->gyr[0][ch - 3];
        size_t k;
        for (k = 1; k < log->n; k++) {
            if ((ch < 3 ? log->acc[k][ch] : log->gyr[k][ch - 3]) != v0) {
                break;
            }
        }
        r->constant[ch] = k == log->n;
        r->constant_value[ch] = v0;
        nconst += r->constant[ch];
    }
    if (nconst == SG_NCH) {
        snprintf(err, err_size, "every channel holds one value over the whole log (stuck, or not recorded): "
                                "nothing to diagnose");
        return -1;
    }
    for (ch = 0; ch < SG_NCH; ch++) {
        if (r->constant[ch]) {
            hx_warn("simgap", "%s: channel %s holds one value (%.6g %s) over the whole log: stuck, or its noise is "
                              "below the output's step; %s",
                    path, sg_channel_name(ch), r->constant_value[ch], sg_channel_unit(ch),
                    r->domain == 1 ? "not analysed" : "the walk is navigated with it as it is");
        }
    }
    return 0;
}

int sg_diagnose(const hx_log_t *log, const char *path, const sg_opts_t *o, sg_result_t *r, char *err, size_t err_size)
{
    double t0 = hx_now_s();
    int rc;
    if (err_size > 0) {
        err[0] = '\0';
    }
    memset(r, 0, sizeof *r);
    snprintf(r->path, sizeof r->path, "%s", path != NULL ? path : "");
    /* a log cut at a bad line or record is diagnosed on the samples before
     * it; the JSON says so (complete, error) as replay's and psd's do */
    r->complete = log->status == FNAV_END;
    if (!r->complete) {
        snprintf(r->input_error, sizeof r->input_error, "%s", log->error);
    }
    r->opts = *o;
    if (r->opts.seeds < 3) {
        r->opts.seeds = 3;
    }
    if (r->opts.seeds > 60) {
        r->opts.seeds = 60;
    }
    r->S = r->opts.seeds;
    r->n = (long)log->n;
    r->rate_hz = sg_log_rate(log);
    if (!(r->rate_hz > 0.0) && log->n > 1 && log->t_ns[log->n - 1] == log->t_ns[0]) {
        /* as replay says it (a rate of "none" was no reason) */
        snprintf(err, err_size, "the time stamps never advance (all %zu samples at one time): is the time column filled?",
                 log->n);
        return -1;
    }
    if (!(r->rate_hz > 0.0)) {
        snprintf(err, err_size, "the log has %zu sample%s and no usable rate", log->n, log->n == 1 ? "" : "s");
        return -1;
    }
    if (log->n < 16) {
        /* a rate it has: not "no usable rate" */
        snprintf(err, err_size, "the log has %zu sample%s, too few to diagnose (16 at least)", log->n,
                 log->n == 1 ? "" : "s");
        return -1;
    }
    /* the stamps' span plus one period (n / rate on a regular log): n / rate
     * alone would say 50 s for a 60 s walk with 10 s of samples missing */
    r->duration_s = log->t_ns != NULL ? (double)(log->t_ns[log->n - 1] - log->t_ns[0]) * 1e-9 + 1.0 / r->rate_hz
                                      : (double)r->n / r->rate_hz;
    r->domain_detected = sg_detect_domain(log, r->rate_hz);
    r->domain = o->domain != 0 ? o->domain : r->domain_detected;
    /* an option of the other domain has no effect: said, not dropped
     * silently (shown under --quiet too, as the other warnings) */
    if (r->domain == 1 && o->closed) {
        hx_warn("simgap", "%s: --closed is for walks (the drift check); ignored on a static log", path);
    }
    if (r->domain == 2 && o->contiguous) {
        hx_warn("simgap", "%s: --contiguous is for static logs (a walk is always split contiguously); ignored on a walk",
                path);
    }
    if (units_of_log(log, path, r, err, err_size) != 0) {
        return -1;
    }
    if (constant_channels(log, path, r, err, err_size) != 0) {
        return -1;
    }
    /* static logs: fit on both ends, held out the middle (a warm-up at the
     * start and the late behaviour are in both); walks: the first part */
    sg_segs_split(r->n, r->opts.fit_frac, r->domain == 1 && !r->opts.contiguous, &r->segs);
    /* the blocks' times from the log's stamps, as the navigation points and
     * the timing's first events are: start / rate would put a walk's
     * held-out segment 10 s early after a 10 s gap in the samples */
    {
        int g, b;
        for (g = 0; g < SG_NSEG; g++) {
            for (b = 0; b < r->segs.nb[g]; b++) {
                const long a = r->segs.start[g][b], e = a + r->segs.n[g][b];
                if (log->t_ns != NULL) {
                    r->seg_start_s[g][b] = (double)(log->t_ns[a] - log->t_ns[0]) * 1e-9;
                    r->seg_end_s[g][b] = e < (long)log->n ? (double)(log->t_ns[e] - log->t_ns[0]) * 1e-9
                                                          : (double)(log->t_ns[log->n - 1] - log->t_ns[0]) * 1e-9 +
                                                                1.0 / r->rate_hz;
                } else {
                    r->seg_start_s[g][b] = (double)a / r->rate_hz;
                    r->seg_end_s[g][b] = (double)e / r->rate_hz;
                }
            }
        }
    }
    sg_timing_analyse(log, r->rate_hz, &r->segs, r->opts.alpha, &r->tim);
    r->stamps_made = log->meta.stamps_made;
    if (r->domain == 1) {
        rc = diagnose_static(log, r, err, err_size);
    } else {
        rc = sg_nav_diagnose(log, r, err, err_size);
    }
    if (rc != 0) {
        if (err_size > 0 && err[0] == '\0') {
            snprintf(err, err_size, "the diagnosis failed (out of memory)");
        }
        return -1;
    }
    verdict(r);
    r->elapsed_s = hx_now_s() - t0;
    return 0;
}

void sg_result_free(sg_result_t *r)
{
    int g, ch;
    for (ch = 0; ch < SG_NCH; ch++) {
        for (g = 0; g < SG_NSEG; g++) {
            sg_plist_free(&r->pl[ch][g]);
            free(r->real[ch][g]);
            free(r->twin[ch][g]);
            free(r->twin_final[ch][g]);
            free(r->vx[ch][g]);
            free(r->vx_final[ch][g]);
            free(r->sh[ch][g]);
            free(r->sh_final[ch][g]);
            sg_cmp_free(&r->ch[ch].cmp_final[g]);
            sg_cmp_free(&r->ch[ch].cmp[g]);
            sg_cmp_free(&r->ch[ch].cmp_prof[g]);
        }
    }
    if (r->nav != NULL) {
        sg_nav_free((sg_nav_t *)r->nav);
        free(r->nav);
    }
    memset(r, 0, sizeof *r);
}
