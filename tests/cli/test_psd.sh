#!/bin/sh
# CLI tests of `harness psd` (run by make test with $HARNESS set).
set -u
H=${HARNESS:-bin/harness}
PY=${PYTHON:-/usr/bin/python3}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
data() {
    for root in "${FNAV_DATA_DIR:-}" ../shared/data /work/shared/data; do
        [ -n "$root" ] && [ -f "$root/$1" ] && { echo "$root/$1"; return; }
    done
}

expect_exit 2 "no input" "$H" psd
expect_exit 1 "missing file" "$H" psd "$T/nope.csv"
expect_exit 2 "nfft not a power of two" "$H" psd x.csv --nfft 48
expect_exit 2 "unknown dc mode" "$H" psd x.csv --dc bogus
expect_exit 2 "global with symmetric window" "$H" psd x.csv --dc global --symmetric
# --spec-nfft is checked with the other options, before the input is read (a value that is no power of two was
# refused only when the spectrogram was drawn, after the analysis and two plots: exit 3, an output failure)
expect_exit 2 "spec-nfft not a power of two" "$H" psd x.csv --spec-nfft 100
expect_err "spec-nfft must be a power of two" "the spectrogram's segment length is refused as a usage error"

# a tiny CSV in the interchange format: a 100 Hz tone at 1000 Hz + gravity on z
awk 'BEGIN { print "t,ax,ay,az,gx,gy,gz"; for (i = 0; i < 4000; i++) { t = i / 1000.0; s = sin(6.283185307 * 100 * t);
     printf "%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f\n", t, s, 0.5 * s, -9.81 + s, 0.1 * s, 0.1 * s, 0.1 * s } }' >"$T/tone.csv"
# few Welch segments: each bin's scatter said (1/sqrt(K) at least; 100 % for one periodogram), and the title's
# count in the singular ('1 segments')
awk 'BEGIN { print "t,ax,ay,az,gx,gy,gz"; s = 3; for (i = 0; i < 5000; i++) { s = (s * 1103515245 + 12345) % 2147483648; r = s / 2147483648.0 - 0.5; printf "%.3f,%.4f,%.4f,%.4f,%.5f,%.5f,%.5f\n", i / 250, r, -r / 2, 9.81 + r / 3, r / 10, -r / 9, r / 8 } }' >"$T/few.csv"
expect_exit 0 "one Welch segment" "$H" psd "$T/few.csv" --nfft 4096
expect_err "few.csv: 1 segment of 4096 samples: each PSD bin scatters by 100 % of its value" "one segment: its scatter warned"
expect_out "dc segment, 1 segment, resolution" "one segment: singular in the title"
expect_exit 0 "three Welch segments" "$H" psd "$T/few.csv" --nfft 2048
expect_err "few.csv: 3 segments of 2048 samples: each PSD bin scatters by at least 58 % of its value" "three segments: at least 1/sqrt(3)"
expect_exit 0 "eighteen Welch segments" "$H" psd "$T/few.csv" --nfft 512
if grep -q "scatters" "$T/err"; then fail "18 segments warned as few"; else pass "18 segments: no warning"; fi
expect_exit 0 "tone" "$H" psd "$T/tone.csv" --json "$T/tone.json" --dc global
# all power at 100 Hz, 15.6 Hz bins: the Hamming main lobe spreads it over +-2 bins, so 95 % of
# the power lies below 100 + 31.25 Hz and above 100 Hz; fs 250 Hz (multiples of 50)
if "$PY" -c 'import json,sys; r=json.load(open(sys.argv[1]))["result"]; assert 100 < r["accel_bandwidth_hz"] < 131.25 and r["fs_hz"] == 250, r' "$T/tone.json"; then
    pass "tone bandwidth"
else
    fail "tone bandwidth"
fi
# the input file as replay's JSON names it, `log`, and `source` kept as its alias (not `source` only)
json "$T/tone.json" 'j["log"] == j["source"] == sys.argv[1].replace("tone.json", "tone.csv")' &&
    pass "psd --json names the log as replay's does (log), source its alias" || fail "psd --json log/source: $(head -c 200 "$T/tone.json")"
expect_out_re "^  lowest usable sampling frequency: 250 Hz \(accelerometers and gyroscopes alike; 95 % of the power, multiples of 50 Hz\)$" \
    "--dc global: the answer line without the pointer"
# the default (--dc segment, the paper's setting) is not the recommended one: the answer line says which it is (the
# 820 Hz walk's 450 Hz would read as the answer, where docs/psd.md recommends --dc global, 300 Hz)
for dc in "" "--dc segment"; do
    expect_exit 0 "tone, ${dc:-the default dc}" "$H" psd "$T/tone.csv" $dc
    expect_out_re "^  lowest usable sampling frequency: 250 Hz \(accelerometers and gyroscopes alike; 95 % of the power, multiples of 50 Hz\) \(--dc segment, the paper's setting; --dc global is recommended: docs/psd.md\)$" \
        "${dc:-the default dc}: the answer line names the setting and the recommended one"
done
expect_exit 0 "tone, --dc linear" "$H" psd "$T/tone.csv" --dc linear
grep -q "is recommended" "$T/out" && fail "--dc linear: the pointer is for the paper's setting only" ||
    pass "--dc linear: no pointer"
expect_exit 3 "unwritable output" "$H" psd "$T/tone.csv" --out /nonexistent/dir/p.csv
# a CSV whose write fails (a full disk; standard output on one): exit 3 with the file, or "standard output", and
# the reason named (hx_out_finish)
if [ -w /dev/full ]; then
    expect_exit 3 "--out onto a full disk" "$H" psd "$T/tone.csv" --out /dev/full
    expect_err "/dev/full: write failed (No space left on device)" "--out onto a full disk: the failed write said"
    expect_exit 3 "--out - onto a full disk" sh -c '"$0" psd "$1" --out - >/dev/full' "$H" "$T/tone.csv"
    expect_err "standard output: write failed (No space left on device)" "--out - onto a full disk: the failed write said"
else
    echo "SKIP psd --out onto a full disk: /dev/full is not writable"
fi
# every output is checked before the Welch work: an unwritable one is exit 3 with nothing printed (not found at
# the end, after the work)
for o in "--out /nonexistent/dir/p.csv" "--json /nonexistent/dir/p.json" "--plot /nonexistent/dir/pd"; do
    expect_exit 3 "unwritable ${o%% *}, before the work" "$H" psd "$T/tone.csv" $o
    if [ ! -s "$T/out" ]; then pass "unwritable ${o%% *}: nothing computed first"; else fail "unwritable ${o%% *}: the tables were printed first"; fi
done
# a --plot DIR made for the check before the work is removed again: a run that ended before the plots (the input
# missing) left it made and empty
expect_exit 1 "a missing input with --plot DIR" "$H" psd "$T/missing.csv" --plot "$T/pmiss"
[ ! -e "$T/pmiss" ] && pass "... the plots' directory not left made and empty" || fail "psd left $T/pmiss made"
# --round 0: the answer is 2 x bandwidth itself; the output said "rounded up to a multiple of 0 Hz" and "multiples of
# 0 Hz", and printed the answer to the hertz
expect_exit 0 "tone, --round 0" "$H" psd "$T/tone.csv" --round 0 --json "$T/r0.json"
expect_out "sampling frequency = 2 x band, not rounded (--round 0)" "--round 0: the criterion says it does not round"
! grep -q "of 0 Hz" "$T/out" && pass "--round 0: no 'multiple(s) of 0 Hz'" || fail "--round 0: 'multiple(s) of 0 Hz' printed"
F=$("$PY" -c 'import json,sys; print("%.1f" % json.load(open(sys.argv[1]))["result"]["fs_hz"])' "$T/r0.json")
expect_out "lowest usable sampling frequency: $F Hz (accelerometers and gyroscopes alike; 95 % of the power, not rounded)" \
    "--round 0: the answer printed as the JSON's, to 0.1 Hz"
# and its value: Nyquist, twice the band (100 to 131.25 Hz, as above), so 200 to 262.5 Hz; each group's too. The
# unrounded answer of one band (the factor 2 dropped) would otherwise pass every test
if "$PY" -c 'import json,sys; r=json.load(open(sys.argv[1]))["result"]
for g in ("accel", "gyro"):
    b, f = r[g + "_bandwidth_hz"], r[g + "_fs_hz"]
    assert 100 < b < 131.25 and abs(f - 2 * b) < 1e-3 * b, (g, b, f)
