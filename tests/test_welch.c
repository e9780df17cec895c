/* Tests of the streaming Welch PSD and the bandwidth rule (src/fnav_welch.c)
 * against scipy.signal.welch vectors (vectors/welch/gen_welch.py), the last
 * segment's spectrum with the global-mean detrending against
 * scipy.signal.periodogram, and analytic cases. */
#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "footnav/fnav_welch.h"
#include "support/fnav_testdata.h"

/* The bandwidth's tolerance against the numpy implementation of the rule. */
#if FNAV_USE_DOUBLE
#define BAND_REL 1e-9
#else
#define BAND_REL 1e-4
#endif

static size_t read_series(const char *rel, double *x, size_t max)
{
    char path[512], line[128];
    FILE *f;
    size_t n = 0;
    if (fnav_vector_path(rel, path, sizeof path) != 0 || (f = fopen(path, "r")) == NULL) {
        return 0;
    }
    while (fgets(line, sizeof line, f) != NULL && n < max) {
        if (line[0] != '#') {
            x[n++] = strtod(line, NULL);
        }
    }
    fclose(f);
    return n;
}

typedef struct {
    char name[64], input[16], window[16], detrend[16], scaling[16];
    double fs;
    unsigned nfft, overlap, nbins;
    int sym;
} vcase_t;

static int parse_case(const char *line, vcase_t *c)
{
    return sscanf(line, "case,%63[^,],%15[^,],%lf,%u,%u,%15[^,],%d,%15[^,],%15[^,],%u", c->name, c->input, &c->fs,
                  &c->nfft, &c->overlap, c->window, &c->sym, c->detrend, c->scaling, &c->nbins) == 10;
}

static void config_of(const vcase_t *c, fnav_welch_config_t *cfg)
{
    *cfg = fnav_welch_config_default;
    cfg->nfft = c->nfft;
    cfg->overlap = c->overlap;
    cfg->window = strcmp(c->window, "hamming") == 0 ? FNAV_WINDOW_HAMMING
                  : strcmp(c->window, "hann") == 0  ? FNAV_WINDOW_HANN
                                                    : FNAV_WINDOW_RECT;
    cfg->symmetric = c->sym;
    cfg->detrend = strcmp(c->detrend, "none") == 0       ? FNAV_DETREND_NONE
                   : strcmp(c->detrend, "constant") == 0 ? FNAV_DETREND_CONSTANT
                   : strcmp(c->detrend, "global") == 0   ? FNAV_DETREND_GLOBAL
                                                         : FNAV_DETREND_LINEAR;
    cfg->scaling = strcmp(c->scaling, "density") == 0 ? FNAV_SCALING_DENSITY : FNAV_SCALING_SPECTRUM;
    cfg->rate_hz = (fnav_real_t)c->fs;
}

/* The two input series of the vectors (read once), and a case's input. */
static double g_synth[6000], g_os820[9000];
static size_t g_nsyn, g_nos;

static void load_inputs(void)
{
    if (g_nsyn == 0u) {
        g_nsyn = read_series("welch/welch_input_synth.txt", g_synth, 6000);
        g_nos = read_series("welch/welch_input_os820.txt", g_os820, 9000);
    }
    assert_int_equal(g_nsyn, 5000);
    assert_int_equal(g_nos, 8192);
}

/* A vector file of vectors/, opened for reading. */
static FILE *open_vector(const char *rel)
{
    char path[512];
    FILE *f;
    assert_int_equal(fnav_vector_path(rel, path, sizeof path), 0);
    f = fopen(path, "r");
    assert_non_null(f);
    return f;
}

/* Push case c's input through w (its segment count and bins checked) and
 * read the average (fnav_welch_get) or, with last, the last segment's
 * periodogram (fnav_welch_last) into psd. */
static void run_case(fnav_welch_t *w, const vcase_t *c, int last, fnav_real_t *psd)
{
    fnav_welch_config_t cfg;
    const int syn = strcmp(c->input, "synth") == 0;
    const double *x = syn ? g_synth : g_os820;
    const size_t n = syn ? g_nsyn : g_nos;
    size_t i;
    config_of(c, &cfg);
    assert_int_equal(fnav_welch_init(w, &cfg), FNAV_OK);
    for (i = 0; i < n; i++) {
        assert_int_equal(fnav_welch_push(w, (fnav_real_t)x[i]), FNAV_OK);
    }
    assert_int_equal(fnav_welch_segments(w), (n - c->nfft) / (c->nfft - c->overlap) + 1u);
    assert_int_equal(fnav_welch_bins(w), c->nbins);
    if (last) {
        assert_int_equal(fnav_welch_last(w, psd, FNAV_WELCH_MAX_BINS), FNAV_OK);
    } else {
        assert_int_equal(fnav_welch_get(w, psd, FNAV_WELCH_MAX_BINS), FNAV_OK);
    }
}

/* Per-bin tolerance against scipy, derived (not measured). Model: every
 * rounding of the float path (the input's to fnav_real_t included) is an
 * independent, mean-zero error of at most u = FNAV_REAL_EPSILON / 2 of the
 * value rounded (the probabilistic model of Higham and Mary, SIAM J. Sci.
 * Comput. 41, 2019), first order in u. One segment's bin X_k (complex,
 * unscaled) then errs by a sum of such terms, each reaching X_k with a
 * coefficient of modulus at most 1 (2 where one FFT value feeds X_k through
 * both Z_k and Z_{m-k}); Hoeffding bounds each of its two parts by
 * lambda sqrt(sum b^2) except with probability 2 exp(-lambda^2 / 2):
 *  - before the FFT, per sample i (b_i = u w_i times the magnitudes rounded):
 *    the input |x_i|, x_i - x_0 (constant, linear; x_i - first sample for
 *    GLOBAL), the detrended value twice (the subtraction, the product with
 *    w_i), and for linear |b i| and |a + b i|; the detrending projects the
 *    input's and x - x_0's errors onto a constant (and a line): those
 *    reach X_k through W_k = sum w_i e^(-2 pi i k i / n) (and V_k = the
 *    same of (i - c) w_i), computed here in double;
 *  - the FFT: the radix-2 DIT of fnav_fft (bit reversal, m = n/2 complex
 *    points, then the real split) is replayed in double; each butterfly
 *    output errs by at most (sqrt2 gamma_2 + mu + sqrt2 u)(|a| + |b|) of its
 *    inputs a, b (mu: the twiddle table's largest error, measured here from
 *    the table), the first stage's by sqrt2 u (|a| + |b|), the split's
 *    X_k by (2 sqrt2 u + (sqrt2 gamma_2 + mu) / 2)(|Z_k| + |Z_{m-k}|);
 *    an error at stage s reaches Z_k for every k = its position mod 2^s.
 * Worst-case (not random) terms added to that: the window's own error
 * sum |w^_i - w_i| |d_i| (from fnav_welch_t's window against the double
 * one); the mean's and slope's recursive sums, u sum |partial sums| / n
 * (and / (n (n^2 - 1) / 12) with the product's u), which shift the whole
 * segment by a constant (a line) and reach X_k through |W_k| (|V_k|); for
 * GLOBAL the record mean's error (Kahan, (2u + 2 N u^2) mean |x - shift|
 * plus the division's u |mu|) through |W_k|, k <= 1.
 * Over K segments, with delta_j the bound of segment j, the average
 * (1/K) sum |X_j + e_j|^2 - |X_j|^2 is within 2 sqrt(mean |X|^2)
 * sqrt(mean delta^2) + mean delta^2 (Cauchy-Schwarz), mean |X|^2 being the
 * reference bin over its scale. The rest is relative to the bin: |X|^2
 * (3 u), the compensated sum (2u + 2 K u^2), a - c, 1/K and the product
 * (3 u), the scale 1/(fs s2) or 1/s1^2 (3 u; its s2, s1 from the float
 * window: their own deviation from the double window's, computed), the last
 * product (u): 12 u + 2 K u^2 + the scale's deviation. GLOBAL's global_fix
 * adds 9 u (sum |X_k|^2 + 2 |mu| |W_k| |sum X_k| + K mu^2 |W_k|^2) over K
 * (three products, two sums, the sums' Kahan 2u) at bins 0 and 1;
 * fnav_welch_last's r - mu s1 adds u (|X_k| + 2 |mu W_k|) to delta there.
 * lambda = 7: each (segment, bin) fails with probability under 4.6e-11,
 * under 1e-4 over the about 1.2e6 of this file. scipy's own error has the
 * same form in double (pocketfft, exact input): the double build allows
 * twice its bound, the float build 1 + 2^-29 times. */
