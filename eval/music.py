"""Measures tactus on drums inside full music mixes (eval/music_corpus.py), the tuning part and the
held-out part side by side.

- Onsets: F, precision and recall at +-50 ms (mir_eval, one-to-one, mean over files) of
  `tactus onsets` (its first column) and of aubioonset mkl and specflux against the drum hits'
  distinct times, per bed level. Every onset the bed causes counts against precision, so recall
  (drum hits that are detected) is the headline.
- Felt pulses: a drum hit gives a felt pulse when the felt render (eval/felt.py, its envelope: the
  magnitude of the analytic signal, so a low carrier's zero crossings do not count as quiet) has
  its largest value over [hit, hit + 60 ms] inside that window (a local peak, not the rise into
  the next one) at least 6 dB above its largest value over the 10 ms before the hit, and a
  `tactus onsets` onset is matched to the hit one-to-one within +-50 ms.
- Isolated hits over music (kick alone and snare alone, 0 to -24 dB, over a bed at -12 and -6 dB
  re the loudest hit, and without bed): Spearman's rho of hit gain -> felt pulse peak, the felt
  peak over [hit, hit + 80 ms] with nothing subtracted, so the bed's own vibration under a soft
  hit lowers rho; the felt snare/kick ratio of the median pulse frequencies (felt.centroid_hz over
  felt.PULSE_WINDOW_S, as evaluate.py's per-kit table, bed included); and the latency onset ->
  felt output at half its pulse peak (felt.half_peak_latency_s), over the hits that give a
  distinct pulse as above (the others' half peak would be the bed's), their count given, and
  the same from the hit's own sound reaching half its peak (its drum stem, |x| over the same
  window): a recorded kick's beater and body take up to 16 ms to rise from its first sample, a
  wait no causal analysis can shorten, so this is what tactus adds; and
  Spearman's rho of hit gain -> the strength `tactus onsets` prints for the hit's onset (a hit
  without one lowest): the hit's own reading, apart from the bed's pulses; and the share of the
  hits whose felt peak stands 6 dB over the bed's own (the bed stem rendered alone, the same
  window), the hits whose order the bed's pulses do not decide.
- Drum part: when `tactus onsets` prints a 4th column (kick, snare, hat or other), the share of
  its onsets matched one-to-one to a hit within +-50 ms whose part is the hit's, per part and
  overall. Where hits coincide the true part is the first of kick, snare, hat among them. And
  the onsets no hit matches, by the part they are named: over a bed, the bed's own onsets, which
  a drums-only mapping silences only when they are named other (parts.drum_min).
"""
import collections
import concurrent.futures
import pathlib
import statistics

import mir_eval
import numpy as np
import scipy.signal
import scipy.stats
import soundfile

import felt
import music_corpus
from shared import AUBIO_ARGS, onset_rows, read_hits, read_mono, run

TOLERANCE_S = 0.05
PULSE_S = 0.06  # a hit's felt pulse is looked for over this long after it
BEFORE_S = 0.01  # against the felt level over this long before it
DISTINCT_DB = 6.0
ISOLATED_PULSE_S = 0.08
ABOVE_BED_DB = 6.0  # an isolated hit's felt peak over the bed's own, to stand out of it
STRENGTH_MATCH_S = 0.02  # an isolated hit's onset, for its strength
PRIORITY = ("kick", "snare", "hat")
NAMED = PRIORITY + ("other",)  # the parts `tactus onsets` names
DETECTORS = ("tactus", "aubio mkl", "aubio specflux")
LEVELS = (None,) + music_corpus.BED_LEVELS_DB
GAIN_LEVELS = (None,) + music_corpus.GAIN_BED_LEVELS_DB
PART_NAMES = {"tuning": "tuning (Sonic Pi kits, FluidR3 bed)",
              "held-out": "held out (GM kits, TimGM6mb and MuseScore beds)",
              "recorded-tuning": "recorded kits, tuning (Hydrogen, FluidR3 bed)",
              "recorded-held-out": "recorded kits, held out (Hydrogen, TimGM6mb and MuseScore beds)"}
