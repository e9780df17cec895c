/* Sim-to-real gap diagnosis, walk domain (hx_simgap_nav.h, docs/simgap.md).
 *
 * The navigation filter (fnav_nav, the project's) runs on the real walk;
 * before every frame the navigator is copied, so that after the frame the
 * prediction of that sample can be repeated on the copy and the
 * zero-velocity update's innovation y and covariance S computed exactly as
 * fnav_ukf_zupt() forms them (the core does not expose them, and its RAM
 * budget on the firmware has no room for them).
 *
 * The twin's motion is the filter's estimated trajectory: the attitude and
 * velocity after every sample define interval-mean angular rates and
 * specific forces (an inverse strapdown), so the twin's truth is exactly
 * what the filter believes happened, impacts included; the twin's sensor
 * adds the baseline noise (and candidate effects) through the simulator's
 * error model, and the same filter runs on it. What the real filter
 * corrected at each update is then motion for the twin, and what remains
 * visible in the real's innovations and not in the twin's is the gap.
 */
#include "hx_simgap_nav.h"

#include <gsl/gsl_cdf.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "footnav/fnav_nav.h"
#include "hx_cli.h"
#include "hx_nav.h"
#include "hx_motion.h"
#include "hx_profile.h"

#define FL_ALIGNED 1u
#define FL_STANCE 2u
#define FL_ZUPT 4u

/* ------------------------------------------------------------ runs */

/** Samples of a walk (the real log's or a twin's), SI, body frame. */
typedef struct {
    long n;
    const int64_t *t_ns;
    double (*acc)[3];
    double (*gyr)[3];
} walk_t;

/** One run of the filter, per sample. */
typedef struct {
    long n;
    unsigned char *flag;
    double (*q)[4], (*v)[3], (*p)[3]; /* posterior */
    double (*y)[3];                   /* innovation of the zero-velocity update */
    double (*S)[6];                   /* its covariance: xx xy xz yy yz zz */
    double *nis;
} navrun_t;

static void navrun_free(navrun_t *r)
{
    free(r->flag);
    free(r->q);
    free(r->v);
    free(r->p);
    free(r->y);
    free(r->S);
    free(r->nis);
    memset(r, 0, sizeof *r);
}

static int navrun_alloc(navrun_t *r, long n)
{
    memset(r, 0, sizeof *r);
    r->n = n;
    r->flag = (unsigned char *)calloc((size_t)n + 1, 1);
    r->q = (double(*)[4])calloc((size_t)n + 1, sizeof *r->q);
    r->v = (double(*)[3])calloc((size_t)n + 1, sizeof *r->v);
    r->p = (double(*)[3])calloc((size_t)n + 1, sizeof *r->p);
    r->y = (double(*)[3])calloc((size_t)n + 1, sizeof *r->y);
    r->S = (double(*)[6])calloc((size_t)n + 1, sizeof *r->S);
    r->nis = (double *)calloc((size_t)n + 1, sizeof *r->nis);
    if (r->flag == NULL || r->q == NULL || r->v == NULL || r->p == NULL || r->y == NULL || r->S == NULL ||
        r->nis == NULL) {
        navrun_free(r);
        return -1;
    }
    return 0;
}

/* Inverse of a symmetric 3x3 (upper: xx xy xz yy yz zz); 0 ok. */
static int inv3(const double s[6], double o[3][3])
{
    double a = s[0], b = s[1], c = s[2], d = s[3], e = s[4], f = s[5];
    double A = d * f - e * e, B = c * e - b * f, C = b * e - c * d;
    double det = a * A + b * B + c * C;
    if (!(det > 0.0)) {
        return -1;
    }
    o[0][0] = A / det;
    o[0][1] = o[1][0] = B / det;
    o[0][2] = o[2][0] = C / det;
    o[1][1] = (a * f - c * c) / det;
    o[1][2] = o[2][1] = (b * c - a * e) / det;
    o[2][2] = (a * d - b * b) / det;
    return 0;
}

/* Innovation and covariance of the zero-velocity update that follows the
 * prediction of this sample, formed as fnav_ukf_zupt() forms them (v = 0,
 * or v - C (w x r) = 0 with the lever states), from the filter's state
 * after the prediction. Internal covariance indices of fnav_ukf.h. */
static void zupt_innovation(const fnav_ukf_t *u, const fnav_real_t gyro[3], double y[3], double S[6])
{
    int i, j, k, l, cols[9], nc = 0;
    double H[3][FNAV_UKF_NMAX], r2 = (double)u->cfg.zupt_sigma_mps * (double)u->cfg.zupt_sigma_mps, P[9][9];
    memset(H, 0, sizeof H);
    for (i = 0; i < 3; i++) {
        H[i][FNAV_UKF_V + i] = 1.0;
        cols[nc++] = FNAV_UKF_V + i;
        y[i] = -(double)u->vel_mps.v[i];
    }
    if (u->cfg.lever) {
        double w[3], C[3][3], r[3], wr[3], uu[3];
        fnav_mat3_t Cm = fnav_quat_to_dcm(u->q_nb);
        for (i = 0; i < 3; i++) {
            w[i] = (double)gyro[i] - (double)u->bg_rps.v[i];
            r[i] = (double)u->lever_m.v[i];
            for (j = 0; j < 3; j++) {
                C[i][j] = (double)Cm.m[i][j];
            }
        }
        wr[0] = w[1] * r[2] - w[2] * r[1];
        wr[1] = w[2] * r[0] - w[0] * r[2];
        wr[2] = w[0] * r[1] - w[1] * r[0];
        for (i = 0; i < 3; i++) {
            uu[i] = C[i][0] * wr[0] + C[i][1] * wr[1] + C[i][2] * wr[2];
            y[i] = uu[i] - (double)u->vel_mps.v[i];
        }
        /* dh/dr = -C [w x], dh/da = [u x] (the UKF leaves out the gyro
         * bias's term, fnav_ukf_zupt) */
        for (i = 0; i < 3; i++) {
            double sw[3][3] = { { 0.0, -w[2], w[1] }, { w[2], 0.0, -w[0] }, { -w[1], w[0], 0.0 } };
            double su[3][3] = { { 0.0, -uu[2], uu[1] }, { uu[2], 0.0, -uu[0] }, { -uu[1], uu[0], 0.0 } };
            for (j = 0; j < 3; j++) {
                double hr = 0.0;
                for (k = 0; k < 3; k++) {
                    hr += C[i][k] * sw[k][j];
                }
                H[i][FNAV_UKF_R + j] = -hr;
                H[i][FNAV_UKF_A + j] = su[i][j];
            }
        }
        for (j = 0; j < 3; j++) {
            cols[nc++] = FNAV_UKF_R + j;
            cols[nc++] = FNAV_UKF_A + j;
        }
    }
    for (k = 0; k < nc; k++) {
        for (l = 0; l < nc; l++) {
            P[k][l] = (double)fnav_ukf_cov(u, cols[k], cols[l]);
        }
    }
    {
        int map[6][2] = { { 0, 0 }, { 0, 1 }, { 0, 2 }, { 1, 1 }, { 1, 2 }, { 2, 2 } }, m;
        for (m = 0; m < 6; m++) {
            double s = 0.0;
            int a = map[m][0], b = map[m][1];
            for (k = 0; k < nc; k++) {
                for (l = 0; l < nc; l++) {
                    s += H[a][cols[k]] * P[k][l] * H[b][cols[l]];
                }
            }
            S[m] = s + (a == b ? r2 : 0.0);
        }
    }
}

/* Run the filter over a walk, recording per sample the posterior state and
 * the innovation of every zero-velocity update. 0, -1 on failure. */
static int nav_run(const walk_t *w, const fnav_nav_config_t *cfg, navrun_t *out)
{
    fnav_nav_t *nav = (fnav_nav_t *)malloc(sizeof *nav), *cp = (fnav_nav_t *)malloc(sizeof *cp);
    long *acc_idx = (long *)malloc(((size_t)w->n + 1) * sizeof *acc_idx);
    long i, nacc = 0, npop = 0;
    int fin = 0;
    if (nav == NULL || cp == NULL || acc_idx == NULL || navrun_alloc(out, w->n) != 0 ||
        fnav_nav_init(nav, cfg) != FNAV_OK) {
        free(nav);
        free(cp);
        free(acc_idx);
        navrun_free(out);
        return -1;
    }
    for (i = 0; i <= w->n; i++) {
        fnav_nav_frame_t fr;
        if (i < w->n) {
            fnav_sample_t s;
            int c;
            memset(&s, 0, sizeof s);
            s.t_ns = w->t_ns[i];
            s.seq = (uint32_t)i;
            for (c = 0; c < 3; c++) {
                s.accel_mps2[c] = (fnav_real_t)w->acc[i][c];
                s.gyro_rps[c] = (fnav_real_t)w->gyr[i][c];
            }
            if (fnav_nav_push(nav, &s) == FNAV_OK) {
                acc_idx[nacc++] = i;
            }
        } else {
            fnav_nav_finish(nav);
            fin = 1;
        }
        for (;;) {
            long k;
            unsigned char fl = 0;
            int c;
            memcpy(cp, nav, sizeof *nav);
            if (fnav_nav_pop(nav, &fr) != FNAV_OK) {
                break;
            }
            if (npop >= nacc) {
                continue;
            }
            k = acc_idx[npop++];
            if (fr.flags & FNAV_FRAME_ALIGNED) {
                fl |= FL_ALIGNED;
            }
            if (fr.flags & FNAV_FRAME_STANCE) {
                fl |= FL_STANCE;
            }
            if ((fr.flags & FNAV_FRAME_ZUPT) && cp->aligned) {
                /* repeat the prediction of this sample on the copy */
                double dt = cp->have_prev ? (double)(w->t_ns[k] - cp->t_prev_ns) * 1e-9 : 0.0;
                double nominal = 1.0 / (double)cp->stance.rate_hz;
                fnav_real_t g[3], a[3];
                for (c = 0; c < 3; c++) {
                    g[c] = (fnav_real_t)w->gyr[k][c];
                    a[c] = (fnav_real_t)w->acc[k][c];
                }
                if (dt > (double)cp->cfg.max_gap_s) {
                    dt = nominal;
                }
                fnav_status_t pst = dt > 0.0 ? fnav_ukf_predict(&cp->ukf, fnav_vec3_from(g), fnav_vec3_from(a),
                                                                 (fnav_real_t)dt)
                                             : FNAV_E_TIME;
                if (pst == FNAV_OK || pst == FNAV_E_DECOMP) {
                    double Si[3][3];
                    zupt_innovation(&cp->ukf, g, out->y[k], out->S[k]);
                    if (inv3(out->S[k], Si) == 0) {
                        double nis = 0.0;
                        int a2, b2;
                        for (a2 = 0; a2 < 3; a2++) {
                            for (b2 = 0; b2 < 3; b2++) {
                                nis += out->y[k][a2] * Si[a2][b2] * out->y[k][b2];
                            }
                        }
                        out->nis[k] = nis;
                        fl |= FL_ZUPT;
                    }
                }
            }
            out->flag[k] = fl;
            for (c = 0; c < 4; c++) {
                out->q[k][c] = (double)nav->ukf.q_nb.q[c];
            }
            for (c = 0; c < 3; c++) {
                out->v[k][c] = (double)nav->ukf.vel_mps.v[c];
                out->p[k][c] = (double)nav->ukf.pos_m.v[c];
            }
        }
        if (fin) {
            break;
        }
    }
    free(nav);
    free(cp);
    free(acc_idx);
    return 0;
}

/* ------------------------------------------------------------ stances */

typedef struct {
    long i0, i1;         /* first and last update sample */
    long first;          /* first update */
    int nupd;
    double nis_first, nis_sum;
    double ee_next, ee_self; /* sums of e_k . e_k+1 and e_k . e_k (normalised innovations) */
    double vres2;        /* squared posterior speed at mid-stance */
    double axis[3];      /* first innovation per axis squared / its variance */
} stance_t;

/* Normalised innovation e = L^-1 y, S = L L^T. */
static void whiten(const double y[3], const double s[6], double e[3])
{
    double l00 = sqrt(s[0] > 0.0 ? s[0] : 1e-30);
    double l10 = s[1] / l00, l20 = s[2] / l00;
    double d1 = s[3] - l10 * l10, l11 = sqrt(d1 > 0.0 ? d1 : 1e-30);
    double l21 = (s[4] - l20 * l10) / l11;
    double d2 = s[5] - l20 * l20 - l21 * l21, l22 = sqrt(d2 > 0.0 ? d2 : 1e-30);
    e[0] = y[0] / l00;
    e[1] = (y[1] - l10 * e[0]) / l11;
    e[2] = (y[2] - l20 * e[0] - l21 * e[1]) / l22;
}

/* Stances of samples [a, b): runs of updates with gaps of at most 2 samples. */
static int stances_of(const navrun_t *r, long a, long b, stance_t *st, int max)
{
    int ns = 0;
    long k = a;
    while (k < b && ns < max) {
        stance_t *s;
        long last, mid, j, cnt = 0;
        double eprev[3];
        int have = 0;
        if (!(r->flag[k] & FL_ZUPT)) {
            k++;
            continue;
        }
        s = &st[ns++];
        memset(s, 0, sizeof *s);
        s->i0 = s->first = k;
        last = k;
        for (j = k; j < b && j - last <= 3; j++) {
            if (r->flag[j] & FL_ZUPT) {
                double e[3];
                whiten(r->y[j], r->S[j], e);
                if (have) {
                    s->ee_next += eprev[0] * e[0] + eprev[1] * e[1] + eprev[2] * e[2];
                }
                s->ee_self += e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
                memcpy(eprev, e, sizeof e);
                have = 1;
                s->nis_sum += r->nis[j];
                s->nupd++;
                last = j;
                cnt++;
            }
        }
        s->i1 = last;
        s->nis_first = r->nis[s->first];
        {
            int c;
            for (c = 0; c < 3; c++) {
                double v = r->S[s->first][c == 0 ? 0 : (c == 1 ? 3 : 5)];
                s->axis[c] = v > 0.0 ? r->y[s->first][c] * r->y[s->first][c] / v : 0.0;
            }
        }
        mid = (s->i0 + s->i1) / 2;
        s->vres2 = r->v[mid][0] * r->v[mid][0] + r->v[mid][1] * r->v[mid][1] + r->v[mid][2] * r->v[mid][2];
        k = last + 1;
        (void)cnt;
    }
    return ns;
}

/* Stances of samples [a, b) as the core's stride segmentation counts them:
 * runs of updates separated by less than the shortest swing (min_swing_s)
 * are one stance. The detector flickers at a landing (the x-io short walk:
 * 23 runs of updates, 17 stances, gaps of 0.02-0.09 s between the pieces of
 * one stance against swings of 0.7-0.9 s), and the too-short rule would
 * count the pieces. The statistics above still use the runs. */
static int stance_begins(const int64_t *t_ns, long last, long k, double min_swing_s)
{
    /* update k after the update last (-1: none) begins a stance */
    return last < 0 || (k - last > 3 && (double)(t_ns[k] - t_ns[last]) * 1e-9 >= min_swing_s);
}

static int stances_counted(const navrun_t *r, const int64_t *t_ns, long a, long b, double min_swing_s)
{
    int n = 0;
    long k, last = -1;
    for (k = a; k < b; k++) {
        if (!(r->flag[k] & FL_ZUPT)) {
            continue;
        }
        if (stance_begins(t_ns, last, k, min_swing_s)) {
            n++;
        }
        last = k;
    }
    return n;
}

/* The first update of the first stance, counted as stances_counted counts
 * them, that begins at or after sample a (b when none does in [a, b)): the
 * held-out part of a walk split at a (docs/simgap.md, section 2). A stance
 * in progress at a, or a piece of it after a flicker of the detector,
 * began in the fit segment: its first update, the observation the fit of
 * the motion effects takes, and its NIS are the fit's. Starting the
 * held-out part at the sample a would hold such a stance out as well, with
 * a mid-stance update as its "first". */
static long stance_from(const navrun_t *r, const int64_t *t_ns, long a, long b, double min_swing_s)
{
    long k, last = -1;
    for (k = a - 1; k >= 0; k--) {
        if (r->flag[k] & FL_ZUPT) {
            last = k;
            break;
        }
    }
    for (k = a; k < b; k++) {
        if (!(r->flag[k] & FL_ZUPT)) {
            continue;
        }
        if (stance_begins(t_ns, last, k, min_swing_s)) {
            return k;
        }
        last = k;
    }
    return b;
}

/* ------------------------------------------------------------ points */

#define NAV_EMPTY_TWIN 2 /* sg_point_t.empty of a window in which a twin has no stance begin */
#define NAV_MIN_HOLD 10 /* held-out stances for a confident answer (docs/simgap.md, "Too short") */
#define NAV_WIN_FULL 6
#define NAV_WIN_SEG 3
#define MAX_ST 4096

/* Every stance of [a, b) in a list of the size it needs (free() it), with
 * their number in *ns; NULL when out of memory. A fixed list of MAX_ST
 * stances would drop those after it without a word: a 90-minute walk has
 * about 4,900. */
static stance_t *stances_all(const navrun_t *r, long a, long b, int *ns)
{
    int cap = MAX_ST;
    for (;;) {
        stance_t *st = (stance_t *)malloc((size_t)cap * sizeof *st);
        if (st == NULL) {
            return NULL;
        }
        *ns = stances_of(r, a, b, st, cap);
        if (*ns < cap || cap > INT_MAX / 2) {
            return st;
        }
        free(st); /* full: there may be more */
        cap *= 2;
    }
}

static double lnpos(double v)
{
    return log(v > 1e-30 ? v : 1e-30);
}

