#!/usr/bin/env python3
"""Build the validation corpus for the Rust port of compare_spec.py and record the Python
tool's verdicts on it.

  gen_corpus.py REF_CASES_DIR OUT_DIR CORPUS_JSON

For every pair (expected, actual) it lays out OUT_DIR/<opts>/exp/<id>/ and .../act/<id>/
(specification.json or error.txt), runs compare_spec.compare_case on them in-process (what
the script's --cases mode runs per case, exceptions turned into 'comparator error' like
its run_one) and writes CORPUS_JSON: each pair as a base case plus a compact patch (the
Rust test re-applies it), its options and the Python verdict (pass, PASS*, max_dev,
all reasons and notes, with OUT_DIR replaced by {ROOT}).

Deterministic: fixed seeds, sorted inputs.
"""
import copy
import json
import math
import os
import random
import shutil
import sys

sys.path.insert(0, '/work/shared/tools')
import compare_spec as C  # noqa: E402

REF, OUT, CORPUS = sys.argv[1], sys.argv[2], sys.argv[3]

CASES = sorted(d for d in os.listdir(REF)
               if os.path.isfile(os.path.join(REF, d, 'specification.json'))
               or os.path.isfile(os.path.join(REF, d, 'error.txt')))
SPECS = {}
ERRORS = {}
for c in CASES:
    p = os.path.join(REF, c, 'specification.json')
    if os.path.isfile(p):
        with open(p) as f:
            SPECS[c] = json.load(f)
    else:
        with open(os.path.join(REF, c, 'error.txt')) as f:
            ERRORS[c] = f.read()
SPEC_CASES = sorted(SPECS)
CHAOTIC_CASES = [c for c in SPEC_CASES if any(C.is_chaotic(n) for n in SPECS[c]['pattern']['panels'])]
PLAIN_CASES = [c for c in SPEC_CASES if c not in CHAOTIC_CASES]


# ------------------------------------------------------------------ patches
def diff(a, b, path, ops):
    """Ops turning a into b: ['set', path, value] / ['del', path]. Dicts whose key order
    changed (other than new keys at the end) and lists whose length changed are replaced."""
    if isinstance(a, dict) and isinstance(b, dict):
        ka, kb = list(a), list(b)
        if kb != [k for k in ka if k in b] + [k for k in kb if k not in a]:
            ops.append(['set', path, b])
            return
        for k in ka:
            if k not in b:
                ops.append(['del', path + [k]])
        for k in kb:
            if k in a:
                diff(a[k], b[k], path + [k], ops)
            else:
                ops.append(['set', path + [k], b[k]])
    elif isinstance(a, list) and isinstance(b, list) and len(a) == len(b):
        for i in range(len(a)):
            diff(a[i], b[i], path + [i], ops)
    elif type(a) is not type(b) or json.dumps(a) != json.dumps(b):
        ops.append(['set', path, b])


def apply(spec, ops):
    spec = copy.deepcopy(spec)
    for op in ops:
        path = op[1]
        if not path:
            spec = copy.deepcopy(op[2])
            continue
        node = spec
        for k in path[:-1]:
            node = node[k]
        if op[0] == 'set':
            node[path[-1]] = copy.deepcopy(op[2])
        else:
            del node[path[-1]]
    return spec


# ------------------------------------------------------------------ helpers
def panels(spec):
    return spec['pattern']['panels']


def stitches(spec):
    return spec['pattern']['stitches']


def chaotic_names(spec):
    return sorted(n for n in panels(spec) if C.is_chaotic(n))


def plain_names(spec):
    return sorted(n for n in panels(spec) if not C.is_chaotic(n))


def stitched_edges(spec):
    return {(s['panel'], s['edge']) for st in stitches(spec) for s in st[:2]}


def seam_edges(spec):
    """(chaotic panel, edge) stitched to a non-chaotic panel (the fitted curves)."""
    out = []
    for st in stitches(spec):
        a, b = st[0], st[1]
        for x, y in ((a, b), (b, a)):
            if C.is_chaotic(x['panel']) and not C.is_chaotic(y['panel']):
                out.append((x['panel'], x['edge']))
    return sorted(set(out))


def edges_of_kind(p, kind):
    out = []
    for k, e in enumerate(p['edges']):
        c = e.get('curvature')
        t = 'line' if c is None else ('quadratic' if isinstance(c, list) else c['type'])
        if t == kind:
            out.append(k)
    return out


# ------------------------------------------------------------------ perturbations
# Each takes a deep copy of a spec and returns it modified (or None if not applicable).
def op_move_vertex(name_sel, dx, dy=0.0, vi=1):
    def f(sp):
        names = name_sel(sp)
        if not names:
            return None
        v = panels(sp)[names[0]]['vertices']
        v[vi % len(v)][0] += dx
        v[vi % len(v)][1] += dy
        return sp
    return f