PARTS = tuple(PART_NAMES)


def level_label(level_db):
    return "alone" if level_db is None else f"{level_db:+d} dB"


def truth(hits):
    """The hits' distinct times (sorted) and each time's part: the first of PRIORITY there."""
    parts = {}
    for t, instrument, _ in hits:
        key = round(t, 6)
        if key not in parts or PRIORITY.index(instrument) < PRIORITY.index(parts[key]):
            parts[key] = instrument
    times = sorted(parts)
    return np.array(times), [parts[t] for t in times]


def tactus_onsets(tactus, wav, preset):
    """Onset times and, when `tactus onsets` prints a 4th column, each onset's part (else None)."""
    rows = onset_rows(tactus, wav, preset)
    times = np.array([float(r[0]) for r in rows])
    has_part = bool(rows) and all(len(r) >= 4 for r in rows)
    return times, ([r[3] for r in rows] if has_part else None)


def aubio_onsets(wav, method):
    out = run(["aubioonset", "-i", wav, "-O", method] + AUBIO_ARGS).stdout
    return np.array([float(line.split()[0]) for line in out.splitlines() if line.strip()])


def felt_render(tactus, wav, renders, preset):
    """The felt render of `wav`: (felt signal, its envelope, rate)."""
    out = renders / f"{wav.stem}.vibration.wav"
    run([tactus, "render", wav, "-o", out, "--force", "--preset", preset])
    y, rate = soundfile.read(out, dtype="float64")
    signal = felt.weighted(y, rate)
    return signal, np.abs(scipy.signal.hilbert(signal)), rate


def gives_pulse(envelope, rate, t, pulse_s=PULSE_S):
    """Whether the felt envelope peaks inside [t, t + pulse_s], DISTINCT_DB above its largest
    value over [t - BEFORE_S, t]."""
    start = int(round(t * rate))
    window = envelope[start:start + int(pulse_s * rate)]
    before = envelope[max(0, start - int(BEFORE_S * rate)):start]
    if len(window) < 2:
        return False
    top = int(np.argmax(window))
    floor = np.max(before) if len(before) else 0.0
    return top < len(window) - 1 and window[top] >= floor * 10 ** (DISTINCT_DB / 20)


def analyse_mix(tactus, entry, directory, renders, preset):
    """One mix's onset scores per detector, its hits giving a felt pulse (count, total) and its
    part matches {part: [right, total]} (None without a part column)."""
    wav = directory / f"{entry['name']}.wav"
    reference, parts = truth(read_hits(directory / f"{entry['name']}.hits.csv"))
    times, labels = tactus_onsets(tactus, wav, preset)
    estimates = {"tactus": times, "aubio mkl": aubio_onsets(wav, "mkl"),
                 "aubio specflux": aubio_onsets(wav, "specflux")}
    scores = {d: mir_eval.onset.f_measure(reference, e, window=TOLERANCE_S)
              for d, e in estimates.items()}
    if entry["bed_db"] is None:  # the drums alone, also in white noise
        noisy = directory / f"{entry['name']}.noise.wav"
        scores["tactus in noise"] = mir_eval.onset.f_measure(
            reference, tactus_onsets(tactus, noisy, preset)[0], window=TOLERANCE_S)
    matches = mir_eval.util.match_events(reference, times, TOLERANCE_S)
    _, envelope, rate = felt_render(tactus, wav, renders, preset)
    pulses = sum(gives_pulse(envelope, rate, reference[i]) for i, _ in matches)
    part_counts = None if labels is None else count_parts(parts, labels, matches)
    return {"scores": scores, "pulses": (pulses, len(reference)), "parts": part_counts,
            "unmatched": None if labels is None else unmatched_parts(labels, matches)}


