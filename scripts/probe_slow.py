#!/usr/bin/env python3
"""Slow gait probe: real walks played slower ("time dilation"), replayed, and
compared with the walk as recorded (docs/harness.md, "Slow walking";
docs/robustness.md, "Probes of an unseen recording").

Method. A walk is played slower by a factor s in (0, 1]: the foot follows
the same path with time stretched by 1/s, p'(t) = p(s t). Then
    attitude          C'_nb(t) = C_nb(s t)
    angular rate      w'_b(t)  = s w_b(s t)
    acceleration in n a'_n(t)  = s^2 a_n(s t)
and, with the specific force f_b = C_bn (a_n - g_n) (docs/frames.md: n is
z down, g_n = (0, 0, +g), at rest f_n = (0, 0, -g)),
    f'_b(t) = C_bn(s t) (s^2 a_n(s t) - g_n)
            = s^2 f_b(s t) + (s^2 - 1) C_bn(s t) g_n.
C_bn g_n = g (-sin(pitch), sin(roll) cos(pitch), cos(roll) cos(pitch)) (the
third row of C_nb = Rz(yaw) Ry(pitch) Rx(roll)): only the tilt enters, so
the drift of the yaw does not. At rest f_b = -C_bn g_n and f'_b = f_b: a
still foot reads the same specific force at every s.

The attitude is footnav's own: `bin/harness replay LOG --out traj.csv`
(roll, pitch, ZYX, rad); the rows before the alignment (zeros) take the
first aligned attitude (the foot stands still there). g is the log's own
|f| at rest (the mean specific force over its first still second), so that
a still stretch of the slowed copy reads the |f| of the original (the
sensor's scale error kept; with 9.80665 a 3DM-GX2 at |f| = 9.8865 would
read between the two). Errors of the replay's tilt (a fraction of a degree)
enter the slowed copy as (1 - s^2) g times that angle, a few hundredths of
a m/s^2 at s = 0.5.

Resampling. The log as converted (`bin/harness convert LOG out.csv`: t,
ax..gz) is put on a uniform grid at its median interval (linear
interpolation; rows with a time stamp not after the one before, the x-io
walk's duplicates, dropped), the signal s^2 f + (s^2 - 1) C_bn g_n and w are
stretched by 1/s at that rate with a polyphase band-limited resampler
(scipy.signal.resample_poly, up/down = the fraction s, line padding), and
w is scaled by s. The sampling rate is the log's; the slowed copy lasts
1/s times as long. s = 1 is the uniform grid alone (no filter).

Sensor errors. The gyro's turn-on bias b (the mean over the first still
second) would be scaled by s with the motion: (1 - s) b is added back. The
log's own noise shrinks by s (gyro) and s^2 (accelerometer), and the
resampler turns it into noise below s times the Nyquist frequency: white
noise is added per channel (seeded by s) so that each channel's standard
deviation over the first still second (1/s seconds in the copy) equals the
original's. The noise's level matches, not its spectrum (a white floor plus
the slowed original's band-limited part).

Checks printed per walk: at s = 1, the copy's closure and strides against
the replay of the log as recorded (for a log on a uniform clock the copy is
the log itself); per s, the replayed speed against s times the walk's at s
t (the median difference where that exceeds 0.5 m/s: a wrong sign or
scale of the gravity term would show here first); | mean |f'| - mean |f| | over the first still second
(1/s seconds in the copy; means, not medians: the 820 Hz walk's |f| is
quantised in steps of 1/300 g) and the noise levels.

Figures per walk and s, default settings (`bin/harness replay X.csv --json
- --strides s.csv --out traj.csv`; with --threshold also `--detector
threshold`):
- cadence: median `cadence_spm` of the stride CSV (steps/min);
- strides: rows of the stride CSV, against the walk as recorded;
- swing ZUPT: share of the frames of the original's swings (its stride
  CSV's swing_start_s..swing_end_s, mapped to t' = t0 + (t - t0) / s) that
  have a ZUPT; swings hit: those with a ZUPT in their middle 80 %; v at ZUPT:
  the largest true speed at a ZUPT in those swings' frames, s times the
  original replay's speed at s t;
- closure: return_error_3d_m (closed walks; footprint walk 31 is not one);
- distance: distance_m, and against the walk as recorded;
- median stride length and median height_change_m of the stride CSV.
After each walk's table, "SHOE at the mid-swing ZUPTs": the ZUPT runs in
the middle 80 % of a swing at a true speed over 0.3 m/s, their length in
samples, where in the swing, and at each run's smallest statistic the SHOE
statistic's two terms (numpy, the detector's formula, window and weights),
|w| and ||f| - g|, and the same at that instant of the walk at s = 1
(medians over the runs).

What it does not model: a slow walker does not replay a normal swing
slower (shorter strides, a lower foot, a flatter landing). The probe shows
where the detector is fragile, not how often a real slow walk gets there.

Usage: /usr/bin/python3 scripts/probe_slow.py [LOG...] [--factors 1,0.85,0.7,0.6,0.5]
       [--threshold] [--tmp DIR] [--keep]
Without LOG: openshoe_gx2 Measurement_100521_2 and _3, openshoe_c_820hz,
footprint walk 31 and the x-io short walk under $DATA (default
../shared/data). HARNESS=path overrides bin/harness. About 25 s for the
five walks and five factors, 36 s with --threshold. --keep (or --tmp)
keeps the copies, DIR/NAME.sS.csv, for replays by hand.
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from fractions import Fraction

import numpy as np
from scipy.signal import resample_poly

from shoe_statistic import shoe_terms

H = os.environ.get('HARNESS', 'bin/harness')
DATA = os.environ.get('DATA', '../shared/data')
DEFAULT_LOGS = ['openshoe_gx2/Measurement_100521_2_data_inert.txt',
                'openshoe_gx2/Measurement_100521_3_data_inert.txt',
                'openshoe_c_820hz/OpenShoeDataSet.txt',
                'pyshoe_vicon_llio/own_3dmgx5_footprints/SensorConnectData_31_imu.csv',
                'xio_ngimu_gait/short_walk.csv']
STILL_S = 1.0  # the log's first still second: noise, gyro bias and |f| at rest


def replay(path, tag, extra=()):
    """Replay path; returns (exit, summary JSON, stride rows, trajectory)."""
    js, st, tr = path + tag + '.json', path + tag + '.str.csv', path + tag + '.traj.csv'
    r = subprocess.run([H, 'replay', path, '--json', js, '--strides', st, '--out', tr, '--quiet', *extra],
                       capture_output=True, text=True)
    try:
        with open(js) as fh:
            j = json.load(fh)
    except (OSError, ValueError):
        j = {}
    try:
        s = np.genfromtxt(st, delimiter=',', names=True)
        s = np.atleast_1d(s)
    except (OSError, ValueError):
        s = None
    try:
        t = np.genfromtxt(tr, delimiter=',', names=True, usecols=(0, 4, 5, 6, 7, 8, 16, 17))
    except (OSError, ValueError):
        t = None
    return r.returncode, j, s, t, r.stderr


def tilt_down(traj):
    """C_bn (0, 0, 1): the n frame's down axis in b, from roll and pitch;
    rows before the alignment (all zero) take the first aligned row's."""
    roll, pitch = traj['roll'].copy(), traj['pitch'].copy()
    moved = (np.abs(roll) + np.abs(pitch)) > 0
    if not moved.any():
        sys.exit('probe_slow.py: the replay never aligned')
    k = np.argmax(moved)
    roll[:k], pitch[:k] = roll[k], pitch[k]
    return np.column_stack([-np.sin(pitch), np.sin(roll) * np.cos(pitch), np.cos(roll) * np.cos(pitch)])


