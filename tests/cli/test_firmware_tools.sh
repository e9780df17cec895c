#!/bin/sh
# The firmware report tools on small images with known answers:
# port/cortex-m/tools/stack_report.py (worst-case stack from
# -fcallgraph-info=su and the disassembly: sums along the deepest path,
# indirect calls resolved by a table, recursion and unlisted indirect calls
# refused) and tools/fw_size.sh (budget check). Skipped visibly without the
# ARM toolchain.
set -u
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
CC=${ARM_CC:-arm-none-eabi-gcc}
PY=${PYTHON:-/usr/bin/python3}
if ! command -v "$CC" >/dev/null 2>&1; then
    echo "SKIP test_firmware_tools.sh: $CC not installed"
    exit 0
fi
ARCH="-mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard"
LD="-nostartfiles --specs=nano.specs -Wl,--gc-sections -Lport/cortex-m/ld -Tcortex-m4f.ld"

# a -> b -> c (volatile locals keep every frame), d called through a pointer
cat >"$T/t.c" <<'EOF'
#include <stdint.h>
typedef int (*fn_t)(int);
int c(int x);
int b(int x);
int a(int x);
int d(int x);
int Reset_Handler(void);
int main(void);
fn_t g_fn;
__attribute__((noinline)) int c(int x) { volatile int v[40]; v[0] = x; return v[0]; }
__attribute__((noinline)) int b(int x) { volatile int v[20]; v[0] = c(x); return v[0]; }
__attribute__((noinline)) int a(int x) { volatile int v[10]; v[0] = b(x); return v[0] + g_fn(x); }
__attribute__((noinline)) int d(int x) { volatile int v[100]; v[0] = x; return v[0]; }
#ifdef RECURSE
__attribute__((noinline)) int r(int x);
__attribute__((noinline)) int r(int x) { volatile int v[4]; v[0] = x; return x > 0 ? 1 + r(x - v[0] / 2) * v[0] : 0; }
#endif
int main(void) { g_fn = d; return a(1)
#ifdef RECURSE
    + r(3)
#endif
    ; }
__attribute__((used)) const uint32_t vec[2] __attribute__((section(".isr_vector"))) = { 0x20001000u, 0 };
int Reset_Handler(void) { return main(); }
EOF
build() { # name extra-flags
    (cd "$T" && $CC $ARCH -Os -fstack-usage -fcallgraph-info=su -c t.c -o "$1.o" $2) &&
        $CC $ARCH $LD -o "$T/$1.elf" "$T/$1.o" -lc >/dev/null 2>&1
}
report() { # name indirect-table
    printf '%s' "$2" >"$T/ind.txt"
    "$PY" port/cortex-m/tools/stack_report.py --elf "$T/$1.elf" --objdump arm-none-eabi-objdump --nm arm-none-eabi-nm \
        --indirect "$T/ind.txt" --reserve-symbol _stack_size "$T/$1.ci" >"$T/out" 2>&1
}
su() { awk -v f="$1" -F'\t' '{ n = split($1, p, ":"); if (p[n] == f) print $2 }' "$T/plain.su"; }

if ! build plain ""; then fail "cannot build the test image"; exit 1; fi
A=$(su a); B=$(su b); C=$(su c); D=$(su d); M=$(su main); R=$(su Reset_Handler)
report plain "a: d
"
st=$?
if [ $st -eq 0 ]; then pass "stack report on a clean image (exit 0)"; else fail "stack report failed"; cat "$T/out"; fi
# the deepest path from Reset_Handler: Reset_Handler > main > a > max(b > c, d)
BC=$((B + C))
[ "$D" -gt "$BC" ] && DEEP=$D || DEEP=$BC
WANT=$((R + M + A + DEEP))
if grep -q "stack: Reset_Handler  *$WANT " "$T/out"; then
    pass "worst case = sum of the -fstack-usage frames on the deepest path ($WANT bytes)"
else
    fail "worst case: expected $WANT bytes"; cat "$T/out"
fi
if grep -q "> d($D)" "$T/out"; then pass "the indirect call resolves to its table target (d, $D bytes)"; else fail "indirect target not on the path"; cat "$T/out"; fi

report plain ""
if [ $? -ne 0 ] && grep -q "a calls through a pointer and is not in" "$T/out"; then
    pass "an indirect call missing from the table fails the report"
else
    fail "an unlisted indirect call was accepted"; cat "$T/out"
fi

if build rec "-DRECURSE"; then
    report rec "a: d
"
    if [ $? -ne 0 ] && grep -q "recursion: r -> r" "$T/out"; then pass "recursion fails the report"; else fail "recursion not detected"; cat "$T/out"; fi
else
    fail "cannot build the recursive test image"
fi

# fw_size.sh: within and over budget
if sh port/cortex-m/tools/fw_size.sh arm-none-eabi-size "$T/plain.elf" 100000 100000 >"$T/out" 2>&1; then
    pass "fw_size.sh within budget (exit 0)"
else
    fail "fw_size.sh within budget"; cat "$T/out"
