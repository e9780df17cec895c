/* Emulator benchmark of the reference firmware (make firmware-bench).
 *
 * Replays a piece of a recorded walk (fnav_cm_slice.h) through the real
 * firmware path: the sample-ready interrupt is raised through the NVIC for
 * every sample, its handler reads the "IMU" (the slice) and pushes into the
 * lock-free ring; the main loop (fnav_cm_app_poll) drains the ring through
 * the port layer, steps the estimators and emits wire frames into an output
 * buffer, as a UART DMA driver would take them.
 *
 * On ARM (qemu-system-arm -M mps2-an386 -icount shift=0) the SysTick counter
 * runs from the core clock in virtual time, and with -icount virtual time
 * advances by a fixed amount per executed instruction, so SysTick counts
 * instructions deterministically. The ratio (instructions per tick) is
 * measured at start on a loop of known length, and the profiling marks of
 * the main loop (fnav_cm_prof.h) turn into instruction counts per call.
 *
 * The same file builds for the host (no SysTick, no NVIC: the interrupt body
 * is called directly); both print the navigation output and a fingerprint
 * of the frame stream, which `make firmware-bench` compares. */
#include <string.h>

#include "fnav_cm_app.h"
#include "fnav_cm_prof.h"
#include "fnav_cm_semihost.h"
#include "fnav_cm_slice.h"

/* Every BURST_EVERY-th sample, BURST samples are queued before the main
 * loop runs, so the ring holds several samples at once. */
#define BURST_EVERY 64u
#define BURST 8u

static fnav_cm_app_t g_app;
static uint32_t g_next; /* next slice sample the "IMU" delivers */

/* ------------------------------------------------------------ the board */

int fnav_cm_imu_read(fnav_sample_t *s)
{
    const fnav_cm_slice_sample_t *x;
    int k;
    if (g_next >= fnav_cm_slice_n) {
        return -1;
    }
    x = &fnav_cm_slice[g_next++];
    s->t_ns = x->t_ns;
    s->seq = x->seq;
    s->flags = x->flags;
    for (k = 0; k < 3; k++) {
        s->accel_mps2[k] = (fnav_real_t)x->acc[k];
        s->gyro_rps[k] = (fnav_real_t)x->gyr[k];
    }
    s->temp_c = FNAV_R(0.0);
    return 0;
}

/* The output link: frames are copied into a buffer that the benchmark
 * drains after each pass of the main loop (outside the measured code). */
static uint8_t g_out[4096];
static uint32_t g_out_n;

int fnav_cm_out_write(const void *bytes, uint32_t n)
{
    if (n > sizeof g_out - g_out_n) {
        return -1;
    }
    memcpy(g_out + g_out_n, bytes, n);
    g_out_n += n;
    return 0;
}

/* ------------------------------------------------------------ output */

typedef struct {
    fnav_wire_decoder_t rx;     /* the receiving end */
    uint32_t frames[6];         /* by type (0: unknown) */
    uint32_t echo_crc;          /* CRC-32 over the SAMPLE frames */
    uint32_t echo_mismatch;     /* echoed samples that differ from the slice */
    uint32_t echo_next;         /* slice index of the next echoed sample */
    uint32_t nav_n;
    uint32_t nav_crc;           /* CRC-32 over the NAV frame payloads */
    fnav_wire_nav_t nav_last;
} sink_t;

static sink_t g_sink;

static uint32_t f32_bits(float v)
{
    uint32_t u;
    memcpy(&u, &v, sizeof u);
    return u;
}

static void print_nav(const char *tag, uint32_t k, const fnav_wire_nav_t *v)
{
    fnav_cm_line_t l;
    int i;
    fnav_cm_line_start(&l);
    fnav_cm_line_str(&l, tag);
    fnav_cm_line_str(&l, " ");
    fnav_cm_line_u64(&l, k);
    fnav_cm_line_str(&l, " ");
    fnav_cm_line_i64(&l, v->t_ns);
    fnav_cm_line_str(&l, " ");
    fnav_cm_line_u64(&l, v->flags);
    for (i = 0; i < 3; i++) {
        fnav_cm_line_str(&l, " ");
        fnav_cm_line_hex32(&l, f32_bits(v->pos_m[i]));
    }
    for (i = 0; i < 3; i++) {
        fnav_cm_line_str(&l, " ");
        fnav_cm_line_hex32(&l, f32_bits(v->euler_rad[i]));
    }
    fnav_cm_line_end(&l);
}

