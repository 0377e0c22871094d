#!/usr/bin/python3
"""Times `tactus render` and `tactus onsets` against `aubioonset`, and `tactus render` against the
I/O floor (`sox` converting the same file to a float WAV: decoding and writing alone), on the
same long real recording, in one run.

usage: bench/compare.py BUILD_DIR [--out bench/results.md] [--runs 7] [--long-runs 3]

The input is Sonic Pi's Amen break (loop_amen_full.flac, 44.1 kHz stereo) looped with sox to
10 and to 60 minutes, kept as FLAC: a real compressed file that both tools decode themselves
(cached in BUILD_DIR/bench-compare). `tactus render` runs the whole pipeline (analysis,
mapping, synthesis, post-processing, float WAV written); `tactus onsets` runs its onset
detection alone, the same job as aubioonset, which runs its default onset method (hfc) with hop
256 and every other parameter stated; both write onset times to a file. The four run in turn,
so a load change on the machine hits all alike; the script prints each one's median wall time,
tactus's ratio to aubioonset, x real time, and peak RSS (GNU time's maximum resident set).
"""
import argparse
import datetime
import os
import pathlib
import platform
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

import soundfile

AMEN = pathlib.Path("/usr/share/sonic-pi/samples/loop_amen_full.flac")


# The I/O floor of a render: the same file decoded and written as a float WAV, nothing else.
def sox_floor(audio, out):
    return ["sox", str(audio), "-e", "floating-point", "-b", "32", str(out)]


# aubioonset's defaults, stated: method hfc ("default"), buffer 512, hop 256, threshold 0.3,
# minioi 12 ms, silence -90 dB, the file's own sample rate.
AUBIO_ARGS = ["-O", "hfc", "-B", "512", "-H", "256", "-t", "0.3", "-M", "0.012", "-s", "-90",
              "-r", "0"]
# 1 + repeats copies of the 6.86 s loop: 88 copies = 10.06 min, 525 copies = 60.0 min.
LOOPS = {"10 min": 87, "60 min": 524}


def work_dir(build_dir):
    """The benchmarks' cache of looped inputs and outputs, BUILD_DIR/bench-compare."""
    work = build_dir / "bench-compare"
    work.mkdir(parents=True, exist_ok=True)
    return work


def looped(work, repeats):
    path = work / f"amen-x{repeats + 1}.flac"
    if not path.exists():
        partial = path.with_suffix(".partial.flac")
        subprocess.run(["sox", str(AMEN), str(partial), "repeat", str(repeats)], check=True)
        partial.rename(path)
    return path


def timed(cmd, stdout=subprocess.DEVNULL):
    """Wall seconds, CPU seconds (user + system) and peak RSS (MiB) of one run of `cmd`; exits
    with its error if it fails. The peak RSS is GNU time's: a child forked from this Python
    process would report Python's own pages as its peak (ru_maxrss counts the image it was
    forked from), so `time` forks it from its own small image instead."""
    with tempfile.TemporaryFile() as stderr, tempfile.NamedTemporaryFile("r") as rss:
        start = time.perf_counter()
        process = subprocess.Popen(["/usr/bin/time", "-f", "%M", "-o", rss.name] + cmd,
                                   stdout=stdout, stderr=stderr)
        _, status, usage = os.wait4(process.pid, 0)
        wall_s = time.perf_counter() - start
        process.returncode = os.waitstatus_to_exitcode(status)
        if process.returncode != 0:
            stderr.seek(0)
            sys.exit(f"bench/compare.py: {' '.join(cmd)} failed ({process.returncode}): "
                     f"{stderr.read().decode(errors='replace').strip()}")
        peak_kib = int(rss.read().split()[-1])
    return wall_s, usage.ru_utime + usage.ru_stime, peak_kib / 1024.0


def measure(tactus, audio, work, runs):
    vibration = work / "out.vibration.wav"
    onsets = work / "out.onsets.txt"
    floor = work / "out.sox.wav"
    # (wall s, CPU s, peak RSS MiB) per run
    runs_of = {"render": [], "onsets": [], "aubio": [], "sox": []}
    for _ in range(runs):
        runs_of["render"].append(timed([tactus, "render", str(audio), "-o", str(vibration)]))
        vibration.unlink()
        onsets.unlink(missing_ok=True)
        runs_of["onsets"].append(timed([tactus, "onsets", str(audio), "-o", str(onsets)]))
        with open(onsets, "w") as out:
            runs_of["aubio"].append(
                timed(["aubioonset", "-i", str(audio)] + AUBIO_ARGS, stdout=out))
        runs_of["sox"].append(timed(sox_floor(audio, floor)))
        floor.unlink()
    return runs_of


