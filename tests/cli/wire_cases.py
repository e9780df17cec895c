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
  restart_early 50 samples, then the sender restarts and sends 300 with the
            same frame seq, time and counter as before but other values (no
            copies), and an END
  glitch    300 samples and an END; sample 150 stamped 0.5 ms before sample
            149 (the frame sequence and the counter going on)
  spike     the same, sample 150 stamped 1000 s ahead
  glitch_copy the glitch case, its early frame (seq 151) sent again after
            frame 153
  spike_first no INFO frame; the first sample stamped 1000 s ahead, then
            299 more and an END
  loss_early 300 samples, frames 141-150 lost on the link, frame 152 stamped
            0.5 ms before frame 151, END
  clockback 300 samples from 100 s and an END; from sample 150 on the stamps
            are 10 s back (the frame sequence and the counter going on)
  lateinfo  100 samples with temperature, then the INFO frame (rate, flags 7:
            nominal rate, temperature, counter; name 'IMU-X'), 200 more, END
  ratechange INFO at 400 Hz (nominal), 100 samples, INFO at 100 Hz, 100
            samples, END
  newflag   INFO flags 5, 100 samples, the same INFO with bit 7 set too (a
            newer sender's flag), 100 samples, END
  ctlname   an INFO frame whose name holds a line break and an escape
            sequence, 300 samples, END
  reboot    Unix-time stamps: 200 samples, the sender reboots (INFO with
            frame seq 0, frames and counter from 0 again, its clock going on
            1 s later), 200 samples and an END counting those 200
  reboot_lost the same, frame 50 after the reboot lost on the link
  reboot_short 5 samples, the reboot, 400 samples of which 3 are lost on the
            link, END 400
  reboot_glitch the reboot case, the third sample after it stamped 3 ms early
  firstahead_loss INFO at rate 0 (counter flag), the first sample stamped
            1000 s ahead, 299 more with frame 5 lost on the link, END
  firstahead_end the first sample stamped 1000 s ahead, 5 more, END
  tempoff   INFO flags 7 (temperature, counter), 100 samples at 25 degC, INFO
            flags 5 (no temperature), 100 samples without one, END
  tempdenied INFO flags 5 (no temperature), 300 samples that carry one, END
  newtype   INFO, 100 samples, a frame of type 0x06 (unknown), 100 samples,
            END
  seqon     INFO flags 1 (no counter), 100 samples whose seq is a running
            index from 0, INFO flags 5 (counter), 100 samples with the
            sensor's counter from 5000, END
  tempnoinfo no INFO frame: 100 samples without a temperature, 100 with
            one (25 degC), END
"""
import math
import os
import struct
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'vectors', 'wire'))
from gen_wire import frame, sample_payload, nav_payload, text, SAMPLE, NAV, INFO, END  # noqa: E402

DT_NS = 2500000  # 400 Hz


def info(rate, flags=4, name='test sender', seq=0):
    return frame(INFO, seq, struct.pack('<dI', rate, flags) + text(name, 32) + text('', 48))


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
    elif case == 'restart_early':
        b = info(400.0) + samples(50)
        b += info(400.0) + b''.join(
            frame(SAMPLE, k + 1, sample_payload(k * DT_NS, k, 2, (9.81, 0.0, 0.0), (0.0, 0.0, 0.0), 0.0))
            for k in range(300))
        b += end(301, 300)
    elif case in ('glitch', 'spike', 'clockback', 'glitch_copy', 'spike_first', 'loss_early'):
        t0 = 100 * 10**9 if case == 'clockback' else 0
        fr = []
        for k in range(300):
            t = t0 + k * DT_NS
            if case in ('glitch', 'glitch_copy') and k == 150:
                t = t0 + 149 * DT_NS - 500000
            elif (case == 'spike' and k == 150) or (case == 'spike_first' and k == 0):
                t += 1000 * 10**9
            elif case == 'clockback' and k >= 150:
                t -= 10 * 10**9
            elif case == 'loss_early' and k == 151:
                t = t0 + 150 * DT_NS - 500000
            fr.append(frame(SAMPLE, k + 1, sample_payload(t, k, 2, (0.0, 0.0, 9.81), (0.0, 0.0, 0.0), 0.0)))
        if case == 'glitch_copy':
            fr.insert(153, fr[150])
        elif case == 'loss_early':
            del fr[140:150]
        b = (b'' if case == 'spike_first' else info(400.0)) + b''.join(fr) + end(301, 300)
    elif case == 'lateinfo':
        fr = [frame(SAMPLE, k + 1, sample_payload(k * DT_NS, k, 3, (0.0, 0.0, 9.81), (0.0, 0.0, 0.0), 25.0))
              for k in range(300)]
        b = b''.join(fr[:100]) + info(400.0, 7, 'IMU-X', 101) + b''.join(
            frame(SAMPLE, k + 2, sample_payload(k * DT_NS, k, 3, (0.0, 0.0, 9.81), (0.0, 0.0, 0.0), 25.0))
            for k in range(100, 300)) + end(302, 300)
    elif case == 'ratechange':
        b = info(400.0, 5) + samples(100) + info(100.0, 5, 'test sender', 101)
        b += b''.join(frame(SAMPLE, 2 + k, still(k)) for k in range(100, 200)) + end(202, 200)
    elif case == 'newflag':
        b = info(400.0, 5) + samples(100) + info(400.0, 5 | 0x80, 'test sender', 101)
        b += b''.join(frame(SAMPLE, 2 + k, still(k)) for k in range(100, 200)) + end(202, 200)
    elif case == 'ctlname':
        b = info(400.0, 4, 'IMU\n"x"\x1b[2J') + samples(300) + end(301, 300)
    elif case in ('reboot', 'reboot_lost', 'reboot_short', 'reboot_glitch'):
        t0 = 1700000000 * 10**9
        n0, n1 = (5, 400) if case == 'reboot_short' else (200, 200)
        b = info(400.0) + samples(n0, 1, t0)
        t1 = t0 + n0 * DT_NS + 10**9
        fr = []
        for k in range(n1):
            t = t1 + k * DT_NS - (3000000 if case == 'reboot_glitch' and k == 2 else 0)
            fr.append(frame(SAMPLE, k + 1, sample_payload(t, k, 2, (0.0, 0.0, 9.81), (0.0, 0.0, 0.0), 0.0)))
        if case == 'reboot_lost':
            del fr[49]
        elif case == 'reboot_short':
            del fr[100:103]
        b += info(400.0) + b''.join(fr) + end(n1 + 1, n1)
    elif case in ('firstahead_loss', 'firstahead_end'):
        n = 300 if case == 'firstahead_loss' else 6
        fr = [frame(SAMPLE, k + 1, sample_payload(k * DT_NS + (1000 * 10**9 if k == 0 else 0), k, 2,
                                                  (0.0, 0.0, 9.81), (0.0, 0.0, 0.0), 0.0)) for k in range(n)]
        if case == 'firstahead_loss':
            del fr[4]
        b = (info(0.0) if case == 'firstahead_loss' else b'') + b''.join(fr) + end(n + 1, n)
    elif case == 'newtype':
        b = info(400.0) + samples(100) + frame(6, 101, bytes(45)) + b''.join(
            frame(SAMPLE, k + 2, still(k)) for k in range(100, 200)) + end(202, 200)
    elif case in ('tempoff', 'tempdenied', 'seqon', 'tempnoinfo'):
        def smp(k, fseq, flags, temp, c=None):
            return frame(SAMPLE, fseq, sample_payload(k * DT_NS, k if c is None else c, flags, (0.0, 0.0, 9.81),
                                                      (0.0, 0.0, 0.0), temp))
        if case == 'tempoff':
            b = info(400.0, 7) + b''.join(smp(k, k + 1, 3, 25.0) for k in range(100))
            b += info(400.0, 5, 'test sender', 101) + b''.join(smp(k, k + 2, 2, math.nan) for k in range(100, 200))
            b += end(202, 200)
        elif case == 'tempdenied':
            b = info(400.0, 5) + b''.join(smp(k, k + 1, 3, 25.0) for k in range(300)) + end(301, 300)
        elif case == 'tempnoinfo':
            b = b''.join(smp(k, k + 1, 2, math.nan) for k in range(100))
            b += b''.join(smp(k, k + 1, 3, 25.0) for k in range(100, 200)) + end(201, 200)
        else:
            b = info(400.0, 1) + b''.join(smp(k, k + 1, 0, 0.0) for k in range(100))
            b += info(400.0, 5, 'test sender', 101) + b''.join(smp(k, k + 2, 2, 0.0, 4900 + k)
                                                              for k in range(100, 200))
            b += end(202, 200)
    else:
        sys.exit('unknown case ' + case)
    with open(out, 'wb') as f:
        f.write(b)


if __name__ == '__main__':
    main()
