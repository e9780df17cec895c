#!/usr/bin/env python3
"""Gait events and stride times of `harness replay --strides` against the
expert footstep events of ipol_gait_xsens (docs/harness.md, "replay",
"Stride CSV").

Only trials 1-x, 2-x and 3-x are read (4-x and 5-x are kept apart for
judging and are never opened: a name outside 1-3 given on the command line
is refused). Each foot's log (`N-M_lf.txt`, `N-M_rf.txt`) is replayed with
the default configuration (`bin/harness replay LOG --strides - --quiet`; the
format is detected from the log's first line, as `--from ipol`).

Time base: the stride CSV's times are s since the log's first sample; the
experts' events (`N-M.json`) are PacketCounter values (harness/cmd_eval.c,
pkt_of_time: the counter itself, one time base for both feet). A time t is
packet c0 + round(t x rate), c0 the log's first PacketCounter (0, 1 or 2 in
these trials) and rate the log's `Acquisition frequency` (100 Hz): the reader
stamps counter / rate, so packets dropped before t still count.

Matching: each row's foot_strike_s goes to the expert swing of that foot
whose end (the heel strike) is nearest, when it is less than TOL = 50 packets
(0.5 s) away; two rows on one expert swing keep the nearer, the other is
unmatched. 0.5 s is under half of every expert stride here (the shortest,
strike to strike, is 0.85 s), so a strike can lie within TOL of only one expert
strike, and well above the events' errors (a few packets): a row on the
wrong stride cannot be taken for a late or early one. It is eval's IPOL_TOL,
so the counts compare with eval's.
Evaluated, as in eval (docs/results.md, ipol_gait_xsens): the expert swings
inside TrialBoundaries (5 packets of slack), clear of UTurnBoundaries, not
overlapping an expert swing of the other foot, and ending by the log's last
packet. Missed: an evaluated expert swing no row matches. Spurious: a row
matching no expert swing whose swing (swing_start_s to swing_end_s) has its
middle inside the trial and outside the U-turn and overlaps no expert swing
left out (the U-turn's included: a row between the turn's last annotated
swing and the next is the turn's).
For every evaluated, matched swing: the foot-off error (foot_off_s - the
swing's start) and the foot-strike error (foot_strike_s - its end), in
packets (samples at 100 Hz); when the row before matched the expert swing
before, the stride-time error (stride_time_s - the experts' strike-to-strike
time, ms) and the cadence error (cadence_spm - 120 / that time, steps/min).
Statistics: the median of |error|, the 90th percentile of |error| (nearest
rank, eval's), the bias (median of the signed error).

Prints a row per trial and foot and the totals over them (STRIDE_DEBUG=1:
every error). --check: exit 1 unless every evaluated expert swing was matched,
no row is spurious, and the median |foot-off| and |foot-strike| errors are at
most 2 packets (eval's targets, docs/results.md), over the trials run.
--eval MD: exit 1 unless every trial and foot run has its row in MD (eval's
ipol_gait_xsens table, `harness eval --out MD`) with the same expert strides,
missed, spurious and median |FO| and |FS| errors: replay's events are eval's
detector's, so any difference is a time-base or event bug of --strides.

Usage (from the repository root, after `make`; HARNESS overrides bin/harness):
  /usr/bin/python3 scripts/stride_ipol.py [--check] [--eval MD] [DATA_DIR] [TRIAL...]
  (DATA_DIR: ../shared/data/ipol_gait_xsens by default; TRIAL: 1-1 ... 3-4,
  every allowed trial found by default)
"""
import csv
import glob
import io
import json
import math
import os
import re
import subprocess
import sys

import numpy as np

TOL = 50  # packets: eval's IPOL_TOL (the docstring says why)
ALLOWED = re.compile(r"^[123]-[0-9]+$")


def pct_rank(v, p):
    """The nearest-rank percentile of eval (cmd_eval.c, pct_rank)."""
    s = sorted(v)
    k = int(math.ceil(p / 100.0 * len(s))) - 1
    return s[min(max(k, 0), len(s) - 1)]


