"""tactus calibrate on a real JACK server (dummy driver): the test's JACK client stands in for an
actuator and its sensor, filtering what it gets with the lra-175 profile's band-pass resonance;
the profile tactus calibrate writes matches lra-175's response within 1 dB over its usable band
(150-235 Hz), and `tactus render --actuator` loads it.

usage: calibrate_test.py TACTUS LIVE_TEST_CLIENT SOURCE_DIR"""

import math
import os
import sys
import tomllib

import numpy as np
import soundfile

from jack_server import JackServer, check

tactus, client, source_dir = sys.argv[1:4]
jack = JackServer(48000)
d = jack.dir
lra_path = os.path.join(source_dir, "actuators", "lra-175.toml")
with open(lra_path, "rb") as f:
    lra = tomllib.load(f)

jack.client(client, "filter", "lra", lra_path)
profile_path = os.path.join(d, "measured.toml")
r = jack.run([tactus, "calibrate", "--backend", "jack", "--output", "lra:1", "--input", "lra:1",
              "-o", profile_path, "--seconds", "3"])
print(r.stderr, end="")
check(r.returncode == 0, "tactus calibrate exits 0")
with open(profile_path, "rb") as f:
    measured = tomllib.load(f)


def lra_response_db(f):
    """The lra-175 profile's response (actuator/profile.hpp: the band-pass term, 0 dB at its
    reference, which is its resonance)."""
    q, f0 = lra["response"]["q"], lra["response"]["resonance_hz"]
    def shape(x):
        x = x / f0
        return -10 * math.log10(1 + q * q * (x - 1 / x) ** 2)
    return shape(f) - shape(lra["reference_hz"])


def measured_response_db(f):
    """The written profile: its points on a log-frequency axis, no model, no roll-off."""
    hz, db = np.array(measured["response"]["points"]).T
    return float(np.interp(math.log(f), np.log(hz), db))


check(measured["rolloff_db_per_octave"] == 0 and measured["response"]["kind"] == "none",
      "the measured points are the whole response")
band = np.geomspace(lra["band_low_hz"], lra["band_high_hz"], 40)
errors = [measured_response_db(f) - lra_response_db(f) for f in band]
print(f"measured - lra-175 over {lra['band_low_hz']}-{lra['band_high_hz']} Hz: "
      f"largest {max(abs(e) for e in errors):.2f} dB")
check(max(abs(e) for e in errors) <= 1.0, "the measured profile matches lra-175 within 1 dB")
check(abs(measured["reference_hz"] - 175) < 5, "its peak is the resonance")

# The profile as --actuator loads it.
hits = os.path.join(d, "tone.wav")
t = np.arange(48000) / 48000
soundfile.write(hits, (0.5 * np.sin(2 * np.pi * 220 * t) * (t % 0.25 < 0.05)).astype(np.float32),
                48000, subtype="FLOAT")
r = jack.run([tactus, "render", hits, "-o", os.path.join(d, "out.wav"), "--actuator", profile_path])
print(r.stderr, end="")
check(r.returncode == 0, "tactus render --actuator loads the measured profile")
