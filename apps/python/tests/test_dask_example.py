"""examples/python/dask_render.py on a two-worker LocalCluster writes, for every folder of a tree,
the files `tactus render -O` writes, sample for sample and in the same format; a file that fails
is reported as the command line reports it and leaves nothing; existing outputs are refused."""

import os
import pathlib
import shutil
import subprocess
import sys

import numpy as np
import pytest
import soundfile

from conftest import cli_error, run

EXAMPLE = pathlib.Path(__file__).parents[3] / "examples" / "python" / "dask_render.py"
SETTINGS = ["envelope.decay_ms=90.125", "mapping.frequency.curve=lin"]


def sound(path):
    """A sound file's rate, format and samples (its chunks of metadata aside: the command line
    says in them how it was made)."""
    info = soundfile.info(path)
    return info.samplerate, info.format, info.subtype, soundfile.read(path, dtype="float32")[0]


def dask_render(*args):
    return subprocess.run([sys.executable, EXAMPLE, *map(str, args)], capture_output=True,
                          text=True, timeout=300)


@pytest.fixture
def tree(tmp_path, amen, stereo_48k):
    """in/a.flac (the Amen break), in/sub/b.wav (48 kHz stereo), in/sub/deeper/c.wav (22.05 kHz
    mono noise), in/sub/broken.wav (not audio), in/notes.txt (not audio, skipped)."""
    root = tmp_path / "in"
    (root / "sub" / "deeper").mkdir(parents=True)
    shutil.copy(amen, root / "a.flac")
    shutil.copy(stereo_48k, root / "sub" / "b.wav")
    subprocess.run(["sox", "-q", "-n", "-r", "22050", "-c", "1", root / "sub" / "deeper" / "c.wav",
                    "synth", "2", "pinknoise", "tremolo", "4", "90"], check=True)
    (root / "sub" / "broken.wav").write_bytes(os.urandom(3000))
    (root / "notes.txt").write_text("not audio\n")
    return root


def test_two_workers_write_what_the_command_line_writes(cli, tree, tmp_path):
    out = tmp_path / "out"
    done = dask_render(tree, "-O", out, "--workers", 2, "--channels", 2, "--set", *SETTINGS)
    assert "on 2 workers" in done.stderr
    # The broken file fails as `tactus render` fails on it, and alone.
    assert done.returncode == 1
    expected_error = cli_error(cli, "render", tree / "sub" / "broken.wav", "-O", tmp_path / "x")
    assert f"tactus: error: {expected_error}" in done.stderr.splitlines()
    assert "1 of 4 files failed, the others were written" in done.stderr
    # The others, folder by folder, as the command line writes them.
    reference = tmp_path / "cli"
    for folder, inputs in {".": ["a.flac"], "sub": ["b.wav"], "sub/deeper": ["c.wav"]}.items():
        run(cli, "render", *[tree / folder / name for name in inputs], "-O", reference / folder,
            "--channels", 2, "--set", *SETTINGS)
    written = sorted(p.relative_to(out) for p in out.rglob("*") if p.is_file())
    expected = sorted(p.relative_to(reference) for p in reference.rglob("*") if p.is_file())
    assert written == expected == sorted(map(pathlib.Path, [
        "a.vibration.wav", "sub/b.vibration.wav", "sub/deeper/c.vibration.wav"]))
    for name in written:
        (rate, fmt, subtype, x), (rate_cli, fmt_cli, subtype_cli, x_cli) = (
            sound(out / name), sound(reference / name))
        assert (rate, fmt, subtype) == (rate_cli, fmt_cli, subtype_cli), name
        assert np.array_equal(x, x_cli), name
    # Nothing partial: no output and no temporary for the file that failed.
    assert not any(p.name.startswith(".") or "broken" in p.name for p in out.rglob("*"))


def test_existing_outputs_and_bad_settings_are_refused_before_any_work(tree, tmp_path):
    out = tmp_path / "out"
    (out / "sub").mkdir(parents=True)
    (out / "sub" / "b.vibration.wav").write_text("kept")
    done = dask_render(tree, "-O", out)
    assert done.returncode != 0
    assert "b.vibration.wav: already exists (use --force to replace it)" in done.stderr
    assert (out / "sub" / "b.vibration.wav").read_text() == "kept"
    assert not (out / "a.vibration.wav").exists()
    done = dask_render(tree, "-O", out, "--set", "envelope.decay=3")
    assert done.returncode != 0
    assert "unknown key 'envelope.decay' (did you mean 'envelope.decay_ms'?)" in done.stderr