static void drain_output(void)
{
    size_t pos = 0;
    for (;;) {
        size_t used;
        fnav_wire_frame_t f;
        if (fnav_wire_decode(&g_sink.rx, g_out + pos, g_out_n - pos, &used, &f) != FNAV_OK) {
            break;
        }
        pos += used;
        g_sink.frames[f.type <= 5u ? f.type : 0u]++;
        if (f.type == FNAV_WIRE_SAMPLE) {
            fnav_sample_t s;
            const fnav_cm_slice_sample_t *x = &fnav_cm_slice[g_sink.echo_next++];
            int k, same;
            g_sink.echo_crc = fnav_crc32(g_sink.echo_crc, f.payload, f.len);
            same = (fnav_wire_parse_sample(&f, &s) == FNAV_OK) && s.t_ns == x->t_ns && s.seq == x->seq;
            for (k = 0; k < 3; k++) {
                same = same && (float)s.accel_mps2[k] == x->acc[k] && (float)s.gyro_rps[k] == x->gyr[k];
            }
            g_sink.echo_mismatch += same ? 0u : 1u;
        } else if (f.type == FNAV_WIRE_NAV) {
            g_sink.nav_crc = fnav_crc32(g_sink.nav_crc, f.payload, f.len);
            if (fnav_wire_parse_nav(&f, &g_sink.nav_last) == FNAV_OK) {
                /* every output, so the comparison with the host covers all */
                print_nav("nav", g_sink.nav_n, &g_sink.nav_last);
                g_sink.nav_n++;
            }
        }
    }
    g_out_n = 0u;
}

/* The Allan and Welch results at the end, as float32 bit patterns, so that
 * the comparison with the host covers them too. */
static void print_estimates(void)
{
    fnav_cm_line_t l;
    fnav_cm_line_start(&l);
#if FNAV_CM_WITH_ALLAN
    {
        unsigned ch;
        size_t i;
        for (ch = 0; ch < FNAV_CM_ALLAN_CHANNELS; ch++) {
            for (i = 0; i < fnav_allan_count(&g_app.est.allan[ch]); i++) {
                fnav_allan_result_t r;
                if (fnav_allan_get(&g_app.est.allan[ch], i, &r) != FNAV_OK || r.terms == 0u) {
                    continue;
                }
                fnav_cm_line_str(&l, "allan ");
                fnav_cm_line_u64(&l, ch);
                fnav_cm_line_str(&l, " ");
                fnav_cm_line_u64(&l, r.tau);
                fnav_cm_line_str(&l, " ");
                fnav_cm_line_u64(&l, r.terms);
                fnav_cm_line_str(&l, " ");
                fnav_cm_line_hex32(&l, f32_bits((float)r.avar));
                fnav_cm_line_end(&l);
            }
        }
    }
#endif
#if FNAV_CM_WITH_WELCH
    {
        static fnav_real_t psd[FNAV_WELCH_MAX_BINS];
        unsigned ch;
        uint32_t k;
        for (ch = 0; ch < FNAV_CM_WELCH_CHANNELS; ch++) {
            const fnav_welch_t *w = &g_app.est.welch[ch];
            if (fnav_welch_get(w, psd, FNAV_WELCH_MAX_BINS) != FNAV_OK) {
                continue;
            }
            for (k = 0; k < fnav_welch_bins(w); k++) {
                fnav_cm_line_str(&l, "welch ");
                fnav_cm_line_u64(&l, ch);
                fnav_cm_line_str(&l, " ");
                fnav_cm_line_u64(&l, k);
                fnav_cm_line_str(&l, " ");
                fnav_cm_line_u64(&l, fnav_welch_segments(w));
                fnav_cm_line_str(&l, " ");
                fnav_cm_line_hex32(&l, f32_bits((float)psd[k]));
                fnav_cm_line_end(&l);
            }
        }
    }
#endif
    (void)l;
}

