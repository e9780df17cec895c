#!/bin/sh
# CLI tests of `harness sim`: usage errors, outputs (.bin, CSV, truth),
# determinism, and effects visible to `harness info`.
# $HARNESS is the harness binary (set by `make test-cli`).
set -u
H=${HARNESS:-bin/harness}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"

# --- usage and bad input: one-line errors, exit 2 (3 for outputs)
expect_exit 0 "sim --help" "$H" sim --help
expect_out "stand, walk, run and loop are sized to it" "--help: which motions --duration sizes (it said all built-ins; stairs, elevator, paper and mixed are cut)"
expect_exit 2 "sim without --out" "$H" sim
expect_err "--out LOG is required" "missing --out is named"
expect_exit 0 "sim --list-effects" "$H" sim --list-effects
for e in white ar1 offset quant flicker rrw ramp thermal vibration jumps saturation scale misalign gsens \
         jitter dropout duplicate alias; do
    if grep -q "^$e " "$T/out"; then pass "catalogue lists $e"; else fail "catalogue lacks $e"; fi
done
expect_exit 2 "unknown effect" "$H" sim --out "$T/x.bin" --effect wobble
expect_err "unknown effect 'wobble'" "unknown effect is named"
expect_exit 2 "bad effect parameter" "$H" sim --out "$T/x.bin" --effect quant:size=3
expect_err "has no parameter 'size'" "bad parameter is named"
expect_exit 2 "effect value out of range" "$H" sim --out "$T/x.bin" --effect dropout:prob=1.5
expect_err "outside" "range error"
# ch= on an effect that acts on whole samples was ignored (dropout:ch=gz
# dropped every channel's sample, exit 0): refused, the effects that take it named
expect_exit 2 "dropout with ch=" "$H" sim --out "$T/ch.bin" --duration 1 --effect dropout:ch=gz:prob=0.5
expect_err "effect dropout acts on whole samples, not on channels: no ch= (ch= is for white ar1 .* gsens)" \
    "dropout with ch=: refused, the effects with channels named"
expect_exit 2 "jitter with ch=" "$H" sim --out "$T/ch.bin" --duration 1 --effect jitter:ch=ax
expect_err "effect jitter acts on whole samples" "jitter with ch=: refused"
expect_exit 2 "montecarlo: alias with ch=" "$H" montecarlo --seeds 1 --duration 1 --effect alias:ch=acc:factor=2
expect_err "effect alias acts on whole samples" "montecarlo: alias with ch=: refused"
# the walking gait's options with no walking stride were ignored without a
# word (sim --motion run --speed 5 --cadence 200: the log byte-identical)
expect_exit 0 "run with --speed" "$H" sim --out "$T/gait.bin" --motion run --duration 20 --speed 5 --cadence 200
expect_err "warning: --speed, --cadence set the walking gait; the motion 'run' has no walking stride (run, stairs and turns keep their own gaits): ignored" \
    "run with --speed, --cadence: said ignored"
expect_exit 0 "stand with --stride" "$H" sim --out "$T/gait.bin" --motion stand --duration 2 --stride 1
expect_err "warning: --stride sets the walking gait; the motion 'stand' has no walking stride (no stride at all): ignored" \
    "stand with --stride: said ignored"
# a gait out of range that the motion never walks: said ignored, not refused
# ("--speed 5 at 110 steps/min makes a stride of 5.455 m, outside [0.05, 5]")
expect_exit 0 "run with --speed 5 alone" "$H" sim --out "$T/gait5.bin" --motion run --duration 5 --speed 5
expect_err "warning: --speed sets the walking gait; the motion 'run' has no walking stride" "run with --speed 5: said ignored"
expect_exit 0 "run without --speed" "$H" sim --out "$T/gait0.bin" --motion run --duration 5
cmp -s "$T/gait5.bin" "$T/gait0.bin" && pass "run with --speed 5: the log of the run without it" || fail "run with --speed 5 changed the log"
expect_exit 2 "walk with --speed 5 alone: the stride out of range" "$H" sim --out "$T/gait.bin" --motion walk --duration 5 --speed 5
expect_err "makes a stride of 5.455 m, outside \[0.05, 5\]" "walk with --speed 5: refused"
expect_exit 0 "walk with --speed" "$H" sim --out "$T/gait.bin" --motion walk --duration 20 --speed 1.5
if grep -q "ignored" "$T/err"; then fail "walk with --speed: warned"; else pass "walk with --speed: no warning"; fi
expect_exit 0 "montecarlo: run with --speed" "$H" montecarlo --motion run --duration 8 --seeds 1 --speed 2 --quiet
expect_err "warning: --speed sets the walking gait; the motion 'run' has no walking stride" "montecarlo: run with --speed: said ignored"
# --impact-ms on a motion without strides raised the internal rate to 10 kHz
# "for impacts" (stand: 5 times as long): left at the default, said ignored
expect_exit 0 "stand with --impact-ms 0.5" "$H" sim --out "$T/gait.bin" --motion stand --duration 2 --impact-ms 0.5
expect_out "^sampling    200 Hz, internal x10 " "stand with --impact-ms: the internal rate left at its default"
expect_err "warning: --impact-ms sets the landing of a stride; the motion 'stand' has no stride: ignored" \
    "stand with --impact-ms: said ignored"