#define BOUND_LAMBDA 7.0

typedef struct {
    const double *x;       /* the record */
    size_t nx;
    const fnav_welch_t *w; /* the estimator that ran it (window, shift, table) */
    int last;              /* fnav_welch_last: the last segment only */
} bound_in_t;

/* one segment's per-bin bound delta_k (unscaled X units) into d[k]; for
 * GLOBAL its raw X_0, X_1 (about shift) into xr[], xi[] */
static void segment_bound(const bound_in_t *b, size_t start, const double *win, const double *wk, const double *vk,
                          double mu_tw, double dmu, double gmu, double *d, double *xr, double *xi)
{
    static double zr[FNAV_WELCH_MAX_NFFT / 2], zi[FNAV_WELCH_MAX_NFFT / 2], es[FNAV_WELCH_MAX_NFFT / 2];
    static double g[FNAV_WELCH_MAX_NFFT / 2], dv[FNAV_WELCH_MAX_NFFT];
    const fnav_welch_config_t *c = &b->w->cfg;
    const double u = (double)FNAV_REAL_EPSILON / 2.0, s2u = sqrt(2.0) * u;
    const double eta_mul = sqrt(2.0) * 2.0 * u / (1.0 - 2.0 * u) + mu_tw;
    const uint32_t n = c->nfft, m = n / 2u;
    const double *x = b->x + start;
    const double cc = 0.5 * (double)(n - 1u), sii = (double)n * ((double)n * n - 1.0) / 12.0;
    double x0 = x[0], mean = 0.0, slope = 0.0, sumb2 = 0.0, proj_c = 0.0, proj_l = 0.0, winerr = 0.0;
    double ps = 0.0, pss = 0.0, ea = 0.0, eb = 0.0;
    uint32_t i, k, len;
    const int lin = c->detrend == FNAV_DETREND_LINEAR, cst = c->detrend == FNAV_DETREND_CONSTANT || lin;
    const int glob = c->detrend == FNAV_DETREND_GLOBAL;
    if (cst) {
        double sxy = 0.0;
        for (i = 0; i < n; i++) {
            const double v = x[i] - x0;
            mean += v;
            sxy += ((double)i - cc) * v;
            ps += fabs(mean);                   /* the float sum's partial sums */
            pss += fabs(sxy) + fabs(((double)i - cc) * v);
        }
        mean /= (double)n;
        ea = u * ps / (double)n + u * fabs(mean);
        if (lin) {
            slope = sxy / sii;
            eb = u * pss / sii + 2.0 * u * fabs(slope);
            ea += u * (fabs(mean) + 2.0 * fabs(slope * cc)) + eb * cc;
            mean -= slope * cc;
        }
    } else if (glob) {
        x0 = (double)b->w->shift; /* the values the ring holds are x - shift */
    } else {
        x0 = 0.0;
    }
    for (i = 0; i < n; i++) {
        const double line = cst ? mean + slope * (double)i : 0.0;
        const double dd = (x[i] - x0) - line;
        double e = fabs(x[i]) + fabs(dd) * 2.0;
        if (cst) {
            e += fabs(x[i] - x[0]);
            proj_c += (fabs(x[i]) + fabs(x[i] - x[0])) * (fabs(x[i]) + fabs(x[i] - x[0]));
            proj_l += ((double)i - cc) * ((double)i - cc) * (fabs(x[i]) + fabs(x[i] - x[0])) *
                      (fabs(x[i]) + fabs(x[i] - x[0]));
        }
        if (lin) {
            e += fabs(slope * (double)i) + fabs(line);
        }
        if (glob) {
            e += fabs(x[i] - b->x[0]) + fabs(dd);
        }
        sumb2 += u * u * win[i] * win[i] * e * e;
        winerr += fabs((double)b->w->win[i] - win[i]) * fabs(dd);
        dv[i] = dd * win[i];
    }
    /* the FFT, replayed: packed, bit-reversed, stage by stage */
    for (i = 0; i < m; i++) {
        zr[i] = dv[2u * i];
        zi[i] = dv[2u * i + 1u];
        g[i] = 0.0;
    }
    {
        uint32_t j = 0;
        for (i = 1; i < m; i++) {
            uint32_t bit = m >> 1;
            for (; (j & bit) != 0u; bit >>= 1) {
                j ^= bit;
            }
            j ^= bit;
            if (i < j) {
                double t = zr[i];
                zr[i] = zr[j];
                zr[j] = t;
                t = zi[i];
                zi[i] = zi[j];
                zi[j] = t;
            }
        }
    }
    for (len = 2u; len <= m; len <<= 1) {
        const uint32_t half = len >> 1;
        const double eta = len == 2u ? s2u : eta_mul + s2u;
        for (i = 0; i < len; i++) {
            es[i] = 0.0;
        }
        for (i = 0; i < m; i += len) {
            uint32_t j;
            for (j = 0; j < half; j++) {
                const double ang = -6.283185307179586476925 * (double)j / (double)len;
                const double wr = cos(ang), wi = sin(ang);
                const double ar = zr[i + j], ai = zi[i + j], br = zr[i + j + half], bi = zi[i + j + half];
                const double tr = br * wr - bi * wi, ti = br * wi + bi * wr;
                const double bnd = eta * (sqrt(ar * ar + ai * ai) + sqrt(br * br + bi * bi));
                zr[i + j] = ar + tr;
                zi[i + j] = ai + ti;
                zr[i + j + half] = ar - tr;
                zi[i + j + half] = ai - ti;
                es[j] += bnd * bnd;
                es[j + half] += bnd * bnd;
            }
        }
        /* X_k hears Z_k and Z_{m-k}: the values at k and -k mod len */
        for (k = 0; k <= m / 2u; k++) {
            const uint32_t r1 = k & (len - 1u), r2 = (m - k) & (len - 1u);
            g[k] += (r1 == r2) ? 4.0 * es[r1] : es[r1] + es[r2];
        }
    }
    for (k = 0; k <= m; k++) {
        const uint32_t kk = k <= m / 2u ? k : m - k; /* X_k and X_{m-k} hear the same Z */
        const double zk = k == m ? sqrt(zr[0] * zr[0] + zi[0] * zi[0])
                                 : sqrt(zr[k % m] * zr[k % m] + zi[k % m] * zi[k % m]);
        const double zq = sqrt(zr[(m - k) % m] * zr[(m - k) % m] + zi[(m - k) % m] * zi[(m - k) % m]);
        const double split = (k == 0u || k == m) ? u * (zk + zq) * 2.0 : (2.0 * s2u + eta_mul / 2.0) * (zk + zq);
        const double var = sumb2 + (k == 0u || k == m ? 2.0 * g[0] : g[kk]) + split * split +
                           (cst ? u * u * wk[k] * wk[k] * proj_c / ((double)n * n) : 0.0) +
                           (lin ? u * u * vk[k] * vk[k] * proj_l / (sii * sii) : 0.0);
        d[k] = sqrt(2.0) * BOUND_LAMBDA * sqrt(var) + winerr + ea * (wk[k] + 4.0 * u * n) + eb * vk[k];
        if (glob && k <= 1u) {
            d[k] += dmu * wk[k];
        }
    }
    if (glob) {
        for (k = 0; k <= 1u; k++) {
            double r = 0.0, im = 0.0;
            for (i = 0; i < n; i++) {
                r += win[i] * (x[i] - x0) * cos(6.283185307179586476925 * (double)(k * i) / (double)n);
                im -= win[i] * (x[i] - x0) * sin(6.283185307179586476925 * (double)(k * i) / (double)n);
            }
            xr[k] = r;
            xi[k] = im;
            if (b->last) {
                d[k] += u * (sqrt(r * r + im * im) + 2.0 * fabs(gmu) * wk[k]);
            }
        }
    }
}

