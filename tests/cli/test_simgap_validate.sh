#!/bin/sh
# CLI tests of `harness simgap-validate`'s options, outputs and statistics
# (run by make test and make sanitize with $HARNESS set; docs/simgap.md,
# "Validation"). Short, coarse runs: they check the command, not the
# diagnosis (tests/cli/test_simgap.sh).
set -u
H=${HARNESS:-bin/harness}
PY=${PYTHON:-/usr/bin/python3}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
# small static cases: 60 s at 50 Hz, 4 twins
FAST="--static-only --duration 60 --rate 50 --seeds 4"

# a static case's held-out tests need 4 twins: with 3 no effect could ever be
# accepted (simgap refuses it, and the validation must too)
expect_exit 2 "static cases with 3 twins" "$H" simgap-validate --cases 1 --static-only --duration 60 --rate 50 --seeds 3
expect_err "at least 4" "static cases with 3 twins: the minimum said"

# an output that cannot be written is said before the run, not after it
# (a full run takes 13 minutes)
expect_exit 3 "unwritable --json: exit 3" "$H" simgap-validate --cases 2 $FAST --json "$T/no/such/dir/v.json"
expect_err "cannot write $T/no/such/dir/v.json" "unwritable --json named"
grep -q "^case" "$T/out" && fail "unwritable --json: the cases ran first" || pass "unwritable --json: said before any case ran"
expect_exit 3 "unwritable --markdown: exit 3" "$H" simgap-validate --cases 2 $FAST --markdown "$T/no/such/dir/v.md"
expect_err "cannot write $T/no/such/dir/v.md" "unwritable --markdown named"
grep -q "^case" "$T/out" && fail "unwritable --markdown: the cases ran first" || pass "unwritable --markdown: said before any case ran"
[ ! -e "$T/v.json" ] && expect_exit 0 "writable outputs still written" "$H" simgap-validate --cases 1 $FAST --quiet \
    --json "$T/v.json" --markdown "$T/v.md"
[ -s "$T/v.json" ] && [ -s "$T/v.md" ] && pass "JSON and Markdown written" || fail "outputs missing"
# --json and --markdown naming one file (also as ./FILE) are a usage error
# before any case runs: the Markdown replaced the JSON, exit 0
expect_exit 2 "--json and --markdown on one file" "$H" simgap-validate --cases 1 $FAST --quiet \
    --json "$T/same.json" --markdown "$T/./same.json"
expect_err "^harness simgap-validate: error: --json $T/same.json and --markdown $T/./same.json name the same file" \
    "--json and --markdown on one file said"
[ ! -e "$T/same.json" ] && pass "--json and --markdown on one file: nothing written" || fail "--json and --markdown on one file: $T/same.json written"

# --seed: sim's range and words (not [0, 2e9], "not an integer"); the case
# generator's seed is a uint32_t
expect_exit 2 "--seed past 2^32 - 1" "$H" simgap-validate --cases 1 $FAST --seed 4294967296
expect_err "^harness simgap-validate: error: --seed '4294967296' is out of range (give a whole number in \[0, 4294967295\])$" "--seed: sim's range and words"
expect_exit 0 "--seed 4294967295, the last seed" "$H" simgap-validate --cases 1 $FAST --quiet --seed 4294967295 --json "$T/vseed.json"
json "$T/vseed.json" "j['seed'] == 4294967295" && pass "--seed 4294967295 written in the JSON" || fail "--seed in the JSON"

# --mag-range: two finite numbers and nothing else
expect_exit 2 "--mag-range with trailing text" "$H" simgap-validate --cases 1 $FAST --mag-range 1,10x
expect_err "mag-range" "--mag-range with trailing text said"
expect_exit 2 "--mag-range to infinity" "$H" simgap-validate --cases 1 $FAST --mag-range 1,inf
expect_err "mag-range" "--mag-range to infinity said"
# a magnitude beyond what the simulator accepts is a usage error that names
# the case and the effect, before any case runs (not exit 3, "cannot draw
# a static case", after the cases before it have run, their results lost)
expect_exit 2 "--mag-range beyond the simulator's range" "$H" simgap-validate --cases 3 $FAST --effects control,ramp \
    --mag-range 1e6,1e6
