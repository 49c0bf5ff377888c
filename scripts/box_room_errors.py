#!/usr/bin/env python3
"""Face-mean and energy errors of a solver against the box rooms and the validation scenes.

Usage: scripts/box_room_errors.py [TOLERANCE] [METHOD] [NAME,NAME...]
Runs build/bin/radiant (or $RADIANT) on every scene of tests/data/box_rooms and tests/data/scenes
that has surface or energy checks (the sealed rooms and spheres only when named) and prints, per
scene, the worst error in units of its bar, each check's error, the error estimate and the time.
"""
import json
import os
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BINARY = os.environ.get('RADIANT', os.path.join(ROOT, 'build', 'bin', 'radiant'))
SETS = [os.path.join(ROOT, 'tests', 'data', 'box_rooms'), os.path.join(ROOT, 'tests', 'data', 'scenes')]
SLOW = ('two-rooms', 'sphere')  # no face-mean checks worth their time unless asked for


def errors(result, checks):
    surfaces = {s['name']: s for s in result['surfaces']}
    stats = result['stats']
    for check in checks:
        if check['what'] == 'surface':
            value = surfaces[check['surface']][check['field']]
            kind = 'E' if 'irradiance' in check['field'] else 'B'
            yield f"{check['surface'][:8]}.{kind}", value / check['value'] - 1, check['rel_tol']
        elif check['what'] == 'energy':
            yield 'energy', stats['absorbed_flux_lm'] / stats['emitted_flux_lm'] - 1, check['rel_tol']


def main():
    tolerance = sys.argv[1] if len(sys.argv) > 1 else '0.01'
    method = sys.argv[2] if len(sys.argv) > 2 else 'hierarchical'
    only = sys.argv[3].split(',') if len(sys.argv) > 3 else None
    total = 0.0
    for directory in SETS:
        with open(os.path.join(directory, 'expected.json')) as f:
            expected = json.load(f)
        for name, checks in expected.items():
            if only and not any(o in name for o in only):
                continue
            if not only and name.startswith(SLOW):
                continue
            start = time.time()
            # All 17 digits: errors of a fraction of a percent are measured on them, not on the
            # 4 digits a result carries by default.
            run = subprocess.run([BINARY, 'solve', os.path.join(directory, name + '.json'),
                                  '--method', method, '--tolerance', tolerance, '--digits', '17'],
                                 capture_output=True, text=True)
            seconds = time.time() - start
            total += seconds
            if run.returncode != 0:
                print(f'{name}: exit {run.returncode}: {run.stderr[-300:]}')
                continue
            result = json.loads(run.stdout)
            found = list(errors(result, checks))
            worst = max((abs(e) / bar for _, e, bar in found), default=0.0)
            parts = ' '.join(f'{label}{e * 100:+.3f}%' for label, e, _ in found)
            print(f"{name:24s} {'FAIL' if worst > 1 else 'ok  '} worst/bar {worst:5.2f} "
                  f"estimate {result['stats']['error_estimate']:.2g} {seconds:5.1f} s  {parts}",
                  flush=True)
    print(f'total {total:.1f} s')


if __name__ == '__main__':
    main()
