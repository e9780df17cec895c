#!/bin/sh
# CLI tests of the command line itself: option and number parsing shared by
# every command (harness/hx_cli.c, hx_nav.c's --param), and `harness help`.
# $HARNESS is the harness binary (set by `make test-cli`).
set -u
H=${HARNESS:-bin/harness}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"

# --- --param switches (adaptive, lever, settle, zaru, closed_form) are 0 or 1:
# zaru=0.5 was cast to int and turned the ZARU off, zaru=-1 or 2 turned it on,
# zaru=1e20 was an undefined double-to-int conversion, all with exit 0
for v in 0.5 -1 2 1e20; do
    expect_exit 2 "--param zaru=$v refused" "$H" replay vectors/walk.bin --quiet --param "zaru=$v"
    expect_err "zaru" "--param zaru=$v: the error names the key"
done
expect_err "0 or 1" "--param switch error says what it takes"
expect_exit 0 "--param zaru=1 accepted" "$H" replay vectors/walk.bin --quiet --param zaru=1
expect_exit 0 "--param lever=0 accepted" "$H" replay vectors/walk.bin --quiet --param lever=0

# --- a lever random walk whose square overflows float32 (fnav_ukf_init): not
# a run with exit 0, the covariance guard clamping the lever's variance at
# every step (47,493 times on gx2 walk 2)
expect_exit 2 "--param lever_rw=1e20 refused" "$H" replay vectors/walk.bin --quiet --param lever_rw=1e20
expect_err "out of range" "--param lever_rw=1e20: the error says the value is out of range"
expect_exit 0 "--param lever_rw=0 accepted" "$H" replay vectors/walk.bin --quiet --param lever_rw=0
# --- an initial yaw sd beyond what the UKF's sigma points represent: taken,
# it would shrink at the first prediction (yaw_sd_deg=90 reads 32.4 deg a
# sample later); refused, naming the largest
expect_exit 2 "--param yaw_sd_deg=90 refused" "$H" replay vectors/walk.bin --quiet --param yaw_sd_deg=90
expect_err "yaw_sd_deg = 90 deg is above 40.5 deg, the largest initial attitude sd" \
    "--param yaw_sd_deg=90: the error names the largest sd (18 states)"
expect_exit 2 "--param tilt_sd_deg=41 refused" "$H" replay vectors/walk.bin --quiet --param tilt_sd_deg=41
expect_err "tilt_sd_deg = 41 deg is above 40.5 deg" "--param tilt_sd_deg=41: named"
expect_exit 0 "--param yaw_sd_deg=40 accepted" "$H" replay vectors/walk.bin --quiet --param yaw_sd_deg=40

# --- `harness help CMD` is CMD's help (not the list of commands), and
# `harness help nosuch` does not exit 0
expect_exit 0 "harness help" "$H" help
expect_out "^commands:" "harness help lists the commands"
expect_exit 0 "harness help replay" "$H" help replay
expect_out "^usage: harness replay LOG" "harness help replay is replay's help"
expect_out "^  --param KEY=VALUE" "harness help replay lists replay's options"
expect_exit 0 "harness --help info" "$H" --help info
expect_out "^usage: harness info LOG" "harness --help info is info's help"
expect_exit 2 "harness help of an unknown command" "$H" help nosuch
expect_err "unknown command 'nosuch'" "harness help nosuch names the command"
if [ -s "$T/out" ]; then fail "harness help nosuch wrote to standard output"; else pass "harness help nosuch: nothing on standard output"; fi
expect_exit 2 "harness help with two commands" "$H" help info replay
# `help help` (and `help --help`, `--help help`) is the general help, as
# `help` alone (not "unknown command 'help'", exit 2)
for w in "help help" "help --help" "--help help" "help -h"; do
    # shellcheck disable=SC2086
    expect_exit 0 "harness $w" "$H" $w
    expect_out "^commands:" "harness $w lists the commands"
done
# the list of commands on a full disk is a write error, as every command's
# output is (not exit 0)
if [ -w /dev/full ]; then
    "$H" --help >/dev/full 2>"$T/err"; rc=$?
    [ "$rc" -eq 3 ] && pass "harness --help >/dev/full exits 3" || fail "harness --help >/dev/full: exit $rc, expected 3"
    "$H" help info >/dev/full 2>"$T/err"; rc=$?
    [ "$rc" -eq 3 ] && pass "harness help info >/dev/full exits 3" || fail "harness help info >/dev/full: exit $rc, expected 3"
fi

