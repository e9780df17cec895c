/* The reference firmware: main() of the generic Cortex-M4F image
 * (make firmware). The board hooks of fnav_port_cortexm.h supply the IMU,
 * the clock and the output link; without a board the image links and runs
 * but has no samples to process. ARM only. */
#include "fnav_cm_app.h"

/* The one application object; the interrupt handler reaches the ring
 * through it. */
static fnav_cm_app_t g_app;

/* Sample-ready interrupt (vector FNAV_CM_SAMPLE_IRQN). */
void FNAV_CM_Sample_IRQHandler(void);
void FNAV_CM_Sample_IRQHandler(void)
{
    fnav_cm_sample_isr(&g_app.port_ctx);
}

int main(void)
{
    /* the application (and its empty ring) first: the board enables the
     * sample-ready interrupt, whose handler pushes into that ring, and
     * fnav_cm_app_init must not run beside a push (fnav_cm_ring.h) */
    if (fnav_cm_app_init(&g_app, &fnav_cm_app_config_default) != FNAV_OK) {
        for (;;) {
            fnav_cm_idle(); /* a bad build-time configuration: nothing to run */
        }
    }
    /* the board sets the clocks, starts the time base
     * (fnav_cm_systick_start(core_hz), unless it has its own
     * fnav_cm_ticks_ns: only it knows the core clock) and enables the
     * sample-ready interrupt (docs/firmware.md, "Board hooks") */
    fnav_cm_board_init();
    (void)fnav_cm_app_announce(&g_app);
    for (;;) {
        (void)fnav_cm_app_poll(&g_app);
        /* sleeps unless a sample came after the last pop (checked with
         * interrupts masked: a poll then a bare WFI slept past it) */
        fnav_cm_port_wait(&g_app.port_ctx);
    }
}
