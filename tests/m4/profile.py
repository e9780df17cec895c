#!/usr/bin/python3
"""Where the UKF step spends its instructions on the Cortex-M4F (tests/m4).

Writes an instrumented copy of src/fnav_ukf.c to build/m4/ukf_prof.c, with a
SysTick mark after each part of the prediction and the update (the anchors
below; a missing anchor is an error, so the script follows the source or
fails), and a copy of tests/m4/main.c that prints the mean instructions of
each part at the end. tests/m4/profile.sh builds and runs them. The marks
cost a few instructions each, so the parts add up to slightly more than the
uninstrumented step (tests/m4/run.sh).
"""
import os
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
B = os.path.join(ROOT, "build", "m4")

HDR = '''#include <stdint.h>
#define SYST_CVR_ (*(volatile uint32_t *)0xE000E018)
unsigned long prof_acc[32], prof_n[32];
static uint32_t prof_last;
#define MARK0() (prof_last = SYST_CVR_)
#define MARK(k) do { uint32_t t_ = SYST_CVR_; prof_acc[k] += (prof_last - t_) & 0xFFFFFFu; prof_n[k]++; \\
                     prof_last = t_; } while (0)
'''

# (anchor, text inserted before it, or after it with a leading '+'), part label
EDITS = [
    ('    guard_cov(f); /* e.g. a covariance set by a caller */', 'MARK0();', None),
    ('    fnav_strapdown_increments(&c->strapdown, &f->hist', 'MARK(0);', 'prediction: covariance guard and Cholesky factor'),
    ('    /* S starts at zero; the closed form assigns', 'MARK(1);', 'prediction: increments, centre strapdown, AR(1) terms'),
    ('    if (c->closed_form && nl > 0) {\n        predict_linear(', 'MARK(2);', 'prediction: clearing S'),
    ('    /* the full sigma points: with the closed form', 'MARK(3);', 'prediction: closed form (maps, F U, scatter)'),
    ('    /* With the propagated centre as reference (D_0 = 0)', 'MARK(4);', 'prediction: attitude sigma points through the strapdown'),
    ('    {\n        fnav_mat3_t C = fnav_quat_to_dcm(x0.q_nb);\n        add_rotated_noise', 'MARK(5);', 'prediction: accumulation of the sigma points, mean, finiteness sum'),
    ('    /* a NaN or an infinity anywhere in S makes', 'MARK(6);', 'prediction: process noise'),
    ('    fnav_strapdown_hist_push(&f->hist, &inc);', 'MARK(7);', 'prediction: fold the mean, copy to P, guard'),
    ('    /* P H^T (n x 3) */', 'MARK0();', None),
    ('    /* S = H P H^T + R', 'MARK(10);', 'update: P H^T'),
    ('    /* the gain K = P H^T S^-1', 'MARK(11);', 'update: S and its inverse'),
    ('    /* Joseph form (I - K H) P (I - K H)^T + K R K^T', 'MARK(12);', 'update: gain, correction, K S'),
    ('    if (!fnav_isfinite(chk)) { /* as in the prediction', 'MARK(13);', 'update: Joseph form'),
    ('    for (i = 0; i < N; i++) {\n        dxi[i]', 'MARK(14);', 'update: copy to P, guard'),
]


def main():
    src = open(os.path.join(ROOT, "src", "fnav_ukf.c")).read()
    labels = {}
    src = src.replace('#include "footnav/fnav_ukf.h"', '#include "footnav/fnav_ukf.h"\n' + HDR, 1)
    for anchor, mark, label in EDITS:
        if src.count(anchor) != 1:
            sys.exit("profile.py: anchor not found once in src/fnav_ukf.c: %r" % anchor[:60])
        src = src.replace(anchor, "    " + mark + "\n" + anchor, 1)
        if label:
            labels[int(mark[5:-2])] = label
    os.makedirs(B, exist_ok=True)
    open(os.path.join(B, "ukf_prof.c"), "w").write(src)
    main_c = open(os.path.join(ROOT, "tests", "m4", "main.c")).read()
    names = "".join('    case %d: sh_puts("  %s: "); break;\n' % (k, v) for k, v in sorted(labels.items()))
    tail = '''    {
        extern unsigned long prof_acc[32], prof_n[32];
        int q;
        for (q = 0; q < 32; q++) {
            if (prof_n[q] == 0) {
                continue;
            }
            switch (q) {
%s            default: break;
            }
            putu("", prof_acc[q] * per_tick / prof_n[q]);
        }
    }
    fnav_cm_sh_exit(0);
}''' % names
    anchor = "    fnav_cm_sh_exit(0);\n}"
    if main_c.count(anchor) != 1:
        sys.exit("profile.py: tests/m4/main.c has no single exit at its end")
    open(os.path.join(B, "main_prof.c"), "w").write(main_c.replace(anchor, tail))


if __name__ == "__main__":
    main()
