#!/bin/sh
# CLI tests of `harness simgap` and `harness simgap-validate` (run by make
# test and make sanitize with $HARNESS set; docs/simgap.md). The logs are
# simulated here with `harness sim`, so the right answer is known.
set -u
H=${HARNESS:-bin/harness}
PY=${PYTHON:-/usr/bin/python3}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"

# usage and input errors
expect_exit 2 "no input" "$H" simgap
expect_exit 2 "static and walk" "$H" simgap x.csv --static --walk
expect_exit 2 "too few seeds" "$H" simgap x.csv --seeds 1
expect_exit 2 "fit fraction out of range" "$H" simgap x.csv --fit-frac 0.95
expect_exit 1 "missing file" "$H" simgap "$T/nope.csv"
# --alpha is the level of each of the diagnosis's three families of tests
# (the gaps, an effect's acceptance, the timing domain; docs/simgap.md,
# "Seeds and alpha"), not of the gap tests alone, as --help once said
"$H" simgap --help >"$T/out" 2>&1
expect_out "^  --alpha A  *false-alarm level of each family of tests: the gap tests, an effect's acceptance, the timing domain (default 0.05)" \
    "--help: --alpha is the level of each family of tests"
expect_exit 2 "validate: zero cases" "$H" simgap-validate --cases 0
expect_exit 2 "validate: bad magnitude range" "$H" simgap-validate --mag-range 3,1
expect_exit 2 "validate: static-only and walk-only" "$H" simgap-validate --static-only --walk-only
expect_exit 2 "validate: unknown effect" "$H" simgap-validate --effects xx
expect_err "unknown effect 'xx'; known: control, quant" "validate: the unknown effect named, the known ones listed"
expect_exit 2 "validate: unknown effect beside a known one" "$H" simgap-validate --effects control,xx
expect_err "unknown effect 'xx'" "validate: unknown effect beside a known one named"
expect_exit 2 "validate: walk effect with --static-only" "$H" simgap-validate --effects scale --static-only
expect_exit 2 "validate: --only beyond --cases" "$H" simgap-validate --only 5 --cases 2
expect_err "only 5 must be below --cases 2" "validate: --only beyond --cases said"
# a static case just over the 2e7 samples: its size said in full, not rounded to the bound it exceeds ('2e+07')
expect_exit 2 "validate: static case of 20000200 samples" "$H" simgap-validate --duration 100001 --rate 200
expect_err "duration 100001 x --rate 200 is 20000200 samples per static case; at most 20000000" \
    "validate: static case's size said in full"

# a static log of 2 s: the held-out part cannot give tight Allan intervals
# over a decade of tau -> "too short", exit 1, and the JSON says why
"$H" sim --motion stand:2 --rate 100 --profile mtx --seed 2 --out "$T/short.csv" >/dev/null 2>&1 || fail "sim short"
expect_exit 1 "too short log" "$H" simgap "$T/short.csv" --quiet --json "$T/short.json"
grep -q "TOO SHORT" "$T/out" && pass "too short said in the summary" || fail "too short summary"
expect_err "^harness simgap: error: .*short.csv: too short for a confident answer: .*decade" "too short said in one error line"
json "$T/short.json" 'j["confident"] is False and j["verdict"]["answer"] == "too-short" and "decade" in j["too_short"]' &&
    pass "too short in the JSON" || fail "too short JSON: $(cat "$T/pyerr")"
# an output that cannot be written fails before the diagnosis, not after it
# (the whole run, minutes on a long log, then exit 3)
expect_exit 3 "--json into a missing directory" "$H" simgap "$T/short.csv" --json "$T/nodir/x.json"
[ ! -s "$T/out" ] && pass "--json unwritable: refused before the diagnosis" || fail "--json unwritable: diagnosed first"
expect_exit 3 "--plot that cannot be created" "$H" simgap "$T/short.csv" --plot "$T/nodir/plots"
[ ! -s "$T/out" ] && pass "--plot unwritable: refused before the diagnosis" || fail "--plot unwritable: diagnosed first"
# ... and its plots are still written (Usage): 2 s hold no Welch band, and
# the PSD panels without a point made gnuplot fail ("x range is invalid"),
# exit 3 and no z.png
expect_exit 1 "too short log with --plot" "$H" simgap "$T/short.csv" --quiet --seeds 6 --plot "$T/shortplot"
[ -s "$T/shortplot/allan.png" ] && [ -s "$T/shortplot/psd.png" ] && [ -s "$T/shortplot/z.png" ] &&
    ! grep -q "gnuplot\|invalid" "$T/err" && pass "too short: the three plots written, gnuplot quiet" ||
    fail "too-short plots: $(ls "$T/shortplot"; grep -m3 "gnuplot\|invalid" "$T/err")"
# a held-out part with no point to compare (0.3 s of a 3 s log): too short,
# not a GSL abort on an undefined null distribution
"$H" sim --motion stand:3 --rate 100 --profile mtx --seed 2 --out "$T/s3.csv" >/dev/null 2>&1 || fail "sim 3 s"
expect_exit 1 "held-out segment without points" "$H" simgap "$T/s3.csv" --quiet --seeds 4 --fit-frac 0.9
expect_err "^harness simgap: error: .*too short for a confident answer" "no held-out point: too short, said"
# ... while with the default split 3 s at 100 Hz are enough (section 5 of
# docs/simgap.md; not "about 5 s")
expect_exit 0 "3 s at 100 Hz: not too short" "$H" simgap "$T/s3.csv" --quiet --seeds 4
# --seed: sim's and montecarlo's range and words, [0, 4294967295] and "not
# a whole number" (not [0, 2e9], "not an integer"):
# every seed simgap derives is uint32_t arithmetic, which wraps, defined
expect_exit 2 "--seed past 2^32 - 1" "$H" simgap "$T/s3.csv" --seed 4294967296
expect_err "^harness simgap: error: --seed '4294967296' is out of range (give a whole number in \[0, 4294967295\])$" "--seed: sim's range and words"
expect_exit 0 "--seed 4294967295, the last seed (its twins' seeds wrap)" "$H" simgap "$T/s3.csv" --quiet --seeds 4 --seed 4294967295 --json "$T/s3seed.json"
json "$T/s3seed.json" "j['settings']['seed'] == 4294967295" &&
    pass "--seed 4294967295 written in the JSON" || fail "--seed in the JSON: $(grep -o '"seed":[^,]*' "$T/s3seed.json" | head -2)"
# a still log read as a walk (--walk): one stance, so the innovations plot's panel of mean NIS held one value,
# and gnuplot printed "Warning: empty y range [0.0172028:0.0172028], ..." on standard error despite --quiet
if command -v gnuplot >/dev/null 2>&1; then
    "$H" sim --motion stand:20 --rate 100 --profile mtx --seed 2 --out "$T/s20.csv" >/dev/null 2>&1 || fail "sim 20 s"
    mkdir -p "$T/s20plots"
    expect_exit 1 "a still log as a walk: too short" "$H" simgap "$T/s20.csv" --walk --quiet --seeds 3 --plot "$T/s20plots"
    if [ -s "$T/s20plots/innovations.png" ] && ! grep -q "empty . range" "$T/err"; then
        pass "one stance plotted without gnuplot warnings"; else fail "one-stance plot: $(grep -i warn "$T/err" | head -2)"; fi
fi

# time-stamp jitter whose spread grows through the log (5 -> 40 us) is
# selected, but its rate fitted on the fit segment is refuted on the held-out
# one: not stationary, so the verdict is not "explained" (a selected timing
# effect never kept it from "explained" before); the same log with a steady
# 20 us jitter is explained, its stamp_s within 10 %
"$H" sim --motion stand:120 --rate 100 --profile mtx --seed 4 --out "$T/jt.csv" >/dev/null 2>&1 || fail "sim jitter base"
for mode in ramp flat; do
    "$PY" - "$T/jt.csv" "$T/jt_$mode.csv" "$mode" <<'PYEOF'
import sys
import numpy as np
src, dst, mode = sys.argv[1:4]
lines = open(src).read().splitlines()
n = len(lines) - 1
sd = np.linspace(5e-6, 40e-6, n) if mode == "ramp" else np.full(n, 20e-6)
t = np.arange(n) * 0.01 + np.random.default_rng(7).normal(0.0, 1.0, n) * sd
with open(dst, "w") as f:
    f.write(lines[0] + "\n")
    for k in range(n):
        f.write("%.9f,%s\n" % (t[k], lines[k + 1].split(",", 1)[1]))
PYEOF
    "$H" simgap "$T/jt_$mode.csv" --seeds 6 --json "$T/jt_$mode.json" > "$T/jt_$mode.out" 2>&1
done
sel='[e for e in j["timing"]["selected"] if e["effect"] == "jitter"]'
json "$T/jt_ramp.json" "len($sel) == 1 and $sel[0][\"held_out_within_noise\"] is False and j[\"verdict\"][\"answer\"] == \"partly-explained\"" &&
    grep -q "jitter: .*beyond noise: .*not stationary" "$T/jt_ramp.out" &&
    pass "jitter that grows: selected, refuted held out, partly explained" || fail "growing jitter: $(grep -E 'jitter|verdict' "$T/jt_ramp.out")"
json "$T/jt_flat.json" "len($sel) == 1 and $sel[0][\"held_out_within_noise\"] is True and j[\"verdict\"][\"answer\"] == \"explained\" and abs($sel[0][\"params\"][\"stamp_s\"] / 20e-6 - 1) < 0.1" &&
    pass "steady jitter: explained, stamp_s within 10 %" || fail "steady jitter: $(grep -E 'jitter|verdict' "$T/jt_flat.out") $(cat "$T/pyerr")"
# an ideal 300 Hz clock whose stamps are written in milliseconds: every
# interval is 3 or 4 ms (a third of them 4), spread sqrt(p (1 - p)) ms =
# 0.471 ms with p = frac(3.333) — the rounding's, not jitter. Against the
# average rounding res/sqrt(6) = 0.408 ms it would be "jitter, 38.6 sigma"
# and the verdict "explained: jitter (stamp_s 0.000167 s)" on a clean log
"$H" sim --motion stand:120 --rate 300 --profile mtx --seed 4 --out "$T/ms.csv" >/dev/null 2>&1 || fail "sim 300 Hz"
awk -F, 'BEGIN { OFS = "," } NR > 1 { $1 = sprintf("%.3f", $1) } { print }' "$T/ms.csv" > "$T/ms3.csv"
"$H" simgap "$T/ms3.csv" --seeds 6 --json "$T/ms3.json" > "$T/ms3.out" 2>&1
json "$T/ms3.json" 'j["timing"]["stamp_resolution_s"] == 0.001 and j["timing"]["selected"] == [] and not j["timing"]["significant"] and j["verdict"]["answer"] == "none"' &&
    pass "stamps rounded to 1 ms at 300 Hz: no jitter" || fail "ms stamps at 300 Hz: $(grep -E 'jitter|verdict' "$T/ms3.out") $(cat "$T/pyerr")"
# 500 samples dropped in one place in the held-out middle: the fit segment
# has none, so the fitted rate is that of the ideal clock, and the held-out
# count's z after fitting is the z before it (both Poisson, capped at 40);
# not 40 before and +2235.8 after, a normal approximation without the cap
"$H" sim --motion stand:120 --rate 100 --profile mtx --seed 4 --out "$T/dr.csv" >/dev/null 2>&1 || fail "sim dropout base"
awk 'NR < 5502 || NR > 6001' "$T/dr.csv" > "$T/dr5.csv"
"$H" simgap "$T/dr5.csv" --seeds 6 --json "$T/dr5.json" > "$T/dr5.out" 2>&1
sel='[e for e in j["timing"]["selected"] if e["effect"] == "dropout"]'
json "$T/dr5.json" "len($sel) == 1 and $sel[0][\"params\"][\"prob\"] == 0 and $sel[0][\"z_held_out_before\"] == $sel[0][\"z_held_out_after\"] == 40 and $sel[0][\"held_out_within_noise\"] is False" &&
    grep -q "dropped samples: 40.0 sigma above an ideal clock; held out after fitting: +40.0 sigma" "$T/dr5.out" &&
    pass "drops in the held-out part only: the same z before and after a fit of rate 0" || fail "dropout z: $(grep -E 'dropped|verdict' "$T/dr5.out") $(cat "$T/pyerr")"
