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
"$H" allan "$T/stand.bin" --profile "$T/mtx.profile" --json "$T/mtx.json" >/dev/null 2>"$T/err"
st=$?
if [ $st -eq 0 ] && [ -s "$T/mtx.profile" ]; then pass "allan writes a profile (exit 0)"; else fail "allan exit $st"; cat "$T/err"; fi
if grep -q "not identifiable within the record" "$T/err"; then pass "bound fallback announced"; else fail "no fallback warning"; cat "$T/err"; fi
if grep -q "^ident_bound_gyro = " "$T/mtx.profile"; then pass "bound channels marked in the profile"; else fail "ident_bound keys"; fi
# the JSON says the same per channel (corrected.ar1_identified = not bound)
if /usr/bin/python3 - "$T/mtx.profile" "$T/mtx.json" <<'PY'
import json, sys
kv = {}
for line in open(sys.argv[1]):
    if '=' in line and not line.startswith('#'):
        k, v = line.split('=', 1)
        kv[k.strip()] = v.split()
bound = [int(x) for x in kv['ident_bound_accel'] + kv['ident_bound_gyro']]
j = {c['name']: c for c in json.load(open(sys.argv[2]))['channels']}
ident = [j[n]['corrected']['ar1_identified'] for n in ('ax', 'ay', 'az', 'gx', 'gy', 'gz')]
sys.exit(0 if all(i == (b == 0) for i, b in zip(ident, bound)) and any(b == 1 for b in bound) else 1)
PY
then pass "the JSON's ar1_identified matches the profile's bound marks"; else fail "ar1_identified in the JSON"; fi
# white-noise densities against the MTx table (deg/s/sqrt(Hz) -> rad/s: 2.6e-2 * pi/180 = 4.54e-4). Every channel
# here is a bound channel, whose profile density is the paper's sigma_v, the ADEV at 1 s (docs/allan.md, "Its
# precision"): one point of the overlapping Allan variance, white FM at m = 200 of n = 180,001 samples, EDF =
# (3n/(2m) - 2(n-1)/(n+1)) 4m^2/(4m^2+5) = 1348 (NIST SP 1065, Table 5, n + 1 phase points), relative sd 1/sqrt(2
# EDF) = 1.93 %, not the 0.17 % of the per-sample sd. Each ratio within 4 of those sd (7.7 %), their mean over the
# six channels within 4 sd/sqrt(6) (3.1 %). Seed 7 gives all six 0.6-2.4 % low (mean -1.4 %, -1.8 sd of the mean):
# chance, not a bias. Over 120 seeds the ratio is 0.9996 (standard error 0.0007, the six channels' mean), the spread
# per channel 1.65-2.06 % (1.93 % predicted), the six's mean 0.75 % (0.79 %), all six on one side in 3 seeds (3.75
# expected), one channel beyond 4 sd (seed 114 gx, 0.919, the ADEV at m = 200 in numpy on its samples 0.918), and the
# simulated noise's per-sample sd is N sqrt(f_s) to 0.02 % per channel (`/usr/bin/python3
# scripts/white_density_seeds.py --seeds 1-120`). A bare 10 % would pass a 4 % low bias on all six (seed 7's values
# x 0.96: mean -5.4 %), which the mean's 3.1 % fails.
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
n = int(kv['ident_samples'][0]) + 1   # phase points
m = 1.0 * float(kv['rate_hz'][0])     # tau = 1 s in samples
edf = (3.0 * (n - 1) / (2.0 * m) - 2.0 * (n - 2) / n) * 4.0 * m * m / (4.0 * m * m + 5.0)
sd = 1.0 / math.sqrt(2.0 * edf)
r = [a / w for a, w in zip(acc + gyr, want_a + want_g)]
mean = sum(r) / len(r)
ok = all(abs(x - 1) < 4 * sd for x in r) and abs(mean - 1) < 4 * sd / math.sqrt(len(r))
print("  white densities / Table V: %s, mean %.4f; sd of one %.4f (EDF %.0f)"
      % (" ".join("%.4f" % x for x in r), mean, sd, edf))
sys.exit(0 if ok else 1)
PY
then pass "white-noise densities within 4 sd (1/sqrt(2 EDF) at 1 s) of Table V, their mean within 4 sd/sqrt(6)"
else fail "white-noise densities"; cat "$T/mtx.profile"; fi
"$H" replay vectors/walk.bin --profile "$T/mtx.profile" --bias-model ar1 --json "$T/s.json" >/dev/null 2>"$T/err" \
    && pass "replay --profile FILE --bias-model ar1" || { fail "replay with the identified profile"; cat "$T/err"; }