assert 200 < r["fs_hz"] < 262.5 and r["fs_hz"] == max(r["accel_fs_hz"], r["gyro_fs_hz"]), r' "$T/r0.json"; then
    pass "--round 0: the answer is 2 x the band"
else
    fail "--round 0: the answer is not 2 x the band: $(cat "$T/r0.json" | tr -d '\n' | cut -c1-400)"
fi
# a step that is no whole number of hertz: the answer 232.5 Hz (a multiple of 2.5) printed to the hertz, "232 Hz",
# in the answer line, the groups' lines and the table's fs_Hz column, would be no multiple of the step, and below what
# the rule asks; it is printed with the step's decimals. With --round 0 the table's fs_Hz column (2 x the band
# itself) is printed to 0.1 Hz, as the answer line, not to the hertz: 231 beside 2xBW_Hz 230.9.
expect_exit 0 "tone, --round 2.5" "$H" psd "$T/tone.csv" --round 2.5 --json "$T/r25.json"
F=$("$PY" -c 'import json,sys; print("%.1f" % json.load(open(sys.argv[1]))["result"]["fs_hz"])' "$T/r25.json")
"$PY" -c 'import json,sys; f = json.load(open(sys.argv[1]))["result"]["fs_hz"]; assert f % 2.5 == 0 and f % 1 != 0, f' "$T/r25.json" &&
    pass "--round 2.5: the tone's answer is a multiple of 2.5 Hz, not of 1 Hz (the case the check needs)" ||
    fail "--round 2.5: the tone's answer $F Hz does not test a fractional step"
expect_out "lowest usable sampling frequency: $F Hz (accelerometers and gyroscopes alike; 95 % of the power, multiples of 2.5 Hz)" \
    "--round 2.5: the answer printed as the JSON's, a multiple of the step"
expect_out "accelerometers: bandwidth 115.4 Hz -> $F Hz" "--round 2.5: the group's answer printed as the JSON's"
expect_out_re "^  ax +[0-9.e+-]+ +115\.4 +230\.9 +$F\$" "--round 2.5: the table's fs_Hz column a multiple of the step"
expect_exit 0 "tone, --round 0 (table)" "$H" psd "$T/tone.csv" --round 0
expect_out_re "^  ax +[0-9.e+-]+ +115\.4 +230\.9 +230\.9\$" "--round 0: the table's fs_Hz column is 2 x the band, to 0.1 Hz"
# a step too small to round anything: --round 1e-40 must not run as "multiples of 9.99995e-41 Hz" (a float subnormal),
# nor 1e-50 and 5e-324 as "not rounded (--round 0)" while the JSON says round_hz 1e-50, exit 0. 0 or a step
# of at least 0.001 Hz, else refused as any bad option value (exit 2, naming the value; docs/psd.md, "Command")
for r in 1e-40 1e-50 5e-324 1e-300 0.0009 1e-6; do
    expect_exit 2 "--round $r refused" "$H" psd "$T/tone.csv" --round $r
    expect_err "^harness psd: error: --round '$r' is neither 0 (not rounded) nor a step in \[0.001, 1e+06\] Hz" \
        "--round $r: the value and the range named"
    [ ! -s "$T/out" ] && pass "--round $r: refused before the work" || fail "--round $r: the tables were printed"
done
expect_exit 2 "--round -1 refused" "$H" psd "$T/tone.csv" --round -1
expect_exit 0 "--round 0.001, the smallest step" "$H" psd "$T/tone.csv" --round 0.001
expect_out_re "^  lowest usable sampling frequency: 230\.893 Hz " "--round 0.001: the answer to the millihertz"
# a threshold that is no whole percentage: --threshold 0.995 is not printed to the percent, "holding 100 % of the
# total power" and "100 % of the power": the threshold is said as given
expect_exit 0 "tone, --threshold 0.995" "$H" psd "$T/tone.csv" --threshold 0.995
expect_out "the band from 0 Hz holding 99.5 % of the total power" "--threshold 0.995: the criterion says 99.5 %"
expect_out_re "^  lowest usable sampling frequency: [0-9]+ Hz \(accelerometers and gyroscopes alike; 99\.5 % of the power, multiples of 50 Hz\)" \
    "--threshold 0.995: the answer line says 99.5 %"
! grep -q "100 %" "$T/out" && pass "--threshold 0.995: no '100 %'" || fail "--threshold 0.995: '100 %' printed"
# every channel constant: no band anywhere, so no answer (not 'lowest usable sampling frequency: 0 Hz' with
# fs_hz 0 and exit 0); the tables are still written and the JSON's answer is null
awk 'BEGIN { print "t,ax,ay,az,gx,gy,gz"; for (i = 0; i < 2000; i++) printf "%.3f,0.1,0.2,9.81,0.01,0,0\n", i / 1000.0 }' \
    >"$T/const.csv"
expect_exit 1 "every channel constant" "$H" psd "$T/const.csv" --json "$T/const.json" --out "$T/const_psd.csv"
expect_err "no channel has power once the DC is treated" "no power on any channel is said, not 0 Hz"
# the summary said 'lowest usable sampling frequency: 0 Hz (accelerometers and gyroscopes alike ...)' and each group
# 'bandwidth 0.0 Hz -> 0 Hz', which the error then had to take back
expect_out "lowest usable sampling frequency: none (no channel has power)" "constant log: the summary gives no answer"
! grep -q -- "-> 0 Hz" "$T/out" && pass "constant log: no group said to need 0 Hz" || fail "constant log: a group needs 0 Hz"
if "$PY" -c 'import json,sys; r=json.load(open(sys.argv[1]))["result"]; assert r["fs_hz"] is None and r["gyro_fs_hz"] is None and r["accel_fs_hz"] is None, r' "$T/const.json" && [ -s "$T/const_psd.csv" ]; then
    pass "constant log: fs_hz null, PSD table written"
else
    fail "constant log: fs_hz not null or PSD table missing"
fi
# the sensitivity table of that log: every row said 0.0 Hz per axis and 0 Hz as the answer, and the JSON's sensitivity
# entries fs_hz 0 (the main answer is null); an axis or group without power is '-', and no entry has no answer
expect_exit 1 "every channel constant, --sensitivity" "$H" psd "$T/const.csv" --sensitivity --json "$T/csens.json"
! grep -E -q "^  (segment|linear|global|none|exclude) .* 0(\.0)? " "$T/out" &&
    grep -E -q "^  segment     64 +[0-9.]+ +- +- +- +- +- +- +- +- +-$" "$T/out" &&
    pass "constant log: sensitivity rows without 0 Hz answers" || fail "constant log: sensitivity rows give 0 Hz"
json "$T/csens.json" 'j["sensitivity"] and all(e["dc"] in ("none", "exclude") and e["fs_hz"] > 0 for e in j["sensitivity"])' &&
    pass "constant log: no sensitivity entry without an answer (none and exclude keep the constant's power)" ||
    fail "constant log: sensitivity entries with fs_hz 0"
# the gyroscopes constant, the accelerometers not: the answer is the accelerometers', with a warning
awk 'BEGIN { print "t,ax,ay,az,gx,gy,gz"; for (i = 0; i < 4000; i++) { t = i / 1000.0; s = sin(6.283185307 * 100 * t);
     printf "%.6f,%.6f,%.6f,%.6f,0,0,0\n", t, s, s, -9.81 + s } }' >"$T/gconst.csv"
expect_exit 0 "constant gyroscopes" "$H" psd "$T/gconst.csv" --json "$T/gconst.json" --dc global
expect_err "^harness psd: warning: $T/gconst.csv: no gyroscope axis has power" "a group without power is said, naming the log"
expect_out "gyroscopes:     no power on any axis (left out)" "constant gyroscopes: their summary line says so, not '-> 0 Hz'"
expect_exit 0 "constant gyroscopes, --sensitivity" "$H" psd "$T/gconst.csv" --dc global --sensitivity
grep -E -q "^  global +64 +[0-9.]+ +[0-9.]+ +[0-9.]+ +[0-9.]+ +- +- +- +250 +- +250$" "$T/out" &&
    pass "constant gyroscopes: their sensitivity columns are '-'" || fail "constant gyroscopes: sensitivity columns"
