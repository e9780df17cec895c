/* Sim-to-real gap: channel models, their exact Allan variance, the joint
 * fit of the baseline and candidate effects to a segment's Allan table, and
 * the special estimators of effects whose signature is not (only) in the
 * Allan curve: value lattice, spectral line, bias steps (hx_simgap.h,
 * docs/simgap.md). */
#include "hx_cli.h"
#include "hx_simgap.h"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_fft_real.h>
#include <gsl/gsl_sf_bessel.h>
#include <gsl/gsl_sf_psi.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ------------------------------------------------------------ models */

int sg_model_find(const sg_chmodel_t *m, int id)
{
    int i;
    for (i = 0; i < m->n; i++) {
        if (m->e[i].id == id) {
            return i;
        }
    }
    return -1;
}

int sg_model_set(sg_chmodel_t *m, const sg_effect_t *e)
{
    int i = sg_model_find(m, e->id);
    if (i < 0) {
        if (m->n >= SG_MAX_EFF) {
            return -1;
        }
        i = m->n++;
    }
    m->e[i] = *e;
    return 0;
}

int sg_model_imuerr(const sg_chmodel_t *m, double rate_hz, uint32_t seed, fnav_imuerr_config_t *cfg)
{
    int i, k;
    *cfg = fnav_imuerr_config_default;
    cfg->seed = seed;
    cfg->rate_hz = (fnav_real_t)rate_hz;
    cfg->oversample = 1u;
    for (i = 0; i < m->n; i++) {
        const sg_effect_t *e = &m->e[i];
        const fnav_effect_info_t *info = fnav_imuerr_effect_info((fnav_effect_id_t)e->id);
        if (info == NULL) {
            return -1;
        }
        for (k = 0; k < info->nparams && k < SG_MAX_PAR; k++) {
            if (fnav_imuerr_param_set(cfg, (fnav_effect_id_t)e->id, k, info->allowed, (fnav_real_t)e->p[k]) !=
                FNAV_OK) {
                return -1;
            }
        }
        if (fnav_imuerr_enable(cfg, (fnav_effect_id_t)e->id, info->allowed) != FNAV_OK) {
            return -1;
        }
    }
    return 0;
}

/* ------------------------------------------------------------ exact AVAR */

/* Allan variance of a unit-variance AR(1), a = 1 / (T f_s), over m samples
 * (the same expression as hx_allan_ident.c, docs/allan.md). */
static double ar1_unit(double m, double a)
{
    const double eps = -expm1(-a);
    const double c = 1.0 - eps;
    const double omc = -expm1(-m * a);
    double br;
    if (m * a < 1e-4) {
        return -expm1(-2.0 * a) * (2.0 * m * m + 1.0) / (6.0 * m);
    }
    br = m + (2.0 * c * (m * eps - omc) - c * omc * omc) / (eps * eps);
    return br > 0.0 ? br / (m * m) : 0.0;
}

/* AVAR per B^2 of the simulator's 12-pole flicker over [lo, hi]. */
static double flicker_unit(double m, double fs, double lo, double hi)
{
    const int P = FNAV_IMUERR_FLICKER_POLES;
    double lnr = log(hi / lo) / (double)(P - 1), s = 0.0;
    int i;
    for (i = 0; i < P; i++) {
        double T = lo * exp(lnr * (double)i);
        s += ar1_unit(m, 1.0 / (T * fs));
    }
    return s * lnr / M_PI;
}

/* AVAR per A^2 of the warm-up A (1 - exp(-t/T)) over a segment [a, b]:
 * block-mean differences are A (T/tau)(1 - e^(-tau/T))^2 e^(-t/T). */
static double thermal_unit(double tau, double T, double a, double b)
{
    double c = b - 2.0 * tau, me, x;
    if (!(c > a) || !(T > 0.0)) {
        return 0.0;
    }
    me = T / (2.0 * (c - a)) * (exp(-2.0 * a / T) - exp(-2.0 * c / T));
    x = -expm1(-tau / T);
    return 0.5 * (T / tau) * (T / tau) * x * x * x * x * me;
}

static double vib_unit(double m, double w)
{
    double s1 = sin(0.5 * w * m), s2 = sin(0.5 * w);
    if (fabs(s2) < 1e-15) {
        return 0.0;
    }
    return s1 * s1 * s1 * s1 / (m * m * s2 * s2);
}

/* Unit basis of an effect's AVAR (coefficient = the square of its magnitude
 * parameter); the other parameters are taken from e. */
double sg_effect_avar_unit(const sg_effect_t *e, double fs, double m, double t0, double t1)
{
    const double tau = m / fs;
    switch (e->id) {
    case FNAV_EFFECT_WHITE: return fs / m;
    case FNAV_EFFECT_AR1: return ar1_unit(m, 1.0 / (e->p[0] * fs));
    case FNAV_EFFECT_QUANT: return e->p[1] != 0.0 ? 1.0 / (4.0 * m * m) : 1.0 / (12.0 * m);
    case FNAV_EFFECT_FLICKER: return flicker_unit(m, fs, e->p[1], e->p[2]);
    case FNAV_EFFECT_RRW: return (2.0 * m * m + 1.0) / (6.0 * m * fs);
    case FNAV_EFFECT_RAMP: return 0.5 * tau * tau;
    case FNAV_EFFECT_THERMAL: return e->p[1] * e->p[1] * thermal_unit(tau, e->p[2], t0, t1);
    case FNAV_EFFECT_VIBRATION: return vib_unit(m, 2.0 * M_PI * e->p[1] / fs);
    case FNAV_EFFECT_JUMPS: return -expm1(-e->p[0] / fs) * (2.0 * m * m + 1.0) / (6.0 * m);
    default: return 0.0;
    }
}

/* Index of the magnitude parameter of an effect (its coefficient is its
 * square), -1 for effects without a static Allan signature. */
static int mag_param(int id)
{
    switch (id) {
    case FNAV_EFFECT_WHITE: return 0;
    case FNAV_EFFECT_AR1: return 1;
    case FNAV_EFFECT_QUANT: return 0;
    case FNAV_EFFECT_FLICKER: return 0;
    case FNAV_EFFECT_RRW: return 0;
    case FNAV_EFFECT_RAMP: return 0;
    case FNAV_EFFECT_THERMAL: return 0;
    case FNAV_EFFECT_VIBRATION: return 0;
    case FNAV_EFFECT_JUMPS: return 1;
    default: return -1;
    }
}

double sg_model_avar(const sg_chmodel_t *mdl, double rate_hz, double m, double t0_s, double t1_s)
{
    double v = 0.0;
    int i;
    for (i = 0; i < mdl->n; i++) {
        const sg_effect_t *e = &mdl->e[i];
        int k = mag_param(e->id);
        if (k < 0) {
            continue;
        }
        v += e->p[k] * e->p[k] * sg_effect_avar_unit(e, rate_hz, m, t0_s, t1_s);
    }
    return v;
}

double sg_model_avar_blocks(const sg_chmodel_t *mdl, double rate_hz, double m, int nb, const double *t0_s,
                            const double *t1_s)
{
    double v = 0.0, w = 0.0;
    int b;
    for (b = 0; b < nb; b++) {
        /* weight: the overlapping terms of the block */
        double wb = (t1_s[b] - t0_s[b]) * rate_hz - 2.0 * m + 1.0;
        if (wb <= 0.0) {
            continue;
        }
        v += wb * sg_model_avar(mdl, rate_hz, m, t0_s[b], t1_s[b]);
        w += wb;
    }
    return w > 0.0 ? v / w : sg_model_avar(mdl, rate_hz, m, t0_s[0], t1_s[0]);
}

/* One-sided PSD of a model at f (continuous-time shapes, u^2/Hz). */
static double model_psd(const sg_chmodel_t *mdl, double f, double fs)
{
    double S = 0.0;
    int i;
    for (i = 0; i < mdl->n; i++) {
        const sg_effect_t *e = &mdl->e[i];
        double w = 2.0 * M_PI * f;
        switch (e->id) {
        case FNAV_EFFECT_WHITE: S += 2.0 * e->p[0] * e->p[0]; break;
        case FNAV_EFFECT_AR1: S += 4.0 * e->p[1] * e->p[1] * e->p[0] / (1.0 + w * w * e->p[0] * e->p[0]); break;
        case FNAV_EFFECT_FLICKER: S += e->p[0] * e->p[0] / (M_PI * f); break;
        case FNAV_EFFECT_RRW: S += e->p[0] * e->p[0] / (2.0 * M_PI * M_PI * f * f); break;
        case FNAV_EFFECT_JUMPS: S += e->p[0] * e->p[1] * e->p[1] / (2.0 * M_PI * M_PI * f * f); break;
        case FNAV_EFFECT_QUANT: {
            double q2 = e->p[0] * e->p[0] / 12.0, sh = 2.0 * sin(M_PI * f / fs);
            S += (e->p[1] != 0.0 ? sh * sh : 1.0) * 2.0 * q2 / fs;
            break;
        }
        default: break;
        }
    }
    return S;
}

/* Deterministic part of a channel model at time t (ramp and thermal drift). */
static double model_drift(const sg_chmodel_t *mdl, double t)
{
    double b = 0.0;
    int i;
    for (i = 0; i < mdl->n; i++) {
        const sg_effect_t *e = &mdl->e[i];
        if (e->id == FNAV_EFFECT_RAMP) {
            b += e->p[0] * t;
        } else if (e->id == FNAV_EFFECT_THERMAL && e->p[2] > 0.0) {
            /* coef (temp - t0), temp = t0 + rise (1 - exp(-t / tau)) */
            b += e->p[0] * e->p[1] * -expm1(-t / e->p[2]);
        }
    }
    return b;
}

/* Expected trend (u/s) or curvature (u) of a block [t0, t1] under a model:
 * the Legendre projections of its deterministic drift (midpoint rule;
 * the random parts have expectation zero); or the level (u) of a two-block
 * segment spanning [t0, t1] with blocks of blk s: the drift's mean over the
 * second block minus its mean over the first. */
