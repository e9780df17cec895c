#!/bin/sh
# CLI tests of `harness merge`: an accelerometer's file and a gyroscope's,
# written apart as MetaWear's MetaBase, phyphox and Sensor Logger write
# them, made from the bundled walk, merged into one log; the values
# against numpy's interpolation and the replay against the walk's own.
# $HARNESS is the harness binary (set by `make test-cli`).
set -u
H=${HARNESS:-bin/harness}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"

expect_exit 0 "merge --help" "$H" merge --help
expect_out "ACC GYRO OUT" "the synopsis names ACC GYRO OUT"
expect_exit 2 "merge without OUT" "$H" merge a.csv b.csv
expect_exit 2 "merge: a bad --units" "$H" merge a.csv b.csv "$T/o.csv" --units accel=furlong
expect_exit 2 "merge: a bad --to" "$H" merge a.csv b.csv "$T/o.csv" --to gx2

# the walk, its 205 duplicated stamps dropped (a merge keeps the first row
# of a stamp, as the files below hold it only once)
expect_exit 0 "walk.bin to CSV" "$H" convert vectors/walk.bin "$T/w.csv"
awk -F, 'NR == 1 || $1 != last { print } { last = $1 }' "$T/w.csv" > "$T/ref.csv"

# the files: metawear (accelerometer in g, the ISO date and epoch beside
# elapsed (s)), phyphox_acc and phyphox (quoted names, m/s^2 and rad/s),
# phyphox_semi (semicolons and decimal commas), mw_acc / mw_gyr (MetaWear's
# MetaBase pair: epoch in whole ms, the date and time, elapsed from each
# file's own first sample; g and deg/s; the gyroscope begins 7 samples
# after the accelerometer), slog_acc / slog_gyr (Sensor Logger: time in ns since
# the epoch, no units, the axes z, y, x; the gyroscope 1.3 ms after each
# accelerometer sample, every 97th row missing and 12 rows from row 3001
# missing: a gap), gyr_bad (a row of text at line 5001), ptb_acc (Physics
# Toolbox Sensor Suite: the g-force gFx in g, then the app's linear
# acceleration ax, gravity removed)
/usr/bin/python3 - "$T" <<'PY' || fail "writing the two-file variants"
import datetime, sys, numpy as np
T = sys.argv[1]
d = np.genfromtxt(T + '/ref.csv', delimiter=',', names=True)
t = d['t'] - d['t'][0]
a = np.column_stack([d['ax'], d['ay'], d['az']])
g = np.column_stack([d['gx'], d['gy'], d['gz']])
with open(T + '/metawear.csv', 'w') as f:
    f.write('epoch (ms),time (-13:00),elapsed (s),x-axis (g),y-axis (g),z-axis (g)\n')
    for ti, ai in zip(t, a):
        f.write('%d,2023-11-14T22.13.20.000,%.9f,%s\n' % (1700000000000 + int(ti * 1000), ti,
                                                          ','.join('%.9g' % (v / 9.80665) for v in ai)))
with open(T + '/phyphox_acc.csv', 'w') as f:
    f.write('"Time (s)","Acceleration x (m/s^2)","Acceleration y (m/s^2)","Acceleration z (m/s^2)"\n')
    for ti, ai in zip(t, a):
        f.write('%.9f,%s\n' % (ti, ','.join('%.9g' % v for v in ai)))
