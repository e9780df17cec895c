#!/bin/sh
# Where the UKF step spends its instructions on the Cortex-M4F: tests/m4 with
# SysTick marks between the parts of fnav_ukf_predict and the update (an
# instrumented copy written by tests/m4/profile.py; src/ is not touched),
# built and run by tests/m4/run.sh. Mean instructions per call of each part
# over 2,998 gx2 samples, after run.sh's own figures. Usage: sh
# tests/m4/profile.sh [the flags of tests/m4/run.sh: -DM4_NOLEVER,
# -DM4_BIASOFF].
set -u
cd "$(dirname "$0")/../.."
command -v /usr/bin/python3 >/dev/null 2>&1 || { echo "  m4 profile: /usr/bin/python3 not installed; skipped"; exit 0; }
/usr/bin/python3 tests/m4/profile.py || exit 1
M4_MAIN=build/m4/main_prof.c M4_UKF=build/m4/ukf_prof.c sh tests/m4/run.sh "$@"
