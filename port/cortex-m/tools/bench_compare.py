#!/usr/bin/env python3
"""Compare the emulator benchmark's output with the same code built for the
host (make firmware-bench).

  bench_compare.py EMULATOR.txt HOST.txt [--replay REPLAY.csv] [--pos-tol M] [--att-tol RAD]

- the "stream:" line must be identical: same samples, frames, and the same
  CRC-32 over every SAMPLE frame the firmware emitted (the wire encoding is
  bit-identical on Cortex-M4F and x86-64);
- the navigation outputs ("nav"/"nav-final" lines, float32 bit patterns of
  position and attitude) are compared: the largest position difference must
  stay within --pos-tol metres. The float operations are IEEE-754 binary32
  on both machines, but the math libraries (newlib vs glibc sinf/cosf/atan2f)
  may differ in the last bit, and the filter can amplify that. Defaults:
  1 mm in position, 1e-5 rad in attitude. A CRC-32 over
  every NAV frame ("navcrc:") tells whether the whole output is bit-identical.
- the Allan variances and Welch PSD bins at the end of the slice ("allan",
  "welch" lines, float32 bit patterns) must agree within --est-rel-tol
  (default 1e-4 relative; they are sums of many float terms, so a last-bit
  difference in one input could move the last bits of the result).
- with --replay, every navigation output of the emulator is also matched by
  its time with the row of `harness replay --out` on the same slice (the
  host float32 result of the harness, written with 6 decimals) and compared
  with the same tolerances. A missing file means replay is not available.
"""
import csv
import os
import argparse
import struct
import sys


def f32(h):
    return struct.unpack('<f', struct.pack('<I', int(h, 16)))[0]


def load_estimates(path):
    """Allan variances and Welch PSD bins: key -> float32 value."""
    est = {}
    for line in open(path):
        w = line.split()
        if w and w[0] in ('allan', 'welch'):
            est[(w[0], int(w[1]), int(w[2]), int(w[3]))] = f32(w[4])
    return est


def compare_estimates(emu, host, rel_tol):
    if not emu and not host:
        return True
    if set(emu) != set(host):
        print('compare: error: different Allan/Welch points on the emulator (%d) and the host (%d)'
              % (len(emu), len(host)))
        return False
    worst, same, bad = 0.0, 0, 0
    for k, e in emu.items():
        h = host[k]
        same += e == h
        d = abs(e - h) / max(abs(h), 1e-30)
        worst = max(worst, d)
    for kind in ('allan', 'welch'):
        n = sum(1 for k in emu if k[0] == kind)
        if n:
            print('compare: %s: %d values, %d bit-identical' % (kind, n, sum(1 for k in emu if k[0] == kind
                                                                               and emu[k] == host[k])))
    print('compare: Allan/Welch largest relative difference %.3g (tolerance %.3g)' % (worst, rel_tol))
    return worst <= rel_tol


def load(path):
    stream, nav, navcrc = None, {}, None
    t0 = None
    for line in open(path):
        w = line.split()
        if not w:
            continue
        if w[0] == 'slice-t0:':
            t0 = int(w[1])
        elif w[0] == 'navcrc:':
            navcrc = line.strip()
        elif w[0] == 'stream:':
            stream = line.strip()
        elif w[0] in ('nav', 'nav-final'):
            nav[(w[0], int(w[1]))] = (int(w[2]), int(w[3]), [f32(x) for x in w[4:7]], [f32(x) for x in w[7:10]],
                                       w[4:10])
    return stream, nav, navcrc, t0


def compare_replay(path, nav, t0, pos_tol, att_tol):
    """Every emulator output against the replay row of the same time."""
    if not os.path.exists(path):
        print('compare: no `harness replay` output (replay not available in this build)')
        return True
    rows = {}
    with open(path) as f:
        for r in csv.DictReader(f):
            rows[r['t']] = r
    if not nav:
        print('compare: replay wrote %d rows; no navigation outputs from the emulator to compare' % len(rows))
        return True
    worst_p = worst_a = 0.0
    missing = 0
    for (tag, k), (t_ns, flags, pos, att, raw) in nav.items():
        key = '%.6f' % ((t_ns - t0) * 1e-9)
        r = rows.get(key)
        if r is None:
            missing += 1
            continue
        worst_p = max(worst_p, max(abs(pos[i] - float(r[c])) for i, c in enumerate(('x', 'y', 'z'))))
        worst_a = max(worst_a, max(abs(att[i] - float(r[c])) for i, c in enumerate(('roll', 'pitch', 'yaw'))))
    print('compare: against `harness replay` of the slice: %d outputs matched by time, %d without a row; largest '
          'differences %.3g m and %.3g rad (the CSV has 6 decimals)' % (len(nav) - missing, missing, worst_p, worst_a))
    ok = missing == 0 and worst_p <= pos_tol and worst_a <= att_tol
    if not ok:
        print('compare: error: the emulator disagrees with `harness replay`')
    return ok


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('emu')
    ap.add_argument('host')
    ap.add_argument('--pos-tol', type=float, default=1e-3)
    ap.add_argument('--att-tol', type=float, default=1e-5)
    ap.add_argument('--replay')
    ap.add_argument('--est-rel-tol', type=float, default=1e-4)
    a = ap.parse_args()
    es, en, ec, et0 = load(a.emu)
    hs, hn, hc, _ = load(a.host)
    ok = True
    if es is None or hs is None:
        print('compare: error: a "stream:" line is missing')
        return 1
    if es != hs:
        print('compare: error: the frame streams differ\n  emulator: %s\n  host:     %s' % (es, hs))
        ok = False
    else:
        print('compare: frame stream identical on the emulator and the host (%s)' % es.split('echo-crc')[1].split()[0])
    if set(en) != set(hn):
        print('compare: error: different navigation outputs (%d on the emulator, %d on the host)' % (len(en), len(hn)))
        ok = False
    elif en:
        worst, worst_att, same, worst_k = 0.0, 0.0, 0, None
        for k in en:
            e, h = en[k], hn[k]
            if e[0] != h[0] or e[1] != h[1]:
                print('compare: error: output %s: time or flags differ' % (k,))
                ok = False
            d = max(abs(x - y) for x, y in zip(e[2], h[2]))
            if d > worst:
                worst, worst_k = d, k
            da = max(abs(x - y) for x, y in zip(e[3], h[3]))
            worst_att = max(worst_att, da)
            same += e[4] == h[4]
        print('compare: %d navigation outputs compared, %d bit-identical in position and attitude; largest '
              'differences %.3g m (output %s, tolerance %.3g m) and %.3g rad' % (len(en), same, worst,
                                                                               worst_k[1] if worst_k else '-',
                                                                               a.pos_tol, worst_att))
        if ec is not None and ec == hc:
            print('compare: every NAV frame bit-identical (%s)' % ec)
        else:
            print('compare: NAV frames not all bit-identical (emulator %s, host %s): the math libraries differ '
                  'in the last bit somewhere; the positions above are within tolerance' % (ec, hc))
        if worst > a.pos_tol or worst_att > a.att_tol:
            print('compare: error: a difference exceeds its tolerance (attitude tolerance %.3g rad)' % a.att_tol)
            ok = False
    else:
        print('compare: no navigation outputs (the navigation filter is not built into the image)')
    if a.replay is not None and not compare_replay(a.replay, en, et0, a.pos_tol, a.att_tol):
        ok = False
    if not compare_estimates(load_estimates(a.emu), load_estimates(a.host), a.est_rel_tol):
        ok = False
    print('compare: %s' % ('ok' if ok else 'FAILED'))
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main())
