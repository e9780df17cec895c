/* Stance detection: SHOE / threshold detectors, adaptive threshold, stride
 * segmentation and gait events (fnav_stance.h). */
#include "footnav/fnav_stance.h"
#include "footnav/fnav_port.h"

#if FNAV_STANCE_MAX_WINDOW < FNAV_STANCE_RATE_PROBE + 1
#define PROBE (FNAV_STANCE_MAX_WINDOW - 1)
#else
#define PROBE FNAV_STANCE_RATE_PROBE
#endif

/* Long runs. The sample counters (n_in, n_raw, n_out) are long, 32 bits on
 * the Cortex-M4F: 2^31 samples are 24.9 days at 1 kHz, 6.2 days at 4 kHz.
 * Every use of them is a difference of two of them or a slot modulo
 * FNAV_STANCE_MAX_WINDOW or FNAV_STANCE_EVENT_BUF (and FNAV_STANCE_JERK_BLOCK,
 * which divides the latter), so once n_out reaches REBASE_AT all three move
 * back by REBASE_STEP, a multiple of both ring sizes below 2^29: every slot
 * and difference stays, and the counters stay between 2^29 and 2^30 for
 * ever (test_stance test_counters_long_run). The run
 * lengths saturate at RUN_MAX instead, above every duration in samples
 * (round_pos() saturates at 1e9). */
#define REBASE_PERIOD ((long)FNAV_STANCE_MAX_WINDOW * (long)FNAV_STANCE_EVENT_BUF)
#define REBASE_STEP (((1L << 29) / REBASE_PERIOD) * REBASE_PERIOD)
#define REBASE_AT (1L << 30)
#define RUN_MAX 1000000001L

/* The foot-strike search's stamps are microseconds modulo 2^32 (71.6 min):
 * a time jump of 2^31 us (35.8 min) or more clears the history before it
 * (segment()). Shorter jumps are looked across; while the history holds an
 * interval of JERK_LONG_NS or more, several of them may add up past 2^32
 * us, and the search sums the stamps' differences one interval at a time
 * (each below 2^31 us). Without such an interval the history spans less
 * than FNAV_STANCE_EVENT_BUF x JERK_LONG_NS = 2^31 us, and the difference
 * of two stamps modulo 2^32 is exact. */
#define JERK_SPAN_NS ((int64_t)2147483648 * 1000)
#define JERK_LONG_NS (JERK_SPAN_NS / FNAV_STANCE_EVENT_BUF)

const fnav_stance_config_t fnav_stance_config_default = FNAV_STANCE_CONFIG_DEFAULT_INIT;

/* cyc_n: bits 0-1 the cycles known, bit 2 a swing start known. */
#define CYC_COUNT 0x3u
#define CYC_START 0x4u

static int pos_finite(fnav_real_t x)
{
    return fnav_isfinite(x) && x > FNAV_R(0.0);
}

/* A noise weight or threshold, which the statistic divides by squared:
 * its square positive and finite as well (in float32 one below about
 * 2.6e-23 has a square of 0, every statistic then Inf; one above 1.8e19
 * an infinite one, its term then 0; test_stance test_config_squares). */
static int sq_ok(fnav_real_t x)
{
    return pos_finite(x) && pos_finite(x * x);
}