if "$PY" -c 'import json,sys; r=json.load(open(sys.argv[1]))["result"]; assert r["gyro_fs_hz"] is None and r["fs_hz"] == r["accel_fs_hz"] == 250, r' "$T/gconst.json"; then
    pass "constant gyroscopes: gyro_fs_hz null, answer from the accelerometers"
else
    fail "constant gyroscopes: JSON"
fi
# the plots of such logs: gnuplot got no point for the gyroscopes' (or any) PSD panel, psd.png failed and exit 3, and
# ccdf.png and spectrogram.png were not drawn (docs/psd.md: the tables and plots are still written)
expect_exit 0 "constant gyroscopes, --plot" "$H" psd "$T/gconst.csv" --dc global --plot "$T/gcplots"
for f in psd ccdf spectrogram; do
    [ -s "$T/gcplots/$f.png" ] && pass "constant gyroscopes: $f.png" || fail "constant gyroscopes: $f.png missing"
done
# the CCDF panel of such a group: its title said 'bandwidths 0, 0, 0 Hz' and a flat line at 0 stood for each axis (all
# the power below 0 Hz); the script is read through a stand-in gnuplot (the spectrogram left out, so the CCDF's is last)
fake_gnuplot "$T/fakegp"
PATH="$T/fakegp:$PATH" GP_SCRIPT="$T/ccdf.gp" "$H" psd "$T/gconst.csv" --dc global --plot "$T/gcfake" --spec-nfft 4096 \
    >/dev/null 2>&1
grep -q "gyroscopes (Fig. 4): bandwidths no power" "$T/ccdf.gp" && ! grep -q "bandwidths 0, 0, 0 Hz" "$T/ccdf.gp" &&
    ! grep -q '\$c3 using' "$T/ccdf.gp" && grep -q '\$c0 using' "$T/ccdf.gp" &&
    pass "constant gyroscopes: CCDF panel says no power, draws no gyroscope line" ||
    fail "constant gyroscopes: CCDF panel shows 0 Hz bands or flat lines"
# the CCDF's y axis is not linear, 0 to 1, where the threshold's crossing (1 - 0.95 = 0.05) sits in the bottom 5 % of
# the panel, but logarithmic down to a floor under the threshold line, the
# line drawn, each CCDF point at the floor where it is 0 (a log axis has no 0: the sine's CCDF is 0 past 100 Hz), the
# bandwidth marks from the panel's bottom to its top (at y = 0 on a log axis they would not be drawn)
"$PY" - "$T/ccdf.gp" <<'PYEOF' && pass "CCDF panel: log y axis, floor under the threshold, no point at or under 0" ||
import re, sys
gp = open(sys.argv[1]).read()
bad = []
if "set logscale y" not in gp: bad.append("no log y axis")
m = re.search(r"set yrange \[([^:]+):1\]", gp)
floor = float(m.group(1)) if m else 0.0
if not (0.0 < floor < 0.05): bad.append("floor %r not in (0, 0.05)" % floor)
if gp.count("0.05 with lines dt 2 lc rgb 'black' title 'threshold") != 2: bad.append("threshold line not in both panels")
ys = [float(l.split()[1]) for blk in re.findall(r"\$c\d << EOD\n(.*?)EOD", gp, re.S) for l in blk.splitlines()]
if not ys or min(ys) < floor: bad.append("a CCDF point under the floor: %r" % (min(ys) if ys else None))
if min(ys) > floor: bad.append("no CCDF point at the floor (the sine's CCDF is 0 past 100 Hz)")
if re.search(r"set arrow from [0-9.e+-]+,0 to", gp): bad.append("a bandwidth mark from y = 0")
if "set arrow from first" not in gp: bad.append("no bandwidth mark")
# the gyroscopes' panel, no power: its x axis was gnuplot's -10..10 with nothing drawn; the log's band, and why
if "set label 1 'no power on any axis'" not in gp or "set xrange [0:500]" not in gp: bad.append("no-power panel")
print(bad)
sys.exit(1 if bad else 0)
PYEOF
    fail "CCDF panel: linear y axis, no threshold line, or a point a log axis cannot show"
# the spectrogram's segment times against scipy.signal.spectrogram's t (Hann
# 16, 50 %, on ax: a chirp of growing amplitude, so a column under another
# segment's time shows in its dB too): no time a sample early, the centre
# taken as the last sample - nfft / 2; the periodic Hann window's centre,
# scipy's t, is the first sample + nfft / 2
awk 'BEGIN { srand(7); print "t,ax,ay,az,gx,gy,gz"; for (k = 0; k < 200; k++) { t = k / 100.0
    printf "%.6f,%.7f,%.7f,%.7f,%.7f,%.7f,%.7f\n", t, (1 + t) * sin(2 * 3.141592653589793 * (2 * t + 2 * t * t)) + 0.01 * (rand() - 0.5),
        0.01 * (rand() - 0.5), -9.8 + 0.01 * (rand() - 0.5), 0.001 * (rand() - 0.5), 0.001 * (rand() - 0.5), 0.001 * (rand() - 0.5) } }' >"$T/chirp.csv"
fake_gnuplot "$T/fakegp"
expect_exit 0 "a chirp, --plot with a stand-in gnuplot" env PATH="$T/fakegp:$PATH" GP_SCRIPT="$T/spec.gp" \
    "$H" psd "$T/chirp.csv" --plot "$T/chirpplots" --spec-nfft 16 --spec-axis ax
# the sensitivity plot: at 800 pixels wide its title runs past the right edge on the shared data's paths, and
# without a margin the lines at the lowest and highest answer run along the frame: 900 wide as psd.png, a
# margin above and below, and the key beside the axes, where no line runs through it (the last script the
# stand-in kept is the sensitivity plot's)
awk 'BEGIN { srand(3); print "t,ax,ay,az,gx,gy,gz"; for (k = 0; k < 3000; k++) { t = k / 200.0
    printf "%.6f,%.7f,%.7f,%.7f,%.7f,%.7f,%.7f\n", t, sin(2 * 3.141592653589793 * 5 * t) + 0.3 * (rand() - 0.5), 0.1 * (rand() - 0.5),
        -9.8 + 0.5 * (rand() - 0.5), 0.5 * sin(2 * 3.141592653589793 * 2 * t), 0.01 * (rand() - 0.5), 0.01 * (rand() - 0.5) } }' >"$T/sens.csv"
expect_exit 0 "--sensitivity --plot with a stand-in gnuplot" env PATH="$T/fakegp:$PATH" GP_SCRIPT="$T/sens.gp" \
    "$H" psd "$T/sens.csv" --plot "$T/sensplots" --sensitivity --round 1
grep -q "^set title 'Lowest usable sampling frequency" "$T/sens.gp" && grep -q "size 900,500" "$T/sens.gp" &&
    grep -q "^set offsets 0, 0, graph 0.05, graph 0.05$" "$T/sens.gp" && grep -q "^set key outside right top$" "$T/sens.gp" &&
    pass "sensitivity.png: 900 wide, a margin above and below its lines, the key beside the axes" ||
    fail "sensitivity.png: $(grep -E 'size|offsets' "$T/sens.gp")"
