#!/usr/bin/env python3
"""Draws what tactus makes of a piece of music: the features it extracts, the vibration it
renders and the sensation level each channel of touch receives through an actuator, beside the
channels' threshold curves (paper Figures 3 and 4, §5). Writes a PNG.

    /usr/bin/python3 examples/python/plot_features.py IN.flac -o features.png \
        [--preset four-channel] [--actuator voice-coil]
"""

import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import tactus  # noqa: E402

CHANNEL_COLOURS = {"P": "tab:blue", "NPI": "tab:orange", "NPII": "tab:green", "NPIII": "tab:red"}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("input", help="audio file (anything libsndfile reads)")
    parser.add_argument("-o", "--output", required=True, help="PNG to write")
    parser.add_argument("--preset", default="music")
    parser.add_argument("--actuator", default="voice-coil")
    args = parser.parse_args()

    x, rate = tactus.read(args.input)
    columns = tactus.analyze(x, rate, preset=args.preset, actuator=args.actuator)
    vibration = tactus.render(x, rate, preset=args.preset, actuator=args.actuator)
    t = columns["time_s"]
    audio_t = np.arange(len(x)) / rate

    fig, axes = plt.subplots(6, 1, figsize=(11, 15), constrained_layout=True,
                             gridspec_kw={"height_ratios": [1, 1, 1, 1, 1, 1.2]})
    ax = axes[0]
    ax.plot(audio_t, x.mean(axis=1), color="0.6", linewidth=0.4)
    for onset in columns["onset_time_s"][columns["onset"] == 1]:
        ax.axvline(onset, color="tab:red", linewidth=0.6, alpha=0.6)
    ax.set(title=f"{os.path.basename(args.input)}: audio and onsets", ylabel="full scale")

    ax = axes[1]
    ax.plot(t, columns["loudness_db"], label="loudness (dB LKFS)")
    ax.set_ylabel("dB")
    twin = ax.twinx()
    twin.semilogy(t, np.maximum(columns["brightness_hz"], 1), color="tab:purple", linewidth=0.8,
                  label="brightness (Hz)")
    twin.set_ylabel("Hz")
    ax.set_title("features")
    ax.legend(loc="upper left")
    twin.legend(loc="upper right")

    ax = axes[2]
    ax.plot(t, columns["frequency_hz"], label="frequency (Hz)")
    ax.set_ylabel("Hz")
    twin = ax.twinx()
    twin.plot(t, columns["amplitude"], color="tab:green", linewidth=0.8, label="amplitude")
    twin.set_ylabel("full scale")
    ax.set_title(f"vibration program ({args.preset})")
    ax.legend(loc="upper left")
    twin.legend(loc="upper right")

    ax = axes[3]
    ax.plot(np.arange(len(vibration)) / rate, vibration[:, 0], color="k", linewidth=0.4)
    ax.set(title=f"vibration for {args.actuator}", ylabel="full scale")

    ax = axes[4]
    for name, colour in CHANNEL_COLOURS.items():
        ax.plot(t, columns[f"{name}_sl_db"], color=colour, label=name)
    ax.plot(t, columns["combined_sl_db"], color="k", linestyle="--", linewidth=0.8,
            label="combined")
    top = max(columns[f"{name}_sl_db"].max() for name in CHANNEL_COLOURS)
    ax.set(title="sensation level per channel of touch", xlabel="time (s)", ylabel="dB SL",
           ylim=(0, 1.35 * max(top, 1.0)))
    ax.legend(loc="upper right", ncol=5)
    for a in axes[:5]:
        a.set_xlim(0, audio_t[-1])

    ax = axes[5]
    f = np.geomspace(0.4, 1000, 300)
    for name, colour in CHANNEL_COLOURS.items():
        ax.semilogx(f, tactus.threshold_db(name, f), color=colour, label=name)
    ax.semilogx(f, tactus.threshold_db("P", f, contact_area_cm2=0.5), color=CHANNEL_COLOURS["P"],
                linestyle=":", label="P, 0.5 cm²")
    ax.semilogx(f, tactus.detection_threshold_db(f), color="k", linestyle="--", linewidth=0.8,
                label="detection (min rule)")
    ax.set(title="threshold curves of the channels of touch (2.9 cm², 1 s)",
           xlabel="frequency (Hz)", ylabel="dB re 1 µm peak")
    ax.legend(loc="upper center", ncol=6, fontsize=8)

    fig.savefig(args.output, dpi=90)
    print(f"{args.output}: {len(t)} frames, {int(columns['onset'].sum())} onsets")


if __name__ == "__main__":
    main()
