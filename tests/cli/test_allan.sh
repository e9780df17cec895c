#!/bin/sh
# CLI tests of `harness allan` (run by make test with $HARNESS set).
set -u
H=${HARNESS:-bin/harness}
PY=${PYTHON:-/usr/bin/python3}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
data() { # data REL -> path or empty
    for root in "${FNAV_DATA_DIR:-}" ../shared/data /work/shared/data; do
        [ -n "$root" ] && [ -f "$root/$1" ] && { echo "$root/$1"; return; }
    done
}

expect_exit 2 "no input" "$H" allan
expect_exit 2 "series without rate" "$H" allan --series /dev/null
expect_exit 2 "log and series" "$H" allan x.csv --series y.txt --rate 1
expect_exit 2 "bad per-octave" "$H" allan --series x --rate 1 --per-octave 3
expect_exit 1 "missing file" "$H" allan "$T/nope.csv"
printf "1e30\n1\n2\n" > "$T/big.txt"
expect_exit 1 "series value beyond the input range" "$H" allan --series "$T/big.txt" --rate 100
expect_err "big.txt:1: 1e+30 is beyond" "the rejected value is named with its line"
expect_exit 2 "empty --channels" "$H" allan vectors/walk.bin --channels ,
expect_err "no channel named" "empty --channels explained"
expect_exit 1 "missing series" "$H" allan --series "$T/nope.txt" --rate 1
# two numbers 300 blanks apart on one line: refused, not read as two lines
awk 'BEGIN { for (i = 0; i < 50; i++) { printf "1.0"; for (j = 0; j < 300; j++) printf " "; print "2.0" } }' > "$T/long.txt"
expect_exit 1 "series line longer than the reader's buffer" "$H" allan --series "$T/long.txt" --rate 1 --no-sim
expect_err "long.txt:1: line longer than" "the long line is named"
expect_exit 0 "paper tables" "$H" allan --paper-tables
grep -q "NavChip (IV)" "$T/out" && pass "paper tables list NavChip" || fail "paper tables output"

# a series with a bad line: the numbers before it are analysed, outputs written, exit 1
awk 'BEGIN { s = 1; for (i = 0; i < 3000; i++) { s = (s * 1103515245 + 12345) % 2147483648; print s / 2147483648.0 } print "oops" }' >"$T/bad.txt"
expect_exit 1 "bad line in series" "$H" allan --series "$T/bad.txt" --rate 10 --no-sim --out "$T/bad.csv"
grep -q "bad.txt:3001: not a number" "$T/err" && pass "bad line reported with its number" || fail "bad line message"
[ "$(grep -c '^series,' "$T/bad.csv")" -gt 10 ] && pass "table written before the error" || fail "table before error"
expect_exit 3 "unwritable output" "$H" allan --series "$T/bad.txt" --rate 10 --no-sim --quiet --out /nonexistent/dir/t.csv

# a log too short for an identification: tables and plot still written, no profile, exit 1
awk 'BEGIN { print "t,ax,ay,az,gx,gy,gz"; for (i = 0; i < 10; i++) printf "%.2f,0.1,0.2,9.8,0.01,0.02,0.0%d\n", i / 100, i }' >"$T/tiny.csv"
expect_exit 1 "too short for a profile" "$H" allan "$T/tiny.csv" --quiet --profile "$T/tiny.profile" --plot "$T/tiny.png"
[ -s "$T/tiny.png" ] && [ ! -e "$T/tiny.profile" ] && pass "plot without profile" || fail "tiny outputs"

P=$(data allan_reference/phasedat/PHASE.DAT)
if [ -n "$P" ]; then
    expect_exit 0 "PHASE.DAT as phase" "$H" allan --series "$P" --phase --rate 1 --per-octave 1 --no-sim \
        --out "$T/p.csv" --json "$T/p.json"
    # Stable32: OADEV tau=1 0.29223 (999 terms), tau=128 0.027674 (745 terms)
    grep -q '^series,u,1,1,0,1,0.29223[0-9]*,' "$T/p.csv" && grep '^series,u,1,1,' "$T/p.csv" | grep -q ',999,' &&
        pass "tau 1 matches Stable32" || fail "tau 1 row: $(grep '^series,u,1,1,' "$T/p.csv")"
    grep '^series,u,128,128,' "$T/p.csv" | awk -F, '{ d = $7 / 0.027674 - 1; exit !(d < 1e-4 && d > -1e-4 && $11 == 745) }' &&
        pass "tau 128 matches Stable32" || fail "tau 128 row: $(grep '^series,u,128,128,' "$T/p.csv")"
    if "$PY" -c 'import json,sys; j=json.load(open(sys.argv[1])); assert j["samples"]==1000 and j["channels"][0]["table"]' "$T/p.json" 2>/dev/null; then
        pass "JSON parses"
    else
        fail "JSON"
    fi
    expect_exit 2 "profile from a series" "$H" allan --series "$P" --rate 1 --profile "$T/x.profile"
else
    echo "SKIP PHASE.DAT tests (shared data not found; set FNAV_DATA_DIR)"
fi

A=$(data adis16405_static/adis16405_imu1_100Hz.csv.gz)
if [ -n "$A" ]; then
    expect_exit 0 "ADIS log, all outputs" "$H" allan "$A" --sim-samples 100000 --quiet --profile "$T/a.profile" \
        --plot "$T/a.png" --json "$T/a.json" --out "$T/a.csv"
    grep -q "^format = footnav-profile 1" "$T/a.profile" && grep -q "^gyro_tau_s = " "$T/a.profile" &&
        grep -q "^accel_bias_sigma_mps2 = " "$T/a.profile" && pass "profile written" || fail "profile content"
    [ -s "$T/a.png" ] && pass "plot written" || fail "plot missing"
    grep -q "corrected: LSQ fit" "$T/out" && pass "parameter table printed" || fail "parameter table"
    expect_exit 2 "profile needs six channels" "$H" allan "$A" --channels gx --profile "$T/b.profile"
else
    echo "SKIP ADIS16405 tests (shared data not found; set FNAV_DATA_DIR)"
fi
if [ "$fails" -ne 0 ]; then echo "test_allan.sh: $fails failure(s)"; exit 1; fi
echo "test_allan.sh: all passed"
