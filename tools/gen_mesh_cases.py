#!/usr/bin/env python3
"""Record the reference's box mesh of a pattern as a mesh test case.

usage: gen_mesh_cases.py SPEC.json OUT_DIR [--res 1.0]

Run with the reference's Python environment (numpy, svgpathtools, the CGAL bindings,
libigl; see shared/reference/drape/FORMAT.md) and its checkout in $GARMENTCODE_REF
(default /work/ref). OUT_DIR's name is the case name. It gets what the mesh tests and
the mesh judge (compare_mesh.py) read: `summary.json`, `boundary.json`,
`<name>_specification.json`, `<name>_vertex_labels.yaml`, `<name>_material.mtl`, and
`seam_lengths.json` (per stitch, the reference's rest length between consecutive
vertices along it, the seam edges the judge compares). With `--files` also the mesh
files (`<name>_boxmesh.obj`, `_sim_segmentation.txt`, `_orig_lens.pickle`) for the
judge, and `seams_detail.json` (each seam edge's rest length beside the 2D spacing of
its two sides). A pattern the reference fails to mesh gets `summary.json` with
`failed: true` and the error.
"""
import argparse
import io
import json
import os
import pickle
import shutil
import sys
import time
import traceback
from contextlib import redirect_stdout
from pathlib import Path

import numpy as np
import yaml

sys.path.insert(0, os.environ.get('GARMENTCODE_REF', '/work/ref'))
from pygarment.meshgen.boxmeshgen import BoxMesh  # noqa: E402
import svgpathtools as svgpath  # noqa: E402


def curve_kind(c):
    if isinstance(c, svgpath.Line):
        return 'line'
    if isinstance(c, svgpath.QuadraticBezier):
        return 'quadratic'
    if isinstance(c, svgpath.CubicBezier):
        return 'cubic'
    return 'circle'


def area2(P, F):
    a, b, c = P[F[:, 0]], P[F[:, 1]], P[F[:, 2]]
    return (b - a)[:, 0] * (c - a)[:, 1] - (b - a)[:, 1] * (c - a)[:, 0]


