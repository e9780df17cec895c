#!/bin/sh
# CLI tests of bad input and failed outputs (the rule of docs/harness.md,
# "Exit status": a clear error and a non-zero exit, never a crash; nothing
# already computed is lost): each check fails on the wrong behaviour it
# names.
set -u
H=${HARNESS:-bin/harness}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"

# --- sim: one output that cannot be written leaves the other whole (exit 3,
# "every other output is still written"). If the first failed write stopped
# the simulation, a truth CSV on a full disk would leave the log cut short
# (1,288 bytes of a 10 s walk, a header and a few rows that read as a valid
# log), and a log that could not be written would leave the truth cut short.
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

# --- ipol: the rate of line 1 ("Acquisition frequency: 100 Hz") is a number
# and the unit Hz. Read with sscanf's "%lf", which stops at the first
# character it cannot use, "100 kHz" would read as 100 Hz and "100,5 Hz" as
# 100 Hz (exit 0, every time off), and a rate of 1e-300 Hz would be taken, to
# fail at the second row as "counter ('1.0') is not a whole number in range".
ipol() { # FILE RATE-TEXT: an ipol file of 300 still samples at 100 Hz under line 1 'Acquisition frequency: RATE-TEXT'
    { printf 'Acquisition frequency: %s\n' "$2"
      printf 'PacketCounter\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\n'
      awk 'BEGIN { for (i = 0; i < 300; i++) printf "%d.0\t0.01\t0.02\t9.81\t0.001\t0.002\t0.003\n", i }'; } >"$1"
}
ipol "$T/ok.txt" "100 Hz"
expect_exit 0 "ipol: 'Acquisition frequency: 100 Hz'" "$H" info "$T/ok.txt" --from ipol
expect_out "^rate        100.000 Hz (nominal)" "ipol: the stated 100 Hz read"
ipol "$T/ok2.txt" "1e2hz"
expect_exit 0 "ipol: 'Acquisition frequency: 1e2hz' (any case, blanks and exponent)" "$H" info "$T/ok2.txt" --from ipol
expect_out "^rate        100.000 Hz (nominal)" "ipol: 1e2hz read as 100 Hz"
for bad in "100 kHz" "100,5 Hz" "100" "100 Hz 50" "1e-300 Hz" "0 Hz" "1e6 Hz" "nan Hz" "Hz"; do
    ipol "$T/bad.txt" "$bad"
    expect_exit 1 "ipol: 'Acquisition frequency: $bad' refused" "$H" info "$T/bad.txt" --from ipol
    expect_err "bad.txt:1: expected 'Acquisition frequency: N Hz'" "ipol: '$bad': line 1 named"
done
ipol "$T/comma.txt" "100,5 Hz"
expect_exit 1 "ipol: a decimal comma in the rate" "$H" info "$T/comma.txt" --from ipol
expect_err "a decimal comma" "ipol: the decimal comma said"
# the header line holds numbers: the format named in words that read for
# every format's name ("a ipol log" before)
{ printf 'Acquisition frequency: 100 Hz\n'
  awk 'BEGIN { for (i = 0; i < 300; i++) printf "%d.0\t0.01\t0.02\t9.81\t0.001\t0.002\t0.003\n", i }'; } >"$T/nohdr.txt"
expect_exit 1 "ipol: data where the header belongs" "$H" info "$T/nohdr.txt" --from ipol
# line 2 is not called "the first line" (cli_mutation_sweep.py --seed 100, c0073, c0094)
expect_err "nohdr.txt:2: the line where the header belongs is data, not a header: a log of format ipol starts with its header" \
    "ipol: the missing header said"
ipol "$T/low.txt" "1e-300 Hz"
expect_exit 1 "ipol: a rate of 1e-300 Hz" "$H" info "$T/low.txt" --from ipol
expect_err "1e-300 Hz is outside \[0.001, 1e+06)" "ipol: the rate out of range said"

# --- replay, an input that stops before its first sample: the error does not
# say "(frames before it were written)" with no frame before it (a header-only
# CSV, a .bin header without records, a .bin whose first record is junk).
printf 't,ax,ay,az,gx,gy,gz\n' >"$T/head.csv"
expect_exit 1 "replay of a header without samples" "$H" replay "$T/head.csv" --quiet --out "$T/head_traj.csv"
expect_err "head.csv: no samples (no frame before it: the outputs hold none)" "replay: no frame said for a log without samples"
grep -q "frames before it were written" "$T/err" && fail "replay: 'frames before it were written' with none" \
    || pass "replay: no claim of frames written before the error"
# its rate line: no sample is not "one sample", and the detector, never
# run, has no fallback rate nor window (it read "one sample gives no rate;
# the stance detector took its fallback of 0.0 Hz), detector window 0
# samples"); info says the same (docs/harness.md, "info")
expect_exit 1 "replay of a header without samples, the summary" "$H" replay "$T/head.csv" --out "$T/head_traj.csv"
expect_out "^rate              none (no sample gives no rate)$" "replay: a log without samples has no rate, said as info says it"
printf 't,ax,ay,az,gx,gy,gz\n0,0,0,9.8,0,0,0\n0.01,x,0,9.8,0,0,0\n' >"$T/one.csv"
expect_exit 1 "replay of a log that stops after its first sample" "$H" replay "$T/one.csv" --quiet --out "$T/one_traj.csv"
expect_err "one.csv:3: column 2 ('x') is not a number (frames before it were written)" "replay: frames before the error said"

# --- an output named .gz: footnav writes no gzip. convert and sim write
# OUT.csv.gz as plain CSV and OUT.bin.gz as plain CSV too (a name not ending
# in .bin is CSV), and gzip -d then fails on it, so this must not pass with
# exit 0 without a word: a warning says so (the file is still written, and
# every command reads it by its content).
expect_exit 0 "convert to x.csv.gz" "$H" convert vectors/walk.bin "$T/x.csv.gz"
expect_err "^harness convert: warning: $T/x.csv.gz: written uncompressed (footnav writes no gzip" "convert: an uncompressed .gz said"
expect_exit 0 "convert to x.bin.gz" "$H" convert vectors/walk.bin "$T/x.bin.gz"
expect_err "^harness convert: warning: $T/x.bin.gz: written uncompressed, as CSV" "convert: a CSV named .bin.gz said"
expect_exit 0 "convert to x.bin.gz --to bin" "$H" convert vectors/walk.bin "$T/y.bin.gz" --to bin
expect_err "^harness convert: warning: $T/y.bin.gz: written uncompressed (footnav writes no gzip" "convert --to bin: an uncompressed .gz said"
expect_exit 0 "info reads the uncompressed .bin.gz by its content" "$H" info "$T/y.bin.gz"
expect_out "^format      bin" "info: the .bin.gz is a .bin"
expect_exit 0 "sim to x.csv.gz" "$H" sim --duration 2 --out "$T/s.csv.gz"
expect_err "^harness sim: warning: $T/s.csv.gz: written uncompressed (footnav writes no gzip" "sim: an uncompressed .gz said"
expect_exit 0 "convert to x.csv: no .gz warning" "$H" convert vectors/walk.bin "$T/x.csv"
grep -q "uncompressed" "$T/err" && fail "convert to x.csv warned of a .gz: $(cat "$T/err")" || pass "convert to x.csv: no .gz warning"

# --- a .bin header's text (sensor, axis note, source) with control
# characters: printed raw by info, a sensor name "x<LF>samples 1" would forge
# a line of info's report and an escape sequence reach the terminal. They
# are read as '?', with a warning.
bin_sensor() { # bin_sensor OUT BYTES: vectors/walk.bin with its sensor name BYTES (a Python bytes literal), the header CRC made again
    "${PY:-/usr/bin/python3}" -c 'import ast, struct, sys, zlib
b = bytearray(open("vectors/walk.bin", "rb").read())
b[24:56] = ast.literal_eval(sys.argv[2]).ljust(32, b"\0")
struct.pack_into("<I", b, 188, zlib.crc32(bytes(b[:188])) & 0xffffffff)
open(sys.argv[1], "wb").write(b)' "$1" "$2"
}
bin_sensor "$T/ctl.bin" 'b"x\nsamples     1\x1b[2J"'
expect_exit 0 "info of a .bin whose sensor name holds a newline and an escape" "$H" info "$T/ctl.bin"
expect_out "^sensor      x?samples     1?\[2J$" "info: the control characters shown as '?'"
[ "$(grep -c '^samples' "$T/out")" -eq 1 ] && pass "info: no forged line" || fail "info: a forged line: $(grep '^samples' "$T/out")"
if tr -d '\n' <"$T/out" | grep -q "$(printf '\033')"; then fail "info: an escape character printed"; else pass "info: no escape character printed"; fi
expect_err "ctl.bin: the header's text holds 2 control characters or bytes that are not UTF-8 (read as '?')" \
    "info: the control characters warned of"
# one such byte (a sensor name saved in Latin-1): the warning in the singular ("that is", not "that are")
bin_sensor "$T/l1.bin" 'b"caf\xe9"'
expect_exit 0 "info of a .bin whose sensor name holds a Latin-1 byte" "$H" info "$T/l1.bin"
expect_out "^sensor      caf?$" "info: the Latin-1 byte shown as '?'"
expect_err "l1.bin: the header's text holds 1 control character or byte that is not UTF-8 (read as '?')" \
    "info: one byte warned of in the singular"
printf '// MT Manager\n// ProductCode: MTi\033[31m-1\n// Update Rate: 100Hz\nPacketCounter\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\n1\t0\t0\t9.8\t0\t0\t0\n2\t0\t0\t9.8\t0\t0\t0\n' >"$T/mt.txt"
expect_exit 0 "info of an MT Manager export whose ProductCode holds an escape" "$H" info "$T/mt.txt"
expect_out "^sensor      Xsens MTi?\[31m-1$" "info: the ProductCode's escape shown as '?'"
expect_err "mt.txt: the ProductCode holds control characters or bytes that are not UTF-8 (read as '?')" \
    "info: the ProductCode's control character warned of"
expect_exit 0 "info of vectors/walk.bin: no control-character warning" "$H" info vectors/walk.bin
grep -q "control characters" "$T/err" && fail "vectors/walk.bin warned of control characters" || pass "vectors/walk.bin: no such warning"

