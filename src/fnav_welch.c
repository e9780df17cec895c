/* Streaming Welch PSD and the lowest usable sampling frequency
 * (see fnav_welch.h, docs/psd.md). */
#include "footnav/fnav_welch.h"

#include <string.h>

const fnav_welch_config_t fnav_welch_config_default = {
    64u, 32u, FNAV_WINDOW_HAMMING, 0, FNAV_DETREND_CONSTANT, FNAV_SCALING_DENSITY, FNAV_R(1.0), FNAV_R(0.0)
};

const fnav_bandwidth_config_t fnav_bandwidth_config_default = { FNAV_R(0.95), FNAV_R(50.0), 0 };

static inline void kahan_add(fnav_real_t *s, fnav_real_t *c, fnav_real_t v)
{
    const fnav_real_t y = v - *c;
    const fnav_real_t t = *s + y;
    *c = (t - *s) - y;
    *s = t;
}

fnav_status_t fnav_welch_init_tagged(fnav_welch_t *w, const fnav_welch_config_t *cfg, uint64_t build_tag,
                                     size_t obj_size, size_t cfg_size)
{
    const fnav_welch_config_t *c = cfg != NULL ? cfg : &fnav_welch_config_default;
    fnav_welch_config_t cc;
    uint32_t i;
    /* compensated sums in fnav_real_t (Kahan): double ones were soft-float
     * calls on the Cortex-M4F, 1,260 bytes of the firmware image for this
     * one init (make firmware: 46,048 -> 44,788; test_psd.sh) */
    fnav_real_t s1 = FNAV_R(0.0), s1c = FNAV_R(0.0), s2 = FNAV_R(0.0), s2c = FNAV_R(0.0);
    fnav_real_t w1r = FNAV_R(0.0), w1rc = FNAV_R(0.0), w1i = FNAV_R(0.0), w1ic = FNAV_R(0.0);
    if (build_tag != FNAV_BUILD_TAG || obj_size != sizeof(fnav_welch_t) || cfg_size != sizeof(fnav_welch_config_t)) {
        return FNAV_E_BUILD; /* the caller's objects have another layout: write nothing */
    }
    if (w == NULL) {
        return FNAV_E_ARG;
    }
    if (c->nfft < 8u || c->nfft > FNAV_WELCH_MAX_NFFT || (c->nfft & (c->nfft - 1u)) != 0u ||
        c->overlap >= c->nfft || (unsigned)c->window > (unsigned)FNAV_WINDOW_RECT ||
        (unsigned)c->detrend > (unsigned)FNAV_DETREND_GLOBAL ||
        (c->detrend == FNAV_DETREND_GLOBAL && c->symmetric) || (unsigned)c->scaling > (unsigned)FNAV_SCALING_SPECTRUM ||
        !(c->rate_hz > FNAV_R(0.0)) || !fnav_isfinite(c->rate_hz) || !(fnav_fabs(c->offset) <= (fnav_real_t)FNAV_INPUT_MAX_ABS) ||
        /* the density scale 1 / (f_s sum w^2) finite and positive: sum w^2
         * is at least nfft / 4 for every window (3 / 8 for Hann), so
         * f_s nfft and 4 / (f_s nfft) finite suffice (a float rate of
         * 1e-40 Hz gave every density Inf, one of 3e38 Hz every one 0;
         * test_welch test_config_and_bad_input) */
        !fnav_isfinite(c->rate_hz * (fnav_real_t)c->nfft) ||
        !fnav_isfinite(FNAV_R(4.0) / (c->rate_hz * (fnav_real_t)c->nfft))) {
        return FNAV_E_CONFIG;
    }
    /* through a copy: cfg may be w's own (a reset, fnav_welch_init(&w,
     * &w.cfg)), which the memset clears; c then reads the one kept in w */
    cc = *c;
    memset(w, 0, sizeof *w);
    w->cfg = cc;
    c = &w->cfg;
    if (fnav_fft_init(&w->fft, c->nfft) != FNAV_OK) {
        return FNAV_E_CONFIG;
    }
    for (i = 0; i < c->nfft; i++) {
        /* periodic: L = N (DFT-even, scipy get_window); symmetric: L = N - 1 */
        const uint32_t L = c->symmetric ? c->nfft - 1u : c->nfft;
        fnav_real_t cph, sph, c1, s1i;
        /* L >= 7 and nfft >= 8 here: FNAV_OK */
        if (fnav_fft_cos_sin_2pi(i, L, &cph, &sph) != FNAV_OK ||
            fnav_fft_cos_sin_2pi(i, c->nfft, &c1, &s1i) != FNAV_OK) {
            return FNAV_E_CONFIG;
        }
        switch (c->window) {
        case FNAV_WINDOW_HAMMING: w->win[i] = FNAV_R(0.54) - FNAV_R(0.46) * cph; break;
        case FNAV_WINDOW_HANN: w->win[i] = FNAV_R(0.5) - FNAV_R(0.5) * cph; break;
        default: w->win[i] = FNAV_R(1.0); break;
        }
        kahan_add(&s1, &s1c, w->win[i]);
        kahan_add(&s2, &s2c, w->win[i] * w->win[i]);
        /* W_1 = sum w_n e^(-2 pi i n / N) */
        kahan_add(&w1r, &w1rc, w->win[i] * c1);
        kahan_add(&w1i, &w1ic, -(w->win[i] * s1i));
    }
    w->s1 = s1 - s1c;
    w->s2 = s2 - s2c;
    w->w1r = w1r - w1rc;
    w->w1i = w1i - w1ic;
    return FNAV_OK;
}