/* Navigation points of samples [a, b) (rate fs), optionally with the drift
 * (truth: the true trajectory's positions, NULL for the real: closed walk),
 * over the stances from sample from (>= a: the held-out segment's first
 * stance, stance_from) on; the windows span [a, b). */
static long nav_points(const navrun_t *r, const int64_t *t_ns, long a, long from, long b, int nwin, int drift,
                       const double (*truth_p)[3], int with_pl, sg_plist_t *pl, double *vals)
{
    int ns, i, w, c;
    stance_t *st = stances_all(r, from, b, &ns);
    long cnt = 0;
    double sf = 0.0, sa = 0.0, nu = 0.0, en = 0.0, es = 0.0, vr = 0.0, ax[3] = { 0, 0, 0 };
    double t0 = (double)(t_ns[a] - t_ns[0]) * 1e-9, t1 = (double)(t_ns[b - 1] - t_ns[0]) * 1e-9;
    sg_point_t p;
    if (st == NULL) {
        return -1;
    }
    for (i = 0; i < ns; i++) {
        sf += st[i].nis_first;
        sa += st[i].nis_sum;
        nu += st[i].nupd;
        en += st[i].ee_next;
        es += st[i].ee_self;
        vr += st[i].vres2;
        for (c = 0; c < 3; c++) {
            ax[c] += st[i].axis[c];
        }
    }
#define ADD(KIND, X, XLO, XHI, VAL) ADDE(KIND, X, XLO, XHI, VAL, 0)
#define ADDE(KIND, X, XLO, XHI, VAL, EMPTY)                                                                            \
    do {                                                                                                               \
        vals[cnt++] = (VAL);                                                                                           \
        if (with_pl) {                                                                                                 \
            memset(&p, 0, sizeof p);                                                                                   \
            p.empty = (EMPTY);                                                                                         \
            p.dom = SG_NAV;                                                                                            \
            p.ch = -1;                                                                                                 \
            p.kind = (KIND);                                                                                           \
            p.x = (X);                                                                                                 \
            p.x_lo = (XLO);                                                                                            \
            p.x_hi = (XHI);                                                                                            \
            p.nblk = 1;                                                                                                \
            if (sg_plist_add(pl, &p) != 0) {                                                                           \
                free(st);                                                                                              \
                return -1;                                                                                             \
            }                                                                                                          \
        }                                                                                                              \
    } while (0)
    /* a segment without a stance (a short walk's held-out part, a foot that
     * never stands still) has no innovation to compare: its points are
     * placeholders outside G, as an empty window's. As the constant ln 1e-30
     * in the real and every twin, the comparison would read as twins that do
     * not vary and the walk would be refused as "a noise-free log?" instead
     * of too short */
    ADDE(SG_NAV_NIS_FIRST, 0.0, t0, t1, lnpos(ns > 0 ? sf / ns : 0.0), ns == 0);
    ADDE(SG_NAV_NIS_ALL, 0.0, t0, t1, lnpos(nu > 0 ? sa / nu : 0.0), ns == 0);
    for (c = 0; c < 3; c++) {
        ADDE(SG_NAV_AXIS, (double)c, t0, t1, lnpos(ns > 0 ? ax[c] / ns : 0.0), ns == 0);
    }
    /* lag 1 needs two consecutive updates in a stance */
    ADDE(SG_NAV_WHITE, 0.0, t0, t1, es > 0.0 ? en / es : 0.0, !(nu - (double)ns > 0.0));
    ADDE(SG_NAV_RESID, 0.0, t0, t1, 0.5 * lnpos(ns > 0 ? vr / ns : 0.0), ns == 0);
    for (w = 0; w < nwin; w++) {
        double wa = t0 + (t1 - t0) * w / nwin, wb = t0 + (t1 - t0) * (w + 1) / nwin, s = 0.0;
        int m = 0;
        for (i = 0; i < ns; i++) {
            double ts = (double)(t_ns[st[i].first] - t_ns[0]) * 1e-9;
            /* the last window closed, so that a stance beginning at the
             * segment's last sample is in one */
            if (ts >= wa && (ts < wb || w == nwin - 1)) {
                s += st[i].nis_first;
                m++;
            }
        }
        /* a window in which no stance begins (inside a long stand) has
         * no first update to compare: a placeholder outside G */
        ADDE(SG_NAV_WIN, 0.5 * (wa + wb), wa, wb, lnpos(m > 0 ? s / m : 0.0), m == 0);
    }
    if (drift && ns >= 2) {
        long i0 = (st[0].i0 + st[0].i1) / 2, i1 = (st[ns - 1].i0 + st[ns - 1].i1) / 2;
        double d[3];
        for (c = 0; c < 3; c++) {
            d[c] = (r->p[i1][c] - r->p[i0][c]) - (truth_p != NULL ? truth_p[i1][c] - truth_p[i0][c] : 0.0);
        }
        ADD(SG_NAV_DRIFT_H, 0.0, t0, t1, 0.5 * lnpos(d[0] * d[0] + d[1] * d[1]));
        ADD(SG_NAV_DRIFT_V, 0.0, t0, t1, lnpos(fabs(d[2])));
    } else if (drift) {
        /* the drift runs from the first stance to the last */
        ADDE(SG_NAV_DRIFT_H, 0.0, t0, t1, lnpos(0.0), 1);
        ADDE(SG_NAV_DRIFT_V, 0.0, t0, t1, lnpos(0.0), 1);
    }
#undef ADD
#undef ADDE
    free(st);
    return cnt;
}

/* A run of n samples for nav_points and the stance counts from a caller's
 * per-sample ZUPT flags and, where given (NULL otherwise), its first-update
 * figures, which nav_points only reads. The caller frees r->flag. */
static int run_of_flags(navrun_t *r, long n, const unsigned char *zupt, const double (*y)[3], const double (*S)[6],
                        const double *nis, const double (*v)[3], const double (*p)[3])
{
    long k;
    memset(r, 0, sizeof *r);
    r->n = n;
    r->flag = (unsigned char *)calloc((size_t)n, 1);
    if (r->flag == NULL) {
        return -1;
    }
    for (k = 0; k < n; k++) {
        r->flag[k] = zupt[k] ? FL_ZUPT : 0u;
    }
    r->y = (double(*)[3])y;
    r->S = (double(*)[6])S;
    r->nis = (double *)nis;
    r->v = (double(*)[3])v;
    r->p = (double(*)[3])p;
    return 0;
}

long sg_nav_stance_points(long n, const int64_t *t_ns, const unsigned char *zupt, const double (*y)[3],
                          const double (*S)[6], const double *nis, const double (*v)[3], const double (*p)[3],
                          int nwin, int drift, double *vals, sg_plist_t *pl)
{
    navrun_t r;
    long cnt;
    if (n < 1 || nwin < 0) {
        return -1;
    }
    if (run_of_flags(&r, n, zupt, y, S, nis, v, p) != 0) {
        return -1;
    }
    cnt = nav_points(&r, t_ns, 0, 0, n, nwin, drift, NULL, pl != NULL, pl, vals);
    free(r.flag);
    return cnt;
}

int sg_nav_held_out_stances(long n, const int64_t *t_ns, const unsigned char *zupt, long split, double min_swing_s,
                            long *from)
{
    navrun_t r;
    int cnt;
    if (n < 1 || split < 0 || split > n || from == NULL) {
        return -1;
    }
    if (run_of_flags(&r, n, zupt, NULL, NULL, NULL, NULL, NULL) != 0) {
        return -1;
    }
    *from = stance_from(&r, t_ns, split, n, min_swing_s);
    cnt = stances_counted(&r, t_ns, *from, n, min_swing_s);
    free(r.flag);
    return cnt;
}

long sg_nav_held_out_points(long n, const int64_t *t_ns, const unsigned char *zupt, const double (*y)[3],
                            const double (*S)[6], const double *nis, const double (*v)[3], const double (*p)[3],
                            long split, double min_swing_s, int nwin, double *vals, sg_plist_t *pl)
{
    navrun_t r;
    long cnt;
    if (n < 1 || nwin < 0 || split < 0 || split >= n) {
        return -1;
    }
    if (run_of_flags(&r, n, zupt, y, S, nis, v, p) != 0) {
        return -1;
    }
    cnt = nav_points(&r, t_ns, split, stance_from(&r, t_ns, split, n, min_swing_s), n, nwin, 0, NULL, pl != NULL,
                     pl, vals);
    free(r.flag);
    return cnt;
}

/* Lattice point of channel ch over samples [a, b). */
static double lattice_val(const walk_t *w, int ch, long a, long b, double q)
{
    double c = 0.0, s = 0.0;
    long k;
    for (k = a + 1; k < b; k++) {
        double x1 = ch < 3 ? w->acc[k][ch] : w->gyr[k][ch - 3], x0 = ch < 3 ? w->acc[k - 1][ch] : w->gyr[k - 1][ch - 3];
        double ph = 2.0 * M_PI * (x1 - x0) / q;
        c += cos(ph);
        s += sin(ph);
    }
    return sg_rayleigh_z(b - a > 1 ? (c * c + s * s) / (double)(b - a - 1) : 0.0);
}

/* The score lattice_val gives a segment of b - a samples all of whose
 * differences lie on the lattice (a quantiser's twin): R = b - a - 1. */
static double lattice_full(long a, long b)
{
    return sg_rayleigh_z((double)(b - a - 1));
}

/* ------------------------------------------------------------ state */

#define NAV_MAX_CAND 16 /* the three linear families, a flat top and a lattice per channel */

/** A walk-domain candidate: effect with the channels and values fitted. */
typedef struct {
    int id;                      /* fnav_effect_id_t */
    int npar;                    /* parameters set */
    int ch[24], k[24];           /* channel and parameter index */
    double val[24];              /* value: the sensor's parameter, y = (I + A) x */
    double eq[24];               /* linear families: the same effect as it acts on the twin's truth (B, below) */
    int has_eq;
    int eq_at[24];               /* eq went past the catalogue's range: -1 below lo, +1 above hi (set to it) */
    int at[24];                  /* val the same (sg_nav_sensor_values): only a limit, not a fit */
    int nalt;                    /* parameters the fit cannot tell from the first (fits within chi2_1 = 1) */
    int alt_ch[4], alt_k[4];
    double alt_val[4];           /* their values fitted alone (the sensor's) */
    int alt_at[4];               /* as at */
    double dQ;                   /* fit-segment improvement (dispersion-scaled) */
    double dQ_hold, z_hold;      /* held-out improvement of the innovations' objective and its z */
    double Q0_hold;              /* held-out objective without the effect (dispersion-scaled) */
    int n_fit, n_hold;           /* stances used */
    int simulated;
    int joined;                  /* a lattice or flat top that joined the selected one (same effect, its channel) */
    int accepted;                /* supported on the fit segment and significant held out (ranked) */
    double G_fit, G_hold, dG_hold, z, t_hold, t_mean, t_sd, expl, expl_lo, expl_hi;
} navcand_t;

typedef struct {
    int ncand;
    navcand_t cand[NAV_MAX_CAND];
    int selected;
    double G_hold_before, G_fit_before;
} navstep_t;

struct sg_nav {
    navrun_t real;
    long n;
    double *t_s;                 /* time of every sample since the first, s */
    double rate_hz;
    int nst[SG_NSEG];
    long hold_from;              /* the held-out segment's first stance (stance_from; the log's end: none) */
    double hold_from_s;          /* its time since the first sample, s */
    double white[SG_NCH];        /* baseline white densities, u/sqrt(Hz) */
    double ar1_tau[SG_NCH], ar1_sig[SG_NCH];
    int from_profile;
    double q[SG_NCH], qz[SG_NCH];/* lattice */
    double q_fit[SG_NCH], q_full[SG_NCH], q_base[SG_NCH]; /* its fit-segment score: real, a quantiser's, the baseline twins' */
    double sat[SG_NCH];          /* saturation plateau found (0: none) */
    int nsat[SG_NCH];
    double (*tf)[3], (*tw)[3];   /* twin truth samples in use: specific force, angular rate */
    double (*mf)[3], (*mw)[3];   /* interval means (an integrating sensor) */
    double (*if_)[3], (*iw)[3];  /* instantaneous values at the stamps (a rate-output sensor) */
    int inst;                    /* 1: the twin samples instantaneous values (chosen on the fit segment) */
    double G_fit_conv[2];        /* fit-segment gap of each sampling convention (mean, instantaneous) */
    double (*tp)[3];             /* twin truth positions */
    sg_plist_t pl[SG_NSEG];
    double *real_v[SG_NSEG];
    double *twin_v[SG_NSEG];     /* baseline twins */
    double *twin_f[SG_NSEG];     /* final-model twins (NULL: baseline) */
    sg_cmp_t cmp[SG_NSEG], cmp_final[SG_NSEG];
    int nsteps, nsel;
    navstep_t step[SG_MAX_STEPS];
    navcand_t sel[SG_MAX_STEPS];
    double sel_expl[SG_MAX_STEPS];
    int gap, within_noise;
    int model_gap;               /* the navigation twins disagree (the filter's model included) */
    fnav_nav_config_t cfg;
    int closed;
    size_t nloc;
    sg_loc_t loc[32];
};

/* ------------------------------------------------------------ twins */

/* Truth of the twin from the real filter's posterior: interval-mean rate
 * w = rotvec(q_{k-1}^-1 q_k) / dt and specific force f = C_mid^T ((v_k -
 * v_{k-1}) / dt - g_n), C_mid the attitude half-way through the interval;
 * before the alignment the foot stands at the first aligned attitude. The
 * twin's true position is the integral of that velocity (linear over each
 * interval: the trapezoid is exact), not the posterior position, which also
 * carries the real filter's position corrections at its updates: with it the
 * twins' drift was the sum of those corrections (0.6 m vertically on GX2
 * run 2, the same in every twin), not their navigation error. */
static void twin_truth(const navrun_t *r, const walk_t *w, double g, double (*tf)[3], double (*tw)[3], double (*tp)[3])
{
    long k, first = -1;
    int c;
    for (k = 0; k < w->n; k++) {
        if (r->flag[k] & FL_ALIGNED) {
            first = k;
            break;
        }
    }
    for (k = 0; k < w->n; k++) {
        if (first < 0 || k <= first) {
            long kk = first < 0 ? 0 : first;
            fnav_quat_t q = fnav_quat((fnav_real_t)r->q[kk][0], (fnav_real_t)r->q[kk][1], (fnav_real_t)r->q[kk][2],
                                      (fnav_real_t)r->q[kk][3]);
            fnav_vec3_t gb;
            if (first < 0) {
                q = fnav_quat_identity();
            }
            gb = fnav_quat_rotate(fnav_quat_conj(q), fnav_vec3(FNAV_R(0.0), FNAV_R(0.0), (fnav_real_t)(-g)));
            for (c = 0; c < 3; c++) {
                tf[k][c] = (double)gb.v[c];
                tw[k][c] = 0.0;
                tp[k][c] = r->p[kk][c];
            }
            continue;
        }
        {
            double dt = (double)(w->t_ns[k] - w->t_ns[k - 1]) * 1e-9;
            double qa[4], qb[4], dq[4], phi[3], sn, ang, hm[4], C[3][3], a[3];
            if (!(dt > 0.0)) {
                for (c = 0; c < 3; c++) {
                    tf[k][c] = tf[k - 1][c];
                    tw[k][c] = tw[k - 1][c];
                    tp[k][c] = tp[k - 1][c];
                }
                continue;
            }
            memcpy(qa, r->q[k - 1], sizeof qa);
            memcpy(qb, r->q[k], sizeof qb);
            /* dq = qa^-1 qb (Hamilton), body-frame rotation over the interval */
            dq[0] = qa[0] * qb[0] + qa[1] * qb[1] + qa[2] * qb[2] + qa[3] * qb[3];
            dq[1] = qa[0] * qb[1] - qa[1] * qb[0] - qa[2] * qb[3] + qa[3] * qb[2];
            dq[2] = qa[0] * qb[2] + qa[1] * qb[3] - qa[2] * qb[0] - qa[3] * qb[1];
            dq[3] = qa[0] * qb[3] - qa[1] * qb[2] + qa[2] * qb[1] - qa[3] * qb[0];
            if (dq[0] < 0.0) {
                for (c = 0; c < 4; c++) {
                    dq[c] = -dq[c];
                }
            }
            sn = sqrt(dq[1] * dq[1] + dq[2] * dq[2] + dq[3] * dq[3]);
            ang = 2.0 * atan2(sn, dq[0]);
            for (c = 0; c < 3; c++) {
                phi[c] = sn > 1e-15 ? dq[c + 1] / sn * ang : 2.0 * dq[c + 1];
                tw[k][c] = phi[c] / dt;
            }
            /* half rotation: qa * exp(phi / 2) */
            {
                double hs = sin(0.25 * ang), hc = cos(0.25 * ang), u[3];
                for (c = 0; c < 3; c++) {
                    u[c] = sn > 1e-15 ? dq[c + 1] / sn : 0.0;
                }
                hm[0] = qa[0] * hc - (qa[1] * u[0] + qa[2] * u[1] + qa[3] * u[2]) * hs;
                hm[1] = qa[0] * u[0] * hs + qa[1] * hc + (qa[2] * u[2] - qa[3] * u[1]) * hs;
                hm[2] = qa[0] * u[1] * hs + qa[2] * hc + (qa[3] * u[0] - qa[1] * u[2]) * hs;
                hm[3] = qa[0] * u[2] * hs + qa[3] * hc + (qa[1] * u[1] - qa[2] * u[0]) * hs;
            }
            {
                fnav_mat3_t Cm = fnav_quat_to_dcm(fnav_quat((fnav_real_t)hm[0], (fnav_real_t)hm[1],
                                                            (fnav_real_t)hm[2], (fnav_real_t)hm[3]));
                int i2, j2;
                for (i2 = 0; i2 < 3; i2++) {
                    for (j2 = 0; j2 < 3; j2++) {
                        C[i2][j2] = (double)Cm.m[i2][j2];
                    }
                }
            }
            for (c = 0; c < 3; c++) {
                a[c] = (r->v[k][c] - r->v[k - 1][c]) / dt - (c == 2 ? g : 0.0);
            }
            for (c = 0; c < 3; c++) {
                tf[k][c] = C[0][c] * a[0] + C[1][c] * a[1] + C[2][c] * a[2];
                tp[k][c] = tp[k - 1][c] + 0.5 * (r->v[k][c] + r->v[k - 1][c]) * dt;
            }
        }
    }
}

