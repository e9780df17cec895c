#!/bin/sh
# The port's SysTick time base in qemu-system-arm (mps2-an386): the stamp's
# milliseconds equal the wraps SysTick's COUNTFLAG counted, a reading goes
# back only in QEMU's late-pending-bit window (tests/m4/ticks.c says why
# QEMU cannot check more; test_port's test_cm_systick_ns does), the stamp's
# arithmetic equals the 64-bit division, and the cost of a stamp is printed. Run by `make
# firmware-bench`; skips with a message when the tools are missing.
set -u
cd "$(dirname "$0")/../.."
for t in arm-none-eabi-gcc qemu-system-arm; do
    command -v "$t" >/dev/null 2>&1 || { echo "  ticks: $t not installed; skipped"; exit 0; }
done
B=build/m4
mkdir -p "$B"
arm-none-eabi-gcc -mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard -Os -std=c99 -Wall -Wextra -Werror \
    -Iinclude -Iport/cortex-m -nostartfiles --specs=nano.specs -Wl,--gc-sections \
    -Lport/cortex-m/ld -Tmps2-an386.ld \
    port/cortex-m/fnav_cm_startup.c port/cortex-m/fnav_cm_semihost.c port/cortex-m/fnav_port_cortexm.c \
    port/cortex-m/fnav_cm_ring.c src/fnav_wire.c src/fnav_port.c tests/m4/ticks.c -lc -lgcc -o "$B/ticks.elf" || exit 1
timeout 300 qemu-system-arm -M mps2-an386 -display none -monitor none -serial none -chardev stdio,id=sh \
    -semihosting-config enable=on,target=native,chardev=sh -icount shift=0 -kernel "$B/ticks.elf"
st=$?
if [ "$st" -ne 0 ]; then echo "ticks: FAILED (status $st)"; exit 1; fi
echo "ticks: the SysTick time base went back only in the emulator's window; its arithmetic matches the division"
