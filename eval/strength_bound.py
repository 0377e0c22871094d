#!/usr/bin/python3
"""How well a hit's strength can be read from the power it adds, at best, inside music: the
bound the hit analysis (src/tactus/analysis/hit_analysis.hpp) works under.

usage: eval/strength_bound.py [--work DIR] [--bed -6] [--template-ms 12]

On the music corpus's isolated hits (eval/music_corpus.py: each kit's kick alone and snare alone,
9 hits 1 s apart at 0 to -24 dB, over a bed at --bed dB), without any detection: at each hit's
true time, the power a Hann spectrum (1.45 ms hop, as the onset detector's) gained over what was
sounding before the hit, the largest over the 25 ms after it, summed
  whole     over every bin up to 5.6 kHz (the analysis band), the 10 ms spectrum over its frame
            that ended 1 ms before the hit (as analysis/added_spectrum.hpp reads it);
  by part   the same over the hit's own part's band: below 150 Hz for kicks, 150 Hz-5.6 kHz
            for snares (the part known);
  strongest the same over whichever of below 150 Hz, 150 Hz-1 kHz and 1-5.6 kHz gained most;
  loudest   whole, each bin over its loudest of the frames of the 50 ms before, counting only the
            bins at least twice that (a bed's own swells left out), in the 23 ms spectrum;
  template  a separation that knows each hit's exact sound: the magnitude spectrum of the
            --template-ms from the hit in the mix fitted, by non-negative least squares up to
            5.6 kHz, as the bed's (as long, ending 2 ms before the hit) plus the hit's own
            spectrum shape (from the drum stem, scaled to unit norm); the reading is that shape's
            weight (a pulse must start within 10 ms: a longer span is what a pulse that grows
            once the hit is heard could follow);
  stem      whole, on the drum stem alone (no bed: the reading's own bound).
Prints Spearman's rho of hit gain -> that power per file, median and worst over the files, per
part of the corpus and instrument: what `gain -> felt peak rho` in eval/results.md could reach if
the pulse followed the added power exactly. The corpus is built in --work once (cached)."""
import argparse
import pathlib
import sys

import numpy as np
import scipy.optimize
import scipy.stats

import music
import music_corpus
from shared import read_hits, read_mono

WINDOW_S, HOP_S = 0.010, 0.00145
REFERENCE_GAP_S, LOOK_S = 0.001, 0.025
LOUDEST_WINDOW_S, LOUDEST_SPAN_S, LOUDEST_TIMES = 0.023, 0.050, 2.0
TOP_HZ, LOW_HZ, MID_HZ = 5600, 150, 1000
TEMPLATE_GAP_S = 0.002


def spectra(x, rate, window_s=WINDOW_S):
    """(power spectra of the Hann frames of x, each frame's end time s, bin frequencies Hz,
    window s)."""
    n, hop = int(rate * window_s), int(rate * HOP_S)
    starts = np.arange(0, len(x) - n, hop)
    frames = np.stack([x[s:s + n] for s in starts]) * np.hanning(n)
    power = np.abs(np.fft.rfft(frames, axis=1)) ** 2
    return power, (starts + n) / rate, np.fft.rfftfreq(n, 1 / rate), window_s


def added(power, ends, freqs, window_s, t, bands, span_s=0.0, times=1.0):
    """The largest power gained within `bands` ((low, high) Hz each) after time t, of the
    strongest band, over each bin's loudest of the frames that ended REFERENCE_GAP_S to
    REFERENCE_GAP_S + span_s before t (span 0: the last one), in the bins at least `times` that."""
    before = np.flatnonzero(ends <= t - REFERENCE_GAP_S)
    reference = power[before[ends[before] > t - REFERENCE_GAP_S - span_s]
                      if span_s > 0 else before[-1:]].max(axis=0)
    after = power[np.flatnonzero((ends > t) & (ends <= t + LOOK_S + window_s))]
    gained = np.where(after >= times * reference, after - reference, 0)
    return max(gained[:, (freqs >= low) & (freqs < high)].sum(axis=1).max() for low, high in bands)