/* ------------------------------------------------------------ profiling */

#if defined(__arm__)
#define SYST_CSR (*(volatile uint32_t *)0xE000E010u)
#define SYST_RVR (*(volatile uint32_t *)0xE000E014u)
#define SYST_CVR (*(volatile uint32_t *)0xE000E018u)
/* NVIC set-enable and set-pending registers: 32 interrupts a word, so
 * interrupt n is bit n % 32 of word n / 32 (ARMv7-M ARM B3.4.4, B3.4.6) */
#define NVIC_ISER(n) (((volatile uint32_t *)0xE000E100u)[(n) / 32])
#define NVIC_ISPR(n) (((volatile uint32_t *)0xE000E200u)[(n) / 32])
#define NVIC_BIT(n) (1u << ((n) % 32))

/* Extra ids beyond the main loop's: the interrupt, the navigation step
 * split by what it did (from FNAV_CM_PROF_NOTE), the stance detector alone,
 * and the calibration. */
#define PROF_ISR ((fnav_cm_prof_id_t)FNAV_CM_PROF_COUNT)
#define PROF_NAV_NOOUT ((fnav_cm_prof_id_t)(FNAV_CM_PROF_COUNT + 1))
#define PROF_NAV_SWING ((fnav_cm_prof_id_t)(FNAV_CM_PROF_COUNT + 2))
#define PROF_NAV_ZUPT ((fnav_cm_prof_id_t)(FNAV_CM_PROF_COUNT + 3))
#define PROF_STANCE ((fnav_cm_prof_id_t)(FNAV_CM_PROF_COUNT + 4))
#define PROF_UKF_PRED ((fnav_cm_prof_id_t)(FNAV_CM_PROF_COUNT + 5))
#define PROF_UKF_STANCE ((fnav_cm_prof_id_t)(FNAV_CM_PROF_COUNT + 6))
#define PROF_UKF_ZUPT ((fnav_cm_prof_id_t)(FNAV_CM_PROF_COUNT + 7))
#define PROF_EMPTY ((fnav_cm_prof_id_t)(FNAV_CM_PROF_COUNT + 8))
#define PROF_N (FNAV_CM_PROF_COUNT + 9)

typedef struct {
    uint32_t begin;
    uint32_t last;
    uint32_t count;
    uint64_t sum;
    uint32_t min, max;
    uint32_t over;       /* calls above the target (navigation step) */
} prof_t;

static prof_t g_prof[PROF_N];

/* The navigation issue's target per step, and the same in SysTick ticks
 * (set after the calibration; 0: not checked yet). */
#define NAV_TARGET_INSTRUCTIONS 40000u
static uint32_t g_nav_target_ticks;

static void prof_add(prof_t *p, uint32_t d)
{
    if ((p == &g_prof[FNAV_CM_PROF_NAV] || p == &g_prof[PROF_UKF_PRED] || p == &g_prof[PROF_UKF_STANCE]) &&
        g_nav_target_ticks != 0u && d > g_nav_target_ticks) {
        p->over++;
    }
    p->last = d;
    p->sum += d;
    p->min = (p->count == 0u || d < p->min) ? d : p->min;
    p->max = (d > p->max) ? d : p->max;
    p->count++;
}

#if FNAV_CM_WITH_NAV
/* The UKF step alone (strapdown prediction plus, in stance, the ZUPT: the
 * quantity of the navigation issue's 40,000-instruction target): before each
 * navigator step the filter is copied; after it, when the step ran exactly
 * one prediction, the same prediction (same sample, interval) and update are
 * replayed on the copy and timed. The copy and the search are not timed. */
static fnav_ukf_t g_ukf_copy;
static uint32_t g_excluded; /* ticks of snapshot + replay inside the current main-loop pass */
static int64_t g_tprev_copy;
static uint32_t g_predicts_before;
static uint32_t g_frame_idx;

static void ukf_snapshot(void)
{
    uint32_t t0 = SYST_CVR;
    g_ukf_copy = g_app.est.nav.ukf;
    g_tprev_copy = g_app.est.nav.t_prev_ns;
    g_predicts_before = g_app.est.nav.ukf.health.predicts;
    g_excluded += (t0 - SYST_CVR) & 0xFFFFFFu;
}