static double model_time_stat(const sg_chmodel_t *mdl, int kind, double t0, double t1, double blk)
{
    enum { NQ = 256 };
    double s = 0.0, q = 0.0, pm = 0.0;
    int i;
    if (kind == SG_TIME_LEVEL) {
        /* mean over the second block minus mean over the first */
        if (!(blk > 0.0) || !(t1 - t0 >= blk)) {
            return (double)NAN;
        }
        for (i = 0; i < NQ; i++) {
            double f = ((double)i + 0.5) / (double)NQ * blk;
            s += model_drift(mdl, t1 - blk + f) - model_drift(mdl, t0 + f);
        }
        return s / (double)NQ;
    }
    if (kind == SG_TIME_CURV) {
        for (i = 0; i < NQ; i++) {
            double u = -1.0 + 2.0 * ((double)i + 0.5) / (double)NQ;
            pm += 0.5 * (3.0 * u * u - 1.0);
        }
        pm /= (double)NQ;
    }
    for (i = 0; i < NQ; i++) {
        double u = -1.0 + 2.0 * ((double)i + 0.5) / (double)NQ;
        double f = model_drift(mdl, t0 + 0.5 * (u + 1.0) * (t1 - t0));
        double b = kind == SG_TIME_TREND ? u : 0.5 * (3.0 * u * u - 1.0) - pm;
        s += f * b;
        q += b * b;
    }
    if (!(q > 0.0) || !(t1 > t0)) {
        return (double)NAN;
    }
    return kind == SG_TIME_TREND ? (s / q) * 2.0 / (t1 - t0) : s / q;
}

double sg_model_lnstat(const sg_chmodel_t *mdl, const sg_point_t *p, double rate_hz, int nb, const double *t0_s,
                       const double *t1_s)
{
    if (p->dom == SG_TIME && (p->kind == SG_TIME_TREND || p->kind == SG_TIME_CURV || p->kind == SG_TIME_LEVEL)) {
        return model_time_stat(mdl, p->kind, p->x_lo, p->x_hi, p->x_blk);
    }
    if (p->dom == SG_ALLAN) {
        double v = sg_model_avar_blocks(mdl, rate_hz, (double)p->m, nb, t0_s, t1_s);
        return v > 0.0 ? log(v) : (double)NAN;
    }
    if (p->dom == SG_PSD && p->n_phase > 0u && p->lag > 0u) {
        double df = rate_hz / (double)p->n_phase, s = 0.0;
        uint32_t k;
        for (k = p->m; k < p->m + p->lag; k++) {
            s += model_psd(mdl, (double)k * df, rate_hz);
        }
        s /= (double)p->lag;
        return s > 0.0 ? log(s) : (double)NAN;
    }
    return (double)NAN;
}

/* ------------------------------------------------------------ table */

void sg_table_from(const sg_plist_t *pl, const double *vals, int ch, double rate_hz, const sg_segs_t *segs, int g,
                   sg_table_t *t)
{
    size_t j, k = 0;
    size_t idx[FNAV_ALLAN_MAX_POINTS];
    int b;
    const double lim = SG_TEST_FRAC * (double)sg_segs_minblock(segs, g) / rate_hz * (1.0 + 1e-9);
    memset(t, 0, sizeof *t);
    t->rate_hz = rate_hz;
    t->nb = segs->nb[g];
    for (b = 0; b < t->nb; b++) {
        t->t0_s[b] = (double)segs->start[g][b] / rate_hz;
        t->t1_s[b] = (double)(segs->start[g][b] + segs->n[g][b]) / rate_hz;
    }
    for (j = 0; j < pl->n && k < FNAV_ALLAN_MAX_POINTS; j++) {
        if (pl->p[j].dom == SG_ALLAN && pl->p[j].ch == ch && vals[j] > -600.0 && pl->p[j].x <= lim) {
            idx[k] = j;
            t->lnav[k] = vals[j];
            t->m[k] = (double)pl->p[j].m;
            k++;
        }
    }
    t->n = k;
    for (j = 0; j < pl->n; j++) {
        const sg_point_t *q = &pl->p[j];
        double L = q->x_hi - q->x_lo;
        if (q->dom != SG_TIME || q->ch != ch ||
            (q->kind != SG_TIME_TREND && q->kind != SG_TIME_CURV && q->kind != SG_TIME_LEVEL) ||
            t->nt >= SG_TAB_NT || !(L > 0.0) || vals[j] != vals[j]) {
            continue;
        }
        t->tkind[t->nt] = q->kind;
        t->tidx[t->nt] = j;
        t->ty[t->nt] = vals[j];
        t->tlo[t->nt] = q->x_lo;
        t->thi[t->nt] = q->x_hi;
        t->tblk[t->nt] = q->x_blk;
        /* white noise sigma^2 per sample: the Legendre coefficient l has
         * variance (2l + 1) sigma^2 / N, so the slope 12 sigma^2 / (N L^2),
         * the curvature 5 sigma^2 / N and a difference of two block means
         * 2 sigma^2 / N (common factor sigma^2 / f_s dropped) */
        if (q->kind == SG_TIME_LEVEL) {
            t->tw[t->nt] = q->x_blk / 2.0;
        } else {
            t->tw[t->nt] = q->kind == SG_TIME_TREND ? L * L * L / 12.0 : L / 5.0;
        }
        t->nt++;
    }
    for (j = 0; j < k; j++) {
        size_t a = j > 0 ? j - 1 : j, bb = j + 1 < k ? j + 1 : j;
        double sl = 0.0, nu, var;
        fnav_allan_noise_t type;
        if (a != bb) {
            sl = 0.5 * (t->lnav[bb] - t->lnav[a]) / log(t->m[bb] / t->m[a]);
        }
        type = fnav_allan_noise_from_slope((fnav_real_t)sl);
        if (type == FNAV_ALLAN_NOISE_RAMP || type == FNAV_ALLAN_NOISE_UNKNOWN) {
            type = type == FNAV_ALLAN_NOISE_RAMP ? FNAV_ALLAN_NOISE_RRW : FNAV_ALLAN_NOISE_WHITE;
        }
        nu = fnav_allan_edf(fnav_allan_noise_alpha(type), pl->p[idx[j]].lag, pl->p[idx[j]].n_phase, 1) *
             (double)(pl->p[idx[j]].nblk > 1 ? pl->p[idx[j]].nblk : 1);
        var = nu > 0.0 ? (nu > 1e6 ? 2.0 / nu : gsl_sf_psi_1(0.5 * nu)) : 1.0;
        /* model floor (SG_FIT_FLOOR): the short-tau points' EDF reach 10^6 */
        t->w[j] = 1.0 / (var + SG_FIT_FLOOR * SG_FIT_FLOOR);
    }
}

void sg_table_time_weights(sg_table_t *t, const double *sd)
{
    double w[SG_TAB_NT];
    int k;
    for (k = 0; k < t->nt; k++) {
        const double v = sd[t->tidx[k]] * sd[t->tidx[k]];
        if (!(v > 0.0) || !isfinite(v)) {
            return; /* keep the white-noise shape */
        }
        w[k] = 1.0 / v;
    }
    if (t->nt > 0) {
        memcpy(t->tw, w, (size_t)t->nt * sizeof *w);
        t->tw_twins = 1;
    }
}

/* The slow random parts of a model (AR(1), flicker, rrw, jumps): what
 * spreads the time points beyond the white noise the twins carry. */
static void slow_parts(const sg_chmodel_t *mdl, sg_chmodel_t *slow)
{
    int i;
    memset(slow, 0, sizeof *slow);
    for (i = 0; i < mdl->n; i++) {
        const int id = mdl->e[i].id;
        if (id == FNAV_EFFECT_AR1 || id == FNAV_EFFECT_FLICKER || id == FNAV_EFFECT_RRW || id == FNAV_EFFECT_JUMPS) {
            slow->e[slow->n++] = mdl->e[i];
        }
    }
}

/* j_l(a)^2, the spherical Bessel function (GSL), replaced far out by the
 * mean of its oscillation, 1 / (2 a^2), which a log grid cannot follow
 * (the weight there is small for the slow parts). */
static double sbessel2(int l, double a)
{
    double j;
    if (a > 40.0) {
        return 0.5 / (a * a);
    }
    j = l == 1 ? gsl_sf_bessel_j1(a) : gsl_sf_bessel_j2(a);
    return j * j;
}

/* Variance of a time point (trend, curvature or level; span [t0, t1],
 * level blocks blk) under a model's slow random parts: the integral of the
 * one-sided PSD S(f) against the statistic's squared transfer function.
 * The Legendre coefficient c_l = (2l + 1)/2 int P_l(u) x du over a block of
 * length L has |W|^2 = (2l + 1)^2 j_l(pi f L)^2 (since int P_l(u)
 * e^(-iau) du = 2 (-i)^l j_l(a)), so var c_l = (2l + 1)^2 int S j_l^2 df
 * (white noise: (2l + 1) sigma^2 / N); the trend is c_1 2 / L. A difference
 * of two block means at centre distance D has |W|^2 = 4 sin^2(pi f D)
 * sinc^2(pi f blk). Trapezoid in ln f over 10^-4 / L .. 10^4 / L. */
static double model_time_var(const sg_chmodel_t *mdl, int kind, double t0, double t1, double blk)
{
    enum { NF = 1200 };
    const double L = t1 - t0;
    double lo, hi, h, s = 0.0;
    sg_chmodel_t slow;
    int i;
    if (!(L > 0.0) || (kind == SG_TIME_LEVEL && !(blk > 0.0 && L > blk))) {
        return 0.0;
    }
    slow_parts(mdl, &slow);
    if (slow.n == 0) {
        return 0.0;
    }
    lo = log(1e-4 / L);
    hi = log(1e4 / L);
    h = (hi - lo) / (double)(NF - 1);
    for (i = 0; i < NF; i++) {
        double f = exp(lo + h * (double)i), W2, a = M_PI * f * L, v;
        if (kind == SG_TIME_LEVEL) {
            double D = L - blk, x = M_PI * f * blk, sc = x < 1e-6 ? 1.0 : sin(x) / x, sn = sin(M_PI * f * D);
            W2 = 4.0 * sn * sn * sc * sc;
        } else if (kind == SG_TIME_TREND) {
            W2 = 9.0 * sbessel2(1, a) * 4.0 / (L * L);
        } else {
            W2 = 25.0 * sbessel2(2, a);
        }
        v = model_psd(&slow, f, 1.0) * W2 * f; /* d f = f d ln f (no quantiser: fs unused) */
        s += (i == 0 || i == NF - 1 ? 0.5 : 1.0) * v;
    }
    return s * h;
}

void sg_table_time_base(sg_table_t *t, const sg_chmodel_t *base)
{
    int k;
    for (k = 0; k < t->nt; k++) {
        t->tvb[k] = model_time_var(base, t->tkind[k], t->tlo[k], t->thi[k], t->tblk[k]);
    }
    t->tvb_set = 1;
}

