#!/usr/bin/python3
"""Where a lost stretch of samples is better integrated as one interval than
skipped as a time jump: the default of fnav_nav_config_t.max_gap_s.

Simulates a 60 s loop walk at 400 Hz (bin/harness sim, noise of the default
profile), removes a stretch of G seconds at 12 random places (uniform in
12-55 s, so mostly in motion, seed 3), replays each with --param max_gap_s
0.5 (the default until 2026-11-30) and 0.05 (every such stretch a time jump),
and prints the RMS and worst distance between the run's end and the end
of the replay without the gap. An interval up to max_gap_s is integrated
with one sample's rates over its whole length; above it, it is a time jump
propagated over one nominal interval (docs/navigation.md, "Timing").

usage: /usr/bin/python3 scripts/max_gap_sweep.py [--harness bin/harness]
"""
import argparse
import csv
import os
import subprocess
import tempfile

import numpy as np


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    ap.add_argument('--harness', default='bin/harness')
    a = ap.parse_args()
    h = os.path.abspath(a.harness)
    with tempfile.TemporaryDirectory() as d:
        w, g, tr = (os.path.join(d, n) for n in ('w.csv', 'g.csv', 'tr.csv'))
        subprocess.run([h, 'sim', '--motion', 'loop', '--duration', '60', '--rate', '400', '--out', w],
                       check=True, capture_output=True)

        def end(fn, max_gap):
            subprocess.run([h, 'replay', fn, '--quiet', '--param', 'max_gap_s=%g' % max_gap, '--out', tr],
                           check=True, capture_output=True)
            with open(tr, newline='') as f:
                rows = list(csv.reader(f))
            return np.array([float(rows[-1][rows[0].index(k)]) for k in ('x', 'y', 'z')])

        with open(w, newline='') as f:
            rows = list(csv.reader(f))
        t = np.array([float(r[0]) for r in rows[1:]])
        ref = end(w, 0.5)
        starts = np.random.default_rng(3).uniform(12.0, 55.0, 12)
        print('lost (s)  integrated (max_gap_s 0.5): rms / worst (m)  time jump (max_gap_s 0.05): rms / worst (m)')
        for gap in (0.1, 0.15, 0.2, 0.25, 0.3, 0.4):
            err = {0.5: [], 0.05: []}
            for t0 in starts:
                keep = [rows[0]] + [r for r, tt in zip(rows[1:], t) if not t0 <= tt < t0 + gap]
                with open(g, 'w', newline='') as f:
                    csv.writer(f).writerows(keep)
                for mg in err:
                    err[mg].append(float(np.linalg.norm(end(g, mg) - ref)))
            print('%8.2f  %20.2f / %5.2f  %27.2f / %5.2f' % (gap, np.sqrt(np.mean(np.square(err[0.5]))),
                  max(err[0.5]), np.sqrt(np.mean(np.square(err[0.05]))), max(err[0.05])), flush=True)


if __name__ == '__main__':
    main()
