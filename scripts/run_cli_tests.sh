#!/bin/sh
# make test-cli: runs each CLI test given, with $HARNESS from the
# environment, its output kept in LOGDIR/cli-test.log and printed; stops at
# the first test that fails.
#   sh scripts/run_cli_tests.sh LOGDIR TEST...
# A test that cannot run a check prints a line starting "skip" (any case)
# and passes. Two variables, both exported by .ci/run, turn such a skip into
# a failure of the run:
#   FNAV_REQUIRE_DATA=1   a skip line naming the shared data
#                         (set when the machine has the data)
#   FNAV_REQUIRE_TOOLS=1  any other skip line: a missing tool (socat, the
#                         ARM toolchain, a C compiler, numpy/scipy), which
#                         scripts/bootstrap.sh --ci installs
set -eu
if [ $# -lt 2 ]; then
    echo "usage: sh scripts/run_cli_tests.sh LOGDIR TEST..." >&2
    exit 2
fi
log=$1/cli-test.log
shift
mkdir -p "$(dirname "$log")"
for t in "$@"; do
    echo "== $t"
    sh "$t" >"$log" 2>&1 || { cat "$log"; exit 1; }
    cat "$log"
    if [ "${FNAV_REQUIRE_DATA:-}" = 1 ] && grep -i -E '^skip.*shared.data' "$log"; then
        echo "$t: shared data not found and FNAV_REQUIRE_DATA=1"
        exit 1
    fi
    if [ "${FNAV_REQUIRE_TOOLS:-}" = 1 ] && grep -i -E '^skip' "$log" | grep -v -i -E 'shared.data'; then
        echo "$t: a check skipped for want of a tool and FNAV_REQUIRE_TOOLS=1 (sh scripts/bootstrap.sh --ci installs every tool)"
        exit 1
    fi
done