/* Unit Allan variance of an effect at point m of a table, pooled over its
 * blocks as the estimator pools them. */
static double table_unit(const sg_effect_t *e, const sg_table_t *t, double m)
{
    double v = 0.0, w = 0.0;
    int b;
    if (e->id != FNAV_EFFECT_THERMAL || t->nb <= 1) {
        return sg_effect_avar_unit(e, t->rate_hz, m, t->t0_s[0], t->t1_s[0]);
    }
    for (b = 0; b < t->nb; b++) {
        double wb = (t->t1_s[b] - t->t0_s[b]) * t->rate_hz - 2.0 * m + 1.0;
        if (wb > 0.0) {
            v += wb * sg_effect_avar_unit(e, t->rate_hz, m, t->t0_s[b], t->t1_s[b]);
            w += wb;
        }
    }
    return w > 0.0 ? v / w : 0.0;
}

/* ------------------------------------------------------------ NNLS */

#define NCOL 8

/* Solve the k x k system M c = v (Gauss with partial pivoting); -1 if singular. */
static int solve(int k, double M[NCOL][NCOL], double *v, double *c)
{
    double A[NCOL][NCOL + 1];
    int i, j, r;
    for (i = 0; i < k; i++) {
        for (j = 0; j < k; j++) {
            A[i][j] = M[i][j];
        }
        A[i][k] = v[i];
    }
    for (i = 0; i < k; i++) {
        int p = i;
        for (r = i + 1; r < k; r++) {
            if (fabs(A[r][i]) > fabs(A[p][i])) {
                p = r;
            }
        }
        if (!(fabs(A[p][i]) > 1e-300)) {
            return -1;
        }
        if (p != i) {
            for (j = 0; j <= k; j++) {
                double t = A[i][j];
                A[i][j] = A[p][j];
                A[p][j] = t;
            }
        }
        for (r = i + 1; r < k; r++) {
            double f = A[r][i] / A[i][i];
            for (j = i; j <= k; j++) {
                A[r][j] -= f * A[i][j];
            }
        }
    }
    for (i = k - 1; i >= 0; i--) {
        double s = A[i][k];
        for (j = i + 1; j < k; j++) {
            s -= A[i][j] * c[j];
        }
        c[i] = s / A[i][i];
    }
    return 0;
}

/* Non-negative least squares min |A c - y|^2, c >= 0, by enumerating the
 * active sets (at most NCOL = 8 columns, 256 sets). Columns are scaled to
 * unit norm first. Returns the residual. */
static double nnls(size_t n, int k, double A[][NCOL], const double *y, double *c)
{
    double scale[NCOL], best = INFINITY, cbest[NCOL];
    unsigned set, nsets = 1u << k;
    int i, j;
    size_t r;
    for (j = 0; j < k; j++) {
        double s = 0.0;
        for (r = 0; r < n; r++) {
            s += A[r][j] * A[r][j];
        }
        scale[j] = s > 0.0 ? 1.0 / sqrt(s) : 0.0;
        cbest[j] = 0.0;
    }
    for (set = 0; set < nsets; set++) {
        int idx[NCOL], na = 0, ok = 1;
        double M[NCOL][NCOL], v[NCOL], cc[NCOL], res = 0.0;
        for (j = 0; j < k; j++) {
            if ((set >> j) & 1u) {
                if (scale[j] == 0.0) {
                    ok = 0;
                }
                idx[na++] = j;
            }
        }
        if (!ok) {
            continue;
        }
        for (i = 0; i < na; i++) {
            v[i] = 0.0;
            for (j = 0; j < na; j++) {
                double s = 0.0;
                for (r = 0; r < n; r++) {
                    s += A[r][idx[i]] * A[r][idx[j]];
                }
                M[i][j] = s * scale[idx[i]] * scale[idx[j]];
            }
            for (r = 0; r < n; r++) {
                v[i] += A[r][idx[i]] * y[r];
            }
            v[i] *= scale[idx[i]];
        }
        if (na > 0 && solve(na, M, v, cc) != 0) {
            continue;
        }
        for (i = 0; i < na; i++) {
            if (!(cc[i] >= 0.0)) {
                ok = 0;
            }
        }
        if (!ok) {
            continue;
        }
        for (r = 0; r < n; r++) {
            double f = 0.0;
            for (i = 0; i < na; i++) {
                f += A[r][idx[i]] * cc[i] * scale[idx[i]];
            }
            res += (f - y[r]) * (f - y[r]);
        }
        if (res < best) {
            best = res;
            for (j = 0; j < k; j++) {
                cbest[j] = 0.0;
            }
            for (i = 0; i < na; i++) {
                cbest[idx[i]] = cc[i] * scale[idx[i]];
            }
        }
    }
    for (j = 0; j < k; j++) {
        c[j] = cbest[j];
    }
    return best;
}

/* ------------------------------------------------------------ fit */

/* Least improvement of the Allan objective that keeps an AR(1) term. */
#define SG_AR1_DQ 10.0

/* Q = sum w (ln a - ln model)^2 of a complete model. */
static double objective(const sg_table_t *t, const sg_chmodel_t *m)
{
    double Q = 0.0;
    size_t j;
    for (j = 0; j < t->n; j++) {
        double mv = sg_model_avar_blocks(m, t->rate_hz, t->m[j], t->nb, t->t0_s, t->t1_s), r;
        if (!(mv > 0.0)) {
            mv = 1e-300;
        }
        r = t->lnav[j] - log(mv);
        Q += t->w[j] * r * r;
    }
    return Q;
}

/* Everything about one fit configuration: the model skeleton (effects with
 * their fixed parameters), which have a free coefficient (the square of the
 * magnitude), and the fixed ones. */
typedef struct {
    sg_chmodel_t m;
    int free_[SG_MAX_EFF];
} skel_t;

/* Solve the linear coefficients of a skeleton for fixed nonlinear params;
 * writes the magnitudes into s->m and returns the log objective. */
static double solve_skel(const sg_table_t *t, skel_t *s)
{
    double A[FNAV_ALLAN_MAX_POINTS][NCOL], y[FNAV_ALLAN_MAX_POINTS], c[NCOL];
    int col[SG_MAX_EFF], k = 0, i;
    size_t j;
    for (i = 0; i < s->m.n; i++) {
        col[i] = s->free_[i] ? k++ : -1;
    }
    for (j = 0; j < t->n; j++) {
        double a = exp(t->lnav[j]), sw = sqrt(t->w[j]), fixed = 0.0;
        for (i = 0; i < s->m.n; i++) {
            const sg_effect_t *e = &s->m.e[i];
            double u = table_unit(e, t, t->m[j]);
            if (col[i] >= 0) {
                A[j][col[i]] = sw * u / a;
            } else if (mag_param(e->id) >= 0) {
                double mg = e->p[mag_param(e->id)];
                fixed += mg * mg * u;
            }
        }
        y[j] = sw * (a - fixed) / a;
    }
    (void)nnls(t->n, k, A, y, c);
    for (i = 0; i < s->m.n; i++) {
        if (col[i] >= 0) {
            s->m.e[i].p[mag_param(s->m.e[i].id)] = sqrt(c[col[i]] > 0.0 ? c[col[i]] : 0.0);
        }
    }
    return objective(t, &s->m);
}

static void set_effect(sg_effect_t *e, int id)
{
    const fnav_effect_info_t *info = fnav_imuerr_effect_info((fnav_effect_id_t)id);
    fnav_imuerr_config_t d = fnav_imuerr_config_default;
    int k;
    memset(e, 0, sizeof *e);
    e->id = id;
    for (k = 0; k < SG_MAX_PAR; k++) {
        e->se[k] = e->ci_lo[k] = e->ci_hi[k] = (double)NAN;
        if (info != NULL && k < info->nparams) {
            e->p[k] = (double)fnav_imuerr_param_get(&d, (fnav_effect_id_t)id, k, 0);
        }
    }
}

/* Standard errors of the magnitudes (and of the AR(1) time) from the
 * Gauss-Newton covariance of the log parameters. It treats the Allan
 * points as independent, while the overlapping estimates at neighbouring
 * tau share most of their data, and comes out too small (0.6 times the
 * spread of the white density on white noise): the diagnosis replaces it
 * by the spread of the twins' refits (se_allan, sg_se_from_refits). */
static void fit_errors(const sg_table_t *t, skel_t *s)
{
    enum { NP = 10 };
    double J[FNAV_ALLAN_MAX_POINTS][NP], M[NCOL][NCOL], cov[NP][NP];
    int pe[NP], pk[NP], np = 0, i, a, b;
    size_t j;
    for (i = 0; i < s->m.n && np < NP - 1; i++) {
        int k = mag_param(s->m.e[i].id);
        if (s->free_[i] && k >= 0 && s->m.e[i].p[k] > 0.0) {
            pe[np] = i;
            pk[np] = k;
            np++;
        }
        if (s->m.e[i].id == FNAV_EFFECT_AR1 && s->m.e[i].p[1] > 0.0 && np < NP) {
            pe[np] = i;
            pk[np] = 0;
            np++;
        }
    }
    if (np == 0 || np > NCOL || (size_t)np >= t->n) {
        return;
    }
    for (a = 0; a < np; a++) {
        double h = 1e-4;
        sg_chmodel_t mp = s->m, mm = s->m;
        mp.e[pe[a]].p[pk[a]] *= exp(h);
        mm.e[pe[a]].p[pk[a]] *= exp(-h);
        for (j = 0; j < t->n; j++) {
            double vp = sg_model_avar_blocks(&mp, t->rate_hz, t->m[j], t->nb, t->t0_s, t->t1_s);
            double vm = sg_model_avar_blocks(&mm, t->rate_hz, t->m[j], t->nb, t->t0_s, t->t1_s);
            J[j][a] = sqrt(t->w[j]) * (log(vp > 0.0 ? vp : 1e-300) - log(vm > 0.0 ? vm : 1e-300)) / (2.0 * h);
        }
    }
    for (a = 0; a < np; a++) {
        for (b = 0; b < np; b++) {
            double sum = 0.0;
            for (j = 0; j < t->n; j++) {
                sum += J[j][a] * J[j][b];
            }
            M[a][b] = sum;
        }
    }
    for (a = 0; a < np; a++) {
        double e[NCOL], col[NCOL];
        for (b = 0; b < np; b++) {
            e[b] = (a == b) ? 1.0 : 0.0;
        }
        if (solve(np, M, e, col) != 0) {
            return;
        }
        for (b = 0; b < np; b++) {
            cov[b][a] = col[b];
        }
    }
    for (a = 0; a < np; a++) {
        double v = cov[a][a];
        sg_effect_t *e = &s->m.e[pe[a]];
        e->se[pk[a]] = v > 0.0 ? e->p[pk[a]] * sqrt(v) : (double)NAN;
        e->se_allan[pk[a]] = v > 0.0;
    }
}