def unmatched_parts(labels, matches):
    """{part: count} of the onsets no drum hit matches (over a bed: the bed's own)."""
    matched = {j for _, j in matches}
    counts = collections.Counter(label for j, label in enumerate(labels) if j not in matched)
    return {p: counts[p] for p in NAMED}


def count_parts(parts, labels, matches):
    """{part: [onsets naming it right, onsets matched to a hit of that part]} over `matches`
    (mir_eval's (hit index, onset index) pairs)."""
    counts = {p: [0, 0] for p in PRIORITY}
    for i, j in matches:
        counts[parts[i]][0] += labels[j] == parts[i]
        counts[parts[i]][1] += 1
    return counts


IsolatedHit = collections.namedtuple("IsolatedHit",
                                     "gain_db peak hz latency_s strength_db bed_peak "
                                     "sound_half_peak_s")


def analyse_gain(tactus, entry, directory, renders, preset):
    """One isolated-hit file's IsolatedHit per hit: its gain, felt peak and felt Hz; its
    half-peak latency, None when it gives no distinct pulse; the strength `tactus onsets` gives
    its onset (matched one-to-one within +-STRENGTH_MATCH_S), None without one; over a bed, the
    felt peak of the bed rendered alone over the same window (its stem, NAME.bed.wav); the time
    the hit's own sound takes to reach half its peak (the drum stem, NAME.drums.wav over a bed)."""
    wav = directory / f"{entry['name']}.wav"
    hits = read_hits(directory / f"{entry['name']}.hits.csv")
    drums, drums_rate = read_mono(
        wav if entry["bed_db"] is None else directory / f"{entry['name']}.drums.wav")
    signal, envelope, rate = felt_render(tactus, wav, renders, preset)
    bed = None if entry["bed_db"] is None else \
        felt_render(tactus, directory / f"{entry['name']}.bed.wav", renders, preset)[0]
    rows = onset_rows(tactus, wav, preset)
    matches = dict(mir_eval.util.match_events(np.array([t for t, _, _ in hits]),
                                              np.array([float(r[0]) for r in rows]),
                                              STRENGTH_MATCH_S))
    out = []
    for i, (t, _, gain) in enumerate(hits):
        segment = felt.pulse(signal, rate, t, ISOLATED_PULSE_S)
        latency = felt.half_peak_latency_s(segment, rate) if gives_pulse(envelope, rate, t) \
            else None
        hz = felt.centroid_hz(felt.pulse(signal, rate, t), rate)
        strength = float(rows[matches[i]][2]) if i in matches else None
        bed_peak = None if bed is None else \
            felt.peak(felt.pulse(bed, rate, t, ISOLATED_PULSE_S))
        sound = felt.half_peak_latency_s(felt.pulse(drums, drums_rate, t, ISOLATED_PULSE_S),
                                         drums_rate)
        out.append(IsolatedHit(gain, felt.peak(segment), hz, latency, strength, bed_peak, sound))
    return out


def measure_part(tactus, directory, manifest, preset, jobs):
    """Every measure of one part of the corpus."""
    renders = directory / "renders"
    renders.mkdir(exist_ok=True)
    with concurrent.futures.ThreadPoolExecutor(jobs) as pool:
        mixes = list(pool.map(lambda e: analyse_mix(tactus, e, directory, renders, preset),
                              manifest["mixes"]))
        gains = list(pool.map(lambda e: analyse_gain(tactus, e, directory, renders, preset),
                              manifest["gain"]))
    by_level = collections.defaultdict(list)
    for entry, result in zip(manifest["mixes"], mixes):
        by_level[entry["bed_db"]].append((entry, result))
    gain_files = collections.defaultdict(dict)  # level -> (kit, instrument) -> hits
    for entry, result in zip(manifest["gain"], gains):
        gain_files[entry["bed_db"]][(entry["kit"], entry["instrument"])] = result
    return {"mixes": by_level, "gain": gain_files}


