/* Streaming fixed-memory Allan deviation (see fnav_allan.h, docs/allan.md). */
#include "footnav/fnav_allan.h"
#include "footnav/fnav_port.h"

#include <string.h>

#define RING0_MASK (FNAV_ALLAN_RING0 - 1u)

const fnav_allan_config_t fnav_allan_config_default = { NULL, 0 };

/* Kahan (compensated) summation: s - c carries the sum to about twice the
 * working precision (Higham, "Accuracy and Stability of Numerical
 * Algorithms", 2nd ed., sec. 4.3). */
static inline void kahan_add(fnav_real_t *s, fnav_real_t *c, fnav_real_t v)
{
    const fnav_real_t y = v - *c;
    const fnav_real_t t = *s + y;
    *c = (t - *s) - y;
    *s = t;
}

/* Level of a valid tau: 0 when it fits the full-rate ring, else the lowest
 * cascade level j with tau / 2^j <= L (then tau / 2^j is in (L/2, L]).
 * Returns -1 when tau cannot be represented. */
static int tau_level(uint32_t tau)
{
    int j;
    if (tau == 0u || (unsigned long)tau > FNAV_ALLAN_TAU_MAX) {
        return -1;
    }
    if (tau <= FNAV_ALLAN_TAU_FULL_MAX) {
        return 0;
    }
    for (j = FNAV_ALLAN_LEVEL_FIRST; j <= FNAV_ALLAN_LEVEL_LAST; j++) {
        if ((tau >> j) <= FNAV_ALLAN_CASCADE_LAG) {
            return ((tau & ((1u << j) - 1u)) == 0u) ? j : -1;
        }
    }
    return -1;
}

int fnav_allan_tau_valid(uint32_t tau)
{
    return tau_level(tau) >= 0;
}

size_t fnav_allan_grid(uint32_t *tau, size_t max, uint32_t tau_max, unsigned per_octave)
{
    size_t n = 0;
    unsigned p = per_octave <= 1u ? 1u : (per_octave == 2u ? 2u : 4u);
    uint32_t k, i, last = 0;
    if (tau == NULL) {
        return 0;
    }
    if ((unsigned long)tau_max > FNAV_ALLAN_TAU_MAX) {
        tau_max = (uint32_t)FNAV_ALLAN_TAU_MAX;
    }
    /* octave k holds 2^k (p + i) / p, i = 0..p-1; keep the integer ones */
    for (k = 0; k < 32u && n < max; k++) {
        uint64_t base = (uint64_t)1u << k;
        for (i = 0; i < p && n < max; i++) {
            uint64_t num = base * (uint64_t)(p + i);
            uint32_t t;
            if (num % p != 0u) {
                continue;
            }
            if (num / p > (uint64_t)tau_max) {
                return n;
            }
            t = (uint32_t)(num / p);
            if (t > last && fnav_allan_tau_valid(t)) {
                tau[n++] = t;
                last = t;
            }
        }
    }
    return n;
}

fnav_status_t fnav_allan_init_tagged(fnav_allan_t *a, const fnav_allan_config_t *cfg, uint64_t build_tag,
                                     size_t obj_size, size_t cfg_size)
{
    uint32_t grid[FNAV_ALLAN_MAX_POINTS]; /* default grid, 4 bytes per point */
    const uint32_t *tau;
    size_t n, i;
    int l;
    if (build_tag != FNAV_BUILD_TAG || obj_size != sizeof(fnav_allan_t) || cfg_size != sizeof(fnav_allan_config_t)) {
        return FNAV_E_BUILD; /* the caller's objects have another layout: write nothing */
    }
    if (a == NULL) {
        return FNAV_E_ARG;
    }
    memset(a, 0, sizeof *a);
    if (cfg == NULL || cfg->tau == NULL) {
        n = fnav_allan_grid(grid, FNAV_ALLAN_MAX_POINTS, (uint32_t)FNAV_ALLAN_TAU_MAX, 2u);
        tau = grid;
    } else {
        tau = cfg->tau;
        n = cfg->n_tau;
    }
    if (n == 0u || n > FNAV_ALLAN_MAX_POINTS) {
        return FNAV_E_CONFIG;
    }
    for (i = 0; i < n; i++) {
        int lev = tau_level(tau[i]);
        if (lev < 0 || (i > 0 && tau[i] <= tau[i - 1])) {
            memset(a, 0, sizeof *a);
            return FNAV_E_CONFIG;
        }
        a->pt[i].level = (uint8_t)lev;
        a->pt[i].lag = (uint16_t)(tau[i] >> lev);
        if (lev == 0) {
            a->npt0 = (uint8_t)(i + 1u);
            /* a block looks back BLOCK - 1 + 2 lag phase values: must stay in the ring */
            a->pt[i].late = (uint8_t)(2u * tau[i] + FNAV_ALLAN_BLOCK > FNAV_ALLAN_RING0);
        }
    }
    a->npt = (uint8_t)n;
    a->nlate0 = a->npt0;
    for (i = 0; i < a->npt0; i++) {
        if (a->pt[i].late) {
            a->nlate0 = (uint8_t)i;
            break;
        }
    }
    /* x_0 = 0 is the first phase value of every level (ring0 is zeroed) */
    for (l = 0; l < FNAV_ALLAN_NLEVELS; l++) {
        a->wc[l] = 1u;
    }
    return FNAV_OK;
}

