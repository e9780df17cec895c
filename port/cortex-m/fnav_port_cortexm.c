/* Cortex-M4F port (see fnav_port_cortexm.h). */
#include "fnav_port_cortexm.h"
#include "fnav_cm_time.h"

void fnav_cm_sample_isr(fnav_cm_port_ctx_t *ctx)
{
    fnav_sample_t s;
    if (fnav_cm_imu_read(&s) == 0) {
        (void)fnav_cm_ring_push(&ctx->ring, &s);
    }
}

uint32_t fnav_cm_sample_isr_fifo(fnav_cm_port_ctx_t *ctx, uint32_t max)
{
    fnav_sample_t s;
    uint32_t n = 0;
    while (n < max && fnav_cm_imu_read(&s) == 0) {
        (void)fnav_cm_ring_push(&ctx->ring, &s);
        n++;
    }
    return n;
}

/* ---- SysTick time base ---- */

#if defined(__arm__)
#define SYST_CSR (*(volatile uint32_t *)0xE000E010u)
#define SYST_RVR (*(volatile uint32_t *)0xE000E014u)
#define SYST_CVR (*(volatile uint32_t *)0xE000E018u)
#define SCB_ICSR (*(volatile uint32_t *)0xE000ED04u)
#define ICSR_PENDSTSET (1u << 26) /* SysTick exception pending (ARMv7-M ARM, B3.2.4) */

/* the time of the SysTick periods whose interrupt ran, in ns (64 bits: 32
 * wrap after 4.3 s) and the fraction of a ns left, in 1/hz ns: a period is
 * reload + 1 core clocks, 1 ms only when 1000 divides the clock, and
 * counting it as 1 ms ran 40.7 ppm fast at 14.7456 MHz (fnav_cm_time.h) */
static volatile uint64_t g_systick_ns;
static volatile uint32_t g_systick_rem;
/* the period's ns and its remainder, the multiply-shift of the core clocks
 * counted within a period to ns and the reload (fnav_cm_time.h) */
static fnav_cm_systick_scale_t g_systick_scale;

void fnav_cm_systick_start(uint32_t core_hz)
{
    const uint32_t reload = core_hz / 1000u - 1u;
    fnav_cm_systick_scale_init(&g_systick_scale, core_hz, reload);
    g_systick_ns = 0u;
    g_systick_rem = 0u;
    SYST_RVR = reload;
    SYST_CVR = 0u;
    SYST_CSR = 0x7u; /* processor clock, interrupt, enable */
}

void fnav_cm_systick_tick(void)
{
    uint64_t ns = g_systick_ns;
    uint32_t rem = g_systick_rem;
    fnav_cm_systick_add(&g_systick_scale, &ns, &rem);
    g_systick_rem = rem;
    g_systick_ns = ns; /* last: the reader's re-read compares it */
}

#if !defined(FNAV_CM_OWN_SYSTICK)
/* Strong: the startup file's weak alias of the default handler must lose
 * whatever the link order (with two weak definitions the first linked
 * wins, and the first SysTick would halt on the default handler). */
void SysTick_Handler(void);
void SysTick_Handler(void)
{
    fnav_cm_systick_tick();
}
#endif

FNAV_CM_WEAK int64_t fnav_cm_ticks_ns(void)
{
    uint64_t ns;
    uint32_t rem, cvr, cvr_after;
    int pending;
    if (g_systick_scale.hz == 0u) { /* not started */
        return 0;
    }
    do { /* re-read if the period's interrupt ran in between */
        ns = g_systick_ns;
        rem = g_systick_rem;
        cvr = SYST_CVR;
        pending = (SCB_ICSR & ICSR_PENDSTSET) != 0u;
        cvr_after = SYST_CVR;
    } while (ns != g_systick_ns);
    /* a pending wrap counted, the counter's ns without a 64-bit division
     * where the scale is exact (fnav_cm_time.h) */
    return fnav_cm_systick_ns(&g_systick_scale, ns, rem, cvr, pending, cvr_after);
}

FNAV_CM_WEAK void fnav_cm_idle(void)
{
    __asm volatile("wfi");
}
#else
void fnav_cm_systick_start(uint32_t core_hz)
{
    (void)core_hz;
}

