#!/usr/bin/env python3
"""Writes a scene file (and its OBJ meshes) scaled by K about the origin: every point
and length times K, directions, colours and angles as they are. Made the scenes in
this folder, which the "extremes" tests run the lessons on (a scene in units 10^5
apart); tests/scale/ checks that the pictures do not change with the unit.
Usage: scale_scene.py SCENE.json K OUT.json"""
import json, sys, os, re
src, k, dst = sys.argv[1], float(sys.argv[2]), sys.argv[3]
scene = json.load(open(src))
P = lambda p: [k * x for x in p]
def each(key, f):
    for item in scene.get(key, []): f(item)
c = scene['camera']; c['eye'] = P(c['eye']); c['look_at'] = P(c['look_at'])
for m in scene.get('materials', []):
    if 'checker_size' in m: m['checker_size'] *= k
def sphere(s): s['center'] = P(s['center']); s['radius'] *= k
def plane(p): p['point'] = P(p['point'])
def box(b): b['min'] = P(b['min']); b['max'] = P(b['max'])
def quad(q): q['corner'] = P(q['corner']); q['edge_u'] = P(q['edge_u']); q['edge_v'] = P(q['edge_v'])
def poly(p): p['corners'] = [P(x) for x in p['corners']]
def light(l): l['position'] = P(l['position'])
def mesh(m):
    name = os.path.join(os.path.dirname(src), m['file'])
    out = os.path.join(os.path.dirname(dst), os.path.basename(dst) + '.' + os.path.basename(m['file']))
    with open(out, 'w') as o:
        for line in open(name):
            w = line.split()
            if w and w[0] == 'v': line = 'v ' + ' '.join(repr(k * float(x)) for x in w[1:4]) + '\n'
            o.write(line)
    m['file'] = os.path.basename(out)
each('spheres', sphere); each('planes', plane); each('boxes', box); each('quads', quad)
each('polygons', poly); each('meshes', mesh); each('point_lights', light); each('quad_lights', quad)
scene['about'] = f"{scene.get('name', '')} scaled by {k:g} (tests/data/scaled/scale_scene.py)"
json.dump(scene, open(dst, 'w'), indent=1)
open(dst, 'a').write('\n')