/* Refit s's value of parameter k of effect id (mp: the effect's magnitude
 * parameter) in *v: 0 when there is none to count (no refit, a value not
 * finite, or the effect's magnitude is zero there and its other parameters
 * are placeholders: an AR(1) of sigma 0 has no time). */
static int refit_value(const sg_chmodel_t *fits, const int *ok, int s, int id, int k, int mp, double *v)
{
    const int j = ok[s] ? sg_model_find(&fits[s], id) : -1;
    if (j < 0 || (k != mp && mp >= 0 && !(fits[s].e[j].p[mp] > 0.0))) {
        return 0;
    }
    *v = fits[s].e[j].p[k];
    return isfinite(*v);
}

int sg_has_ci(const sg_effect_t *e, int k)
{
    return isfinite(e->se[k]) && e->nrefit[k] >= SG_CI_MIN_REFITS && isfinite(e->ci_lo[k]) && isfinite(e->ci_hi[k]);
}

void sg_se_from_refits(sg_chmodel_t *m, const sg_chmodel_t *fits, const int *ok, int S)
{
    double x[SG_MAX_TWINS]; /* one parameter's refit values, in refit order */
    int i, k, s;
    for (i = 0; i < m->n; i++) {
        sg_effect_t *e = &m->e[i];
        const int mp = mag_param(e->id);
        for (k = 0; k < SG_MAX_PAR; k++) {
            double sum = 0.0, sum2 = 0.0, mean;
            int c = 0, j;
            if (!e->se_allan[k]) {
                continue;
            }
            e->se_allan[k] = 0;
            e->nrefit[k] = 0;
            e->ci_lo[k] = e->ci_hi[k] = (double)NAN;
            if (!isfinite(e->se[k])) {
                continue; /* null stays null */
            }
            for (s = 0; s < S && c < SG_MAX_TWINS; s++) {
                if (refit_value(fits, ok, s, e->id, k, mp, &x[c])) {
                    sum += x[c++];
                }
            }
            if (c < 3) {
                e->se[k] = (double)NAN;
                continue;
            }
            mean = sum / (double)c; /* two passes: the sample sd */
            for (j = 0; j < c; j++) {
                sum2 += (x[j] - mean) * (x[j] - mean);
            }
            e->se[k] = sqrt(sum2 / (double)(c - 1));
            e->nrefit[k] = c;
            if (c >= SG_CI_MIN_REFITS) {
                qsort(x, (size_t)c, sizeof x[0], hx_cmp_double);
                e->ci_lo[k] = hx_quantile_sorted(x, c, 0.16);
                e->ci_hi[k] = hx_quantile_sorted(x, c, 0.84);
            }
        }
    }
}

/* Weighted least squares of the time points on nc <= 2 columns X; the
 * coefficients c, their covariance (XᵀWX)⁻¹ in cov; returns the weighted
 * residual sum, INFINITY when singular. */
static double time_ls(const sg_table_t *t, int nc, double X[][2], double *c, double cov[2][2])
{
    double a = 0.0, b = 0.0, d = 0.0, u = 0.0, v = 0.0, det, q = 0.0;
    int k;
    for (k = 0; k < t->nt; k++) {
        a += t->tw[k] * X[k][0] * X[k][0];
        u += t->tw[k] * X[k][0] * t->ty[k];
        if (nc > 1) {
            b += t->tw[k] * X[k][0] * X[k][1];
            d += t->tw[k] * X[k][1] * X[k][1];
            v += t->tw[k] * X[k][1] * t->ty[k];
        }
    }
    if (nc == 1) {
        if (!(a > 0.0)) {
            return INFINITY;
        }
        c[0] = u / a;
        cov[0][0] = 1.0 / a;
    } else {
        det = a * d - b * b;
        if (!(det > 1e-12 * a * d)) {
            return INFINITY;
        }
        c[0] = (d * u - b * v) / det;
        c[1] = (a * v - b * u) / det;
        cov[0][0] = d / det;
        cov[1][1] = a / det;
        cov[0][1] = cov[1][0] = -b / det;
    }
    for (k = 0; k < t->nt; k++) {
        double r = t->ty[k] - c[0] * X[k][0] - (nc > 1 ? c[1] * X[k][1] : 0.0);
        q += t->tw[k] * r * r;
    }
    return q;
}

/* Columns of the time fit at warm-up time constant T: the expected time
 * points of a unit warm-up (1 - exp(-t/T)) and of a unit ramp t. */
static int time_cols(const sg_table_t *t, int th, int rp, double T, double X[][2])
{
    sg_chmodel_t u;
    int k, nc = 0;
    memset(&u, 0, sizeof u);
    u.n = 1;
    for (k = 0; k < t->nt; k++) {
        nc = 0;
        if (th) {
            u.e[0].id = FNAV_EFFECT_THERMAL;
            u.e[0].p[0] = u.e[0].p[1] = 1.0;
            u.e[0].p[2] = T;
            X[k][nc++] = model_time_stat(&u, t->tkind[k], t->tlo[k], t->thi[k], t->tblk[k]);
        }
        if (rp) {
            memset(&u.e[0], 0, sizeof u.e[0]);
            u.e[0].id = FNAV_EFFECT_RAMP;
            u.e[0].p[0] = 1.0;
            X[k][nc++] = model_time_stat(&u, t->tkind[k], t->tlo[k], t->thi[k], t->tblk[k]);
        }
    }
    return nc;
}

/* Time-domain fit of the deterministic drifts of a model (thermal at index
 * it, ramp at ir; -1 when absent) on the blocks' trends and curvatures and
 * the ends' level: the
 * drift A (1 - exp(-t/T)) + R t is linear in A and R for a fixed T (a grid
 * in ln T from 10 s to twice the segment's end, refined by golden section).
 * The signed amplitudes go into the model (thermal: coef = A / rise, rise
 * keeping its value) with standard errors: from the twins' variances when
 * the weights are theirs (conditional on T), else scaled by the residual.
 * Returns 0, -1 when the table has no time points or the fit is singular. */
static int time_fit(const sg_table_t *t, sg_chmodel_t *m, int it, int ir)
{
    enum { NG = 48 };
    double X[SG_TAB_NT][2], c[2] = { 0.0, 0.0 }, cov[2][2], best = INFINITY, bT = 0.0, disp = 1.0, tlo = 0.0,
           thi = 0.0;
    const int th = it >= 0, rp = ir >= 0, np = th + rp;
    int nc, g;
    if (t->nt == 0 || np == 0) {
        return -1;
    }
    if (th) {
        double te = t->t1_s[t->nb - 1], ts = t->t0_s[0], lo = log(10.0), hi, step, a, b;
        const double gr = 0.6180339887498949;
        for (g = 0; g < t->nt; g++) {
            te = t->thi[g] > te ? t->thi[g] : te;
            ts = t->tlo[g] < ts ? t->tlo[g] : ts;
        }
        /* a warm-up that has decayed by 10^6 before the segment begins is
         * not identifiable from it (fitted to a tail, its amplitude would be
         * the tail's times up to e^(t0/T)): T >= t0 / ln(10^6) */
        if (ts / log(1e6) > 10.0) {
            lo = log(ts / log(1e6));
        }
        hi = log(2.0 * (te > 20.0 ? te : 20.0));
        step = (hi - lo) / (double)(NG - 1);
        for (g = 0; g < NG; g++) {
            double T = exp(lo + step * (double)g), q;
            nc = time_cols(t, th, rp, T, X);
            q = time_ls(t, nc, X, c, cov);
            if (q < best) {
                best = q;
                bT = T;
            }
        }
        if (!isfinite(best)) {
            return -1;
        }
        a = log(bT) - step > lo ? log(bT) - step : lo;
        b = log(bT) + step < hi ? log(bT) + step : hi;
        for (g = 0; g < 40 && b - a > 1e-6; g++) {
            double x1 = b - gr * (b - a), x2 = a + gr * (b - a), q1, q2;
            q1 = time_ls(t, time_cols(t, th, rp, exp(x1), X), X, c, cov);
            q2 = time_ls(t, time_cols(t, th, rp, exp(x2), X), X, c, cov);
            if (q1 < q2) {
                b = x2;
            } else {
                a = x1;
            }
        }
        if (time_ls(t, time_cols(t, th, rp, exp(0.5 * (a + b)), X), X, c, cov) <= best) {
            bT = exp(0.5 * (a + b));
        }
        tlo = lo;
        thi = hi;
    }
    nc = time_cols(t, th, rp, bT, X);
    best = time_ls(t, nc, X, c, cov);
    if (!isfinite(best)) {
        return -1;
    }
    if (!t->tw_twins) {
        disp = t->nt > np + (th ? 1 : 0) ? best / (double)(t->nt - np - (th ? 1 : 0)) : (double)NAN;
    }
    if (th) {
        sg_effect_t *e = &m->e[it];
        double rise = e->p[1] != 0.0 ? e->p[1] : 1.0;
        e->p[0] = c[0] / rise;
        e->p[2] = bT;
        e->se[0] = sqrt(cov[0][0] * disp) / fabs(rise);
        e->se_allan[0] = 0;
        e->nrefit[0] = 0; /* its own se: no refits' interval */
        /* the time constant's search interval and whether the fit left it
         * on a bound: a drift still rising as a ramp at the segment's end
         * puts it at the longest (only a lower limit), a step at the start
         * at the shortest (only an upper limit); reported as such, the
         * fit itself unchanged */
        e->lo[2] = exp(tlo);
        e->hi[2] = exp(thi);
        e->at_bound[2] = sg_param_at_bound(bT, e->lo[2], e->hi[2]);
    }
    if (rp) {
        sg_effect_t *e = &m->e[ir];
        e->p[0] = c[th ? 1 : 0];
        e->se[0] = sqrt(cov[th ? 1 : 0][th ? 1 : 0] * disp);
        e->se_allan[0] = 0;
        e->nrefit[0] = 0;
    }
    return 0;
}