fnav_status_t fnav_stance_init_tagged(fnav_stance_t *st, const fnav_stance_config_t *cfg, uint64_t build_tag,
                                      size_t obj_size, size_t cfg_size)
{
    const fnav_stance_config_t *c = cfg;
    size_t i;
    unsigned char *p = (unsigned char *)st;
    if (build_tag != FNAV_BUILD_TAG || obj_size != sizeof(fnav_stance_t) || cfg_size != sizeof(fnav_stance_config_t)) {
        return FNAV_E_BUILD; /* the caller's objects have another layout: write nothing */
    }
    if (st == NULL || cfg == NULL) {
        return FNAV_E_ARG;
    }
    if ((c->detector != FNAV_DETECTOR_SHOE && c->detector != FNAV_DETECTOR_THRESHOLD) ||
        !(fnav_isfinite(c->rate_hz) && c->rate_hz >= FNAV_R(0.0)) || !pos_finite(c->window_s) ||
        !sq_ok(c->sigma_a_mps2) || !sq_ok(c->sigma_g_rps) || !pos_finite(c->gamma) ||
        !sq_ok(c->gyro_thresh_rps) || !sq_ok(c->accel_thresh_mps2) || !pos_finite(c->gravity_mps2) ||
        (c->adaptive != 0 && c->adaptive != 1) || !pos_finite(c->floor_window_s) ||
        !(fnav_isfinite(c->margin_dec) && c->margin_dec >= FNAV_R(0.0)) ||
        !(fnav_isfinite(c->adapt_max_ratio) && c->adapt_max_ratio >= FNAV_R(1.0)) ||
        !(fnav_isfinite(c->min_stance_s) && c->min_stance_s >= FNAV_R(0.0)) ||
        !(fnav_isfinite(c->min_zupt_s) && c->min_zupt_s >= FNAV_R(0.0)) ||
        !(fnav_isfinite(c->min_swing_s) && c->min_swing_s >= FNAV_R(0.0)) || !pos_finite(c->event_window_s) ||
        !(fnav_isfinite(c->min_zupt_cycle) && c->min_zupt_cycle >= FNAV_R(0.0) && c->min_zupt_cycle <= FNAV_R(1.0))) {
        return FNAV_E_CONFIG;
    }
    for (i = 0; i < sizeof *st; i++) {
        p[i] = 0;
    }
    st->cfg = *cfg;
    st->seg = 1; /* the walker starts standing (paper IV.A) */
    st->run_raw = -1;
    return FNAV_OK;
}

/* Nearest integer of a non-negative duration in samples, saturated (a
 * configured duration of years must not overflow the conversion). */
static int round_pos(fnav_real_t x)
{
    return x < FNAV_R(1.0e9) ? (int)(x + FNAV_R(0.5)) : 1000000000;
}

/* The window the configuration asks for at a rate (odd, at least 3),
 * before the ring's cap: FNAV_STANCE_MAX_WINDOW + 1 stands for any longer. */
static int window_wanted(const fnav_stance_t *st, fnav_real_t rate_hz)
{
    const fnav_real_t half_w = FNAV_R(0.5) * st->cfg.window_s * rate_hz;
    const int w = half_w < (fnav_real_t)FNAV_STANCE_MAX_WINDOW ? 2 * (int)half_w + 1 : FNAV_STANCE_MAX_WINDOW + 1;
    return w < 3 ? 3 : w;
}

/* The shortest ZUPT run the configuration asks for at a rate, samples,
 * before the ring's cap. */
static int min_zupt_wanted(const fnav_stance_t *st, fnav_real_t rate_hz)
{
    const int n = round_pos(st->cfg.min_zupt_s * rate_hz);
    return n < 1 ? 1 : n;
}

/* The largest shortest ZUPT run min_zupt_cycle can ask for at a rate (a
 * cycle of FNAV_STANCE_CYCLE_LAG_S), samples, before the ring's cap; 0 when
 * the scaling is off. */
static int zupt_cycle_wanted(const fnav_stance_t *st, fnav_real_t rate_hz)
{
    return st->cfg.min_zupt_cycle > FNAV_R(0.0)
               ? round_pos(st->cfg.min_zupt_cycle * FNAV_STANCE_CYCLE_LAG_S * rate_hz)
               : 0;
}

