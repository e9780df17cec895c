"""Shared by the analysis scripts that replay logs: `LOG... [-- REPLAY OPTIONS]`
arguments and `bin/harness replay LOG --out CSV` for each log.

Not a command; imported by scripts/height_phases.py, scripts/stand_drift.py and
scripts/still_start.py (its argument split).
"""
import os
import subprocess
import sys
import tempfile


def split_args(argv, usage):
    """(logs, replay options) from `LOG... [-- OPTIONS]`; exits with usage when no log is given."""
    if '--' in argv:
        k = argv.index('--')
        logs, opts = argv[:k], argv[k + 1:]
    else:
        logs, opts = argv, []
    if not logs:
        sys.exit(usage)
    return logs, opts


def trajectories(logs, opts):
    """Yields (log, path of its replay trajectory CSV), one log at a time;
    exits with the harness's message when a replay fails."""
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    harness = os.path.join(root, 'bin', 'harness')
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, 'traj.csv')
        for log in logs:
            r = subprocess.run([harness, 'replay', log, '--out', out] + opts,
                               stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
            if r.returncode != 0:
                sys.exit('%s: replay failed (%d): %s' % (log, r.returncode, r.stderr.strip()))
            yield log, out