# --- a .bin header whose CRC is right but whose rate is outside [0, 1e6]
# (docs/log-format.md, "Header"): a negative rate and a NaN are refused as 2e6
# is (tests/test_log.c), naming the file, exit 1; 0 is "unknown", read (lib.sh's
# bin_rate, which also marks the rate nominal)
bin_rate vectors/walk.bin "$T/rneg.bin" -1
expect_exit 1 "info of a .bin whose header rate is -1 Hz" "$H" info "$T/rneg.bin"
expect_err "rneg.bin: header: sample rate -1 Hz is not in \[0, 1e6\]" "a negative header rate refused, the file named"
bin_rate vectors/walk.bin "$T/rnan.bin" nan
expect_exit 1 "info of a .bin whose header rate is NaN" "$H" info "$T/rnan.bin"
expect_err "rnan.bin: header: sample rate nan Hz is not in \[0, 1e6\]" "a NaN header rate refused"
bin_rate vectors/walk.bin "$T/r0.bin" 0
expect_exit 0 "info of a .bin whose header rate is 0 (unknown)" "$H" info "$T/r0.bin"
expect_out "^rate  *398.3[0-9]* Hz (from the time stamps" "a header rate of 0: the rate from the stamps"

# --- convert --start/--end over an input with a bad line: the error does not
# count the samples read as written ("the 200 samples before it were written"
# when --start 2.5 kept none of them and the output holds its header alone).
awk 'BEGIN { print "t,ax,ay,az,gx,gy,gz"; for (i = 0; i < 300; i++) printf "%.2f,%s,0,9.8,0,0,0\n", i / 100, i == 200 ? "nan" : "0.01" }' >"$T/nan200.csv"
expect_exit 1 "convert --start 2.5 of a log with NaN at 2 s" "$H" convert "$T/nan200.csv" "$T/w0.csv" --start 2.5
expect_err "(the 0 samples of the window before it were written, of 200 read)" "convert: none of the window written, said"
[ "$(wc -l <"$T/w0.csv")" -eq 1 ] && pass "convert: the output holds the header alone" || fail "convert: $(wc -l <"$T/w0.csv") lines written"
expect_exit 1 "convert --start 1 of a log with NaN at 2 s" "$H" convert "$T/nan200.csv" "$T/w1.csv" --start 1
expect_err "(the 100 samples of the window before it were written, of 200 read)" "convert: the window's samples counted"
[ "$(wc -l <"$T/w1.csv")" -eq 101 ] && pass "convert: the 100 samples written" || fail "convert: $(wc -l <"$T/w1.csv") lines written, expected 101"
expect_exit 1 "convert without a window of a log with NaN at 2 s" "$H" convert "$T/nan200.csv" "$T/w2.csv"
expect_err "(the 200 samples before it were written)" "convert: without a window, the samples read are those written"
# a header and no sample: said once, not "no samples (the 0 samples before it were written)" (a mutation sweep)
printf 't,ax,ay,az,gx,gy,gz\n' >"$T/hdr_only.csv"
expect_exit 1 "convert of a log with its header alone" "$H" convert "$T/hdr_only.csv" "$T/w3.csv"
expect_err "hdr_only.csv: no samples (the output holds no sample)$" "convert: no sample read, said without a count of 0"
# a .bin written from an input read up to an error had its END record, so
# that every later reader took it as whole (info exit 0, complete): now it
# is left without END, as a killed writer leaves it, with or without --rate
for r in "" 50; do
    expect_exit 1 "convert to .bin${r:+ --rate $r} of a log with NaN at 2 s" "$H" convert "$T/nan200.csv" "$T/cut$r.bin" ${r:+--rate $r}
    expect_exit 1 "info of that .bin${r:+ (--rate $r)}: incomplete" "$H" info "$T/cut$r.bin" --json "$T/cut$r.json"
    expect_err "truncated: no end record after [0-9]* records (its writer did not finish it: killed, or stopped at an error in its input)" \
        "info: the cut .bin${r:+ (--rate $r)} said to be incomplete"
    json "$T/cut$r.json" 'j["complete"] is False and j["samples"] > 0' && pass "info: complete false${r:+ (--rate $r)}" \
        || fail "info: the cut .bin${r:+ (--rate $r)} read as complete"
done
expect_exit 0 "convert to .bin of a whole log" "$H" convert "$T/nan200.csv" "$T/whole.bin" --end 1.5
expect_exit 0 "info of the window's .bin: complete (END written)" "$H" info "$T/whole.bin"
# with --rate too: a window that ends before the error by the resampler's
# reach (ceil(20 fs / rate) + 1 input samples, 0.41 s at 100 -> 50 Hz) is
# whole (it was cut, exit 1); one that ends within that reach is not
expect_exit 0 "convert --rate 50 --end 1.5 of a log with NaN at 2 s" "$H" convert "$T/nan200.csv" "$T/wr.bin" --end 1.5 --rate 50
expect_exit 0 "info of that .bin: complete (END written)" "$H" info "$T/wr.bin"
expect_exit 1 "convert --rate 50 --end 1.9: the error within the resampler's reach" "$H" convert "$T/nan200.csv" "$T/wr2.bin" --end 1.9 --rate 50
expect_exit 1 "info of that .bin: incomplete" "$H" info "$T/wr2.bin"
# a partial input resampled exited 1 after the reader's warning alone, with
# no error said (without --rate: the error); now a closing error says what
# the output covers, as info's and psd's
expect_exit 1 "convert --rate 50 of a log with NaN at 2 s, to CSV" "$H" convert "$T/nan200.csv" "$T/wr3.csv" --rate 50
expect_err "^harness convert: error: $T/nan200.csv: incomplete input (warned above): the output covers the [0-9]* samples before the error$" \
    "convert --rate: the partial input said as an error, with what the output covers"
# --rate on fewer than 4 samples: the error names the file in replay as in
# convert (replay said "too few samples to resample (3)" alone)
printf 't,ax,ay,az,gx,gy,gz\n0,0,0,9.8,0,0,0\n0.01,0,0,9.8,0,0,0\n0.02,0,0,9.8,0,0,0\n' >"$T/three.csv"
expect_exit 1 "replay --rate of a 3-sample log" "$H" replay "$T/three.csv" --rate 20
expect_err "^harness replay: error: $T/three.csv: too few samples to resample (3)$" "replay --rate: the file named"
expect_exit 1 "convert --rate of a 3-sample log" "$H" convert "$T/three.csv" "$T/three20.csv" --rate 20
expect_err "^harness convert: error: $T/three.csv: too few samples to resample (3)$" "convert --rate: the file named"
# and when the reader stopped early, its error is the cause (replay said
# "too few samples to resample (2)" alone)
printf 't,ax,ay,az,gx,gy,gz\n0,0,0,9.8,0,0,0\n0.01,0,0,9.8,0,0,0\n1,2,x\n0.03,0,0,9.8,0,0,0\n' >"$T/bad3.csv"
expect_exit 1 "replay --rate of a log with a bad line 4" "$H" replay "$T/bad3.csv" --rate 20
expect_err "^harness replay: error: $T/bad3.csv:4: 3 columns, expected at least 7 (only 2 samples read: too few to resample)$" \
    "replay --rate: the bad line named as the cause"

# --- an accelerometer that reads exactly 0 (disabled, or not written by the
# logger): info said "gravity along -x" and "f spreads by inf %" with no
# no-gravity line, and its JSON named the axis "-x"
awk 'BEGIN { print "t,ax,ay,az,gx,gy,gz"; for (i = 0; i < 300; i++) printf "%.2f,0,0,0,0.01,0,0\n", i / 100 }' >"$T/zero.csv"
expect_exit 0 "info of a log whose accelerometer reads 0" "$H" info "$T/zero.csv" --json "$T/zero.json"
expect_out "^at rest     no gravity axis: |f| = 0.0000 m/s^2" "info: no gravity axis named when f is 0"
expect_out "no gravity: f is exactly 0 on every axis in the quietest second" "info: the zero accelerometer named"
if grep -q "inf %\|gravity along" "$T/out"; then fail "info: an axis or an infinite spread for f = 0"; else pass "info: no axis, no infinite spread"; fi
json "$T/zero.json" 'j["gravity_axis"] is None and j["up_axis"] is None and j["gravity_magnitude_mps2"] == 0' \
    && pass "info: the JSON names no gravity axis" || fail "info: the JSON names a gravity axis for f = 0"
expect_exit 0 "info of vectors/walk.bin" "$H" info vectors/walk.bin --json "$T/walkinfo.json"
expect_out "^at rest     gravity along -z (+z up)" "info: the walk's gravity axis still named"
json "$T/walkinfo.json" 'j["gravity_axis"] == "-z" and j["up_axis"] == "+z"' && pass "info: the walk's JSON axes" \
    || fail "info: the walk's JSON axes lost"

# --- a header that names a column it reads twice: the first was read
# without a word ("t,ax,ay,az,gx,gy,gz,ax": the values of the second ax,
# perhaps the one meant, were ignored). A warning names both columns.
awk 'BEGIN { print "t,ax,ay,az,gx,gy,gz,ax"; for (i = 0; i < 300; i++) printf "%.2f,0.01,0.02,9.8,0,0,0,5\n", i / 100 }' >"$T/dupax.csv"
expect_exit 0 "info of a header naming ax twice" "$H" info "$T/dupax.csv"
expect_err "dupax.csv:1: the header names 'ax' twice (columns 2 and 8): column 2 is read" "info: the duplicated name warned of"
awk 'BEGIN { print "t,ax,ay,az,gx,gy,gz,x,x"; for (i = 0; i < 300; i++) printf "%.2f,0.01,0.02,9.8,0,0,0,1,2\n", i / 100 }' >"$T/dupx.csv"
expect_exit 0 "info of a header naming an unread column twice" "$H" info "$T/dupx.csv"
grep -q "twice" "$T/err" && fail "a column not read, named twice, warned of: $(cat "$T/err")" || pass "a column not read may be named twice"