/* Window and durations from the rate. */
static void set_rate(fnav_stance_t *st, fnav_real_t rate_hz)
{
    int w = window_wanted(st, rate_hz);
    int n;
    if (w > FNAV_STANCE_MAX_WINDOW) {
        w = FNAV_STANCE_MAX_WINDOW - ((FNAV_STANCE_MAX_WINDOW % 2) == 0 ? 1 : 0);
    }
    st->rate_hz = rate_hz;
    st->win = w;
    st->half = (w - 1) / 2;
    n = round_pos(st->cfg.event_window_s * rate_hz);
    st->n_ev = n < 1 ? 1 : (n > FNAV_STANCE_EVENT_BUF - 1 ? FNAV_STANCE_EVENT_BUF - 1 : n);
    n = round_pos(st->cfg.min_stance_s * rate_hz);
    st->n_min_stance = n < 1 ? 1 : n;
    st->n_min_zupt = min_zupt_wanted(st, rate_hz);
    /* the look-ahead covers the largest run the cycle scaling can ask for
     * (fixed here: a fixed latency); without it, n_min_zupt - 1 */
    n = zupt_cycle_wanted(st, rate_hz);
    n = n > st->n_min_zupt ? n : st->n_min_zupt;
    n = n < 255 ? n : 255; /* cyc_run holds unsigned chars */
    st->lag = n - 1;
    if (st->half + st->lag + 2 > FNAV_STANCE_MAX_WINDOW) {
        st->lag = FNAV_STANCE_MAX_WINDOW - 2 - st->half;
    }
    if (st->n_min_zupt > st->lag + 1) {
        st->n_min_zupt = st->lag + 1;
    }
    st->n_zupt_req = st->n_min_zupt;
    n = round_pos(st->cfg.min_swing_s * rate_hz);
    st->n_min_swing = n < 1 ? 1 : n;
    n = round_pos(st->cfg.floor_window_s * rate_hz / (fnav_real_t)FNAV_STANCE_FLOOR_BLOCKS);
    st->fw_len = n < 1 ? 1 : n;
    /* 10^margin_dec as 1 / exp(-margin_dec ln 10): the firmware links no
     * powf for it (1.9 kB of flash; docs/firmware.md); 5.7e-7 off powf's
     * at the default 0.4, far inside the threshold's own precision */
    st->margin_ratio = FNAV_R(1.0) / fnav_exp_neg(st->cfg.margin_dec * FNAV_R(2.302585093));
}

static const fnav_sample_t *at(const fnav_stance_t *st, long i)
{
    return &st->ring[i % FNAV_STANCE_MAX_WINDOW];
}

/* Median of the positive intervals of the first samples (insertion sort of
 * at most PROBE values). */
static void estimate_rate(fnav_stance_t *st)
{
    int64_t d[PROBE];
    int n = 0, i, j;
    for (i = 1; i < (int)st->n_in && i <= PROBE; i++) {
        int64_t v = at(st, i)->t_ns - at(st, i - 1)->t_ns;
        if (v > 0) {
            for (j = n; j > 0 && d[j - 1] > v; j--) {
                d[j] = d[j - 1];
            }
            d[j] = v;
            n++;
        }
    }
    if (n > 0) {
        int mid = n / 2; /* median interval */
        set_rate(st, FNAV_R(1.0e9) / fnav_i64_to_real(d[mid]));
    } else {
        set_rate(st, FNAV_R(100.0)); /* no usable time stamps: documented fallback */
    }
}

fnav_status_t fnav_stance_push(fnav_stance_t *st, const fnav_sample_t *sample)
{
    long lo;
    if (st == NULL || sample == NULL) {
        return FNAV_E_ARG;
    }
    if (st->win == 0 && !(st->cfg.window_s > FNAV_R(0.0))) {
        /* never initialised (zeroed, as static storage is): init sets a
         * window; tested only before the window is known, so the common
         * push pays nothing for it */
        return FNAV_E_STATE;
    }
    lo = st->n_raw - st->half; /* first sample of the next raw decision's window */
    if (st->finished || st->n_in - st->n_out >= FNAV_STANCE_MAX_WINDOW ||
        (lo > 0 && st->n_in - lo >= FNAV_STANCE_MAX_WINDOW)) {
        /* the caller did not pop the due decisions: the ring is full, or
         * this sample would overwrite the first of the window of the next
         * raw decision (decided at the next pop; a window longer than the
         * look-ahead, h > L, reaches it first;
         * test_stance test_burst_push_same_decisions) */
        return FNAV_E_STATE;
    }
    st->ring[st->n_in % FNAV_STANCE_MAX_WINDOW] = *sample;
    st->n_in++;
    if (st->win == 0) {
        if (st->cfg.rate_hz > FNAV_R(0.0)) {
            set_rate(st, st->cfg.rate_hz);
        } else if (st->n_in > PROBE) {
            estimate_rate(st);
        }
    }
    return FNAV_OK;
}

