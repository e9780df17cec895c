#!/bin/sh
# The port's SysTick time base in qemu-system-arm (mps2-an386): the stamp's
# milliseconds equal the wraps SysTick's COUNTFLAG counted, a reading goes
# back only in QEMU's late-pending-bit window (tests/m4/ticks.c says why
# QEMU cannot check more; test_port's test_cm_systick_ns does), the stamp's
# arithmetic equals the 64-bit division, and the cost of a stamp is printed. Run by `make
# firmware-bench`; skips with a message when the tools are missing.
sh "$(dirname "$0")/port_run.sh" ticks 300
st=$?
if [ "$st" -eq 77 ]; then exit 0; fi
if [ "$st" -ne 0 ]; then echo "ticks: FAILED (status $st)"; exit 1; fi
echo "ticks: the SysTick time base went back only in the emulator's window; its arithmetic matches the division"
