/* Cortex-M4F port skeleton (see fnav_port_cortexm.h). */
#include "fnav_port_cortexm.h"

void fnav_cm_sample_isr(fnav_cm_port_ctx_t *ctx)
{
    fnav_sample_t s;
    if (fnav_cm_imu_read(&s) == 0) {
        (void)fnav_cm_ring_push(&ctx->ring, &s);
    }
}

/* ---- weak defaults: a generic Cortex-M4F without a board ---- */

__attribute__((weak)) int fnav_cm_imu_read(fnav_sample_t *s)
{
    (void)s;
    return -1; /* no IMU attached */
}

/* SysTick: CTRL 0xE000E010, LOAD 0xE000E014, VAL 0xE000E018. The default
 * time base counts SysTick wraps set up by the board; without one, time
 * stands still (samples carry their own time stamps anyway). */
__attribute__((weak)) int64_t fnav_cm_ticks_ns(void)
{
    return 0;
}

__attribute__((weak)) int fnav_cm_out_write(const void *bytes, uint32_t n)
{
    (void)bytes;
    (void)n;
    return 0;
}

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
    if (fnav_cm_out_write(f, (uint32_t)sizeof *f) != 0) {
        return FNAV_E_IO;
    }
    c->frames++;
    return FNAV_OK;
}

void fnav_cm_port_init(fnav_port_t *port, fnav_cm_port_ctx_t *ctx)
{
    fnav_cm_ring_init(&ctx->ring);
    ctx->frames = 0u;
    port->ctx = ctx;
    port->read_sample = cm_read;
    port->now_ns = cm_now;
    port->write_nav = cm_write_nav;
    port->log = 0;
}

void fnav_port_assert_failed(const char *file, int line, const char *expr)
{
    (void)file;
    (void)line;
    (void)expr;
#if defined(__arm__)
    __asm volatile("bkpt #0");
#endif
    for (;;) {
    }
}