# --- `harness --version` (or -V) prints footnav's version, the one of
# include/footnav/fnav_version.h, and exits 0; every JSON output carries it
# as `footnav_version`. Nothing reported a version before (--version was an
# unknown command, exit 2).
HV=$(awk '$1 == "#define" && $2 == "FNAV_VERSION_MAJOR" { a = $3 } $1 == "#define" && $2 == "FNAV_VERSION_MINOR" { b = $3 }
    $1 == "#define" && $2 == "FNAV_VERSION_PATCH" { c = $3 } END { if (a != "" && b != "" && c != "") print a "." b "." c }' \
    include/footnav/fnav_version.h 2>/dev/null)
if [ -n "$HV" ]; then pass "fnav_version.h defines the version ($HV)"; else fail "fnav_version.h: no FNAV_VERSION_MAJOR/MINOR/PATCH"; fi
for o in --version -V; do
    expect_exit 0 "harness $o" "$H" "$o"
    if [ "$(cat "$T/out")" = "harness (footnav) $HV" ]; then pass "harness $o prints 'harness (footnav) $HV' alone"
    else fail "harness $o printed '$(cat "$T/out")', expected 'harness (footnav) $HV'"; fi
    if [ -s "$T/err" ]; then fail "harness $o wrote to standard error"; else pass "harness $o: nothing on standard error"; fi
done
expect_exit 2 "harness --version with an argument" "$H" --version info
expect_err "takes no argument" "harness --version info: the error says --version takes no argument"
expect_exit 0 "harness --help" "$H" --help
expect_out "^ *harness --version" "harness --help names --version"
if [ -w /dev/full ]; then
    "$H" --version >/dev/full 2>"$T/err"; rc=$?
    [ "$rc" -eq 3 ] && pass "harness --version >/dev/full exits 3" || fail "harness --version >/dev/full: exit $rc, expected 3"
fi
expect_exit 0 "info --json -" "$H" info vectors/walk.bin --json -
if json "$T/out" "j.get('footnav_version') == '$HV' and list(j)[0] == 'footnav_version'"; then
    pass "info's JSON starts with footnav_version $HV"
else fail "info's JSON lacks footnav_version $HV as its first key"; fi
expect_exit 0 "replay --json" "$H" replay vectors/walk.bin --quiet --json "$T/r.json"
if json "$T/r.json" "j.get('footnav_version') == '$HV' and list(j)[0] == 'footnav_version' and j['command'].startswith('harness replay')"; then
    pass "replay's JSON starts with footnav_version $HV, its other keys kept"
else fail "replay's JSON lacks footnav_version $HV as its first key"; fi
expect_exit 0 "psd --json" "$H" psd vectors/walk.bin --json "$T/p.json"
if json "$T/p.json" "j.get('footnav_version') == '$HV' and list(j)[0] == 'footnav_version'"; then
    pass "psd's JSON starts with footnav_version $HV"
else fail "psd's JSON lacks footnav_version $HV as its first key"; fi

# --- numbers on the command line are decimal, finite and the whole value,
# read alike by every option (hx_parse_number): strtod took a hexadecimal
# '0x10' as 16 and skipped leading blanks (' 5' passed, '5 ' did not), while
# the log readers refuse both; each refusal is a usage error naming the option
S="$T/s.bin"
for v in 0x10 " 50" "	50" nan inf 1e999 5x "" -5 0; do
    expect_exit 2 "convert --rate '$v' refused" "$H" convert vectors/walk.bin "$T/c.bin" --rate "$v"
    expect_err "--rate" "convert --rate '$v': the error names the option"
done
expect_exit 2 "psd --nfft ' 64' refused" "$H" psd vectors/walk.bin --nfft " 64" --json "$T/p.json"
expect_err "--nfft ' 64' is not a number (give a whole number in \[8, 4096\])" "psd --nfft ' 64': the error names the option"
expect_exit 2 "psd --nfft 99999999999999999999 refused" "$H" psd vectors/walk.bin --nfft 99999999999999999999
expect_exit 2 "sim --duration 0x2 refused" "$H" sim --out "$S" --duration 0x2
expect_err "--duration '0x2' is not a number" "sim --duration 0x2: the error names the option"
expect_exit 2 "--param gamma=0x1p17 refused" "$H" replay vectors/walk.bin --quiet --param gamma=0x1p17
expect_err "gamma" "--param gamma=0x1p17: the error names the key"
expect_exit 2 "--param 'gamma= 1e5' refused" "$H" replay vectors/walk.bin --quiet --param "gamma= 1e5"
expect_exit 2 "sim --effect offset:value=0x1 refused" "$H" sim --out "$S" --duration 2 --effect offset:value=0x1
expect_err "value" "sim --effect offset:value=0x1: the error names the parameter"
expect_exit 2 "sim --mount 0x1,0,0 refused" "$H" sim --out "$S" --duration 2 --mount 0x1,0,0
expect_exit 2 "sim --mount '1, 0,0' refused" "$H" sim --out "$S" --duration 2 --mount "1, 0,0"
expect_err "--mount" "sim --mount: the error names the option"
expect_exit 2 "sim --motion stand:0x2 refused" "$H" sim --out "$S" --motion stand:0x2
expect_exit 2 "sim --motion 'stand: 2' refused" "$H" sim --out "$S" --motion "stand: 2"
expect_exit 2 "simgap-validate --mag-range 0x1,10 refused" "$H" simgap-validate --mag-range 0x1,10 --cases 1 --only 1
expect_err "--mag-range '0x1,10'" "--mag-range 0x1,10: the error names the option"
expect_exit 2 "simgap-validate --mag-range '1, 10' refused" "$H" simgap-validate --mag-range "1, 10" --cases 1 --only 1
expect_err "--mag-range '1, 10'" "--mag-range '1, 10': the error names the option"
# what stays accepted: signs, a point, an exponent, -0 where 0 is allowed;
# and read as the value it spells: the output is the plain spelling's, which
# differs from the option's default (the exit status alone passed a parser
# that took "+1e2" as 1 or "1.5E5" as 1.5)
same_as() { # WHAT FILE_A FILE_B DEFAULT_FILE
    if cmp -s "$2" "$3" && ! cmp -s "$3" "$4"; then pass "$1: the plain spelling's output, not the default's"
    else fail "$1: output differs from the plain spelling's, or the value had no effect"; fi
}
"$H" convert vectors/walk.bin "$T/c100.bin" --rate 100 >/dev/null 2>&1
"$H" convert vectors/walk.bin "$T/c0.bin" >/dev/null 2>&1
expect_exit 0 "convert --rate +1e2" "$H" convert vectors/walk.bin "$T/c.bin" --rate +1e2
same_as "convert --rate +1e2" "$T/c.bin" "$T/c100.bin" "$T/c0.bin"
expect_exit 0 "convert --rate 100." "$H" convert vectors/walk.bin "$T/c.bin" --rate 100.
same_as "convert --rate 100." "$T/c.bin" "$T/c100.bin" "$T/c0.bin"
"$H" sim --out "$T/m_plain.bin" --duration 0.5 --mount -1.5,0,2 --motion stand:0.5 >/dev/null 2>&1
"$H" sim --out "$T/m_none.bin" --duration 0.5 --motion stand:0.5 >/dev/null 2>&1
expect_exit 0 "sim --duration .5 --mount -1.5,0,2e0 --motion stand:0.5" "$H" sim --out "$S" --duration .5 --mount -1.5,0,2e0 --motion stand:0.5
same_as "sim --duration .5 --mount -1.5,0,2e0" "$S" "$T/m_plain.bin" "$T/m_none.bin"
"$H" replay vectors/walk.bin --quiet --param gamma=150000 --out "$T/g_plain.csv" >/dev/null 2>&1
"$H" replay vectors/walk.bin --quiet --out "$T/g_none.csv" >/dev/null 2>&1
expect_exit 0 "--param gamma=1.5E5" "$H" replay vectors/walk.bin --quiet --param gamma=1.5E5 --out "$T/g.csv"
same_as "--param gamma=1.5E5" "$T/g.csv" "$T/g_plain.csv" "$T/g_none.csv"
"$H" sim --out "$T/r_plain.bin" --motion stand:1,walk:3,stand:1 --ring-scale 0 >/dev/null 2>&1
"$H" sim --out "$T/r_none.bin" --motion stand:1,walk:3,stand:1 >/dev/null 2>&1
expect_exit 0 "sim --ring-scale -0" "$H" sim --out "$S" --motion stand:1,walk:3,stand:1 --ring-scale -0
same_as "sim --ring-scale -0" "$S" "$T/r_plain.bin" "$T/r_none.bin"

# --- a range in an error is printed exactly: "--seed '4294967296' is not a
# number in [0, 4.29497e+09]" read as if the value were inside it
expect_exit 2 "sim --seed 4294967296 refused" "$H" sim --out "$T/s.bin" --seed 4294967296
expect_err "--seed '4294967296' is out of range (give a [a-z ]*number in \[0, 4294967295\])" "the --seed range is printed exactly"
expect_exit 2 "live --timeout 0.01 refused" "$H" live /dev/null --timeout 0.01
expect_err "--timeout '0.01' is out of range (give a number in \[0.1, 1000000\])" "the --timeout range is printed exactly"
# 0 is a whole number: "--hangup-after '0' is not a whole number in [1, ...]"
# read as if it were not; each fault is said as what it is
expect_exit 2 "stream --hangup-after 0 refused" "$H" stream vectors/walk.bin "$T/no_port" --hangup-after 0
expect_err "--hangup-after '0' is out of range (give a whole number in \[1, 2000000000\])" "a whole number out of range is said to be out of range"
expect_exit 2 "stream --hangup-after abc refused" "$H" stream vectors/walk.bin "$T/no_port" --hangup-after abc
expect_err "--hangup-after 'abc' is not a number (give a whole number in \[1, 2000000000\])" "text is said to be no number"

# --- a missing positional argument is named ("missing argument" alone left
# the reader to count them against the usage)
expect_exit 2 "info without LOG" "$H" info
expect_err "error: missing argument LOG" "info: the missing LOG is named"
expect_exit 2 "stream without PORT" "$H" stream vectors/walk.bin
expect_err "error: missing argument PORT" "stream: the missing PORT is named"
expect_exit 2 "convert without OUT" "$H" convert vectors/walk.bin
expect_err "error: missing argument OUT" "convert: the missing OUT is named"

# --- an option whose name and value are wider than the usage's column has its
# help on the next line ("--filter-profile NAME|FILE the filter's sensor
# profile" ran the value into the help)
expect_exit 0 "montecarlo --help" "$H" montecarlo --help
expect_out_re "^  --filter-profile NAME\|FILE$" "a wide option stands on its own line"
expect_out_re "^ {25}the filter's sensor profile" "its help follows on the next line, in the column"

# --- info's rate of a time-stamped text log is estimated from the stamps of
# its first 4,096 samples, as every command's (hx_reader_open), while the
# interval line is of the whole log (docs/harness.md, not 1 / the median
# interval), and pyshoe's 2017-11-22-11-22-03_imu.csv reads "rate 200.000 Hz"
# beside "median 4.998 ms" (its first 4,096 intervals have a median of 5.000 ms)
awk 'BEGIN { print "t,ax,ay,az,gx,gy,gz"; t = 0; for (k = 0; k < 9100; k++) { printf "%.6f,0,0,9.8,0,0,0\n", t; t += (k < 4100 ? 0.010 : 0.010002) } }' > "$T/r.csv"
expect_exit 0 "info on a log whose interval grows by 2 us after 4,100 samples" "$H" info "$T/r.csv"
# (stamps exact to the period, every interval the same: a grid, whose median
# interval is exact, and the line says so; stamps no finer than the period
# are not all "coarse", with the line saying "their mean interval without
# gaps", the same 100 Hz)
expect_out "^rate        100.000 Hz (from the time stamps of the first 4,096 samples: 1 / their median interval)$" "the rate is of the first 4,096 samples, and the line says so"
expect_out "^interval    median 10.002 ms" "the interval line is of the whole log"
grep -q "first 4,096 samples" docs/harness.md && pass "docs/harness.md says the rate is of the first 4,096 samples" ||
    fail "docs/harness.md does not say that info's rate comes from the first 4,096 samples"

# --- info --json's counter_drops is null for a log without a sensor counter
# (the text leaves its drops line out), not 0, "no drops", for the xio,
# OpenShoe 820 Hz and footprint logs; a square2 log counts its samples, and
# three missing counter values are 3
awk 'BEGIN { print "sample,f_x_mps2,f_y_mps2,f_z_mps2,w_x_radps,w_y_radps,w_z_radps"; for (k = 0; k < 1000; k++) if (k < 500 || k > 502) printf "%d,0,0,-9.8,0,0,0\n", k }' > "$T/sq.csv"
expect_exit 0 "info --json, a log with a counter" "$H" info "$T/sq.csv" --json "$T/sq.json"
expect_out "^drops       3 (missing sensor counter values)$" "the text counts the drops"
json "$T/sq.json" "j['counter_drops'] == 3" && pass "counter_drops is the number of missing counter values" ||
    fail "counter_drops with a counter: $(grep -o '"counter_drops":[^,]*' "$T/sq.json")"
expect_exit 0 "info --json, a log without a counter" "$H" info "$T/r.csv" --json "$T/nc.json"
grep -q "^drops" "$T/out" && fail "a drops line without a counter" || pass "no drops line without a counter"
json "$T/nc.json" "'counter_drops' in j and j['counter_drops'] is None" && pass "counter_drops is null without a counter" ||
    fail "counter_drops without a counter: $(grep -o '"counter_drops":[^,]*' "$T/nc.json")"
# a sensor counter that steps back (rows out of order, a restarted counter)
# is a timing fault said with its count and first place, on standard output
# and standard error (info was silent: the drops count only steps forward);
# JSON counter_backwards, null without a counter. A .bin whose seq is
# marked the sensor's (flags bit 2, docs/log-format.md) and set 50 back at
# samples 1001-1003 and 1501 (0-based records 1000-1002, 1500)
awk 'BEGIN { print "t,ax,ay,az,gx,gy,gz"; for (k = 0; k < 2000; k++) printf "%.2f,0,0,-9.8,0,0,0\n", k / 100 }' > "$T/seq.csv"
"$H" convert "$T/seq.csv" "$T/seq.bin" 2>/dev/null || fail "convert for the counter check"
"${PY:-/usr/bin/python3}" -c 'import struct, sys, zlib
b = bytearray(open(sys.argv[1], "rb").read())
struct.pack_into("<I", b, 12, struct.unpack_from("<I", b, 12)[0] | 4)
struct.pack_into("<I", b, 188, zlib.crc32(bytes(b[:188])) & 0xffffffff)
for k in (1000, 1001, 1002, 1500):
    o = 192 + 48 * k
    struct.pack_into("<I", b, o + 4, struct.unpack_from("<I", b, o + 4)[0] - 50)
    struct.pack_into("<I", b, o + 44, zlib.crc32(bytes(b[o:o + 44])) & 0xffffffff)
open(sys.argv[2], "wb").write(b)' "$T/seq.bin" "$T/seqback.bin"
expect_exit 0 "info, a counter that steps back" "$H" info "$T/seqback.bin" --json "$T/seqback.json"
expect_out "^counter     steps back 2 times, first at sample 1001 (t = 10.000 s: 950 after 999)$" "info: the counter's steps back counted, the first placed"
expect_err "^harness info: warning: $T/seqback.bin: the sensor counter steps back 2 times (first at sample 1001, t = 10.000 s: 950 after 999)" \
    "info: the counter's steps back warned"
json "$T/seqback.json" "j['counter_backwards'] == 2" && pass "counter_backwards counts the steps back" ||
    fail "counter_backwards: $(grep -o '"counter_backwards":[^,]*' "$T/seqback.json")"
json "$T/sq.json" "j['counter_backwards'] == 0" && json "$T/nc.json" "'counter_backwards' in j and j['counter_backwards'] is None" &&
    pass "counter_backwards 0 with a counter that advances, null without a counter" || fail "counter_backwards: $(cat "$T/pyerr")"
expect_exit 0 "info, a log with a counter that advances" "$H" info "$T/sq.csv"
grep -q "^counter" "$T/out" && fail "a counter line for a counter that advances" || pass "no counter line for a counter that advances"
# a .bin header's source (the command that wrote it, or the file a
# conversion read) is a `source` line and JSON key, as in a file that holds
# no sample (the header alone); null for a format whose header has none
"$H" sim --duration 2 --out "$T/simsrc.bin" > /dev/null 2>&1 || fail "sim for the source check"
expect_exit 0 "info, a simulated .bin" "$H" info "$T/simsrc.bin" --json "$T/simsrc.json"
expect_out "^source      harness sim --motion walk --seed 1$" "info: a .bin's source line names the command that wrote it"
json "$T/simsrc.json" "j['source'] == 'harness sim --motion walk --seed 1'" && pass "JSON source: the .bin header's" ||
    fail "JSON source: $(grep -o '"source":[^,]*' "$T/simsrc.json")"
expect_exit 0 "info, a converted .bin" "$H" info "$T/seq.bin"
# (the header's field holds 59 bytes: a longer path is cut there)
expect_out "^source      $(printf '%.59s' "$T/seq.csv")$" "info: a converted .bin's source line names the file read"
head -c 192 "$T/simsrc.bin" > "$T/srconly.bin"
expect_exit 1 "info, a .bin header with no sample" "$H" info "$T/srconly.bin" --json "$T/srconly.json"
expect_out "^source      harness sim --motion walk --seed 1$" "info: the source line of a .bin with no sample"
json "$T/srconly.json" "j['source'] == 'harness sim --motion walk --seed 1'" && pass "JSON source of a .bin with no sample" ||
    fail "JSON source, no sample: $(grep -o '"source":[^,]*' "$T/srconly.json")"
expect_exit 0 "info, a CSV" "$H" info "$T/r.csv"
grep -q "^source" "$T/out" && fail "a source line for a CSV" || pass "no source line for a CSV (its reader's source is the path)"
json "$T/nc.json" "'source' in j and j['source'] is None" && pass "JSON source is null for a CSV" ||
    fail "JSON source of a CSV: $(grep -o '"source":[^,]*' "$T/nc.json")"

# --- a repeated option takes its last value, and so does `--json -`'s claim
# on standard output: `info LOG --json - --json F` wrote the JSON to F and
# info's text to standard error, leaving standard output empty; `replay LOG
# --out - --out F --json -` was refused as two outputs on standard output
expect_exit 0 "info --json - --json FILE" "$H" info vectors/walk.bin --json - --json "$T/i.json"
expect_out "^samples     16539" "info's text stays on standard output when a later --json names a file"
json "$T/i.json" "j['samples'] == 16539" && pass "the JSON goes to the last --json" || fail "the last --json FILE was not written"
expect_exit 0 "info --json FILE --json -" "$H" info vectors/walk.bin --json "$T/i2.json" --json -
json "$T/out" "j['samples'] == 16539" && pass "the last --json - writes the JSON alone on standard output" || fail "standard output is not the JSON alone: $(head -c 80 "$T/out")"
expect_exit 0 "replay --out - --out FILE --json -" "$H" replay vectors/walk.bin --quiet --out - --out "$T/t.csv" --json -
json "$T/out" "'return_error_3d_m' in j" && pass "replay's JSON alone on standard output, the trajectory in the later --out" || fail "replay --out - --out F --json -: $(head -c 80 "$T/out")"
expect_exit 2 "replay --out F --out - --json -" "$H" replay vectors/walk.bin --quiet --out "$T/t.csv" --out - --json -
expect_err "cannot both write to standard output" "two outputs on standard output are still refused"
expect_exit 2 "replay --out - --json=-" "$H" replay vectors/walk.bin --quiet --out=- --json=-

# --- allan's and psd's `--out -` is standard output, as replay's, live's and
# eval's: not a file named '-' in the current directory, with the table on
# standard output; and `--out - --json -` is refused as two outputs on
# standard output
awk 'BEGIN { print "t,ax,ay,az,gx,gy,gz"; s = 1; for (i = 0; i < 3000; i++) { s = (s * 1103515245 + 12345) % 2147483648; r = s / 2147483648.0 - 0.5; printf "%.2f,%.4f,%.4f,%.4f,%.5f,%.5f,%.5f\n", i / 100, r / 50, -r / 40, -9.81 + r / 30, r / 1000, -r / 900, r / 800 } }' >"$T/still.csv"
for c in allan psd; do
    rm -f ./-
    opts=""
    [ "$c" = allan ] && opts="--no-sim --quiet"
    expect_exit 0 "$c --out -" "$H" $c "$T/still.csv" $opts --out -
    [ ! -e ./- ] && pass "$c --out - writes no file named '-'" || { fail "$c --out - wrote a file named '-'"; rm -f ./-; }
    expect_out_re "^(channel,unit,tau_s|freq_hz,psd_ax)," "$c --out -: the CSV's header on standard output"
    grep -v '^#' "$T/out" | grep -v -q ',' && fail "$c --out -: text beside the CSV on standard output: $(grep -v '^#' "$T/out" | grep -v ',' | head -n 2)" ||
        pass "$c --out -: the CSV alone on standard output"
    expect_exit 2 "$c --out - --json -" "$H" $c "$T/still.csv" $opts --out - --json -
    expect_err "cannot both write to standard output" "$c: two outputs on standard output refused"
done

# --- replay checks --from and --input-rate as every command that reads a log
# (hx_check_input_opts): it refuses --from auto, as the others do, and words
# the error their way
for c in info replay psd allan simgap; do
    expect_exit 2 "$c --from auto refused" "$H" $c vectors/walk.bin --from auto
    expect_err "unknown input format 'auto' (known: bin, csv" "$c --from auto: the shared message"
    expect_exit 2 "$c --input-rate 0x10 refused" "$H" $c vectors/walk.bin --input-rate 0x10
done

# --- stream's --help lists every exit status (130 / 143, Ctrl-C / SIGTERM
# before the END frame, docs/harness.md "stream", and 129, SIGHUP, among them)
expect_exit 0 "stream --help" "$H" stream --help
expect_out "130 (143, 129) interrupted by Ctrl-C (SIGTERM, SIGHUP)" "stream --help names the status of an interrupted stream"

# --- counts and seeds are whole numbers everywhere (hx_arg_whole): allan cut
# --seed 1.5 to 1 and --sim-samples 100.5 to 100 without a word, while sim
# and montecarlo refused the same values
printf '1\n2\n3\n4\n5\n6\n7\n8\n9\n10\n' > "$T/ten.txt"
expect_exit 2 "allan --seed 1.5 refused" "$H" allan --series "$T/ten.txt" --rate 1 --seed 1.5
expect_err "--seed '1.5' is not a whole number (give one in \[0, 4294967295\])" "allan --seed 1.5: the error names the option"
expect_exit 2 "allan --sim-samples 100.5 refused" "$H" allan --series "$T/ten.txt" --rate 1 --sim-samples 100.5
expect_err "--sim-samples '100.5' is not a whole number" "allan --sim-samples 100.5: the error names the option"
expect_exit 2 "sim --seed 1.5 refused" "$H" sim --out "$T/s.bin" --duration 1 --seed 1.5
expect_err "--seed '1.5' is not a whole number" "sim --seed 1.5: the error names the option"
expect_exit 2 "sim --oversample 2.5 refused" "$H" sim --out "$T/s.bin" --duration 1 --oversample 2.5
expect_err "--oversample '2.5' is not a whole number" "sim --oversample 2.5: the error names the option"
expect_exit 2 "montecarlo --seeds 2.5 refused" "$H" montecarlo --seeds 2.5 --duration 2
expect_err "--seeds '2.5' is not a whole number" "montecarlo --seeds 2.5: the error names the option"
expect_exit 0 "sim --seed 1e3 (a whole number)" "$H" sim --out "$T/s.bin" --duration 1 --seed 1e3
# and the counts read as long (psd's --nfft and --overlap, simgap's --seeds,
# allan's --per-octave ...): strtol refused 1.28e2, a whole number, as
# "not an integer", while montecarlo's --seeds took 1e1
expect_exit 0 "psd --nfft 1.28e2 --overlap 6.4e1 (whole numbers)" "$H" psd vectors/walk.bin --nfft 1.28e2 --overlap 6.4e1 --out "$T/pe.csv"
"$H" psd vectors/walk.bin --nfft 128 --overlap 64 --out "$T/pd.csv" >/dev/null 2>&1
cmp -s "$T/pe.csv" "$T/pd.csv" && pass "psd --nfft 1.28e2 --overlap 6.4e1: the spectrum of --nfft 128 --overlap 64" \
    || fail "psd --nfft 1.28e2 differs from --nfft 128"
expect_exit 2 "psd --nfft 128.5 refused" "$H" psd vectors/walk.bin --nfft 128.5
expect_err "^harness psd: error: --nfft '128.5' is not a whole number (give one in \[8, 4096\])$" "psd --nfft 128.5: a whole number's words and range"

# --- a JSON file is UTF-8 text (RFC 8259) whatever the bytes of a file name
# in it: a Latin-1 byte (0xe9) is the replacement character U+FFFD, a
# quote, a backslash and a UTF-8 'ü' are kept as they are. The byte passed
# through as it is would make a strict reader refuse replay's JSON ("'utf-8'
# codec can't decode byte 0xe9")
NAME=$(printf 'w\351lk"\\\303\274.bin')
cp vectors/walk.bin "$T/$NAME"
for c in replay psd; do
    expect_exit 0 "$c --json of a log whose name is not UTF-8" "$H" $c "$T/$NAME" --json "$T/u8_$c.json"
    if "${PY:-/usr/bin/python3}" -c 'import json, sys
j = json.loads(open(sys.argv[1], "rb").read().decode("utf-8"))
p = j.get("log", j.get("source"))
sys.exit(0 if p.endswith("/w\ufffdlk\"\\\u00fc.bin") else 1)' "$T/u8_$c.json" 2>"$T/pyerr"; then
        pass "$c --json: UTF-8, the Latin-1 byte replaced, the rest of the name kept"
    else fail "$c --json with a Latin-1 file name: $(cat "$T/pyerr") $(head -c 120 "$T/u8_$c.json")"; fi
done
rm -f "$T/$NAME"

# --- --help goes to standard output even beside `--json -` (which had already
# turned standard output over to the JSON and sent the help to standard error)
expect_exit 0 "info --json - --help" "$H" info vectors/walk.bin --json - --help
expect_out "^usage: harness info LOG" "the help is on standard output beside --json -"

# --- a long conversion shows progress on standard error (a day at 100 Hz
# takes 11 s to CSV, which would pass without a word). A reader that
# waits 2 s before it drains standard output holds convert past the 1 s after
# which progress appears, however fast the machine; 200,000 samples.
awk 'BEGIN { print "t,ax,ay,az,gx,gy,gz"; for (i = 0; i < 200000; i++) printf "%.2f,0.01,0.02,-9.81,0.001,0.002,0.003\n", i / 100 }' >"$T/long.csv"
"$H" convert "$T/long.csv" - 2>"$T/err" | (sleep 3; cat >/dev/null)
expect_err "^convert: *[0-9]* % (" "convert of a long log: progress on standard error"
expect_err "^convert: done in" "convert of a long log: the progress ends with the time taken"
# past 2 s and 5 % the progress says how long is left at the rate so far
# (a percentage alone, as montecarlo's, leaves a user guessing)
expect_err "^convert: *[0-9]* % ([0-9.]* s, about [0-9]* s left)$" "convert of a long log: the time left"
rm -f "$T/long.csv"

# --- mistakes a user can make that no other test runs (make
# coverage-harness): the command line, an output that cannot be written, an
# empty log, a stream to a file that is not a serial port. Each is refused
# with its exit status and a message naming what is wrong, and leaves no
# output file behind.
expect_exit 2 "a short option no command has (-x)" "$H" info vectors/walk.bin -x
expect_err "^harness info: error: unknown option '-x'" "-x: named as an unknown option"
expect_err "^usage: harness info LOG" "-x: the usage follows"
expect_exit 2 "a second positional argument to info" "$H" info vectors/walk.bin extra
expect_err "^harness info: error: unexpected argument 'extra'" "the extra argument is named"
expect_exit 2 "a value given to a flag (--quiet=1)" "$H" replay vectors/walk.bin --quiet=1
expect_err "^harness replay: error: option --quiet takes no value" "--quiet=1: the flag takes no value"
expect_exit 2 "convert --to with an unknown format" "$H" convert vectors/walk.bin "$T/to.dat" --to xyz
expect_err "^harness convert: error: --to must be bin or csv, not 'xyz'" "--to xyz: the formats it takes"
[ ! -e "$T/to.dat" ] && pass "--to xyz: nothing written" || fail "--to xyz wrote $T/to.dat"
expect_exit 3 "convert to a directory that does not exist" "$H" convert vectors/walk.bin "$T/nodir/x.csv"
expect_err "^harness convert: error: $T/nodir/x.csv: cannot create (No such file or directory)" \
    "convert: the output and the reason named"
expect_exit 3 "replay --out in a directory that does not exist" "$H" replay vectors/walk.bin --quiet --out "$T/nodir/o.csv"
expect_err "^harness replay: error: cannot write $T/nodir/o.csv" "replay --out: the output named"
rm -f "$T/ok.csv"
expect_exit 3 "replay --strides unwritable beside a writable --out" \
    "$H" replay vectors/walk.bin --quiet --out "$T/ok.csv" --strides "$T/nodir/s.csv"
expect_err "^harness replay: error: cannot write $T/nodir/s.csv (No such file or directory)" "--strides: the output and the reason named"
[ ! -e "$T/ok.csv" ] && pass "--strides unwritable: refused before the run, --out not started" || fail "--strides unwritable: --out written"
expect_exit 3 "allan --profile in a directory that does not exist" "$H" allan vectors/walk.bin --profile "$T/nodir/x.profile"
expect_err "^harness allan: error: cannot write $T/nodir/x.profile (No such file or directory)" "allan --profile: the output and the reason named"
: >"$T/empty.csv"
expect_exit 1 "info on an empty file" "$H" info "$T/empty.csv"
expect_err "^harness info: error: $T/empty.csv: empty file" "the empty file is named as such"
expect_exit 2 "stream --rate with --speed" "$H" stream vectors/walk.bin "$T/port" --rate 100 --speed 2
expect_err "^harness stream: error: --rate and --speed exclude each other" "--rate and --speed: named"
expect_exit 3 "stream to a plain file, not a serial port" "$H" stream vectors/walk.bin "$T/empty.csv"
expect_err "^harness stream: error: $T/empty.csv: not a serial port (not a character device)" "stream: a plain file is not a port"
[ ! -s "$T/empty.csv" ] && pass "stream: the plain file was not written to" || fail "stream wrote into $T/empty.csv"
printf 't,ax,ay,az,gx,gy,gz\n' >"$T/hdr.csv"
expect_exit 1 "stream of a log with a header and no sample" "$H" stream "$T/hdr.csv" "$T/port"
expect_err "^harness stream: error: $T/hdr.csv: no samples" "stream: the empty log named"
[ ! -e "$T/port" ] && pass "stream: no port opened or created for an empty log" || fail "stream created $T/port"

# --- a full disk (/dev/full: every write fails with ENOSPC), run by no other
# test (make coverage-harness): the write failure is an output error, exit 3,
# naming the file, not a success.
if [ -c /dev/full ]; then
    expect_exit 3 "convert onto a full disk" "$H" convert vectors/walk.bin /dev/full
    expect_err "^harness convert: error: /dev/full: write failed (No space left on device)" "convert: the failed write named"
    expect_exit 3 "replay --out onto a full disk" "$H" replay vectors/walk.bin --quiet --out /dev/full
    expect_err "^harness replay: error: cannot write the trajectory to /dev/full (No space left on device)$" "replay: the failed write named, with its reason"
    "$H" sim --motion stand --duration 120 --rate 100 --seed 3 --out "$T/still.bin" >/dev/null 2>&1
    expect_exit 3 "allan --profile onto a full disk" "$H" allan "$T/still.bin" --profile /dev/full
    expect_err "^harness allan: error: /dev/full: write failed (No space left on device)" "allan --profile: the failed write named"
    rm -f "$T/still.bin"
else
    echo "skip the full-disk checks (no /dev/full)"
fi

# --- --from naming a format the file is not (run by no other test: make
# coverage-harness): the importer says what it expected at which
# line, exit 1; refused at the header, no --out is written.
printf 't,ax,ay,az,gx,gy,gz\n0,0,0,9.8,0,0,0\n' >"$T/plain.csv"
rm -f "$T/from.csv"
expect_exit 1 "a footnav CSV given as --from ipol" "$H" replay "$T/plain.csv" --from ipol --quiet --out "$T/from.csv"
expect_err "plain.csv:1: expected 'Acquisition frequency: N Hz'" "--from ipol: the header line it expected"
[ ! -e "$T/from.csv" ] && pass "--from ipol: no --out written" || fail "--from ipol: --out written"
expect_exit 1 "a footnav CSV given as --from gx2" "$H" replay "$T/plain.csv" --from gx2 --quiet --out "$T/from.csv"
expect_err "plain.csv: no 'Header:' line found" "--from gx2: the missing Header: line named"
[ ! -e "$T/from.csv" ] && pass "--from gx2: no --out written" || fail "--from gx2: --out written"
printf 'Header:\n1.0 2.0 3.0\n' >"$T/gx2.txt"
expect_exit 1 "a GX2 file whose first data line is not one" "$H" replay "$T/gx2.txt" --from gx2 --quiet
expect_err "gx2.txt:2: not a GX2 data line" "--from gx2: the line that is not GX2 data named"
# and why: its first field is not the hex command byte a data line starts with (a row that lost that field
# said only "not a GX2 data line"; cli_mutation_sweep.py --seed 100, c0070)
expect_err "gx2.txt:2: not a GX2 data line: its first field ('1.0') is not the command byte in hex (0x..., 0xcb" \
    "--from gx2: what a GX2 data line starts with said"
rm -f "$T/plain.csv" "$T/gx2.txt" "$T/from.csv"

# ... and the header checks of the other importers (run by no other test: make
# coverage-harness), a file of blank lines, and an ipol file with its rate line and no header: exit 1, each named
printf 't,ax,ay,az,gx,gy,gz\n0,0,0,9.8,0,0,0\n' >"$T/plain.csv"
for fc in "pyshoe:t_s:t" "adis:acc_x_g:ax" "square2:sample:t" "ngimu:Time (s):t"; do
    f=${fc%%:*}; c=$(echo "$fc" | cut -d: -f2); k=${fc##*:}
    expect_exit 1 "a footnav CSV given as --from $f" "$H" info "$T/plain.csv" --from "$f"
    expect_err "plain.csv:1: header has no column '$c' (the $k column of the $f format)" "--from $f: the column it expected"
done
printf '\n\n\n' >"$T/blank.txt"
expect_exit 1 "a file of blank lines as --from ipol" "$H" info "$T/blank.txt" --from ipol
expect_err "blank.txt: empty file$" "--from ipol: blank lines are an empty file"
expect_exit 1 "a file of blank lines as CSV" "$H" info "$T/blank.txt" --from csv
expect_err "blank.txt: empty file (no header line)" "--from csv: blank lines, no header line"
printf 'Acquisition frequency: 100 Hz\n\n' >"$T/blank.txt"
expect_exit 1 "an ipol file with its rate line alone" "$H" info "$T/blank.txt" --from ipol
expect_err "blank.txt: empty file (no header line)" "--from ipol: the header line missing after the rate"
rm -f "$T/plain.csv" "$T/blank.txt"

# --- the importers' counters (no other test feeds a bad one; docs/log-format.md): square2's sample
# column and ipol's PacketCounter (time = counter / rate), GX2's Counter and Nr. A bad counter ends the read at
# its line, exit 1, naming the line (and, but for GX2, the value), the samples before it kept; ipol's 16-bit
# counter wraps (65535, 0: one interval on), a drop by less than half its range is time going backwards.
sq_log() { # FILE SAMPLE...: a square2 log, one row per sample value
    f=$1; shift
    { echo "sample,f_x_mps2,f_y_mps2,f_z_mps2,w_x_radps,w_y_radps,w_z_radps"
      for s in "$@"; do echo "$s,0.01,0.02,-9.81,0.001,0.002,0.003"; done; } >"$f"
}
ip_log() { # FILE COUNTER...: an ipol trial's log at 100 Hz, one row per counter value
    f=$1; shift
    { printf 'Acquisition frequency: 100 Hz\nPacketCounter\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\n'
      for s in "$@"; do printf '%s\t0.01\t0.02\t9.81\t0.001\t0.002\t0.003\n' "$s"; done; } >"$f"
}
ctr_bad() { # description expected-message command...: exit 1, the message, 2 samples kept
    d=$1; m=$2; shift 2
    expect_exit 1 "$d" "$@"
    expect_err "$m (using the 2 samples before it)" "$d: the line and the reason named"
    expect_out "^samples     2$" "$d: the samples before it kept"
}
sq_log "$T/sq.csv" 0 1 -1 3
ctr_bad "square2, a negative sample number" "sq.csv:4: counter ('-1') is negative" \
    "$H" info "$T/sq.csv" --from square2
sq_log "$T/sq.csv" 0 1 2.5 3
ctr_bad "square2, a fractional sample number" "sq.csv:4: counter ('2.5') is not a whole number in range" \
    "$H" info "$T/sq.csv" --from square2
sq_log "$T/sq.csv" 0 1 abc 3
ctr_bad "square2, a sample number that is text" "sq.csv:4: counter ('abc') is not a number" \
    "$H" info "$T/sq.csv" --from square2
# beyond 32 bits: said so (not "is not a non-negative number", of a counter that is; nor above 4e9, which 32 bits
# still hold)
sq_log "$T/sq.csv" 0 1 5e9 3
ctr_bad "square2, a sample number beyond 32 bits" "sq.csv:4: counter ('5e9') is beyond 32 bits (4294967295)" \
    "$H" info "$T/sq.csv" --from square2
sq_log "$T/sq.csv" 0 1 4294967296 3
ctr_bad "square2, a sample number one beyond 32 bits" "sq.csv:4: counter ('4294967296') is beyond 32 bits (4294967295)" \
    "$H" info "$T/sq.csv" --from square2
sq_log "$T/sq.csv" 4294967293 4294967294 4294967295
expect_exit 0 "square2, a sample number at the 32-bit maximum" "$H" info "$T/sq.csv" --from square2
expect_out "^samples     3$" "square2, 32-bit maximum: three samples read"
sq_log "$T/sq.csv" 0 1 0 3
ctr_bad "square2, a sample number that goes back" "sq.csv:4: time goes backwards (0.000000000 s after 0.010000000 s)" \
    "$H" info "$T/sq.csv" --from square2
ip_log "$T/ip.txt" 1 2 1.5 3
ctr_bad "ipol, a fractional packet counter" "ip.txt:5: counter ('1.5') is not a whole number in range" \
    "$H" info "$T/ip.txt" --from ipol
ip_log "$T/ip.txt" 1 2 -3 3
ctr_bad "ipol, a negative packet counter" "ip.txt:5: counter ('-3') is negative" "$H" info "$T/ip.txt" --from ipol
ip_log "$T/ip.txt" 100 101 50 51
ctr_bad "ipol, a counter that drops by less than half its range" "ip.txt:5: time goes backwards (0.500000000 s after 1.010000000 s)" \
    "$H" info "$T/ip.txt" --from ipol
ip_log "$T/ip.txt" 65533 65534 65535 0 1 2
expect_exit 0 "ipol, the 16-bit counter wrapping" "$H" info "$T/ip.txt" --from ipol
expect_out "^duration    0.050 s$" "ipol wrap: 65535 to 0 is one interval"
expect_out "^drops       0 " "ipol wrap: no sample counted lost"
ip_log "$T/ip.txt" 65533 65534 65535 2 3
expect_exit 0 "ipol, the counter wrapping over lost packets" "$H" info "$T/ip.txt" --from ipol
expect_out "^duration    0.060 s$" "ipol wrap with 2 lost: 65535 to 2 is three intervals"
expect_out "^drops       2 " "ipol wrap with 2 lost: both counted"
# GX2 (docs/log-format.md, openshoe_gx2): Counter (a clock count) and Nr (a sample number) must be 32-bit counts
GXH='Header:      a_x [g]:      a_y [g]:      a_z [g]: ar_x [rad/s]: ar_y [rad/s]: ar_z [rad/s]:      Counter: Checksum:     Nr:   Filtered ts[s]: Unfiltered ts[s]:      Pred. ts[s]: Freq. [Hz]:      m_x [G]:      m_y [G]:      m_z [G]:'
gx_log() { # FILE COUNTER:NR:TS...: a GX2 log, one row per triple
    f=$1; shift
    { printf 'Inertial data.\n\n%s\n' "$GXH"
      for s in "$@"; do
          printf '   0xcb   -0.10581776   +0.15830289   +0.99007481   +0.00535047   -0.01242570   +0.00101861     %s    0x15fd       %s %s %s %s  250.000001   -0.12299968   -0.01066045   -0.46057537 \n' \
              "${s%%:*}" "$(echo "$s" | cut -d: -f2)" "${s##*:}" "${s##*:}" "${s##*:}"
      done; } >"$f"
}
gx_log "$T/gx.txt" 130516848:1:1000.000 130595568:2:1000.004 130674288:3:1000.008
expect_exit 0 "GX2, three good rows" "$H" info "$T/gx.txt" --from gx2
expect_out "^samples     3$" "GX2: three samples read"
gx_log "$T/gx.txt" 130516848:1:1000.000 130595568:2:1000.004 abc:3:1000.008
ctr_bad "GX2, a Counter that is text" "gx.txt:6: Counter ('abc') is not a number" "$H" info "$T/gx.txt" --from gx2
gx_log "$T/gx.txt" 130516848:1:1000.000 130595568:2:1000.004 130674288:3:xyz
ctr_bad "GX2, a time stamp that is text" "gx.txt:6: time stamp Filtered ts ('xyz') is not a number" "$H" info "$T/gx.txt" --from gx2
gx_log "$T/gx.txt" 130516848:1:1000.000 130595568:2:1000.004 130674288:x3:1000.008
ctr_bad "GX2, an Nr that is text" "gx.txt:6: Nr ('x3') is not a number" "$H" info "$T/gx.txt" --from gx2
gx_log "$T/gx.txt" 130516848:1:1000.000 130595568:2:1000.004 130674288:-3:1000.008
ctr_bad "GX2, a negative Nr" "gx.txt:6: Nr ('-3') is not a 32-bit count" "$H" info "$T/gx.txt" --from gx2
gx_log "$T/gx.txt" 130516848:1:1000.000 130595568:2:1000.004 130674288:3.5:1000.008
ctr_bad "GX2, a fractional Nr" "gx.txt:6: Nr ('3.5') is not a 32-bit count" "$H" info "$T/gx.txt" --from gx2
gx_log "$T/gx.txt" 130516848:1:1000.000 130595568:2:1000.004 5e9:3:1000.008
ctr_bad "GX2, a Counter beyond 32 bits" "gx.txt:6: Counter ('5e9') is not a 32-bit count" "$H" info "$T/gx.txt" --from gx2
rm -f "$T/sq.csv" "$T/ip.txt" "$T/gx.txt"

# --- the plotting backend fails or is missing (no other test runs a failing gnuplot with allan, psd, montecarlo,
# simgap or eval, nor checks the other outputs of replay's). A gnuplot that fails partway is an
# output error, exit 3, naming the picture, whose partial file is removed, and every other output is still
# written (docs/harness.md, "Exit status": nothing computed is lost); eval warns, leaves the figure out (no link
# to it) and goes on. Without gnuplot a plot is refused before the input is read, exit 3, nothing written; eval
# writes results.md without figures.
fake_gnuplot_fail "$T/failgp"
mkdir -p "$T/nogp"
"$H" sim --motion stand --duration 30 --rate 100 --seed 3 --out "$T/gst.csv" >/dev/null 2>&1 || fail "sim of a static log"
gp_gone() { # description picture: the partial picture removed, said
    expect_err "error: gnuplot failed to write $2; the partial file was removed" "$1: the failed picture named"
    [ ! -e "$2" ] && pass "$1: no partial picture left" || fail "$1: $2 left behind"
}
expect_exit 3 "replay, gnuplot failing" env PATH="$T/failgp:$PATH" "$H" replay vectors/walk.bin --quiet \
    --plot "$T/gr.png" --out "$T/gr.csv" --json "$T/gr.json" --strides "$T/gr_s.csv"
gp_gone "replay" "$T/gr.png"
[ "$(grep -vc '^#' "$T/gr.csv")" -gt 1000 ] && json "$T/gr.json" '"footnav_version" in j' && csv_rect "$T/gr_s.csv" stride &&
    pass "replay, gnuplot failing: --out, --json and --strides written" || fail "replay, gnuplot failing: outputs"
expect_exit 3 "allan, gnuplot failing" env PATH="$T/failgp:$PATH" "$H" allan "$T/gst.csv" --no-sim --quiet \
    --plot "$T/ga.png" --out "$T/ga.csv" --json "$T/ga.json" --profile "$T/ga.profile"
gp_gone "allan" "$T/ga.png"
[ -s "$T/ga.csv" ] && json "$T/ga.json" '"footnav_version" in j' && grep -q "^format = footnav-profile 1" "$T/ga.profile" &&
    pass "allan, gnuplot failing: --out, --json and --profile written" || fail "allan, gnuplot failing: outputs"
expect_exit 3 "psd, gnuplot failing" env PATH="$T/failgp:$PATH" "$H" psd "$T/gst.csv" --plot "$T/gp_psd" \
    --out "$T/gp.csv" --json "$T/gp.json"
gp_gone "psd" "$T/gp_psd/psd.png"
[ -s "$T/gp.csv" ] && json "$T/gp.json" '"footnav_version" in j' && pass "psd, gnuplot failing: --out and --json written" ||
    fail "psd, gnuplot failing: outputs"
expect_exit 3 "montecarlo, gnuplot failing" env PATH="$T/failgp:$PATH" "$H" montecarlo --seeds 3 --duration 20 \
    --plot "$T/gm.png" --json "$T/gm.json"
gp_gone "montecarlo" "$T/gm.png"
json "$T/gm.json" '"footnav_version" in j' && pass "montecarlo, gnuplot failing: --json written" ||
    fail "montecarlo, gnuplot failing: --json"
expect_exit 3 "simgap, gnuplot failing" env PATH="$T/failgp:$PATH" "$H" simgap "$T/gst.csv" --quiet --seeds 4 \
    --max-effects 0 --plot "$T/gsg" --json "$T/gsg.json"
expect_err "error: gnuplot failed to write $T/gsg/[a-z_]*.png; the partial file was removed" "simgap: the failed picture named"
[ -z "$(ls "$T/gsg")" ] && pass "simgap: no partial picture left" || fail "simgap: $(ls "$T/gsg") left behind"
json "$T/gsg.json" '"footnav_version" in j' && pass "simgap, gnuplot failing: --json written" || fail "simgap, gnuplot failing: --json"
mkdir -p "$T/gev/xio_ngimu_gait"
"$H" sim --motion stand:5,walk:20,stand:5 --rate 100 --seed 2 --out "$T/gev/xio_ngimu_gait/short_walk.csv" >/dev/null 2>&1 ||
    fail "sim of a walk for eval"
expect_exit 0 "eval, gnuplot failing" env PATH="$T/failgp:$PATH" "$H" eval --no-experiments --data "$T/gev" \
    --out "$T/gev/r.md" --json "$T/gev/r.json"
# eval goes on (exit 0): the failure is a warning, as the harness labels what does not stop a run (not
# "error: gnuplot failed ..." with exit 0)
expect_err "harness eval: warning: gnuplot failed to write $T/gev/img/eval-xio.png; the partial file was removed" \
    "eval: the failed picture named, as a warning"
[ ! -e "$T/gev/img/eval-xio.png" ] && pass "eval: no partial picture left" || fail "eval: $T/gev/img/eval-xio.png left behind"
grep -q "error:" "$T/err" && fail "eval, gnuplot failing: an error printed: $(grep 'error:' "$T/err")" ||
    pass "eval, gnuplot failing: no 'error:' printed"
expect_err "warning: figure $T/gev/img/eval-xio.png not drawn (see above); results.md goes on without it" \
    "eval: the figure left out is said"
grep -q "^| short_walk.csv | [0-9]" "$T/gev/r.md" && ! grep -q "eval-xio.png" "$T/gev/r.md" && json "$T/gev/r.json" '"footnav_version" in j' &&
    pass "eval, gnuplot failing: results.md with the walk's row, no link to the missing figure, the JSON" ||
    fail "eval, gnuplot failing: $(grep 'short_walk\|png' "$T/gev/r.md")"
rm -f "$T/gr.csv" "$T/gr.json"
expect_exit 3 "replay --plot without gnuplot" env PATH="$T/nogp" "$H" replay vectors/walk.bin --quiet --plot "$T/gr.png" \
    --out "$T/gr.csv" --json "$T/gr.json"
expect_err "^harness replay: error: cannot draw $T/gr.png: gnuplot is not installed (apt-get install gnuplot-nox)" \
    "replay without gnuplot: said"
[ ! -e "$T/gr.csv" ] && [ ! -e "$T/gr.json" ] && pass "replay without gnuplot: refused before the run, nothing written" ||
    fail "replay without gnuplot: outputs written"
expect_exit 3 "allan --plot without gnuplot" env PATH="$T/nogp" "$H" allan "$T/gst.csv" --no-sim --quiet --plot "$T/ga2.png"
expect_err "^harness allan: error: cannot draw $T/ga2.png: gnuplot is not installed" "allan without gnuplot: said"
for c in "psd:psd.png" "montecarlo:gm4.png" "simgap:z.png"; do
    cmd=${c%%:*}
    case $cmd in
    psd) set -- psd "$T/gst.csv" --plot "$T/gnp" --json "$T/gnp.json" ;;
    montecarlo) set -- montecarlo --seeds 3 --duration 20 --plot "$T/gnp/gm4.png" --json "$T/gnp.json" ;;
    simgap) set -- simgap "$T/gst.csv" --quiet --seeds 4 --max-effects 0 --plot "$T/gnp" --json "$T/gnp.json" ;;
    esac
    mkdir -p "$T/gnp"; rm -f "$T/gnp.json"
    expect_exit 3 "$cmd --plot without gnuplot" env PATH="$T/nogp" "$H" "$@"
    expect_err "^harness $cmd: error: cannot draw $T/gnp/${c#*:}: gnuplot is not installed" "$cmd without gnuplot: said"
    [ ! -e "$T/gnp.json" ] && pass "$cmd without gnuplot: refused before the run, no --json" || fail "$cmd without gnuplot: --json written"
