#!/bin/sh
# make install / make uninstall as a user of the library sees them (README,
# "Using the library in your own program"): `make install DESTDIR=D
# PREFIX=/usr` puts exactly libfootnav.a, the public headers, footnav.pc and
# footnav-harness under D/usr; a program of one's own, compiled away from
# the source tree with nothing but `pkg-config --cflags --libs footnav`,
# builds against the installed files only (it does not before the install),
# initialises a navigator with a built-in profile and navigates 7 s of a
# sensor at rest; installed with FNAV_DEFS=-DFNAV_USE_DOUBLE=1 the library
# is rebuilt in double and footnav.pc makes the program double too; a
# PREFIX with a space installs, and the program builds from pkg-config's
# escaped flags; `make uninstall` with the same variables leaves no file.
# footnav.pc's Version is include/footnav/fnav_version.h's (a VERSION=
# given to make wins), and the program sees its FNAV_VERSION_STRING.
# Each installed header compiles alone (C99 and C++11, -Werror), a C++
# program links through the headers' extern "C" guards, and the library
# exports only fnav_* symbols.
# The installs build in a scratch directory (BUILD=$T/build, about 15 s
# each): the make running this test passes its command-line variables down
# through MAKEFLAGS and the environment, both cleared here (with SAN and OPT
# from make sanitize the library was built with ASan + UBSan, and the
# program, linked without them, did not link). Under make sanitize the test
# is not run: cleared, it would repeat make test's run.
set -u
if [ -n "${SAN:-}" ]; then
    # make sanitize: the installs below clear SAN and build the same
    # unsanitized library and program as make test's run of this test did
    echo "test_install.sh: not run under make sanitize (it builds without the sanitizers, as under make test)"
    exit 0
fi
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
cd "$(dirname "$0")/../.." || exit 1
ROOT=$(pwd)
CC=${CC:-cc} # may hold words, e.g. "ccache gcc"
MAKE=${MAKE:-make}
unset MAKEFLAGS MFLAGS MAKELEVEL MAKEOVERRIDES BUILD HARNESS OPT SAN FNAV_DEFS
if ! command -v pkg-config >/dev/null 2>&1; then
    # scripts/bootstrap.sh installs it: make install's footnav.pc is for pkg-config
    fail "pkg-config not found (sh scripts/bootstrap.sh installs it)"
    echo "test_install.sh: $fails failure(s)"
    exit 1
fi

# pkg-config on the staged tree only: the .pc of D/usr/lib/pkgconfig (no
# system directory), its -I and -L under D (the sysroot)
pc() { # DESTDIR pkg-config-args...
    d=$1; shift
    PKG_CONFIG_LIBDIR="$d/usr/lib/pkgconfig" PKG_CONFIG_SYSROOT_DIR="$d" pkg-config "$@"
}
build_prog() { # DESTDIR OUTPUT: compiles $T/prog.c in $T (away from the source tree) with footnav.pc's flags
    flags=$(pc "$1" --cflags --libs footnav) || return 1
    # shellcheck disable=SC2086
    (cd "$T" && $CC -std=c99 -pedantic -Wall -Wextra -Werror -o "$2" prog.c $flags)
}
# the files make install should put under DESTDIR, sorted
expected_files() {
    {
        echo usr/bin/footnav-harness
        echo usr/lib/libfootnav.a
        echo usr/lib/pkgconfig/footnav.pc
        for h in include/footnav/*.h; do echo "usr/include/footnav/${h##*/}"; done
    } | LC_ALL=C sort
}
installed_files() { # DESTDIR: every file (not directory) under it, relative, sorted (none: no DESTDIR)
    [ -d "$1" ] || return 0
    (cd "$1" && find . ! -type d | sed 's|^\./||' | LC_ALL=C sort)
}

cat >"$T/prog.c" <<'EOF'
#include <stdio.h>
#include <stdlib.h>
#include "footnav/footnav.h"

/* the port's assert hook: a program of one's own defines it (docs/firmware.md) */
void fnav_port_assert_failed(const char *file, int line, const char *expr)
{
    fprintf(stderr, "%s:%d: assertion failed: %s\n", file, line, expr);
    abort();
}

