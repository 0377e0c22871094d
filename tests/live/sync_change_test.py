"""--sync follows a change of settings: `tactus live --sync` on a real JACK server (dummy driver)
plays hits over a quiet steady tone, and /tactus/analysis.hop_ms 5 sent over OSC on the way makes
the vibration later. The sound's delay follows: onsets line up before and after the change
(median within 1 ms, each within half a hop of it: onsets are decided on the hop grid); the
sound is exactly the file delayed by the delay tactus printed at the start, then by the one it
prints for the new settings, and the move between them is a crossfade: no sample-to-sample step
larger than the two delayed copies' own plus the crossfade's share of the gap between them (an
immediate move would step by that whole gap: a click).

usage: sync_change_test.py TACTUS LIVE_TEST_CLIENT"""

import os
import re
import subprocess
import sys
import time

import numpy as np
import soundfile

from jack_server import JackServer, check, free_udp_port, hits, onsets

tactus, client = sys.argv[1:3]
RATE_HZ = 44100
HOP_MS = 5.0         # from the default 1.45 ms: the onset decision comes later
FADE = 441           # Engine::kCrossfadeMs (10 ms) at 44.1 kHz
jack = JackServer(RATE_HZ)
d = jack.dir

x, hits_s = hits(RATE_HZ, 24)
t = np.arange(len(x)) / RATE_HZ
x += (0.02 * np.sin(2 * np.pi * 220 * t + 0.3)).astype(np.float32)  # a jump in it is a click
n = len(x)
path = os.path.join(d, "hits.wav")
soundfile.write(path, x, RATE_HZ, subtype="FLOAT")

recording_path = os.path.join(d, "rec.wav")
recorder = jack.client(client, "record", "rec", "2", str(n / RATE_HZ + 4), recording_path)
port = free_udp_port()
live = jack.start([tactus, "live", "--backend", "jack", "--play", path, "--output", "rec",
                   "--actuator-channels", "1", "--sound-channels", "2", "--sync",
                   "--osc-port", str(port), "--duration", "40"],
                  stderr=subprocess.PIPE, text=True)
started = live.stderr.readline() + live.stderr.readline()
print(started, end="")
check("live on rec" in started, "tactus live started")
time.sleep(0.45 * n / RATE_HZ)  # the player starts at once: the change comes near the middle
sent = jack.run([client, "osc-send", str(port), "/tactus/analysis.hop_ms", "f", str(HOP_MS)])
check(sent.returncode == 0, f"sent /tactus/analysis.hop_ms {HOP_MS}")
live.wait(timeout=60)
messages = live.stderr.read()
print(messages, end="")
check(live.returncode == 0, "tactus live exits 0")
recorder.terminate()
recorder.wait(timeout=30)
vibration, sound = soundfile.read(recording_path, dtype="float32")[0].T

# ---- onsets line up before and after the change ----
heard = onsets(sound, 0.05, RATE_HZ)
felt = onsets(vibration, 0.1 * np.max(np.abs(vibration)), RATE_HZ)  # sync_delay.hpp's first rise
check(len(heard) == len(hits_s) and len(felt) == len(hits_s),
      f"{len(hits_s)} hits heard ({len(heard)}) and felt ({len(felt)})")
offsets_ms = (felt - heard) * 1000 / RATE_HZ
start = heard[0] - int(round(hits_s[0] * RATE_HZ))  # the file's start in the recording
for name, hop_ms, chosen in [("before", 1.45, hits_s < 0.33 * n / RATE_HZ),
                             ("after", HOP_MS, hits_s > 0.6 * n / RATE_HZ)]:
    o = offsets_ms[chosen]
    print(f"{name} the change: vibration onset - sound onset, ms: "
          + " ".join(f"{v:.2f}" for v in o))
    check(len(o) >= 5 and abs(np.median(o)) <= 1.0, f"{name} the change the median lines up within 1 ms")
    check(np.all(np.abs(o) <= hop_ms / 2 + 0.25), f"{name} it, each within half a {hop_ms} ms hop")

# ---- the sound: exactly delayed, then a crossfade to the new delay ----
first = re.search(r"sound delayed (\d+) frames \(--sync\)", started)
moved = re.findall(r"new settings: .*sound delayed (\d+) frames \(--sync\)", messages)
check(first is not None and len(moved) == 1, "tactus printed the delay, then the new one")
d0, d1 = int(first.group(1)), int(moved[0])
print(f"the sound's delay: {d0} frames, then {d1}")
check(d1 > d0 + 1.0e-3 * RATE_HZ, "the longer hop needs a delay over 1 ms longer")
k0 = int(np.flatnonzero(sound)[0])  # the tone starts at once: the file's first sample, delayed
span = np.arange(k0, k0 + d1 - d0 + n)  # the file, whichever the delay
a = np.where(span - k0 < n, x[np.clip(span - k0, 0, n - 1)], 0)
b = np.where(span - k0 - (d1 - d0) >= 0, x[np.clip(span - k0 - (d1 - d0), 0, n - 1)], 0)
y = sound[span]
differs_a, differs_b = np.flatnonzero(y != a), np.flatnonzero(y != b)
last_a = int(differs_a[0]) - 1 if len(differs_a) else len(y) - 1
first_b = int(differs_b[-1]) + 1 if len(differs_b) else 0
print(f"the old delay up to {(k0 + last_a) / RATE_HZ:.3f} s, the new one from "
      f"{(k0 + first_b) / RATE_HZ:.3f} s of the recording")
check(np.array_equal(y[:last_a + 1], a[:last_a + 1]), "up to the move: the file, delayed by the first delay")
check(first_b < len(y) - RATE_HZ and np.array_equal(y[first_b:], b[first_b:]),
      "from the move to the end: the file, delayed by the new delay")
fade = first_b - last_a - 1
check(0.8 * FADE <= fade <= 1.2 * FADE, f"the move is a crossfade of {fade} samples (10 ms)")
w = slice(max(last_a - 64, 1), first_b + 64)
step = np.abs(np.diff(y))[w.start - 1:w.stop - 1]
own = np.maximum(np.abs(np.diff(a)), np.abs(np.diff(b)))[w.start - 1:w.stop - 1]
gap = np.max(np.abs(b[w] - a[w]))
allowed = own + gap / FADE + 1e-5
print(f"largest step at the move {np.max(step):.4f}, the copies' own {np.max(own):.4f}, "
      f"the gap an immediate move would jump {gap:.4f}")
check(np.all(step <= allowed), "no click: no step beyond the copies' own and the crossfade's share")
# Against the copies' typical step: where the move meets a hit, the hit's own steps are as large
# as the gap, whichever way the move is made.
check(gap > 5 * np.median(allowed), "(an immediate move would have stepped far beyond that)")
