"""tactus.render, analyze, onsets and meter give the command line's values, bit for bit; errors
are Python exceptions with its messages; arrays are read in place; the GIL is released."""

import threading
import time
import tracemalloc

import numpy as np
import pytest

import tactus
from conftest import cli_error, read_wav, run


def test_render_equals_the_command_line_on_the_amen_break(cli, amen, tmp_path):
    x, rate = tactus.read(amen)
    y = tactus.render(x, rate)
    run(cli, "render", amen, "-o", tmp_path / "cli.wav")
    expected, expected_rate = read_wav(tmp_path / "cli.wav")
    assert rate == expected_rate == 44100
    # The input's length, then the vibration's tail rung out after it, as the command writes.
    assert y.dtype == np.float32 and y.shape[1] == 1 and x.shape[0] < y.shape[0] < x.shape[0] + rate
    assert np.abs(y).max() > 0.1
    assert np.array_equal(y, expected)


def test_render_with_preset_actuator_settings_equals_the_command_line(cli, amen, tmp_path):
    x, rate = tactus.read(amen)
    with pytest.warns(UserWarning, match="lra-175"):
        y = tactus.render(x, rate, preset="four-channel", actuator="lra-175", actuators=2,
                          settings={"envelope.decay_ms": 90.125}, mapping_frequency_curve="lin")
    run(cli, "render", amen, "-o", tmp_path / "cli.wav", "--preset", "four-channel",
        "--actuator", "lra-175", "--channels", 2, "--set", "envelope.decay_ms=90.125",
        "mapping.frequency.curve=lin")
    expected, _ = read_wav(tmp_path / "cli.wav")
    assert y.shape == expected.shape and y.shape[1] == 2
    assert np.array_equal(y, expected)
    assert not np.array_equal(y[:, :1], tactus.render(x, rate))


def test_render_equals_the_command_line_on_a_stereo_48k_file(cli, stereo_48k, tmp_path):
    x, rate = tactus.read(stereo_48k)
    assert rate == 48000 and x.shape[1] == 2
    run(cli, "render", stereo_48k, "-o", tmp_path / "cli.wav")
    expected, _ = read_wav(tmp_path / "cli.wav")
    assert np.array_equal(tactus.render(x, rate), expected)
    # The same samples decoded by soundfile, interleaved (C order) or as float64: the same.
    decoded, _ = read_wav(stereo_48k)
    assert np.array_equal(decoded, x)
    assert np.array_equal(tactus.render(np.ascontiguousarray(decoded), rate), expected)
    assert np.array_equal(tactus.render(decoded.astype(np.float64), rate), expected)
    # Both channels count: the left one alone renders differently.
    assert not np.array_equal(tactus.render(x[:, 0], rate), expected)


def test_render_with_a_layout_equals_the_command_lines_outputs(cli, stereo_48k, tmp_path):
    """layout=: each output its route, as `tactus render --layout` writes the outputs' channels
    (the file has the sound too: its outputs' channels are compared)."""
    x, rate = tactus.read(stereo_48k)
    layout = tmp_path / "sides.toml"
    layout.write_text('[[output]]\nroute = "channel:1"\n[[output]]\nroute = "channel:2"\n'
                      '[[output]]\nroute = "kick+snare"\nactuator = "voice-coil"\n'
                      '[[output]]\nroute = "band:20-120"\n[output.set]\n'
                      'mapping.frequency.out_max = 80\n')
    y = tactus.render(x, rate, layout=str(layout))
    run(cli, "render", stereo_48k, "-o", tmp_path / "cli.wav", "--layout", layout)
    expected, _ = read_wav(tmp_path / "cli.wav")
    assert y.shape == expected.shape and y.shape[1] == 4
    assert np.array_equal(y, expected)
    assert not np.array_equal(y[:, 0], y[:, 1])  # the right channel is another sound
    engine = tactus.Engine(rate, channels=2, layout=str(layout))
    blocks = [engine.process(x[i:i + 300]) for i in range(0, len(x), 300)]
    assert np.array_equal(np.concatenate(blocks), y[:len(x)])
    with pytest.raises(ValueError, match="leave out actuator= and actuators="):
        tactus.render(x, rate, layout="wrists", actuators=2)
    with pytest.raises(ValueError, match="no layout named 'nope'"):
        tactus.render(x, rate, layout="nope")