/* The steps the detector misses. It finds a step when its size exceeds
 * about c (ev->step_min), so of steps N(0, amp^2) it finds the fraction
 * P(amp) = 2 Q(c / amp): a rate of n found / T underestimates the rate and
 * (with the Allan level K^2 = rate amp^2, which the fit fixes) overstates
 * the size. With u = c / amp, n = (K^2 / amp^2) T P gives
 * u^2 2 Q(u) = n c^2 / (K^2 T); of its two roots the one with the larger
 * steps (u below u*, where u^2 2 Q(u) peaks: 2 Q(u*) = u* phi(u*)) is taken,
 * the one the detection of n steps supports; when n exceeds what any size
 * would give, the rate stays count / span (a rarer, larger step than
 * counted would contradict the count). n and T are the count and the span
 * of the evidence (the fit segment: a rate, so it holds for the middle too).
 * The Allan level is unchanged: rate and amp move along rate amp^2 = K^2. */
static void jumps_rate(sg_chmodel_t *m, const sg_evidence_t *ev)
{
    int k = sg_model_find(m, FNAV_EFFECT_JUMPS), i;
    double K2, c, rhs, lo = 0.0, hi, us, a, b, rel;
    if (k < 0 || ev == NULL || ev->nsteps < 1 || !(ev->step_min > 0.0) || !(ev->span_s > 0.0)) {
        return;
    }
    K2 = m->e[k].p[0] * m->e[k].p[1] * m->e[k].p[1];
    if (!(K2 > 0.0)) {
        return;
    }
    c = ev->step_min;
    rhs = (double)ev->nsteps * c * c / (K2 * ev->span_s);
    /* u*: the root of 2 Q(u) - u phi(u) on [0.5, 2] */
    a = 0.5;
    b = 2.0;
    for (i = 0; i < 60; i++) {
        double u = 0.5 * (a + b);
        if (2.0 * gsl_cdf_ugaussian_Q(u) - u * exp(-0.5 * u * u) / sqrt(2.0 * M_PI) > 0.0) {
            a = u;
        } else {
            b = u;
        }
    }
    us = 0.5 * (a + b);
    hi = us;
    if (!(rhs < us * us * 2.0 * gsl_cdf_ugaussian_Q(us))) {
        /* the Allan level cannot hold that many detectable steps: the rate
         * stays at what was counted (count / span) */
        return;
    }
    for (i = 0; i < 60; i++) {
        double u = 0.5 * (lo + hi);
        if (u * u * 2.0 * gsl_cdf_ugaussian_Q(u) < rhs) {
            lo = u;
        } else {
            hi = u;
        }
    }
    us = 0.5 * (lo + hi);
    if (!(us > 0.0)) {
        return;
    }
    /* the relative error of the size stays that of K (the count's own
     * Poisson error is not added) */
    rel = m->e[k].se[1] / m->e[k].p[1];
    m->e[k].p[1] = c / us;
    m->e[k].p[0] = K2 / (m->e[k].p[1] * m->e[k].p[1]);
    m->e[k].se[1] = rel * m->e[k].p[1];
}

int sg_param_at_bound(double v, double lo, double hi)
{
    if (!(lo > 0.0) || !(hi > lo) || !isfinite(v)) {
        return 0;
    }
    if (v <= lo * (1.0 + SG_BOUND_REL)) {
        return -1;
    }
    return v >= hi * (1.0 - SG_BOUND_REL) ? 1 : 0;
}

double sg_ar1_tau_min(double rate_hz)
{
    const fnav_effect_info_t *ai = fnav_imuerr_effect_info(FNAV_EFFECT_AR1);
    double tmin_s = 1.0 / rate_hz;
    if (ai != NULL && tmin_s < ai->params[0].lo) {
        tmin_s = ai->params[0].lo;
    }
    return tmin_s;
}

int sg_ar1_at_min(const sg_chres_t *c, double rate_hz)
{
    const int ia = sg_model_find(&c->baseline, FNAV_EFFECT_AR1);
    return c->active && ia >= 0 && c->baseline.e[ia].p[1] > 0.0 && rate_hz > 0.0 &&
           c->baseline.e[ia].p[0] <= 1.001 * sg_ar1_tau_min(rate_hz);
}

double sg_time_fit_q(const sg_table_t *t, int thermal)
{
    sg_chmodel_t m;
    double X[SG_TAB_NT][2], c[2], cov[2][2];
    memset(&m, 0, sizeof m);
    if (!t->tw_twins || t->nt == 0) {
        return (double)NAN;
    }
    if (!thermal) {
        return time_ls(t, time_cols(t, 0, 1, 1.0, X), X, c, cov);
    }
    m.n = 1;
    set_effect(&m.e[0], FNAV_EFFECT_THERMAL);
    if (time_fit(t, &m, 0, -1) != 0) {
        return (double)NAN;
    }
    return time_ls(t, time_cols(t, 1, 0, m.e[0].p[2], X), X, c, cov);
}

int sg_fit_model(const sg_table_t *t, double mean, const int *with, int nwith, const sg_evidence_t *ev, double tmax_s,
                 sg_fit_t *out)
{
    skel_t s, best;
    int i, iw = -1, ia = -1, it = -1, ir = -1, nq, qv, ngT, gi, ti, have_th = 0, timefit = 0;
    double tmin_s, bestQ = INFINITY, span = 0.0;
    {
        int b;
        for (b = 0; b < t->nb; b++) {
            span += t->t1_s[b] - t->t0_s[b];
        }
    }
    memset(out, 0, sizeof *out);
    memset(&s, 0, sizeof s);
    if (t->n < 4) {
        return -1;
    }
    s.m.mean = mean;
    set_effect(&s.m.e[0], FNAV_EFFECT_WHITE);
    set_effect(&s.m.e[1], FNAV_EFFECT_AR1);
    s.free_[0] = s.free_[1] = 1;
    iw = 0;
    ia = 1;
    s.m.n = 2;
    best = s;
    for (i = 0; i < nwith; i++) {
        sg_effect_t e;
        set_effect(&e, with[i]);
        switch (with[i]) {
        case FNAV_EFFECT_QUANT:
            e.p[0] = ev->q;
            break;
        case FNAV_EFFECT_VIBRATION:
            e.p[0] = ev->tone_amp;
            e.p[1] = ev->tone_hz;
            e.p[2] = ev->tone_phase;
            break;
        case FNAV_EFFECT_JUMPS:
            e.p[0] = (ev->nsteps > 0 ? (double)ev->nsteps : 1.0) / (span > 0.0 ? span : 1.0);
            break;
        case FNAV_EFFECT_THERMAL:
            have_th = 1;
            break;
        default:
            break;
        }
        if (with[i] == FNAV_EFFECT_QUANT && !(e.p[0] > 0.0)) {
            return -1;
        }
        if (with[i] == FNAV_EFFECT_VIBRATION && !(e.p[1] > 0.0)) {
            return -1;
        }
        s.free_[s.m.n] = (with[i] != FNAV_EFFECT_QUANT && with[i] != FNAV_EFFECT_VIBRATION);
        if (with[i] == FNAV_EFFECT_THERMAL) {
            it = s.m.n;
        }
        if (with[i] == FNAV_EFFECT_RAMP) {
            ir = s.m.n;
        }
        s.m.e[s.m.n++] = e;
        if (s.m.n >= SG_MAX_EFF) {
            break;
        }
    }
    (void)iw;
    (void)span;
    /* the deterministic drifts from the time domain (their signs too); the
     * Allan fit then takes them as fixed */
    if ((it >= 0 || ir >= 0) && time_fit(t, &s.m, it, ir) == 0) {
        timefit = 1;
        have_th = 0;
        if (it >= 0) {
            s.free_[it] = 0;
        }
        if (ir >= 0) {
            s.free_[ir] = 0;
        }
    }
    /* AR(1) correlation time grid: from one sample to tmax, within the
     * catalogue's range (its 1 ms is above one sample beyond 1 kHz: a
     * shorter fitted time would make every twin fail) */
    tmin_s = sg_ar1_tau_min(t->rate_hz);
    {
        const fnav_effect_info_t *ai = fnav_imuerr_effect_info(FNAV_EFFECT_AR1);
        if (ai != NULL && tmax_s > ai->params[0].hi) {
            tmax_s = ai->params[0].hi;
        }
    }
    if (!(tmax_s > tmin_s)) {
        tmax_s = 2.0 * tmin_s;
    }
    ngT = 40;
    nq = (ev != NULL && sg_model_find(&s.m, FNAV_EFFECT_QUANT) >= 0) ? 2 : 1;
    for (qv = 0; qv < nq; qv++) {
        int iq = sg_model_find(&s.m, FNAV_EFFECT_QUANT);
        if (iq >= 0) {
            s.m.e[iq].p[1] = (double)qv;
        }
        for (ti = 0; ti < (have_th ? 24 : 1); ti++) {
            if (have_th) {
                /* warm-up time constants from 10 s to twice the segment */
                double te = t->t1_s[t->nb - 1], lo = 10.0, hi = 2.0 * (te > 20.0 ? te : 20.0);
                s.m.e[it].p[2] = lo * pow(hi / lo, (double)ti / 23.0);
            }
            for (gi = 0; gi < ngT; gi++) {
                double Q;
                s.m.e[ia].p[0] = tmin_s * pow(tmax_s / tmin_s, (double)gi / (double)(ngT - 1));
                Q = solve_skel(t, &s);
                if (Q < bestQ) {
                    bestQ = Q;
                    best = s;
                }
            }
        }
    }
    if (!isfinite(bestQ)) {
        return -1;
    }
    if (have_th) {
        /* the warm-up's time constant from the grid above (the time fit
         * failed): at its first or last point it is a bound, not a fit */
        const double te = t->t1_s[t->nb - 1];
        sg_effect_t *e = &best.m.e[it];
        e->lo[2] = 10.0;
        e->hi[2] = 2.0 * (te > 20.0 ? te : 20.0);
        e->at_bound[2] = sg_param_at_bound(e->p[2], e->lo[2], e->hi[2]);
    }
    /* refine the AR(1) time: golden section in ln T around the grid point */
    {
        double step = log(tmax_s / tmin_s) / (double)(ngT - 1);
        double lo = log(best.m.e[ia].p[0]) - step, hi = log(best.m.e[ia].p[0]) + step;
        const double gr = 0.6180339887498949;
        int k;
        if (lo < log(tmin_s)) {
            lo = log(tmin_s);
        }
        if (hi > log(tmax_s)) {
            hi = log(tmax_s);
        }
        for (k = 0; k < 30 && hi > lo; k++) {
            skel_t s1 = best, s2 = best;
            double x1 = hi - gr * (hi - lo), x2 = lo + gr * (hi - lo), q1, q2;
            s1.m.e[ia].p[0] = exp(x1);
            s2.m.e[ia].p[0] = exp(x2);
            q1 = solve_skel(t, &s1);
            q2 = solve_skel(t, &s2);
            if (q1 < q2) {
                hi = x2;
                if (q1 < bestQ) {
                    bestQ = q1;
                    best = s1;
                }
            } else {
                lo = x1;
                if (q2 < bestQ) {
                    bestQ = q2;
                    best = s2;
                }
            }
        }
    }
    /* keep the AR(1) term only when it pays: without it the objective must
     * be worse by more than SG_AR1_DQ (the Allan points are strongly
     * correlated, so Q over-counts their information; a bump fitted to
     * noise would make the twin's shape wrong on the held-out data) */
    {
        skel_t s0 = best;
        double Q0;
        s0.free_[ia] = 0;
        s0.m.e[ia].p[1] = 0.0;
        Q0 = solve_skel(t, &s0);
        if (Q0 - bestQ < SG_AR1_DQ) {
            best = s0;
            bestQ = Q0;
            best.m.e[ia].p[0] = 1.0;
        }
    }
    /* signs of the drifts from the fit segment's slope (when the Allan
     * table fitted them) */
    for (i = 0; i < best.m.n && !timefit; i++) {
        sg_effect_t *e = &best.m.e[i];
        if (e->id == FNAV_EFFECT_RAMP && ev != NULL && ev->slope < 0.0) {
            e->p[0] = -e->p[0];
        }
        if (e->id == FNAV_EFFECT_THERMAL && ev != NULL && ev->slope < 0.0) {
            /* coef * rise is what the data fix; rise keeps its default */
            e->p[0] = -e->p[0];
        }
    }
    if (best.m.e[ia].p[1] > 0.0) {
        /* the AR(1) time's search, as the baseline's ar1_tau_at_min and
         * ar1_tau_at_max report it (an AR(1) of sigma 0 has no time) */
        best.m.e[ia].lo[0] = tmin_s;
        best.m.e[ia].hi[0] = tmax_s;
        best.m.e[ia].at_bound[0] = sg_param_at_bound(best.m.e[ia].p[0], tmin_s, tmax_s);
    }
    fit_errors(t, &best);
    jumps_rate(&best.m, ev);
    for (i = 0; i < best.m.n; i++) {
        sg_effect_t *e = &best.m.e[i];
        if (e->id == FNAV_EFFECT_THERMAL && !timefit && isfinite(e->se[0])) {
            e->se[0] = fabs(e->se[0]);
        }
        if (e->id == FNAV_EFFECT_AR1 && !(e->p[1] > 0.0)) {
            /* no AR(1) part: keep a harmless time */
            e->p[1] = 0.0;
        }
    }
    out->model = best.m;
    out->Q = bestQ;
    /* with the twins' variances the time points are chi-square-like: a
     * drift the Allan range is too short to see (its excess lies beyond the
     * longest tau analysed) shows in the blocks' trends and level (models
     * without a drift all carry the same Q_time_drift); a random drift,
     * in Q_time, by the spread it gives them */
    out->Q_time = 0.0;
    out->Q_time_drift = 0.0;
    if (t->tw_twins) {
        int k;
        for (k = 0; k < t->nt; k++) {
            double r = t->ty[k] - model_time_stat(&best.m, t->tkind[k], t->tlo[k], t->thi[k], t->tblk[k]);
            double dv = 0.0;
            if (t->tvb_set) {
                /* the model's slow random parts beyond the baseline's widen
                 * the point's spread: Gaussian deviance, the log term the
                 * price of the widening */
                dv = (model_time_var(&best.m, t->tkind[k], t->tlo[k], t->thi[k], t->tblk[k]) - t->tvb[k]) * t->tw[k];
                dv = dv > 0.0 ? dv : 0.0;
            }
            out->Q_time += t->tw[k] * r * r / (1.0 + dv) + log1p(dv);
            out->Q_time_drift += t->tw[k] * r * r;
        }
    }
    out->npts = (int)t->n;
    out->ok = 1;
    return 0;
}