void fnav_stance_finish(fnav_stance_t *st)
{
    FNAV_ASSERT(st != NULL);
    st->finished = 1;
    if (st->win == 0 && st->n_in > 0) {
        if (st->cfg.rate_hz > FNAV_R(0.0)) {
            set_rate(st, st->cfg.rate_hz);
        } else {
            estimate_rate(st);
        }
    }
}

long fnav_stance_pending(const fnav_stance_t *st)
{
    return st->n_in - st->n_out;
}

/* Test statistic of sample i over the window [lo, hi]. */
static fnav_real_t statistic(const fnav_stance_t *st, long lo, long hi)
{
    const fnav_stance_config_t *c = &st->cfg;
    fnav_real_t n = (fnav_real_t)(hi - lo + 1);
    fnav_vec3_t m = fnav_vec3_zero();
    fnav_real_t sa = FNAV_R(0.0), sg = FNAV_R(0.0);
    long j;
    if (c->detector == FNAV_DETECTOR_SHOE) {
        fnav_vec3_t gu;
        for (j = lo; j <= hi; j++) {
            m = fnav_vec3_add(m, fnav_vec3_from(at(st, j)->accel_mps2));
        }
        /* g times the unit vector of the mean specific force (Skog 2010, eq. 13).
         * A zero mean (a sensor that outputs zeros) has no direction; then
         * sum |f_j - g u|^2 = sum |f_j|^2 + W g^2 for every unit u, so any
         * will do (the zero vector made T = 0: "at rest") */
        if (!(fnav_vec3_dot(m, m) > FNAV_R(0.0))) {
            m.v[2] = FNAV_R(1.0);
        }
        gu = fnav_vec3_scale(fnav_vec3_normalize(m), c->gravity_mps2);
        for (j = lo; j <= hi; j++) {
            fnav_vec3_t e = fnav_vec3_sub(fnav_vec3_from(at(st, j)->accel_mps2), gu);
            fnav_vec3_t w = fnav_vec3_from(at(st, j)->gyro_rps);
            sa += fnav_vec3_dot(e, e);
            sg += fnav_vec3_dot(w, w);
        }
        return (sa / (c->sigma_a_mps2 * c->sigma_a_mps2) + sg / (c->sigma_g_rps * c->sigma_g_rps)) / n;
    }
    for (j = lo; j <= hi; j++) {
        fnav_vec3_t w = fnav_vec3_from(at(st, j)->gyro_rps);
        fnav_real_t e = fnav_vec3_norm(fnav_vec3_from(at(st, j)->accel_mps2)) - c->gravity_mps2;
        sa += e * e;
        sg += fnav_vec3_dot(w, w);
    }
    sa /= n * c->accel_thresh_mps2 * c->accel_thresh_mps2;
    sg /= n * c->gyro_thresh_rps * c->gyro_thresh_rps;
    return sa > sg ? sa : sg; /* stance when both RMS values are below their limits */
}

static fnav_real_t jerk_at(const fnav_stance_t *st, long k)
{
    return st->jerk[k % FNAV_STANCE_EVENT_BUF];
}

/* Largest jerk of the FNAV_STANCE_JERK_BLOCK-sample block that starts at
 * decision index k (k a multiple of the block length). */
static fnav_real_t jerk_block_max(const fnav_stance_t *st, long k)
{
    return st->jerk_bmax[(k % FNAV_STANCE_EVENT_BUF) / FNAV_STANCE_JERK_BLOCK];
}

/* Foot-strike: the first sample, in the event window before the stance run
 * that starts at decision index k0, whose jerk reaches half the window's
 * largest jerk: the onset of the heel impact (docs/navigation.md).
 * Whole blocks of the window are read through their maxima (kept as the
 * jerk is stored), so a search costs about n_ev / 8 + 16 reads instead of
 * 2 n_ev: it runs once per stride, inside a stance step with a ZUPT, and
 * keeps that step within the navigation issue's instruction budget
 * (docs/firmware.md). Same answer as the plain two-pass scan. */