if /usr/bin/python3 -c "import json,sys; d=json.load(open(sys.argv[1])); sys.exit(0 if d['return_error_3d_m'] < 5 else 1)" "$T/s.json"; then
    pass "replay with the profile navigates (3-D closure < 5 m)"
else
    fail "replay summary"
fi
# A 1-minute static log (white noise + an AR(1) of T = 50 s, far beyond what 60 s can show): the fit
# of ax converged to T = 8e-6 s, sigma = 1.3e-6 m/s^2, an AR(1) the curve never sees, and the profile
# held it as a fit (a bias the filter would never estimate). The AR(1) must now be resolved by the
# curve (its bump within the measured tau, above the white part by the fit's floor somewhere) or be
# replaced by the bound from the minimum, announced and marked.
/usr/bin/python3 - "$T/short.csv" <<'PY'
import sys
import numpy as np
rng = np.random.default_rng(1)
n, fs, tau = 6000, 100.0, 50.0
c = np.exp(-1.0 / (tau * fs))
def ar(sb):
    b = np.zeros((n, 3)); b[0] = rng.normal(0, sb, 3); d = rng.normal(0, sb * np.sqrt(1 - c * c), (n, 3))
    for i in range(1, n):
        b[i] = c * b[i - 1] + d[i]
    return b
a = np.array([0.0, 0.0, 9.81]) + rng.normal(0, 0.005 * np.sqrt(fs), (n, 3)) + ar(0.005)
g = rng.normal(0, 0.0007 * np.sqrt(fs), (n, 3)) + ar(0.0003)
with open(sys.argv[1], "w") as f:
    f.write("t,ax,ay,az,gx,gy,gz\n")
    for i in range(n):
        f.write("%.9f," % (i / fs) + ",".join("%.9g" % v for v in list(a[i]) + list(g[i])) + "\n")
PY
"$H" allan "$T/short.csv" --no-sim --quiet --profile "$T/short.profile" --json "$T/short.json" >/dev/null 2>"$T/err"
st=$?
if [ $st -eq 0 ] && [ -s "$T/short.profile" ]; then pass "1-minute log: profile written"; else fail "1-minute log: exit $st"; cat "$T/err"; fi
if grep -q "AR(1) bias of ax is not identifiable" "$T/err"; then pass "1-minute log: ax's unresolved AR(1) announced"; else fail "1-minute log: ax's fit kept"; cat "$T/err"; fi
if /usr/bin/python3 - "$T/short.profile" <<'PY'
import sys
kv = {}
for line in open(sys.argv[1]):
    if '=' in line and not line.startswith('#'):
        k, v = line.split('=', 1)
        kv[k.strip()] = v.split()
fs = float(kv['rate_hz'][0])
ok = True
for g in ('accel', 'gyro'):
    bound = [int(x) for x in kv['ident_bound_' + g]]
    taus = [float(x) for x in kv[g + '_tau_s']]
    for b, t in zip(bound, taus):
        ok &= b == 1 or 1.89 * t >= 1.0 / fs   # no fitted AR(1) whose bump lies below one sample
ok &= kv['ident_bound_accel'][0] == '1' and float(kv['accel_tau_s'][0]) > 1.0
sys.exit(0 if ok else 1)
PY
then pass "1-minute log: ax holds the bound from the minimum, no sub-sample AR(1) left"; else fail "1-minute log: profile"; cat "$T/short.profile"; fi
# The bound's two numbers from the Allan minimum (t_BS, BS in the JSON's "paper" block): the AR(1) Allan
# deviation of correlation time T and sd sigma peaks at tau = x T with height y sigma; the bound is
# T = t_BS / x, sigma = BS / y. x and y here come from maximising the continuous AR(1) Allan variance
# 2 sigma^2 T / tau [1 - T / (2 tau) (3 - 4 e^(-tau/T) + e^(-2 tau/T))] (IEEE Std 952-1997, C.8) with
# scipy: x = 1.8926, y = 0.6174. These checks fail a bound with T = t_BS (no 1.89) or sigma = BS / 0.664, which
# would otherwise pass every test.
if /usr/bin/python3 - "$T/short.profile" "$T/short.json" <<'PY'
import json, math, sys
import numpy as np
from scipy.optimize import minimize_scalar
def adev(u):  # u = tau / T, sigma = T = 1
    return math.sqrt(2.0 / u * (1.0 - (3.0 - 4.0 * math.exp(-u) + math.exp(-2.0 * u)) / (2.0 * u)))