if grep -q "raised" "$T/err"; then fail "stand with --impact-ms: the rate raised"; else pass "stand with --impact-ms: no raise said"; fi
expect_exit 0 "walk with --impact-ms 0.5" "$H" sim --out "$T/gait.bin" --motion walk --duration 2 --impact-ms 0.5
expect_out "^sampling    200 Hz, internal x50 " "walk with --impact-ms: the internal rate raised"
# every sample dropped: exit 1 as convert's empty window, the log valid and
# empty (it exited 0 without a word, and info refused the log)
expect_exit 1 "dropout:prob=1" "$H" sim --out "$T/empty.bin" --duration 2 --effect dropout:prob=1
expect_err "error: $T/empty.bin: no sample written: the dropout effect (prob 1) dropped every one of the 401 ticks (the log is valid and empty)" \
    "dropout:prob=1: said"
expect_out "^samples     0 written (401 ticks, 401 dropped, 0 duplicated)$" "dropout:prob=1: the summary printed"
expect_exit 1 "dropout:prob=1: info of the log" "$H" info "$T/empty.bin"
expect_err "error: $T/empty.bin: no samples$" "dropout:prob=1: a whole log without samples (as convert's empty window's)"
expect_exit 1 "dropout:prob=1 to CSV" "$H" sim --out "$T/empty.csv" --duration 2 --effect dropout:prob=1
[ "$(cat "$T/empty.csv")" = "t,ax,ay,az,gx,gy,gz" ] && pass "dropout:prob=1: the CSV is its header" ||
    fail "dropout:prob=1: the CSV's content"
expect_exit 2 "montecarlo dropout:prob=1" "$H" montecarlo --seeds 1 --duration 5 --effect dropout:prob=1
expect_err "error: --effect dropout:prob=1 drops every sample: no run has one to navigate" "montecarlo dropout:prob=1: refused"
expect_exit 2 "unknown motion" "$H" sim --out "$T/x.bin" --motion fly
expect_err "unknown motion 'fly'" "unknown motion is named"
expect_exit 2 "bad motion script" "$H" sim --out "$T/x.bin" --motion stand:5,walk:abc
# a script without items is refused, not one second of standing with exit 0
for m in , ,,; do
    expect_exit 2 "empty motion script '$m'" "$H" sim --out "$T/x.bin" --motion "$m"
    expect_err "empty motion script" "the empty script is named ('$m')"
done
# a built-in scenario sized past an item's range names the scenario, not a
# distance never given ("walk/run needs a distance in (0, 1e5] m: 128320.500")
expect_exit 2 "walk scenario too long" "$H" sim --out "$T/x.bin" --duration 1e5
expect_err "motion 'walk' sized to 100000 s: walk/run needs a distance" "the scenario and its duration are named"
# an extra value where the item takes none or one is refused (not ignored)
for m in stand:5:99 stand:2,turn:90:45 stand:2,elevator:3:9 stand:2,home:77; do
    expect_exit 2 "motion script with an extra value ($m)" "$H" sim --out "$T/x.bin" --motion "$m"
done
# the turn of a walk, run or stairs leg has the bound of a turn item: a
# turn of 1e300 deg would write a log of infinite and NaN gyro samples (1e9
# deg: 7e7 rad/s) with exit 0
for m in walk:1.4:1e300 run:5:-1e9 stairs-up:2:1e300 stairs-down:4:3601; do
    expect_exit 2 "motion leg turning too far ($m)" "$H" sim --out "$T/x.csv" --motion "stand:1,$m"
    expect_err "within +-3600 deg" "the bound on the turn is named ($m)"
done
expect_exit 0 "a walk leg turning the largest angle" "$H" sim --out "$T/x.csv" --rate 100 --motion stand:1,walk:100:-3600