static void ukf_replay_timed(const fnav_nav_frame_t *fr);

/* The replay is measurement, not firmware work: its time is excluded from
 * the enclosing main-loop figure. */
static void ukf_replay(const fnav_nav_frame_t *fr)
{
    uint32_t t0 = SYST_CVR;
    ukf_replay_timed(fr);
    g_excluded += (t0 - SYST_CVR) & 0xFFFFFFu;
}

static void ukf_replay_timed(const fnav_nav_frame_t *fr)
{
    const fnav_nav_t *nav = &g_app.est.nav;
    const fnav_cm_slice_sample_t *x;
    fnav_vec3_t w, a;
    fnav_real_t dt;
    fnav_status_t st;
    uint32_t a0, a1, b1;
    if (nav->ukf.health.predicts != g_predicts_before + 1u || !g_ukf_copy.started) {
        return;
    }
    while (g_frame_idx < fnav_cm_slice_n && fnav_cm_slice[g_frame_idx].t_ns < fr->t_ns) {
        g_frame_idx++;
    }
    if (g_frame_idx >= fnav_cm_slice_n || fnav_cm_slice[g_frame_idx].t_ns != fr->t_ns) {
        return;
    }
    x = &fnav_cm_slice[g_frame_idx];
    w = fnav_vec3((fnav_real_t)x->gyr[0], (fnav_real_t)x->gyr[1], (fnav_real_t)x->gyr[2]);
    a = fnav_vec3((fnav_real_t)x->acc[0], (fnav_real_t)x->acc[1], (fnav_real_t)x->acc[2]);
    dt = (fnav_real_t)(fr->t_ns - g_tprev_copy) * FNAV_R(1.0e-9);
    if (!(dt > FNAV_R(0.0)) || dt > nav->cfg.max_gap_s) {
        return; /* the navigator used the nominal interval: not the same call */
    }
    a0 = SYST_CVR;
    st = fnav_ukf_predict(&g_ukf_copy, w, a, dt);
    a1 = SYST_CVR;
    if (fr->flags & FNAV_FRAME_ZUPT) {
        st = fnav_ukf_zupt(&g_ukf_copy, w);
    }
    b1 = SYST_CVR;
    (void)st; /* statuses are the navigator's business; here only the cost */
    prof_add(&g_prof[PROF_UKF_PRED], (a0 - a1) & 0xFFFFFFu);
    if (fr->flags & FNAV_FRAME_ZUPT) {
        prof_add(&g_prof[PROF_UKF_STANCE], (a0 - b1) & 0xFFFFFFu);
        prof_add(&g_prof[PROF_UKF_ZUPT], (a1 - b1) & 0xFFFFFFu);
    }
}
#endif

/* SysTick counts down, 24 bits: a call shorter than 2^24 ticks is measured
 * exactly by the difference modulo 2^24. */
FNAV_CM_NOIPA void fnav_cm_prof_mark(fnav_cm_prof_id_t id, int begin)
{
    uint32_t now;
    prof_t *p = &g_prof[id];
#if FNAV_CM_WITH_NAV
    if (begin && id == FNAV_CM_PROF_NAV) {
        ukf_snapshot(); /* before reading the clock: not part of the step */
    }
#endif
    now = SYST_CVR;
    if (begin) {
        p->begin = now;
#if FNAV_CM_WITH_NAV
        if (id == FNAV_CM_PROF_SAMPLE) {
            g_excluded = 0u;
        }
#endif
    } else {
#if FNAV_CM_WITH_NAV
        if (id == FNAV_CM_PROF_SAMPLE) {
            now += g_excluded; /* SysTick counts down: later by the excluded ticks */
            g_excluded = 0u;
        }
#endif
        prof_add(p, (p->begin - now) & 0xFFFFFFu);
    }
}

/* The navigation step's cost by what it did: no output yet, an output in
 * swing, an output with a zero-velocity update. */