done
# a --plot directory not there yet is not made when the run is refused for want of gnuplot (not made first and
# left empty, as psd and simgap could)
for cmd in psd simgap; do
    rm -rf "$T/gnpnew"
    case $cmd in
    psd) set -- psd "$T/gst.csv" --plot "$T/gnpnew" ;;
    simgap) set -- simgap "$T/gst.csv" --quiet --seeds 4 --max-effects 0 --plot "$T/gnpnew" ;;
    esac
    expect_exit 3 "$cmd --plot NEWDIR without gnuplot" env PATH="$T/nogp" "$H" "$@"
    expect_err "^harness $cmd: error: cannot draw $T/gnpnew/[a-z]*.png: gnuplot is not installed" "$cmd NEWDIR without gnuplot: said"
    [ ! -e "$T/gnpnew" ] && pass "$cmd without gnuplot: no --plot directory left behind" ||
        fail "$cmd without gnuplot: $T/gnpnew left behind"
done
expect_exit 0 "eval without gnuplot" env PATH="$T/nogp" "$H" eval --no-experiments --data "$T/gev" --out "$T/gev/n.md"
expect_err "warning: no figures: gnuplot is not installed (apt-get install gnuplot-nox)" "eval without gnuplot: said"
grep -q "^| short_walk.csv | [0-9]" "$T/gev/n.md" && ! grep -q "\.png" "$T/gev/n.md" &&
    pass "eval without gnuplot: results.md without figures" || fail "eval without gnuplot: $(grep png "$T/gev/n.md")"