expect_err "mag-range .1e6,1e6.: wants LO,HI" "a magnitude range beyond 1000 said"
grep -q "^case" "$T/out" && fail "magnitude beyond range: cases ran first" || pass "magnitude beyond range: said before any case ran"
# ... and one the simulator refuses on these logs (a dropout probability of
# 1000 x 10 events in 3000 samples): a usage error before the run, naming the
# case and the parameter (not exit 3 after the cases before it have run)
expect_exit 2 "--mag-range the simulator refuses" "$H" simgap-validate --cases 3 $FAST --effects control,dropout \
    --mag-range 1000,1000
expect_err "case [0-9]*: dropout at .*dropout.prob .* outside the simulator's range" "the case, effect and parameter named"
grep -q "^case" "$T/out" && fail "refused magnitude: cases ran first" || pass "refused magnitude: said before any case ran"
# a log too short for a confident answer is no false alarm: 10 s at 10 Hz
# gives "too-short" on every control (not "static 4/4 false alarms
# (100.0 %)" and the target "no")
expect_exit 0 "controls on logs too short" "$H" simgap-validate --cases 4 --effects control --static-only \
    --duration 10 --rate 10 --seeds 4 --json "$T/ts.json"
json "$T/ts.json" 'all(r["verdict"] == "too-short" for r in j["results"])' && pass "the short controls are too-short" ||
    fail "short controls: $(cat "$T/out")"
expect_out "static 0/0 false alarms.*4 too short" "too-short controls are not counted as false alarms"
grep -q "false alarms on controls.*no" "$T/out" && fail "the false-alarm target failed on too-short controls" ||
    pass "no false-alarm target failed on too-short controls"
# ... and a case of an effect answered too-short is no identification: no
# effect, no place, no parameter (walks of 20 s at 50 Hz are all too short;
# case 7, saturation, was scored top-1, located exactly, parameter 0 off)
expect_exit 0 "walks too short" "$H" simgap-validate --walk-only --cases 10 --walk-duration 20 --walk-rate 50 \
    --seeds 3 --json "$T/wts.json"
json "$T/wts.json" 'len(j["results"]) == 10 and all(r["verdict"] == "too-short" for r in j["results"])' &&
    pass "the short walks are too-short" || fail "short walks: $(cat "$T/out")"
# ... said why at the first such case, once (not only in the summary at the
# end)
[ "$(grep -c "^ *too short for an answer: the held-out segment has .* stance.* (a longer --walk-duration gives one)$" "$T/out")" = 1 ] &&
    pass "the first too-short walk says why, once" || fail "too-short walks: no reason at the first: $(head -3 "$T/out")"
# ... with simgap-validate's remedy only: it has no --fit-frac (simgap's
# remedy, added to the reason on 2026-12-07, read "(or a lower --fit-frac,
# 0.6 now, ...) (a longer --walk-duration gives one)")
grep "too short for an answer: the held-out" "$T/out" | grep -q -e "--fit-frac" -e "a longer walk" &&
    fail "too-short walks: simgap's remedy in simgap-validate: $(grep 'held-out' "$T/out")" ||
    pass "the too-short walk names --walk-duration, not simgap's --fit-frac"
json "$T/wts.json" 'all(r["answer"] == "none" and r["location_jaccard"] == 0 and r["param_rel_error"] is None
    for r in j["results"])' && pass "a too-short effect case is no answer" || fail "too-short scored: $(cat "$T/out")"
expect_out_re "^motion +8 +0/8 +0/8 += +0\.0 % .* 0/8 +/ 0\.00 +0/0 +\(-\) +0/0 +\(-\)$" "too-short effect cases: no top-1, location or parameter in the summary ('-' for no median: it printed nan)"
# ... and the summary says why (not 0/8 with every case line saying
# too-short, and the target "no", without a word on it in the summary), in
# the Markdown too
expect_out "^too short for an answer: motion 8 of 8 (scored as misses: no top-1, location or parameter" \
    "too-short effect cases are counted in the summary"