/* Instantaneous values at the stamps of a signal known by its interval
 * means: the quadratic through three consecutive means, evaluated at the
 * end of the middle interval, x(t_k) = (-m_{k-1} + 5 m_k + 2 m_{k+1}) / 6. A
 * rate-output sensor delivers these; a strapdown that takes them as means
 * runs half a sample ahead (docs/simulator.md), and so does the real's. */
static void means_to_inst(const double (*m)[3], long n, double (*x)[3])
{
    long k;
    int c;
    for (k = 0; k < n; k++) {
        for (c = 0; c < 3; c++) {
            if (k == 0 || k == n - 1) {
                x[k][c] = m[k][c];
            } else {
                x[k][c] = (-m[k - 1][c] + 5.0 * m[k][c] + 2.0 * m[k + 1][c]) / 6.0;
            }
        }
    }
}

/* A channel's lattice is a quantiser's when its fit-segment score is nearer
 * what a quantiser's twin gives than what the baseline twins give (both
 * set with the attribution; before it, or without a lattice: no). */
static int lattice_complete(const sg_nav_t *nv, int c)
{
    return nv->q[c] > 0.0 && fabs(nv->q_fit[c] - nv->q_full[c]) < fabs(nv->q_fit[c] - nv->q_base[c]);
}

/* Apply one candidate's values to a configuration (every element of a
 * linear family is set: its defaults are not zero, docs/simulator.md). */
static int apply_cand(fnav_imuerr_config_t *cfg, const navcand_t *cand)
{
    uint32_t mask = 0u;
    int i;
    const fnav_effect_info_t *info = fnav_imuerr_effect_info((fnav_effect_id_t)cand->id);
    int lin = cand->id == FNAV_EFFECT_MISALIGN || cand->id == FNAV_EFFECT_GSENS || cand->id == FNAV_EFFECT_SCALE;
    if (info == NULL) {
        return -1;
    }
    if (cfg->mask[cand->id] == 0u) {
        fnav_imuerr_effect_reset(cfg, (fnav_effect_id_t)cand->id);
        if (lin) {
            int k;
            for (k = 0; k < info->nparams; k++) {
                if (fnav_imuerr_param_set(cfg, (fnav_effect_id_t)cand->id, k, info->allowed, FNAV_R(0.0)) != FNAV_OK) {
                    return -1;
                }
            }
        }
    }
    for (i = 0; i < cand->npar; i++) {
        if (fnav_imuerr_param_set(cfg, (fnav_effect_id_t)cand->id, cand->k[i], 1u << cand->ch[i],
                                  (fnav_real_t)cand->val[i]) != FNAV_OK) {
            return -1;
        }
        mask |= 1u << cand->ch[i];
    }
    if (lin) {
        mask = info->allowed; /* zeros elsewhere */
    }
    if (mask != 0u && fnav_imuerr_enable(cfg, (fnav_effect_id_t)cand->id, mask) != FNAV_OK) {
        return -1;
    }
    return 0;
}

/* Column of the 6x6 error matrix A (y = (I + A) x, rows and columns ax ay
 * az gx gy gz) that parameter k of a linear family sets on channel ch. */
static int lin_col(int id, int ch, int k)
{
    if (id == FNAV_EFFECT_SCALE) {
        return ch;
    }
    if (id == FNAV_EFFECT_MISALIGN) {
        return (ch / 3) * 3 + k;
    }
    return k; /* gsens: the gyro gets G f */
}

int sg_nav_lin_to_sensor(const double B[6][6], double A[6][6])
{
    /* A (I - B) = B, i.e. (I - B)^T A^T = B^T: Gauss-Jordan with partial
     * pivoting on [(I - B)^T | B^T] */
    double G[6][12];
    int i, j, r2;
    for (i = 0; i < 6; i++) {
        for (j = 0; j < 6; j++) {
            G[i][j] = (i == j ? 1.0 : 0.0) - B[j][i];
            G[i][6 + j] = B[j][i];
        }
    }
    for (i = 0; i < 6; i++) {
        int piv = i;
        double d;
        for (r2 = i + 1; r2 < 6; r2++) {
            if (fabs(G[r2][i]) > fabs(G[piv][i])) {
                piv = r2;
            }
        }
        if (!(fabs(G[piv][i]) > 1e-9)) {
            return -1;
        }
        if (piv != i) {
            for (j = 0; j < 12; j++) {
                double t = G[i][j];
                G[i][j] = G[piv][j];
                G[piv][j] = t;
            }
        }
        d = G[i][i];
        for (j = 0; j < 12; j++) {
            G[i][j] /= d;
        }
        for (r2 = 0; r2 < 6; r2++) {
            if (r2 != i && G[r2][i] != 0.0) {
                double fct = G[r2][i];
                for (j = 0; j < 12; j++) {
                    G[r2][j] -= fct * G[i][j];
                }
            }
        }
    }
    for (i = 0; i < 6; i++) {
        for (j = 0; j < 6; j++) {
            A[i][j] = G[j][6 + i]; /* A = (A^T)^T */
        }
    }
    return 0;
}

/* v within the range [lo, hi] of parameter k of effect id (*out); 0 inside,
 * -1 (+1) set to lo (hi); -2 on a bad id or index. */
static int clamp_param(int id, int k, double v, double *out)
{
    const fnav_effect_info_t *info = fnav_imuerr_effect_info((fnav_effect_id_t)id);
    double lo, hi;
    if (info == NULL || k < 0 || k >= info->nparams) {
        return -2;
    }
    lo = info->params[k].lo;
    hi = info->params[k].hi;
    *out = v < lo ? lo : (v > hi ? hi : v);
    return v < lo ? -1 : (v > hi ? 1 : 0);
}

int sg_nav_sensor_values(const double B[6][6], int id, int npar, const int *ch, const int *k, const double *eq,
                         const int *eq_at, double *val, int *at)
{
    double A[6][6];
    int i, nat = 0, sing = sg_nav_lin_to_sensor(B, A) != 0;
    for (i = 0; i < npar; i++) {
        double v;
        if (clamp_param(id, k[i], 0.0, &v) < -1 || ch[i] < 0 || ch[i] >= 6) {
            return -1;
        }
        if (sing) {
            /* I - B singular: the sensor's error is unbounded, past the
             * bound on the side of the trajectory's value */
            at[i] = clamp_param(id, k[i], eq[i] > 0.0 ? (double)INFINITY : -(double)INFINITY, &val[i]);
        } else {
            v = A[ch[i]][lin_col(id, ch[i], k[i])];
            at[i] = clamp_param(id, k[i], v, &val[i]);
            if (at[i] == 0 && eq_at != NULL) {
                /* the trajectory's value was clamped before: the sensor's
                 * is that bound's, a limit too (b / (1 - b) and the identity
                 * keep the side) */
                at[i] = eq_at[i];
            }
        }
        nat += at[i] != 0;
    }
    return nat;
}

/* The sensor's parameters from the fitted ones. The twin's truth is the
 * filter's trajectory, which integrated the real's measurements: its
 * signals are x_t = (I + A) x, the true motion x seen through the sensor's
 * error A. A linear effect fitted on the twin (B, in eq[]) reproduces the
 * real's error signal A x as B x_t, so B (I + A) = A, i.e.
 * A = B (I - B)^-1 (a scale factor b fitted on the trajectory is the
 * sensor's b / (1 - b); misalignment and g-sensitivity alone are unchanged,
 * their B B vanishes). c's values are computed jointly with other's (NULL:
 * none), the effects selected together; values out of the parameter's
 * range (I - B singular) are set to the bound and flagged (at[]), not
 * reported as fits. */
static void to_sensor(navcand_t *c, const navcand_t *other)
{
    double B[6][6];
    int i, m;
    const navcand_t *set[2];
    set[0] = c;
    set[1] = other;
    if (!c->has_eq) {
        return;
    }
    memset(B, 0, sizeof B);
    for (m = 0; m < 2; m++) {
        if (set[m] == NULL || !set[m]->has_eq) {
            continue;
        }
        for (i = 0; i < set[m]->npar; i++) {
            B[set[m]->ch[i]][lin_col(set[m]->id, set[m]->ch[i], set[m]->k[i])] += set[m]->eq[i];
        }
    }
    (void)sg_nav_sensor_values((const double(*)[6])B, c->id, c->npar, c->ch, c->k, c->eq, c->eq_at, c->val, c->at);
}

int sg_nav_param_text(char *b, size_t n, int id, int ch, int k, double v, int at)
{
    const fnav_effect_info_t *info = fnav_imuerr_effect_info((fnav_effect_id_t)id);
    const char *name = info != NULL && k >= 0 && k < info->nparams ? info->params[k].name : "?";
    return snprintf(b, n, "%s.%s=%.3g%s", sg_channel_name(ch), name, v,
                    at < 0   ? " at the catalogue's bound: only an upper limit"
                    : at > 0 ? " at the catalogue's bound: only a lower limit"
                             : "");
}

void sg_nav_bounds_json(cJSON *p, int id, int k, int at)
{
    const fnav_effect_info_t *info = fnav_imuerr_effect_info((fnav_effect_id_t)id);
    cJSON *b;
    if (info == NULL || k < 0 || k >= info->nparams ||
        (id != FNAV_EFFECT_SCALE && id != FNAV_EFFECT_MISALIGN && id != FNAV_EFFECT_GSENS)) {
        cJSON_AddNullToObject(p, "bounds");
        return;
    }
    b = cJSON_AddObjectToObject(p, "bounds");
    cJSON_AddNumberToObject(b, "lo", info->params[k].lo);
    cJSON_AddNumberToObject(b, "hi", info->params[k].hi);
    if (at != 0) {
        cJSON_AddStringToObject(b, "at_bound", at < 0 ? "lower" : "upper");
    } else {
        cJSON_AddNullToObject(b, "at_bound");
    }
}

/* The twin's sensor: the baseline noise (optional) plus candidates' values
 * (a, then b; either may be NULL); linear families act on the twin's truth
 * with their trajectory form (eq[]). */
static int twin_config(const sg_nav_t *nv, const navcand_t *a, const navcand_t *b, uint32_t seed, int noise,
                       fnav_imuerr_config_t *cfg)
{
    int c;
    *cfg = fnav_imuerr_config_default;
    cfg->seed = seed;
    cfg->rate_hz = (fnav_real_t)nv->rate_hz;
    cfg->oversample = 1u;
    if (noise) {
        for (c = 0; c < SG_NCH; c++) {
            cfg->white.density[c] = (fnav_real_t)nv->white[c];
            cfg->ar1.tau_s[c] = (fnav_real_t)(nv->ar1_tau[c] > 1e-3 ? nv->ar1_tau[c] : 1.0);
            cfg->ar1.sigma[c] = (fnav_real_t)nv->ar1_sig[c];
        }
        cfg->mask[FNAV_EFFECT_WHITE] = FNAV_CH_ALL;
        if (nv->from_profile) {
            cfg->mask[FNAV_EFFECT_AR1] = FNAV_CH_ALL;
        }
    }
    {
        const navcand_t *ab[2];
        int m;
        ab[0] = a;
        ab[1] = b;
        for (m = 0; m < 2; m++) {
            navcand_t t;
            if (ab[m] == NULL) {
                continue;
            }
            t = *ab[m];
            if (t.has_eq) {
                memcpy(t.val, t.eq, sizeof t.val);
            }
            if (apply_cand(cfg, &t) != 0) {
                return -1;
            }
        }
    }
    return 0;
}

/* Measurements of one twin: truth through the error model; duplicated
 * stamps repeat the previous sample (as a duplicated delivery does). */
static int twin_walk(const sg_nav_t *nv, const walk_t *rw, const fnav_imuerr_config_t *cfg, walk_t *tw)
{
    fnav_imuerr_t e;
    long k;
    int c;
    tw->n = rw->n;
    tw->t_ns = rw->t_ns;
    tw->acc = (double(*)[3])malloc(((size_t)rw->n + 1) * sizeof *tw->acc);
    tw->gyr = (double(*)[3])malloc(((size_t)rw->n + 1) * sizeof *tw->gyr);
    if (tw->acc == NULL || tw->gyr == NULL || fnav_imuerr_init(&e, cfg) != FNAV_OK) {
        free(tw->acc);
        free(tw->gyr);
        return -1;
    }
    for (k = 0; k < rw->n; k++) {
        fnav_sample_t s;
        if (k > 0 && rw->t_ns[k] <= rw->t_ns[k - 1]) {
            memcpy(tw->acc[k], tw->acc[k - 1], sizeof tw->acc[k]);
            memcpy(tw->gyr[k], tw->gyr[k - 1], sizeof tw->gyr[k]);
            continue;
        }
        memset(&s, 0, sizeof s);
        for (c = 0; c < 3; c++) {
            s.accel_mps2[c] = (fnav_real_t)nv->tf[k][c];
            s.gyro_rps[c] = (fnav_real_t)nv->tw[k][c];
        }
        if (fnav_imuerr_apply(&e, &s) != FNAV_OK) {
            free(tw->acc);
            free(tw->gyr);
            return -1;
        }
        for (c = 0; c < 3; c++) {
            tw->acc[k][c] = (double)s.accel_mps2[c];
            tw->gyr[k][c] = (double)s.gyro_rps[c];
        }
    }
    return 0;
}

/* Points of every segment for one walk and its run. */
static int walk_points(const sg_nav_t *nv, const sg_segs_t *segs, const walk_t *w, const navrun_t *run,
                       const double (*truth_p)[3], int with_pl, sg_plist_t pl[SG_NSEG], double *vals[SG_NSEG])
{
    int g, c;
    for (g = 0; g < SG_NSEG; g++) {
        long a = segs->start[g][0], b = a + segs->n[g][0], cnt;
        /* the held-out stances: from the first that begins in the segment
         * (in each run, the real's and every twin's, by its own updates) */
        long from = g == SG_HOLD ? stance_from(run, w->t_ns, a, b, (double)nv->cfg.stance.min_swing_s) : a;
        cnt = nav_points(run, w->t_ns, a, from, b, g == SG_FULL ? NAV_WIN_FULL : NAV_WIN_SEG,
                         nv->closed && g == SG_FULL, truth_p, with_pl, &pl[g], vals[g]);
        if (cnt < 0) {
            return -1;
        }
        for (c = 0; c < SG_NCH; c++) {
            if (nv->q[c] > 0.0) {
                vals[g][cnt++] = lattice_val(w, c, a, b, nv->q[c]);
                if (with_pl) {
                    sg_point_t p;
                    memset(&p, 0, sizeof p);
                    p.dom = SG_LATTICE;
                    p.ch = c;
                    p.x = p.x_lo = p.x_hi = nv->q[c];
                    p.edf = -1.0;
                    p.nblk = 1;
                    if (sg_plist_add(&pl[g], &p) != 0) {
                        return -1;
                    }
                }
            }
        }
    }
    return 0;
}

/* S twins of a candidate (NULL: the baseline): values per segment. */
static int run_twins(const sg_nav_t *nv, const sg_segs_t *segs, const walk_t *rw, const navcand_t *cand, int S,
                     uint32_t seed0, double *vals[SG_NSEG])
{
    int s, g;
    double *tmp[SG_NSEG];
    sg_plist_t dummy[SG_NSEG];
    memset(dummy, 0, sizeof dummy);
    for (g = 0; g < SG_NSEG; g++) {
        tmp[g] = (double *)malloc((nv->pl[g].n + 16) * sizeof(double));
        if (tmp[g] == NULL) {
            return -1;
        }
    }
    for (s = 0; s < S; s++) {
        fnav_imuerr_config_t cfg;
        walk_t tw;
        navrun_t run;
        if (twin_config(nv, cand, NULL, seed0 + (uint32_t)s, 1, &cfg) != 0 || twin_walk(nv, rw, &cfg, &tw) != 0) {
            break;
        }
        if (nav_run(&tw, &nv->cfg, &run) != 0) {
            free(tw.acc);
            free(tw.gyr);
            break;
        }
        if (walk_points(nv, segs, &tw, &run, (const double(*)[3])nv->tp, 0, dummy, tmp) != 0) {
            navrun_free(&run);
            free(tw.acc);
            free(tw.gyr);
            break;
        }
        for (g = 0; g < SG_NSEG; g++) {
            memcpy(vals[g] + (size_t)s * nv->pl[g].n, tmp[g], nv->pl[g].n * sizeof(double));
        }
        navrun_free(&run);
        free(tw.acc);
        free(tw.gyr);
    }
    for (g = 0; g < SG_NSEG; g++) {
        free(tmp[g]);
    }
    return s == S ? 0 : -1;
}

/* ------------------------------------------------------------ fitting */

/* First-update innovations of the stances of [a, b) of a run (3 per stance)
 * with their covariance and start times; all zero before the first
 * firsts_of, freed by firsts_free. (Sized by the stances, not arrays of
 * MAX_ST, which would drop the stances after the 4,096th without a word,
 * the held-out ones of a 90-minute walk among them.) */
