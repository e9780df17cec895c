/* Noise models and their identification from Allan tables (hx_allan_ident.h,
 * docs/allan.md). */
#include "hx_allan_ident.h"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_multifit.h>
#include <gsl/gsl_multifit_nlinear.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "hx_devs.h"

const hx_allan_fit_opts_t hx_allan_fit_opts_default = { 0, 0, 0.0, 0.05 };

/* ------------------------------------------------------------ model */

/* Allan variance of a unit-variance stationary AR(1) with a = 1/(T f_s),
 * c = e^-a, averaged over m samples. Var(mean) - Cov(adjacent means) with
 * R(k) = c^|k|:
 *   (1/m^2) [ m + 2c (m(1-c) - (1-c^m)) / (1-c)^2 - c (1-c^m)^2 / (1-c)^2 ].
 * For m a < 1e-4 the process is a random walk over the window and the
 * difference above cancels; the random-walk form (1-c^2)(2m^2+1)/(6m) is
 * used there (relative error O(m a)). */
static double ar1_avar_unit(double m, double a)
{
    const double eps = -expm1(-a);      /* 1 - c */
    const double c = 1.0 - eps;
    const double omc = -expm1(-m * a);  /* 1 - c^m */
    double br;
    if (m * a < 1e-4) {
        const double w2 = -expm1(-2.0 * a); /* 1 - c^2: step variance of the walk */
        return w2 * (2.0 * m * m + 1.0) / (6.0 * m);
    }
    br = m + (2.0 * c * (m * eps - omc) - c * omc * omc) / (eps * eps);
    if (br < 0.0) {
        br = 0.0;
    }
    return br / (m * m);
}

/* Unit-amplitude bases: index 0 white (N^2), 1 AR(1) (sigma^2), 2 quantisation
 * (Q^2), 3 random walk (K^2). */
static double basis(int k, double m, double fs, double T)
{
    switch (k) {
    case 0: return fs / m;
    case 1: return ar1_avar_unit(m, 1.0 / (T * fs));
    case 2: return 3.0 * fs * fs / (m * m);
    default: return (2.0 * m * m + 1.0) / (6.0 * m * fs);
    }
}

double hx_noise_model_avar(const hx_noise_model_t *mdl, double rate_hz, double m)
{
    double v = 0.0;
    if (mdl == NULL || !(rate_hz > 0.0) || !(m >= 1.0)) {
        return (double)NAN;
    }
    if (mdl->white > 0.0) {
        v += mdl->white * mdl->white * basis(0, m, rate_hz, 1.0);
    }
    if (mdl->gm_sigma > 0.0 && mdl->gm_tau_s > 0.0) {
        v += mdl->gm_sigma * mdl->gm_sigma * basis(1, m, rate_hz, mdl->gm_tau_s);
    }
    if (mdl->quant > 0.0) {
        v += mdl->quant * mdl->quant * basis(2, m, rate_hz, 1.0);
    }
    if (mdl->rrw > 0.0) {
        v += mdl->rrw * mdl->rrw * basis(3, m, rate_hz, 1.0);
    }
    return v;
}

void hx_noise_model_paper_reading(const fnav_allan_paper_id_t *id, double rate_hz, hx_paper_reading_t reading,
                                  hx_noise_model_t *mdl)
{
    const double tau = (double)id->tau_samples;
    memset(mdl, 0, sizeof *mdl);
    mdl->white = (double)id->sigma_v;
    mdl->gm_sigma = (double)id->sigma_bias;
    mdl->gm_tau_s = tau / rate_hz;
    if (reading == HX_PAPER_DRIVE) {
        /* n_k ~ N(0, sigma_bias^2): stationary variance sigma_bias^2 / (1 - c^2) */
        mdl->gm_sigma = (double)id->sigma_bias / sqrt(-expm1(-2.0 / tau));
    } else if (reading == HX_PAPER_SAMPLE) {
        /* v_k ~ N(0, sigma_v^2) per sample: density sigma_v / sqrt(f_s) */
        mdl->white = (double)id->sigma_v / sqrt(rate_hz);
    }
}

