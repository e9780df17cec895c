/* Cortex-M4F port (see fnav_port_cortexm.h). */
#include "fnav_port_cortexm.h"

void fnav_cm_sample_isr(fnav_cm_port_ctx_t *ctx)
{
    fnav_sample_t s;
    if (fnav_cm_imu_read(&s) == 0) {
        (void)fnav_cm_ring_push(&ctx->ring, &s);
    }
}

/* ---- SysTick time base ---- */

#if defined(__arm__)
#define SYST_CSR (*(volatile uint32_t *)0xE000E010u)
#define SYST_RVR (*(volatile uint32_t *)0xE000E014u)
#define SYST_CVR (*(volatile uint32_t *)0xE000E018u)

static volatile uint32_t g_systick_ms;  /* 1 ms interrupts since start */
static uint32_t g_systick_reload;       /* core clocks per ms - 1 */
static uint32_t g_systick_hz;

void fnav_cm_systick_start(uint32_t core_hz)
{
    g_systick_hz = core_hz;
    g_systick_reload = core_hz / 1000u - 1u;
    g_systick_ms = 0u;
    SYST_RVR = g_systick_reload;
    SYST_CVR = 0u;
    SYST_CSR = 0x7u; /* processor clock, interrupt, enable */
}

/* Weak: a board that needs SysTick for something else replaces it. */
FNAV_CM_WEAK void SysTick_Handler(void);
FNAV_CM_WEAK void SysTick_Handler(void)
{
    g_systick_ms++;
}

FNAV_CM_WEAK int64_t fnav_cm_ticks_ns(void)
{
    uint32_t ms, cvr;
    if (g_systick_hz == 0u) {
        return 0;
    }
    do { /* re-read if the millisecond interrupt hit in between */
        ms = g_systick_ms;
        cvr = SYST_CVR;
    } while (ms != g_systick_ms);
    return (int64_t)ms * 1000000 +
           (int64_t)(g_systick_reload - cvr) * 1000000000 / (int64_t)g_systick_hz;
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