/* ------------------------------------------------------------ evidence */

/* |DFT|^2 with a Hann window at frequency f (cycles per sample), and the
 * complex value. */
static double dft_hann(const double *x, size_t n, double f, double *re, double *im)
{
    double cr = 0.0, ci = 0.0, wsum = 0.0;
    double c1 = cos(2.0 * M_PI * f), s1 = -sin(2.0 * M_PI * f), c = 1.0, s = 0.0;
    size_t k;
    for (k = 0; k < n; k++) {
        double w = 0.5 - 0.5 * cos(2.0 * M_PI * (double)k / (double)n), t;
        cr += w * x[k] * c;
        ci += w * x[k] * s;
        wsum += w;
        t = c * c1 - s * s1;
        s = c * s1 + s * c1;
        c = t;
        if ((k & 1023u) == 1023u) {
            /* re-anchor the recurrence */
            c = cos(2.0 * M_PI * f * (double)(k + 1));
            s = -sin(2.0 * M_PI * f * (double)(k + 1));
        }
    }
    *re = cr / wsum;
    *im = ci / wsum;
    return (*re) * (*re) + (*im) * (*im);
}


/* Strongest spectral line of x (mean removed), by a Hann periodogram
 * against the local median, refined by maximising the DFT. */
static void find_tone(const double *x, size_t n, double fs, sg_evidence_t *ev)
{
    size_t n2 = 1, k, kbest = 0, nb;
    double *b, mean = 0.0, best = 0.0, *tmp;
    const size_t blk = 64;
    ev->tone_hz = ev->tone_amp = ev->tone_phase = 0.0;
    ev->tone_score = 0.0;
    while (2 * n2 <= n) {
        n2 *= 2;
    }
    if (n2 < 1024) {
        return;
    }
    b = (double *)malloc(n2 * sizeof *b);
    tmp = (double *)malloc((n2 / 2 + 1) * sizeof *tmp);
    if (b == NULL || tmp == NULL) {
        free(b);
        free(tmp);
        return;
    }
    for (k = 0; k < n2; k++) {
        mean += x[k];
    }
    mean /= (double)n2;
    for (k = 0; k < n2; k++) {
        double w = 0.5 - 0.5 * cos(2.0 * M_PI * (double)k / (double)n2);
        b[k] = w * (x[k] - mean);
    }
    if (gsl_fft_real_radix2_transform(b, 1, n2) != 0) {
        free(b);
        free(tmp);
        return;
    }
    /* half-complex: b[k] = Re, b[n2 - k] = Im */
    nb = n2 / 2;
    for (k = 1; k < nb; k++) {
        tmp[k] = b[k] * b[k] + b[n2 - k] * b[n2 - k];
    }
    /* local median per block of 64 bins; lines below 8 bins are drift */
    {
        size_t k0;
        double med[64];
        for (k0 = 8; k0 + blk <= nb; k0 += blk) {
            size_t i;
            double md;
            for (i = 0; i < blk; i++) {
                med[i] = tmp[k0 + i];
            }
            qsort(med, blk, sizeof med[0], hx_cmp_double);
            md = 0.5 * (med[blk / 2 - 1] + med[blk / 2]);
            for (i = 0; i < blk && md > 0.0; i++) {
                double r = tmp[k0 + i] / md;
                if (r > best) {
                    best = r;
                    kbest = k0 + i;
                }
            }
        }
    }
    free(b);
    if (kbest == 0) {
        free(tmp);
        return;
    }
    /* ratio to the median of an exponential: P(r > s) = 2^-s per bin */
    ev->tone_score = best * log10(2.0) - log10((double)nb);
    {
        /* refine on the whole segment by golden section over +-1 bin */
        double f0 = (double)kbest / (double)n2, lo = f0 - 1.0 / (double)n2, hi = f0 + 1.0 / (double)n2;
        const double gr = 0.6180339887498949;
        double re, im, fb = f0, pb;
        int it;
        double *xc = (double *)malloc(n * sizeof *xc);
        if (xc == NULL) {
            free(tmp);
            return;
        }
        mean = 0.0;
        for (k = 0; k < n; k++) {
            mean += x[k];
        }
        mean /= (double)n;
        for (k = 0; k < n; k++) {
            xc[k] = x[k] - mean;
        }
        pb = dft_hann(xc, n, fb, &re, &im);
        for (it = 0; it < 40; it++) {
            double x1 = hi - gr * (hi - lo), x2 = lo + gr * (hi - lo), r1, i1, r2, i2;
            double p1 = dft_hann(xc, n, x1, &r1, &i1), p2 = dft_hann(xc, n, x2, &r2, &i2);
            if (p1 > p2) {
                hi = x2;
                if (p1 > pb) {
                    pb = p1;
                    fb = x1;
                }
            } else {
                lo = x1;
                if (p2 > pb) {
                    pb = p2;
                    fb = x2;
                }
            }
        }
        pb = dft_hann(xc, n, fb, &re, &im);
        free(xc);
        ev->tone_hz = fb * fs;
        ev->tone_amp = 2.0 * sqrt(pb);
        ev->tone_phase = atan2(im, re) + 0.5 * M_PI;
    }
    free(tmp);
}

/* Bias steps: two-window mean differences at scales of 64 samples to an
 * eighth of the segment, normalised by their robust spread, Bonferroni over
 * the positions; detections merged across scales. */