# the spectrogram's options without --plot are refused, not ignored with exit 0
expect_exit 2 "--spec-axis without --plot" "$H" psd "$T/sens.csv" --spec-axis gx
expect_err "--spec-axis sets the spectrogram of --plot DIR (spectrogram.png): give --plot DIR" "--spec-axis without --plot: named"
expect_exit 2 "--spec-nfft without --plot" "$H" psd "$T/sens.csv" --spec-nfft 128
expect_err "--spec-nfft sets the spectrogram of --plot DIR" "--spec-nfft without --plot: named"
# the Welch work itself shows progress: --nfft 4096 --overlap 4095 on a 1,000,000-sample static log is a
# transform per sample, minutes that would pass without a word once "psd: reading" ends; 20,000
# samples take about 3 s here: the progress lines (one per 10 % off a terminal) name the work
awk 'BEGIN { srand(9); print "t,ax,ay,az,gx,gy,gz"; for (k = 0; k < 20000; k++) printf "%.4f,%.5f,%.5f,%.5f,%.6f,%.6f,%.6f\n", k / 100.0, rand() - 0.5, rand() - 0.5, -9.8 + rand() - 0.5, 0.01 * (rand() - 0.5), 0.01 * (rand() - 0.5), 0.01 * (rand() - 0.5) }' >"$T/long.csv"
expect_exit 0 "--nfft 4096 --overlap 4095 on 20,000 samples" "$H" psd "$T/long.csv" --nfft 4096 --overlap 4095
grep -q "^psd: Welch: *[0-9]* %" "$T/err" && pass "the Welch work shows progress" || fail "no Welch progress: $(head -c 300 "$T/err")"
# a long log's spectrogram: every segment x every bin went to gnuplot as text (1 M samples: 90 s against 3 s
# without --plot; 3 M: 366 MB in gnuplot); consecutive periodograms are averaged in power into at most 2,000
# columns, said on the time axis, and the numbers of the CSV and JSON stay as they were. 20,000 samples, --spec-nfft 16:
# 2,499 segments, 2 a column (the last, alone, left out), each the mean of scipy's two at the mean of their times
expect_exit 0 "a 20,000-sample spectrogram with a stand-in gnuplot" env PATH="$T/fakegp:$PATH" GP_SCRIPT="$T/lspec.gp" \
    "$H" psd "$T/long.csv" --plot "$T/longplots" --spec-nfft 16 --spec-axis ax --json "$T/long_avg.json"
grep -q "^set xlabel 'time \[s\] (2 segments averaged in power per column)'" "$T/lspec.gp" &&
    pass "a long spectrogram's time axis says the periodograms averaged" || fail "long spectrogram xlabel: $(grep xlabel "$T/lspec.gp")"
expect_exit 0 "the same log without --plot" "$H" psd "$T/long.csv" --json "$T/long_np.json"
"$PY" -c 'import json, sys
a, b = (json.load(open(f)) for f in sys.argv[1:3])
for k in ("source", "log"): a.pop(k, None); b.pop(k, None)
sys.exit(0 if a == b else 1)' "$T/long_avg.json" "$T/long_np.json" && pass "the JSON with --plot as without" ||
    fail "the JSON differs with --plot"
if "$PY" -c 'import scipy' 2>/dev/null; then
    if "$PY" - "$T/long.csv" "$T/lspec.gp" >"$T/pyout" 2>&1 <<'PYEOF'
import sys
import numpy as np
from scipy.signal import spectrogram
d = np.loadtxt(sys.argv[1], delimiter=",", skiprows=1)
f, t, S = spectrogram(d[:, 1], fs=100.0, window="hann", nperseg=16, noverlap=8)
lines = open(sys.argv[2]).read().split("$s << EOD\n")[1].split("EOD\n")[0].split("\n")
rows = np.array([[float(v) for v in l.split()] for l in lines if l.strip()])
ts = np.unique(rows[:, 0])
n = len(t) // 2
assert len(ts) == n <= 2000, (len(ts), len(t))
tm = 0.5 * (t[0:2 * n:2] + t[1:2 * n:2])
Sm = 0.5 * (S[:, 0:2 * n:2] + S[:, 1:2 * n:2])
assert np.allclose(ts, tm, rtol=1e-5, atol=1e-6), (ts[:4], tm[:4])
for j in (0, 1, n // 2, n - 1):
    r = rows[np.abs(rows[:, 0] - tm[j]) < 0.03]
    assert np.allclose(r[:, 2], 10 * np.log10(Sm[:, j]), atol=0.02), (tm[j], r[:3, 2], 10 * np.log10(Sm[:3, j]))
print("%d columns of %d segments" % (n, len(t)))
PYEOF
    then pass "a long spectrogram: pairs of scipy's periodograms averaged ($(cat "$T/pyout"))"
    else fail "a long spectrogram against scipy: $(tail -n 3 "$T/pyout")"; fi
else
    echo "skip: no scipy in $PY (long spectrogram)"
fi
# the colour bar's label would sit on its tick labels ("-10", "-20" under "PSD [dB re 1 (m/s^2)^2/Hz]" on the 820 Hz
# walk): it is moved out past them
grep -q "^set cblabel 'PSD \[dB re 1 (m/s^2)^2/Hz\]' offset 2.5,0$" "$T/spec.gp" &&
    pass "the spectrogram's colour-bar label is offset from its tick labels" || fail "cblabel: $(grep cblabel "$T/spec.gp")"
if "$PY" -c 'import scipy' 2>/dev/null; then
    if "$PY" - "$T/chirp.csv" "$T/spec.gp" >"$T/pyout" 2>&1 <<'PYEOF'
import sys
import numpy as np
from scipy.signal import spectrogram
d = np.loadtxt(sys.argv[1], delimiter=",", skiprows=1)
f, t, S = spectrogram(d[:, 1], fs=100.0, window="hann", nperseg=16, noverlap=8)
lines = open(sys.argv[2]).read().split("$s << EOD\n")[1].split("EOD\n")[0].split("\n")
rows = np.array([[float(v) for v in l.split()] for l in lines if l.strip()])
ts = np.unique(rows[:, 0])
assert len(ts) == len(t), (len(ts), len(t))
assert np.allclose(ts, t, rtol=0, atol=1e-6), (ts[:4], t[:4])
for j, tj in enumerate(t):
    r = rows[np.abs(rows[:, 0] - tj) < 1e-6]
    assert np.allclose(r[:, 1], f, atol=1e-6)
    assert np.allclose(r[:, 2], 10 * np.log10(S[:, j]), atol=0.02), (tj, r[:3, 2], 10 * np.log10(S[:3, j]))
print("%d segments, first at %g s" % (len(t), t[0]))
PYEOF
    then pass "spectrogram times and dB as scipy's ($(cat "$T/pyout"))"; else fail "spectrogram against scipy: $(tail -n 3 "$T/pyout")"; fi
else
    echo "skip: no scipy in $PY (spectrogram times)"
fi
expect_exit 1 "every channel constant, --plot" "$H" psd "$T/const.csv" --plot "$T/cplots"
for f in psd ccdf spectrogram; do
    [ -s "$T/cplots/$f.png" ] && pass "every channel constant: $f.png" || fail "every channel constant: $f.png missing"
done
# the sensitivity plot of such logs: one value on every row (50 Hz) must not make gnuplot warn "empty y range" on
# standard error, nor a log of zeros, no value at all, fail it ("all points y value undefined") with exit 3 instead
# of 1
expect_exit 1 "every channel constant, --plot --sensitivity" "$H" psd "$T/const.csv" --plot "$T/csplots" --sensitivity
[ -s "$T/csplots/sensitivity.png" ] && ! grep -qi "warning: empty\|gnuplot" "$T/err" &&
    pass "constant log: sensitivity.png without a gnuplot warning" || fail "constant log sensitivity: $(cat "$T/err")"
awk 'BEGIN { print "t,ax,ay,az,gx,gy,gz"; for (i = 0; i < 2000; i++) printf "%.3f,0,0,0,0,0,0\n", i / 1000.0 }' >"$T/zero.csv"
expect_exit 1 "a log of zeros, --plot --sensitivity" "$H" psd "$T/zero.csv" --plot "$T/zplots" --sensitivity
for f in psd ccdf spectrogram sensitivity; do
    [ -s "$T/zplots/$f.png" ] && pass "log of zeros: $f.png" || fail "log of zeros: $f.png missing"
done
! grep -qi "gnuplot\|undefined" "$T/err" && pass "log of zeros: no gnuplot error" || fail "log of zeros: $(cat "$T/err")"
# a log shorter than the spectrogram's segment (100 samples, --nfft 64, the default --spec-nfft 256): no spectrogram
# can be drawn; the other plots are, a warning says why it is missing (gnuplot got no data: its STATS_max was
# undefined, a spectrogram.png was left behind and the command exited 3, an output failure)
head -101 "$T/tone.csv" >"$T/short.csv"
expect_exit 0 "log shorter than the spectrogram segment, --plot" "$H" psd "$T/short.csv" --plot "$T/shortplots"
expect_err "^harness psd: warning: $T/short.csv: fewer samples (100) than one spectrogram segment (--spec-nfft 256)" \
    "the missing spectrogram is explained, naming the log"
[ -s "$T/shortplots/psd.png" ] && [ -s "$T/shortplots/ccdf.png" ] && pass "short log: psd.png, ccdf.png" ||
    fail "short log: psd.png or ccdf.png missing"
[ ! -e "$T/shortplots/spectrogram.png" ] && pass "short log: no spectrogram.png" || fail "short log: spectrogram.png written"
# an input whose name has a quote: unescaped in the plots' titles, it would end gnuplot's string, and --plot
# exit 3 with psd.png drawn from a broken script and no ccdf.png
cp "$T/tone.csv" "$T/it's.csv"
expect_exit 0 "input named with a quote, --plot --sensitivity" "$H" psd "$T/it's.csv" --plot "$T/qplots" --sensitivity
for f in psd ccdf spectrogram sensitivity; do
    [ -s "$T/qplots/$f.png" ] && pass "quoted input: $f.png" || fail "quoted input: $f.png missing"
done
! grep -q "gnuplot>" "$T/err" && pass "quoted input: no gnuplot error" || fail "quoted input: gnuplot error"
# a --plot directory whose name has a line break (and a tab, a backslash, a double quote): gnuplot's string must not
# take the break for a space, write "a b/psd.png" elsewhere or nowhere, and --plot exit 3
NLD="$T/a
b	c\\d\"e"
expect_exit 0 "a --plot directory named with a line break" "$H" psd "$T/tone.csv" --plot "$NLD"
for f in psd ccdf spectrogram; do
    [ -s "$NLD/$f.png" ] && pass "line-break directory: $f.png" || fail "line-break directory: $f.png missing"
done
# a --plot directory with a long name (720 bytes, well under PATH_MAX): no picture's path is cut (to 600 bytes by
# psd or to 511 by the plot session, which then looks for the cut name: "gnuplot failed to write" and exit 3 with
# psd.png drawn, and no other plot)
L=$T/$(printf '%0200d' 0)/$(printf '%0200d' 0)/$(printf '%0200d' 0)/$(printf '%0100d' 0)
mkdir -p "$L"
expect_exit 0 "a --plot directory with a 720-byte name" "$H" psd "$T/tone.csv" --plot "$L/p" --sensitivity
for f in psd ccdf spectrogram sensitivity; do
    [ -s "$L/p/$f.png" ] && pass "long directory: $f.png" || fail "long directory: $f.png missing"
done
# a log of one spectrogram segment (300 samples, --spec-nfft 256: the next needs 384): gnuplot's image of one column
# is nothing, and a blank spectrogram.png is not written without a word; not drawn, said
head -301 "$T/tone.csv" >"$T/oneseg.csv"
expect_exit 0 "log of one spectrogram segment, --plot" "$H" psd "$T/oneseg.csv" --plot "$T/oneplots"
expect_err "^harness psd: warning: $T/oneseg.csv: one spectrogram segment (300 samples, --spec-nfft 256 needs 384 for two)" \
    "the missing spectrogram is explained, naming the log"
[ -s "$T/oneplots/psd.png" ] && [ ! -e "$T/oneplots/spectrogram.png" ] && pass "one segment: psd.png, no blank spectrogram.png" ||
    fail "one segment: $(ls "$T/oneplots")"
# a static log: every PSD value below 1 unit^2/Hz, so every dB value of the spectrogram is negative;
# gnuplot's one-column stats dropped them all (outside the frequency axis' range) and --plot exited 3
awk 'BEGIN { srand(7); print "t,ax,ay,az,gx,gy,gz"; for (i = 0; i < 6000; i++)
     printf "%.2f,%.5f,%.5f,%.5f,%.6f,%.6f,%.6f\n", i / 100.0, 0.05 * (rand() - 0.5), 0.05 * (rand() - 0.5),
            9.81 + 0.05 * (rand() - 0.5), 0.007 * (rand() - 0.5), 0.007 * (rand() - 0.5), 0.007 * (rand() - 0.5) }' >"$T/static.csv"
