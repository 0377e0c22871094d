#!/usr/bin/python3
"""Measures tactus's routes (`tactus render --layout`, layouts/*.toml) on the songs of the music
corpus (eval/music_corpus.py, built by eval/evaluate.py or eval/music.py), each part apart.

usage: eval/routes.py BUILD_DIR --work DIR [--jobs 2] [--preset music] [--out FILE]

Every render uses the preset alone (no actuator profile, as eval/music.py); each output channel is
read through the felt model (eval/felt.py's weighting): its felt signal. A song's hits are
music.truth's: its distinct hit times, each time's part the first of kick, snare, hat there.

- Kick and snare on their own outputs (the mix with its bed at 0 dB, NAME-bed+0dB.wav): one
  render with two outputs, route `kick` and route `snare`. A hit gives a pulse on an output by
  music.py's distinct-pulse criterion (the felt envelope's largest value inside the window, not at
  its end, at least 6 dB above its largest value over the 10 ms before the hit), the window
  extended from [hit, hit + 60 ms] to [hit, hit + 80 ms]: a part route starts its pulse when the
  part is decided, parts.settle_ms = 20 ms after the onset. Share of the kick hits with a pulse on
  the kick output, of the snare hits on the snare output (pooled over the part's songs). Then, on
  each output, the other part's hits (snare hits on the kick output, kick hits on the snare
  output) that have no hit of the output's own part (any hit of that instrument in hits.csv)
  within +-100 ms: the felt peak (felt.peak, |felt signal|) of each over [hit, hit + 80 ms],
  against the median felt peak over the same window of the song's own-part hits on that output:
  the difference in dB, its median pooled over the part's songs, and the share of those hits
  10 dB or more below; the song with the lowest share named. Between pulses an output is not
  exactly zero (the previous pulse's decay, the filters' ring: down to -200 dB), so a hit no
  pulse answers can stand 80-100 dB below. A song without own-part hits on an output (a house
  song's snares all fall on its kicks, so are kicks) or without such other-part hits gives none;
  one where fewer than half its own-part hits give a pulse on their output is left out, its count
  given: its median own-part peak is then no pulse's but that decay's, and the others' dB below
  it mean nothing.
- A low band under a voice: every bed has a voice (espeak-ng phrases on bar starts), but the bed
  stem (NAME-bed+0dB.bed.wav) holds it with the bass, chords and melody and the corpus keeps no
  voice stem, so the band route is measured on what it plays of the bed as a whole. One output,
  route `band:20-120` (layouts/seat.toml's band), rendered on the mix, on the bed stem alone and
  on the drum stem alone (NAME-bed+0dB.drums.wav; the stems as they went into the mix). Felt
  energy: the sum of the felt signal squared. Per song: the share of the mix render's felt energy
  inside [hit, hit + 150 ms] of its kick hits (with the share of the song's time those windows
  cover, what an output playing everything evenly would give: its median), and the bed stem
  render's felt energy re the drum stem render's (dB; a silent bed render: -inf). Median over
  songs and the worst song.
- Pan: each song's drums alone (NAME-alone.wav) made stereo, hard left (right channel all zeros)
  and panned 0.8/0.2 (left 0.8 x, right 0.2 x: 12.0 dB apart), rendered with two outputs, route
  `channel:1` and `channel:2` (layouts/wrists.toml's routes). Left re right felt energy (dB):
  median over songs and the worst song (the least apart); inf when the right output is all zeros.
"""
import argparse
import concurrent.futures
import json
import pathlib
import tempfile

import numpy as np
import scipy.signal
import soundfile

import felt
import music
from music_corpus import level_name
from shared import read_hits, read_mono, run

