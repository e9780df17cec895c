/**
 * @file fnav_cm_time.h
 * @brief Time stamps from a board's counters, for fnav_cm_imu_read() (or
 *        any read_sample): the core wants int64 ns that never go back
 *        (fnav_sample_t.t_ns), while a board has a 32-bit microsecond timer
 *        (wraps every 71.6 min), an IMU's 16-bit FIFO time stamp (wraps
 *        every 65.536 ms at 1 us) or one interrupt stamp per FIFO batch.
 *        docs/firmware.md, "Time stamps from a board".
 *
 * Header only (static inline): nothing of it is in an image that does not
 * call it. Portable C; not ISR-safe per object: one fnav_cm_unwrap_t per
 * counter, used from one context (the sample-ready interrupt, typically).
 */
#ifndef FNAV_CM_TIME_H
#define FNAV_CM_TIME_H

#include "footnav/fnav_types.h"

/** Extends a free-running counter of 1..32 bits to 64 bits. */
typedef struct {
    uint32_t mask;  /**< 2^bits - 1: 0xffffffff for a 32-bit timer, 0xffff for a 16-bit FIFO stamp */
    uint32_t last;  /**< last raw reading (masked) */
    int64_t ext;    /**< its extended value, counter ticks */
    int started;    /**< a reading was taken */
} fnav_cm_unwrap_t;

/** Start an unwrapper for a counter whose readings are masked by @p mask
 *  (2^bits - 1). */
static inline void fnav_cm_unwrap_init(fnav_cm_unwrap_t *u, uint32_t mask)
{
    u->mask = mask;
    u->last = 0u;
    u->ext = 0;
    u->started = 0;
}

/** Extended value of the raw reading @p raw, in counter ticks (multiply by
 *  the tick in ns: 1000 for a microsecond timer). The first reading is its
 *  own value. A reading up to half the counter's period ahead of the
 *  previous one is read as that far ahead (across a wrap when it is
 *  smaller); one less than half a period behind as that far behind, so a
 *  back-dated stamp stays behind (the core rejects it, FNAV_E_TIME) instead
 *  of turning into a jump of a whole period ahead. So read the counter at
 *  least every half period (35.8 min for a 32-bit us timer, 32.8 ms for a
 *  16-bit 1-us FIFO stamp: consecutive FIFO samples are far closer); longer
 *  apart, whole periods are lost without a trace. */
static inline int64_t fnav_cm_unwrap(fnav_cm_unwrap_t *u, uint32_t raw)
{
    raw &= u->mask;
    if (!u->started) {
        u->started = 1;
        u->ext = (int64_t)raw;
    } else {
        const int64_t period = (int64_t)u->mask + 1;
        int64_t d = (int64_t)((raw - u->last) & u->mask); /* ahead, modulo the period */
        if (d > period / 2) {
            d -= period; /* behind (half a period is ahead; mask 0: always 0) */
        }
        u->ext += d;
    }
    u->last = raw;
    return u->ext;
}

/** Stamp of sample @p i (0 oldest) of a FIFO batch of @p n read at one
 *  interrupt stamped @p t_irq_ns, the batch's last sample being the
 *  interrupt's: the batch is spread evenly over the interval since the
 *  previous batch's last stamp @p t_prev_ns, so every sample has its own
 *  interval (one stamp for the whole batch makes n - 1 duplicates, which the
 *  core does not propagate, and makes the estimated rate n times too low),
 *  and the interrupt's latency jitter moves each interval by jitter / n,
 *  never behind the previous batch. The stamps never go back, and they repeat
 *  only when the batch spans fewer nanoseconds than it has samples
 *  (t_irq_ns - t_prev_ns < n: fewer distinct stamps than samples fit in the
 *  interval; sample i gets t_prev_ns + floor(span (i + 1) / n)). When the interval is longer than
 *  2 n @p period_ns (the nominal sample interval; samples were lost before
 *  the batch: a FIFO overflow, a stall), the batch is stamped back from
 *  t_irq_ns at period_ns, so the core sees the gap where the samples were
 *  lost (period_ns 0: always spread). t_irq_ns not after t_prev_ns, i >= n
 *  or n = 0: t_prev_ns (a duplicate, never a stamp behind). */
