#!/usr/bin/python3
"""Golden vector for the gap statistics of harness/hx_simgap_stat.c.

sg_compare, sg_lr_test (hx_simgap_stat.c) and sg_score_test (hx_simgap.c)
on a small hand-made point list, computed here in numpy/scipy from the
formulas of docs/simgap.md, section 3 ("The gap, per domain, and its null
distribution") and the comments of hx_simgap.h:

  z_j = (y_real,j - mean_s y_twin,s,j) / sqrt(D_j),
  D_j = var_s(y)/S + max(var_s(y), v_theory,j)   (a theory variance),
        var_s(y) (1 + 1/S)                       (the twins' spread alone),
  v_theory = trigamma(edf / 2) for a chi-square estimate of edf degrees
  of freedom (its ln's variance), 1 for a normal score (edf < 0);
  plus the diagonal vx without refit shifts; with shifts U U^T
  (U = shifts / sqrt(S - 1)) the deviation is first explained as far as
  that covariance allows: a = argmin |D^-1/2 (d - U a)|^2 + |a|^2, solved
  here as a stacked least-squares problem (numpy lstsq), not by the
  normal equations the C code solves by Cholesky;
  twin-only z mapped to the normal score of Student's t(S - 1) tail;
  G = mean over domains of mean min(z^2, 40^2) + |a|^2 / n;
  the null: each twin (minus its shift) against the other S - 1; its mean,
  its variance max(sample variance, 2 sum_ij w_i w_j rho_ij^2 x mean^2)
  with rho^2 from np.corrcoef of the pseudo-reals (r^2 corrected for its
  small-sample bias), G_crit the (1 - alpha) quantile of the scaled
  chi-square of that mean and variance, z_crit = Phi^-1(1 - alpha / 2n).
  The level point (time domain, kind level) and an empty point are outside
  every statistic.

The likelihood-ratio and score tests follow hx_simgap.h: the deviance is
G plus the mean (over domains) of the mean ln D_j; the score statistic is
T = sum_j (mean_b - mean_a)_j (real - mean_a)_j / sd_tot_j^2, its null the
twins of a (minus their shifts) each against the other twins of a and b;
both z = (x - mean) / (sd sqrt(1 + 1/S)).

Writes vectors/simgap/compare.csv (key,index,value); tests/test_simgap.c
(test_compare_golden) reads the inputs from it and requires the outputs.
--check regenerates and compares with the committed file.
"""
import sys
import os
import numpy as np
from scipy import special, stats

SG_PSD, SG_LATTICE, SG_TIME = 1, 2, 5
TREND, CURV, LEVEL = 0, 1, 3
ZCAP = 40.0
S = 6
ALPHA = 0.05 / 24.0

# (domain, kind, edf, empty)
POINTS = [
    (SG_PSD, 0, 8.0, 0), (SG_PSD, 0, 8.0, 0), (SG_PSD, 0, 8.0, 0), (SG_PSD, 0, 8.0, 0),
    (SG_PSD, 0, -1.0, 0),
    (SG_TIME, TREND, 0.0, 0), (SG_TIME, TREND, 0.0, 0), (SG_TIME, CURV, 0.0, 0), (SG_TIME, TREND, 0.0, 0),
    (SG_TIME, LEVEL, 0.0, 0),
    (SG_TIME, CURV, 0.0, 1),
    (SG_LATTICE, 0, -1.0, 0),
]
N = len(POINTS)
RAYLEIGH_R = [1e-20, 1e-8, 0.5, 2.0, 20.0, 30.0, 40.0, 100.0, 400.0]


def included(j):
    dom, kind, _, empty = POINTS[j]
    return not (dom == SG_TIME and kind == LEVEL) and not empty


def v_theory(j):
    edf = POINTS[j][2]
    if edf < 0:
        return 1.0
    if edf > 0:
        return float(special.polygamma(1, 0.5 * edf))
    return 0.0


