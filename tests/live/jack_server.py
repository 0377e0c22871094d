"""A JACK server of a test's own (dummy driver, a unique name so parallel tests never collide),
the project's JACK test client beside it, and the tactus command line run against them.

A test that cannot start jackd exits with SKIP (77, ctest's SKIP_RETURN_CODE) and says why;
everything started is stopped on exit, whatever happens."""

import atexit
import ctypes
import os
import re
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time

import numpy as np

SKIP = 77
PR_SET_PDEATHSIG = 1


def _die_with_parent():
    """In each child: SIGTERM when the test's process dies, even by SIGKILL (a ctest timeout)."""
    ctypes.CDLL("libc.so.6", use_errno=True).prctl(PR_SET_PDEATHSIG, signal.SIGTERM)


def _exit_on_signal(signum, frame):
    sys.exit(128 + signum)  # runs the atexit clean-up


class JackServer:
    def __init__(self, rate_hz, period=256):
        self.name = f"tactus-test-{os.getpid()}"
        self.env = dict(os.environ, JACK_DEFAULT_SERVER=self.name, JACK_NO_AUDIO_RESERVATION="1")
        self.dir = tempfile.mkdtemp(prefix="tactus-jack-")
        self.processes = []
        atexit.register(self.close)
        signal.signal(signal.SIGTERM, _exit_on_signal)
        signal.signal(signal.SIGINT, _exit_on_signal)
        if shutil.which("jackd") is None:
            skip("jackd is not installed (Debian jackd2)")
        self.rate_hz, self.period = rate_hz, period
        self.start_server()

    def start_server(self):
        log = open(os.path.join(self.dir, "jackd.log"), "a")
        self.jackd = subprocess.Popen(
            # Synchronous (-S): a cycle waits for every client, so a machine too busy for the
            # period slows the dummy clock down instead of dropping blocks.
            ["jackd", "--no-realtime", "-S", "-n", self.name, "-d", "dummy", "-r",
             str(self.rate_hz), "-p", str(self.period)],
            stdout=log, stderr=subprocess.STDOUT, env=self.env, start_new_session=True,
            preexec_fn=_die_with_parent)
        self.processes.append(self.jackd)
        for _ in range(100):
            if self.jackd.poll() is not None:
                break
            if subprocess.run(["jack_lsp"], env=self.env, capture_output=True).returncode == 0:
                return
            time.sleep(0.1)
        log.flush()
        with open(os.path.join(self.dir, "jackd.log")) as f:
            tail = f.read().strip().splitlines()[-3:]
        skip("jackd could not start: " + " | ".join(tail))

    def stop_server(self):
        """The server goes away (as a device that disappears)."""
        self.jackd.send_signal(signal.SIGTERM)
        self.jackd.wait(timeout=10)

    def start(self, args, **kwargs):
        """A process of the test, stopped (SIGTERM) at the end if still running."""
        p = subprocess.Popen(args, env=self.env, start_new_session=True,
                             preexec_fn=_die_with_parent, **kwargs)
        self.processes.append(p)
        return p

    def client(self, program, *args):
        """The test's JACK client; returns once it printed "ready"."""
        p = self.start([program, *args], stdout=subprocess.PIPE, text=True)
        line = p.stdout.readline().strip()
        if line != "ready":
            fail(f"{program} {' '.join(args)} did not start ({line!r})")
        return p

    def run(self, args, timeout_s=120):
        return subprocess.run(args, env=self.env, capture_output=True, text=True, timeout=timeout_s)

    def close(self):
        for p in reversed(self.processes):
            if p.poll() is None:
                p.send_signal(signal.SIGTERM)
                try:
                    p.wait(timeout=10)
                except subprocess.TimeoutExpired:
                    p.kill()
                    p.wait()
        self.processes = []
        shutil.rmtree(self.dir, ignore_errors=True)


def skip(why):
    print(f"SKIP: {why}")
    sys.exit(SKIP)


def fail(why):
    print(f"FAIL: {why}")
    sys.exit(1)


def xruns(stderr):
    """The xruns `tactus live` reported when it stopped ("..., N xruns"; 0 if it did not say):
    periods the machine missed."""
    found = re.search(r"(\d+) xruns", stderr)
    return int(found.group(1)) if found else 0


def check(condition, what):
    print(("ok: " if condition else "FAIL: ") + what)
    if not condition:
        sys.exit(1)


def hits(rate_hz, count, seed=7):
    """Hits of a decaying 80 Hz tone with a sharp attack, at uneven times (0.35 to 0.6 s apart,
    the first at 0.3 s or more): the signal (float32) and the hits' times in seconds."""
    rng = np.random.default_rng(seed)
    hits_s = np.cumsum(rng.uniform(0.35, 0.6, count)) + 0.3
    x = np.zeros(int((hits_s[-1] + 0.8) * rate_hz), dtype=np.float32)
    t = np.arange(int(0.15 * rate_hz)) / rate_hz
    burst = (0.8 * np.exp(-t / 0.03) * np.sin(2 * np.pi * 80 * t + 0.5)
             + 0.3 * np.exp(-t / 0.004) * rng.standard_normal(len(t))).astype(np.float32)
    for h in hits_s:
        i = int(round(h * rate_hz))
        x[i:i + len(burst)] += burst
    return x, hits_s


def onsets(x, threshold, rate_hz):
    """First sample of each run above `threshold` after 100 ms below it."""
    above = np.flatnonzero(np.abs(x) > threshold)
    gap = int(0.1 * rate_hz)
    return np.array([a for k, a in enumerate(above) if k == 0 or a - above[k - 1] > gap])


def free_udp_port():
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]
