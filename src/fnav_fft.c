/* Radix-2 FFT (see fnav_fft.h). Cooley-Tukey decimation in time, iterative,
 * bit-reversed input order; the real transform is the usual split of an
 * N-point real sequence into an N/2-point complex one (e.g. Oppenheim &
 * Schafer, "Discrete-Time Signal Processing", 3rd ed., problem 9.51). */
#include "footnav/fnav_fft.h"

/* A table fnav_fft_init made: n a power of two in 4..FNAV_FFT_MAX_N (one
 * never initialised is zeroed, n = 0). */
static int table_ok(const fnav_fft_t *f)
{
    return f->n >= 4u && f->n <= FNAV_FFT_MAX_N && (f->n & (f->n - 1u)) == 0u;
}

/* fnav_fft_cos_sin_2pi without its argument checks: n > 0 */
static void cos_sin_2pi(uint32_t k, uint32_t n, fnav_real_t *c, fnav_real_t *s)
{
    const fnav_real_t two_pi = FNAV_R(6.283185307179586476925);
    uint32_t x = k % n;
    fnav_real_t sgn_s = FNAV_R(1.0), sgn_c = FNAV_R(1.0), cc, ss;
    int swap = 0;
    if ((n & 7u) == 0u) {
        const uint32_t h = n / 2u, q = n / 4u, e = n / 8u;
        if (x >= h) { /* angle in [pi, 2 pi): sin negative, cos even */
            x = n - x;
            sgn_s = -sgn_s;
        }
        if (x > q) { /* (pi/2, pi]: cos negative */
            x = h - x;
            sgn_c = -sgn_c;
        }
        if (x > e) { /* (pi/4, pi/2]: swap sine and cosine */
            x = q - x;
            swap = 1;
        }
    } else if (2u * x > n) {
        x = n - x;
        sgn_s = -sgn_s;
    }
    cc = fnav_cos(two_pi * (fnav_real_t)x / (fnav_real_t)n);
    ss = fnav_sin(two_pi * (fnav_real_t)x / (fnav_real_t)n);
    *c = sgn_c * (swap ? ss : cc);
    *s = sgn_s * (swap ? cc : ss);
}

fnav_status_t fnav_fft_cos_sin_2pi(uint32_t k, uint32_t n, fnav_real_t *c, fnav_real_t *s)
{
    if (c == NULL || s == NULL || n == 0u) {
        return FNAV_E_ARG; /* n = 0 divided by zero (k % n) */
    }
    cos_sin_2pi(k, n, c, s);
    return FNAV_OK;
}

fnav_status_t fnav_fft_init_tagged(fnav_fft_t *f, uint32_t n, uint64_t build_tag, size_t obj_size)
{
    uint32_t k;
    if (build_tag != FNAV_BUILD_TAG || obj_size != sizeof(fnav_fft_t)) {
        return FNAV_E_BUILD; /* the caller's objects have another layout: write nothing */
    }
    if (f == NULL) {
        return FNAV_E_ARG;
    }
    if (n < 4u || n > FNAV_FFT_MAX_N || (n & (n - 1u)) != 0u) {
        return FNAV_E_CONFIG;
    }
    f->n = n;
    f->reserved = 0;
    for (k = 0; k < n / 2u; k++) {
        cos_sin_2pi(k, n, &f->cs[k], &f->sn[k]);
    }
    return FNAV_OK;
}