# a picture that cannot be written (its directory missing): refused before the input is read, exit 3 (replay's
# and psd's were tested; allan's and montecarlo's not)
expect_exit 3 "allan --plot in a directory that does not exist" "$H" allan "$T/gst.csv" --no-sim --quiet \
    --plot "$T/nodir/a.png" --out "$T/ga3.csv"
expect_err "^harness allan: error: cannot write $T/nodir/a.png (No such file or directory)" "allan --plot: the picture named"
[ ! -e "$T/ga3.csv" ] && pass "allan --plot unwritable: nothing written" || fail "allan --plot unwritable: --out written"
expect_exit 3 "montecarlo --plot in a directory that does not exist" "$H" montecarlo --seeds 3 --duration 20 \
    --plot "$T/nodir/m.png" --json "$T/gm3.json"
expect_err "^harness montecarlo: error: cannot write $T/nodir/m.png (No such file or directory)" "montecarlo --plot: the picture named"
[ ! -e "$T/gm3.json" ] && pass "montecarlo --plot unwritable: nothing written" || fail "montecarlo --plot unwritable: --json written"
# a picture cut short (pngcairo exits 0 when its write fails on a full disk): no whole PNG, its IEND chunk last,
# is a failed picture (exit 3, the partial file removed; eval: a warning, no link), not a success with a
# truncated PNG
fake_gnuplot_cut "$T/cutgp"
gp_cut() { # description picture
    expect_err "error: gnuplot failed to write $2 (the PNG is cut short: a full disk?); the partial file was removed" \
        "$1: the picture cut short named"
    [ ! -e "$2" ] && pass "$1: no cut picture left" || fail "$1: $2 left behind"
}
expect_exit 3 "replay, a picture cut short" env PATH="$T/cutgp:$PATH" "$H" replay vectors/walk.bin --quiet --plot "$T/cr.png"
gp_cut "replay" "$T/cr.png"
expect_exit 3 "allan, a picture cut short" env PATH="$T/cutgp:$PATH" "$H" allan "$T/gst.csv" --no-sim --quiet --plot "$T/ca.png"
gp_cut "allan" "$T/ca.png"
expect_exit 3 "psd, a picture cut short" env PATH="$T/cutgp:$PATH" "$H" psd "$T/gst.csv" --plot "$T/cp_psd"
gp_cut "psd" "$T/cp_psd/psd.png"
expect_exit 3 "montecarlo, a picture cut short" env PATH="$T/cutgp:$PATH" "$H" montecarlo --seeds 3 --duration 20 --plot "$T/cm.png"
gp_cut "montecarlo" "$T/cm.png"
# through a symlink: the file it names is the partial one, removed; the link is not
printf 'old' >"$T/cl_t.png" && ln -s cl_t.png "$T/cl.png"
expect_exit 3 "replay, a picture cut short through a symlink" env PATH="$T/cutgp:$PATH" "$H" replay vectors/walk.bin --quiet \
    --plot "$T/cl.png"