void hx_noise_model_from_paper(const fnav_allan_paper_id_t *id, double rate_hz, hx_noise_model_t *mdl)
{
    hx_noise_model_paper_reading(id, rate_hz, HX_PAPER_EQ4, mdl);
}

/* ------------------------------------------------------------ CI, EDF */

double hx_chi2_quantile(double nu, double p)
{
    gsl_error_handler_t *old;
    double q;
    if (nu > 1e4) {
        /* Wilson & Hilferty (1931): within 2.6e-7 of scipy's chi2.ppf for nu in 1e4 .. 1e9 at
         * P = 0.005 .. 0.995, where GSL's search fails (NaN at nu = 81,000, 1.9e6, ...) or
         * lands 3e-5 off (its other tail) */
        const double h = 2.0 / (9.0 * nu), c = 1.0 - h + gsl_cdf_ugaussian_Pinv(p) * sqrt(h);
        return nu * c * c * c;
    }
    old = gsl_set_error_handler_off(); /* a failed search returns NaN, not abort() */
    q = gsl_cdf_chisq_Pinv(p, nu);
    gsl_set_error_handler(old);
    return q;
}

int hx_allan_ci(double dev, double edf, double conf, double *lo, double *hi)
{
    double p;
    if (!(edf > 0.0) || !(conf > 0.0 && conf < 1.0)) {
        *lo = *hi = (double)NAN;
        return -1;
    }
    p = 0.5 * (1.0 - conf);
    /* SP 1065 eq. (45): edf s^2 / chi2(1-p) <= sigma^2 <= edf s^2 / chi2(p) */
    *lo = dev * sqrt(edf / hx_chi2_quantile(edf, 1.0 - p));
    *hi = dev * sqrt(edf / hx_chi2_quantile(edf, p));
    return 0;
}

double hx_allan_point_edf(const fnav_allan_result_t *r, fnav_allan_noise_t type, int overlapping)
{
    return hx_allan_point_edf_alpha(r, fnav_allan_noise_alpha(type), overlapping);
}

double hx_allan_point_edf_alpha(const fnav_allan_result_t *r, int alpha, int overlapping)
{
    if (overlapping) {
        return r->terms > 0u ? fnav_allan_edf(alpha, r->lag, r->n_phase, 1) : -1.0;
    }
    /* non-overlapping: the series at full rate, stride tau */
    if (r->terms_nonoverlap == 0u) {
        return -1.0;
    }
    return fnav_allan_edf(alpha, r->tau, (uint32_t)((uint64_t)(r->n_phase - 1u) * r->stride + 1u), 0);
}

double hx_allan_avar_record(const double *x, size_t n, uint32_t m, int overlapping, uint32_t *terms)
{
    const size_t stride = overlapping ? 1u : (size_t)m;
    double sum = 0.0;
    size_t i, k = 0;
    *terms = 0u;
    if (m == 0u || n <= 2u * (size_t)m) {
        return (double)NAN;
    }
    for (i = 0; i + 2u * (size_t)m < n; i += stride) {
        const double d = x[i + 2u * (size_t)m] - 2.0 * x[i + m] + x[i];
        sum += d * d;
        k++;
    }
    *terms = (uint32_t)k;
    return sum / (2.0 * (double)m * (double)m * (double)k);
}

/* Lag-1 autocorrelation of z_0..z_{n-1} about its mean. */
static double lag1_acf(const double *z, size_t n)
{
    double mean = 0.0, num = 0.0, den = 0.0;
    size_t i;
    for (i = 0; i < n; i++) {
        mean += z[i];
    }
    mean /= (double)n;
    for (i = 0; i < n; i++) {
        const double d = z[i] - mean;
        den += d * d;
        if (i + 1u < n) {
            num += d * (z[i + 1u] - mean);
        }
    }
    return den > 0.0 ? num / den : 0.0;
}

/* Barnes' bias function B1(N, mu): the expected ratio of the standard
 * variance of N frequency averages to their Allan variance for
 * S_y ~ f^alpha, mu = -alpha - 1 (NIST TN 375, 1969; SP 1065 sec. 5.6). */
static double b1_theory(double N, double mu)
{
    if (fabs(mu) < 1e-12) {
        return N * log(N) / (2.0 * (N - 1.0) * log(2.0));
    }
    return N * (1.0 - pow(N, mu)) / (2.0 * (N - 1.0) * (1.0 - pow(2.0, mu)));
}