expect_exit 0 "walks too short, Markdown" "$H" simgap-validate --walk-only --cases 3 --walk-duration 20 --walk-rate 50 \
    --seeds 3 --quiet --markdown "$T/wts.md"
grep -q "^Too short for an answer: motion 3 of 3 (scored as misses" "$T/wts.md" &&
    pass "too-short effect cases are counted in the Markdown" || fail "Markdown: $(grep -i 'short' "$T/wts.md")"

# the terminal summary reads as a table: each count of the confusion matrix
# and of the top-1 by magnitude under its column's name (not the names run
# on one line after the title, the counts 4 characters apart, where the 1 of
# a misalign row stands under 'jumps'), no 'nan' for a case without a
# parameter or shrink, and a control has no multiple of a threshold or
# location (not 'x1.83' and 'loc 0.00': it has no effect to locate)
expect_exit 0 "a control and a line" "$H" simgap-validate --cases 2 --effects control,vibration $FAST \
    --markdown "$T/cv.md"
if "$PY" - "$T/out" <<'PY'
import re, sys
lines = open(sys.argv[1]).read().split('\n')
names = ['none', 'quant', 'quant_shaped', 'flicker', 'rrw', 'ramp', 'thermal', 'vibration', 'jumps', 'jitter',
         'dropout', 'duplicate', 'scale', 'misalign', 'gsens', 'saturation', 'other']
def ends(line, cols):
    e, at = [], 0
    for c in cols:
        m = re.compile(r'(?<!\S)' + re.escape(c) + r'(?!\S)').search(line, at)
        if m is None:
            sys.exit('no column %s in %r' % (c, line))
        e.append(m.end())
        at = m.end()
    return e
def check(title, cols):
    i = [k for k, l in enumerate(lines) if all(re.search(r'(?<!\S)%s(?!\S)' % re.escape(c), l) for c in cols)]
    if not i:
        sys.exit('no header for ' + title)
    want = ends(lines[i[0]], cols)
    rows = 0
    for l in lines[i[0] + 1:]:
        if not l.startswith('  ') or not re.search(r'\d', l):
            break
        got = [m.end() for m in re.finditer(r'\S+', l)][1:]
        if got != want:
            sys.exit('%s: %r: ends %s, header %s' % (title, l, got, want))
        rows += 1
    if rows == 0:
        sys.exit('no rows under ' + title)
check('confusion', names)
check('by magnitude', ['1-2x', '2-4x', '>=4x'] if '>=4x' in open(sys.argv[1]).read() else ['1-2x', '2-4x', '4x'])
PY
then pass "confusion matrix and top-1 by magnitude: counts under their columns"
else fail "summary columns: $(cat "$T/out")"; fi
if grep -q "nan" "$T/out"; then fail "nan in the summary: $(grep nan "$T/out")"; else pass "no nan in the summary"; fi
expect_out_re "^case +1 +static +[a-z]+ +control +on - +x- +-> none .* loc - +perr +- +shrink +- " \
    "a control's line: no multiple, no location"
grep -q "^| 1 | static | [a-z]* | control | - | - | none | [a-z-]* | - | - | - |" "$T/cv.md" &&
    pass "a control's Markdown row: no multiple, no location" || fail "control row: $(grep '| control |' "$T/cv.md")"

# --only K runs one case: the summary counts one case, not --cases N
expect_exit 0 "--only one case" "$H" simgap-validate --cases 8 --only 6 $FAST --json "$T/o.json" --markdown "$T/o.md"
expect_out "^simgap-validate: 1 case (case 6 of 8; seed 1)" "--only: one case said"
json "$T/o.json" 'j["cases"] == 1 and len(j["results"]) == 1 and j["only"] == 6' && pass "--only: JSON counts one case" ||
    fail "--only JSON: $(cat "$T/pyerr")"
grep -q -- "--only 6" "$T/o.md" && grep -q "1 case in" "$T/o.md" && pass "--only: the Markdown's command and count" ||
    fail "--only Markdown: $(grep '^Run' "$T/o.md")"
