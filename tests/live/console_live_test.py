"""Messages of `tactus live` on a terminal: the status line is redrawn in place (\\r), and a
message from another thread (an OSC refusal, a preset reloaded) takes a line of its own above
it instead of being glued to its end. tactus runs against a real JACK server (dummy driver) with
its stderr on a pseudo-terminal; the output is replayed as a terminal shows it.

usage: console_live_test.py TACTUS LIVE_TEST_CLIENT"""

import os
import pty
import subprocess
import sys
import threading
import time

from jack_server import JackServer, check, free_udp_port

tactus, client = sys.argv[1:3]
AMEN = "/usr/share/sonic-pi/samples/loop_amen_full.flac"  # 6.9 s
jack = JackServer(44100)
d = jack.dir


def screen(text):
    """The lines a terminal shows for `text`: \\r goes back to the line's start, ESC[K erases to
    its end, other characters overwrite."""
    lines, line, at = [], [], 0
    i = 0
    while i < len(text):
        if text.startswith("\x1b[K", i):
            del line[at:]
            i += 3
            continue
        c = text[i]
        if c == "\r":
            at = 0
        elif c == "\n":
            lines.append("".join(line))
            line, at = [], 0
        else:
            line[at:at + 1] = [c]
            at += 1
        i += 1
    return lines + ["".join(line)]


preset = os.path.join(d, "mine.toml")
open(preset, "w").write("[envelope]\ndecay_ms = 200\n")
recorder = jack.client(client, "record", "rec", "1", "20", os.path.join(d, "rec.wav"))
port = free_udp_port()
master, terminal = pty.openpty()
live = jack.start([tactus, "live", "--backend", "jack", "--play", AMEN, "--output", "rec",
                   "--osc-port", str(port), "--preset", preset, "--duration", "4.5"],
                  stderr=terminal, stdout=subprocess.DEVNULL)
os.close(terminal)
chunks = []


def read_all():
    while True:
        try:
            data = os.read(master, 4096)
        except OSError:  # EIO: the terminal's last writer closed it
            return
        if not data:
            return
        chunks.append(data)


reader = threading.Thread(target=read_all)
reader.start()
time.sleep(2)  # a few status lines drawn
r = jack.run([client, "osc-send", str(port), "/tactus/post.drive_db", "f", "99"])
check(r.returncode == 0, "sent an out-of-range value")
time.sleep(0.7)
with open(preset + ".new", "w") as f:
    f.write("[envelope]\ndecay_ms = 321\n")
os.rename(preset + ".new", preset)  # as editors save
live.wait(timeout=60)
reader.join(timeout=10)
os.close(master)
output = b"".join(chunks).decode()
lines = screen(output)
print("\n".join(f"| {line}" for line in lines))
check(live.returncode == 0, "tactus live exits 0")
check(output.count("\r") >= 4, "the status line was redrawn in place")
refusal = [line for line in lines if "post.drive_db = 99 is out of range" in line]
reload = [line for line in lines if "mine.toml: reloaded" in line]
check(len(refusal) == 1 and refusal[0].startswith("tactus: osc /tactus/post.drive_db"),
      "the OSC refusal is a line of its own")
check(len(reload) == 1 and reload[0].startswith("tactus: ") and reload[0].endswith("reloaded"),
      "the preset reload is a line of its own")
check(all(line.startswith(("tactus: ", "in ")) or not line for line in lines),
      "every line is a message or the status line, nothing glued together")
after = output.replace("\r\n", "\n").split("allowed -40 to 40 dB\n", 1)[-1]  # the tty's \r\n
check(after.startswith("in ") and "latency" in after.split("\r")[0],
      "the status line drawn again below the message at once")