def test_analyze_equals_the_command_lines_json(cli, amen, tmp_path):
    import json
    x, rate = tactus.read(amen)
    with pytest.warns(UserWarning):
        columns = tactus.analyze(x, rate, preset="four-channel", actuator="voice-coil")
    run(cli, "analyze", amen, "-o", tmp_path / "cli.json", "--preset", "four-channel",
        "--actuator", "voice-coil")
    made = json.loads((tmp_path / "cli.json").read_text())
    assert made["tactus"]["preset"] == "four-channel" and made["tactus"]["actuator"] == "voice-coil"
    rows = made["frames"]
    assert list(columns) == list(rows[0])
    assert len(columns["time_s"]) == len(rows) > 2000
    for name, values in columns.items():
        assert values.dtype == (np.dtype("<U5") if name == "part" else np.float64), name
        assert np.array_equal(values, [row[name] for row in rows]), name
    assert columns["onset"].sum() > 40
    assert tactus.drum_parts == ("kick", "snare", "hat", "other")
    decided = columns["part"][columns["part_decided"] == 1]
    # Each onset's part decided once (the last, near the end, may not be before the input ends).
    assert columns["onset"].sum() - 1 <= len(decided) <= columns["onset"].sum()
    assert len(set(decided)) >= 2


def test_analyze_csv_reads_by_column_name_in_numpy_and_pandas(cli, amen, tmp_path):
    """The CSV mixes numbers with one text column (part): both readers take it by name, with
    the values tactus.analyze() gives (printed to 6 significant digits)."""
    import pandas
    x, rate = tactus.read(amen)
    columns = tactus.analyze(x, rate)
    run(cli, "analyze", amen, "-o", tmp_path / "a.csv")
    table = np.genfromtxt(tmp_path / "a.csv", names=True, dtype=None, encoding=None,
                          comments="#", delimiter=",")
    frame = pandas.read_csv(tmp_path / "a.csv", comment="#")
    assert list(table.dtype.names) == list(frame.columns) == list(columns)
    assert len(table) == len(frame) == len(columns["time_s"])
    for name, values in columns.items():
        for read in (table[name], frame[name].to_numpy()):
            if name == "part":
                assert np.array_equal(read, values), name
            else:
                assert np.issubdtype(read.dtype, np.number), name  # int where all are whole
                assert np.allclose(read, values, rtol=1e-5, atol=1e-9), name
    assert frame["part"].isin(tactus.drum_parts).all()
    assert columns["P_sl_db"].max() > 10 and columns["NPI_sl_db"].max() > 3


def test_onsets_equal_the_command_line(cli, amen, stereo_48k):
    for path in (amen, stereo_48k):
        x, rate = tactus.read(path)
        found = tactus.onsets(x, rate)
        printed = run(cli, "onsets", path).splitlines()
        assert list(found) == ["onset_s", "decided_s", "strength_db", "part"]
        assert len(printed) == len(found["onset_s"]) > 40
        for line, onset, decided, strength, part in zip(
                printed, found["onset_s"], found["decided_s"], found["strength_db"],
                found["part"]):
            assert line == f"{onset:.6f} {decided:.6f} {strength:.2f} {part}"
        assert len(set(found["part"])) >= 2