def op_move_seam_vertex(d, which=0):
    """Move the end vertex of a chaotic panel's seam edge (changes the fitted curve)."""
    def f(sp):
        se = seam_edges(sp)
        if not se:
            return None
        pn, ei = se[which % len(se)]
        p = panels(sp)[pn]
        vi = p['edges'][ei]['endpoints'][1]
        p['vertices'][vi][0] += d
        p['vertices'][vi][1] += d / 2
        return sp
    return f


def op_seam_curve(delta, which=0):
    """Bend a chaotic panel's seam edge (its curvature params, or make a straight one curved)."""
    def f(sp):
        se = seam_edges(sp)
        if not se:
            return None
        pn, ei = se[which % len(se)]
        ed = panels(sp)[pn]['edges'][ei]
        c = ed.get('curvature')
        if c is None:
            ed['curvature'] = {'type': 'quadratic', 'params': [[0.5, delta]]}
        elif isinstance(c, list):
            c[1] += delta
        elif c['type'] == 'circle':
            c['params'][0] *= 1 + delta
        else:
            c['params'][0][1] += delta
        return sp
    return f


def op_curv(kind, delta, chaotic=False):
    def f(sp):
        names = chaotic_names(sp) if chaotic else plain_names(sp)
        for n in names:
            ks = edges_of_kind(panels(sp)[n], kind)
            if ks:
                c = panels(sp)[n]['edges'][ks[0]]['curvature']
                if kind == 'circle':
                    c['params'][0] *= 1 + delta
                else:
                    c['params'][-1][1] += delta
                return sp
        return None
    return f


def op_arc_flag(idx, also_reverse=False):
    def f(sp):
        for n in sorted(panels(sp)):
            ks = edges_of_kind(panels(sp)[n], 'circle')
            if ks:
                ed = panels(sp)[n]['edges'][ks[0]]
                c = ed['curvature']
                c['params'][idx] = int(not c['params'][idx])
                if also_reverse:
                    ed['endpoints'] = ed['endpoints'][::-1]
                return sp
        return None
    return f


def _shift(name, p):
    n = len(p['edges'])
    k = (1 + len(name)) % n if n > 1 else 0
    return C._reindex_panel(p, [(i + k) % n for i in range(n)], False)


def _rev(name, p):
    n = len(p['edges'])
    return C._reindex_panel(p, list(reversed(range(n))), True)


def _rev_shift(name, p):
    n = len(p['edges'])
    return C._reindex_panel(p, [(n - 1 - i + 2) % n for i in range(n)], True)


def _flip_only(name, p):
    """Reverse the loop direction without fixing the curvature (geometry changes)."""
    n = len(p['edges'])
    q, em = C._reindex_panel(p, list(reversed(range(n))), False)
    for ed in q['edges']:
        ed['endpoints'] = ed['endpoints'][::-1]
    return q, em


def op_reindex(fn, sel):
    def f(sp):
        names = set(sel(sp))
        if not names:
            return None
        return C._transform(sp, lambda n, p: fn(n, p) if n in names else (p, {k: k for k in range(len(p['edges']))}))
    return f


def op_rename(sel, new):
    def f(sp):
        names = sel(sp)
        if not names:
            return None
        old = names[0]
        ps = panels(sp)
        sp['pattern']['panels'] = {(new if k == old else k): v for k, v in ps.items()}
        for st in stitches(sp):
            for s in st[:2]:
                if s['panel'] == old:
                    s['panel'] = new
        return sp
    return f


def _stitch_index(sp, chaotic):
    for k, st in enumerate(stitches(sp)):
        t = C.is_chaotic(st[0]['panel']) or C.is_chaotic(st[1]['panel'])
        if t == chaotic:
            return k
    return None


def op_drop_stitch(chaotic=False):
    def f(sp):
        k = _stitch_index(sp, chaotic)
        if k is None:
            return None
        stitches(sp).pop(k)
        return sp
    return f


def op_dup_stitch(chaotic=False):
    def f(sp):
        k = _stitch_index(sp, chaotic)
        if k is None:
            return None
        stitches(sp).append(copy.deepcopy(stitches(sp)[k]))
        return sp
    return f


def op_add_free_stitch():
    def f(sp):
        used = stitched_edges(sp)
        free = [(n, k) for n in plain_names(sp) for k in range(len(panels(sp)[n]['edges'])) if (n, k) not in used]
        if len(free) < 2:
            return None
        stitches(sp).append([{'panel': free[0][0], 'edge': free[0][1]}, {'panel': free[1][0], 'edge': free[1][1]}])
        return sp
    return f


def op_swap_sides():
    def f(sp):
        sp['pattern']['stitches'] = [[st[1], st[0]] + st[2:] for st in stitches(sp)]
        return sp
    return f


def op_shuffle_stitches(seed):
    def f(sp):
        random.Random(seed).shuffle(stitches(sp))
        return sp
    return f


