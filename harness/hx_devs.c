/* Frequency-stability deviations of a whole phase record (hx_devs.h). */
#include "hx_devs.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "footnav/fnav_allan.h"
#include "hx_allan_ident.h"

static const struct {
    const char *name, *title;
} k_dev[HX_DEV_COUNT] = {
    { "adev", "Allan" },       { "oadev", "Overlapping Allan" }, { "mdev", "Modified Allan" }, { "tdev", "Time" },
    { "hdev", "Hadamard" },    { "ohdev", "Overlapping Hadamard" }, { "totdev", "Total" }, { "pdev", "Parabolic" },
    { "mtotdev", "Modified Total" }, { "ttotdev", "Time Total" }, { "htotdev", "Hadamard Total" },
};

const char *hx_dev_name(hx_dev_t k)
{
    return (unsigned)k < HX_DEV_COUNT ? k_dev[k].name : NULL;
}

const char *hx_dev_title(hx_dev_t k)
{
    return (unsigned)k < HX_DEV_COUNT ? k_dev[k].title : NULL;
}

int hx_dev_parse(const char *s, hx_dev_t *k)
{
    unsigned i;
    for (i = 0; i < HX_DEV_COUNT; i++) {
        if (strcmp(s, k_dev[i].name) == 0) {
            *k = (hx_dev_t)i;
            return 0;
        }
    }
    return -1;
}

/* Second difference of the phase at i with lag m. */
static double d2(const double *x, size_t i, size_t m)
{
    return x[i + 2u * m] - 2.0 * x[i + m] + x[i];
}

/* MVAR: the second differences summed over m consecutive starts. The window
 * sum slides (one difference in, one out) and is summed afresh every m
 * starts, so its rounding does not accumulate over the record. */
static double mvar(const double *x, size_t n, size_t m, uint32_t *terms)
{
    const size_t nt = n - 3u * m + 1u; /* n >= 3m checked by the caller */
    double w = 0.0, sum = 0.0;
    size_t i, j;
    for (j = 0; j < nt; j++) {
        if (j % m == 0u) {
            w = 0.0;
            for (i = j; i < j + m; i++) {
                w += d2(x, i, m);
            }
        } else {
            w += d2(x, j + m - 1u, m) - d2(x, j - 1u, m);
        }
        sum += w * w;
    }
    *terms = (uint32_t)nt;
    return sum / (2.0 * (double)m * (double)m * (double)m * (double)m * (double)nt);
}

static double hvar(const double *x, size_t n, size_t m, size_t stride, uint32_t *terms)
{
    double sum = 0.0;
    size_t i, k = 0;
    for (i = 0; i + 3u * m < n; i += stride) {
        const double d = x[i + 3u * m] - 3.0 * x[i + 2u * m] + 3.0 * x[i + m] - x[i];
        sum += d * d;
        k++;
    }
    *terms = (uint32_t)k;
    return sum / (6.0 * (double)m * (double)m * (double)k);
}

/* The record extended by odd reflection about its end points. */
static double x_ext(const double *x, size_t n, long k)
{
    const long last = (long)n - 1;
    if (k < 0) {
        return 2.0 * x[0] - x[-k];
    }
    if (k > last) {
        return 2.0 * x[last] - x[2 * last - k];
    }
    return x[k];
}

static double totvar(const double *x, size_t n, size_t m, uint32_t *terms)
{
    double sum = 0.0;
    long i;
    const long ml = (long)m;
    for (i = 1; i + 1 < (long)n; i++) {
        const double d = x_ext(x, n, i - ml) - 2.0 * x[i] + x_ext(x, n, i + ml);
        sum += d * d;
    }
    *terms = (uint32_t)(n - 2u);
    return sum / (2.0 * (double)m * (double)m * (double)(n - 2u));
}

/* PVAR: z_i = sum over k < m of ((m - 1) / 2 - k) (x_{i+k} - x_{i+m+k}), the
 * difference of two least-squares frequency slopes (up to a factor), written
 * with u_i = x_i - x_{i+m} as (m - 1) / 2 S0_i - S1_i, S0_i = sum u_{i+k},
 * S1_i = sum k u_{i+k}. Both slide (S0_i = S0_{i-1} - u_{i-1} + u_{i-1+m},
 * S1_i = S1_{i-1} + m u_{i-1+m} - S0_i) and are summed afresh every m
 * starts, as in mvar(). */
