#!/bin/sh
# The profile chain across three commands: a simulated static sensor
# (harness sim, the paper's MTx profile) -> harness allan --profile ->
# harness replay --profile on the bundled walk. Also the bound fallback:
# on a short record the MTx biases are not identifiable, yet a valid profile
# is written with a warning per channel.
set -u
H=${HARNESS:-bin/harness}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"

"$H" sim --motion stand --duration 900 --rate 200 --profile mtx --seed 7 --out "$T/stand.bin" >/dev/null 2>"$T/err" \
    && pass "sim a 15-minute static MTx log" || { fail "sim"; cat "$T/err"; }
"$H" allan "$T/stand.bin" --profile "$T/mtx.profile" >/dev/null 2>"$T/err"
st=$?
if [ $st -eq 0 ] && [ -s "$T/mtx.profile" ]; then pass "allan writes a profile (exit 0)"; else fail "allan exit $st"; cat "$T/err"; fi
if grep -q "not identifiable within the record" "$T/err"; then pass "bound fallback announced"; else fail "no fallback warning"; cat "$T/err"; fi
if grep -q "^ident_bound_gyro = " "$T/mtx.profile"; then pass "bound channels marked in the profile"; else fail "ident_bound keys"; fi
# white-noise densities recovered within 10 % of the MTx table (deg/s/sqrt(Hz) -> rad/s: 2.6e-2 * pi/180 = 4.54e-4)
if /usr/bin/python3 - "$T/mtx.profile" <<'PY'
import sys, math
kv = {}
for line in open(sys.argv[1]):
    if '=' in line and not line.startswith('#'):
        k, v = line.split('=', 1)
        kv[k.strip()] = v.split()
acc = [float(x) for x in kv['accel_noise_mps2_rthz']]
gyr = [float(x) for x in kv['gyro_noise_rps_rthz']]
want_a = [8.9e-4, 8.4e-4, 8.4e-4]
want_g = [x * math.pi / 180 for x in (2.6e-2, 2.5e-2, 2.9e-2)]
ok = all(abs(a / w - 1) < 0.1 for a, w in zip(acc + gyr, want_a + want_g))
sys.exit(0 if ok else 1)
PY
then pass "white-noise densities within 10 % of Table V"; else fail "white-noise densities"; cat "$T/mtx.profile"; fi
"$H" replay vectors/walk.bin --profile "$T/mtx.profile" --bias-model ar1 --json "$T/s.json" >/dev/null 2>"$T/err" \
    && pass "replay --profile FILE --bias-model ar1" || { fail "replay with the identified profile"; cat "$T/err"; }
if /usr/bin/python3 -c "import json,sys; d=json.load(open(sys.argv[1])); sys.exit(0 if d['return_error_3d_m'] < 5 else 1)" "$T/s.json"; then
    pass "replay with the profile navigates (3-D closure < 5 m)"
else
    fail "replay summary"
fi
echo "profile chain: $fails failure(s)"
[ "$fails" -eq 0 ]