static inline int64_t fnav_cm_batch_stamp(int64_t t_prev_ns, int64_t t_irq_ns, uint32_t i, uint32_t n,
                                          int64_t period_ns)
{
    uint64_t span, q, r, x;
    if (n == 0u || i >= n || !(t_irq_ns > t_prev_ns)) {
        return t_prev_ns;
    }
    /* unsigned: no int64 overflow for any stamps or period (t_irq - t_prev,
     * span (i + 1) and 2 period_ns overflowed on extreme ones) */
    span = (uint64_t)t_irq_ns - (uint64_t)t_prev_ns;
    q = span / n;
    r = span % n;
    if (period_ns > 0 && (q > 2u * (uint64_t)period_ns || (q == 2u * (uint64_t)period_ns && r > 0u))) {
        /* span > 2 n period_ns: then (n - 1 - i) period_ns < span / 2 */
        return t_irq_ns - (int64_t)(n - 1u - i) * period_ns;
    }
    x = q * (i + 1u) + r * (i + 1u) / n; /* floor(span (i + 1) / n) <= span; r (i + 1) < 2^64 */
    if (x > (uint64_t)INT64_MAX) {
        t_prev_ns += INT64_MAX; /* t_prev_ns < 0 here */
        x -= (uint64_t)INT64_MAX;
    }
    return t_prev_ns + (int64_t)x;
}

/* ---- counter ticks to ns without a 64-bit division ---- */

/** floor(c 1e9 / hz) for counter values c in [0, c_max], precomputed by
 *  fnav_cm_ns_scale_init(). 8 bytes (asserted below): the SysTick time base
 *  keeps it beside its count of periods, and the firmware's RAM
 *  budget counts on that size (docs/firmware.md, "Budget"). */
typedef struct {
    uint32_t mul;            /**< exact: m = ceil(2^k 1e9 / hz); division: hz */
    unsigned int c_max : 24; /**< the largest counter value (SysTick: the reload value); 0 when over 24 bits */
    unsigned int shift : 7;  /**< exact: 32 - k */
    unsigned int exact : 1;  /**< 1: the multiply-shift, 0: the 64-bit division */
} fnav_cm_ns_scale_t;

/* C99 compile-time check: a negative array size if the scale is not 8 bytes */
typedef char fnav_cm_ns_scale_size_check[sizeof(fnav_cm_ns_scale_t) == 8u ? 1 : -1];

/** Precompute floor(c 1e9 / @p hz) for c in [0, @p c_max] (once, at start:
 *  it divides). Granlund & Montgomery, "Division by invariant integers using
 *  multiplication" (PLDI 1994), section 4, with the divisor 1e9 / hz:
 *
 *  Let q = floor(c 1e9 / hz), r = c 1e9 - q hz, m = ceil(2^k 1e9 / hz) and
 *  j = m hz - 2^k 1e9 (0 <= j < hz), so c m / 2^k = q + (r + c j / 2^k) / hz.
 *  With g = gcd(1e9, hz), r is a multiple of g below hz, so r <= hz - g. If
 *  c_max j < 2^k g, then for every c <= c_max,
 *  0 <= r + c j / 2^k < hz - g + g = hz and floor(c m / 2^k) = q: exact.
 *  k is the largest k <= 32 with m < 2^32 (the most precise m; for
 *  hz <= 2 GHz, where k < 32 is not forced by the cap, 2^k >= 2^31 hz / 1e9
 *  > 2000 c_max for SysTick's c_max = hz / 1000 - 1; the code checks
 *  c_max < 2^k in any case).
 *  With c < 2^k (c_max < 2^k is required), c 2^(32 - k) < 2^32 and
 *  floor(c m / 2^k) = floor(c 2^(32 - k) m / 2^32) (< m < 2^32): a shift
 *  and the high word of one 32 x 32 -> 64 multiply (UMULL).
 *
 *  This is the conversion within one SysTick period; the periods' own ns
 *  (reload + 1 clocks each, not 1 ms unless 1000 divides hz) are counted
 *  by fnav_cm_systick_add() below, so that the stamp is exact over any run.
 *  Exact for every clock that divides 1e9 (j = 0) and the usual MCU clocks
 *  (12, 16, 64, 80, 168, 180 MHz, 14.7456 MHz, 2^24 Hz: tests/test_port.c,
 *  test_cm_ns_scale; scripts/ns_scale_search.py). A clock the bound does
 *  not cover (25,000,001 Hz; 1,000,066 Hz, where the multiply-shift alone
 *  is wrong at c = 894), hz = 0, c_max >= 2^24 (hz < 1000 with the reload
 *  wrapped; SysTick's reload has 24 bits) or c_max >= 2^k: the 64-bit
 *  division. */
