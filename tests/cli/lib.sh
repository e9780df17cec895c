# Sourced by the CLI tests after they set T (their scratch directory): a
# tally of passed and failed checks, and checks of a command's exit status,
# standard error and standard output (kept in $T/err and $T/out).
fails=0
pass() { echo "ok   $1"; }
fail() { echo "FAIL $1"; fails=$((fails + 1)); }
expect_exit() { # expected-code description command...
    want=$1; what=$2; shift 2
    "$@" >"$T/out" 2>"$T/err"; got=$?
    if [ "$got" -eq "$want" ]; then pass "$what (exit $got)"; else fail "$what: exit $got, expected $want"; cat "$T/err"; fi
}
expect_err() { # pattern description: checks $T/err
    if grep -q -- "$1" "$T/err"; then pass "$2"; else fail "$2: stderr lacks '$1'"; cat "$T/err"; fi
}
expect_out() { # pattern description: checks $T/out
    if grep -q -- "$1" "$T/out"; then pass "$2"; else fail "$2: stdout lacks '$1'"; cat "$T/out"; fi
}
expect_out_re() { # extended-regex description: checks $T/out (anchor with ^ and $ for a whole line)
    if grep -q -E -- "$1" "$T/out"; then pass "$2"; else fail "$2: stdout lacks /$1/"; cat "$T/out"; fi
}
json() { # json FILE PYTHON-EXPRESSION-ON-j: passes when it is true (uses $PY, /usr/bin/python3 if unset)
    "${PY:-/usr/bin/python3}" -c 'import json,sys; j=json.load(open(sys.argv[1])); sys.exit(0 if eval(sys.argv[2]) else 1)' "$1" "$2" 2>"$T/pyerr"
}
csv_rect() { # csv_rect FILE FIRST: passes when FILE, past its '#' lines, is a header starting FIRST and >= 2 rows each as wide
    "${PY:-/usr/bin/python3}" -c 'import csv, sys
rows = list(csv.reader(l for l in open(sys.argv[1]) if not l.startswith("#")))
sys.exit(0 if len(rows) > 2 and rows[0][0] == sys.argv[2] and all(len(r) == len(rows[0]) for r in rows) else 1)' "$1" "$2" 2>"$T/pyerr"
}
bin_rate() { # bin_rate IN OUT HZ: a .bin with its header's rate set to HZ and marked nominal (flags bit 0), the header CRC made again (docs/log-format.md)
    "${PY:-/usr/bin/python3}" -c 'import struct, sys, zlib
b = bytearray(open(sys.argv[1], "rb").read())
struct.pack_into("<I", b, 12, struct.unpack_from("<I", b, 12)[0] | 1)
struct.pack_into("<d", b, 16, float(sys.argv[3]))
struct.pack_into("<I", b, 188, zlib.crc32(bytes(b[:188])) & 0xffffffff)
open(sys.argv[2], "wb").write(b)' "$@"
}
sigint_default() { # command... &: run it in the background with SIGINT at its default (a script's background job starts with it ignored, which the harness leaves so); it execs, so that $! is the command's pid: never in the foreground
    exec "${PY:-/usr/bin/python3}" -c 'import os, signal, sys; signal.signal(signal.SIGINT, signal.SIG_DFL); os.execv(sys.argv[1], sys.argv[1:])' "$@"
}
fake_gnuplot() { # DIR: a stand-in gnuplot there that keeps its script in $GP_SCRIPT and writes the output file
    # (a PNG's signature and its IEND chunk: the smallest picture the harness takes for a whole one)
    mkdir -p "$1"
    cat >"$1/gnuplot" <<'GP'
#!/bin/sh
cat >"$GP_SCRIPT"
out=$(sed -n "s/^set output '\(.*\)'$/\1/p" "$GP_SCRIPT" | head -n 1)
[ -n "$out" ] && printf '\211PNG\r\n\032\n\000\000\000\000IEND\256B`\202' >"$out"
exit 0
GP
    chmod +x "$1/gnuplot"
}
fake_gnuplot_cut() { # DIR: a stand-in gnuplot that exits 0 with its picture cut short (a PNG signature, no IEND
    # chunk), as pngcairo does on a full disk
    mkdir -p "$1"
    cat >"$1/gnuplot" <<'GP'
#!/bin/sh
s=$(cat)
out=$(printf '%s\n' "$s" | sed -n "s/^set output '\(.*\)'$/\1/p" | head -n 1)
[ -n "$out" ] && printf '\211PNG\r\n\032\n\000\000\000\rIHDR' >"$out"
exit 0
GP
    chmod +x "$1/gnuplot"
}
fake_gnuplot_fail() { # DIR: a stand-in gnuplot that fails partway: it reads its script, starts the output file
    # (a PNG signature, no image; GP_TOUCH=0: leaves it alone, as a gnuplot failing before its set output) and exits 1
    mkdir -p "$1"
    cat >"$1/gnuplot" <<'GP'
#!/bin/sh
s=$(cat)
out=$(printf '%s\n' "$s" | sed -n "s/^set output '\(.*\)'$/\1/p" | head -n 1)
[ "${GP_TOUCH:-1}" = 1 ] && [ -n "$out" ] && printf '\211PNG\r\n' >"$out"
exit 1
GP
    chmod +x "$1/gnuplot"
}