/* The derived tolerance of every bin of a case (see above) into tol[]. */
static void bin_tolerances(const bound_in_t *b, const double *expect, double *tol)
{
    static double win[FNAV_WELCH_MAX_NFFT], wk[FNAV_WELCH_MAX_BINS], vk[FNAV_WELCH_MAX_BINS];
    static double dk[FNAV_WELCH_MAX_BINS], dsq[FNAV_WELCH_MAX_BINS];
    const fnav_welch_config_t *c = &b->w->cfg;
    const double u = (double)FNAV_REAL_EPSILON / 2.0, tp = 6.283185307179586476925;
    const uint32_t n = c->nfft, nb = n / 2u + 1u, hop = n - c->overlap;
    const uint32_t kseg = (uint32_t)((b->nx - n) / hop + 1u);
    double s1 = 0.0, s2 = 0.0, s1f = 0.0, s2f = 0.0, mu_tw = 0.0, gmu = 0.0, dmu = 0.0, rho, t0[2] = { 0, 0 };
    double sxr[2] = { 0, 0 }, sxi[2] = { 0, 0 };
    uint32_t i, k, j, j0;
    for (i = 0; i < n; i++) {
        const double L = c->symmetric ? (double)(n - 1u) : (double)n;
        win[i] = c->window == FNAV_WINDOW_HAMMING ? 0.54 - 0.46 * cos(tp * i / L)
                 : c->window == FNAV_WINDOW_HANN  ? 0.5 - 0.5 * cos(tp * i / L)
                                                  : 1.0;
        s1 += win[i];
        s2 += win[i] * win[i];
        s1f += (double)b->w->win[i];
        s2f += (double)b->w->win[i] * (double)b->w->win[i];
    }
    for (i = 0; i < n / 2u; i++) {
        const double e = hypot((double)b->w->fft.cs[i] - cos(tp * i / n), (double)b->w->fft.sn[i] - sin(tp * i / n));
        mu_tw = e > mu_tw ? e : mu_tw;
    }
    for (k = 0; k < nb; k++) {
        double wr = 0.0, wi = 0.0, vr = 0.0, vi = 0.0;
        for (i = 0; i < n; i++) {
            const double a = tp * (double)((k * i) % n) / (double)n;
            wr += win[i] * cos(a);
            wi -= win[i] * sin(a);
            vr += ((double)i - 0.5 * (n - 1u)) * win[i] * cos(a);
            vi -= ((double)i - 0.5 * (n - 1u)) * win[i] * sin(a);
        }
        wk[k] = hypot(wr, wi);
        vk[k] = hypot(vr, vi);
        dsq[k] = 0.0;
    }
    if (c->detrend == FNAV_DETREND_GLOBAL) {
        double sa = 0.0, sd = 0.0;
        for (i = 0; i < b->nx; i++) {
            sa += b->x[i] - (double)b->w->shift;
            sd += fabs(b->x[i] - (double)b->w->shift);
        }
        gmu = sa / (double)b->nx;
        dmu = (2.0 * u + 2.0 * (double)b->nx * u * u) * sd / (double)b->nx + u * fabs(gmu);
    }
    j0 = b->last ? kseg - 1u : 0u;
    for (j = j0; j < kseg; j++) {
        double xr[2], xi[2];
        segment_bound(b, (size_t)j * hop, win, wk, vk, mu_tw, dmu, gmu, dk, xr, xi);
        for (k = 0; k < nb; k++) {
            dsq[k] += dk[k] * dk[k];
        }
        if (c->detrend == FNAV_DETREND_GLOBAL) {
            for (k = 0; k < 2u; k++) {
                t0[k] += xr[k] * xr[k] + xi[k] * xi[k];
                sxr[k] += xr[k];
                sxi[k] += xi[k];
            }
        }
    }
    {
        const double kk = (double)(kseg - j0);
        const double dev = c->scaling == FNAV_SCALING_DENSITY ? fabs(s2f / s2 - 1.0) : fabs((s1f * s1f) / (s1 * s1) - 1.0);
        rho = 12.0 * u + 2.0 * kk * u * u + dev;
        for (k = 0; k < nb; k++) {
            const double sc = (c->scaling == FNAV_SCALING_DENSITY ? 1.0 / ((double)c->rate_hz * s2) : 1.0 / (s1 * s1)) *
                              ((k == 0u || k == n / 2u) ? 1.0 : 2.0);
            const double drms = sqrt(dsq[k] / kk);
            double t = rho * expect[k] + sc * (2.0 * sqrt(expect[k] / sc) * drms + drms * drms);
            if (c->detrend == FNAV_DETREND_GLOBAL && k <= 1u && !b->last) {
                t += sc / kk * 9.0 * u *
                     (t0[k] + 2.0 * fabs(gmu) * wk[k] * hypot(sxr[k], sxi[k]) + kk * gmu * gmu * wk[k] * wk[k]);
            }
            tol[k] = t * (FNAV_USE_DOUBLE ? 2.0 : 1.0 + ldexp(1.0, -29));
        }
    }
}

/* The bound input of case c run on w. */
static bound_in_t case_bound(const vcase_t *c, const fnav_welch_t *w, int last)
{
    bound_in_t b;
    const int syn = strcmp(c->input, "synth") == 0;
    b.x = syn ? g_synth : g_os820;
    b.nx = syn ? g_nsyn : g_nos;
    b.w = w;
    b.last = last;
    return b;
}

/* Compare a case's spectrum with scipy's, bin by bin, within the derived
 * tolerance of bin_tolerances. The worst errors found, relative to the bin,
 * to the largest bin and to the bin's tolerance, are raised into worst[0..2],
 * the largest tolerance relative to its bin into worst[3]. */
static void compare_bins(const char *what, const vcase_t *c, const bound_in_t *b, const fnav_real_t *psd,
                         const double *expect, double *worst)
{
    static double tol[FNAV_WELCH_MAX_BINS];
    double peak = 0.0;
    size_t i;
    bin_tolerances(b, expect, tol);
    for (i = 0; i < c->nbins; i++) {
        peak = expect[i] > peak ? expect[i] : peak;
    }
    for (i = 0; i < c->nbins; i++) {
        const double e = fabs((double)psd[i] - expect[i]);
        if (e / expect[i] > worst[0]) {
            worst[0] = e / expect[i];
        }
        if (e / peak > worst[1]) {
            worst[1] = e / peak;
        }
        if (e / tol[i] > worst[2]) {
            worst[2] = e / tol[i];
        }
        if (tol[i] / expect[i] > worst[3]) {
            worst[3] = tol[i] / expect[i];
        }
        if (!(e <= tol[i])) {
            fprintf(stderr, "%scase %s bin %zu: %.9g vs %.9g, tolerance %.3g\n", what, c->name, i, (double)psd[i],
                    expect[i], tol[i]);
            fail();
        }
    }
}

/* A "k,value" line of the current case into expect[k]. */
static void read_bin(const char *line, const vcase_t *c, double *expect)
{
    unsigned k;
    double v;
    assert_int_equal(sscanf(line, "%u,%lf", &k, &v), 2);
    assert_true(k < c->nbins);
    expect[k] = v;
}