# the catalogue's inclusive lower bounds hold in the float build too (1e-9
# and 1e-12 round below the double bounds in float, and are not refused)
# a walk slower than replay navigates: warned (replay refuses it later); a standing log at 5 Hz (allan, psd) is not
expect_exit 0 "a walk at 5 Hz" "$H" sim --out "$T/x.csv" --rate 5 --duration 20
expect_err "sim: warning: at 5 Hz the walk is below the 20 Hz that replay navigates as recorded" "a walk at 5 Hz: warned"
expect_exit 0 "standing at 5 Hz" "$H" sim --out "$T/x.csv" --rate 5 --motion stand --duration 20
if grep -q "below the 20 Hz" "$T/err"; then fail "standing at 5 Hz: warned as a walk"; else pass "standing at 5 Hz: no warning"; fi
expect_exit 0 "saturation at its smallest range" "$H" sim --out "$T/x.csv" --motion stand --duration 1 --effect saturation:range=1e-9
expect_exit 0 "quantisation at its smallest step" "$H" sim --out "$T/x.csv" --motion stand --duration 1 --effect quant:lsb=1e-12
# a profile outside the error model's ranges is named as such (it blamed
# --effect options that were never given): at its line with its key, as the
# loader holds every value to the ranges of the commands that use it
sed 's/^accel_tau_s.*/accel_tau_s = 5e-4 100 100/' docs/profiles/generic-mems.profile > "$T/tau.profile"
expect_exit 2 "a profile with a correlation time under 1 ms" "$H" sim --out "$T/x.csv" --motion stand --duration 1 --profile "$T/tau.profile"
expect_err "tau.profile:13: accel_tau_s value 1 '5e-4' outside \[0.001, 1e+09\]" "the profile named, not the effects"
expect_exit 2 "unknown profile" "$H" sim --out "$T/x.bin" --profile nosuchprofile
expect_exit 2 "bad rate" "$H" sim --out "$T/x.bin" --rate -5
expect_exit 2 "three gait figures" "$H" sim --out "$T/x.bin" --speed 1 --cadence 100 --stride 1
expect_exit 2 "sample jitter through the filter" "$H" sim --out "$T/x.bin" --effect jitter:sample_s=1e-4
expect_err "sample_s" "sample jitter error explains"
# refused before any output is begun (no header-only log left behind),
# with advice that fits --decimation mean (not the --oversample 1 the run
# had)
[ ! -e "$T/x.bin" ] && pass "no log left by the sample jitter refusal" || fail "sample jitter refusal left a log"
expect_exit 2 "sample jitter with interval means" "$H" sim --out "$T/xm.bin" --oversample 1 --decimation mean \
    --effect jitter:sample_s=1e-4
expect_err "use --decimation fir with --oversample 1" "sample jitter with means: the advice names --decimation"
[ ! -e "$T/xm.bin" ] && pass "no log left (means)" || fail "sample jitter refusal left a log (means)"
expect_exit 0 "sample jitter with point samples" "$H" sim --out "$T/xp.csv" --duration 1 --oversample 1 \
    --effect jitter:sample_s=1e-4
# a tone above the output band: the FIR removes it, the interval mean only
# attenuates and folds it (the warning said "filtered out" for both)
expect_exit 0 "tone above the band, interval means" "$H" sim --out "$T/vm.csv" --duration 1 --decimation mean \
    --effect vibration:ch=ay:freq_hz=150
expect_err "fold it to 50 Hz" "the mean's warning says the tone folds"
if grep -q "filtered out" "$T/err"; then fail "the mean's warning says filtered out"; else pass "no 'filtered out' for means"; fi
expect_exit 0 "tone above the band, FIR" "$H" sim --out "$T/vf.csv" --duration 1 --effect vibration:ch=ay:freq_hz=150
expect_err "filtered out" "the FIR's warning says filtered out"
# a tone above the internal rate's Nyquist frequency folded before the
# filter saw it: 1990 Hz sampled at 2 kHz reached the output as a whole
# 10 Hz line, told "in the transition band, passes at 100.1 %". The default
# internal rate is raised to 2.5 x the tone (x25 at 200 Hz): the line is
# gone; an --oversample too low for it is warned with the fold it makes
line10() { # the amplitude of the 10 Hz line of az in the log $1
    /usr/bin/python3 -c "
import sys, numpy as np
d = np.genfromtxt(sys.argv[1], delimiter=',', names=True)
x = d['az'] - d['az'].mean()
X = np.abs(np.fft.rfft(x)) * 2 / len(x)
print('%.6f' % X[int(round(10 * len(x) / 200.0))])" "$1"
}
expect_exit 0 "tone at 1990 Hz, default internal rate" "$H" sim --out "$T/v1990.csv" --motion stand --duration 20 \
    --profile none --effect vibration:ch=az:amp=1:freq_hz=1990
expect_out "internal x25 (anti-alias FIR)" "the internal rate raised to 2.5 x the tone"
a10=$(line10 "$T/v1990.csv")
if /usr/bin/python3 -c "import sys; sys.exit(0 if float('$a10') < 1e-3 else 1)"; then pass "1990 Hz: no 10 Hz line ($a10)"
else fail "1990 Hz reaches the output as a 10 Hz line of $a10"; fi
expect_exit 0 "tone at 1990 Hz, --oversample 10" "$H" sim --out "$T/v1990o.csv" --motion stand --duration 20 \
    --profile none --effect vibration:ch=az:amp=1:freq_hz=1990 --oversample 10
expect_err "it is sampled at 2000 Hz (--oversample 10), less than twice its frequency, and folds to 10 Hz before the filter sees it (--oversample 25 or more keeps it as it is), in the anti-alias filter's pass band: it passes whole" \
    "the fold at the internal rate said"
a10=$(line10 "$T/v1990o.csv")
if /usr/bin/python3 -c "import sys; sys.exit(0 if abs(float('$a10') - 1) < 0.01 else 1)"; then pass "the warned fold is in the log ($a10)"
else fail "--oversample 10: the 10 Hz line is $a10, not the whole tone the warning says"; fi
expect_exit 0 "tone at 1990 Hz, point samples" "$H" sim --out "$T/v1990p.csv" --motion stand --duration 2 \
    --profile none --effect vibration:ch=az:amp=1:freq_hz=1990 --oversample 1