def machine():
    model = next((line.split(":", 1)[1].strip() for line in
                  pathlib.Path("/proc/cpuinfo").read_text().splitlines()
                  if line.startswith("model name")), platform.processor())
    load = " ".join(f"{x:.2f}" for x in os.getloadavg())
    return f"{model}, {os.cpu_count()} cores, load average at start {load}"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("build_dir", type=pathlib.Path)
    parser.add_argument("--out", type=pathlib.Path, default=None)
    parser.add_argument("--runs", type=int, default=7, help="runs of each tool, 10-min file")
    parser.add_argument("--long-runs", type=int, default=3, help="runs of each tool, 60-min file")
    args = parser.parse_args()
    if args.runs < 1 or args.long_runs < 1:
        sys.exit("bench/compare.py: --runs and --long-runs must be at least 1")

    tactus = str((args.build_dir / "bin/tactus").resolve())
    for tool in (tactus, "aubioonset", "sox", "/usr/bin/time"):
        if not shutil.which(tool):
            sys.exit(f"bench/compare.py: {tool}: not found")
    work = work_dir(args.build_dir)
    aubio_version = subprocess.run(["dpkg-query", "-W", "-f", "${Version}", "aubio-tools"],
                                   capture_output=True, text=True).stdout.strip()
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True).stdout.strip() or "unknown"

    lines = ["# tactus vs aubioonset: wall time and memory", "",
             f"Generated by `bench/compare.py` on {datetime.date.today()} (tactus {commit}); "
             f"{machine()}.", "",
             f"Input: `{AMEN.name}` (Sonic Pi, 44.1 kHz stereo FLAC) looped with `sox ... repeat "
             "N`, still FLAC, so both tools decode the same real compressed file.", "",
             "- tactus render: `tactus render FILE -o OUT.wav` (the default preset: analysis, "
             "mapping, synthesis, post-processing, float WAV written), the file decoded on a "
             "thread of its own and analysed on another, ahead of the engine's synthesis.",
             "- tactus onsets: `tactus onsets FILE -o OUT.txt` (onset detection alone, the "
             "onsets render triggers pulses on), the file decoded on a thread of its own.",
             f"- aubioonset (aubio-tools {aubio_version}): "
             f"`aubioonset -i FILE {' '.join(AUBIO_ARGS)}` (its default method and hop), onset "
             "times written to a file.",
             "- sox, the I/O floor: `sox FILE -e floating-point -b 32 OUT.wav` (decoding and "
             "writing alone).",
             "- Runs take turns: render, onsets, aubio, sox, render, ...; wall and CPU (user + "
             "system) times are medians; x real time is audio seconds per wall second; peak "
             "RSS is the largest over the runs, as GNU time reports it.", "",
             "| file | audio s | runs | tactus command | tactus wall s | aubio wall s | "
             "tactus / aubio wall | tactus CPU s | aubio CPU s | tactus / aubio CPU | "
             "tactus x real time | aubio x real time | tactus peak RSS MiB | "
             "aubio peak RSS MiB |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    runs_detail, floors = [], []
    for label, repeats in LOOPS.items():
        audio = looped(work, repeats)
        duration_s = soundfile.info(str(audio)).duration
        runs = args.runs if label == "10 min" else args.long_runs
        print(f"{label}: {audio} ({duration_s:.0f} s), {runs} runs of each tool ...",
              file=sys.stderr, flush=True)
        runs_of = measure(tactus, audio, work, runs)
        wall = {tool: statistics.median(r[0] for r in runs_of[tool]) for tool in runs_of}
        cpu = {tool: statistics.median(r[1] for r in runs_of[tool]) for tool in runs_of}
        rss = {tool: max(r[2] for r in runs_of[tool]) for tool in runs_of}
        a = wall["aubio"]
        for command in ("render", "onsets"):
            t = wall[command]
            lines.append(f"| {label} | {duration_s:.0f} | {runs} | {command} | {t:.2f} | "
                         f"{a:.2f} | {t / a:.2f} | {cpu[command]:.2f} | {cpu['aubio']:.2f} | "
                         f"{cpu[command] / cpu['aubio']:.2f} | {duration_s / t:.0f} | "
                         f"{duration_s / a:.0f} | {rss[command]:.1f} | {rss['aubio']:.1f} |")
        runs_detail += [f"- {label}, {tool}: " + ", ".join(f"{r[0]:.2f}" for r in runs_of[tool])
                        for tool in runs_of]
        floors.append(f"| {label} | {wall['render']:.2f} | {wall['sox']:.2f} | "
                      f"{wall['render'] / wall['sox']:.2f} | {rss['sox']:.1f} |")
    lines += ["", "`tactus render` against the I/O floor (medians of the same runs):", "",
              "| file | tactus render wall s | sox wall s | tactus / sox | sox peak RSS MiB |",
              "|---|---|---|---|---|"] + floors
    lines += ["", "Wall seconds of every run:", ""] + runs_detail + [""]
    report = "\n".join(lines)
    print(report)
    if args.out:
        # Sections after this report's own (other benchmarks' records) are kept.
        old = args.out.read_text() if args.out.exists() else ""
        at = old.find("\n# ")
        args.out.write_text(report + (old[at:] if at >= 0 else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