static int take(fnav_nav_t *nav, unsigned long *frames, unsigned long *aligned, double *worst)
{
    fnav_nav_frame_t f;
    fnav_status_t st;
    int k;
    while ((st = fnav_nav_pop(nav, &f)) == FNAV_OK) {
        (*frames)++;
        if (f.flags & FNAV_FRAME_ALIGNED) {
            (*aligned)++;
            for (k = 0; k < 3; k++) {
                double p = (double)f.pos_m[k] < 0.0 ? -(double)f.pos_m[k] : (double)f.pos_m[k];
                if (p > *worst) {
                    *worst = p;
                }
            }
        }
    }
    return st == FNAV_AGAIN || st == FNAV_END ? 0 : -1;
}

int main(void)
{
    static fnav_nav_t nav;
    fnav_nav_config_t cfg = fnav_nav_config_default;
    fnav_sample_t s = {0};
    unsigned long frames = 0, aligned = 0;
    double worst = 0.0;
    int i;
    if (fnav_profile_builtin(&cfg.profile, FNAV_PROFILE_NAVCHIP) != FNAV_OK || fnav_nav_init(&nav, &cfg) != FNAV_OK) {
        return 1;
    }
    for (i = 0; i < 1400; i++) { /* 7 s at rest at 200 Hz, +z up: aligned after 5 s (max_still_s) */
        s.t_ns = (int64_t)i * 5000000;
        s.seq = (uint32_t)i;
        s.accel_mps2[0] = FNAV_R(0.01);
        s.accel_mps2[1] = FNAV_R(-0.02);
        s.accel_mps2[2] = FNAV_R(9.81);
        s.gyro_rps[0] = FNAV_R(0.001);
        s.gyro_rps[1] = FNAV_R(0.002);
        s.gyro_rps[2] = FNAV_R(-0.001);
        if (fnav_nav_push(&nav, &s) != FNAV_OK || take(&nav, &frames, &aligned, &worst) != 0) {
            return 1;
        }
    }
    fnav_nav_finish(&nav);
    if (take(&nav, &frames, &aligned, &worst) != 0) {
        return 1;
    }
    printf("profile %s, fnav_real_t %u bytes: %lu frames, %lu aligned, |position| <= %.4f m\n", nav.cfg.profile.name,
           (unsigned)sizeof(fnav_real_t), frames, aligned, worst);
    printf("footnav %s\n", FNAV_VERSION_STRING);
    return 0;
}
EOF

# before the install: nothing to find, and the program does not build
# (no -Iinclude: the source tree is not on its path)
D="$T/root"
if pc "$D" --exists footnav 2>/dev/null; then
    fail "pkg-config finds footnav before make install"
else
    pass "pkg-config does not find footnav before make install"
fi
# shellcheck disable=SC2086
if (cd "$T" && $CC -std=c99 -o prog0 prog.c -lfootnav -lm) >"$T/err" 2>&1; then
    # a footnav installed on this machine (/usr/local): the staged one comes
    # first on the -I and -L of footnav.pc, but this check cannot be made
    echo "note: footnav is installed on this machine outside the staged tree: not checked that the program needs the install"
elif grep -q 'footnav/footnav.h' "$T/err"; then
    pass "the program does not build without the install (footnav/footnav.h not found)"
else
    fail "the program does not build without the install, but not for want of footnav/footnav.h:"; cat "$T/err"
fi

expect_exit 0 "make install DESTDIR=D PREFIX=/usr" \
    "$MAKE" -C "$ROOT" install DESTDIR="$D" PREFIX=/usr BUILD="$T/build" HARNESS="$T/build/harness"
expected_files >"$T/want"
installed_files "$D" >"$T/got"
if cmp -s "$T/want" "$T/got"; then
    pass "make install put exactly the library, $(grep -c include/ "$T/want") headers, footnav.pc and footnav-harness"
else
    fail "make install: the installed files differ from the expected ones (- expected, + installed)"
    diff -u "$T/want" "$T/got" | sed -n '3,$p'
fi
if [ -x "$D/usr/bin/footnav-harness" ] && ! [ -e "$D/usr/bin/harness" ]; then
    pass "the harness is installed as footnav-harness"
else
    fail "the harness is not installed as footnav-harness (or also as harness)"
