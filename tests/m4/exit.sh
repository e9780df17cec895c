#!/bin/sh
# The exit status of the semihosting images in qemu-system-arm (mps2-an386):
# with SYS_EXIT_EXTENDED the status itself; with the plain SYS_EXIT of a
# debugger without that extension (FNAV_CM_SH_NO_EXIT_EXTENDED) at least
# success or failure, so a failed benchmark never reads as passed. Standalone:
# sh tests/m4/exit.sh; skips with a message when the tools are missing.
set -u
cd "$(dirname "$0")/../.."
for t in arm-none-eabi-gcc qemu-system-arm; do
    command -v "$t" >/dev/null 2>&1 || { echo "  exit: $t not installed; skipped"; exit 0; }
done
B=build/m4
mkdir -p "$B"
fails=0
# run NAME STATUS EXPECT [CFLAGS]: EXPECT is a number or "nonzero"
run() {
    name=$1 status=$2 expect=$3
    shift 3
    arm-none-eabi-gcc -mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard -Os -std=c99 -Wall -Wextra -Werror \
        -Iinclude -Iport/cortex-m -nostartfiles --specs=nano.specs -Wl,--gc-sections \
        -Lport/cortex-m/ld -Tmps2-an386.ld -DFNAV_TEST_STATUS="$status" "$@" \
        port/cortex-m/fnav_cm_startup.c port/cortex-m/fnav_cm_semihost.c tests/m4/exit.c -lc -lgcc \
        -o "$B/exit_$name.elf" || { echo "FAIL exit: $name does not build"; fails=$((fails + 1)); return; }
    timeout 60 qemu-system-arm -M mps2-an386 -display none -monitor none -serial none -chardev stdio,id=sh \
        -semihosting-config enable=on,target=native,chardev=sh -kernel "$B/exit_$name.elf" >/dev/null
    st=$?
    if [ "$expect" = nonzero ]; then
        if [ "$st" -ne 0 ] && [ "$st" -ne 124 ]; then echo "ok   exit: $name: status $st"; return; fi
    elif [ "$st" -eq "$expect" ]; then
        echo "ok   exit: $name: status $st"; return
    fi
    echo "FAIL exit: $name: status $st, expected $expect"
    fails=$((fails + 1))
}
run extended_0 0 0
run extended_5 5 5
run plain_0 0 0 -DFNAV_CM_SH_NO_EXIT_EXTENDED
run plain_3 3 nonzero -DFNAV_CM_SH_NO_EXIT_EXTENDED
if [ "$fails" -ne 0 ]; then echo "exit.sh: $fails failed"; exit 1; fi
echo "exit.sh: all passed"