def measure(build_dir, work, preset, gm_samples, parts=PARTS, jobs=2):
    """Builds the music corpus in `work` (cached) and measures tactus on each of `parts`."""
    tactus = str(pathlib.Path(build_dir) / "bin/tactus")
    manifests = music_corpus.build(work, gm_samples, parts, jobs)
    return {part: measure_part(tactus, pathlib.Path(work) / part, manifests[part], preset, jobs)
            for part in parts}


# Figures of one part.
def onset_means(part, level, detector):
    """Mean (F, P, R) over the files at `level`."""
    return np.mean([r["scores"][detector] for _, r in part["mixes"][level]], axis=0)


def pulse_share(part, level):
    given = sum(r["pulses"][0] for _, r in part["mixes"][level])
    total = sum(r["pulses"][1] for _, r in part["mixes"][level])
    return given / total


def part_accuracy(part, level):
    """{kick, snare, hat, all: share right} or None when tactus prints no part."""
    return pooled_accuracy([r["parts"] for _, r in part["mixes"][level]])


def pooled_accuracy(results):
    """{kick, snare, hat, all: share right} of count_parts() results pooled, or None when one is
    None."""
    if not results or any(r is None for r in results):
        return None
    counts = {p: [sum(r[p][0] for r in results), sum(r[p][1] for r in results)] for p in PRIORITY}
    counts["all"] = [sum(c[0] for c in counts.values()), sum(c[1] for c in counts.values())]
    return {p: (right / total if total else float("nan")) for p, (right, total) in counts.items()}


def unmatched_counts(part, level):
    """{kick, snare, hat, other: count} of the onsets no drum hit matches at `level` (the bed's
    own over a bed), pooled; None when tactus prints no part."""
    results = [r["unmatched"] for _, r in part["mixes"][level]]
    if not results or any(r is None for r in results):
        return None
    return {p: sum(r[p] for r in results) for p in NAMED}


def rhos(part, level, reading="peak"):
    """[(rho of gain -> a reading of IsolatedHit, 'kit instrument')] of every isolated-hit file at
    `level`: the felt peak, or tactus's strength_db (a hit without an onset lowest)."""
    def value(hit):
        v = getattr(hit, reading)
        return -np.inf if v is None else v
    return [(scipy.stats.spearmanr([h.gain_db for h in hits], [value(h) for h in hits]).correlation,
             f"{kit} {instrument}") for (kit, instrument), hits in part["gain"][level].items()]


def snare_kick(part, level):
    """[(felt snare/kick of the median pulse frequencies, kit)] at `level`."""
    files = part["gain"][level]
    hz = {key: statistics.median(h.hz for h in hits) for key, hits in files.items()}
    return [(hz[(kit, "snare")] / hz[(kit, "kick")], kit)
            for kit in sorted({k for k, _ in files})]


def above_bed(hit):
    """Whether an isolated hit's felt peak stands ABOVE_BED_DB over the bed's own (the bed
    rendered alone, same window); the others' peaks are ordered by the bed's pulses."""
    return hit.bed_peak is None or hit.peak >= hit.bed_peak * 10 ** (ABOVE_BED_DB / 20)


def latencies(part, level, since_sound=False, only_above_bed=False):
    """Half-peak latencies (s) of the hits giving a distinct pulse (only_above_bed: of those
    standing above the bed), from the hit or (since_sound) from its own sound's half peak, and
    the number of hits."""
    hits = [h for file in part["gain"][level].values() for h in file
            if not only_above_bed or above_bed(h)]
    return [h.latency_s - (h.sound_half_peak_s if since_sound else 0) for h in hits
            if h.latency_s is not None], len(hits)


# Cells.
def worst_cell(pairs, digits):
    value, where = min(pairs)
    return f"{value:.{digits}f} ({where})"


def above_bed_cell(part, level):
    """The share of the isolated hits standing above the bed (above_bed)."""
    if level is None:
        return "-"
    hits = [h for file in part["gain"][level].values() for h in file]
    above = sum(map(above_bed, hits))
    return f"{above / len(hits):.3f} ({above} of {len(hits)})"


