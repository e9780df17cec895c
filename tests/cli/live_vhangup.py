#!/usr/bin/env python3
"""`harness live` on a tty that hangs up while its device node stays (a
Bluetooth rfcomm link, a vhangup): the reads return 0 at once and poll says
POLLHUP with POLLIN. live must end with exit 1 and a clear message, keeping
the samples received, not loop on the empty reads.

Usage (from tests/cli/test_live.sh): live_vhangup.py HARNESS SEAM OUTDIR
Exit 0 when live behaved, 1 otherwise (the reason on stdout)."""
import fcntl
import os
import subprocess
import sys
import time
import tty

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from wire_cases import info, samples, wait_or_kill  # noqa: E402

TIOCVHANGUP = 0x5437


def main():
    harness, seam, out = sys.argv[1], sys.argv[2], sys.argv[3]
    m, s = os.openpty()
    tty.setraw(m)
    name = os.ttyname(s)
    env = dict(os.environ)
    env["LD_PRELOAD"] = seam + (" " + env["LD_PRELOAD"] if env.get("LD_PRELOAD") else "")
    rec = os.path.join(out, "rec_vh.bin")
    with open(os.path.join(out, "vh.out"), "w") as so, open(os.path.join(out, "vh.err"), "w") as se:
        p = subprocess.Popen([harness, "live", name, "--print-every", "0", "--record", rec], env=env, stdout=so,
                             stderr=se)
        time.sleep(1.0)
        os.write(m, info(400.0) + samples(100))
        time.sleep(1.0)
        try:
            fcntl.ioctl(s, TIOCVHANGUP)
        except OSError as e:
            print("skip: vhangup not permitted here (%s)" % e)
            p.kill()
            p.wait()
            return 0
        rc = wait_or_kill(p, "the hang-up")
        if rc is None:
            return 1
    err = open(os.path.join(out, "vh.err")).read()
    text = open(os.path.join(out, "vh.out")).read()
    if rc != 1:
        print("live exit %d after the hang-up, expected 1" % rc)
        return 1
    if "hung up" not in err:
        print("no hang-up message: %s" % err[-300:])
        return 1
    if "recorded 100 samples" not in text:
        print("the 100 samples are not reported as recorded: %s" % text[-300:])
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
