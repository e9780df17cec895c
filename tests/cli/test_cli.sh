#!/bin/sh
# CLI tests of the command line itself: option and number parsing shared by
# every command (harness/hx_cli.c, hx_nav.c's --param), and `harness help`.
# $HARNESS is the harness binary (set by `make test-cli`).
set -u
H=${HARNESS:-bin/harness}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"

# --- --param switches (adaptive, lever, settle, zaru, closed_form) are 0 or 1:
# zaru=0.5 was cast to int and turned the ZARU off, zaru=-1 or 2 turned it on,
# zaru=1e20 was an undefined double-to-int conversion, all with exit 0
for v in 0.5 -1 2 1e20; do
    expect_exit 2 "--param zaru=$v refused" "$H" replay vectors/walk.bin --quiet --param "zaru=$v"
    expect_err "zaru" "--param zaru=$v: the error names the key"
done
expect_err "0 or 1" "--param switch error says what it takes"
expect_exit 0 "--param zaru=1 accepted" "$H" replay vectors/walk.bin --quiet --param zaru=1
expect_exit 0 "--param lever=0 accepted" "$H" replay vectors/walk.bin --quiet --param lever=0

if [ "$fails" -ne 0 ]; then
    echo "test_cli.sh: $fails failure(s)"
    exit 1
fi
echo "test_cli.sh: all passed"
