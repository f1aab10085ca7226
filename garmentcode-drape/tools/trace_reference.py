"""Frame-by-frame figures of the reference's own simulator on a reference case folder.

Runs the reference's `Cloth` (GarmentCode's pygarment/meshgen/garment.py on its Warp fork,
built for CPU as shared/reference/drape/FORMAT.md says) from the case folder's files (box
mesh, orig_lens, segmentation, vertex labels, sim_props.yaml) on the mean_all body, calling
`Cloth.update` frame by frame, and prints after each frame:

    frame moving max_speed mean_speed lower_y contacts cpu_s [STATIC] [ALIAS]

moving: vertices whose L1 displacement over the frame exceeds the static threshold (0.03 cm);
speeds in cm/s; lower_y: mean y of the lower_interface vertices (cm); contacts: the frame's
body contacts (Warp's soft_contact_count); STATIC: the reference's own is_static says so;
ALIAS: its last_verts and current_verts share memory (on CPU they always do, which is why
its static check passes at the first frame it runs; see docs/drape.md, "Seventh session").
The same columns come from `drape_case` with DRAPE_STATS (stderr).

Usage (in the venv where the fork is installed):
    python trace_reference.py GARMENTCODE_DIR CASE_DIR OUT_DIR FRAMES [DUMP_FROM]
Positions of frames >= DUMP_FROM (up to 420, then every 20th) go to OUT_DIR/ref_FRAME.npy.
"""
import os
import sys
import time
import types
from pathlib import Path

import numpy as np
import yaml

gc_dir, case_dir, out = Path(sys.argv[1]).resolve(), Path(sys.argv[2]).resolve(), Path(sys.argv[3]).resolve()
frames = int(sys.argv[4])
dump_from = int(sys.argv[5]) if len(sys.argv) > 5 else frames
sys.path.insert(0, str(gc_dir))
os.chdir(gc_dir)
import warp as wp  # noqa: E402

wp.init()
from pygarment.meshgen.garment import Cloth  # noqa: E402
from pygarment.meshgen.sim_config import SimConfig  # noqa: E402

out.mkdir(parents=True, exist_ok=True)
case = case_dir.name
config = SimConfig(yaml.safe_load(open(case_dir / 'sim_props.yaml'))['sim']['config'])
body_dir = case_dir.parent.parent / 'bodies'
paths = types.SimpleNamespace(
    in_body_obj=body_dir / 'mean_all.obj',
    body_seg=gc_dir / 'assets/bodies/ggg_body_segmentation.json',
    in_body_mes=gc_dir / 'assets/bodies/mean_all.yaml',
    g_box_mesh=case_dir / f'{case}_boxmesh.obj',
    g_mesh_segmentation=case_dir / f'{case}_sim_segmentation.txt',
    g_orig_edge_len=case_dir / f'{case}_orig_lens.pickle',
    g_specs=case_dir / f'{case}_specification.json',
    g_vert_labels=case_dir / f'{case}_vertex_labels.yaml',
    use_smpl_seg=False,
)
garment = Cloth(case, config, paths)
lower = np.array(yaml.safe_load(open(paths.g_vert_labels)).get('lower_interface', [0]))
print('frame moving max_speed mean_speed lower_y contacts cpu_s', flush=True)
t0 = time.process_time()
last = np.array(garment.current_verts, copy=True)  # our own copy: the reference's is a view
for frame in range(frames):
    garment.frame = frame
    garment.update(frame)
    cur = np.array(garment.current_verts, copy=True)
    d = cur - last
    last = cur
    moving = int((np.abs(d).sum(axis=1) > config.static_threshold).sum())
    speed = np.linalg.norm(d, axis=1) * config.sim_fps
    contacts = int(garment.model.soft_contact_count.numpy()[0])
    checked = frame >= config.zero_gravity_steps and frame >= config.min_sim_steps
    flags = (' STATIC' if checked and garment.is_static()[0] else '') + (
        ' ALIAS' if np.shares_memory(garment.current_verts, garment.last_verts) else '')
    print(f'{frame} {moving} {speed.max():.4f} {speed.mean():.5f} {cur[lower, 1].mean():.4f} {contacts} '
          f'{time.process_time() - t0:.1f}{flags}', flush=True)
    if frame >= dump_from and (frame <= 420 or frame % 20 == 0):
        np.save(out / f'ref_{frame:05d}.npy', cur.astype(np.float32))
