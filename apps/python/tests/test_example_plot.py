"""examples/python/plot_features.py draws the Amen break's features, vibration and sensation
levels into a PNG that holds a real figure."""

import os
import pathlib
import subprocess
import sys

import matplotlib.image
import numpy as np

from conftest import run

EXAMPLE = pathlib.Path(__file__).parents[3] / "examples" / "python" / "plot_features.py"


def test_the_example_writes_a_figure(cli, amen, tmp_path):
    png = tmp_path / "amen.png"
    done = subprocess.run([sys.executable, EXAMPLE, amen, "-o", png, "--preset", "four-channel"],
                          capture_output=True, text=True, env={**os.environ, "MPLBACKEND": "Agg"})
    assert done.returncode == 0, done.stderr
    # As many onsets as the command line finds with the same preset.
    onsets = run(cli, "onsets", amen, "--preset", "four-channel").count("\n")
    assert f"{onsets} onsets" in done.stdout
    assert png.stat().st_size > 100_000
    image = matplotlib.image.imread(png)
    height, width = image.shape[:2]
    assert width > 800 and height > 1000
    rgb = image[..., :3]
    # Six panels of curves: many colours, and every horizontal band of the figure drawn on.
    assert len(np.unique((rgb * 255).astype(np.uint8).reshape(-1, 3), axis=0)) > 500
    bands = np.array_split(rgb, 6, axis=0)
    assert all((band < 0.5).mean() > 0.01 for band in bands)
