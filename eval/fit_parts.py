#!/usr/bin/python3
"""Fits the drum part model and the onset model (src/tactus/analysis/part_model.hpp) and measures
drum part accuracy inside music, on the music corpus (eval/music_corpus.py).

usage: eval/fit_parts.py BUILD_DIR [--work DIR] [--preset music] [--write-header]

Runs `tactus onsets --part-features` on every mix of the corpus's four parts (the corpus is
built in --work once and cached), matches its onsets to the drum hits as eval/music.py does
(+-50 ms, one-to-one; where hits coincide the first of kick, snare, hat) and prints, for the
parts.drum_min that keeps each of KEEPS of the tuning parts' drum hits, per bed level and part,
the share of drum hits the onset model keeps and of the other onsets (over a bed, the bed's
own) it names other; then, per bed level and part, the share of matched onsets whose part
tactus names right (kick / snare / hat / all): as tactus printed it (and per kit, with the
drums alone), and as the model fitted here would; then the same model fitted with two of the
tuning kits left out at a time, measured on those two (the two tuning parts, Sonic Pi's kits and
the recorded tuning kits, are what the model may be chosen on; the held-out parts give the
figures).

The model: multinomial logistic regression (kick, snare, hat) on a hit's own features and their
pairwise products (quadratic terms) and, linearly, its features less the song's recent hits' mean
(PartFeatures::kRecentHits; 3, 4, 6 and 8 measured with two Sonic Pi kits left out: 0.720-0.724
over the bed levels, against 0.706 without them; 2 to 8 with two of both tuning parts' kits left
out: 0.790-0.796), standardised, L2-penalised (L2 from 1e-3, 1e-2,
3e-2 and 1e-1 with two tuning kits left out), classes weighted to equal total weight,
fitted on the onsets matched to a drum hit in the tuning parts only (every bed level), in their
mixes and their isolated hits (without these a kick or a snare played alone, whose numbers equal
their recent mean, was read as the other more often: 0.938 against 1.000 right on Sonic Pi's kits
alone, 0.875 against 0.938 on the General MIDI kits). Onsets no
hit matches (the bed's own) are left out: with them as a fourth class, or with the old rule's "no
drum" gate (little added above 6 kHz), drums were called "other" too often inside music. Those
are the onset model's instead (analysis/onset_rises.hpp): logistic regression of drum hit against
any other onset, on the onset's rises and their pairwise products, standardised, the two classes
weighted alike, fitted on every onset of the tuning parts whose rises were read; parts.drum_min
sets its threshold. --write-header writes both models' coefficients to
src/tactus/analysis/part_model.hpp; rebuild, then run again to see tactus's own figures agree.
"""
import argparse
import collections
import concurrent.futures
import pathlib
import sys

import mir_eval
import numpy as np
import scipy.optimize

import music
import music_corpus
from shared import onset_rows, read_hits

CLASSES = ("kick", "snare", "hat")
RISES = 10  # OnsetRises::kCount: the last numbers of each --part-features row
KEEPS = (0.99, 0.98, 0.95, 0.9)  # shares of the tuning parts' drum hits a drum_min keeps
TUNING = ("tuning", "recorded-tuning")
L2 = 1e-2  # per example, on the standardised weights
HEADER = pathlib.Path(__file__).resolve().parent.parent / "src/tactus/analysis/part_model.hpp"


def onsets_with_features(tactus, wav, preset):
    """(times, tactus's parts, part features, onset rises: one row per onset, nan where not
    read)."""
    rows = onset_rows(tactus, wav, preset, "--part-features")
    times = np.array([float(r[0]) for r in rows])
    numbers = np.array([[float(v) for v in r[4:]] for r in rows]).reshape(len(rows), -1)
    return times, [r[3] for r in rows], numbers[:, :-RISES], numbers[:, -RISES:]


def read_mix(tactus, directory, entry, preset):
    """One mix's onsets: features, true class (other where no hit matches), matched flag and
    tactus's own part."""
    reference, parts = music.truth(read_hits(directory / f"{entry['name']}.hits.csv"))
    times, labels, features, rises = onsets_with_features(
        tactus, directory / f"{entry['name']}.wav", preset)
    truth = ["other"] * len(times)
    matched = np.zeros(len(times), bool)
    for i, j in mir_eval.util.match_events(reference, times, music.TOLERANCE_S):
        truth[j], matched[j] = parts[i], True
    return {"row": ("instrument" in entry, entry["bed_db"]), "kit": entry["kit"],
            "features": features, "rises": rises, "truth": truth, "matched": matched,
            "tactus": labels}


