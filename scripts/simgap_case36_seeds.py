#!/usr/bin/env python3
"""The seeds and draws of simgap-validate's static case i before the cases'
seeds were made disjoint (commit b111ee6, harness/hx_simgap_valid.c), redone
outside the harness: the case generator is fnav_rng_seed(seed, 0x10000 + i)
(splitmix64 filling a xoshiro128+ state, src/fnav_imuerr.c), and
draw_static() takes in turn the profile (urand), the log's seed (u32), the
multiple of the threshold (10^urand for --mag-range 1,10), then for a
non-timing effect one channel (urand < 0.5, then urand * 6) or a sensor's
three. The diagnosis ran with seed 1000 + i. For --seed 1, case 36 (the rrw
of tests/cli/test_simgap.sh, "a random walk that looks like a ramp") this
prints effect rrw, log seed 201791262, diagnosis seed 1036, shimmer, ax,
2.035961...,
as the old binary drew them (and as its JSON reports the multiple).

The case's kind is b111ee6's case_type() with the default options: the
17 kinds (static control, the 8 static effects, the 3 timing ones, walk
control, the 4 walk ones, in harness/hx_simgap_valid.c's k_eff order) in
turn from an offset drawn from fnav_rng_seed(seed, 0x5a5a).

Limits: it derives only what draw_static() drew with the default options
(--mag-range 1,10, all effects, static and walk cases; a static case's
draws do not depend on --duration or --rate until after the channels) and
only a static non-timing case or a static control. It refuses, exit 2
with a message naming the case and why, any other argument (an option
such as --mag-range, a SEED outside [0, 4294967295], a negative CASE) and
a walk case or a timing case, whose draws it does not redo (a walk's come
from sg_nav_draw_case in another order, a timing effect draws no channel).

Run: python3 scripts/simgap_case36_seeds.py [SEED [CASE]]   (defaults 1 36)
Prints one line; tests/cli/test_simgap.sh runs it for --seed 1 case 36 and
takes the seeds its rebuilt rrw uses from it.
The float32 rounding of urand is exact here: (u32 >> 8) * 2^-24.
"""
import sys

# b111ee6's case_types() with the default options: (name, class)
KINDS = ([("control", "static")] +
         [(n, "static") for n in ("quant", "quant_shaped", "flicker", "rrw", "ramp", "thermal", "vibration",
                                  "jumps")] +
         [(n, "timing") for n in ("jitter", "dropout", "duplicate")] +
         [("control", "walk")] +
         [(n, "walk") for n in ("scale", "misalign", "gsens", "saturation")])

M64 = (1 << 64) - 1
M32 = (1 << 32) - 1


def splitmix64(x):
    x = (x + 0x9E3779B97F4A7C15) & M64
    z = x
    z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & M64
    z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & M64
    return x, z ^ (z >> 31)


class Rng:
    """fnav_rng_t: xoshiro128+ 1.0 (Blackman & Vigna 2018)."""

    def __init__(self, seed, stream):
        x = ((seed & M32) << 32) | (stream & M32)
        x, a = splitmix64(x)
        x, b = splitmix64(x)
        self.s = [a & M32, a >> 32, b & M32, b >> 32]
        if not any(self.s):
            self.s[0] = 1

    def u32(self):
        s = self.s
        result = (s[0] + s[3]) & M32
        t = (s[1] << 9) & M32
        s[2] ^= s[0]
        s[3] ^= s[1]
        s[1] ^= s[2]
        s[0] ^= s[3]
        s[2] ^= t
        s[3] = ((s[3] << 11) | (s[3] >> 21)) & M32
        return result

    def uniform(self):
        return (self.u32() >> 8) * 2.0 ** -24


def refuse(msg):
    sys.stderr.write(f"simgap_case36_seeds.py: {msg}\n")
    sys.exit(2)


def whole(arg, what, hi):
    if not arg.isdigit() or int(arg) > hi:
        refuse(f"{what} '{arg}' is not a whole number in [0, {hi}] (usage: simgap_case36_seeds.py [SEED [CASE]]; "
               "only the default options are derived: no --mag-range or other option)")
    return int(arg)


def main():
    if len(sys.argv) > 3:
        refuse("usage: simgap_case36_seeds.py [SEED [CASE]] (only the default options are derived)")
    seed = whole(sys.argv[1], "SEED", M32) if len(sys.argv) > 1 else 1
    case = whole(sys.argv[2], "CASE", 10**6) if len(sys.argv) > 2 else 36
    off = Rng(seed, 0x5A5A).u32() % len(KINDS)
    effect, cls = KINDS[(case + off) % len(KINDS)]
    if cls != "static":
        refuse(f"--seed {seed} case {case} is a {cls} case ({effect}): only static non-timing cases and static "
               "controls are derived (b111ee6's draw_static order)")
    r = Rng(seed, 0x10000 + case)
    profile = ("navchip", "mtx", "shimmer")[int(r.uniform() * 3.0) % 3]
    log_seed = r.u32()
    mult = 1.0 * (10.0 / 1.0) ** r.uniform()
    if effect == "control":
        chans = "none"
    elif r.uniform() < 0.5:
        chans = ("ax", "ay", "az", "gx", "gy", "gz")[int(r.uniform() * 6.0) % 6]
    else:
        chans = "ax+ay+az" if r.uniform() < 0.5 else "gx+gy+gz"
    print(f"--seed {seed} case {case} (b111ee6 derivation): effect {effect}, log seed {log_seed}, "
          f"diagnosis seed {1000 + case}, profile {profile}, channels {chans}, multiple of threshold {mult!r}")


if __name__ == "__main__":
    main()
