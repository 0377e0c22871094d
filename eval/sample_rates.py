#!/usr/bin/python3
"""The same music at every sample rate: the Amen break resampled, rendered and compared.

usage: eval/sample_rates.py BUILD_DIR [--work DIR] [--preset tfd]

Sonic Pi's loop_amen_full.flac (44.1 kHz) is resampled to each rate with
scipy.signal.resample_poly (exact ratios), then `tactus onsets` and `tactus render` run on each
file. Against the 44.1 kHz original: the onsets matched one-to-one within 1 ms (mir_eval), the
pulses (onsets the render answers with a felt pulse), and for each 44.1 kHz onset the felt pulse
(eval/felt.py, measured from that onset in both renders) its frequency and peak, the worst
deviations over all pulses; then each render's output peak.
"""
import math
import pathlib
import sys

import mir_eval
import numpy as np
import scipy.signal
import soundfile

import felt
from shared import onset_times_s, run, section_main

AMEN = pathlib.Path("/usr/share/sonic-pi/samples/loop_amen_full.flac")
REFERENCE_HZ = 44100
RATES_HZ = (16000, 22050, 32000, 44100, 48000, 88200, 96000, 176400, 192000)
MATCH_S = 0.001
PULSE_FLOOR_DB = -40  # a pulse: a felt peak within this of the render's loudest


def measure(build_dir, work, preset="music"):
    """Per rate: onsets, matched, pulses, worst frequency deviation %, worst peak deviation dB,
    output peak dBFS."""
    tactus = str(build_dir / "bin/tactus")
    work.mkdir(parents=True, exist_ok=True)
    x, rate = soundfile.read(AMEN, dtype="float64", always_2d=True)
    if rate != REFERENCE_HZ:
        raise RuntimeError(f"{AMEN}: expected {REFERENCE_HZ} Hz, got {rate}")
    runs = {}
    for hz in RATES_HZ:
        g = math.gcd(hz, REFERENCE_HZ)
        y = x if hz == REFERENCE_HZ else scipy.signal.resample_poly(
            x, hz // g, REFERENCE_HZ // g, axis=0)
        wav = work / f"amen-{hz}.wav"
        soundfile.write(wav, y, hz, subtype="FLOAT")
        out = work / f"amen-{hz}.vibration.wav"
        run([tactus, "render", str(wav), "-o", str(out), "--force", "--preset", preset])
        vibration, _ = soundfile.read(out, dtype="float64", always_2d=True)
        runs[hz] = (onset_times_s(tactus, wav, preset), vibration[:, 0])
    reference_onsets, reference_out = runs[REFERENCE_HZ]
    reference = felt.pulses(reference_out, REFERENCE_HZ, reference_onsets)
    rows = []
    for hz in RATES_HZ:
        onsets, y = runs[hz]
        matched = len(mir_eval.util.match_events(reference_onsets, onsets, MATCH_S))
        own = felt.pulses(y, hz, onsets)
        loudest = max((p for p, _, _ in own), default=0.0)
        pulses = sum(1 for p, _, _ in own if p > 0 and 20 * np.log10(p / loudest) > PULSE_FLOOR_DB)
        at_reference = felt.pulses(y, hz, reference_onsets)
        hz_dev = max(abs(f / fr - 1) * 100 for (_, f, _), (_, fr, _) in zip(at_reference, reference)
                     if fr > 0 and f > 0)
        db_dev = max(abs(20 * np.log10(p / pr)) for (p, _, _), (pr, _, _) in zip(at_reference, reference)
                     if pr > 0 and p > 0)
        peak = float(np.max(np.abs(y)))
        rows.append({"rate": hz, "onsets": len(onsets), "matched": matched, "pulses": pulses,
                     "hz_dev": hz_dev, "db_dev": db_dev, "peak_dbfs": 20 * np.log10(peak)})
    return rows


def section(rows):
    """The report's section: one row per rate."""
    lines = ["## Sample rates", "",
             "Sonic Pi's loop_amen_full.flac resampled from 44.1 kHz (scipy.signal.resample_poly, "
             "exact ratios; `eval/sample_rates.py`). Matched: onsets within 1 ms of a 44.1 kHz "
             "onset (one-to-one); pulses: onsets answered by a felt pulse within 40 dB of the "
             "loudest; Hz and dB: the worst deviation over the 44.1 kHz onsets of the felt pulse "
             "frequency and peak (eval/felt.py) from the 44.1 kHz render's.", "",
             "| rate Hz | onsets | matched within 1 ms | pulses | worst felt Hz deviation % "
             "| worst felt peak deviation dB | output peak dBFS |",
             "|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['rate']} | {r['onsets']} | {r['matched']} | {r['pulses']} | "
                     f"{r['hz_dev']:.2f} | {r['db_dev']:.2f} | {r['peak_dbfs']:.2f} |")
    return lines


if __name__ == "__main__":
    sys.exit(section_main(__doc__, measure, section, "tactus-rates-"))