expect_err "point samples (--oversample 1) fold it to 10 Hz" "point sampling's fold said"
# sharp impacts raise the default internal rate too (5 samples to a
# landing: 0.5 ms at 200 Hz, x50); the defaults (5-8 ms) keep x10
expect_exit 0 "0.5 ms impacts" "$H" sim --out "$T/imp.csv" --motion run --duration 2 --impact-ms 0.5
expect_out "internal x50" "0.5 ms impacts sampled at 10 kHz inside"
expect_err "note: the internal rate is raised to 10000 Hz (x50, the default x10) for impacts shorter than 2.5 ms: the run takes about 5 times as long (--oversample sets it)" \
    "the raise's cost said (the internal xN line alone did not say why)"
expect_exit 0 "default impacts" "$H" sim --out "$T/imp.csv" --motion run --duration 2
expect_out "internal x10" "the default internal rate at the default impacts"
if grep -q "internal rate is raised" "$T/err"; then fail "a note at the default internal rate"
else pass "no note at the default internal rate"; fi
# alias point-samples: --decimation mean and --oversample are said to be
# set aside (montecarlo then tells its filter the samples are instantaneous)
expect_exit 0 "alias with interval means" "$H" sim --out "$T/al.csv" --duration 1 --decimation mean --effect alias
expect_err "the alias effect point-samples the signal: --decimation mean is not applied" "alias over mean said"
expect_exit 0 "alias with --oversample" "$H" sim --out "$T/al.csv" --duration 1 --oversample 8 --effect alias:factor=4
expect_err "the alias effect's factor sets the internal rate (x4): --oversample 8 is not applied" "alias over --oversample said"
# interval means need a sample inside the interval
expect_exit 2 "interval means at --oversample 1" "$H" sim --out "$T/m1.csv" --duration 1 --decimation mean --oversample 1
expect_err "interval means (--decimation mean) need internal samples between the output samples" "mean at x1 refused"
expect_exit 0 "interval means at 2 kHz" "$H" sim --out "$T/m2k.csv" --duration 1 --decimation mean --rate 2000
expect_out "internal x2 (interval means)" "means at 2 kHz sampled at x2 by default (x1 is the default FIR there)"
# in the filter's transition band (0.41-0.59 f_s) a tone passes attenuated:
# 90 Hz at 200 Hz at 91 % (measured on the log), 110 Hz at 9 % folded to 90 Hz
# (neither may be called "filtered out"). The figures the warnings must
# give come from the filter rebuilt in numpy from its formula, not from the
# harness: `/usr/bin/python3 scripts/sim_fir_response.py --tone 200 90 110`
#   90 Hz at 200 Hz (M 10): amplitude 91.118 %
#   110 Hz at 200 Hz (M 10): amplitude 8.937 %, folded to 90 Hz
expect_exit 0 "tone in the transition band" "$H" sim --out "$T/vf.csv" --duration 1 --effect vibration:ch=ay:freq_hz=90
expect_err "passes at 91.1 % of its amplitude" "the transition band's gain is said"
if grep -q "filtered out" "$T/err"; then fail "90 Hz at 200 Hz called filtered out"; else pass "90 Hz not called filtered out"; fi
expect_exit 0 "tone folding from the transition band" "$H" sim --out "$T/vf.csv" --duration 1 --effect vibration:ch=ay:freq_hz=110
expect_err "passes at 8.9 % of its amplitude, folded to 90 Hz" "the fold is said"
# ... and the gain each warning gives is the numpy filter's, at 200 Hz and at
# 150 Hz (M 14: another filter length), each frequency in the transition band:
# equal within the two roundings: half a unit of the warning's "%.1f" (0.05 %)
# and of the script's "%.3f" (0.0005 %)
PY=${PYTHON:-/usr/bin/python3}
if "$PY" -c 'import numpy' 2>/dev/null; then
    for rf in "200 90" "200 110" "150 65" "150 85"; do
        set -- $rf
        "$PY" scripts/sim_fir_response.py --tone "$1" "$2" > "$T/np.txt"
        want=$(sed -n 's/.*amplitude \([0-9.]*\) %.*/\1/p' "$T/np.txt")
        fold=$(sed -n 's/.*\(, folded to [0-9.]* Hz\)$/\1/p' "$T/np.txt")
        "$H" sim --out "$T/vf.csv" --rate "$1" --duration 1 --effect vibration:ch=ay:freq_hz="$2" >/dev/null 2>"$T/err"
        got=$(sed -n "s/.*passes at \([0-9.]*\) % of its amplitude$fold\$/\1/p" "$T/err")
        if [ -n "$want" ] && [ -n "$got" ] &&
            awk -v g="$got" -v w="$want" 'BEGIN { d = g - w; exit !(d <= 0.0505 && d >= -0.0505) }'; then
            pass "$2 Hz at $1 Hz: the gain numpy's filter gives ($got % for $want %$fold)"
        else
            fail "$2 Hz at $1 Hz: numpy's filter gives $want %$fold, the warning: $(cat "$T/err")"
        fi
    done