static void find_steps(const double *x, size_t n, sg_evidence_t *ev)
{
    double *cs, pos[256], size[256], zsc[256], scl[256];
    size_t w, np = 0, k;
    ev->nsteps = 0;
    ev->step_rms = 0.0;
    ev->step_min = 0.0;
    if (n < 512) {
        return;
    }
    cs = (double *)malloc((n + 1) * sizeof *cs);
    if (cs == NULL) {
        return;
    }
    cs[0] = 0.0;
    for (k = 0; k < n; k++) {
        cs[k + 1] = cs[k] + (x[k] - x[0]);
    }
    for (w = 64; 8 * w <= n; w *= 2) {
        size_t hop = w / 4, nd = 0, i;
        double *d, *ad, mad, thr;
        size_t cnt = (n - 2 * w) / hop + 1;
        d = (double *)malloc(cnt * sizeof *d);
        ad = (double *)malloc(cnt * sizeof *ad);
        if (d == NULL || ad == NULL) {
            free(d);
            free(ad);
            break;
        }
        for (k = w; k + w <= n; k += hop) {
            d[nd] = (cs[k + w] - cs[k]) / (double)w - (cs[k] - cs[k - w]) / (double)w;
            ad[nd] = fabs(d[nd]);
            nd++;
        }
        qsort(ad, nd, sizeof *ad, hx_cmp_double);
        mad = 1.4826 * ad[nd / 2];
        thr = gsl_cdf_ugaussian_Qinv(0.0025 / (double)nd);
        if (mad > 0.0 && (ev->step_min == 0.0 || thr * mad < ev->step_min)) {
            ev->step_min = thr * mad;
        }
        for (i = 0; i < nd && mad > 0.0; i++) {
            double z = fabs(d[i]) / mad, t = (double)(w + i * hop);
            size_t j, lo = i > 4 ? i - 4 : 0, hi = i + 4 < nd ? i + 4 : nd - 1;
            int ismax = 1, merged = 0;
            if (z < thr) {
                continue;
            }
            for (j = lo; j <= hi; j++) {
                if (fabs(d[j]) > fabs(d[i])) {
                    ismax = 0;
                }
            }
            if (!ismax) {
                continue;
            }
            for (j = 0; j < np; j++) {
                double sc = scl[j] > (double)w ? scl[j] : (double)w;
                if (fabs(pos[j] - t) < sc) {
                    merged = 1;
                    if (z > zsc[j]) {
                        zsc[j] = z;
                        size[j] = d[i];
                    }
                }
            }
            if (!merged && np < 256) {
                pos[np] = t;
                size[np] = d[i];
                zsc[np] = z;
                scl[np] = (double)w;
                np++;
            }
        }
        free(d);
        free(ad);
    }
    free(cs);
    if (np > 0) {
        double s = 0.0;
        for (k = 0; k < np; k++) {
            s += size[k] * size[k];
        }
        ev->step_rms = sqrt(s / (double)np);
    }
    ev->nsteps = (int)np;
}

void sg_evidence(const double *x, const sg_segs_t *segs, double rate_hz, double q_hint, sg_evidence_t *ev)
{
    sg_evidence_seg(x, segs, SG_FIT, rate_hz, q_hint, ev);
}

void sg_evidence_seg(const double *x, const sg_segs_t *segs, int g, double rate_hz, double q_hint, sg_evidence_t *ev)
{
    double st = 0.0, sx = 0.0, stt = 0.0, stx = 0.0, cnt = 0.0;
    int b, ns = 0, nm = 0;
    double s2 = 0.0, cmin = 0.0;
    memset(ev, 0, sizeof *ev);
    ev->q = q_hint;
    ev->q_z = 0.0;
    if (q_hint > 0.0) {
        double zs = 0.0;
        for (b = 0; b < segs->nb[g]; b++) {
            zs += sg_lattice_z(x + segs->start[g][b], (size_t)segs->n[g][b], q_hint);
        }
        ev->q_z = zs / sqrt((double)segs->nb[g]);
    }
    /* lines in the first block; the phase is referred back from the
     * block's first sample to the log's (the fit segment's first block
     * starts at sample 0) */
    find_tone(x + segs->start[g][0], (size_t)segs->n[g][0], rate_hz, ev);
    if (ev->tone_hz > 0.0 && segs->start[g][0] > 0) {
        double ph = ev->tone_phase - 2.0 * M_PI * ev->tone_hz * (double)segs->start[g][0] / rate_hz;
        ev->tone_phase = ph - 2.0 * M_PI * floor(ph / (2.0 * M_PI));
    }
    for (b = 0; b < segs->nb[g]; b++) {
        sg_evidence_t e2;
        long k;
        memset(&e2, 0, sizeof e2);
        find_steps(x + segs->start[g][b], (size_t)segs->n[g][b], &e2);
        ns += e2.nsteps;
        s2 += e2.step_rms * e2.step_rms * (double)e2.nsteps;
        if (e2.step_min > 0.0) {
            cmin += e2.step_min;
            nm++;
        }
        ev->span_s += (double)segs->n[g][b] / rate_hz;
        for (k = 0; k < segs->n[g][b]; k++) {
            long i = segs->start[g][b] + k;
            double t = (double)i / rate_hz, v = x[i] - x[0];
            st += t;
            sx += v;
            stt += t * t;
            stx += t * v;
            cnt += 1.0;
        }
    }
    ev->nsteps = ns;
    ev->step_rms = ns > 0 ? sqrt(s2 / (double)ns) : 0.0;
    ev->step_min = nm > 0 ? cmin / (double)nm : 0.0;
    if (cnt > 2.0) {
        double den = stt - st * st / cnt;
        ev->slope = den > 0.0 ? (stx - st * sx / cnt) / den : 0.0;
    }
}

/* ------------------------------------------------------------ rrw by likelihood */

/* -2 ln L (up to a constant) of segment g under white (variance r per
 * sample) + AR(1) (phi, stationary variance s2) + rate random walk (qb per
 * sample); y holds the segment's samples, its blocks one after the other,
 * with the deterministic drift removed. A two-state Kalman filter over the
 * segment's blocks, the walk carried across the gaps between them (its
 * variance grows by qb per skipped sample; the AR(1) relaxes towards its
 * stationary variance). The walk starts diffuse: it is set from the first
 * sample, whose term is left out. */
static double rrw_nll(const double *ys, const sg_segs_t *segs, int g, double r, double phi, double s2, double qb)
{
    double a = 0.0, b = 0.0, Paa = s2, Pab = 0.0, Pbb = 0.0, nll = 0.0;
    long last = -1, j = 0;
    int blk, started = 0;
    for (blk = 0; blk < segs->nb[g]; blk++) {
        long k0 = segs->start[g][blk], k1 = k0 + segs->n[g][blk], k;
        for (k = k0; k < k1; k++) {
            double y = ys[j++], v, S, ka, kb;
            if (!started) {
                /* the walk from the first sample, its error -(a + e) */
                b = y;
                Pbb = r + s2;
                Pab = -s2;
                last = k;
                started = 1;
                continue;
            }
            if (k - last == 1) {
                a *= phi;
                Paa = phi * phi * Paa + s2 * (1.0 - phi * phi);
                Pab *= phi;
                Pbb += qb;
            } else {
                const double gap = (double)(k - last), pg = pow(phi, gap);
                a *= pg;
                Paa = pg * pg * Paa + s2 * (1.0 - pg * pg);
                Pab *= pg;
                Pbb += qb * gap;
            }
            last = k;
            v = y - a - b;
            S = Paa + 2.0 * Pab + Pbb + r;
            ka = (Paa + Pab) / S;
            kb = (Pab + Pbb) / S;
            a += ka * v;
            b += kb * v;
            Paa -= ka * ka * S;
            Pab -= ka * kb * S;
            Pbb -= kb * kb * S;
            nll += log(S) + v * v / S;
        }
    }
    return nll;
}

int sg_rrw_ml(const double *x, const sg_segs_t *segs, int g, double rate_hz, sg_chmodel_t *m)
{
    const double gr = 0.6180339887498949, dt = 1.0 / rate_hz;
    double r = 0.0, phi = 0.0, s2 = 0.0, K, lo, hi, *y;
    long ny = 0, j = 0;
    int i, ik = -1, k, blk;
    for (i = 0; i < m->n; i++) {
        const sg_effect_t *e = &m->e[i];
        switch (e->id) {
        case FNAV_EFFECT_WHITE: r = e->p[0] * e->p[0] * rate_hz; break;
        case FNAV_EFFECT_AR1:
            if (e->p[1] > 0.0 && e->p[0] > 0.0) {
                s2 = e->p[1] * e->p[1];
                phi = exp(-dt / e->p[0]);
            }
            break;
        case FNAV_EFFECT_RRW: ik = i; break;
        case FNAV_EFFECT_RAMP:
        case FNAV_EFFECT_THERMAL: break;
        default: return 1; /* no state-space form here: the Allan fit stands */
        }
    }
    if (ik < 0 || !(m->e[ik].p[0] > 0.0) || !(r > 0.0) || segs->nb[g] < 1) {
        return 1;
    }
    /* the samples without the deterministic drift, once: they do not depend on K */
    for (blk = 0; blk < segs->nb[g]; blk++) {
        ny += segs->n[g][blk];
    }
    y = (double *)malloc((size_t)(ny > 0 ? ny : 1) * sizeof *y);
    if (y == NULL) {
        return 1;
    }
    for (blk = 0; blk < segs->nb[g]; blk++) {
        long k0 = segs->start[g][blk], k1 = k0 + segs->n[g][blk], kk;
        for (kk = k0; kk < k1; kk++) {
            y[j++] = x[kk] - model_drift(m, (double)kk * dt);
        }
    }
    K = m->e[ik].p[0];
    lo = log(K) - log(8.0);
    hi = log(K) + log(8.0);
    m->e[ik].lo[0] = exp(lo);
    m->e[ik].hi[0] = exp(hi);
    for (k = 0; k < 40 && hi - lo > 1e-3; k++) {
        double x1 = hi - gr * (hi - lo), x2 = lo + gr * (hi - lo);
        double q1 = rrw_nll(y, segs, g, r, phi, s2, exp(2.0 * x1) * dt);
        double q2 = rrw_nll(y, segs, g, r, phi, s2, exp(2.0 * x2) * dt);
        if (q1 < q2) {
            hi = x2;
        } else {
            lo = x1;
        }
    }
    {
        /* standard error from the curvature of -2 ln L in ln K (Fisher
         * information: half of it) */
        const double lk = 0.5 * (lo + hi), h = 0.05;
        const double q0 = rrw_nll(y, segs, g, r, phi, s2, exp(2.0 * lk) * dt);
        const double qp = rrw_nll(y, segs, g, r, phi, s2, exp(2.0 * (lk + h)) * dt);
        const double qm = rrw_nll(y, segs, g, r, phi, s2, exp(2.0 * (lk - h)) * dt);
        const double curv = (qp - 2.0 * q0 + qm) / (h * h);
        m->e[ik].p[0] = exp(lk);
        m->e[ik].se[0] = curv > 0.0 ? m->e[ik].p[0] * sqrt(2.0 / curv) : (double)NAN;
        m->e[ik].se_allan[0] = 0;
        m->e[ik].nrefit[0] = 0; /* the likelihood's se: no refits' interval */
        /* within a factor 8 of the Allan fit's K: at either end the
         * likelihood's optimum lies beyond it (reported, not moved) */
        m->e[ik].at_bound[0] = sg_param_at_bound(m->e[ik].p[0], m->e[ik].lo[0], m->e[ik].hi[0]);
    }
    free(y);
    return 0;
}

/* ------------------------------------------------ flicker or rrw: the block means' likelihood */

