/* Sim-to-real gap: features of a segment (Allan, Welch bands, value
 * lattice) and the comparison of a real segment with its twins
 * (hx_simgap.h, docs/simgap.md). */
#include "hx_simgap.h"
#include "hx_cli.h"
#include "hx_allan_ident.h"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_sf_psi.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char *const k_dom[SG_NDOM] = { "allan", "psd", "lattice", "timing", "nav", "time" };
static const char *const k_ch[SG_NCH] = { "ax", "ay", "az", "gx", "gy", "gz" };

const char *sg_domain_name(int dom)
{
    return (dom >= 0 && dom < SG_NDOM) ? k_dom[dom] : "?";
}

const char *sg_time_kind_name(int kind)
{
    static const char *const k[SG_TIME_NKIND + 1] = { "trend", "curvature", "steps", "level" };
    return (kind >= 0 && kind <= SG_TIME_LEVEL) ? k[kind] : "?";
}

const char *sg_channel_name(int ch)
{
    return (ch >= 0 && ch < SG_NCH) ? k_ch[ch] : "all";
}

const char *sg_channel_unit(int ch)
{
    return ch < 3 ? "m/s^2" : "rad/s";
}

/* ------------------------------------------------------------ points */

void sg_plist_free(sg_plist_t *l)
{
    free(l->p);
    memset(l, 0, sizeof *l);
}

int sg_plist_add(sg_plist_t *l, const sg_point_t *p)
{
    if (l->n == l->cap) {
        size_t cap = l->cap ? 2 * l->cap : 64;
        sg_point_t *np = (sg_point_t *)realloc(l->p, cap * sizeof *np);
        if (np == NULL) {
            return -1;
        }
        l->p = np;
        l->cap = cap;
    }
    l->p[l->n++] = *p;
    return 0;
}

/* ------------------------------------------------------------ features */

sg_feat_cfg_t sg_feat_cfg_default(double rate_hz)
{
    sg_feat_cfg_t c;
    c.rate_hz = rate_hz;
    c.allan_per_octave = 2u;
    c.tau_frac = SG_TEST_FRAC;
    c.nfft_max = SG_NFFT_MAX;
    c.bands_per_octave = 3u;
    return c;
}

/* Welch segment length for n samples: at least 16 segments. */
static unsigned pick_nfft(long n, unsigned nfft_max)
{
    unsigned nf = 16u;
    if (n < 16 * 16) {
        return 0u;
    }
    while (2u * nf <= nfft_max && (long)(2u * nf) * 16 <= n) {
        nf *= 2u;
    }
    return nf;
}

int sg_acc_init(sg_acc_t *a, const sg_feat_cfg_t *cfg, long n, double q)
{
    fnav_allan_config_t ac;
    unsigned nfft;
    memset(a, 0, sizeof *a);
    a->cfg = *cfg;
    a->n_expect = n;
    a->q = q;
    if (n >= 40) {
        uint32_t tmax = (uint32_t)floor((double)n * cfg->tau_frac);
        size_t i, k = 0;
        uint32_t grid[FNAV_ALLAN_MAX_POINTS];
        size_t ng;
        if (tmax < 1u) {
            tmax = 1u;
        }
        ng = fnav_allan_grid(grid, FNAV_ALLAN_MAX_POINTS, tmax, cfg->allan_per_octave);
        for (i = 0; i < ng; i++) {
            if (grid[i] <= tmax) {
                a->tau[k++] = grid[i];
            }
        }
        a->ntau = k;
        if (k > 0) {
            a->allan = (fnav_allan_t *)malloc(sizeof *a->allan);
            ac.tau = a->tau;
            ac.n_tau = k;
            if (a->allan == NULL || fnav_allan_init(a->allan, &ac) != FNAV_OK) {
                sg_acc_free(a);
                return -1;
            }
        }
    }
    a->td = n >= 16L * SG_TD_K;
    nfft = pick_nfft(n, cfg->nfft_max);
    if (nfft > 0u) {
        fnav_welch_config_t wc = fnav_welch_config_default;
        wc.nfft = nfft;
        wc.overlap = nfft / 2u;
        wc.rate_hz = (fnav_real_t)cfg->rate_hz;
        a->welch = (fnav_welch_t *)malloc(sizeof *a->welch);
        if (a->welch == NULL || fnav_welch_init(a->welch, &wc) != FNAV_OK) {
            sg_acc_free(a);
            return -1;
        }
    }
    return 0;
}

void sg_acc_free(sg_acc_t *a)
{
    free(a->allan);
    free(a->welch);
    a->allan = NULL;
    a->welch = NULL;
}

void sg_acc_push(sg_acc_t *a, double x)
{
    fnav_status_t st;
    if (a->allan != NULL) {
        st = fnav_allan_push(a->allan, (fnav_real_t)x);
        (void)st;
    }
    if (a->welch != NULL) {
        st = fnav_welch_push(a->welch, (fnav_real_t)x);
        (void)st;
    }
    /* the lattice statistic from at most SG_LAT_MAX differences: its z
     * is then up to about 360, far beyond SG_ZCAP, at a fraction of the cost */
    if (a->q > 0.0 && !a->lat_external && a->lm < SG_LAT_MAX) {
        if (a->have_prev) {
            double ph = 2.0 * M_PI * (x - a->prev) / a->q;
            a->lc += cos(ph);
            a->ls += sin(ph);
            a->lm++;
        }
        a->prev = x;
        a->have_prev = 1;
    }
    if (a->td && a->n < a->n_expect) {
        /* u from -1 to 1 over the block; c = P2(u) minus its grid mean
         * 1 / (n - 1), so that sum c = sum u = 0 and the offset x0 drops out */
        const double nm1 = (double)(a->n_expect - 1);
        const double u = 2.0 * (double)a->n / nm1 - 1.0, c = 0.5 * (3.0 * u * u - 1.0) - 1.0 / nm1;
        const double d = a->n == 0 ? 0.0 : x - a->x0;
        const long i = (long)(((double)a->n * (double)SG_TD_K) / (double)a->n_expect);
        if (a->n == 0) {
            a->x0 = x;
        }
        a->s1 += d * u;
        a->s1q += u * u;
        a->s2 += d * c;
        a->s2q += c * c;
        a->sub[i] += d;
        a->subn[i]++;
    }
    a->n++;
}

