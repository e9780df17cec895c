#!/bin/sh
# docs/workflow.md runs as written: every ```sh block of the guide, in
# order, in a scratch directory whose bin/harness is $HARNESS (set by
# `make test-cli`), each under `sh -e`; any block that exits non-zero fails.
# The directory holds nothing else of the repository: a block that reads
# another of its files (vectors/walk.bin) must not be tagged sh.
# Then every line of the guide's ```text blocks (its quoted output; a line
# "..." marks a cut) must be a whole line of what the blocks printed,
# standard output and standard error together, blanks squeezed. The guide
# must keep quoting the figures it is about (the identified noise and bias,
# the lowest usable rate, the closure, the stance count), so that this test
# checks them. The logs come from `harness sim --seed`: no shared data.
# Without gnuplot the plots are drawn by lib.sh's stand-in. WORKFLOW_OUT=FILE
# keeps the blocks' combined output there (to update the quotes from).
set -u
H=${HARNESS:-bin/harness}
case "$H" in /*) ;; *) H=$(pwd)/$H ;; esac
DOC=$(cd "$(dirname "$0")/../../docs" && pwd)/workflow.md
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
if [ ! -x "$H" ]; then
    fail "no harness binary at $H (build it with make)"
    exit 1
fi

# $T/blk_N.sh: the N-th sh block, $T/blk_N.where its docs line;
# $T/quoted: every line of every text block
awk -v D="$T" '
    BEGIN { printf "" > (D "/quoted") }
    /^```/ {
        if (inb) { inb = 0; if (out != "") close(out); next }
        if (fence) { fence = 0; next }
        if ($0 ~ /^```sh[ \t]*$/) {
            k++; inb = 1; out = D "/blk_" k ".sh"; w = D "/blk_" k ".where"
            print "docs/workflow.md:" NR + 1 > w; close(w); printf "" > out; next
        }
        if ($0 ~ /^```text[ \t]*$/) { inb = 1; out = ""; next }
        fence = 1; next
    }
    inb && out != "" { print > out; next }
    inb { print >> (D "/quoted") }
    END { print k + 0 > (D "/count") }' "$DOC"
count=$(cat "$T/count" 2>/dev/null || echo 0)
if [ "$count" -eq 0 ]; then
    fail "no \`\`\`sh block in docs/workflow.md (the extraction is broken, or the guide is gone)"
    exit 1
fi
norm() { sed -E 's/[[:space:]]+/ /g; s/^ //; s/ $//' "$1"; }

mkdir -p "$T/w/bin" "$T/gp"
ln -s "$H" "$T/w/bin/harness"
if ! command -v gnuplot >/dev/null 2>&1; then
    fake_gnuplot "$T/gp"
    GP_SCRIPT=$T/gp/script
    export GP_SCRIPT
fi
start=$(date +%s)
i=1
: >"$T/all"
while [ "$i" -le "$count" ]; do
    where=$(cat "$T/blk_$i.where")
    (cd "$T/w" && PATH="$PATH:$T/gp" sh -e "$T/blk_$i.sh") >>"$T/all" 2>&1
    rc=$?
    if [ "$rc" -ne 0 ]; then
        fail "$where: the block exits $rc (what it printed last:)"
        tail -n 20 "$T/all"
        echo "test_workflow.sh: $fails failure(s)"
        exit 1
    fi
    i=$((i + 1))
done
end=$(date +%s)
pass "the $count sh blocks of docs/workflow.md run (exit 0; $((end - start)) s)"

# the outputs the guide names exist and are not empty
# (a PNG drawn by the stand-in gnuplot is empty)
for f in static.bin walk.bin mysensor.profile walk_traj.csv walk.json walk.csv allan.png walk.png psd/psd.png; do
    p=$T/w/out/workflow/$f
    if case "$f" in *.png) [ -e "$p" ] ;; *) [ -s "$p" ] ;; esac; then pass "out/workflow/$f written"
    else fail "out/workflow/$f missing or empty"; fi
done
[ -n "${WORKFLOW_OUT:-}" ] && cp "$T/all" "$WORKFLOW_OUT"

# every quoted line is a line of the output now
norm "$T/all" >"$T/all.n"
if [ ! -s "$T/quoted" ]; then
    fail "no \`\`\`text block in docs/workflow.md: nothing quoted to check"
else
    norm "$T/quoted" | grep -v -x -e '' -e '\.\.\.' >"$T/quoted.n"
    missing=0
    while IFS= read -r line; do
        if ! grep -q -F -x -e "$line" "$T/all.n"; then
            fail "quoted in docs/workflow.md but not printed now: $line"
            missing=$((missing + 1))
        fi
    done <"$T/quoted.n"
    [ "$missing" -eq 0 ] && pass "the $(wc -l <"$T/quoted.n") quoted output lines are printed as quoted"
fi

# the figures the guide is about are among the quoted (and so checked) lines
while IFS=@ read -r re what; do
    if grep -q -E -e "$re" "$T/quoted.n" 2>/dev/null; then pass "the guide quotes $what"
    else fail "the guide no longer quotes $what (/$re/)"; fi
done <<'EOF'
^Acc x m/s\^2 \|.*\| [0-9.e-]+ [0-9]+ [0-9.e-]+@allan's identified accelerometer noise, tau and bias
^Gyr x deg/s \|.*\| [0-9.e-]+ [0-9]+ [0-9.e-]+@allan's identified gyroscope noise, tau and bias
^accel_noise_mps2_rthz =@the profile's noise densities
^accel_bias_sigma_mps2 =@the profile's bias sigmas
^lowest usable sampling frequency: [0-9]+ Hz@psd's lowest usable sampling frequency
^return-to-start horizontal [0-9.]+ m@replay's closure
^stance [0-9]+ strides, [0-9]+ stance phases@replay's stance count
^health 0 NaN/Inf rejected@replay's health counters
^verdict: @simgap's verdict
EOF

if [ "$fails" -ne 0 ]; then echo "test_workflow.sh: $fails failure(s)"; exit 1; fi
echo "test_workflow.sh: all passed"
