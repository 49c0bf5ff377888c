#!/usr/bin/env python3
"""Face-mean and energy errors of a solver against tests/data/box_rooms and ../shared/validation.

Usage: box_room_errors.py [TOLERANCE] [METHOD] [NAME,NAME...]; RADIANT=binary overrides.
"""
import json, subprocess, sys, time, os
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BIN = os.environ.get('RADIANT', ROOT + '/build/bin/radiant')
sets = [(ROOT + '/tests/data/box_rooms', None), (ROOT + '/../shared/validation/scenes', None)]
tol = sys.argv[1] if len(sys.argv) > 1 else '0.01'
method = sys.argv[2] if len(sys.argv) > 2 else 'hierarchical'
only = sys.argv[3].split(',') if len(sys.argv) > 3 else None
tot_t = 0
for d, _ in sets:
    exp = json.load(open(d + '/expected.json'))
    for name, checks in exp.items():
        if only and not any(o in name for o in only): continue
        if name.startswith('two-rooms') or name.startswith('sphere'):
            if not only: continue
        t0 = time.time()
        p = subprocess.run([BIN, 'solve', f'{d}/{name}.json', '--method', method, '--tolerance', tol],
                           capture_output=True, text=True)
        dt = time.time() - t0; tot_t += dt
        if p.returncode not in (0,):
            print(name, 'rc', p.returncode, p.stderr[-300:]);
        r = json.loads(p.stdout)
        surf = {s['name']: s for s in r['surfaces']}
        worst = 0; parts = []
        for c in checks:
            if c['what'] == 'surface':
                v = surf[c['surface']][c['field']]
                e = v / c['value'] - 1
                parts.append(f"{c['surface'][:8]}.{'E' if 'irr' in c['field'] else 'B'}{e*100:+.2f}")
                worst = max(worst, abs(e) / c['rel_tol'])
            elif c['what'] == 'energy':
                st = r['stats']; e = st['absorbed_flux_lm'] / st['emitted_flux_lm'] - 1
                parts.append(f"energy{e*100:+.3f}")
                worst = max(worst, abs(e) / c['rel_tol'])
        st = r['stats']
        print(f"{name:24s} {'FAIL' if worst>1 else 'ok  '} w={worst:5.2f} t={dt:5.1f}s links={st.get('links', '?')} " + ' '.join(parts), flush=True)
print(f'total time {tot_t:.1f}s')
