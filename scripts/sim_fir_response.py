#!/usr/bin/python3
"""The simulator's anti-alias filter (harness/hx_sim.c, fir_design) rebuilt
in numpy from its formula, and its stop band measured (docs/simulator.md,
"Anti-alias filter"):

  /usr/bin/python3 scripts/sim_fir_response.py [M ...]

For each decimation M (default 10, the 200 Hz output of a 2 kHz internal
rate; 5 and 20 too): the largest gain from the stop band's edge (0.59 f_s)
to the internal Nyquist frequency, the gain at 0.75 f_s (150 Hz at 200 Hz)
and the largest pass-band deviation up to 0.41 f_s, in dB.

  /usr/bin/python3 scripts/sim_fir_response.py --tone RATE_HZ FREQ_HZ [...]

The amplitude gain, in %, of a tone at each FREQ_HZ through the filter of
the default oversampling at the output rate RATE_HZ (M the smallest with
M x rate >= 2 kHz, docs/simulator.md), and the frequency a tone above
rate / 2 folds to: what `harness sim --effect vibration:freq_hz=F` warns of
for a tone in the transition band (tests/cli/test_sim.sh).
"""
import sys

import numpy as np


def design(M, K=10):
    L = 2 * K * M + 1
    c = K * M
    beta = 0.1102 * (60.0 - 8.7)
    n = np.arange(L) - c
    h = np.sinc(n / M) * np.i0(beta * np.sqrt(1.0 - (n / c) ** 2)) / np.i0(beta)
    return n, h / h.sum()


def gain_db(n, h, f_over_fs, M):
    """|H| at frequencies given as fractions of the output rate f_s."""
    f = np.atleast_1d(f_over_fs) / M  # cycles per internal sample
    return 20.0 * np.log10(np.abs(np.exp(-2j * np.pi * np.outer(f, n)) @ h))


def tone(argv):
    rate = float(argv[0])
    M = int(np.ceil(2000.0 / rate - 1e-9))
    n, h = design(M)
    for a in argv[1:]:
        f = float(a)
        g = 10.0 ** (gain_db(n, h, f / rate, M)[0] / 20.0)
        fold = abs(f - rate * np.floor(f / rate + 0.5))
        print("%g Hz at %g Hz (M %d): amplitude %.3f %%%s" % (f, rate, M, 100.0 * g,
                                                               ", folded to %g Hz" % fold if f > rate / 2 else ""))


def main():
    if sys.argv[1:2] == ["--tone"]:
        tone(sys.argv[2:])
        return
    ms = [int(a) for a in sys.argv[1:]] or [10, 5, 20]
    for M in ms:
        n, h = design(M)
        stop = gain_db(n, h, np.linspace(0.59, M / 2.0, 40000), M).max()
        at075 = gain_db(n, h, 0.75, M)[0]
        pas = np.abs(gain_db(n, h, np.linspace(0.0, 0.41, 4000), M)).max()
        print("M %3d: stop band (0.59 f_s ..) at most %.1f dB, at 0.75 f_s %.1f dB, pass band (.. 0.41 f_s) "
              "within %.3f dB" % (M, stop, at075, pas))


if __name__ == "__main__":
    main()