def read_part(tactus, work, part, preset, jobs):
    """Every mix of `part` and every file of its isolated hits (a kit's kick alone or snare alone:
    a drum played by itself, as into an instrument's own actuator)."""
    directory = pathlib.Path(work) / part
    manifest = music_corpus.build(work, pathlib.Path(work) / "gm-samples", (part,), jobs)[part]
    with concurrent.futures.ThreadPoolExecutor(jobs) as pool:
        return list(pool.map(lambda e: read_mix(tactus, directory, e, preset),
                             manifest["mixes"] + manifest["gain"]))


# The table's rows: (isolated hits, bed level).
ROWS = [(False, level) for level in music.LEVELS] + [(True, level) for level in music.GAIN_LEVELS]


def row_label(row):
    isolated, level = row
    return ("isolated kick or snare, " if isolated else "") + music.level_label(level)


def counted(mix, labels):
    return music.count_parts(mix["truth"], labels, [(k, k) for k in np.flatnonzero(mix["matched"])])


def accuracy(mixes, predict):
    """{row: music.pooled_accuracy} with each mix's labels from predict(mix)."""
    by_row = collections.defaultdict(list)
    for mix in mixes:
        by_row[mix["row"]].append(counted(mix, predict(mix)))
    return {row: music.pooled_accuracy(by_row[row]) for row in ROWS}


def quadratic(x):
    """The numbers, then their pairwise products x_i x_j, i <= j."""
    i, j = np.triu_indices(x.shape[1])
    return np.hstack([x, x[:, i] * x[:, j]])


def expanded(x):
    """As part_model.hpp's reader: the hit's own numbers (the first half of each row,
    PartFeatures::kOwn) and their pairwise products, then the numbers relative to the recent
    hits (the second half)."""
    half = x.shape[1] // 2
    return np.hstack([quadratic(x[:, :half]), x[:, half:]])


def fit(x, y, k=len(CLASSES)):
    """(mean, scale, weights [class][feature], bias [class]) of the multinomial logistic model
    of k classes (y in 0 ... k - 1)."""
    mean, scale = x.mean(axis=0), x.std(axis=0) + 1e-9
    z = (x - mean) / scale
    n, d = z.shape
    counts = np.bincount(y, minlength=k)
    sample_weight = (n / (k * np.maximum(counts, 1)))[y]
    onehot = np.eye(k)[y]

    def loss(theta):
        w, b = theta[:k * d].reshape(k, d), theta[k * d:]
        logits = z @ w.T + b
        logits -= logits.max(axis=1, keepdims=True)
        p = np.exp(logits)
        p /= p.sum(axis=1, keepdims=True)
        value = -np.sum(sample_weight * np.log(p[np.arange(n), y] + 1e-300)) / n
        value += 0.5 * L2 * np.sum(w * w)
        g = (sample_weight[:, None] * (p - onehot)) / n
        return value, np.concatenate([(g.T @ z + L2 * w).ravel(), g.sum(axis=0)])

    theta = scipy.optimize.minimize(loss, np.zeros(k * d + k), jac=True, method="L-BFGS-B",
                                    options={"maxiter": 2000}).x
    return mean, scale, theta[:k * d].reshape(k, d), theta[k * d:]


def predictor(model):
    mean, scale, w, b = model

    def predict(mix):
        x = mix["features"]
        labels = ["other"] * len(x)
        if len(x):
            scores = ((expanded(x) - mean) / scale) @ w.T + b
            for i in np.flatnonzero(np.all(np.isfinite(x), axis=1)):
                labels[i] = CLASSES[int(np.argmax(scores[i]))]
        return labels
    return predict


def fit_onsets(mixes):
    """(mean, scale, weights, bias) of the onset model (analysis/onset_rises.hpp): logistic
    regression of a drum hit's onset (one matched to a hit) against any other on the rises and
    their pairwise products, the two classes weighted alike."""
    rises = np.concatenate([m["rises"] for m in mixes if len(m["rises"])])
    drum = np.concatenate([m["matched"] for m in mixes if len(m["rises"])])
    read = np.all(np.isfinite(rises), axis=1)
    mean, scale, w, b = fit(quadratic(rises[read]), drum[read].astype(int), 2)
    return mean, scale, w[1] - w[0], b[1] - b[0]


