/**
 * @file fnav_cm_semihost.h
 * @brief ARM semihosting for the emulator image (qemu-system-arm
 *        -semihosting-config enable=on,target=native): text output to the
 *        host's console and the exit status. No C library I/O is used, so
 *        the image stays free of stdio and malloc. Integer printing only.
 */
#ifndef FNAV_CM_SEMIHOST_H
#define FNAV_CM_SEMIHOST_H

#include <stdint.h>

/** Write a NUL-terminated string to the host console (SYS_WRITE0). */
void fnav_cm_sh_puts(const char *s);
/** End the emulation with an exit status (SYS_EXIT_EXTENDED). */
void fnav_cm_sh_exit(int status) __attribute__((noreturn));

/** A line being built for output (no heap, no printf). */
typedef struct {
    char buf[200];
    unsigned n;
} fnav_cm_line_t;

void fnav_cm_line_start(fnav_cm_line_t *l);
void fnav_cm_line_str(fnav_cm_line_t *l, const char *s);
void fnav_cm_line_u64(fnav_cm_line_t *l, uint64_t v);
void fnav_cm_line_i64(fnav_cm_line_t *l, int64_t v);
/** Fixed point: v / 10^decimals with the decimals printed. */
void fnav_cm_line_fix(fnav_cm_line_t *l, int64_t v, unsigned decimals);
void fnav_cm_line_hex32(fnav_cm_line_t *l, uint32_t v);
/** Append a newline and write the line. */
void fnav_cm_line_end(fnav_cm_line_t *l);

#endif /* FNAV_CM_SEMIHOST_H */
