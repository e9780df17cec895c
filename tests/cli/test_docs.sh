#!/bin/sh
# The documentation against the harness: every option of each command's
# --help is named in that command's document, and every option of a
# synopsis in docs/harness.md is in that command's --help; every key the
# JSON outputs write (replay, info, eval with the shared data, psd, allan,
# montecarlo) is named in theirs; every relative link, anchor and section
# reference of the docs resolves. Without it, the allan JSON's fit keys could
# be documented under names the code never writes, and most psd and allan
# keys go undocumented.
# $HARNESS is the harness binary (set by `make test-cli`).
set -u
H=${HARNESS:-bin/harness}
DOCS=$(cd "$(dirname "$0")/../../docs" && pwd)
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
W="$(dirname "$0")/../../vectors/walk.bin"

# --- options: COMMAND DOCUMENT (--from, --input-rate and --help are the
# conventions of docs/harness.md, shared by every command). A new command
# gets a line here (CONTRIBUTING.md, "Extending footnav").
CMD_DOCS="info harness.md
convert harness.md
merge harness.md
replay harness.md
eval harness.md
live harness.md
stream harness.md
allan allan.md
psd psd.md
sim simulator.md
montecarlo simulator.md
simgap simgap.md
simgap-validate simgap.md"
printf '%s\n' "$CMD_DOCS" | while read -r cmd doc; do
    "$H" "$cmd" --help >"$T/help" 2>&1
    missing=""
    for o in $(sed -n 's/^  \(--[a-z0-9-]*\).*/\1/p' "$T/help"); do
        case "$o" in --from | --input-rate | --help) continue ;; esac
        grep -q -e "$o\([^a-z0-9-]\|\$\)" "$DOCS/$doc" || missing="$missing $o"
    done
    if [ -z "$missing" ]; then pass "$cmd: every --help option is in docs/$doc"
    else fail "$cmd: docs/$doc lacks$missing"; fi
done >"$T/opts"
cat "$T/opts"
fails=$((fails + $(grep -c '^FAIL' "$T/opts")))

# --- every command `harness help` lists is in that list and in the command
# table of docs/harness.md: a new command was checked by nothing above
"$H" help >"$T/cmds" 2>&1
for cmd in $(sed -n '/^commands:/,$s/^  \([a-z][a-z0-9-]*\) .*/\1/p' "$T/cmds"); do
    if printf '%s\n' "$CMD_DOCS" | grep -q "^$cmd "; then pass "$cmd: in test_docs.sh's command list"
    else fail "$cmd: not in test_docs.sh's command list (add '$cmd DOCUMENT' to CMD_DOCS)"; fi
    if grep -q "^| \`$cmd[\` ]" "$DOCS/harness.md"; then pass "$cmd: in docs/harness.md's command table"
    else fail "$cmd: not in docs/harness.md's command table"; fi
done

