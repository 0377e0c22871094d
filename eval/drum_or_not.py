#!/usr/bin/python3
"""How well a drum hit can be told from the bed's own onsets (bass, chords, melody, voice) with
what is heard by the time tactus decides the onset: the bound a pulse that must start at once
(felt latency in music <= 5 / 10 ms) works under.

usage: eval/drum_or_not.py BUILD_DIR [--work DIR]

On every mix of the music corpus (eval/music_corpus.py) with a bed at -6, 0 and +6 dB: the onsets
of `tactus onsets` (start, decision time, strength), each a drum hit when one matches it within
+-50 ms (one-to-one, as eval/music.py), else the bed's. Read from the mix, causally: each band's
power rise in dB, from [start - 11 ms, start - 1 ms] to the last 3 ms before the decision (4th-order
Butterworth bands 30-150 Hz, 150-400 Hz, 400 Hz-1 kHz, 1-2.5 kHz, 2.5-6 kHz, 6-10 kHz, and the
whole signal), and tactus's strength. Prints the area under the ROC curve (drum against bed) of
each number, the largest band rise, and a logistic model on all of them (eval/fit_parts.py's fit,
two classes) fitted on the tuning parts; then, with its threshold set to keep a share of the tuning
part's drum hits, the share of drum hits kept and of the bed's onsets dropped, tuning and held
out. The corpus is built in --work once (cached).
"""
import argparse
import concurrent.futures
import pathlib
import sys

import mir_eval
import numpy as np
import scipy.signal
import scipy.stats

import fit_parts
import music
import music_corpus
from shared import onset_rows, read_hits, read_mono

BANDS_HZ = ((30, 150), (150, 400), (400, 1000), (1000, 2500), (2500, 6000), (6000, 10000))
NAMES = [f"rise {lo}-{hi} Hz" for lo, hi in BANDS_HZ] + ["rise, whole", "strength"]
BEFORE_S, GAP_S, LAST_S = 0.011, 0.001, 0.003
BEDS_DB = (-6, 0, 6)
TUNING, HELD_OUT = ("tuning", "recorded-tuning"), ("held-out", "recorded-held-out")


def rises(path, onsets):
    """[onset][band] power rise, dB, for (start s, decided s) pairs."""
    x, rate = read_mono(path)
    signals = [scipy.signal.sosfilt(scipy.signal.butter(4, band, "bandpass", fs=rate,
                                                        output="sos"), x) for band in BANDS_HZ]
    energy = [np.concatenate([[0.0], np.cumsum(s * s)]) for s in signals + [x]]

    def mean(e, a, b):
        a = min(max(int(a * rate), 0), len(x) - 1)
        b = min(max(int(b * rate), a + 1), len(x))
        return (e[b] - e[a]) / (b - a) + 1e-12
    return [[10 * np.log10(mean(e, max(start, decided - LAST_S), decided)
                           / mean(e, start - BEFORE_S, start - GAP_S)) for e in energy]
            for start, decided in onsets]


def mix_onsets(tactus, wav, hits_csv):
    """(numbers [onset][NAMES], drum hit or not [onset]) of one mix."""
    rows = onset_rows(tactus, wav, "music")
    onsets = [(float(r[0]), float(r[1])) for r in rows]
    reference, _ = music.truth(read_hits(hits_csv))
    drum = np.zeros(len(rows), int)
    for _, j in mir_eval.util.match_events(reference, np.array([o[0] for o in onsets]),
                                           music.TOLERANCE_S):
        drum[j] = 1
    numbers = [r + [float(row[2])] for r, row in zip(rises(wav, onsets), rows)]
    return np.array(numbers).reshape(-1, len(NAMES)), drum


def read(tactus, work, parts, manifests):
    jobs = [(work / part / f"{e['name']}.wav", work / part / f"{e['name']}.hits.csv")
            for part in parts for e in manifests[part]["mixes"] if e["bed_db"] in BEDS_DB]
    with concurrent.futures.ThreadPoolExecutor(2) as pool:
        read_mixes = list(pool.map(lambda job: mix_onsets(tactus, *job), jobs))
    return (np.concatenate([x for x, _ in read_mixes]),
            np.concatenate([y for _, y in read_mixes]))


def auc(drum, score):
    """The probability that a drum hit scores above a bed onset (ties half)."""
    ranks = scipy.stats.rankdata(score)
    hits, others = drum.sum(), (1 - drum).sum()
    return (ranks[drum == 1].sum() - hits * (hits + 1) / 2) / (hits * others)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("build_dir", type=pathlib.Path)
    parser.add_argument("--work", type=pathlib.Path, default=pathlib.Path("/tmp/tactus-music"))
    args = parser.parse_args()
    tactus = str(args.build_dir / "bin/tactus")
    manifests = music_corpus.build(args.work, args.work / "gm-samples", music.PARTS, 2)
    (xt, yt), (xh, yh) = (read(tactus, args.work, parts, manifests) for parts in (TUNING, HELD_OUT))
    print(f"onsets over a bed at {'/'.join(f'{b:+d}' for b in BEDS_DB)} dB: tuning {len(yt)} "
          f"({(yt == 0).sum()} the bed's), held out {len(yh)} ({(yh == 0).sum()} the bed's)")
    print("| number | AUC, tuning | AUC, held out |\n|---|---|---|")
    columns = [(name, xt[:, i], xh[:, i]) for i, name in enumerate(NAMES)]
    columns.append(("largest band rise", xt[:, :6].max(axis=1), xh[:, :6].max(axis=1)))
    mean, scale, w, b = fit_parts.fit(np.clip(xt, -30, 80), yt, 2)
    score = [((np.clip(x, -30, 80) - mean) / scale) @ (w[1] - w[0]) for x in (xt, xh)]
    columns.append(("logistic model on all (fitted on tuning)", *score))
    for name, tuning, held in columns:
        print(f"| {name} | {auc(yt, tuning):.3f} | {auc(yh, held):.3f} |")
    print("\n| drum hits kept, tuning | held out | bed onsets dropped, tuning | held out |\n"
          "|---|---|---|---|")
    for keep in (0.99, 0.97, 0.95):
        threshold = np.quantile(score[0][yt == 1], 1 - keep)
        print(f"| {keep:.2f} | {np.mean(score[1][yh == 1] >= threshold):.3f} | "
              f"{np.mean(score[0][yt == 0] < threshold):.3f} | "
              f"{np.mean(score[1][yh == 0] < threshold):.3f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