fi
expect_exit 0 "footnav-harness --help" "$D/usr/bin/footnav-harness" --help
expect_out "replay" "footnav-harness --help lists the commands"
expect_exit 0 "the installed footnav-harness runs a command (info on the bundled walk)" \
    "$D/usr/bin/footnav-harness" info vectors/walk.bin
pc "$D" --cflags --libs footnav >"$T/out" 2>"$T/err"
expect_out_re "^-I$D/usr/include +-L$D/usr/lib +-lfootnav +-lm *$" \
    "pkg-config --cflags --libs footnav: -I and -L of the install, -lfootnav -lm, no FNAV_USE_DOUBLE in the float build"
PKG_CONFIG_LIBDIR="$D/usr/lib/pkgconfig" pkg-config --define-prefix --cflags footnav >"$T/out" 2>"$T/err"
expect_out_re "^-I$D/usr/include *$" "pkg-config --define-prefix relocates the staged tree too"
PKG_CONFIG_LIBDIR="$D/usr/lib/pkgconfig" pkg-config --modversion footnav >"$T/out" 2>"$T/err"
expect_out_re "^[0-9]+\.[0-9]+\.[0-9]+$" "footnav.pc has a version"
# the version of include/footnav/fnav_version.h, its one source (footnav.pc
# said 0.0.0, the Makefile's own default, before the header had one)
HV=$(awk '$2 == "FNAV_VERSION_MAJOR" { a = $3 } $2 == "FNAV_VERSION_MINOR" { b = $3 } $2 == "FNAV_VERSION_PATCH" { c = $3 }
    END { if (a != "" && b != "" && c != "") print a "." b "." c }' include/footnav/fnav_version.h 2>/dev/null)
if [ -n "$HV" ] && [ "$(cat "$T/out")" = "$HV" ]; then pass "footnav.pc's version is fnav_version.h's ($HV)"
else fail "footnav.pc's version '$(cat "$T/out")' is not fnav_version.h's '$HV'"; fi
# a packager's VERSION= still wins (the library is built: no compilation)
expect_exit 0 "make install VERSION=9.8.7-1 DESTDIR=D3" \
    "$MAKE" -C "$ROOT" install DESTDIR="$T/root-v" PREFIX=/usr VERSION=9.8.7-1 BUILD="$T/build" HARNESS="$T/build/harness"
PKG_CONFIG_LIBDIR="$T/root-v/usr/lib/pkgconfig" pkg-config --modversion footnav >"$T/out" 2>"$T/err"
expect_out_re "^9\.8\.7-1$" "make install VERSION=9.8.7-1: footnav.pc says 9.8.7-1"

if build_prog "$D" prog_float >"$T/err" 2>&1; then
    pass "a program of one's own builds with pkg-config's flags alone (float)"
    expect_exit 0 "the program runs (float)" "$T/prog_float"
    expect_out_re "^profile navchip, fnav_real_t 4 bytes: 1400 frames, 400 aligned, \|position\| <= 0\.00[0-9]{2} m$" \
        "the program navigated 7 s at rest with the NavChip profile: 1400 frames, the last 400 aligned, at the origin (float)"
    expect_out_re "^footnav $HV$" "the program sees FNAV_VERSION_STRING $HV in the installed footnav.h"
else
    fail "the program does not build with pkg-config's flags (float)"; cat "$T/err"
fi

# Each installed header compiles alone, first and twice over, with the
# program's flags (fnav_config_check.h, which fnav_config.h includes, did
# not: its option checks met undefined options, #error "FNAV_STANCE_MAX_WINDOW
# must be in 3..1024"), and from C++ (g++ -std=c++11, -Werror: a C++ program
# links the C library only through the headers' extern "C" guards); every
# symbol the library exports is fnav_*.
# A program's own stricter warnings must not fire in the headers' inline
# functions either (fnav_isfinite's x == x tripped -Wfloat-equal).
HWARN_C="-std=c99 -pedantic -Wall -Wextra -Werror -Wconversion -Wsign-conversion -Wshadow -Wundef -Wdouble-promotion
 -Wfloat-equal -Wcast-qual -Wstrict-prototypes -Wmissing-prototypes"
HWARN_CXX="-std=c++11 -pedantic -Wall -Wextra -Werror -Wconversion -Wsign-conversion -Wshadow -Wundef -Wdouble-promotion
 -Wfloat-equal -Wold-style-cast -Wzero-as-null-pointer-constant"
CXX=${CXX:-g++}
have_cxx=0
command -v "${CXX%% *}" >/dev/null 2>&1 && have_cxx=1
check_headers() { # DESTDIR LABEL: each installed header alone, in C (twice over) and, with a C++ compiler, in C++
    hflags=$(pc "$1" --cflags footnav)
    hbad="" xbad="" x98bad=""
    for h in "$1"/usr/include/footnav/*.h; do
        b=${h##*/}
        printf '#include "footnav/%s"\n#include "footnav/%s"\nint hdr_tu;\n' "$b" "$b" >"$T/hdr.c"
        # shellcheck disable=SC2086
        (cd "$T" && $CC $HWARN_C $hflags -c hdr.c -o hdr.o) >"$T/err" 2>&1 ||
            { hbad="$hbad $b"; head -n 5 "$T/err"; }
        [ "$have_cxx" = 1 ] || continue
        printf '#include "footnav/%s"\nint hdr_tu;\n' "$b" >"$T/hdr.cpp"
        # shellcheck disable=SC2086
        (cd "$T" && $CXX $HWARN_CXX $hflags -c hdr.cpp -o hdr.o) >"$T/err" 2>&1 ||
            { xbad="$xbad $b"; head -n 5 "$T/err"; }
        # and as C++98: FNAV_BUILD_TAG's 1ULL literals were "C++11 long long
        # integer constants" (-Wlong-long) in every file calling an _init
        # shellcheck disable=SC2086
        (cd "$T" && $CXX -std=c++98 -pedantic -Wall -Wextra -Werror $hflags -c hdr.cpp -o hdr.o) >"$T/err" 2>&1 ||
            { x98bad="$x98bad $b"; head -n 5 "$T/err"; }
    done
    if [ -z "$hbad" ]; then
        pass "every installed header compiles alone, included twice ($2; C99, -Werror and a program's stricter warnings)"
    else
        fail "installed headers that do not compile alone ($2):$hbad"
    fi
    if [ "$have_cxx" = 0 ]; then
        echo "SKIP test_install.sh: no C++ compiler ($CXX; apt-get install g++): the headers' C++ check ($2)"
    elif [ -z "$xbad" ]; then
        pass "every installed header compiles alone as C++11 ($2; $CXX -std=c++11 -Werror and stricter warnings)"
    else
        fail "installed headers that do not compile as C++11 ($2):$xbad"
    fi
    if [ "$have_cxx" = 1 ]; then
        if [ -z "$x98bad" ]; then
            pass "every installed header compiles alone as C++98 ($2; $CXX -std=c++98 -pedantic -Werror)"
        else
            fail "installed headers that do not compile as C++98 ($2):$x98bad"
        fi
    fi
}
check_headers "$D" float
# fnav_isfinite reads the bits with memcpy, which a freestanding program
# (-ffreestanding, -fno-builtin: no builtins, as some firmware builds) turned
# into a call of memcpy at every check, at any -O: it is to stay inline
printf '#include "footnav/fnav_math.h"\nint fin(float x, fnav_vec3_t v);\nint fin(float x, fnav_vec3_t v) { return fnav_isfinite(x) + fnav_vec3_isfinite(v); }\n' >"$T/fin.c"
fbad=""
for o in -O0 -O2; do
    for fl in -ffreestanding -fno-builtin; do
        # shellcheck disable=SC2046
        if (cd "$T" && $CC -std=c99 -pedantic -Wall -Wextra -Werror $o $fl $(pc "$D" --cflags footnav) -c fin.c -o fin.o) >"$T/err" 2>&1; then
            nm -u "$T/fin.o" | grep -q -w memcpy && fbad="$fbad $o$fl"
        else
            fbad="$fbad $o$fl(no build)"; head -n 5 "$T/err"
        fi
    done