def increasing(t):
    keep = np.ones(len(t), bool)
    last = t[0]
    for i in range(1, len(t)):
        if t[i] <= last:
            keep[i] = False
        else:
            last = t[i]
    return keep


def load_converted(path):
    """The CSV of `bin/harness convert` (t, ax..gz), rows with a time stamp
    not after the one before dropped."""
    d0 = np.loadtxt(path, delimiter=',', skiprows=1)
    return d0[increasing(d0[:, 0])]


def uniform_grid(d0, t0, dt):
    """The log d0 (t, then channels) on the grid t0 + k dt up to its last
    stamp, each channel interpolated linearly (before d0's first stamp:
    its first row)."""
    tu = t0 + dt * np.arange(int(np.floor((d0[-1, 0] - t0) / dt)) + 1)
    du = np.column_stack([np.interp(tu, d0[:, 0], d0[:, c]) for c in range(1, d0.shape[1])])
    return tu, du


def tilt_on_grid(tu, traj0, t_offset=0.0):
    """tilt_down() of the replay traj0 on the grid tu (unit vectors); the
    trajectory's t plus t_offset is the log's time."""
    ttr = traj0['t'] + t_offset
    ktr = increasing(ttr)
    down = tilt_down(traj0)
    downu = np.column_stack([np.interp(tu, ttr[ktr], down[ktr, c]) for c in range(3)])
    downu /= np.linalg.norm(downu, axis=1)[:, None]
    return downu