FNAV_CM_NOIPA void fnav_cm_prof_note(fnav_cm_prof_id_t id, uint32_t tag)
{
    if (id == FNAV_CM_PROF_NAV) {
        fnav_cm_prof_id_t k = (tag == FNAV_CM_PROF_TAG_NO_OUTPUT)
                                  ? PROF_NAV_NOOUT
                                  : ((tag & FNAV_FRAME_ZUPT) ? PROF_NAV_ZUPT : PROF_NAV_SWING);
        prof_add(&g_prof[k], g_prof[id].last);
#if FNAV_CM_WITH_NAV
        if (tag != FNAV_CM_PROF_TAG_NO_OUTPUT) {
            ukf_replay(&g_app.frame);
        }
#endif
    }
}

#if FNAV_CM_WITH_NAV
/* The stance detector alone (default configuration), fed the same samples
 * outside the main loop, to count one detector update on its own. */
static fnav_stance_t g_stance;
static uint32_t g_stance_next;

static void stance_init(fnav_real_t rate_hz)
{
    fnav_stance_config_t sc = fnav_nav_config_default.stance;
    sc.rate_hz = rate_hz;
    if (fnav_stance_init(&g_stance, &sc) != FNAV_OK) {
        fnav_cm_sh_puts("bench: error: fnav_stance_init failed\n");
        fnav_cm_sh_exit(1);
    }
}

static void stance_feed(uint32_t upto)
{
    while (g_stance_next < upto) {
        const fnav_cm_slice_sample_t *x = &fnav_cm_slice[g_stance_next++];
        fnav_sample_t s;
        fnav_stance_out_t o;
        int k;
        s.t_ns = x->t_ns;
        s.seq = x->seq;
        s.flags = x->flags;
        for (k = 0; k < 3; k++) {
            s.accel_mps2[k] = (fnav_real_t)x->acc[k];
            s.gyro_rps[k] = (fnav_real_t)x->gyr[k];
        }
        s.temp_c = FNAV_R(0.0);
        fnav_cm_prof_mark(PROF_STANCE, 1);
        if (fnav_stance_push(&g_stance, &s) == FNAV_OK) {
            while (fnav_stance_pop(&g_stance, &o) == FNAV_OK) {
            }
        }
        fnav_cm_prof_mark(PROF_STANCE, 0);
    }
}
#endif

/* 2n + 1 instructions: SUBS and BNE per iteration, then BX. */
__attribute__((naked, noinline)) static void spin(uint32_t n)
{
    (void)n;
    __asm volatile(
        "1: subs r0, r0, #1\n"
        "   bne 1b         \n"
        "   bx lr          \n");
}

static uint64_t g_ins_num = 1u, g_ins_den = 1u; /* instructions per tick */

static void systick_calibrate(void)
{
    const uint32_t n = 1000000u;
    uint32_t t0, t1;
    SYST_RVR = 0xFFFFFFu;
    SYST_CVR = 0u;
    SYST_CSR = 0x5u; /* processor clock, no interrupt, enable */
    t0 = SYST_CVR;
    spin(n);
    t1 = SYST_CVR;
    g_ins_num = 2u * (uint64_t)n;
    g_ins_den = (t0 - t1) & 0xFFFFFFu;
    if (g_ins_den == 0u) {
        fnav_cm_sh_puts("bench: error: SysTick does not advance (run qemu with -icount)\n");
        fnav_cm_sh_exit(1);
    }
}

/* Instructions of a tick count, in tenths. */
static uint64_t ins10(uint64_t ticks)
{
    return (ticks * g_ins_num * 10u + g_ins_den / 2u) / g_ins_den;
}

void FNAV_CM_Sample_IRQHandler(void);
void FNAV_CM_Sample_IRQHandler(void)
{
    fnav_cm_prof_mark(PROF_ISR, 1);
    fnav_cm_sample_isr(&g_app.port_ctx);
    fnav_cm_prof_mark(PROF_ISR, 0);
}

static void raise_sample_irq(void)
{
    NVIC_ISPR(FNAV_CM_SAMPLE_IRQN) = NVIC_BIT(FNAV_CM_SAMPLE_IRQN);
    __asm volatile("dsb\n isb" ::: "memory");
}

static void irq_enable(void)
{
    NVIC_ISER(FNAV_CM_SAMPLE_IRQN) = NVIC_BIT(FNAV_CM_SAMPLE_IRQN);
    __asm volatile("cpsie i" ::: "memory");
}