expect_exit 0 "static log, --plot --sensitivity" "$H" psd "$T/static.csv" --plot "$T/splots" --sensitivity
for f in psd ccdf spectrogram sensitivity; do
    [ -s "$T/splots/$f.png" ] && pass "static $f.png" || fail "static $f.png missing"
done
# the same log at its own 100 Hz: white noise to the 50 Hz Nyquist frequency, 2 x 47.5 Hz rounds up to exactly the
# log's rate, so fs_above_log_rate stays false; the answer is not printed as a measured "100 Hz (the accelerometers
# limit it)" without a word, as it is the log's rate by construction
expect_exit 0 "static log at 100 Hz" "$H" psd "$T/static.csv" --json "$T/s100.json"
expect_err "of the Nyquist frequency 50 Hz: the power does not fall off" "a band at the Nyquist frequency is flagged below the log's rate"
expect_err "^harness psd: warning: $T/static.csv: 95 % of the power reaches" "the band-at-Nyquist warning names the log"
expect_out "accelerometers and gyroscopes alike" "a tie between the groups is not called the accelerometers'"
expect_out "DC: each segment's mean removed (a high-pass near f_s/nfft = 1.56 Hz" "the output states its DC treatment"
expect_out "band from 0 Hz holding 95 % of the total power" "the output states its criterion"
"$PY" -c 'import json,sys; d=json.load(open(sys.argv[1])); assert d["band_at_nyquist"] is True and d["fs_above_log_rate"] is False and d["result"]["fs_hz"] == 100, d' "$T/s100.json" &&
    pass "JSON band_at_nyquist on a static log" || fail "JSON band_at_nyquist on a static log"
# ... and not only the warning says that 100 Hz is a lower bound, as the summary line would read as a measurement,
# and the JSON's band_at_nyquist is true also where the rounding alone lifts the answer (below): the summary line
# says so, and the JSON's fs_is_lower_bound and fs_lower_bound_hz
expect_out_re "^  lowest usable sampling frequency: 100 Hz \(accelerometers and gyroscopes alike; 95 % of the power, multiples of 50 Hz\), only a lower bound \(95 % of the power reaches 4[0-9.]+ Hz, 9[0-9] % of the Nyquist frequency: the log cannot show where the band ends\) \(--dc segment, " \
    "static log at 100 Hz: the summary line says the answer is a lower bound"
"$PY" -c 'import json,sys; d=json.load(open(sys.argv[1])); assert d["fs_is_lower_bound"] is True and d["fs_lower_bound_hz"] == 100, d' "$T/s100.json" &&
    pass "JSON fs_is_lower_bound on a static log" || fail "JSON fs_is_lower_bound on a static log: $(head -c 300 "$T/s100.json")"
# the same log at 10 Hz: white noise to the 5 Hz Nyquist frequency, 2 x 4.75 Hz rounded up to 50 Hz, above the
# log's own rate: said, and marked in the JSON
awk -F, 'NR == 1 { print; next } { $1 = sprintf("%.1f", (NR - 2) / 10.0); print }' OFS=, "$T/static.csv" >"$T/static10.csv"
expect_exit 0 "static log at 10 Hz" "$H" psd "$T/static10.csv" --json "$T/s10.json"
expect_err "is above the log's own rate (10 Hz)" "an answer above the log's rate is flagged"
# each warning of the log's data names the log, as allan's do (these four did not: 'psd: warning: 95 % of the power
# reaches ...'; the mutation sweep of stop 93)
expect_err "^harness psd: warning: $T/static10.csv: the answer (50 Hz) is above the log's own rate" \
    "the answer-above-the-rate warning names the log"
"$PY" -c 'import json,sys; d=json.load(open(sys.argv[1])); assert d["fs_above_log_rate"] is True and d["band_at_nyquist"] is True and d["result"]["fs_hz"] == 50, d' "$T/s10.json" &&
    pass "JSON fs_above_log_rate" || fail "JSON fs_above_log_rate"
# above the log's rate the bound is the rate itself (the warning's "read it as 'at least 10 Hz'"), not the answer
expect_out_re "^  lowest usable sampling frequency: 50 Hz \(.*\), only a lower bound of 10 Hz, the log's rate \(95 % of the power reaches 4[0-9.]+ Hz, 9[0-9] % of the Nyquist frequency: the log cannot show where the band ends\)" \
    "static log at 10 Hz: the summary line gives the lower bound, the log's rate"
"$PY" -c 'import json,sys; d=json.load(open(sys.argv[1])); assert d["fs_is_lower_bound"] is True and d["fs_lower_bound_hz"] == 10, d' "$T/s10.json" &&
    pass "JSON fs_lower_bound_hz above the log's rate: the rate" || fail "JSON fs_lower_bound_hz at 10 Hz: $(head -c 300 "$T/s10.json")"
