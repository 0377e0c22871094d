"""tactus.Engine: any block sizes give the output of one call and of `tactus render`; set() and
the parameter attributes go through the live path and, once a change has settled, match
`--set`; the attributes are the parameter table's."""

import numpy as np
import pytest

import tactus
from conftest import read_wav, run


@pytest.fixture(scope="module")
def amen_audio(amen):
    return tactus.read(amen)


def in_blocks(engine, x, sizes):
    """The engine's output for x, in blocks whose sizes cycle through `sizes`."""
    out, done, b = [], 0, 0
    while done < len(x):
        n = sizes[b % len(sizes)]
        out.append(engine.process(x[done:done + n]))
        done, b = done + n, b + 1
    return np.concatenate(out)


def test_any_block_sizes_give_the_output_of_one_call(amen_audio, cli, amen, tmp_path):
    x, rate = amen_audio
    one_call = tactus.Engine(rate, channels=2).process(x)
    run(cli, "render", amen, "-o", tmp_path / "cli.wav")
    rendered = read_wav(tmp_path / "cli.wav")[0]  # the input, then the vibration's tail
    assert len(rendered) > len(one_call)
    assert np.array_equal(one_call, rendered[:len(one_call)])
    short = 2 * int(rate)  # 1-frame blocks: two seconds of Python calls are enough
    sizes = {1: short, 64: None, 1000: None, 4096: None, 10000: None}
    for size, frames in sizes.items():
        y = in_blocks(tactus.Engine(rate, channels=2), x[:frames], [size])
        assert np.array_equal(y, one_call[:len(y)]), f"blocks of {size}"
    varying = [1, 7, 64, 333, 4096, 5000, 0, 2, 129]
    assert np.array_equal(in_blocks(tactus.Engine(rate, channels=2), x, varying), one_call)


def test_a_block_is_read_in_place_in_any_layout(amen_audio):
    x, rate = amen_audio
    expected = tactus.Engine(rate, channels=2).process(x)
    for layout in (np.ascontiguousarray(x), x.astype(np.float64), x.copy(order="F")):
        assert np.array_equal(tactus.Engine(rate, channels=2).process(layout), expected)
    mono = x.mean(axis=1, dtype=np.float32)
    assert np.array_equal(tactus.Engine(rate).process(mono), tactus.render(mono, rate)[:len(mono)])
    with pytest.raises(ValueError, match=r"2 channel\(s\), the engine was made for 1 \(channels=1\); "
                       r"make another with Engine\(rate, channels=2\)"):
        tactus.Engine(rate, channels=1).process(x)


def test_the_channel_count_is_the_first_blocks_unless_given(amen_audio):
    """Engine(rate) takes tactus.read's stereo as it comes: the first block sets the count, and
    the output is that of an engine made for it, parameters set before it included."""
    x, rate = amen_audio
    given = tactus.Engine(rate, channels=2)
    given.envelope_decay_ms = 80
    taken = tactus.Engine(rate)
    taken.envelope_decay_ms = 80
    assert taken.channels == 1
    empty = taken.process(np.zeros((0, 2), np.float32))  # no frames: nothing fixed yet
    assert empty.shape == (0, 1)
    assert np.array_equal(in_blocks(taken, x, [4096]), in_blocks(given, x, [4096]))
    assert taken.channels == 2 and taken.settings["envelope.decay_ms"] == 80
    with pytest.raises(ValueError, match=r"1 channel\(s\), the engine was made for 2 \(its first "
                       r"block's\)"):
        taken.process(x[:, 0])
    taken.reset()
    with pytest.raises(ValueError, match="made for 2"):
        taken.process(x[:, 0])
    mono = tactus.Engine(rate)
    mono.process(x[:100, 0])
    with pytest.raises(ValueError, match="made for 1"):
        mono.process(x[100:200])