/* Shift every phase value of a ring so that it is relative to the current
 * phase: second differences are invariant to a constant, and small values
 * keep the float ring precise however far the phase has drifted. */
static void rebase(fnav_real_t *ring, uint32_t len, fnav_real_t *base, fnav_real_t ph)
{
    const fnav_real_t sh = *base - ph;
    uint32_t i;
    for (i = 0; i < len; i++) {
        ring[i] += sh;
    }
    *base = ph;
}

/* Re-centre the input on the mean of the last RING0 - 1 samples when that
 * mean is further from y_0 than the samples' spread (called when ring0 is
 * full, n = RING0 - 1 mod RING0, so position i holds x_k with k - n = i -
 * (RING0 - 1), and no cascade level is written at this n).
 * y_0 += delta changes every phase value by -delta k, a line, which no second
 * difference sees; every stored value gets the same line, -delta (k - n), so
 * the sums are unchanged. Without it an unrepresentative first sample (a
 * start-up zero) or a drifting mean makes the phase grow by the offset at
 * every sample, and a cascade ring, re-based only when it wraps, spans
 * offset x 17 x 2^j: at 2^17 its float values lose the noise (+3 % ADEV at
 * tau 2^17 on 4.3e6 samples of 9.81 + white noise with a first sample of 0;
 * test_unrepresentative_first_sample). Only beyond the spread: an offset
 * within it is what a representative first sample leaves anyway, and every
 * correction rounds the stored values once more (re-centring at every wrap
 * made test_synthetic_every_level's float error 5 times larger). */
static void recentre(fnav_allan_t *a, uint32_t n)
{
    const uint32_t last = FNAV_ALLAN_RING0 - 1u;
    const fnav_real_t mean = (a->ring0[last] - a->ring0[0]) / (fnav_real_t)last;
    fnav_real_t ss = FNAV_R(0.0), y0, delta;
    uint32_t i, k = 0;
    /* the spread from every 8th sample of the ring (or every one of a ring
     * under 64): enough to compare an offset with, at an eighth of the cost */
    const uint32_t st = FNAV_ALLAN_RING0 >= 64u ? 8u : 1u;
    for (i = st; i <= last; i += st) {
        const fnav_real_t e = (a->ring0[i] - a->ring0[i - 1u]) - mean;
        ss += e * e;
        k++;
    }
    if (!(mean * mean * (fnav_real_t)k > ss)) {
        return;
    }
    y0 = a->y0 + mean;
    delta = y0 - a->y0; /* the step actually taken (exact) */
    for (i = 0; i < FNAV_ALLAN_RING0; i++) {
        a->ring0[i] -= delta * ((fnav_real_t)i - (fnav_real_t)last);
    }
    for (i = 0; i < FNAV_ALLAN_BLOCK; i++) {
        a->ring0[FNAV_ALLAN_RING0 + i] = a->ring0[i];
    }
#if FNAV_ALLAN_NLEVELS > 0
    {
        int l;
        for (l = 0; l < FNAV_ALLAN_NLEVELS; l++) {
            const int j = FNAV_ALLAN_LEVEL_FIRST + l;
            const fnav_real_t step = (fnav_real_t)(1ul << j);
            /* the newest value, index n >> j at the level, sits before wc */
            const fnav_real_t newest = -(fnav_real_t)(n & ((1ul << j) - 1ul));
            fnav_real_t *ring = a->ringc[l];
            uint32_t p = a->wc[l], d;
            for (d = 0; d < FNAV_ALLAN_CASCADE_RING; d++) {
                p = (p == 0u) ? FNAV_ALLAN_CASCADE_RING - 1u : p - 1u;
                ring[p] -= delta * (newest - (fnav_real_t)d * step);
            }
        }
    }
#endif
    a->y0 = y0;
}

/* Level l (= cascade level j) receives the phase x_n, n = k 2^j. */
static void cascade_write(fnav_allan_t *a, int l, int j, uint32_t first, uint32_t end)
{
    fnav_real_t *ring = a->ringc[l];
    const uint32_t w = a->wc[l];
    const uint32_t k = a->n >> j; /* newest phase index at this level */
    const fnav_real_t x = (a->ph - a->basec[l]) - a->pc;
    uint32_t i;
    ring[w] = x;
    for (i = first; i < end; i++) {
        fnav_allan_point_t *p = &a->pt[i];
        const uint32_t m = p->lag;
        uint32_t i1, i2;
        fnav_real_t d, q;
        if (k < 2u * m) {
            break; /* lags ascend within a level */
        }
        i1 = (w >= m) ? w - m : w + FNAV_ALLAN_CASCADE_RING - m;
        i2 = (w >= 2u * m) ? w - 2u * m : w + FNAV_ALLAN_CASCADE_RING - 2u * m;
        d = (x + ring[i2]) - FNAV_R(2.0) * ring[i1];
        q = d * d;
        kahan_add(&p->so, &p->co, q);
        if (k % m == 0u) {
            /* start index k - 2m is a multiple of m: a non-overlapping term */
            kahan_add(&p->sn, &p->cn, q);
        }
    }
    if (w + 1u == FNAV_ALLAN_CASCADE_RING) {
        a->wc[l] = 0u;
        rebase(ring, FNAV_ALLAN_CASCADE_RING, &a->basec[l], a->ph);
    } else {
        a->wc[l] = (uint8_t)(w + 1u);
    }
}