static void test_against_scipy(void **state)
{
    static fnav_welch_t w;
    static fnav_real_t psd[FNAV_WELCH_MAX_BINS];
    static double expect[FNAV_WELCH_MAX_BINS];
    char line[256];
    FILE *f;
    int ncases = 0, nbands = 0;
    double worst[4] = { 0.0, 0.0, 0.0, 0.0 };
    vcase_t c, cur;
    (void)state;
    load_inputs();
    f = open_vector("welch/welch_expected.csv");
    memset(&cur, 0, sizeof cur);
    while (1) {
        char *got = fgets(line, sizeof line, f);
        int is_case = got != NULL && parse_case(line, &c);
        if ((got == NULL || is_case || strncmp(line, "band,", 5) == 0) && cur.nbins > 0) {
            /* run the previous case */
            bound_in_t b;
            run_case(&w, &cur, 0, psd);
            b = case_bound(&cur, &w, 0);
            compare_bins("", &cur, &b, psd, expect, worst);
            ncases++;
            cur.nbins = 0;
        }
        if (got == NULL) {
            break;
        }
        if (is_case) {
            cur = c;
            continue;
        }
        if (strncmp(line, "band,", 5) == 0) {
            /* band,case,threshold,round,exclude_dc,bandwidth,fs_rounded: re-run that case */
            char name[64];
            double thr, rnd, bw, fsr;
            int ex;
            fnav_bandwidth_config_t bc;
            fnav_bandwidth_t out;
            vcase_t bcase;
            FILE *g;
            char l2[256];
            int found = 0;
            assert_int_equal(sscanf(line, "band,%63[^,],%lf,%lf,%d,%lf,%lf", name, &thr, &rnd, &ex, &bw, &fsr), 6);
            g = open_vector("welch/welch_expected.csv");
            while (fgets(l2, sizeof l2, g) != NULL) {
                if (parse_case(l2, &bcase) && strcmp(bcase.name, name) == 0) {
                    found = 1;
                    break;
                }
            }
            fclose(g);
            assert_true(found);
            run_case(&w, &bcase, 0, psd);
            bc.threshold = (fnav_real_t)thr;
            bc.round_hz = (fnav_real_t)rnd;
            bc.exclude_dc = ex;
            assert_int_equal(fnav_welch_bandwidth(psd, bcase.nbins, (fnav_real_t)(bcase.fs / bcase.nfft), &bc, &out,
                                                  NULL),
                             FNAV_OK);
            FNAV_ASSERT_CLOSE(out.bandwidth_hz, bw, 0.0, BAND_REL);
            FNAV_ASSERT_CLOSE(out.fs_rounded_hz, fsr, 0.0, 0.0);
            nbands++;
            continue;
        }
        if (line[0] != '#' && cur.nbins > 0) {
            read_bin(line, &cur, expect);
        }
    }
    fclose(f);
    assert_int_equal(ncases, 12);
    assert_int_equal(nbands, 6);
    fprintf(stderr, "[  INFO    ] %s build: worst per-bin error vs scipy %.2g relative to the bin, %.2g relative "
                    "to the largest bin, %.2g of the derived tolerance (at most %.2g of its bin)\n",
            FNAV_USE_DOUBLE ? "double" : "float", worst[0], worst[1], worst[2], worst[3]);
}

/* fnav_welch_last with the global-mean detrending against scipy
 * (vectors/welch/welch_last_expected.csv, gen_welch.py): after the whole
 * input is pushed, the last segment's spectrum is that of the segment less
 * the mean of every sample pushed, scipy.signal.periodogram(seg - x.mean(),
 * detrend=False). Bins 0 and 1 are the ones the mean correction changes
 * (the periodic window's DFT is zero beyond bin 1). The tolerances of
 * test_against_scipy apply: the same input rounding and offset, one
 * segment's arithmetic instead of an average of several. */
static void test_last_global_against_scipy(void **state)
{
    static fnav_welch_t w;
    static fnav_real_t psd[FNAV_WELCH_MAX_BINS];
    static double expect[FNAV_WELCH_MAX_BINS];
    char line[256];
    FILE *f;
    int ncases = 0;
    vcase_t c, cur;
    (void)state;
    load_inputs();
    f = open_vector("welch/welch_last_expected.csv");
    memset(&cur, 0, sizeof cur);
    while (1) {
        char *got = fgets(line, sizeof line, f);
        int is_case = got != NULL && parse_case(line, &c);
        if ((got == NULL || is_case) && cur.nbins > 0) {
            double worst[4] = { 0.0, 0.0, 0.0, 0.0 };
            bound_in_t b;
            assert_string_equal(cur.detrend, "global");
            run_case(&w, &cur, 1, psd);
            b = case_bound(&cur, &w, 1);
            compare_bins("last segment, ", &cur, &b, psd, expect, worst);
            fprintf(stderr, "[  INFO    ] %s build: last segment, case %s: worst bin %.2g relative, %.2g of the "
                            "derived tolerance\n",
                    FNAV_USE_DOUBLE ? "double" : "float", cur.name, worst[0], worst[2]);
            ncases++;
            cur.nbins = 0;
        }
        if (got == NULL) {
            break;
        }
        if (is_case) {
            cur = c;
            continue;
        }
        if (line[0] != '#' && cur.nbins > 0) {
            read_bin(line, &cur, expect);
        }
    }
    fclose(f);
    assert_int_equal(ncases, 3);
}

/* The mean of the per-segment spectra (fnav_welch_last) is the Welch average.
 * Rounding (u = FNAV_REAL_EPSILON / 2): each segment's power r^2 + i^2 is
 * the same rounded value in fnav_welch_last and in the running sum, which
 * scales it once more (u); the compensated sum is within 2 u of the exact
 * sum of its terms, and the average's a - c, 1 / n, product and scaling
 * round 4 times: 7 u, within 4 FNAV_REAL_EPSILON relative. The reference
 * sums in long double (seen LDBL_EPSILON / 2 for that sum). Measured 0.9
 * and 2.7 epsilon (float, double). (It was 1e-5 relative in float, 1e-12
 * in double: 80 and 4500 epsilon.) */
static void test_last_segment_average(void **state)
{
    static fnav_welch_t w;
    static fnav_real_t one[FNAV_WELCH_MAX_BINS], avg[FNAV_WELCH_MAX_BINS];
    static long double sum[FNAV_WELCH_MAX_BINS];
    fnav_welch_config_t cfg = fnav_welch_config_default;
    uint32_t k, seen = 0;
    int i;
    (void)state;
    cfg.rate_hz = FNAV_R(100.0);
    assert_int_equal(fnav_welch_init(&w, &cfg), FNAV_OK);
    assert_int_equal(fnav_welch_last(&w, one, FNAV_WELCH_MAX_BINS), FNAV_E_STATE);
    assert_int_equal(fnav_welch_get(&w, avg, FNAV_WELCH_MAX_BINS), FNAV_E_STATE);
    memset(sum, 0, sizeof sum);
    for (i = 0; i < 3000; i++) {
        assert_int_equal(fnav_welch_push(&w, (fnav_real_t)(sin(0.3 * i) + 0.01 * (i % 17))), FNAV_OK);
        if (fnav_welch_segments(&w) > seen) {
            seen = fnav_welch_segments(&w);
            assert_int_equal(fnav_welch_last(&w, one, FNAV_WELCH_MAX_BINS), FNAV_OK);
            for (k = 0; k < fnav_welch_bins(&w); k++) {
                sum[k] += (long double)one[k];
            }
        }
    }
    assert_int_equal(fnav_welch_get(&w, avg, FNAV_WELCH_MAX_BINS), FNAV_OK);
    for (k = 0; k < fnav_welch_bins(&w); k++) {
        FNAV_ASSERT_CLOSE(avg[k], (double)(sum[k] / seen), 0.0,
                          4.0 * (double)FNAV_REAL_EPSILON + 0.5 * (double)seen * (double)LDBL_EPSILON);
    }
    assert_int_equal(fnav_welch_get(&w, avg, 10), FNAV_E_SIZE);
    /* fnav_welch_last too refuses a buffer shorter than the bins, and
     * writes nothing into it; NULL is FNAV_E_ARG (make coverage: neither
     * was run) */
    one[0] = FNAV_R(-1.0);
    assert_int_equal(fnav_welch_last(&w, one, fnav_welch_bins(&w) - 1u), FNAV_E_SIZE);
    assert_true(one[0] == FNAV_R(-1.0));
    assert_int_equal(fnav_welch_last(&w, one, fnav_welch_bins(&w)), FNAV_OK);
    assert_true(one[0] >= FNAV_R(0.0));
    assert_int_equal(fnav_welch_last(NULL, one, FNAV_WELCH_MAX_BINS), FNAV_E_ARG);
    assert_int_equal(fnav_welch_last(&w, NULL, FNAV_WELCH_MAX_BINS), FNAV_E_ARG);
    assert_int_equal(fnav_welch_get(NULL, avg, FNAV_WELCH_MAX_BINS), FNAV_E_ARG);
    assert_int_equal(fnav_welch_get(&w, NULL, FNAV_WELCH_MAX_BINS), FNAV_E_ARG);
    assert_int_equal(fnav_welch_get(&w, NULL, FNAV_WELCH_MAX_BINS), FNAV_E_ARG);
}

/* Parseval: with a rectangular window and no detrending, the one-sided
 * density integrates to the mean square of the segments (analytic). */
