"""The perception model through Python holds the library's numbers: the closed forms and the
levels of perception.md (threshold.hpp), the min rule, P's area and duration summation, sensation
level and the channels' combination (sensation.hpp)."""

import numpy as np
import pytest

import tactus

F = np.geomspace(0.5, 1000, 400)


def p_reference_db(f):
    """T_P(f) = -20 + 10 log10((3/7)(250/f)^4 + (4/7)(f/250)^3) (threshold.hpp)."""
    r = 250.0 / f
    return -20.0 + 10 * np.log10(3 / 7 * r**4 + 4 / 7 / r**3)


def test_p_is_the_u_shape_with_its_minimum_at_250_hz():
    p = tactus.threshold_db("P", F)
    assert p.shape == F.shape and p.dtype == np.float64
    assert np.allclose(p, p_reference_db(F), atol=1e-9)
    assert tactus.threshold_db("P", 250.0) == pytest.approx(-20.0)
    # About -12 dB per octave below the minimum.
    assert tactus.threshold_db("P", 40) - tactus.threshold_db("P", 80) == pytest.approx(12, abs=0.6)


def test_npii_is_p_raised_and_the_flat_channels_sit_at_their_levels():
    assert np.allclose(tactus.threshold_db("NPII", F), p_reference_db(F) + 22.5, atol=1e-9)
    assert tactus.threshold_db("NPI", 10.0) == pytest.approx(12.5, abs=0.3)
    assert tactus.threshold_db("NPI", 30.0) == pytest.approx(12.5 - 3.0, abs=0.3)  # the notch
    assert tactus.threshold_db("NPIII", 1.0) == pytest.approx(30.0, abs=0.1)


def test_the_system_detects_at_the_lowest_channel():
    curves = np.array([tactus.threshold_db(c["name"], F) for c in tactus.channels()])
    assert np.allclose(tactus.detection_threshold_db(F), curves.min(axis=0))
    names = [c["name"] for c in tactus.channels()]
    for f, lowest in zip(F[::40], curves.argmin(axis=0)[::40]):
        assert tactus.detecting_channel(f) == names[lowest]
    assert tactus.detecting_channel(250) == "P" and tactus.detecting_channel(10) == "NPI"
    assert tactus.detecting_channel(0.5) == "NPIII"


def test_only_p_sums_over_area_and_duration():
    # Full summation at 80 Hz and above: -3 dB per doubling of contact area and of duration.
    for f in (100, 250, 400):
        small = tactus.threshold_db("P", f, contact_area_cm2=2.9 / 4)
        assert small - tactus.threshold_db("P", f) == pytest.approx(6.0, abs=1e-6)
        short = tactus.threshold_db("P", f, duration_s=0.25)
        assert short - tactus.threshold_db("P", f) == pytest.approx(6.0, abs=1e-6)
    # None at 40 Hz, none on the other channels.
    assert tactus.threshold_db("P", 40, contact_area_cm2=0.1) == pytest.approx(
        tactus.threshold_db("P", 40))
    for name in ("NPI", "NPII", "NPIII"):
        assert np.allclose(tactus.threshold_db(name, F, contact_area_cm2=0.1, duration_s=0.1),
                           tactus.threshold_db(name, F))


def test_sensation_levels_and_their_combination():
    levels = tactus.sensation_level_db("P", F, displacement_db=0.0)
    assert np.allclose(levels, np.maximum(0.0, -p_reference_db(F)))
    # Stronger plus half the weaker, as magnitudes psi = 10^(0.89 SL / 20) - 1.
    psi = lambda sl: 10 ** (0.89 * sl / 20) - 1
    sl = lambda m: 20 / 0.89 * np.log10(m + 1)
    both = tactus.combined_sensation_db([20.0, 10.0, 0.0, 0.0])
    assert both == pytest.approx(sl(psi(20) + 0.5 * psi(10)))
    rows = tactus.combined_sensation_db(np.array([[20.0, 0, 0, 0], [0, 0, 0, 0]]))
    assert np.allclose(rows, [20.0, 0.0])
    with pytest.raises(ValueError, match="unknown channel 'Q'"):
        tactus.threshold_db("Q", 100)
    with pytest.raises(ValueError, match=r"\(\.\.\., 4\)"):
        tactus.combined_sensation_db([1.0, 2.0])


def test_the_channels_are_the_papers_table_1():
    table = {c["name"]: c for c in tactus.channels()}
    assert list(table) == ["P", "NPI", "NPII", "NPIII"]
    assert table["P"]["range_hz"] == (40, 500) and table["NPI"]["sensation"] == "flutter"
    assert table["NPIII"]["receptor"] == "Merkel"


@pytest.mark.parametrize("frequency_hz", [0, -5, np.nan, np.inf, [100, 0, 250]])
def test_frequencies_outside_the_curves_are_refused(frequency_hz):
    """0 Hz gave an infinite threshold and -5 Hz NaN: a ValueError naming the argument."""
    calls = [lambda: tactus.threshold_db("P", frequency_hz),
             lambda: tactus.detection_threshold_db(frequency_hz),
             lambda: tactus.sensation_level_db("P", frequency_hz, 0.0)]
    if np.isscalar(frequency_hz):
        calls.append(lambda: tactus.detecting_channel(frequency_hz))
    for call in calls:
        with pytest.raises(ValueError, match="frequency_hz = .* is out of range: must be above 0"):
            call()
