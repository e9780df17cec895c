#!/usr/bin/env python3
"""Slow gait probe on ipol_gait_xsens: the expert-annotated trials played
slower by a factor s and scored by the real `bin/harness eval` (stride
detection and gait-event timing against the experts; docs/harness.md,
"Slow walking, real walks played slower").

The transform is scripts/probe_slow.py's (imported, not copied: its
docstring has the derivation): w' = s w(st), f' = s^2 f(st) + (s^2 - 1)
C_bn g_n with the tilt from footnav's own replay of each foot's log, at the
log's 100 Hz, the turn-on gyro bias kept and white noise added back to the
first still second's level. Here:

- each foot's log (N-M_lf.txt, N-M_rf.txt) is put on the packet grid from
  packet 0 (time = PacketCounter / 100 Hz, the clock eval and the experts
  use; dropped packets interpolated linearly; before a file's first packet,
  one or two in six files, its first row), so that the two feet of a trial
  share one time origin; the copy's packet k is the original's time
  k s / 100 Hz; rows before the file's own first packet (mapped) are
  dropped, so at s = 1 the copy is the grid from the file's first packet;
- the copy is written in the ipol text format (line 1 `Acquisition
  frequency: 100 Hz`, the original's tab header, a contiguous
  PacketCounter; the magnetometer interpolated at the same instants, not
  used by footnav), with the noise seeded per factor, trial and foot;
- N-M.json's TrialBoundaries, UTurnBoundaries, LeftFootEvents and
  RightFootEvents are mapped packet p -> round(p / s) (ipol_packet(),
  halves up); the other keys are kept;
- `FNAV_DATA_DIR=DIR bin/harness eval --no-plots --no-experiments --out
  DIR/res.md` runs on a folder that holds only ipol_gait_xsens (eval takes a
  copy holding some of the sets), once per s, and once on the original
  files (symbolic links) as the reference; its ipol table and summary line
  are parsed.

Printed: per s the cadence (median and 10th-90th percentiles over the
straight strides of the expert events: two steps per interval between
successive expert foot-offs of one foot, both inside the trial and on one
side of the U-turn; steps/min of the copy), the expert strides, detected,
missed, spurious, median |FO| and |FS| error and their biases in samples of
the copy and times s (samples at the original's time scale); the s = 1
check against the originals; per trial and foot the rows that differ from
the originals'; and for every missed or spurious stride, a python matching
of `bin/harness replay COPY --strides` (the same detector and settings;
its counts are checked against eval's) with the SHOE statistic
(scripts/shoe_statistic.py's terms via probe_slow.shoe_parts) and the
adaptive threshold's floor (minimum of log10 T over the last 2 s, never
below log10 gamma - 0.4: threshold 10^(floor + 0.4) clamped to [gamma, 10
gamma]) around it.

Rounding an event to the copy's packets moves it by up to half a copy
sample (s / 2 original samples); eval's errors are whole samples.

Usage: /usr/bin/python3 scripts/probe_slow_ipol.py [--factors 1,0.9,0.8,0.7,0.6,0.5]
       [--seed N] [--param KEY=VALUE ...] [--tmp DIR] [--keep] [--stance-share]
       [--selftest]
$DATA (default ../shared/data) holds ipol_gait_xsens; trials 1-x to 3-x
(subjects 1-3) only. HARNESS=path overrides bin/harness. About 15 s for
the six factors (progress on stderr). --tmp DIR (or --keep) keeps the
copies, DIR/sS/ipol_gait_xsens/, for eval or replay by hand. --selftest
checks ipol_packet() and map_events() and exits. --seed N (N > 0) draws
another realisation of the added noise (0, the default: the documented
one), to see how much the counts owe to it. --stance-share adds, per s,
the stance shares of docs/harness.md's "Two more tries" (stance_shares()).

--param KEY=VALUE (repeatable; keys: `bin/harness replay --param help`)
is passed to every eval (the originals' and each copy's) and to the
`replay --strides` runs that explain the missed and spurious strides, to
score other detector settings on the same copies: the copies themselves do
not depend on it (the tilt comes from a replay with the defaults), so two
runs with the same --seed differ only by the settings. The explanations
follow gamma, margin_dec, floor_window_s, adapt_max_ratio and min_swing_s
(the threshold's floor and the swing length they quote) and the foot-off
paragraph event_window_s (its window in samples of the copy); the
comparison with docs/results.md (written with the defaults) then says
whether the settings move the originals' ipol figures. Without --param the
output is the same as before the option.
"""
import glob
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from fractions import Fraction

import numpy as np

import probe_slow as ps

RATE = 100.0
GAMMA = 1e5  # footnav's default SHOE threshold (docs/navigation.md, "Stance detector")
# --param KEY=VALUE given on the command line, passed to eval and replay
PARAMS = []
# the detector settings the explanations quote, defaults of `bin/harness replay --param help`; --param overrides
SET = {'gamma': GAMMA, 'margin_dec': 0.4, 'floor_window_s': 2.0, 'adapt_max_ratio': 10.0, 'min_swing_s': 0.25,
       'event_window_s': 0.3}
