#!/bin/sh
# Build tests/m4/NAME.c with the port's portable files and the startup and
# semihosting code for qemu-system-arm's mps2-an386, and run it there (one
# instruction per ns: -icount shift=0) for at most SECONDS.
# usage: sh tests/m4/port_run.sh NAME SECONDS
# Exit status: the image's; 124 when the timeout ended it; 1 when it does
# not build; 77 when the tools are missing (said on standard output).
set -u
cd "$(dirname "$0")/../.."
name=$1 seconds=$2
for t in arm-none-eabi-gcc qemu-system-arm; do
    command -v "$t" >/dev/null 2>&1 || { echo "  $name: $t not installed; skipped"; exit 77; }
done
B=build/m4
mkdir -p "$B"
arm-none-eabi-gcc -mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard -Os -std=c99 -Wall -Wextra -Werror \
    -Iinclude -Iport/cortex-m -nostartfiles --specs=nano.specs -Wl,--gc-sections \
    -Lport/cortex-m/ld -Tmps2-an386.ld \
    port/cortex-m/fnav_cm_startup.c port/cortex-m/fnav_cm_semihost.c port/cortex-m/fnav_port_cortexm.c \
    port/cortex-m/fnav_cm_ring.c src/fnav_wire.c src/fnav_port.c "tests/m4/$name.c" -lc -lgcc -o "$B/$name.elf" || exit 1
timeout "$seconds" qemu-system-arm -M mps2-an386 -display none -monitor none -serial none -chardev stdio,id=sh \
    -semihosting-config enable=on,target=native,chardev=sh -icount shift=0 -kernel "$B/$name.elf"
