#!/usr/bin/python3
"""The end speed of tests/test_axes.c's analytic walk under the axes check's
integration, with the recorded map and the nearest rival map, in float64,
independent of the C code (test_recorded_map_right, test_nearest_rival,
test_flipped_and_swapped, test_cyclic_map, test_frames_behind_the_ring).

The walk (walk_about): 400 Hz, stance 0.4 s, swing 0.5 s turning in place
about the fixed body axis u = (cos phi cos beta, sin phi cos beta, sin beta)
by theta(t) = A (1 - cos(2 pi t / T)) / 2, A = 1 rad, T = 0.5 s, with the
specific force f_b = R(u, theta)^T (0, 0, g) and the rate theta' u.

The check (harness/hx_axes.c, integrate): per sample k of the swing,
q <- q exp(u w_k h), v <- v + (C_nb f_k + g_n) h, first order, the swing's
start attitude C_0 from the still stance's f (exact here: f = (0, 0, g)).
About a fixed axis the quaternion products compose exactly, so the attitude
angle after sample k is Theta_k = h sum_{j<=k} w_j and
C_nb f_k = C_0 R(u, Theta_k - theta_k) (0, 0, g): the end velocity is
    v = h sum_k (R(u, Theta_k - theta_k) - I) (0, 0, g)
(C_0 keeps the norm). The stance samples (w = 0, theta = 0, Theta = 0 up to
the swing) add nothing, and after a whole period of the smooth rate the
Riemann sum Theta ends at 0 to rounding, so the first stance sample that
ends the swing adds nothing either. For the recorded (right) map the error
is the rectangle rule's Theta_k - theta_k = h w_k / 2 + O(h^2): the first
order term's velocity, g h / 2 (theta(T) - theta(0)), vanishes over the turn
and back, and what remains is second order in h.

The float32 allowance the test adds: the C code runs in float (eps = 2^-24
= 6.0e-8 relative rounding); each of the swing's N = 200 steps rounds the
quaternion (from_rotvec, product, normalise) by at most about 4 eps in
angle, at most N 4 eps = 4.8e-5 rad if every rounding had the same sign,
which tilts g by that angle for at most the swing's T = 0.5 s:
g T N 4 eps = 2.4e-4 m/s; the rotated f and the velocity sum add
2 eps g T = 5.9e-7 m/s; the float h (0.0025 is not a float) scales
Theta by 1 + eps: g T A eps = 2.9e-7 m/s. The float32 allowance exceeds the
end speed itself, so in the float build the check has no lower side. The
double build runs the same code in float64: the same sum with eps = 2^-53
(4.4e-13 m/s) bounds it, and the values are printed to 12 digits for it.

Usage: /usr/bin/python3 scripts/axes_walk_ref.py
"""
import itertools

import numpy as np

RATE = 400.0
STANCE, SWING, AMP, G = 0.4, 0.5, 1.0, 9.81
EPS32 = 2.0 ** -24
EPS64 = 2.0 ** -53


def rot(u, a):
    """Rodrigues: the rotation by angle a about the unit axis u."""
    k = np.array([[0.0, -u[2], u[1]], [u[2], 0.0, -u[0]], [-u[1], u[0], 0.0]])
    return np.eye(3) + np.sin(a) * k + (1.0 - np.cos(a)) * (k @ k)


def maps():
    """The 48 signed permutations (the identity, the recorded map, first)."""
    out = []
    for perm in itertools.permutations(range(3)):
        for signs in itertools.product((1.0, -1.0), repeat=3):
            m = np.zeros((3, 3))
            for i in range(3):
                m[i, perm[i]] = signs[i]
            out.append(m)
    return out


def end_speed(phi, beta, m=None):
    """End speed of one swing with the gyro read through the matrix m (None:
    as recorded). A map only turns the fixed axis: the rate w m u."""
    h = 1.0 / RATE
    per = int(round((STANCE + SWING) * RATE))
    u = np.array([np.cos(phi) * np.cos(beta), np.sin(phi) * np.cos(beta), np.sin(beta)])
    z = np.array([0.0, 0.0, G])
    um = u if m is None else m @ u
    v = np.zeros(3)
    big_theta = 0.0
    for i in range(per + 1):  # the swing and the first stance sample after it
        ts = (i % per) / RATE - STANCE
        if 0.0 < ts and i < per:
            th = AMP * 0.5 * (1.0 - np.cos(2.0 * np.pi * ts / SWING))
            w = AMP * 0.5 * (2.0 * np.pi / SWING) * np.sin(2.0 * np.pi * ts / SWING)
        else:
            th, w = 0.0, 0.0
        big_theta += w * h
        v += h * (rot(um, big_theta) @ rot(u, -th) @ z - z)
    return float(np.linalg.norm(v))


def main():
    n = int(round(SWING * RATE))
    quat = G * SWING * n * 4.0 * EPS32
    other = 2.0 * EPS32 * G * SWING + G * SWING * AMP * EPS32
    print("float32 allowance: attitude %.2e + f and sum, h %.2e = %.2e m/s" % (quat, other, quat + other))
    q64 = G * SWING * n * 4.0 * EPS64
    o64 = 2.0 * EPS64 * G * SWING + G * SWING * AMP * EPS64
    print("float64 allowance: attitude %.2e + f and sum, h %.2e = %.2e m/s" % (q64, o64, q64 + o64))
    for beta_deg in (0.0, 20.0):
        beta = np.radians(beta_deg)
        s = [end_speed(np.radians(p), beta) for p in (30.0, 60.0)]
        print("beta %4.1f deg: end speed %.4e m/s (phi 30 deg), %.4e m/s (phi 60 deg); bound %.2e m/s"
              % (beta_deg, s[0], s[1], max(s) + quat + other))
        print("beta %4.1f deg: end speed %.12e m/s (phi 30 deg), %.12e m/s (phi 60 deg)" % (beta_deg, s[0], s[1]))
        # the nearest rival: the least median (6 swings at phi 30, 6 at 60:
        # the mean of the two) over the 47 other maps
        med = sorted((0.5 * (end_speed(np.radians(30.0), beta, m) + end_speed(np.radians(60.0), beta, m)), k)
                     for k, m in enumerate(maps()) if k > 0)
        print("beta %4.1f deg: nearest rival's median end speed %.6f m/s, the next %.6f m/s"
              % (beta_deg, med[0][0], med[1][0]))
        print("beta %4.1f deg: nearest rival's median end speed %.12e m/s" % (beta_deg, med[0][0]))


if __name__ == "__main__":
    main()
