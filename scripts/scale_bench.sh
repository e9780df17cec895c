#!/bin/sh
# The harness on long logs (docs/harness.md, "Scale"): simulates static logs
# of 1, 6 and 24 hours at 100 Hz (the 6-hour one also as CSV and .csv.gz)
# and walks of 30, 60 and 90 minutes at 200 Hz, runs info, convert, allan,
# psd, replay and simgap on them under /usr/bin/time -v, and prints a
# Markdown table: wall time and peak resident memory per command and log.
#
#   sh scripts/scale_bench.sh [DIR]     # scratch directory (default: a new
#                                       # one under /tmp, removed at the end)
#
# About 1 GB of scratch and 8 minutes on the shared two-core machine. Every
# run is niced and stopped after SCALE_TIMEOUT seconds (default 600; the
# table then says "timeout"). SCALE_QUICK=1 runs only the 1-hour static log
# and the 30-minute walk; SCALE_BIG=1 adds a day at 400 Hz (34.6 million
# samples, 1.7 GB .bin and 3.5 GB as CSV at once; about 7 more minutes and
# 5 GB of memory for replay). Run from the repository root after `make`.
set -u
H=${HARNESS:-$(pwd)/bin/harness}
TO=${SCALE_TIMEOUT:-600}
[ -x "$H" ] || { echo "scale_bench: no $H (run make first, from the repository root)" >&2; exit 2; }
[ -x /usr/bin/time ] || { echo "scale_bench: needs /usr/bin/time (Debian package time)" >&2; exit 2; }
if [ $# -ge 1 ]; then
    D=$1
    mkdir -p "$D" || exit 2
else
    D=$(mktemp -d /tmp/scale_bench.XXXXXX) || exit 2
    trap 'rm -rf "$D"' EXIT
fi

# sim NAME MOTION SECONDS RATE EXT
sim() {
    [ -s "$D/$1.$5" ] || nice "$H" sim --motion "$2" --duration "$3" --rate "$4" --out "$D/$1.$5" >/dev/null 2>&1 ||
        { echo "scale_bench: sim $1 failed" >&2; exit 1; }
}

# run LOG-LABEL SAMPLES COMMAND-LABEL harness-args...: one table row
run() {
    log=$1 n=$2 what=$3
    shift 3
    timeout "$TO" /usr/bin/time -v -o "$D/time.txt" nice "$H" "$@" >/dev/null 2>"$D/err.txt"
    rc=$?
    wall=$(sed -n 's/.*Elapsed (wall clock) time (h:mm:ss or m:ss): //p' "$D/time.txt")
    rss=$(sed -n 's/.*Maximum resident set size (kbytes): //p' "$D/time.txt")
    if [ "$rc" -eq 124 ]; then
        wall="timeout ($TO s)"
        rss="-"
    else
        rss=$(awk -v k="$rss" 'BEGIN { printf "%.0f", k / 1024 }')
    fi
    echo "| \`$what\` | $log | $n | $wall | $rss | $rc |"
}

samples() { "$H" info "$1" 2>/dev/null | sed -n 's/^samples *\([0-9]*\).*/\1/p'; }

if [ "${SCALE_QUICK:-0}" = 1 ]; then
    static="st1h:3600"
    walks="walk30:1800"
else
    static="st1h:3600 st6h:21600 st24h:86400"
    walks="walk30:1800 walk60:3600 walk90:5400"
fi

echo "| command | log | samples | wall (m:ss) | peak RSS (MiB) | exit |"
echo "| --- | --- | ---: | ---: | ---: | ---: |"
for s in $static; do
    name=${s%%:*} dur=${s#*:}
    sim "$name" stand "$dur" 100 bin
    L="$D/$name.bin"
    n=$(samples "$L")
    lab="static $((dur / 3600)) h, 100 Hz, .bin"
    run "$lab" "$n" info info "$L"
    run "$lab" "$n" "convert to CSV" convert "$L" "$D/out.csv"
    rm -f "$D/out.csv"
    run "$lab" "$n" allan allan "$L" --out "$D/allan.csv"
    run "$lab" "$n" psd psd "$L" --out "$D/psd.csv"
    run "$lab" "$n" "replay --quiet" replay "$L" --quiet
    [ "$name" = st24h ] || run "$lab" "$n" simgap simgap "$L" --quiet --json "$D/sg.json"
    if [ "$name" = st6h ]; then
        sim "$name" stand "$dur" 100 csv
        gzip -c "$D/$name.csv" >"$D/$name.csv.gz"
        for ext in csv csv.gz; do
            L="$D/$name.$ext"
            lab="static 6 h, 100 Hz, .$ext"
            run "$lab" "$n" info info "$L"
            run "$lab" "$n" "convert to .bin" convert "$L" "$D/out.bin"
            rm -f "$D/out.bin"
            run "$lab" "$n" allan allan "$L" --out "$D/allan.csv"
            run "$lab" "$n" psd psd "$L" --out "$D/psd.csv"
        done
        rm -f "$D/$name.csv" "$D/$name.csv.gz"
    fi
done
if [ "${SCALE_BIG:-0}" = 1 ]; then
    sim st24h400 stand 86400 400 bin
    L="$D/st24h400.bin"
    n=$(samples "$L")
    lab="static 24 h, 400 Hz, .bin"
    run "$lab" "$n" info info "$L"
    run "$lab" "$n" "convert to CSV" convert "$L" "$D/out.csv"
    run "static 24 h, 400 Hz, .csv" "$n" info info "$D/out.csv"
    rm -f "$D/out.csv"
    run "$lab" "$n" allan allan "$L" --out "$D/allan.csv"
    run "$lab" "$n" psd psd "$L" --out "$D/psd.csv"
    run "$lab" "$n" "replay --quiet" replay "$L" --quiet
    rm -f "$L"
fi
for s in $walks; do
    name=${s%%:*} dur=${s#*:}
    sim "$name" walk "$dur" 200 bin
    L="$D/$name.bin"
    n=$(samples "$L")
    lab="walk $((dur / 60)) min, 200 Hz, .bin"
    run "$lab" "$n" info info "$L"
    run "$lab" "$n" psd psd "$L" --out "$D/psd.csv"
    run "$lab" "$n" "replay --quiet" replay "$L" --quiet
    run "$lab" "$n" simgap simgap "$L" --quiet --json "$D/sg.json"
done
echo
echo "scale_bench: $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, $(uname -m), $H"