const char *hx_noise_id_name(hx_noise_id_t how)
{
    static const char *const names[] = { "slope", "acf", "b1", "b1+rn", "held" };
    return (unsigned)how < sizeof names / sizeof names[0] ? names[how] : "?";
}

void hx_allan_mark_periodic(const fnav_allan_noise_t *noise, size_t n, unsigned char *periodic)
{
    int freq_seen = 0; /* a shorter tau read frequency noise */
    size_t i;
    for (i = 0; i < n; i++) {
        periodic[i] = (unsigned char)(freq_seen && noise[i] == FNAV_ALLAN_NOISE_QUANT);
        if (noise[i] != FNAV_ALLAN_NOISE_QUANT && noise[i] != FNAV_ALLAN_NOISE_UNKNOWN) {
            freq_seen = 1;
        }
    }
}

/* R(m) = MVAR / AVAR of the record against its expected values for white
 * (1 / m) and flicker phase noise (SP 1065 sec. 5.6, with the bandwidth at
 * the Nyquist frequency: 2 pi f_h tau = pi m): the nearer on a log scale,
 * +2 or +1; -1 when MVAR or AVAR is not there. For m >= 2 that is a split
 * at their geometric mean, white below; at m = 1 MVAR = AVAR, R = 1 for any
 * noise, white phase noise's value exactly and above the flicker formula's
 * 0.75, where "white below the mean" named every record flicker (+1). */
static int noise_id_rn(const double *x, size_t n, uint32_t m, int *alpha)
{
    const double pi = 3.14159265358979323846;
    uint32_t t1, t2;
    const double mv = hx_dev_var_record(HX_DEV_MDEV, x, n, m, &t1);
    const double av = hx_allan_avar_record(x, n, m, 1, &t2);
    const double r_white = 1.0 / (double)m;
    const double r_flicker = 3.0 * log(256.0 / 27.0) / (2.0 * (1.038 + 3.0 * log(pi * (double)m)));
    if (!(mv >= 0.0) || !(av > 0.0)) {
        return -1;
    }
    {
        const double lr = log(mv / av); /* -inf for MVAR 0: white */
        *alpha = fabs(lr - log(r_white)) <= fabs(lr - log(r_flicker)) ? 2 : 1;
    }
    return 0;
}

/* B1 ratio noise identification from len frequency averages z: alpha -2,
 * -1 or 0, or 2 for phase noise (mu = -2), which B1 cannot split into white
 * and flicker (noise_id_rn() does). */
static int noise_id_b1(const double *z, size_t len, int *alpha)
{
    double mean = 0.0, var = 0.0, avar = 0.0, b1, best = 0.0;
    size_t i;
    int mu;
    for (i = 0; i < len; i++) {
        mean += z[i];
    }
    mean /= (double)len;
    for (i = 0; i < len; i++) {
        var += (z[i] - mean) * (z[i] - mean);
        if (i + 1u < len) {
            avar += (z[i + 1u] - z[i]) * (z[i + 1u] - z[i]);
        }
    }
    var /= (double)(len - 1u);
    avar /= 2.0 * (double)(len - 1u);
    if (!(avar > 0.0)) {
        return -1;
    }
    b1 = var / avar;
    /* the mu whose B1 is nearest on a log scale (boundaries at the geometric means) */
    *alpha = 2;
    for (mu = 1; mu >= -2; mu--) {
        const double d = fabs(log(b1 / b1_theory((double)len, (double)mu)));
        if (mu == 1 || d < best) {
            best = d;
            *alpha = mu == -2 ? 2 : -mu - 1;
        }
    }
    return 0;
}

