/* Start-up code of the Cortex-M4F images: the vector table, the reset
 * handler and the default exception handlers. ARM only (not built for the
 * host). Memory layout symbols come from the linker scripts in ld/. */
#include <stdint.h>
#include <string.h>

#include "fnav_cm_config.h"

extern uint32_t _sidata[]; /* load address of .data (flash) */
extern uint32_t _sdata[];  /* .data in RAM */
extern uint32_t _edata[];
extern uint32_t _sbss[];
extern uint32_t _ebss[];
extern uint32_t _estack[]; /* initial stack pointer: the top of the stack reserve the linker script places at the bottom of RAM */

int main(void);
void Reset_Handler(void);
void fnav_cm_reset_c(void);
void fnav_cm_default_handler(void);

/* Exceptions and interrupts: weak aliases of the default handler, so a
 * board (or the benchmark image) defines only what it uses. */
#define FNAV_CM_HANDLER(name) void name(void) __attribute__((weak, alias("fnav_cm_default_handler")))
FNAV_CM_HANDLER(NMI_Handler);
FNAV_CM_HANDLER(HardFault_Handler);
FNAV_CM_HANDLER(MemManage_Handler);
FNAV_CM_HANDLER(BusFault_Handler);
FNAV_CM_HANDLER(UsageFault_Handler);
FNAV_CM_HANDLER(SVC_Handler);
FNAV_CM_HANDLER(DebugMon_Handler);
FNAV_CM_HANDLER(PendSV_Handler);
FNAV_CM_HANDLER(SysTick_Handler);
FNAV_CM_HANDLER(FNAV_CM_Sample_IRQHandler);

/* External interrupt n: the sample-ready handler at FNAV_CM_SAMPLE_IRQN,
 * the default handler elsewhere. */
#define IRQ(n) (((n) == FNAV_CM_SAMPLE_IRQN) ? FNAV_CM_Sample_IRQHandler : fnav_cm_default_handler)

/* Eight and 32 external interrupts from n. */
#define IRQ8(n) IRQ(n), IRQ((n) + 1), IRQ((n) + 2), IRQ((n) + 3), IRQ((n) + 4), IRQ((n) + 5), IRQ((n) + 6), IRQ((n) + 7)
#define IRQ32(n) IRQ8(n), IRQ8((n) + 8), IRQ8((n) + 16), IRQ8((n) + 24)

/* The vector table: initial stack pointer, then 15 system exceptions and
 * FNAV_CM_IRQ_COUNT external interrupts (ARMv7-M ARM, B1.5.3), a multiple
 * of 32 up to 256: a part with more interrupts than 32 (an STM32F4's 82:
 * 96) sets it, or the vector of an interrupt it enables beyond the table
 * is read from the code after it. A struct keeps the stack pointer (data)
 * apart from the handlers (code) in ISO C. */
typedef struct {
    uint32_t *stack_top;
    void (*handler[15 + FNAV_CM_IRQ_COUNT])(void);
} fnav_cm_vectors_t;

#if FNAV_CM_IRQ_COUNT % 32 != 0 || FNAV_CM_IRQ_COUNT < 32 || FNAV_CM_IRQ_COUNT > 256
#error "FNAV_CM_IRQ_COUNT must be a multiple of 32 from 32 to 256 (fnav_cm_startup.c lists them in blocks of 32)"
#endif

__attribute__((section(".isr_vector"), used)) const fnav_cm_vectors_t fnav_cm_vectors = {
    _estack,
    {
        Reset_Handler, NMI_Handler, HardFault_Handler, MemManage_Handler, BusFault_Handler,
        UsageFault_Handler, 0, 0, 0, 0, SVC_Handler, DebugMon_Handler, 0, PendSV_Handler, SysTick_Handler,
        IRQ32(0)
#if FNAV_CM_IRQ_COUNT > 32
        , IRQ32(32)
#endif
#if FNAV_CM_IRQ_COUNT > 64
        , IRQ32(64)
#endif
#if FNAV_CM_IRQ_COUNT > 96
        , IRQ32(96)
#endif
#if FNAV_CM_IRQ_COUNT > 128
        , IRQ32(128)
#endif
#if FNAV_CM_IRQ_COUNT > 160
        , IRQ32(160)
#endif
#if FNAV_CM_IRQ_COUNT > 192
        , IRQ32(192)
#endif
#if FNAV_CM_IRQ_COUNT > 224
        , IRQ32(224)
#endif
    },
};

/* Reset: give the FPU to the program before anything else runs. The
 * compiler may use FP registers in any C function compiled for the
 * hard-float ABI, so CPACR (0xE000ED88) gets full access for CP10 and CP11
 * here, in assembly, followed by DSB/ISB (ARMv7-M ARM, B3.2.20), before the
 * first C function is called. */
__attribute__((naked, noreturn)) void Reset_Handler(void)
{
    __asm volatile(
        "movw r0, #0xED88      \n"
        "movt r0, #0xE000      \n"
        "ldr  r1, [r0]         \n"
        "orr  r1, r1, #0xF00000\n" /* CP10, CP11: full access */
        "str  r1, [r0]         \n"
        "dsb                   \n"
        "isb                   \n"
        "b    fnav_cm_reset_c  \n");
}

/* C part of the reset: copy .data, zero .bss, run main(). No C library
 * initialisation is needed: the images use no stdio and no heap. */
__attribute__((noreturn, used)) void fnav_cm_reset_c(void)
{
    /* word counts from the linker symbols' addresses (the regions are
     * word-aligned by the linker script) */
    uint32_t n_data = (uint32_t)(((uintptr_t)_edata - (uintptr_t)_sdata) / sizeof(uint32_t));
    uint32_t n_bss = (uint32_t)(((uintptr_t)_ebss - (uintptr_t)_sbss) / sizeof(uint32_t));
    uint32_t i;
    for (i = 0; i < n_data; i++) {
        _sdata[i] = _sidata[i];
    }
    for (i = 0; i < n_bss; i++) {
        _sbss[i] = 0u;
    }
    (void)main();
    for (;;) {
    }
}

/* Unexpected exception: stop where a debugger can see it. */
void fnav_cm_default_handler(void)
{
    __asm volatile("bkpt #0");
    for (;;) {
    }
}