/* The time-domain statistics of a block (SG_TIME_* order): trend (u/s),
 * curvature (u) and the step statistic. */
static void time_stats(const sg_acc_t *a, double v[SG_TIME_NKIND], int *peak)
{
    double m[SG_TD_K], d[SG_TD_K], ad[SG_TD_K], med, mad, big = 0.0;
    const double span_s = (double)(a->n_expect - 1) / a->cfg.rate_hz;
    int i, nd = 0;
    *peak = 1;
    v[SG_TIME_TREND] = a->s1q > 0.0 ? (a->s1 / a->s1q) * 2.0 / span_s : 0.0;
    v[SG_TIME_CURV] = a->s2q > 0.0 ? a->s2 / a->s2q : 0.0;
    for (i = 0; i < SG_TD_K; i++) {
        m[i] = a->subn[i] > 0 ? a->sub[i] / (double)a->subn[i] : 0.0;
    }
    /* lag-2 differences: a step inside sub-block i shows whole in d_i */
    for (i = 1; i + 1 < SG_TD_K; i++) {
        d[nd++] = m[i + 1] - m[i - 1];
    }
    memcpy(ad, d, (size_t)nd * sizeof *ad);
    qsort(ad, (size_t)nd, sizeof *ad, hx_cmp_double);
    med = 0.5 * (ad[(nd - 1) / 2] + ad[nd / 2]);
    for (i = 0; i < nd; i++) {
        ad[i] = fabs(d[i] - med);
        if (ad[i] > big) {
            big = ad[i];
            *peak = i + 1; /* d[i] = m[i + 2] - m[i] */
        }
    }
    qsort(ad, (size_t)nd, sizeof *ad, hx_cmp_double);
    mad = 1.4826 * 0.5 * (ad[(nd - 1) / 2] + ad[nd / 2]);
    v[SG_TIME_STEP] = (mad > 0.0 && big > 0.0) ? log(big / mad) : 0.0;
}

double sg_rayleigh_z(double R)
{
    if (!(R > 0.0)) {
        return -8.0;
    }
    if (R > 30.0) {
        return sqrt(2.0 * R - log(4.0 * M_PI * R));
    }
    /* from the smaller tail: below R = ln 2, Phi(z) = 1 - exp(-R) is
     * -expm1(-R) (exp(-R) rounds to 1 below R = 1.1e-16, and Q^-1(1) is
     * -inf) */
    if (R < 0.6931471805599453) { /* ln 2 */
        return gsl_cdf_ugaussian_Pinv(-expm1(-R));
    }
    return gsl_cdf_ugaussian_Qinv(exp(-R));
}

/* Correlation of the Welch estimates: between segments hop apart (window
 * overlap) and between bins l apart (window leakage), for a locally flat
 * spectrum (Percival & Walden 1993, sec. 6.17). Equivalent degrees of
 * freedom of the mean of B adjacent bins averaged over K segments. */
static double welch_band_edf(unsigned nfft, unsigned K, unsigned B)
{
    double w[SG_NFFT_MAX], s2 = 0.0, rho = 0.0, nu_bin, den = 1.0;
    unsigned n, l, hop = nfft / 2u;
    for (n = 0; n < nfft; n++) {
        w[n] = 0.54 - 0.46 * cos(2.0 * M_PI * (double)n / (double)nfft);
        s2 += w[n] * w[n];
    }
    for (n = 0; n + hop < nfft; n++) {
        rho += w[n] * w[n + hop];
    }
    rho /= s2;
    nu_bin = 2.0 * (double)K / (1.0 + 2.0 * rho * rho * ((double)K - 1.0) / (double)K);
    for (l = 1; l < B && l < 8u; l++) {
        double cr = 0.0, ci = 0.0, c2;
        for (n = 0; n < nfft; n++) {
            double ph = 2.0 * M_PI * (double)(l * n) / (double)nfft;
            cr += w[n] * w[n] * cos(ph);
            ci += w[n] * w[n] * sin(ph);
        }
        c2 = (cr * cr + ci * ci) / (s2 * s2);
        den += 2.0 * (1.0 - (double)l / (double)B) * c2;
    }
    return (double)B * nu_bin / den;
}