r = minimize_scalar(lambda u: -adev(u), bounds=(0.5, 5.0), method="bounded", options={"xatol": 1e-9})
x, y = r.x, adev(r.x)
kv = {}
for line in open(sys.argv[1]):
    if '=' in line and not line.startswith('#'):
        k, v = line.split('=', 1)
        kv[k.strip()] = v.split()
ch = {c['name']: c for c in json.load(open(sys.argv[2]))['channels']}
ok, n = True, 0
for g, names, si in (('accel', ('ax', 'ay', 'az'), 1.0), ('gyro', ('gx', 'gy', 'gz'), math.pi / 180.0)):
    bound = [int(v) for v in kv['ident_bound_' + g]]
    taus = [float(v) for v in kv[g + '_tau_s']]
    sig = [float(v) for v in kv[g + ('_bias_sigma_mps2' if g == 'accel' else '_bias_sigma_rps')]]
    for b, t, s, nm in zip(bound, taus, sig, names):
        if b != 1:
            continue
        p = ch[nm]['paper']
        n += 1
        if abs(t * x / p['t_bs_s'] - 1.0) > 5e-3 or abs(s * y / (p['bs'] * si) - 1.0) > 5e-3:
            print(nm, t, s, p['t_bs_s'] / x, p['bs'] * si / y)
            ok = False
sys.exit(0 if ok and n > 0 else 1)
PY
then pass "1-minute log: each bound is T = t_BS / 1.89, sigma = BS / 0.617 (the AR(1) Allan peak by scipy)"
else fail "1-minute log: the bound's T or sigma against the AR(1) Allan peak"; fi
# a profile edited by hand in the wrong unit (the gyro noise in deg/s/sqrt(Hz), the accelerometer bias in mg) must
# not be taken without a word: replay on the bundled walk ends 0.33 m from its start instead of 0.04 m, health all
# 0. A value no IMU has in the key's unit is a warning naming the key and the unit
# it most likely is in; the run goes on (the value is valid); every command that loads a profile says it once
cp docs/profiles/generic-mems.profile "$T/hand.profile"
sed -i 's/^gyro_noise_rps_rthz = .*/gyro_noise_rps_rthz = 0.0396 0.0422 0.039/' "$T/hand.profile"
expect_exit 0 "replay with a gyro noise in deg/s/sqrt(Hz)" "$H" replay vectors/walk.bin --quiet --profile "$T/hand.profile"
expect_err "warning: $T/hand.profile: gyro_noise_rps_rthz 0.0396 is 2.27 deg/s/sqrt(Hz), above any IMU's (1 deg/s/sqrt(Hz)): in deg/s/sqrt(Hz) or deg/sqrt(h)? the key is in rad/s/sqrt(Hz) (x pi/180 = 0.000691 from deg/s/sqrt(Hz), x pi/10800 = 1.15e-05 from deg/sqrt(h))" \
    "a gyro noise in deg/s/sqrt(Hz): warned with the likely unit"