int hx_allan_noise_id_acf(const double *x, size_t n, uint32_t m, int *alpha, hx_noise_id_t *how)
{
    const size_t len = m > 0u && n > 0u ? (n - 1u) / m : 0u;
    double *z, sx = 0.0, sxx = 0.0, sz = 0.0, sxz = 0.0, slope, icpt, den, delta = 0.0;
    size_t i, k = len;
    int d, a;
    if (len < HX_B1_MIN_POINTS) {
        return -1;
    }
    z = (double *)malloc(len * sizeof *z);
    if (z == NULL) {
        return -1;
    }
    /* frequency averaged over m (non-overlapping): phase differences / m */
    for (i = 0; i < len; i++) {
        z[i] = (x[(i + 1u) * m] - x[i * m]) / (double)m;
    }
    if (len < HX_ACF_MIN_POINTS) {
        const int rc = noise_id_b1(z, len, alpha);
        free(z);
        if (how != NULL) {
            *how = HX_NOISE_ID_B1;
        }
        if (rc == 0 && *alpha == 2 && noise_id_rn(x, n, m, alpha) == 0 && how != NULL) {
            *how = HX_NOISE_ID_B1_RN;
        }
        return rc;
    }
    for (i = 0; i < len; i++) {
        sx += (double)i;
        sxx += (double)i * (double)i;
        sz += z[i];
        sxz += (double)i * z[i];
    }
    /* remove the least-squares line (a frequency drift) */
    den = (double)len * sxx - sx * sx;
    slope = den > 0.0 ? ((double)len * sxz - sx * sz) / den : 0.0;
    icpt = (sz - slope * sx) / (double)len;
    for (i = 0; i < len; i++) {
        z[i] -= icpt + slope * (double)i;
    }
    for (d = 0;; d++) {
        const double r1 = lag1_acf(z, k);
        delta = r1 > -0.999 ? r1 / (1.0 + r1) : -999.0; /* r1 -> -1: strongly alternating, alpha +2 */
        if (delta < 0.25 || d >= 2) {
            break;
        }
        for (i = 0; i + 1u < k; i++) {
            z[i] = z[i + 1u] - z[i];
        }
        k--;
    }
    free(z);
    a = -(int)lround(2.0 * delta) - 2 * d;
    *alpha = a < -2 ? -2 : (a > 2 ? 2 : a);
    if (how != NULL) {
        *how = HX_NOISE_ID_ACF;
    }
    return 0;
}

/* ------------------------------------------------------------ fit */

typedef struct {
    size_t n;
    double *m;     /* averaging factor, samples */
    double *a;     /* measured AVAR */
    double *w;     /* weight of log ADEV residual */
    double fs;
    int comp[4];   /* component k used */
    int ncomp;
} fit_data_t;

static int usable_point(const fnav_allan_result_t *r, double fs, double tau_max_s)
{
    return r->terms >= 2u && isfinite((double)r->avar) && (double)r->avar > 0.0 &&
           (tau_max_s <= 0.0 || (double)r->tau / fs <= tau_max_s * (1.0 + 1e-9));
}

/* Select the points and compute their weights. Returns the count. */
static size_t fit_points(const fnav_allan_result_t *r, size_t n, double fs, double tau_max_s, double floor_rel,
                         fit_data_t *d)
{
    fnav_real_t *slope = (fnav_real_t *)malloc((n > 0 ? n : 1) * sizeof *slope);
    size_t i, k = 0;
    d->n = 0;
    d->fs = fs;
    d->m = (double *)malloc((n > 0 ? n : 1) * sizeof(double));
    d->a = (double *)malloc((n > 0 ? n : 1) * sizeof(double));
    d->w = (double *)malloc((n > 0 ? n : 1) * sizeof(double));
    if (slope == NULL || d->m == NULL || d->a == NULL || d->w == NULL) {
        free(slope);
        return 0;
    }
    fnav_allan_slopes(r, n, slope);
    for (i = 0; i < n; i++) {
        double edf;
        if (!usable_point(&r[i], fs, tau_max_s)) {
            continue;
        }
        edf = hx_allan_point_edf(&r[i], fnav_allan_noise_from_slope(slope[i]), 1);
        if (!(edf > 0.0)) {
            edf = (double)r[i].terms_nonoverlap > 0.0 ? (double)r[i].terms_nonoverlap : 1.0;
        }
        d->m[k] = (double)r[i].tau;
        d->a[k] = (double)r[i].avar;
        d->w[k] = 1.0 / sqrt(1.0 / (2.0 * edf) + floor_rel * floor_rel);
        k++;
    }
    free(slope);
    d->n = k;
    return k;
}