# a rounding step above the rate (--round 2000 on the 1000 Hz tone, band 115 Hz): the answer exceeds the rate through
# the rounding alone, which is said, not that 95 % of the power 'reaches 115.4 Hz, near the Nyquist frequency 500 Hz'
expect_exit 0 "tone, --round 2000" "$H" psd "$T/tone.csv" --round 2000
expect_out_re "^  lowest usable sampling frequency: 2000 Hz \([^)]*\) \(--dc segment[^)]*\)$" \
    "--round 2000: the band ends inside the log's, the answer is no lower bound"
expect_err "^harness psd: warning: $T/tone.csv: the answer (2000 Hz) is above the log's own rate (1000 Hz) only through the rounding to multiples of 2000 Hz" \
    "an answer above the rate by the rounding alone is said so"
! grep -q "near the Nyquist" "$T/err" && pass "--round 2000: a 115 Hz band is not called near the 500 Hz Nyquist frequency" ||
    fail "--round 2000: a 115 Hz band called near the Nyquist frequency"
"$PY" -c 'import json,sys; d=json.load(open(sys.argv[1])); assert d["fs_above_log_rate"] is False and d["band_at_nyquist"] is False' "$T/tone.json" &&
    pass "JSON fs_above_log_rate false below the rate" || fail "fs_above_log_rate on the tone"
"$PY" -c 'import json,sys; d=json.load(open(sys.argv[1])); assert d["fs_is_lower_bound"] is False and d["fs_lower_bound_hz"] is None' "$T/tone.json" &&
    pass "JSON fs_is_lower_bound false, fs_lower_bound_hz null, on the tone" || fail "fs_is_lower_bound on the tone"
expect_exit 0 "tone, --round 2000, --json" "$H" psd "$T/tone.csv" --round 2000 --json "$T/tone2000.json"
"$PY" -c 'import json,sys; d=json.load(open(sys.argv[1])); assert d["fs_above_log_rate"] is True and d["band_at_nyquist"] is True and d["fs_is_lower_bound"] is False and d["fs_lower_bound_hz"] is None, d' "$T/tone2000.json" &&
    pass "JSON: above the rate by the rounding alone, no lower bound" || fail "fs_is_lower_bound with --round 2000: $(head -c 300 "$T/tone2000.json")"
# a value beyond any sensor (and the core's input range): exit 1, the line and column named
awk -F, 'NR == 102 { $5 = "1e30" } { print }' OFS=, "$T/tone.csv" >"$T/huge.csv"
expect_exit 1 "a sample beyond float range" "$H" psd "$T/huge.csv"
expect_err "huge.csv:102: column 5 (.1e30.) is beyond" "the out-of-range value is named with its line and column"
{ echo t,ax,ay,az,gx,gy,gz; i=0; while [ $i -lt 300 ]; do echo 5,0.1,0.2,9.8,0.01,0.02,0.03; i=$((i + 1)); done; } > "$T/same.csv"
expect_exit 1 "time stamps that never advance" "$H" psd "$T/same.csv"
expect_err "sample rate unknown: every time stamp is the same" "says why there is no rate (was: nfft 64 at inf Hz)"
# with the count and the question allan and simgap ask (was the bare phrase; cli_mutation_sweep.py --seed 100, c0078)
expect_err "same.csv: sample rate unknown: every time stamp is the same (all 300 samples at one time): is the time column filled?" \
    "stamps that never advance: the samples counted, the time column questioned"
# the same stamps, then a bad line: the cause is still the rate (not 'the 300 samples before it are fewer than one
# 64-sample segment', which is false)
{ cat "$T/same.csv"; echo 5,x,1,1,1,1,1; } >"$T/samebad.csv"
expect_exit 1 "time stamps that never advance, then a bad line" "$H" psd "$T/samebad.csv"
expect_err "sample rate unknown: every time stamp is the same" "a bad line after stamps that never advance: the rate is named"
! grep -q "fewer than one" "$T/err" && pass "300 samples are not called fewer than one 64-sample segment" ||
    fail "300 samples called fewer than one 64-sample segment"
# a bad line after 43 samples, fewer than one segment: the line is said once, in the warning when it is read, and
# the error names the log, as simgap's and info's (the error repeated 'FILE:45: ... is not a number'; a CLI mutation
# sweep's find, --seed 102 c0118)
head -45 "$T/tone.csv" >"$T/shortbad.csv"; echo 0.045,x,1,1,1,1,1 >>"$T/shortbad.csv"
expect_exit 1 "a bad line after 44 samples" "$H" psd "$T/shortbad.csv"
expect_err "shortbad.csv:46: column 2 ('x') is not a number (using the 44 samples before it)" "a bad line: warned when read"
expect_err "shortbad.csv: incomplete input (warned above): the 44 samples before the error are fewer than one 64-sample segment$" \
    "a bad line before one segment: the error names the log, the samples counted"
[ "$(grep -c "is not a number" "$T/err")" -eq 1 ] && pass "a bad line before one segment: the line said once" ||
    fail "a bad line before one segment: the line said $(grep -c "is not a number" "$T/err") times"
# one stamped sample: too short, not a rate to give (not 'sample rate unknown; give --input-rate', an option the
# stamped CSV ignores)
head -2 "$T/same.csv" >"$T/one.csv"
expect_exit 1 "one stamped sample" "$H" psd "$T/one.csv" --input-rate 100
expect_err "1 sample, fewer than one 64-sample segment" "one sample: too short for a segment (singular)"
expect_err "fewer than one 64-sample segment; a Welch segment needs at least 8 samples: the log is too short for a spectrum$" "one sample: the least a segment needs, and no --nfft offered (none helps)"
# 11 samples: --nfft 8, the least, not "--nfft 8 or less" (--nfft 4 is refused)
head -12 "$T/same.csv" | awk -F, 'NR == 1 { print; next } { $1 = (NR - 2) / 100; print }' OFS=, >"$T/eleven.csv"
expect_exit 1 "11 samples" "$H" psd "$T/eleven.csv"
expect_err "eleven.csv: 11 samples, fewer than one 64-sample segment; give --nfft 8 (the least)$" "11 samples: --nfft 8, not '8 or less'"
# 1001 samples with --nfft 4096: the error says what to do, not only what is missing
awk 'BEGIN { print "t,ax,ay,az,gx,gy,gz"; for (i = 0; i < 1001; i++) printf "%.3f,%.4f,0,9.81,0,0,%.4f\n", i / 100, sin(i), cos(i) }' > "$T/k1.csv"
expect_exit 1 "1001 samples, --nfft 4096" "$H" psd "$T/k1.csv" --nfft 4096
expect_err "k1.csv: 1001 samples, fewer than one 4096-sample segment; give --nfft 512 or less (a power of two)" \
    "a log shorter than a segment: the --nfft that fits is named"
! grep -q "give --input-rate" "$T/err" && pass "one stamped sample: no advice to give --input-rate" ||
    fail "one stamped sample: told to give --input-rate"
# stamps printed to the millisecond at about 398 Hz (2 and 3 ms intervals): the rate from the stamps, not 333 or 500 Hz
awk 'BEGIN { print "t,ax,ay,az,gx,gy,gz"; for (i = 0; i < 3000; i++) printf "%.3f,%.4f,0,9.81,0,0,%.4f\n", i / 398.3, sin(i), cos(i) }' > "$T/ms.csv"
expect_exit 0 "stamps rounded to the millisecond" "$H" psd "$T/ms.csv" --json "$T/ms.json"
expect_out_re "398\.[0-9]+ Hz" "the rate is read from the spans of the stamps"
# those samples are uniform: only their stamps are rounded (to 1 ms, of a 2.5 ms period); it warned '2999 of 2999
# intervals differ from 1/398.3 s by more than 10 %: Welch assumes uniform sampling'
! grep -q "intervals differ" "$T/err" && pass "millisecond stamps of uniform samples: no irregular-sampling warning" ||
    fail "millisecond stamps of uniform samples called irregular: $(cat "$T/err")"