def drum_probability(model, rises):
    """The onset model's probability that each onset is a drum's (1 where it read nothing)."""
    mean, scale, weights, bias = model
    out = np.ones(len(rises))
    read = np.all(np.isfinite(rises), axis=1) if len(rises) else out.astype(bool)
    if read.any():
        out[read] = 1 / (1 + np.exp(-(((quadratic(rises[read]) - mean) / scale) @ weights + bias)))
    return out


def drum_min_keeping(model, mixes, keep):
    """The drum_min that keeps `keep` of the drum hits of `mixes`."""
    p = np.concatenate([drum_probability(model, m["rises"])[m["matched"]] for m in mixes
                        if len(m["rises"])])
    return float(np.quantile(p, 1 - keep))


def kept_and_dropped(mixes, model, drum_min):
    """{row: (share of the drum hits kept, share of the other onsets dropped, their count)}."""
    counts = collections.defaultdict(lambda: np.zeros(4))
    for mix in mixes:
        kept = drum_probability(model, mix["rises"]) >= drum_min
        counts[mix["row"]] += [np.sum(kept & mix["matched"]), np.sum(mix["matched"]),
                               np.sum(~kept & ~mix["matched"]), np.sum(~mix["matched"])]
    return {row: (c[0] / max(c[1], 1), c[2] / max(c[3], 1), int(c[3]))
            for row, c in counts.items()}


def onsets_table(data, model):
    """At a drum_min keeping each of KEEPS of the tuning parts' drum hits: per part of the corpus
    and bed level, the drum hits kept and the other onsets (over a bed, the bed's own) dropped."""
    tuning = [mix for part in TUNING for mix in data[part]]
    print("| drum_min (tuning drum hits kept) | bed | " +
          " | ".join(f"{p}: drum hits kept / others dropped (count)" for p in data) + " |")
    print("|---" * (len(data) + 2) + "|")
    for keep in KEEPS:
        drum_min = drum_min_keeping(model, tuning, keep)
        shares = {part: kept_and_dropped(mixes, model, drum_min) for part, mixes in data.items()}
        for level in music.LEVELS[1:]:
            row = (False, level)
            cells = [f"{shares[p][row][0]:.3f} / {shares[p][row][1]:.3f} ({shares[p][row][2]})"
                     for p in data]
            print(f"| {drum_min:.3f} ({keep:.2f}) | {music.level_label(level)} | " +
                  " | ".join(cells) + " |")


def training_set(mixes):
    """The expanded features and classes of the onsets matched to a hit, decided."""
    x = np.concatenate([m["features"][m["matched"]] for m in mixes if len(m["features"])])
    y = np.array([CLASSES.index(t) for m in mixes for t, hit in zip(m["truth"], m["matched"])
                  if hit])
    keep = np.all(np.isfinite(x), axis=1)
    return expanded(x[keep]), y[keep]


def floats(values):
    return ", ".join(f"{v:.9g}" for v in values)


def write_header(model, onsets, path=HEADER):
    mean, scale, w, b = model
    rows = "\n".join(f"    {{{floats(row)}}}," for row in w)
    onsets_mean, onsets_scale, onsets_weights, onsets_bias = onsets
    path.write_text(f"""// Generated by eval/fit_parts.py (--write-header): do not edit. The drum part model
// (read by analysis/hit_analysis.cpp), a multinomial logistic regression over
// analysis/part_features.hpp's numbers: a hit's own, their pairwise products, and its numbers
// relative to the recent hits; fitted on the tuning parts of the music corpus
// (eval/music_corpus.py); classes kick, snare, hat, in DrumPart's order. And the onset model
// (read by analysis/onset_rises.cpp): a logistic regression of a drum's onset against any other
// sound's over analysis/onset_rises.hpp's numbers and their pairwise products, fitted on every
// onset of the same parts.
#pragma once

#include <array>

#include "tactus/analysis/onset_rises.hpp"
#include "tactus/analysis/part_features.hpp"

namespace tactus::part_model {{

inline constexpr int kClasses = {len(CLASSES)};
// The own numbers, x_i x_j of them for i <= j, then the relative numbers.
inline constexpr int kTerms =
    PartFeatures::kOwn * (PartFeatures::kOwn + 3) / 2 + PartFeatures::kCount - PartFeatures::kOwn;
inline constexpr std::array<float, kTerms> kMean = {{{floats(mean)}}};
inline constexpr std::array<float, kTerms> kScale = {{{floats(scale)}}};
inline constexpr std::array<std::array<float, kTerms>, kClasses> kWeights = {{{{
{rows}
}}}};
inline constexpr std::array<float, kClasses> kBias = {{{floats(b)}}};

// The rises, then x_i x_j of them for i <= j.
inline constexpr int kDrumTerms = OnsetRises::kCount * (OnsetRises::kCount + 3) / 2;
inline constexpr std::array<float, kDrumTerms> kDrumMean = {{{floats(onsets_mean)}}};
inline constexpr std::array<float, kDrumTerms> kDrumScale = {{{floats(onsets_scale)}}};
inline constexpr std::array<float, kDrumTerms> kDrumWeights = {{{floats(onsets_weights)}}};
inline constexpr float kDrumBias = {onsets_bias:.9g};

}}  // namespace tactus::part_model
""")


