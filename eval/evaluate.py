#!/usr/bin/python3
"""Measures tactus on the drum corpus and compares its onsets with aubioonset's.

usage: eval/evaluate.py BUILD_DIR [--out eval/results.md] [--work DIR] [--seed N]
                        [--held-out gm|none] [--music|--no-music]

Builds the corpus with BUILD_DIR/eval/make_drum_corpus (fixed seed), runs `tactus onsets` and
`tactus render` on it, runs aubioonset with every method and bonk~ in Pd (eval/bonk_onsets.pd,
`pd -nogui -batch`; all parameters explicit), and checks: onset F-measure, precision and recall
at +-25 and +-50 ms and the median signed timing offset (mir_eval), snare/kick vibration
frequency ratio, hit gain -> pulse peak Spearman rho, share of output energy in 20-1000 Hz,
output peak, silence in -> silence out, felt snare/kick in the breakbeats, and the time from
each hit's true onset to the output
reaching half its pulse peak, each as felt (eval/felt.py) and raw, with a summary up front; then Sonic Pi's Amen break at every sample rate from 16 to 192 kHz
(eval/sample_rates.py), held synth notes at bass and lead pitches (eval/held_notes.py), and
the corpus through each shipped actuator profile
(eval/actuators.py). The same measures follow on a held-out corpus: General MIDI drum
kits from three Debian soundfonts (eval/gm_kits.py), which no parameter was tuned on. Last, drums
inside music (eval/music.py): full mixes with exact drum truth (eval/music_corpus.py), a tuning
part and a held-out part, measured for onsets, felt pulses, isolated hits and drum parts.
"""
import argparse
import os
import pathlib
import shutil
import statistics
import subprocess
import sys
import tempfile

import mir_eval
import numpy as np
import scipy.stats
import soundfile

import actuators
import felt
import gm_kits
import held_notes
import music
import sample_rates
from shared import AUBIO_ARGS, band_share, read_hits, run

AUBIO_METHODS = ["hfc", "energy", "complex", "phase", "specdiff", "kl", "mkl", "specflux"]
# bonk~'s defaults (Pd 0.53, bonk 1.5), passed explicitly in eval/bonk_onsets.pd: 256-point
# window, hop 128, 11 filters 6 halftones wide, thresh 2.5 5, minvel 7, mask 4 0.7, debounce 0,
# attack-frames 1. It reports an attack when the growth has risen over the high threshold and
# fallen back under the low one, so its times lag the onset by some hops.
BONK_PATCH = pathlib.Path(__file__).resolve().parent / "bonk_onsets.pd"
TOLERANCES_S = (0.025, 0.05)
# A breakbeat hit's pulse is measured over its first 80 ms: the next hit comes 91 ms later at
# worst (sixteenths at 165 BPM).
BREAKBEAT_PULSE_S = 0.08


def column(text, index=0):
    return np.array([float(line.split()[index]) for line in text.splitlines() if line.strip()])


def bonk_onsets(wav, rate_hz):
    """Onset times (s) bonk~ reports for `wav`, run in a real Pd as fast as the CPU allows."""
    pd = shutil.which("pd") or shutil.which("puredata")
    if not pd:
        raise RuntimeError("pd not found (Debian packages puredata-core, puredata-extra)")
    if " " in str(wav):
        raise RuntimeError(f"{wav}: pd -send splits at spaces; use a --work path without them")
    result = subprocess.run([pd, "-nogui", "-batch", "-noaudio", "-r", str(rate_hz), "-send",
                             f"bonk-file symbol {wav}", "-open", str(BONK_PATCH)],
                            check=True, capture_output=True, text=True, timeout=600)
    errors = [line for line in result.stderr.splitlines() if line.startswith("error:")]
    if errors:
        raise RuntimeError(f"{wav}: pd: {errors[0]}")
    return np.array([float(line.split()[1]) / 1000.0 for line in result.stderr.splitlines()
                     if line.startswith("bonk-onset-ms:")])


def onset_scores(reference, estimated):
    """(F, P, R) at each tolerance, then the signed offsets (estimated - reference, s) of the
    one-to-one matches at the widest tolerance."""
    scores = [mir_eval.onset.f_measure(reference, estimated, window=w) for w in TOLERANCES_S]
    matches = mir_eval.util.match_events(reference, estimated, max(TOLERANCES_S))
    offsets = [estimated[j] - reference[i] for i, j in matches]
    return scores, offsets