long sg_acc_finish(sg_acc_t *a, int ch, sg_plist_t *pl, double *vals, size_t cap)
{
    size_t i, cnt = 0;
    sg_point_t p;
    const double fs = a->cfg.rate_hz;
    if (a->allan != NULL) {
        size_t na = fnav_allan_count(a->allan);
        for (i = 0; i < na; i++) {
            fnav_allan_result_t r;
            double av;
            if (fnav_allan_get(a->allan, i, &r) != FNAV_OK || r.terms < 2u) {
                continue;
            }
            if (cnt >= cap) {
                return -1;
            }
            av = (double)r.avar;
            vals[cnt++] = (av > 0.0 && isfinite(av)) ? log(av) : -700.0;
            if (pl != NULL) {
                memset(&p, 0, sizeof p);
                p.dom = SG_ALLAN;
                p.ch = ch;
                p.x = p.x_lo = p.x_hi = (double)r.tau / fs;
                p.m = r.tau;
                p.lag = r.lag;
                p.n_phase = r.n_phase;
                p.w = (double)r.terms;
                p.nblk = 1;
                if (sg_plist_add(pl, &p) != 0) {
                    return -1;
                }
            }
        }
    }
    if (a->welch != NULL && fnav_welch_segments(a->welch) > 0u) {
        fnav_real_t psd[FNAV_WELCH_MAX_BINS];
        uint32_t nb = fnav_welch_bins(a->welch), k, K = fnav_welch_segments(a->welch);
        unsigned nfft = a->welch->cfg.nfft;
        double df = fs / (double)nfft;
        if (fnav_welch_get(a->welch, psd, FNAV_WELCH_MAX_BINS) != FNAV_OK) {
            return -1;
        }
        k = 1u;
        nb -= 1u; /* the Nyquist bin is real-valued (half the degrees of freedom): left out */
        while (k < nb) {
            int band = (int)floor((double)a->cfg.bands_per_octave * log2((double)k) + 1e-9);
            uint32_t k1 = k;
            double s = 0.0;
            while (k1 < nb && (int)floor((double)a->cfg.bands_per_octave * log2((double)k1) + 1e-9) == band) {
                s += (double)psd[k1];
                k1++;
            }
            if (cnt >= cap) {
                return -1;
            }
            s /= (double)(k1 - k);
            vals[cnt++] = s > 0.0 ? log(s) : -700.0;
            if (pl != NULL) {
                memset(&p, 0, sizeof p);
                p.dom = SG_PSD;
                p.ch = ch;
                p.x_lo = ((double)k - 0.5) * df;
                p.x_hi = ((double)k1 - 0.5) * df;
                if (p.x_hi > 0.5 * fs) {
                    p.x_hi = 0.5 * fs;
                }
                p.x = sqrt(p.x_lo * p.x_hi);
                p.m = k;
                p.lag = k1 - k;
                p.n_phase = nfft; /* PSD points: the segment length */
                p.edf = welch_band_edf(nfft, K, k1 - k);
                p.w = (double)K;
                p.nblk = 1;
                if (sg_plist_add(pl, &p) != 0) {
                    return -1;
                }
            }
            k = k1;
        }
    }
    if (a->q > 0.0 && a->lm > 0) {
        double R = (a->lc * a->lc + a->ls * a->ls) / (double)a->lm;
        if (cnt >= cap) {
            return -1;
        }
        vals[cnt++] = sg_rayleigh_z(R);
        if (pl != NULL) {
            memset(&p, 0, sizeof p);
            p.dom = SG_LATTICE;
            p.ch = ch;
            p.x = p.x_lo = p.x_hi = a->q;
            p.edf = -1.0; /* exactly N(0, 1) under the null */
            p.w = 1.0;
            p.nblk = 1;
            if (sg_plist_add(pl, &p) != 0) {
                return -1;
            }
        }
    }
    if (a->td && a->n == a->n_expect) {
        double v[SG_TIME_NKIND];
        int peak;
        int k;
        time_stats(a, v, &peak);
        for (k = 0; k < SG_TIME_NKIND; k++) {
            if (cnt >= cap) {
                return -1;
            }
            vals[cnt++] = v[k];
            if (pl != NULL) {
                memset(&p, 0, sizeof p);
                p.dom = SG_TIME;
                p.ch = ch;
                p.kind = k;
                p.x_lo = a->t0_s;
                p.x_hi = a->t0_s + (double)a->n_expect / fs;
                p.x = 0.5 * (p.x_lo + p.x_hi);
                if (k == SG_TIME_STEP) {
                    /* where the largest lag-2 difference m(i+1) - m(i-1) is:
                     * sub-blocks i-1 to i+1 (a sub-block holds samples
                     * n K / n_expect = i) */
                    const double sub_s = (double)a->n_expect / fs / (double)SG_TD_K;
                    p.t_peak_lo = a->t0_s + (double)(peak - 1) * sub_s;
                    p.t_peak_hi = a->t0_s + (double)(peak + 2) * sub_s;
                }
                p.m = (uint32_t)k;
                p.w = 1.0;
                p.nblk = 1; /* no theory: the twins' spread */
                if (sg_plist_add(pl, &p) != 0) {
                    return -1;
                }
            }
        }
    }
    return (long)cnt;
}

/* ------------------------------------------------------------ segments */

int sg_segacc_init(sg_segacc_t *a, const sg_feat_cfg_t *cfg, const sg_segs_t *s, int g, double q)
{
    int b;
    memset(a, 0, sizeof *a);
    a->nb = s->nb[g];
    for (b = 0; b < a->nb; b++) {
        if (sg_acc_init(&a->b[b], cfg, s->n[g][b], q) != 0) {
            sg_segacc_free(a);
            return -1;
        }
        a->b[b].t0_s = (double)s->start[g][b] / cfg->rate_hz;
    }
    return 0;
}

void sg_segacc_push(sg_segacc_t *a, int blk, double x)
{
    sg_acc_push(&a->b[blk], x);
}

void sg_segacc_free(sg_segacc_t *a)
{
    int b;
    for (b = 0; b < SG_MAX_BLK; b++) {
        sg_acc_free(&a->b[b]);
    }
}