void HardFault_Handler(void);
void HardFault_Handler(void)
{
    fnav_cm_sh_puts("bench: error: hard fault\n");
    fnav_cm_sh_exit(1);
}

void UsageFault_Handler(void);
void UsageFault_Handler(void)
{
    fnav_cm_sh_puts("bench: error: usage fault\n");
    fnav_cm_sh_exit(1);
}

static const char *const k_prof_name[PROF_N] = {
    "ring pop (port read_sample)",
    "navigation step (UKF), all",
    "Allan push (all channels)",
    "Welch push (all channels)",
    "NAV frame out (encode+copy)",
    "SAMPLE frame out",
    "main loop, per sample",
    "sample-ready interrupt",
    "navigation step, no output yet",
    "navigation step, swing",
    "navigation step, stance with ZUPT",
    "stance detector alone (push+pop)",
    "UKF step alone, prediction (every step)",
    "UKF step alone, prediction + ZUPT (stance)",
    "stance update alone (ZUPT)",
    "empty mark pair",
};

static uint64_t minus(uint64_t a, uint64_t b)
{
    return (a > b) ? a - b : 0u;
}

static void print_costs(uint64_t overhead10)
{
    fnav_cm_line_t l;
    int i;
    unsigned built = fnav_cm_est_built();
    fnav_cm_line_start(&l);
    fnav_cm_line_str(&l, "cost (instructions per call, the mark overhead subtracted; min/max resolution: one SysTick tick)");
    fnav_cm_line_end(&l);
    for (i = 0; i < PROF_N - 1; i++) {
        const prof_t *p = &g_prof[i];
        uint64_t mean10;
        fnav_cm_line_str(&l, "cost ");
        fnav_cm_line_str(&l, k_prof_name[i]);
        fnav_cm_line_str(&l, ": ");
        if (!(built & 1u) && (i >= (int)PROF_NAV_NOOUT && i <= (int)PROF_UKF_ZUPT)) {
            continue; /* nothing to split without the filter */
        }
        if ((i == FNAV_CM_PROF_NAV && !(built & 1u)) || (i == FNAV_CM_PROF_ALLAN && !(built & 2u)) ||
            (i == FNAV_CM_PROF_WELCH && !(built & 4u))) {
            fnav_cm_line_str(&l, "not built (stand-in measured: ");
        }
        if (p->count == 0u) {
            fnav_cm_line_str(&l, "no calls");
            fnav_cm_line_end(&l);
            continue;
        }
        mean10 = minus(ins10(p->sum) / p->count, overhead10);
        fnav_cm_line_str(&l, "calls ");
        fnav_cm_line_u64(&l, p->count);
        fnav_cm_line_str(&l, " mean ");
        fnav_cm_line_fix(&l, (int64_t)mean10, 1u);
        fnav_cm_line_str(&l, " min ");
        fnav_cm_line_u64(&l, minus(ins10(p->min), overhead10) / 10u);
        fnav_cm_line_str(&l, " max ");
        fnav_cm_line_u64(&l, minus(ins10(p->max), overhead10) / 10u);
        if ((i == FNAV_CM_PROF_NAV || i == (int)PROF_UKF_PRED || i == (int)PROF_UKF_STANCE) && (built & 1u)) {
            fnav_cm_line_str(&l, "; steps over ");
            fnav_cm_line_u64(&l, NAV_TARGET_INSTRUCTIONS);
            fnav_cm_line_str(&l, ": ");
            fnav_cm_line_u64(&l, p->over);
        }
        if ((i == FNAV_CM_PROF_ALLAN && (built & 2u)) || (i == FNAV_CM_PROF_WELCH && (built & 4u))) {
            uint64_t ch = (i == FNAV_CM_PROF_ALLAN) ? FNAV_CM_ALLAN_CHANNELS : FNAV_CM_WELCH_CHANNELS;
            fnav_cm_line_str(&l, "; per channel push: mean ");
            fnav_cm_line_fix(&l, (int64_t)(mean10 / ch), 1u);
            fnav_cm_line_str(&l, " (");
            fnav_cm_line_u64(&l, ch);
            fnav_cm_line_str(&l, " channels)");
        }
        if ((i == FNAV_CM_PROF_NAV && !(built & 1u)) || (i == FNAV_CM_PROF_ALLAN && !(built & 2u)) ||
            (i == FNAV_CM_PROF_WELCH && !(built & 4u))) {
            fnav_cm_line_str(&l, ")");
        }
        fnav_cm_line_end(&l);
    }
}
#else
static void raise_sample_irq(void)
{
    fnav_cm_sample_isr(&g_app.port_ctx);
}
#endif

