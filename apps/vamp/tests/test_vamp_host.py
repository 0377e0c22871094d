"""The tactus Vamp plugin in a real host, vamp-simple-host (vamp-examples): it is listed with
its outputs, its onsets are those `tactus onsets` prints (labelled with their drum part), its
features those of `tactus analyze`, on the Amen break and on a 48 kHz stereo file."""

import csv
import os
import pathlib
import re
import subprocess

import pytest

HOST = os.environ.get("VAMP_SIMPLE_HOST", "vamp-simple-host")
CLI = os.environ.get("TACTUS_CLI")
AMEN = pathlib.Path("/usr/share/sonic-pi/samples/loop_amen_full.flac")
# An onset's part is decided parts.settle_ms (8 ms in tfd) after it, on the next frame (a hop
# later at most): with margin.
DECIDING_S = 0.02
OUTPUTS = ["onsets", "loudness", "brightness", "noisiness", "pitch", "vibration_frequency",
           "vibration_amplitude", "sensation"]


def host(*args):
    done = subprocess.run([HOST, *map(str, args)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return done.stdout


def features(path, output):
    """(time, [values], label) for every feature the host prints for an output of the plugin
    ("time: values label")."""
    rows = []
    for line in host(f"tactus:tactus:{output}", path).splitlines():
        match = re.match(r"^\s*(-?[\d.]+):\s*([-\d.e+\s]*?)\s*([a-z]*)$", line)
        if match:
            rows.append((float(match[1]), [float(v) for v in match[2].split()], match[3]))
    return rows


@pytest.fixture(scope="module", params=["amen", "stereo_48k"])
def audio(request, tmp_path_factory):
    if request.param == "amen":
        return AMEN
    path = tmp_path_factory.mktemp("vamp") / "amen_48k.wav"
    subprocess.run(["sox", "-q", str(AMEN), "-r", "48000", "-b", "24", str(path), "remix", "1",
                    "2v0.5", "delay", "0", "0.1"], check=True)
    return path


def test_the_host_lists_the_plugin_and_its_outputs():
    assert os.environ.get("VAMP_PATH"), "ctest sets VAMP_PATH to the build's plugin folder"
    listing = host("--list-outputs")
    for output in OUTPUTS:
        assert f"vamp:tactus:tactus:{output}" in listing
    full = host("--list")
    assert '"tactus" [tactus]' in full and "Sensation level per channel of touch" in full


def test_onsets_equal_tactus_onsets(audio):
    onsets = features(audio, "onsets")
    done = subprocess.run([CLI, "onsets", audio], capture_output=True, text=True, check=True)
    # The host pads the last block with silence and the command line reads on for its last
    # part's decision: each may decide an onset in silence after the end, the other not.
    duration = float(subprocess.run(["soxi", "-D", audio], capture_output=True, text=True,
                                    check=True).stdout)
    expected = [line.split() for line in done.stdout.splitlines()
                if float(line.split()[1]) <= duration]
    within = [onset for onset in onsets if onset[1][0] <= duration]
    assert len(onsets) - len(within) <= 1
    assert len(within) == len(expected) > 40
    for (onset, (decided, strength), part), want in zip(within, expected):
        want_onset, want_decided, want_strength = map(float, want[:3])
        assert abs(onset - want_onset) <= 5.01e-7, (onset, want_onset)  # printed to 6 decimals
        assert decided == pytest.approx(want_decided, abs=1e-5)  # the host: 6 digits
        if want_onset > duration - DECIDING_S:
            continue  # the command line stops before its part is decided, the host's padding not
        assert strength == pytest.approx(want_strength, abs=0.0051)  # printed to 0.01 dB
        assert part == want[3], onset
    assert len({part for _, _, part in within}) >= 2


def test_features_equal_tactus_analyze(audio, tmp_path):
    subprocess.run([CLI, "analyze", audio, "-o", tmp_path / "a.csv"], check=True,
                   capture_output=True)
    # A comment line (how the rows were made) follows the CSV's header.
    lines = (tmp_path / "a.csv").read_text().splitlines()
    rows = list(csv.DictReader(line for line in lines if not line.startswith("#")))
    columns = {"loudness": ["loudness_db"], "vibration_frequency": ["frequency_hz"],
               "sensation": ["P_sl_db", "NPI_sl_db", "NPII_sl_db", "NPIII_sl_db",
                             "combined_sl_db"]}
    for output, names in columns.items():
        got = features(audio, output)
        # The host pads the last block with silence: frames past the end come after the file's.
        assert len(got) >= len(rows) > 2000
        for (time, values, _), row in zip(got, rows):
            assert time == pytest.approx(float(row["time_s"]), rel=1e-5)
            want = [float(row[n]) for n in names]
            assert values == pytest.approx(want, rel=1e-5, abs=1e-4), (output, time)
    assert max(float(r["P_sl_db"]) for r in rows) > 10
