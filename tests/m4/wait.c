/* The reference main loop's sleep, fnav_cm_port_wait(), in qemu-system-arm
 * (mps2-an386). The main loop polled the ring, then slept with WFI: a
 * sample pushed by the interrupt after the last empty pop waited in the
 * ring until the next interrupt (the firmware audit). fnav_cm_port_wait()
 * checks the ring with interrupts masked and sleeps only when it is empty.
 *
 * 1. A sample waiting, no interrupt enabled: it returns at once (a bare WFI
 *    sleeps for ever: the script's timeout).
 * 2. The sample-ready interrupt made pending under PRIMASK, the ring still
 *    empty (the interrupt came after the check): WFI wakes on it though it
 *    is masked (ARMv7-M ARM B1.5.19), and its handler runs at the unmask,
 *    before fnav_cm_port_wait() returns: one sample in the ring.
 * 3. Nothing waiting, SysTick at 1 ms: it sleeps until the tick and returns
 *    with the tick counted.
 * Exit status 0 when all hold, 1 otherwise; tests/m4/wait.sh. */
#include <stdint.h>
#include <string.h>

#include "fnav_cm_semihost.h"
#include "fnav_port_cortexm.h"

#define NVIC_ISER0 (*(volatile uint32_t *)0xE000E100u)
#define NVIC_ISPR0 (*(volatile uint32_t *)0xE000E200u)
#define SYST_CSR (*(volatile uint32_t *)0xE000E010u)

void fnav_port_assert_failed(const char *file, int line, const char *expr)
{
    (void)file;
    (void)line;
    (void)expr;
    fnav_cm_sh_exit(2);
}

static fnav_cm_port_ctx_t g_ctx;
static volatile uint32_t g_irqs;

int fnav_cm_imu_read(fnav_sample_t *s)
{
    memset(s, 0, sizeof *s);
    s->seq = g_irqs;
    return 0;
}

void FNAV_CM_Sample_IRQHandler(void);
void FNAV_CM_Sample_IRQHandler(void)
{
    g_irqs++;
    fnav_cm_sample_isr(&g_ctx);
}

static int g_fails;

static void check(int ok, const char *what)
{
    fnav_cm_sh_puts(ok ? "ok   wait: " : "FAIL wait: ");
    fnav_cm_sh_puts(what);
    fnav_cm_sh_puts("\n");
    g_fails += ok ? 0 : 1;
}

static uint32_t waiting(void)
{
    return g_ctx.ring.head - g_ctx.ring.tail;
}

int main(void)
{
    fnav_port_t port;
    fnav_sample_t s;
    int64_t t0;
    fnav_cm_port_init(&port, &g_ctx);

    /* 1 */
    fnav_cm_sample_isr(&g_ctx); /* the interrupt's push, after the last empty pop */
    fnav_cm_port_wait(&g_ctx);
    check(waiting() == 1u, "a sample waiting: no sleep");
    (void)fnav_cm_ring_pop(&g_ctx.ring, &s);

    /* 2 */
    NVIC_ISER0 = 1u << FNAV_CM_SAMPLE_IRQN;
    __asm volatile("cpsid i" ::: "memory");
    NVIC_ISPR0 = 1u << FNAV_CM_SAMPLE_IRQN; /* pending, masked: the handler has not run */
    __asm volatile("dsb\n\tisb" ::: "memory");
    check(g_irqs == 0u && waiting() == 0u, "the interrupt pending under PRIMASK, not yet taken");
    fnav_cm_port_wait(&g_ctx);
    check(g_irqs == 1u && waiting() == 1u, "WFI woke on the masked interrupt; its handler ran before the return");
    (void)fnav_cm_ring_pop(&g_ctx.ring, &s);

    /* 3 */
    fnav_cm_systick_start(25000000u);
    t0 = fnav_cm_ticks_ns();
    fnav_cm_port_wait(&g_ctx);
    check(fnav_cm_ticks_ns() / 1000000 > t0 / 1000000, "nothing waiting: slept until the SysTick interrupt");
    SYST_CSR = 0u;

    fnav_cm_sh_exit(g_fails == 0 ? 0 : 1);
}
