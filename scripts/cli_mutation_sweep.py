#!/usr/bin/env python3
"""Mutation sweep of the harness's command line (docs/robustness.md, "Mutation
sweep of the command line").

Default mode: a real-format input (the first lines of one recording of each
data set) is mutated at random -- cut at a byte, bytes flipped, odd tokens in
fields (nan, inf, 1e308, empty, NUL, 400 digits ...), lines deleted, duplicated,
swapped or blanked, CRLF, columns dropped or added, constant data, a stretch
scaled by 1e6, a garbage tail -- and run through one of info, replay, allan,
psd, convert and simgap. With --eval, one truth or log file of a small eval
data directory (an ipol trial with its events JSON, a vicon trial, a footprint
walk) is mutated and `eval --no-experiments` runs on it.

A case fails when the harness exits with a status other than 0, 1 or 2 (a
signal, an abort), reports an ASan/UBSan error, or runs over the time limit
(120 s; eval 300 s). Failing cases are kept under --out; --keep keeps every
case (its input and the command's outputs, e.g. eval's r.md), and --log FILE
writes one JSON line per case (command, mutation, exit status, the end of its
standard error), to read what the passing cases said.

Build the sanitized harness first (from the repository root):
  make BUILD=build/san HARNESS=build/san/harness OPT="-O1 -g" \\
    SAN="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer" build/san/harness
  /usr/bin/python3 scripts/cli_mutation_sweep.py --seed 1 --cases 300
  /usr/bin/python3 scripts/cli_mutation_sweep.py --eval --seed 2 --cases 150
"""
import argparse
import glob
import gzip
import json
import os
import random
import shutil
import subprocess
import sys

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

TOKENS = [b"nan", b"NaN", b"inf", b"-inf", b"", b"1e308", b"-1e308", b"1e-320", b"0x10", b"+", b"-", b"1e",
          b"9" * 400, b"0", b"-0", b"1,2", b"\x00", b"\xff\xfe", b"  ", b"1e39", b"3.4e38"]
JSON_TOKENS = [b"[", b"]", b"{", b"}", b",", b"null", b"\"x\"", b"[[1]]", b"[]", b"-1e300", b"1e300", b"NaN",
               b"[[1,2],[3]]", b"9" * 30]
COMMANDS = [["info"], ["replay", "--out", "@tr.csv", "--json", "@s.json"], ["allan"], ["psd"], ["convert", "@o.bin"],
            ["simgap", "--json", "@g.json"]]


def head(path, n):
    op = gzip.open if path.endswith(".gz") else open
    lines = []
    with op(path, "rb") as f:
        for i, line in enumerate(f):
            if i >= n:
                break
            lines.append(line)
    return lines


def sources(data):
    s = [("short_walk.csv", data + "/xio_ngimu_gait/short_walk.csv", 6000),
         ("Measurement_100521_2_data_inert.txt", data + "/openshoe_gx2/Measurement_100521_2_data_inert.txt", 4000),
         ("1-1_lf.txt", data + "/ipol_gait_xsens/1-1_lf.txt", 2000),
         ("OpenShoeDataSet.txt", data + "/openshoe_c_820hz/OpenShoeDataSet.txt", 8000),
         ("square2_u.csv", data + "/openshoe_square2/square2_u.csv", 3000),
         ("adis16405_imu1_100Hz.csv.gz", data + "/adis16405_static/adis16405_imu1_100Hz.csv.gz", 30000)]
    for sub in ("vicon_3dmgx3", "own_3dmgx5_footprints"):
        p = sorted(glob.glob(data + "/pyshoe_vicon_llio/%s/*_imu.csv" % sub))
        if p:
            s.append((os.path.basename(p[0]), p[0], 3000))
    return [(name, head(path, n)) for name, path, n in s if os.path.exists(path)]


def sep_of(line):
    return b"," if b"," in line else (b"\t" if b"\t" in line else b" ")


