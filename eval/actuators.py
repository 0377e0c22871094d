#!/usr/bin/python3
"""How the default mapping fits each shipped actuator, measured through the actuator.

usage: eval/actuators.py BUILD_DIR CORPUS_DIR [--work DIR] [--preset tfd] [--render TACTUS]

For every profile in actuators/, the corpus's isolated kick and snare hits and its breakbeats
are rendered with `--actuator NAME`, and the render (the drive) is run through the profile's
time-domain model with `tactus simulate` (an LRA's resonance, an ERM's spin-up and speed-tied
frequency): the displacement. Measured on it, as felt (eval/felt.py): the snare/kick ratio of the
median pulse frequencies (worst kit), Spearman's rho of hit gain -> felt peak (worst kit and
instrument), the hits whose felt peak is below a tenth of their kit's strongest. `tactus meter
RENDER --actuator NAME` (the same model, then the P threshold) says which hits engage P (its
level above threshold within the pulse window) against those the voice-coil render engages, and
the P channel's largest level and share of time engaged over the breakbeats. Energy shares:
the drive's and the displacement's within the profile's usable band. --render renders with
another tactus (a baseline); the model and meter stay BUILD_DIR's.
"""
import argparse
import pathlib
import statistics
import sys
import tempfile

import numpy as np
import scipy.stats
import soundfile

import felt
from shared import band_share, read_hits, run

PROFILES = ("voice-coil", "lra-175", "erm")
TENTH = 0.1


def usable_band(actuators_dir, name):
    values = {}
    for line in (actuators_dir / f"{name}.toml").read_text().splitlines():
        key, _, value = line.partition("=")
        if key.strip() in ("band_low_hz", "band_high_hz"):
            values[key.strip()] = float(value.split("#")[0])
    return values["band_low_hz"], values["band_high_hz"]


def meter_p(tactus, render, name, csv):
    """Times (s) and the P channel's level (dB SL, 0 = not engaged) every 10 ms."""
    run([tactus, "meter", render, "--actuator", name, "-o", csv, "--force"])
    data = np.genfromtxt(csv, delimiter=",", names=True, comments="#")
    return data["time_s"], data["P_sl_db"]


def engaged(times, level, onset_s):
    window = (times >= onset_s) & (times < onset_s + felt.PULSE_WINDOW_S)
    return bool(np.any(level[window] > 0))


def measure(args, tactus, render_tactus, corpus, work, name, band):
    """The measures of one profile."""
    out = work / name
    out.mkdir(parents=True, exist_ok=True)
    result = {"name": name, "ratios": {}, "rho": [], "weak": 0, "hits": 0, "engaged": {},
              "drive_share": 1.0, "displacement_share": 1.0, "p_max": -np.inf,
              "p_engaged": [], "warnings": set()}

    def render(wav):
        drive = out / f"{wav.stem}.vibration.wav"
        displacement = out / f"{wav.stem}.displacement.wav"
        done = run([render_tactus, "render", wav, "-o", drive, "--force", "--preset", args.preset,
                    "--actuator", name])
        result["warnings"].update(line for line in done.stderr.splitlines() if "warning" in line)
        run([tactus, "simulate", drive, "-o", displacement, "--force", "--actuator", name])
        y, rate = soundfile.read(drive, dtype="float64")
        d, _ = soundfile.read(displacement, dtype="float64")
        result["drive_share"] = min(result["drive_share"], band_share(y, rate, *band))
        result["displacement_share"] = min(result["displacement_share"],
                                           band_share(d, rate, *band))
        return drive, d, rate

    for kick_wav in sorted(corpus.glob("gain-*-kick.wav")):
        kit = kick_wav.stem[len("gain-"):-len("-kick")]
        hz, peaks = {}, []
        for instrument in ("kick", "snare"):
            wav = corpus / f"gain-{kit}-{instrument}.wav"
            drive, d, rate = render(wav)
            hits = read_hits(corpus / f"gain-{kit}-{instrument}.hits.csv")
            onsets = [t for t, _, _ in hits]
            measured = felt.pulses(d, rate, onsets)
            hz[instrument] = statistics.median(f for _, f, _ in measured)
            result["rho"].append(scipy.stats.spearmanr(
                [g for _, _, g in hits], [p for p, _, _ in measured]).correlation)
            peaks += [p for p, _, _ in measured]
            times, level = meter_p(tactus, drive, name, out / f"{wav.stem}.meter.csv")
            for t in onsets:
                result["engaged"][(kit, instrument, t)] = engaged(times, level, t)
        result["ratios"][kit] = hz["snare"] / hz["kick"] if hz["kick"] else float("nan")
        strongest = max(peaks)
        result["weak"] += sum(p < TENTH * strongest for p in peaks)
        result["hits"] += len(peaks)
    for wav in sorted(corpus.glob("breakbeat-*.wav")):
        if wav.stem.endswith("-noise"):
            continue
        drive, _, _ = render(wav)
        _, level = meter_p(tactus, drive, name, out / f"{wav.stem}.meter.csv")
        result["p_max"] = max(result["p_max"], float(np.max(level)))
        result["p_engaged"].append(float(np.mean(level > 0)))
    return result


