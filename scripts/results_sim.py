#!/usr/bin/python3
"""The paper checks in simulation (docs/results-sim.md): runs
`harness montecarlo` over the grids below and prints the markdown tables.

  /usr/bin/python3 scripts/results_sim.py [--harness bin/harness] [--seeds 50]
                                          [--jsondir build/results-sim] [--only bias|rate]

A. Bias model (paper V.A): the paper-like closed walk (`--motion paper`,
   185 s, two flights up and down) at 200 Hz with the Table IV-VI sensors,
   the filter with and without the AR(1) bias model on the same samples
   (`--bias-model both`), interval-mean samples (`--decimation mean`, the
   filter's convention), for both readings of the tables' sigma_bias
   (`--bias-sigma given|eq6`, docs/simulator.md).
B. Sampling frequency (paper II, V.B): 120 s of walking and of running at
   100, 200 and 300 Hz, heel strikes as calibrated to the paper's Table III
   (default: walking 7 ms, running 5 ms) and sharper (3 ms: 500 Hz for a
   walk by the same criterion, beyond the 250-300 Hz Table I asks for
   heels), sampled as interval means (an integrating
   sensor, the filter's own convention), through the anti-alias FIR
   (instantaneous band-limited values) and as point samples without any
   filter (`--oversample 1`), for the MTx sensor (random, N seeds) and an ideal
   sensor (`--profile none`: no randomness, one run).
C. Consistency: the paper walk with each sensor, the filter with its AR(1)
   model, interval-mean and instantaneous samples: NEES of position,
   velocity, attitude, biases and all states against the chi-square band.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import time


def run(harness, args, path):
    cmd = [harness, "montecarlo", "--quiet", "--json", path] + args
    t0 = time.time()
    r = subprocess.run(["nice"] + cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if r.returncode != 0:
        sys.stderr.write("failed: %s\n%s" % (" ".join(cmd), r.stderr))
        sys.exit(1)
    with open(path) as f:
        d = json.load(f)
    d["_cmd"] = "harness montecarlo " + " ".join(args)
    d["_secs"] = time.time() - t0
    return d


def fin(x):
    return [v for v in x if v is not None and math.isfinite(v)]


def mean_ci(x):
    """Mean and the half-width of its 95 % interval, Student's t with n - 1
    degrees of freedom (1.96, the normal quantile, until 2026-11-29: 2.5 %
    too narrow at 50 seeds; harness montecarlo uses t too)."""
    from scipy.stats import t as student_t
    x = fin(x)
    n = len(x)
    m = sum(x) / n
    sd = math.sqrt(sum((v - m) ** 2 for v in x) / (n - 1)) if n > 1 else 0.0
    return m, float(student_t.ppf(0.975, n - 1)) * sd / math.sqrt(n) if n > 1 else 0.0


def rms(x):
    x = fin(x)
    return math.sqrt(sum(v * v for v in x) / len(x))


def median(x):
    x = sorted(fin(x))
    n = len(x)
    return x[n // 2] if n % 2 else 0.5 * (x[n // 2 - 1] + x[n // 2])


def bias_model(harness, seeds, jd):
    rows = []
    for prof in ("navchip", "mtx", "shimmer"):
        for reading in ("given", "eq6"):
            args = ["--motion", "paper", "--rate", "200", "--profile", prof, "--bias-sigma", reading,
                    "--seeds", str(seeds), "--bias-model", "both", "--decimation", "mean"]
            d = run(harness, args, os.path.join(jd, "bias_%s_%s.json" % (prof, reading)))
            a, o = d["variants"]
            dh = [y - x for x, y in zip(a["final_h_m"], o["final_h_m"])]
            dv = [y - x for x, y in zip(a["final_v_m"], o["final_v_m"])]
            better = sum(1 for v in dh if v > 0)
            rows.append((prof, reading, d, a, o, dh, dv, better))
            sys.stderr.write("bias %s %s: %.0f s\n" % (prof, reading, d["_secs"]))
    print("| sensor | sigma_bias | closure error, AR(1) on: horiz. RMS / vert. RMS [m] | AR(1) off | "
          "paired off - on, horiz. [m] (95 %) | paired off - on, vert. [m] | on better | position NEES on / off |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- |")
    for prof, reading, d, a, o, dh, dv, better in rows:
        mh, ch = mean_ci(dh)
        mv, cv = mean_ci(dv)
        print("| %s | %s | %.3f / %.3f | %.3f / %.3f | %+.3f +- %.3f | %+.3f +- %.3f | %d of %d | %.2f / %.2f |" % (
            prof, reading, rms(a["final_h_m"]), rms(a["final_v_m"]), rms(o["final_h_m"]), rms(o["final_v_m"]),
            mh, ch, mv, cv, better, d["runs"], a["nees"]["pos"]["time_average"], o["nees"]["pos"]["time_average"]))
    print()
    print("Distance %.1f m between footfalls, %.1f s; %d seeds per row. Commands:" % (
        rows[0][2]["distance_m"], rows[0][2]["duration_s"], seeds))
    print()
    for r in rows:
        print("    " + r[2]["_cmd"])
    print()


def sampling(harness, seeds, jd):
    rows = []
    for motion in ("walk", "run"):
        for prof, n in (("mtx", seeds), ("none", 1)):
            for imp in (0, 3):
                for chain in ("mean", "filtered", "point"):
                    for rate in (100, 200, 300):
                        args = ["--motion", motion, "--duration", "120", "--rate", str(rate), "--profile", prof,
                                "--seeds", str(n)]
                        if imp > 0:
                            args += ["--impact-ms", str(imp)]
                        if chain == "point":
                            args += ["--oversample", "1"]
                        elif chain == "mean":
                            args += ["--decimation", "mean"]
                        d = run(harness, args, os.path.join(
                            jd, "rate_%s_%s_%d_%s_%d.json" % (motion, prof, imp, chain, rate)))
                        rows.append((motion, prof, imp, chain, rate, d))
                        sys.stderr.write("rate %s %s %d %s %d: %.0f s\n" % (motion, prof, imp, chain, rate,
                                                                             d["_secs"]))
    print("| motion | sensor | impact | sampling | 100 Hz: horiz. / vert. [m] | 200 Hz | 300 Hz |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    i = 0
    while i < len(rows):
        motion, prof, imp, chain, _, d = rows[i]
        cells = []
        for k in range(3):
            v = rows[i + k][5]["variants"][0]
            cells.append("%.3f / %.3f" % (rms(v["final_h_m"]), rms(v["final_v_m"])))
        print("| %s (%.0f m) | %s | %s | %s | %s | %s | %s |" % (
            motion, d["distance_m"], "ideal" if prof == "none" else prof,
            "%d ms" % imp if imp > 0 else "Table III (%s)" % ("7 ms" if motion == "walk" else "5 ms"),
            {"mean": "interval means", "filtered": "anti-alias FIR", "point": "point samples"}[chain],
            cells[0], cells[1], cells[2]))
        i += 3
    print()
    print("RMS over %d seeds (MTx) of the final position error after 120 s; the ideal sensor has no randomness "
          "(one run). Commands: `harness montecarlo --quiet --json FILE` with" % seeds)
    print()
    for r in rows:
        print("    " + r[5]["_cmd"])
    print()


def consistency(harness, seeds, jd):
    groups = ("pos", "vel", "att", "bias", "all")
    rows = []
    for prof in ("navchip", "mtx", "shimmer"):
        for decim in ("mean", "fir"):
            args = ["--motion", "paper", "--rate", "200", "--profile", prof, "--seeds", str(seeds),
                    "--bias-model", "ar1", "--decimation", decim]
            d = run(harness, args, os.path.join(jd, "nees_%s_%s.json" % (prof, decim)))
            rows.append((prof, decim, d))
            sys.stderr.write("nees %s %s: %.0f s\n" % (prof, decim, d["_secs"]))
    print("| sensor | samples | " + " | ".join("%s (d=%d)" % (g, n) for g, n in zip(groups, (3, 3, 3, 6, 15))) +
          " | error RMS / predicted sd, horiz. |")
    print("| --- | --- | " + " | ".join("---" for _ in groups) + " | --- |")
    for prof, decim, d in rows:
        v = d["variants"][0]
        cells = []
        for g in groups:
            c = v["nees"][g]
            if c["time_average"] is None:
                cells.append("n/a")
            else:
                cells.append("%.2f (%.0f %%)" % (c["time_average"], 100.0 * c["fraction_in_band"]))
        pred = rms(v["final_pred_h_m"])
        print("| %s | %s | %s | %.2f |" % (prof, "interval means" if decim == "mean" else "instantaneous (FIR)",
                                          " | ".join(cells), rms(v["final_h_m"]) / pred))
    lo, hi = rows[0][2]["variants"][0]["nees"]["pos"]["band_lo"], rows[0][2]["variants"][0]["nees"]["pos"]["band_hi"]
    print()
    print("Time-average of the NEES averaged over %d runs (in brackets: bins inside their 95 %% band); the band "
          "for d = 3 is [%.2f, %.2f]. Commands:" % (seeds, lo, hi))
    print()
    for r in rows:
        print("    " + r[2]["_cmd"])
    print()


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--harness", default="bin/harness")
    ap.add_argument("--seeds", type=int, default=50)
    ap.add_argument("--jsondir", default="build/results-sim")
    ap.add_argument("--only", choices=("bias", "rate", "nees"))
    a = ap.parse_args()
    os.makedirs(a.jsondir, exist_ok=True)
    if a.only in (None, "bias"):
        bias_model(a.harness, a.seeds, a.jsondir)
    if a.only in (None, "rate"):
        sampling(a.harness, max(10, a.seeds * 3 // 5), a.jsondir)
    if a.only in (None, "nees"):
        consistency(a.harness, a.seeds, a.jsondir)
    return 0


if __name__ == "__main__":
    sys.exit(main())