def overlaps(a0, a1, b0, b1):
    return a0 < b1 and a1 > b0


def pair(p, what):
    """A pair of sample indices [x, y], x <= y, as eval takes them (an unknown, NaN, is none)."""
    if not isinstance(p, list) or len(p) != 2 or any(not math.isfinite(x) or x != int(x) for x in p) or p[0] > p[1]:
        raise ValueError("%s holds %r, not a pair of sample indices" % (what, p))
    return int(p[0]), int(p[1])


def pairs(j, key):
    return [pair(p, key) for p in j[key]]


def log_header(path):
    """(rate in Hz, first PacketCounter, last PacketCounter with 16-bit wraps counted on) of a foot log."""
    with open(path) as f:
        m = re.search(r"([0-9.]+)\s*Hz", f.readline())
        if m is None:
            raise ValueError(path + ": no 'Acquisition frequency: N Hz' line")
        f.readline()
        first = last = None
        wraps = 0
        for line in f:
            if not line.strip():
                continue
            c = int(float(line.split()[0]))
            if last is not None and c + wraps < last - 32768:
                wraps += 65536
            last = c + wraps
            if first is None:
                first = c
    return float(m.group(1)), first, last


def replay(log):
    h = os.environ.get("HARNESS", "bin/harness")
    p = subprocess.run([h, "replay", log, "--strides", "-", "--quiet"], stdout=subprocess.PIPE, check=True,
                       universal_newlines=True)
    return list(csv.DictReader(io.StringIO(p.stdout)))


def fnum(s):
    return float(s) if s != "" else None


def foot(rows, evs, oevs, tb, ub, c0, rate, last):
    """The errors of one trial's foot (module docstring)."""
    def pkt(t):
        return None if t is None else c0 + int(round(t * rate))

    r = [dict(fo=pkt(fnum(x["foot_off_s"])), fs=pkt(fnum(x["foot_strike_s"])), s0=pkt(fnum(x["swing_start_s"])),
              s1=pkt(fnum(x["swing_end_s"])), st=fnum(x["stride_time_s"]), cad=fnum(x["cadence_spm"])) for x in rows]
    # each row to the nearest expert strike within TOL; one row per expert swing
    match = [None] * len(r)
    owner = {}
    for k, x in enumerate(r):
        j = min(range(len(evs)), key=lambda q: abs(evs[q][1] - x["fs"]), default=None)
        if j is None or abs(evs[j][1] - x["fs"]) >= TOL:
            continue
        if j in owner:
            o = owner[j]
            if abs(r[o]["fs"] - evs[j][1]) <= abs(x["fs"] - evs[j][1]):
                continue
            match[o] = None
        owner[j] = k
        match[k] = j
    evaluated, excluded = [], []
    for j, (s0, s1) in enumerate(evs):
        outside = overlaps(s0, s1, ub[0], ub[1]) or s0 < tb[0] - 5 or s1 > tb[1] + 5
        both = any(overlaps(a, b, s0, s1) for a, b in oevs)
        if outside or both or s1 > last:
            excluded.append((s0, s1))
            continue
        evaluated.append(j)
    res = dict(expected=len(evaluated), rows=len(r), missed=0, spurious=0, fo=[], fs=[], st=[], cad=[],
               # rows of a short step whose foot-off is not before its foot-strike (swing_s empty), by how much, s
               late_fo=[(x["fo"] - x["fs"]) / rate for x in r if x["fo"] is not None and x["fo"] >= x["fs"]],
               # stance share, 100 stance_s / stride_time_s, of the rows with both, of a straight stride
               # (|heading_change_deg| <= 10) under 2 s (docs/harness.md, "Reading the rows for gait analysis")
               share=[100.0 * fnum(x["stance_s"]) / fnum(x["stride_time_s"]) for x in rows
                      if fnum(x["stance_s"]) is not None and fnum(x["stride_time_s"]) is not None and
                      fnum(x["heading_change_deg"]) is not None and abs(fnum(x["heading_change_deg"])) <= 10.0 and
                      fnum(x["stride_time_s"]) < 2.0])
    for j in evaluated:
        if j not in owner:
            res["missed"] += 1
            continue
        k = owner[j]
        x = r[k]
        if x["fo"] is not None:
            res["fo"].append(x["fo"] - evs[j][0])
        res["fs"].append(x["fs"] - evs[j][1])
        if k > 0 and j > 0 and match[k - 1] == j - 1 and x["st"] is not None:
            t_exp = (evs[j][1] - evs[j - 1][1]) / rate
            res["st"].append(1000.0 * (x["st"] - t_exp))
            res["cad"].append(x["cad"] - 120.0 / t_exp)
    for k, x in enumerate(r):
        if match[k] is not None:
            continue
        mid = (x["s0"] + x["s1"]) // 2
        if not (ub[0] <= mid < ub[1]) and tb[0] - 5 < mid < tb[1] + 5 and \
                not any(overlaps(x["s0"], x["s1"], a, b) for a, b in excluded):
            res["spurious"] += 1
    return res