static double pvar(const double *x, size_t n, size_t m, uint32_t *terms)
{
    const size_t nt = n - 2u * m; /* m <= (n - 1) / 2 checked by the caller */
    const double h = 0.5 * (double)(m - 1u), md = (double)m;
    double s0 = 0.0, s1 = 0.0, sum = 0.0;
    size_t i, k;
    for (i = 0; i < nt; i++) {
        double z;
        if (i % m == 0u) {
            s0 = s1 = 0.0;
            for (k = 0; k < m; k++) {
                const double u = x[i + k] - x[i + m + k];
                s0 += u;
                s1 += (double)k * u;
            }
        } else {
            const double un = x[i + m - 1u] - x[i + 2u * m - 1u];
            s0 += un - (x[i - 1u] - x[i + m - 1u]);
            s1 += md * un - s0;
        }
        z = h * s0 - s1;
        sum += z * z;
    }
    *terms = (uint32_t)nt;
    return 72.0 * sum / (md * md * md * md * md * md * (double)nt);
}

/* The sum of xstar over [a, b), xstar the detrended window x0 (length L,
 * prefix sums p[0..L]) extended at both ends by uninverted even reflection:
 * xstar = (x0 reversed, x0, x0 reversed), 3L values. */
static double xstar_sum(const double *p, size_t L, size_t a, size_t b)
{
    double s = 0.0;
    if (a < L && a < b) { /* xstar[t] = x0[L - 1 - t] */
        const size_t e = b < L ? b : L;
        s += p[L - a] - p[L - e];
        a = e;
    }
    if (a < 2u * L && a < b) { /* xstar[t] = x0[t - L] */
        const size_t e = b < 2u * L ? b : 2u * L;
        s += p[e - L] - p[a - L];
        a = e;
    }
    if (a < b) { /* xstar[t] = x0[3L - 1 - t] */
        s += p[3u * L - a] - p[3u * L - b];
    }
    return s;
}

/* One start of MTOTVAR and HTOTVAR (SP 1065 eqs. 27 and 29; Howe & Vernotte
 * 1999): the L = 3m values v_0 .. v_{L-1} (phase for MTOT, frequency for
 * HTOT; with diff, v_k = x_{k+1} - x_k), less the line through the means of
 * their first and last halves (floor(L / 2) values each, the middle one left
 * out when L is odd; their centres are ceil(L / 2) apart), extended to 9m
 * values by uninverted even reflection; returns the mean over its 6m starts
 * of the squared second difference of m-sample averages. p: 11m + 1 doubles
 * of workspace (the prefix sums, then the 8m block sums). */
static double tot_window(const double *x, int diff, size_t m, double *p)
{
    const size_t L = 3u * m, h = L / 2u;
    const double v0 = diff ? x[1] - x[0] : x[0];
    double *b = p + L + 1u, slope, md = (double)m, sum = 0.0;
    size_t k, j;
    p[0] = 0.0;
    for (k = 0; k < L; k++) { /* prefix sums of v_k - v_0 (the offset cancels in every difference) */
        const double v = diff ? x[k + 1u] - x[k] : x[k];
        p[k + 1u] = p[k] + (v - v0);
    }
    slope = ((p[L] - p[L - h]) - (p[h] - p[0])) / (double)h / (double)(L - h);
    for (k = 1; k <= L; k++) { /* detrend: x0_k = v_k - v_0 - slope k; sum over l < k of l is k (k - 1) / 2 */
        p[k] -= slope * 0.5 * (double)k * (double)(k - 1u);
    }
    for (j = 0; j < 8u * m; j++) { /* the m-sample sums of xstar starting at j */
        b[j] = xstar_sum(p, L, j, j + m);
    }
    for (j = 0; j < 2u * L; j++) {
        const double d = (b[j] - 2.0 * b[j + m] + b[j + 2u * m]) / md;
        sum += d * d;
    }
    return sum / (6.0 * md);
}

/* MTOTVAR (diff 0, phase windows, n - 3m + 1 starts) or HTOTVAR (diff 1,
 * frequency windows, n - 3m starts) as the mean of tot_window() over the
 * starts, in the unit of y squared: MTOTVAR = mean / (2 m^2), HTOTVAR = mean / 6. */
static double totvar_family(const double *x, size_t n, size_t m, int diff, uint32_t *terms)
{
    const size_t nt = n - 3u * m + (diff ? 0u : 1u); /* 3m <= n - diff checked by the caller */
    double *p = malloc((11u * m + 1u) * sizeof *p), sum = 0.0;
    size_t i;
    if (p == NULL) {
        return (double)NAN;
    }
    for (i = 0; i < nt; i++) {
        sum += tot_window(x + i, diff, m, p);
    }
    free(p);
    *terms = (uint32_t)nt;
    return diff ? sum / (6.0 * (double)nt) : sum / (2.0 * (double)m * (double)m * (double)nt);
}

