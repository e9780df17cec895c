#!/bin/sh
# CLI tests of the remedy for time stamps in bursts, one class of format at a
# time (docs/harness.md, "Time stamps in bursts"): the message names a remedy
# the format allows, and following it to the letter makes replay run (exit 0)
# on a walk stamped in bursts, to the trajectory of the same walk stamped
# evenly. One remedy for every format, "leave the time column out and give
# --input-rate N", would be wrong for most: a .bin has no column to leave out
# and ignores --input-rate, so do the time-stamped importers (pyshoe, ngimu,
# an MT Manager export by SampleTimeFine), and a counter's (ipol) only rescales
# the stamps; a CSV whose time column --columns names meets an error when the
# column is cut.
set -u
H=${HARNESS:-bin/harness}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"

# the walk of vectors/walk.bin (16539 samples, 398 Hz) in packets of 4 samples stamped 5 us apart every 10 ms:
# 400 Hz over the log (as tests/cli/test_replay.sh builds it), and the same walk stamped evenly at 400 Hz, whose
# trajectory each remedy followed must give
expect_exit 0 "convert the walk to CSV" "$H" convert vectors/walk.bin "$T/w.csv"
awk -F, 'NR == 1 { print; next } { i = NR - 2; printf "%d,%s,%s,%s,%s,%s,%s\n", (int(i / 4) + 1) * 10000 + 5 * (i % 4), $2, $3, $4, $5, $6, $7 }' \
    "$T/w.csv" > "$T/burst_us.csv"
awk -F, 'NR == 1 { print; next } { printf "%.4f,%s,%s,%s,%s,%s,%s\n", (NR - 2) / 400, $2, $3, $4, $5, $6, $7 }' \
    "$T/w.csv" > "$T/even.csv"
expect_exit 0 "the walk stamped evenly at 400 Hz" "$H" replay "$T/even.csv" --quiet --out "$T/even_traj.csv"
cause="the time stamps come in bursts (samples stamped close together as a logger reads them?): 1 / their median interval gives"
convert_fix="convert it to CSV without the time column (bin/harness convert LOG out.csv; cut -d, -f2- out.csv > in.csv) and give in.csv --input-rate 400 (docs/harness.md, \"Time stamps in bursts\")"

# follow_convert NAME LOG: the remedy of a format other than CSV followed to the letter, with LOG for LOG (in the
# log's directory, as a user would): bin/harness convert LOG out.csv; cut -d, -f2- out.csv > in.csv; replay in.csv
# --input-rate 400, exit 0, to the evenly stamped walk's trajectory
follow_convert() {
    mkdir -p "$T/$1" && cp "$2" "$T/$1/" && log=$(basename "$2")
    (cd "$T/$1" && "$H" convert "$log" out.csv >/dev/null 2>&1 && cut -d, -f2- out.csv > in.csv) ||
        fail "$1: the remedy's convert and cut"
    expect_exit 0 "$1: the remedy followed, replay in.csv --input-rate 400" "$H" replay "$T/$1/in.csv" --quiet \
        --input-rate 400 --out "$T/$1/traj.csv"
    cmp -s "$T/$1/traj.csv" "$T/even_traj.csv" && pass "$1: the remedy gives the evenly stamped walk's trajectory" ||
        fail "$1: the remedy's trajectory differs from the evenly stamped walk's"
}

# 1. the interchange CSV: its time column is left out (cut -d, -f2-), as before
expect_exit 1 "csv: stamps in bursts refused" "$H" replay "$T/burst_us.csv" --quiet --units time=us --out "$T/x.csv"
expect_err "$cause 200000 Hz, but the 16539 samples span 41.34 s, 400 Hz; navigation needs each sample's own time: leave the time column out and give --input-rate 400 (docs/harness.md, \"Time stamps in bursts\")" \
    "csv: the remedy names the time column and --input-rate 400"
cut -d, -f2- "$T/burst_us.csv" > "$T/csv_not.csv"
expect_exit 0 "csv: the remedy followed" "$H" replay "$T/csv_not.csv" --quiet --input-rate 400 --out "$T/csv_traj.csv"
cmp -s "$T/csv_traj.csv" "$T/even_traj.csv" && pass "csv: the remedy gives the evenly stamped walk's trajectory" ||
    fail "csv: the remedy's trajectory differs from the evenly stamped walk's"