PART_PULSE_S = 0.08  # music.PULSE_S + parts.settle_ms: a part route's pulse starts when decided
CLEAR_S = 0.1  # another part's hit counts when no hit of the output's own part is this near
BELOW_DB = 10.0
KICK_WINDOW_S = 0.15  # the band route's felt energy after a kick hit, felt.PULSE_WINDOW_S
BED_DB = 0  # the mixes measured: the bed at 0 dB re the drums
PANS = {"hard left": (1.0, 0.0), "0.8/0.2": (0.8, 0.2)}  # (left, right) gains
LAYOUTS = {"parts": ("kick", "snare"), "band": ("band:20-120",),
           "stereo": ("channel:1", "channel:2")}
OTHER = {"kick": "snare", "snare": "kick"}


def write_layouts(directory):
    """{name: path} of a layout file per LAYOUTS entry, one output per route."""
    paths = {}
    for name, routes in LAYOUTS.items():
        paths[name] = directory / f"{name}.toml"
        paths[name].write_text(f'description = "eval/routes.py: {", ".join(routes)}"\n' + "".join(
            f'[[output]]\nname = "out{k + 1}"\nroute = "{route}"\n'
            for k, route in enumerate(routes)))
    return paths


def felt_outputs(tactus, wav, layout, renders, preset):
    """The felt signal of each output of `wav` rendered with `layout`, and the rate."""
    out = renders / f"{wav.stem}.{layout.stem}.vibration.wav"
    run([tactus, "render", wav, "-o", out, "--force", "--preset", preset, "--layout", layout])
    y, rate = soundfile.read(out, dtype="float64", always_2d=True)
    return [felt.weighted(y[:, k], rate) for k in range(y.shape[1])], rate


def ratio_db(a, b, power=True):
    """a re b in dB (energies, or with power=False amplitudes); b silent: inf."""
    with np.errstate(divide="ignore"):
        return (10 if power else 20) * float(np.log10(a / b)) if b > 0 else float("inf")


def energy(signal):
    return float(np.sum(np.square(signal)))


def felt_peak(signal, rate, t):
    """The felt peak over [t, t + PART_PULSE_S]."""
    return felt.peak(felt.pulse(signal, rate, t, PART_PULSE_S))


def part_outputs(tactus, directory, name, layouts, renders, preset):
    """{part: (pulses on its output per own hit, dB below its own median peak per other hit, or
    None when fewer than half its own hits give a pulse)}."""
    hits = read_hits(directory / f"{name}.hits.csv")
    times, parts = music.truth(hits)
    parts = np.array(parts)
    signals, rate = felt_outputs(tactus, directory / f"{name}.wav", layouts["parts"], renders,
                                 preset)
    out = {}
    for part, signal in zip(LAYOUTS["parts"], signals):
        envelope = np.abs(scipy.signal.hilbert(signal))
        own = np.array([t for t, instrument, _ in hits if instrument == part])
        other = [t for t in times[parts == OTHER[part]] if np.all(np.abs(own - t) > CLEAR_S)]
        own_times = times[parts == part]
        pulses = [music.gives_pulse(envelope, rate, t, PART_PULSE_S) for t in own_times]
        if not pulses:  # a house song's snares all fall on its kicks, so are kicks
            below = []
        elif np.mean(pulses) < 0.5:  # the median own peak is no pulse's
            below = None
        else:
            own_peak = np.median([felt_peak(signal, rate, t) for t in own_times])
            below = [ratio_db(own_peak, felt_peak(signal, rate, t), power=False) for t in other]
        out[part] = (pulses, below)
    return out


def low_band(tactus, directory, name, layouts, renders, preset):
    """(share of the band render's felt energy on the mix after kick hits, the share of time those
    windows cover, bed stem re drum stem felt energy dB)."""
    (mix,), rate = felt_outputs(tactus, directory / f"{name}.wav", layouts["band"], renders, preset)
    bed, drums = (felt_outputs(tactus, directory / f"{name}.{stem}.wav", layouts["band"], renders,
                               preset)[0][0] for stem in ("bed", "drums"))
    inside = np.zeros(len(mix), dtype=bool)
    for t, instrument, _ in read_hits(directory / f"{name}.hits.csv"):
        if instrument == "kick":
            start = int(round(t * rate))
            inside[start:start + int(KICK_WINDOW_S * rate)] = True
    return energy(mix[inside]) / energy(mix), float(inside.mean()), ratio_db(energy(bed),
                                                                              energy(drums))