static int64_t foot_strike(const fnav_stance_t *st, long k0, int64_t t_now_ns, long k_now, int64_t t0_ns)
{
    const long B = FNAV_STANCE_JERK_BLOCK;
    long lo = k0 - st->n_ev, k, kbest = k0;
    fnav_real_t jmax = FNAV_R(0.0), half, j;
    if (lo < 0) {
        lo = 0;
    }
    /* the history ends k_now - k0 = n_min_stance - 1 samples after k0: the window
     * before k0 is cut to what it still holds (replay says so: hx_nav.c, event_reach) */
    if (lo < k_now - (FNAV_STANCE_EVENT_BUF - 1)) {
        lo = k_now - (FNAV_STANCE_EVENT_BUF - 1);
    }
    if (lo >= k0) {
        return t0_ns; /* nothing before the stance is left: its first sample */
    }
    /* the largest jerk in [lo, k0): single samples up to a block boundary,
     * whole blocks, single samples after the last whole block */
    for (k = lo; k < k0 && k % B != 0; k++) {
        j = jerk_at(st, k);
        jmax = j > jmax ? j : jmax;
    }
    for (; k + B <= k0; k += B) {
        j = jerk_block_max(st, k);
        jmax = j > jmax ? j : jmax;
    }
    for (; k < k0; k++) {
        j = jerk_at(st, k);
        jmax = j > jmax ? j : jmax;
    }
    /* the first sample reaching half of it; whole blocks below half skipped */
    half = FNAV_R(0.5) * jmax;
    k = lo;
    while (k < k0) {
        if (k % B == 0 && k + B <= k0 && jerk_block_max(st, k) < half) {
            k += B;
        } else if (jerk_at(st, k) >= half) {
            kbest = k;
            break;
        } else {
            k++;
        }
    }
    if (st->jerk_long_left > 0) {
        /* jumps in the history may span 2^32 us or more together (three of
         * 30 min in 32 bits would put the strike 71.6 min off) */
        int64_t span_us = 0;
        for (k = kbest + 1; k <= k_now; k++) {
            span_us += (int64_t)(uint32_t)(st->jerk_t_us[k % FNAV_STANCE_EVENT_BUF] -
                                           st->jerk_t_us[(k - 1) % FNAV_STANCE_EVENT_BUF]);
        }
        return t_now_ns - span_us * 1000;
    }
    return t_now_ns -
           (int64_t)(uint32_t)(fnav_ns_to_us_u32(t_now_ns) - st->jerk_t_us[kbest % FNAV_STANCE_EVENT_BUF]) * 1000;
}

/* Cycle-scaled shortest ZUPT run (fnav_stance.h): a swing starts at t0_ns;
 * the cycle since the previous swing start gives a run
 * round(min_zupt_cycle * T * rate), between n_min_zupt and lag + 1 (a cycle
 * over FNAV_STANCE_CYCLE_LAG_S gets lag + 1 when the ring allows it); the run
 * in use is the median of the last three (the smaller of two; the one). A
 * cycle longer than FNAV_STANCE_CYCLE_MAX_S (a stand between the strides)
 * or not positive (a new timeline) clears them: back to n_min_zupt. */
static void cycle_update(fnav_stance_t *st, int64_t t0_ns)
{
    unsigned n_cyc = st->cyc_n & CYC_COUNT;
    if (st->cyc_n & CYC_START) {
        const int64_t dt_ns = t0_ns - st->swing_t0_ns;
        const fnav_real_t t_s = fnav_i64_to_real(dt_ns) * FNAV_R(1.0e-9);
        if (dt_ns <= 0 || t_s > FNAV_STANCE_CYCLE_MAX_S) {
            n_cyc = 0;
            st->n_zupt_req = st->n_min_zupt;
        } else {
            int n = round_pos(st->cfg.min_zupt_cycle * t_s * st->rate_hz), a, b, c;
            n = n > st->n_min_zupt ? n : st->n_min_zupt;
            n = n < st->lag + 1 ? n : st->lag + 1;
            st->cyc_run[2] = st->cyc_run[1];
            st->cyc_run[1] = st->cyc_run[0];
            st->cyc_run[0] = (unsigned char)n;
            n_cyc = n_cyc < 3u ? n_cyc + 1u : 3u;
            a = st->cyc_run[0];
            b = st->cyc_run[1];
            c = st->cyc_run[2];
            if (n_cyc == 1u) {
                st->n_zupt_req = a;
            } else if (n_cyc == 2u) {
                st->n_zupt_req = a < b ? a : b;
            } else {
                /* median of three */
                st->n_zupt_req = a < b ? (b < c ? b : (a < c ? c : a)) : (a < c ? a : (b < c ? c : b));
            }
        }
    }
    st->cyc_n = (unsigned char)(n_cyc | CYC_START);
}