typedef struct {
    int n;
    double *t;
    double *swing; /* time since the previous stance's last update (s; the start of the run for the first) */
    double (*y)[3];
    double (*S)[6];
} firsts_t;

static void firsts_free(firsts_t *f)
{
    free(f->t);
    free(f->swing);
    free(f->y);
    free(f->S);
    memset(f, 0, sizeof *f);
}

/* 0, or -1 when out of memory (f then empty). */
static int firsts_of(const navrun_t *r, const int64_t *t_ns, long a, long b, firsts_t *f)
{
    int i, ns;
    stance_t *st = stances_all(r, a, b, &ns);
    firsts_free(f);
    if (st == NULL) {
        return -1;
    }
    f->t = (double *)malloc(((size_t)ns + 1) * sizeof *f->t);
    f->swing = (double *)malloc(((size_t)ns + 1) * sizeof *f->swing);
    f->y = (double(*)[3])malloc(((size_t)ns + 1) * sizeof *f->y);
    f->S = (double(*)[6])malloc(((size_t)ns + 1) * sizeof *f->S);
    if (f->t == NULL || f->swing == NULL || f->y == NULL || f->S == NULL) {
        firsts_free(f);
        free(st);
        return -1;
    }
    for (i = 0; i < ns; i++) {
        f->t[f->n] = (double)(t_ns[st[i].first] - t_ns[0]) * 1e-9;
        f->swing[f->n] = (double)(t_ns[st[i].first] - t_ns[i > 0 ? st[i - 1].i1 : a]) * 1e-9;
        memcpy(f->y[f->n], r->y[st[i].first], sizeof f->y[0]);
        memcpy(f->S[f->n], r->S[st[i].first], sizeof f->S[0]);
        f->n++;
    }
    free(st);
    return 0;
}

long sg_nav_stance_starts(long n, const int64_t *t_ns, const unsigned char *zupt, double *t, long max)
{
    navrun_t r;
    firsts_t *f = (firsts_t *)calloc(1, sizeof *f);
    long k, cnt;
    if (n < 1 || f == NULL || navrun_alloc(&r, n) != 0) {
        free(f);
        return -1;
    }
    for (k = 0; k < n; k++) {
        r.flag[k] = zupt[k] ? FL_ZUPT : 0u;
        r.S[k][0] = r.S[k][3] = r.S[k][5] = 1.0;
    }
    if (firsts_of(&r, t_ns, 0, n, f) != 0) {
        navrun_free(&r);
        free(f);
        return -1;
    }
    cnt = f->n;
    for (k = 0; k < cnt && k < max; k++) {
        t[k] = f->t[k];
    }
    navrun_free(&r);
    firsts_free(f);
    free(f);
    return cnt;
}

/* The stance of b nearest in time to stance i of a (within 0.15 s), or -1. */
static int match(const firsts_t *a, int i, const firsts_t *b)
{
    int j, best = -1;
    double bd = 0.15;
    for (j = 0; j < b->n; j++) {
        double d = fabs(b->t[j] - a->t[i]);
        if (d < bd) {
            bd = d;
            best = j;
        }
    }
    return best;
}

/* The stance of b that observes the same swing as stance i of a, or -1:
 * the nearest in time (within 0.15 s), each other's nearest (one to one),
 * and after a swing of the same duration to 10 % (the first update's
 * innovation is the drift accumulated over the swing; a stance the
 * detector split or started early in one run and not in the other follows
 * a different swing, and its innovation is not the same observation). */
static int nearest(const double *ta, int i, const double *tb, int nb)
{
    int j, best = -1;
    double bd = 0.15;
    for (j = 0; j < nb; j++) {
        double d = fabs(tb[j] - ta[i]);
        if (d < bd) {
            bd = d;
            best = j;
        }
    }
    return best;
}

int sg_nav_match_swing(const double *ta, const double *swa, int na, int i, const double *tb, const double *swb,
                       int nb)
{
    int j = nearest(ta, i, tb, nb);
    if (j < 0 || nearest(tb, j, ta, na) != i || fabs(swb[j] - swa[i]) > 0.1 * swa[i]) {
        return -1;
    }
    return j;
}

static int match_swing(const firsts_t *a, int i, const firsts_t *b)
{
    return sg_nav_match_swing(a->t, a->swing, a->n, i, b->t, b->swing, b->n);
}

/* Noise-free twin run with the given candidate: first-update innovations. */
static int clean_run(const sg_nav_t *nv, const sg_segs_t *segs, const walk_t *rw, const navcand_t *given,
                     const navcand_t *cand, firsts_t *f)
{
    fnav_imuerr_config_t cfg;
    walk_t tw;
    navrun_t run;
    if (twin_config(nv, given, cand, 1u, 0, &cfg) != 0 || twin_walk(nv, rw, &cfg, &tw) != 0) {
        return -1;
    }
    if (nav_run(&tw, &nv->cfg, &run) != 0) {
        free(tw.acc);
        free(tw.gyr);
        return -1;
    }
    if (firsts_of(&run, tw.t_ns, segs->start[SG_FULL][0], segs->start[SG_FULL][0] + segs->n[SG_FULL][0], f) != 0) {
        navrun_free(&run);
        free(tw.acc);
        free(tw.gyr);
        return -1;
    }
    navrun_free(&run);
    free(tw.acc);
    free(tw.gyr);
    return 0;
}

/* Parameters of a linear motion effect family: (channel, parameter index). */
static int family_params(int id, int ch[24], int k[24])
{
    int n = 0, c, j;
    if (id == FNAV_EFFECT_SCALE) {
        for (c = 0; c < 6; c++) {
            ch[n] = c;
            k[n++] = 0;
        }
    } else if (id == FNAV_EFFECT_MISALIGN) {
        for (c = 0; c < 6; c++) {
            for (j = 0; j < 3; j++) {
                if (j != c % 3) {
                    ch[n] = c;
                    k[n++] = j;
                }
            }
        }
    } else if (id == FNAV_EFFECT_GSENS) {
        for (c = 3; c < 6; c++) {
            for (j = 0; j < 3; j++) {
                ch[n] = c;
                k[n++] = j;
            }
        }
    }
    return n;
}

/* Fit a linear motion effect on the fit segment: sensitivities of the
 * first-update innovations to each parameter from noise-free twin runs,
 * then generalised least squares with forward selection of the parameters
 * (each must lower the dispersion-scaled objective by more than chi2_1 at
 * 0.1 %). Then the held-out test: with the parameters fixed, the held-out
 * objective changes by dQ = 2 b - a (a = |J theta|^2_W, b = (J theta)^T W r);
 * without the effect 2 b ~ N(0, 4 disp a), so z = b / sqrt(disp a). The
 * stances come from the whole walk (fr): fitted those before t_split, held
 * out those from t_hold (the held-out segment's first stance, stance_from)
 * on; a piece of the stance across the split between them (a run of
 * updates after a flicker of the detector) is neither. */
static int fit_family(const sg_nav_t *nv, const sg_segs_t *segs, const walk_t *rw, const firsts_t *fr, double t_split,
                      double t_hold, const navcand_t *given, int id, navcand_t *out)
{
    int ch[24], kk[24], np = family_params(id, ch, kk), p, i, a, b;
    double delta = id == FNAV_EFFECT_GSENS ? 1e-3 : 1e-2;
    const size_t nf = (size_t)fr->n + 1; /* J[p * nf + i]: parameter p, stance i */
    firsts_t *base = (firsts_t *)calloc(1, sizeof *base), *pert = (firsts_t *)calloc(1, sizeof *pert);
    firsts_t *pertm = (firsts_t *)calloc(1, sizeof *pertm);
    double (*J)[3] = (double(*)[3])calloc(((size_t)np + 1) * nf, sizeof *J);
    double (*r)[3] = (double(*)[3])calloc(nf, sizeof *r), (*W)[3][3] = (double(*)[3][3])calloc(nf, sizeof *W);
    int *mi = (int *)calloc(nf, sizeof *mi), sel[24], nsel = 0, ok = -1, *hold = (int *)calloc(nf, sizeof *hold);
    double disp = 0.0, Q0 = 0.0, Qh0 = 0.0;
    int nm = 0, nh = 0;
    memset(out, 0, sizeof *out);
    out->id = id;
    if (base == NULL || pert == NULL || pertm == NULL || J == NULL || r == NULL || W == NULL || mi == NULL ||
        hold == NULL || np == 0) {
        goto done;
    }
    if (clean_run(nv, segs, rw, given, NULL, base) != 0) {
        goto done;
    }
    for (i = 0; i < fr->n; i++) {
        mi[i] = match_swing(fr, i, base);
        hold[i] = fr->t[i] >= t_hold;
        if (fr->t[i] >= t_split && !hold[i]) {
            mi[i] = -1;
        }
        if (mi[i] >= 0) {
            double Si[3][3], q = 0.0;
            if (inv3(fr->S[i], Si) != 0) {
                mi[i] = -1;
                continue;
            }
            for (a = 0; a < 3; a++) {
                r[i][a] = fr->y[i][a] - base->y[mi[i]][a];
                for (b = 0; b < 3; b++) {
                    W[i][a][b] = Si[a][b];
                }
            }
            for (a = 0; a < 3; a++) {
                for (b = 0; b < 3; b++) {
                    q += r[i][a] * W[i][a][b] * r[i][b];
                }
            }
            if (hold[i]) {
                Qh0 += q;
                nh++;
            } else {
                Q0 += q;
                nm++;
            }
        }
    }
    if (nm < 5) {
        goto done;
    }
    /* dispersion: the filter's S need not be the innovations' true spread
     * (its own model errors add to them); estimated on the fit stances */
    disp = Q0 / (3.0 * nm);
    if (disp < 1.0) {
        disp = 1.0;
    }
    for (p = 0; p < np; p++) {
        navcand_t c1;
        memset(&c1, 0, sizeof c1);
        c1.id = id;
        c1.npar = 1;
        c1.ch[0] = ch[p];
        c1.k[0] = kk[p];
        c1.val[0] = delta;
        if (clean_run(nv, segs, rw, given, &c1, pert) != 0) {
            goto done;
        }
        c1.val[0] = -delta;
        if (clean_run(nv, segs, rw, given, &c1, pertm) != 0) {
            goto done;
        }
        /* central differences: a one-sided probe of the size of the
         * fitted values made the answer depend on its sign (the same walk
         * turned 180 deg about z, or the probe's sign flipped, named other
         * effects: the consistency audit of 2026-12-06) */
        for (i = 0; i < fr->n; i++) {
            int j = mi[i] >= 0 ? match_swing(base, mi[i], pert) : -1;
            int jm = mi[i] >= 0 ? match_swing(base, mi[i], pertm) : -1;
            for (a = 0; a < 3; a++) {
                J[(size_t)p * nf + i][a] = j >= 0 && jm >= 0 ? (pert->y[j][a] - pertm->y[jm][a]) / (2.0 * delta)
                                                             : 0.0;
            }
        }
    }
    /* forward selection of parameters by GLS on the fit stances */
    {
        double theta[24];
        double Qcur = Q0;
        for (;;) {
            int bestp = -1;
            double bestQ = Qcur, bth[24], Qp[24], thp[24][24];
            for (p = 0; p < np; p++) {
                Qp[p] = (double)INFINITY;
                int in = 0, m, s1, s2, ns = nsel + 1, idx[24];
                double M[24][24], v[24], th[24], Q = 0.0;
                for (m = 0; m < nsel; m++) {
                    in |= sel[m] == p;
                }
                if (in) {
                    continue;
                }
                memcpy(idx, sel, (size_t)nsel * sizeof *idx);
                idx[nsel] = p;
                memset(M, 0, sizeof M);
                memset(v, 0, sizeof v);
                for (i = 0; i < fr->n; i++) {
                    if (mi[i] < 0 || hold[i]) {
                        continue;
                    }
                    for (s1 = 0; s1 < ns; s1++) {
                        for (a = 0; a < 3; a++) {
                            for (b = 0; b < 3; b++) {
                                v[s1] += J[(size_t)idx[s1] * nf + i][a] * W[i][a][b] * r[i][b];
                                for (s2 = 0; s2 < ns; s2++) {
                                    M[s1][s2] += J[(size_t)idx[s1] * nf + i][a] * W[i][a][b] * J[(size_t)idx[s2] * nf + i][b];
                                }
                            }
                        }
                    }
                }
                /* Gauss-Jordan */
                {
                    double A[24][25];
                    int r1, r2, c1;
                    int sing = 0;
                    for (r1 = 0; r1 < ns; r1++) {
                        for (c1 = 0; c1 < ns; c1++) {
                            A[r1][c1] = M[r1][c1];
                        }
                        A[r1][ns] = v[r1];
                    }
                    for (r1 = 0; r1 < ns && !sing; r1++) {
                        double piv = A[r1][r1];
                        if (!(fabs(piv) > 1e-300)) {
                            sing = 1;
                            break;
                        }
                        for (c1 = r1; c1 <= ns; c1++) {
                            A[r1][c1] /= piv;
                        }
                        for (r2 = 0; r2 < ns; r2++) {
                            if (r2 != r1) {
                                double fct = A[r2][r1];
                                for (c1 = r1; c1 <= ns; c1++) {
                                    A[r2][c1] -= fct * A[r1][c1];
                                }
                            }
                        }
                    }
                    if (sing) {
                        continue;
                    }
                    for (r1 = 0; r1 < ns; r1++) {
                        th[r1] = A[r1][ns];
                    }
                }
                for (i = 0; i < fr->n; i++) {
                    double e[3];
                    if (mi[i] < 0 || hold[i]) {
                        continue;
                    }
                    for (a = 0; a < 3; a++) {
                        e[a] = r[i][a];
                        for (s1 = 0; s1 < ns; s1++) {
                            e[a] -= J[(size_t)idx[s1] * nf + i][a] * th[s1];
                        }
                    }
                    for (a = 0; a < 3; a++) {
                        for (b = 0; b < 3; b++) {
                            Q += e[a] * W[i][a][b] * e[b];
                        }
                    }
                }
                Qp[p] = Q;
                memcpy(thp[p], th, (size_t)ns * sizeof *th);
                if (Q < bestQ) {
                    bestQ = Q;
                    bestp = p;
                    memcpy(bth, th, (size_t)ns * sizeof *th);
                }
            }
            /* identifiability: the parameters whose single fits are within
             * one (chi2_1, dispersion-scaled) of the first one's are not told
             * apart by the stances (nearly collinear innovation signatures:
             * roll and yaw rate errors that follow the stride); they are
             * reported with it, best fit first */
            if (nsel == 0 && bestp >= 0) {
                int p2, na = 0, idx2[24], m2;
                for (p2 = 0; p2 < np; p2++) {
                    if (p2 != bestp && Qp[p2] <= bestQ + disp) {
                        for (m2 = na++; m2 > 0 && Qp[idx2[m2 - 1]] > Qp[p2]; m2--) {
                            idx2[m2] = idx2[m2 - 1];
                        }
                        idx2[m2] = p2;
                    }
                }
                out->nalt = na < 4 ? na : 4;
                for (m2 = 0; m2 < out->nalt; m2++) {
                    navcand_t one;
                    memset(&one, 0, sizeof one);
                    one.id = id;
                    one.npar = 1;
                    one.ch[0] = ch[idx2[m2]];
                    one.k[0] = kk[idx2[m2]];
                    one.eq[0] = thp[idx2[m2]][0];
                    one.has_eq = 1;
                    to_sensor(&one, given);
                    out->alt_ch[m2] = one.ch[0];
                    out->alt_k[m2] = one.k[0];
                    out->alt_val[m2] = one.val[0];
                    out->alt_at[m2] = one.at[0];
                }
            }
            /* chi2_1 at 0.1 %: 10.83, on the dispersion-scaled objective */
            if (bestp < 0 || (Qcur - bestQ) / disp < 10.83 || nsel >= 6) {
                break;
            }
            sel[nsel++] = bestp;
            memcpy(theta, bth, (size_t)nsel * sizeof *theta);
            Qcur = bestQ;
        }
        out->dQ = (Q0 - Qcur) / disp;
        out->npar = nsel;
        out->n_fit = nm;
        out->n_hold = nh;
        for (i = 0; i < nsel; i++) {
            out->ch[i] = ch[sel[i]];
            out->k[i] = kk[sel[i]];
            /* the twins take only values in the range: a fit beyond it is
             * that bound, flagged */
            out->eq_at[i] = clamp_param(id, kk[sel[i]], theta[i], &out->eq[i]);
        }
        out->has_eq = 1;
        to_sensor(out, given);
        /* the held-out test with the parameters fixed */
        if (nsel > 0 && nh > 0) {
            double aa = 0.0, bb = 0.0, dh;
            for (i = 0; i < fr->n; i++) {
                double pr[3] = { 0.0, 0.0, 0.0 };
                int m;
                if (mi[i] < 0 || !hold[i]) {
                    continue;
                }
                for (m = 0; m < nsel; m++) {
                    for (a = 0; a < 3; a++) {
                        pr[a] += J[(size_t)sel[m] * nf + i][a] * out->eq[m];
                    }
                }
                for (a = 0; a < 3; a++) {
                    for (b = 0; b < 3; b++) {
                        aa += pr[a] * W[i][a][b] * pr[b];
                        bb += pr[a] * W[i][a][b] * r[i][b];
                    }
                }
            }
            dh = Qh0 / (3.0 * nh);
            dh = dh > disp ? dh : disp;
            out->dQ_hold = (2.0 * bb - aa) / dh;
            out->z_hold = aa > 0.0 ? bb / sqrt(dh * aa) : 0.0;
            out->Q0_hold = Qh0;
            /* fraction of the held-out innovation excess (over the filter's
             * own 3 per stance) that the effect removes, defined where there
             * is an excess: more than two null standard deviations (chi2 with
             * 3 per stance: sd sqrt(6 n)), as for the static domain */
            out->expl = Qh0 - 3.0 * nh > 2.0 * sqrt(6.0 * nh) ? (2.0 * bb - aa) / (Qh0 - 3.0 * nh) : (double)NAN;
            out->expl_lo = out->expl_hi = out->expl;
        }
    }
    ok = 0;
done:
    if (base != NULL) {
        firsts_free(base);
    }
    if (pert != NULL) {
        firsts_free(pert);
    }
    if (pertm != NULL) {
        firsts_free(pertm);
    }
    free(base);
    free(pert);
    free(pertm);
    free(J);
    free(r);
    free(W);
    free(mi);
    free(hold);
    return ok;
}

