#!/usr/bin/env python3
"""Renders a folder tree of audio files to vibration files on a Dask cluster (dask.distributed),
one file per task, through the tactus Python module: the files `tactus render -O` writes, for a
corpus larger than one machine.

    /usr/bin/python3 examples/python/dask_render.py IN_DIR -O OUT_DIR [--workers 2]
        [--scheduler tcp://host:8786] [--preset P] [--actuator A] [--set key=value ...]
        [--channels N] [--force]

IN_DIR/a/b/x.flac becomes OUT_DIR/a/b/x.vibration.wav: for every folder, what
`tactus render IN_DIR/a/b/* -O OUT_DIR/a/b` writes (byte for byte but the write time
libsndfile stamps in the PEAK chunk). Without --scheduler a
LocalCluster of --workers processes runs here; with it, the workers of that scheduler do (each
needs the tactus module and the input and output paths). Settings are checked and outputs
planned before any task runs: an output that exists (without --force) or that two inputs would
share is refused. Each output is written to a temporary file beside it and renamed when complete,
so a file that fails leaves nothing; the others are written, every failure is reported on stderr
as `tactus render` reports it, and the exit status is 1.
"""

import argparse
import pathlib
import sys
import time

import tactus

# What libsndfile reads (the command line tries any file; a tree holds other files too).
AUDIO_SUFFIXES = {".wav", ".flac", ".aif", ".aiff", ".ogg", ".oga", ".opus", ".mp3", ".w64",
                  ".caf", ".au", ".snd"}
SUFFIX = ".vibration.wav"  # tactus render -O's


def plan(in_dir, out_dir, force):
    """(input, output) for every audio file under in_dir; refuses what `tactus render` refuses."""
    jobs, seen = [], {}
    for path in sorted(p for p in in_dir.rglob("*") if p.is_file()):
        if path.suffix.lower() not in AUDIO_SUFFIXES:
            continue
        output = out_dir / path.parent.relative_to(in_dir) / (path.stem + SUFFIX)
        if output in seen:
            sys.exit(f"dask_render: error: {output}: both {seen[output]} and {path} would write it")
        if output.exists() and not force:
            sys.exit(f"dask_render: error: {output}: already exists (use --force to replace it)")
        seen[output] = path
        jobs.append((str(path), str(output)))
    if not jobs:
        sys.exit(f"dask_render: error: {in_dir}: no audio files")
    return jobs


def render_one(job, preset, actuator, channels, settings):
    """Runs on a worker: (input, output, seconds of audio, error message or None)."""
    import warnings

    import tactus as worker_tactus

    source, output = job
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # the actuator's warnings: reported once, up front
            x, rate = worker_tactus.read(source)
            y = worker_tactus.render(x, rate, preset=preset, actuator=actuator,
                                     actuators=channels, settings=settings)
        pathlib.Path(output).parent.mkdir(parents=True, exist_ok=True)
        worker_tactus.write(output, y, rate)
        return source, output, len(x) / rate, None
    except Exception as error:  # reported per file; the others go on
        return source, output, 0.0, str(error)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("input_dir", type=pathlib.Path)
    parser.add_argument("-O", "--output-dir", type=pathlib.Path, required=True)
    parser.add_argument("--scheduler", help="a Dask scheduler's address (default: a LocalCluster)")
    parser.add_argument("--workers", type=int, default=2, help="LocalCluster worker processes")
    parser.add_argument("--preset", default="music")
    parser.add_argument("--actuator")
    parser.add_argument("--set", dest="assignments", nargs="+", default=[], metavar="KEY=VALUE")
    parser.add_argument("--channels", type=int, default=1, help="identical actuator channels")
    parser.add_argument("--force", action="store_true", help="replace existing outputs")
    args = parser.parse_args()

    settings = {}
    for assignment in args.assignments:
        key, _, value = assignment.partition("=")
        settings[key] = value
    try:  # settings, preset and actuator checked here, once, with the command line's messages
        tactus.Engine(48000, preset=args.preset, actuator=args.actuator, actuators=args.channels,
                      settings=settings)
    except ValueError as error:
        sys.exit(f"dask_render: error: {error}")
    if not args.input_dir.is_dir():
        sys.exit(f"dask_render: error: {args.input_dir}: not a directory")
    jobs = plan(args.input_dir, args.output_dir, args.force)

    from dask.distributed import Client, LocalCluster, as_completed

    start = time.perf_counter()
    if args.scheduler:
        cluster, client = None, Client(args.scheduler)
    else:
        # Random ports and no dashboard: several runs on one machine never collide.
        cluster = LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True,
                               scheduler_port=0, dashboard_address=None)
        client = Client(cluster)
    try:
        workers = len(client.scheduler_info()["workers"])
        print(f"dask_render: {len(jobs)} files on {workers} workers", file=sys.stderr)
        ready = time.perf_counter()
        futures = client.map(render_one, jobs, preset=args.preset, actuator=args.actuator,
                             channels=args.channels, settings=settings, pure=False)
        failed, audio_s = [], 0.0
        for future in as_completed(futures):
            source, output, seconds, error = future.result()
            if error:
                failed.append((source, error))
                print(f"tactus: error: {error}", file=sys.stderr)
            else:
                audio_s += seconds
                print(f"{output}: {seconds:.2f} s", file=sys.stderr)
        done = time.perf_counter()
    finally:
        client.close()
        if cluster:
            cluster.close()
    print(f"dask_render: {len(jobs) - len(failed)} of {len(jobs)} files, {audio_s:.1f} s of audio "
          f"in {done - ready:.2f} s ({audio_s / (done - ready):.0f}x real time; "
          f"{ready - start:.2f} s to start the cluster)", file=sys.stderr)
    if failed:
        print(f"dask_render: {len(failed)} of {len(jobs)} files failed, the others were written",
              file=sys.stderr)
        for _, error in failed:
            print(f"  {error}", file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main()
