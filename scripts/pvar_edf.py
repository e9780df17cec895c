#!/usr/bin/python3
"""Reference values for the EDF of the parabolic variance (fnav_allan_edf_pvar()).

An independent double-precision computation from the definitions, for the
golden values of tests/test_allan.c and the figures in docs/allan.md
("Parabolic deviation"). It shares no code with src/fnav_allan.c:

- the filter is built tap by tap from its definition (PVAR: taps
  (m - 1)/2 - k and their negatives, k < m; the overlapping Allan variance:
  1, -2, 1 at lags 0, m, 2m). Its output autocovariance R(j) is the taps'
  autocorrelation summed against the phase's generalized autocovariance,
  the power law's sw(t) (Greenhall & Riley 2003, eq. 8) differenced twice
  over one sample (the sample-averaged phase). The EDF is Greenhall &
  Riley's basic sum (their eq. 10) to J = min(M, 3m) lags, always at the
  full m (no scaling above m = 64, as the C code does);
- `--greenhall` prints the same computation for the overlapping Allan
  filter, which must reproduce Greenhall & Riley's own algorithm
  (fnav_allan_edf_var(alpha, 2, 0, m, n, 1)) wherever that sums exactly;
- `--greenhall-table` the same exact computation for flicker phase noise
  (alpha = 1) at points where Greenhall & Riley's algorithm uses its
  approximation (J > 100 lags, r = M/m > 3: 1/edf = (a0 - a1/r) / (b^2 r),
  b = b0 + b1 ln m, their case 3), which it must approach within a few %;
  and at points of a short record (J > 100 lags, r <= 3), where the
  algorithm takes the basic sum to 100 lags with m scaled to 100 / r;
- `--greenhall-fm-table` the same for the table of their case 2 (large m,
  1/edf = (a0 - a1/r) / r) at r = M/m just above d + 1, where a1 matters
  most: flicker FM with the Allan filter (d = 2), white FM with the
  overlapping Hadamard filter (1, -3, 3, -1 at lags 0, m, 2m, 3m; d = 3,
  4m lags);
- `--greenhall-mod-table` the same for their table 1 (modified, case 1,
  1/edf = (a0 - a1/r) / r) with the modified Allan filter (the Allan taps
  convolved with m ones) at r just above 3;
- `--mc R` checks the model against simulation: R records of white phase,
  white FM and random-walk FM noise, the PVAR of each, and the EDF
  2 mean^2 / var of the R estimates (relative standard error about
  sqrt(2.4 / R) for these EDFs).

`--terms DATA_DIR` compares PDEV of the NBS14 1000-point set with n - 2m and
with n - 2m + 1 terms against SigmaTheta's values (allan_reference/nbs14).

`--nbs14-10` prints PDEV of NIST's 10-point set at m = 2 from the definition
(no published value; at m = 1 PDEV is the overlapping ADEV, 91.22945).

Usage: /usr/bin/python3 scripts/pvar_edf.py [--greenhall] [--greenhall-table] [--greenhall-fm-table] [--greenhall-mod-table] [--mc R] [--nbs14-10] [--terms DATA_DIR]
"""
import math
import os
import sys

import numpy as np

# NIST's 10-point NBS14 fractional frequencies (SP 1065 p. 107)
NBS14_10 = [892.0, 809.0, 823.0, 798.0, 671.0, 644.0, 883.0, 903.0, 677.0]


def phase(y):
    """The phase record x_0 = 0, x_k = y_0 + .. + y_{k-1} of frequencies y."""
    return np.concatenate([[0.0], np.cumsum(y)])


def nbs14_1000_phase(data_dir):
    """The NBS14 1000-point set (allan_reference/nbs14 under data_dir) as its phase record."""
    return phase(np.loadtxt(os.path.join(data_dir, "allan_reference", "nbs14", "nbs14_1000pt_frequency.txt")))


def sw(t, alpha):
    at = abs(t)
    if alpha == 2:
        return -at
    if alpha == 1:
        return t * t * math.log(at) if at > 0 else 0.0
    if alpha == 0:
        return at ** 3
    if alpha == -1:
        return t ** 4 * math.log(at) if at > 0 else 0.0
    if alpha == -2:
        return at ** 5
    raise ValueError(alpha)


def gacv(t, alpha):
    """Generalized autocovariance of the phase averaged over one sample."""
    return 2.0 * sw(t, alpha) - sw(t - 1.0, alpha) - sw(t + 1.0, alpha)


def pvar_taps(m):
    c = (m - 1) / 2.0 - np.arange(m)
    return np.concatenate([c, -c])


def hvar_taps(m):
    w = np.zeros(3 * m + 1)
    w[0], w[m], w[2 * m], w[3 * m] = 1.0, -3.0, 3.0, -1.0
    return w


def mvar_taps(m):
    """The modified Allan filter: m second differences of lag m summed (3m taps)."""
    return np.convolve(avar_taps(m), np.ones(m))


def avar_taps(m):
    w = np.zeros(2 * m + 1)
    w[0], w[m], w[2 * m] = 1.0, -2.0, 1.0
    return w


def edf(taps, m, M, alpha, lags=3):
    L = len(taps)
    J = int(min(M, lags * m))
    q = np.correlate(taps, taps, "full")  # lags -(L - 1) .. L - 1
    t0 = -(L - 1)
    g = np.array([gacv(float(t), alpha) for t in range(t0, J + L)])  # gacv at t0 ..

    def r(j):  # sum over lags tau of q(tau) gacv(j + tau)
        return float(np.dot(q, g[j: j + 2 * L - 1]))

    r0 = r(0)
    s = r0 * r0 + (1.0 - J / M) * r(J) ** 2 + 2.0 * sum((1.0 - j / M) * r(j) ** 2 for j in range(1, J))
    return M * r0 * r0 / s


