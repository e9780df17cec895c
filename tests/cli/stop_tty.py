#!/usr/bin/env python3
"""`harness simgap-validate` with its standard output and error on a terminal
that takes no output (Ctrl-S; a slow terminal or ssh link is the same: the
write waits for room) when the first signal comes: the signal lands inside
the kernel's write of a case's line. The run must stop after that case as
ever, and every case the summary counts must have its line (without
SA_RESTART the write failed with EINTR and stdio dropped the line).

The Ctrl-S is real: XOFF from the master side stops the slave's output
(IXON), and the kernel holds the command's write until XON. No sleep is
tuned to the machine: the command is known to wait in that write when
/proc/PID/syscall names write on standard output on a few reads in a row
(the call never returns while the terminal is stopped), and the signal to
have been handled when it waits in the handler's write of its notice on
standard error.

Usage (from tests/cli/test_simgap_validate.sh): stop_tty.py HARNESS OUTDIR
Exit 0 when the command behaved, 1 otherwise, 3 when this system cannot
show where a process waits (the reason on stdout in each case)."""
import os
import platform
import re
import select
import signal
import subprocess
import sys
import termios
import time

XOFF, XON = b"\x13", b"\x11"
# write(2)'s number in /proc/PID/syscall; elsewhere /proc/PID/wchan is used
WRITE_NR = {"x86_64": 1, "aarch64": 64, "riscv64": 64, "loongarch64": 64, "i386": 4, "i686": 4, "armv7l": 4,
            "ppc64le": 4, "ppc64": 4, "s390x": 4}.get(platform.machine())
LIMIT = 120.0  # seconds for any one wait (ASan builds are slow)


def waits_in_write(pid, fd):
    """(answer, via_wchan): answer True when pid sleeps inside a write to
    fd, None when /proc cannot say; via_wchan True when the answer came
    from /proc/PID/wchan (no usable /proc/PID/syscall)."""
    try:
        with open("/proc/%d/stat" % pid) as f:
            state = f.read().rsplit(")", 1)[1].split()[0]
    except OSError:
        return False, False  # gone
    if state != "S":
        return False, False
    try:
        with open("/proc/%d/syscall" % pid) as f:
            sc = f.read().split()
    except OSError:
        sc = []
    if WRITE_NR is not None and sc and sc[0] == "running":
        return False, False  # caught between calls: asked again
    if WRITE_NR is not None and len(sc) >= 2:
        return sc[0] == str(WRITE_NR) and int(sc[1], 16) == fd, False
    try:
        with open("/proc/%d/wchan" % pid) as f:
            wchan = f.read().strip()
    except OSError:
        wchan = "0"
    if wchan in ("", "0"):
        return None, False
    # the fd is not known this way: after the signal this holds at once,
    # which does no harm (the signal is pending before the XON that wakes
    # the write)
    return wchan in ("wait_woken", "n_tty_write"), True


def wait_blocked(p, fd, what):
    """Wait until p has been inside its write to fd on 5 reads in a row (a
    write that is not held would have returned between them)."""
    t0 = time.monotonic()
    t_end = t0 + LIMIT
    seen = 0
    ever = False
    while seen < 5:
        if p.poll() is not None:
            return "the command exited (%d) before %s" % (p.returncode, what)
        if time.monotonic() > t_end:
            return "the command never waited in %s" % what
        w, via_wchan = waits_in_write(p.pid, fd)
        if w is None:
            return "unknown"
        ever = ever or w
        if via_wchan and not ever and time.monotonic() - t0 > 10.0:
            # this kernel names the wait otherwise: nothing to tell by
            return "unknown"
        seen = seen + 1 if w else 0
        time.sleep(0.02)
    return ""


def main():
    harness, out = sys.argv[1], sys.argv[2]
    m, s = os.openpty()
    a = termios.tcgetattr(s)
    a[0] = (a[0] | termios.IXON) & ~termios.IXANY  # Ctrl-S stops the output, only Ctrl-Q restarts it
    termios.tcsetattr(s, termios.TCSANOW, a)
    got = bytearray()

    def read_for(until, what):
        """Read the master until until() holds (None: until the command's
        end closes the terminal); "" when it did, else why not."""
        t_end = time.monotonic() + LIMIT
        while until is None or not until():
            r, _, _ = select.select([m], [], [], max(0.0, t_end - time.monotonic()))
            if not r:
                return "no %s within %.0f s: %r" % (what, LIMIT, bytes(got[-300:]))
            try:
                b = os.read(m, 4096)
            except OSError:  # EIO: the command (the last holder of the terminal) exited
                b = b""
            if not b:
                return "" if until is None else "the terminal closed before %s: %r" % (what, bytes(got[-300:]))
            got.extend(b)
        return ""

    cmd = [harness, "simgap-validate", "--cases", "40", "--static-only", "--duration", "60", "--rate", "50",
           "--seeds", "4"]
    # SIGINT at its default in the command (a script's background job
    # starts with it ignored, which the harness leaves so)
    p = subprocess.Popen(cmd, stdin=subprocess.DEVNULL, stdout=s, stderr=s,
                         preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    os.close(s)
    try:
        why = read_for(lambda: re.search(rb"^case +0 ", bytes(got), re.M) is not None, "first case line")
        if why:
            print(why)
            return 1
        os.write(m, XOFF)  # Ctrl-S: the next case's line waits
        why = wait_blocked(p, 1, "a write to standard output")
        if why == "unknown":
            print("/proc/PID/syscall and /proc/PID/wchan cannot show where a process waits here")
            return 3
        if why:
            print(why)
            return 1
        p.send_signal(signal.SIGINT)  # inside that write
        # the handler ran: it waits in its own write of the notice on standard error
        why = wait_blocked(p, 2, "the handler's write to standard error")
        if why:
            print(why)
            return 1
        os.write(m, XON)  # Ctrl-Q
        why = read_for(None, "the end")
        if why:
            print(why)
            return 1
        try:
            rc = p.wait(timeout=LIMIT)
        except subprocess.TimeoutExpired:
            print("the command still runs %.0f s after Ctrl-Q" % LIMIT)
            return 1
    finally:
        if p.poll() is None:
            p.kill()
            p.wait()
    text = got.decode("utf-8", "replace").replace("\r\n", "\n")
    with open(os.path.join(out, "stop_tty.out"), "w") as f:
        f.write(text)
    if rc != 130:
        print("exit %d, expected 130: %r" % (rc, text[-600:]))
        return 1
    if "simgap-validate: stopping after the current case" not in text:
        print("no notice of the signal: %r" % text[-600:])
        return 1
    summ = re.search(r"^simgap-validate: (\d+) cases? \(INCOMPLETE", text, re.M)
    if summ is None:
        print("no summary of an incomplete run: %r" % text[-600:])
        return 1
    n = int(summ.group(1))
    shown = [int(c) for c in re.findall(r"^case +(\d+) ", text, re.M)]
    if shown != list(range(n)):
        print("the summary counts %d cases, the lines shown are of cases %s (the line of %s lost)"
              % (n, shown, ", ".join(str(c) for c in range(n) if c not in shown) or "none"))
        return 1
    if "cannot write" in text:
        print("a write failed: %r" % text[-600:])
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