def op_toggle_rw(chaotic=False):
    def f(sp):
        k = _stitch_index(sp, chaotic)
        if k is None:
            return None
        st = stitches(sp)[k]
        if len(st) > 2:
            del st[2:]
        else:
            st.append('right_wrong')
        return sp
    return f


def op_retarget(chaotic=False):
    def f(sp):
        k = _stitch_index(sp, chaotic)
        if k is None:
            return None
        s = stitches(sp)[k][0]
        s['edge'] = (s['edge'] + 1) % len(panels(sp)[s['panel']]['edges'])
        return sp
    return f


def op_euler_equiv(sel):
    def f(sp):
        for n in sel(sp):
            a, b, c = panels(sp)[n]['rotation']
            panels(sp)[n]['rotation'] = [a + 180, 180 - b, c - 180]
        return sp
    return f


def op_rotate(sel, axis, deg):
    def f(sp):
        names = sel(sp)
        if not names:
            return None
        panels(sp)[names[0]]['rotation'][axis] += deg
        return sp
    return f


def op_rot_matrix(sel):
    def f(sp):
        for n in sel(sp):
            panels(sp)[n]['rotation'] = C.rot_matrix(panels(sp)[n]['rotation'], 'XYZ')
        return sp
    return f


def op_translate(sel, axis, d):
    def f(sp):
        names = sel(sp)
        if not names:
            return None
        for n in names:
            panels(sp)[n]['translation'][axis] += d
        return sp
    return f


def op_units(factor, rescale=True):
    def f(sp):
        sp.setdefault('properties', {})['units_in_meter'] = 100 * factor
        if rescale:
            for p in panels(sp).values():
                p['vertices'] = [[x * factor, y * factor] for x, y in p['vertices']]
                p['translation'] = [x * factor for x in p['translation']]
                for ed in p['edges']:
                    c = ed.get('curvature')
                    if isinstance(c, dict) and c['type'] == 'circle':
                        c['params'][0] *= factor
        return sp
    return f


def op_set_prop(key, value):
    def f(sp):
        sp.setdefault('properties', {})[key] = value
        return sp
    return f


def op_legacy_curv():
    def f(sp):
        hit = False
        for p in panels(sp).values():
            for ed in p['edges']:
                c = ed.get('curvature')
                if isinstance(c, dict) and c['type'] == 'quadratic':
                    ed['curvature'] = list(c['params'][0])
                    hit = True
        return sp if hit else None
    return f


def op_absolute_curv():
    def f(sp):
        sp.setdefault('properties', {})['curvature_coords'] = 'absolute'
        for p in panels(sp).values():
            for ed in p['edges']:
                c = ed.get('curvature')
                if isinstance(c, dict) and c['type'] in ('quadratic', 'cubic'):
                    s = p['vertices'][ed['endpoints'][0]]
                    e = p['vertices'][ed['endpoints'][1]]
                    c['params'] = [list(C.rel_to_abs(s, e, q)) for q in c['params']]
        return sp
    return f


def op_split(offset, chaotic):
    def f(sp):
        out, changed = C._split_edges(sp, offset, (lambda n: C.is_chaotic(n) == chaotic))
        return out if changed else None
    return f


def op_retype(chaotic):
    def f(sp):
        names = chaotic_names(sp) if chaotic else plain_names(sp)
        for n in names:
            for ed in panels(sp)[n]['edges']:
                if 'curvature' not in ed:
                    ed['curvature'] = {'type': 'quadratic', 'params': [[0.5, 0.0]]}
                    return sp
        return None
    return f


def op_label(value):
    def f(sp):
        n = plain_names(sp)[0]
        if value is None:
            panels(sp)[n].pop('label', None)
        else:
            panels(sp)[n]['label'] = value
        return sp
    return f


def op_shuffle_panels(seed):
    def f(sp):
        items = list(panels(sp).items())
        random.Random(seed).shuffle(items)
        sp['pattern']['panels'] = dict(items)
        return sp
    return f


def op_merge_edges():
    """Drop the vertex between two consecutive straight free edges of a non-chaotic panel."""
    def f(sp):
        used = stitched_edges(sp)
        for n in plain_names(sp):
            p = panels(sp)[n]
            m = len(p['edges'])
            for k in range(m):
                a, b = p['edges'][k], p['edges'][(k + 1) % m]
                if ('curvature' not in a and 'curvature' not in b and (n, k) not in used
                        and (n, (k + 1) % m) not in used and m > 3):
                    a['endpoints'] = [a['endpoints'][0], b['endpoints'][1]]
                    del p['edges'][(k + 1) % m]
                    for st in stitches(sp):
                        for s in st[:2]:
                            if s['panel'] == n and s['edge'] > (k + 1) % m:
                                s['edge'] -= 1
                    return sp
        return None
    return f


def op_chaotic_group_translate(d, axis=2):
    def f(sp):
        names = chaotic_names(sp)
        if not names:
            return None
        for n in names:
            panels(sp)[n]['translation'][axis] += d
        return sp
    return f