# --- and back: every option of a command's synopsis in docs/harness.md (the
# first code block of its section, ## `CMD`) is in that command's --help
for cmd in $(printf '%s\n' "$CMD_DOCS" | awk '$2 == "harness.md" { print $1 }'); do
    "$H" "$cmd" --help >"$T/help" 2>&1
    awk -v h="## \`$cmd\`" '$0 == h { s = 1; next } s && /^## / { exit }
        s && /^```/ { if (b) exit; b = 1; next } s && b' "$DOCS/harness.md" >"$T/syn"
    if [ ! -s "$T/syn" ]; then fail "$cmd: no synopsis block under ## \`$cmd\` in docs/harness.md"; continue; fi
    extra=""
    for o in $(grep -o -e '--[a-z][a-z0-9-]*' "$T/syn" | sort -u); do
        grep -q -e "^ *$o\([^a-z0-9-]\|\$\)" "$T/help" || extra="$extra $o"
    done
    if [ -z "$extra" ]; then pass "$cmd: every option of its synopsis in docs/harness.md is in --help"
    else fail "$cmd: docs/harness.md's synopsis names options --help lacks:$extra"; fi
done

# --- JSON keys: every key written, at any depth, is named in the document
json_keys() { # JSON file -> one key per line
    /usr/bin/python3 -c '
import json, sys
def walk(v):
    if isinstance(v, dict):
        for k, x in v.items():
            print(k)
            walk(x)
    elif isinstance(v, list):
        for x in v:
            walk(x)
walk(json.load(open(sys.argv[1])))' "$1" | sort -u
}
check_keys() { # what JSON document
    if [ ! -s "$2" ]; then fail "$1: no JSON written"; return; fi
    missing=""
    for k in $(json_keys "$2"); do
        case "$k" in ax | ay | az | gx | gy | gz) continue ;; esac # channels, named as ax..gz
        grep -q -e "\`$k\(\`\|\[\]\)" "$DOCS/$3" || missing="$missing $k"
    done
    if [ -z "$missing" ]; then pass "$1: every JSON key is in docs/$3"
    else fail "$1: docs/$3 lacks the JSON keys$missing"; fi
}
expect_exit 0 "replay --json" "$H" replay "$W" --quiet --json "$T/replay.json"
check_keys "replay --json" "$T/replay.json" harness.md
expect_exit 0 "info --json" "$H" info "$W" --json "$T/info.json"
check_keys "info --json" "$T/info.json" harness.md
expect_exit 0 "psd --json" "$H" psd "$W" --sensitivity --json "$T/psd.json"
check_keys "psd --json" "$T/psd.json" psd.md
# allan on a static log (a walk is refused as not static, docs/allan.md "Command")
"$H" sim --motion stand --duration 120 --rate 100 --profile mtx --seed 3 --out "$T/stand.bin" >/dev/null 2>&1 ||
    fail "sim a static log for allan"
expect_exit 0 "allan --json" "$H" allan "$T/stand.bin" --channels gx,gy --fit-extra --json "$T/allan.json"
check_keys "allan --json" "$T/allan.json" allan.md
# eval needs the shared data (tests/cli/datadir.sh): its headline keys, from
# the main runs alone (--no-experiments; failed_experiment_runs is then null)
. "$(dirname "$0")/datadir.sh"
if [ -n "$D" ]; then
    expect_exit 0 "eval --json" "$H" eval --data "$D" --no-experiments --no-plots --out "$T/results.md" --json "$T/eval.json"
    check_keys "eval --json" "$T/eval.json" harness.md
else
    echo "SKIP test_docs.sh: no shared data, eval's JSON keys not checked"
fi
expect_exit 0 "montecarlo --json" "$H" montecarlo --duration 10 --seeds 2 --bias-model both --quiet --json "$T/mc.json"
check_keys "montecarlo --json" "$T/mc.json" simulator.md

# --- links and section references: every relative Markdown link of README.md,
# CONTRIBUTING.md and docs/*.md names a file that exists, and its #anchor a
# heading of that file (GitHub's slugs); every reference in prose to a
# section of another document, `X.md, "Heading"` (also `X.md "Heading"`,
# `[X.md](X.md), "Heading"`, across a line break), names a heading or a bold
# paragraph label (**Units check.**) of X.md that begins with that text.
# Outside code blocks and inline code.
ROOT=$(cd "$DOCS/.." && pwd)
if (cd "$ROOT" && /usr/bin/python3 - README.md CONTRIBUTING.md docs/*.md) >"$T/links" 2>&1 <<'PY'
import os, re, sys

def norm(s):
    return re.sub(r'\s+', ' ', re.sub(r'[`"*]', '', s)).strip().rstrip('.:').lower()

def slug(h):  # GitHub's anchor of a heading
    h = re.sub(r'\[([^\]]*)\]\([^)]*\)', r'\1', h.replace('`', '')).strip().lower()
    return ''.join(c for c in h if c.isalnum() or c in ' -_').replace(' ', '-')

def prose(path):  # the lines outside fenced code blocks, numbered
    fence = False
    for no, line in enumerate(open(path, encoding='utf-8'), 1):
        if line.startswith('```'):
            fence = not fence
            continue
        if not fence:
            yield no, line

cache = {}
def targets(path):  # (anchors, heading and bold-label texts) of a document
    if path not in cache:
        anchors, labels, seen, text = set(), [], {}, []
        for _, line in prose(path):
            m = re.match(r'#{1,6}\s+(.*?)\s*#*\s*$', line)
            if m:
                s = slug(m.group(1))
                n = seen.get(s, 0)
                seen[s] = n + 1
                anchors.add(s if n == 0 else '%s-%d' % (s, n))
                labels.append(norm(m.group(1)))
            anchors.update(re.findall(r'<a\s+(?:name|id)="([^"]+)"', line))
            text.append(line)
        for m in re.finditer(r'(?:^|\n)\s*(?:[*-]\s+)?\*\*(.+?)\*\*', ''.join(text), re.S):
            labels.append(norm(m.group(1)))
        cache[path] = (anchors, labels)
    return cache[path]

bad = 0
for f in sys.argv[1:]:
    lines = []
    for no, line in prose(f):
        line = re.sub(r'`[^`]*`', lambda m: m.group(0) if re.fullmatch(r'`[\w./-]+\.md`', m.group(0)) else '``', line)
        lines.append(line)
        for m in re.finditer(r'\]\(([^)\s]+)(?:\s+"[^"]*")?\)', line):
            t = m.group(1)
            if re.match(r'[a-z][a-z0-9+.-]*:', t):
                continue  # http:, mailto:
            p, _, frag = t.partition('#')
            tgt = os.path.normpath(os.path.join(os.path.dirname(f), p)) if p else f
            if not os.path.exists(tgt):
                print('%s:%d: link %s: no such file' % (f, no, t)); bad += 1
            elif frag and tgt.endswith('.md') and frag not in targets(tgt)[0]:
                print('%s:%d: link %s: no heading #%s in %s' % (f, no, t, frag, tgt)); bad += 1
    flat = re.sub(r'\s*\n\s*', ' ', ''.join(lines))
    for m in re.finditer(r'([\w./-]+\.md)[`)\]]*,? *\(?"([^"]+)"', flat):
        name, h = m.group(1), m.group(2)
        cands = [os.path.join(os.path.dirname(f), name), os.path.join('docs', os.path.basename(name)), name]
        tgt = next((c for c in cands if os.path.exists(c)), None)
        if tgt is None:
            print('%s: %s, "%s": no such file' % (f, name, h)); bad += 1
        elif not any(x.startswith(norm(h)) for x in targets(tgt)[1]):
            print('%s: %s, "%s": no such heading or bold label in %s' % (f, name, h, tgt)); bad += 1
