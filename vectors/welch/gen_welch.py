#!/usr/bin/python3
"""Golden vectors for the streaming Welch PSD (tests/test_welch.c).

Inputs (committed next to this script):
  welch_input_synth.txt   5000 samples: offset + two sines + LCG noise (below)
  welch_input_os820.txt   8192 samples of the vertical accelerometer (f_z,
                          m/s^2) of the OpenShoe 820 Hz walk, rows 10001..18192
                          of ../shared/data/openshoe_c_820hz/OpenShoeDataSet.txt
                          (CC BY 4.0, see vectors/README.md)
Expected: scipy.signal.welch with the same window, overlap, detrending and
scaling, one-sided, for each case below ("global": welch(x - x.mean(),
detrend=False)); and the bandwidth holding a fraction
of the total power by the rule of docs/psd.md (bin k holds P_k df over
[(k-1/2) df, (k+1/2) df], linear interpolation where the cumulative power
crosses the threshold), written here independently with numpy.

welch_last_expected.csv: for each "global" case, the spectrum of the last
full segment alone (fnav_welch_last after every sample of the input was
pushed): scipy.signal.periodogram(seg - x.mean(), window, detrend=False,
same scaling, one-sided), seg the last segment that fits (start
(K - 1) (nperseg - noverlap), K segments) and x.mean() the mean of the
whole input (the samples pushed so far). Same line format as
welch_expected.csv, without band lines.

welch_long_offset_expected.csv: tests/test_welch.c test_global_long_offset_start's
record, 1,000,000 samples at 1 kHz: white noise (xorshift64 and Box-Muller,
written here in Python's math as the C test writes it in C) with the first
sample 50.0, far from the mean; scipy.signal.welch(x - x.mean(), periodic
Hamming 64, overlap 32, detrend=False, density, one-sided): the default
configuration with FNAV_DETREND_GLOBAL. Same line format, one case line.

--check regenerates and compares with the committed files (relative 1e-12),
and the two inputs with their sources (exact): the synthetic series with its
generator, the OpenShoe excerpt with the shared data (when found; required
under FNAV_REQUIRE_DATA=1).
--write-os820 re-extracts the real-data excerpt (needs the shared data:
$FNAV_DATA_DIR, ../shared/data or /work/shared/data).
"""
import math
import os
import sys
import numpy as np
import scipy
import scipy.signal as sig

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "welch_expected.csv")
OUT_LAST = os.path.join(HERE, "welch_last_expected.csv")
SYN = os.path.join(HERE, "welch_input_synth.txt")
OS8 = os.path.join(HERE, "welch_input_os820.txt")
OUT_LONG = os.path.join(HERE, "welch_long_offset_expected.csv")

# name, input, fs, nperseg, noverlap, window, symmetric, detrend, scaling
CASES = [
    ("paper_hamming64", "synth", 820.0, 64, 32, "hamming", 0, "constant", "density"),
    ("hamming64_sym_nodetrend", "synth", 820.0, 64, 32, "hamming", 1, "none", "density"),
    ("hann256_linear", "synth", 100.0, 256, 128, "hann", 0, "linear", "density"),
    ("hann128_75pct_spectrum", "synth", 100.0, 128, 96, "hann", 0, "constant", "spectrum"),
    ("rect32_nooverlap", "synth", 1.0, 32, 0, "boxcar", 0, "none", "density"),
    ("hamming1024_constant", "synth", 820.0, 1024, 512, "hamming", 0, "constant", "density"),
    ("os820_hamming64", "os820", 820.0, 64, 32, "hamming", 0, "constant", "density"),
    ("os820_hamming1024", "os820", 820.0, 1024, 512, "hamming", 0, "constant", "density"),
    ("os820_hamming256_nodetrend", "os820", 820.0, 256, 128, "hamming", 0, "none", "density"),
    ("os820_hamming64_global", "os820", 820.0, 64, 32, "hamming", 0, "global", "density"),
    ("synth_hann256_global", "synth", 100.0, 256, 100, "hann", 0, "global", "density"),
    ("synth_rect64_global", "synth", 10.0, 64, 0, "boxcar", 0, "global", "spectrum"),
]
# bandwidth checks: case, threshold, round_hz, exclude_dc
BANDS = [
    ("os820_hamming64", 0.95, 50.0, 0),
    ("os820_hamming1024", 0.95, 50.0, 0),
    ("os820_hamming256_nodetrend", 0.95, 50.0, 0),
    ("os820_hamming256_nodetrend", 0.95, 50.0, 1),
    ("paper_hamming64", 0.90, 25.0, 0),
    ("os820_hamming64_global", 0.95, 50.0, 0),
]