/* ------------------------------------------------------------ diagnosis */

static int cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Baseline white noise from the stances of the fit segment: the robust
 * spread of first differences between consecutive stance samples. */
static void stance_noise(const walk_t *w, const navrun_t *r, long a, long b, double fs, double white[SG_NCH])
{
    long k, m = 0;
    int c;
    double *d = (double *)malloc(((size_t)(b - a) + 1) * sizeof *d);
    for (c = 0; c < SG_NCH; c++) {
        white[c] = 0.0;
    }
    if (d == NULL) {
        return;
    }
    for (c = 0; c < SG_NCH; c++) {
        m = 0;
        for (k = a + 1; k < b; k++) {
            if ((r->flag[k] & FL_STANCE) && (r->flag[k - 1] & FL_STANCE) && w->t_ns[k] > w->t_ns[k - 1]) {
                double x1 = c < 3 ? w->acc[k][c] : w->gyr[k][c - 3], x0 = c < 3 ? w->acc[k - 1][c] : w->gyr[k - 1][c - 3];
                d[m++] = fabs(x1 - x0);
            }
        }
        if (m > 10) {
            /* the median by sorting: a selection sort is quadratic, and a
             * walk with a 10-minute stand would spend most of its time here */
            qsort(d, (size_t)m, sizeof *d, cmp_double);
            /* MAD of a difference of two white samples: 0.6745 sqrt(2) sigma */
            white[c] = d[m / 2] / (0.6745 * sqrt(2.0)) / sqrt(fs);
        }
    }
    free(d);
}

/* Saturation: values at the channel's extreme repeated (flat tops). */
static void find_saturation(const walk_t *w, const int *constant, long a, long b, double sat[SG_NCH],
                            int nsat[SG_NCH])
{
    int c;
    long k;
    for (c = 0; c < SG_NCH; c++) {
        double mx = 0.0;
        int n = 0;
        if (constant[c]) {
            /* a stuck output is no clipping: every sample would be a "flat
             * top" and the diagnosis would answer saturation at its value */
            sat[c] = 0.0;
            nsat[c] = 0;
            continue;
        }
        for (k = a; k < b; k++) {
            double x = fabs(c < 3 ? w->acc[k][c] : w->gyr[k][c - 3]);
            mx = x > mx ? x : mx;
        }
        for (k = a; k < b; k++) {
            double x = fabs(c < 3 ? w->acc[k][c] : w->gyr[k][c - 3]);
            if (x >= mx * (1.0 - 1e-6)) {
                n++;
            }
        }
        sat[c] = n >= 3 ? mx : 0.0;
        nsat[c] = n;
    }
}

/* Why a navigation comparison is undefined: twins without noise because the
 * fit segment has no stance to measure it in are not "a noise-free log". */
static const char *nav_cmp_why(const sg_nav_t *nv, const sg_cmp_t *cc)
{
    int c, quiet = !nv->from_profile;
    for (c = 0; c < SG_NCH; c++) {
        quiet &= nv->white[c] == 0.0;
    }
    if (cc->undefined == SG_CMP_FLAT && quiet && nv->nst[SG_FIT] == 0) {
        return "the twins have no noise: it is measured in the fit segment's stances, and it has none";
    }
    return sg_cmp_why(cc);
}

/* Insert candidate i into idx[0..n-1], kept sorted by held-out z, the best
 * first (idx has room for n + 1). */
static void add_by_z(const navcand_t *cand, int *idx, int n, int i)
{
    while (n > 0 && cand[idx[n - 1]].z_hold < cand[i].z_hold) {
        idx[n] = idx[n - 1];
        n--;
    }
    idx[n] = i;
}

/* Of the accepted candidates cand[idx[0..n-1]], sorted by held-out z (the
 * best first), the one to select, as its position in idx: within one z of
 * the best, the fewest parameters win (two effects that explain the same
 * innovations are not told apart by a fraction of a sigma), the higher z
 * among as few. Every step of the forward selection uses it
 * (docs/simgap.md, section 4). */
static int parsimony_pick(const navcand_t *cand, const int *idx, int n)
{
    int b = 0, k;
    for (k = 1; k < n; k++) {
        if (cand[idx[k]].z_hold >= cand[idx[0]].z_hold - 1.0 && cand[idx[k]].npar < cand[idx[b]].npar) {
            b = k;
        }
    }
    return b;
}

