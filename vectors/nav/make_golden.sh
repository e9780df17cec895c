#!/bin/sh
# Golden replays (regression vectors, docs/harness.md): short pieces of real
# walks whose licences allow copying (ISC, MIT, BSD-2; vectors/nav/README.md),
# replayed by the float32 and the float64 build with the default
# configuration. tests/test_nav.c replays the inputs and fails on any change
# of the outputs. After an intended change of the navigation, run
#     sh vectors/nav/make_golden.sh
# and commit the new outputs with the reason in the commit message.
#
# Inputs are written only when missing or empty (they are data, not
# results); a source that cannot be read stops the script (exit 1);
# outputs keep every 25th frame and the last one.
set -eu
cd "$(dirname "$0")/../.."
D=${FNAV_DATA_DIR:-../shared/data}
G=vectors/nav/golden
make -s bin/harness
make -s BUILD=build/double HARNESS=build/double/harness FNAV_DEFS=-DFNAV_USE_DOUBLE=1 build/double/harness
mkdir -p "$G"

piece() { # name source from_s to_s
    # an input of no rows (a header at most) is made again: it is what a run
    # without the shared data used to leave behind
    if [ -f "$G/$1.csv" ] && [ "$(wc -l <"$G/$1.csv")" -gt 1 ]; then return 0; fi
    tmp=$(mktemp)
    if ! bin/harness convert "$2" "$tmp" >/dev/null 2>"$tmp.err"; then
        echo "make_golden.sh: cannot read $2 for the golden input $G/$1.csv (set FNAV_DATA_DIR to the shared data, ../shared/data by default):" >&2
        cat "$tmp.err" >&2
        rm -f "$tmp" "$tmp.err"
        exit 1
    fi
    awk -F, -v S="$3" -v T="$4" 'NR == 1 || (($1 + 0) >= S && ($1 + 0) <= T)' "$tmp" >"$tmp.piece"
    rm -f "$tmp" "$tmp.err"
    if [ "$(wc -l <"$tmp.piece")" -le 1 ]; then
        echo "make_golden.sh: $2 has no sample between $3 and $4 s; $G/$1.csv not written" >&2
        rm -f "$tmp.piece"
        exit 1
    fi
    cat "$tmp.piece" >"$G/$1.csv"
    rm -f "$tmp.piece"
}
piece gx2_walk2 "$D/openshoe_gx2/Measurement_100521_2_data_inert.txt" 0 12
piece xio_short "$D/xio_ngimu_gait/short_walk.csv" 11 19
piece square2 "$D/openshoe_square2/square2_u.csv" 10 30

for n in gx2_walk2 xio_short square2; do
    for b in float double; do
        if [ "$b" = float ]; then h=bin/harness; else h=build/double/harness; fi
        tmp=$(mktemp)
        "$h" replay "$G/$n.csv" --out "$tmp" --quiet
        awk 'NR == 1 || (NR - 2) % 25 == 0 { print; next } { last = $0 } END { if ((NR - 2) % 25 != 0) print last }' \
            "$tmp" > "$G/${n}_traj_$b.csv"
        rm -f "$tmp"
    done
done
echo "golden replays written to $G"
