#!/bin/sh
# Re-run every golden-vector generator (vectors/*/gen_*.py) in --check mode:
# each regenerates its outputs from the independent reference computation and
# exits non-zero if the committed files no longer match within its stated
# tolerances. Needs Debian's python3 with numpy/scipy (/usr/bin/python3).
set -u
PY=${PYTHON:-/usr/bin/python3}
status=0
found=0
for g in vectors/*/gen_*.py; do
    [ -f "$g" ] || continue
    found=1
    if "$PY" "$g" --check; then
        echo "vectors-check: $g ok"
    else
        echo "vectors-check: $g FAILED"
        status=1
    fi
done
[ "$found" -eq 1 ] || { echo "vectors-check: no generators (run from the repository root)"; status=1; }
if [ "$status" -ne 0 ]; then
    echo "vectors-check: a committed vector no longer matches its generator. If a vector file was" \
        "edited by hand, restore it (git checkout -- vectors/); if the reference computation or the code" \
        "it describes changed on purpose, rerun the generator without --check ($PY <script>) and commit" \
        "the new vector with the reason in the commit message."
fi
exit $status