/* Second difference ending at full-rate phase index e (in the ring). */
static inline fnav_real_t diff0(const fnav_allan_t *a, uint32_t e, uint32_t m)
{
    return (a->ring0[e & RING0_MASK] + a->ring0[(e - 2u * m) & RING0_MASK]) -
           FNAV_R(2.0) * a->ring0[(e - m) & RING0_MASK];
}

/* Sum of squared second differences of lag m ending at e = lo..hi with
 * stride st (1: overlapping terms; m: non-overlapping ones, lo a multiple of
 * m), e >= 2m, general ring indexing. */
static fnav_real_t terms0(const fnav_allan_t *a, uint32_t m, uint32_t lo, uint32_t hi, uint32_t st)
{
    fnav_real_t s = FNAV_R(0.0);
    uint64_t e; /* e + st passes 2^32 near the count's end: no wrap back below hi */
    if (lo < 2u * m) {
        lo = 2u * m;
    }
    for (e = lo; e <= hi; e += st) {
        const fnav_real_t d = diff0(a, (uint32_t)e, m);
        s += d * d;
    }
    return s;
}

/* First multiple of m that is >= lo, or UINT32_MAX when it lies beyond
 * (above every end index: the count stops at 2^32 - 2 samples). In 32 bits
 * lo + m - 1 would wrap to a small number near the end, and the
 * non-overlapping sums would take in about 2^32 / m terms of stale ring
 * values (13 times the variance), or never return. */
static inline uint32_t next_multiple(uint32_t lo, uint32_t m)
{
    const uint32_t r = lo % m, add = r == 0u ? 0u : m - r;
    return lo > UINT32_MAX - add ? UINT32_MAX : lo + add;
}

/* The rare work of a push lives out of line so that the common push stays
 * a handful of instructions without register spills. */

/* A block of end indices e = n - BLOCK + 1 .. n has completed (n + 1 a
 * multiple of BLOCK, so the block is aligned in the ring and, thanks to the
 * repeated head of the ring, every lagged run of 32 reads is contiguous). */
static void block0(fnav_allan_t *a, uint32_t n)
{
    const uint32_t e0 = n + 1u - FNAV_ALLAN_BLOCK;
    const fnav_real_t *x0 = &a->ring0[e0 & RING0_MASK];
    uint32_t i;
    for (i = 0; i < a->nlate0; i++) {
        fnav_allan_point_t *p = &a->pt[i];
        const uint32_t m = p->lag;
        fnav_real_t so, sn = FNAV_R(0.0);
        if (n < 2u * m) {
            break; /* lags ascend: no later point has a term yet */
        }
        if (e0 >= 2u * m) {
            const fnav_real_t *x1 = &a->ring0[(e0 - m) & RING0_MASK];
            const fnav_real_t *x2 = &a->ring0[(e0 - 2u * m) & RING0_MASK];
            fnav_real_t s0 = FNAV_R(0.0), s1 = FNAV_R(0.0), s2 = FNAV_R(0.0), s3 = FNAV_R(0.0);
            uint32_t k;
            for (k = 0; k < FNAV_ALLAN_BLOCK; k += 4u) {
                /* x_e - 2 x_{e-m} + x_{e-2m} = m (ybar_2 - ybar_1): four
                 * isomorphic lanes, which the compiler turns into vector code */
                const fnav_real_t d0 = (x0[k] + x2[k]) - FNAV_R(2.0) * x1[k];
                const fnav_real_t d1 = (x0[k + 1u] + x2[k + 1u]) - FNAV_R(2.0) * x1[k + 1u];
                const fnav_real_t d2 = (x0[k + 2u] + x2[k + 2u]) - FNAV_R(2.0) * x1[k + 2u];
                const fnav_real_t d3 = (x0[k + 3u] + x2[k + 3u]) - FNAV_R(2.0) * x1[k + 3u];
                s0 += d0 * d0;
                s1 += d1 * d1;
                s2 += d2 * d2;
                s3 += d3 * d3;
            }
            so = (s0 + s1) + (s2 + s3);
            /* non-overlapping: end indices that are multiples of m */
            if (m == 1u) {
                sn = so;
            } else {
                for (k = (m - e0 % m) % m; k < FNAV_ALLAN_BLOCK; k += m) {
                    const fnav_real_t d = (x0[k] + x2[k]) - FNAV_R(2.0) * x1[k];
                    sn += d * d;
                }
            }
        } else {
            so = terms0(a, m, e0, n, 1u); /* the first terms of this point */
            sn = terms0(a, m, next_multiple(e0, m), n, m);
        }
        kahan_add(&p->so, &p->co, so);
        kahan_add(&p->sn, &p->cn, sn);
    }
}

