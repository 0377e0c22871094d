"""Every call's audio goes through one conversion (audio_view.cpp): integer arrays are scaled to
full scale as libsndfile scales an audio file's samples, so scipy.io.wavfile.read's int16, int32
and uint8 render as the same file read by tactus.read does; complex, non-numeric, NaN and
infinite samples are refused with a ValueError saying what and where."""

import numpy as np
import pytest
import scipy.io.wavfile
import soundfile

import tactus


@pytest.fixture(scope="module")
def two_seconds(amen):
    x, rate = tactus.read(amen)
    return x[:2 * int(rate)], rate


@pytest.mark.parametrize("subtype, dtype", [("PCM_16", np.int16), ("PCM_24", np.int32),
                                            ("PCM_32", np.int32), ("PCM_U8", np.uint8)])
def test_integer_arrays_render_as_their_file_does(two_seconds, tmp_path, subtype, dtype):
    x, rate = two_seconds
    path = tmp_path / "x.wav"
    soundfile.write(path, x, int(rate), subtype=subtype)
    read_rate, integers = scipy.io.wavfile.read(path)
    assert integers.dtype == dtype and read_rate == rate
    from_file, _ = tactus.read(path)  # libsndfile's scaling
    expected = tactus.render(from_file, rate)
    assert np.abs(expected).max() > 0.1
    assert np.array_equal(tactus.render(integers, rate), expected)
    engine = tactus.Engine(rate)
    assert np.array_equal(engine.process(integers), expected[:len(integers)])
    assert np.array_equal(tactus.onsets(integers, rate)["onset_s"],
                          tactus.onsets(from_file, rate)["onset_s"])


def test_full_scale_integers_are_full_scale(tmp_path):
    rate = 48000
    full = {np.int16: (-32768, 32767), np.int32: (-2**31, 2**31 - 1), np.uint8: (0, 255),
            np.int8: (-128, 127)}
    for dtype, (low, high) in full.items():
        x = np.array([low, high, low, high], dtype)
        tactus.write(tmp_path / "y.wav", x, rate)  # float WAV: the samples as converted
        y, _ = tactus.read(tmp_path / "y.wav")
        assert y[0, 0] == -1.0 and 0.99 < y[1, 0] <= 1.0, dtype  # int32: float32 rounds up


@pytest.mark.parametrize("x, message", [
    (np.ones(1000, np.complex64), "audio: complex samples"),
    (np.ones(1000, np.int64), "audio: int64 samples have no audio scale"),
    (np.ones(1000, np.uint16), "audio: uint16 samples have no audio scale"),
    (np.ones(1000, bool), "audio: expected numbers, got bool samples"),
])
def test_samples_that_are_not_audio_are_refused(x, message):
    with pytest.raises(ValueError, match=message):
        tactus.render(x, 48000)
    with pytest.raises(ValueError, match=message):
        tactus.Engine(48000).process(x)


@pytest.mark.parametrize("bad, name", [(np.nan, "NaN"), (np.inf, r"\+inf"), (-np.inf, "-inf")])
def test_non_finite_samples_are_refused_where_they_are(bad, name):
    x = np.zeros((1000, 2), np.float32)
    x[123, 1] = bad
    for call in (lambda: tactus.render(x, 48000), lambda: tactus.analyze(x, 48000),
                 lambda: tactus.onsets(x, 48000), lambda: tactus.meter(x, 48000),
                 lambda: tactus.Engine(48000).process(x)):
        with pytest.raises(ValueError, match=f"audio: sample 123 of channel 1 is {name}"):
            call()