def latency_cell(part, level, since_sound=False, only_above_bed=False):
    if only_above_bed and level is None:
        return "-"
    values, total = latencies(part, level, since_sound, only_above_bed)
    ms = 1000 * np.array(values)
    return f"{np.median(ms):.1f} / {np.percentile(ms, 95):.1f} ({len(values)} of {total})"


def recall_cell(part, detector="tactus"):
    return " / ".join(f"{onset_means(part, level, detector)[2]:.3f}" for level in LEVELS)


def accuracy_cell(part, level):
    accuracy = part_accuracy(part, level)
    if accuracy is None:
        return "n/a"
    return " / ".join(f"{accuracy[p]:.3f}" for p in PRIORITY + ("all",))


def unmatched_cell(part, level):
    counts = unmatched_counts(part, level)
    if counts is None:
        return "n/a"
    total = sum(counts.values())
    if total == 0:
        return "none"
    return " / ".join(f"{counts[p] / total:.3f}" for p in NAMED) + f" ({total})"


def level_table(text, names, parts, cell, columns=""):
    """A paragraph, then a table of one row per bed level: its label, then cell(part, level) for
    each part (headed by its name and `columns`)."""
    return (["", text, "", "| bed | " + " | ".join(n + columns for n in names) + " |",
             "|---" * (len(names) + 1) + "|"] +
            [f"| {level_label(level)} | " + " | ".join(cell(p, level) for p in parts) + " |"
             for level in LEVELS])


def summary(result):
    """The headline figures of each part side by side (evaluate.py's summary)."""
    parts = list(result.values())
    names = [PART_NAMES[p] for p in result]
    levels = "/".join(level_label(level).replace(" dB", "") for level in LEVELS)
    rows = [("music, drums alone: tactus onset F at +-50 ms, clean / white noise -20 dB",
             lambda p: f"{onset_means(p, None, 'tactus')[0]:.3f} / "
                       f"{onset_means(p, None, 'tactus in noise')[0]:.3f}"),
            (f"music: tactus onset recall at +-50 ms, bed {levels} dB", recall_cell),
            ("music: drum hits giving a felt pulse, bed -6 / 0 dB",
             lambda p: f"{pulse_share(p, -6):.3f} / {pulse_share(p, 0):.3f}"),
            ("music: isolated hits, bed -6 dB: gain -> felt pulse peak rho, worst",
             lambda p: worst_cell(rhos(p, -6), 3)),
            ("music: isolated hits, bed -6 dB: felt snare/kick, worst kit",
             lambda p: worst_cell(snare_kick(p, -6), 2)),
            ("music: isolated hits, bed -6 dB: onset -> felt half peak, median / 95th "
             "percentile ms (distinct pulses)", lambda p: latency_cell(p, -6)),
            ("music: isolated hits, bed -6 dB: the hit's sound at half its peak -> felt half "
             "peak, median / 95th percentile ms", lambda p: latency_cell(p, -6, since_sound=True)),
            ("music: drum part right, bed 0 dB, kick / snare / hat / all",
             lambda p: accuracy_cell(p, 0)),
            ("music: the bed's own onsets, bed 0 dB, named kick / snare / hat / other (count)",
             lambda p: unmatched_cell(p, 0))]
    lines = ["| figure, drums inside music | " + " | ".join(names) + " |",
             "|---|" + "---|" * len(names)]
    lines += [f"| {label} | " + " | ".join(cell(p) for p in parts) + " |" for label, cell in rows]
    return lines + [""]


