"""Speed of the Python package against the CLI, on one thread.

    python python/benches/speed.py [--cli PATH]

1. Per design: a design file's text to ``specification.json`` text through
   ``garmentcode.build`` (the median of 7 runs per design, summarised over a fixed
   set of 300 designs: the first samples of seed 2026 on the five built-in bodies).
2. ``sample_dataset`` against ``garmentcode sample`` (the same 2,000 samples,
   ``--jobs 1``, into fresh folders): samples per second and their ratio.

Both must use the same build profile (a wheel from ``pip install ./python`` is a
release build: compare it with ``cargo build --release``'s CLI).
"""

import argparse
import os
import shutil
import statistics
import subprocess
import tempfile
import time

import garmentcode as gc


def design_set(folder):
    bodies = gc.Body.builtin()
    gc.sample_dataset(300, 2026, folder, bodies=bodies, jobs=1)
    out = []
    for name in sorted(n for n in os.listdir(folder) if n.startswith("rand_")):
        text = open(os.path.join(folder, name, "design_params.yaml")).read()
        body = gc.parse_yaml(open(os.path.join(folder, name, "body_measurements.yaml")).read())["body"]["body_sample"]
        out.append((text, gc.Body(body.removesuffix("_apart"))))
    return out


def per_design(designs, runs=7):
    medians = []
    for text, body in designs:
        times = []
        for _ in range(runs):
            start = time.perf_counter()
            gc.build(text, body, name="design").to_json()
            times.append(time.perf_counter() - start)
        medians.append(statistics.median(times))
    return medians


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cli", default=os.environ.get("GARMENTCODE_CLI") or shutil.which("garmentcode"))
    ap.add_argument("--n", type=int, default=2000)
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        designs = design_set(os.path.join(tmp, "set"))
        t = sorted(per_design(designs))
        print(f"build per design ({len(t)} designs): median {1e3 * statistics.median(t):.4f} ms, mean {1e3 * statistics.mean(t):.4f} ms, p90 {1e3 * t[int(0.9 * (len(t) - 1))]:.4f} ms")
        start = time.perf_counter()
        gc.sample_dataset(args.n, 1, os.path.join(tmp, "py"), jobs=1)
        py = args.n / (time.perf_counter() - start)
        print(f"sample_dataset: {py:.0f} samples/s")
        if args.cli:
            start = time.perf_counter()
            subprocess.run([args.cli, "sample", "--n", str(args.n), "--seed", "1", "--jobs", "1", "--out", os.path.join(tmp, "cli")], check=True, capture_output=True)
            cli = args.n / (time.perf_counter() - start)
            print(f"garmentcode sample: {cli:.0f} samples/s; Python / CLI = {py / cli:.3f}")


if __name__ == "__main__":
    main()
