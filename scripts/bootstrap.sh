#!/bin/sh
# Install everything footnav needs on Debian 12 (run as root; idempotent).
# Used by `make deps`, .ci/run and the README quick start.
#   sh scripts/bootstrap.sh         build, run, make test, firmware, bench
#   sh scripts/bootstrap.sh --ci    also the checkers CI runs: valgrind (make
#                                   valgrind), cppcheck and clang-tidy (make
#                                   lint), clang with libFuzzer (make fuzz)
set -eu
PACKAGES="make gcc g++ libc6-dev pkg-config git ca-certificates \
  libcmocka-dev libgsl-dev libserialport-dev libcjson-dev zlib1g-dev \
  gcc-arm-none-eabi libnewlib-arm-none-eabi binutils-arm-none-eabi qemu-system-arm \
  gnuplot-nox socat python3 python3-numpy python3-scipy"
case "${1:-}" in
    --ci) PACKAGES="$PACKAGES valgrind cppcheck clang clang-tidy libclang-rt-14-dev" ;;
    "") ;;
    *) echo "usage: sh scripts/bootstrap.sh [--ci]" >&2; exit 2 ;;
esac
missing=""
for p in $PACKAGES; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -z "$missing" ]; then
    echo "bootstrap: all packages present"
    exit 0
fi
if [ "$(id -u)" -ne 0 ]; then
    SUDO=sudo
else
    SUDO=
fi
echo "bootstrap: installing$missing"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends $missing