static void fit_free(fit_data_t *d)
{
    free(d->m);
    free(d->a);
    free(d->w);
    d->m = d->a = d->w = NULL;
}

static void quality_of(const fit_data_t *d, const hx_noise_model_t *mdl, hx_allan_quality_t *q)
{
    size_t i, imin = 0;
    double ss = 0.0, mx = 1.0;
    memset(q, 0, sizeof *q);
    for (i = 0; i < d->n; i++) {
        const double mv = hx_noise_model_avar(mdl, d->fs, d->m[i]);
        const double lr = 0.5 * log10(mv / d->a[i]);
        const double ratio = pow(10.0, fabs(lr));
        ss += lr * lr;
        if (ratio > mx || !isfinite(ratio)) {
            mx = ratio;
        }
        if (d->a[i] < d->a[imin]) {
            imin = i;
        }
    }
    q->npoints = (int)d->n;
    q->rms_log10 = d->n > 0 ? sqrt(ss / (double)d->n) : (double)NAN;
    q->max_ratio = d->n > 0 ? mx : (double)NAN;
    q->ratio_at_min = d->n > 0 ? sqrt(hx_noise_model_avar(mdl, d->fs, d->m[imin]) / d->a[imin]) : (double)NAN;
}

void hx_allan_quality(const fnav_allan_result_t *r, size_t n, double rate_hz, double tau_max_s,
                      const hx_noise_model_t *mdl, hx_allan_quality_t *q)
{
    fit_data_t d;
    memset(&d, 0, sizeof d);
    fit_points(r, n, rate_hz, tau_max_s, 0.05, &d);
    quality_of(&d, mdl, q);
    fit_free(&d);
}

static void model_set(hx_noise_model_t *mdl, int k, double amp2)
{
    const double v = amp2 > 0.0 ? sqrt(amp2) : 0.0;
    switch (k) {
    case 0: mdl->white = v; break;
    case 1: mdl->gm_sigma = v; break;
    case 2: mdl->quant = v; break;
    default: mdl->rrw = v; break;
    }
}

/* Stage 1 at a fixed T: weighted linear least squares for the squared
 * amplitudes of the components in mask (relative AVAR residuals),
 * unconstrained (no NNLS). Returns the residual sum of squares, or
 * INFINITY when an amplitude is not positive: that T is discarded. */
static double linear_stage(const fit_data_t *d, double T, const int *comp, int nc, double *amp2)
{
    gsl_matrix *X = gsl_matrix_alloc(d->n, (size_t)nc), *cov = gsl_matrix_alloc((size_t)nc, (size_t)nc);
    gsl_vector *y = gsl_vector_alloc(d->n), *c = gsl_vector_alloc((size_t)nc);
    gsl_multifit_linear_workspace *ws = gsl_multifit_linear_alloc(d->n, (size_t)nc);
    double chisq = INFINITY, scale[4];
    size_t i;
    int k, ok = 1;
    if (X == NULL || cov == NULL || y == NULL || c == NULL || ws == NULL) {
        ok = 0;
    }
    for (k = 0; ok && k < nc; k++) {
        double s = 0.0;
        for (i = 0; i < d->n; i++) {
            const double g = d->w[i] * basis(comp[k], d->m[i], d->fs, T) / d->a[i];
            gsl_matrix_set(X, i, (size_t)k, g);
            s += g * g;
        }
        scale[k] = s > 0.0 ? sqrt(s) : 1.0; /* column scaling for conditioning */
        for (i = 0; i < d->n; i++) {
            gsl_matrix_set(X, i, (size_t)k, gsl_matrix_get(X, i, (size_t)k) / scale[k]);
        }
    }
    for (i = 0; ok && i < d->n; i++) {
        gsl_vector_set(y, i, d->w[i]);
    }
    if (ok && gsl_multifit_linear(X, y, c, cov, &chisq, ws) == GSL_SUCCESS) {
        for (k = 0; k < nc; k++) {
            amp2[k] = gsl_vector_get(c, (size_t)k) / scale[k];
            if (!(amp2[k] > 0.0)) {
                chisq = INFINITY;
            }
        }
    } else {
        chisq = INFINITY;
    }
    if (ws) gsl_multifit_linear_free(ws);
    if (X) gsl_matrix_free(X);
    if (cov) gsl_matrix_free(cov);
    if (y) gsl_vector_free(y);
    if (c) gsl_vector_free(c);
    return chisq;
}