/* Segmentation and gait events for decision index k (= st->n_out). */
static void segment(fnav_stance_t *st, fnav_stance_out_t *o)
{
    long k = st->n_out;
    const fnav_real_t *f = o->sample.accel_mps2;
    fnav_real_t fn = fnav_vec3_norm(fnav_vec3_from(f));
    fnav_real_t jerk = FNAV_R(0.0);
    if (st->have_prev) {
        jerk = fnav_vec3_norm(fnav_vec3_sub(fnav_vec3_from(f), fnav_vec3_from(st->prev_acc)));
        if (o->sample.t_ns - st->prev_t_ns >= JERK_LONG_NS) {
            st->jerk_long_left = FNAV_STANCE_EVENT_BUF;
        } else if (st->jerk_long_left > 0) {
            st->jerk_long_left--;
        }
        if (o->sample.t_ns - st->prev_t_ns >= JERK_SPAN_NS || o->sample.t_ns < st->prev_t_ns) {
            /* a time jump the history's microsecond stamps (modulo 2^32)
             * cannot span, or a step back to a new timeline (fnav_nav_push
             * takes one after FNAV_NAV_TIME_RESYNC samples behind; its
             * stamps' differences with the old wrapped: a strike 3695 s
             * early after a step back of 10 min, test_foot_strike_time_jump):
             * the foot-strike search must not look before it
             * (the motion inside is unknown); -1 is below every jerk and
             * every half maximum, so it is never the largest nor chosen */
            int b;
            for (b = 0; b < FNAV_STANCE_EVENT_BUF; b++) {
                st->jerk[b] = -FNAV_R(1.0);
            }
            for (b = 0; b < FNAV_STANCE_EVENT_BUF / FNAV_STANCE_JERK_BLOCK; b++) {
                st->jerk_bmax[b] = -FNAV_R(1.0);
            }
        }
    }
    {
        long slot = k % FNAV_STANCE_EVENT_BUF;
        fnav_real_t *bmax = &st->jerk_bmax[slot / FNAV_STANCE_JERK_BLOCK];
        st->jerk[slot] = jerk;
        if (slot % FNAV_STANCE_JERK_BLOCK == 0 || jerk > *bmax) {
            *bmax = jerk; /* a block starts afresh */
        }
    }
    /* (uint32_t)(t_ns / 1000) without a 64-bit division per sample (fnav_math.h) */
    st->jerk_t_us[k % FNAV_STANCE_EVENT_BUF] = fnav_ns_to_us_u32(o->sample.t_ns);
    st->prev_acc[0] = f[0];
    st->prev_acc[1] = f[1];
    st->prev_acc[2] = f[2];
    st->have_prev = 1;

    if (o->stance == st->run_raw) {
        st->run = st->run < RUN_MAX ? st->run + 1 : RUN_MAX;
    } else {
        st->run = 1;
        st->run_raw = (signed char)o->stance;
        st->run_t0_ns = o->sample.t_ns;
        if (!o->stance) {
            /* a new swing run: foot-off is the largest |f| of its first
             * event window (push-off peak) */
            st->fo_open = 1;
            st->fo_max = fn;
            st->fo_t_ns = o->sample.t_ns;
        } else {
            /* the swing run ended within its event window: the search
             * closes on what it saw (left open, the motion after a short
             * pause would take it over and foot-off would come after
             * foot-strike) */
            st->fo_open = 0;
        }
    }
    if (st->fo_open && !o->stance) {
        if (st->run <= st->n_ev) {
            if (fn > st->fo_max) {
                st->fo_max = fn;
                st->fo_t_ns = o->sample.t_ns;
            }
        } else {
            st->fo_open = 0;
        }
    }
    if (st->seg == 1 && !o->stance && st->run >= st->n_min_swing) {
        st->seg = 0;
        st->fo_pending = 1;
        if (st->cfg.min_zupt_cycle > FNAV_R(0.0)) {
            cycle_update(st, st->run_t0_ns);
        }
        st->swing_t0_ns = st->run_t0_ns; /* the swing began with this run */
    } else if (st->seg == 0 && o->stance && st->run >= st->n_min_stance) {
        st->seg = 1;
        st->strides++;
        o->events |= FNAV_STANCE_EV_STRIDE | FNAV_STANCE_EV_FOOT_STRIKE;
        o->fs_t_ns = foot_strike(st, k - st->run + 1, o->sample.t_ns, k, st->run_t0_ns);
        o->swing_t0_ns = st->swing_t0_ns;
        o->swing_t1_ns = st->run_t0_ns; /* first sample of the stance run */
    }
    if (st->fo_pending && (!st->fo_open || st->seg == 1)) {
        st->fo_pending = 0;
        o->events |= FNAV_STANCE_EV_FOOT_OFF;
        o->fo_t_ns = st->fo_t_ns;
    }
    o->segment_stance = st->seg;
}