static void test_parseval(void **state)
{
    static fnav_welch_t w;
    static fnav_real_t p[FNAV_WELCH_MAX_BINS];
    fnav_welch_config_t cfg = fnav_welch_config_default;
    double ms = 0.0, integral = 0.0;
    uint32_t k;
    int i;
    (void)state;
    cfg.window = FNAV_WINDOW_RECT;
    cfg.detrend = FNAV_DETREND_NONE;
    cfg.overlap = 0;
    cfg.nfft = 128;
    cfg.rate_hz = FNAV_R(50.0);
    assert_int_equal(fnav_welch_init(&w, &cfg), FNAV_OK);
    for (i = 0; i < 1280; i++) {
        const double v = 2.0 + cos(0.05 * i * i); /* chirp with an offset */
        ms += v * v;
        assert_int_equal(fnav_welch_push(&w, (fnav_real_t)v), FNAV_OK);
    }
    assert_int_equal(fnav_welch_get(&w, p, FNAV_WELCH_MAX_BINS), FNAV_OK);
    for (k = 0; k < fnav_welch_bins(&w); k++) {
        integral += (double)p[k] * 50.0 / 128.0;
    }
    FNAV_ASSERT_CLOSE(integral, ms / 1280.0, 0.0, FNAV_USE_DOUBLE ? 1e-12 : 1e-5);
    FNAV_ASSERT_CLOSE(fnav_welch_freq(&w, 64), 25.0, 0.0, 1e-7);
}

/* Bandwidth on spectra whose answer is known. */
static void test_bandwidth_analytic(void **state)
{
    fnav_real_t p[33], ccdf[33];
    fnav_bandwidth_t out;
    fnav_bandwidth_config_t c = fnav_bandwidth_config_default;
    const fnav_real_t df = FNAV_R(12.8125); /* 820 Hz / 64 */
    int k;
    (void)state;
    /* one tone in bin 9: 95 % of it is reached 95 % across the bin */
    for (k = 0; k < 33; k++) {
        p[k] = k == 9 ? FNAV_R(4.0) : FNAV_R(0.0);
    }
    assert_int_equal(fnav_welch_bandwidth(p, 33, df, &c, &out, ccdf), FNAV_OK);
    FNAV_ASSERT_CLOSE(out.bandwidth_hz, (9.0 - 0.5 + 0.95) * 12.8125, 0.0, 1e-6);
    FNAV_ASSERT_CLOSE(out.fs_hz, 2.0 * (9.0 - 0.5 + 0.95) * 12.8125, 0.0, 1e-6);
    FNAV_ASSERT_CLOSE(out.fs_rounded_hz, 250.0, 0.0, 0.0);
    FNAV_ASSERT_CLOSE(out.total, 4.0 * 12.8125, 0.0, 1e-6);
    FNAV_ASSERT_CLOSE(ccdf[8], 1.0, 0.0, 1e-6);
    FNAV_ASSERT_CLOSE(ccdf[9], 0.0, 1e-6, 0.0);
    /* a tone in the Nyquist bin: that bin ends at fmax (31.5 df .. 32 df),
     * so 95 % of it is reached at 31.5 df + 0.95 * df / 2. A hand-made
     * mutant giving the last bin a whole width (to 32.5 df, beyond fmax)
     * passed every suite (fails here, checked) */
    p[9] = FNAV_R(0.0);
    p[32] = FNAV_R(4.0);
    assert_int_equal(fnav_welch_bandwidth(p, 33, df, &c, &out, NULL), FNAV_OK);
    FNAV_ASSERT_CLOSE(out.bandwidth_hz, (31.5 + 0.95 * 0.5) * 12.8125, 0.0, 1e-6);
    p[32] = FNAV_R(0.0);
    /* equal tones in bins 2 and 20: the crossing is 90 % into bin 20 */
    p[9] = FNAV_R(0.0);
    p[2] = FNAV_R(1.0);
    p[20] = FNAV_R(1.0);
    assert_int_equal(fnav_welch_bandwidth(p, 33, df, &c, &out, NULL), FNAV_OK);
    FNAV_ASSERT_CLOSE(out.bandwidth_hz, (20.0 - 0.5 + 0.9) * 12.8125, 0.0, 1e-6);
    /* a huge DC bin decides the answer unless it is excluded */
    p[0] = FNAV_R(1000.0);
    assert_int_equal(fnav_welch_bandwidth(p, 33, df, &c, &out, NULL), FNAV_OK);
    assert_true(out.bandwidth_hz < df * FNAV_R(0.5));
    c.exclude_dc = 1;
    assert_int_equal(fnav_welch_bandwidth(p, 33, df, &c, &out, NULL), FNAV_OK);
    FNAV_ASSERT_CLOSE(out.bandwidth_hz, (20.0 - 0.5 + 0.9) * 12.8125, 0.0, 1e-5);
    /* errors */
    for (k = 0; k < 33; k++) {
        p[k] = FNAV_R(0.0);
    }
    assert_int_equal(fnav_welch_bandwidth(p, 33, df, &c, &out, NULL), FNAV_E_RANGE);
    c.threshold = FNAV_R(1.5);
    assert_int_equal(fnav_welch_bandwidth(p, 33, df, &c, &out, NULL), FNAV_E_ARG);
    assert_int_equal(fnav_welch_bandwidth(NULL, 33, df, NULL, &out, NULL), FNAV_E_ARG);
    /* a rounding step that is not finite: +Inf would pass a check of >= 0
     * and the rounded frequency come out NaN with FNAV_OK */
    p[5] = FNAV_R(1.0);
    c = fnav_bandwidth_config_default;
    c.round_hz = (fnav_real_t)INFINITY;
    assert_int_equal(fnav_welch_bandwidth(p, 33, df, &c, &out, NULL), FNAV_E_ARG);
    c.round_hz = (fnav_real_t)NAN;
    assert_int_equal(fnav_welch_bandwidth(p, 33, df, &c, &out, NULL), FNAV_E_ARG);
    c.round_hz = FNAV_R(50.0);
    assert_int_equal(fnav_welch_bandwidth(p, 33, df, &c, &out, NULL), FNAV_OK);
    /* rounded up to a multiple of 50 Hz; with round_hz = 0 not rounded,
     * fs itself (fnav_welch.h; make coverage: 0 was never tried) */
    {
        const double fs = (double)out.fs_hz, up = (double)out.fs_rounded_hz;
        FNAV_ASSERT_CLOSE(up, 50.0 * ceil(fs / 50.0), 1e-9, 0.0);
        assert_true(up > fs + 1.0); /* the case rounds something */
        c.round_hz = FNAV_R(0.0);
        assert_int_equal(fnav_welch_bandwidth(p, 33, df, &c, &out, NULL), FNAV_OK);
        assert_true(out.fs_rounded_hz == out.fs_hz);
        FNAV_ASSERT_CLOSE(out.fs_hz, fs, 0.0, 0.0);
    }
    /* a step so fine that fs / step overflows float (harness psd --round
     * 1e-40 printed fs_Hz inf): a step that small rounds nothing */
    c.round_hz = (fnav_real_t)1e-37;
    assert_int_equal(fnav_welch_bandwidth(p, 33, df, &c, &out, NULL), FNAV_OK);
    assert_true(fnav_isfinite(out.fs_rounded_hz));
    FNAV_ASSERT_CLOSE(out.fs_rounded_hz, out.fs_hz, 0.0, 1e-6);
}

/* A density is never negative: a spectrum with a negative bin, if taken,
 * would have as total the sum of the positive and negative parts:
 * {0, 4, -3, 0, 1} (df 1 Hz) would give FNAV_OK, a total of 2, a
 * "95 %" band of 0.975 Hz and a CCDF rising from 0 to 0.5. A negative or
 * NaN bin is FNAV_E_RANGE, the DC bin too when it is left out of the
 * total, with nothing written. */
