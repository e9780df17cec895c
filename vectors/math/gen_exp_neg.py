#!/usr/bin/python3
"""Golden vector for fnav_exp_neg (include/footnav/fnav_math.h), float build.

fnav_exp_neg(x) = exp(-x) from additions, multiplications and comparisons
only, so that the filter's decay factors are the same bits on every
IEEE-754 target. This script runs the same algorithm in numpy float32
arithmetic, operation by operation (an independent implementation of the
documented steps: halve x to at most 1/16 counting k, the degree-6 Taylor
polynomial of exp(-y) in Horner form, square k times), and writes the bit
patterns of its results; tests/test_math.c requires the C function to give
exactly those bits. It also checks the accuracy claimed in the header
against exp in float64 on these inputs: relative error at most 1.1e-6 for
x <= 1, 3.4e-5 for x <= 20 and 1.4e-4 up to 80. Those bounds are the
maxima over every float32 in [1e-7, 80]: --exhaustive computes them
(vectorised, about a minute).

x: 0, a log-spaced grid from 1e-7 to 90, and the filter's decay arguments
dt/tau at 100-1000 Hz for tau from 0.03 s (the landing settling) to 1000 s.

--check regenerates and compares with the committed file (bit-exact).
Run: /usr/bin/python3 vectors/math/gen_exp_neg.py [--check | --exhaustive]
"""
import os
import sys

import numpy as np

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "exp_neg.csv")
F = np.float32


def exp_neg(x):
    x = F(x)
    if not (x > F(0.0)):
        return F(1.0)
    if x > F(100.0):
        return F(0.0)
    y, k = x, 0
    while y > F(0.0625):
        y = F(y * F(0.5))
        k += 1
    c6 = F(1.0) / F(720.0)
    c5 = F(1.0) / F(120.0)
    c4 = F(1.0) / F(24.0)
    c3 = F(1.0) / F(6.0)
    t = F(c5 - F(y * c6))
    t = F(c4 - F(y * t))
    t = F(c3 - F(y * t))
    t = F(F(0.5) - F(y * t))
    t = F(F(1.0) - F(y * t))
    p = F(F(1.0) - F(y * t))
    for _ in range(k):
        p = F(p * p)
    return p


def inputs():
    xs = [F(0.0)]
    xs += [F(v) for v in np.logspace(-7, np.log10(90.0), 400)]
    for rate in (100.0, 200.0, 250.0, 400.0, 820.0, 1000.0):
        for tau in (0.03, 0.05, 5.0, 10.0, 50.0, 100.0, 1000.0):
            xs.append(F(F(1.0) / F(rate)) / F(tau))
    return xs


def bits(v):
    return "0x%08x" % int(np.array(v, dtype=np.float32).view(np.uint32))


def rows():
    out = []
    worst = {1.0: 0.0, 20.0: 0.0, 80.0: 0.0}
    for x in inputs():
        r = exp_neg(x)
        ref = np.exp(-np.float64(x))
        rel = abs(np.float64(r) - ref) / ref if ref > 0 else 0.0
        for lim in worst:
            if float(x) <= lim:
                worst[lim] = max(worst[lim], rel)
                break
        out.append("%s,%s,%.9g,%.17g" % (bits(x), bits(r), float(x), float(r)))
    if worst[1.0] > 1.1e-6 or worst[20.0] > 3.4e-5 or worst[80.0] > 1.4e-4:
        sys.exit("gen_exp_neg: accuracy claim broken: %r" % worst)
    print("gen_exp_neg: worst relative error x <= 1: %.3g, <= 20: %.3g, <= 80: %.3g" % (worst[1.0], worst[20.0],
                                                                                      worst[80.0]))
    return out


def exp_neg_vec(x):
    """The same algorithm on a float32 array of x in (0, 100]."""
    k = np.zeros(x.shape, dtype=np.int32)
    y = x.copy()
    while True:
        m = y > F(0.0625)
        if not m.any():
            break
        y[m] = y[m] * F(0.5)
        k[m] += 1
    t = F(F(1.0) / F(120.0)) - y * F(F(1.0) / F(720.0))
    t = F(F(1.0) / F(24.0)) - y * t
    t = F(F(1.0) / F(6.0)) - y * t
    t = F(0.5) - y * t
    t = F(1.0) - y * t
    p = F(1.0) - y * t
    for i in range(int(k.max())):
        m = k > i
        p[m] = p[m] * p[m]
    return p


def exhaustive():
    lo = int(np.array(1e-7, dtype=np.float32).view(np.uint32))
    hi = int(np.array(80.0, dtype=np.float32).view(np.uint32))
    worst = {1.0: (0.0, 0.0), 20.0: (0.0, 0.0), 80.0: (0.0, 0.0)}
    step = 1 << 22
    for a in range(lo, hi + 1, step):
        x = np.arange(a, min(a + step, hi + 1), dtype=np.uint32).view(np.float32)
        rel = np.abs(exp_neg_vec(x).astype(np.float64) - np.exp(-x.astype(np.float64))) / np.exp(-x.astype(np.float64))
        for lim, lower in ((1.0, 0.0), (20.0, 1.0), (80.0, 20.0)):
            m = (x > F(lower)) & (x <= F(lim))
            if m.any():
                i = int(np.argmax(np.where(m, rel, -1.0)))
                if rel[i] > worst[lim][0]:
                    worst[lim] = (float(rel[i]), float(x[i]))
    for lim, (w, xw) in worst.items():
        print("every float32 in [1e-7, 80] with x <= %g: worst relative error %.3g (x = %.9g)" % (lim, w, xw))


def main():
    if "--exhaustive" in sys.argv[1:]:
        exhaustive()
        return
    text = "x_bits,result_bits,x,result\n" + "\n".join(rows()) + "\n"
    if "--check" in sys.argv[1:]:
        with open(OUT) as f:
            if f.read() != text:
                sys.exit("gen_exp_neg: %s differs from the regenerated vector" % OUT)
        return
    with open(OUT, "w") as f:
        f.write(text)


main()