# and the static analysis's join across the gap said, as allan says it
# (five 2 s gaps moved a real log's line and rrw answers unsaid: the
# simgap audit)
if grep -q "1 gap (longest 5.01 s; about 500 samples missing in all, 4.2 % of the log): the static analysis (Allan variances, lines) joins the samples across it as if consecutive" "$T/dr5.out"; then
    pass "the gap joined by the static analysis said"
else fail "the static analysis's gap not said: $(grep -i gap "$T/dr5.out")"; fi
# against the stamps' own period and resolution: 800 Hz stamped to the ms
# (intervals of 1 and 2 ms) has no gap (it warned of 12000, 20 %)
"$H" sim --motion stand:60 --rate 800 --profile mtx --seed 4 --out "$T/s800.csv" >/dev/null 2>&1 || fail "sim 800 Hz"
awk -F, 'BEGIN{OFS=","} NR==1{print;next}{$1=sprintf("%.3f",$1);print}' "$T/s800.csv" > "$T/s800ms.csv"
"$H" simgap "$T/s800ms.csv" --seeds 4 --max-effects 0 > "$T/s800.out" 2>&1
if grep -q "gaps\? (longest" "$T/s800.out"; then fail "stamps to the ms at 800 Hz read as gaps: $(grep 'longest' "$T/s800.out")"
else pass "stamps to the ms at 800 Hz: no gap said"; fi

# an AR(1) bias correlated far longer than the record (2000 s in 600 s)
# fits at the baseline's bound on its correlation time, which the summary
# and the JSON say (a user read three gyros at "tau 20.5 s" as measured
# times; docs/workflow.md), and the catalogue's rate random walk stands in
# for it with K = sigma sqrt(2 / T) (1.58e-4 m/s^2/sqrt(s) here) to within
# 25 %; a short one (0.5 s) is fitted inside the bound
"$H" sim --motion stand:600 --rate 100 --profile none --effect white:ch=ax+ay+az+gx+gy+gz:density=0.001 \
    --effect ar1:ch=ax:tau_s=0.5:sigma=0.005 --effect ar1:ch=ay:tau_s=2000:sigma=0.005 --seed 5 \
    --out "$T/tb.csv" >/dev/null 2>&1 || fail "sim long and short AR(1)"
"$H" simgap "$T/tb.csv" --seeds 6 --quiet --json "$T/tb.json" > "$T/tb.out" 2>&1
b='{c["channel"]: c["baseline"] for c in j["channels"]}'
rrw='[e for e in j["channels"][1]["attribution"]["selected"] if e["effect"] == "rrw"]'
json "$T/tb.json" "$b[\"ay\"][\"ar1_tau_at_max\"] and $b[\"ay\"][\"ar1_tau_s\"] >= 0.999 * $b[\"ay\"][\"ar1_tau_max_s\"] and not $b[\"ax\"][\"ar1_tau_at_max\"] and 0.4 < $b[\"ax\"][\"ar1_tau_s\"] < 0.6 and len($rrw) == 1 and abs($rrw[0][\"params\"][\"k\"] / 1.58e-4 - 1) < 0.25" &&
    grep -q "^  ay .*, tau at the longest this log resolves\$" "$T/tb.out" && ! grep -q "^  ax .*longest" "$T/tb.out" &&
    grep -q "^  (tau at the longest this log resolves: a quarter of the longest Allan tau analysed" "$T/tb.out" &&
    pass "AR(1) beyond the record: tau at its bound, said; rrw stands in with K = sigma sqrt(2/T)" ||
    fail "AR(1) at the bound: $(grep -E 'ar1|rrw|verdict' "$T/tb.out") $(cat "$T/pyerr")"

# a walk with a 40 s stand: the navigation windows in which no stance
# begins carry no first update; they are placeholders outside G, said so
# in the summary and null in the JSON (not points of value 1e-30 with z 0
# that dilute G)
"$H" sim --motion stand:5,walk:15,stand:40,walk:15 --profile mtx --seed 3 --out "$T/pw.csv" >/dev/null 2>&1 || fail "sim walk with a stand"
"$H" simgap "$T/pw.csv" --seeds 6 --json "$T/pw.json" > "$T/pw.out" 2>&1
n_empty=$(grep -c "window .*no stance begins in it (a stand), not compared" "$T/pw.out")
json "$T/pw.json" 'sum(1 for p in j["navigation"]["gap"]["full"]["points"] if p["kind"] == "window" and p["real"] is None and p["z"] is None) == 3' &&
    [ "$n_empty" -eq 3 ] && pass "windows inside a stand are not compared (summary and JSON)" ||
    fail "stand windows: $n_empty in the summary; $(cat "$T/pyerr")"
# each compared window names its time span (six rows read alike)
grep -q "^    window            t 0.0-11.5 s    real " "$T/pw.out" && grep -q "^    window            t 57.5-69.0 s   real " "$T/pw.out" &&
    grep -q "^    window            t 23.0-34.5 s: no stance begins in it (a stand), not compared" "$T/pw.out" &&
    pass "windows named by their time span" || fail "window labels: $(grep -E 'window' "$T/pw.out")"
# a stance across the fit/held-out split (the 40 s stand, in progress at
# the split sample, 41.4 s) began in the fit segment: it is the fit's, and
# the held-out stances begin with the first stance that begins at or after
# the split (docs/simgap.md, section 2). It is not held out too, from the
# split sample on, with a mid-stance update as its "first" (23 stances, fit
# 12, held out 12, "the stance across the split in both")
json "$T/pw.json" '(n := j["navigation"])["stances_fit"] == 12 and n["stances_held_out"] == 11 and n["stances_full"] == 23 and n["held_out_from_s"] > j["split"]["held_out"][0]["start_s"]' &&
    grep -q "^navigation: 23 stances (fit 12, held out 11 from t [0-9.]* s, the first stance to begin at or after the split at 41.4 s); " "$T/pw.out" &&
    pass "the stance across the split is the fit's, not held out" ||
    fail "stance across the split: $(grep -E 'navigation:' "$T/pw.out") $(cat "$T/pyerr")"

# a held-out gap left (no effect tried): the arrow line gives G and max |z|
# with their critical values, the final comparison's, as the JSON has them
# (not only "a significant held-out gap remains", also where G is below its
# critical value and one point's |z| makes it)
"$H" sim --motion stand:600 --rate 100 --profile mtx --effect quant:ch=gz:lsb=0.001 --seed 3 --out "$T/qg.csv" >/dev/null 2>&1 || fail "sim lattice"
"$H" simgap "$T/qg.csv" --seeds 6 --max-effects 0 --quiet --json "$T/qg.json" > "$T/qg.out" 2>&1
line=$(grep "^  -> a significant held-out gap remains (" "$T/qg.out")
json "$T/qg.json" "$(printf '%s' "$line" | sed -n 's/.*(G \([0-9.e+-]*\), critical \([0-9.e+-]*\); max |z| \([0-9.e+-]*\), critical \([0-9.e+-]*\))$/[\1, \2, \3, \4]/p') == (lambda h: [float('%.3g' % h['G']), float('%.3g' % h['G_crit']), round(h['max_abs_z'], 2), round(h['z_crit'], 2)])([c for c in j['channels'] if c['channel'] == 'gz'][0]['gap_final']['held_out'])" &&
    pass "a remaining held-out gap names G, max |z| and their critical values" || fail "remaining gap line: $line $(cat "$T/pyerr")"

# white noise only: a baseline AR(1) fitted to sigma 0 is printed as none,
# not with a tau (the JSON's is null)
"$H" sim --motion stand:120 --rate 100 --profile mtx --effect ar1:off --seed 3 --out "$T/wn.csv" >/dev/null 2>&1 || fail "sim white only"
"$H" simgap "$T/wn.csv" --seeds 6 > "$T/wn.out" 2>&1
expect_exit 0 "static log with --closed" "$H" simgap "$T/wn.csv" --quiet --seeds 4 --closed
expect_err "--closed is for walks .*ignored on a static log" "--closed on a static log said to be ignored"
# a tone on gx: every location's ratio lies on its z's side (a ratio of real
# over the bare twin mean, while z is the residual after the parameter
# uncertainty's correction, would give "34.9 sigma below the twin (ADEV x1.11)")
"$H" sim --motion stand:300 --rate 100 --profile mtx --effect vibration:ch=gx:amp=0.01:freq_hz=12 --seed 5 --out "$T/vt.csv" >/dev/null 2>&1 || fail "sim tone"
"$H" simgap "$T/vt.csv" --quiet --seeds 8 --json "$T/vt.json" >/dev/null 2>&1
json "$T/vt.json" 'len(j["locations"]) > 4 and all(((l["ratio"] > 1) if l["domain"] in ("allan", "psd") else (l["ratio"] > 0)) == (l["peak_z"] > 0) for l in j["locations"] if l["domain"] != "lattice")' &&
    pass "location ratios on their z's side" || fail "location ratio against z: $(cat "$T/pyerr")"
# ... the tone is answered with 8 twins; with 3 every effect would score 0
# sigma on the held-out tests (they need 4) and it be "unexplained", exit 0:
# a usage error for a static log that is attributed
json "$T/vt.json" '[(e["effect"], e["channels"]) for e in j["verdict"]["effects"]] == [("vibration", ["gx"])]' &&
    pass "the tone answered with 8 twins" || fail "tone verdict: $(cat "$T/pyerr")"
expect_exit 2 "a static log with --seeds 3" "$H" simgap "$T/vt.csv" --quiet --seeds 3
expect_err "--seeds 3 is too few for a static log" "--seeds 3 on a static log said"
if grep -q "ar1 (none: sigma 0)" "$T/wn.out" && ! grep -q "ar1 (sigma 0 " "$T/wn.out"; then
    pass "an AR(1) of sigma 0 is printed as none"; else fail "sigma-0 AR(1): $(grep 'ar1 (' "$T/wn.out" | head -3)"; fi

# more than 64 gap locations (two tones, a ramp and a rate random walk on
# every channel): every one is kept, the last channel's too (the first 64
# were kept and the rest dropped without a word)
"$H" sim --motion stand:300 --rate 100 --profile mtx --seed 2 --effect vibration:ch=ax+ay+az+gx+gy+gz:freq_hz=7 \
    --effect vibration:ch=ax+ay+az+gx+gy+gz:freq_hz=23 --effect ramp:ch=ax+ay+az+gx+gy+gz \
    --effect rrw:ch=ax+ay+az+gx+gy+gz --out "$T/many.csv" >/dev/null 2>&1 || fail "sim many gaps"
"$H" simgap "$T/many.csv" --max-effects 0 --json "$T/many.json" > /dev/null 2>&1
json "$T/many.json" 'len(j["locations"]) > 64 and j["locations_dropped"] == 0 and any(l["channel"] == "gz" for l in j["locations"])' &&
    pass "more than 64 locations kept, the last channel's too" || fail "locations: $(cat "$T/pyerr")"

# logs without any noise (simulated with --profile none): the twins do not
# vary, so no gap can be tested; a one-line error and exit 1, not SIGABRT
"$H" sim --duration 30 --profile none --out "$T/nf.csv" >/dev/null 2>&1 || fail "sim noise-free walk"
expect_exit 1 "noise-free walk" "$H" simgap "$T/nf.csv" --quiet --seeds 3
expect_err "^harness simgap: error: .*nf.csv: .*twins do not vary" "noise-free walk: said why"
"$H" sim --motion stand:20 --profile none --out "$T/nfs.csv" >/dev/null 2>&1 || fail "sim noise-free still log"
expect_exit 1 "noise-free still log as a walk" "$H" simgap "$T/nfs.csv" --quiet --seeds 3 --walk
expect_err "^harness simgap: error: " "noise-free still log as a walk: an error line"
# a --plot directory made for the check before the diagnosis is not left
# made and empty by a run that ends before its plots (an input that cannot
# be read, a log without noise; Ctrl-C alike)
expect_exit 1 "missing input with --plot" "$H" simgap "$T/nope.csv" --quiet --plot "$T/nopeplot"
[ ! -e "$T/nopeplot" ] && pass "missing input: no --plot directory left" || fail "missing input: $T/nopeplot left made"
expect_exit 1 "noise-free walk with --plot" "$H" simgap "$T/nf.csv" --quiet --seeds 3 --plot "$T/nfplot"
[ ! -e "$T/nfplot" ] && pass "noise-free walk: no --plot directory left" || fail "noise-free walk: $T/nfplot left made"