static void test_bandwidth_bad_bins(void **state)
{
    fnav_real_t p[5] = { FNAV_R(0.0), FNAV_R(4.0), FNAV_R(-3.0), FNAV_R(0.0), FNAV_R(1.0) }, ccdf[5];
    fnav_bandwidth_t out, copy;
    fnav_bandwidth_config_t c = fnav_bandwidth_config_default;
    int k;
    (void)state;
    memset(&out, 0x5a, sizeof out);
    copy = out;
    for (k = 0; k < 5; k++) {
        ccdf[k] = FNAV_R(7.0);
    }
    assert_int_equal(fnav_welch_bandwidth(p, 5, FNAV_R(1.0), &c, &out, ccdf), FNAV_E_RANGE);
    p[2] = (fnav_real_t)NAN;
    assert_int_equal(fnav_welch_bandwidth(p, 5, FNAV_R(1.0), &c, &out, ccdf), FNAV_E_RANGE);
    p[2] = FNAV_R(0.0);
    p[0] = FNAV_R(-1.0);
    c.exclude_dc = 1;
    assert_int_equal(fnav_welch_bandwidth(p, 5, FNAV_R(1.0), &c, &out, ccdf), FNAV_E_RANGE);
    p[0] = (fnav_real_t)NAN;
    assert_int_equal(fnav_welch_bandwidth(p, 5, FNAV_R(1.0), &c, &out, ccdf), FNAV_E_RANGE);
    assert_memory_equal(&out, &copy, sizeof out);
    for (k = 0; k < 5; k++) {
        assert_true(ccdf[k] == FNAV_R(7.0));
    }
    /* the same spectrum without them: 4 and 1 in bins 1 and 4 */
    p[0] = FNAV_R(0.0);
    c.exclude_dc = 0;
    assert_int_equal(fnav_welch_bandwidth(p, 5, FNAV_R(1.0), &c, &out, ccdf), FNAV_OK);
    FNAV_ASSERT_CLOSE(out.total, 5.0, 0.0, 1e-6);
    /* 4.75 of 5: 0.75 of bin 4's power, bin 4 spanning [3.5, 4] (the last, clipped) */
    FNAV_ASSERT_CLOSE(out.bandwidth_hz, 3.5 + 0.75 * 0.5, 0.0, 1e-6);
}

static void test_config_and_bad_input(void **state)
{
    static fnav_welch_t w, copy;
    fnav_welch_config_t c = fnav_welch_config_default;
    int i;
    (void)state;
    assert_int_equal(fnav_welch_init(NULL, NULL), FNAV_E_ARG);
    /* push too must not dereference a NULL w: every other welch entry
     * point returns FNAV_E_ARG */
    assert_int_equal(fnav_welch_push(NULL, FNAV_R(1.0)), FNAV_E_ARG);
    c.nfft = 48;
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_E_CONFIG);
    c.nfft = FNAV_WELCH_MAX_NFFT * 2u;
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_E_CONFIG);
    c.nfft = 64;
    c.overlap = 64;
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_E_CONFIG);
    c.overlap = 32;
    c.rate_hz = FNAV_R(0.0);
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_E_CONFIG);
    c.rate_hz = FNAV_R(1.0);
    c.window = (fnav_window_t)7;
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_E_CONFIG);
    assert_int_equal(fnav_welch_init(&w, NULL), FNAV_OK);
    for (i = 0; i < 100; i++) {
        assert_int_equal(fnav_welch_push(&w, (fnav_real_t)i), FNAV_OK);
    }
    copy = w;
    assert_int_equal(fnav_welch_push(&w, (fnav_real_t)NAN), FNAV_E_NANINF);
    assert_int_equal(fnav_welch_push(&w, FNAV_R(1.0e30)), FNAV_E_RANGE); /* found by fuzzing */
    assert_memory_equal(&w, &copy, sizeof w);
    c = fnav_welch_config_default;
    c.offset = FNAV_R(1.0e30);
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_E_CONFIG);
    /* checks no suite made (make coverage): a power of two below 8 (8 and
     * FNAV_WELCH_MAX_NFFT accepted), a detrending or scaling outside the
     * enum, the global mean with a symmetric window, a rate not finite */
    c = fnav_welch_config_default;
    c.overlap = 0;
    c.nfft = 4;
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_E_CONFIG);
    c.nfft = 8;
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_OK);
    c.nfft = FNAV_WELCH_MAX_NFFT;
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_OK);
    c = fnav_welch_config_default;
    c.detrend = (fnav_detrend_t)9;
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_E_CONFIG);
    c = fnav_welch_config_default;
    c.scaling = (fnav_scaling_t)9;
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_E_CONFIG);
    c = fnav_welch_config_default;
    c.detrend = FNAV_DETREND_GLOBAL;
    c.symmetric = 1;
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_E_CONFIG);
    c.symmetric = 0;
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_OK);
    c = fnav_welch_config_default;
    c.rate_hz = (fnav_real_t)INFINITY;
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_E_CONFIG);
    c.rate_hz = (fnav_real_t)NAN;
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_E_CONFIG);
    /* a rate whose density scale 1 / (f_s sum w^2) overflows or f_s nfft
     * does: accepted, 1e-40 Hz in float gave every density Inf and 3e38 Hz
     * every one 0, with FNAV_OK; refused, *w unchanged. Inside those
     * limits (float 1e-30 and 1e36 Hz with nfft 64) the densities of
     * these samples are finite and positive. */
    {
#if FNAV_USE_DOUBLE
        const fnav_real_t bad[2] = { 1e-310, 1e307 }, ok[2] = { 1e-300, 1e300 };
#else
        const fnav_real_t bad[2] = { 1e-40f, 3e38f }, ok[2] = { 1e-30f, 1e36f };
#endif
        static fnav_real_t out[FNAV_WELCH_MAX_BINS];
        int k;
        uint32_t b;
        assert_int_equal(fnav_welch_init(&w, NULL), FNAV_OK);
        copy = w;
        for (k = 0; k < 2; k++) {
            c = fnav_welch_config_default;
            c.rate_hz = bad[k];
            assert_int_equal(fnav_welch_init(&w, &c), FNAV_E_CONFIG);
            assert_memory_equal(&w, &copy, sizeof w);
        }
        for (k = 0; k < 2; k++) {
            c = fnav_welch_config_default;
            c.rate_hz = ok[k];
            assert_int_equal(fnav_welch_init(&w, &c), FNAV_OK);
            for (i = 0; i < 64; i++) {
                assert_int_equal(fnav_welch_push(&w, (fnav_real_t)(i % 7)), FNAV_OK);
            }
            assert_int_equal(fnav_welch_get(&w, out, FNAV_WELCH_MAX_BINS), FNAV_OK);
            for (b = 1; b < fnav_welch_bins(&w); b++) {
                assert_true(fnav_isfinite(out[b]) && out[b] > FNAV_R(0.0));
            }
        }
    }
}

/* The offset is removed before anything else: with no detrending, a
 * constant offset equal to the signal's mean gives the spectrum of the
 * zero-mean signal. */
static void test_offset(void **state)
{
    static fnav_welch_t a, b;
    static fnav_real_t pa[FNAV_WELCH_MAX_BINS], pb[FNAV_WELCH_MAX_BINS];
    fnav_welch_config_t c = fnav_welch_config_default;
    uint32_t k;
    int i;
    (void)state;
    c.detrend = FNAV_DETREND_NONE;
    assert_int_equal(fnav_welch_init(&a, &c), FNAV_OK);
    c.offset = FNAV_R(9.75);
    assert_int_equal(fnav_welch_init(&b, &c), FNAV_OK);
    for (i = 0; i < 2000; i++) {
        const double v = 0.3 * sin(0.21 * i);
        assert_int_equal(fnav_welch_push(&a, (fnav_real_t)v), FNAV_OK);
        assert_int_equal(fnav_welch_push(&b, (fnav_real_t)(v + 9.75)), FNAV_OK);
    }
    assert_int_equal(fnav_welch_get(&a, pa, FNAV_WELCH_MAX_BINS), FNAV_OK);
    assert_int_equal(fnav_welch_get(&b, pb, FNAV_WELCH_MAX_BINS), FNAV_OK);
    for (k = 0; k < fnav_welch_bins(&a); k++) {
        FNAV_ASSERT_CLOSE(pb[k], pa[k], FNAV_USE_DOUBLE ? 1e-12 : 1e-6, FNAV_USE_DOUBLE ? 1e-9 : 1e-3);
    }
}

/* The per-segment mean and line (CONSTANT, LINEAR) are removed without
 * losing the segment's small signal to a large offset: gravity on an
 * accelerometer axis, 4096-sample segments. The spectrum with the offset
 * must be that without it, bin 0 included, within 1e-3 of the bin or 1e-6
 * of the largest (a float tolerance against scipy, not derived here).
 * Summing the raw float samples for the mean would put a 1.4 % error into
 * bin 0 of the ADIS16405 az spectrum. */
