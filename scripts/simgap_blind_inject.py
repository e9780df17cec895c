#!/usr/bin/python3
"""Blind injections for `harness simgap` (docs/simgap.md, "Blind injections
into real logs"): writes a copy of a footnav CSV (t,ax,ay,az,gx,gy,gz in s,
m/s^2, rad/s, as `bin/harness convert` writes it) with one effect added that
the diagnosis is not told of, to compare its answer with the untouched
log's.

  /usr/bin/python3 scripts/simgap_blind_inject.py IN.csv OUT.csv CASE [SEED]

CASE: vib, vibq, ramp, ramp10, rampq, warm, warmq, jumps, quant, drop, dup,
jitter, none, scale_CH_S (CH *= 1 + S), mis_CH_FROM_M (CH += M FROM),
gs_CH_FROM_K (gyro CH += K accel FROM), q_CH_STEP (re-quantise), v_CH_A_F
(tone of amplitude A at F Hz). SEED (default 7) draws the rows dropped or
duplicated and the jitter. Written for the review of 2026-12-05.
"""
import sys, numpy as np
inp, out, case = sys.argv[1], sys.argv[2], sys.argv[3]
rng = np.random.default_rng(int(sys.argv[4]) if len(sys.argv) > 4 else 7)
d = np.loadtxt(inp, delimiter=',', skiprows=1)
t = d[:, 0].copy(); C = {'ax':1,'ay':2,'az':3,'gx':4,'gy':5,'gz':6}
x = lambda c: d[:, C[c]]
tr = t - t[0]
info = ''
if case == 'vib':          # 0.05 m/s^2 at 17 Hz on ay, phase 0.3
    d[:, C['ay']] += 0.05*np.sin(2*np.pi*17*tr + 0.3); info = 'ay += 0.05 sin(2pi 17 t + 0.3)'
elif case == 'vibq':       # same tone, then re-quantised to ay's own lsb (as a sensor would)
    q = 0.0326633; d[:, C['ay']] = q*np.round((d[:, C['ay']] + 0.05*np.sin(2*np.pi*17*tr + 0.3))/q); info='ay tone then requant'
elif case == 'ramp':       # gx += 3e-6 rad/s/s * t
    d[:, C['gx']] += 3e-6*tr; info = 'gx += 3e-6 t'
elif case == 'warm':       # gy += 0.004 (1 - exp(-t/120))  (thermal: coef 4e-4 rad/s/degC x 10 degC, tau 120 s)
    d[:, C['gy']] += 0.004*(1 - np.exp(-tr/120)); info = 'gy += 0.004(1-exp(-t/120))'
elif case == 'jumps':      # gx: steps at fixed times, sizes +-0.002 rad/s
    times = [75, 160, 250, 330, 420, 515]; sizes = [0.002, -0.0025, 0.0018, -0.0022, 0.002, -0.0019]
    for tt, s in zip(times, sizes): d[tr >= tt, C['gx']] += s
    info = 'gx steps %s at %s' % (sizes, times)
elif case == 'quant':      # gx re-quantised to 0.002 rad/s
    d[:, C['gx']] = 0.002*np.round(d[:, C['gx']]/0.002); info = 'gx lsb 0.002'
elif case == 'drop':       # delete 60 random rows (0.1 %)
    keep = np.ones(len(d), bool); keep[rng.choice(np.arange(1, len(d)-1), 60, replace=False)] = False
    d = d[keep]; t = d[:, 0]; info = 'dropped 60 rows'
elif case == 'dup':        # duplicate 40 random rows
    idx = np.sort(rng.choice(np.arange(1, len(d)-1), 40, replace=False))
    d = np.insert(d, idx, d[idx], axis=0); t = d[:, 0]; info = 'duplicated 40 rows'
elif case == 'jitter':     # stamps += N(0, 1 ms), sorted-safe
    t = t + rng.normal(0, 1e-3, len(t)); t = np.maximum.accumulate(t); d[:, 0] = t; info = 'stamp jitter 1 ms'
elif case.startswith('scale_'):   # scale_gz_0.02
    _, c, s = case.split('_'); d[:, C[c]] *= 1 + float(s); info = '%s *= 1+%s' % (c, s)
elif case.startswith('mis_'):     # mis_ax_az_0.03 : ax += 0.03 az
    _, c, f, m = case.split('_'); d[:, C[c]] += float(m)*x(f); info = '%s += %s %s' % (c, m, f)
elif case.startswith('gs_'):      # gs_gx_az_0.002 : gx += k az (rad/s per m/s^2)
    _, c, f, k = case.split('_'); d[:, C[c]] += float(k)*x(f); info = '%s += %s %s' % (c, k, f)
elif case == 'warmq':      # warm-up on gy, then re-quantised to the gyro lsb (as the sensor would)
    q = 0.000872664619; d[:, C['gy']] = q*np.round((d[:, C['gy']] + 0.004*(1 - np.exp(-tr/120)))/q); info = 'gy warm then requant'
elif case == 'ramp10':     # gx += 1e-5 rad/s/s * t
    d[:, C['gx']] += 1e-5*tr; info = 'gx += 1e-5 t'
elif case == 'rampq':      # gx += 3e-6 t then requant
    q = 0.000872664619; d[:, C['gx']] = q*np.round((d[:, C['gx']] + 3e-6*tr)/q); info = 'gx ramp 3e-6 then requant'
elif case.startswith('q_'):        # q_gz_0.002 : re-quantise a channel to a step
    _, c, q = case.split('_'); q = float(q); d[:, C[c]] = q*np.round(d[:, C[c]]/q); info = '%s lsb %g' % (c, q)
elif case.startswith('v_'):        # v_ay_0.05_17 : tone on a channel
    _, c, a, f = case.split('_'); d[:, C[c]] += float(a)*np.sin(2*np.pi*float(f)*tr + 0.3); info = '%s += %s sin(2pi %s t+0.3)' % (c, a, f)
elif case == 'none':
    info = 'copy'
else:
    sys.exit('unknown case')
with open(out, 'w') as fo:
    fo.write('t,ax,ay,az,gx,gy,gz\n')
    for r in d:
        fo.write('%.9f,%s\n' % (r[0], ','.join('%.10g' % v for v in r[1:])))
print(case, info, len(d), 'rows')