def still_stats(d0, still0):
    """Over the rows still0 (the first still second): |mean f| (the g of the
    transform), the gyro's mean (its turn-on bias), each channel's standard
    deviation and |f| per row."""
    g = float(np.linalg.norm(d0[still0, 1:4].mean(0)))
    bias_g = d0[still0, 4:7].mean(0)
    sd0 = d0[still0, 1:7].std(0)
    fnorm0 = np.linalg.norm(d0[still0, 1:4], axis=1)
    return g, bias_g, sd0, fnorm0


def factor_rng(s, *more):
    """The added noise's generator for factor s: the same copy whatever the
    list of factors (more: further seed words, e.g. a file's)."""
    return np.random.default_rng([58, int(round(1000 * s)), *more])


def slowed(tu, du, downu, s, g, bias_g, sd0, rng):
    """The uniform-grid log (tu, du = f, w) played slower by s; returns rows
    t, ax..gz at the same rate and the noise levels before the added noise."""
    dt = tu[1] - tu[0]
    f, w = du[:, 0:3], du[:, 3:6]
    if s == 1.0:
        return np.column_stack([tu, f, w]), sd0
    fr = Fraction(s).limit_denominator(100)
    up, down = fr.denominator, fr.numerator
    acc_in = s * s * f + (s * s - 1.0) * g * downu
    fo = resample_poly(acc_in, up, down, axis=0, padtype='line')
    wo = s * resample_poly(w, up, down, axis=0, padtype='line') + (1.0 - s) * bias_g
    n = len(fo)
    to = tu[0] + dt * np.arange(n)
    out = np.column_stack([to, fo, wo])
    still = to < tu[0] + STILL_S / s
    sd = out[still, 1:7].std(0)
    add = np.sqrt(np.maximum(sd0 ** 2 - sd ** 2, 0.0))
    out[:, 1:7] += rng.standard_normal((n, 6)) * add
    return out, sd


def speed_check(traj0, traj, s, t0):
    """Median | |v'(t)| - s |v(t0 + s (t - t0))| | over the frames where the
    expected speed exceeds 0.5 m/s: the slowed copy's replay against s times
    the walk's (the transform's end-to-end check; a mid-swing ZUPT raises it)."""
    if traj is None:
        return None
    sp0 = np.sqrt(traj0['vx'] ** 2 + traj0['vy'] ** 2 + traj0['vz'] ** 2)
    sp = np.sqrt(traj['vx'] ** 2 + traj['vy'] ** 2 + traj['vz'] ** 2)
    ref = s * np.interp(t0 + s * (traj['t'] - t0), traj0['t'], sp0)
    m = ref > 0.5
    return float(np.median(np.abs(sp[m] - ref[m]))) if m.any() else None


