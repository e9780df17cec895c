#!/usr/bin/python3
"""Compare `harness psd --out` (float build) of an ADIS16405 log with
scipy.signal.welch's PSD of the same log, each bin held to a derived bound.

The reference is the shared data's third-party file
(allan_reference/derived_thirdparty/adis16405_imu1_welch_scipy.csv: scipy
signal.welch in double of gyro_x_dps and acc_x_g, Hann periodic, nperseg
4096, noverlap 2048, constant detrend, density, printed to 9 digits). The
harness was run as `harness psd LOG --nfft 4096 --window hann --dc segment
--out t.csv` (float32 samples and arithmetic, printed with %.6g). The bound
of bin k (tests/cli/test_psd.sh used a measured 1e-3 of the bin or 1e-6 of
the largest bin until 2026-12-02) is the sum of:

1. The float arithmetic of src/fnav_welch.c and src/fnav_fft.c, first order
   in u = 2^-24, worst case (no cancellation assumed), for each segment
   from its own exact (double) values x (the samples in SI units), v = x - x0
   (x0 its first sample), y = x - mean(x) and the window w:
   - before the FFT (every error reaches a bin through a DFT of unit-modulus
     factors, so by at most the sum of its magnitudes): the samples' float32
     rounding u|x| and its mean, the rounding of v (u|v| and its mean), of
     y = v - a and of y w (u w|y| each), the window table's error
     |dw| <= 0.5 c_err + u w (c_err: cos of a float argument, below); the
     float sum of the segment mean, a recursive sum, |da| <= u sum_i |T_i| / N
     (T_i its partial sums of v; Higham (4.4); a division by N = 4096 is
     exact), which reaches bin 0 through sum w = N/2 and bin 1 through
     |W_1| = N/4 (the Hann window's DFT is 0 elsewhere) plus sum|dw|;
   - the radix-2 FFT of the N/2 packed complex values (fnav_fft_complex):
     at stage s each butterfly output P = a +- W b errs by
     (sqrt(2) gamma_2 + mu)|b| (the complex product, Higham, "Accuracy and
     Stability of Numerical Algorithms", 2nd ed., lemma 3.5, and the
     twiddle's error mu) + u|P| (the sum); stage 1 (W = 1) by u|P|. Each
     node's error reaches Z_k, k = j mod 2^s, with a unit-modulus factor
     (Z_k = sum_r W^(rk) P_r[k mod L]), so |dZ_k| <= the sum over stages
     of the nodes' bounds at j = k mod L, computed from the exact partial
     DFTs (numpy, in double) of each segment;
   - the real split (fnav_fft_real_packed): |dX_k| <= |dZ_k| + |dZ_(M-k)|
     + u|E_k| + (u + sqrt(2) gamma_2 + mu)|O_k| + u|X_k| (bins 0 and N/2:
     sqrt(2)|dZ_0| + u|X_k|; bin N/4: |dZ_(N/4)|);
   - twiddles and window: cos and sin of theta = fl(fl(2 pi_f x) / N) after
     the octant reduction (theta <= pi/4; 2 pi_f = float32(2 pi)), so
     |d theta| <= (2u + u^2) pi/4, and glibc's cosf and sinf are within
     1 ulp (<= 2u): c_err = 2.01 u pi / 4 + 2u per component, mu =
     sqrt(2) c_err in modulus;
   - then |X|^2 = fl(re^2 + im^2) (gamma_2 |X|^2), each segment's
     2|X_k| D_k + D_k^2 (D_k the bound above), the Kahan sum over K
     segments ((2u + 2 K u^2) of the sum of |X|^2, Higham (4.8)), the
     subtraction acc - accc (u), and the scaling a (1/K) (2/(f_s s2)):
     1/K, f_s s2, the reciprocal and two products (5u), s2 = sum w^2 as a
     Kahan sum of float products (3u + 2 sum w|dw| / sum w^2).
2. The reference's own double arithmetic: the same bound with u = 2^-53
   (first order: the arithmetic part times 2^-29; pocketfft is also a
   Cooley-Tukey FFT with unit-modulus factors).
3. The printing: %.6g of the harness, 0.5 10^(e - 5) for a value of
   exponent e (read from the printed value, the larger where rounding
   carried it to a power of 10), and the reference's %.9g, 0.5 10^(e - 8),
   times the unit factor (pi/180)^2 or 9.80665^2 (double: 1e-16 of it).
The frequencies: the harness prints k f_s/N with %.6g (f_s / N = 100/4096
is exact in binary), the reference with 9 digits: within the two printing
bounds.

Usage: /usr/bin/python3 scripts/psd_scipy_bound.py LOG.csv.gz REF.csv HARNESS_OUT.csv
Prints, per channel, the largest error relative to the bin and to its
bound, and the bound's range relative to the bin; exit status 1 when a bin
or a frequency is beyond its bound.
"""
import gzip
import math
import sys

import numpy as np

N = 4096
HOP = 2048
FS = 100.0


def load_csv(path):
    rows = [l.strip().split(",") for l in open(path) if not l.startswith("#") and l.strip()]
    return {h: np.array([float(r[i]) for r in rows[1:]]) for i, h in enumerate(rows[0])}


def print_err(v, digits):
    """Largest error of %.{digits}g printing of a value printed as v."""
    v = np.abs(v)
    e = np.floor(np.log10(np.where(v > 0, v, 1.0)))
    return np.where(v > 0, 0.5 * 10.0 ** (e - (digits - 1)), 0.0)


