#!/usr/bin/python3
"""Is the white-noise density that `harness allan --profile` recovers from a
simulated static MTx log biased? (tests/cli/test_profile_chain.sh,
docs/allan.md "Corrected identification", docs/simulator.md "Round trip").

For each seed: `harness sim --motion stand --duration D --rate 200 --profile
mtx --seed S`, then `harness allan LOG --profile P --json J`, and in numpy
(double) on the samples of the log (`harness convert`):

  sd     per-sample standard deviation / (N sqrt(f_s)): what the simulator
         put in (white noise after the anti-alias filter, eq. 2; the AR(1)
         of the table's stationary sigma adds < 1e-5 of it)
  tau0   overlapping ADEV at one sample / (N sqrt(f_s))
  1s     overlapping ADEV at exactly 200 samples (tau = 1 s) / N
  prof   the profile's white density / N (the harness's ADEV at 1 s,
         log-log interpolated between its grid points, for a bound
         channel; the fit's for an identified one)

with N the table's density (paper Table V). Prints per channel the mean of
each ratio over the seeds, its standard error (sd / sqrt(seeds)) and the
t statistic of mean - 1; the spread of `prof` over the seeds; and the
spread the EDF predicts: the relative sd of an ADEV is 1 / sqrt(2 EDF), with
the EDF of white FM at m = 200 of n + 1 phase points from NIST SP 1065's
Table 5, (3 n / (2 m) - 2 (n - 1) / (n + 1)) 4 m^2 / (4 m^2 + 5), and the
harness's own at the grid point after 1 s (the JSON's `edf`, m = 224).

Usage: /usr/bin/python3 scripts/white_density_seeds.py [--harness bin/harness] [--seeds 1-20]
       [--duration 900]
"""
import argparse
import json
import math
import os
import subprocess
import tempfile

import numpy as np

FS = 200.0
NAMES = ('ax', 'ay', 'az', 'gx', 'gy', 'gz')
# paper Table V, m/s^2/sqrt(Hz) and deg/s/sqrt(Hz) -> rad/s/sqrt(Hz)
TRUE = np.array([8.9e-4, 8.4e-4, 8.4e-4] + [x * math.pi / 180.0 for x in (2.6e-2, 2.5e-2, 2.9e-2)])


def oadev(y, m):
    """Overlapping Allan deviation of the rate samples y at m samples (SP 1065 eq. 11)."""
    x = np.concatenate(([0.0], np.cumsum(y - y.mean())))
    d = x[2 * m:] - 2.0 * x[m:-m] + x[:-2 * m]
    return math.sqrt(np.mean(d * d) / (2.0 * m * m))


def profile_white(path):
    kv = {}
    for line in open(path):
        if '=' in line and not line.startswith('#'):
            k, v = line.split('=', 1)
            kv[k.strip()] = v.split()
    return np.array([float(v) for v in kv['accel_noise_mps2_rthz'] + kv['gyro_noise_rps_rthz']])


def one_seed(h, seed, duration, tmp):
    b, p, j, c = (os.path.join(tmp, n) for n in ('s.bin', 's.profile', 's.json', 's.csv'))
    subprocess.run([h, 'sim', '--motion', 'stand', '--duration', str(duration), '--rate', '200', '--profile', 'mtx',
                    '--seed', str(seed), '--out', b], check=True, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL)
    subprocess.run([h, 'allan', b, '--profile', p, '--json', j, '--quiet'], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    subprocess.run([h, 'convert', b, c], check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    data = np.loadtxt(c, delimiter=',', skiprows=1, dtype=np.float64)[:, 1:]
    # the CSV's gyro columns are rad/s (docs/log-format.md), as the profile's
    sd = data.std(axis=0, ddof=1) / (TRUE * math.sqrt(FS))
    t0 = np.array([oadev(data[:, i], 1) for i in range(6)]) / (TRUE * math.sqrt(FS))
    t1 = np.array([oadev(data[:, i], 200) for i in range(6)]) / TRUE
    prof = profile_white(p) / TRUE
    ch = {x['name']: x for x in json.load(open(j))['channels']}
    edf = []
    for n in NAMES:
        edf.append(min((r for r in ch[n]['table'] if r['tau_s'] >= 1.0), key=lambda r: r['tau_s'])['edf'])
    return sd, t0, t1, prof, np.array(edf), data.shape[0]


def edf_white_fm(n_phase, m):
    """NIST SP 1065, Table 5: overlapping Allan variance, white FM, N phase points."""
    return (3.0 * (n_phase - 1) / (2.0 * m) - 2.0 * (n_phase - 2) / n_phase) * 4.0 * m * m / (4.0 * m * m + 5.0)


def seeds_arg(s):
    out = []
    for part in s.split(','):
        if '-' in part:
            a, b = part.split('-')
            out += list(range(int(a), int(b) + 1))
        else:
            out.append(int(part))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--harness', default='bin/harness')
    ap.add_argument('--seeds', default='1-20', type=seeds_arg)
    ap.add_argument('--duration', default=900.0, type=float)
    a = ap.parse_args()
    if len(a.seeds) < 2:
        ap.error('--seeds: at least two seeds (a spread over the seeds)')
    res = {k: [] for k in ('sd', 'tau0', '1s', 'prof')}
    edfs = []
    with tempfile.TemporaryDirectory() as tmp:
        for s in a.seeds:
            sd, t0, t1, prof, edf, nsamp = one_seed(a.harness, s, a.duration, tmp)
            for k, v in zip(('sd', 'tau0', '1s', 'prof'), (sd, t0, t1, prof)):
                res[k].append(v)
            edfs.append(edf)
            print('seed %3d  prof/N %s' % (s, ' '.join('%.4f' % x for x in prof)), flush=True)
    n = len(a.seeds)
    edf = np.mean(edfs, axis=0)
    print('\n%d seeds of %g s at 200 Hz, profile mtx; ratio recovered / true: mean, standard error, t = (mean - 1) / se'
          % (n, a.duration))
    print('%-5s' % 'ratio' + ''.join('%23s' % c for c in NAMES) + '%23s' % 'all six')
    for k in ('sd', 'tau0', '1s', 'prof'):
        r = np.array(res[k])
        m, se = r.mean(axis=0), r.std(axis=0, ddof=1) / math.sqrt(n)
        allm, allse = r.mean(), r.mean(axis=1).std(ddof=1) / math.sqrt(n)
        cells = ['%.4f %.4f %+5.1f' % (x, e, (x - 1.0) / e) for x, e in zip(m, se)]
        cells.append('%.4f %.4f %+5.1f' % (allm, allse, (allm - 1.0) / allse))
        print('%-5s' % k + ''.join('%23s' % c for c in cells))
    r = np.array(res['prof'])
    print('%-5s' % 'sd' + ''.join('%23s' % ('%.4f' % x) for x in r.std(axis=0, ddof=1))
          + '   (prof: spread over the seeds)')
    e0 = edf_white_fm(nsamp + 1, 200.0)
    print('%-5s' % 'pred' + ''.join('%23s' % ('%.4f' % (1.0 / math.sqrt(2.0 * e0))) for _ in NAMES)
          + '   (1 / sqrt(2 EDF), SP 1065 EDF %.0f at m = 200)' % e0)
    print('%-5s' % 'hx' + ''.join('%23s' % ('%.4f' % (1.0 / math.sqrt(2.0 * e))) for e in edf)
          + '   (1 / sqrt(2 EDF), the JSON\'s EDF %s at the grid point after 1 s)' % ' '.join('%.0f' % e for e in edf))


if __name__ == '__main__':
    main()