long sg_segacc_finish(sg_segacc_t *a, int ch, sg_plist_t *pl, double *vals, size_t cap)
{
    sg_plist_t p0, p1;
    double *v1;
    long n0, n1, j, m;
    if (a->nb <= 1) {
        return sg_acc_finish(&a->b[0], ch, pl, vals, cap);
    }
    /* the lattice sums of the blocks add up (the step across blocks is not a difference) */
    a->b[0].lc += a->b[1].lc;
    a->b[0].ls += a->b[1].ls;
    a->b[0].lm += a->b[1].lm;
    a->b[1].q = 0.0;
    memset(&p0, 0, sizeof p0);
    memset(&p1, 0, sizeof p1);
    v1 = (double *)malloc((cap + 1) * sizeof *v1);
    if (v1 == NULL) {
        return -1;
    }
    n0 = sg_acc_finish(&a->b[0], ch, &p0, vals, cap);
    n1 = sg_acc_finish(&a->b[1], ch, &p1, v1, cap);
    if (n0 < 0 || n1 < 0) {
        free(v1);
        sg_plist_free(&p0);
        sg_plist_free(&p1);
        return -1;
    }
    /* pool point by point (the blocks are of equal length up to a sample,
     * so their grids agree; a point only one block has is dropped) */
    m = 0;
    for (j = 0; j < n0; j++) {
        sg_point_t q = p0.p[j];
        long k;
        for (k = 0; k < n1; k++) {
            if (p1.p[k].dom == q.dom && p1.p[k].m == q.m && p1.p[k].lag == q.lag) {
                break;
            }
        }
        if (q.dom == SG_LATTICE || q.dom == SG_TIME) {
            k = -2; /* already pooled (lattice), one point per block (time) */
        } else if (k >= n1) {
            continue;
        }
        if (k >= 0) {
            double w0 = q.w, w1 = p1.p[k].w, a0 = exp(vals[j]), a1 = exp(v1[k]);
            double pooled = (w0 * a0 + w1 * a1) / (w0 + w1 > 0.0 ? w0 + w1 : 1.0);
            vals[m] = pooled > 0.0 ? log(pooled) : -700.0;
            if (q.dom == SG_PSD) {
                q.edf = welch_band_edf(q.n_phase, (unsigned)(w0 + w1), q.lag);
            }
            q.w = w0 + w1;
            q.nblk = 2;
        } else {
            vals[m] = vals[j];
        }
        if (pl != NULL && sg_plist_add(pl, &q) != 0) {
            m = -1;
            break;
        }
        m++;
    }
    /* the second block's time-domain points follow the first's */
    for (j = 0; j < n1 && m >= 0; j++) {
        if (p1.p[j].dom != SG_TIME) {
            continue;
        }
        if ((size_t)m >= cap || (pl != NULL && sg_plist_add(pl, &p1.p[j]) != 0)) {
            m = -1;
            break;
        }
        vals[m++] = v1[j];
    }
    /* the level difference between the blocks */
    if (m >= 0 && a->b[0].td && a->b[1].td && a->b[0].n == a->b[0].n_expect && a->b[1].n == a->b[1].n_expect) {
        double mu[2], sx, sn;
        int b, i;
        sg_point_t q;
        for (b = 0; b < 2; b++) {
            sx = 0.0;
            sn = 0.0;
            for (i = 0; i < SG_TD_K; i++) {
                sx += a->b[b].sub[i];
                sn += (double)a->b[b].subn[i];
            }
            mu[b] = a->b[b].x0 + (sn > 0.0 ? sx / sn : 0.0);
        }
        memset(&q, 0, sizeof q);
        q.dom = SG_TIME;
        q.ch = ch;
        q.kind = SG_TIME_LEVEL;
        q.m = (uint32_t)SG_TIME_LEVEL;
        q.x_blk = (double)a->b[0].n_expect / a->b[0].cfg.rate_hz;
        q.x_lo = a->b[0].t0_s;
        q.x_hi = a->b[1].t0_s + (double)a->b[1].n_expect / a->b[1].cfg.rate_hz;
        q.x = 0.5 * (q.x_lo + q.x_hi);
        q.w = 1.0;
        q.nblk = 1; /* no theory: the twins' spread */
        if ((size_t)m >= cap || (pl != NULL && sg_plist_add(pl, &q) != 0)) {
            m = -1;
        } else {
            vals[m++] = mu[1] - mu[0];
        }
    }
    free(v1);
    sg_plist_free(&p0);
    sg_plist_free(&p1);
    return m;
}

/* ------------------------------------------------------------ lattice */

double sg_lattice_z(const double *x, size_t n, double q)
{
    double c = 0.0, s = 0.0;
    size_t k;
    if (!(q > 0.0) || n < 3) {
        return 0.0;
    }
    for (k = 1; k < n; k++) {
        double ph = 2.0 * M_PI * (x[k] - x[k - 1]) / q;
        c += cos(ph);
        s += sin(ph);
    }
    return sg_rayleigh_z((c * c + s * s) / (double)(n - 1));
}

