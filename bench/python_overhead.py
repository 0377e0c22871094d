#!/usr/bin/python3
"""The Python module's overhead against the command line on the 10-minute file.

usage: bench/python_overhead.py BUILD_DIR [--runs 5]

The input is bench/compare.py's 10-minute file (the Amen break looped with sox, FLAC, cached in
BUILD_DIR/bench-compare). Timed in turn, median wall time of --runs runs each:
  cli        `tactus render 10min.flac -o out.wav` (decode, render, write; a new process)
  python     tactus.write(out, tactus.render(*tactus.read(10min.flac))) in this process: the
             same three steps through the module (the whole file in memory)
  cli-wav    `tactus render` of the decoded samples saved as a float WAV (decoding ~free)
  render     tactus.render(x, rate) alone, on those decoded samples (numpy in, numpy out)
plus the one-off `import tactus` in a fresh /usr/bin/python3. The module must be importable
(make build, or PYTHONPATH=BUILD_DIR/python).
"""
import argparse
import pathlib
import resource
import statistics
import subprocess
import sys
import time

from compare import LOOPS, looped, work_dir

import tactus


def cpu_s():
    """CPU seconds (user + system) of this process and of its finished children."""
    own = resource.getrusage(resource.RUSAGE_SELF)
    children = resource.getrusage(resource.RUSAGE_CHILDREN)
    return own.ru_utime + own.ru_stime + children.ru_utime + children.ru_stime


def timed(work):
    """(wall seconds, CPU seconds) of one run of work()."""
    wall, cpu = time.perf_counter(), cpu_s()
    work()
    return time.perf_counter() - wall, cpu_s() - cpu


def median_s(runs, work):
    return statistics.median(timed(work)[0] for _ in range(runs))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("build_dir", type=pathlib.Path)
    parser.add_argument("--runs", type=int, default=5)
    args = parser.parse_args()
    cli = args.build_dir / "bin" / "tactus"
    work = work_dir(args.build_dir)
    flac = looped(work, LOOPS["10 min"])
    out = work / "python-overhead.vibration.wav"

    x, rate = tactus.read(flac)
    seconds = len(x) / rate
    decoded = work / "amen-10min-decoded.wav"
    tactus.write(decoded, x, rate)  # float WAV, the same samples
    run = lambda *cmd: subprocess.run([str(c) for c in cmd], check=True,
                                      stderr=subprocess.DEVNULL)

    import_s = median_s(args.runs, lambda: run("/usr/bin/python3", "-c", "import tactus"))
    base_s = median_s(args.runs, lambda: run("/usr/bin/python3", "-c", "pass"))
    timings = {}
    for _ in range(args.runs):  # in turn, so a load change hits all alike
        for name, job in {
                "cli": lambda: run(cli, "render", flac, "-o", out, "--force"),
                "python": lambda: tactus.write(out, tactus.render(*tactus.read(flac)), rate),
                "cli-wav": lambda: run(cli, "render", decoded, "-o", out, "--force"),
                "render": lambda: tactus.render(x, rate)}.items():
            timings.setdefault(name, []).append(timed(job))
    wall = {name: statistics.median(w for w, _ in t) for name, t in timings.items()}
    cpu = {name: statistics.median(c for _, c in t) for name, t in timings.items()}
    print(f"10-minute file: {seconds / 60:.2f} min at {rate:g} Hz, {x.shape[1]} channels; "
          f"median of {args.runs} runs, wall and CPU (user + system) seconds")
    rows = [("cli", "tactus render FLAC -> WAV", "cli"),
            ("python", "read + render + write (module)", "cli"),
            ("cli-wav", "tactus render float WAV -> WAV", "cli-wav"),
            ("render", "tactus.render on the array", "cli-wav")]
    for name, label, against in rows:
        ratio = "" if name == against else (f"  {wall[name] / wall[against]:.2f}x / "
                                            f"{cpu[name] / cpu[against]:.2f}x {against}")
        print(f"  {name:<8} {label:<32} wall {wall[name]:.3f} s  cpu {cpu[name]:.3f} s  "
              f"({seconds / wall[name]:.0f}x real time){ratio}")
    print(f"  import tactus (fresh interpreter, less `python3 -c pass`): "
          f"{import_s - base_s:.3f} s")
    out.unlink(missing_ok=True)


if __name__ == "__main__":
    sys.exit(main())