done
[ -z "$fbad" ] && pass "fnav_isfinite calls no memcpy in a freestanding program (-O0, -O2; -ffreestanding, -fno-builtin)" ||
    fail "fnav_isfinite calls memcpy with:$fbad"
# the guard in every header that declares anything (fnav_config*.h and
# fnav_version.h hold macros only)
nog=$(cd "$D/usr/include/footnav" && grep -L 'extern "C"' ./*.h | sed 's|^\./||' | grep -v '^fnav_config\|^fnav_version\.h$' | tr '\n' ' ')
if [ -z "$nog" ]; then
    pass "every installed header but fnav_config*.h and fnav_version.h (macros only) has an extern \"C\" guard"
else
    fail "installed headers without an extern \"C\" guard: $nog"
fi
if [ "$have_cxx" = 1 ]; then
    # the program includes the headers one by one (footnav.h wraps them in
    # extern "C" itself) and defines the assert hook as fnav_port.h declares
    # it: C linkage only through each header's own guard
    {
        echo '#include <cstdio>'
        echo '#include <cstdlib>'
        for h in "$D"/usr/include/footnav/fnav_*.h; do echo "#include \"footnav/${h##*/}\""; done
        cat <<'EOF'
void fnav_port_assert_failed(const char *file, int line, const char *expr)
{
    std::fprintf(stderr, "%s:%d: %s\n", file, line, expr);
    std::abort();
}
int main()
{
    static fnav_allan_t a;
    static fnav_welch_t w;
    static fnav_nav_t nav;
    fnav_nav_config_t cfg = fnav_nav_config_default;
    fnav_status_t st = fnav_profile_builtin(&cfg.profile, FNAV_PROFILE_NAVCHIP);
    if (st == FNAV_OK) {
        st = fnav_nav_init(&nav, &cfg);
    }
    if (st == FNAV_OK) {
        st = fnav_welch_init(&w, &fnav_welch_config_default);
    }
    if (st == FNAV_OK) {
        st = fnav_allan_init(&a, NULL);
    }
    if (st == FNAV_OK) {
        st = fnav_allan_push(&a, FNAV_R(1.0));
    }
    std::printf("%s, %u sample\n", fnav_status_str(st), (unsigned)fnav_allan_samples(&a));
    return st == FNAV_OK ? 0 : 1;
}
EOF
    } >"$T/prog.cpp"
    # shellcheck disable=SC2046
    if (cd "$T" && $CXX -std=c++11 -Wall -Wextra -Werror -o prog_cpp prog.cpp $(pc "$D" --cflags --libs footnav)) >"$T/err" 2>&1; then
        expect_exit 0 "a C++ program links the installed library and runs" "$T/prog_cpp"
        expect_out "^ok, 1 sample$" "the C++ program called the library through each header's extern \"C\" guard"
    else
        fail "a C++ program does not build against the installed library"; cat "$T/err"
    fi