static void test_segment_mean_large_offset(void **state)
{
    static fnav_welch_t a, b;
    static fnav_real_t pa[FNAV_WELCH_MAX_BINS], pb[FNAV_WELCH_MAX_BINS];
    fnav_welch_config_t c = fnav_welch_config_default;
    uint32_t k, seed = 12345u;
    int d, i;
    (void)state;
    for (d = 0; d < 2; d++) {
        double pmax = 0.0;
        c.detrend = d == 0 ? FNAV_DETREND_CONSTANT : FNAV_DETREND_LINEAR;
        c.nfft = 4096u;
        c.window = FNAV_WINDOW_HANN;
        assert_int_equal(fnav_welch_init(&a, &c), FNAV_OK);
        assert_int_equal(fnav_welch_init(&b, &c), FNAV_OK);
        for (i = 0; i < 5 * 4096; i++) {
            double v;
            seed = seed * 1664525u + 1013904223u;
            v = 0.01 * ((double)(seed >> 8) / 16777216.0 - 0.5) + 0.002 * sin(0.003 * i);
            assert_int_equal(fnav_welch_push(&a, (fnav_real_t)v), FNAV_OK);
            assert_int_equal(fnav_welch_push(&b, (fnav_real_t)(v - 9.96)), FNAV_OK);
        }
        assert_int_equal(fnav_welch_get(&a, pa, FNAV_WELCH_MAX_BINS), FNAV_OK);
        assert_int_equal(fnav_welch_get(&b, pb, FNAV_WELCH_MAX_BINS), FNAV_OK);
        for (k = 0; k < fnav_welch_bins(&a); k++) {
            pmax = (double)pa[k] > pmax ? (double)pa[k] : pmax;
        }
        for (k = 0; k < fnav_welch_bins(&a); k++) {
            /* the offset signal's float samples carry their own rounding
             * (about 5e-7 against noise of 3e-3): the same size as the
             * tolerance's absolute part */
            FNAV_ASSERT_CLOSE(pb[k], pa[k], FNAV_USE_DOUBLE ? 1e-15 : 1e-6 * pmax, FNAV_USE_DOUBLE ? 1e-9 : 1e-3);
        }
    }
}

/* GLOBAL on a long record whose first sample is far from the mean: white
 * noise, sd 1 at 1 kHz, so the one-sided density is 2e-3 (1e-3 at DC).
 * Bins 0 and 1 are where global_fix cancels large terms; with the first
 * sample as the only shift and plain float sums this test failed in
 * float32 (a double build was right). 31,249 segments: the estimate's own
 * sd is about 0.6 %, and the 4 % held around the analytic density are
 * that statistic's band, not the arithmetic's. The record is deterministic,
 * so every bin is also checked against scipy.signal.welch of the same
 * record less its mean (vectors/welch/welch_long_offset_expected.csv,
 * gen_welch.py, which writes the generator below in Python) to
 * test_against_scipy's derived tolerance (bin_tolerances). */
static void test_global_long_offset_start(void **state)
{
    static double rec[1000000];
    static fnav_welch_t w;
    static fnav_real_t p[FNAV_WELCH_MAX_BINS];
    fnav_welch_config_t c = fnav_welch_config_default;
    uint64_t x = 88172645463325252ull;
    long i;
    (void)state;
    c.detrend = FNAV_DETREND_GLOBAL;
    c.rate_hz = FNAV_R(1000.0);
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_OK);
    for (i = 0; i < 1000000L; i++) {
        double u1, u2, g;
        x ^= x << 13; x ^= x >> 7; x ^= x << 17;
        u1 = 1.0 - (double)(x >> 11) * (1.0 / 9007199254740992.0);
        x ^= x << 13; x ^= x >> 7; x ^= x << 17;
        u2 = (double)(x >> 11) * (1.0 / 9007199254740992.0);
        g = sqrt(-2.0 * log(u1)) * cos(6.283185307179586 * u2);
        rec[i] = i == 0 ? 50.0 : g;
        assert_int_equal(fnav_welch_push(&w, (fnav_real_t)rec[i]), FNAV_OK);
    }
    assert_int_equal(fnav_welch_get(&w, p, FNAV_WELCH_MAX_BINS), FNAV_OK);
    assert_true(fabs((double)p[0] / 1.0e-3 - 1.0) < 0.04);
    assert_true(fabs((double)p[1] / 2.0e-3 - 1.0) < 0.04);
    assert_true(fabs((double)p[2] / 2.0e-3 - 1.0) < 0.04);
    {
        static double expect[FNAV_WELCH_MAX_BINS];
        char line[256];
        double worst[4] = { 0.0, 0.0, 0.0, 0.0 };
        bound_in_t b;
        unsigned nread = 0;
        vcase_t vc;
        FILE *f = open_vector("welch/welch_long_offset_expected.csv");
        memset(&vc, 0, sizeof vc);
        while (fgets(line, sizeof line, f) != NULL) {
            if (line[0] == '#') {
                continue;
            }
            if (parse_case(line, &vc)) {
                /* the configuration the vector was made with */
                assert_true(vc.fs == 1000.0 && vc.nfft == c.nfft && vc.overlap == c.overlap && vc.sym == 0 &&
                            strcmp(vc.window, "hamming") == 0 && c.window == FNAV_WINDOW_HAMMING &&
                            strcmp(vc.detrend, "global") == 0 && strcmp(vc.scaling, "density") == 0 &&
                            c.scaling == FNAV_SCALING_DENSITY);
                continue;
            }
            assert_true(vc.nbins == fnav_welch_bins(&w));
            read_bin(line, &vc, expect);
            nread++;
        }
        fclose(f);
        assert_int_equal(nread, fnav_welch_bins(&w));
        b.x = rec;
        b.nx = 1000000u;
        b.w = &w;
        b.last = 0;
        compare_bins("long offset start: ", &vc, &b, p, expect, worst);
        fprintf(stderr, "[  INFO    ] %s build: long record, first sample 50: worst bin %.2g relative to scipy, "
                        "%.2g of the derived tolerance\n",
                FNAV_USE_DOUBLE ? "double" : "float", worst[0], worst[2]);
    }
}

/* The sample count's end: with a hop of one sample the segment count
 * reaches 2^32 with the samples and must not wrap to 0 (get would then
 * answer FNAV_E_STATE, and the GLOBAL mean divide a sum of every sample
 * by a count that had stopped). 12.4 days at 4 kHz. The counts are moved
 * to their end here, consistently (hop 1: nseg = nsamples - nfft + 1); the
 * push that would make the count 2^32 is refused. */