static FNAV_NOINLINE void push_rare(fnav_allan_t *a, uint32_t n, uint32_t w)
{
    uint32_t i;
    /* level-0 points too long for blocks: every push */
    for (i = a->nlate0; i < a->npt0; i++) {
        fnav_allan_point_t *p = &a->pt[i];
        const uint32_t m = p->lag;
        fnav_real_t dd;
        if (n < 2u * m) {
            break;
        }
        dd = diff0(a, n, m);
        kahan_add(&p->so, &p->co, dd * dd);
        if (n % m == 0u) {
            kahan_add(&p->sn, &p->cn, dd * dd);
        }
    }
    if (((n + 1u) & (FNAV_ALLAN_BLOCK - 1u)) == 0u) {
        block0(a, n);
    }
    if (w == FNAV_ALLAN_RING0 - 1u) {
        /* the ring is full of values relative to base0: re-base them all,
         * and re-centre the input on the ring's mean */
        recentre(a, n);
        rebase(a->ring0, FNAV_ALLAN_RING0 + FNAV_ALLAN_BLOCK, &a->base0, a->ph);
    }
#if FNAV_ALLAN_NLEVELS > 0
    if ((n & ((1u << FNAV_ALLAN_LEVEL_FIRST) - 1u)) == 0u) {
        int l;
        uint32_t first = a->npt0;
        for (l = 0; l < FNAV_ALLAN_NLEVELS; l++) {
            const int j = FNAV_ALLAN_LEVEL_FIRST + l;
            uint32_t end = first;
            if ((n & ((1u << j) - 1u)) != 0u) {
                break;
            }
            while (end < a->npt && a->pt[end].level == (uint8_t)j) {
                end++;
            }
            cascade_write(a, l, j, first, end);
            first = end;
        }
    }
#endif
}

fnav_status_t fnav_allan_push(fnav_allan_t *a, fnav_real_t y)
{
    fnav_real_t d, t, x;
    uint32_t w, n;
    if (a == NULL) {
        return FNAV_E_ARG;
    }
    if (!(fnav_fabs(y) <= FNAV_REAL_MAX)) {
        return FNAV_E_NANINF; /* NaN fails the comparison too */
    }
    if (fnav_fabs(y) > (fnav_real_t)FNAV_INPUT_MAX_ABS) {
        return FNAV_E_RANGE; /* its squares would overflow the sums */
    }
    n = a->n;
    if (n >= UINT32_MAX - 1u) {
        /* 2^32 - 2 samples: their 2^32 - 1 phase values are the most
         * fnav_allan_result_t.n_phase holds */
        return FNAV_E_RANGE;
    }
    if (n == 0u) {
        if (a->npt == 0u) {
            /* never initialised (zeroed, as static storage is) or its init
             * failed: an initialised estimator tracks at least one tau.
             * Checked here, where only the first sample comes, so that the
             * common push pays nothing for it */
            return FNAV_E_STATE;
        }
        a->y0 = y;
    }
    /* phase x_n = x_{n-1} + (y - y0), Kahan-compensated */
    d = (y - a->y0) - a->pc;
    t = a->ph + d;
    a->pc = (t - a->ph) - d;
    a->ph = t;
    a->n = ++n;

    x = (t - a->base0) - a->pc;
    w = n & RING0_MASK;
    a->ring0[w] = x;
    if (w < FNAV_ALLAN_BLOCK) {
        a->ring0[w + FNAV_ALLAN_RING0] = x; /* the repeated head */
    }
    if ((((n + 1u) & (FNAV_ALLAN_BLOCK - 1u)) == 0u) | ((n & ((1u << FNAV_ALLAN_LEVEL_FIRST) - 1u)) == 0u) |
        (a->nlate0 < a->npt0)) {
        push_rare(a, n, w);
    }
    return FNAV_OK;
}

size_t fnav_allan_count(const fnav_allan_t *a)
{
    return a != NULL ? a->npt : 0u;
}

uint32_t fnav_allan_samples(const fnav_allan_t *a)
{
    return a != NULL ? a->n : 0u;
}

fnav_status_t fnav_allan_get(const fnav_allan_t *a, size_t i, fnav_allan_result_t *out)
{
    const fnav_allan_point_t *p;
    uint32_t k, m;
    fnav_real_t tau, so, sn;
    if (a == NULL || out == NULL) {
        return FNAV_E_ARG;
    }
    if (a->npt == 0u) {
        return FNAV_E_STATE; /* never initialised, or its init failed */
    }
    if (i >= a->npt) {
        return FNAV_E_ARG;
    }
    p = &a->pt[i];
    m = p->lag;
    k = a->n >> p->level; /* phase values at the level: k + 1 */
    out->level = p->level;
    out->stride = 1u << p->level;
    out->lag = m;
    out->tau = m << p->level;
    out->n_phase = k + 1u;
    out->terms = (k >= 2u * m) ? k + 1u - 2u * m : 0u;
    out->terms_nonoverlap = (k >= 2u * m) ? k / m - 1u : 0u;
    tau = (fnav_real_t)out->tau;
    so = p->so - p->co;
    sn = p->sn - p->cn;
    if (p->level == 0u && !p->late && a->n % FNAV_ALLAN_BLOCK != FNAV_ALLAN_BLOCK - 1u) {
        /* the terms of the block in progress: end indices lo .. n */
        const uint32_t lo = a->n - a->n % FNAV_ALLAN_BLOCK;
        so += terms0(a, m, lo, a->n, 1u);
        sn += terms0(a, m, next_multiple(lo, m), a->n, m);
    }
    out->avar = out->terms > 0u ? so / (FNAV_R(2.0) * tau * tau * (fnav_real_t)out->terms) : (fnav_real_t)NAN;
    out->avar_nonoverlap = out->terms_nonoverlap > 0u
                               ? sn / (FNAV_R(2.0) * tau * tau * (fnav_real_t)out->terms_nonoverlap)
                               : (fnav_real_t)NAN;
    return FNAV_OK;
}