def op_chaotic_scale(factor):
    """Scale every chaotic panel about its first vertex (a gross but smooth change)."""
    def f(sp):
        names = chaotic_names(sp)
        if not names:
            return None
        for n in names:
            v = panels(sp)[n]['vertices']
            x0, y0 = v[0]
            panels(sp)[n]['vertices'] = [[x0 + (x - x0) * factor, y0 + (y - y0) * factor] for x, y in v]
            for ed in panels(sp)[n]['edges']:
                c = ed.get('curvature')
                if isinstance(c, dict) and c['type'] == 'circle':
                    c['params'][0] *= factor
        return sp
    return f


def op_chaotic_sliver_edge():
    """Split a free edge of a chaotic panel so that one piece is a 0.5 cm sliver."""
    def f(sp):
        used = stitched_edges(sp)
        for n in chaotic_names(sp):
            p = panels(sp)[n]
            for k, ed in enumerate(p['edges']):
                if 'curvature' in ed or (n, k) in used:
                    continue
                s, e = p['vertices'][ed['endpoints'][0]], p['vertices'][ed['endpoints'][1]]
                L = math.hypot(e[0] - s[0], e[1] - s[1])
                if L < 3:
                    continue
                t = 0.5 / L
                p['vertices'].append([s[0] + (e[0] - s[0]) * t, s[1] + (e[1] - s[1]) * t])
                mi = len(p['vertices']) - 1
                a, b = dict(ed), dict(ed)
                a['endpoints'] = [ed['endpoints'][0], mi]
                b['endpoints'] = [mi, ed['endpoints'][1]]
                p['edges'][k:k + 1] = [a, b]
                for st in stitches(sp):
                    for sd in st[:2]:
                        if sd['panel'] == n and sd['edge'] > k:
                            sd['edge'] += 1
                return sp
        return None
    return f


def op_malformed(kind):
    def f(sp):
        n = sorted(panels(sp))[0]
        p = panels(sp)[n]
        if kind == 'no_edges_key':
            del p['edges']
        elif kind == 'empty_edges':
            p['edges'] = []
            sp['pattern']['stitches'] = [st for st in stitches(sp) if n not in (st[0]['panel'], st[1]['panel'])]
        elif kind == 'nan_vertex':
            p['vertices'][0][0] = 'NaN'
        elif kind == 'string_number':
            p['vertices'][0][0] = str(p['vertices'][0][0])
        elif kind == 'bad_index':
            p['edges'][0]['endpoints'] = [0, len(p['vertices']) + 3]
        elif kind == 'neg_index':
            p['edges'][0]['endpoints'] = [p['edges'][0]['endpoints'][0] - len(p['vertices']), p['edges'][0]['endpoints'][1]]
        elif kind == 'translation2':
            p['translation'] = p['translation'][:2]
        elif kind == 'bad_curv_type':
            p['edges'][0]['curvature'] = {'type': 'spline', 'params': []}
        elif kind == 'cubic1':
            p['edges'][0]['curvature'] = {'type': 'cubic', 'params': [[0.3, 0.1]]}
        elif kind == 'circle_same_ends':
            p['vertices'].append(list(p['vertices'][p['edges'][0]['endpoints'][0]]))
            p['edges'][0]['endpoints'] = [p['edges'][0]['endpoints'][0], len(p['vertices']) - 1]
            p['edges'][0]['curvature'] = {'type': 'circle', 'params': [5, 0, 1]}
        elif kind == 'zero_length_stitch':
            # a degenerate (zero-length) straight edge on a stitched chaotic side
            cn = chaotic_names(sp)
            if not cn:
                return None
            se = [(a, b) for a, b in seam_edges(sp)]
            if not se:
                return None
            pn, ei = se[0]
            q = panels(sp)[pn]
            ed = q['edges'][ei]
            ed.pop('curvature', None)
            q['vertices'].append(list(q['vertices'][ed['endpoints'][0]]))
            ed['endpoints'] = [ed['endpoints'][0], len(q['vertices']) - 1]
        elif kind == 'unknown_panel_stitch':
            stitches(sp)[0][0]['panel'] = 'no_such_panel'
        elif kind == 'edge_out_of_range':
            stitches(sp)[0][0]['edge'] = 999
        elif kind == 'negative_edge':
            stitches(sp)[0][0]['edge'] = -1
        elif kind == 'float_edge':
            stitches(sp)[0][0]['edge'] = stitches(sp)[0][0]['edge'] + 0.7
        elif kind == 'stitch_dict':
            stitches(sp)[0] = {'a': 1}
        elif kind == 'stitch_short':
            stitches(sp)[0] = stitches(sp)[0][:1]
        elif kind == 'units_zero':
            sp['properties']['units_in_meter'] = 0
        elif kind == 'units_string':
            sp['properties']['units_in_meter'] = '100'
        elif kind == 'no_panels':
            del sp['pattern']['panels']
        elif kind == 'rotation_2':
            p['rotation'] = p['rotation'][:2]
        elif kind == 'rotation_nan':
            p['rotation'][0] = 'inf'
        elif kind == 'label_int':
            p['label'] = 0
        elif kind == 'flag_int':
            stitches(sp)[0] = stitches(sp)[0][:2] + [1]
        else:
            raise ValueError(kind)
        return sp
    return f


