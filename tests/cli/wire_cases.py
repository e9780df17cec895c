"""Byte streams of misbehaving senders for tests/cli/test_live.sh (framing
from vectors/wire/gen_wire.py, the protocol's independent Python model).

usage: wire_cases.py CASE OUT
  restart   500 samples, then the sender restarts (time and sequence from 0)
            and sends 5 more and an END
  range     300 samples, the 100th with an acceleration of 1e20 m/s^2
  badrate   an INFO frame whose rate is NaN, then 300 samples and an END
  navonly   an INFO frame and 300 NAV frames (an on-sensor filter's output)
  truncend  300 samples, the last one cut after 20 of its 51 bytes (bytes lost
            on the line), then the END frame, then silence
  sensordrop 300 samples whose sensor counter skips 5 values after sample
            149 (lost on the sender), and sample frame 101 lost on the link
  noise     300 samples and an END, with line noise between frames 100 and
            101 and between 200 and 201: a false sync word announcing a
            SAMPLE frame, then 20 zero bytes (two corrupt candidates, no frame
            lost)
"""
import math
import os
import struct
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'vectors', 'wire'))
from gen_wire import frame, sample_payload, nav_payload, text, SAMPLE, NAV, INFO, END  # noqa: E402

DT_NS = 2500000  # 400 Hz


def info(rate):
    return frame(INFO, 0, struct.pack('<dI', rate, 4) + text('test sender', 32) + text('', 48))


def still(k, t0_ns=0):
    return sample_payload(t0_ns + k * DT_NS, k, 2, (0.0, 0.0, 9.81), (0.0, 0.0, 0.0), 0.0)


def samples(n, seq0=1, t0_ns=0):
    return b''.join(frame(SAMPLE, (seq0 + k) & 0xffff, still(k, t0_ns)) for k in range(n))


def end(seq, count):
    return frame(END, seq & 0xffff, struct.pack('<I', count))


def wait_or_kill(p, after):
    """The exit status of process p within 30 s, else None: p killed, and
    'live still running 30 s after AFTER' printed (the scripts' reason)."""
    try:
        return p.wait(timeout=30)
    except subprocess.TimeoutExpired:
        p.kill()
        p.wait()
        print("live still running 30 s after %s" % after)
        return None


def main():
    case, out = sys.argv[1], sys.argv[2]
    if case == 'restart':
        b = info(400.0) + samples(500, 1, 10 * 10**9) + info(400.0) + samples(5, 1, 0) + end(6, 5)
    elif case == 'range':
        b = info(400.0)
        for k in range(300):
            p = still(k)
            if k == 99:
                p = sample_payload(k * DT_NS, k, 2, (1e20, 0.0, 9.81), (0.0, 0.0, 0.0), 0.0)
            b += frame(SAMPLE, k + 1, p)
        b += end(301, 300)
    elif case == 'badrate':
        b = info(math.nan) + samples(300) + end(301, 300)
    elif case == 'repeat':
        # frame 101 (sample 100) sent twice: the same frame seq and sample
        fr = [frame(SAMPLE, k + 1, still(k)) for k in range(300)]
        fr.insert(101, fr[100])
        b = info(400.0) + b''.join(fr) + end(301, 300)
    elif case == 'stale':
        # frame 200 (sample 199) again after frame 201: a late copy, its time going back
        fr = [frame(SAMPLE, k + 1, still(k)) for k in range(300)]
        fr.insert(201, fr[199])
        b = info(400.0) + b''.join(fr) + end(301, 300)
    elif case == 'stale_nav':
        # SAMPLE and NAV frames interleaved on one frame counter; the sample
        # frame of seq 399 again after the NAV frame of seq 402
        fr = []
        for k in range(300):
            fr.append(frame(SAMPLE, 2 * k + 1, still(k)))
            fr.append(frame(NAV, 2 * k + 2, nav_payload(k * DT_NS, k, 1, 0, (0.0, 0.0, 0.0), (0.0, 0.0, 0.0),
                                                         (0.0, 0.0, 0.0))))
        fr.insert(402, fr[398])
        b = info(400.0) + b''.join(fr) + end(601, 300)
    elif case == 'navonly':
        b = info(400.0) + b''.join(
            frame(NAV, k + 1, nav_payload(k * DT_NS, k, 1, 0, (0.0, 0.0, 0.0), (0.0, 0.0, 0.0), (0.0, 0.0, 0.0)))
            for k in range(300))
    elif case == 'truncend':
        # the cut frame announces 51 bytes; the END frame (14) is all that follows
        fr = [frame(SAMPLE, k + 1, still(k)) for k in range(300)]
        fr[-1] = fr[-1][:20]
        b = info(400.0) + b''.join(fr) + end(301, 300)
    elif case == 'sensordrop':
        fr = []
        for k in range(300):
            c = k if k < 150 else k + 5  # the sensor's counter: 150..154 never sent
            fr.append(frame(SAMPLE, k + 1, sample_payload(k * DT_NS, c, 2, (0.0, 0.0, 9.81), (0.0, 0.0, 0.0), 0.0)))
        del fr[100]  # frame seq 101 (counter 100) lost on the link: not the sensor's drop
        b = info(400.0) + b''.join(fr) + end(301, 300)
    elif case == 'noise':
        junk = b'\xa5\x5a' + bytes([SAMPLE, 41]) + bytes(20)
        fr = [frame(SAMPLE, k + 1, still(k)) for k in range(300)]
        fr.insert(200, junk)
        fr.insert(100, junk)
        b = info(400.0) + b''.join(fr) + end(301, 300)
    else:
        sys.exit('unknown case ' + case)
    with open(out, 'wb') as f:
        f.write(b)


if __name__ == '__main__':
    main()
