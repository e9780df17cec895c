#!/bin/sh
# Cortex-M4F instruction counts of the navigation step (make bench): builds
# tests/m4 with the firmware flags and runs it in qemu-system-arm (mps2-an386,
# -icount shift=0, semihosting). Skips with a message when the tools are
# missing. Usage: sh tests/m4/run.sh [extra CFLAGS: -O2, -DM4_BIASOFF (bias
# model off; the default is on), -DM4_NOLEVER (no lever states),
# -DM4_NOSETTLE (no landing settling state), -DM4_ZARU (the stance step
# with the ZARU after the ZUPT)]: the default
# configuration has 18 states, -DM4_NOLEVER the paper's 15, -DM4_BIASOFF 12,
# both 9. M4_MAIN and M4_UKF replace tests/m4/main.c and src/fnav_ukf.c
# (tests/m4/profile.sh passes its instrumented copies).
set -u
cd "$(dirname "$0")/../.."
for t in arm-none-eabi-gcc qemu-system-arm /usr/bin/python3; do
    command -v "$t" >/dev/null 2>&1 || { echo "  m4: $t not installed; skipped"; exit 0; }
done
B=build/m4
mkdir -p "$B"
/usr/bin/python3 tests/m4/gen_data.py "$B/m4_data.h" 3000 || exit 1
OPT="-Os"
for a in "$@"; do case "$a" in -O*) OPT="$a" ;; esac; done
# startup (vector table, FPU enable), semihosting and the linker script are
# the firmware port's (port/cortex-m); only the measuring main() is here
arm-none-eabi-gcc -mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard $OPT -std=c99 "$@" \
    -Iinclude -Iport/cortex-m -I"$B" -nostartfiles --specs=nano.specs -Wl,--gc-sections \
    -Lport/cortex-m/ld -Tmps2-an386.ld \
    port/cortex-m/fnav_cm_startup.c port/cortex-m/fnav_cm_semihost.c "${M4_MAIN:-tests/m4/main.c}" \
    src/fnav_nav.c "${M4_UKF:-src/fnav_ukf.c}" src/fnav_stance.c src/fnav_align.c \
    src/fnav_strapdown.c src/fnav_profile.c src/fnav_port.c -lm -lc -lgcc -o "$B/m4.elf" || exit 1
echo "  Cortex-M4F in qemu-system-arm mps2-an386 -icount shift=0 ($OPT $*):"
timeout 600 qemu-system-arm -M mps2-an386 -nographic -semihosting-config enable=on,target=native \
    -icount shift=0 -kernel "$B/m4.elf" 2>&1 | sed "s/^/    /"
