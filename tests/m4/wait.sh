#!/bin/sh
# The reference main loop's sleep (fnav_cm_port_wait) in qemu-system-arm
# (mps2-an386): no sleep with a sample waiting, a wake on the sample-ready
# interrupt pending under PRIMASK, a sleep until SysTick otherwise
# (tests/m4/wait.c). Run by `make firmware-bench`; skips with a message
# when the tools are missing.
# a sleep nothing wakes ends at the timeout, not in the test
sh "$(dirname "$0")/port_run.sh" wait 20
st=$?
if [ "$st" -eq 77 ]; then exit 0; fi
if [ "$st" -eq 124 ]; then echo "wait: FAILED (the image slept and nothing woke it: timeout)"; exit 1; fi
if [ "$st" -ne 0 ]; then echo "wait: FAILED (status $st)"; exit 1; fi
echo "wait: all passed"