[ "$(grep -c "above any IMU's" "$T/err")" -eq 1 ] && pass "one warning per profile" || fail "warnings: $(cat "$T/err")"
cp docs/profiles/generic-mems.profile "$T/hand2.profile"
sed -i 's/^accel_bias_sigma_mps2 = .*/accel_bias_sigma_mps2 = 5 5 8/' "$T/hand2.profile"
expect_exit 0 "montecarlo with an accelerometer bias in mg" "$H" montecarlo --seeds 2 --duration 10 --quiet --profile "$T/hand2.profile"
expect_err "warning: $T/hand2.profile: accel_bias_sigma_mps2 5 is 0.51 g, above any IMU's in-run bias (0.1 g): in mg or ug? the key is in m/s^2 (x 0.00980665 = 0.049 from mg, x 9.80665e-6 = 4.9e-05 from ug)" \
    "an accelerometer bias in mg: warned with the likely unit"
[ "$(grep -c "above any IMU's" "$T/err")" -eq 1 ] && pass "montecarlo: one warning for its profile" || fail "montecarlo warnings: $(grep -c "above any IMU's" "$T/err")"
# ... and with two such files, the sensor's and the filter's, once each over
# the runs (the loader remembers each file it warned about, up to 64, not the
# last only: tests/test_profile.c, test_load_warns_once_per_file)
expect_exit 0 "montecarlo with two implausible profiles" "$H" montecarlo --seeds 3 --duration 10 --quiet --profile "$T/hand2.profile" --filter-profile "$T/hand.profile"
[ "$(grep -c "hand2.profile: accel_bias_sigma_mps2 5 is" "$T/err")" -eq 1 ] && [ "$(grep -c "hand.profile: gyro_noise_rps_rthz 0.0396 is" "$T/err")" -eq 1 ] &&
    pass "montecarlo: one warning for each of two profiles" || fail "two profiles' warnings: $(grep -c "above any IMU's" "$T/err")"
expect_exit 0 "replay with the generic profile file" "$H" replay vectors/walk.bin --quiet --profile docs/profiles/generic-mems.profile
! grep -q "above any IMU's" "$T/err" && pass "a plausible profile: no warning" || fail "generic-mems.profile warned: $(cat "$T/err")"
# a profile file whose name has no '/' and no '.' is read as a built-in's
# name: the error must say more than "unknown profile" when the file is there
cp docs/profiles/generic-mems.profile "$T/mysensor"
(cd "$T" && "$H" replay "$OLDPWD/vectors/walk.bin" --quiet --profile mysensor) >"$T/out" 2>"$T/err"; st=$?
[ $st -eq 2 ] && pass "a bare name is a built-in's name (exit 2)" || fail "bare name: exit $st, expected 2"
expect_err "unknown profile 'mysensor'.*a file of that name exists: give it as ./mysensor" \
    "the error names the file and how to give it"
(cd "$T" && "$H" replay "$OLDPWD/vectors/walk.bin" --quiet --profile ./mysensor) >"$T/out" 2>"$T/err" &&
    pass "./mysensor is read as the file" || { fail "./mysensor"; cat "$T/err"; }
expect_exit 2 "an unknown name, no such file" "$H" replay vectors/walk.bin --quiet --profile nosuchsensor
! grep -q "file of that name" "$T/err" && pass "no file hint without a file" || fail "file hint for a missing file: $(cat "$T/err")"
# a directory of that name: not "unknown profile 'mydir'" alone; it says the
# name is a directory, not a profile file
mkdir -p "$T/mydir"
(cd "$T" && "$H" replay "$OLDPWD/vectors/walk.bin" --quiet --profile mydir) >"$T/out" 2>"$T/err"; st=$?
[ $st -eq 2 ] && pass "a bare name that is a directory: exit 2" || fail "bare directory name: exit $st, expected 2"
expect_err "unknown profile 'mydir'.*; 'mydir' is a directory, not a profile file$" "the error says the name is a directory"
! grep -q "file of that name" "$T/err" && pass "no file hint for a directory" || fail "file hint for a directory: $(cat "$T/err")"
# the datasheet example of docs/profile-format.md ("From a datasheet") is a
# valid, plausible profile that replay and sim take
awk '/^### From a datasheet/ { s = 1 } s && /^```/ { n++; next } s && n == 1' docs/profile-format.md >"$T/ds.profile"
expect_exit 0 "replay with the datasheet example profile" "$H" replay vectors/walk.bin --quiet --profile "$T/ds.profile"
! grep -q "above any IMU's" "$T/err" && pass "the datasheet example: no units warning" || fail "datasheet example warned: $(cat "$T/err")"
expect_exit 0 "sim with the datasheet example profile" "$H" sim --duration 5 --profile "$T/ds.profile" --out "$T/ds.bin"

# --- a profile file a user got wrong (docs/profile-format.md): each mistake
# is a usage error (exit 2) naming the file, the line and what is wrong, and
# nothing is replayed (these paths of hx_profile.c are otherwise run by no
# test: make coverage-harness).
HDR='format = footnav-profile 1'
bad_profile() { # description expected-message: $T/bad.profile is the file
    expect_exit 2 "profile $1" "$H" replay vectors/walk.bin --quiet --profile "$T/bad.profile" --out "$T/bad_out.csv"
    expect_err "$2" "profile $1: the message"
    [ ! -e "$T/bad_out.csv" ] && pass "profile $1: no output written" || fail "profile $1: an output was written"
    rm -f "$T/bad_out.csv"
}
printf 'rate_hz = 100\n' >"$T/bad.profile"
bad_profile "without its format line" "bad.profile: not a footnav profile (no 'format = footnav-profile 1' line)"
printf 'format = footnav-profile 2\nrate_hz = 100\n' >"$T/bad.profile"
bad_profile "of another format version" "bad.profile:1: format 'footnav-profile 2' not supported (expected 'footnav-profile 1')"
printf '%s\n' "$HDR" >"$T/bad.profile"
bad_profile "without rate_hz" "bad.profile: no line gives rate_hz (a required key)$"
printf '%s\nrate_hz = 100\nrate_hz = 200\n' "$HDR" >"$T/bad.profile"
bad_profile "with rate_hz twice" "bad.profile:3: rate_hz given twice"
printf '%s\nrate_hz = 1e7\n' "$HDR" >"$T/bad.profile"
bad_profile "with rate_hz out of range" "bad.profile:2: rate_hz '1e7' outside \[1, 1e+06\] (an IMU's output rate)"
# a rate that is no positive number is not taken as out of range or as 0 (docs/profile-format.md, "Errors")
for v in 0 -200 200Hz; do
    printf '%s\nrate_hz = %s\n' "$HDR" "$v" >"$T/bad.profile"
    bad_profile "with rate_hz = $v" "bad.profile:2: rate_hz '$v' is not a positive number"
done
rm -f "$T/bad.profile"
bad_profile "that does not exist" "bad.profile: cannot open profile (No such file or directory)"
printf '%s\nrate_hz = 100\nrate 100\n' "$HDR" >"$T/bad.profile"
bad_profile "with a line without '='" "bad.profile:3: expected 'key = value'"
printf '%s\nrate_hz = 100\ngyro_tau_s = 100 100\n' "$HDR" >"$T/bad.profile"
bad_profile "with two values of three" "bad.profile:3: gyro_tau_s needs three positive numbers (x y z)"
printf '%s\nrate_hz = 100\ngyro_tau_s = 100 100 -5\n' "$HDR" >"$T/bad.profile"
bad_profile "with a negative value" "bad.profile:3: gyro_tau_s needs three positive numbers (x y z)"
printf '%s\nrate_hz = 100\ngyro_tau_s = 100 100 100 s\n' "$HDR" >"$T/bad.profile"
bad_profile "with text after the three values" "bad.profile:3: gyro_tau_s: unexpected text after three values"
printf '%s\nrate_hz = 100\ngyro_tau_s = 100 100 100\ngyro_tau_s = 50 50 50\n' "$HDR" >"$T/bad.profile"
bad_profile "with a triple twice" "bad.profile:4: gyro_tau_s given twice"
printf '%s\nrate_hz = 100\nname = a\000b\n' "$HDR" >"$T/bad.profile"
bad_profile "with a NUL byte" "bad.profile:3: NUL byte: not a text file"
{ printf '%s\nrate_hz = 100\n# ' "$HDR"; awk 'BEGIN { for (i = 0; i < 600; i++) printf "x"; print "" }'; } >"$T/bad.profile"
bad_profile "with a 602-character line" "bad.profile:3: line too long (at most 511 characters)"
rm -f "$T/bad.profile"; mkdir "$T/bad.profile"
bad_profile "that is a directory" "bad.profile: cannot read profile ("
rmdir "$T/bad.profile"
# a value one consumer refuses is refused by the loader, at its line with its key, by every command (exit 2,
# nothing read): the filter took gyro_bias_sigma_rps = 1e-25 and refused its configuration naming no key, sim
# refused accel_noise 1e20 and a correlation time of 0.0005 s as "not valid for the error model", simgap read the
# log and blamed it; rate_hz 1e-40 made sim --bias-sigma eq6's bias sd 0; gyro_tau_s = 0x10 was read as 16
limit_case() { # sed-expression expected-message
    sed "$1" "$T/ds.profile" >"$T/lim.profile"
    msg=$2
    for c in replay sim montecarlo simgap; do
        case $c in
        replay) set -- "$H" replay vectors/walk.bin --quiet ;;
        sim) set -- "$H" sim --duration 5 --out "$T/lim.bin" ;;
        montecarlo) set -- "$H" montecarlo --seeds 1 --duration 5 --quiet ;;
        simgap) set -- "$H" simgap vectors/walk.bin --quiet ;;
        esac
        expect_exit 2 "$c: profile $msg" "$@" --profile "$T/lim.profile"
        expect_err "lim.profile:$msg" "$c: profile $msg: the message"
    done
}
limit_case 's/^gyro_bias_sigma_rps = .*/gyro_bias_sigma_rps = 1e-25 4.8e-5 4.8e-5/' \
    "12: gyro_bias_sigma_rps value 1 '1e-25' outside \[1.0842e-19, 1000\]"
