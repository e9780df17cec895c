/* The SysTick time base of port/cortex-m read in thread mode and where a
 * board stamps its samples: inside the sample-ready interrupt, which
 * SysTick (same priority) cannot pre-empt. 100,000 interrupts, each reading
 * fnav_cm_ticks_ns() twice around a short busy loop (the SPI read), and a
 * reading in thread mode after each, against a 1 ms SysTick at 25 MHz.
 *
 * Asserted (exit status 1 otherwise): the loop spans at least MIN_WRAPS
 * millisecond wraps, counted by SysTick's own COUNTFLAG, and the last
 * stamp's milliseconds are that count (not a figure of instructions: a
 * faster or slower stamp moves neither check); a reading that goes back
 * (in either mode) is one of QEMU's window below: less than 1 ms back and
 * at most EMU_WINDOW_NS after a millisecond boundary; and
 * fnav_cm_ns_of_ticks(), the stamp's arithmetic as compiled for the M4,
 * equals the 64-bit division at every counter value of a 25 MHz, a
 * 168 MHz and a 1,000,066 Hz clock (multiply-shift, multiply-shift, division).
 * Reported: the readings that went back, the largest offset after a
 * boundary among them, and the cost of a stamp.
 * On a Cortex-M the wrap that makes SysTick pending is visible in ICSR at
 * once, and fnav_cm_ticks_ns() counts it (in thread mode the exception is
 * taken before the count of periods is read again); QEMU sets the pending
 * bit only when it next services its timers, while its counter already
 * reads the reloaded value, so in the emulator a reading in that window
 * goes back by up to 1 ms, in the interrupt and in thread mode alike. So
 * QEMU cannot check the pending-bit path: tests/test_port.c,
 * test_cm_systick_ns, checks it on the host (docs/firmware.md, "SysTick
 * time stamps"). tests/m4/ticks.sh builds and runs it. */
#include <stdint.h>

#include "fnav_cm_semihost.h"
#include "fnav_cm_time.h"
#include "fnav_port_cortexm.h"

#define NVIC_ISER0 (*(volatile uint32_t *)0xE000E100u)
#define NVIC_ISPR0 (*(volatile uint32_t *)0xE000E200u)
#define SYST_CSR (*(volatile uint32_t *)0xE000E010u)
#define SYST_CSR_COUNTFLAG (1u << 16) /* set at a wrap, cleared by the read (ARMv7-M ARM B3.3.3) */

void fnav_port_assert_failed(const char *file, int line, const char *expr)
{
    (void)file;
    (void)line;
    (void)expr;
    fnav_cm_sh_exit(2);
}

/* a reading that goes back is at most this far after a millisecond
 * boundary: the largest offset this test prints (160 ns, 4 ticks:
 * docs/firmware.md, "Board hooks") plus a margin of 6 ticks (240 ns) for
 * another QEMU's timer servicing; a stamp that loses a millisecond shows
 * up to 1 ms after the boundary */
#define EMU_WINDOW_NS 400
/* the loop must cross millisecond boundaries to read near them: it spans
 * 41 (docs/firmware.md, "Board hooks"), so 10 leaves room for a loop
 * nearly 4 times faster on another QEMU or compiler */
#define MIN_WRAPS 10u

static volatile int64_t g_prev = -1, g_worst, g_back_off;
static volatile uint32_t g_calls, g_back, g_back_thread, g_back_bad;

static void check(int64_t t, int thread)
{
    if (g_prev >= 0 && t < g_prev) {
        g_back++;
        g_back_thread += thread ? 1u : 0u;
        if (g_prev - t > g_worst) {
            g_worst = g_prev - t;
        }
        if (t % 1000000 > g_back_off) {
            g_back_off = t % 1000000; /* the offset after the boundary */
        }
        if (g_prev - t >= 1000000 || t % 1000000 > EMU_WINDOW_NS) {
            g_back_bad++; /* not the emulator's window: a wrong stamp */
        }
    }
    g_prev = t;
}

/* fnav_cm_ns_of_ticks() against the division at every c in [0, hz / 1000 - 1] */
static uint32_t scale_mismatches(uint32_t hz)
{
    fnav_cm_ns_scale_t sc;
    uint32_t c, bad = 0;
    fnav_cm_ns_scale_init(&sc, hz, hz / 1000u - 1u);
    for (c = 0; c <= hz / 1000u - 1u; c++) {
        volatile uint32_t cv = c; /* no constant folding */
        bad += fnav_cm_ns_of_ticks(&sc, cv) != (int64_t)cv * 1000000000 / (int64_t)hz;
    }
    return bad;
}

void FNAV_CM_Sample_IRQHandler(void);
void FNAV_CM_Sample_IRQHandler(void)
{
    volatile int k;
    check(fnav_cm_ticks_ns(), 0);
    for (k = 0; k < 20; k++) {
    }
    check(fnav_cm_ticks_ns(), 0);
    g_calls++;
}

static int64_t empty_stamp(void)
{
    return 0;
}

/* One sample's stamp of a FIFO batch of 8 (fnav_cm_batch_stamp: two 64-bit
 * divisions by n, __aeabi_uldivmod on the M4F), the sample index cycling;
 * volatile inputs keep the call from being folded (a constant n of 8 is a
 * shift). */
static volatile int64_t g_batch_prev = 1234567890123LL, g_batch_irq = 1234567890123LL + 20000123LL;
static volatile uint32_t g_batch_i, g_batch_n = 8u; /* n as a FIFO's count: read, not a constant */
static int64_t batch_stamp(void)
{
    const uint32_t i = g_batch_i;
    g_batch_i = (i + 1u) & 7u;
    return fnav_cm_batch_stamp(g_batch_prev, g_batch_irq, i, g_batch_n, 2500000);
}