static int cmp_dbl(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

double sg_lattice_step(const double *x, size_t n, double *z)
{
    double amax = 0.0, floor_q, q = INFINITY, *r;
    size_t k, nr = 0;
    if (z != NULL) {
        *z = 0.0;
    }
    if (n < 16) {
        return 0.0;
    }
    for (k = 0; k < n; k++) {
        double v = fabs(x[k]);
        amax = v > amax ? v : amax;
    }
    if (!isfinite(amax)) {
        return 0.0; /* an infinite value: no lattice to speak of (nor an exponent to take) */
    }
    /* 10 ulp of float32 at the largest value: finer steps are storage */
    floor_q = 10.0 * ldexp(1.0, (int)floor(log2(amax > 1e-30 ? amax : 1e-30)) - 23);
    for (k = 1; k < n; k++) {
        double d = fabs(x[k] - x[k - 1]);
        if (d > floor_q && d < q) {
            q = d;
        }
    }
    if (!isfinite(q)) {
        return 0.0;
    }
    /* refine: median of d / round(d / q) over the differences of a few steps */
    r = (double *)malloc(n * sizeof *r);
    if (r != NULL) {
        for (k = 1; k < n; k++) {
            double d = fabs(x[k] - x[k - 1]), m = floor(d / q + 0.5);
            if (m >= 1.0 && m <= 64.0 && fabs(d / q - m) < 0.05) {
                r[nr++] = d / m;
            }
        }
        if (nr > 0) {
            qsort(r, nr, sizeof *r, cmp_dbl);
            q = r[nr / 2];
        }
        free(r);
    }
    if (z != NULL) {
        *z = sg_lattice_z(x, n, q);
    }
    return q;
}

/* ------------------------------------------------------------ compare */

void sg_cmp_free(sg_cmp_t *c)
{
    free(c->z);
    free(c->twin_mean);
    free(c->twin_sd);
    free(c->sd_tot);
    free(c->dev);
    free(c->G_null);
    memset(c, 0, sizeof *c);
}

/* Variance of the log of a chi-square estimate with nu degrees of freedom
 * divided by nu: trigamma(nu / 2). */
static double logchi2_var(double nu)
{
    if (!(nu > 0.0)) {
        return 0.0;
    }
    if (nu > 1e6) {
        return 2.0 / nu;
    }
    return gsl_sf_psi_1(0.5 * nu);
}

/* Theoretical variance of each point's real estimate (0: none). For Allan
 * points the noise type comes from the local slope of the twins' mean
 * curve (the model's), the EDF from Greenhall & Riley. */
static void theory_var(const sg_plist_t *pl, const double *mean, double *vt)
{
    size_t j;
    for (j = 0; j < pl->n; j++) {
        const sg_point_t *p = &pl->p[j];
        vt[j] = 0.0;
        if (p->dom == SG_ALLAN) {
            /* slope of log ADEV = half the slope of ln AVAR over ln tau */
            size_t a = j, b = j;
            double sl, nu;
            fnav_allan_noise_t type;
            if (j > 0 && pl->p[j - 1].dom == SG_ALLAN && pl->p[j - 1].ch == p->ch) {
                a = j - 1;
            }
            if (j + 1 < pl->n && pl->p[j + 1].dom == SG_ALLAN && pl->p[j + 1].ch == p->ch) {
                b = j + 1;
            }
            if (a == b) {
                vt[j] = 0.0;
                continue;
            }
            sl = 0.5 * (mean[b] - mean[a]) / log(pl->p[b].x / pl->p[a].x);
            type = fnav_allan_noise_from_slope((fnav_real_t)sl);
            if (type == FNAV_ALLAN_NOISE_RAMP) {
                type = FNAV_ALLAN_NOISE_RRW;
            }
            nu = fnav_allan_edf(fnav_allan_noise_alpha(type), p->lag, p->n_phase, 1);
            vt[j] = logchi2_var(nu * (double)(p->nblk > 1 ? p->nblk : 1));
        } else if (p->edf < 0.0) {
            vt[j] = 1.0;
        } else if (p->edf > 0.0) {
            vt[j] = logchi2_var(p->edf);
        }
    }
}

/* Solve the k x k symmetric positive definite system A x = b in place
 * (Cholesky); -1 when not positive definite. */
static int chol_solve(int k, double *A, double *b)
{
    int i, j, m;
    for (j = 0; j < k; j++) {
        double d = A[j * k + j];
        for (m = 0; m < j; m++) {
            d -= A[j * k + m] * A[j * k + m];
        }
        if (!(d > 0.0)) {
            return -1;
        }
        A[j * k + j] = sqrt(d);
        for (i = j + 1; i < k; i++) {
            double v = A[i * k + j];
            for (m = 0; m < j; m++) {
                v -= A[i * k + m] * A[j * k + m];
            }
            A[i * k + j] = v / A[j * k + j];
        }
    }
    for (i = 0; i < k; i++) {
        double v = b[i];
        for (m = 0; m < i; m++) {
            v -= A[i * k + m] * b[m];
        }
        b[i] = v / A[i * k + i];
    }
    for (i = k - 1; i >= 0; i--) {
        double v = b[i];
        for (m = i + 1; m < k; m++) {
            v -= A[m * k + i] * b[m];
        }
        b[i] = v / A[i * k + i];
    }
    return 0;
}

/* Points that enter the gap statistics: all but the level of a two-block
 * segment, which is fit data for the drifts only (section 4 of
 * docs/simgap.md: a drift extrapolated from the middle to the ends carries
 * a parameter uncertainty on the level that the low-rank correction
 * absorbs without charging its determinant, so as a test point it let a
 * ramp fitted to noise win the likelihood ratio on a control). */
static int gap_point(const sg_point_t *p)
{
    return !(p->dom == SG_TIME && p->kind == SG_TIME_LEVEL) && !p->empty;
}

/* The normal score of a Student t statistic with df degrees of freedom:
 * Phi^-1 of its tail probability, sign kept; beyond the double range of
 * the tail (|t| past about 1e21 for df 15) the t itself, already far past
 * any critical value. */
static double t_to_normal(double t, double df)
{
    double q = gsl_cdf_tdist_Q(fabs(t), df), zn;
    if (!(q > 0.0) || !isfinite(t)) {
        return t;
    }
    zn = gsl_cdf_ugaussian_Qinv(q);
    return t < 0.0 ? -zn : zn;
}

/* z of every point of `real` against the twin rows `rows` (nr of them),
 * and the aggregate. The fitted model's parameter uncertainty is a
 * low-rank covariance U U^T, U = the S refit shifts / sqrt(S - 1): the
 * deviation d is first explained as far as that uncertainty allows,
 * a = argmin sum_j (d_j - (U a)_j)^2 / D_j + |a|^2 (D the noise variance),
 * and the z-scores are the residuals r_j / sqrt(D_j): the Mahalanobis form
 * d^T (D + U U^T)^-1 d = |r|^2_D + |a|^2 (Woodbury). Without shifts the
 * diagonal vx is added to D instead. */
static double zscores(const sg_plist_t *pl, const double *real, const double *twin, const int *rows, int nr,
                      const double *vx, const double *shift, int S, double *z, double *mean_out, double *sd_out,
                      double *sdt_out, double *dev_out, double *G_dom, double *maxz, int *imax, double *lnD_out)
{
    size_t j, n = pl->n;
    double gsum[SG_NDOM], lsum[SG_NDOM], G = 0.0, L = 0.0;
    long gcnt[SG_NDOM];
    int d, nd = 0, r, k = (shift != NULL && S >= 2) ? S : 0, a, b;
    double pen = 0.0;
    double *vt = NULL, *mean = NULL, *D = NULL, *dev = NULL, *M = NULL, *rhs = NULL;
    double res = (double)NAN; /* NaN: out of memory */
    memset(gsum, 0, sizeof gsum);
    memset(lsum, 0, sizeof lsum);
    memset(gcnt, 0, sizeof gcnt);
    mean = (double *)malloc((n + 1) * sizeof *mean);
    vt = (double *)malloc((n + 1) * sizeof *vt);
    D = (double *)malloc((n + 1) * sizeof *D);
    dev = (double *)malloc((n + 1) * sizeof *dev);
    M = (double *)malloc(((size_t)k * (size_t)k + 1) * sizeof *M);
    rhs = (double *)malloc(((size_t)k + 1) * sizeof *rhs);
    if (mean == NULL || vt == NULL || D == NULL || dev == NULL || M == NULL || rhs == NULL) {
        goto done;
    }
    for (j = 0; j < n; j++) {
        double s = 0.0;
        for (r = 0; r < nr; r++) {
            s += twin[(size_t)rows[r] * n + j];
        }
        mean[j] = s / (double)nr;
    }
    theory_var(pl, mean, vt);
    for (j = 0; j < n; j++) {
        double v = 0.0, var, dd;
        for (r = 0; r < nr; r++) {
            dd = twin[(size_t)rows[r] * n + j] - mean[j];
            v += dd * dd;
        }
        v = nr > 1 ? v / (double)(nr - 1) : 0.0;
        if (vt[j] > 0.0) {
            var = v / (double)nr + (vt[j] > v ? vt[j] : v);
        } else {
            var = v * (1.0 + 1.0 / (double)nr);
        }
        if (k == 0 && vx != NULL && vx[j] > 0.0) {
            var += vx[j]; /* the fitted parameters' own uncertainty, diagonal */
        }
        if (!(var > 1e-24)) {
            var = 1e-24;
        }
        D[j] = var;
        dev[j] = real[j] - mean[j];
        if (!gap_point(&pl->p[j])) {
            D[j] = INFINITY; /* no weight anywhere: z = 0, outside G and the ln D sum */
            dev[j] = 0.0;
            var = INFINITY;
        }
        if (mean_out != NULL) {
            mean_out[j] = mean[j];
            sd_out[j] = sqrt(v);
            sdt_out[j] = sqrt(var);
        }
    }
    if (k > 0) {
        /* (U^T D^-1 U + I) a = U^T D^-1 d */
        const double su = 1.0 / sqrt((double)(S - 1));
        for (a = 0; a < k; a++) {
            double sb = 0.0;
            for (j = 0; j < n; j++) {
                sb += shift[(size_t)a * n + j] * su * dev[j] / D[j];
            }
            rhs[a] = sb;
            for (b = 0; b <= a; b++) {
                double sm = 0.0;
                for (j = 0; j < n; j++) {
                    sm += shift[(size_t)a * n + j] * shift[(size_t)b * n + j] * su * su / D[j];
                }
                M[a * k + b] = M[b * k + a] = sm + (a == b ? 1.0 : 0.0);
            }
        }
        if (chol_solve(k, M, rhs) == 0) {
            for (a = 0; a < k; a++) {
                pen += rhs[a] * rhs[a];
            }
            for (j = 0; j < n; j++) {
                double u = 0.0;
                for (a = 0; a < k; a++) {
                    u += shift[(size_t)a * n + j] * su * rhs[a];
                }
                dev[j] -= u;
            }
        }
    }
    if (maxz != NULL) {
        *maxz = 0.0;
        *imax = -1;
    }
    for (j = 0; j < n; j++) {
        double zz = dev[j] / sqrt(D[j]);
        if (dev_out != NULL) {
            dev_out[j] = dev[j]; /* the residual behind z: its sign is z's */
        }
        if (!(vt[j] > 0.0) && nr >= 2) {
            /* a variance from the twins alone: the deviation over its
             * estimate is Student's t with nr - 1 degrees of freedom, not
             * normal, so it is mapped to the normal score of the same tail
             * probability (with 16 twins a t of 4.14, the normal quantile
             * of the Bonferroni level, has a tail 25 times the normal's).
             * Two twins are one degree of freedom: the null of S = 3
             * (each twin against the other two) needs it as the real
             * needs two; with nr >= 3 that null would keep its raw t_1
             * squares, a mean G near 50 (test_simgap
             * test_compare_null_three_twins) */
            zz = t_to_normal(zz, (double)(nr - 1));
        }
        if (z != NULL) {
            z[j] = zz;
        }
        if (!gap_point(&pl->p[j])) {
            continue;
        }
        d = pl->p[j].dom;
        gsum[d] += zz * zz < SG_ZCAP * SG_ZCAP ? zz * zz : SG_ZCAP * SG_ZCAP;
        if (lnD_out != NULL) {
            lsum[d] += log(D[j]);
        }
        gcnt[d]++;
        if (maxz != NULL && fabs(zz) > *maxz) {
            *maxz = fabs(zz);
            *imax = (int)j;
        }
    }
    for (d = 0; d < SG_NDOM; d++) {
        if (G_dom != NULL) {
            G_dom[d] = gcnt[d] > 0 ? gsum[d] / (double)gcnt[d] : (double)NAN;
        }
        if (gcnt[d] > 0) {
            G += gsum[d] / (double)gcnt[d];
            L += lsum[d] / (double)gcnt[d];
            nd++;
        }
    }
    if (lnD_out != NULL) {
        *lnD_out = nd > 0 ? L / (double)nd : 0.0;
    }
    /* |a|^2: how far the parameters had to move, on the scale of one point */
    res = nd > 0 ? G / (double)nd + pen / (double)(n > 0 ? n : 1) : 0.0;
done:
    free(mean);
    free(vt);
    free(D);
    free(dev);
    free(M);
    free(rhs);
    return res;
}

/* Variance of G = sum_j w_j z_j^2 (w_j = 1 / (domains x points of its
 * domain)) for Gaussian z of unit variance with correlation R:
 * 2 sum_ij w_i w_j R_ij^2. R is estimated from the S pseudo-reals (rows of
 * dev, deviations from their mean); r^2 is corrected for its small-sample
 * bias by inverting E[r^2] ~ 1/(S - 1) + rho^2 (1 - 1/(S - 1)), the chord
 * through the exact values at rho = 0 and 1. Between them the exact E[r^2]
 * (Pearson r of S normal pairs, a 2F1 series) lies below the chord, so rho^2
 * comes out low: 0.467 for 0.5 and 0.274 for 0.3 at S = 16
 * (scipy.special.hyp2f1). The chord is kept: the exact inversion would move
 * G_crit where this variance exceeds the null's own, and the committed
 * results. The first-order form rho^2 + (1 - rho^2)^2 / (S - 1) is not
 * what is inverted. */
static double g_corr_var(const sg_plist_t *pl, const double *dev, int S)
{
    size_t n = pl->n, i, j;
    long cnt[SG_NDOM];
    int d, nd = 0, s;
    double *w, *sd, v = 0.0;
    memset(cnt, 0, sizeof cnt);
    for (j = 0; j < n; j++) {
        cnt[pl->p[j].dom] += gap_point(&pl->p[j]);
    }
    for (d = 0; d < SG_NDOM; d++) {
        nd += cnt[d] > 0;
    }
    w = (double *)malloc((n + 1) * sizeof *w);
    sd = (double *)malloc((n + 1) * sizeof *sd);
    if (w == NULL || sd == NULL || nd == 0 || S < 4) {
        free(w);
        free(sd);
        return 0.0;
    }
    for (j = 0; j < n; j++) {
        double q = 0.0;
        w[j] = gap_point(&pl->p[j]) ? 1.0 / ((double)nd * (double)cnt[pl->p[j].dom]) : 0.0;
        for (s = 0; s < S; s++) {
            q += dev[(size_t)s * n + j] * dev[(size_t)s * n + j];
        }
        sd[j] = sqrt(q / (double)(S - 1));
    }
    for (i = 0; i < n; i++) {
        v += w[i] * w[i];
        for (j = i + 1; j < n; j++) {
            double r = 0.0, r2;
            if (!(sd[i] > 0.0) || !(sd[j] > 0.0)) {
                continue;
            }
            for (s = 0; s < S; s++) {
                r += dev[(size_t)s * n + i] * dev[(size_t)s * n + j];
            }
            r /= (double)(S - 1) * sd[i] * sd[j];
            r2 = r * r;
            /* rho^2 ~ (r^2 - 1/(S-1)) / (1 - 1/(S-1)), clipped to [0, 1] */
            r2 = (r2 - 1.0 / (double)(S - 1)) / (1.0 - 1.0 / (double)(S - 1));
            r2 = r2 < 0.0 ? 0.0 : (r2 > 1.0 ? 1.0 : r2);
            v += 2.0 * w[i] * w[j] * r2;
        }
    }
    free(w);
    free(sd);
    return 2.0 * v;
}

int sg_compare(const sg_plist_t *pl, const double *real, const double *twin, int S, const double *vx,
               const double *shift, double alpha, sg_cmp_t *out)
{
    size_t n = pl->n, j;
    int s, r, *rows = NULL;
    double *pseudo = NULL;
    double sum = 0.0, sum2 = 0.0, var, k;
    memset(out, 0, sizeof *out);
    out->n = n;
    out->S = S;
    out->z = (double *)calloc(n + 1, sizeof(double));
    out->twin_mean = (double *)calloc(n + 1, sizeof(double));
    out->twin_sd = (double *)calloc(n + 1, sizeof(double));
    out->sd_tot = (double *)calloc(n + 1, sizeof(double));
    out->dev = (double *)calloc(n + 1, sizeof(double));
    out->G_null = (double *)calloc((size_t)S + 1, sizeof(double));
    rows = (int *)malloc(((size_t)S + 1) * sizeof *rows);
    pseudo = (double *)malloc((n + 1) * sizeof *pseudo);
    if (out->z == NULL || out->twin_mean == NULL || out->twin_sd == NULL || out->sd_tot == NULL || out->dev == NULL ||
        out->G_null == NULL || rows == NULL || pseudo == NULL || S < 2) {
        free(rows);
        free(pseudo);
        sg_cmp_free(out);
        return -1;
    }
    for (s = 0; s < S; s++) {
        rows[s] = s;
    }
    out->G = zscores(pl, real, twin, rows, S, vx, shift, S, out->z, out->twin_mean, out->twin_sd, out->sd_tot, out->dev, out->G_dom,
                     &out->maxz, &out->imax, NULL);
    /* null: each twin in turn as the real, the others as twins; the twin
     * taken as real carries the error of a model refitted to it (shift), as
     * the real carries the error of the model fitted to it */
    for (s = 0; s < S && S >= 3; s++) {
        int m = 0;
        for (r = 0; r < S; r++) {
            if (r != s) {
                rows[m++] = r;
            }
        }
        for (j = 0; j < n; j++) {
            pseudo[j] = twin[(size_t)s * n + j] - (shift != NULL ? shift[(size_t)s * n + j] : 0.0);
        }
        out->G_null[s] = zscores(pl, pseudo, twin, rows, m, vx, shift, S, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL);
        sum += out->G_null[s];
        sum2 += out->G_null[s] * out->G_null[s];
    }
    free(rows);
    if (S >= 3) {
        double vc;
        double *dev = (double *)malloc(((size_t)S * n + 1) * sizeof *dev);
        out->null_mean = sum / (double)S;
        var = (sum2 - sum * sum / (double)S) / (double)(S - 1);
        if (dev != NULL) {
            /* deviations of the pseudo-reals from their mean, in units of
             * the z denominators (their correlation decides G's spread) */
            for (j = 0; j < n; j++) {
                double m = 0.0;
                for (s = 0; s < S; s++) {
                    pseudo[j] = twin[(size_t)s * n + j] - (shift != NULL ? shift[(size_t)s * n + j] : 0.0);
                    dev[(size_t)s * n + j] = pseudo[j];
                    m += pseudo[j];
                }
                m /= (double)S;
                for (s = 0; s < S; s++) {
                    dev[(size_t)s * n + j] = (dev[(size_t)s * n + j] - m) / out->sd_tot[j];
                }
            }
            vc = g_corr_var(pl, dev, S) * out->null_mean * out->null_mean;
            if (vc > var) {
                var = vc;
            }
            free(dev);
        }
    } else {
        out->null_mean = 1.0;
        var = 0.0;
    }
    free(pseudo);
    if (!(var > 0.0)) {
        var = 1.0;
    }
    out->null_sd = sqrt(var);
    out->z_crit = gsl_cdf_ugaussian_Qinv(0.5 * alpha / (double)(n > 0 ? n : 1));
    /* scaled chi-square with the null's mean and variance. It needs a null
     * with a positive, finite mean: no point to compare, twins that do not
     * vary (every null G 0: a noise-free model) or a statistic that is not
     * finite leave nothing to test against: no critical value, nothing
     * significant, and `undefined` says why (the caller decides) */
    k = 2.0 * out->null_mean * out->null_mean / var;
    if (!(k > 0.0) || !isfinite(k)) {
        size_t npts = 0;
        for (j = 0; j < n; j++) {
            npts += gap_point(&pl->p[j]) ? 1u : 0u;
        }
        if (npts == 0) {
            out->undefined = SG_CMP_EMPTY;
        } else if (out->null_mean == 0.0 && isfinite(var)) {
            out->undefined = SG_CMP_FLAT;
        } else {
            out->undefined = SG_CMP_NONFINITE;
        }
        out->G_crit = (double)NAN;
        out->significant = 0;
        return 0;
    }
    out->G_crit = out->null_mean * hx_chi2_quantile(k, 1.0 - alpha) / k;
    if (!isfinite(out->G_crit)) {
        out->undefined = SG_CMP_NONFINITE;
        out->significant = 0;
        return 0;
    }
    out->significant = (out->G > out->G_crit) || (out->maxz > out->z_crit);
    return 0;
}

const char *sg_cmp_why(const sg_cmp_t *c)
{
    switch (c->undefined) {
    case SG_CMP_EMPTY:
        return "the segment has no point to compare (too short)";
    case SG_CMP_FLAT:
        return "the twins do not vary (no noise in the model: a noise-free log?), so the gap has no null "
               "distribution to be tested against";
    case SG_CMP_NONFINITE:
        return "a statistic of the twins is not finite (values out of any sensor's range?), so the gap cannot "
               "be tested";
    default:
        return "";
    }
}

double sg_gap_resampled(const sg_plist_t *pl, const double *real, const double *twin, int S, const int *idx, int S2,
                        const double *vx, const double *shift)
{
    return zscores(pl, real, twin, idx, S2, vx, shift, S, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL);
}

/* The Gaussian deviance of a real (or pseudo-real) against twin rows: G plus
 * the mean ln of the z denominators, with G's weights (domains equal). */
static double deviance(const sg_plist_t *pl, const double *real, const double *twin, const int *rows, int nr,
                       const double *vx, const double *shift, int S)
{
    double lnD = 0.0;
    double G = zscores(pl, real, twin, rows, nr, vx, shift, S, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, &lnD);
    return G + lnD;
}

double sg_lr_test(const sg_plist_t *pl, const double *real, const double *ta, const double *va, const double *sa,
                  const double *tb, const double *vb, const double *sb, int S, double *drop)
{
    size_t n = pl->n, j;
    int s, r, m;
    int *rows = (int *)malloc(((size_t)S + 1) * sizeof *rows);
    double *pseudo = (double *)malloc((n + 1) * sizeof *pseudo);
    double sum = 0.0, sum2 = 0.0, mean, sd, Dr;
    if (drop != NULL) {
        *drop = 0.0;
    }
    if (rows == NULL || pseudo == NULL || S < 4) {
        free(rows);
        free(pseudo);
        return 0.0;
    }
    for (r = 0; r < S; r++) {
        rows[r] = r;
    }
    Dr = deviance(pl, real, ta, rows, S, va, sa, S) - deviance(pl, real, tb, rows, S, vb, sb, S);
    if (drop != NULL) {
        *drop = Dr;
    }
    for (s = 0; s < S; s++) {
        double D;
        /* twin s of a as the real (as in the null of sg_compare), against
         * the other twins of a and of b (b's paired seed shares its noise) */
        for (m = 0, r = 0; r < S; r++) {
            if (r != s) {
                rows[m++] = r;
            }
        }
        for (j = 0; j < n; j++) {
            pseudo[j] = ta[(size_t)s * n + j] - (sa != NULL ? sa[(size_t)s * n + j] : 0.0);
        }
        D = deviance(pl, pseudo, ta, rows, m, va, sa, S) - deviance(pl, pseudo, tb, rows, m, vb, sb, S);
        sum += D;
        sum2 += D * D;
    }
    free(rows);
    free(pseudo);
    mean = sum / (double)S;
    sd = sqrt((sum2 - sum * sum / (double)S) / (double)(S - 1));
    /* a floor at a hundredth of a point's z^2 keeps a candidate that
     * changes nothing from dividing by zero */
    if (!(sd > 1e-2)) {
        sd = 1e-2;
    }
    /* a new draw against the mean and sd of S: the t(S - 1) statistic needs
     * sqrt(1 + 1/S) (as sg_score_test) */
    return (Dr - mean) / (sd * sqrt(1.0 + 1.0 / (double)S));
}
