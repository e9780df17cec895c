#!/bin/sh
# CLI tests of `harness stream` and `harness live` over a pseudo-terminal
# pair made by socat: a real walk streamed and received (recording identical
# to the log), corrupt frames, dropped frames, a port that disappears, a
# receiver killed mid-stream, usage and open errors.
#
# libserialport 0.1.1 refuses ptys; tests/cli/pty_seam.c (LD_PRELOAD) answers
# the two questions a pty cannot (sysfs lookup, modem lines) and leaves every
# other call to libserialport (docs/wire-protocol.md, "Testing without a
# sensor"). Every harness run has a time limit and every socat is killed on
# exit, so the test cannot hang.
# $HARNESS is the harness binary (set by `make test-cli`).
set -u
H=${HARNESS:-bin/harness}
T=$(mktemp -d)
SOCAT=""
LIVE=""
STREAM=""
LIMIT=120 # seconds for any single harness run (ASan builds are slow)
. "$(dirname "$0")/lib.sh"
cleanup() {
    for p in $STREAM $LIVE $SOCAT; do kill "$p" 2>/dev/null; done
    for p in $STREAM $LIVE $SOCAT; do wait "$p" 2>/dev/null; done
    rm -rf "$T"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

if ! command -v socat >/dev/null 2>&1; then
    echo "SKIP test_live.sh: socat is not installed (apt-get install socat)"
    exit 0
fi

# the seam, built for this run unless given
SEAM=${PTYSEAM:-}
if [ -z "$SEAM" ]; then
    SEAM=$T/pty_seam.so
    if ! ${CC:-cc} -shared -fPIC -O2 -Wall -o "$SEAM" tests/cli/pty_seam.c -ldl 2>"$T/cc.err"; then
        cat "$T/cc.err"
        echo "FAIL cannot build tests/cli/pty_seam.c"
        exit 1
    fi
fi
# ASan wants to be first in the library list; the seam must be first too
ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0"
export ASAN_OPTIONS

# wait_for CONDITION TENTHS: poll a shell condition, 0.1 s steps
wait_for() {
    i=0
    while [ "$i" -lt "$2" ]; do
        if eval "$1"; then return 0; fi
        sleep 0.1
        i=$((i + 1))
    done
    return 1
}

start_link() {
    rm -f "$T/a" "$T/b"
    socat -t 1 pty,raw,echo=0,link="$T/a" pty,raw,echo=0,link="$T/b" 2>>"$T/socat.log" &
    SOCAT=$!
    if ! wait_for '[ -L "$T/a" ] && [ -L "$T/b" ]' 100; then
        echo "FAIL socat did not create the pty pair"
        cat "$T/socat.log"
        exit 1
    fi
    A=$(readlink "$T/a")
    B=$(readlink "$T/b")
}
stop_link() {
    if [ -n "$SOCAT" ]; then kill "$SOCAT" 2>/dev/null; wait "$SOCAT" 2>/dev/null; SOCAT=""; fi
}
# start_live ARGS...: live on end A in the background, once it listens
start_live() {
    LD_PRELOAD=$SEAM timeout $LIMIT "$H" live "$A" --print-every 0 "$@" >"$T/live.out" 2>"$T/live.err" &
    LIVE=$!
    if ! wait_for 'grep -q "reading" "$T/live.err"' 200; then
        fail "live did not start"
        cat "$T/live.err"
    fi
}
wait_live() {
    wait "$LIVE"
    LIVE_RC=$?
    LIVE=""
}
# stream ARGS...: stream to end B in the foreground
stream() {
    LD_PRELOAD=$SEAM timeout $LIMIT "$H" stream "$@" "$B" >"$T/stream.out" 2>"$T/stream.err"
    STREAM_RC=$?
}
records() { # records in a .bin being written (header 192 B, records 48 B)
    s=$(wc -c <"$1")
    echo $(((s - 192) / 48))
}
expect_rc() { # got want description
    if [ "$1" -eq "$2" ]; then pass "$3 (exit $1)"; else fail "$3: exit $1, expected $2"; cat "$T/live.err" "$T/stream.err" 2>/dev/null; fi
}
grep_in() { # file pattern description
    if grep -q -- "$2" "$1"; then pass "$3"; else fail "$3: $1 lacks '$2'"; cat "$1"; fi
}

"$H" convert vectors/walk.bin "$T/orig.csv" >/dev/null 2>&1 || { echo "FAIL cannot convert walk.bin"; exit 1; }
N=$(($(wc -l <"$T/orig.csv") - 1))

# --- usage and open errors
timeout $LIMIT "$H" live >/dev/null 2>&1; expect_rc $? 2 "live without PORT"
timeout $LIMIT "$H" stream vectors/walk.bin >/dev/null 2>&1; expect_rc $? 2 "stream without PORT"
timeout $LIMIT "$H" live --help >/dev/null 2>&1; expect_rc $? 0 "live --help"
timeout $LIMIT "$H" live /dev/nonexistent-port >/dev/null 2>"$T/err"; expect_rc $? 3 "live on a missing port"
grep_in "$T/err" "nonexistent-port" "the error names the port"
timeout $LIMIT "$H" live /dev/null >/dev/null 2>"$T/err"; expect_rc $? 3 "live on /dev/null (not a serial port)"
# (not "/dev/null: not a serial port libserialport knows (no /sys/class/tty
# entry): No such file or directory", of a file that exists)
if grep -q "No such file" "$T/err"; then fail "the error on /dev/null says it does not exist: $(cat "$T/err")"; else pass "the error on /dev/null does not say it is missing"; fi
grep_in "$T/err" "no /sys/class/tty/null" "the error names the sysfs entry libserialport looks for"
timeout $LIMIT "$H" live /dev/null --rate 100 >/dev/null 2>"$T/err"; expect_rc $? 2 "live --rate (resampling needs the whole log)"
timeout $LIMIT "$H" live /dev/null --bias-model nope >/dev/null 2>"$T/err"; expect_rc $? 2 "live --bias-model nope"
timeout $LIMIT "$H" live "$T/orig.csv" --baud 0 >/dev/null 2>&1; expect_rc $? 2 "live --baud 0"
timeout $LIMIT "$H" stream "$T/nope.bin" /dev/null >/dev/null 2>&1; expect_rc $? 1 "stream of a missing log"
timeout $LIMIT "$H" stream vectors/walk.bin /dev/null --hangup-after 0 >/dev/null 2>&1; expect_rc $? 2 "stream --hangup-after 0 (was taken for off)"
# the recording and the JSON are written after the session has started (the
# recording at the first sample, the JSON at its end): an output that cannot
# be written is refused before the port is opened, not found when the walk
# is under way or over (the error named the port, or came after the session)
for o in record json; do
    timeout $LIMIT "$H" live /dev/nonexistent-port --$o "$T/no/dir/x.$o" >/dev/null 2>"$T/err"
    expect_rc $? 3 "live --$o into a missing directory"
    grep_in "$T/err" "no/dir/x.$o" "the error names the --$o file, before the port"
done
# a port that cannot be opened (the sensor unplugged) leaves --out as it was:
# were the CSV created before the port is opened, an earlier run's
# trajectory would be emptied by a run that never started; an --out that
# cannot be written is refused first, as --record's
printf 't_s\n1.0\n' >"$T/keep.csv"
timeout $LIMIT "$H" live /dev/nonexistent-port --out "$T/keep.csv" >/dev/null 2>"$T/err"; expect_rc $? 3 "live --out on a missing port"
if [ "$(cat "$T/keep.csv")" = "$(printf 't_s\n1.0')" ]; then pass "an earlier --out is kept when the port cannot be opened"; else fail "the earlier --out was overwritten: $(wc -c <"$T/keep.csv") bytes"; fi
timeout $LIMIT "$H" live /dev/nonexistent-port --out "$T/new.csv" >/dev/null 2>"$T/err"
if [ -e "$T/new.csv" ]; then fail "an --out file was created for a port that cannot be opened"; else pass "no --out file is created when the port cannot be opened"; fi
timeout $LIMIT "$H" live /dev/nonexistent-port --out "$T/no/dir/x.csv" >/dev/null 2>"$T/err"; expect_rc $? 3 "live --out into a missing directory"
grep_in "$T/err" "no/dir/x.csv" "the error names the --out file, before the port"

start_link
# the real libserialport path refuses a pty: this is why the seam exists
timeout $LIMIT "$H" live "$A" >/dev/null 2>"$T/err"; expect_rc $? 3 "live on a pty without the seam"
# by the link socat made, as a user following the docs types it: the error
# names that path and says what to do (not /dev/pts/N only, with "No such
# file or directory" and no word of the seam)
timeout $LIMIT "$H" live "$T/a" >/dev/null 2>"$T/err"; expect_rc $? 3 "live on a pty's link without the seam"
grep_in "$T/err" "$T/a ($A)" "the error names the path given and the device"
grep_in "$T/err" "pseudo-terminal.*tests/cli/pty_seam.c" "the error says a pty needs the seam"

# --- a real walk, streamed and received: the recording is the log and the
# live trajectory is the replay's, to the last digit
start_live --record "$T/rec.bin" --out "$T/live.csv" --json "$T/live.json" --timeout 30 \
    --plot-every 0.5 --plot "$T/live.png" --print-every 0.5
stream vectors/walk.bin --speed 20
expect_rc "$STREAM_RC" 0 "stream walk.bin at 20x"
wait_live
expect_rc "$LIVE_RC" 0 "live receives walk.bin"
timeout $LIMIT "$H" replay vectors/walk.bin --out "$T/replay.csv" --json "$T/replay.json" >"$T/replay.out" 2>&1
expect_rc $? 0 "replay walk.bin"
if cmp -s "$T/live.csv" "$T/replay.csv"; then
    pass "live trajectory identical to replay ($(($(wc -l <"$T/live.csv") - 1)) rows)"
else
    fail "live trajectory differs from replay"; diff "$T/live.csv" "$T/replay.csv" | head -5
fi
grep_in "$T/live.out" "return-to-start" "live prints the replay summary"
grep_in "$T/live.err" "strides" "the status line shows position and stance"
if /usr/bin/python3 -c "
import json, sys
a = json.load(open(sys.argv[1])); b = json.load(open(sys.argv[2]))
keys = [k for k in b if k not in ('log', 'command', 'complete', 'error')]  # complete, error: replay's own
bad = [k for k in keys if a.get(k) != b[k]]
sys.exit(1 if bad else 0)" "$T/live.json" "$T/replay.json"; then
    pass "live --json has the replay's figures"
else
    fail "live --json differs from replay --json"
fi
grep_in "$T/live.out" "$N samples over" "live counts every sample"
# the JSON says whether the stream was complete and what the link did
# (without them a run with lost frames writes the JSON of a clean one), and
# "command" is not "harness live" without its options
if /usr/bin/python3 -c "
import json, sys
d = json.load(open(sys.argv[1])); l = d.get('link') or {}
ok = (d.get('complete') is True and 'error' not in d and '--record' in d.get('command', '')
      and l.get('end') == 'END frame' and l.get('samples') == int(sys.argv[2]) and l.get('recorded') == int(sys.argv[2])
      and l.get('end_count') == int(sys.argv[2]) and l.get('bad_frames') == 0 and l.get('lost_frames') == 0)
sys.exit(0 if ok else 1)" "$T/live.json" "$N"; then
    pass "live --json: complete, the full command, and the link counters"
else
    fail "live --json lacks complete / command / link: $(head -c 400 "$T/live.json")"
fi
# (test_docs.sh checks the other commands' keys; live's needs the pty pair)
if missing=$(/usr/bin/python3 -c "
import json, sys
doc = open('docs/harness.md').read()
print(' '.join(k for k in json.load(open(sys.argv[1])).get('link', {}) if '\`%s\`' % k not in doc))" "$T/live.json") &&
    [ -z "$missing" ]; then
    pass "every key of live's link object is in docs/harness.md"
else
    fail "docs/harness.md lacks live's link keys: $missing"
fi
grep_in "$T/live.out" "END frame, the sender sent $N samples, $N received" "END frame count matches"
grep_in "$T/live.out" "0 bad frames, 0 lost frames" "no link errors on a clean stream"
"$H" convert "$T/rec.bin" "$T/rec.csv" >/dev/null 2>"$T/err"
if cmp -s "$T/rec.csv" "$T/orig.csv"; then pass "recording identical to walk.bin (every value)"; else fail "recording differs from walk.bin"; cat "$T/err"; fi
if command -v gnuplot >/dev/null 2>&1; then
    if [ -s "$T/live.png" ]; then pass "--plot-every drew $T/live.png"; else fail "--plot-every drew nothing"; fi
else
    echo "SKIP the --plot-every picture: gnuplot is not installed (apt-get install gnuplot-nox)"
fi

# --- a gnuplot that fails: the last picture, drawn at the end, is an output that was not written; its child's exit
# status is looked at, so that live does not exit 0 with no live.png; no temporary is left
mkdir -p "$T/badgp"
printf '#!/bin/sh\ncat >/dev/null\necho "gnuplot: cannot draw" >&2\nexit 1\n' >"$T/badgp/gnuplot"
chmod +x "$T/badgp/gnuplot"
OLDPATH=$PATH
PATH="$T/badgp:$PATH"
start_live --timeout 30 --plot "$T/bad.png"
PATH=$OLDPATH
stream vectors/walk.bin --speed 40
wait_live
expect_rc "$LIVE_RC" 3 "live whose last picture gnuplot fails to draw"
grep_in "$T/live.err" "bad.png was not drawn" "the error names the picture"
[ ! -e "$T/bad.png" ] && [ ! -e "$T/bad.png.tmp.png" ] && pass "no picture, no temporary left" ||
    fail "a picture or its temporary left: $(ls "$T" | grep bad.png)"

# --- each picture is drawn beside --plot's path and renamed onto it: a path that is there and is not a regular
# file is refused before the run (a device was replaced by a PNG, exit 0; a dangling symlink by a file); a symlink
# to a file stays a link, the file it names updated (it was replaced by a plain file, its target never drawn)
mkdir "$T/pdir"
ln -s "$T/nowhere.png" "$T/pdang.png"
for p in pdir pdang.png; do
    timeout $LIMIT "$H" live /dev/nonexistent-port --plot "$T/$p" >/dev/null 2>"$T/err"; expect_rc $? 3 "live --plot onto $p"
    grep_in "$T/err" "cannot write $T/$p: not a regular file" "live --plot onto $p: the reason said"
done
[ -d "$T/pdir" ] && [ -L "$T/pdang.png" ] && [ ! -e "$T/nowhere.png" ] && pass "the refused paths are as they were" ||
    fail "a refused --plot path changed: $(ls -l "$T" | grep -e pdir -e pdang -e nowhere)"
if [ "$(id -u)" = 0 ]; then
    # a /dev/full of the test's own (as root the rename replaced the device node)
    mknod -m 666 "$T/pfull" c 1 7
    timeout $LIMIT "$H" live /dev/nonexistent-port --plot "$T/pfull" >/dev/null 2>"$T/err"; expect_rc $? 3 "live --plot onto a device"
    grep_in "$T/err" "cannot write $T/pfull: not a regular file" "live --plot onto a device: the reason said"
    [ -c "$T/pfull" ] && pass "the device node is left as it was" || fail "the device node was replaced"
    rm -f "$T/pfull"
fi
fake_gnuplot "$T/gpwhole"
printf 'old' >"$T/ptarget.png"
ln -s "$T/ptarget.png" "$T/plink.png"
# a link where the picture's temporary file goes: not written through (gnuplot wrote the picture into the
# file it names, and the rename put the link in the picture's place)
printf 'keep' >"$T/pvictim"
ln -s "$T/pvictim" "$T/ptarget.png.tmp.png"
OLDPATH=$PATH
PATH="$T/gpwhole:$PATH"
GP_SCRIPT=$T/gpwhole/script
export GP_SCRIPT
start_live --timeout 30 --plot "$T/plink.png"
PATH=$OLDPATH
stream vectors/walk.bin --speed 40
wait_live
expect_rc "$LIVE_RC" 0 "live --plot onto a symlink to a file"
[ -L "$T/plink.png" ] && [ "$(head -c 4 "$T/ptarget.png" | od -An -c | tr -d ' ')" = "211PNG" ] &&
    [ ! -e "$T/ptarget.png.tmp.png" ] && [ ! -e "$T/plink.png.tmp.png" ] &&
    pass "the link stays a link, the file it names holds the picture" ||
    fail "symlink --plot: $(ls -l "$T" | grep -e plink -e ptarget)"
[ "$(cat "$T/pvictim")" = "keep" ] && [ ! -L "$T/ptarget.png" ] &&
    pass "a link at FILE.tmp.png is not written through" ||
    fail "link at the temporary picture: $(head -c 4 "$T/pvictim" | od -An -c); $(ls -l "$T" | grep -e ptarget)"

# --- corrupt frames: skipped, counted, reported; the rest recorded
start_live --record "$T/rec_c.bin" --timeout 30 --json "$T/live_c.json"
stream vectors/walk.bin --speed 40 --inject-corrupt 1000
wait_live
BAD=$((N / 1000))
expect_rc "$LIVE_RC" 1 "live with corrupt frames (incomplete data)"
if /usr/bin/python3 -c "
import json, sys
d = json.load(open(sys.argv[1])); l = d.get('link') or {}; n = int(sys.argv[2])
ok = (d.get('complete') is False and 'corrupt' in d.get('error', '') and l.get('bad_frames') == n
      and l.get('lost_frames') == n and l.get('noise_frames') == 0)
sys.exit(0 if ok else 1)" "$T/live_c.json" "$BAD"; then
    pass "live --json of a damaged stream: complete false, the error and the counts"
else
    fail "live --json of a damaged stream: $(head -c 400 "$T/live_c.json")"
fi
grep_in "$T/live.out" "$BAD bad frames, $BAD lost frames in $BAD drops" "every corrupt frame counted and reported as a drop"
# the run went on to the END frame: the summary has no replay-style
# "stopped after N samples, at the input error above" line (not there for
# every incomplete run, as live's JSON verdict might put it, before an error
# printed below it)
if grep -q "^stopped " "$T/live.out"; then fail "live's summary says it stopped: $(grep "^stopped " "$T/live.out")"; else pass "live's summary does not say the run stopped at an input error"; fi
grep_in "$T/live.err" "bad frame:" "corrupt frames are reported as they happen"
"$H" convert "$T/rec_c.bin" "$T/rec_c.csv" >/dev/null 2>&1
got=$(($(wc -l <"$T/rec_c.csv") - 1))
if [ "$got" -eq $((N - BAD)) ]; then pass "recording holds every intact sample ($got)"; else fail "recording holds $got samples, expected $((N - BAD))"; fi

# --- dropped frames
start_live --record "$T/rec_d.bin" --timeout 30
stream vectors/walk.bin --speed 40 --inject-drop 500
wait_live
DROP=$((N / 500))
expect_rc "$LIVE_RC" 1 "live with dropped frames"
grep_in "$T/live.out" "0 bad frames, $DROP lost frames in $DROP drops" "every drop counted"
grep_in "$T/live.err" "drop: 1 frame(s) lost before frame seq 501" "the first drop is reported with its sequence number"
grep_in "$T/live.out" "the sender sent $N samples, $((N - DROP)) received" "END count shows the missing samples"
grep_in "$T/stream.out" "$N samples sent to $B ($DROP of them left out by --inject-drop, $((N - DROP)) written)" "stream says how many it left out"

# --- a log with a bad line partway: every sample before it is sent, END
# counts them, and the exit is 1 with the line named (a mutant that exits 0
# here passes every case above)
{ head -501 "$T/orig.csv"; echo "1.0,x,0,0,0,0,0"; tail -n +502 "$T/orig.csv"; } >"$T/bad_mid.csv"
start_live --record "$T/rec_b.bin" --timeout 30
stream "$T/bad_mid.csv" --speed 40
wait_live
expect_rc "$STREAM_RC" 1 "stream of a log with a bad line partway"
grep_in "$T/stream.err" "bad_mid.csv:502" "the stream's warning names the bad line"
grep_in "$T/stream.out" "^stream: 500 samples sent to $B" "stream sent the 500 samples before the bad line"
grep_in "$T/live.out" "END frame, the sender sent 500 samples, 500 received" "live received them all, and END"

# --- the port disappears mid-stream: clean end, recording intact
start_live --record "$T/rec_h.bin" --timeout 60
stream vectors/walk.bin --speed 40 --hangup-after 1000
expect_rc "$STREAM_RC" 0 "stream stops after 1000 samples without END"
# (the last sample taken is held back by one, for a stamp far ahead of its
# neighbours, until the next comes or the run ends)
if ! wait_for '[ "$(records "$T/rec_h.bin")" -ge 999 ]' 300; then fail "live did not record 999 samples"; fi
stop_link # the pty pair vanishes under live
wait_live
expect_rc "$LIVE_RC" 1 "live when the port disappears"
grep_in "$T/live.err" "disappeared\|hung up\|port gone" "a clear message says the port went away"
grep_in "$T/live.out" "recorded 1000 samples" "the summary names the recorded samples"
timeout $LIMIT "$H" info "$T/rec_h.bin" >"$T/info.out" 2>&1
expect_rc $? 0 "the recording is complete and closed (END record written)"
grep_in "$T/info.out" "samples     1000" "the recording holds the 1000 samples"

# --- the link goes away under stream (socat killed): exit 3 with the error,
# and no "done in 2.0 s" after it as if the log had gone out
start_link
start_live --timeout 30
LD_PRELOAD=$SEAM timeout $LIMIT "$H" stream vectors/walk.bin "$B" --speed 4 >"$T/stream.out" 2>"$T/stream.err" &
STREAM=$!
sleep 1.6 # the progress shows after 1 s
stop_link
wait "$STREAM"
STREAM_RC=$?
STREAM=""
wait_live
expect_rc "$STREAM_RC" 3 "stream when the link goes away"
grep_in "$T/stream.err" "write failed" "stream says the write failed"
grep_in "$T/stream.err" "harness stream: .* %" "the progress was showing"
if grep -q "done in" "$T/stream.err"; then fail "stream says done after the port failed: $(cat "$T/stream.err")"; else pass "no 'done' after the port failed"; fi
grep_in "$T/stream.out" "the port failed before all were written" "the summary says the port failed"
# ... and with standard error on a terminal (script(1) gives it one), the
# error starts a line of its own, not written after the progress line
# redrawn in place, "harness stream:  41 % (1.6 s)   harness stream: error:
# write failed"
if command -v script >/dev/null 2>&1; then
    start_link
    start_live --timeout 30
    timeout $LIMIT script -q -e -c "LD_PRELOAD=\"$SEAM\" \"$H\" stream vectors/walk.bin \"$B\" --speed 4 >\"$T/stream_tty.out\"" \
        "$T/stream_tty.txt" >/dev/null 2>&1 </dev/null &
    STREAM=$!
    sleep 1.6
    stop_link
    wait "$STREAM"
    STREAM=""
    wait_live
    tr '\r' '\n' <"$T/stream_tty.txt" >"$T/stream_tty.lines"
    grep_in "$T/stream_tty.lines" "harness stream: .* %" "on a terminal: the progress was showing"
    grep_in "$T/stream_tty.lines" "^harness stream: error: .*write failed" "on a terminal: the error starts its line"
fi

# --- the receiver is killed: every record written so far stays readable
start_link
LD_PRELOAD=$SEAM "$H" live "$A" --print-every 0 --record "$T/rec_k.bin" --timeout 30 >/dev/null 2>"$T/live.err" &
LIVE=$!
wait_for 'grep -q "reading" "$T/live.err"' 200
# (the sender is the harness itself, not a timeout around it, and is ended
# with SIGKILL: a SIGTERM forwarded by timeout to an ASan build exiting
# through LeakSanitizer can leave both spinning, and the test waiting on
# them; the cleanup trap kills it if the test dies first)
LD_PRELOAD=$SEAM "$H" stream vectors/walk.bin "$B" --speed 4 >/dev/null 2>&1 &
STREAM=$!
wait_for '[ -f "$T/rec_k.bin" ] && [ "$(records "$T/rec_k.bin")" -ge 300 ]' 300
kill -9 "$LIVE" 2>/dev/null
wait "$LIVE" 2>/dev/null
LIVE=""
kill -9 "$STREAM" 2>/dev/null
wait "$STREAM" 2>/dev/null
STREAM=""
timeout $LIMIT "$H" convert "$T/rec_k.bin" "$T/rec_k.csv" >/dev/null 2>"$T/err"
expect_rc $? 1 "a killed recording reads as truncated (no END record)"
grep_in "$T/err" "no end record" "the reader says the recording was not closed"
k=$(($(wc -l <"$T/rec_k.csv") - 1))
if [ "$k" -ge 300 ] && head -n $((k + 1)) "$T/orig.csv" | cmp -s - "$T/rec_k.csv"; then
    pass "all $k samples recorded before the kill are intact"
else
    fail "the killed recording ($k samples) is not a prefix of the log"
fi

# --- the sender is interrupted: exit 130 and no END frame (not exit 0, as
# if the stream were complete)
stop_link # the block above leaves its link up
start_link
start_live --record "$T/rec_i.bin" --timeout 60
LD_PRELOAD=$SEAM "$H" stream vectors/walk.bin "$B" --speed 4 >"$T/stream.err" 2>&1 &
STREAM=$!
wait_for '[ -f "$T/rec_i.bin" ] && [ "$(records "$T/rec_i.bin")" -ge 300 ]' 300
kill -INT "$STREAM" 2>/dev/null
wait "$STREAM"
expect_rc $? 130 "stream interrupted by SIGINT"
STREAM=""
grep_in "$T/stream.err" "(interrupted)" "the interrupted stream says so"
stop_link
wait_live

# --- the same signal inside the write itself (tests/cli/eintr_seam.c puts it
# there; by chance a CI run hit it): the write goes on, the stream stops as
# interrupted (it was exit 3, "write failed", as if the port had gone)
if ${CC:-cc} -shared -fPIC -O2 -Wall -o "$T/eintr_seam.so" tests/cli/eintr_seam.c -ldl 2>"$T/cc.err"; then
    start_link
    start_live --timeout 60
    EINTR_SEAM_AT=20 LD_PRELOAD="$SEAM $T/eintr_seam.so" timeout $LIMIT "$H" stream vectors/walk.bin "$B" --speed 4 \
        >"$T/stream.err" 2>&1
    expect_rc $? 130 "stream interrupted by SIGINT inside a write"
    grep_in "$T/stream.err" "(interrupted)" "the stream says it was interrupted"
    if grep -q "write failed" "$T/stream.err"; then fail "the interrupted write was called a port failure"; else pass "no port failure said"; fi
    stop_link
    wait_live
else
    fail "cannot build tests/cli/eintr_seam.c: $(cat "$T/cc.err")"
fi

# --- misbehaving senders (tests/cli/wire_cases.py): whatever live records,
# its own reader reads; what it refuses is reported and fails the run
live_case() { # CASE RECORDING TIMEOUT [LIVE OPTIONS]: live on a new pty pair
    # (nothing left from the case before) receives the case's bytes into end B
    lc_case=$1 lc_rec=$2 lc_timeout=$3
    shift 3
    stop_link
    start_link
    start_live --record "$T/$lc_rec" --timeout "$lc_timeout" "$@"
    /usr/bin/python3 tests/cli/wire_cases.py "$lc_case" "$T/case.bin" || fail "wire_cases.py $lc_case"
    timeout 30 cat "$T/case.bin" >"$B"
    wait_live
}
reads_back() { # RECORDING SAMPLES DESCRIPTION: harness info reads it whole
    timeout $LIMIT "$H" info "$T/$1" >"$T/info.out" 2>&1
    expect_rc $? 0 "$3"
    grep_in "$T/info.out" "samples     $2\$" "it holds $2 samples"
}
live_case restart rec_r.bin 5
expect_rc "$LIVE_RC" 1 "live when the sender restarts (time goes back)"
grep_in "$T/live.err" "the sender restarted: time went back from 11.247500 s to 0.000000 s" "the restart is explained"
reads_back rec_r.bin 500 "the recording up to the restart reads back whole"

live_case range rec_g.bin 5
expect_rc "$LIVE_RC" 1 "live with a sample of 1e20 m/s^2"
grep_in "$T/live.err" "sample frame seq 100 holds a value beyond 1e6" "the out-of-range sample is reported"
reads_back rec_g.bin 299 "the recording without it reads back whole"

live_case repeat rec_rep.bin 5
expect_rc "$LIVE_RC" 0 "live when a sample frame arrives twice (the copy skipped; nothing lost)"
grep_in "$T/live.err" "sample frame seq 101 received twice; the copy skipped" "the repetition is reported"
grep_in "$T/live.out" "0 sequence restarts, 1 repeated sample frames skipped" "the summary counts it, as a repetition and not a restart"
if grep -q "restart:" "$T/live.err"; then fail "the repetition is reported as a sender restart"; cat "$T/live.err"; else pass "no restart reported for a repeated frame"; fi
reads_back rec_rep.bin 300 "the recording holds each sample once"

# a late copy (frame 200 again after 201: its time goes back) is skipped as a
# repetition, not taken for the sender's restart that ended the run with the
# rest of the session lost (the live audit of 2026-12-06), nor followed by a
# frame counted lost
live_case stale rec_stale.bin 5
expect_rc "$LIVE_RC" 0 "live when a sample frame arrives again late (nothing lost)"
grep_in "$T/live.err" "sample frame seq 200 received again after seq 201 (a late copy); skipped" "the late copy is reported"
grep_in "$T/live.out" "0 lost frames" "no frame counted lost after the late copy"
grep_in "$T/live.out" "0 sequence restarts, 1 repeated sample frames skipped" "the summary counts it as a repetition"
if grep -q "restarted" "$T/live.err"; then fail "the late copy ended the run as a restart"; else pass "no restart for a late copy"; fi
reads_back rec_stale.bin 300 "the recording holds each sample once, to the end"
# the same among NAV frames, which share the frame counter: the decoder is set back to the frame after the last
# frame received, not after the last sample frame (the next frame was counted lost; the review of 2026-12-06)
live_case stale_nav rec_stale_nav.bin 5
expect_rc "$LIVE_RC" 0 "live when a sample frame arrives again late among NAV frames (nothing lost)"
grep_in "$T/live.err" "sample frame seq 399 received again after seq 402 (a late copy); skipped" "the late copy among NAV frames is reported"
grep_in "$T/live.out" "0 lost frames" "no frame counted lost after the late copy among NAV frames"
reads_back rec_stale_nav.bin 300 "the recording holds each sample once"

# an INFO rate that --baud cannot carry is said, as stream says it (400
# samples/s of 51-byte frames need 204,000 baud; not to go without a word);
# once, and not at the default 460800
stop_link
start_link
start_live --timeout 5 --baud 115200
/usr/bin/python3 tests/cli/wire_cases.py restart "$T/case.bin" || fail "wire_cases.py restart"
timeout 30 cat "$T/case.bin" >"$B"
wait_live
grep_in "$T/live.err" "warning: the sender's 400 samples/s need 204000 baud; at 115200 baud" "live says the rate needs more than --baud"
[ "$(grep -c "samples/s need" "$T/live.err")" = 1 ] && pass "said once (two INFO frames)" ||
    fail "the baud warning: $(grep -c "samples/s need" "$T/live.err") times"
live_case restart rec_r2.bin 5
if grep -q "samples/s need" "$T/live.err"; then fail "a baud warning at the default 460800"; else pass "no baud warning at 460800"; fi
live_case badrate rec_n.bin 5
expect_rc "$LIVE_RC" 1 "live with an INFO frame whose rate is NaN"
grep_in "$T/live.err" "bad INFO frame seq 0" "the bad INFO frame is reported"
reads_back rec_n.bin 300 "the recording's header is readable (rate unknown)"

live_case navonly rec_v.bin 1
expect_rc "$LIVE_RC" 1 "live from a sender of NAV frames only"
grep_in "$T/live.out" "NAV frames but no SAMPLE frames" "live says why nothing is navigated"
grep_in "$T/live.out" "nothing recorded" "live does not claim a recording"
if [ -e "$T/rec_v.bin" ]; then fail "a recording was created without samples"; else pass "no empty recording left"; fi

live_case truncend rec_t.bin 5
expect_rc "$LIVE_RC" 1 "live when the last sample frame is cut short before END"
grep_in "$T/live.out" "END frame, the sender sent 300 samples, 299 received" "the END frame behind the cut frame is read (it was held until --timeout)"
grep_in "$T/live.out" "1 bad frames, 1 lost frames in 1 drops" "the cut frame is counted"
if grep -q "no valid frame" "$T/live.err"; then fail "live waited for --timeout: $(cat "$T/live.err")"; else pass "live ends at the END frame, not at --timeout"; fi
reads_back rec_t.bin 299 "the recording holds the 299 whole samples"

live_case sensordrop rec_sd.bin 5
expect_rc "$LIVE_RC" 1 "live with a frame lost on the link and samples lost on the sender"
grep_in "$T/live.err" "sensor drop: 5 sample(s) missing by the sensor's counter before sample seq 155" "the sender's own drop is reported"
if grep -q "sensor drop:.*before sample seq 101" "$T/live.err"; then fail "a link drop reported as the sender's"; else pass "the link drop is not taken for the sender's"; fi
grep_in "$T/live.out" "live: sensor: 5 samples missing by the sensor's counter in 1 gaps" "the summary counts the sender's drop"

# line noise between intact frames (a false sync word): corrupt candidates,
# but the sequence numbers show no frame lost and END counts every sample;
# not exit 1 with "incomplete: 0 frames lost, 2 corrupt frames, ... 0 samples
# missing"
live_case noise rec_z.bin 5
expect_rc "$LIVE_RC" 0 "live with line noise between intact frames (nothing lost)"
grep_in "$T/live.err" "bad frame: 1 corrupt frame(s) skipped before frame seq 101; no frame lost (noise on the line)" "the noise is reported as such"
grep_in "$T/live.out" "2 bad frames (2 of them noise between intact frames), 0 lost frames" "the summary counts it apart"
if grep -q "incomplete" "$T/live.err"; then fail "a complete stream called incomplete: $(grep incomplete "$T/live.err")"; else pass "no 'incomplete' for a complete stream"; fi
reads_back rec_z.bin 300 "the recording holds every sample"

# a sender restarted within its first 64 samples, stamping from its sample
# counter, sends the old frame seq, time and counter again with other
# values: no copies (a copy is the same bytes), so the session ends as a
# restart; they were skipped as late copies and then spliced in, exit 0
# (the live audit of 2026-12-06)
live_case restart_early rec_re.bin 5
expect_rc "$LIVE_RC" 1 "live when the sender restarts within 64 samples"
grep_in "$T/live.err" "the sender restarted: time went back from 0.122500 s to 0.000000 s at sample frame seq 1" "the early restart is a restart"
if grep -q "late copy" "$T/live.err"; then fail "the restarted sender's samples taken for late copies"; else pass "no late copies claimed"; fi
reads_back rec_re.bin 50 "the recording holds the first session only"

# a time stamp out of order while the frame sequence goes on is a bad
# sample, not a restart (one stamp 0.5 ms early ended the session)
live_case glitch rec_gl.bin 5
expect_rc "$LIVE_RC" 1 "live with one stamp behind the last (a sample dropped)"
grep_in "$T/live.err" "bad time stamp: sample frame seq 151 stamped 0.372000 s, behind the last sample's 0.372500 s while the frame sequence goes on; skipped" "the stamp out of order is reported"
grep_in "$T/live.out" "1 bad samples (1 of them time stamps out of order)" "the summary counts it"
grep_in "$T/live.out" "END frame, the sender sent 300 samples, 299 received" "the session goes on to its END"
reads_back rec_gl.bin 299 "the recording holds every other sample"
# a stamp far ahead of both neighbours: known at the next sample, which the
# hold of one sample lets drop it (recorded, every later sample went back)
live_case spike rec_sp.bin 5
expect_rc "$LIVE_RC" 1 "live with one stamp 1000 s ahead"
grep_in "$T/live.err" "bad time stamp: sample frame seq 151 stamped 1000.375000 s, ahead of the samples on both sides (0.372500 and 0.377500 s); it is skipped" "the stamp ahead is found and dropped"
grep_in "$T/live.out" "END frame, the sender sent 300 samples, 299 received" "the session goes on past the stamp ahead"
reads_back rec_sp.bin 299 "the recording holds every other sample"
# a late copy of a sample dropped for its stamp is a copy, not a restart
live_case glitch_copy rec_gc.bin 5
grep_in "$T/live.err" "repeated frame: sample frame seq 151 received again after seq 153 (a late copy); skipped" "the copy of a dropped sample is a copy"
grep_in "$T/live.out" "END frame, the sender sent 300 samples, 299 received" "the session goes on to its END"
# the first sample stamped ahead, no INFO, nothing before it to judge by:
# the 8 samples after it, rising, show it; they are taken back
live_case spike_first rec_sf.bin 5
grep_in "$T/live.err" "bad time stamp: sample frame seq 1 stamped 1000.000000 s, ahead of the 8 samples after it (from 0.002500 s), which are taken back; it is skipped" "the first sample stamped ahead is found"
grep_in "$T/live.out" "END frame, the sender sent 300 samples, 299 received" "the session goes on"
reads_back rec_sf.bin 299 "the recording holds every other sample"
# ... with a frame lost on the link among the samples taken back: not the sender's loss
live_case firstahead_loss rec_fl.bin 5
grep_in "$T/live.err" "ahead of the 8 samples after it (from 0.002500 s), which are taken back" "the first sample stamped ahead is found"
if grep -q "sensor drop" "$T/live.err"; then fail "a link loss among the samples taken back called the sender's"; else pass "the link's loss stays the link's"; fi
# ... and a run cut short by END: the 5 after it are taken back, the first dropped
live_case firstahead_end rec_fe.bin 5
grep_in "$T/live.err" "ahead of the 5 samples after it (from 0.002500 s), which are taken back" "a short run at END is taken back too"
reads_back rec_fe.bin 5 "the recording holds the 5 good samples"
# after frames lost on the link the intervals count the frames lost: the
# early sample is the one dropped, not the one before it
live_case loss_early rec_le.bin 5
grep_in "$T/live.err" "bad time stamp: sample frame seq 152 stamped 0.374500 s, behind the last sample's 0.375000 s" "after a loss the early stamp is the one dropped"
# the clock back for good with the sequence going on: eight in a row end the session
live_case clockback rec_cb.bin 5
expect_rc "$LIVE_RC" 1 "live when the sender's clock goes back 10 s"
grep_in "$T/live.err" "the sender's clock went back from 100.372500 s to 90.375000 s at sample frame seq 151 and stayed behind for 8 samples" "the clock gone back is named"
grep_in "$T/live.out" "live: end: the sender's clock went back" "the end line says how the run ended"
reads_back rec_cb.bin 150 "the recording holds the samples before it"
# a reboot whose clock goes on: the session goes on, END counts since the restart
live_case reboot rec_rb.bin 5
expect_rc "$LIVE_RC" 0 "live across a sender's reboot with its clock going on (nothing lost)"
grep_in "$T/live.out" "END frame, the sender sent 200 samples since it restarted, 200 received since (400 in all)" "END is read against the samples since the restart"
reads_back rec_rb.bin 400 "the recording holds both"
live_case reboot_lost rec_rbl.bin 5
expect_rc "$LIVE_RC" 1 "live across a reboot, a frame lost after it"
grep_in "$T/live.err" "incomplete: 1 frames lost, 0 corrupt frames, 0 bad samples, 0 bad INFO frames, 1 samples missing, 0 more than the sender sent" "the loss after the restart is counted against END (not '199 more than the sender sent')"
# (few samples before the reboot, more lost after it: still counted since the restart)
live_case reboot_short rec_rbs.bin 5
grep_in "$T/live.err" "incomplete: 3 frames lost, 0 corrupt frames, 0 bad samples, 0 bad INFO frames, 3 samples missing, 0 more than the sender sent" "3 lost after a reboot that came early are 3 missing"
# the interval across the restart (the reboot's second in it) is not the
# sender's: the early stamp after the reboot is the one dropped
live_case reboot_glitch rec_rbg.bin 5
grep_in "$T/live.err" "bad time stamp: sample frame seq 3 stamped 1700000001.502000 s, behind the last sample's" "after a reboot the early stamp is the one dropped"

# an INFO frame after the first sample (live joined a running sender) is
# written into the recording's header at the end: its sensor, rate and
# temperature flag (the temperatures were not read)
live_case lateinfo rec_li.bin 5
expect_rc "$LIVE_RC" 0 "live when the INFO frame comes after the first samples"
grep_in "$T/live.err" "the header was written again at the end with the sender's last INFO frame (none had come by the first sample)" "the late header is said"
reads_back rec_li.bin "300 (with temperature)" "the recording reads back whole, with its temperatures"
grep_in "$T/info.out" "sensor      IMU-X" "the header names the sender"
grep_in "$T/info.out" "rate        400.000 Hz (nominal)" "the header gives the INFO's rate"
if grep -q "carries a temperature" "$T/info.out"; then fail "the temperatures are not read"; else pass "no temperature warning"; fi
live_case ratechange rec_rc.bin 5
expect_rc "$LIVE_RC" 0 "live when the INFO changes the rate"
grep_in "$T/live.err" "the sender's INFO frame seq 101 changes its rate from 400 to 100 Hz" "the change is warned"
reads_back rec_rc.bin 200 "the recording reads back whole"
if grep -q "(nominal)" "$T/info.out"; then fail "the header keeps a nominal rate that changed"; else pass "the header gives no nominal rate"; fi
# an INFO that differs only in a flag bit this receiver does not know (a
# newer sender's) changes nothing recorded: no rewrite said
live_case newflag rec_nf.bin 5
expect_rc "$LIVE_RC" 0 "live when a later INFO adds an unknown flag bit"
if grep -q "written again" "$T/live.err"; then fail "the header rewritten for an unknown flag bit"; cat "$T/live.err"; else pass "no header rewrite for an unknown flag bit"; fi
reads_back rec_nf.bin 200 "the recording reads back whole"
# the header's temperature and counter bits cover what the recording holds:
# an INFO that stops announcing a temperature mid-session keeps the ones
# recorded under it readable (the header said none, and info called it a
# writer's fault); a temperature the INFO in force says the samples lack is
# discarded, said once; a counter some samples came without is not the
# header's (info counted a running index into a counter as drops)
live_case tempoff rec_toff.bin 5
expect_rc "$LIVE_RC" 0 "live when the INFO stops announcing a temperature"
reads_back rec_toff.bin "200 (with temperature)" "the temperatures recorded under the first INFO are read"
if grep -q "carries a temperature" "$T/info.out"; then fail "the recording's header denies its temperatures"; cat "$T/info.out"; else pass "no temperature warning on the recording"; fi
live_case tempdenied rec_tden.bin 5
expect_rc "$LIVE_RC" 0 "live when the samples carry a temperature the INFO does not announce"
grep_in "$T/live.err" "sample frame seq 1 carries a temperature, but the sender's INFO frame says its samples have none (flags bit 1): the temperatures are not recorded" "the temperatures discarded are said"
reads_back rec_tden.bin 300 "the recording reads back without temperatures"
if grep -q "carries a temperature" "$T/info.out"; then fail "the recording holds temperatures its header denies"; cat "$T/info.out"; else pass "no temperature warning on the recording"; fi
# no INFO: temperatures that start after the first sample set the header's bit at the end (the header written
# at the first sample had none, and the recording read as "a writer's fault?", no temperature read)
live_case tempnoinfo rec_tni.bin 5
expect_rc "$LIVE_RC" 0 "live when the samples' temperatures start after the first sample, no INFO"
grep_in "$T/live.err" "the header was written again at the end: samples after the first carried a temperature (no INFO frame came)" "the rewrite is said"
reads_back rec_tni.bin "200 (with temperature)" "the recording reads back, its temperatures read"
if grep -q "carries a temperature" "$T/info.out"; then fail "the recording's header denies its temperatures"; cat "$T/info.out"; else pass "the header covers the temperatures recorded"; fi
live_case seqon rec_sqon.bin 5
expect_rc "$LIVE_RC" 0 "live when the INFO starts announcing a sensor counter mid-session"
grep_in "$T/live.err" "the header was written again at the end with the sender's last INFO frame (it changed during the session; samples came without the sensor counter it announces: the header gives none)" "the counter bit cleared is said"
reads_back rec_sqon.bin 200 "the recording reads back"
if grep -q "^drops" "$T/info.out"; then fail "a running index read as the sensor's counter"; cat "$T/info.out"; else pass "no counter drops from the samples before the counter"; fi
# a frame of a type this receiver does not know (a newer sender's) is
# skipped and counted, and said once
live_case newtype rec_nt.bin 5 --json "$T/nt.json"
expect_rc "$LIVE_RC" 0 "live with a frame of an unknown type among the samples"
grep_in "$T/live.err" "frame seq 101 is of type 0x06, which this receiver does not know (a newer sender?): such frames are skipped and counted" "the unknown type is said"
grep_in "$T/live.out" "unknown 1)" "and counted"
reads_back rec_nt.bin 200 "the samples around it are recorded"
if /usr/bin/python3 -c "import json,sys; l=json.load(open(sys.argv[1]))['link']; sys.exit(0 if l['unknown_frames'] == 1 else 1)" "$T/nt.json"; then
    pass "the JSON's link counts it (unknown_frames)"; else fail "unknown_frames: $(head -c 400 "$T/nt.json")"; fi
# the sender's text with a line break and an escape sequence (clear screen)
live_case ctlname rec_cn.bin 5
grep_in "$T/live.out" 'live: sender: IMU?"x"?\[2J, 400 Hz' "the sender's name is printed as one line of text"
if grep -q "$(printf '\033')" "$T/live.out"; then fail "an escape byte reached the terminal"; else pass "no escape byte in the summary"; fi
grep_in "$T/live.err" "holds control characters or bytes that are not UTF-8 (shown and recorded as '?')" "said once"
reads_back rec_cn.bin 300 "the recording reads back"
grep_in "$T/info.out" 'sensor      IMU?"x"?\[2J' "the recording's header holds the name as one line"

# interrupt_after_records RECORDING N PAUSE: once the recording holds N
# samples, wait PAUSE s, Ctrl-C live and end the sender running as $DRIP
interrupt_after_records() {
    wait_for '[ -f "$T/$1" ] && [ "$(records "$T/$1")" -ge '"$2"' ]' 100
    sleep "$3"
    kill -INT "$LIVE" 2>/dev/null
    wait_live
    kill "$DRIP" 2>/dev/null
    wait "$DRIP" 2>/dev/null
}

# --- Ctrl-C while a frame is on its way (a real UART delivers a frame in
# pieces, so a stop lands inside one about half of the time at 400 Hz): the
# piece is not a corrupt frame, and the run exits 0 as a stop between frames
# does (not exit 1, "incomplete: 0 frames lost, 1 corrupt frames"). The
# sender drips the piece a byte at a time, so the line is never
# quiet long enough for the decoder to give it up before the signal.
stop_link
start_link
start_live --record "$T/rec_cut.bin"
/usr/bin/python3 -c "
import os, sys, time
sys.path.insert(0, 'tests/cli')
from wire_cases import info, still, frame, SAMPLE
fd = os.open(sys.argv[1], os.O_WRONLY | os.O_NOCTTY)
os.write(fd, info(400.0) + b''.join(frame(SAMPLE, 1 + k, still(k)) for k in range(300)))
for c in frame(SAMPLE, 301, still(300))[:30]:
    os.write(fd, bytes([c]))
    time.sleep(0.2)
time.sleep(2)
os.close(fd)" "$B" &
DRIP=$!
interrupt_after_records rec_cut.bin 300 0.5
expect_rc "$LIVE_RC" 0 "live stopped by Ctrl-C inside a frame, nothing lost"
grep_in "$T/live.out" "live: link: 0 bad frames, 0 lost frames" "the piece of a frame is not counted as a corrupt frame"
grep_in "$T/live.out" "live: end: stopped by SIGINT (Ctrl-C); the frame arriving then was cut" "the summary says a frame was cut by the stop"
reads_back rec_cut.bin 300 "the recording holds the 300 whole samples"

# --- the sensor switched off mid-frame, Ctrl-C pressed after the line was
# quiet long enough for the decoder to give the piece up (IDLE_FLUSH_S): the
# piece is a cut frame as when Ctrl-C comes first (it was counted corrupt,
# exit 1, by how fast the user pressed it: the live audit of 2026-12-06)
stop_link
start_link
start_live --record "$T/rec_off.bin"
/usr/bin/python3 -c "
import os, sys, time
sys.path.insert(0, 'tests/cli')
from wire_cases import info, still, frame, SAMPLE
fd = os.open(sys.argv[1], os.O_WRONLY | os.O_NOCTTY)
os.write(fd, info(400.0) + b''.join(frame(SAMPLE, 1 + k, still(k)) for k in range(300)) + frame(SAMPLE, 301, still(300))[:25])
time.sleep(6)
os.close(fd)" "$B" &
DRIP=$!
interrupt_after_records rec_off.bin 300 3
expect_rc "$LIVE_RC" 0 "live stopped by Ctrl-C seconds after the sensor went off mid-frame"
grep_in "$T/live.out" "live: link: 0 bad frames, 0 lost frames" "the piece left by the switch-off is not a corrupt frame"
grep_in "$T/live.out" "the frame arriving then was cut" "the summary says a frame was cut"
reads_back rec_off.bin 300 "the recording holds the 300 whole samples"

# --- the sender goes quiet with the port still open (stream killed, socat
# still up, so no hang-up): the status line does not say the same thing
# every second, for ever, as if all were well; it says how long no frame has
# come (--timeout only ends the test)
stop_link
start_link
start_live --print-every 0.25 --timeout 2
/usr/bin/python3 -c "
import os, sys
sys.path.insert(0, 'tests/cli')
from wire_cases import info, still, frame, SAMPLE
fd = os.open(sys.argv[1], os.O_WRONLY | os.O_NOCTTY)
os.write(fd, info(400.0) + b''.join(frame(SAMPLE, 1 + k, still(k)) for k in range(100)))
os.close(fd)" "$B" || fail "the quiet sender failed"
wait_live
grep_in "$T/live.err" "live: sensor time 0.2 s, 100 samples | .* | no frame for 1 s" "the status line says no frame has come for 1 s"
grep_in "$T/live.err" "bad frames 0, lost frames 0" "the status line names its counters"

# --- a slow but steady sender: one sample frame every 80 ms for 2 s, each
# gap shorter than --timeout 0.5 and the whole longer: live keeps going (the
# timer restarts at every frame; a mutant of cmd_live.c that never restarts
# it stopped at 0.5 s with 6 samples, checked), then stops at the timeout once the sender
# goes quiet (it holds the port open 1.5 s more: a close is a hang-up)
stop_link
start_link
start_live --timeout 0.5
/usr/bin/python3 -c "
import os, sys, time
sys.path.insert(0, 'tests/cli')
from wire_cases import info, still, frame, SAMPLE
fd = os.open(sys.argv[1], os.O_WRONLY | os.O_NOCTTY)
os.write(fd, info(400.0))
for k in range(25):
    os.write(fd, frame(SAMPLE, 1 + k, still(k)))
    time.sleep(0.08)
time.sleep(1.5)
os.close(fd)" "$B" || fail "the slow sender failed"
wait_live
expect_rc "$LIVE_RC" 1 "live whose slow sender goes quiet (no END)"
grep_in "$T/live.out" "live: $A: 25 samples over" "every one of the 25 slow samples is received"
grep_in "$T/live.out" "live: end: no valid frame for 0.5 s (--timeout)" "the run ends at the timeout once the sender is quiet"

# live_with_gnuplot DIR SCRIPT ARGS...: a fake gnuplot (SCRIPT, printf %b
# escapes) first on live's PATH, live with ARGS on a new pty pair
live_with_gnuplot() {
    mkdir -p "$T/$1"
    printf '%b' "$2" >"$T/$1/gnuplot"
    chmod +x "$T/$1/gnuplot"
    gpdir=$T/$1
    shift 2
    stop_link
    start_link
    PATH="$gpdir:$PATH" LD_PRELOAD=$SEAM "$H" live "$A" --print-every 0 "$@" >"$T/live.out" 2>"$T/live.err" &
    LIVE=$!
    if ! wait_for 'grep -q "reading" "$T/live.err"' 200; then fail "live did not start"; fi
}
# send_still HOLD: an INFO frame and 100 still samples into end B, the line
# then held open HOLD seconds
send_still() {
    /usr/bin/python3 -c "
import os, sys, time
sys.path.insert(0, 'tests/cli')
from wire_cases import info, still, frame, SAMPLE
fd = os.open(sys.argv[1], os.O_WRONLY | os.O_NOCTTY)
os.write(fd, info(400.0) + b''.join(frame(SAMPLE, 1 + k, still(k)) for k in range(100)))
time.sleep(float(sys.argv[2]))
os.close(fd)" "$B" "$1"
}

# --- a signal after the run has ended (here by --timeout), while the last
# picture is drawn: the run still ended by the timeout, and the summary and
# the JSON say so, as the exit status and the error do (not "stopped by
# SIGINT"). A gnuplot that takes 3 s.
live_with_gnuplot slowgp '#!/bin/sh\ncat >/dev/null\nsleep 3\nexit 1\n' --timeout 0.5 --plot "$T/late.png" \
    --plot-every 100 --json "$T/late.json"
send_still 3 &
QUIET=$!
sleep 2 # the timeout at about 0.5 s, then the picture: 3 s
kill -INT "$LIVE" 2>/dev/null
wait_live
wait "$QUIET" 2>/dev/null
grep_in "$T/live.out" "live: end: no valid frame for 0.5 s (--timeout)" "a signal while the last picture is drawn: the end is still the timeout"
if /usr/bin/python3 -c "import json,sys; sys.exit(0 if json.load(open(sys.argv[1]))['link']['end'] == 'timeout' else 1)" "$T/late.json"; then
    pass "the JSON's end is the timeout"; else fail "the JSON's end: $(head -c 600 "$T/late.json")"; fi

# --- a second signal while the last picture is drawn (the run ended by the
# first): the wait for the picture goes on (that handler has no SA_RESTART;
# the interrupted wait said "the last picture was not drawn", exit 3, and
# the picture came after; the live audit). A gnuplot that takes 1 s and
# writes its file.
# (the gnuplot adds a line to a file beside it when it starts: the last
# picture's, whose 1 s the second signal lands in)
# (a whole PNG, its signature and IEND chunk: an empty file is no picture)
mkdir -p "$T/gp1"
printf '\211PNG\r\n\032\n\000\000\000\000IEND\256B`\202' >"$T/gp1/whole.png"
live_with_gnuplot gp1 '#!/bin/sh\necho run >>"${0%/*}/started"\nf=$(sed -n "s/^set output .\\(.*\\).$/\\1/p" | head -n 1)\nsleep 1\ncat "${0%/*}/whole.png" >"$f"\n' \
    --timeout 30 --plot "$T/two.png" --plot-every 100 --record "$T/rec_two.bin"
send_still 0
wait_for '[ -f "$T/rec_two.bin" ] && [ "$(records "$T/rec_two.bin")" -ge 99 ]' 100
kill -INT "$LIVE" 2>/dev/null
wait_for '[ -s "$T/gp1/started" ]' 100
sleep 0.2
kill -INT "$LIVE" 2>/dev/null
wait_live
expect_rc "$LIVE_RC" 0 "live with a second Ctrl-C while the last picture is drawn"
if grep -q "was not drawn" "$T/live.err"; then fail "the interrupted wait called the picture not drawn"; else pass "the picture's wait went on"; fi
if [ -e "$T/two.png" ]; then pass "the last picture is there when live ends"; else fail "no picture when live ended"; fi

# --- the reader of --out - goes away (live ... | head): a write error (exit 3)
# with the summary and a complete recording, not a death by SIGPIPE
stop_link
start_link
( LD_PRELOAD=$SEAM timeout $LIMIT "$H" live "$A" --print-every 0 --record "$T/rec_p.bin" --out - --timeout 3 \
    2>"$T/live.err"; echo $? >"$T/live.rc" ) | head -2 >/dev/null &
PIPED=$!
if ! wait_for 'grep -q "reading" "$T/live.err"' 200; then fail "live did not start"; fi
stream vectors/walk.bin --speed 0
wait "$PIPED"
stop_link
start_link # a fresh pair for the cases below
expect_rc "$(cat "$T/live.rc")" 3 "live whose CSV reader went away"
grep_in "$T/live.err" "recorded" "the summary still names the recording"
# the end's error names standard output, as replay's does (it said "cannot write - (Broken pipe)")
grep_in "$T/live.err" "error: cannot write the trajectory to standard output (Broken pipe)$" "the end's error names standard output"
# ... and so does the error when the write fails, mid-run (it said "cannot write the trajectory CSV (Broken pipe)")
grep_in "$T/live.err" "error: cannot write the trajectory to standard output (Broken pipe); it stops here$" "the mid-run error names standard output"
timeout $LIMIT "$H" info "$T/rec_p.bin" >"$T/info.out" 2>&1
expect_rc $? 0 "the recording is complete and closed"

# --- Ctrl-C while the trajectory waits on a slow reader of --out - (the pipe
# full): the write goes on once the reader reads, and what was computed is
# kept: exit 0, and the CSV is the replay of the recording, row for row. A
# signal that interrupted the blocked write would give "cannot write the
# trajectory CSV", exit 3, and 188 of 304 rows. The signal goes
# to the harness itself: timeout(1) passes one on twice (to the child and to
# its process group), the second of which rightly cuts the write, below.
( LD_PRELOAD=$SEAM "$H" live "$A" --print-every 0 --record "$T/rec_s.bin" --out - --timeout 30 \
    2>"$T/live.err" & echo $! >"$T/live.pid"; wait $!; echo $? >"$T/live.rc" ) | (sleep 4; cat >"$T/slow.csv") &
PIPED=$!
if ! wait_for 'grep -q "reading" "$T/live.err"' 200; then fail "live did not start"; fi
LIVE=$(cat "$T/live.pid") # for the cleanup trap
LD_PRELOAD=$SEAM "$H" stream vectors/walk.bin "$B" --speed 0 >/dev/null 2>&1 &
STREAM=$!
sleep 2
kill -INT "$(cat "$T/live.pid")" 2>/dev/null
wait "$PIPED"
LIVE=""
kill -9 "$STREAM" 2>/dev/null
wait "$STREAM" 2>/dev/null
STREAM=""
stop_link
start_link
expect_rc "$(cat "$T/live.rc")" 0 "live stopped by Ctrl-C while its --out - reader is slow"
if grep -q "cannot write" "$T/live.err"; then fail "the signal broke the trajectory's write: $(grep "cannot write" "$T/live.err")"; else pass "no write error from the signal"; fi
timeout $LIMIT "$H" replay "$T/rec_s.bin" --out "$T/slow_rep.csv" >/dev/null 2>&1
if [ "$(wc -l <"$T/slow.csv")" -gt 1 ] && cmp -s "$T/slow.csv" "$T/slow_rep.csv"; then
    pass "the trajectory written is the replay of the recording ($(($(wc -l <"$T/slow.csv") - 1)) rows)"
else
    fail "the trajectory written ($(wc -l <"$T/slow.csv") lines) is not the replay of the recording ($(wc -l <"$T/slow_rep.csv") lines)"
fi

# ... and a reader that never reads: a second signal interrupts the write,
# and live ends at once with the write error (exit 3) and a closed recording
rm -f "$T/live.rc"
( LD_PRELOAD=$SEAM "$H" live "$A" --print-every 0 --record "$T/rec_s2.bin" --out - --timeout 30 \
    2>"$T/live.err" & echo $! >"$T/live.pid"; wait $!; echo $? >"$T/live.rc" ) | (sleep 30; cat >/dev/null) &
PIPED=$!
if ! wait_for 'grep -q "reading" "$T/live.err"' 200; then fail "live did not start"; fi
LIVE=$(cat "$T/live.pid") # for the cleanup trap
LD_PRELOAD=$SEAM "$H" stream vectors/walk.bin "$B" --speed 0 >/dev/null 2>&1 &
STREAM=$!
sleep 2
kill -INT "$(cat "$T/live.pid")" 2>/dev/null
sleep 0.5
kill -INT "$(cat "$T/live.pid")" 2>/dev/null
if wait_for '[ -s "$T/live.rc" ]' 100; then
    expect_rc "$(cat "$T/live.rc")" 3 "live stopped by a second Ctrl-C while its --out - reader never reads"
else
    fail "live did not end within 10 s of a second Ctrl-C"
fi
kill -9 "$LIVE" 2>/dev/null
LIVE=""
kill -9 "$STREAM" 2>/dev/null
wait "$STREAM" 2>/dev/null
STREAM=""
kill "$PIPED" 2>/dev/null
wait "$PIPED" 2>/dev/null
stop_link
start_link
timeout $LIMIT "$H" info "$T/rec_s2.bin" >"$T/info.out" 2>&1
expect_rc $? 0 "the recording is complete and closed"

# --- memory for the summary's trajectory runs out (ulimit -v): the run
# goes on, the summary covers what fitted and says so (it said nothing:
# "duration 1310.72 s" for 3,750 s received, exit 0; the live audit). Not
# under a sanitizer, whose shadow memory no such limit admits.
if (ulimit -v 45000 && "$H" --version) >/dev/null 2>&1; then
    stop_link
    start_link
    /usr/bin/python3 -c "
import sys
sys.path.insert(0, 'tests/cli')
from wire_cases import info, still, frame, end, SAMPLE
n = 200000
sys.stdout.buffer.write(info(400.0) + b''.join(frame(SAMPLE, (k + 1) & 0xffff, still(k)) for k in range(n)) + end((n + 1) & 0xffff, n))
" >"$T/big.bin"
    ( ulimit -v 45000; LD_PRELOAD=$SEAM exec timeout $LIMIT "$H" live "$A" --print-every 0 --timeout 5 --json "$T/mem.json" \
        >"$T/live.out" 2>"$T/live.err" ) &
    LIVE=$!
    wait_for 'grep -q "reading" "$T/live.err"' 200
    timeout 60 cat "$T/big.bin" >"$B"
    wait_live
    expect_rc "$LIVE_RC" 0 "live whose summary's memory runs out (nothing lost)"
    grep_in "$T/live.err" "out of memory keeping the trajectory (131072 outputs, 20 MB): the summary, --json and --plot cover those" "the partial summary is said"
    grep_in "$T/live.out" "200000 samples over 499.998 s" "every sample was received"
    if grep -q '"summary_partial":[[:space:]]*true' "$T/mem.json"; then pass "the JSON says the summary is partial"; else fail "summary_partial not true: $(cat "$T/mem.json")"; fi
else
    echo "note: the memory case skipped: $H does not start under ulimit -v 45000 (a sanitizer build)"
fi

# --- the tty hangs up under a node that stays (rfcomm, vhangup): exit 1, samples kept
if msg=$(timeout $LIMIT /usr/bin/python3 tests/cli/live_vhangup.py "$H" "$SEAM" "$T"); then
    pass "live ends on a hang-up whose device node stays${msg:+ ($msg)}"
else
    fail "live on a hang-up: $msg"
fi

# --- standard error on a terminal: a warning starts a line of its own
if msg=$(timeout $LIMIT /usr/bin/python3 tests/cli/live_tty.py "$H" "$SEAM" "$T"); then
    pass "on a terminal, a warning does not share the status line"
else
    fail "live on a terminal: $msg"
fi

# --- nobody sends: --timeout ends the run; --json is written all the same
# (not skipped with no frame, leaving an earlier run's file beside the
# emptied --out)
# with --plot-every and no sample yet: no redraw gives gnuplot empty data, whose errors would run down standard
# error every S seconds
if command -v gnuplot >/dev/null 2>&1; then
    start_live --timeout 1.5 --plot-every 0.2 --plot "$T/idle.png"
    wait_live
    expect_rc "$LIVE_RC" 1 "live --plot-every with no sender"
    if grep -qi "gnuplot\|no data\|warning" "$T/live.err"; then fail "no sender, --plot-every: $(grep -i -m3 "gnuplot\|no data\|warning" "$T/live.err")"
    else pass "no sender, --plot-every: no gnuplot message"; fi
fi
echo '{"stale": "an earlier run"}' >"$T/stale.json"
start_live --timeout 1 --json "$T/stale.json"
wait_live
expect_rc "$LIVE_RC" 1 "live --timeout with no sender"
grep_in "$T/live.err" "no valid frame for 1.0 s (--timeout); giving up: nothing received" "the timeout is explained"
grep_in "$T/live.out" "live: end: no valid frame for 1.0 s (--timeout)" "the summary says how the run ended"
if /usr/bin/python3 -c "import json,sys; d=json.load(open(sys.argv[1])); sys.exit(0 if d.get('aligned') is False else 1)" "$T/stale.json"; then
    pass "--json written without a frame (aligned false)"; else fail "--json not rewritten: $(cat "$T/stale.json")"; fi

# --- bytes that never make a frame (a wrong baud rate), ended by SIGTERM:
# exit 1 and messages that say what arrived (not exit 0 as if complete, with
# the status line reading "aligning (keep the foot still)")
stop_link
start_link
LD_PRELOAD=$SEAM "$H" live "$A" --print-every 0.2 >"$T/live.out" 2>"$T/live.err" &
LIVE=$!
wait_for 'grep -q "reading" "$T/live.err"' 200
# 40 times the bytes 0..255: never A5 followed by 5A
/usr/bin/python3 -c "import sys; sys.stdout.buffer.write(bytes(range(256)) * 40)" >"$T/garbage.bin"
timeout 30 cat "$T/garbage.bin" >"$B"
wait_for 'grep -q "10240 bytes received" "$T/live.err"' 100
kill -TERM "$LIVE" 2>/dev/null
wait_live
expect_rc "$LIVE_RC" 1 "live ended by SIGTERM without a sample"
grep_in "$T/live.err" "waiting: 10240 bytes received, no valid frame (wrong --baud" "the status line says bytes came but no frame"
grep_in "$T/live.err" "no sample received from $A: 10240 bytes received" "the end says no sample was received"
grep_in "$T/live.out" "live: end: stopped by SIGTERM" "the summary says how the run ended"

# --- a recording that cannot be written (a full disk): the summary counts
# what the file holds, not what was received (not 40 recorded)
start_live --record /dev/full
stream vectors/walk.bin --speed 0
wait_live
grep_in "$T/live.out" "recorded 0 samples" "a failed recording counts what it holds"

# --- a trajectory that cannot be written (a full disk): the reason is given
# (not "cannot write the trajectory CSV; it stops here" and "cannot write
# /dev/full" alone), the summary and the JSON are still written, exit 3
rm -f "$T/fulllive.json"
start_live --out /dev/full --json "$T/fulllive.json"
stream vectors/walk.bin --speed 0
wait_live
expect_rc "$LIVE_RC" 3 "live --out onto a full disk"
grep_in "$T/live.err" "cannot write the trajectory CSV (No space left on device); it stops here" "live: the failed write's reason given"
grep_in "$T/live.err" "cannot write /dev/full (No space left on device)" "live: the end names the file and the reason"
grep_in "$T/live.out" "return-to-start" "live: the summary written beside the failed CSV"
[ -s "$T/fulllive.json" ] && pass "live: the JSON written beside the failed CSV" || fail "live: no JSON beside the failed CSV"

# --- stream interrupted while a write waits on a port nobody reads: it
# stops at once with 143 (not waiting out the 10 s write timeout, then
# exiting 3, as libserialport resumes an interrupted write)
stop_link
start_link
LD_PRELOAD=$SEAM "$H" stream vectors/walk.bin "$B" --speed 0 >"$T/stream.out" 2>"$T/stream.err" &
STREAM=$!
sleep 1
t0=$(date +%s)
kill -TERM "$STREAM" 2>/dev/null
wait "$STREAM"
STREAM_RC=$?
STREAM=""
dt=$(($(date +%s) - t0))
expect_rc "$STREAM_RC" 143 "stream stopped by SIGTERM while its write is blocked"
if [ "$dt" -le 5 ]; then pass "it stopped within $dt s"; else fail "it took $dt s to stop"; fi
grep_in "$T/stream.out" "the interrupt cut the write" "stream says the batch was cut"
# ... and by SIGHUP (the terminal it runs in closes), as live handles it:
# stream does not die of it, with no summary of what it had sent; 129 as for
# any signal, 128 + its number
# stream_signalled SIG LOG ARGS...: stream LOG to end B, signalled with SIG
# after 1 s; its status in STREAM_RC
stream_signalled() {
    sig=$1
    log=$2
    shift 2
    LD_PRELOAD=$SEAM "$H" stream "$log" "$B" "$@" >"$T/stream.out" 2>"$T/stream.err" &
    STREAM=$!
    sleep 1
    kill -"$sig" "$STREAM" 2>/dev/null
    wait "$STREAM"
    STREAM_RC=$?
    STREAM=""
}
stop_link
start_link
stream_signalled HUP vectors/walk.bin --speed 0
expect_rc "$STREAM_RC" 129 "stream stopped by SIGHUP while its write is blocked"
grep_in "$T/stream.out" "(interrupted)" "stream stopped by SIGHUP says what it sent"

# --- hx_serial_write on a slow but steady reader (4 KB every 200 ms once the
# pty is full: each pause shorter than the 500 ms timeout, the whole longer)
# completes, and on a reader that reads nothing gives up after the timeout
# (tests/cli/serial_write_slow.c, built here against harness/hx_serial.c; a
# mutant that never restarted the timer after progress gave up after 1.1 s
# and passed every other case, checked)
if ${CC:-cc} -std=c99 -Wall -D_POSIX_C_SOURCE=200809L -Iharness -o "$T/serial_write_slow" \
    tests/cli/serial_write_slow.c harness/hx_serial.c -lserialport 2>"$T/cc.err"; then
    if msg=$(LD_PRELOAD=$SEAM timeout $LIMIT "$T/serial_write_slow"); then
        pass "a write to a slow but steady reader completes; to a silent one it times out"
    else
        fail "hx_serial_write's idle timer: $msg"
    fi
else
    fail "cannot build tests/cli/serial_write_slow.c: $(cat "$T/cc.err")"
fi

# --- stream: an interrupt while the END frame drains interrupts nothing:
# every sample and END reach the receiver, exit 0 (not 130)
stop_link
start_link # a fresh pair: the stream above was not read to its end
# 622 samples: the last write (78 samples and END, after four full 8 KB
# batches) is the one the pty pair's buffers cannot take until live reads
head -623 "$T/orig.csv" >"$T/short.csv"
LD_PRELOAD=$SEAM timeout $LIMIT "$H" stream "$T/short.csv" "$B" --speed 0 >"$T/stream.out" 2>"$T/stream.err" &
STREAM=$!
sleep 1
kill -INT "$STREAM" 2>/dev/null
sleep 0.3
start_live --timeout 5
wait "$STREAM"
STREAM_RC=$?
STREAM=""
wait_live
if grep -q "END frame, the sender sent 622 samples, 622 received" "$T/live.out"; then
    expect_rc "$STREAM_RC" 0 "stream interrupted while its END frame drained"
else
    # smaller pty buffers (another kernel) block an earlier batch: then the
    # interrupt did stop the stream before END, and 130 is right
    expect_rc "$STREAM_RC" 130 "stream interrupted before its END frame"
fi
stop_link

# --- stream (the stream audit of 2026-12-06): a log whose stamps imply a
# rate beyond the protocol's 1e6 Hz (read in us: 400 MHz) sends rate 0 in
# its INFO frame, which the receiver takes (it refused the frame and called
# the clean stream incomplete, exit 1)
stop_link
start_link
start_live --timeout 5
head -301 "$T/orig.csv" >"$T/s300.csv"
stream "$T/s300.csv" --units time=us --speed 0
wait_live
expect_rc "$STREAM_RC" 0 "stream of a log read in us (a 400 MHz rate)"
grep_in "$T/stream.err" "the log's rate 3.9863e+08 Hz is beyond the wire protocol's 1e6 Hz; the INFO frame gives it as 0" "stream says the rate is sent as unknown"
expect_rc "$LIVE_RC" 0 "live takes its INFO frame"
if grep -q "bad INFO frame" "$T/live.err"; then fail "the INFO frame was refused"; else pass "no bad INFO frame"; fi
# a Ctrl-C in the wait for a sample not yet due sends nothing more (the
# sample after a 3 s gap went out at once, 2 s early)
{ head -101 "$T/orig.csv"; tail -n +102 "$T/orig.csv" | head -100 |
    awk -F, -v OFS=, '{ $1 = $1 + 3; print }'; } >"$T/gap.csv"
start_live --timeout 10
stream_signalled INT "$T/gap.csv" --speed 1
expect_rc "$STREAM_RC" 130 "stream interrupted in a 3 s gap"
grep_in "$T/stream.out" "^stream: 100 samples sent to" "nothing after the gap was sent"
stop_link
wait_live
start_link
# a --speed whose wait overflows, or that underflows to 0, is refused (both played at full speed)
for sp in 1e-22 1e-400; do
    timeout $LIMIT "$H" stream "$T/s300.csv" "$B" --speed $sp >"$T/stream.out" 2>"$T/stream.err"
    expect_rc $? 2 "stream --speed $sp"
    grep_in "$T/stream.err" "give 0 (as fast as the port takes it) or at least 0.001" "--speed $sp: the message says what is allowed"
done
# the arguments swapped: a serial device as the log is refused, not read for ever
LD_PRELOAD=$SEAM timeout 20 "$H" stream "$A" "$T/s300.csv" >"$T/stream.out" 2>"$T/stream.err"
expect_rc $? 2 "stream PORT LOG (swapped)"
grep_in "$T/stream.err" "is a character device (a terminal, a serial port), not a log: the order is" "the swap is named"
# --hangup-after beyond the log: said (the END frame went out without a word)
start_live --timeout 5
stream "$T/s300.csv" --speed 0 --hangup-after 1000
wait_live
grep_in "$T/stream.err" "--hangup-after 1000: .* has 300 samples, which end first, with the END frame" "a hang-up beyond the log is said"
stop_link

# a recording's name holding an escape sequence: the summary's `recorded ... to` line shows it with '?' (it wrote
# it as it was, as the port's name in its first line)
start_link
start_live --record "$T/r$(printf '\033')[2J.bin" --timeout 5
stream "$T/s300.csv" --speed 0
wait_live
if LC_ALL=C grep -q "$(printf '\033')" "$T/live.out" "$T/live.err"; then fail "live: the recording's escape reached the terminal"
else pass "live: the recording's name shown without its control characters"; fi
grep_in "$T/live.out" "recorded 300 samples to .*/r?\[2J.bin" "live: the recorded line with '?' for the control character"
stop_link

if [ "$fails" -ne 0 ]; then
    echo "test_live.sh: $fails failure(s)"
    exit 1
fi
echo "test_live.sh: all passed"