def glob_of(g, panel, loc):
    if loc < panel.n_stitches:
        return int(g.verts_loc_glob[(panel.panel_name, loc)])
    return int(loc + panel.glob_offset - panel.n_stitches)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('spec')
    ap.add_argument('out')
    ap.add_argument('--res', type=float, default=1.0)
    ap.add_argument('--files', action='store_true')
    args = ap.parse_args()
    out = Path(args.out)
    name = out.name
    out.mkdir(parents=True, exist_ok=True)
    spec_copy = out / f'{name}_specification.json'
    shutil.copyfile(args.spec, spec_copy)
    summary = dict(case=name, resolution=args.res, failed=False, error=None)
    log = io.StringIO()
    t0 = time.process_time()
    try:
        with redirect_stdout(log):
            g = BoxMesh(str(spec_copy), args.res)
            g.load()
    except BaseException as e:  # the reference's errors derive from BaseException
        summary.update(failed=True, error=f'{type(e).__name__}: {e}', traceback=traceback.format_exc())
        json.dump(summary, open(out / 'summary.json', 'w'), indent=1)
        print(f'{name}: reference failed: {summary["error"]}')
        return
    summary['timing'] = dict(cpu_meshgen_s=round(time.process_time() - t0, 4))
    with open(spec_copy, 'w') as f:
        json.dump(g.spec, f, indent=2)

    V = np.asarray(g.vertices, float)
    F = np.asarray(g.faces, int)
    n_stitch = sum(1 for s in g.stitch_segmentation if isinstance(s, list))
    panels, bpanels = {}, {}
    face_start = 0
    for pn in g.panelNames:
        p = g.panels[pn]
        P = np.asarray(p.panel_vertices, float)
        faces = []
        for f in p.panel_faces:
            gl = g._get_glob_ids(p, f)
            if len(set(gl)) == 3:
                faces.append(list(f))
        faces = np.asarray(faces, int).reshape(-1, 3)
        nb = len({v for e in p.edges for v in e.vertex_range})
        panels[pn] = dict(
            n_local_vertices=len(P), n_stitch_local_vertices=int(p.n_stitches), n_boundary_local_vertices=nb,
            n_interior_vertices=len(P) - nb, n_faces=len(faces),
            n_faces_dropped_after_stitching=len(p.panel_faces) - len(faces),
            area_2d=float(np.abs(area2(P, faces)).sum() / 2) if len(faces) else 0.0)
        R = np.asarray(g.panels[pn].rot_trans_panel([[1, 0], [0, 1], [0, 0]]), float)
        Rm = np.stack([R[0] - R[2], R[1] - R[2], np.cross(R[0] - R[2], R[1] - R[2])], axis=1)
        edges = []
        for ei, e in enumerate(p.edges):
            st = None
            for k, s in enumerate(g.stitches):
                if (s.panel_1, s.edge_1) == (pn, ei) or (s.panel_2, s.edge_2) == (pn, ei):
                    st = k
            edges.append(dict(idx=ei, n=len(e.vertex_range), n_edge_verts=int(e.n_edge_verts), stitch=st,
                              label=e.label or None, curve=curve_kind(e.curve), length=float(e.curve.length()),
                              local=[int(v) for v in e.vertex_range],
                              glob=[glob_of(g, p, v) for v in e.vertex_range],
                              xy=[[float(x) for x in P[v]] for v in e.vertex_range]))
        bpanels[pn] = dict(rotation_deg=[float(x) for x in p.rotation], translation=[float(x) for x in p.translation],
                           R=Rm.tolist(), norm=[float(x) for x in p.norm], n_stitches=int(p.n_stitches),
                           glob_offset=int(p.glob_offset), n_local=len(P),
                           face_range=[face_start, face_start + len(faces)], edges=edges)
        face_start += len(faces)
    counts = {f'{pn}:{e["idx"]}': e['n'] for pn in g.panelNames for e in bpanels[pn]['edges']}
    seg = [','.join(s) if isinstance(s, list) else s for s in g.stitch_segmentation]
    stitches, bstitches, seams, rest = {}, [], [], {}
    lens = {(int(a), int(b)): float(v) for (a, b), v in g.orig_lens.items()}
    for k, s in enumerate(g.stitches):
        r1, r2 = g._swap_stitch_ranges(s)
        p1, p2 = g.panels[s.panel_1], g.panels[s.panel_2]
        gl = [glob_of(g, p1, v) for v in r1]
        label = f'stitch_{k}'
        stitches[label] = dict(pairs=len(gl), n_distinct_vertices=len(set(gl)),
                               n_labeled_vertices=sum(1 for line in seg if label in line.split(',')),
                               side_1=[s.panel_1, s.edge_1], side_2=[s.panel_2, s.edge_2],
                               right_wrong=not s.swap, label=s.label)
        bstitches.append(dict(id=k, panel_1=s.panel_1, edge_1=s.edge_1, panel_2=s.panel_2, edge_2=s.edge_2,
                              swap=bool(s.swap), n=len(gl), label=s.label, glob=gl))
        for i in range(len(gl) - 1):
            key = (min(gl[i], gl[i + 1]), max(gl[i], gl[i + 1]))
            if key[0] == key[1] or key not in lens:
                continue
            d1 = float(np.linalg.norm(np.asarray(p1.panel_vertices[r1[i]]) - p1.panel_vertices[r1[i + 1]]))
            d2 = float(np.linalg.norm(np.asarray(p2.panel_vertices[r2[i]]) - p2.panel_vertices[r2[i + 1]]))
            seams.append(dict(stitch=k, pair=i, glob=list(key), length=lens[key], side_1=d1, side_2=d2))
        rest[label] = [lens.get((min(a, b), max(a, b))) if a != b else None for a, b in zip(gl[:-1], gl[1:])]
    # The vertex labels as the reference saves them (stitch labels appended as in save_vertex_labels).
    labels = {k: list(v) for k, v in g.vertex_labels.items()}
    for v, sl in enumerate(g.stitch_segmentation):
        if not isinstance(sl, list):
            break
        for st in sl:
            lab = g.stitches[int(st.split('_')[-1])].label
            if lab is not None:
                labels.setdefault(lab, []).append(v)
    summary.update(n_vertices=len(V), n_faces=len(F), n_stitch_vertices=n_stitch, n_panels=len(g.panelNames),
                   n_stitches=len(g.stitches), n_orig_lens=len(lens),
                   n_vertex_labels={k: len(v) for k, v in labels.items()}, panels=panels,
                   edge_vertex_counts=counts, stitches=stitches,
                   log=dict(n_impossible_gt_edge_msgs=log.getvalue().count('Impossible to set')))
    json.dump(summary, open(out / 'summary.json', 'w'), indent=1)
    json.dump(dict(resolution=args.res, panel_order=list(g.panelNames), panels=bpanels, stitches=bstitches,
                   n_vertices=len(V), n_faces=len(F), n_stitch_vertices=n_stitch),
              open(out / 'boundary.json', 'w'))
    json.dump(rest, open(out / 'seam_lengths.json', 'w'))
    if args.files:
        json.dump(seams, open(out / 'seams_detail.json', 'w'), indent=0)
    with open(out / f'{name}_vertex_labels.yaml', 'w') as f:
        yaml.dump({k: [int(x) for x in v] for k, v in labels.items()}, f, default_flow_style=False, sort_keys=False)
    with open(out / f'{name}_material.mtl', 'w') as f:
        f.write('newmtl panels_texture\nNs 0.000000\nKa 1.000000 1.000000 1.000000\nKs 0.000000 0.000000 0.000000\n'
                'Ke 0.000000 0.000000 0.000000\nNi 1.000000\nd 1.000000\nillum 1\n'
                f'map_Kd {name}_texture_fabric.png\n')
    if args.files:
        with open(out / f'{name}_boxmesh.obj', 'w') as f:
            for v in V:
                f.write('v {} {} {}\n'.format(*(repr(float(x)) for x in v)))
            for t in g.vertex_texture:
                f.write('vt {} {}\n'.format(*(repr(float(x)) for x in t)))
            for a, ta, b, tb, c, tc in g.faces_with_texture:
                f.write(f'f {a + 1}/{ta + 1} {b + 1}/{tb + 1} {c + 1}/{tc + 1}\n')
        with open(out / f'{name}_sim_segmentation.txt', 'w') as f:
            f.write(''.join(line + '\n' for line in seg))
        with open(out / f'{name}_orig_lens.pickle', 'wb') as f:
            pickle.dump(g.orig_lens, f)
    print(f'{name}: {len(V)} vertices, {len(F)} faces, {len(seams)} seam edges')


if __name__ == '__main__':
    main()