/* One segment: the last nfft samples of the ring, oldest first. */
static void segment(fnav_welch_t *w)
{
    const uint32_t n = w->cfg.nfft, h = n / 2u;
    const fnav_real_t *x = w->ring;
    fnav_real_t *re = w->re, *im = w->im;
    fnav_real_t a = FNAV_R(0.0), b = FNAV_R(0.0), x0 = FNAV_R(0.0);
    uint32_t i, p;
    if (w->cfg.detrend == FNAV_DETREND_CONSTANT || w->cfg.detrend == FNAV_DETREND_LINEAR) {
        fnav_real_t sum = FNAV_R(0.0), sxy = FNAV_R(0.0);
        const fnav_real_t c = FNAV_R(0.5) * (fnav_real_t)(n - 1u);
        /* sums about the segment's first sample: with gravity on the axis a
         * float sum of the raw samples rounds the mean at the size of the
         * signal left after it (bin 0 of a 4096-sample segment off by
         * 1.4 %, test_segment_mean_large_offset) */
        x0 = x[w->pos];
        for (i = 0, p = w->pos; i < n; i++) {
            const fnav_real_t v = x[p] - x0;
            sum += v;
            sxy += ((fnav_real_t)i - c) * v;
            p = (p + 1u == n) ? 0u : p + 1u;
        }
        a = sum / (fnav_real_t)n; /* the segment mean, less x0 */
        if (w->cfg.detrend == FNAV_DETREND_LINEAR) {
            /* least-squares slope about the centre: sum (i - c)^2 = n (n^2 - 1) / 12 */
            const fnav_real_t nn = (fnav_real_t)n;
            b = sxy / (nn * (nn * nn - FNAV_R(1.0)) / FNAV_R(12.0));
            a -= b * c; /* line a + b i */
        }
    }
    /* detrend, window and pack: re[k] = x[2k], im[k] = x[2k+1] */
    for (i = 0, p = w->pos; i < h; i++) {
        const fnav_real_t i0 = (fnav_real_t)(2u * i);
        const fnav_real_t v0 = x[p];
        fnav_real_t v1;
        p = (p + 1u == n) ? 0u : p + 1u;
        v1 = x[p];
        p = (p + 1u == n) ? 0u : p + 1u;
        re[i] = ((v0 - x0) - (a + b * i0)) * w->win[(size_t)2u * i];
        im[i] = ((v1 - x0) - (a + b * (i0 + FNAV_R(1.0)))) * w->win[(size_t)2u * i + 1u];
    }
    if (fnav_fft_real_packed(&w->fft, re, im) != FNAV_OK) {
        return; /* never: the table is the one fnav_welch_init made */
    }
    if (w->cfg.detrend == FNAV_DETREND_GLOBAL) {
        /* compensated: global_fix subtracts terms of the size of these sums */
        kahan_add(&w->x0, &w->x0c, re[0]);
        kahan_add(&w->x1r, &w->x1rc, re[1]);
        kahan_add(&w->x1i, &w->x1ic, im[1]);
    }
    for (i = 0; i <= h; i++) {
        kahan_add(&w->acc[i], &w->accc[i], re[i] * re[i] + im[i] * im[i]);
    }
    w->nseg++;
}