def magnitude(x, rate, start_s, span_s):
    """The Hann-windowed magnitude spectrum up to TOP_HZ of the span_s from start_s."""
    segment = x[max(0, int(start_s * rate)):int((start_s + span_s) * rate)]
    size = 1 << (4 * len(segment) - 1).bit_length()  # zero-padded to 4x or more
    spectrum = np.abs(np.fft.rfft(segment * np.hanning(len(segment)), size))
    return spectrum[np.fft.rfftfreq(size, 1 / rate) <= TOP_HZ]


def template_weight(mix, stem, rate, t, span_s):
    """The weight of the hit's own spectrum shape in the mix's, beside the bed's just before."""
    shape = magnitude(stem, rate, t, span_s)
    shape /= np.linalg.norm(shape) + 1e-30
    bed = magnitude(mix, rate, t - TEMPLATE_GAP_S - span_s, span_s)
    (_, weight), _ = scipy.optimize.nnls(np.stack([bed, shape], axis=1),
                                         magnitude(mix, rate, t, span_s))
    return weight


def readings(entry, directory, template_s):
    """{reading: rho of gain -> added power} for one isolated-hit file."""
    hits = read_hits(directory / f"{entry['name']}.hits.csv")
    gains = [g for _, _, g in hits]
    own = [(0, LOW_HZ)] if entry["instrument"] == "kick" else [(LOW_HZ, TOP_HZ)]
    variants = {"whole": [(0, TOP_HZ)], "by part": own,
                "strongest": [(0, LOW_HZ), (LOW_HZ, MID_HZ), (MID_HZ, TOP_HZ)]}
    (mix_x, rate), (stem_x, _) = (read_mono(directory / f"{entry['name']}{suffix}.wav")
                                  for suffix in ("", ".drums"))
    mix = spectra(mix_x, rate)
    out = {name: scipy.stats.spearmanr(gains, [added(*mix, t, bands) for t, _, _ in hits])[0]
           for name, bands in variants.items()}
    fine = spectra(mix_x, rate, LOUDEST_WINDOW_S)
    out["loudest"] = scipy.stats.spearmanr(gains, [
        added(*fine, t, [(0, TOP_HZ)], LOUDEST_SPAN_S, LOUDEST_TIMES) for t, _, _ in hits])[0]
    out["template"] = scipy.stats.spearmanr(
        gains, [template_weight(mix_x, stem_x, rate, t, template_s) for t, _, _ in hits])[0]
    stem = spectra(stem_x, rate)
    out["stem"] = scipy.stats.spearmanr(gains, [added(*stem, t, [(0, TOP_HZ)])
                                                for t, _, _ in hits])[0]
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--work", type=pathlib.Path, default=pathlib.Path("/tmp/tactus-music"))
    parser.add_argument("--bed", type=int, default=-6, choices=music_corpus.GAIN_BED_LEVELS_DB)
    parser.add_argument("--template-ms", type=float, default=12.0)
    args = parser.parse_args()
    manifests = music_corpus.build(args.work, args.work / "gm-samples", music.PARTS, 2)
    print(f"isolated hits over a bed at {args.bed:+g} dB: rho of hit gain -> added power, "
          "median / worst over the files")
    names = ("whole", "by part", "strongest", "loudest", "template", "stem")
    print("| part | instrument | files | " + " | ".join(names) + " |")
    print("|---|---|---|" + "---|" * len(names))
    for part in music.PARTS:
        entries = [e for e in manifests[part]["gain"] if e["bed_db"] == args.bed]
        for instrument in ("kick", "snare"):
            rows = [readings(e, args.work / part, args.template_ms / 1000) for e in entries
                    if e["instrument"] == instrument]
            cells = [f"{np.median([r[k] for r in rows]):.2f} / {np.min([r[k] for r in rows]):.2f}"
                     for k in names]
            print(f"| {music.PART_NAMES[part]} | {instrument} | {len(rows)} | "
                  + " | ".join(cells) + " |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