def evaluate(args, tactus, work, kits=None, samples=None):
    """Builds one corpus in `work` (Sonic Pi's kits, or `kits` from the `samples` directory),
    runs every detector on it and renders it; returns its measures."""
    corpus = work / "corpus"
    renders = work / "renders"
    renders.mkdir(parents=True, exist_ok=True)
    env = dict(os.environ, TACTUS_SAMPLES=str(samples)) if samples else None
    subprocess.run([str(args.build_dir / "bin/make_drum_corpus"), str(corpus), str(args.seed)] +
                   (kits or []), check=True, capture_output=True, env=env)
    # "tactus decided" scores the time each onset was decided (`tactus onsets`' second column)
    # instead of its estimated start: its latency, as bonk~'s times are.
    detectors = ["tactus", "tactus decided"] + ["aubio " + m for m in AUBIO_METHODS] + ["bonk~"]
    # condition -> detector -> ([per-file (F, P, R) per tolerance], [pooled offsets])
    scores = {c: {d: ([], []) for d in detectors} for c in ("clean", "noise")}
    for wav in sorted(corpus.glob("breakbeat-*.wav")):
        name = wav.stem
        condition = "noise" if name.endswith("-noise") else "clean"
        reference = np.loadtxt(corpus / f"{name}.onsets.txt", ndmin=1)
        tactus_onsets = run([tactus, "onsets", wav, "--preset", args.preset]).stdout
        estimates = {"tactus": column(tactus_onsets, 0),
                     "tactus decided": column(tactus_onsets, 1)}
        for m in AUBIO_METHODS:
            estimates["aubio " + m] = column(
                run(["aubioonset", "-i", wav, "-O", m] + AUBIO_ARGS).stdout)
        estimates["bonk~"] = bonk_onsets(wav, soundfile.info(wav).samplerate)
        for detector, estimated in estimates.items():
            per_file, offsets = scores[condition][detector]
            file_scores, file_offsets = onset_scores(reference, estimated)
            per_file.append(file_scores)
            offsets.extend(file_offsets)
        out = renders / f"{name}.vibration.wav"
        run([tactus, "render", str(wav), "-o", str(out), "--force", "--preset", args.preset])

    per_kit = []
    latencies = {"": [], "raw_": []}  # felt, raw
    worst_share, worst_peak = 1.0, 0.0
    for kick_wav in sorted(corpus.glob("gain-*-kick.wav")):
        kit = kick_wav.stem[len("gain-"):-len("-kick")]
        result = {"kit": kit}
        for instrument in ("kick", "snare"):
            wav = corpus / f"gain-{kit}-{instrument}.wav"
            out = renders / f"gain-{kit}-{instrument}.vibration.wav"
            run([tactus, "render", str(wav), "-o", str(out), "--force", "--preset", args.preset])
            y, rate = soundfile.read(out, dtype="float64")
            hits = read_hits(corpus / f"gain-{kit}-{instrument}.hits.csv")
            onsets = [t for t, _, _ in hits]
            gains = [g for _, _, g in hits]
            for prefix, weight in (("", True), ("raw_", False)):
                measured = felt.pulses(y, rate, onsets, weight)
                latencies[prefix].extend(latency for _, _, latency in measured)
                result[f"{instrument}_{prefix}rho"] = scipy.stats.spearmanr(
                    gains, [peak for peak, _, _ in measured]).correlation
                result[f"{instrument}_{prefix}hz"] = statistics.median(f for _, f, _ in measured)
            worst_share = min(worst_share, band_share(y, rate))
            worst_peak = max(worst_peak, float(np.max(np.abs(y))))
        for prefix in ("", "raw_"):
            kick, snare = result[f"kick_{prefix}hz"], result[f"snare_{prefix}hz"]
            result[prefix + "ratio"] = snare / kick if kick else float("nan")
        per_kit.append(result)
    breakbeat_ratios = []  # (felt snare/kick, file) of each clean breakbeat
    for out in sorted(renders.glob("breakbeat-*.vibration.wav")):
        y, rate = soundfile.read(out, dtype="float64")
        worst_share = min(worst_share, band_share(y, rate))
        worst_peak = max(worst_peak, float(np.max(np.abs(y))))
        name = out.name[:-len(".vibration.wav")]
        if not name.endswith("-noise"):
            hits = read_hits(corpus / f"{name}.hits.csv")
            hz = {i: statistics.median(f for _, f, _ in felt.pulses(
                y, rate, [t for t, inst, _ in hits if inst == i], window_s=BREAKBEAT_PULSE_S))
                for i in ("kick", "snare")}
            breakbeat_ratios.append((hz["snare"] / hz["kick"], name))

    return {"detectors": detectors, "scores": scores, "per_kit": per_kit,
            "breakbeat_ratios": breakbeat_ratios,
            "latencies": latencies[""], "raw_latencies": latencies["raw_"], "share": worst_share, "peak": worst_peak}


