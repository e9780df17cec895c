#!/usr/bin/python3
"""Unit-to-unit spread of the Allan identification (docs/results-allan.md).
Usage: allan_spread.py adis1.json adis2.json adis3.json  (outputs of
`harness allan LOG --json FILE`). Prints a markdown table: per channel the
three units' values and the spread (max/min) of the corrected parameters and
of the paper's bias stability."""
import json
import sys

units = [json.load(open(p)) for p in sys.argv[1:]]
names = ["ax", "ay", "az", "gx", "gy", "gz"]
print("| chan | unit | sigma_v (u/sqrt(Hz)) | spread | tau (s) | spread | sigma_bias (u) | spread | BS (u) | spread |")
print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
for c in names:
    rows = [next(ch for ch in u["channels"] if ch["name"] == c) for u in units]
    def col(key, part="corrected"):
        v = [r[part][key] for r in rows]
        return " / ".join("%.3g" % x for x in v), max(v) / min(v)
    sv, ssv = col("sigma_v")
    ts, sts = col("tau_s")
    sb, ssb = col("sigma_bias")
    bs, sbs = col("bs", "paper")
    print("| %s | %s | %s | %.2f | %s | %.2f | %s | %.2f | %s | %.2f |" % (c, rows[0]["unit"], sv, ssv, ts, sts, sb, ssb, bs, sbs))