/* Stage 2 residuals: p = [log amp2_k ..., log T]. */
static int lm_f(const gsl_vector *p, void *params, gsl_vector *f)
{
    const fit_data_t *d = (const fit_data_t *)params;
    const double T = exp(gsl_vector_get(p, (size_t)d->ncomp));
    size_t i;
    for (i = 0; i < d->n; i++) {
        double v = 0.0;
        int k;
        for (k = 0; k < d->ncomp; k++) {
            v += exp(gsl_vector_get(p, (size_t)k)) * basis(d->comp[k], d->m[i], d->fs, T);
        }
        gsl_vector_set(f, i, d->w[i] * 0.5 * log(v / d->a[i]));
    }
    return GSL_SUCCESS;
}

int hx_allan_fit(const fnav_allan_result_t *r, size_t n, double rate_hz, const hx_allan_fit_opts_t *opts,
                 hx_noise_model_t *out, hx_allan_quality_t *q)
{
    const hx_allan_fit_opts_t *o = opts != NULL ? opts : &hx_allan_fit_opts_default;
    fit_data_t d;
    double best = INFINITY, bestT = 0.0, best_amp[4] = { 0, 0, 0, 0 };
    int best_comp[4] = { 0, 1, 2, 3 }, best_nc = 0;
    double tmin, tmax, lt;
    int subset, it = 0;
    memset(&d, 0, sizeof d);
    memset(out, 0, sizeof *out);
    if (q != NULL) {
        memset(q, 0, sizeof *q);
    }
    if (!(rate_hz > 0.0) || fit_points(r, n, rate_hz, o->tau_max_s, o->model_floor, &d) < 4u) {
        fit_free(&d);
        return -1;
    }
    /* stage 1: correlation times from half the smallest to 20 x the largest tau */
    tmin = 0.5 * d.m[0] / rate_hz;
    tmax = 20.0 * d.m[d.n - 1] / rate_hz;
    for (lt = log(tmin); lt <= log(tmax) + 1e-9; lt += log(tmax / tmin) / 96.0) {
        const double T = exp(lt);
        /* subsets: white and AR(1) always; quantisation and random walk if asked */
        for (subset = 0; subset < 4; subset++) {
            int comp[4], nc = 0;
            double amp[4], chi;
            if (((subset & 1) && !o->with_quant) || ((subset & 2) && !o->with_rrw)) {
                continue;
            }
            comp[nc++] = 0;
            comp[nc++] = 1;
            if (subset & 1) {
                comp[nc++] = 2;
            }
            if (subset & 2) {
                comp[nc++] = 3;
            }
            if ((size_t)nc + 1u >= d.n) {
                /* the amplitudes and T need more points than parameters:
                 * 4 points took the four-term solve (exact, RMS 0) and then
                 * GSL's Levenberg-Marquardt failed on 5 parameters from 4
                 * residuals (its error handler: abort() unless turned off) */
                continue;
            }
            chi = linear_stage(&d, T, comp, nc, amp);
            if (chi < best) {
                best = chi;
                bestT = T;
                best_nc = nc;
                memcpy(best_comp, comp, sizeof comp);
                memcpy(best_amp, amp, sizeof amp);
            }
        }
    }
    if (!isfinite(best)) {
        fit_free(&d);
        return -1;
    }
    /* stage 2: Levenberg-Marquardt on log ADEV from the best stage-1 point */
    {
        const size_t np = (size_t)best_nc + 1u;
        gsl_multifit_nlinear_parameters fp = gsl_multifit_nlinear_default_parameters();
        gsl_multifit_nlinear_workspace *w;
        gsl_multifit_nlinear_fdf fdf;
        gsl_vector *p0 = gsl_vector_alloc(np);
        int k, info = 0;
        if (p0 == NULL) { /* with GSL's handler off, an allocation failure comes back as NULL */
            fit_free(&d);
            return -1;
        }
        d.ncomp = best_nc;
        memcpy(d.comp, best_comp, sizeof d.comp);
        for (k = 0; k < best_nc; k++) {
            gsl_vector_set(p0, (size_t)k, log(best_amp[k]));
        }
        gsl_vector_set(p0, (size_t)best_nc, log(bestT));
        fdf.f = lm_f;
        fdf.df = NULL;
        fdf.fvv = NULL;
        fdf.n = d.n;
        fdf.p = np;
        fdf.params = &d;
        w = gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &fp, d.n, np);
        if (w != NULL && gsl_multifit_nlinear_init(p0, &fdf, w) == GSL_SUCCESS) {
            gsl_error_handler_t *old = gsl_set_error_handler_off();
            int st = gsl_multifit_nlinear_driver(200, 1e-10, 1e-10, 1e-12, NULL, NULL, &info, w);
            gsl_set_error_handler(old);
            it = (int)gsl_multifit_nlinear_niter(w);
            if (st == GSL_SUCCESS || st == GSL_EMAXITER || st == GSL_ENOPROG) {
                const gsl_vector *p = gsl_multifit_nlinear_position(w);
                int finite = 1;
                /* the parameters themselves, not only their logs: exp() of a
                 * finite log overflowed (white noise with one wild point:
                 * Q, sigma and T infinite, RMS NaN, reported as a fit) */
                for (k = 0; k < (int)np; k++) {
                    const double v = exp(gsl_vector_get(p, (size_t)k));
                    finite = finite && isfinite(v);
                }
                if (finite) {
                    for (k = 0; k < best_nc; k++) {
                        best_amp[k] = exp(gsl_vector_get(p, (size_t)k));
                    }
                    bestT = exp(gsl_vector_get(p, (size_t)best_nc));
                }
            }
        }
        if (w != NULL) {
            gsl_multifit_nlinear_free(w);
        }
        gsl_vector_free(p0);
        for (k = 0; k < best_nc; k++) {
            model_set(out, best_comp[k], best_amp[k]);
        }
        out->gm_tau_s = bestT;
    }
    if (q != NULL) {
        quality_of(&d, out, q);
        q->iterations = it;
    }
    fit_free(&d);
    return 0;
}

