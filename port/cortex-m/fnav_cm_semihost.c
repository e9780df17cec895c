/* ARM semihosting (see fnav_cm_semihost.h). The semihosting call is
 * BKPT 0xAB on M-profile with the operation in r0 and the argument in r1
 * (ARM "Semihosting for AArch32 and AArch64", v2.0). On the host build the
 * same functions write to stdout, so the benchmark runs there too. */
#include "fnav_cm_semihost.h"

#if defined(__arm__)
#define SYS_WRITE0 0x04
#define SYS_EXIT 0x18
#define SYS_EXIT_EXTENDED 0x20
#define ADP_STOPPED_APPLICATION_EXIT 0x20026u
#define ADP_STOPPED_RUNTIME_ERROR_UNKNOWN 0x20023u

__attribute__((naked)) static int semihost_call(int op, const void *arg)
{
    (void)op;
    (void)arg;
    __asm volatile(
        "bkpt 0xAB\n"
        "bx lr    \n");
}

void fnav_cm_sh_puts(const char *s)
{
    (void)semihost_call(SYS_WRITE0, s);
}

void fnav_cm_sh_exit(int status)
{
    /* SYS_EXIT_EXTENDED carries the status itself; a debugger without that
     * extension (or an image built with FNAV_CM_SH_NO_EXIT_EXTENDED, for one
     * that halts on an operation it does not know) gets the plain SYS_EXIT,
     * whose reason code says success or failure: a failure goes as
     * ADP_Stopped_RunTimeErrorUnknown, never as ADP_Stopped_ApplicationExit,
     * success (tests/m4/exit.sh) */
    const uintptr_t reason = (status == 0) ? ADP_STOPPED_APPLICATION_EXIT : ADP_STOPPED_RUNTIME_ERROR_UNKNOWN;
#if !defined(FNAV_CM_SH_NO_EXIT_EXTENDED)
    uint32_t block[2];
    block[0] = ADP_STOPPED_APPLICATION_EXIT;
    block[1] = (uint32_t)status;
    (void)semihost_call(SYS_EXIT_EXTENDED, block);
#endif
    (void)semihost_call(SYS_EXIT, (const void *)reason);
    for (;;) {
    }
}
#else
#include <stdio.h>
#include <stdlib.h>

void fnav_cm_sh_puts(const char *s)
{
    fputs(s, stdout);
}

void fnav_cm_sh_exit(int status)
{
    fflush(stdout);
    exit(status);
}
#endif

void fnav_cm_line_start(fnav_cm_line_t *l)
{
    l->n = 0u;
    l->buf[0] = '\0';
}

static void put_char(fnav_cm_line_t *l, char c)
{
    if (l->n + 2u < sizeof l->buf) { /* room for '\n' and NUL */
        l->buf[l->n++] = c;
        l->buf[l->n] = '\0';
    }
}

void fnav_cm_line_str(fnav_cm_line_t *l, const char *s)
{
    while (*s != '\0') {
        put_char(l, *s++);
    }
}

void fnav_cm_line_u64(fnav_cm_line_t *l, uint64_t v)
{
    char d[21];
    int k = 0;
    do {
        d[k++] = (char)('0' + (int)(v % 10u));
        v /= 10u;
    } while (v != 0u);
    while (k > 0) {
        put_char(l, d[--k]);
    }
}

void fnav_cm_line_i64(fnav_cm_line_t *l, int64_t v)
{
    if (v < 0) {
        put_char(l, '-');
        fnav_cm_line_u64(l, (uint64_t)(-(v + 1)) + 1u);
    } else {
        fnav_cm_line_u64(l, (uint64_t)v);
    }
}

void fnav_cm_line_fix(fnav_cm_line_t *l, int64_t v, unsigned decimals)
{
    uint64_t scale = 1u, a;
    unsigned i;
    for (i = 0; i < decimals; i++) {
        scale *= 10u;
    }
    if (v < 0) {
        put_char(l, '-');
        a = (uint64_t)(-(v + 1)) + 1u;
    } else {
        a = (uint64_t)v;
    }
    fnav_cm_line_u64(l, a / scale);
    if (decimals > 0u) {
        uint64_t frac = a % scale;
        put_char(l, '.');
        for (scale /= 10u; scale > 0u; scale /= 10u) {
            put_char(l, (char)('0' + (int)((frac / scale) % 10u)));
        }
    }
}

void fnav_cm_line_hex32(fnav_cm_line_t *l, uint32_t v)
{
    static const char hex[] = "0123456789abcdef";
    int i;
    for (i = 28; i >= 0; i -= 4) {
        put_char(l, hex[(v >> i) & 0xFu]);
    }
}

void fnav_cm_line_end(fnav_cm_line_t *l)
{
    l->buf[l->n++] = '\n';
    l->buf[l->n] = '\0';
    fnav_cm_sh_puts(l->buf);
    fnav_cm_line_start(l);
}