# the Markdown's command reproduces the run: the walks' rate is in it
expect_exit 0 "walk rate in the command" "$H" simgap-validate --cases 8 --only 7 --walk-only --walk-duration 20 \
    --walk-rate 100 --seeds 3 --quiet --markdown "$T/w.md"
grep -q -- "--walk-only" "$T/w.md" && grep -q -- "--walk-rate 100" "$T/w.md" && pass "--walk-rate in the Markdown's command" ||
    fail "Markdown command: $(grep '^Run' "$T/w.md")"

# a walk effect beyond half the simulator's range is set at that bound, and
# its multiple is the one set: a misalignment clipped to 0.5 said 1000 x, and
# a negative scale factor was clipped to -5 (the range is -0.9..10), refused,
# and the run ended at case 2 with "cannot draw a walk case" (exit 3)
expect_exit 0 "walk effects at 1000 x: every case drawn" "$H" simgap-validate --walk-only --effects scale,misalign,gsens \
    --mag-range 1000,1000 --cases 3 --walk-duration 20 --seeds 3 --quiet --json "$T/wc.json"
json "$T/wc.json" 'j["cases"] == 3 and all(r["multiple_of_threshold"] < 1000 for r in j["results"]
    if abs(r["values"][0]) >= 0.45)' && pass "a clipped walk magnitude's multiple is the one set" ||
    fail "clipped walk magnitudes: $(cat "$T/pyerr") $(cat "$T/out")"
# each case's seeds are in the JSON (case i of --seed S: its diagnosis S + 20000 i, its log 12010 further)
json "$T/wc.json" 'all(r["diagnosis_seed"] == (j["seed"] + 20000 * r["case"]) % 2**32 and
    r["log_seed"] == (r["diagnosis_seed"] + 12010) % 2**32 for r in j["results"]) and len(j["results"]) == 3' &&
    pass "each case's log and diagnosis seeds in the JSON" || fail "case seeds in the JSON: $(cat "$T/pyerr")"
# --help says which seeds case i uses and how far apart two runs' seeds must be (docs/simgap.md's option table)
expect_exit 0 "--help" "$H" simgap-validate --help
expect_out "case i owns the seeds S + 20000 i ... S + 20000 i + 19999" "--help: case i's seeds"
expect_out "two runs share nothing when their seeds are at least 20000 x --cases apart" "--help: independent runs"
# --json - is standard output, as psd's and allan's: --help says so (it
# said "every case and its score as JSON" alone), and standard output holds
# the JSON alone, the case lines and summary on standard error
expect_out "every case and its score as JSON ('-': standard output, the text then on standard error)" "--help: --json - named"
expect_exit 0 "--json -" "$H" simgap-validate --cases 1 $FAST --json -
json "$T/out" "j['schema'] == 'footnav-simgap-validate/1' and j['cases'] == 1" && pass "--json -: standard output is the JSON" ||
    fail "--json -: standard output is no JSON: $(cat "$T/pyerr")"
expect_err "^case   0 " "--json -: the case line on standard error"
# make simgap-validation's controls take the first seed past the first run's cases, derived from SIMGAP_SEED and
# SIMGAP_CASES (Makefile), not a constant: before, SIMGAP_CASES=41 gave the controls 800001, its case 40's seeds
R=$(dirname "$0")/../..
mkseed() { # the controls' --seed that make -n simgap-validation prints with the given overrides
    make -s -n -C "$R" simgap-validation HARNESS=/bin/true "$@" 2>/dev/null |
        sed -n 's/.*--effects control --cases [0-9]* --seed \([0-9]*\) .*/\1/p'
}
[ "$(mkseed)" = 800001 ] && pass "make simgap-validation: the controls' seed 800001 by default (1 + 40 x 20000)" ||
    fail "make's default controls' seed: '$(mkseed)'"
[ "$(mkseed SIMGAP_CASES=41)" = 820001 ] && pass "SIMGAP_CASES=41: the controls' seed 820001, past case 40" ||
    fail "SIMGAP_CASES=41: the controls' seed '$(mkseed SIMGAP_CASES=41)'"