int sg_nav_diagnose(const hx_log_t *log, sg_result_t *r, char *err, size_t err_size)
{
    sg_nav_t *nv = (sg_nav_t *)calloc(1, sizeof *nv);
    hx_nav_opts_t no;
    walk_t rw;
    const int S = r->opts.seeds;
    const double alpha = r->opts.alpha / 4.0;
    int g, c;
    uint32_t seed = r->opts.seed + 7777u;
    if (nv == NULL) {
        snprintf(err, err_size, "out of memory");
        return -1;
    }
    r->nav = nv;
    nv->n = r->n;
    nv->rate_hz = r->rate_hz;
    nv->t_s = (double *)malloc(((size_t)r->n + 1) * sizeof *nv->t_s);
    if (nv->t_s == NULL) {
        snprintf(err, err_size, "out of memory");
        return -1;
    }
    {
        long k;
        for (k = 0; k < (long)r->n; k++) {
            nv->t_s[k] = (double)(log->t_ns[k] - log->t_ns[0]) * 1e-9;
        }
    }
    nv->closed = r->opts.closed;
    memset(&no, 0, sizeof no);
    /* the filter of the configuration this domain was validated with
     * (docs/simgap.md): bias model off, the NavChip's noise unless a profile
     * is given (the navigation's default before it became the AR(1) model) */
    no.profile = r->opts.profile != NULL ? r->opts.profile : "navchip";
    no.bias_model = "off";
    if (hx_nav_config(&no, &nv->cfg, err, err_size) != 0) {
        return -1;
    }
    nv->cfg.settle = 0; /* nor the landing settling state, added after the validation */
    rw.n = (long)log->n;
    rw.t_ns = log->t_ns;
    rw.acc = log->acc;
    rw.gyr = log->gyr;
    if (nav_run(&rw, &nv->cfg, &nv->real) != 0) {
        snprintf(err, err_size, "the navigation filter could not run on the log");
        return -1;
    }
    /* the held-out stances begin with the first that begins in the held-out
     * segment: a stance across the split is the fit's (stance_from) */
    nv->hold_from = stance_from(&nv->real, log->t_ns, r->segs.start[SG_HOLD][0],
                                r->segs.start[SG_HOLD][0] + r->segs.n[SG_HOLD][0], (double)nv->cfg.stance.min_swing_s);
    nv->hold_from_s = nv->hold_from < (long)log->n ? (double)(log->t_ns[nv->hold_from] - log->t_ns[0]) * 1e-9
                                                   : (double)NAN;
    for (g = 0; g < SG_NSEG; g++) {
        nv->nst[g] = stances_counted(&nv->real, log->t_ns, g == SG_HOLD ? nv->hold_from : r->segs.start[g][0],
                                     r->segs.start[g][0] + r->segs.n[g][0], (double)nv->cfg.stance.min_swing_s);
    }
    /* a confident answer: at least 10 held-out stances, whose mean
     * first-update NIS (chi2_3 / 3 per stance) is known to -44 % / +57 %
     * (95 %: the quantiles of chi2_30 / 30); +-50 % would take 13. The
     * interval is computed, not typed; the remedy is named (until
     * 2026-12-07 it was not) */
    r->confident = 1;
    if (nv->nst[SG_HOLD] < NAV_MIN_HOLD) {
        const double dof = 3.0 * NAV_MIN_HOLD;
        char known[160];
        size_t len;
        /* none: no innovation to average (it read "0 stances ...; the mean
         * innovation of fewer than 10 is not known to -44 % / +57 %", an
         * interval about a mean that does not exist) */
        if (nv->nst[SG_HOLD] == 0) {
            snprintf(known, sizeof known, "no stance with zero-velocity updates, so no innovation to average");
        } else {
            snprintf(known, sizeof known,
                     "%d stance%s with zero-velocity updates; the mean innovation of fewer than %d is not known to "
                     "-%.0f %% / +%.0f %% (95 %%)",
                     nv->nst[SG_HOLD], nv->nst[SG_HOLD] == 1 ? "" : "s", NAV_MIN_HOLD,
                     100.0 * (1.0 - gsl_cdf_chisq_Pinv(0.025, dof) / dof),
                     100.0 * (gsl_cdf_chisq_Pinv(0.975, dof) / dof - 1.0));
        }
        len = (size_t)snprintf(r->why, sizeof r->why, "the held-out segment has %s", known);
        r->confident = 0;
        if (r->opts.cmd != NULL && strcmp(r->opts.cmd, "simgap") == 0 && len < sizeof r->why) {
            /* simgap's remedy; simgap-validate has no --fit-frac and names
             * its own (--walk-duration) after this */
            snprintf(r->why + len, sizeof r->why - len, ": a longer walk, %d or more stances in its last %.0f %%%s%g%s",
                     NAV_MIN_HOLD, 100.0 * (1.0 - r->opts.fit_frac),
                     r->opts.fit_frac > 0.2 + 1e-9 ? " (or a lower --fit-frac, " : " (--fit-frac ", r->opts.fit_frac,
                     r->opts.fit_frac > 0.2 + 1e-9 ? " now, to hold out more of it)" : ", holds out the most it can)");
        }
    }
    /* baseline noise */
    if (r->opts.profile != NULL) {
        fnav_profile_t p = nv->cfg.profile;
        nv->from_profile = 1;
        for (c = 0; c < 3; c++) {
            nv->white[c] = (double)p.accel_noise_mps2_rthz[c];
            nv->white[3 + c] = (double)p.gyro_noise_rps_rthz[c];
            nv->ar1_tau[c] = (double)p.accel_tau_s[c];
            nv->ar1_tau[3 + c] = (double)p.gyro_tau_s[c];
            nv->ar1_sig[c] = (double)p.accel_bias_sigma_mps2[c];
            nv->ar1_sig[3 + c] = (double)p.gyro_bias_sigma_rps[c];
        }
    } else {
        stance_noise(&rw, &nv->real, r->segs.start[SG_FIT][0], r->segs.start[SG_FIT][0] + r->segs.n[SG_FIT][0],
                     r->rate_hz, nv->white);
    }
    for (c = 0; c < SG_NCH; c++) {
        double *x = (double *)malloc(((size_t)r->n + 1) * sizeof *x);
        long k;
        if (x == NULL) {
            return -1;
        }
        for (k = 0; k < r->n; k++) {
            x[k] = c < 3 ? log->acc[k][c] : log->gyr[k][c - 3];
        }
        nv->q[c] = sg_lattice_step(x, (size_t)r->n, &nv->qz[c]);
        nv->q_fit[c] = nv->q_full[c] = nv->q_base[c] = (double)NAN;
        if (!(nv->qz[c] > gsl_cdf_ugaussian_Qinv(0.5 * alpha / SG_NCH))) {
            nv->q[c] = 0.0;
        }
        free(x);
    }
    find_saturation(&rw, r->constant, r->segs.start[SG_FIT][0], r->segs.start[SG_FIT][0] + r->segs.n[SG_FIT][0],
                    nv->sat, nv->nsat);
    /* the twin's truth */
    nv->mf = (double(*)[3])malloc(((size_t)r->n + 1) * sizeof *nv->mf);
    nv->mw = (double(*)[3])malloc(((size_t)r->n + 1) * sizeof *nv->mw);
    nv->if_ = (double(*)[3])malloc(((size_t)r->n + 1) * sizeof *nv->if_);
    nv->iw = (double(*)[3])malloc(((size_t)r->n + 1) * sizeof *nv->iw);
    nv->tp = (double(*)[3])malloc(((size_t)r->n + 1) * sizeof *nv->tp);
    if (nv->mf == NULL || nv->mw == NULL || nv->if_ == NULL || nv->iw == NULL || nv->tp == NULL) {
        return -1;
    }
    twin_truth(&nv->real, &rw, (double)nv->cfg.gravity_mps2, nv->mf, nv->mw, nv->tp);
    means_to_inst((const double(*)[3])nv->mf, r->n, nv->if_);
    means_to_inst((const double(*)[3])nv->mw, r->n, nv->iw);
    if (getenv("SG_NAVDEBUG") != NULL) {
        /* development aid: the twin truth as a CSV log */
        FILE *df = fopen(getenv("SG_NAVDEBUG"), "w");
        long k;
        if (df != NULL) {
            fprintf(df, "t,ax,ay,az,gx,gy,gz\n");
            for (k = 0; k < r->n; k++) {
                fprintf(df, "%.9f,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", (double)(rw.t_ns[k] - rw.t_ns[0]) * 1e-9,
                        nv->mf[k][0], nv->mf[k][1], nv->mf[k][2], nv->mw[k][0], nv->mw[k][1], nv->mw[k][2]);
            }
            fclose(df);
        }
    }
    /* real points */
    for (g = 0; g < SG_NSEG; g++) {
        nv->real_v[g] = (double *)malloc(256 * sizeof(double));
        if (nv->real_v[g] == NULL) {
            return -1;
        }
    }
    if (walk_points(nv, &r->segs, &rw, &nv->real, NULL, 1, nv->pl, nv->real_v) != 0) {
        snprintf(err, err_size, "navigation statistics failed");
        return -1;
    }
    for (g = 0; g < SG_NSEG; g++) {
        nv->twin_v[g] = (double *)malloc(((size_t)S * nv->pl[g].n + 1) * sizeof(double));
        if (nv->twin_v[g] == NULL) {
            return -1;
        }
    }
    if (!r->opts.quiet) {
        fprintf(stderr, "simgap: %d baseline twins of the walk, two sampling conventions...\n", S);
    }
    /* the sampling convention is part of the baseline: both are simulated
     * and the one with the smaller fit-segment gap is kept */
    {
        int conv;
        double *tv[2][SG_NSEG];
        sg_cmp_t cc[2][SG_NSEG];
        memset(cc, 0, sizeof cc);
        for (conv = 0; conv < 2; conv++) {
            nv->tf = conv ? nv->if_ : nv->mf;
            nv->tw = conv ? nv->iw : nv->mw;
            for (g = 0; g < SG_NSEG; g++) {
                tv[conv][g] = (double *)malloc(((size_t)S * nv->pl[g].n + 1) * sizeof(double));
                if (tv[conv][g] == NULL) {
                    return -1;
                }
            }
            if (run_twins(nv, &r->segs, &rw, NULL, S, seed, tv[conv]) != 0) {
                snprintf(err, err_size, "twin simulation failed");
                return -1;
            }
        }
        /* a window in which the real has a stance begin but a twin none has
         * no twin statistic (the twin's is the placeholder ln 1e-30): not
         * compared either (a 6 s walk's window would read "real 0.0007 twin
         * 1e-30 (sd 1e-12) z +13.5" and be located as a gap) */
        for (g = 0; g < SG_NSEG; g++) {
            size_t k;
            int s2;
            for (k = 0; k < nv->pl[g].n; k++) {
                sg_point_t *p = &nv->pl[g].p[k];
                if (p->dom != SG_NAV || p->kind != SG_NAV_WIN || p->empty) {
                    continue;
                }
                for (conv = 0; conv < 2; conv++) {
                    for (s2 = 0; s2 < S; s2++) {
                        if (tv[conv][g][(size_t)s2 * nv->pl[g].n + k] <= lnpos(0.0)) {
                            p->empty = NAV_EMPTY_TWIN;
                        }
                    }
                }
            }
        }
        for (conv = 0; conv < 2; conv++) {
            for (g = 0; g < SG_NSEG; g++) {
                if (sg_compare(&nv->pl[g], nv->real_v[g], tv[conv][g], S, NULL, NULL, alpha, &cc[conv][g]) != 0) {
                    return -1;
                }
            }
            for (g = 0; g < SG_NSEG; g++) {
                if (cc[conv][g].undefined > SG_CMP_EMPTY) {
                    break;
                }
            }
            if (g < SG_NSEG && (r->confident || nv->nst[SG_FIT] > 0 || nv->from_profile)) {
                /* nothing to test the walk against (a noise-free log, or
                 * statistics out of range): an input the diagnosis cannot
                 * answer, said as such. But a walk too short for lack of
                 * stances is said to be too short: with no stance in the
                 * fit segment the twins get no noise (it is measured in the
                 * stances) and do not vary, and a foot that never stood
                 * still would be refused as "a noise-free log?" with no
                 * summary or JSON */
                int c2, g2;
                snprintf(err, err_size, "the navigation gap of the walk cannot be tested: %s",
                         nav_cmp_why(nv, &cc[conv][g]));
                for (c2 = 0; c2 < 2; c2++) { /* both conventions were simulated; cc of a later one is zeroed */
                    for (g2 = 0; g2 < SG_NSEG; g2++) {
                        free(tv[c2][g2]);
                        sg_cmp_free(&cc[c2][g2]);
                    }
                }
                return -1;
            }
            nv->G_fit_conv[conv] = cc[conv][SG_FIT].G;
            if (getenv("SG_NAVDEBUG") != NULL) {
                fprintf(stderr, "conv %d: nis_first twin %g real %g\n", conv, exp(cc[conv][SG_FULL].twin_mean[0]),
                        exp(nv->real_v[SG_FULL][0]));
            }
        }
        nv->inst = nv->G_fit_conv[1] < nv->G_fit_conv[0];
        nv->tf = nv->inst ? nv->if_ : nv->mf;
        nv->tw = nv->inst ? nv->iw : nv->mw;
        for (g = 0; g < SG_NSEG; g++) {
            free(nv->twin_v[g]);
            nv->twin_v[g] = tv[nv->inst][g];
            nv->cmp[g] = cc[nv->inst][g];
            free(tv[!nv->inst][g]);
            sg_cmp_free(&cc[!nv->inst][g]);
        }
    }
    nv->gap = nv->cmp[SG_FULL].significant || nv->cmp[SG_HOLD].significant;
    /* locations: navigation points beyond the critical z */
    {
        const sg_plist_t *pl = &nv->pl[SG_FULL];
        size_t j;
        for (j = 0; j < pl->n && nv->nloc < 32; j++) {
            const sg_cmp_t *cc = &nv->cmp[SG_FULL];
            /* an undefined comparison (a walk too short for one) locates nothing */
            if (!cc->undefined && fabs(cc->z[j]) > cc->z_crit) {
                sg_loc_t *L = &nv->loc[nv->nloc++];
                L->dom = pl->p[j].dom;
                L->ch = pl->p[j].ch;
                L->kind = pl->p[j].kind;
                if (L->dom == SG_NAV && L->kind == SG_NAV_AXIS) {
                    L->ch = (int)pl->p[j].x; /* the n-frame axis, 0 1 2 */
                }
                L->seg = SG_FULL;
                L->x_lo = pl->p[j].x_lo;
                L->x_hi = pl->p[j].x_hi;
                L->peak_z = cc->z[j];
                /* the navigation statistics are logs (ratio real/twin) but
                 * whiteness and the lattice's normal score are not (real -
                 * twin, as for a static log; as a log the lattice would read
                 * exp(168) = 2e78) */
                L->ratio = (L->dom == SG_NAV && pl->p[j].kind != SG_NAV_WHITE)
                               ? exp(nv->real_v[SG_FULL][j] - cc->twin_mean[j])
                               : nv->real_v[SG_FULL][j] - cc->twin_mean[j];
                L->npts = 1;
            }
        }
    }
    /* attribution: the motion effects by innovation regression (fit on the
     * fit stances, tested on the held-out ones), saturation and quantisation
     * by their evidence on both segments; then twins of the selected effect
     * for the held-out navigation gap before and after */
    {
        firsts_t *fr = (firsts_t *)calloc(1, sizeof *fr);
        const double zacc = gsl_cdf_ugaussian_Qinv(r->opts.alpha / (double)(3 + 2 * SG_NCH));
        const double t_split = (double)(rw.t_ns[r->segs.start[SG_HOLD][0]] - rw.t_ns[0]) * 1e-9;
        const double t_hold = nv->hold_from < rw.n ? nv->hold_from_s : (double)INFINITY;
        navstep_t *st = &nv->step[0];
        static const int fams[] = { FNAV_EFFECT_SCALE, FNAV_EFFECT_MISALIGN, FNAV_EFFECT_GSENS };
        int f, i, order[NAV_MAX_CAND], nord = 0;
        double sath[SG_NCH];
        int nsath[SG_NCH];
        if (fr == NULL) {
            return -1;
        }
        memset(st, 0, sizeof *st);
        st->selected = -1;
        st->G_hold_before = nv->cmp[SG_HOLD].G;
        st->G_fit_before = nv->cmp[SG_FIT].G;
        if (firsts_of(&nv->real, rw.t_ns, 0, r->n, fr) != 0) {
            free(fr);
            return -1;
        }
        find_saturation(&rw, r->constant, r->segs.start[SG_HOLD][0], r->segs.start[SG_HOLD][0] + r->segs.n[SG_HOLD][0],
                        sath, nsath);
        for (f = 0; f < 3 && r->confident; f++) {
            navcand_t cd;
            if (!r->opts.quiet) {
                fprintf(stderr, "simgap: fitting %s on the fit stances...\n",
                        fnav_imuerr_effect_info((fnav_effect_id_t)fams[f])->name);
            }
            if (fit_family(nv, &r->segs, &rw, fr, t_split, t_hold, NULL, fams[f], &cd) == 0 && cd.npar > 0) {
                st->cand[st->ncand++] = cd;
            }
        }
        for (c = 0; c < SG_NCH && st->ncand < NAV_MAX_CAND; c++) {
            if (nv->sat[c] > 0.0) {
                navcand_t cd;
                memset(&cd, 0, sizeof cd);
                cd.id = FNAV_EFFECT_SATURATION;
                cd.npar = 1;
                cd.ch[0] = c;
                cd.val[0] = nv->sat[c];
                cd.dQ = (double)nv->nsat[c];
                /* held out: the same flat top again (at least 3 samples) */
                cd.dQ_hold = (double)nsath[c];
                cd.z_hold = (sath[c] > 0.0 && fabs(sath[c] - nv->sat[c]) <= 1e-6 * nv->sat[c]) ? SG_ZCAP : 0.0;
                cd.expl = cd.expl_lo = cd.expl_hi = (double)NAN;
                st->cand[st->ncand++] = cd;
            }
        }
        for (c = 0; c < SG_NCH; c++) {
            /* a quantiser puts every difference on its lattice; a channel
             * whose values are only partly coherent with the step (the
             * NGIMU long walk's gx and gz) is not one, and twins that
             * quantise it overshoot its score (there, held out: real 42
             * and 11, quantised twins 150, the baseline's 1): a candidate
             * needs a fit-segment score nearer the quantiser's than the
             * baseline twins' (NaN, set with the lattice, when none) */
            long fa = r->segs.start[SG_FIT][0], fb = fa + r->segs.n[SG_FIT][0];
            size_t j;
            if (!(nv->q[c] > 0.0)) {
                continue;
            }
            nv->q_fit[c] = lattice_val(&rw, c, fa, fb, nv->q[c]);
            nv->q_full[c] = lattice_full(fa, fb);
            nv->q_base[c] = 0.0; /* N(0, 1) for continuous values */
            for (j = 0; j < nv->pl[SG_FIT].n; j++) {
                if (nv->pl[SG_FIT].p[j].dom == SG_LATTICE && nv->pl[SG_FIT].p[j].ch == c &&
                    nv->cmp[SG_FIT].twin_mean != NULL) {
                    nv->q_base[c] = nv->cmp[SG_FIT].twin_mean[j];
                }
            }
        }
        for (c = 0; c < SG_NCH && st->ncand < NAV_MAX_CAND; c++) {
            if (lattice_complete(nv, c)) {
                navcand_t cd;
                memset(&cd, 0, sizeof cd);
                cd.id = FNAV_EFFECT_QUANT;
                cd.npar = 1;
                cd.ch[0] = c;
                cd.val[0] = nv->q[c];
                cd.dQ = nv->qz[c];
                cd.z_hold = lattice_val(&rw, c, r->segs.start[SG_HOLD][0],
                                        r->segs.start[SG_HOLD][0] + r->segs.n[SG_HOLD][0], nv->q[c]);
                cd.dQ_hold = cd.z_hold;
                cd.expl = cd.expl_lo = cd.expl_hi = (double)NAN;
                st->cand[st->ncand++] = cd;
            }
        }
        /* accepted: supported on the fit segment and significant held out;
         * ranked by the held-out z */
        for (i = 0; i < st->ncand; i++) {
            const navcand_t *cd = &st->cand[i];
            int isfam = cd->id != FNAV_EFFECT_SATURATION && cd->id != FNAV_EFFECT_QUANT;
            if ((!isfam || cd->dQ >= 10.83) && cd->z_hold > zacc) {
                st->cand[i].accepted = 1;
                add_by_z(st->cand, order, nord++, i);
            }
        }
        if (nord > 1) {
            const int b0 = parsimony_pick(st->cand, order, nord);
            if (b0 != 0) {
                int t = order[b0];
                memmove(order + 1, order, (size_t)b0 * sizeof *order);
                order[0] = t;
            }
        }
        st->selected = nord > 0 ? order[0] : -1;
        nv->nsteps = st->ncand > 0 ? 1 : 0;
        if (nord > 0) {
            int k4;
            nv->sel[0] = st->cand[order[0]];
            nv->sel_expl[0] = st->cand[order[0]].expl;
            nv->nsel = 1;
            /* a lattice or a flat top is a property of each channel, tested
             * on that channel alone: when one is selected, every other
             * channel whose own lattice (flat top) passed joins it, one
             * effect over several channels (a sensor quantises all six) */
            if (nv->sel[0].id == FNAV_EFFECT_QUANT || nv->sel[0].id == FNAV_EFFECT_SATURATION) {
                for (k4 = 1; k4 < nord && nv->sel[0].npar < 24; k4++) {
                    navcand_t *o = &st->cand[order[k4]];
                    if (o->id == nv->sel[0].id) {
                        nv->sel[0].ch[nv->sel[0].npar] = o->ch[0];
                        nv->sel[0].k[nv->sel[0].npar] = o->k[0];
                        nv->sel[0].val[nv->sel[0].npar] = o->val[0];
                        nv->sel[0].npar++;
                        o->joined = 1;
                    }
                }
                for (k4 = 1; k4 < nv->sel[0].npar; k4++) { /* in channel order */
                    navcand_t *m = &nv->sel[0];
                    int k5;
                    for (k5 = k4; k5 > 0 && m->ch[k5 - 1] > m->ch[k5]; k5--) {
                        int tc = m->ch[k5], tk = m->k[k5];
                        double tvl = m->val[k5];
                        m->ch[k5] = m->ch[k5 - 1];
                        m->k[k5] = m->k[k5 - 1];
                        m->val[k5] = m->val[k5 - 1];
                        m->ch[k5 - 1] = tc;
                        m->k[k5 - 1] = tk;
                        m->val[k5 - 1] = tvl;
                    }
                }
            }
        }
        /* further steps: the other linear families refitted given the
         * selected ones (their clean twins carry them) */
        for (i = 1; i < r->opts.max_steps && nv->nsel == i && nv->sel[0].id != FNAV_EFFECT_SATURATION &&
                    nv->sel[0].id != FNAV_EFFECT_QUANT;
             i++) {
            navstep_t *s2 = &nv->step[i];
            int bi, m2, ord2[3], n2 = 0; /* ord2: the accepted of the three families, by held-out z */
            memset(s2, 0, sizeof *s2);
            s2->selected = -1;
            /* no twins are run before a later step: its held-out and fit G
             * are not known (null in the JSON, not 0) */
            s2->G_hold_before = s2->G_fit_before = (double)NAN;
            for (f = 0; f < 3; f++) {
                navcand_t cd;
                int used = 0;
                for (m2 = 0; m2 < nv->nsel; m2++) {
                    used |= nv->sel[m2].id == fams[f];
                }
                if (used || nv->nsel > 1) {
                    continue;
                }
                if (fit_family(nv, &r->segs, &rw, fr, t_split, t_hold, &nv->sel[0], fams[f], &cd) == 0 && cd.npar > 0) {
                    s2->cand[s2->ncand] = cd;
                    if (cd.dQ >= 10.83 && cd.z_hold > zacc) { /* accepted, as in the first step */
                        s2->cand[s2->ncand].accepted = 1;
                        add_by_z(s2->cand, ord2, n2++, s2->ncand);
                    }
                    s2->ncand++;
                }
            }
            nv->nsteps = i + 1;
            if (n2 == 0) {
                break;
            }
            bi = ord2[parsimony_pick(s2->cand, ord2, n2)];
            s2->selected = bi;
            nv->sel[nv->nsel] = s2->cand[bi];
            nv->sel_expl[nv->nsel] = s2->cand[bi].expl;
            nv->nsel++;
        }
        /* twins of the top effect: the navigation gap before and after */
        if (nv->nsel > 0) {
            navcand_t *cd = &nv->sel[0], *top = &st->cand[order[0]];
            double *tv[SG_NSEG];
            int okv = 1;
            for (g = 0; g < SG_NSEG; g++) {
                tv[g] = (double *)malloc(((size_t)S * nv->pl[g].n + 1) * sizeof(double));
                okv &= tv[g] != NULL;
            }
            if (okv && run_twins(nv, &r->segs, &rw, cd, S, seed, tv) == 0) {
                for (g = 0; g < SG_NSEG; g++) {
                    if (sg_compare(&nv->pl[g], nv->real_v[g], tv[g], S, NULL, NULL, alpha, &nv->cmp_final[g]) != 0) {
                        okv = 0;
                    }
                    nv->twin_f[g] = tv[g];
                }
                if (okv) {
                    cd->simulated = top->simulated = 1;
                    cd->G_fit = top->G_fit = nv->cmp_final[SG_FIT].G;
                    cd->G_hold = top->G_hold = nv->cmp_final[SG_HOLD].G;
                    cd->dG_hold = top->dG_hold = nv->cmp[SG_HOLD].G - cd->G_hold;
                }
            } else {
                for (g = 0; g < SG_NSEG; g++) {
                    free(tv[g]);
                }
            }
        }
        nv->within_noise = nv->nsel > 0 ? (nv->cmp_final[SG_HOLD].z != NULL && !nv->cmp_final[SG_HOLD].significant)
                                        : !nv->cmp[SG_HOLD].significant;
        /* the navigation twins' gap is dominated by the filter's own model
         * (stance, integration), which a twin built from the filter's
         * trajectory cannot reproduce (docs/simgap.md): it is reported as the
         * model gap; the sensor gap is what the effects explain on held-out
         * stances, the lattice and the flat tops */
        /* the sensor's values of effects selected together, jointly */
        if (nv->nsel > 1) {
            to_sensor(&nv->sel[0], &nv->sel[1]);
        }
        nv->model_gap = nv->gap;
        nv->gap = nv->nsel > 0;
        firsts_free(fr);
        free(fr);
    }
    return 0;
}

/* ------------------------------------------------------------ outputs */

void sg_nav_verdict_counts(const sg_nav_t *nv, int *gaps, int *sel, int *open)
{
    (void)open; /* what remains of a walk's gap is the filter's model: reported, not counted */
    if (nv->gap) {
        (*gaps)++;
        *sel += nv->nsel;
    }
}

void sg_nav_free(sg_nav_t *nv)
{
    int g;
    navrun_free(&nv->real);
    free(nv->mf);
    free(nv->mw);
    free(nv->if_);
    free(nv->iw);
    free(nv->tp);
    free(nv->t_s);
    for (g = 0; g < SG_NSEG; g++) {
        sg_plist_free(&nv->pl[g]);
        free(nv->real_v[g]);
        free(nv->twin_v[g]);
        free(nv->twin_f[g]);
        sg_cmp_free(&nv->cmp[g]);
        sg_cmp_free(&nv->cmp_final[g]);
    }
    memset(nv, 0, sizeof *nv);
}

static const char *kind_name(int k)
{
    static const char *const nm[SG_NAV_NKIND] = { "nis_first", "nis_all", "axis", "whiteness", "residual_velocity",
                                                   "window", "drift_h", "drift_v" };
    return (k >= 0 && k < SG_NAV_NKIND) ? nm[k] : "?";
}

/* The n-frame axis of an `axis` point or location, with its leading space. */
static const char *axis_name(int a)
{
    return a == 0 ? " x" : (a == 1 ? " y" : " z");
}

/* 1 when candidate j of step st ties with the step's selected one: a
 * linear family, accepted (supported on the fit segment, significant held
 * out), its held-out z within 1 of the best accepted one's (the parsimony
 * rule's band, parsimony_pick), with no more parameters than the selected: the held-out stances do not tell them apart, and which
 * is ranked first can turn on the probe's rounding (the consistency audit
 * of 2026-12-06: a 40 % gz scale on a simulated walk against a gz
 * g-sensitivity from az, held-out z 7.31 and 7.34). */
static int tied_with_selected(const navstep_t *st, int j)
{
    const navcand_t *sel, *cd;
    double zbest;
    int k;
    if (st->selected < 0 || j == st->selected || j >= st->ncand) {
        return 0;
    }
    sel = &st->cand[st->selected];
    cd = &st->cand[j];
    zbest = sel->z_hold; /* the band of parsimony_pick: within 1 of the best accepted */
    for (k = 0; k < st->ncand; k++) {
        if (st->cand[k].accepted && st->cand[k].z_hold > zbest) {
            zbest = st->cand[k].z_hold;
        }
    }
    return cd->accepted && cd->id != FNAV_EFFECT_SATURATION && cd->id != FNAV_EFFECT_QUANT &&
           sel->id != FNAV_EFFECT_SATURATION && sel->id != FNAV_EFFECT_QUANT && cd->id != sel->id && !cd->joined &&
           cd->z_hold >= zbest - 1.0 && cd->npar <= sel->npar;
}

static void cand_text(char *b, size_t n, const navcand_t *cd)
{
    const fnav_effect_info_t *info = fnav_imuerr_effect_info((fnav_effect_id_t)cd->id);
    size_t o = (size_t)snprintf(b, n, "%s", info != NULL ? info->name : "?");
    int i;
    for (i = 0; i < cd->npar && o < n; i++) {
        o += (size_t)snprintf(b + o, n - o, "%s", i ? ", " : " (");
        if (o < n) {
            o += (size_t)sg_nav_param_text(b + o, n - o, cd->id, cd->ch[i], cd->k[i], cd->val[i], cd->at[i]);
        }
    }
    if (cd->npar > 0 && o < n) {
        snprintf(b + o, n - o, ")");
    }
}

