"""What the evaluation scripts share: running a tool, aubioonset's parameters, reading a sound
file as mono, reading a corpus file's hits, `tactus onsets`' times, the share of a render's energy
inside a band, and the command line of a script that prints one section of the report."""
import argparse
import pathlib
import subprocess
import tempfile

import numpy as np
import soundfile

# aubioonset's defaults, passed explicitly: buffer 512, hop 256, threshold 0.3, minioi 12 ms,
# silence -90 dB.
AUBIO_ARGS = ["-B", "512", "-H", "256", "-t", "0.3", "-M", "0.012", "-s", "-90"]


def run(cmd):
    """Runs `cmd` (paths allowed), raising on failure; its output captured as text."""
    return subprocess.run([str(c) for c in cmd], check=True, capture_output=True, text=True)


def read_mono(path):
    """(samples in float64, the channels' mean; sample rate Hz) of a sound file."""
    x, rate = soundfile.read(path, dtype="float64", always_2d=True)
    return x.mean(axis=1), rate


def read_hits(path):
    """(time s, instrument, gain dB) of each hit in a corpus's NAME.hits.csv."""
    rows = [line.split(",") for line in path.read_text().splitlines()[1:]]
    return [(float(t), instrument, float(g)) for t, instrument, g in rows]


def onset_rows(tactus, wav, preset, *options):
    """The lines `tactus onsets` prints for `wav` (onset s, decided s, strength dB, part, then what
    `options` add), each split into its fields."""
    text = run([tactus, "onsets", wav, "--preset", preset, *options]).stdout
    return [line.split() for line in text.splitlines() if line.strip()]


def onset_times_s(tactus, wav, preset):
    """The onset times `tactus onsets` prints for `wav`."""
    return np.array([float(r[0]) for r in onset_rows(tactus, wav, preset)])


def band_share(y, rate, low_hz=20.0, high_hz=1000.0):
    """The share of `y`'s energy within [low_hz, high_hz] (silence: all of it)."""
    power = np.abs(np.fft.rfft(y)) ** 2
    freqs = np.fft.rfftfreq(len(y), 1.0 / rate)
    total = power.sum()
    return 1.0 if total == 0 else power[(freqs >= low_hz) & (freqs <= high_hz)].sum() / total


def section_main(doc, measure, section, work_prefix):
    """`SCRIPT BUILD_DIR [--work DIR] [--preset NAME]`: prints section(measure(build dir, work,
    preset)); the work folder a new temporary one unless given."""
    parser = argparse.ArgumentParser(description=doc.splitlines()[0])
    parser.add_argument("build_dir", type=pathlib.Path)
    parser.add_argument("--work", type=pathlib.Path, default=None)
    parser.add_argument("--preset", default="music")
    args = parser.parse_args()
    work = args.work or pathlib.Path(tempfile.mkdtemp(prefix=work_prefix))
    print("\n".join(section(measure(args.build_dir, work, args.preset))))
    return 0
