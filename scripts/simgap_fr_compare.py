#!/usr/bin/python3
"""Flicker against rrw in the held-out ranking, read from `--verbose` output.

Usage:
  bin/harness simgap-validate --static-only --effects flicker --cases 16 \
      --seed 11 --duration 3600 --rate 200 --seeds 16 --mag-range 1,4 \
      --verbose > vf_s11.txt          (and seed 12, and --effects rrw)
  /usr/bin/python3 scripts/simgap_fr_compare.py vf_s11.txt vf_s12.txt vr_s11.txt vr_s12.txt

For every channel and forward-selection step at which both `flicker` and
`rrw` were simulated and both passed the held-out acceptance (score or
likelihood-ratio z above the Bonferroni-t critical value, explained-fraction
interval not at or below zero), prints the difference of their held-out
deviance drops (both folds, the ranking key `dL_rank`), grouped by the
withheld effect. Then replays one decision rule on the same output, without
rerunning anything: within a sensor triad whose channels chose differently
between flicker and rrw, the pooled deviance drops of the triad decide, and
a channel switches when the pooled winner passed its tests there.
Reads text only; the acceptance rule is sg_opts_default's (alpha 0.05, 16
seeds, 6 channels x 5 candidates x 2 tests) as in hx_simgap.c attribute().
"""
import re
import statistics
import sys

from scipy.stats import t as student_t

ZACC = float(student_t.isf(0.05 / (6 * 5 * 2), 15))
STEP = re.compile(r"^  step (\d+) ([* ]) (\S+) .*?held out: G (\S+) -> (\S+), score ([+-][\d.]+) sigma"
                  r".*?likelihood ratio ([+-][\d.]+) sigma.*?deviance drop (\S+) \(ends (\S+)\), (.*)$")
CASE = re.compile(r"^case\s+(\d+)\s+static\s+(\S+)\s+(\S+)\s+on (\S+)\s+x([\d.]+)\s+-> (\S+)")


def parse(path):
    cases, cur, ch = [], None, None
    with open(path) as fh:
        for line in fh:
            if line.startswith("simgap case:"):
                cur = {"ch": {}}
                continue
            m = re.match(r"^attribution (\w\w) ", line)
            if m and cur is not None:
                ch = m.group(1)
                cur["ch"][ch] = {}
                continue
            m = STEP.match(line)
            if m and cur is not None:
                lo = float("nan")
                mm = re.search(r"\(68 %: (-?[\d.]+)\.\.", m.group(10))
                if mm:
                    lo = float(mm.group(1))
                zd, zg = float(m.group(6)), float(m.group(7))
                cur["ch"][ch].setdefault(int(m.group(1)), {})[m.group(3)] = {
                    "sel": m.group(2) == "*",
                    "dl": float(m.group(8)),
                    "acc": (zd > ZACC or zg > ZACC) and not (lo <= 0.0),
                }
                continue
            m = CASE.match(line)
            if m and cur is not None:
                cur.update(n=int(m.group(1)), truth=m.group(3), on=m.group(4), mag=float(m.group(5)),
                           ans=m.group(6), path=path)
                cases.append(cur)
                cur = None
    return cases


def both_accepted(cases):
    out = {}
    for c in cases:
        for steps in c["ch"].values():
            for st in steps.values():
                f, r = st.get("flicker"), st.get("rrw")
                if f and r and f["acc"] and r["acc"]:
                    out.setdefault(c["truth"], []).append(f["dl"] - r["dl"])
    return out


def triad_pool(c):
    """Channels that would switch under triad pooling: (channel, from, to)."""
    sw = []
    for tri in (("ax", "ay", "az"), ("gx", "gy", "gz")):
        rows = []
        for ch in tri:
            for _, st in sorted(c["ch"].get(ch, {}).items()):
                sel = [e for e, v in st.items() if v["sel"]]
                if sel and sel[0] in ("flicker", "rrw"):
                    rows.append((ch, sel[0], st))
                    break
        if len(rows) < 2 or len({r[1] for r in rows}) < 2:
            continue
        pf = sum(r[2].get("flicker", {}).get("dl", 0.0) for r in rows)
        pr = sum(r[2].get("rrw", {}).get("dl", 0.0) for r in rows)
        win = "flicker" if pf > pr else "rrw"
        for ch, sel, st in rows:
            if sel != win and st.get(win, {}).get("acc"):
                sw.append((ch, sel, win, pf, pr))
    return sw


def main(paths):
    cases = [c for p in paths for c in parse(p)]
    print("held-out deviance drop, flicker minus rrw, where both passed the held-out tests "
          "(critical z %.2f):" % ZACC)
    for truth, d in sorted(both_accepted(cases).items()):
        neg = sum(1 for v in d if v < 0.0)
        print("  withheld %-8s %2d channel-steps: median %+.2f, range %+.2f .. %+.2f, rrw ahead on %d" %
              (truth, len(d), statistics.median(d), min(d), max(d), neg))
    print("triad pooling replayed on the same output:")
    for c in cases:
        sw = triad_pool(c)
        if sw:
            print("  %s case %d (%s on %s, x%.2f, answered %s): %s" %
                  (c["path"].split("/")[-1], c["n"], c["truth"], c["on"], c["mag"], c["ans"],
                   "; ".join("%s %s -> %s (pooled flicker %.2f, rrw %.2f)" % s for s in sw)))


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit("usage: simgap_fr_compare.py VERBOSE_OUTPUT...")
    main(sys.argv[1:])