def zscores(real, twin, rows, vx, shift):
    """z, G, per-domain G, max |z| (point), mean ln D, dev, sd_tot."""
    T = twin[rows]
    nr = len(rows)
    mean = T.mean(axis=0)
    v = T.var(axis=0, ddof=1) if nr > 1 else np.zeros(N)
    vt = np.array([v_theory(j) for j in range(N)])
    D = np.where(vt > 0, v / nr + np.maximum(vt, v), v * (1.0 + 1.0 / nr))
    if shift is None and vx is not None:
        D = D + np.where(vx > 0, vx, 0.0)
    D = np.maximum(D, 1e-24)
    inc = np.array([included(j) for j in range(N)])
    dev = np.where(inc, real - mean, 0.0)
    pen = 0.0
    if shift is not None:
        U = shift.T / np.sqrt(S - 1.0)                 # n x S
        w = np.where(inc, 1.0 / np.sqrt(D), 0.0)       # D^-1/2, 0 outside
        A = np.vstack([U * w[:, None], np.eye(S)])
        b = np.concatenate([dev * w, np.zeros(S)])
        a = np.linalg.lstsq(A, b, rcond=None)[0]
        pen = float(a @ a)
        dev = dev - U @ a
    Dz = np.where(inc, D, np.inf)
    z = dev / np.sqrt(Dz)
    if nr >= 3:
        for j in range(N):
            if vt[j] == 0.0 and inc[j]:
                q = stats.t.sf(abs(z[j]), nr - 1)
                zn = stats.norm.isf(q)
                z[j] = -zn if z[j] < 0 else zn
    gdom, ldom = {}, {}
    for d in sorted(set(p[0] for p in POINTS)):
        idx = [j for j in range(N) if inc[j] and POINTS[j][0] == d]
        if idx:
            gdom[d] = float(np.mean(np.minimum(z[idx] ** 2, ZCAP ** 2)))
            ldom[d] = float(np.mean(np.log(D[idx])))
    G = float(np.mean(list(gdom.values()))) + pen / N
    lnD = float(np.mean(list(ldom.values())))
    zi = np.where(inc, np.abs(z), -1.0)
    imax = int(np.argmax(zi))
    return dict(z=z, G=G, gdom=gdom, maxz=float(zi[imax]), imax=imax, lnD=lnD, dev=dev,
                sd_tot=np.sqrt(Dz))


def compare(real, twin, vx, shift):
    allr = list(range(S))
    out = zscores(real, twin, allr, vx, shift)
    sh = shift if shift is not None else np.zeros((S, N))
    pseudo = twin - sh
    gnull = np.array([zscores(pseudo[s], twin, [r for r in allr if r != s], vx, shift)["G"] for s in allr])
    m = float(gnull.mean())
    var = float(gnull.var(ddof=1))
    # the points' correlation: G = sum_j w_j z_j^2, var G = 2 sum_ij w_i w_j rho_ij^2 (Gaussian z)
    inc = np.array([included(j) for j in range(N)])
    doms = [POINTS[j][0] for j in range(N)]
    cnt = {d: sum(1 for j in range(N) if inc[j] and doms[j] == d) for d in set(doms)}
    nd = sum(1 for d in cnt if cnt[d] > 0)
    w = np.array([1.0 / (nd * cnt[doms[j]]) if inc[j] else 0.0 for j in range(N)])
    X = (pseudo - pseudo.mean(axis=0)) / out["sd_tot"]
    X = np.where(np.isfinite(X), X, 0.0)
    live = [j for j in range(N) if np.any(X[:, j] != 0.0)]
    R2 = np.eye(N)
    C = np.corrcoef(X[:, live].T)
    c = 1.0 / (S - 1.0)
    R2l = np.clip((C ** 2 - c) / (1.0 - c), 0.0, 1.0)
    for a, ja in enumerate(live):
        for b, jb in enumerate(live):
            if ja != jb:
                R2[ja, jb] = R2l[a, b]
    vc = 2.0 * float(w @ R2 @ w) * m * m
    var = max(var, vc)
    k = 2.0 * m * m / var
    gcrit = m * stats.chi2.ppf(1.0 - ALPHA, k) / k
    zcrit = stats.norm.isf(0.5 * ALPHA / N)
    out.update(gnull=gnull, null_mean=m, null_sd=np.sqrt(var), G_crit=gcrit, z_crit=zcrit,
               significant=int(out["G"] > gcrit or out["maxz"] > zcrit))
    return out