/* A segment's block means (D samples each, at most BM_MAXN + 1 per data
 * block) are differenced, which makes a walk stationary, and their exact
 * Gaussian likelihood follows from closed-form autocovariances of every
 * random part of the model; flicker has no finite state-space form for the
 * exact filter of sg_rrw_ml, but its 12 poles have one here
 * (scripts/flicker_rrw_limit.py is the independent double-precision version
 * of the same likelihood). */

#define BM_MAXN 400 /* differenced block means per data block */

/* autocovariance of the first differences of D-long block means, lags
 * 0..n-1, of a model's random parts (deterministic drifts excluded);
 * returns -1 for parts without a Gaussian form here */
static int bm_diff_acov(const sg_chmodel_t *m, double fs, double D, int n, double *d)
{
    double c[BM_MAXN + 2];
    int i, k, j;
    for (k = 0; k < n; k++) {
        d[k] = 0.0;
    }
    for (i = 0; i < m->n; i++) {
        const sg_effect_t *e = &m->e[i];
        int npole = 0;
        double s2[FNAV_IMUERR_FLICKER_POLES], tau[FNAV_IMUERR_FLICKER_POLES], K2 = 0.0, W = 0.0;
        switch (e->id) {
        case FNAV_EFFECT_WHITE: W = e->p[0] * e->p[0] / D; break;
        case FNAV_EFFECT_QUANT:
            if (e->p[1] != 0.0) {
                break; /* noise-shaped: its block means carry one LSB over the block, negligible */
            }
            W = e->p[0] * e->p[0] / 12.0 / (fs * D);
            break;
        case FNAV_EFFECT_AR1:
            if (e->p[1] > 0.0 && e->p[0] > 0.0) {
                s2[0] = e->p[1] * e->p[1];
                tau[0] = e->p[0];
                npole = 1;
            }
            break;
        case FNAV_EFFECT_FLICKER: {
            const int P = FNAV_IMUERR_FLICKER_POLES;
            double lnr = log(e->p[2] / e->p[1]) / (double)(P - 1);
            for (j = 0; j < P; j++) {
                tau[j] = e->p[1] * exp(lnr * (double)j);
                s2[j] = e->p[0] * e->p[0] * lnr / M_PI;
            }
            npole = P;
            break;
        }
        case FNAV_EFFECT_RRW: K2 = e->p[0] * e->p[0]; break;
        case FNAV_EFFECT_JUMPS: K2 = e->p[0] * e->p[1] * e->p[1]; break;
        case FNAV_EFFECT_RAMP:
        case FNAV_EFFECT_THERMAL: break;
        default: return -1;
        }
        d[0] += 2.0 * W + K2 * 2.0 * D / 3.0;
        if (n > 1) {
            d[1] += -W + K2 * D / 6.0;
        }
        for (j = 0; j < npole; j++) {
            const double a = D / tau[j], g = s2[j] / (a * a);
            c[0] = 2.0 * g * (a - 1.0 + exp(-a));
            for (k = 1; k <= n; k++) {
                c[k] = g * (2.0 * cosh(a) - 2.0) * exp(-(double)k * a);
                if (!isfinite(c[k])) {
                    c[k] = 0.0;
                }
            }
            d[0] += 2.0 * (c[0] - c[1]);
            for (k = 1; k < n; k++) {
                d[k] += 2.0 * c[k] - c[k - 1] - c[k + 1];
            }
        }
    }
    return 0;
}

/* Durbin-Levinson: phi_{k+1,k+1} = (acv(k+1) - sum_j phi_{k,j} acv(k+1-j)) / v_k,
 * phi_{k+1,j} = phi_{k,j} - phi_{k+1,k+1} phi_{k,k+1-j}, v_{k+1} = v_k (1 - phi_{k+1,k+1}^2)
 * (Brockwell and Davis, Time Series: Theory and Methods, 5.2.1) */
double sg_toeplitz_nll2(const double *acv, int nblk, const int *nd, const double *const *dd)
{
    double phi[BM_MAXN], prev[BM_MAXN];
    int nmax = 0, k, j, b;
    double v = acv[0], q = 0.0;
    for (b = 0; b < nblk; b++) {
        if (nd[b] > BM_MAXN) {
            return (double)NAN;
        }
        nmax = nd[b] > nmax ? nd[b] : nmax;
    }
    for (k = 0; k < nmax; k++) {
        /* phi holds phi_{k,1..k}: the predictor of sample k from the k before it */
        if (!(v > 0.0)) {
            return INFINITY;
        }
        for (b = 0; b < nblk; b++) {
            if (k < nd[b]) {
                double e = dd[b][k];
                for (j = 0; j < k; j++) {
                    e -= phi[j] * dd[b][k - 1 - j];
                }
                q += log(v) + e * e / v;
            }
        }
        if (k + 1 < nmax) {
            double num = acv[k + 1], a;
            for (j = 0; j < k; j++) {
                num -= phi[j] * acv[k - j];
                prev[j] = phi[j];
            }
            a = num / v;
            for (j = 0; j < k; j++) {
                phi[j] = prev[j] - a * prev[k - 1 - j];
            }
            phi[k] = a;
            v *= 1.0 - a * a;
        }
    }
    return q;
}

/* -2 ln L with the model as it is (NaN: a part without a Gaussian form) */
static double bm_eval(const sg_chmodel_t *m, double fs, double Ds, int nblk, const int *nd, const double *const *dd)
{
    double acv[BM_MAXN + 1];
    if (bm_diff_acov(m, fs, Ds, BM_MAXN, acv) != 0) {
        return (double)NAN;
    }
    return sg_toeplitz_nll2(acv, nblk, nd, dd);
}

/* golden section for one parameter p (searched in ln p over [lo, hi]),
 * the others fixed; leaves the best value in *p and returns its -2 ln L */
static double bm_golden(sg_chmodel_t *m, double *p, double lo, double hi, double fs, double Ds, int nblk,
                        const int *nd, const double *const *dd)
{
    const double gr = 0.6180339887498949;
    double x1 = hi - gr * (hi - lo), x2 = lo + gr * (hi - lo), q1, q2, p0 = *p, q0;
    q0 = bm_eval(m, fs, Ds, nblk, nd, dd);
    *p = exp(x1);
    q1 = bm_eval(m, fs, Ds, nblk, nd, dd);
    *p = exp(x2);
    q2 = bm_eval(m, fs, Ds, nblk, nd, dd);
    while (hi - lo > 5e-3) {
        if (q1 < q2) {
            hi = x2;
            x2 = x1;
            q2 = q1;
            x1 = hi - gr * (hi - lo);
            *p = exp(x1);
            q1 = bm_eval(m, fs, Ds, nblk, nd, dd);
        } else {
            lo = x1;
            x1 = x2;
            q1 = q2;
            x2 = lo + gr * (hi - lo);
            *p = exp(x2);
            q2 = bm_eval(m, fs, Ds, nblk, nd, dd);
        }
    }
    if (q0 <= q1 && q0 <= q2) {
        *p = p0;
        return q0;
    }
    *p = q1 < q2 ? exp(x1) : exp(x2);
    return q1 < q2 ? q1 : q2;
}

int sg_bm_fit(const double *x, const sg_segs_t *segs, int g, double rate_hz, sg_chmodel_t *m, int id, double *nll2)
{
    double dd[SG_MAX_BLK][BM_MAXN], acv[1];
    const double *rows[SG_MAX_BLK];
    const double h = 0.05;
    int nd[SG_MAX_BLK], blk, ik, mp;
    long nmax = 0, D;
    double Ds, c, q, qp, qm, curv, *p;
    ik = sg_model_find(m, id);
    mp = mag_param(id);
    if ((id != FNAV_EFFECT_FLICKER && id != FNAV_EFFECT_RRW) || ik < 0 || !(m->e[ik].p[mp] > 0.0) ||
        bm_diff_acov(m, rate_hz, 1.0, 1, acv) != 0) {
        return 1;
    }
    for (blk = 0; blk < segs->nb[g]; blk++) {
        nmax = segs->n[g][blk] > nmax ? segs->n[g][blk] : nmax;
    }
    /* at most BM_MAXN + 1 block means per data block */
    D = (nmax + BM_MAXN) / (BM_MAXN + 1);
    D = D < 1 ? 1 : D;
    Ds = (double)D / rate_hz;
    for (blk = 0; blk < segs->nb[g]; blk++) {
        long k0 = segs->start[g][blk], nb = segs->n[g][blk] / D, b;
        double prev = 0.0;
        nd[blk] = 0;
        for (b = 0; b < nb; b++) {
            double s = 0.0;
            long k;
            for (k = k0 + b * D; k < k0 + (b + 1) * D; k++) {
                s += x[k] - model_drift(m, (double)k / rate_hz);
            }
            s /= (double)D;
            if (b > 0 && nd[blk] < BM_MAXN) {
                dd[blk][nd[blk]++] = s - prev;
            }
            prev = s;
        }
        if (nd[blk] < 2) {
            return 1; /* a block too short for a likelihood */
        }
    }
    for (blk = 0; blk < segs->nb[g]; blk++) {
        rows[blk] = dd[blk];
    }
    p = &m->e[ik].p[mp];
    c = log(*p);
    m->e[ik].lo[mp] = exp(c - log(30.0));
    m->e[ik].hi[mp] = exp(c + log(30.0));
    q = bm_golden(m, p, c - log(30.0), c + log(30.0), rate_hz, Ds, segs->nb[g], nd, rows);
    if (!(q < (double)INFINITY)) {
        return 1;
    }
    /* standard error from the curvature of -2 ln L in ln magnitude */
    c = *p;
    *p = c * exp(h);
    qp = bm_eval(m, rate_hz, Ds, segs->nb[g], nd, rows);
    *p = c * exp(-h);
    qm = bm_eval(m, rate_hz, Ds, segs->nb[g], nd, rows);
    *p = c;
    curv = (qp + qm - 2.0 * q) / (h * h);
    m->e[ik].se[mp] = curv > 0.0 ? c * sqrt(2.0 / curv) : (double)NAN;
    m->e[ik].se_allan[mp] = 0;
    m->e[ik].nrefit[mp] = 0; /* the likelihood's se: no refits' interval */
    /* the golden section stops 5e-3 wide in ln magnitude: within that of
     * an end of the factor-30 interval the optimum lies at or beyond it */
    m->e[ik].at_bound[mp] = log(c / m->e[ik].lo[mp]) <= 5e-3 ? -1 : (log(m->e[ik].hi[mp] / c) <= 5e-3 ? 1 : 0);
    *nll2 = q;
    return 0;
}