sys.exit(1 if bad else 0)
PY
then pass "every relative link, anchor and section reference of the docs resolves"
else fail "broken links or section references:"; cat "$T/links"; fi

# --- section references in the sources: a program message or a comment that
# names a section of the docs, `docs/X.md, "Heading"` (a message's string
# literals joined as the compiler joins them), names a heading or a bold
# label of X.md that begins with that text, as the docs' own references
# above (a numbered heading, "5. Too short", also without its number). The
# bursts refusal of `--rate` named "--rate HZ (resampling)" for a week after
# the section was renamed (tests/cli/test_replay.sh checks the message).
if (cd "$ROOT" && /usr/bin/python3 - harness/*.[ch] src/*.c include/footnav/*.h port/*/*.[ch] tests/*.c) >"$T/srcrefs" 2>&1 <<'PY'
import os, re, sys, glob

def norm(s):
    return re.sub(r'\s+', ' ', re.sub(r'[`"*]', '', s)).strip().rstrip('.:').lower()

def prose(path):
    fence = False
    for line in open(path, encoding='utf-8'):
        if line.startswith('```'):
            fence = not fence
            continue
        if not fence:
            yield line

cache = {}
def labels(path):  # heading and bold-label texts; a numbered heading ("5. Too short") also without its number
    if path not in cache:
        labs, text = [], []
        for line in prose(path):
            m = re.match(r'#{1,6}\s+(.*?)\s*#*\s*$', line)
            if m:
                labs.append(norm(m.group(1)))
                labs.append(norm(re.sub(r'^\d+\.\s+', '', m.group(1))))
            text.append(line)
        for m in re.finditer(r'(?:^|\n)\s*(?:[*-]\s+)?\*\*(.+?)\*\*', ''.join(text), re.S):
            labs.append(norm(m.group(1)))
        cache[path] = labs
    return cache[path]

def texts(src):  # (kind, text): each comment, and each run of adjacent string literals joined
    tok = re.compile(r'/\*.*?\*/|//[^\n]*|"(?:[^"\\\n]|\\.)*"|\'(?:[^\'\\\n]|\\.)*\'', re.S)
    run, end = [], -1
    for m in tok.finditer(src):
        t = m.group(0)
        if t[0] == '"':
            if run and src[end:m.start()].strip() == '':
                run.append(t[1:-1])
            else:
                if run:
                    yield 'string', ''.join(run)
                run = [t[1:-1]]
            end = m.end()
            continue
        if run:
            yield 'string', ''.join(run)
            run = []
        if t.startswith('/*'):
            yield 'comment', re.sub(r'\n\s*\*?\s?', ' ', t[2:-2])
        elif t.startswith('//'):
            yield 'comment', t[2:]
    if run:
        yield 'string', ''.join(run)

n = bad = 0
for f in sys.argv[1:]:
    for kind, t in texts(open(f, encoding='utf-8').read()):
        if kind == 'string':
            t = t.replace('\\n', ' ').replace('\\"', '"')
        for m in re.finditer(r'docs/([\w.-]+\.md)[`)\]]*,? *\(?"([^"]{1,100})"', t):
            name, h = m.group(1), m.group(2)
            if '%' in h or re.fullmatch(r'[A-Z]+', h):
                continue  # a format's placeholder: the section comes at run time (checked by the CLI tests)
            n += 1
            p = os.path.join('docs', name)
            if not os.path.exists(p):
                print('%s: docs/%s, "%s": no such file' % (f, name, h)); bad += 1
            elif not any(x.startswith(norm(h)) for x in labels(p)):
                print('%s: docs/%s, "%s": no such heading or bold label' % (f, name, h)); bad += 1
print('%d section references in the sources, %d unresolved' % (n, bad))
sys.exit(1 if bad or n < 50 else 0)
PY
then pass "every section of the docs that a source names exists: $(tail -1 "$T/srcrefs")"
else fail "section references in the sources:"; cat "$T/srcrefs"; fi

if [ "$fails" -ne 0 ]; then echo "test_docs.sh: $fails failure(s)"; exit 1; fi
echo "test_docs.sh: all passed"