# ------------------------------------------------------------------ the corpus
def first_plain(sp):
    return plain_names(sp)[:1]


def first_chaotic(sp):
    return chaotic_names(sp)[:1]


def all_panels(sp):
    return sorted(panels(sp))


PERTURB = [
    # (label, op, cases, options)
    ('vertex +0.03 cm', op_move_vertex(first_plain, 0.03), PLAIN_CASES[::3] + CHAOTIC_CASES[:3], {}),
    ('vertex +0.06 cm', op_move_vertex(first_plain, 0.06), PLAIN_CASES[1::3] + CHAOTIC_CASES[3:6], {}),
    ('vertex +1 cm', op_move_vertex(first_plain, 1.0), PLAIN_CASES[2::4], {}),
    ('vertex +0.03/-0.04 cm (diag)', op_move_vertex(first_plain, 0.03, -0.04, 2), PLAIN_CASES[::5], {}),
    ('vertex +0.049 cm', op_move_vertex(first_plain, 0.049, 0, 0), PLAIN_CASES[::6], {}),
    ('vertex +0.06 cm, tol 0.1', op_move_vertex(first_plain, 0.06), PLAIN_CASES[::6], {'tol': 0.1}),
    ('chaotic panel vertex +0.03 cm', op_move_vertex(first_chaotic, 0.03), CHAOTIC_CASES, {}),
    ('chaotic panel vertex +0.3 cm', op_move_vertex(first_chaotic, 0.3, 0, 0), CHAOTIC_CASES, {}),
    ('chaotic seam vertex +0.05 cm', op_move_seam_vertex(0.05), CHAOTIC_CASES, {}),
    ('chaotic seam vertex +0.2 cm', op_move_seam_vertex(0.2), CHAOTIC_CASES, {}),
    ('chaotic seam vertex +0.6 cm', op_move_seam_vertex(0.6, 1), CHAOTIC_CASES, {}),
    ('chaotic seam vertex +3 cm', op_move_seam_vertex(3.0), CHAOTIC_CASES, {}),
    ('chaotic seam curve bent 0.002', op_seam_curve(0.002), CHAOTIC_CASES, {}),
    ('chaotic seam curve bent 0.01', op_seam_curve(0.01, 1), CHAOTIC_CASES, {}),
    ('chaotic seam curve bent 0.05', op_seam_curve(0.05), CHAOTIC_CASES, {}),
    ('chaotic seam curve bent 0.01, no chaotic rule', op_seam_curve(0.01, 1), CHAOTIC_CASES[::2],
     {'chaotic_rule': False}),
    ('chaotic seam curve bent 0.01, sliver 0.2 / gain 2', op_seam_curve(0.01, 1), CHAOTIC_CASES[1::2],
     {'sliver': 0.2, 'gain': 2.0}),
    ('chaotic panels translated 0.02 cm z', op_chaotic_group_translate(0.02), CHAOTIC_CASES[::2], {}),
    ('chaotic panels translated 0.5 cm z', op_chaotic_group_translate(0.5), CHAOTIC_CASES[1::2], {}),
    ('chaotic panels translated 5 cm y', op_chaotic_group_translate(5.0, 1), CHAOTIC_CASES[::3], {}),
    ('chaotic panels scaled 1.002', op_chaotic_scale(1.002), CHAOTIC_CASES, {}),
    ('chaotic panels scaled 1.03', op_chaotic_scale(1.03), CHAOTIC_CASES[::2], {}),
    ('chaotic panels scaled 1.03, chaos tols raised', op_chaotic_scale(1.03), CHAOTIC_CASES[1::2],
     {'outline': 10.0, 'stitch': 10.0, 'ratio': 0.5, 'seam_ratio': 0.5}),
    ('chaotic sliver edge added', op_chaotic_sliver_edge(), CHAOTIC_CASES, {}),
    ('chaotic edge split (same geometry)', op_split(0.0, True), CHAOTIC_CASES[::2], {}),
    ('chaotic straight edge as quadratic', op_retype(True), CHAOTIC_CASES[1::2], {}),
    ('quadratic param +0.001', op_curv('quadratic', 0.001), SPEC_CASES[::3], {}),
    ('quadratic param +0.05', op_curv('quadratic', 0.05), SPEC_CASES[1::3], {}),
    ('cubic param +0.0005', op_curv('cubic', 0.0005), SPEC_CASES[::3], {}),
    ('cubic param +0.02', op_curv('cubic', 0.02), SPEC_CASES[1::3], {}),
    ('chaotic cubic param +0.02', op_curv('cubic', 0.02, True), CHAOTIC_CASES, {}),
    ('circle radius x1.0001', op_curv('circle', 0.0001), SPEC_CASES[::3], {}),
    ('circle radius x1.05', op_curv('circle', 0.05), SPEC_CASES[1::3], {}),
    ('arc large flag toggled', op_arc_flag(1), SPEC_CASES[::3], {}),
    ('arc right flag toggled', op_arc_flag(2), SPEC_CASES[1::3], {}),
    ('arc right flag toggled + endpoints swapped (same arc)', op_arc_flag(2, True), SPEC_CASES[2::3], {}),
    ('loops cyclically shifted', op_reindex(_shift, all_panels), SPEC_CASES[::6], {}),
    ('loops reversed', op_reindex(_rev, all_panels), SPEC_CASES[1::6], {}),
    ('loops reversed + shifted', op_reindex(_rev_shift, all_panels), SPEC_CASES[2::8], {}),
    ('loops reversed, strict', op_reindex(_rev, all_panels), SPEC_CASES[3::9], {'strict': True}),
    ('one loop reversed without fixing curvature', op_reindex(_flip_only, first_plain), SPEC_CASES[::3], {}),
    ('chaotic loop reversed', op_reindex(_rev, first_chaotic), CHAOTIC_CASES, {}),
    ('panel renamed', op_rename(first_plain, 'renamed_panel'), SPEC_CASES[::4], {}),
    ('chaotic panel renamed to a plain name', op_rename(first_chaotic, 'sleeve_x'), CHAOTIC_CASES[::2], {}),
    ('plain panel renamed to a chaotic name', op_rename(first_plain, 'left_hood'), PLAIN_CASES[::5], {}),
    ('stitch dropped', op_drop_stitch(), SPEC_CASES[::3], {}),
    ('chaotic stitch dropped', op_drop_stitch(True), CHAOTIC_CASES, {}),
    ('stitch duplicated', op_dup_stitch(), SPEC_CASES[1::3], {}),
    ('chaotic stitch duplicated', op_dup_stitch(True), CHAOTIC_CASES[::2], {}),
    ('stitch added between free edges', op_add_free_stitch(), SPEC_CASES[2::3], {}),
    ('stitch sides swapped', op_swap_sides(), SPEC_CASES[::6], {}),
    ('stitches shuffled', op_shuffle_stitches(5), SPEC_CASES[1::6], {}),
    ('right_wrong toggled', op_toggle_rw(), SPEC_CASES[::2], {}),
    ('chaotic right_wrong toggled', op_toggle_rw(True), CHAOTIC_CASES, {}),
    ('stitch moved to the next edge', op_retarget(), SPEC_CASES[1::3], {}),
    ('chaotic stitch moved to the next edge', op_retarget(True), CHAOTIC_CASES[::2], {}),
    ('equivalent Euler triples', op_euler_equiv(all_panels), SPEC_CASES[::3], {}),
    ('equivalent Euler triples, extrinsic convention', op_euler_equiv(all_panels), SPEC_CASES[1::6],
     {'euler': 'xyz'}),
    ('rotation as 3x3 matrix', op_rot_matrix(all_panels), SPEC_CASES[2::4], {}),
    ('panel rotated 0.01 deg about y', op_rotate(first_plain, 1, 0.01), SPEC_CASES[::4], {}),
    ('panel rotated 0.5 deg about x', op_rotate(first_plain, 0, 0.5), SPEC_CASES[1::4], {}),
    ('panel translated 0.03 cm x', op_translate(first_plain, 0, 0.03), SPEC_CASES[::4], {}),
    ('panel translated 0.06 cm z', op_translate(first_plain, 2, 0.06), SPEC_CASES[1::4], {}),
    ('panel translated 1 cm y', op_translate(first_plain, 1, 1.0), SPEC_CASES[2::4], {}),
    ('units_in_meter 1000, coordinates x10', op_units(10), SPEC_CASES[::8], {}),
    ('units_in_meter 1, coordinates /100', op_units(0.01), SPEC_CASES[1::8], {}),
    ('units_in_meter 1000 only', op_units(10, False), SPEC_CASES[2::6], {}),
    ('legacy list curvature', op_legacy_curv(), SPEC_CASES[::3], {}),
    ('absolute curvature coordinates', op_absolute_curv(), SPEC_CASES[1::4], {}),
    ('free edge split (same geometry)', op_split(0.0, False), SPEC_CASES[::5], {}),
    ('free edge split, vertex pushed 0.2 cm', op_split(0.2, False), SPEC_CASES[1::5], {}),
    ('free edge split, vertex pushed 0.03 cm', op_split(0.03, False), SPEC_CASES[2::5], {}),
    ('straight edge as quadratic (same geometry)', op_retype(False), SPEC_CASES[::4], {}),
    ('two straight edges merged', op_merge_edges(), SPEC_CASES[::3], {}),
    ('panel label changed', op_label('other'), SPEC_CASES[::5], {}),
    ('panel label changed, strict', op_label('other'), SPEC_CASES[1::5], {'strict': True}),
    ('panel label removed', op_label(None), SPEC_CASES[2::7], {}),
    ('panel label empty string, strict', op_label(''), SPEC_CASES[3::9], {'strict': True}),
    ('panel order shuffled', op_shuffle_panels(3), [c for c in SPEC_CASES if len(SPECS[c]['pattern']['panels']) <= 4][:4], {}),
    ('curvature_coords bogus value', op_set_prop('curvature_coords', 'other'), SPEC_CASES[::12], {}),
]
MALFORMED = ['no_edges_key', 'empty_edges', 'nan_vertex', 'string_number', 'bad_index', 'neg_index',
             'translation2', 'bad_curv_type', 'cubic1', 'circle_same_ends', 'zero_length_stitch',
             'unknown_panel_stitch', 'edge_out_of_range', 'negative_edge', 'float_edge', 'stitch_dict',
             'stitch_short', 'units_zero', 'units_string', 'no_panels', 'rotation_2', 'rotation_nan',
             'label_int', 'flag_int']