# --- the adis format's names (acc_x_g ... gyro_z_dps) with a time column:
# the data set has none, and its reader read such a log at 100 Hz (a log
# stamped at 200 Hz played at half speed: a walk of "timestamp_ms,acc_x_g,
# ..." replayed to 285 m for 40, exit 0 without a word about the column).
# Detection now takes such a header for another logger's and reads it by its
# stamps, the names matched; --from adis still reads the data set's way and
# names the column it leaves unread.
awk 'BEGIN { print "t,gyro_x_dps,gyro_y_dps,gyro_z_dps,acc_x_g,acc_y_g,acc_z_g"; for (i = 0; i < 400; i++) printf "%.3f,0.1,0.2,0.3,0,0,-1\n", i / 200 }' >"$T/adis_t.csv"
expect_exit 0 "info of an adis-named CSV with a time column" "$H" info "$T/adis_t.csv"
expect_out "^rate        200.000 Hz" "the adis names with a column t: read by the 200 Hz stamps"
expect_err "adis_t.csv: header read as --columns t=t,ax=acc_x_g,ay=acc_y_g,az=acc_z_g,gx=gyro_x_dps,gy=gyro_y_dps,gz=gyro_z_dps --units accel=g,gyro=deg/s (names matched" "info: the names matched said"
expect_out "^peak        |a| 0.00 0.00 1.00 g, |w| 0.1 0.2 0.3 deg/s" "the adis names with a column t: g and deg/s read"
awk 'BEGIN { print "timestamp_ms,acc_x_g,acc_y_g,acc_z_g,gyro_x_dps,gyro_y_dps,gyro_z_dps"; for (i = 0; i < 400; i++) printf "%.1f,0,0,-1,0.1,0.2,0.3\n", i * 5 }' >"$T/adis_ms.csv"
expect_exit 0 "info of an adis-named CSV with a time column in ms" "$H" info "$T/adis_ms.csv"
expect_out "^rate        200.000 Hz" "the adis names with timestamp_ms: read by the 200 Hz stamps"
expect_err "adis_ms.csv: header read as --columns t=timestamp_ms,.* --units time=ms,accel=g,gyro=deg/s" "info: the ms stamps named"
expect_exit 0 "--from adis on the file with a column t" "$H" info "$T/adis_t.csv" --from adis
expect_err "adis_t.csv: the column 't' is not read: the adis format has no time stamps" "--from adis: the time column named"
expect_err "give --from csv --columns t=t,ax=acc_x_g,ay=acc_y_g,az=acc_z_g,gx=gyro_x_dps,gy=gyro_y_dps,gz=gyro_z_dps --units accel=g,gyro=deg/s" "--from adis: how to read it said"
expect_out "^rate        100.000 Hz" "--from adis: the data set's rate"
# any name taken for time is named, not only 't' (the reader looked for 't'
# alone: timestamp_ms went under "no time stamps; assuming ... 100 Hz"),
# with the unit its name gives
expect_exit 0 "--from adis on the file with timestamp_ms" "$H" info "$T/adis_ms.csv" --from adis
expect_err "adis_ms.csv: the column 'timestamp_ms' is not read: the adis format has no time stamps" "--from adis: timestamp_ms named"
expect_err "give --from csv --columns t=timestamp_ms,ax=acc_x_g,.* --units time=ms,accel=g,gyro=deg/s$" "--from adis: its ms unit given"
# the square2 format reads its counter 'sample' at 100 Hz: a time column
# beside it was not read without a word (a 200 Hz log at half speed)
awk 'BEGIN { print "t,sample,f_x_mps2,f_y_mps2,f_z_mps2,w_x_radps,w_y_radps,w_z_radps"; for (i = 0; i < 400; i++) printf "%.3f,%d,0,0,-9.8,0.1,0.2,0.3\n", i / 200, i }' >"$T/sq_t.csv"
expect_exit 0 "info of a square2-named CSV with a time column" "$H" info "$T/sq_t.csv"
expect_err "sq_t.csv: the column 't' is not read: the square2 format has no time stamps (its counter 'sample' is read at 100 Hz" "square2: the time column named"
expect_exit 0 "square2: the remedy followed" "$H" info "$T/sq_t.csv" --from csv --columns t=t,ax=f_x_mps2,ay=f_y_mps2,az=f_z_mps2,gx=w_x_radps,gy=w_y_radps,gz=w_z_radps
expect_out "^rate        200.000 Hz" "square2: the remedy reads the 200 Hz stamps"

# --- an output that cannot be written: the error gives the reason, as
# convert's and sim's do: not only "cannot write DIR" for replay's --out (a
# directory, a missing directory), nor "cannot write FILE" for a JSON that
# fails as it is written (a full disk).
expect_exit 3 "replay --out a directory" "$H" replay vectors/walk.bin --quiet --out "$T"
expect_err "^harness replay: error: cannot write $T (Is a directory)" "replay --out: the reason given"
expect_exit 3 "replay --out in a missing directory" "$H" replay vectors/walk.bin --quiet --out "$T/no/such/t.csv"
expect_err "^harness replay: error: cannot write $T/no/such/t.csv (No such file or directory)" "replay --out: the missing directory said"
if [ -w /dev/full ]; then
    expect_exit 3 "info --json onto a full disk" "$H" info vectors/walk.bin --json /dev/full
    expect_err "^harness info: error: cannot write /dev/full (No space left on device)" "info --json: the reason given"
    expect_out "^samples     16539" "info: the report still printed"
    # simgap-validate's --markdown onto a full disk: exit 3 without a word
    expect_exit 3 "simgap-validate --markdown onto a full disk" "$H" simgap-validate --cases 1 --duration 60 --seeds 4 \
        --quiet --markdown /dev/full
    expect_err "^harness simgap-validate: error: /dev/full: write failed (No space left on device)" \
        "simgap-validate --markdown: the failed write said"
fi
# allan's --out - sends its text to standard error, where it was
# block-buffered: the failed write's error (a closed pipe, a full disk)
# landed inside a table's line ("... LSQ fit oharness allan: error:
# standard output: ..."); now a line at a time, every message starts its line
if [ -w /dev/full ]; then
    sh -c '"$0" allan vectors/walk.bin --no-sim --out - 2>"$1" >/dev/full' "$H" "$T/lb_err"
    if grep -q '.harness allan: ' "$T/lb_err"; then fail "allan --out - onto a full disk: a message inside a line of text"
    elif grep -q '^harness allan: error: standard output: write failed' "$T/lb_err"; then
        pass "allan --out - onto a full disk: the messages on lines of their own"
    else fail "allan --out - onto a full disk: no write error said"; fi
fi
# a file-size limit (ulimit -f) reached: SIGXFSZ killed replay without a
# word (exit 153), its JSON not written; now the write fails (EFBIG), named,
# exit 3, and the JSON written with what was done
expect_exit 3 "replay --out past a file-size limit" sh -c 'ulimit -f 100 && exec "$@"' sh "$H" replay vectors/walk.bin \
    --quiet --out "$T/fsz.csv" --json "$T/fsz.json"
expect_err "^harness replay: error: cannot write the trajectory to $T/fsz.csv (File too large)" "... the limit named"
json "$T/fsz.json" 'j["complete"] is False' && pass "... the JSON written, incomplete" || fail "... no incomplete JSON"

# --- replay of a log whose time stamps come in pairs (intervals of 0.1 ms
# and 9.9 ms by turns: a logger stamping each pair of 200 Hz samples as it
# reads them). info, allan and psd warn of the bursts; replay must not run
# without a word, its stance detector at 101 Hz (1 / the median of its first
# 32 intervals) with a 3-sample window where 200 Hz gives 5. It warns as
# they do, with the detector's rate and the --input-rate remedy.
expect_exit 0 "sim: a 200 Hz walk" "$H" sim --duration 20 --rate 200 --out "$T/w200.csv"
awk -F, 'NR == 1 { print; next } { k = NR - 2; $1 = sprintf("%.4f", int(k / 2) * 0.01 + (k % 2) * 0.0001); print }' OFS=, \
    "$T/w200.csv" >"$T/pairs.csv"
expect_exit 0 "replay of a log stamped in pairs (runs, as before)" "$H" replay "$T/pairs.csv" --quiet
expect_err "^harness replay: warning: $T/pairs.csv: the time stamps come in bursts (.*): 1 / their median interval gives 101.01 Hz, but the 4001 samples span 20 s, 200 Hz; the stance detector takes 101 Hz" "replay: the paired stamps warned of, with the detector's rate"
expect_err "leave the time column out and give --input-rate 200 (docs/harness.md, \"Time stamps in bursts\")" "replay: the remedy info names"
expect_exit 0 "info of the log stamped in pairs" "$H" info "$T/pairs.csv"
expect_err "leave the time column out and give --input-rate 200" "info: the same remedy"
# the stamps are distinct, 0.1 ms apart in each pair: the cause is samples
# stamped close together, not samples sharing one stamp (the median interval
# is the long one, 9.9 ms, as it is for shared stamps)
expect_err "the time stamps come in bursts (samples stamped close together as a logger reads them?): 1 / their median interval gives 101.01 Hz" "info: the paired stamps' cause is close stamping"
cut -d, -f2- "$T/pairs.csv" >"$T/pairs_cut.csv"
expect_exit 0 "replay: the remedy followed" "$H" replay "$T/pairs_cut.csv" --input-rate 200
expect_out "detector window 5 samples" "replay: the remedy gives the 5-sample window of 200 Hz"
grep -q "bursts" "$T/err" && fail "replay: the remedy still warned: $(cat "$T/err")" || pass "replay: no warning once the remedy is followed"
expect_exit 0 "replay of the evenly stamped walk" "$H" replay "$T/w200.csv" --quiet
grep -q "bursts" "$T/err" && fail "replay of an even log warned: $(cat "$T/err")" || pass "replay: no bursts warning on evenly stamped stamps"

