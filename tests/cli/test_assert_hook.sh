#!/bin/sh
# The port's assert hook, fnav_port_assert_failed (include/footnav/fnav_port.h),
# is declared FNAV_NORETURN (fnav_types.h): a definition that can return
# does not compile with the project's flags (-Werror), with the host's C
# compilers (gcc, clang) and arm-none-eabi-gcc, in the float and the double
# build; definitions that end the program (abort, an endless loop) do, and
# so do a CMocka test's (mock_assert, then abort() not reached) and the
# repository's own (port/linux, port/cortex-m, the emulator
# images' in tests/m4 and the benchmark). A returning hook is undefined
# behaviour once the core relies on the attribute (docs/firmware.md, "The
# callbacks' contract"). A compiler that is not installed is skipped
# visibly.
set -u
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
WARN="-std=c99 -pedantic -Wall -Wextra -Wmissing-prototypes -Wdouble-promotion -Wshadow -Wstrict-prototypes -Werror"
ARM_ARCH="-mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard"

cat >"$T/returns.c" <<'EOF'
#include "footnav/footnav.h"
int g_asserts;
void fnav_port_assert_failed(const char *file, int line, const char *expr)
{
    (void)file;
    (void)line;
    (void)expr;
    g_asserts++; /* records and returns: not allowed */
}
EOF
cat >"$T/aborts.c" <<'EOF'
#include <stdlib.h>
#include "footnav/footnav.h"
void fnav_port_assert_failed(const char *file, int line, const char *expr)
{
    (void)file;
    (void)line;
    (void)expr;
    abort();
}
EOF
cat >"$T/spins.c" <<'EOF'
#include "footnav/footnav.h"
void fnav_port_assert_failed(const char *file, int line, const char *expr)
{
    (void)file;
    (void)line;
    (void)expr;
    for (;;) {
    }
}
EOF

# a CMocka test's hook: mock_assert longjmps but is not declared noreturn,
# so the hook ends in abort() (not reached); without it, it is refused
cat >"$T/mock_asserts.c" <<'EOF'
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <stdlib.h>
#include <cmocka.h>
#include "footnav/footnav.h"
void fnav_port_assert_failed(const char *file, int line, const char *expr)
{
    mock_assert(0, expr, file, line);
    abort(); /* not reached: mock_assert longjmps */
}
EOF
grep -v 'not reached' "$T/mock_asserts.c" >"$T/mock_only.c"

# compiler label extra-flags
check_compiler() {
    cc_=$1; label=$2; extra=$3
    if ! command -v "$cc_" >/dev/null 2>&1; then
        echo "SKIP test_assert_hook.sh: $cc_ not installed, the hook not checked with it"
        return
    fi
    for defs in "" "-DFNAV_USE_DOUBLE=1"; do
        b=float; [ -n "$defs" ] && b=double
        # shellcheck disable=SC2086
        if "$cc_" $WARN $extra $defs -Iinclude -c -o "$T/r.o" "$T/returns.c" >"$T/err" 2>&1; then
            fail "$label ($b): a hook that returns compiles: fnav_port_assert_failed is not declared noreturn"
        elif grep -q -i 'noreturn' "$T/err"; then
            pass "$label ($b): a hook that returns is refused as a noreturn function that returns"
        else
            fail "$label ($b): a hook that returns is refused, but not for returning"; cat "$T/err"
        fi
        # the host's cmocka.h (not for the ARM compiler, nor where CMocka is missing)
        mock=
        if [ "$label" != arm-none-eabi-gcc ]; then
            if "$cc_" -E -o /dev/null "$T/mock_asserts.c" -Iinclude >/dev/null 2>&1; then
                mock=mock_asserts
                # shellcheck disable=SC2086
                if "$cc_" $WARN $extra $defs -Iinclude -c -o "$T/r.o" "$T/mock_only.c" >"$T/err" 2>&1; then
                    fail "$label ($b): a hook that only calls mock_assert compiles: it is not declared noreturn"
                elif grep -q -i 'noreturn' "$T/err"; then
                    pass "$label ($b): a hook that only calls mock_assert is refused (mock_assert is not noreturn)"
                else
                    fail "$label ($b): a hook that only calls mock_assert is refused, but not for returning"
                    cat "$T/err"
                fi
            else
                echo "SKIP test_assert_hook.sh: cmocka.h not found by $cc_, the mock_assert hook not checked"
            fi
        fi
        for ok in spins $( [ "$label" = arm-none-eabi-gcc ] || echo aborts) $mock; do
            # shellcheck disable=SC2086
            if "$cc_" $WARN $extra $defs -Iinclude -c -o "$T/o.o" "$T/$ok.c" >"$T/err" 2>&1; then
                pass "$label ($b): a hook that $ok compiles"
            else
                fail "$label ($b): a hook that $ok does not compile"; cat "$T/err"
            fi
        done
    done
}
check_compiler "${CC:-cc}" cc ""
check_compiler clang clang ""
ARM_CC=${ARM_CC:-arm-none-eabi-gcc}
check_compiler "$ARM_CC" arm-none-eabi-gcc "$ARM_ARCH"

# the repository's own hooks compile against the noreturn declaration
# (make builds port/linux and port/cortex-m; these are the others)
if command -v "$ARM_CC" >/dev/null 2>&1; then
    FW_CONFIG="-DFNAV_CONFIG_FILE=\"fnav_cm_fw_config.h\""
    # tests/m4/main.c's data header, made as tests/m4/run.sh makes it (10 samples)
    /usr/bin/python3 tests/m4/gen_data.py "$T/m4_data.h" 10 >"$T/err" 2>&1 || { fail "tests/m4/gen_data.py failed"; cat "$T/err"; }
    for f in port/cortex-m/fnav_cm_fault.c port/cortex-m/fnav_cm_bench.c tests/m4/main.c tests/m4/ticks.c; do
        # shellcheck disable=SC2086
        if "$ARM_CC" $WARN $ARM_ARCH -Os -Iinclude -Iport/cortex-m -I"$T" "$FW_CONFIG" -DFNAV_CM_PROFILE=1 \
            -c -o "$T/h.o" "$f" >"$T/err" 2>&1; then
            pass "$f: its hook compiles as noreturn (arm-none-eabi-gcc)"
        elif grep -q -i 'noreturn' "$T/err"; then
            fail "$f: its hook can return"; cat "$T/err"
        else
            fail "$f: does not compile with the project's flags"; cat "$T/err"
        fi
    done
fi
if [ "$fails" -ne 0 ]; then echo "test_assert_hook.sh: $fails failure(s)"; exit 1; fi
echo "test_assert_hook.sh: all passed"
