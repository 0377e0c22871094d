#!/usr/bin/python3
"""Throughput of examples/python/dask_render.py on a 2-worker LocalCluster against
`tactus render -j 2` on the same folder.

usage: bench/dask_throughput.py BUILD_DIR [--files 4] [--runs 3]

The folder holds --files copies of bench/compare.py's 10-minute file (FLAC, cached in
BUILD_DIR/bench-compare). In turn, --runs times each: `tactus render DIR/*.flac -O OUT -j 2`
and `dask_render.py DIR -O OUT --workers 2` (the module must be importable: make build, or
PYTHONPATH=BUILD_DIR/python); the median wall time of each, as minutes of audio per second, and
for Dask also the time after its cluster is up (the script's own figure); the CPU time (user +
system) of each run, workers included.
"""
import argparse
import os
import pathlib
import re
import resource
import shutil
import statistics
import subprocess
import sys
import time

from compare import LOOPS, looped, work_dir

EXAMPLE = pathlib.Path(__file__).resolve().parents[1] / "examples" / "python" / "dask_render.py"


def children_cpu_s():
    """CPU seconds (user + system) of every finished descendant (the workers included)."""
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("build_dir", type=pathlib.Path)
    parser.add_argument("--files", type=int, default=4)
    parser.add_argument("--runs", type=int, default=3)
    args = parser.parse_args()
    cli = args.build_dir / "bin" / "tactus"
    work = work_dir(args.build_dir)
    flac = looped(work, LOOPS["10 min"])
    folder = work / "dask-in"
    shutil.rmtree(folder, ignore_errors=True)
    folder.mkdir()
    for i in range(args.files):
        os.link(flac, folder / f"amen-{i}.flac")
    minutes = args.files * float(subprocess.run(["soxi", "-D", str(flac)], capture_output=True,
                                                text=True, check=True).stdout) / 60
    out = work / "dask-out"
    walls = {"cli": [], "dask": [], "dask-after-start": []}
    cpus = {"cli": [], "dask": []}
    for _ in range(args.runs):
        shutil.rmtree(out, ignore_errors=True)
        start, cpu = time.perf_counter(), children_cpu_s()
        subprocess.run([str(cli), "render", *sorted(map(str, folder.glob("*.flac"))), "-O",
                        str(out), "-j", "2"], check=True, stderr=subprocess.DEVNULL)
        walls["cli"].append(time.perf_counter() - start)
        cpus["cli"].append(children_cpu_s() - cpu)
        shutil.rmtree(out)
        start, cpu = time.perf_counter(), children_cpu_s()
        done = subprocess.run([sys.executable, str(EXAMPLE), str(folder), "-O", str(out),
                               "--workers", "2"], check=True, capture_output=True, text=True)
        walls["dask"].append(time.perf_counter() - start)
        cpus["dask"].append(children_cpu_s() - cpu)
        walls["dask-after-start"].append(
            float(re.search(r"of audio in ([\d.]+) s", done.stderr)[1]))
    shutil.rmtree(out)
    shutil.rmtree(folder)
    print(f"{args.files} files, {minutes:.1f} min of audio; median of {args.runs} runs")
    for name, label in [("cli", "tactus render -j 2"), ("dask", "dask_render.py, 2 workers"),
                        ("dask-after-start", "  of which rendering (cluster up)")]:
        wall = statistics.median(walls[name])
        cpu = f"  cpu {statistics.median(cpus[name]):6.2f} s" if name in cpus else ""
        print(f"  {label:<34} wall {wall:6.2f} s  {minutes / wall:6.1f} min of audio per s{cpu}")


if __name__ == "__main__":
    sys.exit(main())
