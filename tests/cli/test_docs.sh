#!/bin/sh
# The documentation against the harness: every option of each command's
# --help is named in that command's document, and every key the JSON outputs
# write (replay, info, psd, allan) is named in theirs. A review found the
# allan JSON's fit keys documented under names the code never wrote and most
# psd and allan keys undocumented (2026-11-28).
# $HARNESS is the harness binary (set by `make test-cli`).
set -u
H=${HARNESS:-bin/harness}
DOCS=$(cd "$(dirname "$0")/../../docs" && pwd)
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
W="$(dirname "$0")/../../vectors/walk.bin"

# --- options: COMMAND DOCUMENT (--from, --input-rate and --help are the
# conventions of docs/harness.md, shared by every command)
while read -r cmd doc; do
    "$H" "$cmd" --help >"$T/help" 2>&1
    missing=""
    for o in $(sed -n 's/^  \(--[a-z0-9-]*\).*/\1/p' "$T/help"); do
        case "$o" in --from | --input-rate | --help) continue ;; esac
        grep -q -e "$o\([^a-z0-9-]\|\$\)" "$DOCS/$doc" || missing="$missing $o"
    done
    if [ -z "$missing" ]; then pass "$cmd: every --help option is in docs/$doc"
    else fail "$cmd: docs/$doc lacks$missing"; fi
done <<EOF
info harness.md
convert harness.md
replay harness.md
eval harness.md
live harness.md
stream harness.md
allan allan.md
psd psd.md
sim simulator.md
montecarlo simulator.md
simgap simgap.md
simgap-validate simgap.md
EOF

# --- JSON keys: every key written, at any depth, is named in the document
json_keys() { # JSON file -> one key per line
    /usr/bin/python3 -c '
import json, sys
def walk(v):
    if isinstance(v, dict):
        for k, x in v.items():
            print(k)
            walk(x)
    elif isinstance(v, list):
        for x in v:
            walk(x)
walk(json.load(open(sys.argv[1])))' "$1" | sort -u
}
check_keys() { # what JSON document
    if [ ! -s "$2" ]; then fail "$1: no JSON written"; return; fi
    missing=""
    for k in $(json_keys "$2"); do
        case "$k" in ax | ay | az | gx | gy | gz) continue ;; esac # channels, named as ax..gz
        grep -q -e "\`$k\(\`\|\[\]\)" "$DOCS/$3" || missing="$missing $k"
    done
    if [ -z "$missing" ]; then pass "$1: every JSON key is in docs/$3"
    else fail "$1: docs/$3 lacks the JSON keys$missing"; fi
}
expect_exit 0 "replay --json" "$H" replay "$W" --quiet --json "$T/replay.json"
check_keys "replay --json" "$T/replay.json" harness.md
expect_exit 0 "info --json" "$H" info "$W" --json "$T/info.json"
check_keys "info --json" "$T/info.json" harness.md
expect_exit 0 "psd --json" "$H" psd "$W" --sensitivity --json "$T/psd.json"
check_keys "psd --json" "$T/psd.json" psd.md
# allan on a static log (a walk is refused as not static since 2026-11-28, docs/allan.md "Command")
"$H" sim --motion stand --duration 120 --rate 100 --profile mtx --seed 3 --out "$T/stand.bin" >/dev/null 2>&1 ||
    fail "sim a static log for allan"
expect_exit 0 "allan --json" "$H" allan "$T/stand.bin" --channels gx,gy --fit-extra --json "$T/allan.json"
check_keys "allan --json" "$T/allan.json" allan.md
expect_exit 0 "montecarlo --json" "$H" montecarlo --duration 10 --seeds 2 --bias-model both --quiet --json "$T/mc.json"
check_keys "montecarlo --json" "$T/mc.json" simulator.md

if [ "$fails" -ne 0 ]; then echo "test_docs.sh: $fails failure(s)"; exit 1; fi
echo "test_docs.sh: all passed"