# --- a .bin whose header states a rate its stamps contradict (1000 Hz
# stated, stamps 5 ms apart): info must not print the stated rate without a
# word, as its search for the rest takes windows of 1000 samples, 5 s of the
# 200 Hz log. A warning names both rates and the remedy; a stated rate
# within 10 % of the stamps' is not questioned.
expect_exit 0 "convert: the 200 Hz walk as a .bin" "$H" convert "$T/w200.csv" "$T/w200.bin"
bin_rate "$T/w200.bin" "$T/r1000.bin" 1000
expect_exit 0 "info of a .bin stating 1000 Hz over 5 ms stamps (runs, as before)" "$H" info "$T/r1000.bin"
expect_out "^rate        1000.000 Hz (nominal)" "info: the stated rate still printed"
expect_err "^harness info: warning: $T/r1000.bin: the file states 1000 Hz, but its time stamps give 200 Hz (5.000 ms apart)" "info: the contradiction warned of"
expect_err "convert it to CSV (bin/harness convert $T/r1000.bin out.csv), whose rate comes from its stamps" "info: the remedy named"
"$H" convert "$T/r1000.bin" "$T/r1000.csv" 2>/dev/null
expect_exit 0 "info: the remedy followed" "$H" info "$T/r1000.csv"
expect_out "^rate        200.000 Hz (from the time stamps" "info: the converted CSV's rate is the stamps'"
for hz in 200 215; do
    bin_rate "$T/w200.bin" "$T/r$hz.bin" $hz
    expect_exit 0 "info of a .bin stating $hz Hz over 5 ms stamps" "$H" info "$T/r$hz.bin"
    grep -q "file states" "$T/err" && fail "info: $hz Hz stated for 200 Hz stamps warned of: $(cat "$T/err")" || pass "info: $hz Hz stated for 200 Hz stamps (within 10 %) not questioned"
done
expect_exit 0 "info of vectors/walk.bin" "$H" info vectors/walk.bin
grep -q "file states" "$T/err" && fail "info: vectors/walk.bin's rate questioned: $(cat "$T/err")" || pass "info: vectors/walk.bin's rate not questioned"

# --- sim --mount out of range: any number was taken (--mount 1e30,0,0
# simulated a sensor turned by 1e30 degrees, exit 0). Roll and yaw lie in
# [-180, 180] and pitch in [-90, 90], which reach every mounting (ZYX Euler
# angles); beyond, a command-line error as --rate's (exit 2).
for m in 1e30,0,0 0,91,0 0,-90.5,0 0,0,181 -180.01,0,0 0,0,-1e300; do
    expect_exit 2 "sim --mount $m refused" "$H" sim --motion stand:2 --out "$T/m.csv" --mount "$m"
    expect_err "^harness sim: error: --mount '$m': roll, pitch, yaw in degrees within \[-180, 180\], \[-90, 90\], \[-180, 180\]" "sim --mount $m: the ranges said"
done
[ -e "$T/m.csv" ] && fail "sim --mount out of range wrote a log" || pass "sim --mount out of range: no log written"
for m in 180,90,-180 -180,-90,180 0,10,90; do
    expect_exit 0 "sim --mount $m (the range's ends) taken" "$H" sim --motion stand:2 --out "$T/m_ok.csv" --mount "$m"
done

# --- info of a log that holds no sample (a .bin header with no record, one
# closed by its END record, a CSV header alone): the error alone, no report
# and no JSON. Now the report says what the file is and that it holds no
# sample, the JSON says so (samples 0, complete false, the error), exit 1
# (bad or incomplete input: docs/harness.md, "Exit status").
head -c 192 vectors/walk.bin >"$T/hdr.bin"
"${PY:-/usr/bin/python3}" -c 'import struct, sys, zlib
r = bytearray(48)
struct.pack_into("<HHIq", r, 0, 0xA5E0, 0, 0, 0)
struct.pack_into("<I", r, 44, zlib.crc32(bytes(r[:44])) & 0xffffffff)
open(sys.argv[2], "wb").write(open(sys.argv[1], "rb").read(192) + bytes(r))' vectors/walk.bin "$T/closed.bin"
for f in hdr.bin closed.bin head.csv; do
    rm -f "$T/e.json"
    expect_exit 1 "info of $f, no sample" "$H" info "$T/$f" --json "$T/e.json"
    expect_out "^samples     0 (the file holds no sample: nothing to analyse)" "info $f: the empty log said"
    expect_out "^file        $T/$f" "info $f: the file named"
    expect_err "^harness info: error: $T/$f: " "info $f: the reader's error given"
    json "$T/e.json" 'j["samples"] == 0 and j["complete"] is False and len(j["error"]) > 0 and j["rate_change"] is None' \
        && pass "info $f: the JSON says the log is empty" || fail "info $f: no JSON saying the log is empty"
done
# the empty log's JSON comes from info's own writer (not a list of its keys kept by hand): the same keys
# in the same order as a log's that was read in part (both have "error"), and as a whole log's but "error"
head -c 10000 vectors/walk.bin >"$T/part.bin"
expect_exit 1 "info --json of a truncated walk" "$H" info "$T/part.bin" --json "$T/part.json"
expect_exit 0 "info --json of the walk" "$H" info vectors/walk.bin --json "$T/whole.json"
for f in hdr.bin head.csv; do
    expect_exit 1 "info --json of $f, no sample" "$H" info "$T/$f" --json "$T/e.json"
    json "$T/e.json" "list(j) == list(json.load(open('$T/part.json'))) and [k for k in j if k != 'error'] == list(json.load(open('$T/whole.json')))" \
        && pass "info $f: the empty log's JSON has a log's keys" \
        || fail "info $f: the empty log's JSON keys differ from a log's: $(tr -d '\n\t' <"$T/e.json")"
done
expect_out "^format      csv" "info head.csv: its format said"
expect_exit 1 "info of closed.bin (format and sensor)" "$H" info "$T/closed.bin"
expect_out "^sensor      x-io NGIMU" "info closed.bin: the header's sensor said"
expect_err "closed.bin: no samples" "info closed.bin: no samples said"
expect_exit 1 "info of a file that is no log: no report" "$H" info "$T/err" --from bin
[ -s "$T/out" ] && fail "info of a non-log printed a report: $(cat "$T/out")" || pass "info of a non-log: no report, as before"

# --- replay --out of an input with no sample: a 0-byte file, no CSV header
# (the port writes the header with the first frame). It now holds the
# header alone, a valid empty CSV (docs/harness.md, "replay", --out).
expect_exit 0 "replay --out of a walk: the header to compare" "$H" replay vectors/walk.bin --quiet --out "$T/walk_traj.csv"
for f in head.csv hdr.bin closed.bin; do
    rm -f "$T/e_traj.csv"
    expect_exit 1 "replay --out of $f, no sample" "$H" replay "$T/$f" --quiet --out "$T/e_traj.csv"
    [ "$(wc -l <"$T/e_traj.csv")" -eq 1 ] && [ "$(cat "$T/e_traj.csv")" = "$(head -n 1 "$T/walk_traj.csv")" ] \
        && pass "replay $f: --out holds the trajectory CSV's header alone" \
        || fail "replay $f: --out holds $(wc -c <"$T/e_traj.csv") bytes, not the header alone"
done
expect_exit 1 "replay --out - of head.csv" "$H" replay "$T/head.csv" --out -
[ "$(cat "$T/out")" = "$(head -n 1 "$T/walk_traj.csv")" ] && pass "replay --out -: the header alone on standard output" \
    || fail "replay --out -: standard output holds '$(head -c 200 "$T/out")'"

# --- a CSV header whose units are spelled in UTF-8 (docs/log-format.md,
# "Names read without --columns"): the degree sign (U+00B0), the micro
# signs (U+00B5, U+03BC) and superscript two (U+00B2) read as deg, u and 2.
# Otherwise 'gx [°/s]', 'gyr_x(°/s)', 'acc_x [m/s²]' and 't [µs]' would
# match no channel and the file be refused (header has no column 't'); and
# a unit not read ('gx [°/h]', 'ax_µg') is named.
expect_exit 0 "the walk as CSV, for the units' headers" "$H" convert vectors/walk.bin "$T/u_walk.csv"
head -n 401 "$T/u_walk.csv" >"$T/u_ref.csv"
u_hdr() { # FILE HEADER TIME-SCALE GYRO-SCALE: the walk's first 400 samples under HEADER, time and rates multiplied
    { printf '%s\n' "$2"
      awk -F, -v ts="$3" -v gs="$4" 'NR > 1 && NR <= 401 {
          printf "%.17g,%s,%s,%s,%.17g,%.17g,%.17g\n", $1 * ts, $2, $3, $4, $5 * gs, $6 * gs, $7 * gs }' "$T/u_walk.csv"
    } >"$1"
}
DPS=$(awk 'BEGIN { printf "%.17g", 180 / atan2(0, -1) }')
u_hdr "$T/u_deg.csv" 'time [s],acc_x [m/s²],acc_y [m/s²],acc_z [m/s²],gx [°/s],gy [°/s],gz [°/s]' 1 "$DPS"
u_hdr "$T/u_par.csv" 'Time (µs),AccX (m/s²),AccY (m/s²),AccZ (m/s²),gyr_x(°/s),gyr_y(°/s),gyr_z(°/s)' 1000000 "$DPS"
u_hdr "$T/u_mu.csv" 'time_μs,acc_x,acc_y,acc_z,gyro_x_°/s,gyro_y_°/s,gyro_z_°/s' 1000000 "$DPS"
for f in u_deg u_par u_mu; do
    expect_exit 0 "info $f.csv (UTF-8 units)" "$H" info "$T/$f.csv"
    expect_err "header read as --columns .* --units .*gyro=deg/s" "info $f.csv: the header read, the rates in deg/s"
    expect_exit 0 "convert $f.csv" "$H" convert "$T/$f.csv" "$T/$f.out.csv"
    if cmp -s "$T/u_ref.csv" "$T/$f.out.csv"; then pass "$f.csv: the walk's samples, to the float32"
    else fail "$f.csv: read otherwise than the walk's CSV"; fi
done
expect_err "--units time=us,gyro=deg/s" "u_mu.csv: the Greek mu read as micro"
# --units takes the same spellings (time=µs, gyro=°/s: not unknown units, exit 2)
expect_exit 0 "convert with --units time=µs,accel=m/s²,gyro=°/s" "$H" convert "$T/u_par.csv" "$T/u_opt.csv" \
    --columns 't=Time (µs),ax=AccX (m/s²),ay=AccY (m/s²),az=AccZ (m/s²),gx=gyr_x(°/s),gy=gyr_y(°/s),gz=gyr_z(°/s)' \
    --units time=µs,accel=m/s²,gyro=°/s