ms = 1700000000000 + np.floor(t * 1000).astype(np.int64)
def metawear(path, unit, vals, first):
    with open(path, 'w') as f:
        f.write('epoch (ms),time (-13:00),elapsed (s),x-axis (%s),y-axis (%s),z-axis (%s)\n' % (unit, unit, unit))
        for k in range(first, len(t)):
            loc = datetime.datetime.fromtimestamp(ms[k] // 1000 - 13 * 3600, datetime.timezone.utc)
            f.write('%d,%s.%03d,%.3f,%s\n' % (ms[k], loc.strftime('%Y-%m-%dT%H:%M:%S'), ms[k] % 1000,
                                              (ms[k] - ms[first]) / 1000, ','.join('%.9g' % v for v in vals[k])))
metawear(T + '/mw_acc.csv', 'g', a / 9.80665, 0)
metawear(T + '/mw_gyr.csv', 'deg/s', np.degrees(g), 7)
with open(T + '/phyphox.csv', 'w') as f:
    f.write('"Time (s)","Gyroscope x (rad/s)","Gyroscope y (rad/s)","Gyroscope z (rad/s)"\n')
    for ti, gi in zip(t, g):
        f.write('%.9f,%s\n' % (ti, ','.join('%.9g' % v for v in gi)))
with open(T + '/phyphox_semi.csv', 'w') as f:
    f.write('"Time (s)";"Gyroscope x (rad/s)";"Gyroscope y (rad/s)";"Gyroscope z (rad/s)"\n')
    for ti, gi in zip(t, g):
        f.write(('%.9f;%s\n' % (ti, ';'.join('%.9g' % v for v in gi))).replace('.', ','))
ns = 1733300000 * 10**9 + np.round(t * 1e9).astype(np.int64)
keep = np.ones(len(t), bool)
keep[::97] = False
keep[3001:3013] = False
with open(T + '/slog_acc.csv', 'w') as f:
    f.write('time,seconds_elapsed,z,y,x\n')
    for k in range(len(t)):
        f.write('%d,%.9f,%.9g,%.9g,%.9g\n' % (ns[k], t[k], a[k, 2], a[k, 1], a[k, 0]))
gs = ns + 1300000
with open(T + '/slog_gyr.csv', 'w') as f:
    f.write('time,seconds_elapsed,z,y,x\n')
    for k in np.flatnonzero(keep):
        f.write('%d,%.9f,%.9g,%.9g,%.9g\n' % (gs[k], t[k] + 0.0013, g[k, 2], g[k, 1], g[k, 0]))
with open(T + '/ptb_acc.csv', 'w') as f:
    f.write('time,gFx,gFy,gFz,ax,ay,az\n')
    for ti, ai in zip(t, a):
        f.write('%.9f,%s\n' % (ti, ','.join('%.9g' % v for v in list(ai / 9.80665) + list(ai - [0, 0, 9.8]))))
# the iOS app's g-force file: a local date and time to 0.1 ms, the
# magnitude gFTotal beside the axes; its gyroscope file on the same clock
day = datetime.datetime(2018, 10, 3, 17, 23, 55)
dts = [(day + datetime.timedelta(microseconds=int(round(ti * 1e4)) * 100)).strftime('%Y-%m-%d %H:%M:%S.%f')[:-2]
       for ti in t]
with open(T + '/ptb_ios_acc.csv', 'w') as f:
    f.write('time,gFx,gFy,gFz,gFTotal\n')
    for di, ai in zip(dts, a / 9.80665):
        f.write('%s,%s,%.9g\n' % (di, ','.join('%.9g' % v for v in ai), np.linalg.norm(ai)))
with open(T + '/ptb_ios_gyr.csv', 'w') as f:
    f.write('time,wx,wy,wz\n')
    for di, gi in zip(dts, g):
        f.write('%s,%s\n' % (di, ','.join('%.9g' % v for v in gi)))
lines = open(T + '/phyphox.csv').read().splitlines(True)
lines[5000] = '0.5,oops,1,2\n'
open(T + '/gyr_bad.csv', 'w').write(''.join(lines))
PY

# --- phyphox's accelerometer and gyroscope on the same stamps: the walk again
expect_exit 0 "merge phyphox_acc + phyphox" "$H" merge "$T/phyphox_acc.csv" "$T/phyphox.csv" "$T/m1.csv"
expect_err "phyphox_acc.csv: 16334 samples, .* time 'Time (s)' in s, x, y, z 'Acceleration x (m/s^2)', 'Acceleration y (m/s^2)', 'Acceleration z (m/s^2)' in m/s2$" \
    "phyphox's accelerometer file read by its names"
expect_err "wrote 16334 samples at the accelerometer's stamps" "every sample written"
if msg=$(/usr/bin/python3 - "$T/ref.csv" "$T/m1.csv" <<'PY'
import sys, numpy as np
r, m = (np.genfromtxt(f, delimiter=',', names=True) for f in sys.argv[1:3])
da = max(np.abs(r[k] - m[k]).max() for k in ('ax', 'ay', 'az'))
dg = max(np.abs(r[k] - m[k]).max() for k in ('gx', 'gy', 'gz'))
dt = np.abs((r['t'] - r['t'][0]) - m['t']).max()
print('accel %.3g m/s^2, gyro %.3g rad/s, time %.3g s' % (da, dg, dt))
sys.exit(0 if len(r) == len(m) and da < 2e-6 and dg == 0 and dt < 5e-10 else 1)
PY
); then pass "phyphox pair: the walk's values ($msg)"; else fail "phyphox pair values: $msg"; fi
expect_exit 0 "replay the walk" "$H" replay "$T/ref.csv" --out "$T/ref_traj.csv" --quiet
expect_exit 0 "replay the merged walk" "$H" replay "$T/m1.csv" --out "$T/m1_traj.csv" --quiet
if msg=$(/usr/bin/python3 - "$T/ref_traj.csv" "$T/m1_traj.csv" <<'PY'
import sys, numpy as np
a, b = (np.genfromtxt(f, delimiter=',', names=True) for f in sys.argv[1:3])
d = max(np.abs(a[k] - b[k]).max() for k in ('x', 'y', 'z'))
print('%.2g m apart' % d)
sys.exit(0 if len(a) == len(b) and d < 1e-3 else 1)
PY
); then pass "the merged walk replays to the walk's path ($msg)"; else fail "merged walk's path: $msg"; fi

# --- Physics Toolbox's g-force is the accelerometer, not the app's linear
# acceleration beside it (before: two columns for each axis, refused)
expect_exit 0 "merge ptb_acc + phyphox" "$H" merge "$T/ptb_acc.csv" "$T/phyphox.csv" "$T/m5.csv"
expect_err "ptb_acc.csv: 16334 samples, .* x, y, z 'gFx', 'gFy', 'gFz' in g$" "the g-force read, in g"
if msg=$(/usr/bin/python3 - "$T/ref.csv" "$T/m5.csv" <<'PY'
import sys, numpy as np
r, m = (np.genfromtxt(f, delimiter=',', names=True) for f in sys.argv[1:3])
da = max(np.abs(r[k] - m[k]).max() for k in ('ax', 'ay', 'az'))
print('accel %.3g m/s^2' % da)
sys.exit(0 if len(r) == len(m) and da < 2e-6 else 1)
PY
); then pass "Physics Toolbox's g-force: the walk's accelerations ($msg)"; else fail "ptb_acc values: $msg"; fi

# --- the iOS app's g-force file (dates and times, gFTotal beside the axes)
# with a gyroscope's file on the same clock: the walk's values at the
# stamps rounded to 0.1 ms, as the app writes them
expect_exit 0 "merge ptb_ios_acc + ptb_ios_gyr" "$H" merge "$T/ptb_ios_acc.csv" "$T/ptb_ios_gyr.csv" "$T/m6.csv"
expect_err "ptb_ios_acc.csv: 16334 samples, .* time 'time' as dates and times, x, y, z 'gFx', 'gFy', 'gFz' in g$" \
    "the iOS g-force read by its names, gFTotal left"
if msg=$(/usr/bin/python3 - "$T/ref.csv" "$T/m6.csv" <<'PY'
import sys, numpy as np
r, m = (np.genfromtxt(f, delimiter=',', names=True) for f in sys.argv[1:3])
t = r['t'] - r['t'][0]
da = max(np.abs(r[k] - m[k]).max() for k in ('ax', 'ay', 'az'))
dg = max(np.abs(r[k] - m[k]).max() for k in ('gx', 'gy', 'gz'))
dt = np.abs(np.round(t * 1e4) / 1e4 - (m['t'] - m['t'][0])).max()
print('accel %.3g m/s^2, gyro %.3g rad/s, time %.3g s' % (da, dg, dt))
# the merged t is Unix seconds (1.5e9), which a double holds to 2.4e-7 s
sys.exit(0 if len(r) == len(m) and da < 2e-6 and dg == 0 and dt < 5e-7 else 1)
PY
); then pass "the iOS g-force with its gyroscope: the walk's values ($msg)"; else fail "ptb_ios values: $msg"; fi

# --- semicolons and decimal commas read as the commas and points
expect_exit 0 "merge phyphox_acc + phyphox_semi" "$H" merge "$T/phyphox_acc.csv" "$T/phyphox_semi.csv" "$T/m2.csv"
if cmp -s "$T/m1.csv" "$T/m2.csv"; then pass "semicolons and decimal commas: the same log"
else fail "semicolons and decimal commas: the log differs"; fi
# a row with decimal points among decimal commas: read as decimals too,
# the line said (merge read it without a word, as the log reader did)
sed '501s/,/./g' "$T/phyphox_semi.csv" >"$T/phyphox_mix.csv"
expect_exit 0 "merge phyphox_acc + phyphox_mix" "$H" merge "$T/phyphox_acc.csv" "$T/phyphox_mix.csv" "$T/m2m.csv"
expect_err "phyphox_mix.csv:501: a number with a decimal point ('$(sed -n '501s/,.*//p' "$T/phyphox.csv")') in a log whose numbers have decimal commas ('0,000000000', line 2): both read as decimal marks" \
    "merge: decimal points among commas said, the line named"
if cmp -s "$T/m1.csv" "$T/m2m.csv"; then pass "decimal commas and points: the same log"
else fail "decimal commas and points: the log differs"; fi

# --- MetaWear's pair: merged on the logger's clock, "epoch (ms)", not on
# "elapsed (s)", which each file counts from its own first sample (the
# gyroscope's 7 samples, about 17 ms, after the accelerometer's); values
# against numpy's: the accelerometer's whole-ms stamps from the gyroscope's
# first on (a stamp repeated once in ms dropped), the gyroscope's values
# at the same stamps
expect_exit 0 "merge a MetaWear pair" "$H" merge "$T/mw_acc.csv" "$T/mw_gyr.csv" "$T/mw.csv"
expect_err "mw_acc.csv: .* time 'epoch (ms)' in ms, x, y, z 'x-axis (g)', 'y-axis (g)', 'z-axis (g)' in g$" \
    "MetaWear: the epoch chosen over the date and elapsed (s)"
expect_err "mw_gyr.csv: .* time 'epoch (ms)' in ms, .* in deg/s$" "MetaWear's gyroscope: the epoch, deg/s"
if msg=$(/usr/bin/python3 - "$T/mw_acc.csv" "$T/mw_gyr.csv" "$T/mw.csv" <<'PY'
import sys, numpy as np
A, G = (np.loadtxt(f, delimiter=',', skiprows=1, usecols=(0, 3, 4, 5)) for f in sys.argv[1:3])
def first_of_each(x):
    keep = np.concatenate([[True], np.diff(x[:, 0]) > 0])
    return x[keep]
A, G = first_of_each(A), first_of_each(G)
A = A[(A[:, 0] >= G[0, 0]) & (A[:, 0] <= G[-1, 0])]
want_g = np.column_stack([np.interp(A[:, 0], G[:, 0], np.radians(G[:, k])) for k in (1, 2, 3)])
m = np.genfromtxt(sys.argv[3], delimiter=',', names=True)
got_ms = np.array([round(float(r.split(',')[0]) * 1000) for r in open(sys.argv[3]).read().split()[1:]], np.int64)
n_ok = len(m) == len(A)
dg = np.abs(np.column_stack([m['gx'], m['gy'], m['gz']]) - want_g).max() if n_ok else np.inf
da = np.abs(np.column_stack([m['ax'], m['ay'], m['az']]) - A[:, 1:] * 9.80665).max() if n_ok else np.inf
print('%d samples (numpy: %d), gyro %.3g rad/s, accel %.3g m/s^2 off' % (len(m), len(A), dg, da))
sys.exit(0 if n_ok and (got_ms == A[:, 0].astype(np.int64)).all() and dg < 2e-6 and da < 2e-5 else 1)
PY
); then pass "MetaWear pair: numpy's values on the epoch ($msg)"; else fail "MetaWear pair: $msg"; fi
# without the epoch, MetaBase's date and time in dots (2023-11-14T09.13.20.123)
# is read before elapsed (s), which counts from each file's own first
# sample (the gyroscope's 7 samples late): the pair merged as by the epoch
for f in mw_acc mw_gyr; do
    awk -F, 'BEGIN { OFS = "," } NR > 1 { gsub(":", ".", $2) } { $1 = ""; sub("^,", ""); print }' "$T/$f.csv" > "$T/${f}_dot.csv"
done
expect_exit 0 "merge a MetaBase pair by its dotted date" "$H" merge "$T/mw_acc_dot.csv" "$T/mw_gyr_dot.csv" "$T/mw_dot.csv"
expect_err "mw_acc_dot.csv: .* time 'time (-13:00)' as dates and times" "MetaBase: the dotted date read over elapsed (s)"
if msg=$(/usr/bin/python3 - "$T/mw.csv" "$T/mw_dot.csv" <<'PY'
import sys, numpy as np
a, b = (np.genfromtxt(f, delimiter=',', names=True) for f in sys.argv[1:3])
n_ok = len(a) == len(b)
dv = max(np.abs(a[k] - b[k]).max() for k in ('ax', 'ay', 'az', 'gx', 'gy', 'gz')) if n_ok else np.inf
dt = np.abs((a['t'] - a['t'][0]) - (b['t'] - b['t'][0])).max() if n_ok else np.inf
print('%d and %d samples, values %.3g, times %.3g s off' % (len(a), len(b), dv, dt))
sys.exit(0 if n_ok and dv == 0 and dt < 1e-9 else 1)
PY
); then pass "MetaBase pair by the dotted date: the epoch's merge ($msg)"; else fail "MetaBase dotted date: $msg"; fi
# without the epoch and the date, elapsed (s) is read and the start at 0 of
# both files is said
for f in mw_acc mw_gyr; do cut -d, -f3- "$T/$f.csv" > "$T/${f}_el.csv"; done
expect_exit 0 "merge a MetaWear pair by elapsed (s)" "$H" merge "$T/mw_acc_el.csv" "$T/mw_gyr_el.csv" "$T/mw_el.csv"
expect_err "warning: both files' time ('elapsed (s)', 'elapsed (s)') starts at 0: if each counts from its own first sample" \
    "elapsed from 0 in both files: said"
expect_exit 0 "merge phyphox (Time from 0, not elapsed)" "$H" merge "$T/phyphox_acc.csv" "$T/phyphox.csv" "$T/o.csv"
if grep -q "starts at 0" "$T/err"; then fail "the start warning for phyphox's shared Time (s)"; else pass "no start warning for phyphox's Time (s)"; fi
rm -f "$T/o.csv"
# a MetaWear file (its clock since 1970) and a phyphox file (from a start)
expect_exit 1 "merge MetaWear's accelerometer with phyphox's gyroscope" "$H" merge "$T/mw_acc.csv" "$T/phyphox.csv" "$T/o.csv"
expect_err "the files do not overlap in time: .*mw_acc.csv's time ('epoch (ms)') reads as a date (since 1970), .*phyphox.csv's ('Time (s)') as seconds from a start or a time of day: not one clock" \
    "two clocks named"

# --- Sensor Logger: ns since the epoch named by no unit, refused with the
# unit they look like; with --units time=ns the gyroscope interpolated at
# the accelerometer's stamps (numpy's np.interp, the gap left out)
expect_exit 1 "Sensor Logger without --units" "$H" merge "$T/slog_acc.csv" "$T/slog_gyr.csv" "$T/m3.csv"
expect_err "slog_acc.csv: the time column 'time' names no unit, and in seconds its stamps give .* Hz: they look like nanoseconds, a .* Hz log (give --units time=ns)" \
    "the stamps' unit named"
if [ -e "$T/m3.csv" ]; then fail "a refused merge wrote its output"; else pass "nothing written before the refusal"; fi
expect_exit 0 "Sensor Logger with --units time=ns" "$H" merge "$T/slog_acc.csv" "$T/slog_gyr.csv" "$T/m3.csv" --units time=ns
expect_err "slog_acc.csv: .* x, y, z 'x', 'y', 'z' in m/s2 (no unit named)" "the bare axes read (z, y, x in the file)"
if msg=$(/usr/bin/python3 - "$T/slog_acc.csv" "$T/slog_gyr.csv" "$T/m3.csv" <<'PY'
import sys, numpy as np
acc, gyr = (np.loadtxt(f, delimiter=',', skiprows=1, dtype=np.float64) for f in sys.argv[1:3])
ta = np.loadtxt(sys.argv[1], delimiter=',', skiprows=1, usecols=0, dtype=np.int64)
tg = np.loadtxt(sys.argv[2], delimiter=',', skiprows=1, usecols=0, dtype=np.int64)
m = np.genfromtxt(sys.argv[3], delimiter=',', names=True)
per = np.median(np.diff(tg))
# the gyroscope's interval around each accelerometer stamp; out of its span or over 3 periods: left out
j = np.searchsorted(tg, ta, side='right') - 1
inside = (j >= 0) & (j < len(tg) - 1) | (ta == tg[-1])
jj = np.clip(j, 0, len(tg) - 2)
span = tg[jj + 1] - tg[jj]
ok = inside & ((ta == tg[jj]) | (span <= round(3 * 1e9 / (1e9 / per))))
want_t = ta[ok]
w = (ta[ok] - tg[jj[ok]]) / span[ok]
want_g = gyr[jj[ok], 2:] + w[:, None] * (gyr[jj[ok] + 1, 2:] - gyr[jj[ok], 2:])
got_t = np.array([int(r.split(',')[0].replace('.', '')) for r in open(sys.argv[3]).read().split()[1:]], np.int64)
dg = np.abs(np.column_stack([m['gz'], m['gy'], m['gx']]) - want_g).max() if len(m) == len(want_t) else np.inf
da = np.abs(np.column_stack([m['az'], m['ay'], m['ax']]) - acc[ok, 2:]).max() if len(m) == len(want_t) else np.inf
print('%d samples (numpy: %d), stamps exact to the ns, gyro %.3g rad/s, accel %.3g m/s^2 off' % (len(m), len(want_t), dg, da))
sys.exit(0 if len(m) == len(want_t) and (got_t == want_t).all() and dg < 2e-6 and da < 2e-6 else 1)
PY
); then pass "Sensor Logger: numpy's interpolation ($msg)"; else fail "Sensor Logger interpolation: $msg"; fi

# --- Polar Sensor Logger's ACC and GYRO files (Verity Sense, H10): semicolons,
# the phone's time per packet (a date: not read), the sensor's own clock in
# ns since 2000 (read: both files share it), mg and deg/s; the gyroscope
# begun 3 samples after the accelerometer. Before, "the header names no
# time column"
/usr/bin/python3 - "$T" <<'PY' || fail "writing the Polar pair"
import sys, numpy as np
T = sys.argv[1]
d = np.genfromtxt(T + '/ref.csv', delimiter=',', names=True)
ns = 726849693410011776 + np.round((d['t'] - d['t'][0]) * 1e9).astype(np.int64)
def polar(path, unit, cols, first):
    with open(path, 'w') as f:
        f.write('Phone timestamp;sensor timestamp [ns];X [%s];Y [%s];Z [%s]\n' % (unit, unit, unit))
        for k in range(first, len(ns)):
            f.write('2023-01-12T14:41:%06.3f;%d;%s\n' % (33.466 + k * 0.0025 % 20, ns[k], ';'.join('%.6f' % v for v in cols[k])))
polar(T + '/polar_acc.txt', 'mg', np.column_stack([d['ax'], d['ay'], d['az']]) / 9.80665e-3, 0)
polar(T + '/polar_gyr.txt', 'dps', np.degrees(np.column_stack([d['gx'], d['gy'], d['gz']])), 3)
PY
expect_exit 0 "merge a Polar Sensor Logger pair" "$H" merge "$T/polar_acc.txt" "$T/polar_gyr.txt" "$T/polar.csv"
expect_err "polar_acc.txt: .* time 'sensor timestamp \[ns\]' in ns, x, y, z 'X \[mg\]', 'Y \[mg\]', 'Z \[mg\]' in mg$" \
    "Polar: the sensor's clock read, not the phone's, in mg"
expect_err "polar_gyr.txt: .* time 'sensor timestamp \[ns\]' in ns, .* in deg/s$" "Polar's gyroscope: the sensor's clock, deg/s"
if msg=$(/usr/bin/python3 - "$T/ref.csv" "$T/polar.csv" <<'PY'
import sys, numpy as np
r, m = (np.genfromtxt(f, delimiter=',', names=True) for f in sys.argv[1:3])
r = r[3:]  # the accelerometer's samples within the gyroscope's span
n_ok = len(r) == len(m)
da = max(np.abs(r[k] - m[k]).max() for k in ('ax', 'ay', 'az')) if n_ok else np.inf
dg = max(np.abs(r[k] - m[k]).max() for k in ('gx', 'gy', 'gz')) if n_ok else np.inf
# the stamps as text, to the ns (a float64 of 7.3e8 s holds 1.2e-7 s)
ns = [np.array([int(l.split(',')[0].replace('.', '')) for l in open(f).read().split()[1:]], np.int64) for f in sys.argv[1:3]]
tr, tm = ns[0][3:], ns[1]
dt = np.abs((tr - tr[0]) - (tm - tm[0])).max() if n_ok else -1
print('%d samples (the walk\'s from the gyroscope\'s first: %d), accel %.3g m/s^2, gyro %.3g rad/s, stamps %d ns off' % (len(m), len(r), da, dg, dt))
sys.exit(0 if n_ok and da < 2e-5 and dg < 2e-6 and dt == 0 else 1)
PY
); then pass "Polar pair: the walk's values ($msg)"; else fail "Polar pair: $msg"; fi

# --- the other commands refuse one sensor's file and name merge
expect_exit 1 "info on the gyroscope's file" "$H" info "$T/phyphox.csv"
expect_err "phyphox.csv:1: header has no column 't'; expected t,ax,ay,az,gx,gy,gz\[,temp\]; the gyroscope's alone (one sensor's file? bin/harness merge ACC GYRO OUT" \
    "info names merge for a gyroscope's file"
expect_exit 1 "replay on the accelerometer's file of bare axes" "$H" replay "$T/metawear.csv"
expect_err "metawear.csv:1: header has no column 't'; .*; a time and x, y, z alone (one sensor's file? bin/harness merge ACC GYRO OUT" \
    "replay names merge for a file of a time and x, y, z"
expect_exit 1 "info on a log without gyroscope columns" "$H" info "$T/ref.csv" --columns gx=nosuch
if grep -q "merge ACC GYRO" "$T/err"; then fail "a six-channel log's refusal names merge"; else pass "a six-channel log's refusal does not name merge"; fi

# --- bad input
expect_exit 1 "files swapped" "$H" merge "$T/phyphox.csv" "$T/phyphox_acc.csv" "$T/o.csv"
expect_err "phyphox.csv:1: the header names the gyroscope's channels ('Gyroscope x (rad/s)'), not the accelerometer's: the files swapped?" \
    "swapped files named"
expect_exit 1 "a log with both sensors" "$H" merge "$T/ref.csv" "$T/phyphox.csv" "$T/o.csv"
expect_err "ref.csv:1: the header names the accelerometer and the gyroscope: a log with both is read as it is" \
    "a log with both sensors is sent to the other commands"
expect_exit 2 "one file twice" "$H" merge "$T/phyphox.csv" "$T/phyphox.csv" "$T/o.csv"
expect_exit 2 "the output is an input" "$H" merge "$T/metawear.csv" "$T/phyphox.csv" "$T/phyphox.csv"
expect_exit 3 "an output in a directory that does not exist" "$H" merge "$T/metawear.csv" "$T/phyphox.csv" "$T/no/o.csv"
expect_err "no/o.csv" "the output named"
if grep -q "samples," "$T/err"; then fail "the files read before the output was found unwritable"
else pass "the output checked before the files are read"; fi
expect_exit 1 "a .bin given as a file" "$H" merge vectors/walk.bin "$T/phyphox.csv" "$T/o.csv"
expect_err "walk.bin: binary data, not a log" "a .bin refused as the readers refuse binary data"
expect_exit 1 "a missing file" "$H" merge "$T/metawear.csv" "$T/nosuch.csv" "$T/o.csv"
expect_err "nosuch.csv: cannot open" "the missing file named"
awk -F, 'BEGIN { OFS = "," } NR > 1 { $1 += 1000 } { print }' "$T/phyphox.csv" > "$T/late.csv"
expect_exit 1 "files that do not overlap" "$H" merge "$T/phyphox_acc.csv" "$T/late.csv" "$T/o.csv"
expect_err "the files do not overlap in time" "no overlap named"
rm -f "$T/o.csv"
expect_exit 1 "a row of text in the gyroscope's file" "$H" merge "$T/phyphox_acc.csv" "$T/gyr_bad.csv" "$T/o.csv"
expect_err "gyr_bad.csv:5001: column 2 ('Gyroscope x (rad/s)') is not a number: 'oops' (the 4999 samples before it are merged)" \
    "the bad row named"
n=$(($(wc -l < "$T/o.csv") - 1))
if [ "$n" -gt 4900 ] && [ "$n" -le 4999 ]; then pass "the samples before the bad row written ($n)"
else fail "samples written before the bad row: $n"; fi
# into a .bin: no END record (it read as whole), as convert's
expect_exit 1 "a bad row, merged into a .bin" "$H" merge "$T/phyphox_acc.csv" "$T/gyr_bad.csv" "$T/o.bin"
expect_exit 1 "info of that .bin: incomplete" "$H" info "$T/o.bin"
expect_err "truncated: no end record after" "the merged .bin said to be incomplete"
# exit 1 said as an error, not after warnings alone (as convert's and info's)
expect_exit 1 "a row of text in the gyroscope's file: the exit said" "$H" merge "$T/phyphox_acc.csv" "$T/gyr_bad.csv" "$T/o.csv"
expect_err "^harness merge: error: $T/gyr_bad.csv: incomplete input (warned above): the [0-9]* samples written cover its 4999 before the error$" \
    "the partial merge said as an error, with what it covers"

# the text checks the log reader makes (hx_log.c), made by merge's reader
# too: a NUL block, a stray delimiter, a cut last line, one sample, a
# header wider than the columns read, lines ending in CR alone
head -300 "$T/phyphox_acc.csv" > "$T/a300.csv"
/usr/bin/python3 - "$T" <<'PY' || fail "writing the text variants"
import sys
T = sys.argv[1]
s = open(T + '/a300.csv').read()
lines = s.split('\n')
b = bytearray(s.encode())
i = s.index('\n' + lines[101].split(',')[0] + ',')   # the row of line 102
j = s.index('\n', i + 1)
b[j - 2:j + 198] = b'\0' * 200                        # its last value's end and the rows after it zeroed
open(T + '/a_nul.csv', 'wb').write(bytes(b))
open(T + '/a_nulend.csv', 'wb').write(s[:s.index(lines[299])].encode() + lines[299][:8].encode() + b'\0' * 40)
f = lines[61].split(',')
f[1] = f[1][:-2] + ',' + f[1][-2:]                    # a stray delimiter in row 61's first value (its last two
                                                      # digits a value within 1e6: beyond, the row stops merge)
open(T + '/a_split.csv', 'w').write('\n'.join(lines[:61] + [','.join(f)] + lines[62:]))
body = lines[:299] + [lines[299][:-3]]                 # the last line cut inside its value, no newline
open(T + '/a_cut.csv', 'w').write('\n'.join(body))
open(T + '/a_one.csv', 'w').write('\n'.join(lines[:2]) + '\n')
wide = ['"pad%d"' % k for k in range(70)]
open(T + '/a_wide.csv', 'w').write('\n'.join([','.join(wide + lines[0].split(','))] +
                                             [','.join(['0'] * 70 + l.split(',')) for l in lines[1:299]]) + '\n')
open(T + '/a_cr.csv', 'w').write('\r'.join(lines[:20]) + '\r')
open(T + '/a_crcrlf.csv', 'w', newline='').write(''.join(l + '\r\r\n' for l in lines[:299]))
open(T + '/a_trail.csv', 'w').write('\n'.join([lines[0] + ','] + lines[1:299]) + '\n')
PY
expect_exit 1 "merge: a NUL block in the accelerometer's file" "$H" merge "$T/a_nul.csv" "$T/phyphox.csv" "$T/o.csv"
expect_err "a_nul.csv:102: a NUL byte in the text (binary data, e.g. a logger's unwritten blocks) (the 100 samples before it are merged)" \
    "merge: the NUL block refused at its line, the samples before it merged"
expect_exit 1 "merge: a NUL block in a last line without a newline" "$H" merge "$T/a_nulend.csv" "$T/phyphox.csv" "$T/o.csv"
expect_err "a_nulend.csv:300: a NUL byte in the text" "merge: the NUL in the last line named, not read as a cut line"
expect_exit 0 "merge: a stray delimiter in a row" "$H" merge "$T/a_split.csv" "$T/phyphox.csv" "$T/o.csv"
expect_err "a_split.csv:62: 1 row with more fields than the header's 4 (the first here): where a stray delimiter split a field" \
    "merge: the row with more fields than the header warned"
expect_exit 0 "merge: a last line cut without a newline" "$H" merge "$T/a_cut.csv" "$T/phyphox.csv" "$T/o.csv"
expect_err "a_cut.csv:300: last line has no newline and ends in a value the reader uses, which may be cut (file cut off mid-write?); ignored" \
    "merge: the cut last line dropped with a warning"
expect_err "a_cut.csv: 298 samples" "merge: the cut line not read"
expect_exit 1 "merge: one sample" "$H" merge "$T/a_one.csv" "$T/phyphox.csv" "$T/o.csv"
expect_err "a_one.csv: only one sample: merging needs two or more from each file" "merge: one sample refused"
expect_exit 1 "merge: the axes past column 64" "$H" merge "$T/a_wide.csv" "$T/phyphox.csv" "$T/o.csv"
expect_err "(merge reads the first 64 columns of a header; this one has more)" "merge: the column limit named"
expect_exit 1 "merge: lines ending in CR alone" "$H" merge "$T/a_cr.csv" "$T/phyphox.csv" "$T/o.csv"
expect_err "its lines end in a carriage return alone" "merge: CR line ends named"
# CR CR LF ('\r\n' written by a Windows text-mode file) is a line end, not
# a CR alone; a header's trailing delimiter names no field (every row was
# warned "fewer fields than the header's 5")
expect_exit 0 "merge: CR CR LF line ends" "$H" merge "$T/a_crcrlf.csv" "$T/phyphox.csv" "$T/o.csv"
expect_err "a_crcrlf.csv: 298 samples" "merge: CR CR LF read"
expect_exit 0 "merge: a header ending in a delimiter" "$H" merge "$T/a_trail.csv" "$T/phyphox.csv" "$T/o.csv"
if grep -q "fewer fields" "$T/err"; then fail "merge: a trailing delimiter counted as a field"; else pass "merge: a header's trailing delimiter names no field"; fi

# the files of one sensor at 100 Hz, 300 rows (c_acc: t,acc_x,acc_y,acc_z;
# c_gyr: t,gyr_x,gyr_y,gyr_z), and variants of the accelerometer's
/usr/bin/python3 - "$T" <<'PY' || fail "writing the c_ files"
import sys
T = sys.argv[1]
def rows(z, n=300, rate=100.0):
    return ['%.4f,0.01,-0.02,%s' % (i / rate, z(i)) for i in range(n)]
acc = rows(lambda i: '9.8')
open(T + '/c_acc.csv', 'w').write('\n'.join(['t,acc_x,acc_y,acc_z'] + acc) + '\n')
open(T + '/c_gyr.csv', 'w').write('\n'.join(['t,gyr_x,gyr_y,gyr_z'] + rows(lambda i: '0.001')) + '\n')
# row 100 (line 101) 5000 characters long: a free-text field after the axes
long_ = acc[:99] + [acc[99] + ',' + 'n' * 4990] + acc[100:]
open(T + '/c_long.csv', 'w').write('\n'.join(['t,acc_x,acc_y,acc_z'] + long_) + '\n')
# row 200 (line 201) beyond what a sensor reads: 1e39 (a float's Inf in a
# .bin), 5e6 m/s^2 (1 g in ug), 2e5 g (below 1e6 as written, 1.96e6 m/s^2)
for name, z in (('c_inf', '1e39'), ('c_ug', '5e6'), ('c_g', '2e5')):
    v = rows(lambda i: z if i == 199 else ('1' if name == 'c_g' else '9.8'))
    open(T + '/' + name + '.csv', 'w').write('\n'.join(['t,acc_x,acc_y,acc_z'] + v) + '\n')
# headers the log reader finds (docs/log-format.md, "CSV interchange"):
# numpy's savetxt header, commented, with commas and with blanks; Excel's
# separator line; a note before a header naming no axis (line 2)
import numpy as np
d = np.array([[float(x) for x in r.split(',')] for r in acc])
np.savetxt(T + '/c_np.csv', d, delimiter=',', header='t,acc_x,acc_y,acc_z')
np.savetxt(T + '/c_npb.csv', d, header='t acc_x acc_y acc_z')
open(T + '/c_sep.csv', 'w').write('\n'.join(['sep=;', 't;acc_x;acc_y;acc_z'] + [r.replace(',', ';') for r in acc]) + '\n')
open(T + '/c_note.csv', 'w').write('\n'.join(['# logger v2', 'time,foo,bar,baz'] + acc) + '\n')
# a slow logger: 12.5 Hz, stamps in seconds, no unit named
open(T + '/c_acc12.csv', 'w').write('\n'.join(['t,acc_x,acc_y,acc_z'] + rows(lambda i: '9.8', rate=12.5)) + '\n')
open(T + '/c_gyr12.csv', 'w').write('\n'.join(['t,gyr_x,gyr_y,gyr_z'] + rows(lambda i: '0.001', rate=12.5)) + '\n')
PY
# merge's lines are as long as the log reader's (HX_LINE_MAX): a row of
# 5000 characters stops it there (it read lines up to 8191)
expect_exit 1 "merge: a line longer than the log reader's" "$H" merge "$T/c_long.csv" "$T/c_gyr.csv" "$T/o.csv"
expect_err "c_long.csv:101: line longer than 4095 bytes with its line end (the 99 samples before it are merged)" \
    "merge: the over-long line named as the log reader names it"
# a value beyond 1e6 in SI units stops the file at its row, as the log
# reader stops (merge wrote it, exit 0: 1e39 a .bin record info refused as
# NaN or Inf, 5e6 a CSV row it refused as beyond 1e+06)
expect_exit 1 "merge: a value of 1e39" "$H" merge "$T/c_inf.csv" "$T/c_gyr.csv" "$T/o.csv"
expect_err "c_inf.csv:201: column 4 ('1e39') is beyond 1e+06 in SI units (no sensor reads that) (the 199 samples before it are merged)" \
    "merge: 1e39 refused at its row in the log reader's words"
expect_exit 0 "info of the samples merged before 1e39" "$H" info "$T/o.csv"
expect_exit 1 "merge: a value of 5e6 m/s^2" "$H" merge "$T/c_ug.csv" "$T/c_gyr.csv" "$T/o.bin"
expect_err "c_ug.csv:201: column 4 ('5e6') is beyond 1e+06 in SI units (no sensor reads that; in ug? 1 g is 1e6 ug: give --units accel=ug)" \
    "merge: 5e6 refused, ug asked about as the log reader asks"
expect_exit 1 "merge: 2e5 g, beyond 1e6 once in m/s^2" "$H" merge "$T/c_g.csv" "$T/c_gyr.csv" "$T/o.csv" --units accel=g
expect_err "c_g.csv:201: column 4 ('2e5' g, 1.96e+06 m/s^2) is beyond 1e+06 in SI units" "merge: the value judged in SI units, quoted in both"
# the header found as the log reader finds it (merge read numpy's first
# row as the header, 'the header names no accelerometer axis', and said
# line 1 of a header on line 2)
for v in c_np c_npb c_sep; do
    expect_exit 0 "merge: $v's header found as the log reader finds it" "$H" merge "$T/$v.csv" "$T/c_gyr.csv" "$T/o.csv"
    expect_err "$v.csv: 300 samples, 100 Hz, 2.99 s; time 't' in s, x, y, z 'acc_x', 'acc_y', 'acc_z'" "merge: $v read whole"
done
expect_exit 1 "merge: a header naming no axis under a note" "$H" merge "$T/c_note.csv" "$T/c_gyr.csv" "$T/o.csv"
expect_err "c_note.csv:2: the header names no accelerometer axis" "merge: the header's own line named"
# an error of the first data row at its own line (it said the header's)
printf '# note\n\nt,acc_x,acc_y,acc_z\n\nabc,0,0,9.8\n0.01,0,0,9.8\n' >"$T/c_row.csv"
expect_exit 1 "merge: text in the first row's time" "$H" merge "$T/c_row.csv" "$T/c_gyr.csv" "$T/o.csv"
expect_err "c_row.csv:5: the time column ('t') holds no number in the first row ('abc')" "merge: the first row's own line named"
# the ug question's remedy names the --units given, not a unit a header
# names: 'time (ms)' made it 'give --units time=ms,accel=ug', which read the
# gyroscope's seconds as ms (400 samples at 100 kHz, exit 0)
awk 'BEGIN { print "time (ms),acc_x,acc_y,acc_z"; for (i = 0; i < 300; i++) printf "%d,0,0,9806650\n", i * 10 }' >"$T/c_ugms.csv"
expect_exit 1 "merge: ug values under a 'time (ms)' header" "$H" merge "$T/c_ugms.csv" "$T/c_gyr.csv" "$T/o.csv"
expect_err "in ug? 1 g is 1e6 ug: give --units accel=ug)" "merge: the ug remedy names accel=ug alone"
expect_exit 0 "merge: the remedy followed" "$H" merge "$T/c_ugms.csv" "$T/c_gyr.csv" "$T/o.csv" --units accel=ug
# stamps of 1 to 20 Hz in seconds: the remedy names seconds too (it named
# ms alone, which made the 12.5 Hz log one of 12.5 kHz), and it works
expect_exit 1 "merge: a 12.5 Hz log, its time unit not named" "$H" merge "$T/c_acc12.csv" "$T/c_gyr12.csv" "$T/o.csv"
expect_err "in seconds its stamps give 12.5 Hz: they look like milliseconds, a 1.25e+04 Hz log (give --units time=ms); if they are seconds, a 12.5 Hz log: --units time=s" \
    "merge: seconds named beside ms for a 12.5 Hz log"
expect_exit 0 "merge: the 12.5 Hz log with --units time=s" "$H" merge "$T/c_acc12.csv" "$T/c_gyr12.csv" "$T/o.csv" --units time=s
expect_err "c_acc12.csv: 300 samples, 12.5 Hz, 23.92 s" "merge: the 12.5 Hz log read in seconds"
# --units time= is one option for two files: a time whose header names
# its unit is read in it (a 'time (ms)' file was read in the ns that
# --units time=ns gave the other file's bare 'time': 2.99 us long, merged
# to 300 samples in 3 us, exit 0), with a warning
awk 'BEGIN { print "time (ms),acc_x,acc_y,acc_z"; for (i = 0; i < 300; i++) printf "%d,0.1,0.2,9.8\n", i * 10 }' >"$T/c_accms.csv"
awk 'BEGIN { print "time,gyr_x,gyr_y,gyr_z"; for (i = 0; i < 300; i++) printf "%d0000000,0.01,0.02,0.03\n", i }' >"$T/c_gyrns.csv"
expect_exit 0 "merge: a 'time (ms)' file and a bare time with --units time=ns" \
    "$H" merge "$T/c_accms.csv" "$T/c_gyrns.csv" "$T/o.csv" --units time=ns
expect_err "c_accms.csv: 300 samples, 100 Hz, 2.99 s; time 'time (ms)' in ms" "merge: the time's named unit wins over --units"
expect_err "c_gyrns.csv: 300 samples, 100 Hz, 2.99 s; time 'time' in ns" "merge: --units time= reads the bare time"
expect_err "warning: .*c_accms.csv: time 'time (ms)' names its unit: read in ms, not in the ns of --units time=ns" \
    "merge: the --units time not read is said"
expect_err "c_accms.csv: time 'time (ms)' names its unit: .*a name that gives the wrong unit is mended in the header)" \
    "merge: the remedy for a wrong named unit said"
if [ "$(tail -n 1 "$T/o.csv" | cut -d, -f1)" = "2.990000000" ] && [ "$(grep -c . "$T/o.csv")" -eq 301 ]; then
    pass "merge: 300 samples to 2.99 s"
else
    fail "merge: 300 samples to 2.99 s: $(grep -c . "$T/o.csv") lines, last $(tail -n 1 "$T/o.csv")"
fi

# a field holding an escape sequence, past the first 600 bytes (which the
# binary-data check reads): merge's own reader quotes it with its control
# characters as '?', as the single-file reader does
awk 'BEGIN { print "t,ax,ay,az"; for (k = 0; k < 200; k++) if (k == 100) printf "1.00,0\033]0;X\007,0,-9.8\n"; else printf "%.2f,0,0,-9.8\n", k / 100 }' > "$T/escacc.csv"
awk 'BEGIN { print "t,gx,gy,gz"; for (k = 0; k < 200; k++) printf "%.2f,0,0,0\n", k / 100 }' > "$T/escgyr.csv"
"$H" merge "$T/escacc.csv" "$T/escgyr.csv" "$T/escout.csv" > "$T/out" 2> "$T/err"
if LC_ALL=C grep -q "$(printf '\033')" "$T/err" "$T/out"; then fail "merge: an escape character of the file reached the terminal"
else pass "merge: no escape character of the file in the messages"; fi
grep -q "is not a number: '0?\]0;X?'" "$T/err" && pass "merge: the field quoted with its control characters as '?'" ||
    fail "merge: the field's quote: $(cat "$T/err")"

if [ "$fails" -ne 0 ]; then
    echo "test_merge.sh: $fails failure(s)"
    exit 1
fi
echo "test_merge.sh: all passed"