def synth():
    a, c, mask = 6364136223846793005, 1442695040888963407, (1 << 64) - 1
    s = 12345
    y = np.empty(5000)
    for k in range(5000):
        s = (a * s + c) & mask
        u = float(s >> 32) / 4294967296.0
        y[k] = 9.81 + 0.7 * np.sin(0.0377 * k) + 0.2 * np.sin(1.3 * k + 0.4) + (u - 0.5)
    return y


def window(name, n, sym):
    if name == "boxcar":
        return np.ones(n)
    return sig.get_window(name, n, fftbins=not sym)


def welch(x, fs, n, nov, win, sym, detrend, scaling):
    w = window(win, n, sym)
    if detrend == "global":
        # the whole record's mean removed first (footnav's FNAV_DETREND_GLOBAL)
        x = x - x.mean()
        detrend = "none"
    f, p = sig.welch(x, fs=fs, window=w, nperseg=n, noverlap=nov, detrend=False if detrend == "none" else detrend,
                     scaling=scaling, return_onesided=True)
    return f, p


def bandwidth(p, df, thr, round_hz, exclude_dc):
    n = len(p)
    pw = p * df
    if exclude_dc:
        pw = pw.copy()
        pw[0] = 0.0
    total = pw.sum()
    cum = np.cumsum(pw)
    k = int(np.argmax(cum >= thr * total))
    lo = 0.0 if k == 0 else (k - 0.5) * df
    hi = (n - 1) * df if k == n - 1 else (k + 0.5) * df
    before = cum[k] - pw[k]
    bw = lo + min(max((thr * total - before) / pw[k], 0.0), 1.0) * (hi - lo)
    fs = 2 * bw
    return bw, np.ceil(fs / round_hz) * round_hz


def last_segment(x, fs, n, nov, win, sym, detrend, scaling):
    """Periodogram of the last full segment less the whole record's mean
    (fnav_welch_last with the global-mean detrending)."""
    assert detrend == "global"
    w = window(win, n, sym)
    k = (len(x) - n) // (n - nov) + 1  # segments
    s = (k - 1) * (n - nov)
    f, p = sig.periodogram(x[s:s + n] - x.mean(), fs=fs, window=w, nfft=n, detrend=False, return_onesided=True,
                           scaling=scaling)
    return f, p


def long_offset_record():
    """test_global_long_offset_start's input, as its C loop makes it: per
    sample two xorshift64 (13, 7, 17) draws u1 = 1 - (x >> 11) 2^-53, u2 =
    (x >> 11) 2^-53 and g = sqrt(-2 ln u1) cos(2 pi u2); sample 0 is 50.0."""
    mask = (1 << 64) - 1
    x = 88172645463325252
    out = np.empty(1000000)
    for i in range(1000000):
        x ^= (x << 13) & mask
        x ^= x >> 7
        x ^= (x << 17) & mask
        u1 = 1.0 - float(x >> 11) * (1.0 / 9007199254740992.0)
        x ^= (x << 13) & mask
        x ^= x >> 7
        x ^= (x << 17) & mask
        u2 = float(x >> 11) * (1.0 / 9007199254740992.0)
        out[i] = 50.0 if i == 0 else math.sqrt(-2.0 * math.log(u1)) * math.cos(6.283185307179586 * u2)
    return out


def long_offset():
    fs, n, nov = 1000.0, 64, 32
    f, p = welch(long_offset_record(), fs, n, nov, "hamming", 0, "global", "density")
    lines = ["# scipy %s numpy %s: scipy.signal.welch of test_global_long_offset_start's record less its mean "
             "(one-sided)\n" % (scipy.__version__, np.__version__),
             "case,long_offset_hamming64_global,xorshift_bm,%.17g,%d,%d,hamming,0,global,density,%d\n"
             % (fs, n, nov, len(p))]
    for k, v in enumerate(p):
        lines.append("%d,%.17e\n" % (k, v))
    return lines


def read(path):
    return np.array([float(l) for l in open(path) if l.strip() and not l.startswith("#")])


