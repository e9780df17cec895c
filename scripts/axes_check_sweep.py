#!/usr/bin/python3
"""How well the replay's axes check (docs/harness.md, "Axes check") works.

Two parts, both through bin/harness replay --json (the check's own code):

1. Every walk of the shared data as recorded: the recorded gyro map should be
   the best of the 48, and no walk flagged. Prints, per walk, the swings
   judged, the median end speed of the recorded map and of its nearest rival,
   and their ratio (how clearly the walk tells the right map).
2. --corrupt: for each walk named (paths relative to the data directory),
   every one of the 47 wrong maps applied to the recorded gyro; counts the
   cases flagged, and among them those whose suggested fix undoes the map.

Usage: /usr/bin/python3 scripts/axes_check_sweep.py [--data DIR] [--harness BIN]
       [--corrupt WALK...]

The run in docs/harness.md ("Axes check"): without options, then with
  --corrupt xio_ngimu_gait/short_walk.csv xio_ngimu_gait/long_walk.csv
  openshoe_gx2/Measurement_100521_2_data_inert.txt
  openshoe_gx2/Measurement_100521_31_data_inert.txt
  pyshoe_vicon_llio/own_3dmgx5_footprints/SensorConnectData_31_imu.csv
  pyshoe_vicon_llio/own_3dmgx5_footprints/SensorConnectData_35_imu.csv
  pyshoe_vicon_llio/vicon_3dmgx3/2017-11-22-11-28-39_imu.csv
  ipol_gait_xsens/1-1_lf.txt ipol_gait_xsens/1-5_lf.txt
  openshoe_c_820hz/OpenShoeDataSet.txt
"""
import argparse
import glob
import json
import os
import subprocess
import sys
import tempfile

import numpy as np

PERM = [(0, 1, 2), (0, 2, 1), (1, 0, 2), (1, 2, 0), (2, 0, 1), (2, 1, 0)]


def map_matrix(k):
    """Map k of harness/hx_axes.c: out_i = s_i w_p(i), s_i = -1 when bit i of k is set."""
    p, m = PERM[k // 8], np.zeros((3, 3))
    for i in range(3):
        m[i, p[i]] = -1.0 if (k >> i) & 1 else 1.0
    return m


def map_name(k):
    p = PERM[k // 8]
    return '(' + ', '.join(('-' if (k >> i) & 1 else '') + 'g' + 'xyz'[p[i]] for i in range(3)) + ')'


def replay_axes(harness, log, tmp):
    out = os.path.join(tmp, 'r.json')
    if os.path.exists(out):
        os.remove(out)
    subprocess.run([harness, 'replay', log, '--json', out, '--quiet'], capture_output=True)
    if not os.path.exists(out):
        return None
    return json.load(open(out))['axes']


def real_walks(data):
    pats = ['openshoe_gx2/*_data_inert.txt', 'xio_ngimu_gait/*.csv', 'pyshoe_vicon_llio/*/*_imu.csv',
            'ipol_gait_xsens/*_?f.txt', 'openshoe_c_820hz/*.txt', 'openshoe_square2/*.csv']
    skip = ('license', 'source', 'readme')
    return [w for p in pats for w in sorted(glob.glob(os.path.join(data, p)))
            if not os.path.basename(w).lower().startswith(skip)]


def part_real(harness, data, tmp):
    checked = best = flagged = 0
    ratios, scaled = [], []
    print('%-44s %6s %9s %9s %6s %s' % ('walk', 'swings', 'recorded', 'rival', 'ratio', 'verdict'))
    for w in real_walks(data):
        a = replay_axes(harness, w, tmp)
        name = os.path.relpath(w, data)
        if a is None or a['problem'] is None:
            print('%-44s %6s %9s %9s %6s %s' % (name, a['swings'] if a else '-', '-', '-', '-',
                                                a['message'] if a else 'replay failed'))
            continue
        checked += 1
        best += a['best_map'] == '(gx, gy, gz)'
        flagged += a['problem'] or bool(a.get('time_problem'))
        ratios.append(a['v_other_mps'] / a['v_recorded_mps'])
        scaled.append(a['v_scaled_mps'] / a['v_recorded_mps'])
        print('%-44s %6d %9.3f %9.3f %6.3f %s' % (name, a['swings'], a['v_recorded_mps'], a['v_other_mps'],
                                                  ratios[-1], 'FLAGGED ' + a['best_map'] if a['problem']
                                                  else 'TIME x%g' % a['time_scale'] if a.get('time_problem')
                                                  else 'agree'))
    print('\n%d walks checked: the recorded map is the best on %d, flagged on %d; nearest rival %.3f-%.3f times '
          'the recorded map\'s end speed (median %.3f)' % (checked, best, flagged, min(ratios), max(ratios),
                                                           float(np.median(ratios))))
    print('time scales (x0.5, x0.8, x1.25, x2 of the intervals): the best ends %.3f-%.3f times the recorded '
          'time\'s end speed (median %.3f; flagged at 1/1.5 = 0.667 or less)'
          % (min(scaled), max(scaled), float(np.median(scaled))))
    return flagged


def part_corrupt(harness, data, walks, tmp):
    total = flagged = right = 0
    for w in walks:
        src = os.path.join(data, w)
        csv = os.path.join(tmp, 'c.csv')
        subprocess.run([harness, 'convert', src, csv, '--to', 'csv'], check=True, capture_output=True)
        d = np.genfromtxt(csv, delimiter=',', names=True)
        g = np.stack([d['gx'], d['gy'], d['gz']], 1)
        missed = []
        for k in range(1, 48):
            kcsv = os.path.join(tmp, 'k.csv')
            np.savetxt(kcsv, np.column_stack([d['t'], d['ax'], d['ay'], d['az'], g @ map_matrix(k).T]),
                       delimiter=',', header='t,ax,ay,az,gx,gy,gz', comments='', fmt=['%.9f'] + ['%.9g'] * 6)
            a = replay_axes(harness, kcsv, tmp)
            inv = [j for j in range(48) if np.allclose(map_matrix(j), map_matrix(k).T)][0]
            total += 1
            if a is not None and a['problem']:
                flagged += 1
                if a['best_map'] == map_name(inv):
                    right += 1
                else:
                    missed.append('%s: fix %s, suggested %s' % (map_name(k), map_name(inv), a['best_map']))
            else:
                why = ('%.2f vs %.2f m/s' % (a['v_recorded_mps'], a['v_best_mps'])
                       if a is not None and a['v_recorded_mps'] is not None else (a['message'] if a else 'failed'))
                missed.append('%s: not flagged (%s)' % (map_name(k), why))
        print('%s: %d of 47 flagged%s' % (w, 47 - sum('not flagged' in m for m in missed),
                                           ''.join('\n    ' + m for m in missed)), flush=True)
    print('\n%d wrong maps on %d walks: %d flagged, %d of them with the right fix' % (total, len(walks), flagged, right))
    return flagged - right


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    here = os.path.dirname(os.path.abspath(__file__))
    ap.add_argument('--data', default=os.path.join(here, '..', '..', 'shared', 'data'))
    ap.add_argument('--harness', default=os.path.join(here, '..', 'bin', 'harness'))
    ap.add_argument('--corrupt', nargs='+', metavar='WALK')
    a = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        if a.corrupt:
            return 1 if part_corrupt(a.harness, a.data, a.corrupt, tmp) else 0
        return 1 if part_real(a.harness, a.data, tmp) else 0


if __name__ == '__main__':
    sys.exit(main())