def section(results):
    reference = next(r for r in results if r["name"] == "voice-coil")["engaged"]
    lines = ["## Through each actuator (isolated hits and clean breakbeats)", "",
             "Each profile's render (`--actuator NAME`, the default preset) run through the "
             "profile's time-domain model (`tactus simulate`: an LRA's resonance, an ERM's spin-up "
             "and speed-tied frequency) and measured as felt (eval/felt.py) on the displacement. "
             "snare/kick: the ratio of the median felt pulse frequencies, worst kit; rho: hit gain "
             "-> felt peak, worst kit and instrument; weak: hits felt below a tenth of their kit's "
             "strongest; engaged: hits whose P level (`tactus meter RENDER --actuator NAME`) is "
             "above threshold within 150 ms of the onset, of those the voice-coil render engages; "
             "P max and engaged %: over the clean breakbeats (largest level; mean share of time); "
             "in band: the worst file's energy within the profile's usable band, of the drive and "
             "of the displacement.", "",
             "| actuator | snare/kick (worst kit) | rho (worst) | weak hits | engaged | "
             "P max dB SL | P engaged % | drive in band | displacement in band |",
             "|---|---|---|---|---|---|---|---|---|"]
    for r in results:
        worst_kit = min(r["ratios"], key=r["ratios"].get)
        kept = sum(1 for hit, on in reference.items() if on and r["engaged"].get(hit))
        lines.append(
            f"| {r['name']} | {r['ratios'][worst_kit]:.2f} ({worst_kit}) | {min(r['rho']):.3f} | "
            f"{r['weak']} of {r['hits']} | {kept} of {sum(reference.values())} | "
            f"{r['p_max']:.1f} | {100 * np.mean(r['p_engaged']):.1f} | "
            f"{100 * r['drive_share']:.1f} % | {100 * r['displacement_share']:.1f} % |")
    lines += ["", "Felt snare/kick per kit:", ""]
    for r in results:
        lines.append(f"- {r['name']}: " + ", ".join(f"{kit} {ratio:.2f}"
                                                    for kit, ratio in r["ratios"].items()))
    lines += ["", "Warnings the renders printed (one line per profile):", ""]
    for r in results:
        for w in sorted(r["warnings"]) or ["(none)"]:
            lines.append(f"- {r['name']}: `{w}`")
    return lines


def evaluate(build_dir, corpus, work, preset="music", render_tactus=None):
    tactus = build_dir / "bin/tactus"
    args = argparse.Namespace(preset=preset)
    actuators_dir = pathlib.Path(__file__).resolve().parent.parent / "actuators"
    results = [measure(args, tactus, render_tactus or tactus, corpus, work, name,
                       usable_band(actuators_dir, name)) for name in PROFILES]
    return section(results)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("build_dir", type=pathlib.Path)
    parser.add_argument("corpus", type=pathlib.Path)
    parser.add_argument("--work", type=pathlib.Path, default=None)
    parser.add_argument("--preset", default="music")
    parser.add_argument("--render", type=pathlib.Path, default=None,
                        help="the tactus that renders (default: BUILD_DIR's)")
    args = parser.parse_args()
    work = args.work or pathlib.Path(tempfile.mkdtemp(prefix="tactus-actuators-"))
    print("\n".join(evaluate(args.build_dir, args.corpus, work, args.preset, args.render)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
