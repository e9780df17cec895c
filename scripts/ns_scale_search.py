#!/usr/bin/env python3
"""fnav_cm_ns_scale_init() (port/cortex-m/fnav_cm_time.h) in exact integers:
k, m and the mode for a few clocks, and the first clock from 1,000,001 Hz
up whose multiply-shift alone (without the correction) is wrong at some
counter value c <= hz / 1000 - 1: tests/test_port.c, test_cm_ns_scale,
uses it (1,000,066 Hz, c = 894). Run: python3 scripts/ns_scale_search.py"""
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


for hz in (1000000, 12000000, 16000000, 25000000, 64000000, 80000000, 168000000, 180000000, 250000000,
           16777216, 14745600, 25000001, 1000066):
    print(hz, "k=%d m=%d %s" % (params(hz)[0], params(hz)[1], "EXACT" if params(hz)[2] else "FIX"))

for hz in range(1000001, 1001000):
    k, m, exact = params(hz)
    bad = [c for c in range(hz // 1000) if (c * m >> k) != c * 10**9 // hz]
    if bad:
        print("first clock needing the correction: %d Hz (mode %s), c = %s" % (hz, "EXACT" if exact else "FIX", bad))
        break
