#!/usr/bin/python3
"""Double-precision reference for the float32-vs-float64 agreement test.

Runs the float64 build of the same navigation code (`build/double/harness
replay`, default configuration) over every real foot-mounted walk in the
shared data directory and writes, per walk, the distance travelled (step to
step through the stance mid-points) and the final position (last stance
mid-point), to vectors/nav/double_reference.csv. tests/test_nav.c replays the
walks in its own build and requires the final positions to agree with this
reference within 0.1 % of the distance (float32 build) or 1e-9 relative
(float64 build, regression).

  /usr/bin/python3 vectors/nav/gen_double_reference.py          # regenerate
  /usr/bin/python3 vectors/nav/gen_double_reference.py --check  # compare, exit 1 on a change

--check tolerance: 1e-9 m absolute + 1e-9 relative (the float64 build is
deterministic on one machine; a difference means the code changed and the
reference must be regenerated with the reason in the commit message).
Without the shared data the check is skipped (exit 0, with a message; exit 1
with FNAV_REQUIRE_DATA=1, as in CI).
"""
import glob
import json
import os
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
OUT = os.path.join(ROOT, "vectors", "nav", "double_reference.csv")


def data_dir():
    for d in (os.environ.get("FNAV_DATA_DIR", ""), os.path.join(ROOT, "..", "shared", "data"), "/work/shared/data"):
        if d and os.path.isfile(os.path.join(d, "MANIFEST.md")):
            return os.path.abspath(d)
    return None


def walks(d):
    pats = ["openshoe_gx2/*_data_inert.txt", "xio_ngimu_gait/*.csv", "pyshoe_vicon_llio/own_3dmgx5_footprints/*_imu.csv",
            "pyshoe_vicon_llio/vicon_3dmgx3/*_imu.csv", "openshoe_square2/square2_u.csv",
            "openshoe_c_820hz/OpenShoeDataSet.txt", "ipol_gait_xsens/*_[lr]f.txt"]
    out = []
    for p in pats:
        out += sorted(os.path.relpath(f, d) for f in glob.glob(os.path.join(d, p)))
    return out


def run(d):
    subprocess.run(["make", "-s", "-C", ROOT, "BUILD=build/double", "HARNESS=build/double/harness",
                    "FNAV_DEFS=-DFNAV_USE_DOUBLE=1", "build/double/harness"], check=True,
                   stdout=subprocess.DEVNULL)
    harness = os.path.join(ROOT, "build", "double", "harness")
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        js = os.path.join(tmp, "s.json")
        for rel in walks(d):
            r = subprocess.run([harness, "replay", os.path.join(d, rel), "--quiet", "--json", js],
                               stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            if r.returncode not in (0, 1) or not os.path.exists(js):
                raise SystemExit("replay failed on %s (exit %d)" % (rel, r.returncode))
            with open(js) as f:
                j = json.load(f)
            os.remove(js)
            e = j["end_position_m"]
            rows.append((rel, j["distance_m"] or 0.0, e[0], e[1], e[2]))
    return rows


def write(rows):
    with open(OUT, "w") as f:
        f.write("# float64 build, default configuration; gen_double_reference.py\n")
        f.write("walk,distance_m,end_x_m,end_y_m,end_z_m\n")
        for r in rows:
            f.write("%s,%.12g,%.12g,%.12g,%.12g\n" % r)


def read():
    rows = []
    with open(OUT) as f:
        for line in f:
            if line.startswith("#") or line.startswith("walk,"):
                continue
            p = line.strip().split(",")
            rows.append((p[0],) + tuple(float(x) for x in p[1:]))
    return rows


def main():
    d = data_dir()
    if d is None:
        print("gen_double_reference: shared data not found; skipped")
        return 1 if os.environ.get("FNAV_REQUIRE_DATA") == "1" else 0
    rows = run(d)
    if "--check" not in sys.argv:
        write(rows)
        print("wrote %s (%d walks)" % (OUT, len(rows)))
        return 0
    ref = {r[0]: r for r in read()}
    bad = 0
    for r in rows:
        q = ref.get(r[0])
        if q is None:
            print("missing in reference: %s" % r[0])
            bad += 1
            continue
        for a, b in zip(r[1:], q[1:]):
            if abs(a - b) > 1e-9 + 1e-9 * abs(b):
                print("%s: %.12g != reference %.12g" % (r[0], a, b))
                bad += 1
                break
    if len(rows) != len(ref):
        print("reference has %d walks, data %d" % (len(ref), len(rows)))
        bad += 1
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
