#!/bin/sh
# The firmware's stack check (make firmware: port/cortex-m/tools/stack_report.py)
# on the nesting the Makefile configures (FW_STACK_PRIORITIES: SysTick above
# the sample-ready interrupt) with room for a board's IMU read
# (FW_IMU_READ_ROOM) and a board's own read linked in (FW_BOARD_SRC):
# 1. the reference image fits its reserve, two levels nested;
# 2. a reserve 8 bytes under that worst case fails (the report's one-level
#    total, 1,476, passed any reserve from 1,476 up: the firmware audit);
# 3. a board read within the room (tests/m4/board_read.c, a 14-byte burst)
#    fits; 4. one past it (a 30-byte burst) fails;
# 5. with no priority named (one level) the total is lower.
# Each image in its own build/m4/stack-* folder. Run by `make firmware-bench`;
# skips with a message when the tools are missing.
set -u
cd "$(dirname "$0")/../.."
for t in arm-none-eabi-gcc python3; do
    command -v "$t" >/dev/null 2>&1 || { echo "  stack: $t not installed; skipped"; exit 0; }
done
MK=${MAKE:-make}
fails=0
# fw NAME ARGS...: build the image, its report in build/m4/stack-NAME.txt; the status of make
fw() {
    name=$1
    shift
    env -u MAKEFLAGS -u MFLAGS "$MK" -j1 firmware ARM_BUILD="build/m4/stack-$name" "$@" >"build/m4/stack-$name.txt" 2>&1
}
total_of() {
    sed -n 's/^stack: total worst case.* = \([0-9]*\) bytes$/\1/p' "build/m4/stack-$1.txt"
}
ok() { echo "ok   stack: $1"; }
bad() { echo "FAIL stack: $1 (build/m4/stack-$2.txt)"; fails=$((fails + 1)); }
mkdir -p build/m4

if fw ref && grep -q '^stack: total worst case, 2 interrupt levels nested' build/m4/stack-ref.txt; then
    ok "the reference image fits its reserve, SysTick nested above the sample-ready interrupt ($(total_of ref) bytes)"
else
    bad "the reference image" ref
fi
t=$(total_of ref)
if [ -n "$t" ]; then
    under=$(( (t - 1) / 8 * 8 ))
    if ! fw under FW_STACK_SIZE="$under" && grep -q "exceeds the reserve of $under bytes" build/m4/stack-under.txt; then
        ok "a reserve of $under bytes, under the nested worst case, fails"
    else
        bad "a reserve of $under bytes passed" under
    fi
fi
if fw read14 FW_BOARD_SRC=tests/m4/board_read.c; then
    ok "a board read within the room ($(awk '{ print $2 }' build/m4/stack-read14/obj/tests/m4/board_read.su) bytes of its own) fits"
else
    bad "a board read within the room" read14
fi
if ! fw read30 FW_BOARD_SRC=tests/m4/board_read.c FW_DEFS=-DFNAV_TEST_READ_BYTES=30 &&
    grep -q 'exceeds the reserve' build/m4/stack-read30.txt; then
    ok "a board read past the room fails ($(total_of read30) bytes)"
else
    bad "a board read past the room passed" read30
fi
if fw flat FW_STACK_PRIORITIES= && [ -n "$t" ] && [ "$(total_of flat)" -lt "$t" ] &&
    grep -q '^stack: total worst case, 1 interrupt level nested' build/m4/stack-flat.txt; then
    ok "one interrupt level: $(total_of flat) bytes"
else
    bad "one interrupt level" flat
fi
if [ "$fails" -ne 0 ]; then echo "stack.sh: $fails failed"; exit 1; fi
echo "stack.sh: all passed"