def pan(tactus, directory, song, layouts, renders, preset):
    """{pan: left re right felt energy dB} of the song's drums alone, panned."""
    x, rate = read_mono(directory / f"{song}-{level_name(None)}.wav")
    out = {}
    for k, (label, (left, right)) in enumerate(PANS.items()):
        stereo = renders / f"{song}-pan{k}.wav"
        soundfile.write(stereo, np.column_stack([left * x, right * x]), rate, subtype="FLOAT")
        (l, r), _ = felt_outputs(tactus, stereo, layouts["stereo"], renders, preset)
        out[label] = ratio_db(energy(l), energy(r))
    return out


def analyse_song(tactus, directory, entry, layouts, renders, preset):
    name = entry["name"]
    return {"where": f"{entry['style']} {entry['kit']}",
            "parts": part_outputs(tactus, directory, name, layouts, renders, preset),
            "band": low_band(tactus, directory, name, layouts, renders, preset),
            "pan": pan(tactus, directory, entry["song"], layouts, renders, preset)}


def measure(build_dir, work, preset, jobs):
    """{part: [each song's analyse_song()]} of the built corpus in `work`."""
    tactus = str(pathlib.Path(build_dir) / "bin/tactus")
    with tempfile.TemporaryDirectory(prefix="tactus-routes-") as tmp:
        renders = pathlib.Path(tmp)
        layouts = write_layouts(renders)
        with concurrent.futures.ThreadPoolExecutor(jobs) as pool:
            futures = {}
            for part in music.PARTS:
                directory = pathlib.Path(work) / part
                manifest = json.loads((directory / "manifest.json").read_text())
                futures[part] = [pool.submit(analyse_song, tactus, directory, e, layouts, renders,
                                             preset)
                                 for e in manifest["mixes"] if e["bed_db"] == BED_DB]
            return {part: [f.result() for f in songs] for part, songs in futures.items()}


# Cells of one part's songs.
def pulse_cell(songs, part):
    pulses = [p for s in songs for p in s["parts"][part][0]]
    return f"{np.mean(pulses):.3f} ({sum(pulses)} of {len(pulses)})"


def below_cells(songs, part):
    """(median dB below, share BELOW_DB below with the worst song) of the other part's hits."""
    lists = [(s["parts"][part][1], s["where"]) for s in songs]
    below = [d for ds, _ in lists if ds for d in ds]
    share = lambda ds: np.mean(np.array(ds) >= BELOW_DB)  # noqa: E731
    shares = [(share(ds), where) for ds, where in lists if ds]
    worst = min(shares)
    where = "every song" if len({v for v, _ in shares}) == 1 else worst[1]
    return (f"{np.median(below):.1f} ({len(below)} hits; songs with none "
            f"{sum(ds == [] for ds, _ in lists)}, left out {sum(ds is None for ds, _ in lists)})",
            f"{share(below):.3f}, worst {worst[0]:.2f} ({where})")


def spread_cell(songs, value, highest_worst=False, digits=1):
    """Median over songs / the worst song of value(song) (every song when all are equal)."""
    values = [(value(s), s["where"]) for s in songs]
    worst = max(values) if highest_worst else min(values)
    where = "every song" if len({v for v, _ in values}) == 1 else worst[1]
    return f"{np.median([v for v, _ in values]):.{digits}f} / {worst[0]:.{digits}f} ({where})"


