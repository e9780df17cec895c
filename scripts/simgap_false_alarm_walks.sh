#!/bin/sh
# The false-alarm check of docs/simgap.md ("Usage", "Seeds and alpha"):
# 50 baseline-only simulated walks (60 s, mtx profile, seeds 1-50) through
# `simgap`; prints each seed's verdict, then how many answered an effect.
# Usage: sh scripts/simgap_false_alarm_walks.sh [HARNESS]   (default bin/harness; about 5 min)
set -u
H=${1:-bin/harness}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
n=0
for S in $(seq 1 50); do
    "$H" sim --motion walk --duration 60 --profile mtx --seed "$S" --out "$T/w.csv" >/dev/null 2>&1 || { echo "seed $S: sim failed"; exit 1; }
    v=$("$H" simgap "$T/w.csv" 2>/dev/null | grep '^verdict')
    echo "$S $v"
    case "$v" in "verdict: none"*) ;; *) n=$((n + 1)) ;; esac
done
echo "$n of 50 answered an effect"
