#!/usr/bin/env python3
"""A static log of white noise only (docs/simgap.md, "Limitations"): the
input on which any effect `harness simgap` names is a false alarm.

300 s at 100 Hz, accelerometers 1e-3 m/s^2/sqrt(Hz) around (0, 0, g),
gyros 1e-4 rad/s/sqrt(Hz) around 0; numpy's default generator seeded with
1000 + SEED.

Usage: /usr/bin/python3 scripts/white_log.py SEED OUT.csv
       bin/harness simgap OUT.csv --static --seeds 16 --seed SEED
"""
import sys

import numpy as np


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    seed, out = int(sys.argv[1]), sys.argv[2]
    fs, n = 100.0, 30001
    rng = np.random.default_rng(1000 + seed)
    t = np.arange(n) / fs
    dens = np.array([1e-3, 1e-3, 1e-3, 1e-4, 1e-4, 1e-4])
    x = np.array([0.0, 0.0, 9.80665, 0.0, 0.0, 0.0]) + rng.standard_normal((n, 6)) * dens * np.sqrt(fs)
    np.savetxt(out, np.column_stack([t, x]), fmt=['%.4f'] + ['%.9g'] * 6, delimiter=',',
               header='t,ax,ay,az,gx,gy,gz', comments='')


if __name__ == '__main__':
    main()
