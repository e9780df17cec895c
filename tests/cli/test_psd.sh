#!/bin/sh
# CLI tests of `harness psd` (run by make test with $HARNESS set).
set -u
H=${HARNESS:-bin/harness}
PY=${PYTHON:-/usr/bin/python3}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
fail=0
ok() { echo "ok   $1"; }
bad() { echo "FAIL $1"; fail=1; }
expect() {
    want=$1; name=$2; shift 2
    "$@" >"$T/out" 2>"$T/err"; got=$?
    if [ "$got" -eq "$want" ]; then ok "$name (exit $got)"; else bad "$name: exit $got, wanted $want"; cat "$T/err"; fi
}
data() {
    for root in "${FNAV_DATA_DIR:-}" ../shared/data /work/shared/data; do
        [ -n "$root" ] && [ -f "$root/$1" ] && { echo "$root/$1"; return; }
    done
}

expect 2 "no input" "$H" psd
expect 1 "missing file" "$H" psd "$T/nope.csv"
expect 2 "nfft not a power of two" "$H" psd x.csv --nfft 48
expect 2 "unknown dc mode" "$H" psd x.csv --dc bogus
expect 2 "global with symmetric window" "$H" psd x.csv --dc global --symmetric

# a tiny CSV in the interchange format: a 100 Hz tone at 1000 Hz + gravity on z
awk 'BEGIN { print "t,ax,ay,az,gx,gy,gz"; for (i = 0; i < 4000; i++) { t = i / 1000.0; s = sin(6.283185307 * 100 * t);
     printf "%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f\n", t, s, 0.5 * s, -9.81 + s, 0.1 * s, 0.1 * s, 0.1 * s } }' >"$T/tone.csv"
expect 0 "tone" "$H" psd "$T/tone.csv" --json "$T/tone.json" --dc global
# all power at 100 Hz, 15.6 Hz bins: the Hamming main lobe spreads it over +-2 bins, so 95 % of
# the power lies below 100 + 31.25 Hz and above 100 Hz; fs 250 Hz (multiples of 50)
if "$PY" -c 'import json,sys; r=json.load(open(sys.argv[1]))["result"]; assert 100 < r["accel_bandwidth_hz"] < 131.25 and r["fs_hz"] == 250, r' "$T/tone.json"; then
    ok "tone bandwidth"
else
    bad "tone bandwidth"
fi
expect 3 "unwritable output" "$H" psd "$T/tone.csv" --out /nonexistent/dir/p.csv

O=$(data openshoe_c_820hz/OpenShoeDataSet.txt)
if [ -n "$O" ]; then
    expect 0 "820 Hz walk, paper settings" "$H" psd "$O" --input-rate 820 --json "$T/o.json" --out "$T/o.csv" \
        --plot "$T/plots" --sensitivity
    # per-segment mean, Hamming 64: vertical accelerometer near 220 Hz -> 450 Hz (issue #4)
    "$PY" -c 'import json,sys; r=json.load(open(sys.argv[1]))["result"]; assert r["fs_hz"] == 450 and 200 < r["axes"]["az"]["bandwidth_hz"] < 240, r' "$T/o.json" &&
        ok "paper setting answer" || bad "paper setting answer"
    for f in psd ccdf spectrogram sensitivity; do
        [ -s "$T/plots/$f.png" ] && ok "$f.png" || bad "$f.png missing"
    done
    grep -q "^  global    1024" "$T/out" && ok "sensitivity table" || bad "sensitivity table"
    expect 0 "820 Hz walk, recommended" "$H" psd "$O" --input-rate 820 --dc global --nfft 256 --json "$T/g.json"
    "$PY" -c 'import json,sys; r=json.load(open(sys.argv[1]))["result"]; assert r["fs_hz"] == 300, r' "$T/g.json" &&
        ok "recommended setting answer" || bad "recommended setting answer"
else
    echo "SKIP 820 Hz walk tests (shared data not found; set FNAV_DATA_DIR)"
fi
exit $fail