def mutate(rng, lines):
    L = list(lines)
    b0 = 1 if len(L) > 1 else 0

    def pick():
        return rng.randrange(b0, len(L)) if len(L) > b0 else 0

    k = rng.randrange(14)
    if k == 0:
        blob = b"".join(L)
        cut = rng.randrange(len(blob) + 1)
        return [blob[:cut]], "cut at byte %d" % cut
    if k == 1:
        blob = bytearray(b"".join(L))
        for _ in range(rng.randrange(1, 20)):
            blob[rng.randrange(len(blob))] = rng.randrange(256)
        return [bytes(blob)], "bytes flipped"
    if k == 2:
        for _ in range(rng.randrange(1, 5)):
            i = pick()
            s = sep_of(L[i])
            f = L[i].rstrip(b"\r\n").split(s)
            f[rng.randrange(len(f))] = rng.choice(TOKENS)
            L[i] = s.join(f) + b"\n"
        return L, "tokens in fields"
    if k == 3:
        for _ in range(rng.randrange(1, 50)):
            if len(L) > 1:
                del L[pick()]
        return L, "lines deleted"
    if k == 4:
        for _ in range(rng.randrange(1, 50)):
            i = pick()
            L.insert(i, L[i])
        return L, "lines duplicated"
    if k == 5:
        for _ in range(rng.randrange(1, 10)):
            i, j = pick(), pick()
            L[i], L[j] = L[j], L[i]
        return L, "lines swapped"
    if k == 6:
        n = rng.choice([0, 1, 2, 3, 10])
        return L[:n], "first %d lines" % n
    if k == 7:
        return [x.rstrip(b"\r\n") + b"\r\n" for x in L], "CRLF"
    if k == 8:
        for _ in range(rng.randrange(1, 5)):
            i = pick()
            s = sep_of(L[i])
            f = L[i].rstrip(b"\r\n").split(s)
            if len(f) > 1:
                del f[rng.randrange(len(f))]
            L[i] = s.join(f) + b"\n"
        return L, "column dropped"
    if k == 9:
        i = pick()
        L[i] = L[i].rstrip(b"\r\n") + b",7\n"
        return L, "column added"
    if k == 10:
        return L[:b0] + [L[pick()]] * (len(L) - b0), "constant data"
    if k == 11:
        i = pick()
        for j in range(i, min(len(L), i + rng.randrange(1, 400))):
            s = sep_of(L[j])
            out = []
            for x in L[j].rstrip(b"\r\n").split(s):
                try:
                    out.append(repr(float(x) * 1e6).encode())
                except ValueError:
                    out.append(x)
            L[j] = s.join(out) + b"\n"
        return L, "scaled by 1e6"
    if k == 12:
        return L + [b"garbage tail without newline"], "garbage tail"
    for _ in range(rng.randrange(1, 10)):
        L.insert(pick(), rng.choice([b"\n", b"# comment\n", b"   \n", b";\n"]))
    return L, "blank and comment lines"


def run(argv, limit):
    try:
        r = subprocess.run(argv, capture_output=True, timeout=limit)
        return r.returncode, r.stderr
    except subprocess.TimeoutExpired:
        return "timeout", b""


def failed(rc, err):
    return rc not in (0, 1, 2) or b"Sanitizer" in err or b"runtime error" in err


def record(a, d, argv, what, rc, err):
    """--log's line for one case; the case's directory is removed unless it
    failed or --keep"""
    if a.log:
        with open(a.log, "a") as f:
            f.write(json.dumps({"case": os.path.basename(d), "argv": argv, "mutation": what, "exit": rc,
                                "stderr": err.decode(errors="replace")[-2000:]}) + "\n")
    if not failed(rc, err) and not a.keep:
        shutil.rmtree(d)


def sweep_commands(a, rng):
    srcs = sources(a.data)
    if not srcs:
        # not an IndexError from random.choice (a clone outside the
        # repository's parent directory finds no ../shared/data)
        sys.exit("no recording of any data set under %s: give --data DIR or set FNAV_DATA_DIR" % a.data)
    bad = 0
    for c in range(a.cases):
        name, lines = rng.choice(srcs)
        ml, what = mutate(rng, lines)
        d = os.path.join(a.out, "c%04d" % c)
        os.makedirs(d, exist_ok=True)
        p = os.path.join(d, name)
        blob = b"".join(ml)
        with (gzip.open(p, "wb") if name.endswith(".gz") else open(p, "wb")) as f:
            f.write(blob)
        cmd = rng.choice(COMMANDS)
        argv = [a.harness, cmd[0], p] + [x.replace("@", d + "/") for x in cmd[1:]]
        rc, err = run(argv, 120)
        if failed(rc, err):
            bad += 1
            print("FAIL case %d: %s %s (%s): exit %s\n  %s" % (c, cmd[0], name, what, rc,
                  err.decode(errors="replace")[-600:].replace("\n", "\n  ")), flush=True)
        record(a, d, argv, "%s: %s" % (name, what), rc, err)
    return bad