/* ------------------------------------------------------------ noise type */

fnav_allan_noise_t fnav_allan_noise_from_slope(fnav_real_t slope)
{
    if (!fnav_isfinite(slope)) {
        return FNAV_ALLAN_NOISE_UNKNOWN;
    }
    if (slope < FNAV_R(-0.75)) {
        return FNAV_ALLAN_NOISE_QUANT;
    }
    if (slope < FNAV_R(-0.25)) {
        return FNAV_ALLAN_NOISE_WHITE;
    }
    if (slope < FNAV_R(0.25)) {
        return FNAV_ALLAN_NOISE_FLICKER;
    }
    if (slope < FNAV_R(0.75)) {
        return FNAV_ALLAN_NOISE_RRW;
    }
    return FNAV_ALLAN_NOISE_RAMP;
}

const char *fnav_allan_noise_name(fnav_allan_noise_t t)
{
    switch (t) {
    case FNAV_ALLAN_NOISE_QUANT: return "quantisation";
    case FNAV_ALLAN_NOISE_WHITE: return "white";
    case FNAV_ALLAN_NOISE_FLICKER: return "flicker";
    case FNAV_ALLAN_NOISE_RRW: return "rate-random-walk";
    case FNAV_ALLAN_NOISE_RAMP: return "ramp";
    case FNAV_ALLAN_NOISE_UNKNOWN: break;
    }
    return "unknown";
}

int fnav_allan_noise_alpha(fnav_allan_noise_t t)
{
    switch (t) {
    case FNAV_ALLAN_NOISE_QUANT: return 2;
    case FNAV_ALLAN_NOISE_FLICKER: return -1;
    case FNAV_ALLAN_NOISE_RRW: /* fall through: a ramp is not a power law; use the nearest */
    case FNAV_ALLAN_NOISE_RAMP: return -2;
    case FNAV_ALLAN_NOISE_WHITE:
    case FNAV_ALLAN_NOISE_UNKNOWN: break;
    }
    return 0;
}

static int usable(const fnav_allan_result_t *r)
{
    return r->terms > 0u && fnav_isfinite(r->avar) && r->avar > FNAV_R(0.0);
}

void fnav_allan_slopes(const fnav_allan_result_t *r, size_t n, fnav_real_t *slope)
{
    size_t i;
    if (r == NULL || slope == NULL) {
        return;
    }
    for (i = 0; i < n; i++) {
        fnav_real_t sx = FNAV_R(0.0), sy = FNAV_R(0.0), sxx = FNAV_R(0.0), sxy = FNAV_R(0.0), cnt = FNAV_R(0.0);
        size_t k, lo = i > 0 ? i - 1 : 0, hi = i + 1 < n ? i + 1 : i;
        slope[i] = (fnav_real_t)NAN;
        if (!usable(&r[i])) {
            continue;
        }
        for (k = lo; k <= hi; k++) {
            fnav_real_t lx, ly;
            if (!usable(&r[k])) {
                continue;
            }
            /* log tau and log ADEV relative to point i (a line's slope
             * ignores the shift): the logs themselves (ln tau up to 14)
             * made cnt sxx - sx^2 cancel and lost 1e-3 of the slope in
             * float */
            lx = fnav_log((fnav_real_t)r[k].tau / (fnav_real_t)r[i].tau);
            ly = FNAV_R(0.5) * fnav_log(r[k].avar / r[i].avar);
            sx += lx;
            sy += ly;
            sxx += lx * lx;
            sxy += lx * ly;
            cnt += FNAV_R(1.0);
        }
        if (cnt >= FNAV_R(2.0)) {
            const fnav_real_t den = cnt * sxx - sx * sx;
            if (den > FNAV_R(0.0)) {
                slope[i] = (cnt * sxy - sx * sy) / den;
            }
        }
    }
}

/* ------------------------------------------------------------ EDF */
/* Greenhall & Riley (PTTI 2003), eqs. (7)-(10) and tables 1-3, for the
 * d-th difference variances (d = 1, 2: Allan, 3: Hadamard), unmodified
 * (filter factor F = m, INFINITY for its large-m limit) or modified (F = 1),
 * with stride factor S (m overlapping, 1 non-overlapping). */

#define EDF_JMAX 100.0

static double gh_sw(double t, int alpha)
{
    const double at = fabs(t);
    switch (alpha) {
    case 2: return -at;
    case 1: return at > 0.0 ? t * t * log(at) : 0.0;
    case 0: return at * at * at;
    case -1: return at > 0.0 ? t * t * t * t * log(at) : 0.0;
    case -2: return at * at * at * at * at;
    case -3: return at > 0.0 ? t * t * t * t * t * t * log(at) : 0.0;
    case -4: return at * at * at * at * at * at * at;
    default: return 0.0;
    }
}