# incomplete input: the diagnosis runs on the samples before the error, and
# exit 1 comes with the line (or record) warned once, naming the file and
# line, and a closing error of the samples used, as info's and psd's (the
# bad line was said twice, "(using the N samples before it)" as a warning
# and again as the error, "(diagnosed on the N samples before it)")
"$H" sim --motion stand:4 --rate 100 --profile mtx --seed 2 --out "$T/tx.csv" >/dev/null 2>&1 || fail "sim text"
{ head -n 301 "$T/tx.csv"; echo abc; } > "$T/tx2.csv"
expect_exit 1 "CSV with text at line 302" "$H" simgap "$T/tx2.csv" --quiet --seeds 4 --json "$T/tx2.json"
expect_err "^harness simgap: warning: .*tx2.csv:302: .*(using the 300 samples before it)$" "text in the CSV: warned with FILE:LINE"
expect_err "^harness simgap: error: .*tx2.csv: incomplete input (warned above): the .*300 samples before the error" \
    "text in the CSV: a closing error of the samples used"
n=$(grep -c "tx2.csv:302" "$T/err")
[ "$n" -eq 1 ] && pass "text in the CSV: the bad line said once" || fail "text in the CSV: the bad line said $n times"
[ -s "$T/tx2.json" ] && pass "text in the CSV: JSON still written" || fail "text in the CSV: no JSON"
# the JSON says the input stopped early, as replay's, info's and psd's do
# (without a key for it a log cut at a bad line reads as a whole one)
json "$T/tx2.json" 'j["complete"] is False and "tx2.csv:302" in j["error"] and j["log"]["samples"] == 300' &&
    pass "text in the CSV: JSON complete false, error names FILE:LINE" || fail "text in the CSV: JSON complete/error: $(cat "$T/pyerr")"
head -c 50000 "$(dirname "$0")/../../vectors/walk.bin" > "$T/trunc.bin"
expect_exit 1 "truncated .bin" "$H" simgap "$T/trunc.bin" --quiet --seeds 4
expect_err "^harness simgap: warning: .*trunc.bin: truncated" "truncated .bin: warned"
expect_err "^harness simgap: error: .*trunc.bin: incomplete input (warned above)" "truncated .bin: error line"

# a static log above 1 kHz whose AR(1) time is near the catalogue's 1 ms:
# were the baseline fit's time grid to begin at one sample (0.25 ms), the
# fitted 0.9995 ms would be refused by the simulator and every twin fail
# ("twin simulation failed on channel ax", exit 1)
"$H" sim --motion stand:30 --rate 4000 --profile mtx --effect ar1:tau_s=0.001:sigma=0.05 --seed 3 --out "$T/hr.csv" >/dev/null 2>&1 || fail "sim 4 kHz"
expect_exit 0 "static log at 4 kHz with an AR(1) of 1 ms" "$H" simgap "$T/hr.csv" --static --quiet --seeds 6 --json "$T/hr.json"
json "$T/hr.json" 'all(c["baseline"]["ar1_tau_s"] >= 0.001 and c["baseline"]["ar1_sigma"] > 0.04 for c in j["channels"])' &&
    pass "4 kHz: the AR(1) fitted within the catalogue" || fail "4 kHz AR(1): $(cat "$T/pyerr")"

# a static CSV (t,ax,ay,az,gx,gy,gz, SI) of 600 s at 100 Hz, MTx noise, gyro z
# rounded to 0.001 rad/s: found on gz (lattice), attributed to quant with the
# right LSB, the held-out gap explained, no other channel flagged
"$H" sim --motion stand:600 --rate 100 --profile mtx --seed 3 --effect quant:ch=gz:lsb=0.001 \
    --out "$T/q.csv" >/dev/null 2>&1 || fail "sim quant"
head -n 1 "$T/q.csv" | grep -q '^t,ax,ay,az,gx,gy,gz$' && pass "CSV input header" || fail "CSV header"
expect_exit 0 "static log with quantisation" "$H" simgap "$T/q.csv" --quiet --seeds 8 --json "$T/q.json" --plot "$T/qp"
grep -q "^verdict: explained (parameters of the final refit on the fit segment, the first and last 30 %): quant" "$T/out" && pass "summary names quant, its parameters labelled as the final refit" || fail "summary: $(grep verdict "$T/out")"
json "$T/q.json" 'j["schema"] == "footnav-simgap/1" and j["log"]["domain"] == "static" and j["log"]["domain_from"] == "detected" and j["complete"] is True and "error" not in j' &&
    pass "JSON schema and domain" || fail "JSON schema/domain: $(cat "$T/pyerr")"
json "$T/q.json" 'j["verdict"]["answer"] == "explained" and j["verdict"]["unconfirmed"] == [] and j["effects"][0]["effect"] == "quant" and j["effects"][0]["rank"] == 1 and [c["channel"] for c in j["effects"][0]["channels"]] == ["gz"]' &&
    pass "quant ranked first, on gz only" || fail "ranked effects: $(cat "$T/pyerr")"
json "$T/q.json" 'abs(j["effects"][0]["channels"][0]["params"]["lsb"] / 0.001 - 1) < 0.01 and j["effects"][0]["channels"][0]["explained"] >= 0.7' &&
    pass "LSB within 1 %, held-out gap explained >= 70 %" || fail "quant parameters: $(cat "$T/pyerr")"
json "$T/q.json" '[c["channel"] for c in j["channels"] if c["gap_significant"]] == ["gz"] and any(l["channel"] == "gz" and l["domain"] == "lattice" for l in j["locations"])' &&
    pass "gap located on gz, lattice domain" || fail "locations: $(cat "$T/pyerr")"
# a lattice location's ratio is real - twin of the lattice score, as for the
# time domain (docs/simgap.md, not real/twin)
json "$T/q.json" 'len([l for l in j["locations"] if l["domain"] == "lattice"]) >= 1 and all(abs(l["ratio"] - (p["real"] - p["twin"])) < 1e-6 * (1 + abs(l["ratio"])) for l in j["locations"] if l["domain"] == "lattice" for c in j["channels"] if c["channel"] == l["channel"] for p in c["points"]["full"] if p["domain"] == "lattice")' &&
    pass "lattice location: ratio is real - twin" || fail "lattice location ratio: $(cat "$T/pyerr")"
json "$T/q.json" 'all(c["attribution"]["within_noise"] for c in j["channels"])' &&
    pass "remaining gap within noise on every channel" || fail "within noise: $(cat "$T/pyerr")"
# the forward selection stops once the held-out gap is within noise
# (docs/simgap.md, "Stopping rule" (a)): gz, explained by quant at its first
# step, has no second one (with the rule read from the third step on, a
# hand-made mutant, gz has two, and without this check every test passes)
json "$T/q.json" 'j["channels"][5]["channel"] == "gz" and len(j["channels"][5]["attribution"]["steps"]) == 1' &&
    pass "no step after the held-out gap is explained" || fail "steps after within noise: $(cat "$T/pyerr")"
json "$T/q.json" 'j["split"]["method"].startswith("sandwich") and all(abs(cd["z"] - (cd["z_held_out_middle"] + cd["z_held_out_ends"]) / 2 ** 0.5) < 1e-6 * (1 + abs(cd["z"])) for c in j["channels"] for s in c["attribution"]["steps"] for cd in s["candidates"] if cd["simulated"] and cd["z_held_out_ends"] is not None) and any(cd["effect"] == "quant" and cd["selected"] and cd["z_held_out_ends"] is not None and cd["z_held_out_middle"] > 0 and cd["z_held_out_ends"] > 0 for s in j["channels"][5]["attribution"]["steps"] for cd in s["candidates"])' &&
    pass "both folds scored: z combines middle and ends, quant significant on both" || fail "two folds: $(cat "$T/pyerr")"
json "$T/q.json" 'all(sorted(p["kind"] for p in c["points"]["held_out"] if p["domain"] == "time") == ["curvature", "steps", "trend"] for c in j["channels"]) and all(cd["z_lr"] is not None and abs(cd["z_lr"] - (cd["z_lr_held_out_middle"] + cd["z_lr_held_out_ends"]) / 2 ** 0.5) < 1e-6 * (1 + abs(cd["z_lr"])) for c in j["channels"] for s in c["attribution"]["steps"] for cd in s["candidates"] if cd["simulated"] and cd["z_lr_held_out_ends"] is not None)' &&
    pass "time-domain points per channel; likelihood-ratio z combines both folds" || fail "time domain / z_lr: $(cat "$T/pyerr")"
[ -s "$T/qp/allan.png" ] && [ -s "$T/qp/psd.png" ] && [ -s "$T/qp/z.png" ] && pass "plots written" || fail "plots: $(ls "$T/qp" 2>&1)"
expect_exit 3 "unwritable JSON" "$H" simgap "$T/q.csv" --quiet --seeds 3 --max-effects 0 --json /nonexistent/dir/q.json

# deterministic drifts (docs/simgap.md, section 4: fitted on the blocks'
# trend, curvature and level, signs included). A warm-up on gz (coef -2e-4
# rad/s/degC over the default 10 degC rise, tau 100 s) and a ramp on gx
# (-1e-6 rad/s/s, whose Allan excess lies beyond the longest tau analysed
# of a 600 s log) are named on their channel with their signed parameters
# within 25 %; the ramp's warm-up rival is set aside as nested in it.
# 16 twins, as the validation: with 8 the acceptance level (Student's t
# with 7 degrees of freedom at alpha/60) is 5.0 sigma
"$H" sim --motion stand:600 --rate 100 --profile mtx --seed 7 --effect thermal:ch=gz:coef=-0.0002:tau_s=100 \
    --out "$T/th.csv" >/dev/null 2>&1 || fail "sim thermal"
expect_exit 0 "static log with a warm-up" "$H" simgap "$T/th.csv" --quiet --seeds 16 --json "$T/th.json"
json "$T/th.json" '(lambda e: e["effect"] == "thermal" and [c["channel"] for c in e["channels"]] == ["gz"] and abs(e["channels"][0]["params"]["coef"] / -2e-4 - 1) < 0.25 and abs(e["channels"][0]["params"]["tau_s"] / 100 - 1) < 0.25)(j["effects"][0])' &&
    pass "warm-up on gz, coefficient (sign included) and time constant within 25 %" || fail "thermal: $(cat "$T/pyerr"; grep verdict "$T/out")"
"$H" sim --motion stand:600 --rate 100 --profile mtx --seed 8 --effect ramp:ch=gx:rate=-1e-6 \
    --out "$T/rp.csv" >/dev/null 2>&1 || fail "sim ramp"
expect_exit 0 "static log with a ramp" "$H" simgap "$T/rp.csv" --quiet --seeds 16 --json "$T/rp.json"
json "$T/rp.json" '(lambda e: e["effect"] == "ramp" and [c["channel"] for c in e["channels"]] == ["gx"] and abs(e["channels"][0]["params"]["rate"] / -1e-6 - 1) < 0.25)(j["effects"][0]) and any(cd["effect"] == "thermal" and cd["nested_in_ramp"] and not cd["simulated"] for s in j["channels"][3]["attribution"]["steps"] for cd in s["candidates"])' &&
    pass "ramp on gx, signed rate within 25 %, the warm-up nested in it" || fail "ramp: $(cat "$T/pyerr"; grep verdict "$T/out")"

# a bias offset of 1e-3 rad/s on gx in the first and last 30 % only (the
# fit segment): the whole log's gap is significant, the held-out middle has
# none, so no effect is confirmed; the verdict is `unexplained` and the
# summary says why on gx alone
"$H" sim --motion stand:600 --rate 100 --profile mtx --seed 9 --out "$T/e.csv" >/dev/null 2>&1 || fail "sim ends"
"$PY" -c '
import sys
src, dst = open(sys.argv[1]), open(sys.argv[2], "w")
hdr = src.readline()
dst.write(hdr)
gi = hdr.strip().split(",").index("gx")
for line in src:
    f = line.strip().split(",")
    if float(f[0]) < 180.0 or float(f[0]) >= 420.0:
        f[gi] = "%.9g" % (float(f[gi]) + 1e-3)
    dst.write(",".join(f) + "\n")
