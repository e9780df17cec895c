#!/bin/sh
# Quick start on a fresh Debian 12 machine (as root): install the Debian
# packages footnav needs, build it, and run the main job on the bundled
# example walk. Safe to run again (nothing is reinstalled or rebuilt needlessly).
set -eu
cd "$(dirname "$0")/.."
sh scripts/bootstrap.sh
make -j"$(nproc 2>/dev/null || echo 2)"
mkdir -p out
echo
echo "== bin/harness replay vectors/walk.bin"
bin/harness replay vectors/walk.bin --out out/walk_traj.csv --json out/walk_summary.json --plot out/walk.png
echo
echo "trajectory: out/walk_traj.csv, summary: out/walk_summary.json, plot: out/walk.png"