# the same stamps with 30 samples lost (one every 100 rows): those 30 intervals are irregular
awk 'NR == 1 || (NR - 1) % 100 != 50' "$T/ms.csv" >"$T/msgap.csv"
expect_exit 0 "millisecond stamps with lost samples" "$H" psd "$T/msgap.csv"
expect_err "30 of 2969 intervals differ" "lost samples under millisecond stamps are counted"
expect_err "^harness psd: warning: $T/msgap.csv: 30 of 2969 intervals differ" "the irregular-intervals warning names the log"
# 100 Hz stamps printed to 10 ms (exact intervals: the period is one resolution) with 30 single samples lost: each
# 20 ms interval is within 10 % + the 10 ms resolution of 10 ms, which must not leave them without a warning
awk 'BEGIN { print "t,ax,ay,az,gx,gy,gz"; for (i = 0; i < 3000; i++) if (i % 100 != 50) printf "%.2f,%.4f,0,9.81,0,0,%.4f\n", i / 100, sin(i), cos(i) }' > "$T/cs.csv"
expect_exit 0 "10 ms stamps at 100 Hz with lost samples" "$H" psd "$T/cs.csv"
expect_err "30 of 2969 intervals differ" "single lost samples under stamps of one period's resolution are counted"
# the time column in milliseconds (100 Hz read as 0.1 Hz): not only "the answer (50 Hz) is above the log's own rate
# (0.1 Hz)" hints at it; the unit and the divisor are named, the status unchanged (0)
awk 'BEGIN { print "t,ax,ay,az,gx,gy,gz"; for (i = 0; i < 3000; i++) printf "%d,%.4f,0,9.81,0,0,%.4f\n", i * 10, sin(i), cos(i) }' > "$T/tms.csv"
expect_exit 0 "time stamps in milliseconds" "$H" psd "$T/tms.csv"
expect_err "the samples are 10 s apart (0.1 Hz): are the time stamps in seconds? (they look like milliseconds, a 100 Hz log: give --units time=ms)" \
    "time in milliseconds is named, with the --units item"
# the other way: read with --units time=ns, 1e6 times too fast (100 MHz), not without a word: the unit that fits
# is named
expect_exit 0 "time stamps in milliseconds read as ns" "$H" psd "$T/tms.csv" --units time=ns
expect_err "the samples are 1e-08 s apart (1e+08 Hz): are the time stamps in nanoseconds? (they look like milliseconds, a 100 Hz log: give --units time=ms)" \
    "stamps too fast: ms read as ns told time=ms"
# stamps in bursts (packets of 4 samples stamped 5 us apart as a logger reads them, every 10 ms: the walk of
# vectors/walk.bin, 400 Hz over the log), in us read as such: psd must not warn "are the time stamps in
# microseconds? (they look like milliseconds, a 200 Hz log: give --units time=ms)", 1000 times too slow, where replay
# judges the log's span too; the same test (hx_time_unit_rate)
expect_exit 0 "convert the walk to CSV (stamps in bursts)" "$H" convert vectors/walk.bin "$T/bw.csv"
awk -F, 'NR == 1 { print; next } { i = NR - 2; printf "%d,%s,%s,%s,%s,%s,%s\n", (int(i / 4) + 1) * 10000 + 5 * (i % 4), $2, $3, $4, $5, $6, $7 }' \
    "$T/bw.csv" > "$T/burst_us.csv"
expect_exit 0 "stamps in bursts, read as us" "$H" psd "$T/burst_us.csv" --units time=us
# a CSV names no sensor: the first line names the format ("(csv log)"), not "(unknown)", as allan and info
# do; the JSON's sensor stays the reader's "unknown"
expect_out "^harness psd: $T/burst_us.csv (csv log), 16539 samples" "psd: a CSV's first line names the format, as allan's does"
if grep -q "are the time stamps in\|look like" "$T/err"; then fail "psd: stamps in bursts told a time unit: $(cat "$T/err")"; else
    pass "psd: stamps in bursts (400 Hz over the log) told no time unit"; fi
# ... but its frequencies, read at 200 kHz, are not given with only "intervals differ ...: Welch assumes uniform
# sampling"; a warning names the rate over the span and --input-rate (exit 0)
expect_err "psd: warning: $T/burst_us.csv: the time stamps come in bursts (samples stamped close together as a logger reads them?): 1 / their median interval gives 200000 Hz, but the 16539 samples span 41.34 s, 400 Hz; the frequencies are read at 2e+05 Hz, the stamps' rate, not the sampling rate: leave the time column out and give --input-rate 400 (docs/harness.md, \"Time stamps in bursts\")" \
    "psd: stamps in bursts warned, the stamps' rate said, 400 Hz and --input-rate named"
# the same stamps in a .bin whose header states 400 Hz (nominal): the frequencies are read at it, which the span
# keeps; it is not told "not the sampling rate"
"$H" convert "$T/burst_us.csv" "$T/burst_us.bin" --units time=us >/dev/null 2>&1 || fail "psd: convert the bursts to .bin"
bin_rate "$T/burst_us.bin" "$T/burst_nom.bin" 400 || fail "psd: the .bin's rate set"
expect_exit 0 "stamps in bursts, the .bin's stated 400 Hz" "$H" psd "$T/burst_nom.bin"
expect_err "400 Hz; the frequencies are read at 400 Hz, the rate the file states, which the samples' span keeps, not the stamps' 200000 Hz (docs/harness.md, \"Time stamps in bursts\")" \
    "psd: stamps in bursts at the stated rate: the rate and its source said"
grep -q "not the sampling rate" "$T/err" && fail "psd: stated rate kept by the span told 'not the sampling rate'" || pass "psd: stated rate kept by the span, not told 'not the sampling rate'"
grep -q "file states [0-9]" "$T/err" && fail "psd: stamps in bursts at the stated rate also told the stated-rate warning" || pass "psd: stamps in bursts: the burst warning alone"
# a .bin whose header states a rate its stamps contradict (1000 Hz stated, stamps 5 ms apart): psd does not analyse
# it at the stated rate without a word, but gives info's warning (hx_stated_rate_warn); a
# stated rate within 10 % of the stamps' (215 Hz), and the log's own 200 Hz, are not questioned
"$H" sim --motion stand:20 --rate 200 --out "$T/sr200.bin" >/dev/null 2>&1 || fail "psd: sim of a 200 Hz .bin"
bin_rate "$T/sr200.bin" "$T/sr1000.bin" 1000 && bin_rate "$T/sr200.bin" "$T/sr215.bin" 215 || fail "psd: the .bin's rate set"
expect_exit 0 "psd of a .bin stating 1000 Hz over 5 ms stamps (runs, as before)" "$H" psd "$T/sr1000.bin"
expect_err "^harness psd: warning: $T/sr1000.bin: the file states 1000 Hz, but its time stamps give 200 Hz (5.000 ms apart): the frequencies are read at the stated rate; if the stamps are right, convert it to CSV (bin/harness convert $T/sr1000.bin out.csv), whose rate comes from its stamps" \
    "psd: a stated rate the stamps contradict warned of, with the remedy"
for f in sr215 sr200; do
    expect_exit 0 "psd of $f.bin" "$H" psd "$T/$f.bin"
    grep -q "file states [0-9]" "$T/err" && fail "psd: $f.bin's stated rate questioned: $(cat "$T/err")" || pass "psd: $f.bin's stated rate (within 10 %) not questioned"
done
expect_exit 0 "psd of the bundled walk" "$H" psd vectors/walk.bin
grep -q "come in bursts" "$T/err" && fail "psd: the bundled walk warned of bursts" || pass "psd: the bundled walk, no burst warning"

O=$(data openshoe_c_820hz/OpenShoeDataSet.txt)
if [ -n "$O" ]; then
    expect_exit 0 "820 Hz walk, paper settings" "$H" psd "$O" --input-rate 820 --json "$T/o.json" --out "$T/o.csv" \
        --plot "$T/plots" --sensitivity
    # per-segment mean, Hamming 64: vertical accelerometer near 220 Hz -> 450 Hz (issue #4)
    "$PY" -c 'import json,sys; r=json.load(open(sys.argv[1]))["result"]; assert r["fs_hz"] == 450 and 200 < r["axes"]["az"]["bandwidth_hz"] < 240, r' "$T/o.json" &&
        pass "paper setting answer" || fail "paper setting answer"
    for f in psd ccdf spectrogram sensitivity; do
        [ -s "$T/plots/$f.png" ] && pass "$f.png" || fail "$f.png missing"
    done
    grep -q "^  global    1024" "$T/out" && pass "sensitivity table" || fail "sensitivity table"
    expect_exit 0 "820 Hz walk, recommended" "$H" psd "$O" --input-rate 820 --dc global --nfft 256 --json "$T/g.json"
    "$PY" -c 'import json,sys; d=json.load(open(sys.argv[1])); r=d["result"]; assert r["fs_hz"] == 300 and d["band_at_nyquist"] is False, d' "$T/g.json" &&
        pass "recommended setting answer" || fail "recommended setting answer"
