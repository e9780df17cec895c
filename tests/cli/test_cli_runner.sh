#!/bin/sh
# scripts/run_cli_tests.sh (make test-cli) on stand-in tests: a check
# skipped for want of a tool fails the run under FNAV_REQUIRE_TOOLS=1 (CI,
# where scripts/bootstrap.sh --ci installs every tool) and passes without it;
# a skip for want of the shared data fails under FNAV_REQUIRE_DATA=1 only.
# Then the real tests' tool skips: test_live.sh with no socat on the PATH,
# test_firmware_tools.sh and test_doc_snippets.sh with no compiler.
set -u
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
cd "$(dirname "$0")/../.." || exit 1

mk() { # NAME LINE...: a stand-in test printing each LINE, exiting 0
    f=$T/$1.sh; shift
    : >"$f"
    for l in "$@"; do printf 'echo "%s"\n' "$l" >>"$f"; done
}
# run DATA TOOLS TEST...: the runner with the two variables as given (empty: unset) and the
# assignments of $RUN_ENV (words without blanks), output in $T/out
RUN_ENV=""
run() {
    d=$1; tl=$2; shift 2
    # shellcheck disable=SC2086
    env FNAV_REQUIRE_DATA="$d" FNAV_REQUIRE_TOOLS="$tl" $RUN_ENV sh scripts/run_cli_tests.sh "$T/log" "$@" >"$T/out" 2>"$T/err"
}
expect_run() { # WANT DESCRIPTION DATA TOOLS TEST...
    want=$1; what=$2; shift 2
    run "$@"; got=$?
    if [ "$got" -eq "$want" ]; then pass "$what (exit $got)"; else fail "$what: exit $got, expected $want"; cat "$T/out" "$T/err"; fi
}

mk tool "SKIP fake.sh: socat is not installed (apt-get install socat)" "ok   the rest"
mk tool_lc "ok   one check" "skip: no scipy in /usr/bin/python3 (spectrogram times)"
mk data "SKIP fake walk tests (shared data not found; set FNAV_DATA_DIR)"
mk data2 "skip shared-data checks (no ../shared/data; set FNAV_DATA_DIR)"
mk clean "ok   skipped by the gate: a check whose words hold skip" "ok   done"
printf 'echo "FAIL something"\nexit 1\n' >"$T/failing.sh"
printf 'echo "second ran"\n' >"$T/second.sh"

# --- a skip for want of a tool
expect_run 0 "a tool's skip passes without FNAV_REQUIRE_TOOLS" "" "" "$T/tool.sh"
expect_out "^SKIP fake.sh: socat is not installed" "the skip line is shown"
expect_run 0 "a tool's skip passes under FNAV_REQUIRE_DATA=1 alone" 1 "" "$T/tool.sh"
expect_run 1 "a tool's skip fails under FNAV_REQUIRE_TOOLS=1" "" 1 "$T/tool.sh"
expect_out "$T/tool.sh: a check skipped for want of a tool and FNAV_REQUIRE_TOOLS=1" "the failure names the test and the variable"
expect_run 1 "a lower-case 'skip:' line fails under FNAV_REQUIRE_TOOLS=1" "" 1 "$T/tool_lc.sh"
expect_run 1 "the run stops at the test whose tool is missing" "" 1 "$T/tool.sh" "$T/second.sh"
if grep -q "second ran" "$T/out"; then fail "the test after it ran"; else pass "the test after it did not run"; fi

# --- a skip for want of the shared data (the variable of its own)
expect_run 0 "a data skip passes under FNAV_REQUIRE_TOOLS=1" "" 1 "$T/data.sh" "$T/data2.sh"
expect_run 1 "a data skip fails under FNAV_REQUIRE_DATA=1" 1 "" "$T/data.sh"
expect_out "$T/data.sh: shared data not found and FNAV_REQUIRE_DATA=1" "the failure names the test and the variable"
expect_run 1 "a 'skip shared-data' line fails under FNAV_REQUIRE_DATA=1" 1 "" "$T/data2.sh"

# --- no skip, and a failing test
expect_run 0 "a test without a skip line passes under both" 1 1 "$T/clean.sh" "$T/second.sh"
expect_out "second ran" "every test given is run"
expect_run 1 "a failing test fails the run" "" "" "$T/failing.sh" "$T/second.sh"
expect_out "FAIL something" "its output is shown"
if grep -q "second ran" "$T/out"; then fail "the test after a failure ran"; else pass "the run stops at the failure"; fi

# --- the real tests' tool skips
# test_live.sh with a PATH holding only what it needs before it looks for socat
mkdir -p "$T/bin"
for c in sh mktemp dirname rm cat grep mkdir; do
    p=$(command -v "$c") && ln -s "$p" "$T/bin/$c"
done
if [ -e "$T/bin/socat" ] || [ ! -e "$T/bin/sh" ]; then
    fail "the stand-in PATH has socat or lacks sh"
else
    RUN_ENV="PATH=$T/bin"
    expect_run 0 "test_live.sh without socat passes without FNAV_REQUIRE_TOOLS" "" "" tests/cli/test_live.sh
    expect_out "^SKIP test_live.sh: socat is not installed" "test_live.sh says it skipped"
    expect_run 1 "test_live.sh without socat fails under FNAV_REQUIRE_TOOLS=1" "" 1 tests/cli/test_live.sh
    expect_out "tests/cli/test_live.sh: a check skipped for want of a tool" "the failure names test_live.sh"
fi
RUN_ENV="ARM_CC=no-such-arm-gcc"
expect_run 0 "test_firmware_tools.sh without the ARM compiler passes without FNAV_REQUIRE_TOOLS" "" "" \
    tests/cli/test_firmware_tools.sh
expect_out "^SKIP test_firmware_tools.sh: no-such-arm-gcc not installed" "test_firmware_tools.sh says it skipped"
expect_run 1 "test_firmware_tools.sh without the ARM compiler fails under FNAV_REQUIRE_TOOLS=1" "" 1 \
    tests/cli/test_firmware_tools.sh
RUN_ENV="CC=no-such-cc"
expect_run 1 "test_doc_snippets.sh without a C compiler fails under FNAV_REQUIRE_TOOLS=1" "" 1 \
    tests/cli/test_doc_snippets.sh
expect_out "^SKIP test_doc_snippets.sh: no C compiler (no-such-cc) found" "test_doc_snippets.sh says it skipped"
RUN_ENV=""

if [ "$fails" -ne 0 ]; then echo "test_cli_runner.sh: $fails failure(s)"; exit 1; fi
echo "test_cli_runner.sh: all passed"