def generate():
    inputs = {"synth": read(SYN), "os820": read(OS8)}
    lines = ["# scipy %s numpy %s: scipy.signal.welch (one-sided) and the docs/psd.md bandwidth rule\n"
             % (scipy.__version__, np.__version__)]
    spectra = {}
    for name, inp, fs, n, nov, win, sym, det, sc in CASES:
        f, p = welch(inputs[inp], fs, n, nov, win, sym, det, sc)
        spectra[name] = (p, fs / n)
        lines.append("case,%s,%s,%.17g,%d,%d,%s,%d,%s,%s,%d\n" % (name, inp, fs, n, nov, win, sym, det, sc, len(p)))
        for k, v in enumerate(p):
            lines.append("%d,%.17e\n" % (k, v))
    for name, thr, rnd, ex in BANDS:
        p, df = spectra[name]
        bw, fsr = bandwidth(p, df, thr, rnd, ex)
        lines.append("band,%s,%.17g,%.17g,%d,%.17e,%.17g\n" % (name, thr, rnd, ex, bw, fsr))
    last = ["# scipy %s numpy %s: scipy.signal.periodogram of the last segment less the record's mean (one-sided)\n"
            % (scipy.__version__, np.__version__)]
    for name, inp, fs, n, nov, win, sym, det, sc in CASES:
        if det != "global":
            continue
        f, p = last_segment(inputs[inp], fs, n, nov, win, sym, det, sc)
        last.append("case,%s,%s,%.17g,%d,%d,%s,%d,%s,%s,%d\n" % (name, inp, fs, n, nov, win, sym, det, sc, len(p)))
        for k, v in enumerate(p):
            last.append("%d,%.17e\n" % (k, v))
    return lines, last


def compare(old, new):
    if len(old) != len(new):
        return "line count differs"
    for a, b in zip(old[1:], new[1:]):
        fa, fb = a.strip().split(","), b.strip().split(",")
        if fa[0] in ("case",) and fa != fb:
            return "case line differs: " + a
        if fa[0] == "band":
            if fa[:5] != fb[:5] or abs(float(fa[5]) - float(fb[5])) > 1e-9 * abs(float(fb[5])) or fa[6] != fb[6]:
                return "band differs: " + a
        elif fa[0] != "case":
            x, y = float(fa[1]), float(fb[1])
            if abs(x - y) > 1e-12 * abs(y) + 1e-300:
                return "value differs: %s vs %s" % (a.strip(), b.strip())
    return None


def data_dir():
    """The shared data, where the tests look for it (tests/support/fnav_testdata.c,
    gen_double_reference.py): $FNAV_DATA_DIR, ../shared/data, /work/shared/data."""
    root = os.path.join(HERE, "..", "..")
    for d in (os.environ.get("FNAV_DATA_DIR", ""), os.path.join(root, "..", "shared", "data"), "/work/shared/data"):
        if d and os.path.isfile(os.path.join(d, "MANIFEST.md")):
            return os.path.abspath(d)
    return "(shared data not found)"


OS8_SRC = os.path.join(data_dir(), "openshoe_c_820hz", "OpenShoeDataSet.txt")


def os820_text():
    rows = open(OS8_SRC).read().splitlines()[10000:18192]
    return ("# OpenShoe 820 Hz walk (CC BY 4.0, data OpenShoe ISC): f_z [m/s^2], rows 10001-18192\n"
            + "".join(r.split(",")[2].strip() + "\n" for r in rows))


def synth_text():
    return ("# synthetic: 9.81 + 0.7 sin(0.0377 k) + 0.2 sin(1.3 k + 0.4) + (u - 0.5), u from a 64-bit LCG\n"
            + "".join("%.17g\n" % v for v in synth()))


def main():
    if "--write-os820" in sys.argv:
        with open(OS8, "w") as f:
            f.write(os820_text())
    if "--write-synth" in sys.argv or not os.path.exists(SYN):
        with open(SYN, "w") as f:
            f.write(synth_text())
    lines, last = generate()
    longo = long_offset()
    if "--check" in sys.argv:
        status = 0
        # the inputs too: an input edited and the expected values regenerated
        # from it would otherwise pass
        inputs = [(SYN, synth_text())]
        if os.path.exists(OS8_SRC):
            inputs.append((OS8, os820_text()))
        else:
            print("gen_welch: %s not found; the OpenShoe excerpt is not compared with its source" % OS8_SRC)
            if os.environ.get("FNAV_REQUIRE_DATA") == "1":  # as gen_double_reference.py: CI has the data
                status = 1
        for path, text in inputs:
            if not os.path.exists(path) or open(path).read() != text:
                print("gen_welch: %s differs from its source (regenerate: gen_welch.py --write-synth --write-os820)"
                      % os.path.basename(path))
                status = 1
        for path, new in ((OUT, lines), (OUT_LAST, last), (OUT_LONG, longo)):
            err = compare(open(path).readlines(), new) if os.path.exists(path) else "missing"
            if err:
                print("gen_welch: %s: %s" % (os.path.basename(path), err))
                status = 1
        return status
    with open(OUT, "w") as f:
        f.writelines(lines)
    with open(OUT_LAST, "w") as f:
        f.writelines(last)
    with open(OUT_LONG, "w") as f:
        f.writelines(longo)
    return 0


if __name__ == "__main__":
    sys.exit(main())
