"""tactus.stream_file and stream_buffer: an Engine run over a file or over an array by the
command line's run loop; the same audio gives the same vibration, sample for sample, and with
ring_out the vibration `tactus render` writes, bit for bit."""

import numpy as np
import pytest

import tactus
from conftest import read_wav, run


def test_stream_buffer_equals_stream_file_and_the_command_line(cli, stereo_48k, tmp_path):
    x, rate = tactus.read(stereo_48k)
    from_file = tactus.stream_file(tactus.Engine(rate), stereo_48k)
    from_buffer = tactus.stream_buffer(tactus.Engine(rate), x)
    assert from_file.dtype == np.float32 and from_file.shape == (x.shape[0], 1)
    assert np.abs(from_file).max() > 0.1
    assert np.array_equal(from_buffer, from_file)
    # As process() over the same samples, block by block.
    engine = tactus.Engine(rate)
    blocks = [engine.process(x[i:i + 1000]) for i in range(0, x.shape[0], 1000)]
    assert np.array_equal(np.concatenate(blocks), from_buffer)
    # With the tail rung out: `tactus render`, bit for bit.
    run(cli, "render", stereo_48k, "-o", tmp_path / "cli.wav")
    expected, _ = read_wav(tmp_path / "cli.wav")
    rendered = tactus.stream_buffer(tactus.Engine(rate), x, ring_out=True)
    assert rendered.shape == expected.shape and rendered.shape[0] > x.shape[0]
    assert np.array_equal(rendered, expected)
    assert np.array_equal(tactus.stream_file(tactus.Engine(rate), stereo_48k, ring_out=True),
                          expected)


def test_stream_keeps_the_engines_state_and_frames(amen):
    x, rate = tactus.read(amen)
    half = x.shape[0] // 2
    engine = tactus.Engine(rate, keep_frames=True)
    y = np.concatenate([tactus.stream_buffer(engine, x[:half]),
                        tactus.stream_buffer(engine, x[half:])])
    assert np.array_equal(y, tactus.stream_buffer(tactus.Engine(rate), x))
    frames = engine.frames()
    assert frames["time_s"].size > 100 and np.all(np.diff(frames["time_s"]) > 0)


def test_stream_errors_name_the_file_and_the_rate(amen, tmp_path):
    x, rate = tactus.read(amen)
    with pytest.raises(ValueError, match="engine runs at 48000 Hz"):
        tactus.stream_file(tactus.Engine(48000), amen)
    with pytest.raises(ValueError, match="missing.wav"):
        tactus.stream_file(tactus.Engine(rate), tmp_path / "missing.wav")
    with pytest.raises(ValueError, match="3 channel"):
        tactus.stream_buffer(tactus.Engine(rate, channels=1), np.zeros((100, 3), np.float32))
    with pytest.raises(ValueError, match="no audio frames"):
        tactus.stream_buffer(tactus.Engine(rate), np.zeros(0, np.float32))