static double gh_sx(double t, double F, int alpha)
{
    if (isinf(F)) {
        return gh_sw(t, alpha + 2);
    }
    return F * F * (2.0 * gh_sw(t, alpha) - gh_sw(t - 1.0 / F, alpha) - gh_sw(t + 1.0 / F, alpha));
}

/* eq. (9): sz(t) = sum over k = -d..d of (-1)^k C(2d, d + k) sx(t + k);
 * d = 2 gives the weights 6, -4, -4, 1, 1 */
static double gh_sz(double t, double F, int alpha, int d)
{
    static const double binom[4][4] = { { 1, 0, 0, 0 }, { 2, 1, 0, 0 }, { 6, 4, 1, 0 }, { 20, 15, 6, 1 } };
    double s = binom[d][0] * gh_sx(t, F, alpha), sign = -1.0;
    int k;
    for (k = 1; k <= d; k++) {
        s += sign * binom[d][k] * (gh_sx(t - (double)k, F, alpha) + gh_sx(t + (double)k, F, alpha));
        sign = -sign;
    }
    return s;
}

static double gh_basic_sum(double J, double M, double S, double F, int alpha, int d)
{
    double s = gh_sz(0.0, F, alpha, d), sum;
    const long jn = (long)J; /* J is a whole number (<= EDF_JMAX) */
    long j;
    sum = s * s;
    s = gh_sz(J / S, F, alpha, d);
    sum += (1.0 - J / M) * s * s;
    for (j = 1; j < jn; j++) {
        s = gh_sz((double)j / S, F, alpha, d);
        sum += 2.0 * (1.0 - (double)j / M) * s * s;
    }
    return sum;
}

/* C(2d, d + k) for d = 1..3, |k| <= d. */
static double binom_2d(int d, int k)
{
    double c = 1.0;
    int i;
    const int n = 2 * d, j = d + (k < 0 ? -k : k);
    for (i = 1; i <= n - j; i++) {
        c = c * (double)(j + i) / (double)i;
    }
    return c;
}