EVENT_KEYS = ('LeftFootEvents', 'RightFootEvents')
PAIR_KEYS = ('TrialBoundaries', 'UTurnBoundaries')


def log(msg):
    print(msg, file=sys.stderr)
    sys.stderr.flush()


def ipol_packet(p, s):
    """The copy's packet of the original's packet p (time p / 100 Hz,
    stretched by 1/s): round(p / s), halves up, exact for s a fraction
    p/q with q <= 100; a value that is not a number (NaN in the data set)
    stays as it is."""
    if not isinstance(p, (int, float)) or isinstance(p, bool) or not math.isfinite(p):
        return p
    x = Fraction(p) / Fraction(s).limit_denominator(100)
    return int(math.floor(x + Fraction(1, 2)))


def map_events(js, s):
    """A copy of an N-M.json dict with its boundaries and events mapped by
    ipol_packet(); the other keys as they are."""
    out = dict(js)
    for k in PAIR_KEYS:
        if isinstance(js.get(k), list):
            out[k] = [ipol_packet(p, s) for p in js[k]]
    for k in EVENT_KEYS:
        if isinstance(js.get(k), list):
            out[k] = [[ipol_packet(p, s) for p in ev] if isinstance(ev, list) else ev for ev in js[k]]
    return out


def selftest():
    assert ipol_packet(527, 1.0) == 527
    assert ipol_packet(0, 0.5) == 0
    assert ipol_packet(527, 0.5) == 1054
    assert ipol_packet(7, 0.7) == 10            # 10.0 exactly
    assert ipol_packet(8, 0.7) == 11            # 11.43
    assert ipol_packet(9, 0.6) == 15            # 15.0 exactly (not 14.999...)
    assert ipol_packet(3, 0.8) == 4             # 3.75
    assert ipol_packet(1, 0.4) == 3             # 2.5: halves up
    assert ipol_packet(459, 0.9) == 510         # 510.0 exactly
    assert math.isnan(ipol_packet(float('nan'), 0.5))
    js = {'Subject': 1, 'Weight': float('nan'), 'TrialBoundaries': [459, 2464], 'UTurnBoundaries': [1316, 1474],
          'LeftFootEvents': [[527, 574]], 'RightFootEvents': [[459, 507], [584, 629]]}
    m = map_events(js, 0.5)
    assert m['TrialBoundaries'] == [918, 4928] and m['UTurnBoundaries'] == [2632, 2948]
    assert m['LeftFootEvents'] == [[1054, 1148]] and m['RightFootEvents'] == [[918, 1014], [1168, 1258]]
    assert m['Subject'] == 1 and math.isnan(m['Weight']) and js['TrialBoundaries'] == [459, 2464]
    assert map_events(js, 1.0)['LeftFootEvents'] == [[527, 574]]
    # the mapped time is the original's divided by s to half a copy packet
    for s in (0.9, 0.8, 0.7, 0.6, 0.5):
        for p in range(0, 5000, 7):
            assert abs(ipol_packet(p, s) - p / s) <= 0.5 + 1e-9
    print('probe_slow_ipol.py selftest: ok')


def read_ipol(path):
    """An ipol foot log: (header line, rows: packet, acc 3, gyr 3, mag 3)."""
    with open(path) as fh:
        first = fh.readline()
        header = fh.readline()
    if not first.startswith('Acquisition frequency: 100 Hz') or not header.startswith('PacketCounter'):
        sys.exit('probe_slow_ipol.py: %s: not an ipol_gait_xsens log at 100 Hz' % path)
    d = np.loadtxt(path, skiprows=2, delimiter='\t')
    if d.ndim != 2 or d.shape[1] != 10 or np.any(np.diff(d[:, 0]) <= 0):
        sys.exit('probe_slow_ipol.py: %s: expected 10 columns and an increasing PacketCounter' % path)
    return header, d


def expert_cadence(js):
    """Steps/min of the straight strides: 2 steps per interval between
    successive expert foot-offs of one foot, both inside the trial and on
    one side of the U-turn (packets at 100 Hz)."""
    tb, ub = js['TrialBoundaries'], js.get('UTurnBoundaries') or [0, 0]
    out = []
    for k in EVENT_KEYS:
        fo = [e[0] for e in js[k] if isinstance(e, list) and tb[0] <= e[0] and e[1] <= tb[1]
              and not (e[0] < ub[1] and e[1] > ub[0])]
        for a, b in zip(fo, fo[1:]):
            if (a < ub[0]) == (b < ub[0]):
                out.append(2 * 60.0 * RATE / (b - a))
    return out