double hx_dev_var_record(hx_dev_t k, const double *x, size_t n, uint32_t m_u, uint32_t *terms)
{
    const size_t m = (size_t)m_u;
    *terms = 0u;
    if (x == NULL || m == 0u) {
        return (double)NAN;
    }
    switch (k) {
    case HX_DEV_ADEV:
    case HX_DEV_OADEV: return hx_allan_avar_record(x, n, m_u, k == HX_DEV_OADEV, terms);
    /* the record's length against the span of one term, without forming k m (no overflow) */
    case HX_DEV_MDEV:
    case HX_DEV_TDEV: return m <= n / 3u ? mvar(x, n, m, terms) : (double)NAN;
    case HX_DEV_HDEV:
    case HX_DEV_OHDEV:
        return n > 0u && m <= (n - 1u) / 3u ? hvar(x, n, m, k == HX_DEV_HDEV ? m : 1u, terms) : (double)NAN;
    case HX_DEV_TOTDEV: return n >= 3u && m <= (n - 1u) / 2u ? totvar(x, n, m, terms) : (double)NAN;
    case HX_DEV_PDEV:
        if (n == 0u || m > (n - 1u) / 2u) {
            return (double)NAN;
        }
        return m == 1u ? hx_allan_avar_record(x, n, 1u, 1, terms) : pvar(x, n, m, terms);
    case HX_DEV_MTOTDEV:
    case HX_DEV_TTOTDEV: return m <= n / 3u ? totvar_family(x, n, m, 0, terms) : (double)NAN;
    case HX_DEV_HTOTDEV:
        if (n == 0u || m > (n - 1u) / 3u) {
            return (double)NAN;
        }
        /* at m = 1 the overlapping Hadamard variance (SP 1065: "for best consistency") */
        return m == 1u ? hvar(x, n, 1u, 1u, terms) : totvar_family(x, n, m, 1, terms);
    default: return (double)NAN;
    }
}

uint64_t hx_dev_work(hx_dev_t k, size_t n, uint32_t m)
{
    const uint64_t m3 = 3u * (uint64_t)m;
    switch (k) {
    case HX_DEV_MTOTDEV:
    case HX_DEV_TTOTDEV: return m > 0u && m3 <= n ? ((uint64_t)n - m3 + 1u) * 2u * m3 : 0u;
    case HX_DEV_HTOTDEV: return m > 1u && m3 + 1u <= n ? ((uint64_t)n - m3) * 2u * m3 : 0u;
    default: return 0u;
    }
}

double hx_dev_scale(hx_dev_t k, uint32_t m, double rate_hz)
{
    return k == HX_DEV_TDEV || k == HX_DEV_TTOTDEV ? (double)m / rate_hz / sqrt(3.0) : 1.0;
}

double hx_dev_edf(hx_dev_t k, int alpha, uint32_t m, size_t n)
{
    /* SP 1065 Table 7, TOTVAR: edf = b T / tau - c, rows alpha = 0, -1, -2 */
    static const double tot[3][2] = { { 1.50, 0.0 }, { 1.17, 0.22 }, { 0.93, 0.36 } };
    /* SP 1065 Table 8, MTOTVAR (and TTOT): edf = b T / tau - c, rows alpha = 2 .. -2 */
    static const double mtot[5][2] = { { 1.90, 2.10 }, { 1.20, 1.40 }, { 1.10, 1.20 }, { 0.85, 0.50 }, { 0.75, 0.31 } };
    const uint32_t np = n > UINT32_MAX ? UINT32_MAX : (uint32_t)n;
    switch (k) {
    case HX_DEV_ADEV:
    case HX_DEV_OADEV: return fnav_allan_edf_var(alpha, 2, 0, m, np, k == HX_DEV_OADEV);
    case HX_DEV_MDEV:
    case HX_DEV_TDEV: return fnav_allan_edf_var(alpha, 2, 1, m, np, 1);
    case HX_DEV_HDEV:
    case HX_DEV_OHDEV: return fnav_allan_edf_var(alpha, 3, 0, m, np, k == HX_DEV_OHDEV);
    case HX_DEV_TOTDEV:
        if (alpha > 0) {
            return fnav_allan_edf_var(alpha, 2, 0, m, np, 1);
        }
        if (alpha < -2 || m == 0u) {
            return -1.0;
        }
        return tot[-alpha][0] * (double)n / (double)m - tot[-alpha][1];
    case HX_DEV_PDEV: return fnav_allan_edf_pvar(alpha, m, np);
    case HX_DEV_MTOTDEV:
    case HX_DEV_TTOTDEV:
        if (alpha > 2 || alpha < -2 || m == 0u) {
            return -1.0;
        }
        return mtot[2 - alpha][0] * (double)n / (double)m - mtot[2 - alpha][1];
    case HX_DEV_HTOTDEV:
        /* no published EDF at hand: the overlapping Hadamard variance's, which
         * the total form only raises (a conservative interval; docs/allan.md) */
        return fnav_allan_edf_var(alpha, 3, 0, m, np, 1);
    default: return -1.0;
    }
}
