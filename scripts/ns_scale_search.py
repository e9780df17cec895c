#!/usr/bin/env python3
"""fnav_cm_ns_scale_init() (port/cortex-m/fnav_cm_time.h) in exact integers:
k, m and the case ("exact": the multiply-shift, proven equal to the
division; "division": the bound does not cover the clock) for a few clocks,
and the first clock from 1,000,001 Hz up where the multiply-shift with its
largest k is wrong at some counter value c <= hz / 1000 - 1 (so the bound
must refuse it): tests/test_port.c, test_cm_ns_scale, uses it (1,000,066 Hz,
c = 894). Run: python3 scripts/ns_scale_search.py"""
from math import gcd


def params(hz):
    k = 32
    while True:
        m = -(-(10**9 << k) // hz)  # ceil(2^k 1e9 / hz)
        if m < 2**32:
            break
        k -= 1
    j = m * hz - (10**9 << k)
    exact = (hz // 1000 - 1) * j < (gcd(10**9, hz) << k)
    return k, m, exact


def case(exact):
    return "exact" if exact else "division"


for hz in (1000000, 12000000, 16000000, 25000000, 64000000, 80000000, 168000000, 180000000, 250000000,
           16777216, 14745600, 25000001, 1000066):
    k, m, exact = params(hz)
    print(hz, "k=%d m=%d %s" % (k, m, case(exact)))

for hz in range(1000001, 1001000):
    k, m, exact = params(hz)
    bad = [c for c in range(hz // 1000) if (c * m >> k) != c * 10**9 // hz]
    if bad:
        print("first clock where the multiply-shift alone is wrong: %d Hz (%s), c = %s" % (hz, case(exact), bad))
        break
