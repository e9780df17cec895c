#!/bin/sh
# CLI tests of bad input and failed outputs found by the robustness hunt of
# 2026-12-01 (the rule of docs/harness.md, "Exit status": a clear error and
# a non-zero exit, never a crash; nothing already computed is lost): each
# check failed before its fix.
set -u
H=${HARNESS:-bin/harness}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"

# --- sim: one output that cannot be written leaves the other whole (exit 3,
# "every other output is still written"). Until 2026-12-01 the first failed
# write stopped the simulation: a truth CSV on a full disk left the log cut
# short (1,288 bytes of a 10 s walk, a header and a few rows that read as a
# valid log), and a log that could not be written left the truth cut short.
# (No summary is printed when an output failed: tests/cli/test_sim.sh.)
expect_exit 0 "sim: the reference log and truth" "$H" sim --duration 10 --out "$T/ref.csv" --truth "$T/ref_truth.csv"
if [ -w /dev/full ]; then
    expect_exit 3 "sim --truth onto a full disk" "$H" sim --duration 10 --out "$T/log.csv" --truth /dev/full
    expect_err "^harness sim: error: /dev/full: write failed (No space left on device)" "sim: the truth's failed write named"
    if cmp -s "$T/ref.csv" "$T/log.csv"; then pass "sim: the log written whole when the truth fails"
    else fail "sim: the log cut short when the truth fails ($(wc -c <"$T/log.csv") of $(wc -c <"$T/ref.csv") bytes)"; fi
    expect_exit 3 "sim --out onto a full disk" "$H" sim --duration 10 --out /dev/full --truth "$T/truth.csv"
    expect_err "^harness sim: error: /dev/full: write failed (No space left on device)" "sim: the log's failed write named"
    if cmp -s "$T/ref_truth.csv" "$T/truth.csv"; then pass "sim: the truth written whole when the log fails"
    else fail "sim: the truth cut short when the log fails ($(wc -c <"$T/truth.csv") of $(wc -c <"$T/ref_truth.csv") bytes)"; fi
else
    echo "skip the full-disk checks of sim (no /dev/full)"
fi

if [ "$fails" -ne 0 ]; then echo "test_bad_input.sh: $fails failure(s)"; exit 1; fi
echo "test_bad_input.sh: all passed"