def build_pairs():
    pairs = []

    def add(cat, desc, exp, act, opts=None):
        pairs.append(dict(cat=cat, desc=desc, exp=exp, act=act, opts=opts or {}))

    # 1. every reference case against itself
    for c in CASES:
        src = {'case': c} if c in SPECS else {'error': ERRORS[c]}
        add('self', 'identity', src, src)
    # 2. perturbations
    for label, op, cases, opts in PERTURB:
        for c in cases:
            sp = op(copy.deepcopy(SPECS[c]))
            if sp is None:
                continue
            ops = []
            diff(SPECS[c], sp, [], ops)
            add('perturbed', label, {'case': c}, {'case': c, 'patch': ops}, opts)
    # ... a few in the other direction (the perturbed spec as the expected one)
    for label, op, cases, opts in PERTURB[::6]:
        for c in cases[:2]:
            sp = op(copy.deepcopy(SPECS[c]))
            if sp is None:
                continue
            ops = []
            diff(SPECS[c], sp, [], ops)
            add('perturbed', label + ' (as expected)', {'case': c, 'patch': ops}, {'case': c}, opts)
    for k, kind in enumerate(MALFORMED):
        for c in (SPEC_CASES[k % len(SPEC_CASES)], CHAOTIC_CASES[k % len(CHAOTIC_CASES)]):
            sp = op_malformed(kind)(copy.deepcopy(SPECS[c]))
            if sp is None:
                continue
            ops = []
            diff(SPECS[c], sp, [], ops)
            add('malformed', 'malformed actual: ' + kind, {'case': c}, {'case': c, 'patch': ops})
        if k % 3 == 0:
            c = SPEC_CASES[(k + 7) % len(SPEC_CASES)]
            sp = op_malformed(kind)(copy.deepcopy(SPECS[c]))
            if sp is not None:
                ops = []
                diff(SPECS[c], sp, [], ops)
                add('malformed', 'malformed expected: ' + kind, {'case': c, 'patch': ops}, {'case': c})
    for c in SPEC_CASES[::7]:
        add('malformed', 'actual is not JSON', {'case': c}, {'raw': '{"pattern": {"panels": '})
        add('malformed', 'actual is a JSON list', {'case': c}, {'raw': '[1, 2]'})
        add('malformed', 'actual has NaN literal', {'case': c},
            {'raw': json.dumps(SPECS[c]).replace('"translation": [', '"translation": [NaN, ', 1)} if c == SPEC_CASES[0] else
            {'raw': '{"pattern": {"panels": {"a": {"vertices": [[0, 0], [1, NaN], [1, 1]], "edges": [{"endpoints": [0, 1]}]}}}}'})
        add('malformed', 'actual has a BOM / trailing data', {'case': c},
            {'raw': '\ufeff{}' if c == SPEC_CASES[0] else '{"pattern": {}} x'})
    # error.txt vs spec
    errs = sorted(ERRORS)
    for i, c in enumerate(SPEC_CASES[::5]):
        add('errors', 'expected spec, actual error', {'case': c}, {'error': 'RuntimeError: boom\nmore\n'})
        add('errors', 'expected spec, actual empty error', {'case': c}, {'error': '  \n'})
        e = errs[i % len(errs)]
        add('errors', 'expected error, actual spec', {'error': ERRORS[e]}, {'case': c})
        add('errors', 'expected error, actual both', {'error': ERRORS[e]}, {'case': c, 'also_error': 'x'})
        add('errors', 'expected spec, actual nothing', {'case': c}, {'empty': True})
        add('errors', 'expected error, actual nothing', {'error': ERRORS[e]}, {'empty': True})
        add('errors', 'expected spec, actual directory missing', {'case': c}, {'missing': True})
    for e in errs:
        add('errors', 'expected error, actual other error', {'error': ERRORS[e]}, {'error': 'ValueError: other'})
    # 3. cross-case pairs
    by_names = {}
    for c in SPEC_CASES:
        by_names.setdefault(tuple(sorted(SPECS[c]['pattern']['panels'])), []).append(c)
    for group in by_names.values():
        for a, b in zip(group, group[1:]):
            add('cross', 'same panel names', {'case': a}, {'case': b})
            add('cross', 'same panel names', {'case': b}, {'case': a})
    rng = random.Random(7)
    for _ in range(40):
        a, b = rng.sample(SPEC_CASES, 2)
        add('cross', 'random pair', {'case': a}, {'case': b})
    for a, b in zip(CHAOTIC_CASES, CHAOTIC_CASES[1:]):
        add('cross', 'chaotic pair', {'case': a}, {'case': b})
    for k, p in enumerate(pairs):
        p['id'] = f'p{k:04d}'
    return pairs