void sg_nav_print(const sg_nav_t *nv, FILE *f, const sg_result_t *r)
{
    int c, i, j;
    size_t k;
    char b[256];
    /* the held-out stances begin with the first that begins at or after the
     * split: a stance across it is the fit's alone, and fit + held out =
     * all */
    fprintf(f, "navigation: %d stance%s (fit %d, held out %d", nv->nst[SG_FULL], nv->nst[SG_FULL] == 1 ? "" : "s",
            nv->nst[SG_FIT], nv->nst[SG_HOLD]);
    if (nv->hold_from_s == nv->hold_from_s) {
        fprintf(f, " from t %.1f s, the first stance to begin at or after the split at %.1f s", nv->hold_from_s,
                r->seg_start_s[SG_HOLD][0]);
    } else {
        fprintf(f, ": no stance begins at or after the split at %.1f s", r->seg_start_s[SG_HOLD][0]);
    }
    fprintf(f, "); twin noise %s:", nv->from_profile ? "from the profile" : "from the stances (white)");
    for (c = 0; c < SG_NCH; c++) {
        fprintf(f, " %s %.3g", sg_channel_name(c), nv->white[c]);
    }
    fprintf(f, " /sqrt(Hz); twin samples: %s (fit-segment gap %.3g as interval means, %.3g as instantaneous values)\n",
            nv->inst ? "instantaneous values" : "interval means", nv->G_fit_conv[0], nv->G_fit_conv[1]);
    for (c = 0; c < SG_NCH; c++) {
        if (nv->q[c] > 0.0) {
            fprintf(f, "  %s lies on a lattice of step %.4g (z %.0f)", sg_channel_name(c), nv->q[c], nv->qz[c]);
            if (nv->q_fit[c] == nv->q_fit[c] && !lattice_complete(nv, c)) {
                fprintf(f, ", only partly (fit-segment score %.0f; a quantiser's %.0f, the twins' %.0f): not a quantiser",
                        nv->q_fit[c], nv->q_full[c], nv->q_base[c]);
            }
            fputc('\n', f);
        }
        if (nv->sat[c] > 0.0) {
            fprintf(f, "  %s reaches %.4g %d times (flat tops)\n", sg_channel_name(c), nv->sat[c], nv->nsat[c]);
        }
    }
    for (i = 0; i < SG_NSEG; i++) {
        static const char *const nm[SG_NSEG] = { "whole walk", "fit", "held out" };
        if (nv->cmp[i].undefined) { /* it printed "crit nan" */
            fprintf(f, "  %-10s not tested: %s\n", nm[i], nav_cmp_why(nv, &nv->cmp[i]));
            continue;
        }
        fprintf(f, "  %-10s G %.3g (null %.2g, crit %.2g, max |z| %.1f)%s\n", nm[i], nv->cmp[i].G, nv->cmp[i].null_mean,
                nv->cmp[i].G_crit, nv->cmp[i].maxz, nv->cmp[i].significant ? " SIGNIFICANT" : "");
    }
    for (k = 0; k < nv->pl[SG_FULL].n; k++) {
        const sg_point_t *p = &nv->pl[SG_FULL].p[k];
        if (p->dom != SG_NAV) {
            continue;
        }
        if (p->empty) {
            fprintf(f, "    %-17s %st %.1f-%.1f s: %s, not compared\n", kind_name(p->kind),
                    p->kind == SG_NAV_AXIS ? (p->x == 0.0 ? "x " : p->x == 1.0 ? "y " : "z ") : "", p->x_lo, p->x_hi,
                    p->kind == SG_NAV_WIN && p->empty == NAV_EMPTY_TWIN ? "no stance begins in it in a twin"
                    : p->kind == SG_NAV_WIN    ? "no stance begins in it (a stand)"
                    : p->kind == SG_NAV_WHITE  ? "no stance with two consecutive updates"
                    : (p->kind == SG_NAV_DRIFT_H || p->kind == SG_NAV_DRIFT_V) ? "fewer than two stances"
                                               : "no stance");
            continue;
        }
        /* the sd is z's denominator, of the log of the statistic but for
         * whiteness: printed next to the statistic itself as "sd 0.08" it
         * would read as 0.64 +- 0.08 NIS for a spread of 8 % */
        if (p->kind == SG_NAV_WIN) { /* which window: otherwise the six rows read alike */
            snprintf(b, sizeof b, "t %.1f-%.1f s", p->x_lo, p->x_hi);
        } else {
            snprintf(b, sizeof b, "%s", p->kind == SG_NAV_AXIS ? (p->x == 0.0 ? "x" : p->x == 1.0 ? "y" : "z") : "");
        }
        fprintf(f, "    %-17s %-15s real %-9.4g twin %-9.4g (%s %.3g) z %+.1f\n", kind_name(p->kind), b,
                p->kind == SG_NAV_WHITE ? nv->real_v[SG_FULL][k] : exp(nv->real_v[SG_FULL][k]),
                p->kind == SG_NAV_WHITE ? nv->cmp[SG_FULL].twin_mean[k] : exp(nv->cmp[SG_FULL].twin_mean[k]),
                p->kind == SG_NAV_WHITE ? "sd" : "sd of ln", nv->cmp[SG_FULL].sd_tot[k], nv->cmp[SG_FULL].z[k]);
    }
    for (k = 0; k < nv->nloc; k++) {
        const sg_loc_t *L = &nv->loc[k];
        if (L->dom == SG_LATTICE) { /* a channel's lattice statistic, not a navigation point */
            fprintf(f, "  gap: lattice %s, step %.4g, %.1f sigma %s the twin\n", sg_channel_name(L->ch), L->x_lo,
                    fabs(L->peak_z), L->peak_z > 0 ? "above" : "below");
        } else {
            fprintf(f, "  gap: navigation %s%s, t %.1f-%.1f s, %.1f sigma %s the twin\n", kind_name(L->kind),
                    L->kind == SG_NAV_AXIS ? axis_name(L->ch) : "", L->x_lo, L->x_hi, fabs(L->peak_z),
                    L->peak_z > 0 ? "above" : "below");
        }
    }
    if (nv->nsteps > 0) {
        fprintf(f, "attribution (innovation regression on the fit stances; held out: objective change and its z):\n");
    }
    for (i = 0; i < nv->nsteps; i++) {
        for (j = 0; j < nv->step[i].ncand; j++) {
            const navcand_t *cd = &nv->step[i].cand[j];
            cand_text(b, sizeof b, cd);
            fprintf(f, "  %c %-52s fit %.1f; held out: %+.1f, z %+.1f",
                    j == nv->step[i].selected ? '*' : (cd->joined ? '+' : ' '), b,
                    cd->dQ, cd->dQ_hold, cd->z_hold);
            if (cd->expl == cd->expl) {
                fprintf(f, ", explains %.0f %% of the held-out innovation excess", 100.0 * cd->expl);
            }
            if (cd->simulated) {
                fprintf(f, "; twins: held-out gap %.3g -> %.3g", nv->step[i].G_hold_before, cd->G_hold);
            }
            fprintf(f, "\n");
            if (cd->nalt > 0) {
                const fnav_effect_info_t *info = fnav_imuerr_effect_info((fnav_effect_id_t)cd->id);
                int m;
                fprintf(f, "      as good a fit (within chi2 1) in place of %s.%s:", sg_channel_name(cd->ch[0]),
                        info->params[cd->k[0]].name);
                for (m = 0; m < cd->nalt; m++) {
                    sg_nav_param_text(b, sizeof b, cd->id, cd->alt_ch[m], cd->alt_k[m], cd->alt_val[m], cd->alt_at[m]);
                    fprintf(f, "%s %s", m ? "," : "", b);
                }
                fprintf(f, "\n");
            }
        }
        {
            int nt = 0;
            for (j = 0; j < nv->step[i].ncand; j++) {
                if (tied_with_selected(&nv->step[i], j)) {
                    cand_text(b, sizeof b, &nv->step[i].cand[j]);
                    fprintf(f, "%s %s", nt++ ? ";" : "    tied with the selected (held-out z within 1, no more parameters):",
                            b);
                }
            }
            if (nt > 0) {
                fprintf(f, "\n    these stances do not tell them apart: read the selected as one of them\n");
            }
        }
    }
    if (nv->model_gap) {
        fprintf(f, "  the navigation twins' innovations differ from the real's (G above): a twin built from the filter's own\n"
                   "  trajectory cannot carry the filter's stance and integration model errors, which dominate foot-mounted\n"
                   "  innovations even with a perfect sensor (docs/simgap.md); this model gap is reported, not attributed\n");
    }
    for (i = 0; i < nv->nsel; i++) {
        cand_text(b, sizeof b, &nv->sel[i]);
        fprintf(f, "  selected: %s\n", b);
    }
}

static cJSON *cand_json(const navcand_t *cd)
{
    const fnav_effect_info_t *info = fnav_imuerr_effect_info((fnav_effect_id_t)cd->id);
    cJSON *o = cJSON_CreateObject(), *a = cJSON_AddArrayToObject(o, "params");
    int i;
    cJSON_AddStringToObject(o, "effect", info != NULL ? info->name : "?");
    for (i = 0; i < cd->npar; i++) {
        cJSON *p = cJSON_CreateObject();
        cJSON_AddStringToObject(p, "channel", sg_channel_name(cd->ch[i]));
        cJSON_AddStringToObject(p, "param", info->params[cd->k[i]].name);
        hx_json_num(p, "value", cd->val[i]);
        hx_json_num(p, "trajectory_value", cd->has_eq ? cd->eq[i] : (double)NAN); /* null: not a linear family */
        sg_nav_bounds_json(p, cd->id, cd->k[i], cd->at[i]);
        cJSON_AddItemToArray(a, p);
    }
    {
        /* parameters the stances cannot tell from the first one (empty: none) */
        cJSON *alt = cJSON_AddArrayToObject(o, "indistinguishable");
        for (i = 0; i < cd->nalt; i++) {
            cJSON *p = cJSON_CreateObject();
            cJSON_AddStringToObject(p, "channel", sg_channel_name(cd->alt_ch[i]));
            cJSON_AddStringToObject(p, "param", info->params[cd->alt_k[i]].name);
            hx_json_num(p, "value", cd->alt_val[i]);
            sg_nav_bounds_json(p, cd->id, cd->alt_k[i], cd->alt_at[i]);
            cJSON_AddItemToArray(alt, p);
        }
    }
    hx_json_num(o, "fit_dQ", cd->dQ);
    hx_json_num(o, "held_out_dQ", cd->dQ_hold);
    hx_json_num(o, "held_out_z", cd->z_hold);
    hx_json_num(o, "explained", cd->expl);
    cJSON_AddNumberToObject(o, "stances_fit", cd->n_fit);
    cJSON_AddNumberToObject(o, "stances_held_out", cd->n_hold);
    cJSON_AddBoolToObject(o, "simulated", cd->simulated);
    if (cd->simulated) {
        hx_json_num(o, "G_fit", cd->G_fit);
        hx_json_num(o, "G_held_out", cd->G_hold);
        hx_json_num(o, "dG_held_out", cd->dG_hold);

    }
    return o;
}

void sg_nav_verdict_text(const sg_nav_t *nv, FILE *f, int *first)
{
    int i;
    char b[256];
    for (i = 0; i < nv->nsel; i++) {
        int j, nt = 0;
        cand_text(b, sizeof b, &nv->sel[i]);
        fprintf(f, "%s %s (walk: held-out stances", *first ? ":" : ";", b);
        for (j = 0; i < nv->nsteps && j < nv->step[i].ncand; j++) {
            if (tied_with_selected(&nv->step[i], j)) {
                fprintf(f, "%s%s", nt++ ? ", " : "; tied with ",
                        fnav_imuerr_effect_info((fnav_effect_id_t)nv->step[i].cand[j].id)->name);
            }
        }
        fprintf(f, ")");
        *first = 0;
    }
}

void sg_nav_verdict_json(const sg_nav_t *nv, cJSON *arr)
{
    int i, j;
    for (i = 0; i < nv->nsel; i++) {
        const navcand_t *cd = &nv->sel[i];
        const fnav_effect_info_t *info = fnav_imuerr_effect_info((fnav_effect_id_t)cd->id);
        cJSON *o = cJSON_CreateObject(), *ch = cJSON_AddArrayToObject(o, "channels"), *pa;
        uint32_t seen = 0u;
        cJSON_AddStringToObject(o, "effect", info != NULL ? info->name : "?");
        cJSON_AddStringToObject(o, "domain", "nav");
        for (j = 0; j < cd->npar; j++) {
            if (!((seen >> cd->ch[j]) & 1u)) {
                cJSON_AddItemToArray(ch, cJSON_CreateString(sg_channel_name(cd->ch[j])));
                seen |= 1u << cd->ch[j];
            }
        }
        pa = cJSON_AddArrayToObject(o, "params");
        for (j = 0; j < cd->npar; j++) {
            cJSON *p = cJSON_CreateObject();
            cJSON_AddStringToObject(p, "channel", sg_channel_name(cd->ch[j]));
            cJSON_AddStringToObject(p, "param", info != NULL ? info->params[cd->k[j]].name : "?");
            hx_json_num(p, "value", cd->val[j]);
            sg_nav_bounds_json(p, cd->id, cd->k[j], cd->at[j]);
            cJSON_AddItemToArray(pa, p);
        }
        cJSON_AddItemToArray(arr, o);
    }
}

void sg_nav_locations_json(const sg_nav_t *nv, cJSON *arr)
{
    size_t k;
    for (k = 0; k < nv->nloc; k++) {
        const sg_loc_t *L = &nv->loc[k];
        cJSON *lo = cJSON_CreateObject();
        if (L->dom == SG_LATTICE) {
            cJSON_AddStringToObject(lo, "channel", sg_channel_name(L->ch));
        } else {
            cJSON_AddNullToObject(lo, "channel");
        }
        cJSON_AddStringToObject(lo, "domain", sg_domain_name(L->dom));
        if (L->dom == SG_NAV) {
            cJSON_AddStringToObject(lo, "kind", kind_name(L->kind));
            if (L->kind == SG_NAV_AXIS) {
                cJSON_AddStringToObject(lo, "axis", axis_name(L->ch) + 1);
            }
        }
        cJSON_AddStringToObject(lo, "segment", "full");
        hx_json_num(lo, "x_lo", L->x_lo);
        hx_json_num(lo, "x_hi", L->x_hi);
        cJSON_AddStringToObject(lo, "x_unit", L->dom == SG_LATTICE ? "u" : "s");
        hx_json_num(lo, "peak_z", L->peak_z);
        hx_json_num(lo, "ratio", L->ratio);
        cJSON_AddNumberToObject(lo, "points", L->npts);
        cJSON_AddItemToArray(arr, lo);
    }
}

cJSON *sg_nav_json(const sg_nav_t *nv, const sg_result_t *r)
{
    static const char *const segn[SG_NSEG] = { "full", "fit", "held_out" };
    cJSON *o = cJSON_CreateObject(), *a, *w;
    int g, i, j, c;
    size_t k;
    (void)r;
    cJSON_AddNumberToObject(o, "stances_full", nv->nst[SG_FULL]);
    cJSON_AddNumberToObject(o, "stances_fit", nv->nst[SG_FIT]);
    cJSON_AddNumberToObject(o, "stances_held_out", nv->nst[SG_HOLD]);
    hx_json_num(o, "held_out_from_s", nv->hold_from_s);
    cJSON_AddStringToObject(o, "twin_noise", nv->from_profile ? "profile" : "stances");
    cJSON_AddStringToObject(o, "twin_sampling", nv->inst ? "instantaneous" : "interval-mean");
    hx_json_num(o, "G_fit_interval_mean", nv->G_fit_conv[0]);
    hx_json_num(o, "G_fit_instantaneous", nv->G_fit_conv[1]);
    w = cJSON_AddObjectToObject(o, "white_density");
    for (c = 0; c < SG_NCH; c++) {
        hx_json_num(w, sg_channel_name(c), nv->white[c]);
    }
    a = cJSON_AddArrayToObject(o, "lattices");
    for (c = 0; c < SG_NCH; c++) {
        if (nv->q[c] > 0.0) {
            cJSON *lo = cJSON_CreateObject();
            cJSON_AddStringToObject(lo, "channel", sg_channel_name(c));
            hx_json_num(lo, "step", nv->q[c]);
            hx_json_num(lo, "z", nv->qz[c]);
            hx_json_num(lo, "fit_score", nv->q_fit[c]);
            hx_json_num(lo, "quantiser_score", nv->q_full[c]);
            hx_json_num(lo, "twin_score", nv->q_base[c]);
            cJSON_AddBoolToObject(lo, "quantiser", lattice_complete(nv, c));
            cJSON_AddItemToArray(a, lo);
        }
    }
    a = cJSON_AddObjectToObject(o, "gap");
    for (g = 0; g < SG_NSEG; g++) {
        cJSON *s = cJSON_AddObjectToObject(a, segn[g]), *pts;
        hx_json_num(s, "G", nv->cmp[g].G);
        hx_json_num(s, "G_null_mean", nv->cmp[g].null_mean);
        hx_json_num(s, "G_null_sd", nv->cmp[g].null_sd);
        hx_json_num(s, "G_crit", nv->cmp[g].G_crit);
        hx_json_num(s, "max_abs_z", nv->cmp[g].maxz);
        hx_json_num(s, "z_crit", nv->cmp[g].z_crit);
        cJSON_AddBoolToObject(s, "significant", nv->cmp[g].significant);
        pts = cJSON_AddArrayToObject(s, "points");
        for (k = 0; k < nv->pl[g].n; k++) {
            const sg_point_t *p = &nv->pl[g].p[k];
            cJSON *po = cJSON_CreateObject();
            cJSON_AddStringToObject(po, "domain", sg_domain_name(p->dom));
            cJSON_AddStringToObject(po, "kind", p->dom == SG_NAV ? kind_name(p->kind) : sg_channel_name(p->ch));
            hx_json_num(po, "x", p->x);
            hx_json_num(po, "x_lo", p->x_lo);
            hx_json_num(po, "x_hi", p->x_hi);
            /* a placeholder (a window without a stance onset): null */
            hx_json_num(po, "real", p->empty ? (double)NAN : nv->real_v[g][k]);
            hx_json_num(po, "twin", p->empty ? (double)NAN : nv->cmp[g].twin_mean[k]);
            hx_json_num(po, "sd", p->empty ? (double)NAN : nv->cmp[g].sd_tot[k]);
            hx_json_num(po, "z", p->empty ? (double)NAN : nv->cmp[g].z[k]);
            cJSON_AddItemToArray(pts, po);
        }
    }
    a = cJSON_AddArrayToObject(o, "steps");
    for (i = 0; i < nv->nsteps; i++) {
        cJSON *s = cJSON_CreateObject(), *ca = cJSON_AddArrayToObject(s, "candidates");
        hx_json_num(s, "G_held_out_before", nv->step[i].G_hold_before);
        for (j = 0; j < nv->step[i].ncand; j++) {
            cJSON *co = cand_json(&nv->step[i].cand[j]);
            cJSON_AddBoolToObject(co, "selected", j == nv->step[i].selected);
            cJSON_AddBoolToObject(co, "joined", nv->step[i].cand[j].joined != 0);
            cJSON_AddBoolToObject(co, "tied_with_selected", tied_with_selected(&nv->step[i], j));
            cJSON_AddItemToArray(ca, co);
        }
        cJSON_AddItemToArray(a, s);
    }
    a = cJSON_AddArrayToObject(o, "selected");
    for (i = 0; i < nv->nsel; i++) {
        cJSON_AddItemToArray(a, cand_json(&nv->sel[i]));
    }
    cJSON_AddBoolToObject(o, "gap_significant", nv->gap);
    cJSON_AddBoolToObject(o, "model_gap", nv->model_gap);
    cJSON_AddBoolToObject(o, "within_noise", nv->within_noise);
    return o;
}

