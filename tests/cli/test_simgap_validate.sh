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
json() { # json FILE PYTHON-EXPRESSION-ON-j: passes when it is true
    "$PY" -c 'import json,sys; j=json.load(open(sys.argv[1])); sys.exit(0 if eval(sys.argv[2]) else 1)' "$1" "$2" 2>"$T/pyerr"
}
# small static cases: 60 s at 50 Hz, 3 twins
FAST="--static-only --duration 60 --rate 50 --seeds 3"

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

if [ "$fails" -ne 0 ]; then echo "test_simgap_validate.sh: $fails failure(s)"; exit 1; fi
echo "test_simgap_validate.sh: all passed"