' "$T/e.csv" "$T/e2.csv" || fail "offset the ends"
expect_exit 0 "gap in the fit segment only" "$H" simgap "$T/e2.csv" --quiet --seeds 16 --json "$T/e2.json"
grep -q "^  gx: the whole log's gap .* does not show on the held-out middle .* so no effect can be confirmed" "$T/out" &&
    [ "$(grep -c "^  [ag][xyz]: " "$T/out")" -eq 1 ] && pass "summary: the unconfirmed gap on gx said, no other channel" ||
    fail "unconfirmed gap: $(grep -A3 verdict "$T/out")"
json "$T/e2.json" 'j["verdict"]["answer"] == "unexplained" and j["verdict"]["effects"] == [] and [c["channel"] for c in j["channels"] if c["gap"]["full"]["significant"]] == ["gx"] and not j["channels"][3]["gap"]["held_out"]["significant"] and [(u["channel"], u["reason"]) for u in j["verdict"]["unconfirmed"]] == [("gx", "not-held-out")]' &&
    pass "unconfirmed gap: verdict unexplained, gap on gx, none held out" || fail "unconfirmed JSON: $(cat "$T/pyerr")"

# --walk on a static log is honoured (domain given, not detected)
expect_exit 0 "domain given" "$H" simgap "$T/q.csv" --quiet --seeds 3 --max-effects 0 --static --json "$T/g.json"
json "$T/g.json" 'j["log"]["domain_from"] == "option"' && pass "domain_from option" || fail "domain_from: $(cat "$T/pyerr")"

# --profile on a static log: the given parameterisation is tested as is.
# A log simulated with the MTx profile: the MTx model shows no gap, the
# NavChip model (7x lower gyro noise) a gap on every channel, located in the
# Allan and PSD domains; the fitted baseline has none either way
"$H" sim --motion stand:300 --rate 100 --profile mtx --seed 5 --out "$T/m.csv" >/dev/null 2>&1 || fail "sim mtx"
expect_exit 0 "given profile, right" "$H" simgap "$T/m.csv" --quiet --seeds 8 --max-effects 0 --profile mtx --json "$T/m1.json"
json "$T/m1.json" 'j["profile"] == "mtx" and not any(c["profile"]["gap"]["full"]["significant"] or c["gap"]["full"]["significant"] for c in j["channels"]) and j["profile_locations"] == []' &&
    pass "the right profile explains the log" || fail "right profile: $(cat "$T/pyerr")"
expect_exit 0 "given profile, wrong" "$H" simgap "$T/m.csv" --quiet --seeds 8 --max-effects 0 --profile navchip --json "$T/m2.json" --plot "$T/mp"
json "$T/m2.json" 'all(c["profile"]["gap"]["full"]["significant"] and c["profile"]["gap"]["held_out"]["significant"] and not c["gap"]["full"]["significant"] for c in j["channels"]) and {l["channel"] for l in j["profile_locations"] if l["domain"] == "allan" and l["ratio"] > 5} == {"gx", "gy", "gz"}' &&
    pass "the wrong profile: gap on every channel, gyro ADEV x5+" || fail "wrong profile: $(cat "$T/pyerr")"
grep -q "^where the given model misses" "$T/out" && pass "summary lists where the profile misses" || fail "profile summary"
expect_exit 2 "unknown profile (refused before the log is read)" "$H" simgap "$T/m.csv" --quiet --seeds 3 --profile "$T/nope.profile"

# a simulated walk (CSV): detected as a walk, the navigation domain reported
# (innovations per stance, the filter's model gap kept apart from the sensor
# verdict); a 12 s walk has too few held-out stances for a confident answer
"$H" sim --motion walk --duration 40 --rate 100 --profile mtx --seed 4 --out "$T/w.csv" >/dev/null 2>&1 || fail "sim walk"
expect_exit 0 "walk log" "$H" simgap "$T/w.csv" --quiet --seeds 6 --json "$T/w.json" --plot "$T/wp"
json "$T/w.json" 'j["log"]["domain"] == "walk" and j["log"]["domain_from"] == "detected" and j["navigation"]["stances_held_out"] >= 10 and "model_gap" in j["navigation"] and j["verdict"]["answer"] == "none"' &&
    pass "walk detected, navigation domain in the JSON, no sensor effect claimed" || fail "walk JSON: $(cat "$T/pyerr")"
[ -s "$T/wp/innovations.png" ] && pass "innovation plot" || fail "innovation plot: $(ls "$T/wp" 2>&1)"
# the split's blocks are timed by the log's stamps, as the navigation
# windows are: with 15-25 s cut out, the held-out segment's first sample
# (index 1800 of 3001) is at 28 s, where index / rate would say 18 s; too
# short a walk, but the JSON is written
awk -F, 'NR == 1 || $1 < 15 || $1 >= 25' "$T/w.csv" > "$T/wgap.csv"
"$H" simgap "$T/wgap.csv" --quiet --seeds 3 --json "$T/wgap.json" >/dev/null 2>&1
json "$T/wgap.json" 'j["split"]["held_out"][0]["samples"] == 1201 and abs(j["split"]["held_out"][0]["start_s"] - 28.0) < 1e-6 and j["split"]["fit"][0]["end_s"] == j["split"]["held_out"][0]["start_s"] and abs(j["split"]["held_out"][0]["end_s"] - 40.01) < 1e-6' &&
    pass "walk with a gap: the split's times are the stamps'" || fail "split times: $(cat "$T/pyerr")"
# and its duration is the stamps' span plus a period (not n / rate, 30.01 s,
# in the JSON and the summary's first line)
json "$T/wgap.json" 'abs(j["log"]["duration_s"] - 40.01) < 1e-6 and j["log"]["samples"] == 3001' &&
    pass "walk with a gap: its duration from the stamps" || fail "duration: $(cat "$T/pyerr")"
# an option of the other domain is said to be ignored, not dropped silently
# (--contiguous on a walk, --closed on a static log)
expect_exit 0 "walk with --contiguous" "$H" simgap "$T/w.csv" --quiet --seeds 3 --contiguous
expect_err "--contiguous is for static logs .*ignored on a walk" "--contiguous on a walk said to be ignored"
# the same walk with its accelerometer in g: named before any work, exit 1
awk -F, 'NR == 1 { print; next } { printf "%s,%.7g,%.7g,%.7g,%s,%s,%s\n", $1, $2 / 9.80665, $3 / 9.80665, $4 / 9.80665, $5, $6, $7 }' \
    "$T/w.csv" > "$T/wg.csv"
expect_exit 1 "walk in g" "$H" simgap "$T/wg.csv" --quiet --seeds 4
expect_err "not in m/s^2 but in g (give --units accel=g)" "a walk in g is named as such, with the --units item"
# the same walk (in rad/s) read with --units gyro=deg/s: 57.3 times too small, a walk that never turns faster
# than 0.75 rad/s, detected as static (its rates stay below 1 rad/s), must not be analysed as one without a word;
# named as replay names it: a warning of the static analysis, and with --walk
# an error before any work, exit 1
expect_exit 0 "walk in rad/s read with gyro=deg/s" "$H" simgap "$T/w.csv" --quiet --seeds 4 --units gyro=deg/s
expect_err "the log is in rad/s already? (read as deg/s by --units gyro=deg/s: leave gyro=deg/s out)" \
    "simgap: a walk in rad/s read with gyro=deg/s is named"
expect_exit 1 "walk in rad/s read with gyro=deg/s, --walk" "$H" simgap "$T/w.csv" --quiet --seeds 4 --walk \
    --units gyro=deg/s
expect_err "the log is in rad/s already? (read as deg/s by --units gyro=deg/s: leave gyro=deg/s out)" \
    "simgap --walk: a walk in rad/s read with gyro=deg/s is named"
# a static log with its gyro in deg/s: its noise of tenths of a "rad/s"
# reaches 1 rad/s within every second, so it must not be detected as a walk
# without a stance and answered "too short" for its stances (exit 1): it is
# static, with a warning naming deg/s
"$H" sim --motion stand:30 --rate 100 --profile mtx --seed 3 --out "$T/sd.csv" >/dev/null 2>&1 || fail "sim static for deg/s"
awk -F, 'NR == 1 { print; next } { printf "%s,%s,%s,%s,%.7g,%.7g,%.7g\n", $1, $2, $3, $4, $5 * 57.29577951308232, $6 * 57.29577951308232, $7 * 57.29577951308232 }' \
    "$T/sd.csv" > "$T/sdeg.csv"
expect_exit 0 "static log with the gyro in deg/s" "$H" simgap "$T/sdeg.csv" --quiet --seeds 4 --max-effects 0 --json "$T/sdeg.json"
json "$T/sdeg.json" 'j["log"]["domain_detected"] == "static" and j["verdict"]["answer"] != "too-short"' &&
    pass "a static gyro in deg/s is detected as static" || fail "static deg/s domain: $(cat "$T/pyerr")"
expect_err "spreads by 0.[0-9]* rad/s RMS .* probably in deg/s (give --units gyro=deg/s)" \
    "a static gyro in deg/s is named, with the --units item"
expect_exit 0 "the same static log in rad/s" "$H" simgap "$T/sd.csv" --quiet --seeds 4 --max-effects 0
if grep -q "deg/s" "$T/err"; then fail "a static gyro in rad/s named as deg/s"; else pass "no deg/s warning on a static gyro in rad/s"; fi
# a walk in rad/s given --static: its gyro's spread is the motion's, not a
# unit; it was warned "probably in deg/s (give --units gyro=deg/s)", a remedy
# that makes its rates 57 times too small. The summary says it looks like a walk
"$H" sim --motion walk --duration 30 --rate 100 --profile mtx --seed 3 --out "$T/wks.csv" >/dev/null 2>&1 || fail "sim walk for --static"
expect_exit 0 "a walk in rad/s given --static" "$H" simgap "$T/wks.csv" --quiet --seeds 3 --max-effects 0 --static
if grep -q "deg/s" "$T/err"; then fail "a walk given --static named as deg/s: $(cat "$T/err")"; else pass "no deg/s warning on a walk given --static"; fi
expect_out "^domain: static as given (--static); the log looks like a walk" "a walk given --static: said on the summary"
# the same static log with its time column in milliseconds (100 Hz read as
# 0.1 Hz): not analysed at 0.1 Hz without a word, as allan and psd name the
# unit; a warning, the status unchanged
awk -F, 'NR == 1 { print; next } { printf "%.6f,%s,%s,%s,%s,%s,%s\n", $1 * 1000, $2, $3, $4, $5, $6, $7 }' "$T/sd.csv" > "$T/sdms.csv"
expect_exit 0 "static log with its time in milliseconds" "$H" simgap "$T/sdms.csv" --quiet --seeds 4 --max-effects 0
expect_err "the samples are 10 s apart (0.1 Hz): are the time stamps in seconds? (they look like milliseconds, a 100 Hz log: give --units time=ms)" \
    "a static log's time in milliseconds is named, with the --units item"
# the other way: read with --units time=ns, 1e6 times too fast (100 MHz), not analysed without a word: the
# same warning names the unit that fits
expect_exit 0 "static log with its time in milliseconds, read as ns" "$H" simgap "$T/sdms.csv" --quiet --seeds 4 \
    --max-effects 0 --units time=ns
expect_err "the samples are 1e-08 s apart (1e+08 Hz): are the time stamps in nanoseconds? (they look like milliseconds, a 100 Hz log: give --units time=ms)" \
    "a static log's ms stamps read as ns are named, with the --units item"
# the static log stamped in bursts (packets of 4 samples stamped 5 us apart, every 40 ms: 100 Hz over the log), in
# us read as such: simgap must not warn "are the time stamps in microseconds? (they look like milliseconds, a 200 Hz
# log: give --units time=ms)", 1000 times too slow; replay's test of the span
awk -F, 'NR == 1 { print; next } { i = NR - 2; printf "%d,%s,%s,%s,%s,%s,%s\n", (int(i / 4) + 1) * 40000 + 5 * (i % 4), $2, $3, $4, $5, $6, $7 }' \
    "$T/sd.csv" > "$T/sdburst.csv"
expect_exit 0 "static log stamped in bursts, read as us" "$H" simgap "$T/sdburst.csv" --quiet --seeds 4 --max-effects 0 \
    --units time=us
if grep -q "are the time stamps in\|look like" "$T/err"; then fail "simgap: stamps in bursts told a time unit: $(cat "$T/err")"; else
    pass "simgap: stamps in bursts (100 Hz over the log) told no time unit"; fi