if cmp -s "$T/u_ref.csv" "$T/u_opt.csv"; then pass "--units in UTF-8: the walk's samples"
else fail "--units in UTF-8: read otherwise than the walk's CSV"; fi
expect_exit 2 "--units gyro=°/h" "$H" info "$T/u_par.csv" --units gyro=°/h
expect_err "gyro=°/h: the rate unit is rad/s, deg/s (dps, °/s) or mdps" "--units gyro=°/h: refused, the value as given"
# --columns alone on names that state their units: read in SI units as
# asked, with a warning naming the column and the --units that reads them
# (not read without a word)
expect_exit 0 "convert with --columns alone over UTF-8 units" "$H" convert "$T/u_deg.csv" "$T/u_col.csv" \
    --columns 't=time [s],ax=acc_x [m/s²],ay=acc_y [m/s²],az=acc_z [m/s²],gx=gx [°/s],gy=gy [°/s],gz=gz [°/s]'
expect_err "u_deg.csv:1: column 5 ('gx \[°/s\]') names deg/s, but the rates are read in rad/s (--units gyro=deg/s reads the column's unit)" \
    "--columns alone: the unit the name states and the --units that reads it"
expect_exit 0 "the same with --units gyro=°/s" "$H" convert "$T/u_deg.csv" "$T/u_col.csv" --units gyro=°/s \
    --columns 't=time [s],ax=acc_x [m/s²],ay=acc_y [m/s²],az=acc_z [m/s²],gx=gx [°/s],gy=gy [°/s],gz=gz [°/s]'
if grep -q "names" "$T/err"; then fail "--columns with the named units: warned ($(cat "$T/err"))"
else pass "--columns with the named units: no warning"; fi
cmp -s "$T/u_ref.csv" "$T/u_col.csv" && pass "--columns with the named units: the walk's samples" \
    || fail "--columns with the named units: read otherwise than the walk's CSV"
# a unit not read: refused, the column, its name and the unit named
u_hdr "$T/u_degh.csv" 't,ax,ay,az,gx [°/h],gy [°/h],gz [°/h]' 1 1
expect_exit 1 "info of gx [°/h]" "$H" info "$T/u_degh.csv"
expect_err "u_degh.csv:1: header has no column 'gx'.*column 5 ('gx \[°/h\]') names a unit not read, '°/h' (a rate's: rad/s, deg/s" \
    "a rate unit not read: the column and the unit named"
# micro-g (µg, μg, ug: 9.80665e-6 m/s^2, the standard g that g and mg are read with) is read, in a header and in
# --units; 'ax_µg' is not refused as 'a unit not read' (exit 1). The walk's accelerations in µg give
# the walk's samples and info's figures; another unit (ng) is still refused, the list naming µg
u_ug() { # FILE HEADER: the walk's first 400 samples under HEADER, the accelerations in micro-g
    { printf '%s\n' "$2"
      awk -F, 'NR > 1 && NR <= 401 { printf "%s,%.17g,%.17g,%.17g,%s,%s,%s\n", $1, $2 / 9.80665e-6, $3 / 9.80665e-6,
          $4 / 9.80665e-6, $5, $6, $7 }' "$T/u_walk.csv"
    } >"$1"
}
expect_exit 0 "info of the walk in m/s^2" "$H" info "$T/u_ref.csv"
grep -v "^file " "$T/out" >"$T/u_ref.info"
u_ug "$T/u_ug.csv" 'time,ax_µg,ay_µg,az_µg,gx,gy,gz'
u_ug "$T/u_ug2.csv" 't,ax [ug],ay [ug],az [ug],gx,gy,gz'
u_ug "$T/u_ug3.csv" 't,acc_x (μg),acc_y (μg),acc_z (μg),gx,gy,gz'
for f in u_ug u_ug2 u_ug3; do
    expect_exit 0 "info of $f.csv (accelerations in micro-g)" "$H" info "$T/$f.csv"
    expect_err "header read as --columns .* --units accel=ug" "info $f.csv: the header read, the accelerations in ug"
    grep -v "^file " "$T/out" | cmp -s - "$T/u_ref.info" && pass "info $f.csv: the figures of the walk in m/s^2" ||
        fail "info $f.csv: figures differ from the walk in m/s^2: $(grep -v '^file ' "$T/out" | diff - "$T/u_ref.info")"
    expect_exit 0 "convert $f.csv" "$H" convert "$T/$f.csv" "$T/$f.out.csv"
    cmp -s "$T/u_ref.csv" "$T/$f.out.csv" && pass "$f.csv: the walk's samples, to the float32" ||
        fail "$f.csv: read otherwise than the walk's CSV"
done
for u in ug µg μg; do
    expect_exit 0 "--units accel=$u" "$H" convert "$T/u_ug.csv" "$T/u_ugopt.csv" --units "accel=$u" \
        --columns 't=time,ax=ax_µg,ay=ay_µg,az=az_µg,gx=gx,gy=gy,gz=gz'
    cmp -s "$T/u_ref.csv" "$T/u_ugopt.csv" && pass "--units accel=$u: the walk's samples" ||
        fail "--units accel=$u: read otherwise than the walk's CSV"
done
expect_exit 2 "--units accel=ng" "$H" info "$T/u_ug.csv" --units accel=ng
expect_err "accel=ng: the acceleration unit is m/s2 (m/s^2, m/s², mps2), g, mg or ug (µg)" "--units accel=ng: the list names ug"
u_ug "$T/u_ng.csv" 'time,ax_ng,ay_ng,az_ng,gx,gy,gz'
expect_exit 1 "info of ax_ng" "$H" info "$T/u_ng.csv"
expect_err "column 2 ('ax_ng') names a unit not read, 'ng' (an acceleration's: m/s^2 or m/s2 or m/s² or mps2, g, mg, ug or µg)" \
    "nano-g (no unit read): the column and the unit named, the list with micro-g"

# after the gzip data: a second gzip member (concatenated .gz files, valid: gunzip reads them whole) is read, and
# bytes that are no gzip member (trailing junk, a block's zero padding) are a warning naming the file and their count,
# the samples those of the gzip data, as gunzip says "decompression OK, trailing garbage ignored". The junk is not
# ignored without a word (as zlib's gzread does); docs/log-format.md, "After the gzip data"
head -n 201 "$T/u_ref.csv" >"$T/z.csv"
gzip -c "$T/z.csv" >"$T/z.csv.gz"
expect_exit 0 "info of the plain CSV" "$H" info "$T/z.csv"
grep -v "^file " "$T/out" >"$T/z.info"
{ head -n 101 "$T/z.csv" | gzip -c; tail -n +102 "$T/z.csv" | gzip -c; } >"$T/zcat.csv.gz"
{ cat "$T/z.csv.gz"; printf 'JUNKJUNK\n'; } >"$T/zjunk.csv.gz"
{ cat "$T/z.csv.gz"; head -c 512 /dev/zero; } >"$T/zpad.csv.gz"
for f in z.csv.gz zcat.csv.gz zjunk.csv.gz zpad.csv.gz; do
    expect_exit 0 "info $f" "$H" info "$T/$f"
    grep -v "^file " "$T/out" | cmp -s - "$T/z.info" && pass "info $f: the 200 samples of the plain CSV" ||
        fail "info $f: not the plain CSV's figures: $(grep -v '^file ' "$T/out" | diff - "$T/z.info" | head -5)"
done
expect_exit 0 "info z.csv.gz (again)" "$H" info "$T/z.csv.gz"
grep -q "after the end of the gzip data" "$T/err" && fail "a clean .gz: warned of bytes after it" || pass "a clean .gz: no warning"
expect_exit 0 "info zcat.csv.gz (again)" "$H" info "$T/zcat.csv.gz"
grep -q "after the end of the gzip data" "$T/err" && fail "two gzip members: the second called junk" ||
    pass "two gzip members: read whole, no warning"
expect_exit 0 "info zjunk.csv.gz (again)" "$H" info "$T/zjunk.csv.gz"
expect_err "^harness info: warning: $T/zjunk.csv.gz: 9 bytes after the end of the gzip data are no gzip member (trailing junk): ignored" \
    "trailing junk after a .gz: a warning with the file and the byte count"
expect_exit 0 "info zpad.csv.gz (again)" "$H" info "$T/zpad.csv.gz"
expect_err "zpad.csv.gz: 512 bytes after the end of the gzip data are no gzip member (zero bytes, padding): ignored" \
    "zero padding after a .gz: a warning with the byte count, said as zeros"
# a .bin.gz the same (its records read by gzread, not by lines)
gzip -c vectors/walk.bin >"$T/zw.bin.gz"
{ cat "$T/zw.bin.gz"; printf 'trailer'; } >"$T/zwjunk.bin.gz"
expect_exit 0 "replay of a .bin.gz with junk after it" "$H" replay "$T/zwjunk.bin.gz" --json "$T/zwjunk.json"
expect_err "zwjunk.bin.gz: 7 bytes after the end of the gzip data are no gzip member (trailing junk): ignored" \
    "trailing junk after a .bin.gz: warned"
expect_exit 0 "replay of the .bin.gz" "$H" replay "$T/zw.bin.gz" --json "$T/zw.json"
json "$T/zwjunk.json" '[j[k] for k in ("duration_s", "distance_m", "strides")] == [json.load(open(sys.argv[1].replace("zwjunk", "zw")))[k] for k in ("duration_s", "distance_m", "strides")] and j["duration_s"] > 0' &&
    pass "a .bin.gz with junk: the samples of the .bin.gz" || fail "a .bin.gz with junk: other samples"

# --- a file of another, binary format given as a log (a plot, a zip): no
# importer's header is found and it is read as CSV, whose error on line 1
# would be "header has no column 't' ... give --from FORMAT for another
# format, or give its names and units with --columns and --units" (a PNG of
# docs/img, exit 1): advice no such file can follow. It is named as binary
# data, neither a .bin nor text (exit 1). So is one given to allan as a
# --series of numbers (the same helper, hx_head_not_text), not
# "plot.png:2: not a number" (its first line taken for a header).
cp "$(ls docs/img/*.png | head -n 1)" "$T/plot.png"
printf 'PK\003\004\024\000\006\000\010\000\000\000!\000' >"$T/book.xlsx"
for f in plot.png book.xlsx; do
    for c in info replay psd "allan --rate 100 --series"; do
        kind=log
        case $c in *--series) kind=series ;; esac
        expect_exit 1 "$c of $f (binary, no $kind)" "$H" $c "$T/$f"
        case $f in
        *.png) expect_err "$f: binary data, not a $kind: " "$c: $f said to be binary data" ;;
        *) expect_err "$f: not a $kind but a ZIP archive (an app's export of several files, or an .xlsx or .ods workbook): unzip it (unzip $T/$f) and give the log inside; a workbook: save its sheet as CSV$" \
            "$c: $f named as a ZIP archive, with what to do" ;;
        esac
        grep -q -- "--columns" "$T/err" && fail "$c: $f: the advice of --columns given" || pass "$c: $f: no --columns advice"
    done
