#!/usr/bin/env python3
"""Golden vectors for the footnav wire protocol (docs/wire-protocol.md).

An independent encoder AND decoder of the protocol, written from the
specification with Python's struct and zlib.crc32 (not from the C code):

  frames.bin    - a clean stream: INFO, SAMPLEs (duplicate time stamp,
                  negative zero, extreme values), NAV, STATUS, a frame of an
                  unknown type, END
  frames.txt    - the decoded content of frames.bin, one line per frame
  corrupt.bin   - the same frames with damage: garbage before the first
                  frame, a flipped payload bit, a truncated frame followed by
                  a whole one, a frame dropped from the sequence, a known type
                  with a wrong length, a false sync word announcing a long
                  frame, a duplicated frame, idle bytes, a partial header
  corrupt.txt   - what a decoder that follows the specification delivers
                  from corrupt.bin (frame lines), then its counters

tests/test_wire.c requires the C encoder to reproduce frames.bin byte for byte
from frames.txt and the C decoder to deliver frames.txt and corrupt.txt.

  /usr/bin/python3 vectors/wire/gen_wire.py          # (re)write
  /usr/bin/python3 vectors/wire/gen_wire.py --check  # compare (exact)
"""
import os
import struct
import sys
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
SYNC = b'\xa5\x5a'
SAMPLE, NAV, STATUS, INFO, END = 1, 2, 3, 4, 5
KNOWN_LEN = {SAMPLE: 41, NAV: 53, STATUS: 20, INFO: 92, END: 4}


def f32(x):
    return struct.unpack('<f', struct.pack('<f', x))[0]


def frame(ftype, seq, payload):
    assert len(payload) <= 255
    body = struct.pack('<BBH', ftype, len(payload), seq) + payload
    return SYNC + body + struct.pack('<I', zlib.crc32(body) & 0xffffffff)


def text(s, n):
    b = s.encode('ascii')[:n - 1]
    return b + b'\0' * (n - len(b))


def sample_payload(t_ns, seq, flags, acc, gyr, temp):
    return struct.pack('<qIB', t_ns, seq, flags) + struct.pack('<7f', *(list(acc) + list(gyr) + [temp]))


def nav_payload(t_ns, seq, flags, health, pos, vel, eul):
    return struct.pack('<qIBI', t_ns, seq, flags, health) + struct.pack('<9f', *(list(pos) + list(vel) + list(eul)))


def fmt_g(x):
    return '%.9g' % x


def describe(ftype, seq, p):
    """One text line per frame, the format tests/test_wire.c parses."""
    if ftype == SAMPLE:
        t_ns, sseq, flags = struct.unpack_from('<qIB', p, 0)
        v = struct.unpack_from('<7f', p, 13)
        return 'sample %d %d %d %d %s' % (seq, t_ns, sseq, flags, ' '.join(fmt_g(x) for x in v))
    if ftype == NAV:
        t_ns, sseq, flags, health = struct.unpack_from('<qIBI', p, 0)
        v = struct.unpack_from('<9f', p, 17)
        return 'nav %d %d %d %d %d %s' % (seq, t_ns, sseq, flags, health, ' '.join(fmt_g(x) for x in v))
    if ftype == STATUS:
        return 'status %d %s' % (seq, ' '.join(str(x) for x in struct.unpack('<5I', p)))
    if ftype == INFO:
        rate, flags = struct.unpack_from('<dI', p, 0)
        sensor = p[12:44].split(b'\0')[0].decode('ascii')
        axes = p[44:92].split(b'\0')[0].decode('ascii')
        return 'info %d %.17g %d %s|%s' % (seq, rate, flags, sensor, axes)
    if ftype == END:
        return 'end %d %d' % (seq, struct.unpack('<I', p)[0])
    return 'unknown %d %d %d' % (seq, ftype, len(p))


def decode(stream):
    """Reference decoder, from the specification (docs/wire-protocol.md):
    search the sync word; a known type must have its length; a whole frame
    must pass the CRC; on any failure discard one byte and search again; a
    corrupt frame that starts inside the extent of one already counted is
    not counted again, unless a valid frame was delivered since (a valid
    frame ends the extent: the counted candidate was false). Sequence: a forward jump of k < 32768 counts one gap
    and k lost frames; a backward jump counts a reset."""
    buf = bytearray(stream)
    out = []
    st = dict(frames=0, bad_frames=0, skipped_bytes=0, lost=0, gaps=0, resets=0, unknown=0)
    bad_until = 0
    expect = None
    i = 0
    n = len(buf)
    while i < n:
        def skip():
            nonlocal i, bad_until
            st['skipped_bytes'] += 1
            i += 1
            bad_until = max(0, bad_until - 1)

        def reject(extent):
            nonlocal bad_until
            if bad_until == 0:
                st['bad_frames'] += 1
                bad_until = extent
            skip()

        if buf[i] != 0xA5:
            skip()
            continue
        if i + 1 >= n:
            break  # incomplete: stays buffered
        if buf[i + 1] != 0x5A:
            skip()
            continue
        if i + 6 > n:
            break
        ftype, ln = buf[i + 2], buf[i + 3]
        if ftype in KNOWN_LEN and KNOWN_LEN[ftype] != ln:
            reject(6)
            continue
        total = 6 + ln + 4
        if i + total > n:
            break
        body = bytes(buf[i + 2:i + 6 + ln])
        crc = struct.unpack_from('<I', buf, i + 6 + ln)[0]
        if zlib.crc32(body) & 0xffffffff != crc:
            reject(total)
            continue
        seq = struct.unpack_from('<H', buf, i + 4)[0]
        st['frames'] += 1
        if ftype not in KNOWN_LEN:
            st['unknown'] += 1
        if expect is not None and seq != expect:
            gap = (seq - expect) & 0xffff
            if gap < 0x8000:
                st['gaps'] += 1
                st['lost'] += gap
            else:
                st['resets'] += 1
        expect = (seq + 1) & 0xffff
        out.append(describe(ftype, seq, bytes(buf[i + 6:i + 6 + ln])))
        i += total
        bad_until = 0
    return out, st


