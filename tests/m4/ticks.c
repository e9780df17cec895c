/* The SysTick time base of port/cortex-m read in thread mode and where a
 * board stamps its samples: inside the sample-ready interrupt, which
 * SysTick (same priority) cannot pre-empt. 100,000 interrupts, each reading
 * fnav_cm_ticks_ns() twice around a short busy loop (the SPI read), and a
 * reading in thread mode after each, against a 1 ms SysTick at 25 MHz.
 *
 * Asserted (exit status 1 otherwise): no thread-mode reading goes back, and
 * time advances. Reported only: the in-interrupt readings that went back.
 * On a Cortex-M the wrap that makes SysTick pending is visible in ICSR at
 * once, and fnav_cm_ticks_ns() counts it; QEMU sets the pending bit only
 * when it next services its timers (after the translation block), while
 * its counter already reads the reloaded value, so in the emulator a
 * reading in that window still goes back by up to 1 ms (docs/firmware.md).
 * tests/m4/ticks.sh builds and runs it. */
#include <stdint.h>

#include "fnav_cm_semihost.h"
#include "fnav_port_cortexm.h"

#define NVIC_ISER0 (*(volatile uint32_t *)0xE000E100u)
#define NVIC_ISPR0 (*(volatile uint32_t *)0xE000E200u)

void fnav_port_assert_failed(const char *file, int line, const char *expr)
{
    (void)file;
    (void)line;
    (void)expr;
    fnav_cm_sh_exit(2);
}

static volatile int64_t g_prev = -1, g_worst;
static volatile uint32_t g_calls, g_back, g_back_thread;

static void check(int64_t t, int thread)
{
    if (g_prev >= 0 && t < g_prev) {
        g_back++;
        g_back_thread += thread ? 1u : 0u;
        if (g_prev - t > g_worst) {
            g_worst = g_prev - t;
        }
    }
    g_prev = t;
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

int main(void)
{
    fnav_cm_line_t l;
    uint32_t i;
    int64_t t_end;
    fnav_cm_systick_start(25000000u);
    NVIC_ISER0 = 1u << FNAV_CM_SAMPLE_IRQN;
    for (i = 0; i < 100000u; i++) {
        volatile int k;
        NVIC_ISPR0 = 1u << FNAV_CM_SAMPLE_IRQN;
        for (k = 0; k < 10; k++) {
        }
        check(fnav_cm_ticks_ns(), 1); /* thread mode, between interrupts */
    }
    t_end = fnav_cm_ticks_ns();
    fnav_cm_line_start(&l);
    fnav_cm_line_str(&l, "ticks: ");
    fnav_cm_line_u64(&l, g_calls);
    fnav_cm_line_str(&l, " interrupts over ");
    fnav_cm_line_fix(&l, t_end / 1000, 3);
    fnav_cm_line_str(&l, " ms; readings that went back: ");
    fnav_cm_line_u64(&l, g_back_thread);
    fnav_cm_line_str(&l, " in thread mode, ");
    fnav_cm_line_u64(&l, g_back - g_back_thread);
    fnav_cm_line_str(&l, " in the interrupt (QEMU's late pending bit; worst ");
    fnav_cm_line_i64(&l, g_worst);
    fnav_cm_line_str(&l, " ns)");
    fnav_cm_line_end(&l);
    fnav_cm_sh_exit(g_back_thread == 0u && g_calls == 100000u && t_end > 50000000 ? 0 : 1);
}
