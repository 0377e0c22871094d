"""tactus live with an instrument's input on a real JACK server (dummy driver): the test's JACK
client plays the Amen break into `tactus live --input src` (both channels, downmixed by the
engine); tactus hears every onset `tactus render` finds in the file, and the vibration it plays
has the render's envelope, and a level within the range the render's own takes when the file starts
at each point of the analysis hop grid (the stream starts at an arbitrary one, so the two agree
closely, not sample for sample).

usage: input_live_test.py TACTUS LIVE_TEST_CLIENT"""

import os
import re
import subprocess
import sys

import numpy as np
import soundfile

from jack_server import JackServer, check

tactus, client = sys.argv[1:3]
AMEN = "/usr/share/sonic-pi/samples/loop_amen.flac"
jack = JackServer(44100)
d = jack.dir

rendered_path = os.path.join(d, "render.wav")
r = jack.run([tactus, "render", AMEN, "-o", rendered_path])
check(r.returncode == 0, "tactus render exits 0")
pulses = int(re.search(r"(\d+) pulses", r.stderr).group(1))
rendered = soundfile.read(rendered_path, dtype="float32")[0]


def energy(x):
    return float(np.sum(np.asarray(x, dtype=np.float64) ** 2))


# Each pulse's amplitude is read from the analysis frame its onset lands on, so where the hop grid
# (analysis.hop_ms, 64 samples here at the default preset) falls on the file moves the render's
# level (by about 2.5 dB on the Amen break): the file rendered after 0, 8, 16, ... samples of
# silence, across one hop, gives the range the live level may take.
amen, amen_rate = soundfile.read(AMEN, dtype="float32")
shown = jack.run([tactus, "presets", "--show", "music"]).stdout
hop_samples = int(round(float(re.search(r"analysis\.hop_ms\s+([\d.]+)", shown).group(1)) * 1e-3 *
                        amen_rate))
phase_levels_db = []
for delay in range(0, hop_samples, 8):
    shifted_path, out_path = os.path.join(d, "shifted.wav"), os.path.join(d, "shifted-render.wav")
    soundfile.write(shifted_path, np.concatenate([np.zeros((delay,) + amen.shape[1:], np.float32),
                                                  amen]), amen_rate, subtype="FLOAT")
    r = jack.run([tactus, "render", shifted_path, "-o", out_path, "--force"])
    check(r.returncode == 0, f"tactus render exits 0 ({delay} samples of silence first)")
    phase_levels_db.append(10 * np.log10(energy(soundfile.read(out_path)[0]) / energy(rendered)))
print(f"render level at each hop phase: {min(phase_levels_db):+.2f} to {max(phase_levels_db):+.2f} dB")

recording_path = os.path.join(d, "rec.wav")
recorder = jack.client(client, "record", "rec", "1", "12", recording_path)
jack.client(client, "play", "src", AMEN)
live = jack.run([tactus, "live", "--backend", "jack", "--input", "src", "--output", "rec",
                 "--duration", "6"])
print(live.stderr, end="")
check(live.returncode == 0, "tactus live --input exits 0")
heard = int(re.search(r"(\d+) onsets", live.stderr).group(1))
check(heard == pulses, f"every onset of the file heard ({heard} of {pulses})")
recorder.terminate()
recorder.wait(timeout=30)
recording = soundfile.read(recording_path, dtype="float32")[0]

# The pulses start at analysis frames, whose grid (1.45 ms, whole 16 kHz samples) falls on the
# stream at an arbitrary phase: a pulse may start up to a hop apart from the render's, and its
# carrier with it. Compared is what that leaves alone, the envelope (|x| over 5 ms windows),
# aligned by cross-correlation, and the level.
window = int(0.005 * 44100)


def envelope(x):
    return np.convolve(np.abs(x), np.ones(window) / window, mode="same")


rendered_env, recording_env = envelope(rendered), envelope(recording)
size = 1 << int(np.ceil(np.log2(len(recording) + len(rendered))))
corr = np.fft.irfft(np.fft.rfft(recording_env, size) * np.conj(np.fft.rfft(rendered_env, size)),
                    size)
lag = int(np.argmax(corr[:len(recording) - len(rendered) + 1]))
live_out = recording[lag:lag + len(rendered)]
live_env = recording_env[lag:lag + len(rendered)]
similarity = np.dot(live_env, rendered_env) / np.sqrt(np.sum(live_env ** 2) *
                                                      np.sum(rendered_env ** 2))
level_db = 10 * np.log10(energy(live_out) / energy(rendered))
print(f"envelope correlation with the render {similarity:.3f}, level {level_db:+.2f} dB")
check(similarity > 0.9, "the vibration has the render's envelope")
check(min(phase_levels_db) - 0.5 < level_db < max(phase_levels_db) + 0.5,
      "and a level the render takes at some hop phase (within 0.5 dB)")