FNAV_NORETURN void fnav_port_assert_failed(const char *file, int line, const char *expr)
{
    fnav_cm_line_t l;
    fnav_cm_line_start(&l);
    fnav_cm_line_str(&l, "bench: error: assertion failed: ");
    fnav_cm_line_str(&l, file);
    fnav_cm_line_str(&l, ":");
    fnav_cm_line_i64(&l, line);
    fnav_cm_line_str(&l, ": ");
    fnav_cm_line_str(&l, expr);
    fnav_cm_line_end(&l);
    fnav_cm_sh_exit(1);
}

/* ------------------------------------------------------------ main */

int main(void)
{
    fnav_cm_app_config_t cfg = fnav_cm_app_config_default;
    fnav_cm_line_t l;
    uint32_t i, processed = 0u;
    int status = 0;

    fnav_cm_line_start(&l);
    fnav_cm_line_str(&l, "footnav firmware benchmark: ");
    fnav_cm_line_str(&l, fnav_cm_slice_source);
    fnav_cm_line_str(&l, ", estimators built mask ");
    fnav_cm_line_u64(&l, fnav_cm_est_built());
    fnav_cm_line_end(&l);
    fnav_cm_line_str(&l, "slice-t0: ");
    fnav_cm_line_i64(&l, fnav_cm_slice_n > 0u ? fnav_cm_slice[0].t_ns : 0);
    fnav_cm_line_end(&l);

    cfg.rate_hz = (fnav_cm_slice_rate_hz > 0.0) ? (fnav_real_t)fnav_cm_slice_rate_hz : FNAV_R(400.0);
    cfg.nav_every = 1u;    /* every output, for the trajectory comparison */
    cfg.sample_every = 1u; /* echo every sample: a fingerprint of the stream */
    cfg.status_every = 0u; /* STATUS carries the uptime, which differs between host and emulator */
    if (fnav_cm_app_init(&g_app, &cfg) != FNAV_OK) {
        fnav_cm_sh_puts("bench: error: fnav_cm_app_init failed\n");
        fnav_cm_sh_exit(1);
    }
    fnav_wire_decoder_init(&g_sink.rx);
    (void)fnav_cm_app_announce(&g_app);
    drain_output();

#if defined(__arm__)
    {
        uint64_t overhead10;
        systick_calibrate();
        /* the overhead of a mark pair, averaged over every phase of the
         * tick (the spin of 1..41 iterations shifts the phase) */
        for (i = 0; i < 4100u; i++) {
            spin(1u + i % 41u);
            fnav_cm_prof_mark(PROF_EMPTY, 1);
            fnav_cm_prof_mark(PROF_EMPTY, 0);
        }
        overhead10 = ins10(g_prof[PROF_EMPTY].sum) / g_prof[PROF_EMPTY].count;
        /* ticks of target + overhead instructions, rounded down: a step is
         * counted over when its count, less the overhead, exceeds the target */
        g_nav_target_ticks = (uint32_t)(((uint64_t)NAV_TARGET_INSTRUCTIONS * 10u + overhead10) * g_ins_den /
                                        (g_ins_num * 10u));
        fnav_cm_line_str(&l, "systick: ");
        fnav_cm_line_fix(&l, (int64_t)((g_ins_num * 1000u + g_ins_den / 2u) / g_ins_den), 3u);
        fnav_cm_line_str(&l, " instructions per tick (a ");
        fnav_cm_line_u64(&l, g_ins_num);
        fnav_cm_line_str(&l, "-instruction loop took ");
        fnav_cm_line_u64(&l, g_ins_den);
        fnav_cm_line_str(&l, " ticks); mark pair overhead ");
        fnav_cm_line_fix(&l, (int64_t)overhead10, 1u);
        fnav_cm_line_end(&l);
        irq_enable();
#if FNAV_CM_WITH_NAV
        stance_init(cfg.nav_rate_hz);
#endif
#endif

        for (i = 0; i < fnav_cm_slice_n;) {
            uint32_t k, burst = (i % BURST_EVERY == BURST_EVERY - 1u) ? BURST : 1u;
            for (k = 0; k < burst && i < fnav_cm_slice_n; k++, i++) {
                raise_sample_irq();
            }
            processed += fnav_cm_app_poll(&g_app);
            drain_output();
#if defined(__arm__) && FNAV_CM_WITH_NAV
            stance_feed(i);
#endif
        }

#if defined(__arm__)
        print_costs(overhead10);
    }
#endif

    if (g_sink.nav_n > 0u) {
        print_nav("nav-final", g_sink.nav_n - 1u, &g_sink.nav_last);
    }
    print_estimates();
    fnav_cm_line_str(&l, "stream: samples ");
    fnav_cm_line_u64(&l, processed);
    fnav_cm_line_str(&l, " overruns ");
    fnav_cm_line_u64(&l, g_app.port_ctx.ring.overruns);
    fnav_cm_line_str(&l, " frames info/sample/nav ");
    fnav_cm_line_u64(&l, g_sink.frames[FNAV_WIRE_INFO]);
    fnav_cm_line_str(&l, "/");
    fnav_cm_line_u64(&l, g_sink.frames[FNAV_WIRE_SAMPLE]);
    fnav_cm_line_str(&l, "/");
    fnav_cm_line_u64(&l, g_sink.frames[FNAV_WIRE_NAV]);
    fnav_cm_line_str(&l, " bad ");
    fnav_cm_line_u64(&l, g_sink.rx.stats.bad_frames + g_sink.rx.stats.lost);
    fnav_cm_line_str(&l, " echo-crc ");
    fnav_cm_line_hex32(&l, g_sink.echo_crc);
    fnav_cm_line_str(&l, " echo-mismatch ");
    fnav_cm_line_u64(&l, g_sink.echo_mismatch);
    fnav_cm_line_str(&l, " est-errors ");
    fnav_cm_line_u64(&l, g_app.est_errors);
    fnav_cm_line_end(&l);
    fnav_cm_line_str(&l, "navcrc: ");
    fnav_cm_line_hex32(&l, g_sink.nav_crc);
    fnav_cm_line_str(&l, " over ");
    fnav_cm_line_u64(&l, g_sink.nav_n);
    fnav_cm_line_str(&l, " NAV frames");
    fnav_cm_line_end(&l);

    if (processed != fnav_cm_slice_n || g_app.port_ctx.ring.overruns != 0u ||
        g_sink.frames[FNAV_WIRE_SAMPLE] != fnav_cm_slice_n || g_sink.echo_mismatch != 0u ||
        g_sink.rx.stats.bad_frames != 0u || g_sink.rx.stats.lost != 0u) {
        fnav_cm_sh_puts("bench: error: the stream is not complete and intact\n");
        status = 1;
    }
#if FNAV_CM_WITH_NAV
    /* every frame the filter released is an output and, at nav_every 1, a
     * NAV frame (not one per sample: a sample can release several frames
     * together, and none is dropped) */
    if (g_app.nav_outputs != g_app.est.nav.stats.frames || g_sink.frames[FNAV_WIRE_NAV] != g_app.nav_outputs) {
        fnav_cm_line_str(&l, "bench: error: the filter released ");
        fnav_cm_line_u64(&l, g_app.est.nav.stats.frames);
        fnav_cm_line_str(&l, " frames, the app counted ");
        fnav_cm_line_u64(&l, g_app.nav_outputs);
        fnav_cm_line_str(&l, " outputs and sent ");
        fnav_cm_line_u64(&l, g_sink.frames[FNAV_WIRE_NAV]);
        fnav_cm_line_str(&l, " NAV frames");
        fnav_cm_line_end(&l);
        status = 1;
    }
#endif
    fnav_cm_sh_puts(status == 0 ? "bench: ok\n" : "bench: FAILED\n");
    fnav_cm_sh_exit(status);
    return status;
}
