"""What the evaluation scripts share: running a tool, aubioonset's parameters, reading a corpus
file's hits, and the share of a render's energy inside a band."""
import subprocess

import numpy as np

# aubioonset's defaults, passed explicitly: buffer 512, hop 256, threshold 0.3, minioi 12 ms,
# silence -90 dB.
AUBIO_ARGS = ["-B", "512", "-H", "256", "-t", "0.3", "-M", "0.012", "-s", "-90"]


def run(cmd):
    """Runs `cmd` (paths allowed), raising on failure; its output captured as text."""
    return subprocess.run([str(c) for c in cmd], check=True, capture_output=True, text=True)


def read_hits(path):
    """(time s, instrument, gain dB) of each hit in a corpus's NAME.hits.csv."""
    rows = [line.split(",") for line in path.read_text().splitlines()[1:]]
    return [(float(t), instrument, float(g)) for t, instrument, g in rows]


def band_share(y, rate, low_hz=20.0, high_hz=1000.0):
    """The share of `y`'s energy within [low_hz, high_hz] (silence: all of it)."""
    power = np.abs(np.fft.rfft(y)) ** 2
    freqs = np.fft.rfftfreq(len(y), 1.0 / rate)
    total = power.sum()
    return 1.0 if total == 0 else power[(freqs >= low_hz) & (freqs <= high_hz)].sum() / total
