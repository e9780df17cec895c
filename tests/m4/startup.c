#include <stdint.h>
extern uint32_t _sidata, _sdata, _edata, _sbss, _ebss, _estack;
int main(void);
void Reset_Handler(void);
void Default_Handler(void);
void Default_Handler(void) { for (;;) {} }
__attribute__((section(".isr_vector"))) const void *vectors[16] = {
    &_estack, (void *)Reset_Handler, (void *)Default_Handler, (void *)Default_Handler,
    (void *)Default_Handler, (void *)Default_Handler, (void *)Default_Handler, 0, 0, 0, 0,
    (void *)Default_Handler, (void *)Default_Handler, 0, (void *)Default_Handler, (void *)Default_Handler };
static int semihost(int op, void *arg) {
    register int r0 __asm__("r0") = op; register void *r1 __asm__("r1") = arg;
    __asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory"); return r0; }
void sh_puts(const char *s);
void sh_puts(const char *s) { semihost(0x04, (void *)s); }
void Reset_Handler(void) {
    uint32_t *s = &_sidata, *d = &_sdata;
    while (d < &_edata) *d++ = *s++;
    for (d = &_sbss; d < &_ebss;) *d++ = 0;
    *(volatile uint32_t *)0xE000ED88 |= (0xFu << 20); /* CPACR: FPU on */
    __asm__ volatile("dsb\n isb");
    main();
    semihost(0x18, (void *)0x20026);
    for (;;) {}
}
void fnav_port_assert_failed(const char *file, int line, const char *expr);
void fnav_port_assert_failed(const char *file, int line, const char *expr) { (void)file; (void)line; sh_puts(expr); sh_puts(" ASSERT\n"); semihost(0x18, (void *)0x20026); for (;;) {} }