# ... and it is warned of the bursts as allan and psd warn (the taus at 1 / the median interval, 200 kHz; not
# without a word), the rate of the whole packets named for --input-rate
expect_err "harness simgap: warning: $T/sdburst.csv: the time stamps come in bursts (samples stamped close together as a logger reads them?): 1 / their median interval gives 200000 Hz, but the .* samples span .* s, 100 Hz; the taus and frequencies are read at 2e+05 Hz, the stamps' rate, not the sampling rate: leave the time column out and give --input-rate 100 (docs/harness.md, \"Time stamps in bursts\")" \
    "a static log stamped in bursts: warned, the stamps' rate said, --input-rate 100 named"
# the same stamps in a .bin whose header states the rate (flag bit 0, nominal): simgap reads at the stated rate,
# and does not say "not the sampling rate" of 100 Hz, which the span keeps; the rate the file
# states is named, kept or not by the span (50 Hz stated: not kept, --input-rate 100 named)
"$H" convert "$T/sdburst.csv" "$T/sdburst.bin" --units time=us >/dev/null 2>&1 || fail "convert the bursts to .bin"
bin_rate "$T/sdburst.bin" "$T/sdnom.bin" 100 && bin_rate "$T/sdburst.bin" "$T/sdnom50.bin" 50
expect_exit 0 "static log stamped in bursts, the .bin's stated 100 Hz" "$H" simgap "$T/sdnom.bin" --quiet --seeds 4 --max-effects 0
expect_err "harness simgap: warning: $T/sdnom.bin: the time stamps come in bursts (samples stamped close together as a logger reads them?): 1 / their median interval gives 200000 Hz, but the 3001 samples span 30 s, 100 Hz; the taus and frequencies are read at 100 Hz, the rate the file states, which the samples' span keeps, not the stamps' 200000 Hz (docs/harness.md, \"Time stamps in bursts\")" \
    "a static log stamped in bursts at its stated rate: the rate and its source said, no remedy"
grep -q "not the sampling rate" "$T/err" && fail "stated rate kept by the span: told 'not the sampling rate'" || pass "stated rate kept by the span: not told 'not the sampling rate'"
expect_exit 0 "static log stamped in bursts, the .bin's stated 50 Hz" "$H" simgap "$T/sdnom50.bin" --quiet --seeds 4 --max-effects 0
# (a .bin has no time column to leave out and ignores --input-rate: the conversion to CSV without it is named, not
# "leave the time column out"; tests/cli/test_bursts.sh follows it)
expect_err "100 Hz; the taus and frequencies are read at 50 Hz, the rate the file states, which the samples' span does not keep: convert it to CSV without the time column (bin/harness convert LOG out.csv; cut -d, -f2- out.csv > in.csv) and give in.csv --input-rate 100 (docs/harness.md, \"Time stamps in bursts\")" \
    "a static log stamped in bursts at a stated rate the span does not keep: said, the conversion and --input-rate 100 named"
# a walk stamped in bursts (vectors/walk.bin, 400 Hz, in packets of 4 samples 5 us apart every 10 ms) would be read at
# 200 kHz, detected as static (its one-second windows 200,000 samples long) and analysed as one, exit 0; with one
# stamp per packet navigated and twinned at 100 Hz. Both are refused as replay refuses stamps in bursts,
# before the diagnosis, with --walk too; the remedy (no time column, --input-rate 400) is diagnosed as a 400 Hz walk
"$H" convert vectors/walk.bin "$T/bw.csv" >/dev/null 2>&1 || fail "convert the walk to CSV (bursts)"
awk -F, 'NR == 1 { print; next } { i = NR - 2; printf "%d,%s,%s,%s,%s,%s,%s\n", (int(i / 4) + 1) * 10000 + 5 * (i % 4), $2, $3, $4, $5, $6, $7 }' \
    "$T/bw.csv" > "$T/bw_burst.csv"
awk -F, 'NR == 1 { print; next } { i = NR - 2; printf "%d,%s,%s,%s,%s,%s,%s\n", (int(i / 4) + 1) * 10000, $2, $3, $4, $5, $6, $7 }' \
    "$T/bw.csv" > "$T/bw_shared.csv"
expect_exit 1 "a walk stamped in bursts" "$H" simgap "$T/bw_burst.csv" --units time=us --seeds 4 --json "$T/bw_burst.json"
expect_err "^harness simgap: error: $T/bw_burst.csv: the time stamps come in bursts (samples stamped close together as a logger reads them?): 1 / their median interval gives 200000 Hz, but the 16539 samples span 41.34 s, 400 Hz; navigation needs each sample's own time: leave the time column out and give --input-rate 400 (docs/harness.md, \"Time stamps in bursts\")" \
    "a walk stamped in bursts: refused with replay's message, --input-rate 400 named"
[ "$(wc -l < "$T/err")" -eq 1 ] && pass "a walk stamped in bursts: the error line alone" || fail "a walk stamped in bursts: $(cat "$T/err")"
[ -s "$T/out" ] && fail "a walk stamped in bursts: a summary printed" || pass "a walk stamped in bursts: no summary (refused before the diagnosis)"
json "$T/bw_burst.json" 'j["complete"] is False and set(j) == {"footnav_version", "command", "complete", "error"} and "in bursts" in j["error"]' \
    && pass "a walk stamped in bursts: no diagnosis in the JSON, the failure only" || fail "a walk stamped in bursts: $(head -c 300 "$T/bw_burst.json")"
expect_exit 1 "a walk stamped in bursts, --walk" "$H" simgap "$T/bw_burst.csv" --units time=us --seeds 4 --walk
expect_err "come in bursts (samples stamped close together .* give --input-rate 400 (" "a walk stamped in bursts, --walk: refused"
expect_exit 1 "a walk with one stamp per packet" "$H" simgap "$T/bw_shared.csv" --units time=us --seeds 4
expect_err "^harness simgap: error: $T/bw_shared.csv: the time stamps come in bursts (samples that share one stamp: one per packet, or stamps coarser than the sampling?): 1 / their median interval gives 100 Hz, but the 16539 samples span 41.34 s, 400 Hz; navigation needs each sample's own time: leave the time column out and give --input-rate 400 (" \
    "a walk with one stamp per packet: refused, --input-rate 400 named"
cut -d, -f2- "$T/bw_burst.csv" > "$T/bw_not.csv"
"$H" simgap "$T/bw_not.csv" --input-rate 400 --seeds 4 --quiet > "$T/out" 2> "$T/err"
expect_out "walk, 16539 samples at 400 Hz" "the remedy (no time column, --input-rate 400): diagnosed as a 400 Hz walk"
grep -q "come in bursts" "$T/err" && fail "the remedy: still refused as bursts" || pass "the remedy: no burst refusal"
# in g as well: the units warning and the time warning each name both items, one --units value
awk -F, 'NR == 1 { print; next } { printf "%s,%.7g,%.7g,%.7g,%s,%s,%s\n", $1, $2 / 9.80665, $3 / 9.80665, $4 / 9.80665, $5, $6, $7 }' \
    "$T/sdms.csv" > "$T/sdgms.csv"
expect_exit 0 "static log in g with its time in milliseconds" "$H" simgap "$T/sdgms.csv" --quiet --seeds 4 --max-effects 0
expect_err "not in m/s^2 but in g (give --units time=ms,accel=g)" "g and ms: the units warning names both items"
expect_err "(they look like milliseconds, a 100 Hz log: give --units time=ms,accel=g)" "g and ms: the time warning names both items"
# a walk on gyro lattices: the summary names the lattice as such, not as a
# navigation point at t 0; every gyro's lattice is selected, not the top one's alone
"$H" sim --motion walk --duration 40 --rate 100 --profile mtx --seed 4 --effect quant:ch=gyro:lsb=0.002 --out "$T/wq.csv" >/dev/null 2>&1 || fail "sim walk with quantisation"
expect_exit 0 "walk log on a lattice" "$H" simgap "$T/wq.csv" --seeds 4 --json "$T/wq.json"
expect_out "gap: lattice gz, step 0.002" "a walk's lattice gap is named as a lattice"
if grep -q "gap: navigation nis_first, t 0.0-0.0" "$T/out"; then fail "lattice gap printed as a navigation point"; else pass "no lattice gap printed as a navigation point"; fi
json "$T/wq.json" 'sorted(p["channel"] for p in j["navigation"]["selected"][0]["params"]) == ["gx", "gy", "gz"] and j["navigation"]["selected"][0]["effect"] == "quant"' &&
    pass "the three gyros' lattices selected together" || fail "walk lattice selection: $(cat "$T/pyerr")"
json "$T/wq.json" 'all(l["quantiser"] for l in j["navigation"]["lattices"] if l["channel"] in ("gx", "gy", "gz"))' &&
    pass "a quantiser's lattices are complete" || fail "walk lattices: $(cat "$T/pyerr")"
# a real walk with one quantised gyro and two gyros only partly on a fine
# lattice (x-io NGIMU, long walk: gy on 0.06 deg/s; gx and gz coherent with
# about 5 urad/s mainly at small rates): only gy is a quantiser, the others
# are named as partial lattices and not simulated (a quantiser's twins would
# overshoot their score and widen the held-out gap)
. "$(dirname "$0")/datadir.sh"
if [ -n "$D" ] && [ -f "$D/xio_ngimu_gait/long_walk.csv" ]; then
    expect_exit 0 "NGIMU long walk" "$H" simgap "$D/xio_ngimu_gait/long_walk.csv" --closed --quiet --seeds 4 --json "$T/xl.json"
    expect_out "gx lies on a lattice of step 4.9" "NGIMU gx lattice reported"
    grep -q "^  gx lies on a lattice.*only partly.*not a quantiser" "$T/out" && pass "gx named a partial lattice" || fail "gx lattice line: $(grep 'gx lies' "$T/out")"
    json "$T/xl.json" '[(s["effect"], [p["channel"] for p in s["params"]]) for s in j["navigation"]["selected"]] == [("quant", ["gy"])] and [l["channel"] for l in j["navigation"]["lattices"] if not l["quantiser"]] == ["gx", "gz"] and all(l["fit_score"] < 0.5 * l["quantiser_score"] for l in j["navigation"]["lattices"] if not l["quantiser"])' &&
        pass "only gy's lattice selected as quant" || fail "NGIMU lattices: $(cat "$T/pyerr")"
    json "$T/xl.json" 'any(c["effect"] == "quant" and c["selected"] and c["G_held_out"] < j["navigation"]["steps"][0]["G_held_out_before"] for c in j["navigation"]["steps"][0]["candidates"])' &&
        pass "gy's quantiser lowers the held-out navigation gap" || fail "NGIMU held-out gap: $(cat "$T/pyerr")"
    # a walk's lattice location gives real - twin of its normal score, as a
    # static log's does (not exp of it: 2e78 on the short walk)
    json "$T/xl.json" 'all(0 < l["ratio"] < 1e4 for l in j["locations"] if l["domain"] == "lattice") and any(l["domain"] == "lattice" for l in j["locations"])' &&
        pass "a walk's lattice location: real - twin" || fail "walk lattice ratio: $(cat "$T/pyerr")"
    # a later step of the walk's selection ran no twins before it: its
    # held-out G is null, not 0
    expect_exit 0 "GX2 walk 2" "$H" simgap "$D/openshoe_gx2/Measurement_100521_2_data_inert.txt" --closed --quiet --seeds 4 --json "$T/g2.json"
    json "$T/g2.json" 'len(j["navigation"]["steps"]) > 1 and j["navigation"]["steps"][0]["G_held_out_before"] > 0 and all(s["G_held_out_before"] is None for s in j["navigation"]["steps"][1:])' &&
        pass "later walk steps: held-out G null" || fail "walk steps G: $(cat "$T/pyerr")"
    # every step of the walk's forward selection is parsimonious: on GX2 walk
    # 32 the second step's scale (gz, ay: 2 parameters) and g-sensitivity (gy
    # from z: 1) are 0.002 sigma apart on the held-out stances; within one z
    # the fewer parameters win, as in the first step (the second step took
    # the higher z alone, and the scale won by the last digits of the filter;
    # the default 16 twins: the z depend on them)
    expect_exit 0 "GX2 walk 32" "$H" simgap "$D/openshoe_gx2/Measurement_100521_32_data_inert.txt" --closed --quiet --json "$T/g32.json"
    json "$T/g32.json" '(c := {x["effect"]: x for x in j["navigation"]["steps"][1]["candidates"]}) and c["gsens"]["selected"] and abs(c["gsens"]["held_out_z"] - c["scale"]["held_out_z"]) < 1 and len(c["gsens"]["params"]) < len(c["scale"]["params"])' &&
        pass "a later step: within one z the fewer parameters win" || fail "walk step parsimony: $(cat "$T/pyerr")"