def sections(result):
    """The onset, per-kit and whole-output tables of one corpus."""
    detectors, scores, per_kit = result["detectors"], result["scores"], result["per_kit"]
    lines = ["## Onsets", "",
             "F-measure, precision and recall at +-25 and +-50 ms (mir_eval, one-to-one; mean "
             "over files) and the median signed offset detected - true of the matches at +-50 ms "
             "(all files pooled). Noise: white, -20 dB re the music's RMS. aubioonset: "
             f"`{' '.join(AUBIO_ARGS)}`; bonk~: `eval/bonk_onsets.pd` in `pd -nogui -batch`, "
             "its defaults passed explicitly (window 256, hop 128, thresh 2.5 5, minvel 7, "
             "mask 4 0.7), times as bonk~ reports them. tactus: the estimated onset start; "
             "tactus decided: the time the onset was decided (its detection latency).", "",
             "| detector | condition | F 25 ms | P 25 ms | R 25 ms | F 50 ms | P 50 ms | R 50 ms "
             "| median offset ms |",
             "|---|---|---|---|---|---|---|---|---|"]
    for condition, label in (("clean", "clean"), ("noise", "noise -20 dB")):
        for detector in detectors:
            per_file, offsets = scores[condition][detector]
            mean = np.mean(per_file, axis=0)  # [tolerance][F, P, R]
            offset = f"{1000 * np.median(offsets):+.1f}" if offsets else "-"
            cells = " | ".join(f"{v:.3f}" for v in mean.ravel())
            lines.append(f"| {detector} | {label} | {cells} | {offset} |")
    lines += ["", "## Vibration per kit (isolated hits, gains 0 to -24 dB)", "",
              "Felt: the output weighted by the skin's sensitivity (eval/felt.py: the inverse of "
              "the P threshold, -12 dB/octave below 250 Hz, -9 dB/octave above, zero phase). "
              "Hz: the median pulse carrier frequency; rho: Spearman's rho of hit gain -> pulse "
              "peak. Raw: the same of the unweighted output.", "",
              "| kit | kick Hz | snare Hz | snare/kick | kick rho | snare rho "
              "| raw snare/kick | raw kick rho | raw snare rho |",
              "|---|---|---|---|---|---|---|---|---|"]
    for r in per_kit:
        lines.append(f"| {r['kit']} | {r['kick_hz']:.0f} | {r['snare_hz']:.0f} | "
                     f"{r['ratio']:.2f} | {r['kick_rho']:.3f} | {r['snare_rho']:.3f} | "
                     f"{r['raw_ratio']:.2f} | {r['kick_raw_rho']:.3f} | {r['snare_raw_rho']:.3f} |")
    felt_ms = 1000 * np.array(result["latencies"])
    raw_ms = 1000 * np.array(result["raw_latencies"])
    lines += ["", "## Whole output", "",
              f"- output energy within 20-1000 Hz (worst file): {100 * result['share']:.3f} %",
              f"- output peak (worst file): {result['peak']:.4f} full scale",
              f"- onset -> felt output at half its pulse peak: median {np.nanmedian(felt_ms):.1f} ms, "
              f"95th percentile {np.nanpercentile(felt_ms, 95):.1f} ms",
              f"- onset -> raw output at half its pulse peak: median {np.nanmedian(raw_ms):.1f} ms, "
              f"90th percentile {np.nanpercentile(raw_ms, 90):.1f} ms",
              f"- felt snare/kick in the clean breakbeats, where hits overlap (each hit's first "
              f"{1000 * BREAKBEAT_PULSE_S:.0f} ms): median over the files "
              f"{np.median([r for r, _ in result['breakbeat_ratios']]):.2f}, worst "
              "{:.2f} ({})".format(*min(result["breakbeat_ratios"]))]
    return lines