# 2. a CSV whose time column --columns names (a Movella DOT-like CSV, SampleTimeFine in us, Gyr_* in deg/s,
# docs/log-format.md "MT Manager export"): the remedy names the --columns item to drop; the column cut from the
# file with t= kept is an error (exit 1), as a one-size remedy ("leave the time column out") followed to the letter
# would have it
awk -F, 'NR > 1 { i = NR - 2; printf "%d,%d,0.1,0.2,0.3,%s,%s,%s,%.9g,%.9g,%.9g\n", i, 12345678 + (int(i / 4) + 1) * 10000 + 5 * (i % 4), $2, $3, $4, $5 * 57.29577951308232, $6 * 57.29577951308232, $7 * 57.29577951308232 }
    BEGIN { print "PacketCounter,SampleTimeFine,Euler_X,Euler_Y,Euler_Z,Acc_X,Acc_Y,Acc_Z,Gyr_X,Gyr_Y,Gyr_Z" }' "$T/w.csv" > "$T/dot.csv"
ch="ax=Acc_X,ay=Acc_Y,az=Acc_Z,gx=Gyr_X,gy=Gyr_Y,gz=Gyr_Z"
expect_exit 1 "dot csv: stamps in bursts refused" "$H" replay "$T/dot.csv" --quiet --from csv --columns "t=SampleTimeFine,$ch" \
    --units time=us,gyro=deg/s --out "$T/x.csv"
expect_err "400 Hz; navigation needs each sample's own time: leave the time column out (drop t=SampleTimeFine from --columns) and give --input-rate 400 (docs/harness.md" \
    "dot csv: the remedy names the --columns item to drop"
cut -d, -f1,3- "$T/dot.csv" > "$T/dot_cut.csv"
expect_exit 1 "dot csv: the column cut, t= kept: an error" "$H" replay "$T/dot_cut.csv" --quiet --from csv \
    --columns "t=SampleTimeFine,$ch" --units gyro=deg/s --input-rate 400 --out "$T/x.csv"
expect_exit 0 "dot csv: the remedy followed (t= dropped, --input-rate 400)" "$H" replay "$T/dot.csv" --quiet --from csv \
    --columns "$ch" --units time=us,gyro=deg/s --input-rate 400 --out "$T/dot_traj.csv" --json "$T/dot.json"
expect_exit 0 "the evenly stamped walk, JSON" "$H" replay "$T/even.csv" --quiet --out /dev/null --json "$T/even.json"
# deg/s written with 9 digits moves the float32 rates by an ulp: the same strides, not the same bytes
json "$T/dot.json" 'j["strides"] == json.load(open(sys.argv[1].replace("dot.json", "even.json")))["strides"] and j["strides"] > 0' &&
    pass "dot csv: the remedy navigates the evenly stamped walk's strides" || fail "dot csv: strides differ from the evenly stamped walk's"

# 3. the .bin: no time column, --input-rate ignored (said), so the old remedy left it refused
expect_exit 0 "bin: the bursts as a .bin" "$H" convert "$T/burst_us.csv" "$T/burst.bin" --units time=us
expect_exit 1 "bin: stamps in bursts refused" "$H" replay "$T/burst.bin" --quiet --out "$T/x.csv"
expect_err "burst.bin: $cause 200000 Hz, but the 16539 samples span 41.34 s, 400 Hz; navigation needs each sample's own time: $convert_fix" \
    "bin: the remedy names the conversion to CSV without the time column"
expect_exit 1 "bin: --input-rate 400 alone (the old remedy) still refused" "$H" replay "$T/burst.bin" --quiet --input-rate 400 --out "$T/x.csv"
follow_convert bin "$T/burst.bin"
# info, psd and allan warn with the same remedy; a .bin header's rate the span does not keep (50 Hz) names it too
expect_exit 0 "bin: info warns" "$H" info "$T/burst.bin"
expect_err "the rate line gives 2e+05 Hz, the stamps' rate, not the sampling rate: $convert_fix" "bin: info's warning names the conversion"
bin_rate "$T/burst.bin" "$T/burst50.bin" 50
expect_exit 0 "bin at a stated 50 Hz: psd warns" "$H" psd "$T/burst50.bin" --out "$T/psd.csv"
expect_err "the frequencies are read at 50 Hz, the rate the file states, which the samples' span does not keep: $convert_fix" \
    "bin at a stated 50 Hz: psd's warning names the conversion"
# ... and --rate's resampler refuses it with the same remedy
expect_exit 1 "bin: --rate 100 refused" "$H" replay "$T/burst.bin" --quiet --rate 100 --out "$T/x.csv"
expect_err "resampling needs each sample's own time: convert it to CSV without the time column (bin/harness convert LOG out.csv; cut -d, -f2- out.csv > in.csv) and give in.csv --input-rate 400 (docs/harness.md, \"Resampling (--rate HZ)\")" \
    "bin: --rate's refusal names the conversion"