else
    echo "SKIP NGIMU lattice test (shared data not found; set FNAV_DATA_DIR)"
fi
# stances are counted as the data set marks them: the stance detector
# flickers at some landings, and the pieces of one stance (0.03 s apart,
# swings 0.8-0.9 s) must not count as two. The vicon walk 11-22-03's stride
# file (the source's own stance marks) has 23 stances, 9 from the held-out
# segment's start (t >= 19.48 s): too short; the pieces would make 25 and 10
# and a confident answer
V="$D/pyshoe_vicon_llio/vicon_3dmgx3/2017-11-22-11-22-03"
if [ -n "$D" ] && [ -f "${V}_imu.csv" ]; then
    cp "${V}_strides_gcp.csv" "$T/vs.csv"
    expect_exit 1 "vicon walk with a split stance" "$H" simgap "${V}_imu.csv" --quiet --seeds 3 --json "$T/vc.json"
    json "$T/vc.json" '(n := j["navigation"])["stances_full"] == sum(1 for l in open(sys.argv[1].replace("vc.json", "vs.csv"))) - 1 == 23 and n["stances_held_out"] == 9 and j["verdict"]["answer"] == "too-short"' &&
        pass "stances counted as the data set's stride marks" || fail "vicon stances: $(cat "$T/pyerr")"
else
    echo "SKIP vicon stance count test (shared data not found; set FNAV_DATA_DIR)"
fi
"$H" sim --motion walk --duration 12 --rate 100 --profile mtx --seed 5 --out "$T/w2.csv" >/dev/null 2>&1 || fail "sim short walk"
expect_exit 1 "short walk" "$H" simgap "$T/w2.csv" --quiet --seeds 4 --json "$T/w2.json"
json "$T/w2.json" 'j["verdict"]["answer"] == "too-short" and "stance" in j["too_short"]' &&
    pass "short walk: too few stances said" || fail "short walk JSON: $(cat "$T/pyerr")"
# its held-out segment has no stance: said as none, not as an interval about a mean of none ('0 stances ...; the
# mean innovation of fewer than 10 is not known to -44 % / +57 %'; a CLI mutation sweep's find, --seed 102 c0021)
expect_err "w2.csv: too short for a confident answer: the held-out segment has no stance with zero-velocity updates, so no innovation to average: a longer walk" \
    "short walk: no held-out stance, said as none"
grep -q "is not known to" "$T/err" && fail "short walk: an interval about a mean of none" ||
    pass "short walk: no interval about a mean of none"
# and the remedy is named (until 2026-12-07 it was not)
expect_err "a longer walk, 10 or more stances in its last 40 % (or a lower --fit-frac, 0.6 now, to hold out more of it)" \
    "short walk: the remedy named"
# a 6-s walk holds one stance out: the mean first-update NIS of 10 stances (chi2_30 / 30) is known to 0.560 -
# 1.566 at 95 % (scipy chi2.ppf), not to +-50 %
"$H" sim --motion walk --duration 6 --rate 100 --profile mtx --seed 5 --out "$T/w6.csv" >/dev/null 2>&1 || fail "sim 6-s walk"
expect_exit 1 "6-s walk" "$H" simgap "$T/w6.csv" --quiet --seeds 4
expect_err "the held-out segment has 1 stance with zero-velocity updates; the mean innovation of fewer than 10 is not known to -44 % / +57 % (95 %): a longer walk" \
    "6-s walk: the interval of 10 stances"

# the domain forced against the detection is said in the summary (the JSON
# has domain_detected; a walk analysed as a static log is a user's choice)
expect_exit 0 "short walk forced static" "$H" simgap "$T/w2.csv" --static --quiet --seeds 4
expect_out "^domain: static as given (--static); the log looks like a walk" "forced domain said against the detected one"

# a profile whose name holds a quote: the plots are written (the quote must
# not end the gnuplot string: exit 3, psd.png and z.png missing)
sed 's/^name = .*/name = Bob'"'"'s MEMS/' docs/profiles/generic-mems.profile > "$T/bob.profile"
expect_exit 0 "a profile name with a quote, --plot" "$H" simgap "$T/m.csv" --quiet --seeds 4 --max-effects 0 --profile "$T/bob.profile" --plot "$T/bobp"
[ -s "$T/bobp/allan.png" ] && [ -s "$T/bobp/psd.png" ] && [ -s "$T/bobp/z.png" ] && pass "plots with a quoted profile name" || fail "quoted profile plots: $(ls "$T/bobp" 2>&1)"
# a walk without a stance (a spinning foot): too short, exit 1, and the
# innovation plot says so instead of failing (exit 3)
"$H" sim --motion stand --duration 60 --profile mtx --out "$T/sp0.csv" >/dev/null 2>&1 || fail "sim for spin"
awk -F, 'BEGIN { OFS = "," } NR == 1 { print; next } $1 < 30 { $7 = $7 + 3; print }' "$T/sp0.csv" > "$T/spin.csv"
expect_exit 1 "a walk without a stance, --plot" "$H" simgap "$T/spin.csv" --walk --quiet --plot "$T/spinp" --json "$T/spin.json"
[ -s "$T/spinp/innovations.png" ] && pass "innovation plot without a stance" || fail "no innovation plot: $(ls "$T/spinp" 2>&1)"
# ... and said to be too short; its navigation points are not compared
# (there is no innovation: compared, they would be ln 1e-30, located as
# nis_first 30 sigma below the twin, ratio 1e-23; with fewer seeds, and
# without a stance in the fit segment the twins get no noise, the walk must
# not be refused as "the twins do not vary (... a noise-free log?)" with no
# summary or JSON)
expect_err "^harness simgap: error: .*spin.csv: too short for a confident answer: the held-out segment has no stance with zero-velocity updates" "a walk without a stance: too short, said"
json "$T/spin.json" 'j["verdict"]["answer"] == "too-short" and j["navigation"]["stances_full"] == 0 and all(l["domain"] != "nav" for l in j["locations"])' &&
    pass "a walk without a stance: no navigation point located" || fail "no-stance JSON: $(cat "$T/pyerr")"
# a walk with a 5 s gap in its samples: the innovation plot draws each stance
# at its time, as the summary's windows count it, not at the sample index
# over the mean rate, every stance after the gap 5 s early (the last at 30.2
# s instead of 35.2 s, before the last window's start, 33.4 s, in which the
# JSON has a stance begin). A stand-in gnuplot keeps the script.
"$H" sim --motion walk --duration 40 --rate 100 --profile mtx --seed 4 --out "$T/wg0.csv" >/dev/null 2>&1 || fail "sim walk for a gap"
awk -F, 'NR == 1 || $1 < 15 || $1 >= 20' "$T/wg0.csv" > "$T/wgap.csv"
fake_gnuplot "$T/fakegp"
PATH="$T/fakegp:$PATH" GP_SCRIPT="$T/gp.txt" "$H" simgap "$T/wgap.csv" --quiet --seeds 3 --json "$T/wgap.json" --plot "$T/wgapp" >/dev/null 2>&1
sed -n '/^\$d << EOD/,/^EOD/p' "$T/gp.txt" | sed '1d;$d' | cut -d' ' -f1 > "$T/wgap.t"
json "$T/wgap.json" '(w := [p for p in j["navigation"]["gap"]["full"]["points"] if p["kind"] == "window"][-1])["real"] is not None and max(float(x) for x in open(sys.argv[1].replace(".json", ".t"))) >= w["x_lo"]' &&
    pass "innovation plot: stances at their time across a gap" || fail "innovation plot times: $(tail -1 "$T/wgap.t") $(cat "$T/pyerr")"
# the walk's gap carries the null's sd, as a static channel's does: the
# critical value is the scaled chi-square's with the null's mean m and sd s,
# G_crit = m chi2.ppf(1 - alpha / 4, k) / k, k = 2 m^2 / s^2 (section 3: a
# walk's family is its four tests; scipy).
# The walk's gap has a G_null_sd (docs/simgap.md)
json "$T/wgap.json" '(c := __import__("scipy.stats").stats.chi2) and (a := j["settings"]["alpha"] / 4) and all((g := j["navigation"]["gap"][seg])["G_null_sd"] > 0 and abs(g["G_crit"] - g["G_null_mean"] * c.ppf(1 - a, (k := 2 * g["G_null_mean"] ** 2 / g["G_null_sd"] ** 2)) / k) <= 1e-6 * g["G_crit"] for seg in j["navigation"]["gap"] if j["navigation"]["gap"][seg]["G_crit"] is not None) and len([s for s in j["navigation"]["gap"].values() if s["G_crit"] is not None]) >= 2' &&
    pass "walk gap: G_null_sd, and G_crit from it" || fail "walk gap null sd: $(cat "$T/pyerr")"
# a walk of a few strides whose fit segment holds no stance (6 s; the
# alignment takes the first seconds): its points were the constant ln 1e-30
# in the real and every twin, and the walk was refused in the same way
"$H" sim --motion walk --duration 6 --rate 200 --profile mtx --seed 2 --out "$T/w6.csv" >/dev/null 2>&1 || fail "sim 6 s walk"
expect_exit 1 "a walk of a few strides" "$H" simgap "$T/w6.csv" --quiet --seeds 4 --json "$T/w6.json"
expect_err "^harness simgap: error: .*w6.csv: too short for a confident answer" "a walk of a few strides: too short, said"
json "$T/w6.json" '(n := j["navigation"])["stances_fit"] == 0 and n["gap"]["fit"]["G_crit"] is None and all(p["z"] is None for p in n["gap"]["fit"]["points"])' &&
    pass "a walk of a few strides: the fit segment's points not compared" || fail "few strides JSON: $(cat "$T/pyerr")"
# its window 4-5 s, where the real has a stance begin and no twin one, is
# not compared with the twins' placeholder ln 1e-30 (sd 1e-12), which would
# locate it 13.5 sigma above the twin
json "$T/w6.json" 'all(l.get("kind") != "window" for l in j["locations"]) and any(p["kind"] == "window" and p["z"] is None and p["x_lo"] >= 3.9 for p in j["navigation"]["gap"]["full"]["points"])' &&
    pass "a walk of a few strides: a window without a twin stance not compared" || fail "few strides window: $(cat "$T/pyerr")"

# a channel that holds one value over the whole log (stuck): said as such, not
# as a log "too short" for its Allan points; the other channels are diagnosed
# whatever the stuck channel's place (before, one stuck gz left ax-gy
# attributed and the verdict too-short, one stuck ax stopped every channel
# after it) and the plots are written (gnuplot refused the empty panel: exit 3)
"$H" sim --motion stand:120 --rate 100 --profile mtx --seed 6 --out "$T/st.csv" >/dev/null 2>&1 || fail "sim still log"
awk -F, 'BEGIN { OFS = "," } NR > 1 { $2 = "0.25" } { print }' "$T/st.csv" > "$T/stk.csv"
expect_exit 0 "static log with a stuck ax" "$H" simgap "$T/stk.csv" --seeds 6 --json "$T/stk.json" --plot "$T/stkplot"
expect_err "^harness simgap: warning: .*channel ax holds one value (0.25 m/s^2) over the whole log" "stuck channel: warned"
expect_out "^ax holds one value (0.25 m/s^2) over the whole log: .*not analysed" "stuck channel: said in the summary"
grep -q "TOO SHORT" "$T/out" && fail "stuck channel called too short" || pass "stuck channel: not called too short"
json "$T/stk.json" 'j["confident"] and j["constant_channels"] == [{"channel": "ax", "value": 0.25}] and [c["analysed"] for c in j["channels"]] == [False] + [True] * 5 and all(len(c["attribution"]["steps"]) > 0 for c in j["channels"][1:]) and j["verdict"]["answer"] != "too-short"' &&
    pass "stuck channel: the others diagnosed and attributed" || fail "stuck channel JSON: $(cat "$T/pyerr")"
