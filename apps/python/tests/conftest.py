"""Shared fixtures: the tactus command line (TACTUS_CLI, set by ctest), the Amen break and a
stereo 48 kHz file made from it, and running the command line for reference outputs."""

import os
import pathlib
import subprocess

import numpy as np
import pytest
import soundfile

import tactus

AMEN = pathlib.Path("/usr/share/sonic-pi/samples/loop_amen_full.flac")


@pytest.fixture(scope="session")
def cli():
    path = os.environ.get("TACTUS_CLI")
    if not path:
        pytest.fail("TACTUS_CLI names the tactus program (ctest sets it)")
    return path


def run(cli, *args):
    """Runs `tactus ARGS`; returns its stdout. Fails the test on a non-zero exit."""
    done = subprocess.run([cli, *map(str, args)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return done.stdout


def cli_error(cli, *args):
    """The one-line message of a command that must fail."""
    done = subprocess.run([cli, *map(str, args)], capture_output=True, text=True)
    assert done.returncode != 0
    return done.stderr.strip().splitlines()[-1].removeprefix("tactus: error: ")


def read_wav(path):
    samples, rate = soundfile.read(path, dtype="float32", always_2d=True)
    return samples, rate


@pytest.fixture(scope="session")
def amen():
    assert AMEN.exists(), "the Amen break comes with sonic-pi-samples"
    return AMEN


@pytest.fixture(scope="session")
def stereo_48k(tmp_path_factory):
    """The Amen break at 48 kHz, 24-bit stereo, its right channel a tenth of a second late and
    6 dB down (two different channels)."""
    path = tmp_path_factory.mktemp("audio") / "amen_48k_stereo.wav"
    subprocess.run(["sox", "-q", str(AMEN), "-r", "48000", "-b", "24", str(path),
                    "remix", "1", "2v0.5", "delay", "0", "0.1"], check=True)
    info = soundfile.info(str(path))
    assert (info.samplerate, info.channels) == (48000, 2)
    return path