static inline void fnav_cm_ns_scale_init(fnav_cm_ns_scale_t *s, uint32_t hz, uint32_t c_max)
{
    uint32_t k = 33u, m = 0u;
    s->mul = hz; /* the division */
    s->c_max = c_max <= 0xffffffu ? c_max : 0u; /* the division keeps it for the SysTick stamp's reload */
    s->shift = 0u;
    s->exact = 0u;
    if (hz == 0u || c_max > 0xffffffu) {
        return;
    }
    while (k > 0u) { /* the largest k <= 32 with m < 2^32 */
        uint64_t mm;
        k--;
        mm = ((UINT64_C(1000000000) << k) + hz - 1u) / hz;
        if (mm <= UINT64_C(0xffffffff)) {
            m = (uint32_t)mm;
            break;
        }
    }
    if (m == 0u || (uint64_t)c_max >= (UINT64_C(1) << k)) {
        return;
    }
    {
        const uint64_t j = (uint64_t)m * hz - (UINT64_C(1000000000) << k);
        uint32_t a = 1000000000u, b = hz; /* g = gcd(1e9, hz), Euclid */
        while (b != 0u) {
            const uint32_t t = a % b;
            a = b;
            b = t;
        }
        if ((uint64_t)c_max * j >= ((uint64_t)a << k)) {
            return; /* not provably exact: the division */
        }
    }
    s->mul = m;
    s->c_max = c_max & 0xffffffu; /* <= 0xffffff (above): the mask only says so to -Wconversion */
    s->shift = (32u - k) & 0x7fu;
    s->exact = 1u;
}

/** floor(@p c 1e9 / hz): (int64_t)c * 1000000000 / (int64_t)hz, the same
 *  value for every c in [0, c_max] (@p s from fnav_cm_ns_scale_init(); 0 for
 *  hz 0). On the Cortex-M4, for an exact clock: a shift and a UMULL instead
 *  of a call to __aeabi_ldivmod. A c above c_max (SysTick's counter cannot
 *  read more than its reload: ARMv7-M ARM B3.3) is taken as c_max by the
 *  multiply-shift (the scale does not keep hz), and divided by the
 *  division. */
static inline int64_t fnav_cm_ns_of_ticks(const fnav_cm_ns_scale_t *s, uint32_t c)
{
    if (s->exact) {
        const uint32_t cc = c <= s->c_max ? c : (uint32_t)s->c_max;
        return (int64_t)(uint32_t)(((uint64_t)(cc << s->shift) * s->mul) >> 32); /* cc < 2^k: no bit lost */
    }
    return s->mul == 0u ? 0 : (int64_t)((uint64_t)c * 1000000000u / s->mul); /* unsigned: no sign fix-up */
}

/** The SysTick time base's constants (fnav_cm_systick_scale_init()): one
 *  period, p = reload + 1 core clocks, is tick_ns + tick_rem / hz ns. */
typedef struct {
    fnav_cm_ns_scale_t scale; /**< the counter within a period to ns; c_max: the reload */
    uint32_t hz;              /**< core clock, Hz; 0: not started (every stamp 0) */
    uint32_t tick_ns;         /**< floor(p 1e9 / hz) */
    uint32_t tick_rem;        /**< p 1e9 mod hz */
} fnav_cm_systick_scale_t;

/** Set up @p s for a SysTick counting @p hz with reload @p reload (once, at
 *  start: it divides). hz 0, a reload over 24 bits (SysTick's) or a period
 *  of 2^32 - 1 ns or more: hz 0, the time base reads 0. */