else
    echo "SKIP the transition band's gains against numpy: $PY has no numpy (apt-get install python3-numpy)"
fi
# a landing takes at most 30 % of the swing: a longer --impact-ms is said
# (not shortened without a word)
expect_exit 0 "long impact" "$H" sim --out "$T/x.csv" --duration 1 --impact-ms 160
expect_err "longer than 30 % of a swing, the longest landing: walk 137 ms, run 152 ms" "the cap is named"
expect_exit 0 "calibrated impact" "$H" sim --out "$T/x.csv" --duration 1 --impact-ms 7
if grep -q "longer than 30 %" "$T/err"; then fail "a 7 ms impact warned"; else pass "no warning at 7 ms"; fi
# --bias-sigma eq6 rereads a profile's bias sd: with --profile none (no bias
# model) it is said to be ignored, not dropped without a word
expect_exit 0 "eq6 on the ideal sensor" "$H" sim --out "$T/x.csv" --duration 1 --profile none --bias-sigma eq6
expect_err "no bias model: ignored" "eq6 without a profile said"
expect_exit 0 "eq6 on a profile" "$H" sim --out "$T/x.csv" --duration 1 --profile mtx --bias-sigma eq6
if grep -q "ignored" "$T/err"; then fail "eq6 with a profile warned"; else pass "eq6 with a profile: no warning"; fi
# ... and on a profile file it is said: a file's bias sd is most likely the
# stationary sd of `allan --profile`, which eq6 makes 50-600 times larger,
# not to go without a word
expect_exit 0 "eq6 on a profile file" "$H" sim --out "$T/x.csv" --duration 1 --bias-sigma eq6 \
    --profile "$(dirname "$0")/../../docs/profiles/generic-mems.profile"
expect_err "warning: --bias-sigma eq6 rereads the bias sd of the profile file" "eq6 on a profile file is said"
# a gait figure derived from --speed keeps its option's range (50 m strides
# were walked; a cadence of 1200 /min was blamed on the gait fractions)
expect_exit 2 "derived stride out of range" "$H" sim --out "$T/x.csv" --duration 5 --speed 10 --cadence 20
expect_err "makes a stride of 60 m, outside" "the derived stride is named"
expect_exit 2 "derived cadence out of range" "$H" sim --out "$T/x.csv" --duration 5 --speed 5 --stride 0.5
expect_err "makes a cadence of 1200 steps/min, outside" "the derived cadence is named"
expect_exit 0 "derived gait in range" "$H" sim --out "$T/x.csv" --duration 5 --speed 1.5 --stride 1.5
expect_exit 2 "bad --decimation" "$H" sim --out "$T/x.bin" --decimation cubic
expect_err "fir or mean" "decimation error lists the kinds"
# more samples than the 32-bit record counter holds (1e11 were asked for and the run began)
expect_exit 2 "1e11 samples" "$H" sim --out "$T/big.bin" --motion stand:10 --duration 1e6 --rate 1e5
expect_err "at most 2^32 - 1" "the sample count's bound is said"
[ ! -e "$T/big.bin" ] && pass "no output begun for a refused size" || fail "an output begun for a refused size"
expect_exit 0 "integrating sensor" "$H" sim --out "$T/m.bin" --duration 3 --rate 100 --decimation mean
expect_out "interval means" "summary names the decimation"
expect_exit 3 "unwritable output" "$H" sim --out "$T/no/such/dir/x.bin" --duration 2
expect_exit 3 "unwritable truth" "$H" sim --out "$T/x.bin" --truth "$T/no/such/dir/t.csv" --duration 2
# an output that fails while the run writes it (a full disk): exit 3, the
# file named, no summary (a mutant that exits 0 on a failed truth write,
# summary printed, passes every case above)
if [ -w /dev/full ]; then
    expect_exit 3 "truth CSV onto a full disk" "$H" sim --out "$T/x.bin" --truth /dev/full --duration 2
    expect_err "/dev/full: write failed" "the truth file's failed write is said"
    if [ -s "$T/out" ]; then fail "a summary after the truth write failed: $(head -1 "$T/out")"; else
        pass "no summary after the truth write failed"; fi
    expect_exit 3 "log onto a full disk" "$H" sim --out /dev/full --duration 2
    expect_err "/dev/full: write failed" "the log's failed write is said"
    if [ -s "$T/out" ]; then fail "a summary after the log write failed: $(head -1 "$T/out")"; else
        pass "no summary after the log write failed"; fi
    # one error line with the reason, as convert's: a .bin log (whose
    # record write fails in the run) said "write failed" and then, on
    # closing, "write failed (No space left on device)"; the truth CSV said
    # no reason
    ln -s /dev/full "$T/full.bin"
    for o in "--out $T/full.bin" "--out $T/x.bin --truth /dev/full"; do
        # shellcheck disable=SC2086
        expect_exit 3 "sim $o" "$H" sim $o --duration 2
        if [ "$(grep -c 'error:' "$T/err")" -eq 1 ] && grep -q "write failed (No space left on device)" "$T/err"; then
            pass "sim $o: one error line with the reason"; else fail "sim $o: the write error said twice or without its reason"; cat "$T/err"; fi
    done