def swing_stats(st0, traj0, traj, s, t0):
    """Share of the original's swing frames (mapped by 1/s) with a ZUPT, the
    swings with a ZUPT in their middle 80 %, and the largest true speed at
    those ZUPTs (s times the original's speed at the mapped time)."""
    if st0 is None or traj is None:
        return None, None, None
    tt, z = traj['t'], traj['zupt'] > 0
    h = 0.5 * np.median(np.diff(tt))  # a swing runs from its first frame to the next stance's first, excluded
    sp0 = np.sqrt(traj0['vx'] ** 2 + traj0['vy'] ** 2 + traj0['vz'] ** 2)
    tot = hit_frames = hits = 0
    vmax = 0.0
    for a, b in zip(st0['swing_start_s'], st0['swing_end_s']):
        if not (np.isfinite(a) and np.isfinite(b)):
            continue
        a1, b1 = t0 + (a - t0) / s, t0 + (b - t0) / s
        m = (tt >= a1 - h) & (tt < b1 - h)
        tot += m.sum()
        hit_frames += (m & z).sum()
        mid = (tt > a1 + 0.1 * (b1 - a1)) & (tt < b1 - 0.1 * (b1 - a1)) & z
        if mid.any():
            hits += 1
        if (m & z).any():
            tau = t0 + s * (tt[m & z] - t0)
            vmax = max(vmax, s * np.interp(tau, traj0['t'], sp0).max())
    return (hit_frames / tot if tot else None), hits, vmax


def shoe_parts(d, g=9.80665, sigma_a=0.01, sigma_g=np.radians(0.1), window_s=0.025):
    """The SHOE statistic's two terms per sample (docs/navigation.md, "Stance
    detector"; Skog et al. 2010, eq. 13): 1/W sum |f_j - g u|^2 / sigma_a^2 and
    1/W sum |w_j|^2 / sigma_g^2 over the centred window of W samples (25 ms,
    odd), u the window's mean specific force direction; footnav's default
    weights and gravity. A numpy computation, not the C detector."""
    dt = np.median(np.diff(d[:, 0]))
    W = int(round(window_s / dt))
    W += W % 2 == 0
    n, h = len(d), W // 2
    ta, tg = np.full(n, np.nan), np.full(n, np.nan)
    ta[h:n - h], tg[h:n - h] = shoe_terms(d[:, 1:4], d[:, 4:7], W, g, sigma_a, sigma_g)
    return ta, tg


def explain(st0, traj0, traj, d, parts1, d1, s, t0):
    """The ZUPT runs in the middle 80 % of the original's swings (mapped by
    1/s) where the true speed (s times the original's) exceeds 0.3 m/s: their
    length, their phase in the swing, and at each run's smallest T the
    statistic's terms, |w| and ||f| - g| in the copy and at the same instant
    of the walk at s = 1 (d1, parts1)."""
    if st0 is None or traj is None:
        return None
    tt, z = traj['t'], traj['zupt'] > 0
    sp0 = np.sqrt(traj0['vx'] ** 2 + traj0['vy'] ** 2 + traj0['vz'] ** 2)
    ta, tg = shoe_parts(d)
    ta1, tg1 = parts1
    rows = []
    edges = np.flatnonzero(np.diff(np.concatenate([[0], z.astype(int), [0]])))
    for a, b in zip(edges[0::2], edges[1::2]):
        for sa, sb in zip(st0['swing_start_s'], st0['swing_end_s']):
            if not (np.isfinite(sa) and np.isfinite(sb)):
                continue
            a1, b1 = t0 + (sa - t0) / s, t0 + (sb - t0) / s
            if tt[a] > a1 + 0.1 * (b1 - a1) and tt[b - 1] < b1 - 0.1 * (b1 - a1):
                k = np.searchsorted(d[:, 0], tt[a:b])
                k = k[k < len(d)]
                i = k[np.nanargmin(ta[k] + tg[k])]
                tau = t0 + s * (d[i, 0] - t0)
                v = s * np.interp(tau, traj0['t'], sp0)
                if v > 0.3:
                    j = min(np.searchsorted(d1[:, 0], tau), len(d1) - 1)
                    rows.append((b - a, (d[i, 0] - a1) / (b1 - a1), np.log10(ta[i] + tg[i]), np.log10(ta[i]),
                                 np.log10(tg[i]), np.linalg.norm(d[i, 4:7]), abs(np.linalg.norm(d[i, 1:4]) - 9.80665),
                                 v, np.log10(ta1[j] + tg1[j]), np.log10(ta1[j]), np.log10(tg1[j]),
                                 np.linalg.norm(d1[j, 4:7]), np.linalg.norm(d1[j, 1:4])))
                break
    return np.array(rows)


def med(st, col):
    if st is None or col not in st.dtype.names:
        return None
    v = st[col][np.isfinite(st[col])]
    return float(np.median(v)) if len(v) else None