static inline void fnav_cm_systick_scale_init(fnav_cm_systick_scale_t *s, uint32_t hz, uint32_t reload)
{
    const uint64_t x = ((uint64_t)reload + 1u) * UINT64_C(1000000000);
    fnav_cm_ns_scale_init(&s->scale, hz, reload);
    s->hz = 0u;
    s->tick_ns = 0u;
    s->tick_rem = 0u;
    if (hz == 0u || reload > 0xffffffu || x / hz >= UINT64_C(0xffffffff)) {
        return;
    }
    s->hz = hz;
    s->tick_ns = (uint32_t)(x / hz);
    s->tick_rem = (uint32_t)(x % hz);
}

/** One period more on the count (@p ns, @p rem): ns + rem / hz is the
 *  periods' time, exactly (rem < hz). SysTick_Handler's work; no division. */
static inline void fnav_cm_systick_add(const fnav_cm_systick_scale_t *s, uint64_t *ns, uint32_t *rem)
{
    uint32_t add = s->tick_ns; /* under 2^32 - 1 (fnav_cm_systick_scale_init): add + 1 fits */
    if (*rem >= s->hz - s->tick_rem) { /* rem + tick_rem >= hz, without the overflow */
        *rem -= s->hz - s->tick_rem;
        add++;
    } else {
        *rem += s->tick_rem;
    }
    *ns += add;
}

/** The SysTick time base's stamp in ns from one reading of its state
 *  (port/cortex-m/fnav_port_cortexm.c, fnav_cm_ticks_ns()): @p ns and @p
 *  rem, the count of the periods whose interrupt has run (the time of W
 *  periods of p = reload + 1 clocks is W p 1e9 / hz = ns + rem / hz ns, kept
 *  by fnav_cm_systick_add()); @p cvr, the counter (SYST_CVR) read after it;
 *  @p pending, ICSR.PENDSTSET read after that; @p cvr_after, the counter
 *  read after the pending bit. @p s from fnav_cm_systick_scale_init(s, hz,
 *  reload); hz 0: 0.
 *
 *  The stamp is floor(C 1e9 / hz) for the C = W p + (reload - cvr) core
 *  clocks since the start, exactly, at any clock and over any run: the
 *  count of periods carries its fraction of a ns (rem), so a clock that
 *  1000 does not divide is not taken as 1 ms per period (at 14.7456 MHz the
 *  period is 14,745 clocks, 999.96 us: the stamp ran 40.7 ppm fast until
 *  2026-12-06). C 1e9 = (ns hz + rem) + (q hz + r) with q, r the quotient
 *  and remainder of the counter's c 1e9 by hz: the stamp is ns + q, plus 1
 *  when rem + r >= hz; r < hz needs only 32-bit products.
 *
 *  Pending set: the counter wrapped and its interrupt has not run (the
 *  caller is in an interrupt of the same or higher priority, or interrupts
 *  are masked). The wrap came before the pending bit was read, so @p
 *  cvr_after belongs to the next period: one period more and cvr_after
 *  (@p cvr may be from either side of the wrap). Pending clear: @p cvr (a
 *  wrap after the pending read shows only in @p cvr_after, which is not
 *  used). Two wraps before the interrupt runs cannot be told apart.
 *  Pure: tests/test_port.c, test_cm_systick_ns and test_cm_systick_long_run,
 *  check every order of a wrap and the reads, and the stamp after an hour
 *  of periods, on the host. */
static inline int64_t fnav_cm_systick_ns(const fnav_cm_systick_scale_t *s, uint64_t ns, uint32_t rem, uint32_t cvr,
                                         int pending, uint32_t cvr_after)
{
    uint32_t c, q, r;
    if (s->hz == 0u) {
        return 0;
    }
    if (pending) {
        fnav_cm_systick_add(s, &ns, &rem);
        cvr = cvr_after;
    }
    c = (uint32_t)s->scale.c_max - cvr; /* SysTick's counter never reads above its reload */
    q = (uint32_t)fnav_cm_ns_of_ticks(&s->scale, c); /* under tick_ns + 1 */
    r = c * 1000000000u - q * s->hz;                 /* mod 2^32: exact, as r < hz */
    return (int64_t)(ns + q + (r >= s->hz - rem ? 1u : 0u));
}

#endif /* FNAV_CM_TIME_H */