def arith_bound(x, u):
    """Per-bin bound (first order in u) on the float error of K * PSD / scale,
    i.e. of sum_s |X_k^s|^2 as fnav_welch accumulates it, and the exact sum."""
    M = N // 2
    K = (len(x) - N) // HOP + 1
    n = np.arange(N)
    w = 0.5 - 0.5 * np.cos(2.0 * math.pi * n / N)
    g2 = 2.0 * u / (1.0 - 2.0 * u)
    c_err = (2.0 * u + u * u) * math.pi / 4.0 + 2.0 * u
    mu = math.sqrt(2.0) * c_err
    dw = 0.5 * c_err + u * w
    mulerr = math.sqrt(2.0) * g2 + mu
    seg = np.stack([x[s * HOP:s * HOP + N] for s in range(K)])  # (K, N)
    mean = seg.mean(axis=1, keepdims=True)
    v = seg - seg[:, :1]
    y = seg - mean
    ax, av, ay = np.abs(seg), np.abs(v), np.abs(y)
    pre = u * ((ax * w).sum(1) + ax.mean(1) * w.sum() + (av * w).sum(1) + av.mean(1) * w.sum() +
               2.0 * (ay * w).sum(1)) + (ay * dw).sum(1)  # (K,)
    da = u * np.abs(np.cumsum(v, axis=1)).sum(1) / N
    wy = w * y
    z = wy[:, 0::2] + 1j * wy[:, 1::2]  # (K, M) packed
    ez = np.zeros((K, M))
    kk = np.arange(M)
    L = 2
    while L <= M:
        R = M // L
        P = np.fft.fft(z.reshape(K, L, R), axis=1)  # P[:, j, r] = partial DFT r at j
        if L == 2:
            e = u * np.abs(P)
        else:
            H = np.fft.fft(z.reshape(K, L // 2, 2 * R), axis=1)  # children, length L/2
            b = H[:, :, R:]  # the odd child of r is r + R
            b = np.concatenate([b, b], axis=1)  # j and j + L/2 share a child value
            e = mulerr * np.abs(b) + u * np.abs(P)
        ez += e.sum(axis=2)[:, kk % L]
        L *= 2
    Z = np.fft.fft(z, axis=1)
    X = np.fft.rfft(wy, axis=1)  # (K, M + 1)
    dX = np.zeros((K, M + 1))
    k = np.arange(1, M)
    Zk, Zq = Z[:, k], np.conj(Z[:, M - k])
    E, O = 0.5 * (Zk + Zq), (Zk - Zq) / 2j
    dX[:, 1:M] = ez[:, k] + ez[:, M - k] + u * np.abs(E) + (u + mulerr) * np.abs(O) + u * np.abs(X[:, 1:M])
    dX[:, M // 2] = ez[:, M // 2]  # X_(N/4) = conj Z_(N/4), untouched by the split
    dX[:, 0] = math.sqrt(2.0) * ez[:, 0] + u * np.abs(X[:, 0])
    dX[:, M] = math.sqrt(2.0) * ez[:, 0] + u * np.abs(X[:, M])
    dX += pre[:, None]
    dX[:, 0] += da * (N / 2.0 + dw.sum())
    dX[:, 1] += da * (N / 4.0 + dw.sum())
    a2 = np.abs(X) ** 2
    s = a2.sum(axis=0)
    d = (2.0 * np.abs(X) * dX + dX * dX + g2 * a2).sum(axis=0)
    d += (2.0 * u + 2.0 * K * u * u) * s + u * s
    s2rel = 3.0 * u + 2.0 * (w * dw).sum() / (w * w).sum()
    d += (5.0 * u + s2rel) * s
    return d, s, K, w


def main():
    log, ref_path, got_path = sys.argv[1:4]
    cols = np.loadtxt(gzip.open(log, "rt"), delimiter=",", skiprows=1, usecols=(0, 3))
    ref, got = load_csv(ref_path), load_csv(got_path)
    assert len(ref["freq_hz"]) == len(got["freq_hz"]) == N // 2 + 1
    bad = 0
    df = np.abs(ref["freq_hz"] - got["freq_hz"])
    ftol = print_err(got["freq_hz"], 6) + print_err(ref["freq_hz"], 9)
    bad += int((df > ftol).sum())
    for name, rk, gk, col, unit in (("gyro x", "psd_gyro_x", "psd_gx", 0, math.pi / 180.0),
                                    ("acc x", "psd_acc_x", "psd_ax", 1, 9.80665)):
        x = cols[:, col] * unit
        d, s, K, w = arith_bound(x, 2.0 ** -24)
        d_ref, _, _, _ = arith_bound(x, 2.0 ** -53)
        scale = 2.0 / (FS * (w * w).sum() * K)  # one-sided density; bins 0 and N/2 once
        scale = np.full(N // 2 + 1, scale)
        scale[0] /= 2.0
        scale[-1] /= 2.0
        r = ref[rk] * unit * unit
        g = got[gk]
        tol = scale * (d + d_ref) + print_err(g, 6) + print_err(ref[rk], 9) * unit * unit * (1.0 + 1e-15)
        err = np.abs(g - r)
        nb = int((err > tol).sum())
        bad += nb
        print("%s: K %d; largest error %.3g of the bin, %.3g of its bound; bound %.3g to %.3g of the bin "
              "(arithmetic alone %.3g to %.3g; bins 0 and 1 %.3g and %.3g, the others %.3g to %.3g); "
              "%d bins beyond" %
              (name, K, (err / r).max(), (err / tol).max(), (tol / r).min(), (tol / r).max(),
               (scale * d / r).min(), (scale * d / r).max(), tol[0] / r[0], tol[1] / r[1],
               (tol[2:] / r[2:]).min(), (tol[2:] / r[2:]).max(), nb))
    print("frequencies: largest difference %.3g Hz, %d beyond the printing bound" % (df.max(), int((df > ftol).sum())))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