[ -L "$T/cl.png" ] && [ ! -e "$T/cl_t.png" ] && pass "a picture cut short through a symlink: its file removed, the link kept" ||
    fail "a picture cut short through a symlink: $(ls -l "$T" | grep cl_t)"
expect_exit 0 "eval, a picture cut short" env PATH="$T/cutgp:$PATH" "$H" eval --no-experiments --data "$T/gev" --out "$T/gev/c.md"
expect_err "harness eval: warning: gnuplot failed to write $T/gev/img/eval-xio.png (the PNG is cut short: a full disk?); the partial file was removed" \
    "eval: the picture cut short named, as a warning"
[ ! -e "$T/gev/img/eval-xio.png" ] && ! grep -q "eval-xio.png" "$T/gev/c.md" && pass "eval: no cut picture, no link to it" ||
    fail "eval, a picture cut short: linked or left"
# a --plot path that is there and is not a regular file (a device: the picture was lost there, exit 0) is
# refused before the work, exit 3, and left as it is; a /dev/full of the test's own (root makes the node)
fake_gnuplot "$T/wholegp"
if [ "$(id -u)" = 0 ] && mknod -m 666 "$T/dfull" c 1 7 2>/dev/null; then
    mkdir -p "$T/dpsd" && mknod -m 666 "$T/dpsd/psd.png" c 1 7
    for c in replay allan psd montecarlo; do
        case $c in
        replay) set -- replay vectors/walk.bin --quiet --plot "$T/dfull" --json "$T/dj.json"; d=$T/dfull ;;
        allan) set -- allan "$T/gst.csv" --no-sim --quiet --plot "$T/dfull" --json "$T/dj.json"; d=$T/dfull ;;
        psd) set -- psd "$T/gst.csv" --plot "$T/dpsd" --json "$T/dj.json"; d=$T/dpsd/psd.png ;;
        montecarlo) set -- montecarlo --seeds 3 --duration 20 --plot "$T/dfull" --json "$T/dj.json"; d=$T/dfull ;;
        esac
        rm -f "$T/dj.json"
        expect_exit 3 "$c --plot onto a device" env PATH="$T/wholegp:$PATH" GP_SCRIPT="$T/dgp.txt" "$H" "$@"
        expect_err "^harness $c: error: cannot write $d: not a regular file" "$c --plot onto a device: said"
        [ -c "$d" ] && [ ! -e "$T/dj.json" ] && pass "$c --plot onto a device: refused before the work, the node left" ||
            fail "$c --plot onto a device: the node replaced, or --json written"
    done
    # eval: a warning, and the figure left out of results.md
    rm -f "$T/gev/img/eval-xio.png" && mknod -m 666 "$T/gev/img/eval-xio.png" c 1 7
    expect_exit 0 "eval, a figure onto a device" env PATH="$T/wholegp:$PATH" GP_SCRIPT="$T/dgp.txt" "$H" eval \
        --no-experiments --data "$T/gev" --out "$T/gev/d.md"
    expect_err "harness eval: warning: cannot write $T/gev/img/eval-xio.png: not a regular file" "eval, a figure onto a device: a warning"
    [ -c "$T/gev/img/eval-xio.png" ] && ! grep -q "eval-xio.png" "$T/gev/d.md" && pass "eval, a figure onto a device: not linked, the node left" ||
        fail "eval, a figure onto a device: linked, or the node replaced"
    rm -f "$T/dfull" "$T/dpsd/psd.png" "$T/gev/img/eval-xio.png"