int hx_allan_identify(const fnav_allan_result_t *r, size_t n, double rate_hz, const hx_allan_fit_opts_t *opts,
                      hx_allan_ident_t *out)
{
    const hx_allan_fit_opts_t *o = opts != NULL ? opts : &hx_allan_fit_opts_default;
    uint32_t tau_max = 0;
    int paper_range = 1;
    memset(out, 0, sizeof *out);
    if (o->tau_max_s > 0.0) {
        /* the same inclusive limit as the table, the noise regions and the
         * fit (tau <= limit (1 + 1e-9)): truncated, a point at exactly 10 %
         * of a record whose limit rounds just below it would be left out of
         * the minimum search, and a limit under one sample would become 0,
         * "no limit" */
        const double t = floor(o->tau_max_s * rate_hz * (1.0 + 1e-9));
        tau_max = t >= 4294967295.0 ? UINT32_MAX : (uint32_t)t;
        paper_range = t >= 1.0;
    }
    if (paper_range && fnav_allan_identify_paper(r, n, (fnav_real_t)rate_hz, tau_max, &out->paper) == FNAV_OK) {
        out->paper_ok = 1;
        hx_noise_model_from_paper(&out->paper, rate_hz, &out->paper_model);
        hx_allan_quality(r, n, rate_hz, o->tau_max_s, &out->paper_model, &out->paper_quality);
        hx_noise_model_paper_reading(&out->paper, rate_hz, HX_PAPER_DRIVE, &out->paper_drive_model);
        hx_allan_quality(r, n, rate_hz, o->tau_max_s, &out->paper_drive_model, &out->paper_drive_quality);
        {
            hx_noise_model_t ms;
            hx_noise_model_paper_reading(&out->paper, rate_hz, HX_PAPER_SAMPLE, &ms);
            hx_allan_quality(r, n, rate_hz, o->tau_max_s, &ms, &out->paper_sample_quality);
        }
    }
    out->fit_ok = hx_allan_fit(r, n, rate_hz, o, &out->fit, &out->fit_quality) == 0;
    return (out->paper_ok || out->fit_ok) ? 0 : -1;
}