def report(result):
    """The report's markdown lines: a table per measure, a column per part."""
    parts = list(result.values())
    header = ["| figure | " + " | ".join(p.replace("-", " ") for p in result) + " |",
              "|---" * (len(result) + 1) + "|"]

    def table(rows):
        return header + [f"| {label} | " + " | ".join(cell(p) for p in parts) + " |"
                         for label, cell in rows] + [""]

    clear = f"no {{}} hit within +-{1000 * CLEAR_S:.0f} ms"
    lines = ["# Routes", "",
             "`eval/routes.py`: tactus's layout routes on the music corpus's songs "
             "(`eval/music_corpus.py`), rendered with the preset alone and read through the felt "
             "model (`eval/felt.py`). Songs: " +
             ", ".join(f"{len(s)} {p}" for p, s in result.items()) + ".", "",
             "## Kick and snare on their own outputs, bed 0 dB", "",
             "Two outputs, route `kick` and route `snare`. Pulse: music.py's distinct felt "
             f"pulse over [hit, hit + {1000 * PART_PULSE_S:.0f} ms] (a part route starts when "
             "the part is decided, 20 ms after the onset), pooled. Below: the other part's hits "
             f"({clear.format('own-part')}), their felt peak over the same window re the median "
             "felt peak of the song's own-part hits on that output: median dB (pooled), and the "
             f"share {BELOW_DB:.0f} dB or more below with the song of the lowest share. Left "
             "out: the songs where fewer than half the own-part hits give a pulse on their "
             "output, whose median own-part peak is the decay between pulses.", ""]
    lines += table(
        [("kick hits with a pulse on the kick output", lambda p: pulse_cell(p, "kick")),
         ("snare hits with a pulse on the snare output", lambda p: pulse_cell(p, "snare")),
         (f"kick output: snare hits ({clear.format('kick')}) below the kick hits' median "
          "felt peak, median dB", lambda p: below_cells(p, "kick")[0]),
         (f"kick output: share of those snare hits {BELOW_DB:.0f} dB or more below",
          lambda p: below_cells(p, "kick")[1]),
         (f"snare output: kick hits ({clear.format('snare')}) below the snare hits' median "
          "felt peak, median dB", lambda p: below_cells(p, "snare")[0]),
         (f"snare output: share of those kick hits {BELOW_DB:.0f} dB or more below",
          lambda p: below_cells(p, "snare")[1])])
    lines += ["## A low band route under a voice", "",
              "One output, route `band:20-120`. The corpus keeps no voice stem: its bed stem "
              "holds the voice with bass, chords and melody, so this is the band route on the "
              "bed as a whole. Felt energy: the felt signal squared, summed. Median over songs / "
              "the worst song.", ""]
    lines += table(
        [(f"the mix: felt energy within {1000 * KICK_WINDOW_S:.0f} ms after kick hits, share",
          lambda p: spread_cell(p, lambda s: s["band"][0], digits=3)),
         ("the mix: the share of the time those windows cover",
          lambda p: f"{np.median([s['band'][1] for s in p]):.3f} (median)"),
         ("the bed stem alone re the drum stem alone, felt energy dB",
          lambda p: spread_cell(p, lambda s: s["band"][2], highest_worst=True))])
    lines += ["## Pan", "",
              "The drums alone made stereo, two outputs, route `channel:1` and `channel:2`: "
              "left re right felt energy, dB (inf: the right output all zeros). Median over "
              "songs / the worst song (the least apart).", ""]
    lines += table([(f"{label} (input {ratio_db(left, right, power=False):.1f} dB)",
                     lambda p, label=label: spread_cell(p, lambda s: s["pan"][label]))
                    for label, (left, right) in PANS.items()])
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("build_dir", type=pathlib.Path)
    parser.add_argument("--work", type=pathlib.Path, required=True,
                        help="the music corpus's folder (eval/music_corpus.py, built)")
    parser.add_argument("--preset", default="music")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--out", type=pathlib.Path, default=None)
    args = parser.parse_args()
    text = "\n".join(report(measure(args.build_dir, args.work, args.preset, args.jobs)))
    print(text)
    if args.out:
        args.out.write_text(text + "\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