FNAV_CM_WEAK int64_t fnav_cm_ticks_ns(void)
{
    return 0;
}

FNAV_CM_WEAK void fnav_cm_idle(void)
{
}
#endif

/* ---- weak defaults: a generic Cortex-M4F without a board ---- */

FNAV_CM_WEAK void fnav_cm_board_init(void)
{
}

FNAV_CM_WEAK int fnav_cm_imu_read(fnav_sample_t *s)
{
    (void)s;
    return -1; /* no IMU attached */
}

FNAV_CM_WEAK int fnav_cm_out_write(const void *bytes, uint32_t n)
{
    (void)bytes;
    (void)n;
    return 0;
}

void fnav_cm_port_wait(fnav_cm_port_ctx_t *ctx)
{
    /* masked, a push cannot come between the check and the sleep; one made
     * pending meanwhile still wakes WFI (ARMv7-M ARM B1.5.19), and its
     * handler runs at CPSIE. DSB: the sleep after every store is done
     * (Arm's WFI idiom); ISB: the handler runs before the next instruction. */
#if defined(__arm__)
    __asm volatile("cpsid i" ::: "memory");
#endif
    if (ctx->ring.head == ctx->ring.tail) {
#if defined(__arm__)
        __asm volatile("dsb" ::: "memory");
#endif
        fnav_cm_idle();
    }
#if defined(__arm__)
    __asm volatile("cpsie i" ::: "memory");
    __asm volatile("isb" ::: "memory");
#endif
}

/* ---- frame output ---- */

static fnav_status_t send(fnav_cm_port_ctx_t *c, size_t n)
{
    if (n == 0u) {
        return FNAV_E_SIZE; /* cannot happen: tx holds the largest frame */
    }
    c->tx_seq++;
    if (fnav_cm_out_write(c->tx, (uint32_t)n) != 0) {
        c->tx_dropped++; /* the receiver sees the gap in seq */
        return FNAV_E_IO;
    }
    c->frames++;
    return FNAV_OK;
}

fnav_status_t fnav_cm_port_send_sample(fnav_cm_port_ctx_t *ctx, const fnav_sample_t *s)
{
    return send(ctx, fnav_wire_encode_sample(ctx->tx, sizeof ctx->tx, ctx->tx_seq, s));
}

fnav_status_t fnav_cm_port_send_status(fnav_cm_port_ctx_t *ctx, const fnav_wire_status_t *st)
{
    return send(ctx, fnav_wire_encode_status(ctx->tx, sizeof ctx->tx, ctx->tx_seq, st));
}

fnav_status_t fnav_cm_port_send_info(fnav_cm_port_ctx_t *ctx, const fnav_wire_info_t *info)
{
    return send(ctx, fnav_wire_encode_info(ctx->tx, sizeof ctx->tx, ctx->tx_seq, info));
}

/* ---- fnav_port_t callbacks ---- */

static fnav_status_t cm_read(void *ctx, fnav_sample_t *s)
{
    fnav_cm_port_ctx_t *c = (fnav_cm_port_ctx_t *)ctx;
    return fnav_cm_ring_pop(&c->ring, s) ? FNAV_OK : FNAV_AGAIN;
}

static int64_t cm_now(void *ctx)
{
    (void)ctx;
    return fnav_cm_ticks_ns();
}

static fnav_status_t cm_write_nav(void *ctx, const fnav_nav_frame_t *f)
{
    fnav_cm_port_ctx_t *c = (fnav_cm_port_ctx_t *)ctx;
    return send(c, fnav_wire_encode_nav(c->tx, sizeof c->tx, c->tx_seq, f));
}

void fnav_cm_port_init(fnav_port_t *port, fnav_cm_port_ctx_t *ctx)
{
    fnav_cm_ring_init(&ctx->ring);
    ctx->frames = 0u;
    ctx->tx_dropped = 0u;
    ctx->tx_seq = 0u;
    port->ctx = ctx;
    port->read_sample = cm_read;
    port->now_ns = cm_now;
    port->write_nav = cm_write_nav;
    port->log = 0;
}
