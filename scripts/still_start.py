#!/usr/bin/env python3
"""How much stillness a recording needs before the first step
(docs/navigation.md, "Initial alignment", "How long to stand still first").

Each log is replayed whole, and its first swing found (the first sample
after the first stance phase whose stance flag is 0). The log is then cut
to start S seconds before that swing, for each S of --before, and replayed
again: the horizontal return-to-start error (% of the step-to-step path)
for each S, then the median and the worst over the logs per S.

With --bias, also the gyro bias the alignment handed the filter (the first
non-zero row of the trajectory's bgx-bgz) and the walk's last one, deg/s,
for the whole log and each cut.

Usage (from the repository root, after `make`; about 2 s per replay):
  /usr/bin/python3 scripts/still_start.py LOG... [--before 0.3,0.5,0.8,1.2,2] [--bias] [-- REPLAY OPTIONS]
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

import numpy as np

from replay_runs import split_args

H = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "bin", "harness")


def replay(log, tmp, opts):
    """(summary JSON, trajectory) of `harness replay LOG`; exits with the harness's message on failure."""
    out, js = os.path.join(tmp, "tr.csv"), os.path.join(tmp, "r.json")
    r = subprocess.run([H, "replay", log, "--out", out, "--json", js, "--quiet"] + opts, capture_output=True,
                       text=True)
    if r.returncode != 0:
        sys.exit("%s: replay failed (%d): %s" % (log, r.returncode, r.stderr.strip()))
    with open(js) as f:
        return json.load(f), np.genfromtxt(out, delimiter=",", names=True)


def first_swing(tr):
    """Time of the first sample after the first stance phase, or None."""
    st = tr["stance"] > 0
    if not st.any():
        return None
    i = int(np.argmax(st))
    after = np.nonzero(~st[i:])[0]
    return None if after.size == 0 else float(tr["t"][i + after[0]])


def gyro_bias(tr):
    """(aligned, last) gyro bias of a trajectory, deg/s: its first non-zero bgx-bgz row and its last."""
    b = np.degrees(np.column_stack([tr["bgx"], tr["bgy"], tr["bgz"]]))
    nz = np.nonzero(np.any(b != 0.0, axis=1))[0]
    return (b[nz[0]] if nz.size else b[0]), b[-1]


def show_bias(label, tr):
    b0, b1 = gyro_bias(tr)
    print("  %-10s gyro bias aligned (%+.2f, %+.2f, %+.2f), at the end (%+.2f, %+.2f, %+.2f) deg/s"
          % ((label,) + tuple(b0) + tuple(b1)))


def main():
    usage = __doc__.split("Usage")[1].split("\n", 2)[1].strip()
    argv, opts = split_args(sys.argv[1:], usage)
    ap = argparse.ArgumentParser(usage=usage)
    ap.add_argument("logs", nargs="+")
    ap.add_argument("--before", default="0.3,0.5,0.8,1.2,2", help="stillness kept before the first swing, s")
    ap.add_argument("--bias", action="store_true", help="print the aligned and the last gyro bias of each run")
    a = ap.parse_args(argv)
    before = [float(x) for x in a.before.split(",")]
    print("horizontal return-to-start error, % of the step-to-step path, log cut to start S s before its first swing")
    print("%-38s %9s %7s" % ("log", "swing (s)", "whole") + "".join("  S=%-5g" % s for s in before))
    per = [[] for _ in before]
    with tempfile.TemporaryDirectory() as tmp:
        for log in a.logs:
            base = os.path.join(tmp, "base.csv")
            r = subprocess.run([H, "convert", log, base, "--to", "csv"], capture_output=True, text=True)
            if r.returncode != 0:
                sys.exit("%s: convert failed: %s" % (log, r.stderr.strip()))
            d = np.genfromtxt(base, delimiter=",", names=True)
            j, tr = replay(base, tmp, opts)
            ts = first_swing(tr)
            if ts is None:
                sys.exit("%s: no stance followed by a swing" % log)
            row, trs = [], []
            for k, s in enumerate(before):
                m = d["t"] >= ts - s
                cut = os.path.join(tmp, "cut.csv")
                np.savetxt(cut, np.column_stack([d["t"][m] - d["t"][m][0]] +
                                                [d[c][m] for c in ("ax", "ay", "az", "gx", "gy", "gz")]),
                           delimiter=",", header="t,ax,ay,az,gx,gy,gz", comments="", fmt="%.9g")
                jc, tc = replay(cut, tmp, opts)
                trs.append(tc)
                per[k].append(jc["return_error_h_pct"])
                row.append(jc["return_error_h_pct"])
            print("%-38s %9.2f %7.2f" % (os.path.basename(log)[:38], ts, j["return_error_h_pct"]) +
                  "".join("  %7.2f" % x for x in row))
            if a.bias:
                show_bias("whole", tr)
                for s, tc in zip(before, trs):
                    show_bias("S=%g" % s, tc)
            sys.stdout.flush()
    print("%-38s %9s %7s" % ("median", "", "") + "".join("  %7.2f" % np.median(p) for p in per))
    print("%-38s %9s %7s" % ("worst", "", "") + "".join("  %7.2f" % np.max(p) for p in per))


if __name__ == "__main__":
    main()
