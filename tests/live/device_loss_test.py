"""A device that disappears while `tactus live` runs: the JACK server is stopped under it and
started again. tactus says so in one line, keeps the engine, retries until the server returns,
plays on and exits 0 at --duration; it never crashes.

usage: device_loss_test.py TACTUS"""

import subprocess
import sys
import time

from jack_server import JackServer, check

tactus = sys.argv[1]
jack = JackServer(44100)
live = jack.start([tactus, "live", "--backend", "jack", "--play",
                   "/usr/share/sonic-pi/samples/loop_amen.flac", "--loop", "--duration", "8"],
                  stderr=subprocess.PIPE, text=True)
check("live on" in live.stderr.readline(), "tactus live started")
time.sleep(2)
jack.stop_server()
time.sleep(2)
jack.start_server()
live.wait(timeout=60)
messages = live.stderr.read()
print(messages, end="")
check(live.returncode == 0, "tactus live exits 0 at --duration")
check("the audio device stopped after" in messages, "the loss is said")
check("the audio device is back" in messages, "and the return")
before_s = float(messages.split("the audio device stopped after ")[1].split(" s")[0])
played_s = float(messages.split("tactus: stopped after ")[1].split(" s")[0])
check(played_s > before_s + 0.5,
      f"it played on after the return ({before_s:.2f} s of audio before, {played_s:.2f} s in all)")