fi
nm -g --defined-only "$D/usr/lib/libfootnav.a" 2>/dev/null | awk 'NF == 3 { print $3 }' | LC_ALL=C sort -u >"$T/syms"
if [ ! -s "$T/syms" ]; then
    fail "nm found no symbol in the installed libfootnav.a"
elif grep -v '^fnav_' "$T/syms" >"$T/leak"; then
    fail "the installed library exports symbols outside fnav_*: $(tr '\n' ' ' <"$T/leak")"
else
    pass "the installed library exports only fnav_* symbols ($(wc -l <"$T/syms" | tr -d ' '))"
fi

# A PREFIX with a space (no DESTDIR: installed where it is used). footnav.pc
# held it as written, and pkg-config splits its values at blanks:
# `-I/x/my prefix/include` became -I/x/my and a stray prefix/include. Its
# variables now escape a space with a backslash, which pkg-config keeps in
# what it prints (-I/x/my\ prefix/include), for the shell that reads the
# command line (make's recipes, or eval here) to join again. A program
# then builds from `pkg-config --cflags --libs footnav` alone, and make
# install and make uninstall quote the paths they are given.
P="$T/my prefix"
expect_exit 0 "make install PREFIX='.../my prefix'" \
    "$MAKE" -C "$ROOT" install PREFIX="$P" BUILD="$T/build" HARNESS="$T/build/harness"
expected_files | sed 's|^usr/||' >"$T/want"
installed_files "$P" >"$T/got"
if cmp -s "$T/want" "$T/got"; then
    pass "make install into a PREFIX with a space put exactly the expected files"