# 4. a time-stamped importer (pyshoe: t_s, m/s^2, rad/s): --input-rate ignored, as for the .bin
awk -F, 'NR == 1 { print "t_s,ax_mps2,ay_mps2,az_mps2,gx_radps,gy_radps,gz_radps"; next } { i = NR - 2; printf "%.6f,%s,%s,%s,%s,%s,%s\n", ((int(i / 4) + 1) * 10000 + 5 * (i % 4)) / 1e6, $2, $3, $4, $5, $6, $7 }' \
    "$T/w.csv" > "$T/py.csv"
expect_exit 1 "pyshoe: stamps in bursts refused" "$H" replay "$T/py.csv" --quiet --out "$T/x.csv"
expect_err "py.csv: $cause 200000 Hz, but the 16539 samples span 41.34 s, 400 Hz; navigation needs each sample's own time: $convert_fix" \
    "pyshoe: the remedy names the conversion to CSV without the time column"
expect_exit 1 "pyshoe: --input-rate 400 alone still refused" "$H" replay "$T/py.csv" --quiet --input-rate 400 --out "$T/x.csv"
follow_convert pyshoe "$T/py.csv"

# 5. an MT Manager export timed by SampleTimeFine (100 us ticks: packets of 4 one tick apart every 10 ms)
awk -F, 'BEGIN { OFS = "\t"; print "// MT Manager version: 2022.2.0"; print "PacketCounter", "SampleTimeFine", "Acc_X", "Acc_Y", "Acc_Z", "Gyr_X", "Gyr_Y", "Gyr_Z" }
    NR > 1 { i = NR - 2; print i, 1000 + (int(i / 4) + 1) * 100 + (i % 4), $2, $3, $4, $5, $6, $7 }' "$T/w.csv" > "$T/mt.txt"
expect_exit 1 "mtmanager: stamps in bursts refused" "$H" replay "$T/mt.txt" --quiet --out "$T/x.csv"
expect_err "mt.txt: $cause 10000 Hz, but the 16539 samples span 41.34 s, 400 Hz; navigation needs each sample's own time: $convert_fix" \
    "mtmanager: the remedy names the conversion to CSV without the time column"
expect_exit 1 "mtmanager: --input-rate 400 alone still refused" "$H" replay "$T/mt.txt" --quiet --input-rate 400 --out "$T/x.csv"
follow_convert mtmanager "$T/mt.txt"

# 6. a counter's format (ipol: PacketCounter / the stated rate) with 4 samples to each counter value: the stamps
# shared, which replay navigates with the coarse-stamps note and info warns of; --input-rate 400 only rescales
# the counter (the bursts stay, 1600 Hz over the span)
awk -F, 'BEGIN { OFS = "\t"; print "Acquisition frequency: 100 Hz"; print "PacketCounter", "Acc_X", "Acc_Y", "Acc_Z", "Gyr_X", "Gyr_Y", "Gyr_Z" }
    NR > 1 { i = NR - 2; print int(i / 4), $2, $3, $4, $5, $6, $7 }' "$T/w.csv" > "$T/ip.txt"
expect_exit 0 "ipol: info on a counter shared by 4 samples" "$H" info "$T/ip.txt"
expect_err "ip.txt: the time stamps come in bursts (samples that share one stamp: one per packet, or stamps coarser than the sampling?): 1 / their median interval gives 100 Hz, but the 16539 samples span 41.34 s, 400 Hz; the rate line gives 100 Hz, the rate the file states, which the samples' span does not keep: $convert_fix" \
    "ipol: info's warning names the conversion to CSV without the time column"
expect_exit 0 "ipol: info --input-rate 400 (the old remedy)" "$H" info "$T/ip.txt" --input-rate 400
expect_err "samples span 10.34 s, 1600 Hz" "ipol: --input-rate 400 rescales the counter, the bursts stay"
expect_exit 0 "ipol: replay navigates one sample of each 4" "$H" replay "$T/ip.txt" --out "$T/x.csv"
expect_out "repeat the time stamp before them .*convert it to CSV without the time column (bin/harness convert LOG out.csv; cut -d, -f2- out.csv > in.csv) and give in.csv the rate with --input-rate HZ" \
    "ipol: replay's coarse-stamps note names the conversion"
follow_convert ipol "$T/ip.txt"
expect_exit 0 "ipol: info on the remedy's CSV" "$H" info "$T/ipol/in.csv" --input-rate 400
grep -q "come in bursts" "$T/err" && fail "ipol: the remedy's CSV still warned of bursts" || pass "ipol: the remedy's CSV, no burst warning"

if [ "$fails" -ne 0 ]; then echo "test_bursts.sh: $fails failure(s)"; exit 1; fi
echo "test_bursts.sh: all passed"