def deviance(real, twin, rows, vx, shift):
    o = zscores(real, twin, rows, vx, shift)
    return o["G"] + o["lnD"]


def lr_test(real, ta, va, sa, tb, vb, sb):
    allr = list(range(S))
    Dr = deviance(real, ta, allr, va, sa) - deviance(real, tb, allr, vb, sb)
    pa = ta - (sa if sa is not None else 0.0)
    Ds = np.array([deviance(pa[s], ta, [r for r in allr if r != s], va, sa)
                   - deviance(pa[s], tb, [r for r in allr if r != s], vb, sb) for s in allr])
    sd = max(Ds.std(ddof=1), 1e-2)
    return (Dr - Ds.mean()) / (sd * np.sqrt(1.0 + 1.0 / S)), Dr


def score_test(real, ca, ta, sa, tb):
    D = ca["sd_tot"] ** 2
    inc = np.isfinite(D)
    ma, mb = ta.mean(axis=0), tb.mean(axis=0)
    T = float(np.sum(((mb - ma) * (real - ma) / D)[inc]))
    Ts = []
    for s in range(S):
        others = [r for r in range(S) if r != s]
        a1, b1 = ta[others].mean(axis=0), tb[others].mean(axis=0)
        ps = ta[s] - sa[s]
        Ts.append(float(np.sum(((b1 - a1) * (ps - a1) / D)[inc])))
    Ts = np.array(Ts)
    return (T - Ts.mean()) / (Ts.std(ddof=1) * np.sqrt(1.0 + 1.0 / S)), T, Ts.mean(), Ts.std(ddof=1)


def build():
    rng = np.random.RandomState(20261134)
    centre = rng.normal(0.0, 1.0, N)
    spread = np.array([0.5, 0.5, 0.5, 0.5, 0.3, 1.0, 1.0, 1.0, 1.0, 2.0, 1.0, 0.7])
    twin = centre + spread * rng.normal(0.0, 1.0, (S, N))
    off = np.array([0.3, -0.4, 3.0, 0.1, 200.0, 0.5, -6.0, 0.2, 1.5, 9.0, 0.0, -0.8])
    real = twin.mean(axis=0) + off * spread
    vx = 0.02 * (1.0 + np.arange(N)) / N
    shift = 0.2 * spread * rng.normal(0.0, 1.0, (S, N))
    sig = np.where(np.arange(N) < 5, 0.8, 0.0) * spread   # the effect b: a PSD excess
    tb = twin + sig + 0.05 * spread * rng.normal(0.0, 1.0, (S, N))
    sb = 0.2 * spread * rng.normal(0.0, 1.0, (S, N))
    # c: one point beyond z_crit, G below G_crit (significant by max |z| alone)
    off_c = np.zeros(N)
    off_c[2] = 5.0
    real_c = twin.mean(axis=0) + off_c * spread
    return real, twin, vx, shift, tb, sb, real_c