fi
HA=$(cd "$(dirname "$H")" && pwd)/$(basename "$H")
(cd "$T" && "$HA" sim --out x2.bin --truth - --duration 2 >/dev/null 2>"$T/err"); rc=$?
if [ $rc -eq 2 ] && [ ! -e "$T/-" ] && grep -q "needs a file name" "$T/err"; then pass "sim --truth - refused (it wrote a file named -)"; else fail "sim --truth -: exit $rc"; fi

# the same file under two spellings (x3.bin, ./x3.bin), not there before:
# refused, exit 2 (stat could not tell before the log existed, and the
# truth CSV was written into the .bin, exit 0)
(cd "$T" && "$HA" sim --out x3.bin --truth ./x3.bin --duration 2 >/dev/null 2>"$T/err"); rc=$?
if [ $rc -eq 2 ] && grep -q "name the same file" "$T/err"; then pass "sim --truth ./F --out F refused"; else fail "sim --truth ./x3.bin --out x3.bin: exit $rc"; fi

# --- a walk: .bin log, truth CSV, summary
expect_exit 0 "sim walk 20 s" "$H" sim --motion walk --duration 20 --rate 100 --out "$T/w.bin" --truth "$T/t.csv"
expect_out_re "^samples     2001 written" "2001 samples at 100 Hz over 20 s"
expect_out "anti-alias FIR" "filtered by default"
n=$(wc -l <"$T/t.csv")
if [ "$n" -eq 2002 ]; then pass "truth has a row per tick"; else fail "truth rows $n, expected 2002"; fi
if head -1 "$T/t.csv" | grep -q "^t,seq,count,px,py,pz,vx,vy,vz,qw,qx,qy,qz,roll,pitch,yaw,fx,fy,fz,wx,wy,wz,still,zero_vel,phase,leg,odo,bax,bay,baz,bgx,bgy,bgz$"; then
    pass "truth header"; else fail "truth header"; head -1 "$T/t.csv"; fi
expect_exit 0 "info reads the simulated log" "$H" info "$T/w.bin"
expect_out "rate        100.000 Hz (nominal)" "nominal rate in the header"
expect_out "gravity along +z (-z up)" "the simulated foot (z down, frames.md): gravity along +z at rest"
expect_out_re "^samples     2001$" "info sample count"

# --rate 1 is in the option's range, but the default oversampling (2 kHz
# internally: x2000) exceeded the error model's limit of 1024 and the run
# was refused as "the effects are inconsistent"
expect_exit 0 "sim --rate 1" "$H" sim --rate 1 --duration 20 --out "$T/r1.csv"
expect_out "internal x1024" "--rate 1: the largest oversampling"
# the default is the smallest M with M x rate >= 2 kHz (docs/simulator.md):
# 2000 / 300 = 6.67 -> 7, 2000 / 150 = 13.3 -> 14 (a mutant rounding down,
# 1800 and 1950 Hz internally, passed every test: 200 and 100 Hz divide 2000)
expect_exit 0 "sim --rate 300" "$H" sim --rate 300 --duration 1 --out "$T/r300.csv"
expect_out "internal x7 " "--rate 300: internal x7 (2100 Hz)"
expect_exit 0 "sim --rate 150" "$H" sim --rate 150 --duration 1 --out "$T/r150.csv"
expect_out "internal x14 " "--rate 150: internal x14 (2100 Hz)"
# --ring-scale reaches the walk's ringing: 1 is the default, 0 changes the
# samples (a mutant that left the walking gait's ringing unscaled passed;
# the run and stair gaits were scaled, the default motion is a walk)
for k in 0 1; do
    "$H" sim --motion stand:1,walk:3,stand:1 --profile none --rate 200 --ring-scale $k --out "$T/ring$k.csv" >/dev/null 2>&1 ||
        fail "sim --ring-scale $k"
done
"$H" sim --motion stand:1,walk:3,stand:1 --profile none --rate 200 --out "$T/ringd.csv" >/dev/null 2>&1 || fail "sim ring default"
if cmp -s "$T/ring1.csv" "$T/ringd.csv"; then pass "--ring-scale 1 is the default"; else fail "--ring-scale 1 differs from the default"; fi
if cmp -s "$T/ring0.csv" "$T/ringd.csv"; then fail "--ring-scale 0 left the walk's ringing"; else pass "--ring-scale 0 changes the walk"; fi

# --- a --duration that cuts the motion before its last stride (or ride) is
# said: a 'walk' of 4 s is 4 s of standing, a 'loop' of 20 s ends 1.2 m from
# its start, which the document says it ends at (neither may be silent); a
# walk whose last standing is shortened, or a script lengthened by standing,
# is not cut
for c in "walk 4" "loop 20" "paper 30" "stand:1,elevator:3 3"; do
    set -- $c
    expect_exit 0 "sim $1 cut at $2 s" "$H" sim --motion "$1" --duration "$2" --out "$T/cut.bin"
    expect_err "warning: --duration $2 cuts the motion '$1'" "the cut of '$1' at $2 s is said"
