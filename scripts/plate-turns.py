#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
# The full metamorphic sweep of one plate example (issue 24): the 24 right-angle turns, 8 random
# turns x 3 units (the design written in mm, in m and in inches, with "unit") x 6 and 9 decimals; each designed with the
# CLI and the result checked with `desia check`. The unit tests run a subset of it
# (tests/core/plate_turns_test.cpp); this prints every failure.
#   python3 scripts/plate-turns.py examples/plate/table.json cut [right,random]
import json, math, random, subprocess, sys, os, itertools, tempfile
WORK = tempfile.mkdtemp(prefix='desia-turns-')
DESIA = os.environ.get('DESIA', os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'build', 'native', 'core', 'cli', 'desia'))
def rot_random(seed):
    r = random.Random(seed)
    q = [r.gauss(0,1) for _ in range(4)]; n = math.sqrt(sum(x*x for x in q)); a,b,c,d = [x/n for x in q]
    return [[a*a+b*b-c*c-d*d, 2*(b*c-a*d), 2*(b*d+a*c)],[2*(b*c+a*d), a*a-b*b+c*c-d*d, 2*(c*d-a*b)],[2*(b*d-a*c), 2*(c*d+a*b), a*a-b*b-c*c+d*d]]
def right_angle_turns():
    out = []
    for perm in itertools.permutations(range(3)):
        for signs in itertools.product([1,-1], repeat=3):
            M = [[0]*3 for _ in range(3)]
            for i in range(3): M[i][perm[i]] = signs[i]
            det = (M[0][0]*(M[1][1]*M[2][2]-M[1][2]*M[2][1]) - M[0][1]*(M[1][0]*M[2][2]-M[1][2]*M[2][0]) + M[0][2]*(M[1][0]*M[2][1]-M[1][1]*M[2][0]))
            if det == 1: out.append(M)
    return out
def apply(R, p, dec, scale):
    v = [sum(R[i][j]*p[j] for j in range(3))*scale for i in range(3)]
    return [round(x, dec) if dec else x for x in v]
def turn(doc, R, dec, scale):
    def pts(lst): return [apply(R, p, dec, scale) for p in lst]
    def plate(p):
        p = dict(p)
        if 'faces' in p: p['faces'] = [pts(f) for f in p['faces']]
        if 'outline' in p: p['outline'] = pts(p['outline']); p['thickness'] = p['thickness']*scale
        if 'holes' in p:
            p['holes'] = [[pts(f) for f in h] if 'faces' in p else pts(h) for h in p['holes']]
        if 'attached' in p: p['attached'] = [plate(a) for a in p['attached']]
        return p
    doc = dict(doc)
    for sec in ('plates','fabricationPlates'):
        if sec in doc: doc[sec] = [plate(p) for p in doc[sec]]
    return doc
def run(args, timeout=120):
    try:
        r = subprocess.run([DESIA]+args, capture_output=True, text=True, timeout=timeout)
        return r.returncode, (r.stdout+r.stderr)
    except subprocess.TimeoutExpired:
        return 'T', ''
if __name__ == '__main__':
    ex, joints = sys.argv[1], sys.argv[2]
    kinds = sys.argv[3].split(',') if len(sys.argv) > 3 else ['right','random']
    scales = [(1.0, None), (0.001, 'm'), (1 / 25.4, 'in')]; decs = [6, 9]  # the file in mm, m, inches
    doc = json.load(open(ex))
    cases = []
    if 'right' in kinds:
        for k, R in enumerate(right_angle_turns()): cases.append((f'r{k}', R, 0, 1.0, None))
    if 'random' in kinds:
        for s in range(1, 9):
            for sc, unit in scales:
                for d in decs: cases.append((f'q{s}{unit or "mm"}d{d}', rot_random(s), d, sc, unit))
    fails = []
    base = os.path.basename(ex)
    for name, R, dec, sc, unit in cases:
        inp = os.path.join(WORK, f'in_{base}_{name}.json'); out = os.path.join(WORK, f'out_{base}_{name}.json')
        moved = turn(doc, R, dec, sc)
        if unit: moved['unit'] = unit
        json.dump(moved, open(inp, 'w'))
        if os.path.exists(out): os.remove(out)
        rc, txt = run(['design','plate','--input',inp,'--joints',joints,'--seed','1','--output',out])
        crc = '-'
        if rc == 0:
            crc, ctxt = run(['check', out])
            if crc != 0: txt = ctxt
        ok = rc == 0 and crc == 0
        if not ok:
            last = [l for l in txt.splitlines() if l.strip()][-1:] 
            fails.append((name, rc, crc, last))
    print(f'{base} {joints}: {len(cases)-len(fails)}/{len(cases)} pass')
    for f in fails[:12]: print('  ', f)
