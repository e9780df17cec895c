#!/bin/sh
# CLI tests of `harness eval` on data directories laid out like the shared
# data but holding more or other files (a holdout of the same kinds): every
# walk is evaluated or named, none is dropped without a word.
# $HARNESS is the harness binary (set by `make test-cli`).
set -u
H=${HARNESS:-bin/harness}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
. "$(dirname "$0")/datadir.sh"

# a still log (no stride: a failed run of a judged set, quick to replay)
still() {
    awk 'BEGIN { print "t,ax,ay,az,gx,gy,gz"; for (i = 0; i < 2000; i++) printf "%.3f,0.01,0.02,9.81,0.001,0,0\n", i / 200 }' > "$1"
}

# --- more walks than eval once had room for (64 per folder, the rest
# dropped without a word and exit 0): every one gets its row
mkdir -p "$T/many/openshoe_gx2"
still "$T/still.csv"
i=1
while [ $i -le 70 ]; do
    ln -s "$T/still.csv" "$T/many/openshoe_gx2/Measurement_2000_${i}_data_inert.txt"
    i=$((i + 1))
done
expect_exit 1 "eval: 70 walks in a folder" "$H" eval --no-experiments --data "$T/many" --out "$T/many.md" --json "$T/many.json"
rows=$(grep -c "^| Measurement_2000_[0-9]* | - |" "$T/many.md")
if [ "$rows" -eq 70 ] && grep -q '"failed_runs":[[:space:]]*70' "$T/many.json"; then
    pass "every one of 70 walks has its row and run"; else fail "70 walks: $rows rows, $(grep -o '"failed_runs":[^,]*' "$T/many.json")"; fi

# --- eval stopped (SIGTERM; Ctrl-C is SIGINT) or failing on the way left
# its --out empty or cut: `fopen "w"` before the runs emptied the tracked
# docs/results.md. The report is written beside it and renamed at the
# end: the previous report stays whole, no part is left
cp "$T/many.md" "$T/keep.md"
"$H" eval --data "$T/many" --out "$T/keep.md" >/dev/null 2>&1 &
ev_pid=$!
sleep 2
if kill -TERM "$ev_pid" 2>/dev/null; then
    wait "$ev_pid"; ev_rc=$?
    [ "$ev_rc" -eq 143 ] && pass "eval stopped by SIGTERM: exit 143" || fail "eval stopped by SIGTERM: exit $ev_rc"
    cmp -s "$T/many.md" "$T/keep.md" && pass "... the previous report kept whole" || fail "... the previous report changed ($(wc -c < "$T/keep.md") bytes)"
    [ -e "$T/keep.md.part" ] && fail "... its part left behind" || pass "... no part left behind"
else
    wait "$ev_pid"
    echo "SKIP eval stopped by SIGTERM: it ended within 2 s"
fi
# a signal ignored when eval starts stays ignored (`nohup eval`: its
# report's handler caught SIGHUP and the run died, exit 129)
sh -c 'trap "" HUP; exec "$@"' sh "$H" eval --no-experiments --data "$T/many" --out "$T/nohup.md" >/dev/null 2>&1 &
ev_pid=$!
sleep 0.5
kill -HUP "$ev_pid" 2>/dev/null
wait "$ev_pid"; ev_rc=$?
[ "$ev_rc" -eq 1 ] && [ -s "$T/nohup.md" ] && pass "eval with SIGHUP ignored: a SIGHUP does not end it (exit 1, the report written)" ||
    fail "eval with SIGHUP ignored: exit $ev_rc"
# --out a symlink to no file: the report is written through it, the link
# kept (the part renamed onto it replaced the link); and a report keeps its
# file's mode (a 0600 one came back 0644)
ln -s "$T/evtarget.md" "$T/evlink.md"
expect_exit 1 "eval --out a symlink to no file" "$H" eval --no-experiments --data "$T/many" --out "$T/evlink.md"
[ -L "$T/evlink.md" ] && [ -s "$T/evtarget.md" ] && pass "... the link kept, its target written" ||
    fail "... $(ls -l "$T/evlink.md" "$T/evtarget.md" 2>&1)"
cp "$T/many.md" "$T/priv.md"; chmod 600 "$T/priv.md"
expect_exit 1 "eval --out a 0600 report" "$H" eval --no-experiments --data "$T/many" --out "$T/priv.md"
[ "$(stat -c %a "$T/priv.md")" = 600 ] && pass "... its mode kept" || fail "... mode $(stat -c %a "$T/priv.md")"

# --- a walk read to its end on which the filter never aligned (it moves
# throughout) is a failed run for that reason: its row must not say "input
# ends early (... no still period ...): the walk was read only in part"
mkdir -p "$T/noal/openshoe_gx2"
awk 'BEGIN { srand(5); print "t,ax,ay,az,gx,gy,gz"; for (i = 0; i < 4000; i++)
    printf "%.3f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f\n", i / 200, 4 * (rand() - 0.5), 4 * (rand() - 0.5),
        9.81 + 4 * (rand() - 0.5), 5 + rand() - 0.5, 3 + rand() - 0.5, rand() - 0.5 }' \
    > "$T/noal/openshoe_gx2/Measurement_2000_1_data_inert.txt"
expect_exit 1 "eval: a walk that never aligns" "$H" eval --no-experiments --no-plots --data "$T/noal" --out "$T/noal.md" --json "$T/noal.json"
if grep -q "^| Measurement_2000_1 | - |.*| not run: the filter never aligned: no still period of [0-9.]* s or more found" "$T/noal.md" &&
    ! grep -q "read only in part" "$T/noal.md" && json "$T/noal.json" 'j["failed_runs"] == 1'; then
    pass "a walk that never aligned is a failed run, named as such"; else fail "never aligned: $(grep '^| Measurement' "$T/noal.md")"; fi
# ... and why it never aligned, as replay says it: a time column that never
# advances is not named "no still period at the start"
mkdir -p "$T/t0/openshoe_gx2"
awk 'BEGIN { print "t,ax,ay,az,gx,gy,gz"; for (i = 0; i < 4000; i++) print "0,0.01,0.02,9.81,0.001,0.002,0.003" }' \
    > "$T/t0/openshoe_gx2/Measurement_2000_1_data_inert.txt"
expect_exit 1 "eval: a walk whose time stamps never advance" "$H" eval --no-experiments --no-plots --data "$T/t0" --out "$T/t0.md"
if grep -q "^| Measurement_2000_1 | - |.*| not run: the filter never aligned: the time stamps never advance" "$T/t0.md"; then
    pass "a walk whose time stamps never advance: the reason in its row"; else fail "time stamps: $(grep '^| Measurement' "$T/t0.md")"; fi

# --- with the experiments on, a bad walk is one failed run (its repeats
# under the experiments' settings are counted apart, not added to
# failed_runs, up to eight per walk)
mkdir -p "$T/exp/openshoe_gx2"
ln -s "$T/still.csv" "$T/exp/openshoe_gx2/Measurement_2000_1_data_inert.txt"
expect_exit 1 "eval with experiments: one bad walk" "$H" eval --data "$T/exp" --out "$T/exp.md" --json "$T/exp.json"
if grep -q '"failed_runs":[[:space:]]*1,' "$T/exp.json" && grep -q '"failed_experiment_runs":[[:space:]]*[1-9]' "$T/exp.json" \
    && grep -q '\*\*1 run(s) failed\*\*' "$T/exp.md" && grep -q "of the experiments' runs failed" "$T/exp.md"; then
    pass "a bad walk counts once; the experiments' repeats apart"
else fail "experiments: $(grep -o '"failed[a-z_]*":[^,]*' "$T/exp.json")"; fi
# ... and is warned about once: not by each of its ten failed repeats, the same "no stride detected" again
# (the repeats' count is in the JSON and under the targets)
n=$(grep -c "Measurement_2000_1_data_inert.txt: no stride detected: no closure to judge" "$T/err")
[ "$n" -eq 1 ] && pass "a bad walk's fault is warned once, not once per experiment run" ||
    fail "a bad walk's fault with the experiments on: warned $n times"
# the rate experiment's row of a walk that failed: dashes, as every table
# (not "nan | nan | nan")
mkdir -p "$T/expx/xio_ngimu_gait"
ln -s "$T/still.csv" "$T/expx/xio_ngimu_gait/short_walk.csv"
expect_exit 1 "eval with experiments: one failed xio walk" "$H" eval --data "$T/expx" --out "$T/expx.md" --no-plots
if grep -q "^| xio short_walk.csv (~400 Hz) | 3-D closure (m) | - | - | - |$" "$T/expx.md" && ! grep -qi "nan" "$T/expx.md"; then
    pass "a failed walk's experiment rows read '-', no nan"; else fail "failed walk in the experiments: $(grep -i 'nan' "$T/expx.md")"; fi

# --- truth files eval refuses (docs/robustness.md, "Bad-input catalogue: eval's truth files"), none of which
# another test feeds: a footprint truth with one readable stride row, one whose rows are all unreadable
# (junk after a y, a position beyond 1e6 m, a fifth field), one with 1,025 strides; a vicon trial whose every
# motion-capture position lies beyond 1e6 m; ipol events files without TrialBoundaries, without the left foot's
# events, of more than 16 MB, and with 257 events. Each is read before its walk is replayed (the logs here are
# placeholders): every one keeps its row with the reason, and counts as a failed run. An events file of exactly
# 16 MiB is read whole: its row names its (empty) log, not the events file. And a footprint walk and a vicon
# trial whose truth strides all lie past the log's end.
B="$T/tbad"
FPD="$B/pyshoe_vicon_llio/own_3dmgx5_footprints"; VD="$B/pyshoe_vicon_llio/vicon_3dmgx3"; ID="$B/ipol_gait_xsens"
mkdir -p "$FPD" "$VD" "$ID"
for w in one junk many; do ln -s "$T/still.csv" "$FPD/${w}_imu.csv"; done
printf 'strideIndex,time,x,y\n10,0.05,0.0,0.0\n' >"$FPD/one_strides_gcp.csv"
printf 'strideIndex,time,x,y\n10,0.05,0.0,0.0x\n20,0.1,1e7,0.0\n30,0.15,1.0,0.0,9\n' >"$FPD/junk_strides_gcp.csv"
awk 'BEGIN { print "strideIndex,time,x,y"; for (i = 0; i < 1025; i++) printf "%d,%.3f,%.2f,0\n", i, i / 200, 0.7 * i }' \
    >"$FPD/many_strides_gcp.csv"
printf 'strideIndex,time,x,y\n10,0.05,0,0\n20,0.1,1,0\n' >"$VD/far_strides_gcp.csv"
ln -s "$T/still.csv" "$VD/one_imu.csv"
cp "$FPD/one_strides_gcp.csv" "$VD/one_strides_gcp.csv"
awk 'BEGIN { print "t,ax,ay,az,gx,gy,gz,x,y"; for (i = 0; i < 100; i++) printf "%.3f,0,0,9.81,0,0,0,2e6,-3e6\n", i / 200 }' \
    >"$VD/far_imu.csv"