done
for c in "walk 60" "walk 30" "loop 90" "stand:1,walk:3 20"; do
    set -- $c
    expect_exit 0 "sim $1 for $2 s" "$H" sim --motion "$1" --duration "$2" --out "$T/cut.bin"
    if grep -q "cuts the motion" "$T/err"; then fail "'$1' for $2 s called cut: $(cat "$T/err")"; else pass "'$1' for $2 s: no cut said"; fi
done
# the defaults of --duration are in the help, and are what runs
expect_exit 0 "sim --help" "$H" sim --help
expect_out "default: the motion's own length, stand, walk and run sized to 60 s and loop to 90 s, in whole strides" \
    "--help gives --duration's defaults"
expect_exit 0 "sim loop, default duration" "$H" sim --motion loop --rate 50 --out "$T/loop.bin"
expect_out_re "^duration    (8[5-9]|9[0-5])\.[0-9]+ s" "the default loop lasts about 90 s"
expect_exit 0 "sim walk, default duration" "$H" sim --rate 50 --out "$T/walk.bin"
expect_out_re "^duration    (5[5-9]|6[0-5])\.[0-9]+ s" "the default walk lasts about 60 s"

# --- the summary counts the strides of the output, not of the whole motion
# (a 30 s cut of 'paper' said 154 strides, those of its 185 s)
expect_exit 0 "sim walk cut before the first stride" "$H" sim --motion walk --duration 4 --out "$T/w4.bin"
expect_out_re "^duration    4\.000 s, 0 strides, 0\.00 m between footfalls" "no stride within 4 s of standing"
# ... and its duration and end are those of the last sample: a --duration
# between two ticks (7.0049 s at 100 Hz: the last sample is at 7.000 s)
# must not print 7.005 s and the truth at 7.0049 s, 2 cm past the log's
# last position; compared with the truth CSV's last row
expect_exit 0 "sim with --duration between ticks" "$H" sim --motion walk:20 --duration 7.0049 --rate 100 \
    --profile none --out "$T/w7.bin" --truth "$T/w7.csv"
want=$(tail -n 1 "$T/w7.csv" | awk -F, '{ printf "duration    %.3f s, .* %.2f m between footfalls, ends at \\(%.3f, %.3f, %.3f\\) m", $1, $27, $4, $5, $6 }')
expect_out_re "^$want\$" "the summary's duration and end are the last sample's ($want)"
expect_exit 0 "sim paper cut at 30 s" "$H" sim --motion paper --duration 30 --out "$T/p30.bin"
n30=$(sed -n 's/^duration .* s, \([0-9]*\) strides.*/\1/p' "$T/out")
expect_exit 0 "sim paper whole" "$H" sim --motion paper --out "$T/p.bin"
nall=$(sed -n 's/^duration .* s, \([0-9]*\) strides.*/\1/p' "$T/out")
if [ -n "$n30" ] && [ -n "$nall" ] && [ "$n30" -gt 0 ] && [ "$n30" -lt "$nall" ]; then
    pass "paper: $n30 strides in 30 s of $nall"; else fail "paper strides: $n30 in 30 s, $nall in all"; fi

# --- CSV output and determinism
expect_exit 0 "sim to CSV" "$H" sim --duration 5 --rate 200 --seed 7 --out "$T/a.csv"
expect_exit 0 "same seed again" "$H" sim --duration 5 --rate 200 --seed 7 --out "$T/b.csv"
if cmp -s "$T/a.csv" "$T/b.csv"; then pass "same seed, same log"; else fail "same seed gave different logs"; fi
expect_exit 0 "another seed" "$H" sim --duration 5 --rate 200 --seed 8 --out "$T/c.csv"
if cmp -s "$T/a.csv" "$T/c.csv"; then fail "different seeds gave the same log"; else pass "different seed, different log"; fi
if head -1 "$T/a.csv" | grep -q "^t,ax,ay,az,gx,gy,gz$"; then pass "CSV header"; else fail "CSV header"; fi
n=$(wc -l <"$T/a.csv")
if [ "$n" -eq 1002 ]; then pass "CSV rows"; else fail "CSV rows $n, expected 1002"; fi
expect_exit 0 "CSV on stdout" "$H" sim --duration 1 --rate 100 --out -
n=$(wc -l <"$T/out")
if [ "$n" -eq 102 ]; then pass "CSV on stdout rows"; else fail "stdout rows $n, expected 102"; fi
# ... and the summary on standard error, as replay's with --out - (not
# dropped: no word of the profile, effects or samples)
expect_err "^samples     101 written" "--out -: the summary on standard error"
if grep -q "^samples" "$T/out"; then fail "--out -: the summary in the CSV"; else pass "--out -: the CSV alone on standard output"; fi