def sweep_eval(a, rng):
    base = os.path.join(a.out, "base")
    files = {"ipol_gait_xsens": ["1-1.json", "1-1_lf.txt", "1-1_rf.txt"],
             "pyshoe_vicon_llio/vicon_3dmgx3": ["2017-11-22-11-22-03_imu.csv", "2017-11-22-11-22-03_strides_gcp.csv"],
             "pyshoe_vicon_llio/own_3dmgx5_footprints": ["SensorConnectData_34_imu.csv",
                                                         "SensorConnectData_34_strides_gcp.csv"]}
    targets = ["ipol_gait_xsens/1-1.json", "ipol_gait_xsens/1-1_lf.txt",
               "pyshoe_vicon_llio/vicon_3dmgx3/2017-11-22-11-22-03_strides_gcp.csv",
               "pyshoe_vicon_llio/vicon_3dmgx3/2017-11-22-11-22-03_imu.csv",
               "pyshoe_vicon_llio/own_3dmgx5_footprints/SensorConnectData_34_strides_gcp.csv"]
    missing = [os.path.join(sub, n) for sub, names in files.items() for n in names
               if not os.path.isfile(os.path.join(a.data, sub, n))]
    if missing:
        # not a FileNotFoundError traceback from shutil.copy (a clone outside
        # the repository's parent directory finds no ../shared/data), as the
        # default mode says it
        sys.exit("no eval data under %s (%s missing%s): give --data DIR or set FNAV_DATA_DIR"
                 % (a.data, missing[0], ", and %d more" % (len(missing) - 1) if len(missing) > 1 else ""))
    shutil.rmtree(base, ignore_errors=True)
    for sub, names in files.items():
        os.makedirs(os.path.join(base, sub))
        for n in names:
            shutil.copy(os.path.join(a.data, sub, n), os.path.join(base, sub))
    bad = 0
    for c in range(a.cases):
        d = os.path.join(a.out, "e%04d" % c)
        shutil.rmtree(d, ignore_errors=True)
        shutil.copytree(base, d)
        t = rng.choice(targets)
        p = os.path.join(d, t)
        blob = bytearray(open(p, "rb").read())
        k = rng.randrange(4)
        if k == 0:
            blob = blob[:rng.randrange(len(blob) + 1)]
        elif k == 1:
            for _ in range(rng.randrange(1, 10)):
                i = rng.randrange(len(blob))
                blob[i:i + rng.randrange(1, 8)] = rng.choice(JSON_TOKENS)
        elif k == 2:
            for _ in range(rng.randrange(1, 10)):
                blob[rng.randrange(len(blob))] = rng.randrange(256)
        else:
            i = rng.randrange(len(blob))
            blob[i:i] = rng.choice(JSON_TOKENS) * rng.randrange(1, 3000)
        with open(p, "wb") as f:
            f.write(bytes(blob))
        argv = [a.harness, "eval", "--no-experiments", "--data", d, "--out", d + "/r.md"]
        rc, err = run(argv, 300)
        if failed(rc, err):
            bad += 1
            print("FAIL case %d: eval, %s mutated (kind %d): exit %s\n  %s" % (c, t, k, rc,
                  err.decode(errors="replace")[-600:].replace("\n", "\n  ")), flush=True)
        record(a, d, argv, "%s (kind %d)" % (t, k), rc, err)
    return bad


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--harness", default=os.path.join(ROOT, "build", "san", "harness"))
    ap.add_argument("--data", default=os.environ.get("FNAV_DATA_DIR", os.path.join(ROOT, "..", "shared", "data")))
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--cases", type=int, default=300)
    ap.add_argument("--eval", action="store_true", help="mutate an eval data directory's files instead")
    ap.add_argument("--out", default=None, help="scratch and failing cases (default /tmp/fnav-sweep-SEED)")
    ap.add_argument("--keep", action="store_true", help="keep every case's directory, not only the failing ones")
    ap.add_argument("--log", default=None, help="append one JSON line per case (command, mutation, exit, stderr)")
    a = ap.parse_args()
    if not os.access(a.harness, os.X_OK):
        sys.exit("no harness at %s (build the sanitized one: see the docstring)" % a.harness)
    a.out = a.out or "/tmp/fnav-sweep-%d%s" % (a.seed, "-eval" if a.eval else "")
    os.makedirs(a.out, exist_ok=True)
    rng = random.Random(a.seed)
    bad = sweep_eval(a, rng) if a.eval else sweep_commands(a, rng)
    print("%d cases, %d failed%s" % (a.cases, bad, " (kept in %s)" % a.out if bad else ""))
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
