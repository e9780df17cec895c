#!/usr/bin/env python3
"""`harness live` with its standard error on a terminal: the status line is
redrawn in place (a carriage return, no newline), and a warning that comes
while one is drawn must start a line of its own, not follow the status line
on the same line ("... | bad 0 lost 0   harness live: warning: bad frame:
...").

Usage (from tests/cli/test_live.sh): live_tty.py HARNESS SEAM OUTDIR
Exit 0 when live behaved, 1 otherwise (the reason on stdout)."""
import math
import os
import subprocess
import sys
import threading
import time
import tty

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from wire_cases import info, still, frame, end, sample_payload, wait_or_kill, SAMPLE, DT_NS  # noqa: E402


def main():
    harness, seam, out = sys.argv[1], sys.argv[2], sys.argv[3]
    m, s = os.openpty()  # the serial port: live reads the slave
    tty.setraw(m)
    name = os.ttyname(s)
    em, es = os.openpty()  # live's standard error: a terminal
    env = dict(os.environ)
    env["LD_PRELOAD"] = seam + (" " + env["LD_PRELOAD"] if env.get("LD_PRELOAD") else "")
    got = bytearray()

    def drain():
        while True:
            try:
                b = os.read(em, 4096)
            except OSError:  # EIO: live (the last holder of the terminal) exited
                return
            if not b:
                return
            got.extend(b)

    with open(os.path.join(out, "tty.out"), "w") as so:
        p = subprocess.Popen([harness, "live", name, "--print-every", "0.1", "--timeout", "5"], env=env,
                             stdout=so, stderr=es)
    os.close(es)
    reader = threading.Thread(target=drain)
    reader.start()
    time.sleep(0.5)
    os.write(m, info(400.0) + b''.join(frame(SAMPLE, 1 + k, still(k)) for k in range(100)))
    time.sleep(0.4)  # status lines drawn
    nan = sample_payload(100 * DT_NS, 100, 2, (math.nan, 0.0, 9.81), (0.0, 0.0, 0.0), 0.0)
    os.write(m, frame(SAMPLE, 101, nan))  # a warning: "bad sample"
    time.sleep(0.4)
    os.write(m, b''.join(frame(SAMPLE, 1 + k, still(k)) for k in range(101, 200)) + end(201, 200))
    rc = wait_or_kill(p, "the END frame")
    if rc is None:
        return 1
    reader.join(timeout=5)
    text = got.decode("utf-8", "replace")
    with open(os.path.join(out, "tty.err"), "w") as f:
        f.write(text)
    if rc != 1:
        print("live exit %d with a NaN sample, expected 1" % rc)
        return 1
    if "\rlive: " not in text:
        print("no status line redrawn in place: %r" % text[-300:])
        return 1
    warned = 0
    for line in text.split("\n"):
        line = line.rstrip("\r")
        k = line.find("harness live: warning:")
        if k < 0:
            continue
        warned += 1
        if line[:k].strip("\r") != "":
            print("a warning shares a line with the status line: %r" % line)
            return 1
    if warned == 0:
        print("no warning on standard error: %r" % text[-300:])
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