double fnav_allan_edf_var(int alpha, int d, int modified, uint32_t m_u, uint32_t n_phase, int overlapping)
{
    /* Table 1 (modified, F = 1) and table 2 (unmodified, large m): (a0, a1)
     * for rows alpha = 2 .. -4 and columns d = 1, 2, 3; 0, 0 where the
     * variance does not converge (alpha + 2 d <= 1) */
    static const double t1[7][3][2] = {
        { { 2.0 / 3.0, 1.0 / 3.0 }, { 7.0 / 9.0, 0.5 }, { 22.0 / 25.0, 2.0 / 3.0 } },
        { { 0.840, 0.345 }, { 0.997, 0.616 }, { 1.141, 0.843 } },
        { { 1.079, 0.368 }, { 1.033, 0.607 }, { 1.184, 0.848 } },
        { { 0, 0 }, { 1.048, 0.534 }, { 1.180, 0.816 } },
        { { 0, 0 }, { 1.302, 0.535 }, { 1.175, 0.777 } },
        { { 0, 0 }, { 0, 0 }, { 1.194, 0.703 } },
        { { 0, 0 }, { 0, 0 }, { 1.489, 0.702 } },
    };
    static const double t2[7][3][2] = {
        { { 1.5, 0.5 }, { 35.0 / 18.0, 1.0 }, { 231.0 / 100.0, 1.5 } },
        { { 78.6, 25.2 }, { 790.0, 410.0 }, { 9950.0, 6520.0 } },
        { { 2.0 / 3.0, 1.0 / 6.0 }, { 2.0 / 3.0, 1.0 / 3.0 }, { 7.0 / 9.0, 0.5 } },
        { { 0, 0 }, { 0.852, 0.375 }, { 0.997, 0.617 } },
        { { 0, 0 }, { 1.079, 0.368 }, { 1.033, 0.607 } },
        { { 0, 0 }, { 0, 0 }, { 1.053, 0.553 } },
        { { 0, 0 }, { 0, 0 }, { 1.302, 0.535 } },
    };
    /* Table 3 (unmodified, alpha = 1): b0, b1 for d = 1, 2, 3 */
    static const double t3[3][2] = { { 6.0, 4.0 }, { 15.23, 12.0 }, { 47.8, 40.0 } };
    const double dd = (double)d, m = (double)m_u, N = (double)n_phase;
    const double F = modified ? 1.0 : m;
    const double S = overlapping ? m : 1.0;
    const double L = m / F + m * dd;
    double M, J, r, inv;
    const double *a;
    if (d < 1 || d > 3 || alpha > 2 || alpha + 2 * d <= 1 || m_u == 0u || N < L) {
        return -1.0; /* N = L: one difference, M = 1 */
    }
    M = 1.0 + floor(S * (N - L) / m);
    J = M < (dd + 1.0) * S ? M : (dd + 1.0) * S;
    r = M / S;
    if (modified) {
        /* case 1: every alpha */
        a = t1[2 - alpha][d - 1];
        if (J <= EDF_JMAX) {
            const double z0 = gh_sz(0.0, 1.0, alpha, d);
            inv = gh_basic_sum(J, M, S, 1.0, alpha, d) / (z0 * z0 * M);
        } else if (r > dd + 1.0) {
            inv = (1.0 / r) * (a[0] - a[1] / r);
        } else {
            const double z0 = gh_sz(0.0, 1.0, alpha, d);
            inv = gh_basic_sum(EDF_JMAX, EDF_JMAX, EDF_JMAX / r, 1.0, alpha, d) / (z0 * z0 * EDF_JMAX);
        }
    } else if (alpha <= 0 || alpha == 2) {
        /* case 2 (alpha <= 0) and, through the basic sum, case 4 (alpha = 2) */
        a = t2[2 - alpha][d - 1];
        if (J <= EDF_JMAX) {
            const double mp = (alpha == 2 || m * (dd + 1.0) <= EDF_JMAX) ? m : (double)INFINITY;
            const double z0 = gh_sz(0.0, mp, alpha, d);
            inv = gh_basic_sum(J, M, S, mp, alpha, d) / (z0 * z0 * M);
        } else if (alpha == 2) {
            /* case 4: K = ceil(r); the table's form holds for K > d only.
             * With K <= d (fewer terms than the averaging factor: they share
             * no sample) 1/edf = (1/M) sum over |k| < K of (1 - |k|/r)
             * (C(2d, d+k) / C(2d, d))^2; the table's form gives an EDF above
             * M (1,096 against 952 at m = 1024 of 3,000 phase values) or
             * none */
            const double K = ceil(r);
            if (K > dd) {
                inv = (1.0 / M) * (a[0] - a[1] / r);
            } else {
                const double c0 = binom_2d(d, 0);
                int k;
                inv = 1.0;
                for (k = 1; (double)k < K; k++) {
                    const double c = binom_2d(d, k) / c0;
                    inv += 2.0 * (1.0 - (double)k / r) * c * c;
                }
                inv /= M;
            }
        } else if (r > dd + 1.0) {
            inv = (1.0 / r) * (a[0] - a[1] / r);
        } else {
            const double mp = EDF_JMAX / r;
            const double z0 = gh_sz(0.0, (double)INFINITY, alpha, d);
            inv = gh_basic_sum(EDF_JMAX, EDF_JMAX, mp, (double)INFINITY, alpha, d) / (z0 * z0 * EDF_JMAX);
        }
    } else {
        /* case 3, alpha = 1 */
        const double b = t3[d - 1][0] + t3[d - 1][1] * log(m);
        a = t2[1][d - 1];
        if (J <= EDF_JMAX) {
            const double z0 = gh_sz(0.0, m, 1, d);
            inv = gh_basic_sum(J, M, S, m, 1, d) / (z0 * z0 * M);
        } else if (r > dd + 1.0) {
            inv = (1.0 / (b * b * r)) * (a[0] - a[1] / r);
        } else {
            const double mp = EDF_JMAX / r;
            inv = gh_basic_sum(EDF_JMAX, EDF_JMAX, mp, mp, 1, d) / (b * b * EDF_JMAX);
        }
    }
    return inv > 0.0 ? 1.0 / inv : -1.0;
}

/* PVAR: R(t) = sum over tau of q(tau) sx(t + tau), q the autocorrelation of
 * the taps (symmetric, q[0 .. 2m - 1] for tau >= 0), sx the phase's
 * sample-averaged generalized autocovariance (gh_sx() with F = 1, t in
 * samples). */
#define EDF_PVAR_MMAX 64u

static double pvar_r(const double *q, uint32_t len, double t, int alpha)
{
    double r = q[0] * gh_sx(t, 1.0, alpha);
    uint32_t k;
    for (k = 1; k < len; k++) {
        r += q[k] * (gh_sx(t + (double)k, 1.0, alpha) + gh_sx(t - (double)k, 1.0, alpha));
    }
    return r;
}

/* Tap k of the PVAR filter of length 2 mp: (mp - 1) / 2 - k on the first
 * half, its negative (of k - mp) on the second. */
static double pvar_tap(uint32_t k, uint32_t mp)
{
    const double c = 0.5 * (double)(mp - 1u) - (double)(k % mp);
    return k < mp ? c : -c;
}