# (m, n_phase) points: exact range, the scaled range's two branches (m > 64
# with few lags, and with many), and the NBS14 1000-point octaves
POINTS = [(2, 40), (4, 60), (8, 50), (16, 200), (64, 1001), (100, 260), (128, 1001), (256, 1001)]


def simulate(alpha, n, rng):
    e = rng.standard_normal(n)
    if alpha == 2:
        return e
    if alpha == 0:
        return np.cumsum(e)
    return np.cumsum(np.cumsum(e))  # alpha = -2


def pvar_record(x, m, terms=None):
    """PVAR from the definition with `terms` terms (default n - 2m; the record allows n - 2m + 1)."""
    n = len(x)
    c = (m - 1) / 2.0 - np.arange(m)
    u = x[: n - m] - x[m:]
    z = np.convolve(u, c[::-1], "valid")[: n - 2 * m if terms is None else terms]
    return 72.0 * np.mean(z * z) / m ** 6


def main():
    args = sys.argv[1:]
    if "--greenhall" in args:
        print("overlapping Allan filter (compare fnav_allan_edf_var(alpha, 2, 0, m, n, 1)):")
        for alpha in (2, 1, 0, -1, -2):
            print(" ".join("%d/%d: %.10g" % (m, n, edf(avar_taps(m), m, n - 2 * m, alpha))
                           for m, n in POINTS[:4]), " alpha", alpha)
    if "--greenhall-table" in args:
        print("overlapping Allan filter, alpha 1, exact sum (compare fnav_allan_edf_var(1, 2, 0, m, n, 1)):")
        print(" ".join("%d/%d: %.10g" % (m, n, edf(avar_taps(m), m, n - 2 * m, 1))
                       for m, n in ((40, 1001), (64, 3001), (128, 4001))))
        print("the same where J > 100 and r = M/m <= 3 (the scaled basic sum):")
        print(" ".join("%d/%d: %.10g" % (m, n, edf(avar_taps(m), m, n - 2 * m, 1))
                       for m, n in ((64, 278), (128, 556), (40, 200), (100, 450))))
    if "--greenhall-fm-table" in args:
        # r = M/m just above d + 1, where a1/r matters most
        print("overlapping Allan filter, alpha -1, exact sum (compare fnav_allan_edf_var(-1, 2, 0, m, n, 1)):")
        print(" ".join("%d/%d: %.10g" % (m, n, edf(avar_taps(m), m, n - 2 * m, -1))
                       for m, n in ((40, 206), (64, 332), (128, 648), (40, 600))))
        print("overlapping Hadamard filter, alpha 0, exact sum to 4m lags (compare fnav_allan_edf_var(0, 3, 0, m, n, 1)):")
        print(" ".join("%d/%d: %.10g" % (m, n, edf(hvar_taps(m), m, n - 3 * m, 0, 4))
                       for m, n in ((40, 330), (64, 527), (128, 1050))))
    if "--greenhall-mod-table" in args:
        print("modified Allan filter, exact sum (compare fnav_allan_edf_var(alpha, 2, 1, m, n, 1)):")
        for alpha in (2, 0, -2):
            print(" ".join("%d/%d: %.10g" % (m, n, edf(mvar_taps(m), m, n - 3 * m + 1, alpha))
                           for m, n in ((40, 250), (64, 400), (128, 800))), " alpha", alpha)
    if "--mc" in args:
        reps = int(args[args.index("--mc") + 1])
        rng = np.random.default_rng(1)
        print("simulation, %d records each: alpha m n  EDF(simulated)  EDF(model)" % reps)
        for alpha in (2, 0, -2):
            for m, n in ((4, 64), (16, 256), (16, 100)):
                v = np.array([pvar_record(simulate(alpha, n, rng), m) for _ in range(reps)])
                print("%+d %3d %4d  %7.2f  %7.2f" % (alpha, m, n, 2.0 * v.mean() ** 2 / v.var(),
                                                     edf(pvar_taps(m), m, n - 2 * m, alpha)))
    if "--nbs14-10" in args:
        x = phase(NBS14_10)
        print("NBS14 10-point PDEV at m = 2: %.10g" % math.sqrt(pvar_record(x, 2)))
    if "--terms" in args:
        d = args[args.index("--terms") + 1] + "/allan_reference/nbs14/"
        x = nbs14_1000_phase(args[args.index("--terms") + 1])
        n = len(x)
        print("m  PDEV/SigmaTheta - 1 with n - 2m terms, with n - 2m + 1")
        rows = [l.split(",") for l in open(d + "nbs14_1000pt_pdev_expected.csv") if l[:1].isdigit()]
        for m, want in ((float(a), float(b)) for a, b in rows):
            m = int(m)
            if m == 1:
                continue
            dev = [math.sqrt(pvar_record(x, m, k)) for k in (n - 2 * m, n - 2 * m + 1)]
            print("%3d  %+.1e  %+.1e" % (m, dev[0] / want - 1.0, dev[1] / want - 1.0))
    if any(a in args for a in ("--greenhall", "--greenhall-table", "--greenhall-fm-table", "--greenhall-mod-table", "--mc", "--nbs14-10", "--terms")):
        return
    print("/* scripts/pvar_edf.py: PVAR EDF, rows alpha = 2 .. -2, columns (m, n_phase) =")
    print(" * " + ", ".join("(%d, %d)" % p for p in POINTS) + " */")
    for alpha in (2, 1, 0, -1, -2):
        vals = [edf(pvar_taps(m), m, n - 2 * m, alpha) for m, n in POINTS]
        print("{ " + ", ".join("%.10g" % v for v in vals) + " },")


if __name__ == "__main__":
    main()