def parse_summary(sec):
    """The figures of eval's ipol summary line in the text sec, or None."""
    m = re.search(r'(\d+) trials and feet: (\d+) expert strides, (\d+) detected, (\d+) missed .*?, (\d+) spurious '
                  r'.*?; (\d+) expert swings left out.*?median \|FO error\| ([\d.]+) samples \(bias ([+-]?[\d.]+), '
                  r'90th percentile ([\d.]+)\), median \|FS error\| ([\d.]+) samples \(bias ([+-]?[\d.]+), '
                  r'90th percentile ([\d.]+)\)', sec, re.S)
    if not m:
        return None
    k = ('files', 'expert', 'detected', 'missed', 'spurious', 'both', 'fo', 'fo_bias', 'fo_p90', 'fs', 'fs_bias',
         'fs_p90')
    return {kk: float(m.group(i + 1)) for i, kk in enumerate(k)}


def param_args():
    """The --param options given on the command line, for bin/harness."""
    return [a for kv in PARAMS for a in ('--param', kv)]


def run_eval(ddir):
    """`bin/harness eval` on ddir (with the --param settings); (ipol rows {(trial, foot): (...)}, summary dict,
    exit, stderr)."""
    res = os.path.join(ddir, 'res.md')
    r = subprocess.run([ps.H, 'eval', '--no-plots', '--no-experiments', '--out', res, *param_args()],
                       env=dict(os.environ, FNAV_DATA_DIR=ddir), capture_output=True, text=True)
    rows, summ = {}, None
    try:
        md = open(res).read()
    except OSError:
        return rows, summ, r.returncode, r.stderr
    sec = md.split('## ipol_gait_xsens', 1)[-1]
    for m in re.finditer(r'^\| (\d+-\d+) \| (left|right) \| (\d+) \| (\d+) \| (\d+) \| (\d+) \| ([\d.-]+) \| ([\d.-]+) \| '
                         r'(.*?) \|$', sec, re.M):
        rows[(m.group(1), m.group(2))] = tuple(int(m.group(i)) for i in range(3, 7)) + (m.group(7), m.group(8), m.group(9))
    summ = parse_summary(sec)
    return rows, summ, r.returncode, r.stderr


def overlaps(a0, a1, b0, b1):
    return a0 < b1 and a1 > b0


