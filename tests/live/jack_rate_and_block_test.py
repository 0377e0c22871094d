"""A JACK server sets the rate and the block size (dummy driver at 48 kHz, 256 frames): `tactus
live --block 64` says in one line that the server runs 256; a file at 22.05 kHz is converted for
the player (its tone comes out at its frequency, level and length); `--rate 22050` is refused in
one line that says the server's rate, before anything plays.

usage: jack_rate_and_block_test.py TACTUS LIVE_TEST_CLIENT"""

import os
import sys

import numpy as np
import soundfile

from jack_server import JackServer, check

tactus, client = sys.argv[1:3]
RATE_HZ, FILE_RATE_HZ, TONE_HZ, SECONDS = 48000, 22050, 1000.0, 1.5
jack = JackServer(RATE_HZ, 256)
d = jack.dir

t = np.arange(int(SECONDS * FILE_RATE_HZ)) / FILE_RATE_HZ
path = os.path.join(d, "tone22k.wav")
soundfile.write(path, (0.5 * np.sin(2 * np.pi * TONE_HZ * t)).astype(np.float32), FILE_RATE_HZ,
                subtype="FLOAT")

out = os.path.join(d, "rec.wav")
recorder = jack.client(client, "record", "rec", "2", str(SECONDS + 4), out)
live = jack.run([tactus, "live", "--backend", "jack", "--play", path, "--output", "rec",
                 "--sound-channels", "2", "--block", "64", "--duration", "20"])
print(live.stderr, end="")
check(live.returncode == 0, "tactus live plays the 22.05 kHz file on the 48 kHz server")
check("tactus: --block 64: the JACK server runs 256 frames a block; using 256\n" in live.stderr,
      "--block 64: one line says the server runs 256")
check(f"tactus: {path}: 22050 Hz, converted to the device's 48000 Hz\n" in live.stderr,
      "one line says the file is converted")
recorder.terminate()
recorder.wait(timeout=30)
sound = soundfile.read(out, dtype="float32")[0][:, 1]
loud = np.flatnonzero(np.abs(sound) > 0.05)
played = sound[loud[0]:loud[-1] + 1]
length_s = len(played) / RATE_HZ
spectrum = np.abs(np.fft.rfft(played * np.hanning(len(played))))
peak_hz = np.argmax(spectrum) * RATE_HZ / len(played)
middle = played[len(played) // 4: 3 * len(played) // 4]
level_db = 20 * np.log10(np.sqrt(np.mean(middle ** 2)) * np.sqrt(2) / 0.5)
print(f"played {length_s:.4f} s, tone at {peak_hz:.1f} Hz, level {level_db:+.3f} dB re the file's")
check(abs(length_s - SECONDS) < 1e-3, "as long as the file")
check(abs(peak_hz - TONE_HZ) < 2, "the tone at its frequency")
check(abs(level_db) < 0.05, "and its level")

refused = jack.run([tactus, "live", "--backend", "jack", "--play", path, "--output", "system",
                    "--rate", "22050", "--duration", "2"])
lines = refused.stderr.strip().splitlines()
print(refused.stderr, end="")
check(refused.returncode != 0 and len(lines) == 1, "--rate 22050: refused, one line")
check(lines[0].startswith("tactus: error: --rate 22050: the JACK server runs at 48000 Hz"),
      "naming the option and the server's rate")