def summary(corpora):
    """The headline figures of each corpus side by side, the worst kit named."""
    def f_at_50(result, condition):
        return np.mean(result["scores"][condition]["tactus"][0], axis=0)[1][0]

    def worst(result, key):
        kit = min(result["per_kit"], key=lambda r: r[key])
        return f"{kit[key]:.2f} ({kit['kit']})"

    def worst_rho(result, prefix):
        value, where = min((r[f"{i}_{prefix}rho"], f"{r['kit']} {i}")
                           for r in result["per_kit"] for i in ("kick", "snare"))
        return f"{value:.3f} ({where})"

    def breakbeats(result):
        ratios = result["breakbeat_ratios"]
        return f"{np.median([r for r, _ in ratios]):.2f} / " + "{:.2f} ({})".format(*min(ratios))

    def latency(result):
        ms = 1000 * np.array(result["latencies"])
        return f"{np.nanmedian(ms):.1f} / {np.nanpercentile(ms, 95):.1f}"

    rows = [("onset F at +-50 ms, clean / noise -20 dB",
             lambda r: f"{f_at_50(r, 'clean'):.3f} / {f_at_50(r, 'noise'):.3f}"),
            ("hit gain -> felt pulse peak rho, worst", lambda r: worst_rho(r, "")),
            ("onset -> felt output at half its pulse peak, median / 95th percentile ms", latency),
            ("felt snare/kick frequency ratio, worst kit", lambda r: worst(r, "ratio")),
            ("raw snare/kick frequency ratio, worst kit", lambda r: worst(r, "raw_ratio")),
            ("felt snare/kick in the clean breakbeats, median / worst file", breakbeats)]
    names = [name for name, _ in corpora]
    lines = ["## Summary", "", "| figure | " + " | ".join(names) + " |",
             "|---|" + "---|" * len(names)]
    for label, measure in rows:
        lines.append(f"| {label} | " + " | ".join(measure(r) for _, r in corpora) + " |")
    return lines + [""]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("build_dir", type=pathlib.Path)
    parser.add_argument("--out", type=pathlib.Path, default=None)
    parser.add_argument("--work", type=pathlib.Path, default=None)
    parser.add_argument("--preset", default="music")
    parser.add_argument("--seed", type=int, default=1, help="corpus seed (1 is the tuning set)")
    parser.add_argument("--held-out", choices=("gm", "none"), default="gm",
                        help="also measure the General MIDI kits tactus was not tuned on")
    parser.add_argument("--music", action=argparse.BooleanOptionalAction, default=True,
                        help="also measure drums inside full music mixes (eval/music.py)")
    args = parser.parse_args()

    tactus = str(args.build_dir / "bin/tactus")
    work = args.work or pathlib.Path(tempfile.mkdtemp(prefix="tactus-eval-"))
    tuned = evaluate(args, tactus, work / "sonic-pi")

    silent = work / "silence.wav"
    soundfile.write(silent, np.zeros(44100 * 3), 44100, subtype="FLOAT")
    run([tactus, "render", str(silent), "-o", str(work / "silence.vibration.wav"), "--force",
         "--preset", args.preset])
    silence_out, _ = soundfile.read(work / "silence.vibration.wav")
    silence_exact = bool(np.all(silence_out == 0))

    tables = sections(tuned)
    lines = ["# tactus on the drum corpus", "",
             f"Generated by `eval/evaluate.py` (preset `{args.preset}`); corpus: "
             f"{len(tuned['per_kit'])} kits of Sonic Pi drum hits, seed {args.seed}.", ""]
    summary_at = len(lines)
    lines += tables
    lines += [f"- digital silence in -> exact silence out: {'yes' if silence_exact else 'NO'}", ""]
    lines += sample_rates.section(sample_rates.measure(args.build_dir, work / "sample-rates",
                                                       args.preset)) + [""]
    lines += held_notes.section(held_notes.measure(args.build_dir, work / "held-notes",
                                                   args.preset)) + [""]
    lines += actuators.evaluate(args.build_dir, work / "sonic-pi" / "corpus", work / "actuators",
                                args.preset) + [""]
    if args.held_out == "gm":
        samples = work / "gm-samples"
        kits = gm_kits.render(samples)
        held_out = evaluate(args, tactus, work / "gm", kits, samples)
        tables = sections(held_out)
        lines += ["# Held out: General MIDI drum kits", "",
                  f"The same measures on {len(kits)} kits tactus was not tuned on: the drum kits "
                  "of the soundfonts of Debian's fluid-soundfont-gm, "
                  "musescore-general-soundfont-small and timgm6mb-soundfont, rendered one hit at "
                  "a time by fluidsynth (`eval/gm_kits.py`: note-on at 0, velocity 100, no reverb "
                  "or chorus; soft-attack acoustic bass drums in two kits), placed as above "
                  f"(seed {args.seed}).", ""]
        lines += ["#" + line if line.startswith("## ") else line for line in tables] + [""]
    music_summary = []
    if args.music:
        parts = music.PARTS if args.held_out == "gm" else ("tuning", "recorded-tuning")
        measured = music.measure(args.build_dir, work / "music", args.preset, work / "gm-samples",
                                 parts)
        lines += music.section(measured) + [""]
        music_summary = music.summary(measured)
    corpora = [("Sonic Pi kits (tuned)", tuned)]
    if args.held_out == "gm":
        corpora.append(("General MIDI kits (held out)", held_out))
    lines[summary_at:summary_at] = summary(corpora) + music_summary
    report = "\n".join(lines)
    print(report)
    if args.out:
        args.out.write_text(report)
    return 0


if __name__ == "__main__":
    sys.exit(main())
