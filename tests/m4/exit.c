/* The exit status of a semihosting image (port/cortex-m/fnav_cm_semihost.c):
 * main ends with fnav_cm_sh_exit(FNAV_TEST_STATUS). tests/m4/exit.sh builds
 * it with and without FNAV_CM_SH_NO_EXIT_EXTENDED (the plain SYS_EXIT of a
 * debugger without the extension) and checks the emulator's status. */
#include "fnav_cm_semihost.h"

#ifndef FNAV_TEST_STATUS
#error "build with -DFNAV_TEST_STATUS=N"
#endif

int main(void)
{
    fnav_cm_sh_puts("exit: calling fnav_cm_sh_exit\n");
    fnav_cm_sh_exit(FNAV_TEST_STATUS);
}
