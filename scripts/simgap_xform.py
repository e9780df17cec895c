#!/usr/bin/env python3
"""Blind transforms / injections on a CSV t,ax,ay,az,gx,gy,gz (SI), for the simgap consistency checks of docs/simgap.md ("Limitations", "Consistency").
usage: xform.py IN OUT OP [args]
ops: rot AX_DEG AY_DEG AZ_DEG   rotate acc and gyro by R = Rz Ry Rx
     perm                      cyclic axis permutation x->y->z->x (a proper rotation)
     rot90z                    90 deg about z: new x = -old y, new y = old x
     cols                      reorder columns, header renamed (use --columns)
     up2                       upsample x2 by zero-order hold (each sample repeated, t midpoints)
     upl2                      upsample x2 by linear interpolation
     step CH T0 SIZE           add SIZE to channel CH for t >= T0 (relative to first t)
     scale CH F                multiply channel CH by F
     white CH DENS SEED        add white noise of density DENS (u/sqrt(Hz))
"""
import sys, numpy as np
inp, out, op = sys.argv[1:4]; a = sys.argv[4:]
d = np.genfromtxt(inp, delimiter=',', names=True)
names = d.dtype.names[:7]
X = np.vstack([d[n] for n in names]).T
t = X[:, 0]; acc = X[:, 1:4]; gyr = X[:, 4:7]
ch = dict(ax=1, ay=2, az=3, gx=4, gy=5, gz=6)
def R_of(rx, ry, rz):
    rx, ry, rz = np.radians([rx, ry, rz])
    Rx = np.array([[1,0,0],[0,np.cos(rx),-np.sin(rx)],[0,np.sin(rx),np.cos(rx)]])
    Ry = np.array([[np.cos(ry),0,np.sin(ry)],[0,1,0],[-np.sin(ry),0,np.cos(ry)]])
    Rz = np.array([[np.cos(rz),-np.sin(rz),0],[np.sin(rz),np.cos(rz),0],[0,0,1]])
    return Rz @ Ry @ Rx
hdr = 't,ax,ay,az,gx,gy,gz'
if op == 'rot':
    R = R_of(*map(float, a[:3])); X[:, 1:4] = acc @ R.T; X[:, 4:7] = gyr @ R.T
elif op == 'perm':
    R = np.array([[0,0,1],[1,0,0],[0,1,0]]); X[:, 1:4] = acc @ R.T; X[:, 4:7] = gyr @ R.T
elif op == 'rot90z':
    R = np.array([[0,-1,0],[1,0,0],[0,0,1]]); X[:, 1:4] = acc @ R.T; X[:, 4:7] = gyr @ R.T
elif op == 'cols':
    order = [6, 0, 2, 4, 1, 5, 3]  # gz,t,ay,gx,ax,gy,az
    X = X[:, order]; hdr = 'rate_z,time,acc_y,rate_x,acc_x,rate_y,acc_z'
elif op == 'up2':
    dt = np.median(np.diff(t)); Y = np.repeat(X, 2, axis=0); Y[1::2, 0] += dt / 2; X = Y
elif op == 'upl2':
    tn = np.empty(2 * len(t) - 1); tn[0::2] = t; tn[1::2] = (t[:-1] + t[1:]) / 2
    X = np.column_stack([tn] + [np.interp(tn, t, X[:, k]) for k in range(1, 7)])
elif op == 'step':
    k = ch[a[0]]; X[t - t[0] >= float(a[1]), k] += float(a[2])
elif op == 'scale':
    X[:, ch[a[0]]] *= float(a[1])
elif op == 'white':
    k = ch[a[0]]; fs = 1 / np.median(np.diff(t)); rng = np.random.default_rng(int(a[2]))
    X[:, k] += rng.standard_normal(len(t)) * float(a[1]) * np.sqrt(fs)
else:
    sys.exit('unknown op')
np.savetxt(out, X, delimiter=',', fmt='%.10g', header=hdr, comments='')
