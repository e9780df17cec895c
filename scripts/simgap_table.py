#!/usr/bin/env python3
"""docs/simgap-results.md's static table from `harness simgap --json` reports.

For each report (one static log, e.g. an ADIS16405 unit) and channel: the
held-out gap G of the baseline twin and of the final model (with the final
comparison's critical value), and the effects forward selection accepted,
in order, with the fraction of the held-out excess each explained (of what
was left before its step) and its 68 % bootstrap interval.

Usage: /usr/bin/python3 scripts/simgap_table.py LABEL=REPORT.json...
e.g.   /usr/bin/python3 scripts/simgap_table.py 1=adis1.json 2=adis2.json 3=adis3.json
"""
import json
import math
import sys

DEG = 180.0 / math.pi


def num(v, digits=2):
    """v with `digits` significant digits, no exponent for everyday sizes."""
    if v == 0 or not math.isfinite(v):
        return '%g' % v
    e = int(math.floor(math.log10(abs(v))))
    if -3 <= e < 5:
        return ('%.*f' % (max(digits - 1 - e, 0), v))
    return '%.*e' % (digits - 1, v)


def size(v, unit):
    """An accelerometer size in mm/s^2 below 0.01 m/s^2, a gyro's in deg/s."""
    if unit == 'm/s^2':
        return (num(v * 1000.0) + ' mm/s²') if abs(v) < 0.01 else (num(v, 3) + ' m/s²')
    return num(v * DEG) + ' °/s'


def effect(cd, unit):
    p, name = cd['params'], cd['effect']
    if name == 'quant':
        lsb = (num(p['lsb'], 3) + ' m/s²') if unit == 'm/s^2' else (num(p['lsb'] * DEG) + ' °/s')
        return 'quant ' + lsb + (', noise-shaped form' if p.get('shaped') else '')
    if name == 'vibration':
        return 'vibration %s at %.3f Hz' % (size(p['amp'], unit), p['freq_hz'])
    if name == 'flicker':
        return 'flicker B ' + size(p['b'], unit)
    if name == 'rrw':
        return 'rrw K %s %s' % (num(p['k']), 'm/s²/√s' if unit == 'm/s^2' else 'rad/s/√s')
    if name == 'jumps':
        return 'jumps %s/h of %s' % (num(p['rate_hz'] * 3600.0), size(p['amp'], unit))
    if name == 'thermal':
        u = 'm/s²' if unit == 'm/s^2' else 'rad/s'
        return 'thermal %s %s over %s °C, τ %.0f s' % (num(p['coef'] * p['rise_c']), u, num(p['rise_c']), p['tau_s'])
    if name == 'ramp':
        return 'ramp %s %s/s' % (num(p['rate']), 'm/s²' if unit == 'm/s^2' else 'rad/s')
    return name


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    print('| unit | ch | G held out: baseline → final (crit) | effects accepted, in order (explained) |')
    print('| --- | --- | --- | --- |')
    for arg in sys.argv[1:]:
        label, _, path = arg.partition('=')
        rep = json.load(open(path))
        for c in rep['channels']:
            if not c.get('analysed', True):
                continue
            g0 = c['gap']['held_out']['G']
            gf = c['gap_final']['held_out']
            acc = []
            for st in c['attribution']['steps']:
                for cd in st['candidates']:
                    if cd.get('selected'):
                        e = effect(cd, c['unit'])
                        if cd.get('explained') is not None:
                            e += ' (%.0f %%' % (100.0 * cd['explained'])
                            if cd.get('explained_lo') is not None and cd.get('explained_hi') is not None:
                                e += ', %.0f-%.0f' % (100.0 * cd['explained_lo'], 100.0 * cd['explained_hi'])
                            e += ')'
                        acc.append(e)
            print('| %s | %s | %s → %s (%s) | %s |' % (label, c['channel'], num(g0, 3), num(gf['G'], 2) if gf['G'] < 100 else '%.0f' % gf['G'],
                                                     num(gf['G_crit'], 2), '; '.join(acc) or '—'))


if __name__ == '__main__':
    main()