def match(js, key, sw, fo, fs, last):
    """eval's ipol_match (harness/cmd_eval.c) in python, packets: the
    evaluated expert swings missed (with the reason) and the detected swings
    that are spurious."""
    tb, ub = js['TrialBoundaries'], js.get('UTurnBoundaries') or [0, 0]
    okey = EVENT_KEYS[1 - EVENT_KEYS.index(key)]
    used = [0] * len(sw)
    missed, n_exp = [], 0
    for s0, s1 in js[key]:
        outside = overlaps(s0, s1, ub[0], ub[1]) or s0 < tb[0] - 5 or s1 > tb[1] + 5
        both = any(overlaps(a, b, s0, s1) for a, b in js[okey])
        if outside or both or s1 > last:
            for k, (a, b) in enumerate(sw):
                if used[k] == 0 and overlaps(a, b, s0, s1):
                    used[k] = 2
            continue
        n_exp += 1
        hit = next((k for k, (a, b) in enumerate(sw) if used[k] != 1 and overlaps(a, b, s0, s1)), -1)
        bfo = min(fo, key=lambda x: abs(x - s0)) if fo else None
        bfs = min(fs, key=lambda x: abs(x - s1)) if fs else None
        if hit < 0 or bfo is None or bfs is None or abs(bfo - s0) >= 50 or abs(bfs - s1) >= 50:
            missed.append((s0, s1, hit, bfo, bfs))
            continue
        used[hit] = 1
    spur = [(a, b) for k, (a, b) in enumerate(sw) if used[k] == 0 and not (ub[0] <= (a + b) // 2 < ub[1])
            and tb[0] - 5 < (a + b) // 2 < tb[1] + 5]
    return n_exp, missed, spur, used


def threshold_log10(lt):
    """The adaptive threshold's log10 per sample (docs/navigation.md,
    "Adaptive threshold"), approximately: the floor is the minimum of log10
    T over the floor_window_s (2 s) before (not the 8 blocks' minima), never
    below log10 gamma - margin_dec (0.4); the threshold the floor plus
    margin_dec, clamped to [gamma, gamma adapt_max_ratio] (the --param
    settings, SET)."""
    n, w = len(lt), int(round(SET['floor_window_s'] * RATE))
    lg, mg = math.log10(SET['gamma']), SET['margin_dec']
    fl = np.array([np.nanmin(lt[max(0, i - w):i]) if i > 0 and np.isfinite(lt[max(0, i - w):i]).any() else np.nan
                   for i in range(n)])
    fl = np.maximum(np.nan_to_num(fl, nan=lg - mg), lg - mg)
    return np.clip(fl + mg, lg, lg + math.log10(SET['adapt_max_ratio']))


def runs_below(lt, thr, a, b):
    """The runs of log10 T < threshold in packets [a, b) of the copy (rows
    a.. of lt): (start, length)."""
    m = lt[a:b] < thr[a:b]
    e = np.flatnonzero(np.diff(np.concatenate([[0], m.astype(int), [0]])))
    return [(a + x, y - x) for x, y in zip(e[0::2], e[1::2])]


def replay_strides(copy_txt, kmin, tmp):
    """`bin/harness replay COPY --strides` (the detector eval runs, with the
    same settings): swings [start, end) and each row's foot-off and
    foot-strike (None where the CSV has none), in packets of the copy; None
    when the replay fails."""
    st_csv = os.path.join(tmp, 'replay.str.csv')
    r = subprocess.run([ps.H, 'replay', copy_txt, '--strides', st_csv, '--quiet', *param_args()], capture_output=True,
                       text=True)
    if r.returncode:
        log('warning: %s: replay failed: %s' % (copy_txt, r.stderr.strip()))
        return None
    st = np.atleast_1d(np.genfromtxt(st_csv, delimiter=',', names=True))
    pk = lambda v: int(round(v * RATE)) + kmin if np.isfinite(v) else None  # replay counts from the first sample
    return ([(pk(a), pk(b)) for a, b in zip(st['swing_start_s'], st['swing_end_s'])],
            [pk(x) for x in st['foot_off_s']], [pk(x) for x in st['foot_strike_s']])


def fo_window(js, key, rs):
    """Per evaluated expert swing (inside the trial, clear of the U-turn)
    with a detected swing over it: how far the expert's foot-off lies after
    the detected swing's start, and the reported foot-off's error (packets;
    the foot-off search spans event_window_s, 0.3 s, from the swing's
    start)."""
    tb, ub = js['TrialBoundaries'], js.get('UTurnBoundaries') or [0, 0]
    sw, fo, _ = rs
    out = []
    for s0, s1 in js[key]:
        if s0 < tb[0] or s1 > tb[1] or overlaps(s0, s1, ub[0], ub[1]):
            continue
        k = next((k for k, (a, b) in enumerate(sw) if overlaps(a, b, s0, s1)), None)
        if k is not None and fo[k] is not None:
            out.append((s0 - sw[k][0], fo[k] - s0))
    return out


def explain(copy_txt, js, key, kmin, tmp):
    """The missed and spurious strides of one copied foot log: replay's
    strides (the same detector) matched as eval does, each with the SHOE
    statistic's runs under the threshold around it."""
    rs = replay_strides(copy_txt, kmin, tmp)
    if rs is None:
        return ['replay failed'], -1, -1, -1, [], []
    sw = rs[0]
    fo = [x for x in rs[1] if x is not None]
    fs = [x for x in rs[2] if x is not None]
    _, d = read_ipol(copy_txt)
    dd = np.column_stack([d[:, 0] / RATE, d[:, 1:7]])
    ta, tg = ps.shoe_parts(dd)
    lt = np.log10(ta + tg)
    thr = threshold_log10(lt)
    last = int(d[-1, 0])
    n_exp, missed, spur, _ = match(js, key, sw, fo, fs, last)
    out, tags = [], []
    row = lambda p: p - kmin
    min_swing = int(round(SET['min_swing_s'] * RATE))  # min_swing_s, samples of the copy
    for s0, s1, hit, bfo, bfs in missed:
        up = [n for _, n in runs_below(-lt, -thr, row(s0), row(s1))]  # runs of T over the threshold
        dsw = [x for x in sw if overlaps(x[0], x[1], s0, s1)]
        if not dsw:
            tag = 'missed, no detected swing: T over the threshold %s min_swing_s' % (
                'shorter than' if max(up or [0]) < min_swing else 'for')
        elif abs(bfo - s0) >= 50 and bfo < s0:
            tag = 'missed, foot-off early: the detected swing began before the expert\'s foot-off'
        elif abs(bfo - s0) >= 50:
            tag = 'missed, foot-off late: only a post-strike swing over it'
        else:
            tag = 'missed, foot-strike %s' % ('early' if bfs < s1 else 'late')
        tags.append(tag)
        ends = [e for e in js[key] if isinstance(e, list)]
        where = ' (the foot\'s first expert swing in the trial)' if s0 == min(
            e[0] for e in ends if e[0] >= js['TrialBoundaries'][0] - 5) else (
            ' (the foot\'s last expert swing in the trial)' if s1 == max(
                e[1] for e in ends if e[1] <= js['TrialBoundaries'][1] + 5) else '')
        out.append('%s%s: expert swing [%d, %d]: detected swings over it %s, nearest FO %s (%+d), FS %s (%+d); '
                   'max log10 T in it %.2f, longest run over the threshold %d samples' %
                   (tag, where, s0, s1, dsw, bfo, (bfo - s0) if bfo is not None else 0, bfs,
                    (bfs - s1) if bfs is not None else 0, np.nanmax(lt[row(s0):row(s1)]), max(up or [0])))
    post = []
    for a, b in spur:
        near = [e for e in js[key] if overlaps(e[0] - 30, e[1] + 30, a, b)]
        pe = max([y for x, y in sw if y <= a] or [a])  # the detected stance before it: [pe, a]
        inside = [e for e in near if e[0] < pe < e[1]]
        if any(overlaps(a, b, m[0], m[1]) for m in missed):
            tag = 'spurious, the detected swing of a missed expert swing (events 50 samples or more off)'
        elif not near:
            tag = 'spurious, no expert swing of this foot within 30 samples'
        elif inside and b > inside[0][1]:
            tag = 'spurious, a stance from inside the expert swing, then the motion around the foot-strike over ' \
                  'min_swing_s'
            post.append((a - pe, b - a, pe - inside[0][1], (pe - inside[0][0]) / (inside[0][1] - inside[0][0])))
        elif inside:
            tag = 'spurious, split: a stance inside the expert swing'
        else:
            tag = 'spurious, other'
        tags.append(tag)
        seg = lt[row(a):row(b)]
        out.append('%s: detected swing [%d, %d] (%d samples), the stance before it [%d, %d], expert swings near it '
                   '%s; log10 T in it: max %.2f, median %.2f (threshold %.2f-%.2f)' %
                   (tag, a, b, b - a, pe, a, near, np.nanmax(seg), np.nanmedian(seg), np.nanmin(thr[row(a):row(b)]),
                    np.nanmax(thr[row(a):row(b)])))
    return out, n_exp, len(missed), len(spur), tags, post


def stance_shares(copy_txt, js, key, kmin, tmp):
    """The stance share of one copied foot log (docs/harness.md, "Two more
    tries"): each detected stance (the gap between successive swings of
    `bin/harness replay COPY --strides`) against the median of the three
    stances before it. Returned: the shares of the late-swing stances (the
    stances before the spurious strides explain() calls "a stance from
    inside the expert swing, then the motion around the foot-strike") and
    of the stances before a matched stride, and the count of late-swing
    stances with fewer than three stances before them (left out); None
    when the replay fails."""
    rs = replay_strides(copy_txt, kmin, tmp)
    if rs is None:
        return None
    sw = rs[0]
    fo = [x for x in rs[1] if x is not None]
    fs = [x for x in rs[2] if x is not None]
    _, d = read_ipol(copy_txt)
    _, missed, spur, used = match(js, key, sw, fo, fs, int(d[-1, 0]))
    late, matched, short = [], [], 0
    stance = lambda j: sw[j][0] - sw[j - 1][1]
    for k in range(1, len(sw)):
        a, b = sw[k]
        is_late = False
        if used[k] != 1 and (a, b) in spur and not any(overlaps(a, b, m[0], m[1]) for m in missed):
            pe = sw[k - 1][1]
            inside = [e for e in js[key] if overlaps(e[0] - 30, e[1] + 30, a, b) and e[0] < pe < e[1]]
            is_late = bool(inside) and b > inside[0][1]
        if k < 4:  # fewer than three stances before it (swings k-4..k-1)
            short += is_late
            continue
        share = stance(k) / float(np.median([stance(j) for j in range(k - 3, k)]))
        if used[k] == 1:
            matched.append(share)
        elif is_late:
            late.append(share)
    return late, matched, short


def trials(data):
    names = sorted(os.path.basename(p)[:-5] for p in glob.glob(os.path.join(data, 'ipol_gait_xsens', '*.json')))
    # subjects 1-3 only (4-x and 5-x are kept unseen)
    return [n for n in names if re.fullmatch(r'[123]-\d+', n)]


def main():
    args = sys.argv[1:]
    if '--selftest' in args:
        selftest()
        return
    tmp, factors, keep = ps.take_common(args, 'probe_slow_ipol.py', [1.0, 0.9, 0.8, 0.7, 0.6, 0.5], __doc__)
    shares = '--stance-share' in args
    if shares:
        args.remove('--stance-share')
    seed = 0
    if '--seed' in args:
        i = args.index('--seed')
        try:
            seed = int(args[i + 1])
        except (IndexError, ValueError):
            sys.exit('probe_slow_ipol.py: --seed takes a whole number from 0 up')
        if seed < 0:
            sys.exit('probe_slow_ipol.py: --seed takes a whole number from 0 up')
        del args[i:i + 2]
    while '--param' in args:
        i = args.index('--param')
        kv = args[i + 1] if i + 1 < len(args) else ''
        k, _, v = kv.partition('=')
        if not k or not v:
            sys.exit('probe_slow_ipol.py: --param takes KEY=VALUE (keys: bin/harness replay --param help)')
        if k in SET:
            try:
                SET[k] = float(v)
            except ValueError:
                sys.exit('probe_slow_ipol.py: --param %s: %s is not a number' % (k, v))
        PARAMS.append(kv)
        del args[i:i + 2]
    if args:
        sys.exit(__doc__)
    src = os.path.join(ps.DATA, 'ipol_gait_xsens')
    names = trials(ps.DATA)
    if not names:
        sys.exit('probe_slow_ipol.py: no trials 1-x to 3-x in %s' % src)
    mine = tmp is None
    tmp = tmp or tempfile.mkdtemp(prefix='probe_slow_ipol_')
    os.makedirs(tmp, exist_ok=True)
    start = time.time()
    try:
        # the reference: eval on the original files
        ref = os.path.join(tmp, 'orig', 'ipol_gait_xsens')
        os.makedirs(ref, exist_ok=True)
        for n in names:
            for suf in ('.json', '_lf.txt', '_rf.txt'):
                dst = os.path.join(ref, n + suf)
                if not os.path.lexists(dst):
                    os.symlink(os.path.abspath(os.path.join(src, n + suf)), dst)
        log('eval on the %d original trials' % len(names))
        rows0, summ0, rc0, err0 = run_eval(os.path.dirname(ref))
        if summ0 is None:
            sys.exit('probe_slow_ipol.py: eval on the originals gave no ipol summary (exit %d): %s' % (rc0, err0))
        # per foot: the packet grid, the tilt, the still second
        prep = {}
        for ti, n in enumerate(names):
            for fi, foot in enumerate(('lf', 'rf')):
                path = os.path.join(src, '%s_%s.txt' % (n, foot))
                header, d = read_ipol(path)
                t = d[:, 0] / RATE
                c0 = int(d[0, 0])
                trj = os.path.join(tmp, '%s_%s.traj.csv' % (n, foot))
                r = subprocess.run([ps.H, 'replay', path, '--out', trj, '--quiet'], capture_output=True, text=True)
                if r.returncode:
                    sys.exit('probe_slow_ipol.py: %s: replay failed: %s' % (path, r.stderr.strip()))
                traj0 = np.genfromtxt(trj, delimiter=',', names=True, usecols=(0, 7, 8, 16))
                still0 = t < t[0] + ps.STILL_S
                if not traj0['stance'][traj0['t'] < ps.STILL_S].all():
                    log('warning: %s_%s: the first %.1f s is not all stance' % (n, foot, ps.STILL_S))
                dg = np.column_stack([t, d[:, 1:10]])
                tu, du = ps.uniform_grid(dg, 0.0, 1.0 / RATE)  # packet 0 on: both feet share the origin
                downu = ps.tilt_on_grid(tu, traj0, t[0])  # replay's t counts from the file's first packet
                g, bias_g, sd0, _ = ps.still_stats(dg, still0)
                prep[(n, foot)] = (header, c0, tu, du, downu, g, bias_g, sd0, ti, fi, len(d))
        results = {}
        for s in factors:
            ddir = os.path.join(tmp, 's%.2f' % s)
            idir = os.path.join(ddir, 'ipol_gait_xsens')
            os.makedirs(idir, exist_ok=True)
            cad = []
            kmins = {}
            for n in names:
                with open(os.path.join(src, n + '.json')) as fh:
                    js = json.load(fh)
                mj = map_events(js, s)
                with open(os.path.join(idir, n + '.json'), 'w') as fh:
                    json.dump(mj, fh)
                cad += expert_cadence(mj)
                for foot in ('lf', 'rf'):
                    header, c0, tu, du, downu, g, bias_g, sd0, ti, fi, _ = prep[(n, foot)]
                    rng = ps.factor_rng(s, ti, fi, *([seed] if seed else []))
                    out, _ = ps.slowed(tu, du[:, 0:6], downu, s, g, bias_g, sd0, rng)
                    k = np.rint(out[:, 0] * RATE).astype(int)  # the copy's packets (tu starts at packet 0)
                    kmin = ipol_packet(c0, s) if c0 else 0
                    keep_rows = k >= kmin
                    out, k = out[keep_rows], k[keep_rows]
                    mag = np.column_stack([np.interp(k * s / RATE, tu, du[:, c]) for c in range(6, 9)])
                    kmins[(n, foot)] = kmin
                    p = os.path.join(idir, '%s_%s.txt' % (n, foot))
                    with open(p, 'w') as fh:
                        fh.write('Acquisition frequency: 100 Hz\n' + header)
                        np.savetxt(fh, np.column_stack([k.astype(float), out[:, 1:7], mag]), delimiter='\t',
                                   fmt=['%.1f'] + ['%.6f'] * 9)
            log('s %.2f: copies written (%.0f s); eval' % (s, time.time() - start))
            rows, summ, rc, err = run_eval(ddir)
            if summ is None:
                sys.exit('probe_slow_ipol.py: s %.2f: eval gave no ipol summary (exit %d): %s' % (s, rc, err))
            fw = []
            for n in names:
                with open(os.path.join(idir, n + '.json')) as fh:
                    mj = json.load(fh)
                for foot, key in (('lf', EVENT_KEYS[0]), ('rf', EVENT_KEYS[1])):
                    rs = replay_strides(os.path.join(idir, '%s_%s.txt' % (n, foot)), kmins[(n, foot)], tmp)
                    if rs is not None:
                        fw += fo_window(mj, key, rs)
            results[s] = (rows, summ, rc, np.array(cad), kmins, np.array(fw))
        # the report
        if PARAMS:
            print('Settings (eval and replay): %s' % ' '.join('--param ' + kv for kv in PARAMS))
        print('Reference, eval on the original files: %d trials and feet, %d expert strides, %d detected, %d missed, '
              '%d spurious, median |FO| %.1f (bias %+.1f), |FS| %.1f (bias %+.1f) samples (exit %d)' %
              (summ0['files'], summ0['expert'], summ0['detected'], summ0['missed'], summ0['spurious'], summ0['fo'],
               summ0['fo_bias'], summ0['fs'], summ0['fs_bias'], rc0))
        print('\n| s | cadence, steps/min (10th-90th pct) | expert strides | detected | missed | spurious | '
              'median /FO/ (bias) | median /FS/ (bias) | the same x s (original samples) | eval exit |')
        print('| ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | --- | ---: |')
        for s in factors:
            rows, m, rc, cad, _, _ = results[s]
            print('| %.2f | %.1f (%.1f-%.1f) | %d | %d | %d | %d | %.1f (%+.1f) | %.1f (%+.1f) | FO %.2f (%+.2f), '
                  'FS %.2f (%+.2f) | %d |' %
                  (s, np.median(cad), np.percentile(cad, 10), np.percentile(cad, 90), m['expert'], m['detected'],
                   m['missed'], m['spurious'], m['fo'], m['fo_bias'], m['fs'], m['fs_bias'], s * m['fo'],
                   s * m['fo_bias'], s * m['fs'], s * m['fs_bias'], rc))
        nev = int(round(SET['event_window_s'] * RATE))  # the foot-off search, samples of the copy
        print('\nThe foot-off search (the largest |f| in the %g s, %d samples, after the detected swing\'s start) per s: '
              'expert swings of the straight phases with a detected swing over them; the expert\'s foot-off after '
              'that swing\'s start, median (10th-90th percentile); the share beyond %d samples; the reported foot-off\'s '
              'median error, for those beyond and those within (samples of the copy):' % (SET['event_window_s'], nev, nev))
        for s in factors:
            fw = results[s][5]
            far = fw[:, 0] > nev
            print('s %.2f: %d swings, expert foot-off %.0f (%.0f-%.0f) samples after the swing\'s start, %.0f %% beyond '
                  '%d; foot-off error median %+.0f beyond, %+.0f within (median |error| %.1f within)' %
                  (s, len(fw), np.median(fw[:, 0]), np.percentile(fw[:, 0], 10), np.percentile(fw[:, 0], 90),
                   100 * far.mean(), nev, np.median(fw[far, 1]) if far.any() else float('nan'),
                   np.median(fw[~far, 1]), np.median(np.abs(fw[~far, 1]))))
        try:
            with open(os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'docs', 'results.md')) as fh:
                doc = parse_summary(fh.read().split('## ipol_gait_xsens', 1)[-1])
        except OSError:
            doc = None
        if doc is not None:
            print('\ndocs/results.md: %d expert strides, %d missed, %d spurious, median |FO| %.1f (bias %+.1f), |FS| %.1f '
                  '(bias %+.1f); eval on the originals now%s: %s' %
                  (doc['expert'], doc['missed'], doc['spurious'], doc['fo'], doc['fo_bias'], doc['fs'], doc['fs_bias'],
                   ' (with the --param settings)' if PARAMS else '', 'the same' if all(doc[k] == summ0[k] for k in doc) else 'DIFFERENT'))
        if 1.0 in results:
            rows, m = results[1.0][0:2]
            same = all(m[k] == summ0[k] for k in ('expert', 'detected', 'missed', 'spurious', 'fo', 'fs', 'fo_bias',
                                                   'fs_bias', 'fo_p90', 'fs_p90'))
            print('\nCheck at s = 1 (the packet grid, dropped packets interpolated) against the originals: %s' %
                  ('the same ipol summary (strides, missed, spurious, medians, biases, 90th percentiles)' if same
                   else 'DIFFERENT'))
            bad = [k for k in sorted(rows0) if rows.get(k) != rows0[k]] + [k for k in rows if k not in rows0]
            print('  per trial and foot: %s' % ('every one of the %d rows the same' % len(rows0) if not bad else
                                                '%d rows differ' % len(bad)))
            for key in bad:
                print('  %s %s: original %s, copy %s' % (key[0], key[1], rows0.get(key, ('-',))[:6],
                                                         rows.get(key, ('-',))[:6]))
        print('\nPer trial and foot, rows that differ from the originals\' (expert, detected, missed, spurious, '
              'median |FO|, |FS| in copy samples):')
        for s in factors:
            rows = results[s][0]
            diff = ['%s %s %s' % (k[0], k[1], rows.get(k, ('-',))[:6]) for k in sorted(rows0)
                    if rows.get(k, ('-',))[1:4] != rows0[k][1:4]]
            print('s %.2f: %s' % (s, '; '.join(diff) if diff else 'detected, missed and spurious as the originals\''))
        print('\nMissed and spurious strides (replay --strides of the copy matched as eval does; SHOE statistic in '
              'numpy; packets of the copy):')
        any_bad = False
        tally, posts = {}, {}
        for s in factors:
            rows, _, _, _, kmins, _ = results[s]
            for key in sorted(rows):
                if rows[key][2] == 0 and rows[key][3] == 0:
                    continue
                any_bad = True
                n, side = key
                foot = 'lf' if side == 'left' else 'rf'
                with open(os.path.join(tmp, 's%.2f' % s, 'ipol_gait_xsens', n + '.json')) as fh:
                    mj = json.load(fh)
                lines, n_exp, nm, nsp, tg, pst = explain(os.path.join(tmp, 's%.2f' % s, 'ipol_gait_xsens',
                                                             '%s_%s.txt' % (n, foot)), mj,
                                                'LeftFootEvents' if side == 'left' else 'RightFootEvents',
                                                kmins[(n, foot)], tmp)
                agree = (n_exp, nm, nsp) == (rows[key][0], rows[key][2], rows[key][3])
                print('s %.2f, %s %s (eval: %d expert, %d missed, %d spurious; replay matched: %d, %d, %d%s):' %
                      (s, n, side, rows[key][0], rows[key][2], rows[key][3], n_exp, nm, nsp,
                       '' if agree else ' -- DIFFERENT'))
                for ln in lines:
                    print('  ' + ln)
                posts.setdefault(s, []).extend(pst)
                for t in tg:
                    tally.setdefault(t, {})
                    tally[t][s] = tally[t].get(s, 0) + 1
        if not any_bad:
            print('none')
        else:
            print('\nThe same by mechanism (count per s):\n\n| mechanism | %s |\n| --- |%s' %
                  (' | '.join('s = %.2f' % s for s in factors), ' ---: |' * len(factors)))
            for t in sorted(tally):
                print('| %s | %s |' % (t, ' | '.join(str(tally[t].get(s, 0)) for s in factors)))
            print('\nThe stance-then-motion ones: the stance\'s length, the motion\'s length (the spurious swing), the '
                  'stance\'s start against the expert\'s foot-strike, and its phase in the expert swing (0 = foot-off, '
                  '1 = foot-strike); median (range), samples of the copy:')
            for s in factors:
                v = np.array(posts.get(s, []))
                if len(v):
                    print('s %.2f (%d): stance %.0f (%d-%d), motion %.0f (%d-%d), stance start %+.0f (%+d to %+d), '
                          'phase %.2f (%.2f-%.2f)' % (s, len(v), np.median(v[:, 0]), v[:, 0].min(), v[:, 0].max(),
                                                      np.median(v[:, 1]), v[:, 1].min(), v[:, 1].max(),
                                                      np.median(v[:, 2]), v[:, 2].min(), v[:, 2].max(),
                                                      np.median(v[:, 3]), v[:, 3].min(), v[:, 3].max()))
        if shares:
            print('\nStance share (each detected stance against the median of the three stances before it; '
                  'replay --strides of every copy): the late-swing stances (before the "a stance from inside the '
                  'expert swing" strides) and the stances before a matched stride:')
            for s in factors:
                kmins, late, matched, short = results[s][4], [], [], 0
                for n in names:
                    with open(os.path.join(tmp, 's%.2f' % s, 'ipol_gait_xsens', n + '.json')) as fh:
                        mj = json.load(fh)
                    for foot, key in (('lf', EVENT_KEYS[0]), ('rf', EVENT_KEYS[1])):
                        r = stance_shares(os.path.join(tmp, 's%.2f' % s, 'ipol_gait_xsens', '%s_%s.txt' % (n, foot)),
                                          mj, key, kmins[(n, foot)], tmp)
                        if r is not None:
                            late += r[0]
                            matched += r[1]
                            short += r[2]
                print('s %.2f: late-swing stances %d, share up to %s (%d more with fewer than three stances before '
                      'them); before a matched stride %d, share down to %s' %
                      (s, len(late), '%.2f' % max(late) if late else '-', short, len(matched),
                       '%.2f' % min(matched) if matched else '-'))
        print('\n%.0f s' % (time.time() - start))
    finally:
        if mine and not keep:
            shutil.rmtree(tmp, ignore_errors=True)
        else:
            print('files kept in %s' % tmp)


if __name__ == '__main__':
    main()
