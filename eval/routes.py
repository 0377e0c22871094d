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
  it mean nothing. Then the same at each parts.route_min of ROUTE_MINS (--set): its trade.
- A low band under a voice: every bed has a voice (espeak-ng phrases on bar starts), but the bed
  stem (NAME-bed+0dB.bed.wav) holds it with the bass, chords and melody. One output, route
  `band:20-120` (layouts/seat.toml's band), rendered on the mix, on the bed stem alone and on the
  drum stem alone (NAME-bed+0dB.drums.wav; the stems as they went into the mix). Felt energy: the
  sum of the felt signal squared. Per song: the share of the mix render's felt energy inside
  [hit, hit + 150 ms] of its kick hits (with the share of the song's time those windows cover,
  what an output playing everything evenly would give: its median), and the bed stem render's
  felt energy re the drum stem render's (dB; a silent bed render: -inf). Median over songs and
  the worst song.
  The voice alone: the corpus keeps no voice stem, so each song's voice is rebuilt from its song
  spec, music_corpus.songs_of(part, kits_of(part, gm_samples)) (the held-out part's GM kit
  renders read from the cache beside the corpus, WORK/gm-samples or WORK/../gm-samples; none
  rendered: without a complete cache the part is "not rebuilt"), by music_corpus.voice_part, and
  checked against the bed stem: the song's bass, chords and melody are rebuilt too
  (music_corpus.render_parts, in the corpus's fluidsynth slots) and the whole bed
  (music_corpus.bed_mix) fitted to the bed stem by least squares (one gain: the bed's level re
  the drums and the mix's normalisation); the largest difference left, dB re the stem's peak,
  is reported (its worst song per part; about -124 dB is the stem's 24-bit rounding) and a part
  whose worst song is above -90 dB is "not rebuilt". The voice as it went into the mix is its
  bed_mix term (-2 dB re RMS 1) times that gain, written as a float WAV at the song's rate (dry:
  a reverb or compand song's mix has the bus processing, its voice alone not), and rendered with
  one output, route `band:20-120`, and with one output, route `all`. Per part: the band render's
  felt energy on the voice alone re the band render's on the mix (dB; -inf when the voice's band
  output is exactly silent, its felt signal all zeros), median over songs and the worst
  (highest) song, with the share of songs whose voice band output is exactly silent; and the
  `all` render's felt energy on the voice alone re the `all` render's on the mix (dB), its
  median: the voice is felt where it is routed.
- Pan: each song's drums alone (NAME-alone.wav) made stereo, hard left (right channel all zeros)
  and panned 0.8/0.2 (left 0.8 x, right 0.2 x: 12.0 dB apart), rendered with two outputs, route
  `channel:1` and `channel:2` (layouts/wrists.toml's routes). Left re right felt energy (dB):
  median over songs and the worst song (the least apart); inf when the right output is all zeros.
"""
import argparse
import concurrent.futures
import json
import pathlib
import subprocess
import tempfile

import numpy as np
import scipy.signal
import soundfile

import felt
import gm_kits
import music
import music_corpus
from music_corpus import level_name
from shared import read_hits, read_mono, run

PART_PULSE_S = 0.08  # music.PULSE_S + parts.settle_ms: a part route's pulse starts when decided
CLEAR_S = 0.1  # another part's hit counts when no hit of the output's own part is this near
BELOW_DB = 10.0
KICK_WINDOW_S = 0.15  # the band route's felt energy after a kick hit, felt.PULSE_WINDOW_S
BED_DB = 0  # the mixes measured: the bed at 0 dB re the drums
PANS = {"hard left": (1.0, 0.0), "0.8/0.2": (0.8, 0.2)}  # (left, right) gains
VOICE_FIT_DB = -90.0  # the rebuilt bed, fitted to the bed stem, differs from it at most this much
LAYOUTS = {"parts": ("kick", "snare"), "band": ("band:20-120",), "all": ("all",),
           "stereo": ("channel:1", "channel:2")}
OTHER = {"kick": "snare", "snare": "kick"}
# parts.route_min swept for its trade (1: only the hits named the route's part; the default 0.35
# is the least of these keeping the tuning parts' share of other-part hits 10 dB under at 0.85).
ROUTE_MINS = (1.0, 0.5, 0.4, 0.35, 0.3, 0.25, 0.2)


def write_layouts(directory):
    """{name: path} of a layout file per LAYOUTS entry, one output per route."""
    paths = {}
    for name, routes in LAYOUTS.items():
        paths[name] = directory / f"{name}.toml"
        paths[name].write_text(f'description = "eval/routes.py: {", ".join(routes)}"\n' + "".join(
            f'[[output]]\nname = "out{k + 1}"\nroute = "{route}"\n'
            for k, route in enumerate(routes)))
    return paths


def felt_outputs(tactus, wav, layout, renders, preset, route_min=None):
    """The felt signal of each output of `wav` rendered with `layout` (and parts.route_min), and
    the rate."""
    tail = "" if route_min is None else f".route-min-{route_min}"
    out = renders / f"{wav.stem}.{layout.stem}{tail}.vibration.wav"
    run([tactus, "render", wav, "-o", out, "--force", "--preset", preset, "--layout", layout]
        + ([] if route_min is None else ["--set", f"parts.route_min={route_min}"]))
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


def part_outputs(tactus, directory, name, layouts, renders, preset, route_min=None):
    """{part: (pulses on its output per own hit, dB below its own median peak per other hit, or
    None when fewer than half its own hits give a pulse)}."""
    hits = read_hits(directory / f"{name}.hits.csv")
    times, parts = music.truth(hits)
    parts = np.array(parts)
    signals, rate = felt_outputs(tactus, directory / f"{name}.wav", layouts["parts"], renders,
                                 preset, route_min)
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
    windows cover, bed stem re drum stem felt energy dB, the band render's felt energy on the
    mix)."""
    (mix,), rate = felt_outputs(tactus, directory / f"{name}.wav", layouts["band"], renders, preset)
    bed, drums = (felt_outputs(tactus, directory / f"{name}.{stem}.wav", layouts["band"], renders,
                               preset)[0][0] for stem in ("bed", "drums"))
    inside = np.zeros(len(mix), dtype=bool)
    for t, instrument, _ in read_hits(directory / f"{name}.hits.csv"):
        if instrument == "kick":
            start = int(round(t * rate))
            inside[start:start + int(KICK_WINDOW_S * rate)] = True
    return (energy(mix[inside]) / energy(mix), float(inside.mean()),
            ratio_db(energy(bed), energy(drums)), energy(mix))


def gm_samples_of(work):
    """The folder beside the corpus holding every GM kit render (eval/gm_kits.py) the held-out
    part's kits are, or None (none is rendered here)."""
    names = [f"{kit}_{i}.flac" for kit in gm_kits.KITS for i in gm_kits.INSTRUMENTS]
    for folder in (work / "gm-samples", work.parent / "gm-samples"):
        if all((folder / n).exists() for n in names):
            return folder
    return None


def rebuilt_voices(part, directory, gm_samples, tmp):
    """{song: (its voice as it went into its mix with the bed at BED_DB, the rebuilt bed's largest
    difference from the bed stem dB re the stem's peak)} of the part's songs, or why not rebuilt."""
    if gm_samples is None and part not in ("tuning", "recorded-tuning", "recorded-held-out"):
        return "not rebuilt (no cached GM kit renders)"
    songs = [s for s in music_corpus.songs_of(part, music_corpus.kits_of(part, gm_samples))
             if s["style"] != "gain"]  # the gain beds follow the songs in every fluidsynth file
    work = tmp / f"voices-{part}"
    work.mkdir()
    groups, others = {}, {}
    for song in songs:
        groups.setdefault((song["font"], song["rate"]), []).append(song)
    for (font, rate), group in groups.items():
        others.update(music_corpus.render_parts(group, font, rate, work))
    out = {}
    for song in songs:
        voice = music_corpus.voice_part(song, work)
        bed = music_corpus.bed_mix(dict(others[song["name"]], voice=voice))
        stem, rate = read_mono(directory / f"{song['name']}-{level_name(BED_DB)}.bed.wav")
        if rate != song["rate"] or len(stem) != len(bed):
            return f"not rebuilt ({song['name']}: {len(bed)} samples at {song['rate']} Hz)"
        gain = np.dot(stem, bed) / np.dot(bed, bed)
        out[song["name"]] = (gain * music_corpus.bed_mix({"voice": voice}),
                             ratio_db(np.max(np.abs(stem - gain * bed)), np.max(np.abs(stem)),
                                      power=False))
    worst = max(d for _, d in out.values())
    return out if worst <= VOICE_FIT_DB else f"not rebuilt (rebuilt bed {worst:.1f} dB off)"


def voice_alone(tactus, entry, voice, mix_band, directory, layouts, renders, preset):
    """The song's voice alone: {band: its band render's felt energy re the mix's dB, silent:
    whether its felt signal is all zeros, all: its `all` render's felt energy re the mix's dB,
    fit: the rebuilt bed's difference from the bed stem dB}."""
    wav = renders / f"{entry['song']}-voice.wav"
    soundfile.write(wav, voice[0], entry["rate"], subtype="FLOAT")
    (band,), _ = felt_outputs(tactus, wav, layouts["band"], renders, preset)
    (every,), _ = felt_outputs(tactus, wav, layouts["all"], renders, preset)
    (mix,), _ = felt_outputs(tactus, directory / f"{entry['name']}.wav", layouts["all"], renders,
                             preset)
    return {"band": ratio_db(energy(band), mix_band), "silent": energy(band) == 0,
            "all": ratio_db(energy(every), energy(mix)), "fit": voice[1]}


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


def analyse_song(tactus, directory, entry, voice, layouts, renders, preset):
    """The song's figures; `voice`: (its rebuilt voice, the fit) or why it is not rebuilt."""
    name = entry["name"]
    band = low_band(tactus, directory, name, layouts, renders, preset)
    return {"where": f"{entry['style']} {entry['kit']}",
            "parts": part_outputs(tactus, directory, name, layouts, renders, preset),
            "band": band,
            "voice": voice if isinstance(voice, str) else voice_alone(
                tactus, entry, voice, band[3], directory, layouts, renders, preset),
            "pan": pan(tactus, directory, entry["song"], layouts, renders, preset)}


def measure(build_dir, work, preset, jobs):
    """{part: [each song's analyse_song()]} of the built corpus in `work`."""
    tactus = str(pathlib.Path(build_dir) / "bin/tactus")
    with tempfile.TemporaryDirectory(prefix="tactus-routes-") as tmp:
        renders = pathlib.Path(tmp)
        layouts = write_layouts(renders)
        gm_samples = gm_samples_of(pathlib.Path(work))
        with concurrent.futures.ThreadPoolExecutor(jobs) as pool:
            voices = {part: pool.submit(rebuilt_voices, part, pathlib.Path(work) / part,
                                        gm_samples, renders) for part in music.PARTS}
            futures = {}
            for part in music.PARTS:
                directory = pathlib.Path(work) / part
                manifest = json.loads((directory / "manifest.json").read_text())
                try:
                    rebuilt = voices[part].result()
                except (OSError, KeyError, subprocess.CalledProcessError) as error:
                    rebuilt = f"not rebuilt ({type(error).__name__})"
                songs = [e for e in manifest["mixes"] if e["bed_db"] == BED_DB]
                futures[part] = [pool.submit(
                    analyse_song, tactus, directory, e,
                    rebuilt if isinstance(rebuilt, str) else rebuilt[e["song"]],
                    layouts, renders, preset) for e in songs]
                for value in ROUTE_MINS:
                    futures[part, value] = [pool.submit(
                        part_outputs, tactus, directory, e["name"], layouts, renders, preset,
                        value) for e in songs]
            songs = {key: [f.result() for f in fs] for key, fs in futures.items()}
            return {part: [dict(song, trade={v: songs[part, v][k] for v in ROUTE_MINS})
                           for k, song in enumerate(songs[part])] for part in music.PARTS}


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


def trade_cell(songs, route_min):
    """Kick / snare hits with a pulse on their output; the share of the other part's hits 10 dB
    or more below on the kick / snare output; at parts.route_min = route_min."""
    def pooled(part):
        pulses = [p for s in songs for p in s["trade"][route_min][part][0]]
        below = [d for s in songs for d in (s["trade"][route_min][part][1] or [])]
        return np.mean(pulses), np.mean(np.array(below) >= BELOW_DB)
    (kick, kick_under), (snare, snare_under) = pooled("kick"), pooled("snare")
    return f"{kick:.3f} / {snare:.3f}; {kick_under:.3f} / {snare_under:.3f}"


def spread_cell(songs, value, highest_worst=False, digits=1):
    """Median over songs / the worst song of value(song) (every song when all are equal)."""
    values = [(value(s), s["where"]) for s in songs]
    worst = max(values) if highest_worst else min(values)
    where = "every song" if len({v for v, _ in values}) == 1 else worst[1]
    return f"{np.median([v for v, _ in values]):.{digits}f} / {worst[0]:.{digits}f} ({where})"


def voice_cell(songs, cell):
    """cell(songs) when the part's voices were rebuilt, else why not."""
    return songs[0]["voice"] if isinstance(songs[0]["voice"], str) else cell(songs)


def silent_cell(songs):
    silent = [s["voice"]["silent"] for s in songs]
    return f"{np.mean(silent):.3f} ({sum(silent)} of {len(silent)})"


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
    lines += ["### The trade of `parts.route_min`", "",
              "A part route also plays a hit the part model finds at least `parts.route_min` "
              "likely to be one of its parts (1: only the hits named its part). Each cell: kick / "
              "snare hits with a pulse on their own output; then the share of the other part's "
              f"hits {BELOW_DB:.0f} dB or more below on the kick / snare output, as above. The "
              "default, 0.35, is the least value here keeping both shares at 0.85 or more on the "
              "two tuning parts.", ""]
    lines += table([(f"`parts.route_min` {value:g}", lambda p, value=value: trade_cell(p, value))
                    for value in ROUTE_MINS])
    lines += ["## A low band route under a voice", "",
              "One output, route `band:20-120`. The bed stem holds the voice with bass, chords "
              "and melody. The corpus keeps no voice stem: each song's voice is rebuilt from its "
              "song spec (`music_corpus.voice_part`) and checked by rebuilding the whole bed and "
              "fitting it (one gain) to the bed stem; the voice alone at its level in the mix "
              "(without the mix's reverb or compand) is rendered with one output, route "
              "`band:20-120`, and with one output, route `all`, each against the same route on "
              "the mix (-inf: the voice's band output exactly silent). Felt energy: the felt "
              "signal squared, summed. Median over songs / the worst song.", ""]
    lines += table(
        [(f"the mix: felt energy within {1000 * KICK_WINDOW_S:.0f} ms after kick hits, share",
          lambda p: spread_cell(p, lambda s: s["band"][0], digits=3)),
         ("the mix: the share of the time those windows cover",
          lambda p: f"{np.median([s['band'][1] for s in p]):.3f} (median)"),
         ("the bed stem alone re the drum stem alone, felt energy dB",
          lambda p: spread_cell(p, lambda s: s["band"][2], highest_worst=True)),
         ("the rebuilt bed fitted to the bed stem: largest difference, dB re the stem's peak "
          "(worst song)",
          lambda p: voice_cell(p, lambda p: f"{max(s['voice']['fit'] for s in p):.1f}")),
         ("the voice alone re the mix, band route felt energy dB (worst: highest)",
          lambda p: voice_cell(p, lambda p: spread_cell(p, lambda s: s["voice"]["band"],
                                                        highest_worst=True))),
         ("songs whose band output on the voice alone is exactly silent, share",
          lambda p: voice_cell(p, silent_cell)),
         ("the voice alone re the mix, `all` route felt energy dB",
          lambda p: voice_cell(p, lambda p: f"{np.median([s['voice']['all'] for s in p]):.1f} "
                                            "(median)"))])
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