fi
if ! sh port/cortex-m/tools/fw_size.sh arm-none-eabi-size "$T/plain.elf" 10 100000 >"$T/out" 2>&1 &&
    grep -q "FLASH OVER BUDGET" "$T/out"; then
    pass "fw_size.sh fails over the flash budget"
else
    fail "fw_size.sh did not fail over budget"; cat "$T/out"
fi

# docs/firmware.md's "RAM by object" rows add up to its total (a stale row
# shows as a sum off the total: the SysTick base's 28 bytes, which is 16,
# and the application's 224, which is 220, would make it 16 bytes more)
awk '/^RAM by object/ { on = 1; next }
     on && /^\| \*\*total\*\*/ { t = $0; gsub(/[^0-9]/, "", t); total = t; on = 0; next }
     on && /^\| / && !/^\| (object|---)/ { n = split($0, c, "|"); v = c[n - 1]; gsub(/[ ,]/, "", v);
         k = split(v, p, "+"); for (i = 1; i <= k; i++) sum += p[i] }
     END { printf "%d %d\n", sum, total }' docs/firmware.md >"$T/ramsum"
read -r RSUM RTOTAL <"$T/ramsum"
if [ "$RTOTAL" -gt 0 ] && [ "$RSUM" -eq "$RTOTAL" ]; then
    pass "docs/firmware.md RAM by object: the rows add up to the total ($RTOTAL bytes)"
else
    fail "docs/firmware.md RAM by object: rows sum to $RSUM bytes, the total says $RTOTAL"
fi

# docs/firmware.md's object sizes against sizeof on the target (nm -S of a
# probe object), with the firmware's options and with the harness defaults
# (the filter's 11,640 bytes with the defaults on the target, not a stale 11,632)
cat >"$T/sz.c" <<'EOF'
#include "footnav/fnav_nav.h"
#include "footnav/fnav_allan.h"
#include "footnav/fnav_welch.h"
char sz_nav[sizeof(fnav_nav_t)];
char sz_allan[sizeof(fnav_allan_t)];
char sz_welch[sizeof(fnav_welch_t)];
EOF
sizes() { # extra-flags: prints "nav allan welch" in bytes
    $CC $ARCH -std=c99 -Iinclude -Iport/cortex-m $1 -c "$T/sz.c" -o "$T/sz.o" || return 1
    arm-none-eabi-nm -S "$T/sz.o" | while read -r _ z _ n; do echo "$n $((0x$z))"; done |
        awk '{ v[$1] = $2 } END { printf "%d %d %d\n", v["sz_nav"], v["sz_allan"], v["sz_welch"] }'
}
comma() { printf '%s' "$1" | sed -e :a -e 's/\([0-9]\)\([0-9]\{3\}\)\($\|,\)/\1,\2\3/;ta'; }
sizes '-DFNAV_CONFIG_FILE="fnav_cm_fw_config.h"' >"$T/fwsz" || fail "cannot compile the size probe"
sizes "" >"$T/hxsz" || fail "cannot compile the size probe (defaults)"
read -r FN FA FW <"$T/fwsz"
read -r HN HA HW <"$T/hxsz"
for want in "| $(comma "$FN") |" "| $(comma $((6 * FA))) |" "| $(comma $((3 * FW))) |" \
    "need $(comma "$HN") bytes for the" "$(comma "$HA") per Allan channel"; do
    if grep -q -F -- "$want" docs/firmware.md; then
        pass "docs/firmware.md has the size '$want' (sizeof on the target)"
    else
        fail "docs/firmware.md lacks '$want' (sizeof on the target)"
    fi
done

# tests/support/stack_usage.py (make bench's stack figure): a root it cannot
# find is an error, exit 1 (not "not found" printed with exit 0)
mkdir -p "$T/noci"
"$PY" tests/support/stack_usage.py "$T/noci" fnav_nav_step >"$T/out" 2>"$T/err"; rc=$?
if [ "$rc" -eq 1 ]; then pass "stack_usage.py: an unknown root fails (exit 1)"; else fail "stack_usage.py unknown root: exit $rc"; fi
expect_err "fnav_nav_step: not found" "stack_usage.py: the unknown root named"

# The linker script's layout: the stack reserve at the bottom of RAM, .data
# and .bss above it, so an overflow writes below RAM and faults (it sat
# right after .bss, whose last object, the application, an overflow
# overwrote without a fault: the firmware audit)
sym() { arm-none-eabi-nm "$T/plain.elf" | awk -v s="$1" '$3 == s { print $1 }'; }
if [ "$(sym _sstack)" = "20000000" ] && [ -n "$(sym _sdata)" ] &&
    [ "$((0x$(sym _sdata)))" -ge "$((0x$(sym _estack)))" ]; then
    pass "the stack reserve at the bottom of RAM (_sstack $(sym _sstack), _estack $(sym _estack), _sdata $(sym _sdata))"
else
    fail "the stack reserve not at the bottom of RAM: _sstack $(sym _sstack), _estack $(sym _estack), _sdata $(sym _sdata)"
fi

