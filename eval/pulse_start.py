#!/usr/bin/python3
"""What a drum hit's pulse can say in its first milliseconds: the pitch tactus gives it then, and
how much of the hit lies below 150 Hz by then.

usage: eval/pulse_start.py BUILD_DIR [--work DIR] [--preset music]

On the music corpus's isolated hits (eval/music_corpus.py: each kit's kick alone and snare alone,
9 hits 1 s apart at 0 to -24 dB, drums alone and over a bed at -12 and -6 dB):
  pulse Hz  the vibration frequency `tactus analyze` maps for the hit (its `frequency_hz`) AFTER_MS
            after the frame that decided its onset (an onset within +-20 ms of the hit), median
            over the kit's hits; printed as each kit's snare/kick, median and worst over the kits.
            The felt snare/kick of eval/results.md weighs the whole pulse by its felt energy,
            whose strongest part is its start.
  below 150 Hz  on the drum stem (no bed), the share of the loudest hit's energy below 150 Hz
            (4th-order Butterworth split) in its first AFTER_MS, smallest and largest over the
            kits: what any reading could know of a kick's body by then.
The corpus is built in --work once (cached)."""
import argparse
import concurrent.futures
import csv
import pathlib
import sys
import tempfile

import numpy as np
import scipy.signal

import music
import music_corpus
from shared import read_hits, read_mono, run

AFTER_MS = (3, 6, 12, 24)
MATCH_S = 0.02
SPLIT_HZ = 150


def pulse_hz(tactus, wav, hits, preset):
    """Per hit, the mapped frequency AFTER_MS after its onset was decided (nan: none)."""
    text = run([tactus, "analyze", wav, "--preset", preset]).stdout
    rows = list(csv.DictReader(line for line in text.splitlines() if not line.startswith("#")))
    times = np.array([float(r["time_s"]) for r in rows])
    hz = np.array([float(r["frequency_hz"]) for r in rows])
    decided = np.flatnonzero([r["onset"] == "1" for r in rows])
    starts = np.array([float(rows[k]["onset_time_s"]) for k in decided])
    out = []
    for t, _, _ in hits:
        near = decided[np.abs(starts - t) < MATCH_S] if len(decided) else decided
        out.append([np.interp(times[near[0]] + ms / 1000, times, hz) if len(near) else np.nan
                    for ms in AFTER_MS])
    return np.array(out)


def low_share(stem, hits):
    """The loudest hit's share of energy below SPLIT_HZ in its first AFTER_MS."""
    x, rate = read_mono(stem)
    low = scipy.signal.sosfilt(scipy.signal.butter(4, SPLIT_HZ, "low", fs=rate, output="sos"), x)
    high = x - low
    t = max(hits, key=lambda hit: hit[2])[0]
    shares = []
    for ms in AFTER_MS:
        span = slice(int(t * rate), int((t + ms / 1000) * rate))
        below, above = np.sum(low[span] ** 2), np.sum(high[span] ** 2)
        shares.append(below / (below + above + 1e-30))
    return shares


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("build_dir", type=pathlib.Path)
    parser.add_argument("--work", type=pathlib.Path, default=None)
    parser.add_argument("--preset", default="music")
    args = parser.parse_args()
    work = args.work or pathlib.Path(tempfile.mkdtemp(prefix="tactus-pulse-start-"))
    tactus = args.build_dir / "bin" / "tactus"
    manifests = music_corpus.build(work, work / "gm-samples", music.PARTS, 2)
    after = " / ".join(str(ms) for ms in AFTER_MS)
    print(f"isolated hits: snare/kick of the pulse's frequency {after} ms after the onset was "
          "decided, median / worst over the kits; the drum stem's share below 150 Hz in the "
          "loudest hit's first ms, smallest-largest over the kits")
    print("| part | bed | pulse snare/kick | kicks below 150 Hz | snares below 150 Hz |")
    print("|---|---|---|---|---|")
    for part in music.PARTS:
        directory = work / part
        entries = manifests[part]["gain"]
        hits = {e["name"]: read_hits(directory / f"{e['name']}.hits.csv") for e in entries}
        with concurrent.futures.ThreadPoolExecutor(2) as pool:
            hz = list(pool.map(lambda e: np.nanmedian(pulse_hz(
                tactus, directory / f"{e['name']}.wav", hits[e["name"]], args.preset), axis=0),
                entries))
        # The drums alone: each kit's stem is its file without a bed.
        shares = {i: [low_share(directory / f"{e['name']}.wav", hits[e["name"]])
                      for e in entries if e["bed_db"] is None and e["instrument"] == i]
                  for i in ("kick", "snare")}
        spans = [" / ".join(f"{lo:.2f}-{hi:.2f}"
                            for lo, hi in zip(np.min(shares[i], axis=0), np.max(shares[i], axis=0)))
                 for i in ("kick", "snare")]
        for level in music.GAIN_LEVELS:
            by_kit = {(e["kit"], e["instrument"]): h for e, h in zip(entries, hz)
                      if e["bed_db"] == level}
            ratios = np.array([by_kit[(kit, "snare")] / by_kit[(kit, "kick")]
                               for kit, instrument in by_kit if instrument == "kick"])
            cells = [f"{np.nanmedian(r):.2f} / {np.nanmin(r):.2f}" for r in ratios.T]
            alone = spans if level is None else ["", ""]
            print(f"| {music.PART_NAMES[part]} | {music.level_label(level)} | "
                  + ", ".join(cells) + f" | {alone[0]} | {alone[1]} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
