#!/usr/bin/python3
"""Write the paper's own identification (III.C as written: sigma_v = ADEV at
1 s, BS at the minimum, tau = t_BS f_s, sigma_bias = BS / sqrt(tau), read
with eq. 4) of one log as a footnav profile, from `harness allan --json`:

    bin/harness allan LOG --no-sim --quiet --json allan.json
    docs/tools/paper_profile.py allan.json NAME > paper.profile
    bin/harness simgap LOG --profile paper.profile     # the Fig. 7 check

Units: the JSON gives gyro values in deg/s (the paper's tables); the profile
is SI (docs/profile-format.md). Used for docs/simgap-results.md.
"""
import json
import math
import sys


def main():
    if len(sys.argv) != 3:
        sys.stderr.write("usage: paper_profile.py ALLAN.json NAME\n")
        return 2
    j = json.load(open(sys.argv[1]))
    fs = float(j["rate_hz"])
    ch = {c["name"]: c for c in j["channels"]}
    if sorted(ch) != ["ax", "ay", "az", "gx", "gy", "gz"]:
        sys.stderr.write("paper_profile.py: the JSON must hold all six channels\n")
        return 1

    def row(names, key):
        out = []
        for n in names:
            p = ch[n]["paper"]
            k = math.pi / 180.0 if ch[n]["unit"] == "deg/s" else 1.0
            if key == "tau":
                out.append(p["tau_samples"] / fs)
            else:
                out.append(p[key] * k)
        return " ".join("%.6g" % v for v in out)

    acc, gyr = ["ax", "ay", "az"], ["gx", "gy", "gz"]
    print("# footnav sensor profile (docs/profile-format.md)")
    print("# The paper's identification (III.C as written, eq. 4 reading) of %s," % j.get("source", "?"))
    print("# from `harness allan --json` via docs/tools/paper_profile.py (docs/simgap-results.md).")
    print("format = footnav-profile 1")
    print("name = %s" % sys.argv[2])
    print("rate_hz = %g" % fs)
    print("accel_noise_mps2_rthz = %s" % row(acc, "sigma_v"))
    print("accel_tau_s = %s" % row(acc, "tau"))
    print("accel_bias_sigma_mps2 = %s" % row(acc, "sigma_bias"))
    print("gyro_noise_rps_rthz = %s" % row(gyr, "sigma_v"))
    print("gyro_tau_s = %s" % row(gyr, "tau"))
    print("gyro_bias_sigma_rps = %s" % row(gyr, "sigma_bias"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