/* GLOBAL, once, before the first segment: move the shift from the first
 * sample to the first segment's mean. global_fix takes the record's mean mu
 * (relative to the shift) out of bins 0 and 1 as sum |X_k|^2 - 2 mu Re(..)
 * + K mu^2 |W_k|^2, which cancels terms of K mu^2 |W_k|^2 against the noise
 * power: with the first sample as the shift, mu is of the size of one
 * sample's noise; with a segment's mean, of that over sqrt(nfft). Only
 * samples of the first segment have been pushed (nsamples == nfft). */
static void recentre(fnav_welch_t *w)
{
    const uint32_t n = w->cfg.nfft;
    fnav_real_t m = FNAV_R(0.0);
    uint32_t i;
    for (i = 0; i < n; i++) {
        m += w->ring[i];
    }
    m /= (fnav_real_t)n;
    w->shift += m;
    w->gs = FNAV_R(0.0);
    w->gc = FNAV_R(0.0);
    for (i = 0; i < n; i++) {
        w->ring[i] -= m;
        kahan_add(&w->gs, &w->gc, w->ring[i]);
    }
}

fnav_status_t fnav_welch_push(fnav_welch_t *w, fnav_real_t x)
{
    uint32_t n;
    if (w == NULL) {
        return FNAV_E_ARG;
    }
    n = w->cfg.nfft;
    if (n == 0u) {
        return FNAV_E_STATE; /* never initialised (zeroed, as static storage is) */
    }
    if (!fnav_isfinite(x)) {
        return FNAV_E_NANINF;
    }
    if (fnav_fabs(x) > (fnav_real_t)FNAV_INPUT_MAX_ABS) {
        return FNAV_E_RANGE; /* its square would overflow the periodogram */
    }
    if (w->nsamples == UINT32_MAX) {
        /* the counts are full: a further segment would wrap nseg (hop 1),
         * and the GLOBAL mean needs the count of what gs sums */
        return FNAV_E_RANGE;
    }
    if (w->cfg.detrend == FNAV_DETREND_GLOBAL) {
        /* the first sample becomes a fixed shift (any constant cancels in
         * the global-mean correction) so that the sums stay small */
        if (w->nsamples == 0u) {
            w->shift = x - w->cfg.offset;
        }
        kahan_add(&w->gs, &w->gc, (x - w->cfg.offset) - w->shift);
    }
    w->ring[w->pos] = (x - w->cfg.offset) - w->shift;
    /* >=, not ==: the index can never run past the ring (n >= 1 here: an
     * estimator never initialised was refused above) */
    w->pos = (w->pos + 1u >= n) ? 0u : w->pos + 1u;
    w->nsamples++;
    if (w->fill < n) {
        w->fill++;
        if (w->fill == n) {
            if (w->cfg.detrend == FNAV_DETREND_GLOBAL) {
                recentre(w);
            }
            segment(w);
            w->since = 0;
        }
        return FNAV_OK;
    }
    if (++w->since == n - w->cfg.overlap) {
        segment(w);
        w->since = 0;
    }
    return FNAV_OK;
}

uint32_t fnav_welch_segments(const fnav_welch_t *w)
{
    return w != NULL ? w->nseg : 0u;
}