/* Raw decision for sample n_raw, whose window is complete: statistic,
 * (adaptive) threshold, below-threshold flag, into the confirmation queue. */
static void decide_raw(fnav_stance_t *st)
{
    long i = st->n_raw, lo, hi;
    fnav_real_t stat, gamma, g0;
    int q = (int)(i % FNAV_STANCE_MAX_WINDOW);
    lo = i - st->half;
    hi = i + st->half;
    if (lo < 0) {
        lo = 0;
    }
    if (lo < st->n_in - FNAV_STANCE_MAX_WINDOW) {
        lo = st->n_in - FNAV_STANCE_MAX_WINDOW;
    }
    if (hi > st->n_in - 1) {
        hi = st->n_in - 1;
    }
    stat = statistic(st, lo, hi);
    g0 = st->cfg.detector == FNAV_DETECTOR_SHOE ? st->cfg.gamma : FNAV_R(1.0);
    gamma = g0;
    if (st->cfg.adaptive) {
        /* floor F of log10 T: its minimum over the last floor_window_s (the
         * completed blocks and the one being filled), never below
         * log10(gamma) - margin; the threshold of this sample comes from the
         * samples before it. log10 is monotonic, so the minima are kept in
         * T itself and 10^(F + margin) = min T * 10^margin: no logarithm or
         * power per sample (10^margin is computed once, at the rate). */
        fnav_real_t l = stat > FNAV_R(1.0e-30) ? stat : FNAV_R(1.0e-30);
        int k;
        if (st->floor_valid) {
            fnav_real_t fl = st->fw_cur;
            for (k = 0; k < st->fw_nblk; k++) {
                fl = st->fw_blk[k] < fl ? st->fw_blk[k] : fl;
            }
            gamma = fnav_clamp(fl * st->margin_ratio, g0, g0 * st->cfg.adapt_max_ratio);
        } else {
            st->floor_valid = 1;
            st->fw_cur = l;
        }
        st->fw_cur = l < st->fw_cur ? l : st->fw_cur;
        if (++st->fw_fill >= st->fw_len) {
            st->fw_blk[st->fw_head] = st->fw_cur;
            st->fw_head = (st->fw_head + 1) % FNAV_STANCE_FLOOR_BLOCKS;
            if (st->fw_nblk < FNAV_STANCE_FLOOR_BLOCKS) {
                st->fw_nblk++;
            }
            st->fw_fill = 0;
            st->fw_cur = FNAV_R(1.0e30);
        }
    }
    st->dq_stat[q] = stat;
    st->dq_gamma[q] = gamma;
    st->dq_raw[q] = (unsigned char)(stat < gamma);
    st->n_raw++;
}

/* The lock-in guard (fnav_stance.h): a raw stance run of st->back samples
 * (at least n_min_zupt) just ended, accepted or rejected; remember it and
 * recompute the cap, half the longest remembered run. */
