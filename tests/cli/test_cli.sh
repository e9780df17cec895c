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

# --- `harness help CMD` is CMD's help (it printed the list of commands, and
# `harness help nosuch` exited 0)
expect_exit 0 "harness help" "$H" help
expect_out "^commands:" "harness help lists the commands"
expect_exit 0 "harness help replay" "$H" help replay
expect_out "^usage: harness replay LOG" "harness help replay is replay's help"
expect_out "^  --param KEY=VALUE" "harness help replay lists replay's options"
expect_exit 0 "harness --help info" "$H" --help info
expect_out "^usage: harness info LOG" "harness --help info is info's help"
expect_exit 2 "harness help of an unknown command" "$H" help nosuch
expect_err "unknown command 'nosuch'" "harness help nosuch names the command"
if [ -s "$T/out" ]; then fail "harness help nosuch wrote to standard output"; else pass "harness help nosuch: nothing on standard output"; fi
expect_exit 2 "harness help with two commands" "$H" help info replay
# the list of commands on a full disk is a write error, as every command's
# output is (it exited 0)
if [ -w /dev/full ]; then
    "$H" --help >/dev/full 2>"$T/err"; rc=$?
    [ "$rc" -eq 3 ] && pass "harness --help >/dev/full exits 3" || fail "harness --help >/dev/full: exit $rc, expected 3"
    "$H" help info >/dev/full 2>"$T/err"; rc=$?
    [ "$rc" -eq 3 ] && pass "harness help info >/dev/full exits 3" || fail "harness help info >/dev/full: exit $rc, expected 3"
fi

if [ "$fails" -ne 0 ]; then
    echo "test_cli.sh: $fails failure(s)"
    exit 1
fi
echo "test_cli.sh: all passed"