else
    echo "SKIP 820 Hz walk tests (shared data not found; set FNAV_DATA_DIR)"
fi
A=$(data adis16405_static/adis16405_imu1_100Hz.csv.gz)
R=$(data allan_reference/derived_thirdparty/adis16405_imu1_welch_scipy.csv)
if [ -n "$A" ] && [ -n "$R" ]; then
    # scipy.signal.welch (third party: Hann, nperseg 4096, 50 %, constant detrend, density) of gyro x and acc x of
    # ADIS log 1: every bin within its derived bound (scripts/psd_scipy_bound.py, whose docstring derives it: the
    # float arithmetic of fnav_welch and fnav_fft to first order, worst case, from each segment's own values and
    # partial DFTs; the reference's double arithmetic; the %.6g and %.9g printing), every frequency within the two
    # printing bounds (a derived bound, not a tolerance measured on the result: 1e-3 of the bin or 1e-6 of the
    # largest bin, and 1e-4 Hz)
    expect_exit 0 "ADIS log 1, scipy's setting" "$H" psd "$A" --nfft 4096 --window hann --dc segment --out "$T/a.csv"
    if "$PY" "$(dirname "$0")/../../scripts/psd_scipy_bound.py" "$A" "$R" "$T/a.csv" >"$T/bound" 2>&1
    then pass "Welch at nfft 4096 = scipy on ADIS log 1 (gyro x, acc x, every bin within its derived bound)"
    else fail "Welch 4096 vs scipy: $(cat "$T/bound")"; fi
else
    echo "SKIP ADIS16405 Welch test (shared data not found; set FNAV_DATA_DIR)"
fi
# --- --json of a log cut by a bad line: complete false and the reader's
# error, as info's, replay's, allan's and simgap's (not complete without
# error); a whole log complete true
awk 'BEGIN { srand(2); print "t,ax,ay,az,gx,gy,gz"; for (i = 0; i < 3000; i++) { g = (i == 1500) ? "nan" : sprintf("%.5f", 0.01 * (rand() - 0.5));
    printf "%.3f,%.4f,0.05,9.81,%s,0.001,0\n", i / 200, 0.01 * (rand() - 0.5), g } }' >"$T/nanrow.csv"
expect_exit 1 "psd of a log with a NaN half way, --json" "$H" psd "$T/nanrow.csv" --json "$T/nanrow.json"
json "$T/nanrow.json" 'j["complete"] is False and j["error"].endswith("nanrow.csv:1502: column 5 (\x27nan\x27) is NaN or Inf") and j["samples"] == 1500' &&
    pass "psd --json of a cut log: complete false, the reader's error" || fail "psd --json of a cut log: $(tr -d '\n\t' <"$T/nanrow.json" | tail -c 300)"
expect_err "error: .*nanrow.csv: incomplete input (warned above): the results cover the 1500 samples before the error" \
    "psd of a cut log: the closing error names the log (it named none)"
expect_exit 0 "psd of a whole log, --json" "$H" psd vectors/walk.bin --json "$T/whole.json"
json "$T/whole.json" 'j["complete"] is True and "error" not in j' && pass "psd --json of a whole log: complete true, no error" ||
    fail "psd --json of a whole log: $(tr -d '\n\t' <"$T/whole.json" | tail -c 200)"

# --- the --out CSV's first line, a comment naming the log, stays one line
# when the log's name holds a line break (the rest of the name must not
# begin a line of its own, read as the header)
NL=$(printf 'new\nline.bin')
cp vectors/walk.bin "$T/$NL"
c=psd; first=freq_hz
"$H" $c "$T/$NL" --out "$T/nl_$c.csv" >/dev/null 2>&1
if csv_rect "$T/nl_$c.csv" "$first"; then
    pass "$c --out of a log whose name holds a line break: one comment line, every row as wide as the header"
else fail "$c --out with a line break in the log's name: $(head -c 200 "$T/nl_$c.csv")"; fi
rm -f "$T/$NL"

# --- the Welch and FFT core as the Cortex-M4F firmware builds them: float
# arithmetic only. fnav_welch_init() summing the window (sum w, sum w^2, W_1)
# in double would mean soft-float calls on the single-precision FPU: the only
# double arithmetic in the firmware image, 1.9 KB of libgcc (__aeabi_dadd,
# __aeabi_dmul, ...). Skipped without the cross-compiler.
ARMCC=${ARM_CC:-arm-none-eabi-gcc}
ARMNM=${ARM_NM:-arm-none-eabi-nm}
if command -v "$ARMCC" >/dev/null 2>&1 && command -v "$ARMNM" >/dev/null 2>&1; then
    for s in fnav_welch fnav_fft; do
        if ! "$ARMCC" -mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard -Os -std=c99 -Iinclude \
            -Iport/cortex-m -DFNAV_CONFIG_FILE='"fnav_cm_fw_config.h"' -c "src/$s.c" -o "$T/$s.o" 2>"$T/err"; then
            fail "$s.c for the Cortex-M4F: $(head -c 300 "$T/err")"
            continue
        fi
        dbl=$("$ARMNM" -u "$T/$s.o" | grep -E '__aeabi_(d[a-z0-9]+|f2d|i2d|ui2d|l2d|ul2d)$' | awk '{print $2}' | tr '\n' ' ')
        if [ -z "$dbl" ]; then
            pass "$s.c for the Cortex-M4F calls no soft-float double helper"
        else
            fail "$s.c for the Cortex-M4F calls soft-float double helpers: $dbl"
        fi
    done
else
    echo "skip: no $ARMCC (the core's Cortex-M4F objects)"
fi

# a 5 s gap was only "1 of 4999 intervals differ": its length and the samples it lost are said, as allan's; a
# time stamp written twice (0, 10, 10, 30 ms) is said as such, not as a sample missing
awk 'BEGIN { srand(5); print "t,ax,ay,az,gx,gy,gz"; for (i = 0; i < 5500; i++) { if (i >= 2000 && i < 2500) continue
    printf "%.2f,%.5f,%.5f,%.5f,%.5f,%.5f,%.5f\n", i / 100, (rand() - 0.5) / 50, (rand() - 0.5) / 50, 9.81 + (rand() - 0.5) / 50,
        (rand() - 0.5) / 500, (rand() - 0.5) / 500, (rand() - 0.5) / 500 } }' >"$T/gap5.csv"
expect_exit 0 "a 5 s gap" "$H" psd "$T/gap5.csv"
# one interval said as what it is, "(a gap of ...)", not ", 1 of them a gap (longest ...)" (a CLI mutation sweep's find)
expect_err "1 of 4999 intervals differs from 1/100 s by more than 10 % (a gap of 5.01 s; about 500 samples missing, 9.1 % of the log): Welch" \
    "a 5 s gap: its length and the samples lost, in the singular"
awk -F, 'NR == 1003 { $1 = "10.00" } { print }' OFS=, "$T/gap5.csv" >"$T/rep.csv"
expect_exit 0 "a time stamp written twice" "$H" psd "$T/rep.csv"
expect_err "1 of them a time stamp repeated, 1 of them a gap of 5.01 s (about 500 samples missing, 9.1 % of the log)" \
    "a repeated stamp: said, no sample missing for it; the one gap without 'longest' and 'in all'"
# --help: --json - and sensitivity.png's --sensitivity
"$H" psd --help >"$T/out" 2>&1
expect_out "--json FILE .*'-': standard output" "psd --help: --json - said"
expect_out "sensitivity.png with --sensitivity" "psd --help: sensitivity.png needs --sensitivity"

if [ "$fails" -ne 0 ]; then echo "test_psd.sh: $fails failure(s)"; exit 1; fi
echo "test_psd.sh: all passed"