limit_case 's/^accel_noise_mps2_rthz = .*/accel_noise_mps2_rthz = 6.86e-4 1e20 6.86e-4/' \
    "7: accel_noise_mps2_rthz value 2 '1e20' outside \[1.17549e-38, 1000\]"
limit_case 's/^accel_tau_s = .*/accel_tau_s = 100 100 0.0005/' "8: accel_tau_s value 3 '0.0005' outside \[0.001, 1e+09\]"
limit_case 's/^gyro_tau_s = .*/gyro_tau_s = 1e10 100 100/' "11: gyro_tau_s value 1 '1e10' outside \[0.001, 1e+09\]"
limit_case 's/^rate_hz = .*/rate_hz = 1e-40/' "6: rate_hz '1e-40' outside \[1, 1e+06\]"
limit_case 's/^gyro_tau_s = .*/gyro_tau_s = 0x10 1 1/' "11: gyro_tau_s value 1 '0x10' is not a decimal number"
# sim --bias-sigma eq6 rescales the bias sd by sqrt(tau rate) / 0.617: a file within the limits can leave them
# (rate 1e6 Hz, tau 1000 s: 0.1 -> 5125): refused naming the key and eq6, not "not valid for the error model"
sed 's/^rate_hz = .*/rate_hz = 1000000/; s/^accel_tau_s = .*/accel_tau_s = 1000 1000 1000/; s/^accel_bias_sigma_mps2 = .*/accel_bias_sigma_mps2 = 0.1 0.1 0.1/' \
    "$T/ds.profile" >"$T/eq6.profile"
