#!/bin/sh
# scripts/check_vectors.sh (make vectors-check) on a scratch copy of the
# Welch vectors: it passes on the committed files, fails with what to do when
# a vector or an input no longer matches its generator, and fails (not
# passes) when it finds no generator at all. Needs /usr/bin/python3 with
# numpy/scipy; the committed tree is never touched.
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
. tests/cli/lib.sh
ROOT=$PWD
PY=${PY:-/usr/bin/python3}
if ! "$PY" -c 'import numpy, scipy' 2>/dev/null; then
    echo "skip: $PY lacks numpy/scipy"
    exit 0
fi
mkdir -p "$T/x/vectors" "$T/x/scripts" "$T/empty"
cp -R vectors/welch "$T/x/vectors/"
cp scripts/check_vectors.sh "$T/x/scripts/"
# gen_welch.py finds the OpenShoe source at ../../../shared/data from its folder
[ -d "$ROOT/../shared/data" ] && ln -s "$ROOT/../shared" "$T/shared"

expect_exit 1 "no generator found: a failure" sh -c "cd '$T/empty' && PYTHON='$PY' sh '$ROOT/scripts/check_vectors.sh'"
expect_out "no generators" "no generators: said"

expect_exit 0 "committed Welch vectors pass" sh -c "cd '$T/x' && PYTHON='$PY' sh scripts/check_vectors.sh"

# one digit of an expected value changed
cp "$T/x/vectors/welch/welch_expected.csv" "$T/keep.csv"
sed '5s/^2,3/2,4/' "$T/keep.csv" >"$T/x/vectors/welch/welch_expected.csv"
cmp -s "$T/keep.csv" "$T/x/vectors/welch/welch_expected.csv" && fail "the mutation changed nothing"
expect_exit 1 "an edited expected value fails" sh -c "cd '$T/x' && PYTHON='$PY' sh scripts/check_vectors.sh"
expect_out "welch_expected.csv: value differs" "the changed file named"
expect_out "commit the new vector with the reason" "what to do said"
cp "$T/keep.csv" "$T/x/vectors/welch/welch_expected.csv"

# an input edited and the expected values regenerated from it: the input
# no longer comes from its generator
sed '100s/^9/8/' vectors/welch/welch_input_synth.txt >"$T/x/vectors/welch/welch_input_synth.txt"
cmp -s vectors/welch/welch_input_synth.txt "$T/x/vectors/welch/welch_input_synth.txt" && fail "the mutation changed nothing"
"$PY" "$T/x/vectors/welch/gen_welch.py" >/dev/null 2>&1
expect_exit 1 "an edited input with regenerated expectations fails" sh -c "cd '$T/x' && PYTHON='$PY' sh scripts/check_vectors.sh"
expect_out "welch_input_synth.txt differs from its source" "the edited input named"

# the OpenShoe excerpt is compared with its source wherever the tests find
# the shared data ($FNAV_DATA_DIR first): a changed source row is seen
mkdir -p "$T/nodata/x/vectors" "$T/fake/openshoe_c_820hz"
cp -R vectors/welch "$T/nodata/x/vectors/"
SRC=
for d in "${FNAV_DATA_DIR:-}" "$ROOT/../shared/data" /work/shared/data; do
    if [ -n "$d" ] && [ -f "$d/MANIFEST.md" ]; then SRC=$d/openshoe_c_820hz/OpenShoeDataSet.txt; break; fi
done
if [ -n "$SRC" ] && [ -f "$SRC" ]; then
    : >"$T/fake/MANIFEST.md"
    awk -F, 'NR == 10001 { $3 = $3 + 1 } { print }' OFS=, "$SRC" \
        >"$T/fake/openshoe_c_820hz/OpenShoeDataSet.txt"
    expect_exit 1 "the excerpt against a changed source (FNAV_DATA_DIR) fails" \
        env FNAV_DATA_DIR="$T/fake" "$PY" "$T/nodata/x/vectors/welch/gen_welch.py" --check
    expect_out "welch_input_os820.txt differs from its source" "the excerpt named"
else
    echo "skip: shared data not found (the OpenShoe excerpt check)"
fi

# every copied piece of real data names its licence file, and the file is there
# (vectors/README.md: the rows naming a licence; vectors/nav/README.md)
cat >"$T/lic.py" <<'PYEOF'
import os, re, sys
bad = 0
for readme in ("vectors/README.md", "vectors/nav/README.md"):
    base = os.path.dirname(readme)
    text = open(readme).read()
    units = [l for l in text.splitlines() if l.startswith("| `")] if readme == "vectors/README.md" \
        else re.split(r"\n(?=- )", text.split("Sources and licences")[1])[1:]
    for u in units:
        if not re.search(r"\b(MIT|ISC|BSD|CC BY)", u):
            continue
        files = re.findall(r"`([^` ]*LICENSE[^` ]*)`", u)
        if not files:
            print("%s: no licence file named in: %s" % (readme, u[:90])); bad += 1
        for f in files:
            if not os.path.isfile(os.path.join(base, f)):
                print("%s: %s missing" % (readme, f)); bad += 1
sys.exit(1 if bad else 0)
PYEOF
expect_exit 0 "each real-data excerpt names a licence file that exists" "$PY" "$T/lic.py"

# vectors/nav/make_golden.sh in a scratch tree (a stub Makefile, both
# harnesses the one under test): without the shared data it stops, exit 1,
# and leaves no golden input behind (it used to write an empty one, which
# later runs kept); with the data an empty input is made again, and the
# inputs and float outputs it makes are the committed ones
if [ -n "${HARNESS:-}" ] && [ -x "$HARNESS" ]; then
    mkdir -p "$T/g/vectors/nav" "$T/g/bin" "$T/g/build/double"
    cp vectors/nav/make_golden.sh "$T/g/vectors/nav/"
    printf 'bin/harness:\nbuild/double/harness:\n' >"$T/g/Makefile"
    case "$HARNESS" in /*) HA="$HARNESS" ;; *) HA="$PWD/$HARNESS" ;; esac # a link to a relative path would dangle
    ln -s "$HA" "$T/g/bin/harness"
    ln -s "$HA" "$T/g/build/double/harness"
    expect_exit 1 "make_golden.sh without the shared data fails" \
        env FNAV_DATA_DIR="$T/nowhere" sh "$T/g/vectors/nav/make_golden.sh"
    expect_err "set FNAV_DATA_DIR" "what to do said"
    if [ -e "$T/g/vectors/nav/golden/gx2_walk2.csv" ]; then fail "an empty golden input was left behind"; else pass "no golden input left behind"; fi
    if [ -n "$SRC" ]; then
        : >"$T/g/vectors/nav/golden/gx2_walk2.csv"
        expect_exit 0 "make_golden.sh with the shared data" \
            env FNAV_DATA_DIR="$(dirname "$(dirname "$SRC")")" sh "$T/g/vectors/nav/make_golden.sh"
        for f in gx2_walk2.csv xio_short.csv square2.csv gx2_walk2_traj_float.csv xio_short_traj_float.csv square2_traj_float.csv; do
            if cmp -s "vectors/nav/golden/$f" "$T/g/vectors/nav/golden/$f"; then pass "make_golden.sh remakes $f as committed"
            else fail "make_golden.sh made a different $f"; fi
        done
    else
        echo "skip: shared data not found (make_golden.sh with the data)"
    fi
else
    echo "skip: no HARNESS (make_golden.sh)"
fi

if [ "$fails" -ne 0 ]; then
    echo "test_vectors.sh: $fails failure(s)"
    exit 1
fi
echo "test_vectors.sh: all passed"
