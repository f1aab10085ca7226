#!/usr/bin/env python3
"""SIGGRAPH-logo side cut: bundled outline data and reference test data.

Run with the reference's Python environment (svgpathtools 1.8.0, numpy 1.26) and the
GarmentCode repository (MIT) checked out at REF (default /work/ref):

  gen_logo_data.py rust OUT.rs        writes the Rust data module with the outline
                                      segments exactly as svgpathtools parses
                                      assets/img/siggraph_logo_thick_connection.svg
  gen_logo_data.py check OUT.rs       re-reads the numbers of OUT.rs and checks them
                                      bit for bit against svgpathtools' parse
  gen_logo_data.py halves OUT.json    records the reference's split halves
                                      (EdgeSeqFactory.halfs_from_svg) for several
                                      target heights
  gen_logo_data.py cases DIR          for every DIR/case-*/ holding design.yaml and
                                      body.txt, builds the reference pattern and writes
                                      specification.json (or error.txt) and checks.json

Floats are written with Python's shortest round-trip repr, which Rust parses to the
same f64.
"""
import json
import os
import re
import sys

REF = os.environ.get('GARMENTCODE_REF', '/work/ref')
SVG = os.path.join(REF, 'assets/img/siggraph_logo_thick_connection.svg')
BODIES = '/work/shared/reference/bodies'
WIDTHS = [2.0, 4.5, 8.0, 8.7, 12.5, 17.0625, 17.325, 17.642887499999993,
          18.266167499999998, 18.8125875, 25.0, 40.0, 120.0]


def parse():
    import svgpathtools
    paths, _ = svgpathtools.svg2paths(SVG)
    out = []
    for p in paths:
        segs = []
        for s in p:
            kind = type(s).__name__
            assert kind in ('Line', 'CubicBezier'), kind
            segs.append((kind, [(z.real, z.imag) for z in s.bpoints()]))
        out.append(segs)
    return out


def rust(out_file):
    lines = [
        '//! Outline of the SIGGRAPH logo used by the `SIGGRAPH_logo` decorative side cut.',
        '//!',
        '//! Data only: the four closed outlines of `assets/img/siggraph_logo_thick_connection.svg`',
        '//! from the GarmentCode repository (MIT licence), as absolute segments in SVG',
        '//! coordinates (y down) exactly as svgpathtools 1.8.0 parses the file (relative',
        '//! commands resolved; the zero-length `h0` lines kept). Generated and checked bit',
        '//! for bit by `tools/gen_logo_data.py`.',
        '',
        'use garmentcode::parity::svgpath::Seg;',
        '',
        'const fn l(a: [f64; 2], b: [f64; 2]) -> Seg {',
        '    Seg::Line([a, b])',
        '}',
        '',
        'const fn c(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> Seg {',
        '    Seg::Cubic([a, b, c, d])',
        '}',
        '',
        '/// The outlines, in the file\'s order.',
        'pub const OUTLINES: [&[Seg]; 4] = [',
    ]

    def pt(p):
        return '[%r, %r]' % (float(p[0]), float(p[1]))

    for segs in parse():
        lines.append('    &[')
        for kind, pts in segs:
            f = 'l' if kind == 'Line' else 'c'
            lines.append('        %s(%s),' % (f, ', '.join(pt(p) for p in pts)))
        lines.append('    ],')
    lines.append('];')
    with open(out_file, 'w') as f:
        f.write('\n'.join(lines) + '\n')


def check(rs_file):
    text = open(rs_file).read()
    body = text[text.index('pub const OUTLINES'):]
    calls = re.findall(r'\b([lc])\(([^()]*)\)', body)
    ours = []
    for f, args in calls:
        nums = [float(x) for x in re.findall(r'-?[0-9][0-9.e+-]*', args)]
        ours.append(('Line' if f == 'l' else 'CubicBezier', nums))
    ref = [(k, [v for p in pts for v in p]) for segs in parse() for k, pts in segs]
    assert len(ours) == len(ref), (len(ours), len(ref))
    for (k1, a), (k2, b) in zip(ours, ref):
        assert k1 == k2 and len(a) == len(b), (k1, k2)
        for x, y in zip(a, b):
            assert x.hex() == y.hex(), (x, y)
    print(f'{len(ours)} segments match svgpathtools bit for bit')


def edge_json(e):
    from pygarment.garmentcode.edge import CurveEdge
    d = {'start': [float(v) for v in e.start], 'end': [float(v) for v in e.end]}
    if isinstance(e, CurveEdge):
        d['controls'] = [[float(v) for v in c] for c in e.control_points]
    return d


def halves(out_file):
    os.chdir(REF)
    sys.path.insert(0, REF)
    import pygarment as pyg
    out = []
    for w in WIDTHS:
        left, right = pyg.EdgeSeqFactory.halfs_from_svg(SVG, target_height=w)
        out.append({
            'width': w,
            'left': [[edge_json(e) for e in s] for s in left],
            'right': [[edge_json(e) for e in s] for s in right],
        })
    with open(out_file, 'w') as f:
        json.dump(out, f, indent=1)


def cases(root):
    os.chdir(REF)  # the garment program opens the SVG relative to the repository root
    sys.path.insert(0, '/work')
    sys.path.insert(0, REF)
    from refrun import build
    import pattern_sampler
    for name in sorted(os.listdir(root)):
        case = os.path.join(root, name)
        if not os.path.isfile(os.path.join(case, 'design.yaml')):
            continue
        body_name = open(os.path.join(case, 'body.txt')).read().strip()
        body_file = os.path.join(case, body_name)
        if not os.path.exists(body_file):
            body_file = os.path.join(BODIES, body_name)
        import yaml
        with open(os.path.join(case, 'design.yaml')) as f:
            design = yaml.safe_load(f)['design']
        checks = {}
        try:
            pattern_sampler.assert_param_combinations(design)
            checks['param_combinations'] = 'ok'
        except Exception as e:  # noqa: BLE001
            checks['param_combinations'] = f'{type(e).__name__}: {e}'
        for f in ('specification.json', 'error.txt'):
            if os.path.exists(os.path.join(case, f)):
                os.remove(os.path.join(case, f))
        try:
            g, pat = build(os.path.join(case, 'design.yaml'), body_file)
            if len(pat.panel_order()) == 0:
                raise RuntimeError('VisPattern::ERROR::Asked to save an empty pattern')
        except Exception as e:  # noqa: BLE001
            with open(os.path.join(case, 'error.txt'), 'w') as f:
                f.write(f'{type(e).__name__}: {e}\n')
            print(name, 'error', e)
            continue
        with open(os.path.join(case, 'specification.json'), 'w') as f:
            json.dump(pat.spec, f, indent=2)
        length = g.length()
        floor = g.body['height'] - g.body['head_l']
        checks.update({
            'total_length': length,
            'floor_length': floor,
            'total_length_ok': bool(length <= floor + 1),
            'self_intersecting': bool(g.is_self_intersecting()),
        })
        with open(os.path.join(case, 'checks.json'), 'w') as f:
            json.dump(checks, f, indent=2)
        panels = pat.spec['pattern']['panels']
        print(name, 'ok', {k: len(v['edges']) for k, v in panels.items() if 'skirt' in k})


if __name__ == '__main__':
    {'rust': rust, 'check': check, 'halves': halves, 'cases': cases}[sys.argv[1]](
        os.path.abspath(sys.argv[2]))