# a walk and a trial whose truth strides all lie past the log's end (a truth of another walk): replayed, then
# "fewer than 2 truth strides ... inside the replayed samples" (the vicon log with the position columns 8 and 9)
"$H" sim --motion stand:5,walk:10,stand:3 --rate 100 --out "$FPD/out_imu.csv" >/dev/null 2>&1 || fail "sim of a walk for eval"
awk -F, 'NR == 1 { print "t,ax,ay,az,gx,gy,gz,px,py"; next } { print $0 ",0.5,0.25" }' "$FPD/out_imu.csv" >"$VD/out_imu.csv"
printf 'strideIndex,time,x,y\n100000,500,0,0\n100100,500.5,1,0\n' >"$FPD/out_strides_gcp.csv"
cp "$FPD/out_strides_gcp.csv" "$VD/out_strides_gcp.csv"
for t in 1-1 1-2 1-3 1-4 1-5; do : >"$ID/${t}_lf.txt"; : >"$ID/${t}_rf.txt"; done
printf '{"LeftFootEvents": [[10, 20]], "RightFootEvents": [[30, 40]]}\n' >"$ID/1-1.json"
printf '{"TrialBoundaries": [0, 100], "RightFootEvents": [[30, 40]]}\n' >"$ID/1-2.json"
head -c $((16 * 1048576 + 1)) /dev/zero | tr '\000' ' ' >"$ID/1-3.json"
pre='{"TrialBoundaries": [0, 100], "LeftFootEvents": [[10, 20]], "RightFootEvents": [[30, 40]], "Pad": "'
{ printf '%s' "$pre"; head -c $((16 * 1048576 - ${#pre} - 2)) /dev/zero | tr '\000' x; printf '"}'; } >"$ID/1-4.json"
awk 'BEGIN { printf "{\"TrialBoundaries\": [0, 9000], \"LeftFootEvents\": ["; for (i = 0; i < 257; i++)
    printf "%s[%d, %d]", i ? ", " : "", 30 * i + 10, 30 * i + 20; print "], \"RightFootEvents\": []}" }' >"$ID/1-5.json"
expect_exit 1 "eval: truth files it refuses" "$H" eval --no-experiments --no-plots --data "$B" --out "$T/tbad.md" \
    --json "$T/tbad.json"
if [ "$(wc -c <"$ID/1-4.json")" -eq 16777216 ] && [ "$(wc -c <"$ID/1-3.json")" -eq 16777217 ]; then
    pass "the events files are 16 MiB and one byte more"; else fail "events file sizes: $(wc -c "$ID/1-3.json" "$ID/1-4.json")"; fi
tb_row() { # description pattern: a row of tbad.md
    if grep -q "$2" "$T/tbad.md"; then pass "$1"; else fail "$1: no row /$2/"; grep "not run" "$T/tbad.md"; fi
}
tb_row "one readable stride row" "^| one | - |.*| not run: truth file has 1 readable stride row (strideIndex, _, x, y), 2 needed |$"
tb_row "no readable stride row (junk, 1e7 m, five fields)" \
    "^| junk | - |.*| not run: truth file has 0 readable stride rows (strideIndex, _, x, y), 2 needed |$"
tb_row "1,025 strides" "^| many | - |.*| not run: truth file has more than 1024 strides |$"
tb_row "vicon: one readable stride row" \
    "^| one | - | - | - | - | not run: truth file has 1 readable stride row (strideIndex, _, x, y), 2 needed |$"
tb_row "every motion-capture position beyond 1e6 m" "^| far | - |.*| not run: no motion-capture position columns |$"
# ... with the spans to check it by: the log's, the truth strides' (samples and s), how many lie inside (the
# bare phrase gave no number)
outw="fewer than 2 truth strides with a position fall inside the replayed samples: the log replayed spans [0-9.]* s, its truth's 2 strides samples 100000 to 100100 (1000\.0 to 1001\.0 s at the log's 100 Hz), 0 of them inside it with a position, the first (the reference) not among them: is the truth file another walk's, or the log cut short?"
tb_row "footprint truth past the log's end" "^| out | - | - | - | - | - | - | not run: $outw |$"
tb_row "vicon truth past the log's end" "^| out | - | - | - | - | not run: $outw |$"
for f in left right; do
    tb_row "events without TrialBoundaries ($f)" "^| 1-1 | $f | - |.*| not run: the events file has no TrialBoundaries pair |$"
    tb_row "events without LeftFootEvents ($f)" "^| 1-2 | $f | - |.*| not run: the events file has no LeftFootEvents |$"
    tb_row "an events file over 16 MB ($f)" \
        "^| 1-3 | $f | - |.*| not run: cannot read the events file (larger than 16 MB or unreadable) |$"
    tb_row "257 events ($f)" "^| 1-5 | $f | - |.*| not run: LeftFootEvents holds 257 events, more than 256 |$"
    tb_row "an events file of 16 MiB is read whole ($f): its empty log named" "^| 1-4 | $f | - |.*| not run: empty file |$"
done
json "$T/tbad.json" 'j["failed_runs"] == 17' && pass "each refused truth is a failed run (17)" ||
    fail "refused truths: failed_runs $(grep -o '"failed_runs":[^,]*' "$T/tbad.json")"
# the warning names the truth file it is about (not the walk's IMU log); a
# missing one, the IMU log ("W_imu.csv: no truth file W_strides_gcp.csv")
expect_err "own_3dmgx5_footprints/one_strides_gcp.csv: truth file has 1 readable stride row " "the refusal names the truth file"
expect_err "own_3dmgx5_footprints/many_strides_gcp.csv: truth file has more than 1024 strides" "the refusal names the truth file (1,025)"
expect_err "vicon_3dmgx3/one_strides_gcp.csv: truth file has 1 readable stride row " "vicon: the refusal names the truth file"
expect_err "vicon_3dmgx3/far_imu.csv: no motion-capture position columns" "no position: the IMU log that holds them named"
expect_err "own_3dmgx5_footprints/out_imu.csv: $outw\$" "a truth past the log's end: warned with the spans"
# a recording's events file serves both feet: its TrialBoundaries error was warned once per foot, now once per
# recording (each foot keeps its row and its failed run, above)
n=$(grep -c "1-1.json: the events file has no TrialBoundaries pair" "$T/err")
[ "$n" -eq 1 ] && pass "no TrialBoundaries: warned once per recording" || fail "no TrialBoundaries: warned $n times"
rm -rf "$B"
# an events file's fault that only one foot's events have: the foot missing (no LeftFootEvents, no
# RightFootEvents) or one of its pairs not a pair (an end before its start, NaN). The foot itself fails on it,
# and so does the other foot, whose evaluation needs them (both feet in the air): the same fault is warned about
# once, not once per foot, naming the events file and what is wrong; each foot keeps its row
# and its failed run. The logs are empty placeholders: the events file is read first.
B="$T/evonce"; ID="$B/ipol_gait_xsens"
mkdir -p "$ID"
for t in 1-1 1-2 1-3 1-4; do : >"$ID/${t}_lf.txt"; : >"$ID/${t}_rf.txt"; done
printf '{"TrialBoundaries": [0, 100], "RightFootEvents": [[30, 40]]}\n' >"$ID/1-1.json"
printf '{"TrialBoundaries": [0, 100], "LeftFootEvents": [[10, 20]]}\n' >"$ID/1-2.json"
printf '{"TrialBoundaries": [0, 100], "LeftFootEvents": [[10, 20], [50, 40]], "RightFootEvents": [[30, 40]]}\n' >"$ID/1-3.json"
printf '{"TrialBoundaries": [0, 100], "LeftFootEvents": [[10, 20]], "RightFootEvents": [[30, NaN]]}\n' >"$ID/1-4.json"
expect_exit 1 "eval: events files with one foot's events missing or bad" "$H" eval --no-experiments --no-plots \
    --data "$B" --out "$T/evonce.md" --json "$T/evonce.json"
for c in "1-1.json: the events file has no LeftFootEvents" "1-2.json: the events file has no RightFootEvents" \
    "1-3.json: LeftFootEvents\[1\] is not a pair of sample indices" \
    "1-4.json: RightFootEvents\[0\] is not a pair of sample indices"; do
    n=$(grep -c "^harness eval: warning: $ID/$c\$" "$T/err")
    [ "$n" -eq 1 ] && pass "warned once per recording: $c" || fail "warned $n times: $c"
done
n=$(grep -c "^| 1-[1-4] | \(left\|right\) | - | - | - | - | - | - | not run: .*\(FootEvents\|sample indices\) |$" "$T/evonce.md")
[ "$n" -eq 8 ] && json "$T/evonce.json" 'j["failed_runs"] == 8' && pass "each foot keeps its row and its failed run (8)" ||
    fail "one foot's events at fault: $n rows, $(grep -o '"failed_runs":[^,]*' "$T/evonce.json")"
rm -rf "$B"

# --- no "nan" in results.md where a figure cannot be computed (the tables and summaries print "-" or say why;
# not "nan", exit 0): an unjudged closed walk without a stride (path 0, so no 3-D %),
# an ipol trial whose expert swings are all missed (no event to time: the summary's and the target's medians),
# and a footprint walk whose truth strides all stand at the first one's position (no measured path: its final
# % would be nan, and with it the section's median and mean; a failed run, as a judged closed walk without a stride)
B="$T/nofig"
mkdir -p "$B/ipol_gait_xsens" "$B/openshoe_square2" "$B/pyshoe_vicon_llio/own_3dmgx5_footprints"
for f in lf rf; do
    awk 'BEGIN { print "Acquisition frequency: 100 Hz"; print "PacketCounter\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\tMag_X\tMag_Y\tMag_Z"
                 for (i = 0; i < 3000; i++) printf "%d.0\t0.1\t0.2\t9.81\t0.001\t0.002\t0.001\t0.5\t0\t-0.4\n", i }' \
        >"$B/ipol_gait_xsens/1-1_$f.txt"
done
printf '{"TrialBoundaries": [100, 2900], "UTurnBoundaries": [1400, 1500], "LeftFootEvents": [[500, 550], [700, 750]], "RightFootEvents": [[600, 650], [800, 850]]}\n' \
    >"$B/ipol_gait_xsens/1-1.json"
awk 'BEGIN { print "t,ax,ay,az,gx,gy,gz"; for (i = 0; i < 4000; i++) printf "%.3f,0.01,0.02,9.81,0.001,0,0\n", i / 100 }' \
    >"$B/openshoe_square2/still.csv"
"$H" sim --motion stand:5,walk:10,stand:3 --rate 200 --out "$B/pyshoe_vicon_llio/own_3dmgx5_footprints/same_imu.csv" \
    >/dev/null 2>&1 || fail "sim of a walk for eval"
printf 'strideIndex,time,x,y\n100,0.5,1.0,2.0\n1500,7.5,1.0,2.0\n2500,12.5,1.0,2.0\n' \
    >"$B/pyshoe_vicon_llio/own_3dmgx5_footprints/same_strides_gcp.csv"
expect_exit 1 "eval: figures that cannot be computed" "$H" eval --no-experiments --no-plots --data "$B" \
    --out "$T/nofig.md" --json "$T/nofig.json"
if grep -qi "nan" "$T/nofig.md"; then fail "nan in results.md: $(grep -i 'nan' "$T/nofig.md")"; else pass "no nan in results.md"; fi
grep -q "^| openshoe_square2/still.csv | 100 | 0.00 | 0.000 | 0.000 | - | +0.000 | " "$T/nofig.md" &&
    pass "a closed walk without a path: its 3-D % a dash" || fail "still closed walk: $(grep '^| openshoe_square2' "$T/nofig.md")"
grep -q "^| same | - | - | - | - | - | - | not run: the truth's strides span no path (all at the first stride's position): no final-stride error as a share of it |$" \
    "$T/nofig.md" && json "$T/nofig.json" 'j["failed_runs"] == 1 and j["footprints_final_pct_median"] is None' &&
    pass "a footprint truth without a path: a failed run, said" || fail "truth without a path: $(grep '^| same' "$T/nofig.md")"
expect_err "same_strides_gcp.csv: the truth's strides span no path" "a truth without a path: the truth file named"
grep -q "Event timing: no expert swing detected, no event to time (target <= 2: \*\*not met\*\*)" "$T/nofig.md" &&
    grep -q "^| ipol: median event timing error <= 2 samples | no event timed | \*\*not met\*\* |$" "$T/nofig.md" &&
    json "$T/nofig.json" 'j["ipol_missed"] == 4 and j["ipol_fo_err_median"] is None' &&
    pass "ipol without a detected swing: no event to time, said" || fail "ipol without events: $(grep 'Event timing\|event timing' "$T/nofig.md")"
rm -rf "$B"

# --- the paired tables of the experiments when every walk ties (the same figure in both runs, here a footprint
# walk whose log never moves: final error = the truth's last stride in every configuration): no untied walk for
# the sign test, whose p is "-", not "nan", as every figure that cannot be computed
B="$T/ties"; P="$B/pyshoe_vicon_llio/own_3dmgx5_footprints"
mkdir -p "$P"
awk 'BEGIN { print "t,ax,ay,az,gx,gy,gz"; for (i = 0; i < 4000; i++) printf "%.3f,0,0,9.80665,0,0,0\n", i / 200 }' >"$P/still_imu.csv"
printf 'strideIndex,time,x,y\n100,0.5,0,0\n1500,7.5,1.0,0\n2500,12.5,2.0,0\n' >"$P/still_strides_gcp.csv"
expect_exit 0 "eval with experiments: a walk that ties in every pair" "$H" eval --no-plots --data "$B" --out "$T/ties.md"
if grep -qi "nan" "$T/ties.md"; then fail "ties: nan in results.md: $(grep -i 'nan' "$T/ties.md")"; else pass "ties: no nan in results.md"; fi
n=$(grep -c "^| [a-zA-Z0-9 ]* | footprints final-stride error (%) | 1 | 0 of 0 | +0.00 \[+0.00, +0.00\] | - |$" "$T/ties.md")
[ "$n" -eq 5 ] && pass "ties: each paired row's sign test is '-' (4 profiles, 100 vs 200 Hz)" ||
    fail "ties: $n paired rows with '-': $(grep 'footprints final-stride error (%)' "$T/ties.md")"
rm -rf "$B"

# --- the other closed walks are reported, not judged: one without a stride keeps its row (exit 0), and so do its
# rate experiment's runs. They are not judged as a closure (openshoe_gx2's, xio's): "no stride detected: no closure
# to judge", two failed experiment runs, exit 1 and dashes (a still walk at 400 Hz, above the
# experiment's 200 Hz)
B="$T/unjudged"
mkdir -p "$B/openshoe_c_820hz"
awk 'BEGIN { print "t,ax,ay,az,gx,gy,gz"; for (i = 0; i < 8000; i++) printf "%.4f,0.01,0.02,9.81,0.001,0,0\n", i / 400 }' \
    >"$B/openshoe_c_820hz/walk.txt"
expect_exit 0 "eval with experiments: an unjudged walk without a stride" "$H" eval --no-plots --data "$B" \
    --out "$T/unjudged.md" --json "$T/unjudged.json"
grep -q "^| openshoe_c_820hz/walk.txt (400 Hz) | 3-D closure (m) | [0-9.]* | [0-9.]* | [0-9.]* |$" "$T/unjudged.md" &&
    json "$T/unjudged.json" 'j["failed_experiment_runs"] == 0' && ! grep -q "no closure to judge" "$T/err" &&
    pass "an unjudged walk's rate experiment: reported, not judged" ||
    fail "unjudged walk's experiment: $(grep '^| openshoe_c_820hz/walk.txt (' "$T/unjudged.md") $(grep warning "$T/err")"
rm -rf "$B"

# --- a figures' directory that exists but is no directory (--plots naming a file, or a file img beside --out): an
# error before the run, exit 3, as a directory that cannot be made, results.md not touched. Passing the check
# (mkdir's EEXIST), each figure would print "error: cannot write .../eval-gx2.png (Not a
# directory)" in the middle of a run that ended with exit 0
B="$T/pfile"
mkdir -p "$B/data/openshoe_gx2" "$B/md"
still "$B/data/openshoe_gx2/Measurement_2000_1_data_inert.txt"
: >"$B/figs"
: >"$B/md/img"
echo "kept" >"$B/md/r.md"
expect_exit 3 "eval --plots naming a file" "$H" eval --no-experiments --data "$B/data" --out "$B/md/r.md" --plots "$B/figs"
expect_err "^harness eval: error: the figures' directory $B/figs is not a directory$" "--plots naming a file: said"
expect_exit 3 "eval: a file img beside --out" "$H" eval --no-experiments --data "$B/data" --out "$B/md/r.md"
expect_err "^harness eval: error: the figures' directory $B/md/img is not a directory$" "a file img beside --out: said"
[ "$(cat "$B/md/r.md")" = "kept" ] && pass "figures' directory not a directory: results.md not touched" ||
    fail "figures' directory not a directory: results.md overwritten"
rm -rf "$B"

# --- a data directory with a long name (561 bytes, far under PATH_MAX): eval must not keep 511 bytes of it and say
# "no shared data in" the cut name, exit 4. It is evaluated; one too long for eval's room (over 1,023
# bytes) is refused as such, exit 2, not taken for a missing directory
B=$T/$(printf '%0200d' 0)/$(printf '%0200d' 1)/$(printf '%0140d' 2)
mkdir -p "$B/openshoe_gx2"
still "$B/openshoe_gx2/Measurement_2000_1_data_inert.txt"
expect_exit 1 "eval: a data directory of $(printf '%s' "$B" | wc -c) bytes" "$H" eval --no-experiments --no-plots --data "$B" \
    --out "$T/longdata.md"
grep -q "^| Measurement_2000_1 | - |.*| not run: no stride detected: no closure to judge |$" "$T/longdata.md" &&
    pass "a data directory with a long name: its walk evaluated" || fail "long data directory: $(head -c 300 "$T/err")"
B2=$B/$(printf '%0250d' 3)/$(printf '%0250d' 4)
mkdir -p "$B2/openshoe_gx2"
expect_exit 2 "eval: a data directory longer than eval's room" "$H" eval --no-experiments --no-plots --data "$B2" --out "$T/longdata2.md"
expect_err "^harness eval: error: the data directory .* is longer than 1023 bytes" "a data directory too long: said"
rm -rf "$T/$(printf '%0200d' 0)"

# --- a walk whose file name holds '|' (or a line break): written as it is into a Markdown table row, it would make
# one cell more and break the table; escaped ("\|"; a control character as '?'). And in a row's
# reason, where '|' must not be made '/' (an ipol trial 1|1 without its events file: "cannot open 1/1.json", another
# name)
B="$T/pipe"
mkdir -p "$B/openshoe_gx2" "$B/openshoe_square2" "$B/ipol_gait_xsens"
: >"$B/ipol_gait_xsens/1|1_lf.txt"
still "$B/openshoe_gx2/a|b_data_inert.txt"
still "$B/openshoe_square2/c|d.csv"
still "$B/openshoe_square2/e
f.csv"
expect_exit 1 "eval: walks named with '|' and a line break" "$H" eval --no-experiments --no-plots --data "$B" --out "$T/pipe.md"
bad=$(awk '/^\|/ { l = $0; gsub(/\\\|/, "", l); n = gsub(/\|/, "", l);
             if (!intab) { want = n; intab = 1 } else if (n != want) print FNR ": " $0 }
     !/^\|/ { intab = 0 }' "$T/pipe.md")
if [ -z "$bad" ] && grep -q '^| a\\|b | - |' "$T/pipe.md" && grep -q '^| openshoe_square2/c\\|d.csv | ' "$T/pipe.md" &&
    grep -q '^| openshoe_square2/e?f.csv | ' "$T/pipe.md" &&
    [ "$(grep -c '^| 1\\|1 | \(left\|right\) | - | .* | not run: cannot open 1\\|1.json (No such file or directory) |$' "$T/pipe.md")" -eq 2 ]; then
    pass "names with '|' and a line break: escaped, every row as wide as its table"
else fail "names with '|': rows with a wrong cell count: $bad"; fi
rm -rf "$B"

# --- results.md that cannot be written (a full disk): exit 3, the reason given, and the JSON of --json still
# written, eval not returning before it ("nothing computed is lost", docs/harness.md), and the error does not
# say "cannot write /dev/full" without why
if [ -w /dev/full ]; then
    B="$T/full"
    mkdir -p "$B/openshoe_square2"
    still "$B/openshoe_square2/s.csv"
    expect_exit 3 "eval --out onto a full disk" "$H" eval --no-experiments --no-plots --data "$B" --out /dev/full --json "$T/full.json"
    expect_err "^harness eval: error: cannot write /dev/full (No space left on device)$" "eval --out onto a full disk: the reason given"
    json "$T/full.json" 'j["failed_runs"] == 0 and "gx2_h_pct_median" in j' && pass "eval --out onto a full disk: the JSON written" ||
        fail "eval --out onto a full disk: no JSON"
    rm -rf "$B"
else
    echo "skip eval's full-disk check (no /dev/full)"
fi
# ... and one that cannot be opened, before the run: the reason given too
mkdir -p "$T/nof/openshoe_square2"
still "$T/nof/openshoe_square2/s.csv"
expect_exit 3 "eval --out in a missing directory" "$H" eval --no-experiments --no-plots --data "$T/nof" --out "$T/no/such/r.md"
expect_err "^harness eval: error: cannot write $T/no/such/r.md (No such file or directory)$" "eval --out in a missing directory: the reason"

# a --data that does not exist, or is a file: said so (exit 4 as before).
# It read "no shared data in DIR (give --data DIR or set FNAV_DATA_DIR)",
# as for a directory without the data, to a user who gave --data
expect_exit 4 "eval --data of a missing directory" "$H" eval --no-experiments --no-plots --data "$T/typo" --out "$T/typo.md"
expect_err "^harness eval: error: no shared data in $T/typo: it does not exist (No such file or directory)$" "eval --data missing: said"
echo x >"$T/afile"
expect_exit 4 "eval --data of a file" "$H" eval --no-experiments --no-plots --data "$T/afile" --out "$T/typo.md"
expect_err "^harness eval: error: no shared data in $T/afile: it is not a directory$" "eval --data a file: said"
[ -e "$T/typo.md" ] && fail "eval --data missing: results written" || pass "eval --data missing: no results file"
mkdir -p "$T/emptydir"
expect_exit 4 "eval --data of an empty directory" "$H" eval --no-experiments --no-plots --data "$T/emptydir" --out "$T/typo.md"
expect_err "no shared data in $T/emptydir (neither MANIFEST.md nor a data set folder" "eval --data empty: what is missing said"

# a data directory with its MANIFEST.md and set folders but not one walk
# (a copy not synced): nothing to run on, exit 4, the results file left as
# it was (not overwritten with "no data" everywhere, exit 0)
mkdir -p "$T/nowalk/openshoe_gx2" "$T/nowalk/ipol_gait_xsens"
echo "# Real data for footnav" > "$T/nowalk/MANIFEST.md"
echo "kept" > "$T/nowalk.md"
expect_exit 4 "eval: set folders without a walk" "$H" eval --no-experiments --data "$T/nowalk" --out "$T/nowalk.md"
expect_err "no walk or trial in any data set folder of $T/nowalk" "no walk: said"
if [ "$(cat "$T/nowalk.md")" = "kept" ]; then pass "no walk: the results file is not touched"; else fail "no walk: results file overwritten"; fi

# licence and readme files whatever their case (the shared data has
# ISC_license.txt and LICENSE_BSD-2.txt): not walks (replayed and failed, exit 1)
mkdir -p "$T/docs/openshoe_c_820hz" "$T/docs/xio_ngimu_gait" "$T/docs/openshoe_gx2"
still "$T/docs/openshoe_c_820hz/walk.txt"
for f in readme.txt ISC_license.txt Licence.txt SOURCE.txt; do echo "not a walk" > "$T/docs/openshoe_c_820hz/$f"; done
echo "a,b" > "$T/docs/xio_ngimu_gait/Readme.csv"
echo "not a walk" > "$T/docs/openshoe_gx2/README_data_inert.txt"
expect_exit 0 "eval: licence and readme files in any case" "$H" eval --no-experiments --data "$T/docs" --out "$T/docs.md"
if grep -qi "readme\|licen\|SOURCE.txt" "$T/docs.md" "$T/err"; then fail "a licence or readme file taken for a walk: $(grep -i 'readme\|licen\|SOURCE' "$T/docs.md" "$T/err")";
else pass "licence and readme files are not walks, whatever their case"; fi
if grep -q "^| openshoe_c_820hz/walk.txt | " "$T/docs.md"; then pass "the walk beside them is evaluated"; else fail "walk beside the docs missing"; fi
if grep -q "^No walks found in \`$T/docs/openshoe_square2\`." "$T/docs.md"; then pass "the other closed set's absence is said"; else
    fail "absent openshoe_square2 not named"; fi
# the paths' axes are the navigation frame's x and y (docs/frames.md: x along the sensor's heading at the alignment,
# no magnetometer): not 'north x' and 'east y', which a figure in a paper reads as geographic (in eval's figures as
# in replay's plot)
fake_gnuplot "$T/fakegp"
PATH="$T/fakegp:$PATH" GP_SCRIPT="$T/gp_eval.txt" "$H" eval --no-experiments --data "$T/docs" --out "$T/docs_gp.md" \
    --plots "$T/docs_figs" >/dev/null 2>&1
if grep -q "^set xlabel 'y (m, right of the start heading)'" "$T/gp_eval.txt" &&
    grep -q "^set ylabel 'x (m, along the start heading)'" "$T/gp_eval.txt" && ! grep -q -i "north\|east" "$T/gp_eval.txt"; then
    pass "eval's path figure: axes named after the start heading, not north and east"
else fail "eval path labels: $(grep label "$T/gp_eval.txt" 2>/dev/null | tr '\n' ' ')"; fi

if [ -n "$D" ]; then
    D=$(cd "$D" && pwd) # the symlinks below need an absolute target
    # a walk's truth without its IMU log, an ipol trial's logs without their
    # events, a trial without one foot's log: failed runs with their rows (the
    # first two were passed over without a word); a file under no name of
    # the set: warned about and named under its section
    mkdir -p "$T/orph/pyshoe_vicon_llio/own_3dmgx5_footprints" "$T/orph/pyshoe_vicon_llio/vicon_3dmgx3" \
        "$T/orph/ipol_gait_xsens" "$T/orph/openshoe_gx2"
    ln -s "$D/pyshoe_vicon_llio/own_3dmgx5_footprints/SensorConnectData_31_strides_gcp.csv" \
        "$T/orph/pyshoe_vicon_llio/own_3dmgx5_footprints/SensorConnectData_44_strides_gcp.csv"
    ln -s "$D/pyshoe_vicon_llio/vicon_3dmgx3/2017-11-22-11-22-03_strides_gcp.csv" \
        "$T/orph/pyshoe_vicon_llio/vicon_3dmgx3/2018-01-01-10-00-00_strides_gcp.csv"
    for f in lf rf; do ln -s "$D/ipol_gait_xsens/1-1_$f.txt" "$T/orph/ipol_gait_xsens/4-14_$f.txt"; done
    ln -s "$D/ipol_gait_xsens/1-2.json" "$T/orph/ipol_gait_xsens/4-13.json"
    ln -s "$D/ipol_gait_xsens/1-2_lf.txt" "$T/orph/ipol_gait_xsens/4-13_lf.txt"
    ln -s "$D/openshoe_gx2/Measurement_100521_2_data_inert.txt" "$T/orph/openshoe_gx2/Measurement_100601_8_data_inert.TXT"
    expect_exit 1 "eval: truth without its log, logs without their events" "$H" eval --no-experiments --data "$T/orph" --out "$T/orph.md" --json "$T/orph.json"
    if grep -q "^| SensorConnectData_44 | - |.*| not run: no IMU log SensorConnectData_44_imu.csv |" "$T/orph.md" &&
        grep -q "^| 2018-01-01-10-00-00 | - |.*| not run: no IMU log 2018-01-01-10-00-00_imu.csv |" "$T/orph.md"; then
        pass "a truth file without its IMU log keeps a row"; else fail "truth without log: $(grep 'not run' "$T/orph.md")"; fi
    if [ "$(grep -c "^| 4-14 | \(left\|right\) | - |.*| not run: cannot open 4-14.json (No such file or directory) |" "$T/orph.md")" -eq 2 ] &&
        grep -q "^| 4-13 | right | - |.*| not run: no IMU log 4-13_rf.txt |" "$T/orph.md" &&
        grep -q "^| 4-13 | left | 15 |" "$T/orph.md"; then
        pass "ipol logs without their events (the reason said), a trial without one foot: rows"; else fail "ipol orphans: $(grep '^| 4-1' "$T/orph.md")"; fi
    if grep -q '"failed_runs":[[:space:]]*5' "$T/orph.json"; then pass "each counted as a failed run"; else
        fail "orphans: $(grep -o '"failed_runs":[^,]*' "$T/orph.json")"; fi
    expect_err "Measurement_100601_8_data_inert.TXT: not read" "a file under no name of its set is warned about"
    if grep -q "^Not read (no name of this set's data files, \`\*_data_inert.txt\`): \`Measurement_100601_8_data_inert.TXT\`." "$T/orph.md"; then
        pass "and named under its section"; else fail "unread file: $(grep 'Not read' "$T/orph.md")"; fi
    bad=$(awk '/^\|/ { l = $0; gsub(/\\\|/, "", l); n = gsub(/\|/, "", l);
                 if (!intab) { want = n; intab = 1 } else if (n != want) print FILENAME ":" FNR }
         !/^\|/ { intab = 0 }' "$T/orph.md")
    if [ -z "$bad" ]; then pass "tables well formed"; else fail "rows with a wrong cell count: $bad"; fi

    # truth files: footprint walk 31's truth cut off mid-line (its last y,
    # -0.5529..., read as -5.529 gave a 5.3 m final error without a word) and
    # without its header (its first stride, the reference, was taken for the
    # header); a vicon trial whose motion capture is lost (NaN, an empty
    # cell) at a stride, and one whose log is cut in half
    FP="$D/pyshoe_vicon_llio/own_3dmgx5_footprints/SensorConnectData_31"
    VI="$D/pyshoe_vicon_llio/vicon_3dmgx3/2017-11-22-11-28-39"
    P="$T/truth/pyshoe_vicon_llio/own_3dmgx5_footprints"; V="$T/truth/pyshoe_vicon_llio/vicon_3dmgx3"
    mkdir -p "$P" "$V"
    for w in cut nohead short; do ln -s "${FP}_imu.csv" "$P/${w}_imu.csv"; done
    head -c $(($(wc -c < "${FP}_strides_gcp.csv") - 20)) "${FP}_strides_gcp.csv" > "$P/cut_strides_gcp.csv"
    tail -n +2 "${FP}_strides_gcp.csv" > "$P/nohead_strides_gcp.csv"
    head -n $(($(wc -l < "${FP}_strides_gcp.csv") / 2)) "${FP}_strides_gcp.csv" > "$P/short_strides_gcp.csv"
    n=$(($(wc -l < "${FP}_strides_gcp.csv") - 2))
    row=$(($(sed -n 6p "${VI}_strides_gcp.csv" | cut -d, -f1 | awk '{ printf "%d", $1 }') + 2)) # the 5th stride's line
    awk -F, -v r=$row 'BEGIN { OFS = "," } NR == r { $8 = "nan" } { print }' "${VI}_imu.csv" > "$V/lost_imu.csv"
    awk -F, -v r=$row 'BEGIN { OFS = "," } NR == r { $8 = ""; $9 = "" } { print }' "${VI}_imu.csv" > "$V/empty_imu.csv"
    head -n $(($(wc -l < "${VI}_imu.csv") / 2)) "${VI}_imu.csv" > "$V/half_imu.csv"
    for w in lost empty half; do ln -s "${VI}_strides_gcp.csv" "$V/${w}_strides_gcp.csv"; done
    expect_exit 0 "eval: truth files cut, without header, motion capture lost" "$H" eval --no-experiments --data "$T/truth" --out "$T/truth.md"
    if grep -q "^| cut | $((n - 1)) | .*| truth's last line cut off (no newline): not read |" "$T/truth.md"; then
        pass "a truth file cut off mid-line: its last row not read, and noted"; else fail "cut truth: $(grep '^| cut' "$T/truth.md")"; fi
    # ... and warned about on standard error, once, naming the file, the line and its text (only the row's
    # note said so: exit 0, nothing on stderr); exit 0 still (the walk is scored on the other rows)
    expect_err "^harness eval: warning: $P/cut_strides_gcp.csv:$((n + 2)): truth's last line cut off (no newline): not read ('[0-9.e+]*,.*,-5\.529': " \
        "a truth file's cut last line is warned about, its line and text named"
    if [ "$(grep -c "cut off (no newline)" "$T/err")" -eq 1 ]; then pass "the cut truth line warned once"; else
        fail "cut truth warnings: $(grep "cut off (no newline)" "$T/err")"; fi
    if grep -q "^| nohead | $n | " "$T/truth.md"; then pass "a truth file without a header keeps its first stride"; else
        fail "headerless truth: $(grep '^| nohead' "$T/truth.md")"; fi
    # a truth that stops half way (complete lines): the unscored end is noted
    if grep -q "^| short | .*| truth ends [0-9]* s before the log: its end not scored |" "$T/truth.md" &&
        ! grep -q "^| nohead | .*truth ends" "$T/truth.md"; then
        pass "a truth ending before the log is noted"; else fail "short truth: $(grep '^| short' "$T/truth.md")"; fi
    if grep -q "^| lost | [0-9]* | [0-9.]* | [0-9.]* | [0-9.]* | 1 stride without a truth position not scored |" "$T/truth.md" &&
        grep -q "^| empty | [0-9]* | [0-9.]* | [0-9.]* | [0-9.]* | 1 stride without a truth position not scored |" "$T/truth.md"; then
        pass "a stride without motion capture is left out and noted"; else fail "lost motion capture: $(grep '^| \(lost\|empty\)' "$T/truth.md")"; fi
    if grep -q "^| half | [0-9]* |.*| [0-9]* strides outside the log not scored |" "$T/truth.md"; then
        pass "vicon strides outside the log are noted"; else fail "vicon log cut: $(grep '^| half' "$T/truth.md")"; fi
    if grep -qi "nan" "$T/truth.md"; then fail "nan in the results: $(grep -i '| nan\|nan |' "$T/truth.md")"; else pass "no nan in the figures"; fi
    # truth rows with junk in a field (from a mutation sweep): a
    # y followed by text, a stride index cut to "1.5e", a row split into five
    # fields ("8.,9.27e+00": its timestamp read as x, x as y). sscanf takes
    # what comes before the junk: here a path of 84.1 m for 47.9 and an RMS
    # of 3.55 m for 0.44, without a word; in the sweep a footprint 2e16 m
    # away (path 39579392000000320.0 m, final 0.00 %, exit 0). They are
    # unreadable rows. So is a line of 600 characters (its index followed by
    # x and 600 zeros), which read 511 characters at a time would be one
    # unreadable row and its tail a stride at sample 0; and an x of -7e42 m
    # (in the sweep a path of 1.4e43 m, final 0.00 %)
    J="$T/junk/pyshoe_vicon_llio/own_3dmgx5_footprints"
    mkdir -p "$J"
    ln -s "${FP}_imu.csv" "$J/junk_imu.csv"
    awk -F, 'BEGIN { OFS = "," } NR == 4 { $4 = $4 "\"x\"" } NR == 6 { $1 = "1.5e" } NR == 8 { $2 = "8.," $2 }
             NR == 10 { $1 = $1 "x" sprintf("%0600d", 0) } NR == 12 { $3 = "-7e42" } { print }' \
        "${FP}_strides_gcp.csv" > "$J/junk_strides_gcp.csv"
    expect_exit 0 "eval: truth rows with junk in a field" "$H" eval --no-experiments --no-plots --data "$T/junk" --out "$T/junk.md"
    if grep -q "^| junk | $((n - 5)) | 4[0-9]\.[0-9] | .*| 5 unreadable truth rows ignored |" "$T/junk.md"; then
        pass "truth rows with junk in a field are unreadable rows, noted"; else fail "junk truth: $(grep '^| junk' "$T/junk.md")"; fi
    # ... and warned about on standard error (only the row's note said so: exit 0, nothing on stderr), naming
    # the truth file, the count, and the first one's line and text (exit 0 still: the walk is scored on the rest)
    expect_err "^harness eval: warning: $J/junk_strides_gcp.csv:4: 5 unreadable truth rows ignored (the first here: '8\.95.*e-01\"x\"'): a row is strideIndex, _, x, y" \
        "unreadable truth rows are warned about, the first one's line and text named"
    # a NUL byte inside a row is no long line: the row after it must not be
    # taken for the rest of a long one and lost without a word (as a long
    # line told by a missing newline, which a NUL also gives, would be)
    ln -s "${FP}_imu.csv" "$J/nul_imu.csv"
    awk 'NR == 4 { printf "%s%cjunk\n", $0, 0; next } { print }' "${FP}_strides_gcp.csv" > "$J/nul_strides_gcp.csv"
    expect_exit 0 "eval: a truth row with a NUL byte" "$H" eval --no-experiments --no-plots --data "$T/junk" --out "$T/junk.md"
    if grep -Eq "^\| nul \| ($n \| 47\.9 \| .* \|  \||$((n - 1)) \| 47\.9 \| .* \| 1 unreadable truth row ignored \|)$" "$T/junk.md"; then
        pass "a truth row with a NUL byte takes no other row with it"; else fail "NUL truth: $(grep '^| nul' "$T/junk.md")"; fi
    # the vicon positions in the IMU file, read as the truth rows: a y of
    # 1.04xyz at the 5th stride is not read as 1.04; a line of 600 characters
    # (an x followed by 600 ']') just before it is not two rows, so that the
    # 5th stride would take the position of the row before and every later
    # one too (from a mutation sweep): one row without a position
    VJ="$T/vjunk/pyshoe_vicon_llio/vicon_3dmgx3"
    mkdir -p "$VJ"
    awk -F, -v r=$row 'BEGIN { OFS = "," } NR == r { $9 = $9 "xyz" } { print }' "${VI}_imu.csv" > "$VJ/yjunk_imu.csv"
    awk -F, -v r=$((row - 1)) 'BEGIN { OFS = "," } NR == r { $8 = $8 sprintf("%600s", "") } { gsub(/ /, "]"); print }' \
        "${VI}_imu.csv" > "$VJ/long_imu.csv"
    ln -s "${VI}_imu.csv" "$VJ/plain_imu.csv"
    # and an x beyond 1e6 m (FNAV_INPUT_MAX_ABS) at the 5th stride: no position there (no other test feeds one;
    # docs/robustness.md, "Bad-input catalogue: eval's truth files")
    awk -F, -v r=$row 'BEGIN { OFS = "," } NR == r { $8 = "2e6" } { print }' "${VI}_imu.csv" > "$VJ/far_imu.csv"
    for w in yjunk long plain far; do ln -s "${VI}_strides_gcp.csv" "$VJ/${w}_strides_gcp.csv"; done
    expect_exit 0 "eval: vicon positions with junk, a long line" "$H" eval --no-experiments --no-plots --data "$T/vjunk" --out "$T/vjunk.md"
    plain=$(grep '^| plain | ' "$T/vjunk.md" | cut -d'|' -f3-)
    if grep -q "^| yjunk | [0-9]* | [0-9.]* | [0-9.]* | [0-9.]* | 1 stride without a truth position not scored |" "$T/vjunk.md" &&
        [ -n "$plain" ] && [ "$(grep '^| long | ' "$T/vjunk.md" | cut -d'|' -f3-)" = "$plain" ]; then
        pass "vicon positions: junk after a y is no position, a long line one row"
    else fail "vicon junk: $(grep '^| \(yjunk\|long\) ' "$T/vjunk.md")"; fi
    if grep -q "^| far | [0-9]* | [0-9.]* | [0-9.]* | [0-9.]* | 1 stride without a truth position not scored |" "$T/vjunk.md"; then
        pass "vicon positions: an x beyond 1e6 m is no position"; else fail "vicon far: $(grep '^| far ' "$T/vjunk.md")"; fi
    # a vicon trial that starts walking (its first 0.25 s cut off: 0.1 s of
    # stillness before the first stride, too little to align on): the filter
    # aligns in a later stance, the strides before are not navigated and would
    # be scored against frames at position 0 without a word (median stride
    # error 0.93 m against the whole trial's 0.07 m). Their row
    # says so; the whole trial, whose first stride lies in the still period
    # the alignment used, has no such note
    VE="$D/pyshoe_vicon_llio/vicon_3dmgx3/2017-11-22-11-52-02"
    E="$T/early/pyshoe_vicon_llio/vicon_3dmgx3"
    mkdir -p "$E"
    awk 'NR == 1 || NR > 51' "${VE}_imu.csv" > "$E/early_imu.csv"
    awk -F, 'BEGIN { OFS = "," } NR == 1 { print; next } { $1 = sprintf("%d", $1 + 0.5) - 50; if ($1 >= 0) print }' \
        "${VE}_strides_gcp.csv" > "$E/early_strides_gcp.csv"
    ln -s "${VE}_imu.csv" "$E/whole_imu.csv"
    ln -s "${VE}_strides_gcp.csv" "$E/whole_strides_gcp.csv"
    expect_exit 0 "eval: a vicon trial that starts walking" "$H" eval --no-experiments --no-plots --data "$T/early" --out "$T/early.md"
    if grep -q "^| early | .*1 truth stride before the alignment, a step between (log starts walking): not navigated |" "$T/early.md" &&
        grep -q "^| whole | [0-9]* | [0-9.]* | [0-9.]* | [0-9.]* |  |" "$T/early.md"; then
        pass "truth strides before the alignment are noted"; else fail "early start: $(grep '^| \(early\|whole\)' "$T/early.md")"; fi
    # a walk cut off mid-line two thirds in (no closed loop): the reader's
    # warning is in its row, not only on standard error
    mkdir -p "$T/cutw/openshoe_gx2"
    W="$D/openshoe_gx2/Measurement_100521_2_data_inert.txt"
    head -c $(($(wc -c < "$W") * 2 / 3)) "$W" > "$T/cutw/openshoe_gx2/Measurement_100601_13_data_inert.txt"
    ln -s "$W" "$T/cutw/openshoe_gx2/"
    expect_exit 0 "eval: a walk cut off mid-line" "$H" eval --no-experiments --data "$T/cutw" --out "$T/cutw.md"
    if grep -q "^| Measurement_100601_13 | [0-9].* | last line cut off mid-write: not read |" "$T/cutw.md" &&
        grep -q "^| Measurement_100521_2 | [0-9].* |  |" "$T/cutw.md"; then
        pass "a walk cut off mid-line is noted in its row"; else fail "cut walk: $(grep '^| Measurement' "$T/cutw.md")"; fi
    # a walk whose line 8000 is not data (half way): the reader stops there.
    # Not a note in the row only, no warning, exit 0, and the half walk's
    # closure (26.6 %) judged against the targets
    mkdir -p "$T/badl/openshoe_gx2"
    awk 'NR == 8000 { $2 = "abc" } { print }' "$W" > "$T/badl/openshoe_gx2/Measurement_100601_14_data_inert.txt"
    ln -s "$W" "$T/badl/openshoe_gx2/"
    expect_exit 1 "eval: a walk with a malformed line half way" "$H" eval --no-experiments --data "$T/badl" --out "$T/badl.md" --json "$T/badl.json"
    expect_err "Measurement_100601_14_data_inert.txt: input ends early (line 8000: " "the walk's bad line is warned about, with its number"
    if grep -q "^| Measurement_100601_14 | - |.*| not run: input ends early (line 8000: .*read only in part |" "$T/badl.md" &&
        grep -q "^| Measurement_100521_2 | [0-9].* |  |" "$T/badl.md" && json "$T/badl.json" 'j["failed_runs"] == 1'; then
        pass "a walk read only in part is a failed run, the other walk is judged"; else fail "bad line: $(grep '^| Measurement' "$T/badl.md")"; fi
    # 70 ipol trials (trial 1-1 under other numbers): 140 rows, and the
    # summary counts them all
    mkdir -p "$T/ipmany/ipol_gait_xsens"
    i=1
    while [ $i -le 70 ]; do
        for x in .json _lf.txt _rf.txt; do ln -s "$D/ipol_gait_xsens/1-1$x" "$T/ipmany/ipol_gait_xsens/9-$i$x"; done
        i=$((i + 1))
    done
    expect_exit 0 "eval: 70 ipol trials" "$H" eval --no-experiments --data "$T/ipmany" --out "$T/ipmany.md"
    rows=$(grep -c "^| 9-[0-9]* | \(left\|right\) | 15 \| 17 |" "$T/ipmany.md")
    if [ "$rows" -eq 140 ] && grep -q "^140 trials and feet: 2240 expert strides" "$T/ipmany.md"; then
        pass "every one of 70 ipol trials is scored"; else fail "70 ipol trials: $rows rows; $(grep 'trials and feet' "$T/ipmany.md" | cut -c1-60)"; fi
    # an ipol foot's log with a malformed line half way, the other foot's
    # cut off mid-line half way: neither read up to there without a word (no
    # warning, no note, exit 0), with the expert strides after it counted as
    # missed (8 and 8: the detector blamed for the data)
    mkdir -p "$T/ipbad/ipol_gait_xsens"
    ln -s "$D/ipol_gait_xsens/1-1.json" "$T/ipbad/ipol_gait_xsens/1-1.json"
    awk 'BEGIN { FS = OFS = "\t" } NR == 1500 { $2 = "abc" } { print }' "$D/ipol_gait_xsens/1-1_lf.txt" > "$T/ipbad/ipol_gait_xsens/1-1_lf.txt"
    R="$D/ipol_gait_xsens/1-1_rf.txt"
    head -c $(($(wc -c < "$R") / 2)) "$R" > "$T/ipbad/ipol_gait_xsens/1-1_rf.txt"
    expect_exit 1 "eval: ipol logs with a bad line, cut off" "$H" eval --no-experiments --data "$T/ipbad" --out "$T/ipbad.md" --json "$T/ipbad.json"
    expect_err "1-1_lf.txt: input ends early (line 1500: " "the ipol log's bad line is warned about, with its number"
    expect_err "1-1_rf.txt:[0-9]*: last line is incomplete" "the cut ipol log is warned about"
    if grep -q "^| 1-1 | left | - |.*| not run: input ends early (line 1500: .*read only in part |" "$T/ipbad.md" &&
        grep -q "^| 1-1 | right | [0-9]* | [0-9]* | 0 | 0 | .*| last line cut off mid-write: not read; [1-9][0-9]* expert swings after the log's end not evaluated |" "$T/ipbad.md" &&
        json "$T/ipbad.json" 'j["failed_runs"] == 1 and j["ipol_missed"] == 0'; then
        pass "a bad ipol log is a failed run; a cut one leaves the swings after its end out, noted"
    else fail "ipol bad logs: $(grep '^| 1-1' "$T/ipbad.md")"; fi
    # the experts' indices are PacketCounter values (one TrialBoundaries pair
    # for both feet, whose files start at different counters): a left foot
    # log whose first 3 packets were lost (starting at counter 3) scores as
    # the whole one; counted from the file's first packet its events moved 3
    # packets early and the row read 4.0 and 2.0
    mkdir -p "$T/ipfirst/ipol_gait_xsens"
    for x in .json _rf.txt; do ln -s "$D/ipol_gait_xsens/1-1$x" "$T/ipfirst/ipol_gait_xsens/"; done
    awk 'NR < 3 || NR > 5' "$D/ipol_gait_xsens/1-1_lf.txt" > "$T/ipfirst/ipol_gait_xsens/1-1_lf.txt"
    expect_exit 0 "eval: an ipol log whose first packets were lost" "$H" eval --no-experiments --data "$T/ipfirst" --out "$T/ipfirst.md"
    if grep -q "^| 1-1 | left | 15 | 15 | 0 | 0 | 2.0 | 1.0 |  |$" "$T/ipfirst.md"; then
        pass "ipol: events in counter values, not packets since the file's first"; else fail "ipol first packets lost: $(grep '^| 1-1 | left' "$T/ipfirst.md")"; fi
    # several expert swings close together: 1-1's left swing [641, 687]
    # annotated as three, the middle one with the right foot in the air too
    # (left out). The one detected swing there detects one of them, not
    # counted twice (16 detected, 0 missed), as leaving the middle one out
    # could clear the mark that the first had taken it
    mkdir -p "$T/ipdbl/ipol_gait_xsens"
    for f in lf rf; do ln -s "$D/ipol_gait_xsens/1-1_$f.txt" "$T/ipdbl/ipol_gait_xsens/"; done
    sed 's/\[641, 687\]/[641, 660], [661, 665], [666, 687]/; s/"RightFootEvents": \[/"RightFootEvents": [[661, 665], /' \
        "$D/ipol_gait_xsens/1-1.json" > "$T/ipdbl/ipol_gait_xsens/1-1.json"
    expect_exit 0 "eval: expert swings close together" "$H" eval --no-experiments --data "$T/ipdbl" --out "$T/ipdbl.md"
    if grep -q "^| 1-1 | left | 16 | 15 | 1 | 0 | " "$T/ipdbl.md"; then
        pass "ipol: a detected swing detects one expert swing, not two"; else fail "ipol double match: $(grep '^| 1-1 | left' "$T/ipdbl.md")"; fi
    # an unknown (NaN) expert event or U-turn boundary: not read as 0, which
    # would make [641, NaN] a missed stride, [NaN, 2580] of the right foot a
    # swing over the whole trial that left every left swing out ("0 expert
    # strides", exit 0), and a NaN U-turn none (its strides judged)
    mkdir -p "$T/ipnan/ipol_gait_xsens"
    for t in 1-1 1-2 1-4; do for f in lf rf; do ln -s "$D/ipol_gait_xsens/${t}_$f.txt" "$T/ipnan/ipol_gait_xsens/"; done; done
    sed 's/\[641, 687\]/[641, NaN]/' "$D/ipol_gait_xsens/1-1.json" > "$T/ipnan/ipol_gait_xsens/1-1.json"
    sed 's/"UTurnBoundaries": \[[0-9]*, [0-9]*\]/"UTurnBoundaries": [NaN, NaN]/' "$D/ipol_gait_xsens/1-2.json" > "$T/ipnan/ipol_gait_xsens/1-2.json"
    sed 's/\[[0-9]*, 2580\]\]}$/[NaN, 2580]]}/' "$D/ipol_gait_xsens/1-4.json" > "$T/ipnan/ipol_gait_xsens/1-4.json"
    expect_exit 1 "eval: NaN in ipol events files" "$H" eval --no-experiments --data "$T/ipnan" --out "$T/ipnan.md" --json "$T/ipnan.json"
    if [ "$(grep -c "^| 1-1 | \(left\|right\) | - |.*| not run: LeftFootEvents\[1\] is not a pair of sample indices |" "$T/ipnan.md")" -eq 2 ] &&
        [ "$(grep -c "^| 1-2 | \(left\|right\) | - |.*| not run: the events file's UTurnBoundaries is not a pair of sample indices |" "$T/ipnan.md")" -eq 2 ] &&
        [ "$(grep -c "^| 1-4 | \(left\|right\) | - |.*| not run: RightFootEvents\[[0-9]*\] is not a pair of sample indices |" "$T/ipnan.md")" -eq 2 ] &&
        json "$T/ipnan.json" 'j["failed_runs"] == 6'; then
        pass "an unknown event or U-turn boundary fails its trial, named"; else fail "ipol NaN: $(grep '^| 1-' "$T/ipnan.md")"; fi
else
    echo "skip shared-data checks (no ../shared/data; set FNAV_DATA_DIR)"
fi

# --- the bias-model experiment compares pairs that differ only in the model
# (not one "off" run, with the generic profile's white noise, against every
# table), walk by walk with the spread and a sign test
if [ -n "$D" ] && [ -f "$D/xio_ngimu_gait/short_walk.csv" ]; then
    mkdir -p "$T/bx/xio_ngimu_gait"
    ln -s "$(cd "$D" && pwd)/xio_ngimu_gait/short_walk.csv" "$T/bx/xio_ngimu_gait/short_walk.csv"
    expect_exit 0 "eval with experiments on one xio walk" "$H" eval --data "$T/bx" --out "$T/bx.md"
    if grep -q "| data set | figure | navchip off | navchip ar1 | mtx off | mtx ar1 | shimmer off | shimmer ar1 | generic MEMS off | generic MEMS ar1 |" "$T/bx.md"; then
        pass "experiment 1: an off and an ar1 column per profile"; else fail "experiment 1 columns: $(grep '^| data set' "$T/bx.md" | head -1)"; fi
    # run outside the repository root: the default's pair is kept (the
    # generic profile was read from docs/profiles/ by a relative path, and
    # its two columns were dropped with a warning only)
    HA=$(cd "$(dirname "$H")" && pwd)/$(basename "$H")
    (cd "$T" && "$HA" eval --data "$T/bx" --out "$T/bx2.md" --no-plots > /dev/null 2> "$T/bx2.err")
    if grep -q "| generic MEMS off | generic MEMS ar1 |$" "$T/bx2.md" && ! grep -q "cannot open profile" "$T/bx2.err" &&
        [ "$(grep '^| xio short_walk.csv | 3-D closure (m) |' "$T/bx2.md")" = "$(grep '^| xio short_walk.csv | 3-D closure (m) |' "$T/bx.md")" ]; then
        pass "experiment 1 outside the repository root: the same columns and figures"
    else fail "experiment 1 from $T: $(grep '^| data set' "$T/bx2.md" | head -1) $(cat "$T/bx2.err" | grep warn)"; fi
    row=$(grep "^| xio short_walk.csv | 3-D closure (m) |" "$T/bx.md" | head -1)
    mtxoff=$("$H" replay "$T/bx/xio_ngimu_gait/short_walk.csv" --bias-model off --profile mtx --json - --quiet 2>/dev/null |
        sed -n 's/.*"return_error_3d_m":[[:space:]]*\([0-9.]*\).*/\1/p')
    want=$(printf "%.3f" "$mtxoff")
    got=$(echo "$row" | awk -F'|' '{ gsub(/ /, "", $6); print $6 }')
    if [ "$got" = "$want" ]; then pass "mtx off = replay --bias-model off --profile mtx ($got m)"; else fail "mtx off column $got, replay $want ($row)"; fi
    if grep -q "^| generic MEMS | xio 3-D closure (m) | 1 | [01] of 1 | [-+]0\.[0-9]* \[[-+]0\.[0-9]*, [-+]0\.[0-9]*\] | 1\.000 |" "$T/bx.md"; then
        pass "experiment 1: paired per-walk differences with range and sign test"
    else fail "experiment 1 paired row: $(grep '^| generic MEMS |' "$T/bx.md")"; fi
else
    echo "skip the bias-model experiment (xio_ngimu_gait/short_walk.csv not in the shared data)"
fi

# --- a reader's warning or note about a walk is printed once per eval, not
# by each of the walk's eleven runs (the table's and the experiments'
# repeats): a gx2 walk cut off mid-line must not print its "last line is
# incomplete" 11 times, nor each walk its timer-restart note
if [ -n "$D" ] && [ -f "$D/openshoe_gx2/Measurement_100521_31_data_inert.txt" ]; then
    mkdir -p "$T/rw/openshoe_gx2"
    ln -s "$(cd "$D" && pwd)/openshoe_gx2/Measurement_100521_31_data_inert.txt" "$T/rw/openshoe_gx2/"
    "$H" eval --data "$T/rw" --out "$T/rw.md" --no-plots > /dev/null 2> "$T/rw.err"
    nw=$(grep -c "Measurement_100521_31_data_inert.txt:16790: last line is incomplete" "$T/rw.err")
    nn=$(grep -c "note: .*Measurement_100521_31_data_inert.txt: the sensor's timer restarted" "$T/rw.err")
    dup=$(grep -E "warning:|note:" "$T/rw.err" | sort | uniq -d | head -1)
    if [ "$nw" -eq 1 ] && [ "$nn" -eq 1 ] && [ -z "$dup" ] &&
        grep -q "note: .* repeated by the walks' later runs, printed once" "$T/rw.err"; then
        pass "a walk's reader warning and note printed once per eval, the repeats counted"
    else fail "repeated reader messages: warning $nw times, note $nn times, repeated: $dup"; fi
else
    echo "skip the repeated reader warnings (openshoe_gx2 walk 31 not in the shared data)"
fi

# --- a figures' directory whose name has spaces and parentheses: linked as written in results.md, it is no
# Markdown link (a destination ends at a space; the figure is not shown); it is percent-encoded
if [ -n "$D" ]; then
    mkdir -p "$T/sp/xio_ngimu_gait" "$T/sp md"
    ln -s "$D/xio_ngimu_gait/short_walk.csv" "$T/sp/xio_ngimu_gait/short_walk.csv"
    expect_exit 0 "eval --plots in a directory named with spaces" "$H" eval --no-experiments --data "$T/sp" \
        --out "$T/sp md/r.md" --plots "$T/sp md/my figs (1)"
    if grep -q '^!\[xio_ngimu_gait: paths and heights\](my%20figs%20%281%29/eval-xio.png)$' "$T/sp md/r.md" &&
        head -c 8 "$T/sp md/my figs (1)/eval-xio.png" | grep -q PNG; then
        pass "eval: a figure in a directory with spaces is drawn and linked percent-encoded"
    else fail "eval: figure link $(grep -o '^!\[.*' "$T/sp md/r.md")"; fi
    # and one whose name is long (720 bytes, under PATH_MAX): not cut to 599 bytes, with the figures going into a
    # directory of the cut name
    L=$T/$(printf '%0200d' 0)/$(printf '%0200d' 0)/$(printf '%0200d' 0)
    mkdir -p "$L"
    expect_exit 0 "eval --plots in a directory with a long name" "$H" eval --no-experiments --data "$T/sp" \
        --out "$L/r.md" --plots "$L/$(printf '%0100d' 0)"
    head -c 8 "$L/$(printf '%0100d' 0)/eval-xio.png" 2>/dev/null | grep -q PNG &&
        grep -q "^!\[xio_ngimu_gait: paths and heights\]($(printf '%0100d' 0)/eval-xio.png)$" "$L/r.md" &&
        pass "eval: the figure in the long directory, linked" || fail "eval: figure of a long --plots: $(ls "$L")"
fi

# --- the strides' figure: its title and key as one line would be wider than a picture of three panels (the
# footprints' figure cut both ends off, "circles: the truth there" among them) and far wider than one panel's; each
# line of the title fits the picture, at 6 px a character (a stand-in gnuplot keeps the script)
# footprint_walk DIR N: DIR made a data directory that holds footprint walk N alone (its IMU log and
# strides), linked from the shared data; P set to its footprints directory
footprint_walk() {
    P="$1/pyshoe_vicon_llio/own_3dmgx5_footprints"
    mkdir -p "$P"
    for f in imu strides_gcp; do
        ln -s "$D/pyshoe_vicon_llio/own_3dmgx5_footprints/SensorConnectData_$2_$f.csv" "$P/SensorConnectData_$2_$f.csv"
    done
}
if [ -n "$D" ]; then
    footprint_walk "$T/one" 31
    fake_gnuplot "$T/fakegp"
    PATH="$T/fakegp:$PATH" GP_SCRIPT="$T/strides.gp" "$H" eval --no-experiments --data "$T/one" --out "$T/one.md" \
        >/dev/null 2>&1
    if awk '/^set terminal/ { split($5, wh, ","); w = wh[1] }
            /^set multiplot/ { t = $0; sub(/^[^\x27]*\x27/, "", t); sub(/\x27$/, "", t); n = split(t, line, /\x27\."\\n"\.\x27/)
                               for (i = 1; i <= n; i++) { if (6 * length(line[i]) > w) bad = 1 }; seen = 1 }
            END { exit !(seen && w > 0 && !bad) }' "$T/strides.gp"; then
        pass "eval strides figure: each title line fits the picture"
    else fail "eval strides figure: title wider than the picture: $(grep -E '^set (terminal|multiplot)' "$T/strides.gp")"; fi
fi

# --- the figures of the per-stride table, from an independent computation:
# scripts/eval_stride_ref.py recomputes with numpy, from the walk's truth and
# the trajectory of `harness replay --out` (the same navigation), the strides,
# the measured path (sum of the truth's stride-to-stride distances), the
# median stride error (of 24: the mean of the middle two), the RMS, the final
# error and its share of the path. Without this comparison the path from the
# first stride instead of the one before, a truth y with the wrong sign, the
# final % of the median error, a median of an even count that takes the
# upper middle value, would all pass
if [ -n "$D" ]; then
    footprint_walk "$T/fpref" 34
    expect_exit 0 "eval: one footprint walk" "$H" eval --no-experiments --no-plots --data "$T/fpref" --out "$T/fpref.md"
    expect_exit 0 "replay: the same walk" "$H" replay "$P/SensorConnectData_34_imu.csv" --out "$T/fp34.csv" --quiet
    if /usr/bin/python3 "$(dirname "$0")/../../scripts/eval_stride_ref.py" "$T/fp34.csv" "$P/SensorConnectData_34_strides_gcp.csv" \
        "$(grep '^| SensorConnectData_34 |' "$T/fpref.md")" >"$T/ref" 2>&1; then
        pass "eval footprints: strides, path, median, RMS, final and final % as numpy computes them"
    else fail "eval footprints against scripts/eval_stride_ref.py: $(cat "$T/ref")"; fi
fi

# --- the return-to-start table of the GX2 walks against
# scripts/eval_closure_ref.py: 3-D = sqrt(horizontal^2 + vertical^2), each
# % = 100 x error / path, vertical up positive as the trajectory's
# -(z_end - z_start), the summary line the median (worst) of the rows. A 3-D
# error without its height part, a vertical with the wrong sign and a
# "median 3-D" taken of the horizontal % would otherwise pass every test
if [ -n "$D" ]; then
    G="$T/gxref/openshoe_gx2"
    mkdir -p "$G"
    for w in 2 3 30 32; do ln -s "$D/openshoe_gx2/Measurement_100521_${w}_data_inert.txt" "$G/"; done
    expect_exit 0 "eval: four GX2 walks" "$H" eval --no-experiments --no-plots --data "$T/gxref" --out "$T/gxref.md"
    expect_exit 0 "replay: GX2 walk 2" "$H" replay "$G/Measurement_100521_2_data_inert.txt" --out "$T/g2.csv" --quiet
    if /usr/bin/python3 "$(dirname "$0")/../../scripts/eval_closure_ref.py" "$T/gxref.md" "Measurement_100521_2=$T/g2.csv" \
        >"$T/ref" 2>&1; then
        pass "eval GX2 closure: 3-D, %, vertical sign and the summary's medians consistent"
    else fail "eval GX2 closure against scripts/eval_closure_ref.py: $(cat "$T/ref")"; fi
fi

# --- scripts/probe_slow_ipol.py: the ipol events mapped to a slowed copy's
# packets (round(p / s), halves up, NaN kept, other keys kept), and with the
# shared data the copy at s = 1 (the packet grid from packet 0, dropped
# packets interpolated, written in the ipol format into an ipol-only data
# folder) scored by eval as the original files are, row by row
# (docs/harness.md, "Slow walking, real walks played slower")
PS="$(dirname "$0")/../../scripts/probe_slow_ipol.py"
expect_exit 0 "probe_slow_ipol.py --selftest: the event mapping" /usr/bin/python3 "$PS" --selftest
if [ -n "$D" ] && [ -d "$D/ipol_gait_xsens" ]; then
    if HARNESS="$H" DATA="$D" /usr/bin/python3 "$PS" --factors 1 --tmp "$T/pslow" >"$T/pslow.txt" 2>"$T/pslow.err" &&
        grep -q "^Check at s = 1 .*: the same ipol summary" "$T/pslow.txt" &&
        grep -q "^  per trial and foot: every one of the 28 rows the same" "$T/pslow.txt"; then
        pass "probe_slow_ipol.py at s = 1: eval on the copies as on the originals"
    else fail "probe_slow_ipol.py at s = 1: $(grep -A3 '^Check' "$T/pslow.txt") $(tail -3 "$T/pslow.err")"; fi
fi
# --param KEY=VALUE goes to eval (the originals' and the copies') and to the
# replays that explain the misses: min_swing_s=0.6 misses strides at s = 1
# (first and last steps), the originals' figures then differ from
# docs/results.md, and replay's matching agrees with eval's on every row
expect_exit 1 "probe_slow_ipol.py --param without =" /usr/bin/python3 "$PS" --param min_swing_s
expect_err "takes KEY=VALUE" "probe_slow_ipol.py --param without =: says what it takes"
if [ -n "$D" ] && [ -d "$D/ipol_gait_xsens" ]; then
    if HARNESS="$H" DATA="$D" /usr/bin/python3 "$PS" --factors 1 --param min_swing_s=0.6 >"$T/pslowp.txt" \
        2>"$T/pslowp.err" && grep -q "^Settings (eval and replay): --param min_swing_s=0.6$" "$T/pslowp.txt" &&
        grep -q "^Reference, eval on the original files: 28 trials and feet, 458 expert strides, [0-9]* detected, [1-9][0-9]* missed" \
            "$T/pslowp.txt" &&
        grep -q "eval on the originals now (with the --param settings): DIFFERENT$" "$T/pslowp.txt" &&
        grep -q "replay matched" "$T/pslowp.txt" && ! grep -q "replay matched.*DIFFERENT" "$T/pslowp.txt"; then
        pass "probe_slow_ipol.py --param min_swing_s=0.6: passed to eval and to replay"
    else fail "probe_slow_ipol.py --param: $(head -3 "$T/pslowp.txt") $(tail -3 "$T/pslowp.err")"; fi
fi

# --- a log of another format than CSV with stamps in bursts (pyshoe's t_s, packets of 4 samples 5 us apart every
# 10 ms, as tests/cli/test_bursts.sh builds it): its refusal carries the remedy "convert it to CSV ...", some 390
# bytes past the path, which eval's replay buffer (400 bytes with the path) and a row's note (200) would cut short
# (docs/harness.md, "Time stamps in bursts"). The whole message reaches the warning and the row.
mkdir -p "$T/bursts_in_a_folder_named_at_some_length/openshoe_gx2"
"$H" convert vectors/walk.bin "$T/wb.csv" >/dev/null 2>&1 || fail "bursts: convert vectors/walk.bin"
awk -F, 'NR == 1 { print "t_s,ax_mps2,ay_mps2,az_mps2,gx_radps,gy_radps,gz_radps"; next } { i = NR - 2; printf "%.6f,%s,%s,%s,%s,%s,%s\n", ((int(i / 4) + 1) * 10000 + 5 * (i % 4)) / 1e6, $2, $3, $4, $5, $6, $7 }' \
    "$T/wb.csv" > "$T/bursts_in_a_folder_named_at_some_length/openshoe_gx2/Measurement_2000_1_data_inert.txt"
expect_exit 1 "eval: a non-CSV walk stamped in bursts" "$H" eval --no-experiments --no-plots \
    --data "$T/bursts_in_a_folder_named_at_some_length" --out "$T/bursts.md"
bursts_msg="the time stamps come in bursts (samples stamped close together as a logger reads them?): 1 / their median interval gives 200000 Hz, but the 16539 samples span 41.34 s, 400 Hz; navigation needs each sample's own time: convert it to CSV without the time column (bin/harness convert LOG out.csv; cut -d, -f2- out.csv > in.csv) and give in.csv --input-rate 400 (docs/harness.md, \"Time stamps in bursts\")"
if grep -qxF "harness eval: warning: $T/bursts_in_a_folder_named_at_some_length/openshoe_gx2/Measurement_2000_1_data_inert.txt: $bursts_msg" "$T/err"; then
    pass "bursts: eval's warning carries the whole remedy"; else fail "bursts: warning $(grep warning "$T/err")"; fi
if grep -qxF "| Measurement_2000_1 | - | - | - | - | - | - | - | - | not run: $bursts_msg |" "$T/bursts.md"; then
    pass "bursts: the walk's row carries the whole remedy"; else fail "bursts: row $(grep '^| Measurement' "$T/bursts.md")"; fi

# --- an ipol trial whose logs end before the first expert swing (each cut to 30,000 bytes): no expert swing is
# evaluated, and neither target is judged ("nothing evaluated"; the detection target read "met" on 0 expert
# strides, its JSON ipol_missed 0, the timing line "no expert swing detected")
if [ -n "$D" ]; then
    B="$T/ipolcut"
    mkdir -p "$B/ipol_gait_xsens"
    cp "$D/ipol_gait_xsens/1-1.json" "$B/ipol_gait_xsens/"
    for f in lf rf; do head -c 30000 "$D/ipol_gait_xsens/1-1_$f.txt" >"$B/ipol_gait_xsens/1-1_$f.txt"; done
    expect_exit 0 "eval: ipol logs cut before the first expert swing" "$H" eval --no-experiments --no-plots --data "$B" \
        --out "$T/ipolcut.md" --json "$T/ipolcut.json"
    if grep -q "^| ipol: no missed or spurious strides | no expert swing to evaluate, 0 spurious | nothing evaluated |$" "$T/ipolcut.md" &&
        grep -q "^| ipol: median event timing error <= 2 samples | no expert swing to evaluate | nothing evaluated |$" "$T/ipolcut.md" &&
        grep -q "Event timing: no expert swing to evaluate, no event to time (target <= 2: nothing evaluated)" "$T/ipolcut.md" &&
        ! grep -q "| met |" "$T/ipolcut.md" &&
        json "$T/ipolcut.json" 'j["ipol_missed"] is None and j["ipol_missed_strict"] is None and j["ipol_spurious"] == 0'; then
        pass "no expert swing evaluated: the ipol targets say nothing evaluated, ipol_missed null"
    else fail "ipol with nothing evaluated: $(grep '^| ipol' "$T/ipolcut.md") $(grep -o '"ipol_missed":[^,]*' "$T/ipolcut.json")"; fi
    rm -rf "$B"
else
    echo "SKIP eval with nothing ipol evaluated: no shared data"
fi

# --- a data set folder there but not readable was taken for one that is absent ("No walks found", its targets
# "no data", exit 0, without a word): warned with the reason, a failed run (exit 1), and said in its section.
# A folder's name that is a file (root meets it), and a folder without read permission (as another user:
# root reads any folder)
B="$T/unread"
mkdir -p "$B/openshoe_square2"
still "$B/openshoe_square2/walk.csv"
: >"$B/openshoe_gx2"
expect_exit 1 "eval: a data set folder's name a file" "$H" eval --no-experiments --no-plots --data "$B" --out "$T/unread.md" \
    --json "$T/unread.json"
expect_err "warning: cannot read $B/openshoe_gx2 (Not a directory): its walks are not evaluated" "... warned with the reason"
grep -q "^Cannot read \`$B/openshoe_gx2\` (Not a directory): its walks are not evaluated.$" "$T/unread.md" &&
    ! grep -q "No walks found in \`$B/openshoe_gx2\`" "$T/unread.md" && json "$T/unread.json" 'j["failed_runs"] == 1' &&
    pass "... said in its section, a failed run" || fail "unreadable folder: $(grep -i 'gx2`' "$T/unread.md")"
# its targets "not run (cannot read)", not "no data" (the review's: the section said it, the Targets did not)
[ "$(grep -c '^| openshoe_gx2 .* | - | not run (cannot read) |$' "$T/unread.md")" -eq 3 ] &&
    pass "... its targets not run (cannot read)" || fail "unreadable folder's targets: $(grep '^| openshoe_gx2' "$T/unread.md")"
if [ "$(id -u)" -eq 0 ] && command -v setpriv >/dev/null 2>&1; then
    rm "$B/openshoe_gx2"
    mkdir -p "$B/openshoe_gx2" "$T/unread_out"
    still "$B/openshoe_gx2/Measurement_2000_1_data_inert.txt"
    chmod 000 "$B/openshoe_gx2"
    chmod 755 "$T"; chmod 777 "$T/unread_out"; chmod -R a+rX "$B/openshoe_square2"
    expect_exit 1 "eval as another user: a data set folder without read permission" \
        setpriv --reuid=65534 --regid=65534 --clear-groups "$H" eval --no-experiments --no-plots --data "$B" \
        --out "$T/unread_out/r.md"
    expect_err "warning: cannot read $B/openshoe_gx2 (Permission denied)" "... warned with the reason"
    grep -q "^Cannot read \`$B/openshoe_gx2\` (Permission denied)" "$T/unread_out/r.md" &&
        pass "... said in its section" || fail "folder without permission: $(grep -i 'gx2`' "$T/unread_out/r.md")"
    chmod 755 "$B/openshoe_gx2"
else
    echo "SKIP eval with a data set folder without read permission: needs root and setpriv to run as another user"
fi
rm -rf "$B"

# --- a figures' directory that is there but cannot be written in: found before the run (exit 3), results.md not
# touched (the run went ahead, then each of the six figures said "error: cannot write .../img/eval-gx2.png
# (Permission denied)", exit 0). Run as another user (root writes in any directory)
if [ "$(id -u)" -eq 0 ] && command -v setpriv >/dev/null 2>&1 && command -v gnuplot >/dev/null 2>&1; then
    B="$T/roimg"
    mkdir -p "$B/data/openshoe_gx2" "$B/md/img"
    still "$B/data/openshoe_gx2/Measurement_2000_1_data_inert.txt"
    echo "kept" >"$B/md/r.md"
    chmod 755 "$T"; chmod -R a+rX "$B"; chmod 777 "$B/md"; chmod 666 "$B/md/r.md"; chmod 555 "$B/md/img"
    expect_exit 3 "eval as another user: a figures' directory not writable" \
        setpriv --reuid=65534 --regid=65534 --clear-groups "$H" eval --no-experiments --data "$B/data" --out "$B/md/r.md"
    expect_err "^harness eval: error: cannot write in the figures' directory $B/md/img (Permission denied)$" "... said"
    [ "$(cat "$B/md/r.md")" = "kept" ] && ! grep -q "cannot write .*eval-gx2.png" "$T/err" &&
        pass "... before the run: results.md not touched" || fail "figures' directory not writable: $(head -c 300 "$T/err")"
    chmod 755 "$B/md/img"
    rm -rf "$B"
else
    echo "SKIP eval with a figures' directory not writable: needs root, setpriv and gnuplot to run as another user"
fi

# --- the command results.md names is the one that ran: the data named by $FNAV_DATA_DIR in front of it (left
# out, the line rerun read ../shared/data), a single-quoted directory quoted; and a command longer than 1,023
# bytes whole (it was cut there without a mark)
B="$T/cmd data'x"
mkdir -p "$B/openshoe_gx2"
still "$B/openshoe_gx2/Measurement_2000_1_data_inert.txt"
FNAV_DATA_DIR="$B" "$H" eval --no-experiments --no-plots --out "$T/cmd.md" >/dev/null 2>&1
[ "$(sed -n 3p "$T/cmd.md")" = "Written by \`FNAV_DATA_DIR='$T/cmd data'\\''x' ./bin/harness eval --no-experiments --no-plots --out $T/cmd.md\` (float32 build). Every number below comes from that command;" ] ||
    [ "$(sed -n 3p "$T/cmd.md")" = "Written by \`FNAV_DATA_DIR='$T/cmd data'\\''x' ./bin/harness eval --no-experiments --no-plots --out $T/cmd.md\` (float64 build). Every number below comes from that command;" ] &&
    pass "eval with \$FNAV_DATA_DIR: the command named with it" || fail "FNAV_DATA_DIR command: $(sed -n 3p "$T/cmd.md")"
FNAV_DATA_DIR="$B" "$H" eval --no-experiments --no-plots --data "$B" --out "$T/cmd2.md" >/dev/null 2>&1
grep -q "^Written by \`./bin/harness eval --no-experiments --no-plots --data '$T/cmd data'" "$T/cmd2.md" &&
    pass "... not when --data named the data" || fail "--data over FNAV_DATA_DIR: $(sed -n 3p "$T/cmd2.md")"
J="$T$(printf '/.%.0s' $(seq 600))/cmd.json"
"$H" eval --no-experiments --no-plots --data "$B" --out "$T/cmd3.md" --json "$J" >/dev/null 2>&1
grep -qF -- "--json $J\` (float" "$T/cmd3.md" && pass "a command of over 1,023 bytes named whole" ||
    fail "long command: $(sed -n 3p "$T/cmd3.md" | tail -c 100)"
rm -rf "$B"

# --- a data set found whose runs all failed: its targets read "not run (failed)", not "no data" as if absent;
# and a data directory without a MANIFEST.md is not said to have one ("Data: `DIR` (MANIFEST.md)")
B="$T/failset"
mkdir -p "$B/xio_ngimu_gait"
head -c 5000 /dev/urandom >"$B/xio_ngimu_gait/short_walk.csv"
expect_exit 1 "eval: xio's short walk unreadable" "$H" eval --no-experiments --no-plots --data "$B" --out "$T/failset.md"
grep -q "^| xio short 3-D < 82 mm | - | not run (failed) |$" "$T/failset.md" &&
    grep -q "^| xio long 3-D < 421 mm | - | no data |$" "$T/failset.md" &&
    pass "a set found whose run failed: not run (failed); one absent: no data" ||
    fail "failed set's target: $(grep '^| xio' "$T/failset.md")"
grep -q "Data: \`$B\` (no MANIFEST.md)" "$T/failset.md" && pass "no MANIFEST.md: said" ||
    fail "no MANIFEST.md: $(grep -o 'Data: [^.]*' "$T/failset.md")"
rm -rf "$B"

# --- a data directory whose name holds backticks: each path is one Markdown code span, delimited by more
# backticks than any run inside, padded where it ends with one (a single backtick ended the span at the
# name's own backtick)
B="$T/tick\`s\`\`"
mkdir -p "$B/openshoe_gx2"
still "$B/openshoe_gx2/Measurement_2000_1_data_inert.txt"
"$H" eval --no-experiments --no-plots --data "$B" --out "$T/tick.md" >/dev/null 2>&1
grep -qF "Data: \`\`\` $B \`\`\` (no MANIFEST.md)" "$T/tick.md" &&
    grep -qF "No walks found in \`\`\`$B/xio_ngimu_gait\`\`\`." "$T/tick.md" &&
    grep -q "^Written by \`\`\`\./bin/harness eval .*\`\`\` (float" "$T/tick.md" &&
    pass "a data path with backticks: one code span each" ||
    fail "backticks in the data path: $(sed -n 3p "$T/tick.md"; grep -F 'xio_ngimu_gait' "$T/tick.md" | head -1)"
rm -rf "$B"

# --- the threshold detector named with its limits, as replay's config line (it read "(adaptive threshold)", the
# SHOE's words)
B="$T/thr"
mkdir -p "$B/openshoe_gx2"
still "$B/openshoe_gx2/Measurement_2000_1_data_inert.txt"
"$H" eval --no-experiments --no-plots --data "$B" --detector threshold --out "$T/thr.md" >/dev/null 2>&1
grep -qF 'detector `threshold` (window RMS |w| < 34.38 deg/s and ||f| - g| < 0.6 m/s^2, adaptive limits), lever' "$T/thr.md" &&
    pass "eval --detector threshold: its limits named" || fail "threshold label: $(sed -n 4p "$T/thr.md" | head -c 300)"
rm -rf "$B"

echo "test_eval_data: $fails failure(s)"
[ "$fails" -eq 0 ]
