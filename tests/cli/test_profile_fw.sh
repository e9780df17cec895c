#!/bin/sh
# The built-in profiles on the Cortex-M4F: a program that takes one with
# fnav_profile_builtin or fnav_profile_by_name, built as docs/firmware.md's
# "In your own build" builds (unused sections collected), links no
# soft-float double helper (__aeabi_dmul, __aeabi_ddiv, __aeabi_d2f, the
# comparisons, ...): the paper's tables are converted by the compiler
# (src/fnav_profile.c; the same bits as fnav_profile_from_paper's, test_profile
# test_builtin_exact). fnav_profile_from_paper takes a double rate and does
# link them, which the check must see (else it would prove nothing).
# Skipped visibly without the cross-compiler.
set -u
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
ARM_CC=${ARM_CC:-arm-none-eabi-gcc}
ARM_NM=${ARM_NM:-arm-none-eabi-nm}
if ! command -v "$ARM_CC" >/dev/null 2>&1 || ! command -v "$ARM_NM" >/dev/null 2>&1; then
    echo "SKIP test_profile_fw.sh: no $ARM_CC or $ARM_NM, the Cortex-M4F build not checked"
    exit 0
fi
FLAGS="-mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard -Os -std=c99 -pedantic -Wall -Wextra -Werror
 -Iinclude -ffunction-sections -fdata-sections -Wl,--gc-sections --specs=nano.specs --specs=nosys.specs"
DBL='__aeabi_(d[a-z0-9]+|f2d|i2d|ui2d|l2d|ul2d)$'

# prog CALL: a program whose profile comes from CALL (p: the profile)
prog() {
    cat <<EOF
#include <stdlib.h>
#include "footnav/footnav.h"
void fnav_port_assert_failed(const char *file, int line, const char *expr)
{
    (void)file;
    (void)line;
    (void)expr;
    abort();
}
volatile float g_sink;
int main(void)
{
    fnav_profile_t p;
    const fnav_profile_paper_row_t *rows = fnav_profile_paper_table(FNAV_PROFILE_MTX);
    (void)rows;
    if ($1 != FNAV_OK) {
        return 1;
    }
    g_sink = (float)p.gyro_tau_s[0];
    return 0;
}
EOF
}

# name CALL WANT (none: no helper may be linked; some: at least one must be)
check() {
    prog "$2" >"$T/$1.c"
    # shellcheck disable=SC2086
    if ! "$ARM_CC" $FLAGS -o "$T/$1.elf" "$T/$1.c" src/*.c -lm >"$T/err" 2>&1; then
        fail "$1: does not build for the Cortex-M4F"; cat "$T/err"
        return
    fi
    dbl=$("$ARM_NM" "$T/$1.elf" | awk '{ print $NF }' | grep -E "$DBL" | tr '\n' ' ')
    if [ "$3" = none ] && [ -z "$dbl" ]; then
        pass "$1: the Cortex-M4F image links no soft-float double helper"
    elif [ "$3" = none ]; then
        fail "$1: the Cortex-M4F image links soft-float double helpers: $dbl"
    elif [ -n "$dbl" ]; then
        pass "$1: the Cortex-M4F image links soft-float double helpers, as expected ($dbl)"
    else
        fail "$1: no soft-float double helper found: the check cannot see them"
    fi
}
check builtin 'fnav_profile_builtin(&p, FNAV_PROFILE_NAVCHIP)' none
check by_name 'fnav_profile_by_name(&p, "shimmer")' none
check from_paper 'fnav_profile_from_paper(&p, "x", 100.0, fnav_profile_paper_table(FNAV_PROFILE_MTX))' some

if [ "$fails" -ne 0 ]; then echo "test_profile_fw.sh: $fails failure(s)"; exit 1; fi
echo "test_profile_fw.sh: all passed"