expect_exit 2 "sim --bias-sigma eq6 past the limits" "$H" sim --duration 5 --out "$T/lim.bin" --bias-sigma eq6 --profile "$T/eq6.profile"
expect_err "read by --bias-sigma eq6: accel_bias_sigma_mps2 value 1 5125.* outside \[1.0842e-19, 1000\]" "... the key named"
# a name goes to stdout: an ESC in it is refused, not sent to the terminal
sed 's/^name = .*/name = a\x1b[2Jb/' "$T/ds.profile" >"$T/bad.profile"
bad_profile "with an ESC in its name" "bad.profile:5: name has a control character (byte 2, 0x1b)"
# ... and a byte that is not UTF-8 (a name saved in Latin-1): refused as such, not passed to the terminal as a raw
# byte (0x9B is CSI to a terminal of 8-bit controls); a UTF-8 letter is a name's text
sed "s/^name = .*/name = caf$(printf '\351')/" "$T/ds.profile" >"$T/bad.profile"
bad_profile "with a Latin-1 byte in its name" "bad.profile:5: name has a byte that is not UTF-8 text (byte 4, 0xe9)"
sed "s/^name = .*/name = caf$(printf '\303\251')/" "$T/ds.profile" >"$T/utf8.profile"
expect_exit 0 "a profile whose name holds a UTF-8 letter" "$H" replay vectors/walk.bin --quiet --profile "$T/utf8.profile" \
    --out "$T/utf8_out.csv"
# a name of 20 two-byte letters (40 bytes) is kept to 31 bytes: cut before a letter (15), not inside the 16th,
# which the name check would then refuse
sed "s/^name = .*/name = $(printf '\303\251%.0s' 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20)/" "$T/ds.profile" >"$T/utf8l.profile"
expect_exit 0 "a profile whose name is 20 two-byte letters" "$H" replay vectors/walk.bin --profile "$T/utf8l.profile" \
    --out "$T/utf8_out.csv"
expect_out "^config  *profile $(printf '\303\251%.0s' 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15) (file " \
    "the name of 20 two-byte letters shown as its first 15, no byte of the 16th"
# a misspelt required key: its line is named in the error about the missing key
sed 's/^gyro_noise_rps_rthz/gyro_nosie/' "$T/ds.profile" >"$T/bad.profile"
bad_profile "with a misspelt required key" \
    "bad.profile: no line gives gyro_noise_rps_rthz (a required key; line 10 has 'gyro_nosie', unknown: misspelt?)"