static int64_t batch_empty(void)
{
    const uint32_t i = g_batch_i;
    g_batch_i = (i + 1u) & 7u;
    return g_batch_prev + g_batch_irq + (int64_t)i + (int64_t)g_batch_n;
}

/* Instructions per call of @p f, through a volatile pointer (not inlined):
 * at -icount shift=0 one instruction is 1 ns of virtual time, and the
 * SysTick time base counts it (plus its own interrupt, ~1 per 1e6). */
static int64_t cost_ns(int64_t (*volatile f)(void), uint32_t n)
{
    volatile int64_t sink;
    uint32_t i;
    const int64_t t0 = fnav_cm_ticks_ns();
    for (i = 0; i < n; i++) {
        sink = f();
    }
    (void)sink;
    return fnav_cm_ticks_ns() - t0;
}

/* One line: what @p f costs more than @p empty per call, over 10000 calls
 * each (head, the figure, mid, both totals, tail). */
static void report_cost(const char *head, int64_t (*f)(void), int64_t (*empty)(void), const char *mid,
                        const char *tail)
{
    fnav_cm_line_t l;
    const int64_t c_f = cost_ns(f, 10000u), c_empty = cost_ns(empty, 10000u);
    fnav_cm_line_start(&l);
    fnav_cm_line_str(&l, head);
    fnav_cm_line_fix(&l, (c_f - c_empty) / 10, 3);
    fnav_cm_line_str(&l, mid);
    fnav_cm_line_i64(&l, c_f);
    fnav_cm_line_str(&l, " and ");
    fnav_cm_line_i64(&l, c_empty);
    fnav_cm_line_str(&l, tail);
    fnav_cm_line_end(&l);
}

int main(void)
{
    fnav_cm_line_t l;
    uint32_t i, wraps = 0, wraps_after;
    int64_t t_end;
    uint32_t mism;
    int ms_ok;
    fnav_cm_systick_start(25000000u); /* writes CVR: COUNTFLAG clear */
    NVIC_ISER0 = 1u << FNAV_CM_SAMPLE_IRQN;
    for (i = 0; i < 100000u; i++) {
        volatile int k;
        NVIC_ISPR0 = 1u << FNAV_CM_SAMPLE_IRQN;
        for (k = 0; k < 10; k++) {
        }
        check(fnav_cm_ticks_ns(), 1); /* thread mode, between interrupts */
        wraps += (SYST_CSR & SYST_CSR_COUNTFLAG) != 0u; /* polled far more often than once a ms */
    }
    wraps += (SYST_CSR & SYST_CSR_COUNTFLAG) != 0u;
    t_end = fnav_cm_ticks_ns();
    wraps_after = wraps + ((SYST_CSR & SYST_CSR_COUNTFLAG) != 0u); /* a wrap between the two */
    ms_ok = t_end / 1000000 >= (int64_t)wraps && t_end / 1000000 <= (int64_t)wraps_after;
    fnav_cm_line_start(&l);
    fnav_cm_line_str(&l, "ticks: ");
    fnav_cm_line_u64(&l, g_calls);
    fnav_cm_line_str(&l, " interrupts over ");
    fnav_cm_line_fix(&l, t_end / 1000, 3);
    fnav_cm_line_str(&l, " ms (");
    fnav_cm_line_u64(&l, wraps);
    fnav_cm_line_str(&l, ms_ok ? " wraps counted by COUNTFLAG, as many ms stamped" : " wraps counted, NOT the ms stamped");
    fnav_cm_line_str(&l, "); readings that went back: ");
    fnav_cm_line_u64(&l, g_back_thread);
    fnav_cm_line_str(&l, " in thread mode, ");
    fnav_cm_line_u64(&l, g_back - g_back_thread);
    fnav_cm_line_str(&l, " in the interrupt (QEMU's late pending bit; worst ");
    fnav_cm_line_i64(&l, g_worst);
    fnav_cm_line_str(&l, " ns)");
    fnav_cm_line_end(&l);
    fnav_cm_line_start(&l);
    fnav_cm_line_str(&l, "ticks: those went back at most ");
    fnav_cm_line_i64(&l, g_back_off);
    fnav_cm_line_str(&l, " ns after a ms boundary; ");
    fnav_cm_line_u64(&l, g_back_bad);
    fnav_cm_line_str(&l, " outside the window of ");
    fnav_cm_line_i64(&l, EMU_WINDOW_NS);
    fnav_cm_line_str(&l, " ns");
    fnav_cm_line_end(&l);
    mism = scale_mismatches(25000000u) + scale_mismatches(168000000u) + scale_mismatches(1000066u);
    fnav_cm_line_start(&l);
    fnav_cm_line_str(&l, "ticks: fnav_cm_ns_of_ticks() against the 64-bit division at 25 MHz, 168 MHz, 1000066 Hz: ");
    fnav_cm_line_u64(&l, mism);
    fnav_cm_line_str(&l, " mismatches");
    fnav_cm_line_end(&l);
    /* the cost of a stamp, reported only (docs/firmware.md, "SysTick") */
    report_cost("ticks: fnav_cm_ticks_ns() costs ", fnav_cm_ticks_ns, empty_stamp,
                " instructions per call more than an empty function (10000 calls: ", " ns at 1 instruction per ns)");
    /* a FIFO batch's per-sample stamp, reported only (docs/firmware.md,
     * "Time stamps from a board") */
    report_cost("ticks: fnav_cm_batch_stamp() costs ", batch_stamp, batch_empty,
                " instructions per sample more than reading its inputs (batches of 8; 10000 calls: ", " ns)");
    fnav_cm_sh_exit(g_back_bad == 0u && mism == 0u && g_calls == 100000u && wraps >= MIN_WRAPS && ms_ok ? 0 : 1);
}