# ------------------------------------------------------------------ layout + verdicts
def materialise(root, p):
    for side, key in (('exp', 'exp'), ('act', 'act')):
        src = p[key]
        d = os.path.join(root, side, p['id'])
        if src.get('missing'):
            continue
        os.makedirs(d, exist_ok=True)
        if 'case' in src:
            sp = apply(SPECS[src['case']], src.get('patch', []))
            with open(os.path.join(d, 'specification.json'), 'w') as f:
                json.dump(sp, f)
            if 'also_error' in src:
                with open(os.path.join(d, 'error.txt'), 'w') as f:
                    f.write(src['also_error'])
        elif 'error' in src:
            with open(os.path.join(d, 'error.txt'), 'w') as f:
                f.write(src['error'])
        elif 'raw' in src:
            with open(os.path.join(d, 'specification.json'), 'w') as f:
                f.write(src['raw'])


def opts_key(o):
    return '_'.join(f'{k}-{v}' for k, v in sorted(o.items())) or 'default'


def verdict(root, p):
    o = p['opts']
    C._set_chaos_params(o.get('outline', 2.8), o.get('ratio', 0.065), o.get('sliver', 1.0),
                        o.get('stitch', 3.3), o.get('seam_ratio', 0.0025), o.get('gain', 3.5))
    kw = dict(step=C.SAMPLE_STEP, convention=o.get('euler', 'XYZ'), strict=o.get('strict', False),
              chaotic_rule=o.get('chaotic_rule', True))
    info = {}
    try:
        ok, dev, reasons, notes = C.compare_case(os.path.join(root, 'exp', p['id']),
                                                 os.path.join(root, 'act', p['id']),
                                                 o.get('tol', C.DEFAULT_TOL), info=info, **kw)
    except Exception as ex:
        ok, dev, reasons, notes = False, math.inf, [f'comparator error: {type(ex).__name__}: {ex}'], []
    norm = lambda s: s.replace(root, '{ROOT}')  # noqa: E731
    reasons, notes = [norm(r) for r in reasons], [norm(n) for n in notes]
    return dict(ok=bool(ok), star=bool(ok and info.get('rule_needed')),
                max_dev=None if dev == math.inf else dev,
                n_reasons=len(reasons), reasons=reasons[:3], n_notes=len(notes),
                text_hash=fnv1a('\x1f'.join(reasons) + '\x1e' + '\x1f'.join(notes)))