[ -s "$T/stkplot/allan.png" ] && [ -s "$T/stkplot/psd.png" ] && [ -s "$T/stkplot/z.png" ] &&
    pass "stuck channel: plots written" || fail "stuck channel plots"
# --quiet drops the progress, not the warnings (this one among them)
expect_exit 0 "stuck ax, --quiet" "$H" simgap "$T/stk.csv" --quiet --seeds 3 --max-effects 0
expect_err "channel ax holds one value" "stuck channel: warned under --quiet"
# a stuck channel on a walk is no saturation (every sample its own extreme:
# not answered saturation at the stuck value)
awk -F, 'BEGIN { OFS = "," } NR > 1 { $5 = "0.002" } { print }' "$T/w.csv" > "$T/wstk.csv"
expect_exit 0 "walk with a stuck gx" "$H" simgap "$T/wstk.csv" --quiet --seeds 4 --json "$T/wstk.json"
json "$T/wstk.json" 'all(s["effect"] != "saturation" for s in j["navigation"]["selected"])' &&
    pass "a stuck channel is not saturation" || fail "stuck walk channel: $(cat "$T/pyerr"; grep verdict "$T/out")"
# progress (not a terminal: a line per tenth of the work, after the first
# second): never backwards, and 100 % only at the end, not reached a third
# into a one-hour log's run and then silent (an estimate counting four
# candidates per channel; forward selection simulates up to the prescreen's
# three + lattice + line per step and fold, three steps); on two minutes of
# the ADIS16405 such an estimate prints it at 3.2 s of 4.0.
progress_ok() { # progress_ok STDERR-FILE
    "$PY" - "$1" <<'PY'
import re, sys
lines = [l for l in open(sys.argv[1]) if l.startswith("simgap:")]
pct = [(float(m.group(1)), float(m.group(2))) for l in lines for m in [re.match(r"simgap: +(\d+) % \(([\d.]+) s\)", l)] if m]
done = [float(m.group(1)) for l in lines for m in [re.match(r"simgap: done in ([\d.]+) s", l)] if m]
ok = all(b[0] >= a[0] for a, b in zip(pct, pct[1:]))
ok = ok and all(t >= done[0] - 0.15 for p, t in pct if p >= 100) if done else ok
sys.exit(0 if ok else 1)
PY
}
progress_ok "$T/err" && pass "stuck channel: progress reaches 100 % at the end" || fail "progress: $(grep '^simgap:' "$T/err" | tr '\n' ' ')"
if [ -n "$D" ] && [ -f "$D/adis16405_static/adis16405_imu1_100Hz.csv.gz" ]; then
    gzip -dc "$D/adis16405_static/adis16405_imu1_100Hz.csv.gz" 2>/dev/null | head -n 12001 > "$T/adis2m.csv"
    expect_exit 0 "two minutes of the ADIS16405" "$H" simgap "$T/adis2m.csv" --from adis --json "$T/adis2m.json"
    progress_ok "$T/err" && pass "ADIS16405, two minutes: progress reaches 100 % at the end" ||
        fail "progress on the ADIS16405: $(grep '^simgap:' "$T/err" | tr '\n' ' ')"
    # the format has no time stamps (index / rate): no timing to analyse; the
    # made stamps were reported as a clean clock of 0.01 s resolution
    expect_out "^timing: the log has no time stamps" "ADIS16405: no timing, said"
    grep -q "stamp resolution" "$T/out" && fail "ADIS16405: made stamps analysed" || pass "ADIS16405: made stamps not analysed"
    json "$T/adis2m.json" 'j["timing"]["has_stamps"] is False and j["timing"]["stamps_made_from_rate"] is True' &&
        pass "ADIS16405 JSON: no stamps" || fail "ADIS16405 JSON timing: $(cat "$T/pyerr")"
else
    echo "SKIP the ADIS16405 progress test (shared data not found; set FNAV_DATA_DIR)"
fi
awk -F, 'BEGIN { OFS = "," } NR > 1 { $2 = "0"; $3 = "0"; $4 = "9.8"; $5 = "0"; $6 = "0"; $7 = "0" } { print }' "$T/st.csv" > "$T/stk6.csv"
expect_exit 1 "every channel constant" "$H" simgap "$T/stk6.csv" --quiet --seeds 4
expect_err "^harness simgap: error: .*every channel holds one value" "every channel constant: said why"
# a channel that does not vary within one segment only (stuck over the
# held-out middle; or over each of the fit segment's ends, at two values) has
# nothing to fit or to test there: it is said as such, not analysed, counted
# as a gap no catalogue effect explains, and the other channels are
# diagnosed. It must not make the whole log "too short" ("within +-25 % over
# only 0.00 decades", "fewer than 4 Allan points (channel ax)"), exit 1, with
# no attribution on any channel. Samples 3600-8400 are the middle.
awk -F, 'BEGIN { OFS = "," } NR > 1 && NR - 2 >= 3598 && NR - 2 < 8404 { $2 = "0.25" } { print }' "$T/st.csv" > "$T/stm.csv"
expect_exit 0 "ax stuck over the held-out middle" "$H" simgap "$T/stm.csv" --quiet --seeds 6 --json "$T/stm.json" --plot "$T/stmplot"
expect_err "^harness simgap: warning: .*channel ax does not vary within the held-out segment (0.25 m/s^2" "stuck middle: warned"
grep -q "TOO SHORT" "$T/out" && fail "stuck middle called too short" || pass "stuck middle: not called too short"
json "$T/stm.json" 'j["confident"] and j["constant_channels"] == [] and j["constant_segments"] == [{"channel": "ax", "segment": "held_out", "value": 0.25}] and [c["analysed"] for c in j["channels"]] == [False] + [True] * 5 and all(len(c["attribution"]["steps"]) > 0 for c in j["channels"][1:]) and j["verdict"]["answer"] == "unexplained"' &&
    pass "stuck middle: the others diagnosed, the stuck part a gap" || fail "stuck middle JSON: $(cat "$T/pyerr")"
json "$T/stm.json" 'j["timing"]["has_stamps"] is True and j["timing"]["stamps_made_from_rate"] is False' &&
    pass "a CSV's own stamps: analysed" || fail "a CSV's stamps: $(cat "$T/pyerr")"
[ -s "$T/stmplot/allan.png" ] && [ -s "$T/stmplot/psd.png" ] && [ -s "$T/stmplot/z.png" ] &&
    pass "stuck middle: plots written" || fail "stuck middle plots"
awk -F, 'BEGIN { OFS = "," } NR > 1 && NR - 2 < 3602 { $2 = "0.25" } NR > 1 && NR - 2 >= 8399 { $2 = "0.26" } { print }' "$T/st.csv" > "$T/ste.csv"
expect_exit 0 "ax stuck over each of the fit segment's ends" "$H" simgap "$T/ste.csv" --quiet --seeds 6 --json "$T/ste.json"
expect_out "^ax does not vary within the fit segment (0.25 m/s^2 at its start)" "stuck ends: said in the summary"
json "$T/ste.json" 'j["confident"] and j["constant_segments"] == [{"channel": "ax", "segment": "fit", "value": 0.25}] and [c["analysed"] for c in j["channels"]] == [False] + [True] * 5' &&
    pass "stuck ends: not analysed, the others are" || fail "stuck ends JSON: $(cat "$T/pyerr")"
awk -F, 'BEGIN { OFS = "," } NR > 1 && NR - 2 >= 3598 && NR - 2 < 8404 { $2 = $3 = $4 = $5 = $6 = $7 = "0.5" } { print }' "$T/st.csv" > "$T/stm6.csv"
expect_exit 1 "every channel stuck over the middle" "$H" simgap "$T/stm6.csv" --static --quiet --seeds 4
expect_err "^harness simgap: error: .*no channel varies over both the fit and the held-out segment" "every channel stuck over the middle: said why"
# the JSON schema of docs/simgap.md: every documented key present, null where
# it cannot be computed (G_per_domain's domains without points; a too-short
# log's final model is its baseline)
json "$T/stk.json" 'all(set(c["gap"][g]["G_per_domain"]) == {"allan", "psd", "lattice", "time"} and set(c["gap_final"][g]["G_per_domain"]) == {"allan", "psd", "lattice", "time"} for c in j["channels"] if c["analysed"] for g in ("full", "fit", "held_out"))' &&
    pass "G_per_domain: every static domain present" || fail "G_per_domain keys: $(cat "$T/pyerr")"
json "$T/short.json" 'all(set(c["gap_final"]) == {"full", "fit", "held_out"} for c in j["channels"] if c["analysed"])' &&
    pass "too short: gap_final present (the baseline)" || fail "too-short gap_final: $(cat "$T/pyerr")"

# a walk with a 40 % scale error on gz: found on gz, the sensor's value (the
# trajectory's b = 0.4 / 1.4 = 0.29 converted, A = B (I - B)^-1) within 10 %,
# most of the held-out innovation excess explained (docs/simgap.md, "Walks").
# On this walk a gz g-sensitivity from az and a gx misalignment fit the
# held-out stances as well (held-out z 7.34 and 7.29 against the scale's
# 7.31): the scale is selected or named tied with the selected, in the
# summary, the verdict and the JSON (tied_with_selected)
"$H" sim --motion walk --duration 60 --rate 200 --profile mtx --seed 4 --effect scale:ch=gz:sf=0.4 --out "$T/ws.csv" >/dev/null 2>&1 || fail "sim walk with scale"
expect_exit 0 "walk with scale" "$H" simgap "$T/ws.csv" --quiet --seeds 6 --json "$T/ws.json"
cp "$T/out" "$T/ws.out"
json "$T/ws.json" 'j["navigation"]["selected"][0]["explained"] >= 0.7 and any(c["effect"] == "scale" and (c["selected"] or c["tied_with_selected"]) and len(c["params"]) == 1 and c["params"][0]["channel"] == "gz" and abs(c["params"][0]["value"] - 0.4) < 0.04 for c in j["navigation"]["steps"][0]["candidates"])' &&
    pass "walk: scale on gz, the sensor's value, selected or tied with it, held-out excess explained" || fail "walk scale JSON: $(cat "$T/pyerr")"
if json "$T/ws.json" 'j["navigation"]["selected"][0]["effect"] != "scale"'; then
    grep -q "^verdict: .*(walk: held-out stances; tied with [a-z, ]*scale" "$T/ws.out" &&
        pass "walk: the verdict names the scale as tied" || fail "walk: the tie not in the verdict: $(grep '^verdict' "$T/ws.out")"
fi
# the walk's gap locations are in the JSON's locations[] (not printed
# only), the n-frame axis named; every candidate has indistinguishable[] and
# trajectory_value (null for a family that is not linear)
json "$T/ws.json" 'len(j["locations"]) == sum(1 for l in open(sys.argv[1].replace(".json", ".out")) if l.startswith("  gap: ")) > 0 and all(l["domain"] in ("nav", "lattice") and l["segment"] == "full" for l in j["locations"]) and all(l["axis"] in ("x", "y", "z") for l in j["locations"] if l.get("kind") == "axis")' &&
    pass "walk: locations in the JSON as in the summary" || fail "walk locations: $(cat "$T/pyerr")"
json "$T/ws.json" 'all(isinstance(c["indistinguishable"], list) and all("trajectory_value" in p for p in c["params"]) for st in j["navigation"]["steps"] for c in st["candidates"])' &&
    pass "walk: candidates' documented keys present" || fail "walk candidate keys: $(cat "$T/pyerr")"
# the summary's spread of a navigation point is that of its log (z's
# denominator), said as such: "twin 0.6416 (sd 0.0815)" alone would read as
# +-0.08 NIS for a spread of 8 %; whiteness is no log
grep -q "^    nis_first .*(sd of ln [0-9.e+-]*) z" "$T/ws.out" && grep -q "^    whiteness .*(sd [0-9.e+-]*) z" "$T/ws.out" &&
    pass "walk summary: the spread of the log said as such" || fail "walk summary sd: $(grep -E 'nis_first|whiteness' "$T/ws.out")"