/* ------------------------------------------------------------ simulation */

int hx_noise_sim_init(hx_noise_sim_t *s, const hx_noise_model_t *mdl, double rate_hz, unsigned long seed)
{
    gsl_rng *rng;
    memset(s, 0, sizeof *s);
    if (mdl == NULL || !(rate_hz > 0.0) || !(mdl->white >= 0.0) || !(mdl->gm_sigma >= 0.0) ||
        (mdl->gm_sigma > 0.0 && !(mdl->gm_tau_s > 0.0))) {
        return -1;
    }
    rng = gsl_rng_alloc(gsl_rng_mt19937);
    if (rng == NULL) {
        return -1;
    }
    gsl_rng_set(rng, seed);
    s->rng = rng;
    s->rate_hz = rate_hz;
    s->sd_white = mdl->white * sqrt(rate_hz);
    if (mdl->gm_sigma > 0.0) {
        const double a = 1.0 / (mdl->gm_tau_s * rate_hz);
        s->c = exp(-a);                                           /* eq. (3), c = e^(-1/tau) */
        s->sd_drive = mdl->gm_sigma * sqrt(-expm1(-2.0 * a));     /* eq. (4) */
        s->b = mdl->gm_sigma * gsl_ran_gaussian_ziggurat(rng, 1.0); /* stationary start */
    }
    s->sd_quant = mdl->quant > 0.0 ? mdl->quant : 0.0;
    s->sd_rw = mdl->rrw > 0.0 ? mdl->rrw / sqrt(rate_hz) : 0.0;
    if (s->sd_quant > 0.0) {
        s->xq = s->sd_quant * gsl_ran_gaussian_ziggurat(rng, 1.0);
    }
    return 0;
}

double hx_noise_sim_next(hx_noise_sim_t *s)
{
    gsl_rng *rng = (gsl_rng *)s->rng;
    double e = 0.0;
    if (s->sd_drive > 0.0) {
        s->b = s->c * s->b + s->sd_drive * gsl_ran_gaussian_ziggurat(rng, 1.0); /* eq. (3) */
        e += s->b;
    }
    if (s->sd_white > 0.0) {
        e += s->sd_white * gsl_ran_gaussian_ziggurat(rng, 1.0); /* v_k, eq. (2) */
    }
    if (s->sd_quant > 0.0) {
        const double x = s->sd_quant * gsl_ran_gaussian_ziggurat(rng, 1.0);
        e += (x - s->xq) * s->rate_hz;
        s->xq = x;
    }
    if (s->sd_rw > 0.0) {
        s->rw += s->sd_rw * gsl_ran_gaussian_ziggurat(rng, 1.0);
        e += s->rw;
    }
    return e;
}

void hx_noise_sim_free(hx_noise_sim_t *s)
{
    if (s->rng != NULL) {
        gsl_rng_free((gsl_rng *)s->rng);
        s->rng = NULL;
    }
}

size_t hx_allan_simulate(const hx_noise_model_t *mdl, double rate_hz, uint32_t n, unsigned long seed,
                         const fnav_allan_config_t *cfg, fnav_allan_result_t *out)
{
    hx_noise_sim_t s;
    fnav_allan_t *a = (fnav_allan_t *)malloc(sizeof *a);
    size_t i, np;
    uint32_t k;
    if (a == NULL || hx_noise_sim_init(&s, mdl, rate_hz, seed) != 0) {
        free(a);
        return 0;
    }
    if (fnav_allan_init(a, cfg) != FNAV_OK) {
        hx_noise_sim_free(&s);
        free(a);
        return 0;
    }
    for (k = 0; k < n; k++) {
        if (fnav_allan_push(a, (fnav_real_t)hx_noise_sim_next(&s)) != FNAV_OK) {
            break;
        }
    }
    np = fnav_allan_count(a);
    for (i = 0; i < np; i++) {
        if (fnav_allan_get(a, i, &out[i]) != FNAV_OK) {
            np = i;
            break;
        }
    }
    hx_noise_sim_free(&s);
    free(a);
    return np;
}