# Live parameters, each turned once mid-file at a block boundary.
LIVE_CHANGES = [("envelope.decay_ms", 90.125), ("mapping.frequency.out_max", 300),
                ("mapping.frequency.curve", "lin"), ("post.drive_db", 6),
                ("onset.threshold", 20)]


@pytest.mark.parametrize("key, value", LIVE_CHANGES)
def test_a_live_change_mid_file_matches_set_from_there_on(amen_audio, cli, amen, tmp_path, key,
                                                          value):
    x, rate = amen_audio
    plain = tactus.render(x, rate)[:len(x)]  # without the tail, as the engine plays it
    run(cli, "render", amen, "-o", tmp_path / "set.wav", "--set", f"{key}={value}")
    with_set = read_wav(tmp_path / "set.wav")[0]
    cut = 3 * 44100 // 64 * 64  # a block boundary three seconds in
    engine = tactus.Engine(rate, channels=2)
    before = in_blocks(engine, x[:cut], [64])
    engine.set(key, value)  # from the next block on
    after = in_blocks(engine, x[cut:], [64])
    y = np.concatenate([before, after])
    assert np.array_equal(y[:cut], plain[:cut]), "nothing changes before the call"
    changed = np.nonzero(y[cut:, 0] != plain[cut:, 0])[0]
    assert len(changed) and changed[0] < 0.5 * rate, "the change is heard promptly"
    # The change glides (at most 50 ms) and what sounded before it decays: two seconds later
    # the output is --set's, sample for sample to within rounding (a smoothed value that came
    # from elsewhere can settle an ulp or two of the float output away: -160 dB), and not the
    # unchanged output.
    settled = cut + 2 * int(rate)
    assert np.max(np.abs(y[settled:] - with_set[settled:len(y)])) <= 1e-8
    assert not np.array_equal(y[settled:], plain[settled:len(y)])


def test_attributes_take_the_live_path_as_set_does(amen_audio):
    x, rate = amen_audio
    cut = 2 * 44100 // 64 * 64
    by_set, by_attribute = tactus.Engine(rate, channels=2), tactus.Engine(rate, channels=2)
    a = [by_set.process(x[:cut]), by_attribute.process(x[:cut])]
    by_set.set("mapping.frequency.out_max", 250)
    by_attribute.mapping_frequency_out_max = 250
    assert by_attribute.mapping_frequency_out_max == 250.0
    assert by_attribute.settings["mapping.frequency.out_max"] == 250.0
    assert np.array_equal(by_set.process(x[cut:]), by_attribute.process(x[cut:]))


@pytest.mark.parametrize("key, value", [("onset.window_ms", 9.9), ("post.lookahead_ms", 3.0)])
def test_a_structural_change_mid_file_keeps_every_onset_and_leaves_no_gap(amen_audio, key, value):
    x, rate = amen_audio
    plain = tactus.Engine(rate, channels=2, keep_frames=True)
    y_plain = in_blocks(plain, x, [64])
    held = tactus.Engine(rate, channels=2, keep_frames=True, settings={key: value})
    y_held = in_blocks(held, x, [64])
    engine = tactus.Engine(rate, channels=2, keep_frames=True)
    cut = 3 * 44100 // 64 * 64
    before = in_blocks(engine, x[:cut], [64])
    engine.set(key, value)  # a new pipeline, primed with the input so far, crossfaded in
    y = np.concatenate([before, in_blocks(engine, x[cut:], [64])])
    assert engine.latency == held.latency
    assert engine.settings[key] == value
    # Neither change alters the analysis (9.9 ms and 10 ms are both 160-sample windows at the
    # 16 kHz analysis rate): the primed pipeline finds every hit the unchanged one finds, at the
    # same time.
    frames, expected = engine.frames(), plain.frames()
    assert np.array_equal(frames["onset_time_s"][frames["onset"] == 1],
                          expected["onset_time_s"][expected["onset"] == 1])
    # No gap: around the change, every 5 ms window is at least a third of the quieter of the
    # outputs with either setting held throughout.
    window = int(0.005 * rate)
    for start in range(cut - 10 * window, cut + 20 * window, window):
        part = slice(start, start + window)
        quieter = min(np.abs(y_plain[part]).max(), np.abs(y_held[part]).max())
        if quieter > 0.02:
            assert np.abs(y[part]).max() > quieter / 3, start / rate