def stats(v):
    if not v:
        return float("nan"), float("nan"), float("nan")
    a = np.abs(np.array(v, dtype=float))
    return float(np.median(a)), float(pct_rank(a, 90.0)), float(np.median(np.array(v, dtype=float)))


def main():
    args = sys.argv[1:]
    check = "--check" in args
    args = [a for a in args if a != "--check"]
    eval_rows = None
    if "--eval" in args:
        i = args.index("--eval")
        if i + 1 >= len(args):
            sys.exit("--eval needs eval's results file")
        eval_rows = {}
        with open(args[i + 1]) as f:
            for line in f:
                m = re.match(r"^\| ([0-9]+-[0-9]+) \| (left|right) \| ([0-9]+) \| [0-9]+ \| ([0-9]+) \| ([0-9]+) \| "
                             r"([0-9.]+|-) \| ([0-9.]+|-) \|", line)
                if m:
                    eval_rows[(m.group(1), m.group(2))] = m.group(3, 4, 5, 6, 7)
        del args[i:i + 2]
    d = "../shared/data/ipol_gait_xsens"
    if args and os.path.isdir(args[0]):
        d = args.pop(0)
    trials = args
    for t in trials:
        if not ALLOWED.match(t):
            sys.exit("trial %s: only 1-x, 2-x and 3-x may be read (4-x and 5-x are kept for judging)" % t)
    if not trials:
        # glob only the allowed names: 4-x and 5-x are never listed or opened
        found = set()
        for s in "123":
            for p in glob.glob(os.path.join(d, s + "-*.json")):
                n = os.path.basename(p)[: -len(".json")]
                if ALLOWED.match(n):
                    found.add(n)
        trials = sorted(found, key=lambda n: tuple(int(x) for x in n.split("-")))
    if not trials:
        sys.exit("no trial 1-x, 2-x or 3-x in " + d)
    tot = dict(expected=0, rows=0, missed=0, spurious=0, fo=[], fs=[], st=[], cad=[], late_fo=[], share=[])
    differ = []
    print("trial foot   expert  rows  matched  missed  spurious  med|FO|  med|FS|  FO_bias  FS_bias  "
          "med|dT|_ms  p90|dT|_ms  (samples at 100 Hz unless ms)")
    for t in trials:
        with open(os.path.join(d, t + ".json")) as f:
            j = json.load(f)  # NaN (unknown weights) reads as float nan
        tb = pair(j["TrialBoundaries"], "TrialBoundaries")
        ub = pair(j["UTurnBoundaries"], "UTurnBoundaries") if "UTurnBoundaries" in j else (0, 0)
        for side, key, okey in (("lf", "LeftFootEvents", "RightFootEvents"),
                                ("rf", "RightFootEvents", "LeftFootEvents")):
            log = os.path.join(d, "%s_%s.txt" % (t, side))
            rate, c0, last = log_header(log)
            res = foot(replay(log), pairs(j, key), pairs(j, okey), tb, ub, c0, rate, last)
            if os.environ.get("STRIDE_DEBUG"):
                print("  FO", res["fo"], "FS", res["fs"], "dT_ms", np.round(res["st"], 1).tolist())
            for k in tot:
                tot[k] += res[k]
            fo, fs, st = stats(res["fo"]), stats(res["fs"]), stats(res["st"])
            if eval_rows is not None:
                nm = (t, "left" if side == "lf" else "right")
                mine = (str(res["expected"]), str(res["missed"]), str(res["spurious"]),
                        "%.1f" % fo[0] if res["fo"] else "-", "%.1f" % fs[0] if res["fs"] else "-")
                if eval_rows.get(nm) != mine:
                    differ.append("%s %s: eval %s, --strides %s (expert, missed, spurious, median |FO|, |FS|)" % (
                        nm + (eval_rows.get(nm, "no row"), mine)))
            print("%-5s %-5s  %6d  %4d  %7d  %6d  %8d  %7.1f  %7.1f  %+7.1f  %+7.1f  %10.1f  %10.1f" % (
                t, "left" if side == "lf" else "right", res["expected"], res["rows"],
                res["expected"] - res["missed"], res["missed"], res["spurious"], fo[0], fs[0], fo[2], fs[2],
                st[0], st[1]))
    fo, fs, st, cad = stats(tot["fo"]), stats(tot["fs"]), stats(tot["st"]), stats(tot["cad"])
    print("all: %d trials and feet, %d expert strides, %d rows, %d matched, %d missed, %d spurious" % (
        2 * len(trials), tot["expected"], tot["rows"], tot["expected"] - tot["missed"], tot["missed"],
        tot["spurious"]))
    print("foot-off    (%d): median |error| %.1f samples, 90th percentile %.1f, bias %+.1f" % (len(tot["fo"]), *fo))
    print("foot-strike (%d): median |error| %.1f samples, 90th percentile %.1f, bias %+.1f" % (len(tot["fs"]), *fs))
    print("stride time (%d): median |error| %.1f ms, 90th percentile %.1f ms, bias %+.1f ms, largest %.1f ms" % (
        len(tot["st"]), *st, max(abs(e) for e in tot["st"]) if tot["st"] else float("nan")))
    print("cadence     (%d): median |error| %.2f steps/min, 90th percentile %.2f, bias %+.2f" % (len(tot["cad"]), *cad))
    print("foot-off not before foot-strike (swing_s empty): %d of %d rows, by %.2f s at most" % (
        len(tot["late_fo"]), tot["rows"], max(tot["late_fo"], default=0.0)))
    if tot["share"]:
        print("stance share (%d rows with stance_s and stride_time_s, |heading change| <= 10 deg, stride < 2 s): "
              "median %.1f %%, 10th-90th percentile %.1f-%.1f %%" % (
                  len(tot["share"]), np.median(tot["share"]), np.percentile(tot["share"], 10),
                  np.percentile(tot["share"], 90)))
    if eval_rows is not None:
        if differ:
            sys.exit("eval's table differs:\n" + "\n".join(differ))
        print("eval: the same expert strides, missed, spurious and median event errors in every row (%d)" % (
            2 * len(trials)))
    if check:
        bad = []
        if tot["missed"] or tot["spurious"]:
            bad.append("%d missed, %d spurious (target: none)" % (tot["missed"], tot["spurious"]))
        if not (fo[0] <= 2.0 and fs[0] <= 2.0):
            bad.append("median |FO| %.1f, |FS| %.1f samples (target <= 2)" % (fo[0], fs[0]))
        if bad:
            sys.exit("check failed: " + "; ".join(bad))
        print("check: met (none missed or spurious, median |FO| and |FS| <= 2 samples)")


if __name__ == "__main__":
    main()