int sg_nav_plot(const sg_nav_t *nv, const sg_result_t *r, const char *dir, const char *cmd)
{
    hx_plot_t p;
    char path[HX_PLOT_PATH_SIZE];
    int ns, i;
    stance_t *st = stances_all(&nv->real, 0, nv->n, &ns);
    (void)r;
    if (st == NULL) {
        return -1;
    }
    snprintf(path, sizeof path, "%s/innovations.png", dir);
    if (hx_plot_open(&p, cmd, path, 1100, 700) != 0) {
        free(st);
        return -1;
    }
    fprintf(p.gp, "set multiplot layout 2,1 title 'Zero-velocity-update innovations of the real walk'\n");
    if (ns == 0) {
        /* no stance, no update: two empty panels that say so (gnuplot
         * refuses an empty log axis, and the run would exit 3 instead of
         * the too-short answer's 1) */
        fprintf(p.gp, "set xrange [0:1]\nset yrange [0:1]\nset xlabel 't [s]'\nset ylabel 'NIS'\n"
                      "set title 'NIS of the first update of each stance: no stance detected'\nplot -1 notitle\n"
                      "set title 'mean NIS over each stance: no stance detected'\nplot -1 notitle\n"
                      "unset multiplot\n");
        free(st);
        return hx_plot_close(&p, cmd);
    }
    /* one stance, or all at one time: a range around them (gnuplot warned
     * of an empty x range) */
    fprintf(p.gp, "set xrange [%.4f:%.4f]\n", nv->t_s[st[0].first] - 0.5, nv->t_s[st[ns - 1].first] + 0.5);
    fprintf(p.gp, "$d << EOD\n");
    for (i = 0; i < ns; i++) {
        /* the stance's start time, not the sample index over the mean rate
         * (after a 5 s gap every later stance would be drawn 5 s early,
         * apart from the summary's windows) */
        fprintf(p.gp, "%.4f %.6g %.6g\n", nv->t_s[st[i].first], st[i].nis_first,
                st[i].nupd > 0 ? st[i].nis_sum / st[i].nupd : 0.0);
    }
    fprintf(p.gp, "EOD\n");
    {
        int g = SG_FULL;
        double tw = 0.0;
        size_t k;
        for (k = 0; k < nv->pl[g].n; k++) {
            if (nv->pl[g].p[k].kind == SG_NAV_NIS_FIRST && nv->pl[g].p[k].dom == SG_NAV) {
                tw = exp(nv->cmp[g].twin_mean[k]);
            }
        }
        fprintf(p.gp, "set logscale y\nset xlabel 't [s]'\nset ylabel 'NIS'\nset title 'NIS of the first update of "
                      "each stance (line: the twins'' mean, 3 = chi-square mean)'\n");
        fprintf(p.gp, "plot $d using 1:2 with impulses lw 2 title 'real, first update', %.6g with lines lw 2 title "
                      "'twins (mean)', 3 with lines dt 2 lc rgb 'black' title 'chi2_3 mean'\n",
                tw);
    }
    {
        /* one stance (a still log read as a walk), or equal means: one value
         * on the log axis, and gnuplot warned "empty y range" on standard
         * error, --quiet or not; a factor 2 either side of it */
        double lo = HUGE_VAL, hi = 0.0;
        for (i = 0; i < ns; i++) {
            const double v = st[i].nupd > 0 ? st[i].nis_sum / st[i].nupd : 0.0;
            if (v > 0.0) {
                lo = v < lo ? v : lo;
                hi = v > hi ? v : hi;
            }
        }
        if (hi > 0.0 && hi < 1.01 * lo) {
            fprintf(p.gp, "set yrange [%.6g:%.6g]\n", 0.5 * lo, 2.0 * hi);
        }
    }
    fprintf(p.gp, "set title 'mean NIS over each stance'\nplot $d using 1:3 with impulses lw 2 title 'real'\n");
    fprintf(p.gp, "unset multiplot\n");
    free(st);
    return hx_plot_close(&p, cmd);
}

/* ------------------------------------------------------------ validation */

void sg_nav_scores(const sg_nav_t *nv, double *score, int neff, uint32_t *flagged)
{
    const sgv_effect_t *E;
    int n, i, j, c;
    E = sgv_effects(&n);
    (void)neff;
    for (i = 0; i < nv->nsel; i++) {
        for (j = 0; j < n; j++) {
            if (E[j].id == nv->sel[i].id && strcmp(E[j].name, "quant_shaped") != 0) {
                score[j] += nv->sel[i].dG_hold > 0.0 ? nv->sel[i].dG_hold : 1e-9;
                break;
            }
        }
        for (c = 0; c < nv->sel[i].npar; c++) {
            *flagged |= 1u << nv->sel[i].ch[c];
        }
    }
}

void sg_nav_truth_errors(const sg_nav_t *nv, int id, uint32_t mask, const double *truth, double *pe, int *np,
                         double *sh, int *ns)
{
    int i, c;
    for (i = 0; i < nv->nsel; i++) {
        if (nv->sel[i].id != id) {
            continue;
        }
        for (c = 0; c < nv->sel[i].npar; c++) {
            int ch = nv->sel[i].ch[c];
            if (((mask >> ch) & 1u) && truth[ch] != 0.0) {
                pe[(*np)++] = fabs(nv->sel[i].val[c] - truth[ch]) / fabs(truth[ch]);
            }
        }
        sh[(*ns)++] = nv->sel_expl[i];
    }
}

/* First-update innovations of a simulated walk through the default filter. */
static int sim_firsts(const char *script, const fnav_imuerr_config_t *cfg, const fnav_nav_config_t *nc, firsts_t *f,
                      double peak[SG_NCH], char *why, size_t why_size)
{
    hx_log_t L;
    walk_t w;
    navrun_t run;
    char err[HX_ERR_SIZE];
    int c;
    long k;
    if (sgv_simulate(script, cfg, 0, &L, err, sizeof err) != 0) {
        snprintf(why, why_size, "simulating the walk: %s", err);
        return -1;
    }
    w.n = (long)L.n;
    w.t_ns = L.t_ns;
    w.acc = L.acc;
    w.gyr = L.gyr;
    if (peak != NULL) {
        for (c = 0; c < SG_NCH; c++) {
            peak[c] = 0.0;
            for (k = 0; k < w.n; k++) {
                double x = fabs(c < 3 ? w.acc[k][c] : w.gyr[k][c - 3]);
                peak[c] = x > peak[c] ? x : peak[c];
            }
        }
    }
    if (nav_run(&w, nc, &run) != 0) {
        snprintf(why, why_size, "the filter could not run on the simulated walk");
        hx_log_free(&L);
        return -1;
    }
    if (firsts_of(&run, w.t_ns, 0, w.n, f) != 0) {
        snprintf(why, why_size, "out of memory");
        navrun_free(&run);
        hx_log_free(&L);
        return -1;
    }
    navrun_free(&run);
    hx_log_free(&L);
    return 0;
}

int sg_nav_draw_case(const sgv_opts_t *o, int type, uint32_t log_seed, fnav_rng_t *rng, sgv_case_t *cs,
                     fnav_imuerr_config_t *cfg, char *script, size_t script_size, char *why, size_t why_size)
{
    const sgv_effect_t *E;
    int n, c, i;
    fnav_profile_t prof;
    fnav_nav_config_t nc = fnav_nav_config_default;
    hx_motion_config_t mc = hx_motion_config_default();
    firsts_t *f0 = NULL, *f1 = NULL, *f2 = NULL;
    double peak[SG_NCH];
    fnav_imuerr_config_t clean;
    int rc = -1;
    E = sgv_effects(&n);
    cs->log_seed = log_seed;
    /* the filter as in sg_nav_diagnose: bias model off, NavChip noise, no
     * settling state */
    nc.bias_model = FNAV_BIAS_OFF;
    nc.settle = 0;
    snprintf(why, why_size, "unknown reason");
    if (fnav_profile_builtin(&nc.profile, FNAV_PROFILE_NAVCHIP) != FNAV_OK) {
        snprintf(why, why_size, "the built-in NavChip profile is not available");
        return -1;
    }
    cs->profile = (int)((double)fnav_rng_uniform(rng) * 3.0) % 3;
    if (fnav_profile_builtin(&prof, (fnav_profile_id_t)cs->profile) != FNAV_OK) {
        snprintf(why, why_size, "built-in profile %d is not available", cs->profile);
        return -1;
    }
    if (hx_motion_scenario("loop", &mc, o->walk_duration_s, script, script_size) != 0) {
        snprintf(why, why_size, "no loop walk of %g s (--walk-duration)", o->walk_duration_s);
        return -1;
    }
    *cfg = fnav_imuerr_config_default;
    cfg->rate_hz = (fnav_real_t)o->walk_rate_hz;
    (void)fnav_rng_u32(rng); /* was the log's seed: drawn still, so the later draws are as before */
    cfg->seed = log_seed;
    if (fnav_imuerr_config_from_profile(cfg, &prof) != FNAV_OK) {
        snprintf(why, why_size, "profile %d is not valid for the error model at %g Hz", cs->profile, o->walk_rate_hz);
        return -1;
    }
    cs->cls = SGV_MOTION;
    cs->mult = o->mag_lo * pow(o->mag_hi / o->mag_lo, (double)fnav_rng_uniform(rng));
    if (type < 0) {
        return 0;
    }
    clean = *cfg;
    clean.mask[FNAV_EFFECT_WHITE] = 0u;
    clean.mask[FNAV_EFFECT_AR1] = 0u;
    f0 = (firsts_t *)calloc(1, sizeof *f0);
    f1 = (firsts_t *)calloc(1, sizeof *f1);
    f2 = (firsts_t *)calloc(1, sizeof *f2);
    if (f0 == NULL || f1 == NULL || f2 == NULL) {
        snprintf(why, why_size, "out of memory");
        goto done;
    }
    if (sim_firsts(script, &clean, &nc, f0, peak, why, why_size) != 0) {
        goto done;
    }
    if (E[type].id == FNAV_EFFECT_SATURATION) {
        /* a full scale below the walk's peak: the impacts clip */
        double frac = 0.6 + 0.35 * (double)fnav_rng_uniform(rng);
        c = (int)((double)fnav_rng_uniform(rng) * 6.0) % 6;
        cs->mask = 1u << c;
        cs->value[c] = peak[c] * frac;
        cs->mult = 1.0 / frac;
        if (fnav_imuerr_param_set(cfg, FNAV_EFFECT_SATURATION, 0, 1u << c, (fnav_real_t)cs->value[c]) != FNAV_OK ||
            fnav_imuerr_enable(cfg, FNAV_EFFECT_SATURATION, 1u << c) != FNAV_OK) {
            snprintf(why, why_size, "a full scale of %g on channel %d is outside the saturation effect's range",
                     cs->value[c], c);
            goto done;
        }
        rc = 0;
        goto done;
    }
    {
        /* one element of a linear family; its detectable magnitude on this
         * walk: the noncentrality of the first-update innovations,
         * sum (J theta)^T S^-1 (J theta) / dispersion, reaches 25 (5 sigma) */
        int ch, k, m;
        double delta = E[type].id == FNAV_EFFECT_GSENS ? 1e-3 : 1e-2, disp = 0.0, sjj = 0.0, thr, v;
        navcand_t cd;
        fnav_imuerr_config_t pert = clean;
        int nmatch = 0;
        if (E[type].id == FNAV_EFFECT_GSENS) {
            ch = 3 + (int)((double)fnav_rng_uniform(rng) * 3.0) % 3;
            k = (int)((double)fnav_rng_uniform(rng) * 3.0) % 3;
        } else if (E[type].id == FNAV_EFFECT_MISALIGN) {
            ch = (int)((double)fnav_rng_uniform(rng) * 6.0) % 6;
            k = (ch % 3 + 1 + (int)((double)fnav_rng_uniform(rng) * 2.0) % 2) % 3;
        } else {
            ch = (int)((double)fnav_rng_uniform(rng) * 6.0) % 6;
            k = 0;
        }
        memset(&cd, 0, sizeof cd);
        cd.id = E[type].id;
        cd.npar = 1;
        cd.ch[0] = ch;
        cd.k[0] = k;
        cd.val[0] = delta;
        if (apply_cand(&pert, &cd) != 0) {
            snprintf(why, why_size, "the probe magnitude %g is outside the %s effect's range", delta, E[type].name);
            goto done;
        }
        if (sim_firsts(script, &pert, &nc, f2, NULL, why, why_size) != 0 ||
            sim_firsts(script, cfg, &nc, f1, NULL, why, why_size) != 0) {
            goto done;
        }
        for (i = 0; i < f0->n; i++) {
            int j1 = match(f0, i, f1), j2 = match(f0, i, f2), a, b;
            double Si[3][3], J[3], rr[3];
            if (j1 < 0 || j2 < 0 || inv3(f1->S[j1], Si) != 0) {
                continue;
            }
            for (a = 0; a < 3; a++) {
                J[a] = (f2->y[j2][a] - f0->y[i][a]) / delta;
                rr[a] = f1->y[j1][a] - f0->y[i][a];
            }
            for (a = 0; a < 3; a++) {
                for (b = 0; b < 3; b++) {
                    sjj += J[a] * Si[a][b] * J[b];
                    disp += rr[a] * Si[a][b] * rr[b];
                }
            }
            nmatch++;
        }
        if (nmatch < 5 || !(sjj > 0.0)) {
            if (nmatch < 5) {
                snprintf(why, why_size, "%d zero-velocity updates of the simulated walk could be matched, 5 needed to "
                                        "size the effect (a longer or faster walk: --walk-duration, --walk-rate)", nmatch);
            } else {
                snprintf(why, why_size, "the %s effect does not change this walk's innovations", E[type].name);
            }
            goto done;
        }
        disp /= 3.0 * nmatch;
        disp = disp > 1.0 ? disp : 1.0;
        thr = sqrt(25.0 * disp / sjj);
        v = thr * cs->mult * ((double)fnav_rng_uniform(rng) < 0.5 ? -1.0 : 1.0);
        {
            /* at most half the simulator's range on the drawn sign (scale's
             * is -0.9..10: a negative draw was clipped at -5, refused, and
             * the run ended with "cannot draw a walk case"); the multiple is
             * then what was set (it said 1000 x for a clipped 0.5) */
            const fnav_effect_info_t *info = fnav_imuerr_effect_info((fnav_effect_id_t)E[type].id);
            double lim = 0.5 * (v > 0.0 ? (double)info->params[k].hi : -(double)info->params[k].lo);
            if (fabs(v) > lim) {
                v = v > 0.0 ? lim : -lim;
                cs->mult = lim / thr;
            }
        }
        cs->mask = 1u << ch;
        cs->value[ch] = v;
        cd.val[0] = v;
        for (m = 0; m < SG_NCH; m++) {
            if (m != ch) {
                cs->value[m] = 0.0;
            }
        }
        if (apply_cand(cfg, &cd) != 0) {
            snprintf(why, why_size, "the drawn magnitude %g is outside the %s effect's range", v, E[type].name);
            goto done;
        }
        rc = 0;
    }
done:
    if (f0 != NULL) {
        firsts_free(f0);
    }
    if (f1 != NULL) {
        firsts_free(f1);
    }
    if (f2 != NULL) {
        firsts_free(f2);
    }
    free(f0);
    free(f1);
    free(f2);
    return rc;
}
