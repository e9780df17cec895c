#!/bin/sh
# The C examples of the documentation compile and run as written: every
# ```c block of README.md and docs/*.md is taken as the body of
#     static int doc_snippet(const fnav_real_t *x, const fnav_real_t *y, size_t n)
# (x and y: one channel's samples each, n of them; return 0 on success, a
# negative value on an error), compiled with the project's warning flags in
# the float and the double build against the core sources and run on n =
# 100,000 uniform samples in [-1, 1]. A block with a main() is a whole
# program (the port example of docs/firmware.md): compiled as it is and run
# with a CSV log on standard input (t,ax,ay,az,gx,gy,gz with a header line:
# 400 samples at 200 Hz of a sensor at rest, +z up); it must exit 0, and
# with arm-none-eabi-gcc it must also build for the Cortex-M4F. A block
# that is not meant to compile must not be tagged c. Skipped visibly
# without a C compiler.
set -u
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
cd "$(dirname "$0")/../.." || exit 1
CC=${CC:-cc} # may hold words, e.g. "ccache gcc"
# shellcheck disable=SC2086
if ! command -v ${CC%% *} >/dev/null 2>&1; then
    echo "SKIP test_doc_snippets.sh: no C compiler ($CC) found"
    exit 0
fi
# the WARN flags of the Makefile (keep the two in step)
WARN="-std=c99 -pedantic -Wall -Wextra -Wmissing-prototypes -Wdouble-promotion -Wshadow -Wstrict-prototypes -Werror"

# one file per block: $T/snip_N.c holds the block, $T/snip_N.where its file:line
awk -v D="$T" '
    FNR == 1 { inb = 0; fence = 0 }
    /^```/ {
        if (inb) { inb = 0; close(out); next }
        if (fence) { fence = 0; next }
        if ($0 ~ /^```c[ \t]*$/) {
            k++; inb = 1; out = D "/snip_" k ".c"; w = D "/snip_" k ".where"
            print FILENAME ":" FNR + 1 > w; close(w); printf "" > out; next
        }
        fence = 1; next
    }
    inb { print > out }
    END { print k + 0 > (D "/count") }' README.md docs/*.md
count=$(cat "$T/count" 2>/dev/null || echo 0)
if [ "$count" -eq 0 ]; then
    fail "no \`\`\`c block found in README.md or docs/*.md (the extraction is broken, or the examples are gone)"
    exit 1
fi

cat >"$T/wrap_head.h" <<'EOF'
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include "footnav/footnav.h"
void fnav_port_assert_failed(const char *file, int line, const char *expr)
{
    fprintf(stderr, "assertion failed: %s:%d: %s\n", file, line, expr);
    abort();
}
static int doc_snippet(const fnav_real_t *x, const fnav_real_t *y, size_t n)
{
    (void)x;
    (void)y;
    (void)n;
EOF
cat >"$T/wrap_tail.h" <<'EOF'
    return 0;
}
#define DOC_N 100000u
static fnav_real_t doc_x[DOC_N], doc_y[DOC_N];
int main(void)
{
    unsigned long s = 12345u;
    size_t k;
    for (k = 0; k < DOC_N; k++) { /* uniform in [-1, 1], a fixed LCG */
        s = (s * 1103515245u + 12345u) & 0x7fffffffu;
        doc_x[k] = (fnav_real_t)((double)s / 1073741823.5 - 1.0);
        s = (s * 1103515245u + 12345u) & 0x7fffffffu;
        doc_y[k] = (fnav_real_t)((double)s / 1073741823.5 - 1.0);
    }
    return doc_snippet(doc_x, doc_y, DOC_N) == 0 ? 0 : 1;
}
EOF

awk 'BEGIN { print "t,ax,ay,az,gx,gy,gz"; for (k = 0; k < 400; k++) printf "%.3f,0.01,-0.02,9.81,0.001,0.002,-0.001\n", k / 200 }' >"$T/rest.csv"