# --- the summary's effect lines give the values as set, not their float
# rounding (0.05 not printed 0.0500000007, nor the MTx density 0.00089
# 0.000890000025), and still parse back to them
expect_exit 0 "effect values in the summary" "$H" sim --out "$T/x.csv" --duration 1 --profile mtx \
    --effect offset:value=0.05 --effect quant:ch=gyro:lsb=1.0653e-3
expect_out_re "^effect      offset:ch=all:value=0\.05$" "offset 0.05 printed as given"
expect_out "white:ch=ax:density=0.00089 " "the MTx density printed as tabulated"
expect_out "quant:ch=gyro:lsb=0.0010653:shaped=0" "the quantisation step printed as given"
spec=$(sed -n 's/^effect      \(offset:.*\)$/\1/p' "$T/out")
expect_exit 0 "the printed effect run again" "$H" sim --out "$T/y.csv" --duration 1 --profile mtx --effect "$spec" \
    --effect quant:ch=gyro:lsb=1.0653e-3
if cmp -s "$T/x.csv" "$T/y.csv"; then pass "the printed effect is the one set"; else fail "'$spec' gives another log"; fi

# --- effects that `harness info` sees
expect_exit 0 "dropout + duplicate" "$H" sim --duration 20 --rate 100 --out "$T/d.bin" \
    --effect dropout:prob=0.05 --effect duplicate:prob=0.05
# the summary's counts: written = ticks - dropped + duplicated, and the
# dropped and duplicated are what info finds in the log (a mutant counting
# single ticks as duplicated passed every check here)
SIMN=$(sed -n 's/^samples *\([0-9]*\) written (\([0-9]*\) ticks, \([0-9]*\) dropped, \([0-9]*\) duplicated)$/\1 \2 \3 \4/p' "$T/out")
expect_exit 0 "info on drops" "$H" info "$T/d.bin"
if grep -Eq "^drops +[1-9]" "$T/out"; then pass "drops visible in the counter"; else fail "no drops"; cat "$T/out"; fi
if grep -Eq "^duplicates +[1-9]" "$T/out"; then pass "duplicates visible"; else fail "no duplicates"; cat "$T/out"; fi
set -- $SIMN
if [ $# -eq 4 ] && [ "$1" -eq $(($2 - $3 + $4)) ] && grep -Eq "^drops +$3 " "$T/out" && grep -Eq "^duplicates +$4 " "$T/out"
then pass "sim's written, dropped and duplicated counts agree with info's"; else fail "sim counts '$SIMN' vs info: $(grep -E '^(drops|duplicates)' "$T/out")"; fi
# the summary's peaks are those of the log: every sample dropped, none
# (the dropped samples are not counted); the summary is printed before the
# error of an empty log (exit 1)
expect_exit 1 "every sample dropped" "$H" sim --duration 2 --rate 100 --out "$T/d0.csv" --effect dropout:prob=1
expect_out_re "^samples     0 written" "no sample written"
expect_out_re "^peaks       largest on one axis: f 0\.0 m/s\^2 \(0\.0 g\), w 0\.00 rad/s" "no peak from dropped samples"
# the peaks are the largest reading of any one axis (what a sensor's range
# must hold), not the norm that '|f|' and '|w|' read as: a static log
# (f = (0, 0, -g)) peaks at g, and the label says which
expect_exit 0 "peaks of a static log" "$H" sim --motion stand --duration 1 --profile none --mount 0,45,0 --out "$T/pk.csv"
expect_out_re "^peaks       largest on one axis: f 6\.9 m/s\^2 \(0\.7 g\), w 0\.00 rad/s" \
    "peaks: the largest axis (g cos 45 deg = 6.9 m/s^2 at a 45 deg pitch mount), said so"
expect_exit 0 "saturation at 4 g" "$H" sim --motion run --duration 15 --rate 200 --out "$T/s.bin" \
    --effect saturation:ch=acc:range=39.2266
expect_exit 0 "info on clipping" "$H" info "$T/s.bin"
if grep -Eq "^saturation .*a[xyz] [1-9]" "$T/out"; then pass "clipping visible"; else fail "no clipping"; cat "$T/out"; fi
expect_exit 0 "thermal writes temperature" "$H" sim --duration 3 --rate 100 --out "$T/th.csv" --effect thermal
if head -1 "$T/th.csv" | grep -q ",temp$"; then pass "temperature column"; else fail "no temperature column"; fi
expect_exit 0 "every scenario" sh -c "for m in stand walk run stairs elevator loop paper mixed; do \
    \"$H\" sim --motion \$m --rate 100 --out \"$T/m.bin\" >/dev/null || exit 1; done"
expect_exit 0 "a script with every leg" "$H" sim --motion "stand:2,walk:5:30,run:6,stairs-up:4,turn:90,stairs-down:4,elevator:3,home,stand:2" \
    --rate 100 --out "$T/s2.bin"
expect_out "ends at (0.000, 0.000, -3.000)" "script ends at the start, 3 m up (elevator)"

if [ "$fails" -ne 0 ]; then echo "test_sim.sh: $fails failure(s)"; exit 1; fi
echo "test_sim.sh: all passed"