def rows():
    real, twin, vx, shift, tb, sb, real_c = build()
    out = [("S", 0, S), ("n", 0, N), ("alpha", 0, ALPHA)]
    for j, (dom, kind, edf, empty) in enumerate(POINTS):
        out += [("pt_dom", j, dom), ("pt_kind", j, kind), ("pt_edf", j, edf), ("pt_empty", j, empty)]
    for j in range(N):
        out += [("real", j, real[j]), ("vx", j, vx[j])]
    for s in range(S):
        for j in range(N):
            i = s * N + j
            out += [("twin", i, twin[s, j]), ("shift", i, shift[s, j]), ("twin_b", i, tb[s, j]),
                    ("shift_b", i, sb[s, j])]
    # a: diagonal vx, no shifts; b: shifts. The seed is one of those whose
    # null variance is the correlation term's in a and the null G's sample
    # variance in b, so that both branches of the max are pinned
    for tag, sh in (("a", None), ("b", shift)):
        c = compare(real, twin, vx, sh)
        by_sample = c["gnull"].var(ddof=1) >= c["null_sd"] ** 2
        assert by_sample == (tag == "b"), "the null variance's branch of case " + tag
        for j in range(N):
            out += [(tag + "_z", j, c["z"][j]), (tag + "_dev", j, c["dev"][j])]
        for s in range(S):
            out.append((tag + "_G_null", s, c["gnull"][s]))
        for d, g in c["gdom"].items():
            out.append((tag + "_G_dom", d, g))
        out += [(tag + "_G", 0, c["G"]), (tag + "_maxz", 0, c["maxz"]), (tag + "_imax", 0, c["imax"]),
                (tag + "_null_mean", 0, c["null_mean"]), (tag + "_null_sd", 0, c["null_sd"]),
                (tag + "_G_crit", 0, c["G_crit"]), (tag + "_z_crit", 0, c["z_crit"]),
                (tag + "_significant", 0, c["significant"])]
    c = compare(real_c, twin, vx, None)
    assert c["G"] < c["G_crit"] and c["maxz"] > c["z_crit"], "case c: max |z| alone"
    out += [("real_c", j, real_c[j]) for j in range(N)]
    out += [("c_G", 0, c["G"]), ("c_maxz", 0, c["maxz"]), ("c_G_crit", 0, c["G_crit"]),
            ("c_z_crit", 0, c["z_crit"]), ("c_significant", 0, c["significant"])]
    # sg_rayleigh_z: the exact normal score Phi^-1(1 - exp(-R)), from the
    # smaller of the two tails (no cancellation: 1 - exp(-R) is -expm1(-R));
    # the C code is asymptotic beyond R = 30 (tests/test_simgap.c bounds that)
    for i, R in enumerate(RAYLEIGH_R):
        z = stats.norm.isf(np.exp(-R)) if R > np.log(2.0) else stats.norm.ppf(-np.expm1(-R))
        out += [("rayleigh_R", i, R), ("rayleigh_z", i, z)]
    # sg_explained: the fraction of the excess (Ga - null mean) that going
    # from twins a to twins b removes, (Ga - Gb) / (Ga - null mean), with a
    # null mean of 1 and sd of 1 given (Ga is case b's G)
    Ga = zscores(real, twin, list(range(S)), vx, shift)["G"]
    Gb = zscores(real, tb, list(range(S)), vx, sb)["G"]
    out += [("expl_Ga", 0, Ga), ("expl_Gb", 0, Gb), ("expl_f", 0, (Ga - Gb) / (Ga - 1.0))]
    z, drop = lr_test(real, twin, None, shift, tb, None, sb)
    out += [("lr_z", 0, z), ("lr_drop", 0, drop)]
    z, drop = lr_test(real, twin, vx, None, tb, vx, None)
    out += [("lr_vx_z", 0, z), ("lr_vx_drop", 0, drop)]
    cb = compare(real, twin, vx, shift)
    z, t, tm, ts = score_test(real, cb, twin, shift, tb)
    out += [("score_z", 0, z), ("score_t", 0, t), ("score_t_mean", 0, tm), ("score_t_sd", 0, ts)]
    return out


def text():
    lines = ["# vectors/simgap/gen_compare.py: key,index,value (docs/simgap.md, section 3)"]
    for k, i, v in rows():
        lines.append("%s,%d,%.17g" % (k, i, float(v)))
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "compare.csv")
    t = text()
    if "--check" in sys.argv[1:]:
        with open(path) as f:
            ok = f.read() == t
        print("compare.csv: " + ("matches" if ok else "DIFFERS"))
        sys.exit(0 if ok else 1)
    with open(path, "w") as f:
        f.write(t)
    print("wrote " + path)