static void test_sample_count_end(void **state)
{
    static fnav_welch_t w;
    fnav_welch_config_t c = fnav_welch_config_default;
    fnav_real_t out[FNAV_WELCH_MAX_BINS];
    int i, refused = 0;
    (void)state;
    c.nfft = 8u;
    c.overlap = 7u;
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_OK);
    for (i = 0; i < 40; i++) {
        assert_int_equal(fnav_welch_push(&w, (fnav_real_t)(0.1 * (double)(i % 5))), FNAV_OK);
    }
    w.nsamples = UINT32_MAX - 20u;
    w.nseg = w.nsamples - c.nfft + 1u;
    for (i = 0; i < 40; i++) {
        fnav_status_t st = fnav_welch_push(&w, (fnav_real_t)(0.1 * (double)(i % 5)));
        if (st == FNAV_E_RANGE) {
            refused++;
        } else {
            assert_int_equal(st, FNAV_OK);
        }
    }
    assert_int_equal(refused, 20);
    assert_int_equal(w.nsamples, UINT32_MAX);
    assert_int_equal(fnav_welch_segments(&w), UINT32_MAX - c.nfft + 1u);
    assert_int_equal(fnav_welch_get(&w, out, FNAV_WELCH_MAX_BINS), FNAV_OK);
    for (i = 0; i < 5; i++) {
        assert_true(fnav_isfinite(out[i]) && out[i] >= FNAV_R(0.0));
    }
    /* The value: the sums hold the 40 + 20 samples pushed (53 segments of
     * the period-5 input; the second loop's i % 5 continues the first's),
     * divided by the count moved to its end. Reference: the 53 periodograms
     * in double (constant detrend, periodic Hamming, density at 1 Hz, a
     * direct DFT), times 53 / (2^32 - 8). Tolerance: bin_tolerances' bound
     * of the 53-segment average (the same arithmetic), scaled the same way,
     * plus u of the bin for the count's conversion to fnav_real_t (2^32 - 8
     * is not a float; a double holds it). */
    {
        double rec[60], ref[5], tol[5], worst = 0.0, wtol = 0.0;
        const double cnt = (double)(UINT32_MAX - c.nfft + 1u), tp = 6.283185307179586476925;
        bound_in_t b;
        uint32_t j, k, n;
        for (j = 0; j < 60u; j++) {
            rec[j] = 0.1 * (double)(j % 5u);
        }
        for (k = 0; k < 5u; k++) {
            double s2 = 0.0, acc = 0.0;
            for (j = 0; j + 8u <= 60u; j++) {
                double mean = 0.0, re = 0.0, im = 0.0;
                for (n = 0; n < 8u; n++) {
                    mean += rec[j + n] / 8.0;
                }
                for (n = 0; n < 8u; n++) {
                    const double wn = 0.54 - 0.46 * cos(tp * n / 8.0);
                    re += wn * (rec[j + n] - mean) * cos(tp * (double)(k * n) / 8.0);
                    im -= wn * (rec[j + n] - mean) * sin(tp * (double)(k * n) / 8.0);
                }
                acc += re * re + im * im;
            }
            for (n = 0; n < 8u; n++) {
                s2 += (0.54 - 0.46 * cos(tp * n / 8.0)) * (0.54 - 0.46 * cos(tp * n / 8.0));
            }
            ref[k] = acc / 53.0 / s2 * ((k == 0u || k == 4u) ? 1.0 : 2.0);
        }
        b.x = rec;
        b.nx = 60u;
        b.w = &w;
        b.last = 0;
        bin_tolerances(&b, ref, tol);
        for (k = 0; k < 5u; k++) {
            const double e = ref[k] * 53.0 / cnt, t = tol[k] * 53.0 / cnt + (double)FNAV_REAL_EPSILON / 2.0 * e;
            FNAV_ASSERT_CLOSE(out[k], e, t, 0.0);
            worst = fabs((double)out[k] / e - 1.0) > worst ? fabs((double)out[k] / e - 1.0) : worst;
            wtol = t / e > wtol ? t / e : wtol;
        }
        fprintf(stderr, "[  INFO    ] %s build: at the count's end, worst bin %.2g relative to the double reference "
                        "(derived tolerance at most %.2g of the bin)\n",
                FNAV_USE_DOUBLE ? "double" : "float", worst, wtol);
    }
}

/* An estimator never initialised (static storage, zeroed) or whose init
 * failed before it ever succeeded: nfft is 0. Push must not step the ring
 * index past the end (pos + 1 == 0 never wraps it), writing out of bounds
 * from the FNAV_WELCH_MAX_NFFT-th push on (a library user's probe); the
 * index stays in the ring, no segment completes and
 * fnav_welch_get says FNAV_E_STATE, as before the first segment. */
static void test_not_initialised(void **state)
{
    static fnav_welch_t w, copy;
    fnav_welch_config_t c = fnav_welch_config_default;
    fnav_real_t out[FNAV_WELCH_MAX_BINS];
    uint32_t i;
    (void)state;
    c.nfft = 48; /* refused: w stays zeroed */
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_E_CONFIG);
    /* a push says FNAV_E_STATE, as fnav_nav_push does, before it looks at
     * the sample, and takes nothing (not FNAV_OK with the sample counted) */
    memset(&copy, 0, sizeof copy);
    for (i = 0; i < FNAV_WELCH_MAX_NFFT + 8u; i++) {
        assert_int_equal(fnav_welch_push(&w, FNAV_R(1.0)), FNAV_E_STATE);
    }
    assert_int_equal(fnav_welch_push(&w, (fnav_real_t)NAN), FNAV_E_STATE);
    assert_memory_equal(&w, &copy, sizeof w);
    assert_int_equal(fnav_welch_segments(&w), 0);
    assert_int_equal(fnav_welch_bins(&w), 0); /* 0 bins, not nfft / 2 + 1 of nfft 0 */
    /* the accessors answer 0 rather than read through NULL or divide by
     * nfft 0 (fnav_welch_freq dereferenced NULL and gave NaN here) */
    assert_true(fnav_welch_freq(&w, 1) == FNAV_R(0.0));
    assert_true(fnav_welch_freq(NULL, 1) == FNAV_R(0.0));
    assert_int_equal(fnav_welch_bins(NULL), 0);
    assert_int_equal(fnav_welch_segments(NULL), 0);
    assert_int_equal(fnav_welch_get(&w, out, FNAV_WELCH_MAX_BINS), FNAV_E_STATE);
    assert_int_equal(fnav_welch_last(&w, out, FNAV_WELCH_MAX_BINS), FNAV_E_STATE);
    /* an init that succeeds afterwards starts from scratch */
    assert_int_equal(fnav_welch_init(&w, NULL), FNAV_OK);
    for (i = 0; i < 64u; i++) {
        assert_int_equal(fnav_welch_push(&w, (fnav_real_t)(i % 3u)), FNAV_OK);
    }
    assert_int_equal(fnav_welch_segments(&w), 1);
    assert_int_equal(fnav_welch_get(&w, out, FNAV_WELCH_MAX_BINS), FNAV_OK);
    /* a failed init leaves an initialised estimator as it was (fnav_welch.h) */
    copy = w;
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_E_CONFIG);
    assert_memory_equal(&w, &copy, sizeof w);
}

/* Re-initialising with the estimator's own configuration (a reset,
 * fnav_welch_init(&w, &w.cfg)): an init that cleared the estimator,
 * configuration included, before it read the configuration's nfft again
 * would return FNAV_E_CONFIG and leave the estimator zeroed (every push
 * then FNAV_E_STATE), where fnav_welch.h says a failed init leaves it as
 * it was. It must reset it: no segment, the same
 * configuration, and the same spectrum as a fresh estimator after the same
 * samples. */
static void test_reinit_own_config(void **state)
{
    static fnav_welch_t w, fresh;
    static fnav_real_t pw[FNAV_WELCH_MAX_BINS], pf[FNAV_WELCH_MAX_BINS];
    fnav_welch_config_t c = fnav_welch_config_default;
    uint32_t k;
    int i;
    (void)state;
    c.nfft = 128u;
    c.overlap = 96u;
    c.window = FNAV_WINDOW_HANN;
    c.detrend = FNAV_DETREND_GLOBAL;
    c.rate_hz = FNAV_R(250.0);
    assert_int_equal(fnav_welch_init(&w, &c), FNAV_OK);
    for (i = 0; i < 700; i++) {
        assert_int_equal(fnav_welch_push(&w, (fnav_real_t)(3.0 + sin(0.7 * i))), FNAV_OK);
    }
    assert_true(fnav_welch_segments(&w) > 0u);
    assert_int_equal(fnav_welch_init(&w, &w.cfg), FNAV_OK);
    assert_memory_equal(&w.cfg, &c, sizeof c);
    assert_int_equal(fnav_welch_segments(&w), 0);
    assert_int_equal(fnav_welch_init(&fresh, &c), FNAV_OK);
    for (i = 0; i < 500; i++) {
        const fnav_real_t v = (fnav_real_t)(0.5 * cos(0.31 * i) + 0.01 * (i % 11));
        assert_int_equal(fnav_welch_push(&w, v), FNAV_OK);
        assert_int_equal(fnav_welch_push(&fresh, v), FNAV_OK);
    }
    assert_int_equal(fnav_welch_get(&w, pw, FNAV_WELCH_MAX_BINS), FNAV_OK);
    assert_int_equal(fnav_welch_get(&fresh, pf, FNAV_WELCH_MAX_BINS), FNAV_OK);
    for (k = 0; k < fnav_welch_bins(&w); k++) {
        assert_true(pw[k] == pf[k]); /* the same arithmetic on the same samples */
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_against_scipy),
        cmocka_unit_test(test_last_segment_average),
        cmocka_unit_test(test_last_global_against_scipy),
        cmocka_unit_test(test_parseval),
        cmocka_unit_test(test_bandwidth_analytic),
        cmocka_unit_test(test_bandwidth_bad_bins),
        cmocka_unit_test(test_config_and_bad_input),
        cmocka_unit_test(test_offset),
        cmocka_unit_test(test_segment_mean_large_offset),
        cmocka_unit_test(test_global_long_offset_start),
        cmocka_unit_test(test_sample_count_end),
        cmocka_unit_test(test_not_initialised),
        cmocka_unit_test(test_reinit_own_config),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
