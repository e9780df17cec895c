#!/bin/sh
# Where the UKF step spends its instructions on the Cortex-M4F: tests/m4 with
# SysTick marks between the parts of fnav_ukf_predict and the update (an
# instrumented copy written by tests/m4/profile.py; src/ is not touched).
# Mean instructions per call of each part over 3,000 gx2 samples. Usage: sh
# tests/m4/profile.sh [the flags of tests/m4/run.sh: -DM4_NOLEVER,
# -DM4_BIASOFF]. Skips with a message when the tools are missing.
set -u
cd "$(dirname "$0")/../.."
for t in arm-none-eabi-gcc qemu-system-arm /usr/bin/python3; do
    command -v "$t" >/dev/null 2>&1 || { echo "  m4 profile: $t not installed; skipped"; exit 0; }
done
B=build/m4
mkdir -p "$B"
/usr/bin/python3 tests/m4/gen_data.py "$B/m4_data.h" 3000 || exit 1
/usr/bin/python3 tests/m4/profile.py || exit 1
arm-none-eabi-gcc -mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard -Os -std=c99 "$@" \
    -Iinclude -Iport/cortex-m -I"$B" -Isrc -nostartfiles --specs=nano.specs -Wl,--gc-sections \
    -Lport/cortex-m/ld -Tmps2-an386.ld \
    port/cortex-m/fnav_cm_startup.c port/cortex-m/fnav_cm_semihost.c "$B/main_prof.c" \
    src/fnav_nav.c "$B/ukf_prof.c" src/fnav_stance.c src/fnav_align.c \
    src/fnav_strapdown.c src/fnav_profile.c src/fnav_port.c -lm -lc -lgcc -o "$B/m4_prof.elf" || exit 1
echo "  UKF parts, Cortex-M4F (qemu-system-arm mps2-an386 -icount shift=0, -Os $*), mean instructions per call:"
timeout 600 qemu-system-arm -M mps2-an386 -nographic -semihosting-config enable=on,target=native \
    -icount shift=0 -kernel "$B/m4_prof.elf" 2>&1 | sed "s/^/    /"