uint32_t fnav_welch_bins(const fnav_welch_t *w)
{
    return w != NULL && w->cfg.nfft > 0u ? w->cfg.nfft / 2u + 1u : 0u; /* 0: never initialised */
}

fnav_real_t fnav_welch_freq(const fnav_welch_t *w, uint32_t k)
{
    if (w == NULL || w->cfg.nfft == 0u) {
        return FNAV_R(0.0); /* as bins and segments answer 0 for NULL */
    }
    return (fnav_real_t)k * w->cfg.rate_hz / (fnav_real_t)w->cfg.nfft;
}

/* Scale of bin k: one-sided (x2 except DC and Nyquist), density or spectrum. */
static fnav_real_t bin_scale(const fnav_welch_t *w, uint32_t k)
{
    const uint32_t h = w->cfg.nfft / 2u;
    const fnav_real_t base = w->cfg.scaling == FNAV_SCALING_DENSITY ? FNAV_R(1.0) / (w->cfg.rate_hz * w->s2)
                                                                    : FNAV_R(1.0) / (w->s1 * w->s1);
    return (k == 0u || k == h) ? base : FNAV_R(2.0) * base;
}

/* Mean of the samples so far (after offset and shift), for GLOBAL. */
static fnav_real_t global_mean(const fnav_welch_t *w)
{
    return w->nsamples > 0u ? (w->gs - w->gc) / (fnav_real_t)w->nsamples : FNAV_R(0.0);
}

/* Sum over segments of |X_k - mu W_k|^2 from the sums kept (k = 0, 1; the
 * periodic window's DFT is zero beyond): sum |X_k|^2 - 2 mu Re(conj(W_k) sum X_k)
 * + K mu^2 |W_k|^2. */
static fnav_real_t global_fix(const fnav_welch_t *w, uint32_t k, fnav_real_t acc)
{
    const fnav_real_t mu = global_mean(w), K = (fnav_real_t)w->nseg;
    fnav_real_t v;
    if (k == 0u) {
        v = acc - FNAV_R(2.0) * mu * w->s1 * (w->x0 - w->x0c) + K * mu * mu * w->s1 * w->s1;
    } else if (k == 1u) {
        v = acc - FNAV_R(2.0) * mu * (w->w1r * (w->x1r - w->x1rc) + w->w1i * (w->x1i - w->x1ic)) +
            K * mu * mu * (w->w1r * w->w1r + w->w1i * w->w1i);
    } else {
        return acc;
    }
    return v > FNAV_R(0.0) ? v : FNAV_R(0.0);
}

/* The checks fnav_welch_get and fnav_welch_last share: FNAV_OK with the
 * number of bins in *nb; FNAV_E_ARG, FNAV_E_SIZE (out shorter than the
 * bins) or FNAV_E_STATE (no segment yet). */
static fnav_status_t out_check(const fnav_welch_t *w, const fnav_real_t *out, size_t n_out, uint32_t *nb)
{
    if (w == NULL || out == NULL) {
        return FNAV_E_ARG;
    }
    *nb = fnav_welch_bins(w);
    if (n_out < *nb) {
        return FNAV_E_SIZE;
    }
    if (w->nseg == 0u) {
        return FNAV_E_STATE;
    }
    return FNAV_OK;
}

fnav_status_t fnav_welch_get(const fnav_welch_t *w, fnav_real_t *out, size_t n_out)
{
    uint32_t k, nb = 0u;
    fnav_real_t inv;
    const fnav_status_t st = out_check(w, out, n_out, &nb);
    if (st != FNAV_OK) {
        return st;
    }
    inv = FNAV_R(1.0) / (fnav_real_t)w->nseg;
    for (k = 0; k < nb; k++) {
        fnav_real_t a = w->acc[k] - w->accc[k];
        if (w->cfg.detrend == FNAV_DETREND_GLOBAL) {
            a = global_fix(w, k, a);
        }
        out[k] = a * inv * bin_scale(w, k);
    }
    return FNAV_OK;
}