[ "$(mkseed SIMGAP_SEED=7 SIMGAP_CASES=3)" = 60007 ] && pass "SIMGAP_SEED=7 SIMGAP_CASES=3: the controls' seed 60007" ||
    fail "SIMGAP_SEED=7 SIMGAP_CASES=3: the controls' seed '$(mkseed SIMGAP_SEED=7 SIMGAP_CASES=3)'"
[ "$(mkseed SIMGAP_SEED=4294967295 SIMGAP_CASES=2)" = 39999 ] && pass "the controls' seed wraps past 2^32 - 1" ||
    fail "the controls' seed past 2^32 - 1: '$(mkseed SIMGAP_SEED=4294967295 SIMGAP_CASES=2)'"

# a static case too big to hold (1e11 samples: it would run for ever) is a usage error; walk-only runs ignore the
# static size
expect_exit 2 "static case of 1e11 samples" "$H" simgap-validate --cases 1 --duration 1e6 --rate 1e5
expect_err "samples per static case; at most 20000000" "the static case's size is bounded and said"

# Ctrl-C stops the run before its next case and reports and writes the
# cases run (not lost: a full run takes 13 minutes); exit 130
sigint_default "$H" simgap-validate --cases 40 $FAST --json "$T/i.json" --markdown "$T/i.md" >"$T/out" 2>"$T/err" &
pid=$!
k=0
while ! grep -q "^case" "$T/out" 2>/dev/null && [ $k -lt 600 ]; do sleep 0.1; k=$((k + 1)); done
kill -INT $pid
wait $pid
rc=$?
[ $rc -eq 130 ] && pass "interrupted run: exit 130" || fail "interrupted run: exit $rc, $(cat "$T/err")"
expect_err "interrupted: the report covers the cases run" "interruption said"
grep -q "^simgap-validate: [0-9]* cases* (INCOMPLETE" "$T/out" && pass "the summary says incomplete" ||
    fail "summary: $(grep '^simgap-validate' "$T/out")"
json "$T/i.json" 'j["complete"] is False and 1 <= j["cases"] < 40 and len(j["results"]) == j["cases"]' &&
    pass "interrupted run: JSON of the cases run, complete false" || fail "interrupted JSON: $(cat "$T/pyerr")"
# and why, in `error` as the other commands' JSON (not complete false alone)
json "$T/i.json" 'j["error"].startswith("interrupted by SIGINT")' && pass "interrupted run: the JSON's error names the signal" ||
    fail "interrupted JSON's error: $(tr -d '\n\t' <"$T/i.json" | head -c 300)"
grep -q "incomplete" "$T/i.md" && pass "interrupted run: the Markdown says incomplete" || fail "Markdown: $(grep '^Run' "$T/i.md")"
json "$T/o.json" 'j["complete"] is True and "error" not in j' && pass "a full --only run: complete true, no error" ||
    fail "--only complete: $(tr -d '\n\t' <"$T/o.json" | head -c 300)"
# ... and when the signal lands inside the write of a case's line to a
# terminal that takes no output (Ctrl-S, a slow link), that line is written
# once the terminal takes it: every case the summary counts has its line
# (the write failed with EINTR, and the line was lost)
if ! "$PY" -c 'import termios, select' 2>/dev/null; then
    echo "SKIP the signal inside a write to a stopped terminal: $PY lacks termios or select"
else
    msg=$("$PY" "$(dirname "$0")/stop_tty.py" "$H" "$T")
    case $? in
    0) pass "a signal inside the write of a case's line to a stopped terminal: the line kept, exit 130" ;;
    3) echo "note: the signal inside a write to a stopped terminal not checked: $msg" ;; # this system's /proc, no tool to install
    *) fail "a signal inside a write to a stopped terminal: $msg" ;;
    esac
fi

if [ "$fails" -ne 0 ]; then echo "test_simgap_validate.sh: $fails failure(s)"; exit 1; fi
echo "test_simgap_validate.sh: all passed"