else
    fail "make install into a PREFIX with a space (- expected, + installed)"
    diff -u "$T/want" "$T/got" | sed -n '3,$p'
fi
esc=$(printf '%s' "$P" | sed 's/ /\\\\ /g')
PKG_CONFIG_LIBDIR="$P/lib/pkgconfig" pkg-config --cflags --libs footnav >"$T/out" 2>"$T/err"
expect_out_re "^-I$esc/include +-L$esc/lib +-lfootnav +-lm *$" \
    "pkg-config --cflags --libs footnav: the PREFIX's space escaped, one word each"
flags=$(PKG_CONFIG_LIBDIR="$P/lib/pkgconfig" pkg-config --cflags --libs footnav)
if (cd "$T" && eval "$CC -std=c99 -pedantic -Wall -Wextra -Werror -o prog_space prog.c $flags") >"$T/err" 2>&1; then
    pass "a program builds from pkg-config --cflags --libs footnav with a space in PREFIX"
    expect_exit 0 "the program runs (PREFIX with a space)" "$T/prog_space"
    expect_out_re "^profile navchip, fnav_real_t 4 bytes: 1400 frames, 400 aligned" "the same navigation (PREFIX with a space)"
else
    fail "the program does not build from pkg-config's flags with a space in PREFIX"; cat "$T/err"
fi
expect_exit 0 "make uninstall PREFIX='.../my prefix'" \
    "$MAKE" -C "$ROOT" uninstall PREFIX="$P" BUILD="$T/build" HARNESS="$T/build/harness"
installed_files "$P" >"$T/got"
if [ -s "$T/got" ]; then fail "make uninstall left files under the PREFIX with a space:"; cat "$T/got"; else
    pass "make uninstall left no file under the PREFIX with a space"; fi

# A path holding ', # or a tab: the recipes quote the paths with ' (a '
# ended the quote: a shell syntax error part-way, `Unterminated quoted
# string`), and footnav.pc cannot carry a # (a comment to pkg-config: the
# prefix cut there, the flags pointing elsewhere) or a tab (pkg-config prints
# a space for it, which splits the flag; make's patsubst splits there too). make install and make uninstall refuse
# such a path, naming the variable and the character, before building or
# installing anything.
TAB=$(printf '\t')
for c in "'" "#" "$TAB"; do
    case $c in "'") name="an apostrophe (')" ;; "#") name="a hash (#)" ;; *) name="a tab" ;; esac
    for goal in install uninstall; do
        for v in PREFIX DESTDIR LIBDIR; do
            bad="$T/bad${c}dir"
            case $v in
                PREFIX) set -- PREFIX="$bad" ;;
                DESTDIR) set -- DESTDIR="$bad" PREFIX=/usr ;;
                LIBDIR) set -- DESTDIR="$T/stage-bad" LIBDIR="/usr/li${c}b" ;;
            esac
            expect_exit 2 "make $goal with $name in $v is refused" \
                "$MAKE" -C "$ROOT" "$goal" "$@" BUILD="$T/build" HARNESS="$T/build/harness"
            expect_err "make $goal: $v holds $name" "the error names $v and the character"
            if [ -e "$bad" ] || [ -e "$T/stage-bad" ]; then
                fail "make $goal with $name in $v created a directory"; rm -rf "$bad" "$T/stage-bad"
            else
                pass "make $goal with $name in $v created nothing"
            fi
        done
    done
done

# The double build: FNAV_DEFS at install rebuilds the same BUILD in double
# (the objects follow FNAV_DEFS) and footnav.pc passes it on; a program
# built as float against the double library would read its frames wrong.
D2="$T/root-double"
expect_exit 0 "make install FNAV_DEFS=-DFNAV_USE_DOUBLE=1 (same BUILD, rebuilt)" \
    "$MAKE" -C "$ROOT" install DESTDIR="$D2" PREFIX=/usr BUILD="$T/build" HARNESS="$T/build/harness" \
    FNAV_DEFS=-DFNAV_USE_DOUBLE=1