# The vector table's external interrupts: FNAV_CM_IRQ_COUNT of them (a
# part with more than 32 sets it; an enabled interrupt beyond the table
# read its vector from the code after it), the sample handler at
# FNAV_CM_SAMPLE_IRQN, refused unless a multiple of 32
if $CC $ARCH -Os -std=c99 -Iinclude -Iport/cortex-m -DFNAV_CM_IRQ_COUNT=96 -DFNAV_CM_SAMPLE_IRQN=40 \
    -c port/cortex-m/fnav_cm_startup.c -o "$T/vec.o" 2>"$T/err"; then
    n=$(arm-none-eabi-size -A "$T/vec.o" | awk '$1 == ".isr_vector" { print $2 }')
    if [ "$n" = "448" ]; then pass "96 external interrupts: a table of 448 bytes (4 x (1 + 15 + 96))"
    else fail "96 external interrupts: the table has $n bytes, not 448"; fi
    at=$(arm-none-eabi-objdump -r -j .isr_vector "$T/vec.o" | awk '$3 == "FNAV_CM_Sample_IRQHandler" { print $1 }')
    if [ "$at" = "000000e0" ]; then pass "the sample handler at external interrupt 40 (byte 224)"
    else fail "the sample handler at byte 0x$at, not 0xe0 (interrupt 40)"; fi
else
    fail "fnav_cm_startup.c does not build with 96 interrupts: $(cat "$T/err")"
fi
if $CC $ARCH -Os -std=c99 -Iinclude -Iport/cortex-m -DFNAV_CM_IRQ_COUNT=40 \
    -c port/cortex-m/fnav_cm_startup.c -o "$T/vec.o" 2>"$T/err"; then
    fail "FNAV_CM_IRQ_COUNT=40 built: the table would not hold it"
elif grep -q "multiple of 32" "$T/err"; then pass "FNAV_CM_IRQ_COUNT=40 refused at compile time"
else fail "FNAV_CM_IRQ_COUNT=40: $(cat "$T/err")"; fi

# the benchmark image's sample interrupt at 40: the NVIC's enable and
# pending bits are bit 8 of their second words (ISER1 0xE000E104, ISPR1
# 0xE000E204); a shift of 1 by 40 into the first words did not build
if $CC $ARCH -Os -std=c99 -pedantic -Wall -Wextra -Werror -Iinclude -Iport/cortex-m \
    -DFNAV_CONFIG_FILE='"fnav_cm_fw_config.h"' -DFNAV_CM_PROFILE=1 -DFNAV_CM_IRQ_COUNT=64 \
    -DFNAV_CM_SAMPLE_IRQN=40 -c port/cortex-m/fnav_cm_bench.c -o "$T/bench40.o" 2>"$T/err"; then
    arm-none-eabi-objdump -d "$T/bench40.o" >"$T/bench40.s"
    if grep -Eq 'str(\.w)?[[:space:]].*@ 0x104$' "$T/bench40.s" && grep -Eq 'str(\.w)?[[:space:]].*@ 0x204$' "$T/bench40.s"
    then pass "sample interrupt 40: the benchmark sets ISER1 and ISPR1"
    else fail "sample interrupt 40: no store to ISER1 / ISPR1 (+0x104, +0x204) in the benchmark"; fi
else
    fail "fnav_cm_bench.c does not build with the sample interrupt at 40: $(cat "$T/err")"
fi

# the firmware's objects are rebuilt when the compiler's flags change: they
# are part of the options stamp the objects depend on
make -n firmware ARM_BUILD="$T/arm" >/dev/null 2>&1
cp "$T/arm/fw-options.stamp" "$T/stamp0"
make -n firmware ARM_BUILD="$T/arm" ARM_CFLAGS="-O2 -mthumb" >/dev/null 2>&1
if grep -q -- "-Os" "$T/stamp0" && grep -q -- "-O2 -mthumb" "$T/arm/fw-options.stamp"; then
    pass "ARM_CFLAGS is part of the firmware's options stamp"
else fail "ARM_CFLAGS not in the options stamp: $(cat "$T/stamp0") / $(cat "$T/arm/fw-options.stamp")"; fi
# an object newer than the stamp (as if built by the plain build) is up to
# date until the flags change
make -n firmware ARM_BUILD="$T/arm" >/dev/null 2>&1
mkdir -p "$T/arm/obj/src" && touch "$T/arm/obj/src/fnav_ukf.o"
if make -q ARM_BUILD="$T/arm" "$T/arm/obj/src/fnav_ukf.o" >/dev/null 2>&1 &&
    make -n ARM_BUILD="$T/arm" ARM_CFLAGS="-O2 -mthumb" "$T/arm/obj/src/fnav_ukf.o" 2>/dev/null |
    grep -q -- "-O2 -mthumb.*fnav_ukf"; then
    pass "an object built with other flags is rebuilt"
else fail "src/fnav_ukf.o not rebuilt when ARM_CFLAGS changed"; fi

if [ "$fails" -ne 0 ]; then
    echo "test_firmware_tools.sh: $fails failure(s)"
    exit 1
fi
echo "test_firmware_tools.sh: all passed"
