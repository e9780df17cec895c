/* Programmer-error hook of the core (fnav_port.h) for the Cortex-M images:
 * break into the debugger and halt. Weak, so the emulator image can report
 * through semihosting instead. ARM only. */
#include "footnav/fnav_port.h"
#include "fnav_cm_config.h"

FNAV_CM_WEAK FNAV_NORETURN void fnav_port_assert_failed(const char *file, int line, const char *expr)
{
    (void)file;
    (void)line;
    (void)expr;
    __asm volatile("bkpt #0");
    for (;;) {
    }
}