for build in float double; do
    defs=""
    [ "$build" = double ] && defs="-DFNAV_USE_DOUBLE=1"
    mkdir -p "$T/$build"
    # shellcheck disable=SC2086
    if ! (cd "$T/$build" && $CC $WARN $defs -O0 -I"$OLDPWD/include" -c "$OLDPWD"/src/*.c) >"$T/err" 2>&1; then
        fail "the core sources do not compile ($build)"; cat "$T/err"; continue
    fi
    i=1
    while [ "$i" -le "$count" ]; do
        where=$(cat "$T/snip_$i.where")
        if grep -q 'int main(' "$T/snip_$i.c"; then
            cp "$T/snip_$i.c" "$T/$build/s$i.c"
        else
            cat "$T/wrap_head.h" "$T/snip_$i.c" "$T/wrap_tail.h" >"$T/$build/s$i.c"
        fi
        # shellcheck disable=SC2086
        if $CC $WARN $defs -O1 -Iinclude -o "$T/$build/s$i" "$T/$build/s$i.c" "$T/$build"/*.o -lm >"$T/err" 2>&1; then
            if "$T/$build/s$i" <"$T/rest.csv" >"$T/out" 2>"$T/err"; then
                pass "$where: the C example compiles and runs ($build)"
            else
                fail "$where: the C example compiles but returns an error ($build)"; cat "$T/err"
            fi
        else
            fail "$where: the C example does not compile with the project's flags ($build)"; cat "$T/err"
        fi
        i=$((i + 1))
    done
done
# A whole program also builds for the Cortex-M4F as docs/firmware.md ("In
# your own build") says: with the flags of the page's command (the line that
# begins with arm-none-eabi-gcc, its continuation lines joined, the words
# before -o), which must collect unused sections (-ffunction-sections
# -fdata-sections -Wl,--gc-sections, each checked here), with newlib-nano
# and its I/O stubs (nosys), linked.
ARM_CC=${ARM_CC:-arm-none-eabi-gcc}
ARM_NM=${ARM_NM:-arm-none-eabi-nm}
DOC_ARM_FLAGS=$(awk '
    /^arm-none-eabi-gcc / { on = 1; cmd = "" }
    on { line = $0; cont = sub(/\\[ \t]*$/, "", line); cmd = cmd " " line; if (!cont) { print cmd; exit } }
' docs/firmware.md | awk '{ for (i = 2; i <= NF && $i != "-o"; i++) printf "%s ", $i }')
if [ -z "$DOC_ARM_FLAGS" ]; then
    fail "docs/firmware.md: no arm-none-eabi-gcc command found (\"In your own build\")"
fi
for flag in -ffunction-sections -fdata-sections -Wl,--gc-sections --specs=nano.specs --specs=nosys.specs; do
    case " $DOC_ARM_FLAGS " in
    *" $flag "*) pass "docs/firmware.md: the Cortex-M4F command has $flag" ;;
    *) fail "docs/firmware.md: the Cortex-M4F command lacks $flag (flags: $DOC_ARM_FLAGS)" ;;
    esac
done
if command -v "$ARM_CC" >/dev/null 2>&1 && [ -n "$DOC_ARM_FLAGS" ]; then
    i=1
    while [ "$i" -le "$count" ]; do
        where=$(cat "$T/snip_$i.where")
        if grep -q 'int main(' "$T/snip_$i.c"; then
            # shellcheck disable=SC2086
            if "$ARM_CC" $DOC_ARM_FLAGS $WARN -o "$T/arm_s$i.elf" "$T/snip_$i.c" src/*.c -lm >"$T/err" 2>&1; then
                pass "$where: the C program builds for the Cortex-M4F"
                # only what the program reaches is in the image: the port
                # example navigates, so none of the core's Allan, Welch or
                # wire-protocol code (fnav_allan_edf_var: double arithmetic,
                # soft-float on the M4F) may be linked in
                if ! command -v "$ARM_NM" >/dev/null 2>&1; then
                    echo "SKIP test_doc_snippets.sh: no $ARM_NM, the image's symbols not checked"
                elif grep -q 'fnav_allan_\|fnav_welch_\|fnav_wire_' "$T/snip_$i.c"; then
                    :
                elif "$ARM_NM" "$T/arm_s$i.elf" | grep -E ' [Tt] (fnav_allan_|fnav_welch_|fnav_wire_)' >"$T/unused"; then
                    fail "$where: the Cortex-M4F image holds $(wc -l <"$T/unused") core functions the program never calls\
 (e.g. $(awk 'NR == 1 { print $3 }' "$T/unused")): the build lacks -ffunction-sections -fdata-sections -Wl,--gc-sections"
                else
                    pass "$where: the Cortex-M4F image holds none of the core functions the program never calls"
                fi
            else
                fail "$where: the C program does not build for the Cortex-M4F"; cat "$T/err"
            fi
        fi
        i=$((i + 1))
    done
else
    echo "SKIP test_doc_snippets.sh: no $ARM_CC, the Cortex-M4F build of the programs not checked"
fi
if [ "$fails" -ne 0 ]; then echo "test_doc_snippets.sh: $fails failure(s)"; exit 1; fi
echo "test_doc_snippets.sh: all passed"