def fmt(v, f):
    return f % v if v is not None else '-'


def take_common(args, prog, factors, usage):
    """Removes the options both probes take from args: --tmp DIR, --factors
    F,F,... and --keep; returns (tmp or None, factors, keep)."""
    tmp, keep = None, False
    if '--tmp' in args:
        i = args.index('--tmp')
        if i + 1 >= len(args):
            sys.exit(usage)
        tmp = args[i + 1]
        del args[i:i + 2]
    if '--factors' in args:
        i = args.index('--factors')
        try:
            factors = [float(x) for x in args[i + 1].split(',')]
        except (IndexError, ValueError):
            sys.exit('%s: --factors takes numbers separated by commas, e.g. 1,0.85,0.7' % prog)
        del args[i:i + 2]
        # the resampler stretches by a fraction with a denominator up to 100
        if any(not 0 < x <= 1 or abs(float(Fraction(x).limit_denominator(100)) - x) > 1e-12 for x in factors):
            sys.exit('%s: a factor lies in (0, 1] and is a fraction p/q with q <= 100 (0.85, 0.7, 0.6, ...)' % prog)
    if '--keep' in args:
        keep = True
        args.remove('--keep')
    return tmp, factors, keep


def main():
    args = sys.argv[1:]
    tmp, factors, keep = take_common(args, 'probe_slow.py', [1.0, 0.85, 0.7, 0.6, 0.5], __doc__)
    extra_det = '--threshold' in args
    if extra_det:
        args.remove('--threshold')
    if any(a.startswith('-') for a in args):
        sys.exit(__doc__)
    logs = args or [os.path.join(DATA, p) for p in DEFAULT_LOGS]
    mine = tmp is None
    tmp = tmp or tempfile.mkdtemp(prefix='probe_slow_')
    os.makedirs(tmp, exist_ok=True)
    try:
        start = time.time()
        dets = [('shoe', ())] + ([('threshold', ('--detector', 'threshold'))] if extra_det else [])
        for log in logs:
            name = os.path.basename(log)
            closed = 'SensorConnectData' not in name
            base = os.path.join(tmp, name + '.csv')
            r = subprocess.run([H, 'convert', log, base], capture_output=True, text=True)
            if r.returncode:
                sys.exit('probe_slow.py: %s: convert failed: %s' % (log, r.stderr.strip()))
            d0 = load_converted(base)
            rec = {}
            for det, ex in dets:
                rec[det] = replay(base, '.rec.' + det, ex)
            rc, j0, st0, traj0, _ = rec['shoe']
            if traj0 is None or not j0:
                sys.exit('probe_slow.py: %s: the replay as recorded failed' % log)
            t0 = d0[0, 0]
            still0 = d0[:, 0] < t0 + STILL_S
            tr_still = traj0['stance'][traj0['t'] < t0 + STILL_S]
            if not tr_still.all():
                print('warning: %s: the first %.1f s is not all stance' % (name, STILL_S))
            dt = np.median(np.diff(d0[:, 0]))
            tu, du = uniform_grid(d0, t0, dt)
            downu = tilt_on_grid(tu, traj0)
            g, bias_g, sd0, fnorm0 = still_stats(d0, still0)
            print('\n%s: %.1f Hz (median interval), %d rows on the grid, still |f| %.4f m/s^2, '
                  'still noise sd acc %.4f %.4f %.4f m/s^2, gyro %.5f %.5f %.5f rad/s' %
                  (log, 1 / dt, len(tu), g, *sd0))
            # fmt: a walk of one stride (square2) has no cadence nor median
            print('as recorded: exit %d, closure 3-D %.3f m, distance %.2f m, %d strides, median cadence %s '
                  'steps/min, median stride %s m, median height change %s m' %
                  (rc, j0['return_error_3d_m'], j0['distance_m'], j0['strides'], fmt(med(st0, 'cadence_spm'), '%.1f'),
                   fmt(med(st0, 'length_m'), '%.3f'), fmt(med(st0, 'height_change_m'), '%+.4f')))
            print('\n| s | detector | cadence (steps/min) | strides (as recorded) | swing frames with ZUPT | '
                  'swings hit | v at ZUPT (m/s) | closure 3-D (m) | distance (m) | distance vs recorded | '
                  'median stride (m) | median height change (m) | still mean /f/ change (m/s^2) | speed vs s x recorded (m/s) | '
                  'exit |')
            print('| ---: | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |')
            d1 = np.column_stack([tu, du])
            parts1 = shoe_parts(d1)
            notes = []
            for s in factors:
                rng = factor_rng(s)
                out, sd = slowed(tu, du, downu, s, g, bias_g, sd0, rng)
                p = os.path.join(tmp, '%s.s%.2f.csv' % (name, s))
                np.savetxt(p, out, delimiter=',', header='t,ax,ay,az,gx,gy,gz', comments='', fmt='%.9g')
                still = out[:, 0] < t0 + STILL_S / s
                dfn = abs(np.mean(np.linalg.norm(out[still, 1:4], axis=1)) - np.mean(fnorm0))
                sd1 = out[still, 1:7].std(0)
                if s != 1.0:
                    print('<!-- s %.2f: still noise sd before adding %s, after %s (original %s) -->' %
                          (s, np.array2string(sd, precision=5), np.array2string(sd1, precision=5),
                           np.array2string(sd0, precision=5)))
                for det, ex in dets:
                    rc, j, st, traj, err = replay(p, '.' + det, ex)
                    jr = rec[det][1]
                    share, hits, vmax = swing_stats(st0, traj0, traj, s, t0)
                    if det == 'shoe' and s != 1.0:
                        ex = explain(st0, traj0, traj, out, parts1, d1, s, t0)
                        if ex is not None and len(ex):
                            m = np.median(ex, 0)
                            notes.append('s %.2f: %d ZUPT runs in mid-swing at over 0.3 m/s: %d-%d frames (median %d), '
                                         'at %.2f-%.2f of the swing; at their smallest T: log10 T %.2f (accelerometer term '
                                         '%.2f, gyro term %.2f), |w| %.2f rad/s, ||f| - g| %.2f m/s^2, true speed %.2f m/s; '
                                         'the same instants at s = 1: log10 T %.2f (%.2f, %.2f), |w| %.2f rad/s, |f| %.1f '
                                         'm/s^2 (medians)' % (s, len(ex), ex[:, 0].min(), ex[:, 0].max(), m[0],
                                                              ex[:, 1].min(), ex[:, 1].max(), *m[2:]))
                    nsw = int(np.isfinite(st0['swing_start_s']).sum())
                    dist = j.get('distance_m')
                    row = (s, det, fmt(med(st, 'cadence_spm'), '%.1f'),
                           '%s (%d)' % (j.get('strides', '-'), jr.get('strides', 0)),
                           fmt(None if share is None else 100 * share, '%.1f %%'),
                           '%s of %d' % (hits, nsw), fmt(vmax if hits else None, '%.2f'),
                           fmt(j.get('return_error_3d_m') if closed else None, '%.3f'),
                           fmt(dist, '%.2f'),
                           fmt(None if dist is None or not jr.get('distance_m') else 100 * (dist / jr['distance_m'] - 1), '%+.1f %%'),
                           fmt(med(st, 'length_m'), '%.3f'), fmt(med(st, 'height_change_m'), '%+.4f'),
                           '%.4f' % dfn, fmt(speed_check(rec[det][3], traj, s, t0), '%.3f'), rc)
                    print('| %.2f | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %d |' % row)
                    sys.stdout.flush()
                    if s == 1.0:
                        print('<!-- s 1 against the log as recorded (%s): closure %+.4f m, distance %+.4f m, '
                              'strides %+d -->' % (det, j.get('return_error_3d_m', np.nan) - jr['return_error_3d_m'],
                                                   j.get('distance_m', np.nan) - jr['distance_m'],
                                                   j.get('strides', 0) - jr['strides']))
            if notes:
                print('\nSHOE at the mid-swing ZUPTs (default settings):\n' + '\n'.join(notes))
        print('\n%.0f s' % (time.time() - start))
    finally:
        if mine and not keep:
            shutil.rmtree(tmp, ignore_errors=True)
        elif mine:
            print('files kept in %s' % tmp)


if __name__ == '__main__':
    main()