static void raw_run_end(fnav_stance_t *st)
{
    int j, longest;
    for (j = FNAV_STANCE_RAW_RUNS - 1; j > 0; j--) {
        st->raw_runs[j] = st->raw_runs[j - 1];
    }
    st->raw_runs[0] = (unsigned char)(st->back < 255 ? st->back : 255);
    longest = 0;
    for (j = 0; j < FNAV_STANCE_RAW_RUNS; j++) {
        longest = st->raw_runs[j] > longest ? st->raw_runs[j] : longest;
    }
    st->raw_cap = (unsigned char)(longest / 2);
}

fnav_status_t fnav_stance_pop(fnav_stance_t *st, fnav_stance_out_t *out)
{
    long i, k, fwd;
    int q, req;
    if (st == NULL || out == NULL) {
        return FNAV_E_ARG;
    }
    if (st->win == 0) {
        if (!(st->cfg.window_s > FNAV_R(0.0))) {
            return FNAV_E_STATE; /* never initialised: its decisions would divide by a zero sigma */
        }
        return (st->finished && st->n_in == 0) ? FNAV_END : FNAV_AGAIN;
    }
    /* raw decisions for every sample whose window is complete */
    while (st->n_raw < st->n_in && (st->finished || st->n_raw + st->half <= st->n_in - 1)) {
        decide_raw(st);
    }
    i = st->n_out;
    if (i >= st->n_in) {
        return st->finished ? FNAV_END : FNAV_AGAIN;
    }
    if (i >= st->n_raw || (!st->finished && i + st->lag >= st->n_raw)) {
        return FNAV_AGAIN;
    }
    FNAV_ASSERT(i >= st->n_in - FNAV_STANCE_MAX_WINDOW);
    q = (int)(i % FNAV_STANCE_MAX_WINDOW);
    out->sample = *at(st, i);
    out->stat = st->dq_stat[q];
    out->gamma = st->dq_gamma[q];
    out->raw_stance = st->dq_raw[q];
    /* length of the raw stance run through i, looking ahead at most lag
     * (saturated: a foot at rest for days stays at rest) */
    if (!out->raw_stance && st->back >= st->n_min_zupt && st->cfg.min_zupt_cycle > FNAV_R(0.0)) {
        raw_run_end(st);
    }
    st->back = out->raw_stance ? (st->back < RUN_MAX ? st->back + 1 : RUN_MAX) : 0;
    fwd = 0;
    if (out->raw_stance) {
        for (k = i + 1; k < st->n_raw && k <= i + st->lag; k++) {
            if (!st->dq_raw[k % FNAV_STANCE_MAX_WINDOW]) {
                break;
            }
            fwd++;
        }
    }
    req = st->n_zupt_req;
    if (req > st->raw_cap) {
        /* the lock-in guard (fnav_stance.h): at most half the longest recent
         * raw run, never below n_min_zupt (n_zupt_req is n_min_zupt when
         * min_zupt_cycle is 0: nothing changes then) */
        req = st->raw_cap > st->n_min_zupt ? st->raw_cap : st->n_min_zupt;
    }
    out->stance = out->raw_stance && st->back + fwd >= req;
    out->events = 0;
    out->fo_t_ns = 0;
    out->fs_t_ns = 0;
    out->swing_t0_ns = 0;
    out->swing_t1_ns = 0;
    segment(st, out);
    st->prev_t_ns = out->sample.t_ns;
    st->n_out++;
    if (st->n_out >= REBASE_AT) {
        st->n_in -= REBASE_STEP;
        st->n_raw -= REBASE_STEP;
        st->n_out -= REBASE_STEP;
    }
    return FNAV_OK;
}

unsigned fnav_stance_cut(const fnav_stance_t *st)
{
    unsigned cut = 0u;
    FNAV_ASSERT(st != NULL);
    if (st->win == 0) {
        return 0u; /* the rate is not known yet */
    }
    if (window_wanted(st, st->rate_hz) > st->win) {
        cut |= FNAV_STANCE_CUT_WINDOW;
    }
    if (min_zupt_wanted(st, st->rate_hz) > st->n_min_zupt) {
        cut |= FNAV_STANCE_CUT_MIN_ZUPT;
    }
    if (zupt_cycle_wanted(st, st->rate_hz) > st->lag + 1) {
        cut |= FNAV_STANCE_CUT_ZUPT_CYCLE;
    }
    return cut;
}
