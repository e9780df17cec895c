/* Frequency-stability deviations of a whole phase record (hx_devs.h). */
#include "hx_devs.h"

#include <math.h>
#include <string.h>

#include "footnav/fnav_allan.h"
#include "hx_allan_ident.h"

static const struct {
    const char *name, *title;
} k_dev[HX_DEV_COUNT] = {
    { "adev", "Allan" },       { "oadev", "Overlapping Allan" }, { "mdev", "Modified Allan" }, { "tdev", "Time" },
    { "hdev", "Hadamard" },    { "ohdev", "Overlapping Hadamard" }, { "totdev", "Total" }, { "pdev", "Parabolic" },
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
    default: return (double)NAN;
    }
}

double hx_dev_scale(hx_dev_t k, uint32_t m, double rate_hz)
{
    return k == HX_DEV_TDEV ? (double)m / rate_hz / sqrt(3.0) : 1.0;
}

double hx_dev_edf(hx_dev_t k, int alpha, uint32_t m, size_t n)
{
    /* SP 1065 Table 7, TOTVAR: edf = b T / tau - c, rows alpha = 0, -1, -2 */
    static const double tot[3][2] = { { 1.50, 0.0 }, { 1.17, 0.22 }, { 0.93, 0.36 } };
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
    default: return -1.0;
    }
}
