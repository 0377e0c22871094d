"""What the skin feels of a vibration signal, for the evaluation's measures.

The output is weighted by the skin's sensitivity: the inverse of the P channel's threshold,
0 dB at its most sensitive 250 Hz, -12 dB/octave below and -9 dB/octave above (docs/perception.md,
"P channel"). A component the flattening filter boosts at low frequency then counts as equally
felt, not as stronger, and not as the pulse's pitch. The weighting is a magnitude (the threshold
curve has no phase) applied with zero phase on the whole signal's spectrum, so it adds no delay of
its own to the latency measured through it: a minimum-phase filter of the same magnitude would
add about 1.2 ms to the median onset -> half felt peak (weighted(..., minimum_phase=True)).
"""
import numpy as np

BEST_HZ = 250.0
BELOW_DB_PER_OCTAVE = 12.0
ABOVE_DB_PER_OCTAVE = 9.0
PULSE_WINDOW_S = 0.15  # a pulse is measured over this long after its hit's onset


def weighting_db(freqs_hz):
    f = np.maximum(np.asarray(freqs_hz, dtype=float), 1e-3)
    octaves = np.log2(f / BEST_HZ)
    return np.where(octaves < 0, BELOW_DB_PER_OCTAVE * octaves, -ABOVE_DB_PER_OCTAVE * octaves)


def _minimum_phase(log_magnitude):
    """The minimum-phase spectrum (full FFT length n) with this log magnitude (natural log, the
    rfft bins of an even n): the folded real cepstrum."""
    n = 2 * (len(log_magnitude) - 1)
    cepstrum = np.fft.irfft(log_magnitude, n)
    fold = np.zeros(n)
    fold[0] = cepstrum[0]
    fold[1:n // 2] = 2 * cepstrum[1:n // 2]
    fold[n // 2] = cepstrum[n // 2]
    return np.exp(np.fft.rfft(fold))


def weighted(y, rate_hz, minimum_phase=False):
    """`y` (mono) as felt: filtered by the sensitivity weighting (zero phase, or minimum phase)."""
    y = np.asarray(y, dtype=float)
    if y.ndim > 1:
        y = y[:, 0]
    # Padding keeps the filter's ring from wrapping round onto the start.
    n = int(2 ** np.ceil(np.log2(len(y) + rate_hz // 4 + 2)))
    freqs = np.fft.rfftfreq(n, 1.0 / rate_hz)
    db = weighting_db(freqs)
    db[0] = db[1]  # DC: the weighting's limit (the band-limited output has none)
    log_magnitude = db * np.log(10) / 20
    response = _minimum_phase(log_magnitude) if minimum_phase else np.exp(log_magnitude)
    return np.fft.irfft(np.fft.rfft(y, n) * response, n)[:len(y)]


def pulse(felt, rate_hz, onset_s, window_s=PULSE_WINDOW_S):
    start = int(round(onset_s * rate_hz))
    return felt[start:start + int(window_s * rate_hz)]


def peak(segment):
    return float(np.max(np.abs(segment))) if len(segment) else 0.0


def zero_crossing_hz(segment, rate_hz):
    """Carrier frequency of a pulse from its zero crossings where it is above 10 % of its peak
    (the raw measure: a square wave's harmonics add crossings)."""
    top = peak(segment)
    if top == 0:
        return 0.0
    loud = np.nonzero(np.abs(segment) > 0.1 * top)[0]
    part = segment[loud[0]:loud[-1] + 1]
    crossings = np.count_nonzero(np.signbit(part[1:]) != np.signbit(part[:-1]))
    return crossings / 2.0 / (len(part) / rate_hz)


def centroid_hz(segment, rate_hz):
    """A pulse's frequency as felt: the centroid of its power spectrum on a log-frequency axis
    (a glide or a square wave's harmonics are averaged as felt, not counted as crossings)."""
    if peak(segment) == 0:
        return 0.0
    power = np.abs(np.fft.rfft(segment * np.hanning(len(segment)))) ** 2
    freqs = np.fft.rfftfreq(len(segment), 1.0 / rate_hz)
    power, freqs = power[1:], freqs[1:]
    return float(np.exp(np.sum(power * np.log(freqs)) / np.sum(power)))


def half_peak_latency_s(segment, rate_hz):
    """Time from the pulse window's start (the hit's onset) to |felt| reaching half its peak."""
    top = peak(segment)
    if top == 0:
        return float("nan")
    return np.argmax(np.abs(segment) >= 0.5 * top) / rate_hz


def pulses(y, rate_hz, onsets_s, weight=True, window_s=PULSE_WINDOW_S):
    """Peak, frequency (Hz) and half-peak latency (s) of the pulse after each onset, measured
    over `window_s`: felt (its frequency the felt spectrum's centroid) or, without `weight`, raw
    (zero crossings)."""
    signal = weighted(y, rate_hz) if weight else np.asarray(y, dtype=float)
    frequency = centroid_hz if weight else zero_crossing_hz
    out = []
    for t in onsets_s:
        seg = pulse(signal, rate_hz, t, window_s)
        out.append((peak(seg), frequency(seg, rate_hz), half_peak_latency_s(seg, rate_hz)))
    return out