pc "$D2" --cflags footnav >"$T/out" 2>"$T/err"
expect_out_re "^-I$D2/usr/include +-DFNAV_USE_DOUBLE=1 *$" "footnav.pc of the double build carries -DFNAV_USE_DOUBLE=1"
check_headers "$D2" double
if build_prog "$D2" prog_double >"$T/err" 2>&1; then
    pass "the program builds with pkg-config's flags alone (double)"
    expect_exit 0 "the program runs (double)" "$T/prog_double"
    expect_out_re "^profile navchip, fnav_real_t 8 bytes: 1400 frames, 400 aligned, \|position\| <= 0\.00[0-9]{2} m$" \
        "the same navigation in double"
else
    fail "the program does not build with pkg-config's flags (double)"; cat "$T/err"
fi

for d in "$D" "$D2"; do
    expect_exit 0 "make uninstall DESTDIR=${d##*/} PREFIX=/usr" \
        "$MAKE" -C "$ROOT" uninstall DESTDIR="$d" PREFIX=/usr BUILD="$T/build" HARNESS="$T/build/harness"
    installed_files "$d" >"$T/got"
    if [ -s "$T/got" ]; then
        fail "make uninstall left files under ${d##*/}:"; cat "$T/got"
    else
        pass "make uninstall left no file under ${d##*/}"
    fi
    if [ -d "$d/usr/include/footnav" ]; then
        fail "make uninstall left the empty include/footnav directory"
    else
        pass "make uninstall removed include/footnav"
    fi
done
# a file of someone else's in include/footnav is left, and so is the
# directory (the double build again: BUILD is not rebuilt, the uninstalls
# above without FNAV_DEFS did not mark its objects stale)
expect_exit 0 "make install again" \
    "$MAKE" -C "$ROOT" install DESTDIR="$D" PREFIX=/usr BUILD="$T/build" HARNESS="$T/build/harness" \
    FNAV_DEFS=-DFNAV_USE_DOUBLE=1
if grep -q -e ' -c ' "$T/out"; then
    fail "make install again with the same FNAV_DEFS recompiled (after make uninstall without FNAV_DEFS):"
    grep -e ' -c ' "$T/out" | head -n 3
else
    pass "make install again with the same FNAV_DEFS compiles nothing (make uninstall left the objects' stamp alone)"
fi
: >"$D/usr/include/footnav/mine.h"
expect_exit 0 "make uninstall with a foreign file in include/footnav" \
    "$MAKE" -C "$ROOT" uninstall DESTDIR="$D" PREFIX=/usr BUILD="$T/build" HARNESS="$T/build/harness"
installed_files "$D" >"$T/got"
if [ "$(cat "$T/got")" = usr/include/footnav/mine.h ]; then
    pass "make uninstall removes only what make install put"
else
    fail "make uninstall with a foreign file: left $(tr '\n' ' ' <"$T/got")"
fi

# make clean and a build in one run with FNAV_DEFS (a copy of the tree:
# make clean removes build/ and bin/): the stamp the build makes again
# records FNAV_DEFS, so a later make without FNAV_DEFS rebuilds the library
# (it found the double objects up to date, and make install would have put
# them beside a footnav.pc without -DFNAV_USE_DOUBLE=1)
C="$T/copy"
mkdir -p "$C" && cp -R Makefile src include "$C/"
expect_exit 0 "make clean libfootnav.a FNAV_DEFS=-DFNAV_USE_DOUBLE=1 (one run, a copy of the tree)" \
    "$MAKE" -C "$C" clean build/host/libfootnav.a FNAV_DEFS=-DFNAV_USE_DOUBLE=1
if [ "$(cat "$C/build/host/fnav-defs.stamp" 2>/dev/null)" = -DFNAV_USE_DOUBLE=1 ]; then
    pass "the stamp remade after make clean holds the run's FNAV_DEFS"
else
    fail "the stamp remade after make clean does not hold -DFNAV_USE_DOUBLE=1: '$(cat "$C/build/host/fnav-defs.stamp" 2>/dev/null)'"
fi
expect_exit 1 "then make -q libfootnav.a without FNAV_DEFS: the double library is out of date" \
    "$MAKE" -C "$C" -q build/host/libfootnav.a

if [ "$fails" -ne 0 ]; then echo "test_install.sh: $fails failure(s)"; exit 1; fi
echo "test_install.sh: all passed"