double fnav_allan_edf_pvar(int alpha, uint32_t m_u, uint32_t n_phase)
{
    double q[2u * EDF_PVAR_MMAX] = { 0.0 };
    const uint32_t mp = m_u > EDF_PVAR_MMAX ? EDF_PVAR_MMAX : m_u, len = 2u * mp;
    double M, J, step, r0, sum, r;
    uint32_t k, i, j, jn;
    if (alpha > 2 || alpha < -2 || m_u == 0u || n_phase < 3u || m_u > (n_phase - 1u) / 2u) {
        return -1.0;
    }
    if (m_u == 1u) {
        return fnav_allan_edf_var(alpha, 2, 0, 1u, n_phase, 1);
    }
    for (k = 0; k < len; k++) { /* q starts at zero */
        for (i = 0; i + k < len; i++) {
            q[k] += pvar_tap(i, mp) * pvar_tap(i + k, mp);
        }
    }
    M = (double)(n_phase - 2u * m_u);
    J = M < 3.0 * (double)m_u ? M : 3.0 * (double)m_u;
    step = (double)mp / (double)m_u; /* one lag of m in lags of mp */
    if (J > 3.0 * (double)EDF_PVAR_MMAX) {
        /* more lags than m = 64 has: the sum on mp's own lag grid */
        M *= step;
        J = floor(M < 3.0 * (double)mp ? M : 3.0 * (double)mp);
        step = 1.0;
    }
    jn = (uint32_t)J;
    r0 = pvar_r(q, len, 0.0, alpha);
    r = jn > 0u ? pvar_r(q, len, (double)jn * step, alpha) : 0.0;
    sum = r0 * r0 + (1.0 - (double)jn / M) * r * r;
    for (j = 1; j < jn; j++) {
        r = pvar_r(q, len, (double)j * step, alpha);
        sum += 2.0 * (1.0 - (double)j / M) * r * r;
    }
    return sum > 0.0 && r0 != 0.0 ? M * r0 * r0 / sum : -1.0;
}

double fnav_allan_edf(int alpha, uint32_t m_u, uint32_t n_phase, int overlapping)
{
    return alpha < -2 ? -1.0 : fnav_allan_edf_var(alpha, 2, 0, m_u, n_phase, overlapping);
}

/* ------------------------------------------------------------ paper id */

fnav_status_t fnav_allan_identify_paper(const fnav_allan_result_t *r, size_t n, fnav_real_t rate_hz,
                                        uint32_t tau_max, fnav_allan_paper_id_t *id)
{
    size_t i, imin = 0, nvalid = 0, lo = n, hi = n;
    fnav_real_t best = FNAV_REAL_MAX, one_s;
    if (r == NULL || id == NULL || !(rate_hz > FNAV_R(0.0)) || !fnav_isfinite(rate_hz)) {
        return FNAV_E_ARG;
    }
    one_s = rate_hz; /* 1 s in samples */
    for (i = 0; i < n; i++) {
        if (!usable(&r[i])) {
            continue;
        }
        nvalid++;
        if ((fnav_real_t)r[i].tau <= one_s) {
            lo = i;
        }
        if ((fnav_real_t)r[i].tau >= one_s && hi == n) {
            hi = i;
        }
        if ((tau_max == 0u || r[i].tau <= tau_max) && r[i].avar < best) {
            best = r[i].avar;
            imin = i;
        }
    }
    if (nvalid < 2u || lo == n || hi == n || best == FNAV_REAL_MAX) {
        return FNAV_E_RANGE;
    }
    /* sigma_v: ADEV at 1 s, interpolated in log-log (section III.C.1) */
    if (lo == hi) {
        id->sigma_v = fnav_sqrt(r[lo].avar);
    } else {
        const fnav_real_t x0 = fnav_log((fnav_real_t)r[lo].tau), x1 = fnav_log((fnav_real_t)r[hi].tau);
        const fnav_real_t y0 = FNAV_R(0.5) * fnav_log(r[lo].avar), y1 = FNAV_R(0.5) * fnav_log(r[hi].avar);
        const fnav_real_t u = (fnav_log(one_s) - x0) / (x1 - x0);
        id->sigma_v = fnav_exp(y0 + u * (y1 - y0));
    }
    /* BS and t_BS: the minimum, refined by a parabola in log-log through the
     * minimum grid point and its neighbours when both are usable */
    {
        fnav_real_t lt = fnav_log((fnav_real_t)r[imin].tau), la = FNAV_R(0.5) * fnav_log(r[imin].avar);
        if (imin > 0 && imin + 1 < n && usable(&r[imin - 1]) && usable(&r[imin + 1]) &&
            (tau_max == 0u || r[imin + 1].tau <= tau_max)) {
            const fnav_real_t x0 = fnav_log((fnav_real_t)r[imin - 1].tau), x2 = fnav_log((fnav_real_t)r[imin + 1].tau);
            const fnav_real_t y0 = FNAV_R(0.5) * fnav_log(r[imin - 1].avar);
            const fnav_real_t y2 = FNAV_R(0.5) * fnav_log(r[imin + 1].avar);
            /* divided differences of the parabola through (x0,y0), (lt,la), (x2,y2) */
            const fnav_real_t d1 = (la - y0) / (lt - x0), d2 = (y2 - la) / (x2 - lt);
            const fnav_real_t c2 = (d2 - d1) / (x2 - x0);
            if (c2 > FNAV_R(0.0)) {
                fnav_real_t xv = FNAV_R(0.5) * (x0 + lt) - d1 / (FNAV_R(2.0) * c2);
                xv = fnav_clamp(xv, x0, x2);
                la = y0 + d1 * (xv - x0) + c2 * (xv - x0) * (xv - lt);
                lt = xv;
            }
        }
        id->bs = fnav_exp(la);
        id->tau_samples = fnav_exp(lt); /* eq. (5): tau = t_BS f_s */
        id->t_bs_s = id->tau_samples / rate_hz;
        id->sigma_bias = id->bs / fnav_sqrt(id->tau_samples); /* eq. (6) */
        id->i_min = (uint32_t)imin;
    }
    return FNAV_OK;
}