def test_meter_equals_the_command_line(cli, amen, tmp_path):
    import pandas
    run(cli, "render", amen, "-o", tmp_path / "v.wav")
    run(cli, "meter", tmp_path / "v.wav", "-o", tmp_path / "meter.csv", "--contact-area", 0.5)
    y, rate = tactus.read(tmp_path / "v.wav")
    levels = tactus.meter(y, rate, contact_area_cm2=0.5)
    # Read as analyze's CSV is: the names from the first line, the comment line skipped.
    table = np.genfromtxt(tmp_path / "meter.csv", delimiter=",", names=True, comments="#")
    frame = pandas.read_csv(tmp_path / "meter.csv", comment="#")
    assert list(levels) == list(table.dtype.names) == list(frame.columns)
    for name in levels:
        assert np.array_equal(np.round(levels[name], 2), table[name]), name
        assert np.array_equal(np.round(levels[name], 2), frame[name].to_numpy()), name
    assert levels["P_sl_db"].max() > 10


@pytest.mark.parametrize("call, args", [
    (lambda x, r: tactus.render(x, r, settings={"envelope.decay": 100}),
     ["--set", "envelope.decay=100"]),
    (lambda x, r: tactus.render(x, r, envelope_decay_ms=-3), ["--set", "envelope.decay_ms=-3"]),
    (lambda x, r: tactus.render(x, r, mapping_frequency_curve="cubic"),
     ["--set", "mapping.frequency.curve=cubic"]),
    (lambda x, r: tactus.render(x, r, preset="no-such-preset"), ["--preset", "no-such-preset"]),
    (lambda x, r: tactus.render(x, r, actuator="no-such-actuator"),
     ["--actuator", "no-such-actuator"]),
])
def test_errors_carry_the_command_lines_messages(cli, amen, tmp_path, call, args):
    x, rate = tactus.read(amen)
    expected = cli_error(cli, "render", amen, "-o", tmp_path / "out.wav", *args)
    with pytest.raises(ValueError) as error:
        call(x, rate)
    assert expected.removeprefix("--set: ") == str(error.value)
    assert not (tmp_path / "out.wav").exists()


def test_bad_arrays_and_rates_are_value_errors():
    with pytest.raises(ValueError, match="no audio frames"):
        tactus.render(np.zeros(0, np.float32), 48000)
    with pytest.raises(ValueError, match="dimensions"):
        tactus.render(np.zeros((4, 4, 4), np.float32), 48000)
    with pytest.raises(ValueError, match="sample rate"):
        tactus.render(np.zeros(100, np.float32), 4000)
    with pytest.raises(ValueError, match="python_name|did you mean 'envelope_decay_ms'"):
        tactus.render(np.zeros(100, np.float32), 48000, envelope_decay=3)
    with pytest.raises(ValueError, match="cannot read audio"):
        tactus.read("/nonexistent.wav")


def test_audio_is_read_in_place_not_copied(amen):
    x, rate = tactus.read(amen)
    x = np.asfortranarray(np.tile(x, (8, 1)))  # 55 s, 19 MB of float32
    tracemalloc.start()
    y = tactus.render(x, rate)
    _, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    assert x.nbytes // 2 < y.nbytes < x.nbytes // 2 + 4 * 11 * rate  # the input and its tail
    # The output (room for the longest tail, 10 s) and the engine's own buffers, but no copy of
    # the input.
    assert peak < y.nbytes + 4 * 10 * rate + x.nbytes // 4, peak


def test_the_gil_is_released_while_rendering(amen):
    x, rate = tactus.read(amen)
    x = np.asfortranarray(np.tile(x, (20, 1)))  # 2.3 minutes of audio
    done = threading.Event()
    spans = []

    def render():
        start = time.perf_counter()
        tactus.render(x, rate)
        spans.append((start, time.perf_counter()))
        done.set()

    ticks = []
    thread = threading.Thread(target=render)
    thread.start()
    while not done.is_set():
        ticks.append(time.perf_counter())
        time.sleep(0.001)
    thread.join()
    start, end = spans[0]
    during = [t for t in ticks if start <= t <= end]
    assert end - start > 0.1
    gaps = np.diff([start, *during, end])
    # Holding the GIL would stop this thread for the whole render.
    assert gaps.max() < 0.5 * (end - start), (gaps.max(), end - start)
