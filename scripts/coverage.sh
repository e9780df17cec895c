#!/bin/sh
# Line and branch coverage of DIR/*.c (and of the inline functions of
# include/footnav/*.h and DIR/*.h as DIR's objects compiled them), from the
# .gcda files a --coverage build left in BUILD/obj/DIR: DIR src is the core
# run by the CMocka suites (make coverage), DIR harness the Linux tool run by
# the CLI tests (make coverage-harness); the target builds and runs first.
# Prints one row per file and the totals; the annotated sources (FILE.gcov,
# "#####" marks a line never run, "taken 0" or "never executed" a branch) go
# to BUILD/gcov/.
#   sh scripts/coverage.sh [BUILD [DIR]]  (default build/cov src; run from the repository root)
set -u
BUILD=${1:-build/cov}
DIR=${2:-src}
GCOV=${GCOV:-gcov}
OBJ=$BUILD/obj/$DIR
if ! ls "$OBJ"/*.gcda >/dev/null 2>&1; then
    echo "coverage: no .gcda files in $OBJ (run make coverage or make coverage-harness, which build with --coverage and run the tests)" >&2
    exit 1
fi
OUT=$BUILD/gcov
rm -rf "$OUT"
mkdir -p "$OUT"
# gcov writes FILE.gcov into its working directory and finds the sources
# by the relative names the objects were compiled with: run it from the
# root, then move the annotated files.
"$GCOV" -b -c -o "$OBJ" "$DIR"/*.c >"$OUT/summary.txt" 2>"$OUT/gcov.err" || {
    cat "$OUT/gcov.err" >&2
    echo "coverage: $GCOV failed" >&2
    exit 1
}
mv ./*.gcov "$OUT"/ 2>/dev/null
# The summary has, per source file, "File 'NAME'", "Lines executed:P% of N"
# and "Taken at least once:P% of N" (or "No branches"); a header used by
# several objects is listed once, its counts merged.
awk -v dir="$DIR" '
function cnt(pct, n) { return int(pct * n / 100 + 0.5) }
function row(name, lh, ln, bh, bn) {
    printf "%-32s %6.1f%% %5d/%-5d %6s %5d/%-5d\n", name, ln ? 100 * lh / ln : 100, lh, ln,
        bn ? sprintf("%.1f%%", 100 * bh / bn) : "-", bh, bn
}
/^File / {
    f = $0; sub(/^File \047/, "", f); sub(/\047$/, "", f)
    keep = (f ~ ("^" dir "/.*\\.[ch]$") || f ~ /^include\/footnav\/.*\.h$/)
    if (keep && !(f in lines)) { order[++nf] = f; lines[f] = 0; lhit[f] = 0; br[f] = 0; bhit[f] = 0 }
    next
}
keep && /^Lines executed:/ {
    split($0, a, /[:% ]+/); lines[f] = a[5]; lhit[f] = cnt(a[3], a[5]); next
}
keep && /^Taken at least once:/ {
    split($0, a, /[:% ]+/); br[f] = a[7]; bhit[f] = cnt(a[5], a[7]); next
}
/^$/ { keep = 0 }
END {
    printf "%-32s %7s %11s %7s %11s\n", "file", "lines", "hit/total", "branch", "taken/total"
    for (i = 1; i <= nf; i++) {
        f = order[i]
        if (f ~ ("^" dir "/.*\\.c$")) { row(f, lhit[f], lines[f], bhit[f], br[f]); sl += lines[f]; slh += lhit[f]; sb += br[f]; sbh += bhit[f] }
    }
    for (i = 1; i <= nf; i++) {
        f = order[i]
        if (f !~ ("^" dir "/.*\\.c$")) { row(f, lhit[f], lines[f], bhit[f], br[f]); hl += lines[f]; hlh += lhit[f]; hb += br[f]; hbh += bhit[f] }
    }
    row("total " dir "/*.c", slh, sl, sbh, sb)
    row("total " dir "/*.c + headers", slh + hlh, sl + hl, sbh + hbh, sb + hb)
}' "$OUT/summary.txt"
echo "coverage: annotated sources in $OUT/ (##### = line never run; branch \"taken 0\"/\"never executed\" = branch never taken)"
