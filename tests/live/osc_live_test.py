"""OSC control and monitoring of `tactus live` on a real JACK server (dummy driver): a parameter
sent with liblo while the file plays changes the actuator output exactly as the same --set does
offline (`tactus render --set`) from that point on, after its glide and the limiter's release; the
output up to that point is the render without it. A listener receives the features, the
vibration program at --osc-rate and each onset once, with its drum part and strength. Bad messages get one line on stderr each and
change nothing. A parameter's address without a value is answered, to the sender's port, with
the value in force; a set is answered with the value it put in force.

usage: osc_live_test.py TACTUS LIVE_TEST_CLIENT SOURCE_DIR"""

import os
import subprocess
import sys
import time

import numpy as np
import soundfile

from jack_server import JackServer, check, fail, free_udp_port

tactus, client, source_dir = sys.argv[1:4]
AMEN = "/usr/share/sonic-pi/samples/loop_amen_full.flac"  # 6.9 s
RATE_HZ = 44100
KEY, VALUE = "post.drive_db", "0"  # from the preset's 12 dB
OSC_RATE_HZ = 50
jack = JackServer(RATE_HZ)
d = jack.dir


def render(name, *extra):
    path = os.path.join(d, name + ".wav")
    r = jack.run([tactus, "render", AMEN, "-o", path, *extra])
    check(r.returncode == 0, f"tactus render {' '.join(extra)} exits 0")
    # The file's length: the player stops with it (the render rings the tail out after it).
    return soundfile.read(path, dtype="float32")[0][:soundfile.info(AMEN).frames]


before = render("before")
after = render("after", "--set", f"{KEY}={VALUE}")
check(np.max(np.abs(before - after)) > 0.01, f"--set {KEY}={VALUE} changes the render")
n = len(before)

seconds = soundfile.info(AMEN).duration + 4
recording_path = os.path.join(d, "rec.wav")
recorder = jack.client(client, "record", "rec", "1", str(seconds), recording_path)
control_port, listen_port = free_udp_port(), free_udp_port()
listener = jack.client(client, "osc-listen", str(listen_port), str(seconds))
live = jack.start([tactus, "live", "--backend", "jack", "--play", AMEN, "--output", "rec",
                   "--osc-port", str(control_port), "--osc-send", f"127.0.0.1:{listen_port}",
                   "--osc-rate", str(OSC_RATE_HZ), "--duration", "30"],
                  stderr=subprocess.PIPE, text=True)
started = live.stderr.readline()
print(started, end="")
check("live on rec" in started, "tactus live started")
time.sleep(2.5)


def send(*args):
    r = jack.run([client, "osc-send", str(control_port), *args])
    check(r.returncode == 0, f"sent {' '.join(args)}")


# Refused, each with one line: nothing they carry may reach the output.
send("/tactus/post.drive_db", "f", "99")          # out of range
send("/tactus/post.drive", "f", "0")              # unknown
send("/tactus/post.drive_db", "s", "loud")        # wrong type
send("/tactus/actuator/3/gain", "f", "-6")        # no such actuator


def ask(*args):
    """One message from the client's own port: the answer, as the client prints it."""
    r = jack.run([client, "osc-ask", str(control_port), "2", *args])
    check(r.returncode == 0, f"asked {' '.join(args)}")
    return r.stdout.strip()


was = ask(f"/tactus/{KEY}")
print(f"the answer to /tactus/{KEY}: {was!r}")
check(was == f"/tactus/{KEY} 12", "a question is answered with the value in force (the preset's)")
now = ask(f"/tactus/{KEY}", "f", VALUE)
print(f"the answer to /tactus/{KEY} {VALUE}: {now!r}")
check(now == f"/tactus/{KEY} {VALUE}", "a set is answered with the value it put in force")
live.wait(timeout=60)
messages = live.stderr.read()
print(messages, end="")
check(live.returncode == 0, "tactus live exits 0")
refusals = [line for line in messages.splitlines() if line.startswith("tactus: osc ")]
check(len(refusals) == 4, f"four refused messages, one line each ({len(refusals)})")
recorder.terminate()
recorder.wait(timeout=30)
listener.terminate()
heard = listener.communicate(timeout=30)[0].splitlines()

recording = soundfile.read(recording_path, dtype="float32")[0]
nz = np.flatnonzero(recording)
check(len(nz) > 0, "the actuator output was recorded")
# The stream's start: the render's first non-zero sample.
start = int(nz[0]) - int(np.flatnonzero(before)[0])
live_out = recording[start:start + n]
check(len(live_out) == n, "the recording holds the whole file")
tolerance = 1e-5
differs_before = np.flatnonzero(np.abs(live_out - before) > tolerance)
differs_after = np.flatnonzero(np.abs(live_out - after) > tolerance)
change_at = int(differs_before[0]) if len(differs_before) else n
settled_at = int(differs_after[-1]) + 1 if len(differs_after) else 0
print(f"the output leaves the plain render at {change_at / RATE_HZ:.3f} s and equals the "
      f"--set render from {settled_at / RATE_HZ:.3f} s on (the file: {n / RATE_HZ:.2f} s)")
check(change_at > 0.25 * RATE_HZ, "up to the message, the output is the render without --set")
check(settled_at - change_at < 1.0 * RATE_HZ,
      "within 1 s (the glide and the limiter's release) it equals the render with --set")
check(n - settled_at > 1.0 * RATE_HZ, "and stays equal to the end of the file")

# ---- what the listener heard ----
features = [line.split() for line in heard if line.startswith("/tactus/features ")]
vibration = [line.split() for line in heard if line.startswith("/tactus/vibration ")]
onsets = [line.split() for line in heard if line.startswith("/tactus/onset ")]
played_s = n / RATE_HZ
print(f"listener: {len(features)} features, {len(vibration)} vibration, {len(onsets)} onsets")
check(len(features) >= 0.8 * OSC_RATE_HZ * played_s, "features arrive at --osc-rate")
check(len(features) <= 1.2 * OSC_RATE_HZ * (played_s + 1), "and no faster")
check(all(len(f) == 5 for f in features), "loudness_db brightness_hz noisiness pitch_hz")
loudness = np.array([float(f[1]) for f in features])
check(np.max(loudness) > -30 and np.min(loudness) < np.max(loudness) - 3,
      "the loudness follows the drums")
check(len(vibration) == len(features) and all(len(v) == 3 for v in vibration),
      "vibration frequency_hz amplitude with each")
check(len(onsets) >= 10 and all(len(o) == 3 for o in onsets), "onsets: part strength_db")
parts = [o[1] for o in onsets]
check(all(p in ("kick", "snare", "hat", "other") for p in parts), f"drum parts by name: {set(parts)}")
# dB LKFS: K-weighting's +4 dB shelf lifts a loud hit a little past 0
check(all(-90 < float(o[2]) < 6 for o in onsets), "strengths in dB (LKFS scale)")
# One message per onset, with the parts `tactus onsets` prints for the file (live, the analysis
# hop grid starts before the file does: a part may differ here and there).
printed = jack.run([tactus, "onsets", AMEN])
expected = [line.split()[3] for line in printed.stdout.splitlines()]
print(f"parts sent    {' '.join(parts)}\nparts printed {' '.join(expected)}")
check(abs(len(parts) - len(expected)) <= 1, "one message per onset")
for part in set(parts) | set(expected):
    check(abs(parts.count(part) - expected.count(part)) <= max(2, 0.1 * expected.count(part)),
          f"{part}: {parts.count(part)} sent, {expected.count(part)} printed")
