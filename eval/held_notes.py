#!/usr/bin/python3
"""Held synth notes: one onset each, their start, or a pulse train.

usage: eval/held_notes.py BUILD_DIR [--work DIR] [--preset music]

A held note is one onset. A sawtooth held 3 s at 48 kHz (additive, every harmonic below 0.45 of
the rate, -10 dBFS peak, a 0.2 s fade-out), at bass and lead pitches, as it is and low-passed at
2 kHz (2nd-order Butterworth, as synth basses are filtered): `tactus onsets` should print one
line for each. The short onset window sees a part of a low note's period, and the window's edge
crossing the wave's step each period reads as a rise (src/tactus/analysis/onset_detector.hpp,
kSpanMs); with `onset.min_interval_ms` 50 a note that re-triggers every period gives about 55.
"""
import sys

import numpy as np
import scipy.signal
import soundfile

from shared import onset_times_s, section_main

RATE_HZ = 48000
PITCHES_HZ = (41.2, 55.0, 65.4, 82.4, 110.0, 146.8, 220.0, 440.0)  # E1 A1 C2 E2 A2 D3 A3 A4
HELD_S, FADE_S, LEAD_S = 3.0, 0.2, 0.1
LOW_PASS_HZ = 2000


def sawtooth(frequency_hz):
    """The held note with its silence before and after."""
    t = np.arange(int(HELD_S * RATE_HZ)) / RATE_HZ
    harmonics = np.arange(1, int(0.45 * RATE_HZ / frequency_hz) + 1)
    wave = np.zeros_like(t)
    for k in harmonics:
        wave += np.sin(2 * np.pi * k * frequency_hz * t) / k
    wave *= 0.3 * 2 / np.pi
    wave *= np.minimum(1.0, (len(t) - np.arange(len(t))) / (FADE_S * RATE_HZ))
    return np.concatenate([np.zeros(int(LEAD_S * RATE_HZ)), wave, np.zeros(int(LEAD_S * RATE_HZ))])


def measure(build_dir, work, preset="music"):
    """Per pitch: onsets of the full-band note and of the low-passed one."""
    tactus = str(build_dir / "bin/tactus")
    work.mkdir(parents=True, exist_ok=True)
    low_pass = scipy.signal.butter(2, LOW_PASS_HZ, fs=RATE_HZ, output="sos")
    rows = []
    for hz in PITCHES_HZ:
        note = sawtooth(hz)
        counts = []
        for name, x in (("full", note), ("low-passed", scipy.signal.sosfilt(low_pass, note))):
            wav = work / f"sawtooth-{hz:g}-{name}.wav"
            soundfile.write(wav, x, RATE_HZ, subtype="FLOAT")
            counts.append(len(onset_times_s(tactus, wav, preset)))
        rows.append({"pitch": hz, "full": counts[0], "low": counts[1]})
    return rows


def section(rows):
    """The report's section: one row per pitch."""
    lines = ["## Held synth notes", "",
             f"A sawtooth held {HELD_S:g} s at {RATE_HZ // 1000} kHz (every harmonic, -10 dBFS "
             f"peak) and the same low-passed at {LOW_PASS_HZ // 1000} kHz, as synth basses are "
             "(`eval/held_notes.py`): `tactus onsets` per note; one is its start, more are "
             "pulses the note's own period gives.", "",
             "| pitch Hz | onsets, every harmonic | onsets, low-passed |", "|---|---|---|"]
    lines += [f"| {r['pitch']:g} | {r['full']} | {r['low']} |" for r in rows]
    return lines


if __name__ == "__main__":
    sys.exit(section_main(__doc__, measure, section, "tactus-held-"))