def clean_frames():
    fr = []
    seq = 65530  # the counter wraps inside the stream
    fr.append(frame(INFO, seq, struct.pack('<dI', 400.0, 0x7) + text('golden-vector', 32) +
                    text('x fwd, y left, z up at rest', 48)))
    samples = [
        (1000000000, 7, 2, (0.125, -0.5, 9.80665), (0.001, -0.002, 0.003), 21.5),
        (1002500000, 8, 3, (-156.9064, 156.9064, -0.0), (34.906585, -34.906585, 0.5), 22.0),
        (1002500000, 9, 2, (1e-7, 3.4e38, -1.17549435e-38), (6.283185307, 0.0, -1.5), 0.0),
        (-5, 4294967295, 0, (1.0, 2.0, 3.0), (4.0, 5.0, 6.0), -40.25),
    ]
    for t, sseq, flags, a, g, temp in samples:
        seq = (seq + 1) & 0xffff
        fr.append(frame(SAMPLE, seq, sample_payload(t, sseq, flags, [f32(x) for x in a],
                                                   [f32(x) for x in g], f32(temp))))
    seq = (seq + 1) & 0xffff
    fr.append(frame(NAV, seq, nav_payload(1002500000, 9, 0x5, 0x80000001, (12.5, -3.25, 0.0625),
                                          (1.5, 0.0, -0.125), (0.01, -0.02, 3.1415927))))
    seq = (seq + 1) & 0xffff
    fr.append(frame(STATUS, seq, struct.pack('<5I', 4, 1, 0, 2, 123456)))
    seq = (seq + 1) & 0xffff
    fr.append(frame(0x7E, seq, b'future payload'))
    seq = (seq + 1) & 0xffff
    fr.append(frame(END, seq, struct.pack('<I', 4)))
    return fr


def build():
    fr = clean_frames()
    clean = b''.join(fr)
    lines, st = decode(clean)
    assert st['frames'] == len(fr) and st['bad_frames'] == 0 and st['lost'] == 0
    # damage: garbage (with a lone sync byte) before the first frame
    bad = b'\x00\xa5\x13\xa5'
    bad += fr[0]
    # a flipped bit in a sample payload
    f = bytearray(fr[1]); f[20] ^= 0x10; bad += bytes(f)
    # a truncated frame (first 17 bytes), then a whole one
    bad += fr[2][:17] + fr[2]
    # fr[3] dropped: one lost frame
    # a known type (NAV) announced with a wrong length
    bad += SYNC + bytes([NAV, 40, 0, 0]) + b'\x11' * 8
    bad += fr[4]
    # a false sync word inside garbage, announcing a long unknown frame
    bad += SYNC + bytes([0x33, 200]) + b'\x00' * 10
    # the frames inside that false frame's extent are found once its CRC fails
    # (idle-line zeros complete the false frame); a damaged STATUS frame after
    # the first of them, still inside that extent, counts as a corrupt frame of
    # its own; a duplicated STATUS frame makes the sequence go backwards
    f = bytearray(fr[6]); f[8] ^= 0x01
    bad += fr[5] + bytes(f) + fr[6] + fr[6] + fr[7] + fr[8]
    bad += b'\x00' * 80
    bad += b'\xa5\x5a\x01'  # trailing partial header
    clines, cst = decode(bad)
    return {
        'frames.bin': clean,
        'frames.txt': ('\n'.join(lines) + '\n').encode(),
        'corrupt.bin': bad,
        'corrupt.txt': ('\n'.join(clines) + '\n' +
                        'stats %d %d %d %d %d %d %d\n' % (cst['frames'], cst['bad_frames'], cst['skipped_bytes'],
                                                           cst['lost'], cst['gaps'], cst['resets'],
                                                           cst['unknown'])).encode(),
    }


def main():
    out = build()
    check = '--check' in sys.argv[1:]
    status = 0
    for name, data in sorted(out.items()):
        path = os.path.join(HERE, name)
        if check:
            try:
                with open(path, 'rb') as fh:
                    old = fh.read()
            except OSError:
                old = None
            if old != data:
                print('gen_wire: %s differs from the regenerated vector' % name)
                status = 1
        else:
            with open(path, 'wb') as fh:
                fh.write(data)
    return status


if __name__ == '__main__':
    sys.exit(main())