done
# other archives, containers and databases a log may come in, by their
# magic bytes (each format's published signature): named, with what to do
# (before: "binary data" with the bytes, or "a NUL byte" at some line)
"${PY:-/usr/bin/python3}" - "$T" <<'PY' || fail "write the containers"
import bz2, gzip, io, lzma, sys, tarfile, zipfile
T = sys.argv[1]
csv = b't,ax,ay,az,gx,gy,gz\n0,0,0,9.8,0,0,0\n'
with zipfile.ZipFile(T + '/export.zip', 'w') as z:
    z.writestr('walk.csv', csv)
open(T + '/walk.csv.bz2', 'wb').write(bz2.compress(csv))
open(T + '/walk.csv.xz', 'wb').write(lzma.compress(csv))
with tarfile.open(T + '/walk.tar.gz', 'w:gz') as t:
    info = tarfile.TarInfo('walk.csv'); info.size = len(csv); t.addfile(info, io.BytesIO(csv))
open(T + '/walk.h5', 'wb').write(b'\x89HDF\r\n\x1a\n' + bytes(64))
open(T + '/walk.bag', 'wb').write(b'#ROSBAG V2.0\nE\x00\x00\x00' + bytes(64))
open(T + '/walk.mat', 'wb').write(b'MATLAB 5.0 MAT-file, Platform: GLNXA64' + bytes(90))
open(T + '/walk.db', 'wb').write(b'SQLite format 3\x00' + bytes(84))
open(T + '/walk.xls', 'wb').write(b'\xd0\xcf\x11\xe0\xa1\xb1\x1a\xe1' + bytes(64))
open(T + '/bzh.csv', 'wb').write(b'BZh,ax\n1,2\n')  # text that begins as bzip2's magic does
PY
for fw in "export.zip:a ZIP archive" "walk.csv.bz2:bzip2-compressed data: decompress it (bunzip2 -k $T/walk.csv.bz2)" \
    "walk.csv.xz:xz-compressed data: decompress it (unxz -k $T/walk.csv.xz)" "walk.tar.gz:a tar archive: extract it (tar xf $T/walk.tar.gz)" \
    "walk.h5:an HDF5 file" "walk.bag:a ROS bag: write its IMU topic as CSV (rostopic echo -b $T/walk.bag -p /TOPIC > imu.csv)" \
    "walk.mat:a MATLAB .mat file" "walk.db:an SQLite database" "walk.xls:an Excel .xls workbook"; do
    f=${fw%%:*} w=${fw#*:}
    expect_exit 1 "replay of $f" "$H" replay "$T/$f"
    if grep -qF -- "$f: not a log but $w" "$T/err"; then pass "$f: named as $w"; else fail "$f: $(cat "$T/err")"; fi
done
printf "t,x,y,z\n0,0,0,0\n" >"$T/gyr1.csv"
expect_exit 1 "merge of a zip" "$H" merge "$T/export.zip" "$T/gyr1.csv" "$T/m.csv"
expect_err "export.zip: not a log but a ZIP archive" "merge: the zip named"
expect_exit 1 "info of a text CSV that begins with BZh" "$H" info "$T/bzh.csv"
if grep -q "bzip2" "$T/err"; then fail "a text CSV that begins with BZh taken for bzip2"; else pass "a text CSV that begins with BZh is text"; fi
expect_exit 1 "convert of plot.png" "$H" convert "$T/plot.png" "$T/plot.csv"
expect_err "plot.png: binary data, not a log: its first bytes 89 50 4e 47 0d 0a 1a 0a hold 0x1a at byte 7" "convert: the bytes named"
# a CSV saved as UTF-16 (Windows' "Unicode text" export, with or without its
# byte-order mark): "FILE:1: a NUL byte in the text (binary data, e.g. a
# logger's unwritten blocks)" with the mark, the --columns advice without
# it, where the file only needs saving as UTF-8
head -n 50 vectors/nav/golden/gx2_walk2.csv >"$T/u8.csv"
"${PY:-/usr/bin/python3}" -c 'import sys; t = open(sys.argv[1]).read(); open(sys.argv[2], "wb").write(t.encode("utf-16")); open(sys.argv[3], "wb").write(t.encode("utf-16-le")); open(sys.argv[4], "wb").write(t.encode("utf-16-be"))' \
    "$T/u8.csv" "$T/u16.csv" "$T/u16le.csv" "$T/u16be.csv" || fail "write the UTF-16 copies"
for fe in u16.csv:UTF-16 u16le.csv:UTF-16LE u16be.csv:UTF-16BE; do
    f=${fe%%:*} e=${fe#*:}
    for c in info replay "allan --rate 100 --series"; do
        expect_exit 1 "$c of $f (UTF-16)" "$H" $c "$T/$f"
        expect_err "$f: UTF-16 text, not UTF-8 (save it as UTF-8, e.g. iconv -f $e -t UTF-8 $T/$f" "$c: $f said to be $e"
    done
done
expect_exit 0 "info of the UTF-8 original" "$H" info "$T/u8.csv"
expect_exit 0 "allan --series of the UTF-8 original's column 2" "$H" allan --rate 100 --series "$T/u8.csv" --column 2 --no-sim --quiet
expect_exit 1 "allan --series of plot.png" "$H" allan --rate 100 --series "$T/plot.png"
expect_err "plot.png: binary data, not a series: its first bytes 89 50 4e 47 0d 0a 1a 0a hold 0x1a at byte 7, which no text holds" \
    "allan --series: the bytes named"
# a CSV in another layout is still told about --columns
printf 'stamp;x;y;z\n0;0;0;9.8\n' >"$T/other2.csv"
expect_exit 1 "info of a text CSV of no known layout" "$H" info "$T/other2.csv"
expect_err "give its names and units with --columns and --units" "a text CSV of no known layout: --columns advised"

# --- '-' given to an output option that cannot write to standard output:
# not a PNG named '-' (exit 0) from `replay --plot -`, nor from allan's,
# psd's (a directory '-'), montecarlo's and simgap's --plot, allan's
# --profile, simgap-validate's --markdown and eval's --plots, nor live's
# --plot - and --record -, as sim's --truth - is refused. Each is a usage
# error naming the option, exit 2, before anything is read or written (run
# in an empty directory, which stays empty).
HA=$(cd "$(dirname "$H")" && pwd)/$(basename "$H")
W=$(pwd)/vectors/walk.bin
mkdir "$T/dash"
dash() { # description expected-option command...: exit 2, the option named, no '-' made
    what=$1; opt=$2; shift 2
    expect_exit 2 "$what" sh -c 'cd "$1" && shift && exec "$@"' sh "$T/dash" "$@"
    expect_err "error: $opt needs a .* name ('-' is not standard output here" "$what: the option named"
    if [ -e "$T/dash/-" ]; then fail "$what: a file '-' made"; rm -rf "$T/dash/-"; else pass "$what: no file '-' made"; fi
}
dash "replay --plot -" --plot "$HA" replay "$W" --quiet --plot -
dash "allan --plot -" --plot "$HA" allan "$W" --quiet --no-sim --plot -
dash "allan --profile -" --profile "$HA" allan "$W" --quiet --no-sim --profile -
dash "psd --plot -" --plot "$HA" psd "$W" --plot -
dash "montecarlo --plot -" --plot "$HA" montecarlo --duration 12 --seeds 2 --quiet --plot -
dash "simgap --plot -" --plot "$HA" simgap "$W" --quiet --plot -
dash "simgap-validate --markdown -" --markdown "$HA" simgap-validate --cases 1 --quiet --markdown -
dash "eval --plots -" --plots "$HA" eval --data "$T/nodata" --out "$T/r.md" --plots -
dash "live --plot -" --plot "$HA" live "$T/noport" --plot -
dash "live --record -" --record "$HA" live "$T/noport" --record -
dash "sim --truth -" --truth "$HA" sim --duration 2 --out "$T/s.csv" --truth -

# --- an option value refused by a rule of its own (a power of two, a word
# of a list) is named, as a number out of range is (docs/harness.md,
# "Numbers"): `psd --nfft 100` said "--nfft must be a power of two in
# 8..4096" and `allan --m 10,1` "--m must be positive whole numbers ...",
# without the value given (exit 2, as still).
bad_value() { # description expected-stderr command...
    bv_what=$1; bv_want=$2; shift 2
    expect_exit 2 "$bv_what" "$@"
    expect_err "$bv_want" "$bv_what: the value named"
}
bad_value "psd --nfft 100" "error: --nfft must be a power of two in 8..4096, not '100'" "$H" psd vectors/walk.bin --nfft 100
bad_value "psd --spec-nfft 100" "error: --spec-nfft must be a power of two in 8..4096, not '100'" "$H" psd vectors/walk.bin --spec-nfft 100 --plot "$T/p"
bad_value "psd --window hanning" "error: --window must be hamming, hann or rect, not 'hanning'" "$H" psd vectors/walk.bin --window hanning
bad_value "psd --dc mean" "error: --dc must be segment, linear, global, none or exclude, not 'mean'" "$H" psd vectors/walk.bin --dc mean
bad_value "psd --spec-axis x" "error: --spec-axis must be one of ax, ay, az, gx, gy, gz, not 'x'" "$H" psd vectors/walk.bin --spec-axis x --plot "$T/p"
bad_value "allan --per-octave 3" "error: --per-octave must be 1, 2 or 4, not '3'" "$H" allan vectors/walk.bin --per-octave 3
# 5 and 0 said "not a whole number in [1, 4]", as if 3 were taken
bad_value "allan --per-octave 5" "error: --per-octave must be 1, 2 or 4, not '5'" "$H" allan vectors/walk.bin --per-octave 5
bad_value "allan --per-octave 0" "error: --per-octave must be 1, 2 or 4, not '0'" "$H" allan vectors/walk.bin --per-octave 0
# --phase or --column with a log: it named both for either
bad_value "allan LOG --column 2" "error: --column applies to --series only (a log's columns are named with --columns MAP)" "$H" allan vectors/walk.bin --column 2
bad_value "allan LOG --phase" "error: --phase applies to --series only (a log holds rates and specific forces, not a phase)" "$H" allan vectors/walk.bin --phase
bad_value "allan --estimator fast" "error: --estimator must be exact or streaming, not 'fast'" "$H" allan vectors/walk.bin --estimator fast
bad_value "allan --m 10,1" "error: --m must be positive whole numbers separated by commas, strictly ascending, at most [0-9]*, not '10,1'" "$H" allan vectors/walk.bin --estimator exact --m 10,1
bad_value "sim --mount 0,10" "error: --mount needs R,P,Y in degrees, e.g. --mount 0,10,90, not '0,10'" "$H" sim --out "$T/m.csv" --mount 0,10
[ -e "$T/p" ] && fail "psd: the refused run made its plot directory" || pass "psd: no plot directory made"

# --- psd's and allan's --out CSV onto a full disk: the error gave no reason
# ("harness psd: error: /dev/full: write failed"), where every other
# output's says why, as sim's above; the JSON is still written (exit 3)
if [ -w /dev/full ]; then
    expect_exit 3 "psd --out onto a full disk" "$H" psd vectors/walk.bin --out /dev/full --json "$T/pfull.json"
    expect_err "^harness psd: error: /dev/full: write failed (No space left on device)$" "psd: the CSV's failed write said with its reason"
    json "$T/pfull.json" 'j["samples"] > 0' && pass "psd: the JSON written beside the failed CSV" || fail "psd: no JSON beside the failed CSV"
    expect_exit 3 "allan --out onto a full disk" "$H" allan vectors/walk.bin --no-sim --quiet --out /dev/full --json "$T/afull.json"
    expect_err "^harness allan: error: /dev/full: write failed (No space left on device)$" "allan: the CSV's failed write said with its reason"
    [ -s "$T/afull.json" ] && pass "allan: the JSON written beside the failed CSV" || fail "allan: no JSON beside the failed CSV"
else
    echo "skip the full-disk checks of psd and allan (no /dev/full)"
fi

# --- a command stopped by its input before its JSON was written (allan, psd,
# simgap on a log without samples wrote none: a pipeline read no file, or the
# previous run's) writes {command, complete: false, error}; exit 1 stays.
printf 't,ax,ay,az,gx,gy,gz\n' > "$T/nosamples.csv"
for c in allan psd simgap; do
    echo '{"stale": true}' > "$T/fail_$c.json"
    expect_exit 1 "$c: a log without samples" "$H" $c "$T/nosamples.csv" --json "$T/fail_$c.json"
    expect_err "nosamples.csv: no samples" "$c: no samples said"
    json "$T/fail_$c.json" 'j["complete"] is False and j["error"].endswith("nosamples.csv: no samples") and j["command"].startswith("harness '$c' ") and "stale" not in j' \
        && pass "$c: the failure JSON replaces the previous run's" || fail "$c: no failure JSON: $(head -c 300 "$T/fail_$c.json")"
done
# the reader's error said once (allan added "too few samples before the error to know the sample rate")
n=$(grep -c 'error:' "$T/err")
[ "$n" -eq 1 ] && pass "simgap: one error for a log without samples" || fail "simgap: $n errors: $(cat "$T/err")"
expect_exit 1 "allan: a log without samples" "$H" allan "$T/nosamples.csv"
n=$(grep -c 'error:' "$T/err")
[ "$n" -eq 1 ] && pass "allan: one error for a log without samples" || fail "allan: $n errors: $(cat "$T/err")"
# '--json -' gets it on standard output; the input named as --json is never overwritten
expect_exit 1 "psd: a log without samples, --json -" "$H" psd "$T/nosamples.csv" --json -
json "$T/out" 'j["complete"] is False' && pass "psd --json -: the failure JSON on standard output" || fail "psd --json -: $(head -c 300 "$T/out")"
cp "$T/nosamples.csv" "$T/self.csv"
expect_exit 2 "allan: the input as --json" "$H" allan "$T/self.csv" --json "$T/self.csv"
cmp -s "$T/nosamples.csv" "$T/self.csv" && pass "allan: the input given as --json left as it was" || fail "allan: the input overwritten"
# a usage error writes nothing
rm -f "$T/usage.json"
expect_exit 2 "psd: a usage error" "$H" psd "$T/nosamples.csv" --nfft 7 --json "$T/usage.json"
[ ! -e "$T/usage.json" ] && pass "psd: no JSON on a usage error" || fail "psd: a JSON written on a usage error"

# a field holding an escape sequence (OSC: set the terminal's title) is
# quoted in the reader's messages with its control characters read as '?'
# (the .bin header's rule): it reached the terminal as it was
printf 't,ax,ay,az,gx,gy,gz\n0,0,0,-9.8,0,0,0\n0.01,0\033]0;PWNED\007,0,-9.8,0,0,0\n' > "$T/esc.csv"
expect_exit 1 "info, a field holding an escape sequence" "$H" info "$T/esc.csv" --json "$T/esc.json"
if LC_ALL=C grep -q "$(printf '\033')" "$T/err" "$T/out"; then fail "an escape character of the file reached the terminal"
else pass "no escape character of the file in the messages"; fi
expect_err "column 2 ('0?]0;PWNED?') is not a number" "the field quoted with its control characters as '?'"
expect_out "^incomplete  .*column 2 ('0?]0;PWNED?') is not a number" "info's incomplete line: the same"
expect_exit 1 "replay, the same field" "$H" replay "$T/esc.csv" --out "$T/esc_traj.csv" --quiet
if LC_ALL=C grep -q "$(printf '\033')" "$T/err"; then fail "replay: an escape character of the file reached the terminal"
else pass "replay: no escape character of the file in the messages"; fi
# the same with a C1 control in UTF-8 (U+009B, C2 9B: a terminal's CSI, as
# ESC [ is), one '?' for its two bytes; before, the ASCII rule let it through
printf 't,ax,ay,az,gx,gy,gz\n0,0,0,-9.8,0,0,0\n0.01,0\302\2332J,0,-9.8,0,0,0\n' > "$T/csi.csv"
expect_exit 1 "info, a field holding a C1 control (U+009B)" "$H" info "$T/csi.csv"
if LC_ALL=C grep -q "$(printf '\302\233')" "$T/err" "$T/out"; then fail "a C1 control of the file reached the terminal"
else pass "no C1 control of the file in the messages"; fi
expect_err "column 2 ('0?2J') is not a number" "the C1 control quoted as one '?'"
# one sample before the error: "1 sample", not "1 samples"
expect_err "(using the 1 sample before it)" "info: one sample before the error in the singular (warning)"
expect_err "the results cover the 1 sample before the error" "info: one sample before the error in the singular (error)"
# a byte of no UTF-8 character (a raw 0x9B: CSI to a terminal of 8-bit controls, the Linux console out of UTF-8
# mode; Latin-1's 0xE9) is shown as '?' too, a UTF-8 letter as it is; before, the raw bytes reached the terminal
printf 't,ax,ay,az,gx,gy,gz\n0,0,0,-9.8,0,0,0\n0.01,0\2332J\351\303\251,0,-9.8,0,0,0\n' > "$T/raw.csv"
expect_exit 1 "info, a field holding a raw 0x9B and a Latin-1 byte" "$H" info "$T/raw.csv"
if LC_ALL=C grep -q "$(printf '\233')" "$T/err" "$T/out"; then fail "a raw 0x9B of the file reached the terminal"
else pass "no raw 0x9B of the file in the messages"; fi
expect_err "column 2 ('0?2J?$(printf '\303\251')') is not a number" "bytes of no UTF-8 character as '?', a UTF-8 letter kept"
expect_exit 1 "info of a missing file with a Latin-1 name" "$H" info "$T/caf$(printf '\351').csv"
expect_err "caf?.csv: cannot open" "a Latin-1 byte of a file name as '?'"
printf 't,ax,ay,az,gx,gy,gz\n0,0,0,-9.8,0,0,0\n' > "$T/one.csv"
expect_exit 1 "simgap, a log of one sample" "$H" simgap "$T/one.csv"
expect_err "the log has 1 sample and no usable rate" "simgap: one sample in the singular"
# stamps that never advance, and a short log with a rate: each said for
# what it is (allan said "give --rate", simgap "no usable rate" for both)
{ echo "t,ax,ay,az,gx,gy,gz"; awk 'BEGIN { for (i = 0; i < 3000; i++) print "5.0,0.01,0.02,9.81,0.001,0.002,0.003" }'; } > "$T/const_t.csv"
expect_exit 1 "allan, stamps that never advance" "$H" allan "$T/const_t.csv" --no-sim
expect_err "sample rate unknown: every time stamp is the same (is the time column filled?" "allan: the stamps named"
expect_exit 1 "simgap, stamps that never advance" "$H" simgap "$T/const_t.csv"
expect_err "the time stamps never advance (all 3000 samples at one time)" "simgap: the stamps named"
{ echo "t,ax,ay,az,gx,gy,gz"; awk 'BEGIN { for (i = 0; i < 10; i++) printf "%.2f,0.01,0.02,9.81,0.001,0.002,0.003\n", i * 0.01 }'; } > "$T/ten.csv"
expect_exit 1 "simgap, ten samples at 100 Hz" "$H" simgap "$T/ten.csv"
expect_err "the log has 10 samples, too few to diagnose (16 at least)" "simgap: too few said, not 'no usable rate'"
# one sample with a rate (--input-rate): "1 sample", as without one
printf 'ax,ay,az,gx,gy,gz\n0.01,0.02,9.81,0.001,0.002,0.003\n' > "$T/one_nt.csv"
expect_exit 1 "simgap, one sample at a given rate" "$H" simgap "$T/one_nt.csv" --input-rate 100
expect_err "the log has 1 sample, too few to diagnose (16 at least)" "simgap: one sample with a rate in the singular"

# a file name holding an escape sequence (a data set's file, reached by a
# glob): the messages and the reports' file lines show it with '?' for
# each control character; before, info's `file` line, replay's `log`
# line, allan's, psd's and simgap's headers and every message naming the
# path (`cannot open`) wrote it as it was
escname="$T/w$(printf '\033')]0;X$(printf '\007').csv"
expect_exit 0 "sim into a file name holding an escape sequence" "$H" sim --duration 10 --out "$escname"
for c in info replay "allan --no-sim" psd simgap; do
    # shellcheck disable=SC2086 # the command and its option split
    "$H" $c "$escname" >"$T/out" 2>"$T/err"
    if LC_ALL=C grep -q "$(printf '\033')" "$T/out" "$T/err"; then fail "$c: the file name's escape reached the terminal"
    else pass "$c: the file name shown without its control characters"; fi
done
expect_exit 0 "info of that file" "$H" info "$escname"
expect_out "^file        .*/w?]0;X?.csv$" "info: the file line with '?' for each control character"
expect_exit 1 "info of a missing file whose name holds an escape" "$H" info "$T/none$(printf '\033')[2J"
expect_err "none?\[2J: cannot open" "the message's path with '?' for its control character"
# the same for the other report lines that name a file: sim's `log`, `truth` and `profile` lines, replay's
# `config` line (a profile file's name) and montecarlo's `sensor` line; before, they wrote it as it was
escprof="$T/p$(printf '\033')[2J.profile"
cp "$(dirname "$0")/../../docs/profiles/generic-mems.profile" "$escprof"
"$H" sim --duration 10 --out "$T/w$(printf '\033')[2J.csv" --truth "$T/t$(printf '\033')[2J.csv" --profile "$escprof" \
    >"$T/out" 2>"$T/err"
if LC_ALL=C grep -q "$(printf '\033')" "$T/out" "$T/err"; then fail "sim: a file name's escape reached the terminal"
else pass "sim: the log, truth and profile lines without their control characters"; fi
expect_out "^profile     .*/p?\[2J.profile$" "sim: the profile line with '?' for the control character"
expect_out "^log         .*/w?\[2J.csv$" "sim: the log line with '?' for the control character"
expect_out "^truth       .*/t?\[2J.csv$" "sim: the truth line with '?' for the control character"
for c in replay montecarlo; do
    if [ "$c" = replay ]; then "$H" replay "$escname" --profile "$escprof"
    else "$H" montecarlo --seeds 2 --duration 10 --profile "$escprof"; fi >"$T/out" 2>"$T/err"
    if LC_ALL=C grep -q "$(printf '\033')" "$T/out" "$T/err"; then fail "$c: the profile file's escape reached the terminal"
    elif grep -q "p?\[2J.profile" "$T/out"; then pass "$c: the profile file's name shown with '?'"
    else fail "$c: the profile file's name not shown"; fi
done

# names that hold blanks ("Time (s)") in a file whose fields are separated by blanks (x-io's header with its
# commas made blanks) cannot be told apart: said so, with the remedy; not "a time and x, y, z alone (one
# sensor's file? ... merge" (the header's lone X, Y, Z), nor "7 columns, expected at least 8" alone
printf 'Time (s) Gyroscope X (deg/s) Gyroscope Y (deg/s) Gyroscope Z (deg/s) Accelerometer X (g) Accelerometer Y (g) Accelerometer Z (g)\n0 0.1 0.2 0.3 0 0 1\n0.0025 0.1 0.2 0.3 0 0 1\n' >"$T/ngblank.csv"
expect_exit 1 "x-io's header separated by blanks refused" "$H" info "$T/ngblank.csv"
expect_err "ngblank.csv:1: header has no column 't'; expected t,ax,ay,az,gx,gy,gz\[,temp\]; the fields are separated by blanks and the header's names hold blanks ('(s)' is its field 2 alone), which cannot be told apart: separate the fields with commas or tabs$" \
    "names holding blanks in a blank-separated header: said, with the remedy"
printf 'Time [s] ax ay az gx gy gz\n0 0 0 9.8 0 0 0\n0.01 0 0 9.8 0 0 0\n' >"$T/tblank.csv"
expect_exit 1 "a time name holding a blank in a blank-separated header refused" "$H" info "$T/tblank.csv"
expect_err "tblank.csv:2: 7 columns, expected at least 8; the fields are separated by blanks and the header's names hold blanks ('\[s\]' is its field 2 alone)" \
    "the row's short count said with its cause"
# ... but a unit alone past the columns read ("t ax ... gz [SI]", the header read by its names) does not make a
# row cut short (the last line of a copy stopped early) such a header: the short count alone, no remedy about blanks
printf 't ax ay az gx gy gz [SI]\n0 0 0 9.8 0 0 0 x\n0.01 0 0 9.8 0 0 0 x\n0.02 0 0 9.8\n' >"$T/ucut.csv"
expect_exit 1 "a row cut short under a header with a unit alone past the columns read" "$H" info "$T/ucut.csv"
expect_err "ucut.csv:4: 4 columns, expected at least 7 (using the 2 samples before it)" "a cut row: its short count, no claim about the header's names"
# ... nor a header whose one unit alone is its last field, a note ("sec ax ... gz (SI)"): what is wrong there is
# the name of a column, said as before, not the blanks (which separating the fields with commas does not mend)
printf 'sec ax ay az gx gy gz (SI)\n0 0 0 9.8 0 0 0 x\n' >"$T/unote.csv"
expect_exit 1 "a blank-separated header with a unit alone as its last field, its time named 'sec'" "$H" info "$T/unote.csv"
expect_err "unote.csv:1: header has no column 't'; expected t,ax,ay,az,gx,gy,gz\[,temp\] (t in s: name the time column t" \
    "a unit alone as the last field: the missing name said, not the blanks"
# a unit alone longer than the message quotes is cut and marked "...", not cut without a mark inside it
printf 'Time (seconds_since_the_start_of_the_log) Gyroscope X (deg/s) Gyroscope Y (deg/s) Gyroscope Z (deg/s) Accelerometer X (g) Accelerometer Y (g) Accelerometer Z (g)\n0 0.1 0.2 0.3 0 0 1\n' >"$T/ulong.csv"
expect_exit 1 "x-io's header separated by blanks, its first unit long" "$H" info "$T/ulong.csv"
expect_err "('(seconds_since_the_s\.\.\.' is its field 2 alone)" "a long unit alone: cut and marked"

# a header of numbers counting the columns from 1 is no pandas header (pandas counts from 0): --columns t=0,... over it
# is told how it counts, without naming pandas
printf '1,2,3,4,5,6,7\n0,0,0,9.8,0,0,0\n' >"$T/from1.csv"
expect_exit 1 "--columns t=0,... over a header counting from 1" "$H" info "$T/from1.csv" --columns t=0,ax=1,ay=2,az=3,gx=4,gy=5,gz=6
expect_err "from1.csv:1: the header counts the columns from 1, and --columns names them as it does: t=0 is not one of its names, 1 to 7 (the first column is 1)$" \
    "a header counting from 1: how it counts, pandas not named"

# two Consensys devices in one file: every channel has two candidates, more than the refusal holds; the list is cut
# after a whole item and marked "; ...", not inside a name (it ended "gx: 2 candidates (A_Gyr" before 2026-12-07)
cols="Timestamp_Unix_CAL Accel_WR_X_CAL Accel_WR_Y_CAL Accel_WR_Z_CAL Gyro_X_CAL Gyro_Y_CAL Gyro_Z_CAL"
{
    hdr=""; for d in A B; do for c in $cols; do hdr="$hdr${hdr:+,}${d}_$c"; done; done; echo "$hdr"
    echo "ms,m/(s^2),m/(s^2),m/(s^2),deg/s,deg/s,deg/s,ms,m/(s^2),m/(s^2),m/(s^2),deg/s,deg/s,deg/s"
    echo "1595933810034.18,0.39,0.1,9.8,-2.75,0,0,1595933810034.18,0.39,0.1,9.8,-2.75,0,0"
} > "$T/two_shimmers.csv"
expect_exit 1 "two Consensys devices in one file" "$H" info "$T/two_shimmers.csv"
expect_err "t: 2 candidates (A_Timestamp_Unix_CAL, B_Timestamp_Unix_CAL); .*; az: 2 candidates (A_Accel_WR_Z_CAL, B_Accel_WR_Z_CAL); ... (no importer's header recognised" \
    "two devices' candidates: the list cut after a whole item, marked"

# a message is written whole, not a character at a time: stderr is unbuffered, and the rule's first form wrote
# each character by itself (a write(2) per byte, some 60 for this message; a parallel job's line into the same
# log could split); now the prefix, the text and the line end (strace, where it runs)
if command -v strace >/dev/null 2>&1 && strace -o /dev/null true >/dev/null 2>&1; then
    # (LeakSanitizer cannot run under ptrace: a sanitizer build's own lines, "==PID==...", are not the message's)
    ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0 \
        strace -e trace=write -o "$T/strace" "$H" info "$T/none$(printf '\033')[2J" >/dev/null 2>&1
    nw=$(grep '^write(2,' "$T/strace" | grep -v -c '^write(2, "==[0-9]*==')
    [ "$nw" -le 4 ] && pass "the message written whole ($nw writes)" || fail "the message written in $nw writes (a byte each?)"
else
    echo "note: the message's writes not counted (no strace, or it cannot trace here)"
fi

# --- scripts/cli_mutation_sweep.py with no data under --data (a clone
# outside the repository's parent finds no ../shared/data): says so and how
# to give it, in both modes; --eval wrote a FileNotFoundError traceback from
# shutil.copy (the default mode's IndexError was mended before)
PY=${PYTHON:-/usr/bin/python3}
if [ -x "$PY" ]; then
    for mode in "" --eval; do
        env -u FNAV_DATA_DIR "$PY" scripts/cli_mutation_sweep.py $mode --harness "$H" --data "$T/nodata" --cases 1 \
            --out "$T/sweep" >"$T/out" 2>"$T/err"
        rc=$?
        [ "$rc" -eq 1 ] && grep -q "under $T/nodata.*: give --data DIR or set FNAV_DATA_DIR" "$T/err" &&
            ! grep -q Traceback "$T/err" &&
            pass "cli_mutation_sweep.py ${mode:-(default)}: no data said, --data named, no traceback" ||
            fail "cli_mutation_sweep.py ${mode:-(default)} with no data: exit $rc, $(tail -n 1 "$T/err")"
    done
else
    echo "skip cli_mutation_sweep.py with no data (no $PY)"
fi

if [ "$fails" -ne 0 ]; then echo "test_bad_input.sh: $fails failure(s)"; exit 1; fi
echo "test_bad_input.sh: all passed"