fnav_status_t fnav_welch_last(const fnav_welch_t *w, fnav_real_t *out, size_t n_out)
{
    uint32_t k, nb = 0u;
    const fnav_status_t st = out_check(w, out, n_out, &nb);
    if (st != FNAV_OK) {
        return st;
    }
    for (k = 0; k < nb; k++) {
        fnav_real_t r = w->re[k], i = w->im[k];
        if (w->cfg.detrend == FNAV_DETREND_GLOBAL && k <= 1u) {
            const fnav_real_t mu = global_mean(w);
            r -= mu * (k == 0u ? w->s1 : w->w1r);
            i -= mu * (k == 0u ? FNAV_R(0.0) : w->w1i);
        }
        out[k] = (r * r + i * i) * bin_scale(w, k);
    }
    return FNAV_OK;
}

fnav_status_t fnav_welch_bandwidth(const fnav_real_t *psd, size_t n, fnav_real_t df_hz,
                                   const fnav_bandwidth_config_t *cfg, fnav_bandwidth_t *out, fnav_real_t *ccdf)
{
    const fnav_bandwidth_config_t *c = cfg != NULL ? cfg : &fnav_bandwidth_config_default;
    const size_t k0 = c->exclude_dc ? 1u : 0u;
    const fnav_real_t fmax = (fnav_real_t)(n - 1u) * df_hz;
    fnav_real_t total = FNAV_R(0.0), comp = FNAV_R(0.0), target, cum = FNAV_R(0.0);
    size_t k;
    int found = 0;
    if (psd == NULL || out == NULL || n < 2u || !(df_hz > FNAV_R(0.0)) || !(c->threshold > FNAV_R(0.0)) ||
        !(c->threshold <= FNAV_R(1.0)) || !(c->round_hz >= FNAV_R(0.0)) || !fnav_isfinite(c->round_hz)) {
        return FNAV_E_ARG;
    }
    for (k = 0; k < n; k++) {
        if (!(psd[k] >= FNAV_R(0.0))) {
            return FNAV_E_RANGE; /* a density is never negative (nor NaN), bin 0 included */
        }
        if (k >= k0) {
            kahan_add(&total, &comp, psd[k] * df_hz); /* power in bin k: P_k df (Parseval) */
        }
    }
    total -= comp;
    if (!(total > FNAV_R(0.0)) || !fnav_isfinite(total)) {
        return FNAV_E_RANGE;
    }
    out->total = total;
    target = c->threshold * total;
    comp = FNAV_R(0.0);
    out->bandwidth_hz = fmax;
    for (k = 0; k < n; k++) {
        const fnav_real_t lo = k == 0u ? FNAV_R(0.0) : ((fnav_real_t)k - FNAV_R(0.5)) * df_hz;
        const fnav_real_t hi = k + 1u == n ? fmax : ((fnav_real_t)k + FNAV_R(0.5)) * df_hz;
        const fnav_real_t p = k < k0 ? FNAV_R(0.0) : psd[k] * df_hz;
        const fnav_real_t before = cum - comp;
        kahan_add(&cum, &comp, p);
        if (!found && cum - comp >= target) {
            const fnav_real_t frac = p > FNAV_R(0.0) ? (target - before) / p : FNAV_R(1.0);
            out->bandwidth_hz = lo + fnav_clamp(frac, FNAV_R(0.0), FNAV_R(1.0)) * (hi - lo);
            found = 1;
        }
        if (ccdf != NULL) {
            const fnav_real_t r = FNAV_R(1.0) - (cum - comp) / total;
            ccdf[k] = r > FNAV_R(0.0) ? r : FNAV_R(0.0);
        }
    }
    out->fs_hz = FNAV_R(2.0) * out->bandwidth_hz;
    out->fs_rounded_hz = out->fs_hz;
    if (c->round_hz > FNAV_R(0.0)) {
        /* a step so small that the quotient overflows rounds nothing (it gave Inf) */
        const fnav_real_t q = out->fs_hz / c->round_hz;
        if (fnav_isfinite(q)) {
            out->fs_rounded_hz = fnav_ceil(q) * c->round_hz;
        }
    }
    return FNAV_OK;
}