else
    echo "SKIP --plot onto a device: not root"
fi

# --- an output checked before the run leaves no trace: a dangling symlink given as --json stays a link, the
# JSON written into the file it names (the check created that file empty and removed the path: the link, which
# the JSON then replaced by a plain file); a run refused by another output leaves neither
ln -s dang_t.json "$T/dang.json"
expect_exit 0 "replay --json onto a dangling symlink" "$H" replay vectors/walk.bin --quiet --json "$T/dang.json"
[ -L "$T/dang.json" ] && json "$T/dang_t.json" '"footnav_version" in j' && pass "dangling --json: the link kept, its file written" ||
    fail "dangling --json: $(ls -l "$T" | grep dang)"
ln -s dang2_t.json "$T/dang2.json"
expect_exit 3 "replay --json onto a dangling symlink, --out unwritable" "$H" replay vectors/walk.bin --quiet \
    --json "$T/dang2.json" --out "$T/nodir/x.csv"
[ -L "$T/dang2.json" ] && [ ! -e "$T/dang2_t.json" ] && pass "a refused run: the dangling link kept, no file made" ||
    fail "a refused run: $(ls -l "$T" | grep dang2)"

if [ "$fails" -ne 0 ]; then
    echo "test_cli.sh: $fails failure(s)"
    exit 1
fi
echo "test_cli.sh: all passed"