# an unknown key is ignored (a later version's key), with a warning naming its line and the key it likely meant;
# allan's optional keys and x_* are not warned about
{ cat "$T/ds.profile"; printf 'gyro_nosie = 1 1 1\nName = t\nx_mine = 1\nident_samples = 5\npaper_gyro_tau_s = 1 1 1\n'; } >"$T/unk.profile"
expect_exit 0 "replay with unknown keys in the profile" "$H" replay vectors/walk.bin --quiet --profile "$T/unk.profile"
expect_err "warning: $T/unk.profile:13: unknown key 'gyro_nosie' ignored (did you mean gyro_noise_rps_rthz?)" \
    "an unknown key: warned at its line with the key it likely meant"
expect_err "unk.profile:14: unknown key 'Name' ignored (did you mean name?)" "Name: did you mean name"
[ "$(grep -c "unknown key" "$T/err")" -eq 2 ] && pass "x_, ident_ and paper_ keys: no warning" ||
    fail "unknown-key warnings: $(cat "$T/err")"
# an unknown key near no known one: the warning says how to keep a key of one's own; tabs around a key and its
# values are blanks (docs/profile-format.md, "Format" and "Optional keys")
{ sed 's/^gyro_tau_s = \(.*\)/gyro_tau_s\t=\t\1\t/' "$T/ds.profile"; printf 'colour = red\n'; } >"$T/own.profile"
expect_exit 0 "replay with a key of no known spelling and a tab-separated line" "$H" replay vectors/walk.bin --quiet \
    --profile "$T/own.profile"
expect_err "own.profile:13: unknown key 'colour' ignored (a key of your own starts with x_)$" \
    "an unknown key near no known one: x_ named"
expect_exit 0 "montecarlo with unknown keys in the profile" "$H" montecarlo --seeds 2 --duration 5 --quiet \
    --profile "$T/unk.profile"
[ "$(grep -c "unknown key 'gyro_nosie'" "$T/err")" -eq 1 ] && pass "montecarlo: the unknown key warned about once" ||
    fail "montecarlo unknown-key warnings: $(grep -c "unknown key" "$T/err")"
# more unknown keys than are listed: the rest counted; a path too long for the warning buffer (1,024 bytes)
# left every line out and said nothing; a C1 control in a key (U+009B, a terminal's CSI) quoted as '?'
{ cat "$T/ds.profile"; for i in 1 2 3 4 5 6 7 8 9 10; do printf 'y_%d = 1\n' "$i"; done; } >"$T/many.profile"
expect_exit 0 "replay with 10 unknown keys" "$H" replay vectors/walk.bin --quiet --profile "$T/many.profile"
[ "$(grep -c "unknown key 'y_" "$T/err")" -eq 8 ] && expect_err "many.profile: 2 more unknown keys ignored$" \
    "10 unknown keys: 8 listed, 2 counted" || fail "10 unknown keys: $(cat "$T/err")"
LP=$T
for c in p q r s t u v w x y z o; do LP="$LP/$(printf "$c%.0s" $(seq 250))"; done # 3,000 bytes and more
mkdir -p "$LP"
{ cat "$T/ds.profile"; printf 'y_1 = 1\ny_2 = 1\n'; } >"$LP/long.profile"
expect_exit 0 "replay with unknown keys in a profile of a long path" "$H" replay vectors/walk.bin --quiet \
    --profile "$LP/long.profile"
expect_err "long.profile:13: unknown key 'y_1' ignored" "an unknown key warned with a path of over 3,000 bytes"
expect_err "long.profile: 1 more unknown key ignored$" "... the line without room counted"
{ cat "$T/ds.profile"; printf 'bad\302\233[31mkey = 1\n'; } >"$T/c1.profile"
expect_exit 0 "replay with a C1 control in an unknown key" "$H" replay vectors/walk.bin --quiet --profile "$T/c1.profile"
expect_err "unknown key 'bad?\[31mkey' ignored" "a C1 control in a key quoted as '?'"
# a line of exactly 511 characters is still read (the limit is inclusive)
{ cat "$T/ds.profile"; printf '# '; awk 'BEGIN { for (i = 0; i < 509; i++) printf "x"; print "" }'; } >"$T/edge.profile"
expect_exit 0 "a profile with a 511-character comment line" "$H" replay vectors/walk.bin --quiet --profile "$T/edge.profile"

echo "profile chain: $fails failure(s)"
[ "$fails" -eq 0 ]