# --closed on a closed loop (the truth ends where it started) with a 2 % az
# scale error: the real filter pulls its position back at every stance, and
# the twins' drift is their own navigation error against their truth, the
# integral of the velocity their signals were built from. Measured against
# the real filter's posterior positions instead, which carry those
# corrections, every twin would "drift" 0.58 m vertically (ln sd 0.024,
# the real filter's summed corrections; on GX2 run 2 0.61 m, where replay's
# trajectory CSV gives 0.67 m for the sum), and the summary say the real
# walk drifts 4.7 sigma less than its twins. twin: ln m, -1.61 = ln 0.2
"$H" sim --motion loop --duration 60 --rate 200 --profile mtx --seed 3 --effect scale:ch=az:sf=0.02 --out "$T/loop.csv" >/dev/null 2>&1 || fail "sim closed loop"
expect_exit 0 "closed loop, --closed" "$H" simgap "$T/loop.csv" --closed --quiet --seeds 4 --json "$T/loop.json"
json "$T/loop.json" '(d := [p for p in j["navigation"]["gap"]["full"]["points"] if p["kind"] == "drift_v"][0]) and d["twin"] < -1.61 and abs(d["z"]) < j["navigation"]["gap"]["full"]["z_crit"]' &&
    pass "closed walk: the twins' drift is their own error" || fail "closed-walk twin drift: $(cat "$T/pyerr")"

# a small validation run on withheld effects: a control, a line and a
# quantiser (short static logs); the line and the quantiser must be named and
# the control left alone
expect_exit 0 "simgap-validate small run" "$H" simgap-validate --cases 3 --static-only --duration 300 --seeds 6 \
    --effects control,quant,vibration --json "$T/v.json" --markdown "$T/v.md"
grep -q "^confusion" "$T/out" && grep -q "^targets:" "$T/out" && pass "confusion matrix and targets printed" ||
    fail "validate output"
json "$T/v.json" 'j["schema"] == "footnav-simgap-validate/1" and len(j["results"]) == 3' &&
    pass "validate JSON: three cases" || fail "validate JSON: $(cat "$T/pyerr")"
json "$T/v.json" 'all((r["answer"] == "none") if r["truth"] == "control" else (r["answer"].startswith(r["truth"].split("_")[0]) and r["param_rel_error"] <= 0.25 and r["held_out_shrink"] >= 0.7) for r in j["results"])' &&
    pass "validate: effects named with parameters within 25 %, control clean" || fail "validate answers: $(cat "$T/pyerr"; cat "$T/out")"
grep -q "^| control " "$T/v.md" && grep -q "^# Sim-to-real gap diagnosis: validation" "$T/v.md" && pass "validate Markdown" ||
    fail "validate Markdown"
# a rate random walk whose one-hour realisation tilts the fit segment's
# blocks like a ramp: the time points' deviance lets rrw be simulated next
# to the ramp, and the held-out data choose it (docs/simgap.md, section 4,
# step 2, "Prescreen"). The log and the diagnosis are those of
# simgap-validate --cases 40 --seed 1's case 36 before the cases' seeds
# were made disjoint (commit b111ee6: the log's seed the case generator's
# draw, 201791262, the diagnosis seed 1000 + 36;
# scripts/simgap_case36_seeds.py redoes those draws), rebuilt with sim and
# simgap as that case ran them: a one-hour stand at 200 Hz, point samples,
# the Shimmer profile, rrw on ax at 2.04 x its threshold (K 0.000145591301
# m/s^2/sqrt(s), the float the validation set), 16 twins. The diagnosis
# JSON is the old binary's for that case, key by key (elapsed time and log
# name aside; docs/simgap-history.md, "The random drifts' time-point
# deviance"). Today's case 36 (sgv_case_seeds: this sim with --seed 732011,
# simgap --seed 720001) is another realisation, on which rrw fits the
# blocks best (fit dQ 1097, the ramp 904): not the hard case
# The seeds are the script's, not pasted: it must print these (log 201791262,
# diagnosis 1036, the b111ee6 binary's JSON), and refuse the cases whose
# draws it does not redo (a timing case, 8; a walk case, 10; an option)
C36=$("$PY" "$(dirname "$0")/../../scripts/simgap_case36_seeds.py" 1 36 2>"$T/err")
L36=$(echo "$C36" | sed -n 's/.* log seed \([0-9]*\),.*/\1/p')
D36=$(echo "$C36" | sed -n 's/.* diagnosis seed \([0-9]*\),.*/\1/p')
P36=$(echo "$C36" | sed -n 's/.* profile \([a-z]*\),.*/\1/p')
E36=$(echo "$C36" | sed -n 's/.* effect \([a-z_]*\), .* channels \([a-z+]*\),.*/\1:ch=\2/p')
[ "$L36" = 201791262 ] && [ "$D36" = 1036 ] && [ "$P36" = shimmer ] && [ "$E36" = rrw:ch=ax ] &&
    pass "simgap_case36_seeds.py: --seed 1 case 36 is rrw on ax, Shimmer, log seed 201791262, diagnosis 1036" ||
    fail "simgap_case36_seeds.py 1 36: '$C36' $(cat "$T/err")"
for a in "1 8:a timing case (dropout)" "1 10:a walk case (control)" "--mag-range:not a whole number"; do
    "$PY" "$(dirname "$0")/../../scripts/simgap_case36_seeds.py" ${a%%:*} >"$T/out" 2>"$T/err"
    [ $? -eq 2 ] && [ ! -s "$T/out" ] && grep -q "${a#*:}" "$T/err" && pass "simgap_case36_seeds.py ${a%%:*}: refused" ||
        fail "simgap_case36_seeds.py ${a%%:*}: not refused with '${a#*:}': $(cat "$T/out" "$T/err")"
done
"$H" sim --motion stand:3600 --rate 200 --profile "$P36" --oversample 1 --seed "$L36" \
    --effect "$E36:k=0.000145591301" --out "$T/r36.bin" >/dev/null 2>&1 || fail "sim: a random walk that tilts the blocks"
expect_exit 0 "simgap: a random walk that looks like a ramp" "$H" simgap "$T/r36.bin" --static --seed "$D36" --seeds 16 \
    --quiet --json "$T/r36.json"
# the case is the hard one: on ax the ramp fits the fit segment best (fit dQ
# 2480, rrw 2468) and is simulated next to rrw. Should this fail, the log
# no longer tilts the blocks (the simulator draws other noise, or the fit
# reads the blocks otherwise) and the check below tests nothing hard: find
# another such realisation
json "$T/r36.json" '(c := {x["effect"]: x for x in [h for h in j["channels"] if h["channel"] == "ax"][0]["attribution"]["steps"][0]["candidates"]}) and c["ramp"]["simulated"] and c["rrw"]["simulated"] and c["ramp"]["fit_dQ"] == max(x["fit_dQ"] for x in c.values() if x["fit_dQ"] is not None)' &&
    pass "rrw that tilts the blocks: the ramp fits them best and is simulated" || fail "case 36 not the hard one: $(cat "$T/pyerr")"
# ... and the held-out data name rrw alone, explaining >= 70 % of the
# held-out excess (the validation's shrink: the selected rrw's explained)
json "$T/r36.json" '[(e["effect"], e["channels"]) for e in j["verdict"]["effects"]] == [("rrw", ["ax"])] and [(s["effect"], s["explained"] >= 0.7) for s in [h for h in j["channels"] if h["channel"] == "ax"][0]["attribution"]["selected"]] == [("rrw", True)]' &&
    pass "a random walk that tilts the blocks is rrw, not ramp" || fail "rrw that tilts the blocks: $(cat "$T/pyerr"; cat "$T/out")"
# a line only in the ends (the sandwich split's fit segment), none in the
# middle: neither fold may confirm it. The second fold fits on the middle,
# so it must take the line's evidence from the middle (which has none), not
# the ends' it is tested on; borrowing it, a 13 Hz tone fitted on the ends
# "explained" the ends' own gap and the answer was partly-explained
"$PY" - "$T/te.csv" <<'PY' || fail "tone-in-the-ends log"
import sys
import numpy as np
fs, n = 100.0, 60001
rng = np.random.default_rng(3)
t = np.arange(n) / fs
x = np.array([0, 0, 9.80665, 0, 0, 0]) + rng.standard_normal((n, 6)) * np.array([1e-3] * 3 + [1e-4] * 3) * np.sqrt(fs)
a = (n * 6 // 10) // 2
b = n - (n * 6 // 10 - a)
on = np.ones(n)
on[a:b] = 0.0
x[:, 5] += 3e-4 * np.sin(2 * np.pi * 13.0 * t + 0.3) * on
np.savetxt(sys.argv[1], np.column_stack([t, x]), fmt=['%.4f'] + ['%.9g'] * 6, delimiter=',', header='t,ax,ay,az,gx,gy,gz', comments='')
PY
expect_exit 0 "static log with a line in the ends only" "$H" simgap "$T/te.csv" --static --quiet --json "$T/te.json"
json "$T/te.json" 'j["verdict"]["answer"] not in ("explained", "partly-explained") and j["verdict"]["effects"] == []' &&
    pass "a line in the fit segment only is not confirmed by either fold" || fail "tone in the ends: $(cat "$T/pyerr"; "$PY" -c 'import json,sys; print(json.load(open(sys.argv[1]))["verdict"])' "$T/te.json")"

# one held-out stance is "1 stance", not "1 stances"
"$H" sim --motion stand:5,walk:2,stand:3 --rate 100 --out "$T/one.csv" >/dev/null 2>&1 || fail "sim one stance"
expect_exit 1 "one held-out stance" "$H" simgap "$T/one.csv" --walk --seeds 3 --json "$T/one.json"
expect_err "has 1 stance with zero-velocity updates" "one stance in the singular"

# --- --quiet ("no progress indicator") holds for the reading of the log too:
# not "simgap: reading: 52 %". The run is
# stopped 0.1 s in, while it reads 2 M lines, for 1.3 s of wall time, after
# which progress would show; a stuck log then exits at once. Without
# --quiet the same run shows the progress (the control: a machine that reads
# the log in under 0.1 s cannot show either, and says so).
awk 'BEGIN { print "t,ax,ay,az,gx,gy,gz"; for (i = 0; i < 2000000; i++) printf "%.2f,0.01,0.02,-9.81,0.001,0.002,0.003\n", i / 100 }' >"$T/big.csv"
held_run() { # ERRFILE ARGS...: simgap on big.csv, stopped 0.1 s in for 1.3 s
    e=$1
    shift
    "$H" simgap "$T/big.csv" "$@" --json "$T/big.json" >/dev/null 2>"$e" &
    p=$!
    sleep 0.1
    kill -STOP "$p" 2>/dev/null
    sleep 1.3
    kill -CONT "$p" 2>/dev/null
    wait "$p" 2>/dev/null
}
held_run "$T/loud.err"
held_run "$T/quiet.err" --quiet
if ! grep -q "^simgap: reading: *[0-9]* %" "$T/loud.err"; then
    echo "note: the 2 M-line log was read in under 0.1 s: --quiet's reading not checked"
elif grep -q "reading" "$T/quiet.err"; then
    fail "simgap --quiet printed the reading's progress: $(head -n 2 "$T/quiet.err")"
else
    pass "simgap --quiet: no progress while reading (shown without it)"
fi
rm -f "$T/big.csv"

# drops only in the held-out part (every 40th sample of the last fifth): the whole log shows them, the fit segment
# has none, so no rate: named as such, not "dropout (prob 0)", whose twin reproduces nothing (the consistency
# audit: four IPOL trials); the JSON's rate_from_fit false
expect_exit 0 "a walk for late drops" "$H" sim --duration 40 --out "$T/late.csv" --seed 3
n=$(wc -l < "$T/late.csv")
awk -v n="$n" 'NR == 1 || NR < 0.8 * n || NR % 40 != 0' "$T/late.csv" > "$T/late_drop.csv"
expect_exit 0 "drops in the held-out part only" "$H" simgap "$T/late_drop.csv" --seeds 4 --json "$T/late_drop.json"
expect_out "^verdict: .*dropout (held-out segment only: no rate from the fit segment)" "late drops: no rate from the fit said"
grep -q "dropout (prob 0)" "$T/out" && fail "late drops: dropout (prob 0) named" || pass "late drops: no dropout (prob 0)"
json "$T/late_drop.json" '[e["rate_from_fit"] for e in j["timing"]["selected"] if e["effect"] == "dropout"] == [False]' \
    && pass "late drops: rate_from_fit false" || fail "late drops: rate_from_fit"

if [ "$fails" -ne 0 ]; then echo "test_simgap.sh: $fails failure(s)"; exit 1; fi
echo "test_simgap.sh: all passed"