fnav_status_t fnav_fft_complex(const fnav_fft_t *f, fnav_real_t *re, fnav_real_t *im, uint32_t m)
{
    uint32_t i, j, len;
    if (f == NULL || re == NULL || im == NULL) {
        return FNAV_E_ARG;
    }
    if (!table_ok(f)) {
        return FNAV_E_STATE;
    }
    /* an m not a power of two ran the butterflies past its m entries; one
     * above n (fnav_fft.h allows n / 2) made the table's stride 0, every
     * twiddle of that stage 1 */
    if (m < 2u || m > f->n / 2u || (m & (m - 1u)) != 0u) {
        return FNAV_E_SIZE;
    }
    /* bit-reversal permutation */
    for (i = 1, j = 0; i < m; i++) {
        uint32_t bit = m >> 1;
        for (; (j & bit) != 0u; bit >>= 1) {
            j ^= bit;
        }
        j ^= bit;
        if (i < j) {
            fnav_real_t t = re[i];
            re[i] = re[j];
            re[j] = t;
            t = im[i];
            im[i] = im[j];
            im[j] = t;
        }
    }
    /* first stage: butterflies with twiddle 1 */
    for (i = 0; i + 1u < m; i += 2u) {
        const fnav_real_t ar = re[i], ai = im[i], br = re[i + 1u], bi = im[i + 1u];
        re[i] = ar + br;
        im[i] = ai + bi;
        re[i + 1u] = ar - br;
        im[i + 1u] = ai - bi;
    }
    for (len = 4u; len <= m; len <<= 1) {
        const uint32_t half = len >> 1;
        const uint32_t step = f->n / len; /* e^(-2 pi i j / len) = table[j * n / len] */
        for (i = 0; i < m; i += len) {
            fnav_real_t *r0 = re + i, *i0 = im + i, *r1 = re + i + half, *i1 = im + i + half;
            uint32_t t = 0;
            for (j = 0; j < half; j++, t += step) {
                const fnav_real_t wr = f->cs[t], wi = -f->sn[t];
                const fnav_real_t xr = r1[j] * wr - i1[j] * wi;
                const fnav_real_t xi = r1[j] * wi + i1[j] * wr;
                r1[j] = r0[j] - xr;
                i1[j] = i0[j] - xi;
                r0[j] += xr;
                i0[j] += xi;
            }
        }
    }
    return FNAV_OK;
}

fnav_status_t fnav_fft_real_packed(const fnav_fft_t *f, fnav_real_t *re, fnav_real_t *im)
{
    uint32_t m, k;
    fnav_status_t st;
    if (f == NULL) {
        return FNAV_E_ARG;
    }
    /* checks re, im and the table (n = 0, never initialised, sent the
     * split loop below to k < 0 - k, past every array) */
    m = f->n / 2u;
    st = fnav_fft_complex(f, re, im, m);
    if (st != FNAV_OK) {
        return st;
    }
    /* X_k = E_k + W^k O_k, E_k = (Z_k + conj Z_{m-k}) / 2, O_k = (Z_k - conj Z_{m-k}) / 2i,
     * W = e^(-2 pi i / n); pairs (k, m - k) are done together, in place. */
    {
        const fnav_real_t z0r = re[0], z0i = im[0];
        re[0] = z0r + z0i;
        im[0] = FNAV_R(0.0);
        re[m] = z0r - z0i;
        im[m] = FNAV_R(0.0);
    }
    for (k = 1; k < m - k; k++) {
        const uint32_t q = m - k;
        const fnav_real_t ar = re[k], ai = im[k], br = re[q], bi = im[q];
        /* E_k, O_k and E_q = conj E_k, O_q = conj O_k */
        const fnav_real_t er = FNAV_R(0.5) * (ar + br), ei = FNAV_R(0.5) * (ai - bi);
        const fnav_real_t or_ = FNAV_R(0.5) * (ai + bi), oi = FNAV_R(-0.5) * (ar - br);
        const fnav_real_t wr = f->cs[k], wi = -f->sn[k];   /* W^k */
        const fnav_real_t tr = wr * or_ - wi * oi, ti = wr * oi + wi * or_;
        re[k] = er + tr;
        im[k] = ei + ti;
        /* X_q = E_q + W^q O_q = conj(E_k) - conj(W^k O_k) because W^q = -conj(W^k) */
        re[q] = er - tr;
        im[q] = ti - ei;
    }
    if (k == m - k) {
        im[k] = -im[k]; /* X_{m/2} = conj Z_{m/2} */
    }
    return FNAV_OK;
}