def test_frames_are_analyzes_columns(amen_audio):
    x, rate = amen_audio
    engine = tactus.Engine(rate, channels=2, keep_frames=True)
    in_blocks(engine, x, [512])
    frames = engine.frames()
    columns = tactus.analyze(x, rate)
    assert len(frames) == 24
    for name, values in frames.items():
        assert np.array_equal(values, columns[name]), name
    assert set(frames["part"]) <= set(tactus.drum_parts)
    assert len(engine.frames()["time_s"]) == 0, "each frame once"


def test_latency_is_the_look_ahead(amen_audio):
    _, rate = amen_audio
    look_ahead_ms = next(p["default"] for p in tactus.params()
                         if p["key"] == "post.lookahead_ms")
    engine = tactus.Engine(48000)
    # To within the internal rate's resolution: 4 output samples at 48 kHz.
    assert engine.latency == pytest.approx(look_ahead_ms * 1e-3 * 48000, abs=4)
    longer = tactus.Engine(48000, post_lookahead_ms=2 * look_ahead_ms)
    assert longer.latency == pytest.approx(2 * engine.latency, abs=4)
    assert (engine.sample_rate, engine.channels, engine.actuators) == (48000, 1, 1)


def test_every_parameter_is_an_attribute_documented_from_the_table():
    table = tactus.params()
    assert len(table) > 60
    names = [p["name"] for p in table]
    assert len(set(names)) == len(names)
    engine = tactus.Engine(48000)
    for p in table:
        attribute = getattr(tactus.Engine, p["name"])
        doc = attribute.__doc__
        assert doc.startswith(p["key"] + " ("), doc
        assert p["help"] in doc and ("live" if p["live"] else "structural") in doc
        for choice in p["choices"]:
            assert choice in doc
        value = getattr(engine, p["name"])
        if p["choices"]:
            assert value == p["choices"][int(p["default"])]
        else:
            assert value == p["default"]
    assert "Hz" in tactus.Engine.mapping_frequency_out_max.__doc__


def test_bad_values_are_refused_and_change_nothing():
    engine = tactus.Engine(48000)
    with pytest.raises(ValueError, match=r"^post.drive_db = 99 is out of range"):
        engine.post_drive_db = 99
    with pytest.raises(ValueError, match="is not one of: lin, log, exp"):
        engine.set("mapping.frequency.curve", "cubic")
    with pytest.raises(ValueError, match="did you mean 'envelope.decay_ms'"):
        engine.set("envelope.decay", 3)
    assert engine.post_drive_db == tactus.Engine(48000).post_drive_db
    with pytest.raises(ValueError, match="sample rate"):
        tactus.Engine(1000)


def test_process_in_one_thread_frames_and_set_in_another(amen_audio):
    import threading
    import time
    x, rate = amen_audio
    long = np.asfortranarray(np.tile(x, (40, 1)))  # some 280 s of audio: a second or more
    engine = tactus.Engine(rate, channels=2, keep_frames=True)
    thread = threading.Thread(target=engine.process, args=(long,))
    thread.start()
    time.sleep(0.2)  # well inside the long block
    frames, refused = 0, False
    while thread.is_alive():
        try:
            engine.process(x[:64])
        except ValueError as error:
            refused = "already running" in str(error)
        engine.envelope_decay_ms = 120.0  # the control thread, while audio runs
        frames += len(engine.frames()["time_s"])  # waits for process() without the GIL
    thread.join(timeout=60)
    assert not thread.is_alive()
    frames += len(engine.frames()["time_s"])
    assert abs(frames - len(long) / engine.hop_samples) < 1
    assert refused, "a second process() while one runs is refused"