def section(result):
    """The "Drums inside music" section's markdown lines."""
    names = [PART_NAMES[p] for p in result]
    parts = list(result.values())
    rule = "|---" * len(names) + "|"
    n_mixes = {name: len([1 for level in p["mixes"].values() for _ in level])
               for name, p in zip(names, parts)}
    lines = ["# Drums inside music", "",
             "Full mixes with exact drum truth (`eval/music_corpus.py`): a drum stem of one-shot "
             "hits placed sample-exactly in rock, house, funk (16ths, ghost snares), half-time "
             "and swung hip-hop patterns at 70-172 BPM, accents and ghost notes -14..-8 dB; a bed "
             "of bass, chords or a pad and a melody (fluidsynth, General MIDI programs on melodic "
             "channels) and an espeak-ng voice; mixed alone and with the bed at -12, -6, 0 and "
             "+6 dB re the drums (RMS of each stem over the song), some through sox reverb and/or "
             "compand, peak-normalised to -1 dBFS, a quarter at 48 kHz. Tuning part: the Sonic Pi "
             "kits, FluidR3 beds, seed 1; held out: the General MIDI kits of the held-out corpus, "
             "TimGM6mb and MuseScore beds with other programs and voices, seed 2, plus shuffle "
             "and two-step patterns. Recorded kits (`eval/recorded_kits.py`): Hydrogen's kits "
             "(Debian's hydrogen-drumkits), acoustic kits sampled at several strengths (each hit "
             "plays its velocity's recording) and electronic kits, six for tuning and five held "
             "out, in songs drawn as the tuning and the held-out part's (seeds 3 and 4). The "
             "drums alone are also measured in white noise "
             f"{music_corpus.NOISE_DB} dB re their RMS. Files: " +
             ", ".join(f"{n} {name}" for name, n in n_mixes.items()) + ".", "",
             "## Onsets in music", "",
             "Mean over the files of each bed level of F, precision and recall at +-50 ms "
             "(mir_eval, one-to-one) against the drum hits' distinct times. The bed's own onsets "
             "count as false positives; recall is the share of drum hits detected. aubioonset: "
             f"`{' '.join(AUBIO_ARGS)}`.", "",
             "| detector | bed | " + " | ".join(f"{n}: R / P / F" for n in names) + " |",
             "|---|---" + rule]
    for detector in DETECTORS:
        for level in LEVELS:
            cells = [" / ".join(f"{v:.3f}" for v in onset_means(p, level, detector)[[2, 1, 0]])
                     for p in parts]
            lines.append(f"| {detector} | {level_label(level)} | " + " | ".join(cells) + " |")
    cells = [" / ".join(f"{v:.3f}" for v in onset_means(p, None, "tactus in noise")[[2, 1, 0]])
             for p in parts]
    lines.append(f"| tactus | alone in white noise {music_corpus.NOISE_DB} dB | " +
                 " | ".join(cells) + " |")
    lines += ["", "tactus recall per style (alone / -12 / -6 / 0 / +6 dB):", ""]
    for name, p in zip(names, parts):
        styles = sorted({e["style"] for e, _ in p["mixes"][None]})
        per_style = []
        for style in styles:
            cells = [np.mean([r["scores"]["tactus"][2] for e, r in p["mixes"][level]
                              if e["style"] == style]) for level in LEVELS]
            per_style.append(f"{style} " + "/".join(f"{c:.2f}" for c in cells))
        lines.append(f"- {name}: " + ", ".join(per_style))
    lines += ["", "## Drum hits that give a felt pulse"]
    lines += level_table(
        f"A hit gives a felt pulse when the felt render's envelope peaks within "
        f"{1000 * PULSE_S:.0f} ms after it, {DISTINCT_DB:.0f} dB above its level over the "
        f"{1000 * BEFORE_S:.0f} ms before (which holds the previous hit's and the bed's "
        "vibration), and a tactus onset is matched to it (+-50 ms, one-to-one). Share of "
        "the drum hits' distinct times.",
        names, parts, lambda p, level: f"{pulse_share(p, level):.3f}")
    lines += ["", "## Isolated hits over music", "",
              "Each kit's kick alone and snare alone, 9 hits 1 s apart at 0 to -24 dB, without "
              "bed and over a bed at -12 and -6 dB re the loudest hit (the bed's RMS against the "
              f"0 dB hit's over its first {1000 * music_corpus.REFERENCE_S:.0f} ms). Pulse peak: "
              f"the felt peak over [hit, hit + {1000 * ISOLATED_PULSE_S:.0f} ms], the bed's "
              "vibration included (nothing subtracted); rho: Spearman's of hit gain -> pulse "
              "peak; snare/kick: of the median felt pulse frequencies (felt centroid over "
              f"{1000 * felt.PULSE_WINDOW_S:.0f} ms, as in the per-kit table); latency: onset -> "
              "felt output at half its pulse peak, over the hits giving a distinct pulse (as "
              "above, without the onset condition), and from the hit's own sound (its drum "
              "stem) reaching half its peak, what tactus adds to the sound's own rise; tactus "
              "strength: the strength `tactus onsets` gives the onset within "
              f"+-{1000 * STRENGTH_MATCH_S:.0f} ms of the hit (a hit without one lowest), the "
              "hit's own reading, whatever the bed's pulses do to the felt peak; above the bed: "
              "the hits whose felt peak is "
              f"{ABOVE_BED_DB:.0f} dB or more above the felt peak, over the same window, of the "
              "bed rendered alone (its stem): the others' peaks, and so rho, are the bed's "
              "pulses' as much as the hit's.", "",
              "| figure | bed | " + " | ".join(names) + " |", "|---|---" + rule]
    figures = [("gain -> felt peak rho, worst", lambda p, lv: worst_cell(rhos(p, lv), 3)),
               ("gain -> felt peak rho, median",
                lambda p, lv: f"{np.median([r for r, _ in rhos(p, lv)]):.3f}"),
               ("felt snare/kick, worst kit", lambda p, lv: worst_cell(snare_kick(p, lv), 2)),
               ("felt snare/kick, median over kits",
                lambda p, lv: f"{np.median([r for r, _ in snare_kick(p, lv)]):.2f}"),
               ("onset -> felt half peak, median / p95 ms", latency_cell),
               ("the hit's sound at half its peak -> felt half peak, median / p95 ms",
                lambda p, lv: latency_cell(p, lv, since_sound=True)),
               (f"the same, hits {ABOVE_BED_DB:.0f} dB above the bed's own felt peak",
                lambda p, lv: latency_cell(p, lv, since_sound=True, only_above_bed=True)),
               (f"hits {ABOVE_BED_DB:.0f} dB above the bed's own felt peak", above_bed_cell),
               ("gain -> tactus strength rho, median / worst",
                lambda p, lv: f"{np.median([r for r, _ in rhos(p, lv, 'strength_db')]):.3f} / "
                              + worst_cell(rhos(p, lv, "strength_db"), 3))]
    for label, cell in figures:
        for level in GAIN_LEVELS:
            lines.append(f"| {label} | {level_label(level)} | " +
                         " | ".join(cell(p, level) for p in parts) + " |")
    lines += ["", "## Drum part"]
    lines += level_table(
        "`tactus onsets`' 4th column (kick, snare, hat, other), over its onsets matched "
        "one-to-one to a drum hit within +-50 ms: the share naming the hit's part, per "
        "true part and overall; where hits coincide the true part is the first of kick, "
        "snare, hat among them. n/a: tactus prints no part. The part model "
        "(src/tactus/analysis/part_model.hpp) is fitted on the tuning parts only; "
        "`eval/fit_parts.py BUILD_DIR --work DIR` re-runs this table alone (about 10 s on "
        "a built corpus) and `--write-header` refits it; it also prints the model fitted "
        "with two tuning kits left out at a time, measured on them.",
        names, parts, accuracy_cell, ": kick / snare / hat / all")
    lines += level_table(
        "The onsets no drum hit matches (+-50 ms), by the part tactus names them: over a bed, the "
        "bed's own onsets (bass, chords, melody, voice), which a drums-only mapping "
        "(`presets/drums.toml`: `parts.other.gain_db = -60`) plays as drums unless they are "
        "named other; alone, the drums' own false onsets. Shares and count.",
        names, parts, unmatched_cell, ": kick / snare / hat / other")
    return lines