def kits_left_out(mixes, kits_out=2):
    """{row: accuracy pooled over the folds}, each fold fitted without `kits_out` kits and
    measured on them."""
    kits = sorted({m["kit"] for m in mixes})
    counts = collections.defaultdict(list)
    for start in range(0, len(kits), kits_out):
        out = set(kits[start:start + kits_out])
        predict = predictor(fit(*training_set([m for m in mixes if m["kit"] not in out])))
        for mix in mixes:
            if mix["kit"] in out:
                counts[mix["row"]].append(counted(mix, predict(mix)))
    return {row: music.pooled_accuracy(counts[row]) for row in ROWS}


def kits_table(data):
    """Each kit's hits named right of those matched, kick / snare / hat, with the drums alone:
    where the part model's errors lie."""
    print("| part | kit | kick / snare / hat right, drums alone |")
    print("|---|---|---|")
    for part, mixes in data.items():
        kits = collections.defaultdict(list)
        for mix in mixes:
            if mix["row"] == (False, None):
                kits[mix["kit"]].append(counted(mix, mix["tactus"]))
        for kit, results in sorted(kits.items()):
            cells = [f"{sum(r[p][0] for r in results)}/{sum(r[p][1] for r in results)}"
                     for p in music.PRIORITY]
            print(f"| {part} | {kit} | {' / '.join(cells)} |")


def table(results):
    names = list(results)
    print("| bed | " + " | ".join(f"{n}: kick / snare / hat / all" for n in names) + " |")
    print("|---" * (len(names) + 1) + "|")
    for row in ROWS:
        cells = [" / ".join("-" if np.isnan(r[row][p]) else f"{r[row][p]:.3f}"
                            for p in music.PRIORITY + ("all",)) for r in results.values()]
        print(f"| {row_label(row)} | " + " | ".join(cells) + " |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("build_dir", type=pathlib.Path)
    parser.add_argument("--work", type=pathlib.Path, default=pathlib.Path("/tmp/tactus-music"))
    parser.add_argument("--preset", default="music")
    parser.add_argument("--write-header", action="store_true")
    parser.add_argument("--jobs", type=int, default=2)
    args = parser.parse_args()
    tactus = str(args.build_dir / "bin/tactus")
    data = {part: read_part(tactus, args.work, part, args.preset, args.jobs)
            for part in music.PARTS}
    tuning = [mix for part in TUNING for mix in data[part]]
    model, onsets = fit(*training_set(tuning)), fit_onsets(tuning)
    print("the onset model fitted now (tuning parts):")
    onsets_table(data, onsets)
    print("\ndrum part right, tactus as built:")
    table({part: accuracy(mixes, lambda m: m["tactus"]) for part, mixes in data.items()})
    print("\ndrum part right per kit, tactus as built:")
    kits_table(data)
    print("\nthe model fitted now (tuning parts):")
    table({part: accuracy(mixes, predictor(model)) for part, mixes in data.items()})
    print("\nfitted with two tuning kits left out, measured on them:")
    table({"tuning, kits left out": kits_left_out(tuning)})
    if args.write_header:
        write_header(model, onsets)
        print(f"\nwrote {HEADER}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