def fnv1a(text):
    """64-bit FNV-1a of the UTF-8 text, as hex (the test recomputes it)."""
    h = 0xcbf29ce484222325
    for b in text.encode('utf-8', 'surrogatepass'):
        h = ((h ^ b) * 0x100000001b3) & 0xffffffffffffffff
    return f'{h:016x}'


def main():
    pairs = build_pairs()
    if os.path.isdir(OUT):
        shutil.rmtree(OUT)
    for p in pairs:
        root = os.path.join(OUT, opts_key(p['opts']))
        materialise(root, p)
    for k, p in enumerate(pairs):
        root = os.path.join(OUT, opts_key(p['opts']))
        p['python'] = verdict(root, p)
        if k % 50 == 0:
            print(f'{k}/{len(pairs)}', file=sys.stderr)
    with open(CORPUS, 'w') as f:
        f.write('{"pairs": [\n')
        f.write(',\n'.join(json.dumps(p, separators=(',', ':')) for p in pairs))
        f.write('\n]}\n')
    cats = {}
    for p in pairs:
        c = cats.setdefault(p['cat'], [0, 0, 0])
        c[0] += 1
        c[1] += p['python']['ok']
        c[2] += p['python']['star']
    for c, (n, ok, star) in cats.items():
        print(f'{c}: {n} pairs, {ok} pass ({star} PASS*)')


if __name__ == '__main__':
    main()
