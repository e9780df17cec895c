#!/usr/bin/env python3
"""Golden vectors for the footnav .bin log format v1 (docs/log-format.md).

An independent writer of the format, written from the specification with
Python's struct and zlib.crc32 (not from the C code). It produces:
  sample_v1.bin  - a small log: header + 6 sample records + end record
  sample_v1.csv  - the same samples as CSV interchange (t,ax,ay,az,gx,gy,gz,temp)
The C tests (tests/test_log.c) read sample_v1.bin and must get exactly the
values of sample_v1.csv, and the C writer must reproduce sample_v1.bin byte
for byte from sample_v1.csv.

  /usr/bin/python3 vectors/logformat/gen_logformat.py          # (re)write
  /usr/bin/python3 vectors/logformat/gen_logformat.py --check  # compare
"""
import os
import struct
import sys
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))

def f32(x):
    """Round a Python float to float32 and back."""
    return struct.unpack('<f', struct.pack('<f', x))[0]

def header(rate_hz, flags, sensor, axes, source):
    def field(s, n):
        b = s.encode('ascii')[:n - 1]
        return b + b'\0' * (n - len(b))
    h = b'FNAV' + struct.pack('<HHHHI', 1, 192, 48, 0, flags) + struct.pack('<d', rate_hz)
    h += field(sensor, 32) + field('m/s^2 rad/s degC ns', 24) + field(axes, 48) + field(source, 60)
    assert len(h) == 188
    return h + struct.pack('<I', zlib.crc32(h) & 0xffffffff)

def record(rtype, flags, seq, t_ns, vals):
    r = struct.pack('<HHIq', rtype, flags, seq, t_ns) + struct.pack('<7f', *vals)
    assert len(r) == 44
    return r + struct.pack('<I', zlib.crc32(r) & 0xffffffff)

# Samples: a duplicate time stamp (seq 3 and 4 share t), a gap (seq 6 missing),
# negative and tiny values, temperature present.
SAMPLES = [
    (0, 0,          (0.125, -0.5, 9.80665, 0.001, -0.002, 0.003), 21.5),
    (1, 2500000,    (0.25, -0.375, 9.75, 0.0105, -1.25e-5, 3.0), 21.5),
    (2, 5000000,    (-3.5, 1.0e-7, 12.0, -6.283185307, 0.0, 1.5), 21.625),
    (3, 7500000,    (1.0, 2.0, 3.0, 4.0, 5.0, 6.0), 21.75),
    (4, 7500000,    (1.0, 2.0, 3.0, 4.0, 5.0, 6.0), 21.75),
    (6, 12500000,   (-156.9064, 156.9064, -0.0, 34.906585, -34.906585, 0.5), 22.0),
]

def build():
    flags = 0x1 | 0x2 | 0x4  # rate nominal, temperature, sensor counter
    out = header(400.0, flags, 'golden-vector', 'x fwd, y left, z up', 'vectors/logformat')
    csv = ['t,ax,ay,az,gx,gy,gz,temp']
    for seq, t_ns, v, temp in SAMPLES:
        vals = [f32(x) for x in v] + [f32(temp)]
        out += record(0xA501, 0x1, seq, t_ns, vals)
        csv.append('%d.%09d,%s' % (t_ns // 10**9, t_ns % 10**9,
                                   ','.join('%.9g' % x for x in vals)))
    out += record(0xA5E0, 0, len(SAMPLES), SAMPLES[-1][1], [0.0] * 7)
    return out, ('\n'.join(csv) + '\n').encode('ascii')

def main():
    bin_bytes, csv_bytes = build()
    paths = {os.path.join(HERE, 'sample_v1.bin'): bin_bytes,
             os.path.join(HERE, 'sample_v1.csv'): csv_bytes}
    if '--check' in sys.argv:
        ok = True
        for p, b in paths.items():
            if not os.path.exists(p) or open(p, 'rb').read() != b:
                print('mismatch:', p)
                ok = False
        sys.exit(0 if ok else 1)
    for p, b in paths.items():
        with open(p, 'wb') as f:
            f.write(b)
    print('wrote', ', '.join(sorted(paths)))

if __name__ == '__main__':
    main()
