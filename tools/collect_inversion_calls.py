"""Collect test vectors for curve_match_tangents from the reference.

Monkeypatches (at runtime, without editing /work/ref) the reference's
`curve_match_tangents` and the `minimize` it uses, builds every reference case
design and a number of random designs with sleeves or hoods on the five
bodies, and logs every call: inputs (4 absolute control points, t0, t1,
target_len) and scipy's output (shift, final control points, fun, nit, nfev).

Usage: /work/refenv/bin/python collect.py OUT.json N_RANDOM SEED [WORKER NWORKERS]
"""
import sys, json, random, os, traceback, time
from copy import deepcopy
import numpy as np
import yaml

sys.path.insert(0, '/work/ref')
sys.path.insert(0, '/work/ref/assets/garment_programs')
import pygarment
from pygarment.garmentcode import operators as ops
from assets.garment_programs.meta_garment import MetaGarment
from assets.bodies.body_params import BodyParameters

CASES = '/work/shared/reference/cases'
BODIES = '/work/shared/reference/bodies'
BODY_FILES = sorted(f for f in os.listdir(BODIES) if f.endswith('.yaml'))

LOG = []          # all calls
CTX = {}          # current design context
_last_min = {}    # last scipy result from the patched minimize

_orig_cmt = ops.curve_match_tangents
_orig_min = ops.minimize


def _min_wrap(*args, **kw):
    res = _orig_min(*args, **kw)
    _last_min['res'] = res
    return res


def _cmt_wrap(curve, target_tan0, target_tan1, target_len=None,
              return_as_edge=False, verbose=False):
    cps = [[float(p.real), float(p.imag)] for p in curve.bpoints()]
    tl = curve.length() if target_len is None else target_len
    _last_min.clear()
    out = _orig_cmt(curve, target_tan0, target_tan1, target_len,
                    return_as_edge=False, verbose=verbose)
    res = _last_min['res']
    rec = dict(
        source=CTX.get('source'), body=CTX.get('body'),
        caller=_caller(),
        cps=cps,
        t0=[float(x) for x in np.asarray(target_tan0, float)],
        t1=[float(x) for x in np.asarray(target_tan1, float)],
        target_len=float(tl),
        ref_shift=[float(x) for x in res.x],
        ref_cps=[[float(a), float(b)] for a, b in out],
        ref_fun=float(res.fun), ref_nit=int(res.nit), ref_nfev=int(res.nfev),
        ref_success=bool(res.success),
    )
    LOG.append(rec)
    if return_as_edge:
        return pygarment.CurveEdge(start=out[0], end=out[-1],
                                   control_points=out[1:3], relative=False)
    return out


def _caller():
    import inspect
    for fr in inspect.stack()[2:6]:
        if fr.function in ('ArmholeCurve', '__init__'):
            return 'sleeve' if fr.function == 'ArmholeCurve' else 'hood'
    return 'other'


ops.minimize = _min_wrap
ops.curve_match_tangents = _cmt_wrap
pygarment.garmentcode.operators.curve_match_tangents = _cmt_wrap
try:
    pygarment.ops.curve_match_tangents = _cmt_wrap
except AttributeError:
    pass


def build(design, body_file):
    body = BodyParameters(os.path.join(BODIES, body_file))
    g = MetaGarment('g', body, design)
    g.assembly()


def has_calls(d):
    """True if the design would call curve_match_tangents (sleeves or a hood)."""
    if d['meta']['upper']['v'] is None:
        return False
    hood = d['collar']['component']['style']['v'] == 'Hood2Panels'
    sl = not d['sleeve']['sleeveless']['v']
    if d['left']['enable_asym']['v']:
        sl = sl or not d['left']['sleeve']['sleeveless']['v']
    return hood or sl


def main():
    out, n_rand, seed = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    worker, nworkers = (int(sys.argv[4]), int(sys.argv[5])) if len(sys.argv) > 5 else (0, 1)
    t_start = time.time()
    if worker == 0:
        for case in sorted(os.listdir(CASES)):
            with open(os.path.join(CASES, case, 'design.yaml')) as f:
                design = yaml.safe_load(f)['design']
            body = open(os.path.join(CASES, case, 'body.txt')).read().strip()
            CTX.update(source=case, body=body)
            try:
                build(design, body)
            except Exception as e:
                print(case, 'error', repr(e)[:100])
        print('cases done', len(LOG), time.time() - t_start, flush=True)
    random.seed(seed)
    sampler = pygarment.DesignSampler('/work/ref/assets/design_params/default.yaml')
    k = 0
    tries = 0
    while k < n_rand:
        d = sampler.randomize()
        tries += 1
        if not has_calls(d):
            continue
        idx = k
        k += 1
        if idx % nworkers != worker:
            continue
        body = BODY_FILES[idx % len(BODY_FILES)]
        CTX.update(source=f'random-{seed}-{idx}', body=body)
        try:
            build(deepcopy(d), body)
        except Exception as e:
            print(idx, 'error', repr(e)[:100])
        if idx % 20 == 0:
            print(idx, len(LOG), round(time.time() - t_start, 1), flush=True)
            with open(out, 'w') as f:
                json.dump(LOG, f)
    with open(out, 'w') as f:
        json.dump(LOG, f)
    print('done', len(LOG), 'tries', tries)


if __name__ == '__main__':
    main()
