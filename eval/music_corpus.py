"""Full music mixes whose drum hits are exactly known, for measuring tactus on drums inside music.

A song is a drum stem and a bed without drums. The drum stem is one-shot hits placed sample-exactly
as eval/drum_corpus.cpp places them (each sample trimmed to its first sample above 1 % of its peak
and scaled to peak 1, then the hit's gain), in one of several styles, so every hit's time, part
and gain is known. The bed is a bass line, chords (a pad, or comping stabs) and a melody, rendered
by fluidsynth from MIDI written here on melodic channels (no drum channel, reverb and chorus off),
and a voice-like lead: espeak-ng phrases placed on bar starts. Its parts are balanced by RMS (bass
0 dB, chords -3 dB, melody -5 dB, voice -2 dB).

Each song is written alone (the drums only) and with its bed at -12, -6, 0 and +6 dB re the
drums, the RMS of the bed stem over the whole song against the RMS of the drum stem over the whole
song. Some songs put the whole mix through sox's `reverb` and/or a bus compressor (`compand`, no
look-ahead delay, so no hit moves); the alone version of such a song gets the same processing.
Every mix is then peak-normalised to -1 dBFS. Per mix: NAME.wav (mono), NAME.hits.csv
(time_s,instrument,gain_db as eval/drum_corpus.cpp writes it: instrument kick|snare|hat, gain re
the sample's peak) and, with a bed, NAME.drums.wav and NAME.bed.wav: the two stems as they went
into the mix, scaled by the mix's normalisation, without the bus processing.

Isolated hits over music: per kit, its kick alone and its snare alone, 9 hits 1 s apart from 0.25 s
at gains 0, -3, ..., -24 dB (minus 1 dB, shuffled, as drum_corpus.cpp's gain_series), alone and
over a bed at -12 and -6 dB re the loudest hit: the bed's RMS over the whole file against the RMS
of the 0 dB hit over its first 100 ms. No bus processing, 44.1 kHz.

The drums alone are also written in white noise (NAME.noise.wav, NOISE_DB re their RMS).

Four parts. Tuning: the eight Sonic Pi kits of eval/drum_corpus.cpp's kits() (read from that file),
beds from FluidR3_GM, styles rock, house, funk, half-time and hip-hop, seed 1. Held out: the
General MIDI kits of eval/gm_kits.py, beds from TimGM6mb and MuseScore_General with other GM
programs, voices and phrases, the same five style families drawn with seed 2 and two styles the
tuning part lacks (shuffle, two-step), so no pattern repeats. Recorded kits (eval/recorded_kits.py:
Hydrogen's acoustic kits sampled at several strengths, each hit playing its velocity's recording,
and electronic kits), tuning and held out: their beds, programs and styles as the tuning and the
held-out part's, seeds 3 and 4. A quarter of the songs are at
48 kHz, the rest at 44.1 kHz. manifest.json lists every file with its part, song, kit, style,
tempo, bed level, processing and rate. Files that exist are left as they are.
"""
import concurrent.futures
import json
import pathlib
import re
import subprocess
import tempfile

import numpy as np
import scipy.signal
import soundfile

import gm_kits
import recorded_kits

EVAL = pathlib.Path(__file__).resolve().parent
SONIC_PI = pathlib.Path("/usr/share/sonic-pi/samples")
FONTS = {"fluid": "/usr/share/sounds/sf2/FluidR3_GM.sf2",
         "timgm6mb": "/usr/share/sounds/sf2/TimGM6mb.sf2",
         "musescore": "/usr/share/sounds/sf3/MuseScore_General.sf3"}
BED_LEVELS_DB = (-12, -6, 0, 6)
GAIN_BED_LEVELS_DB = (-12, -6)
PEAK = 10 ** (-1 / 20)  # -1 dBFS
LEAD_S, TAIL_S = 0.3, 0.8
PART_DB = {"bass": 0.0, "chords": -3.0, "melody": -5.0, "voice": -2.0}
NOISE_DB = -20  # the drums alone are also written in white noise this far below their RMS
REFERENCE_S = 0.1  # the isolated sets' bed level is re the loudest hit's RMS over this long
SLOT_S = 16.0  # each song's bed part is rendered in a slot this long (song, then ring)
SONGS_PER_KIT = 2
FX = {"dry": [], "reverb": ["reverb", "40", "50", "70"],
      "compand": ["compand", "0.005,0.12", "6:-40,-40,-20,-12,0,-6", "0", "-20", "0"],
      "reverb+compand": ["reverb", "30", "50", "60",
                         "compand", "0.005,0.12", "6:-40,-40,-20,-12,0,-6", "0", "-20", "0"]}

# GM programs (0-based) per role; the held-out part uses none of the tuning part's.
PROGRAMS = {
    "tuning": {"bass": [33, 34, 38], "pad": [48, 89, 16], "stabs": [0, 4, 26],
               "melody": [80, 56, 73, 65]},
    "held-out": {"bass": [32, 35, 39], "pad": [49, 91, 19], "stabs": [2, 5, 27, 25],
                 "melody": [81, 61, 66, 11]},
}
VOICES = {
    "tuning": {"voices": ["en+f3", "en+m3", "en-us+f2"],
               "phrases": ["oh yeah", "feel the beat tonight", "la la la la", "hold on to me"]},
    "held-out": {"voices": ["en+f4", "en-gb+m2", "en-us+m5", "en+f1"],
                 "phrases": ["come on now", "we are dancing", "na na na", "take me higher"]},
}
STYLES = {"tuning": ["rock", "house", "funk", "halftime", "hiphop"],
          "held-out": ["rock", "house", "funk", "halftime", "hiphop", "shuffle", "twostep"]}
TEMPO_BPM = {"rock": (100, 140), "house": (118, 128), "funk": (88, 112), "halftime": (140, 170),
             "hiphop": (70, 96), "shuffle": (72, 100), "twostep": (160, 172)}
SEEDS = {"tuning": 1, "held-out": 2, "recorded-tuning": 3, "recorded-held-out": 4}
# The recorded kits' parts take their beds' programs, voices, fonts and styles from these.
BEDS_OF = {"tuning": "tuning", "held-out": "held-out", "recorded-tuning": "tuning",
           "recorded-held-out": "held-out"}
PROGRESSIONS = {"major": [[0, 7, 9, 5], [0, 5, 7, 0], [2, 7, 0, 9]],
                "minor": [[0, 8, 3, 10], [0, 5, 7, 0], [0, 10, 8, 7]]}
SCALES = {"major": [0, 2, 4, 5, 7, 9, 11], "minor": [0, 2, 3, 5, 7, 8, 10]}


def sonic_pi_kits():
    """(name, kick, snare, hat) of each kit of eval/drum_corpus.cpp's kits(), read from it so the
    two lists cannot drift apart."""
    source = (EVAL / "drum_corpus.cpp").read_text()
    body = source[source.index("kits() {"):]
    body = body[:body.index("};")]
    return re.findall(r'\{"([^"]+)", "([^"]+)", "([^"]+)", "([^"]+)"\}', body)


# Drum patterns. Each returns one bar's hits as (position in steps, instrument, gain dB), with
# the bar's number of steps; positions may be fractional (swing).
def rock(rng, bar, bars):
    hits = [(s, "hat", rng.uniform(-8, -5) if s % 4 == 0 else rng.uniform(-12, -8))
            for s in range(0, 16, 2)]
    hits += [(0, "kick", rng.uniform(-1, 0)), (8, "kick", rng.uniform(-4, -1))]
    hits += [(s, "kick", rng.uniform(-6, -2)) for s in (6, 10, 11) if rng.random() < 0.35]
    hits += [(4, "snare", rng.uniform(-2, 0)), (12, "snare", rng.uniform(-2, 0))]
    if bar == bars - 1:  # a fill into the next round
        hits += [(s, "snare", rng.uniform(-10, -3)) for s in (13, 14, 15)]
    return hits, 16


def house(rng, bar, bars):
    hits = [(s, "kick", rng.uniform(-1.5, 0)) for s in (0, 4, 8, 12)]
    hits += [(s, "hat", rng.uniform(-6, -3)) for s in (2, 6, 10, 14)]
    hits += [(s, "hat", rng.uniform(-14, -10)) for s in (1, 3, 5, 7, 9, 11, 13, 15)
             if rng.random() < 0.25]
    hits += [(4, "snare", rng.uniform(-4, -1)), (12, "snare", rng.uniform(-4, -1))]
    return hits, 16


def funk(rng, bar, bars):
    hits = [(s, "hat", rng.uniform(-8, -5) if s % 2 == 0 else rng.uniform(-14, -10))
            for s in range(16)]
    hits += [(0, "kick", rng.uniform(-1, 0))]
    hits += [(s, "kick", rng.uniform(-5, -1)) for s in (3, 6, 7, 10, 11, 14) if rng.random() < 0.4]
    hits += [(4, "snare", rng.uniform(-2, 0)), (12, "snare", rng.uniform(-2, 0))]
    hits += [(s, "snare", rng.uniform(-14, -8)) for s in (1, 3, 7, 9, 11, 15) if rng.random() < 0.3]
    return hits, 16


def halftime(rng, bar, bars):
    hits = [(s, "hat", rng.uniform(-9, -5)) for s in range(0, 16, 2)]
    hits += [(0, "kick", rng.uniform(-1, 0))]
    hits += [(s, "kick", rng.uniform(-5, -1)) for s in (3, 6, 10, 11, 14) if rng.random() < 0.35]
    hits += [(8, "snare", rng.uniform(-1.5, 0))]
    hits += [(s, "snare", rng.uniform(-14, -8)) for s in (5, 13, 15) if rng.random() < 0.15]
    return hits, 16


def hiphop(rng, bar, bars):
    """Swung sixteenths: each odd sixteenth late by a swing of 55-62 % of the eighth."""
    swing = 2 * rng.uniform(0.55, 0.62)
    at = lambda s: s - 1 + swing if s % 2 else s  # noqa: E731
    hits = [(at(s), "hat", rng.uniform(-9, -5) if s % 2 == 0 else rng.uniform(-14, -9))
            for s in range(16) if s % 2 == 0 or rng.random() < 0.3]
    hits += [(0, "kick", rng.uniform(-1, 0))]
    hits += [(at(s), "kick", rng.uniform(-5, -1)) for s in (7, 10, 11, 13) if rng.random() < 0.45]
    hits += [(4, "snare", rng.uniform(-2, 0)), (12, "snare", rng.uniform(-2, 0))]
    hits += [(at(s), "snare", rng.uniform(-14, -8)) for s in (9, 15) if rng.random() < 0.25]
    return hits, 16


def shuffle(rng, bar, bars):
    """Triplet eighths, 12 to the bar: hats on the first and third of each beat's three."""
    hits = [(b * 3 + t, "hat", rng.uniform(-8, -5) if t == 0 else rng.uniform(-13, -9))
            for b in range(4) for t in (0, 2)]
    hits += [(0, "kick", rng.uniform(-1, 0)), (6, "kick", rng.uniform(-4, -1))]
    hits += [(s, "kick", rng.uniform(-6, -2)) for s in (5, 8, 11) if rng.random() < 0.3]
    hits += [(3, "snare", rng.uniform(-2, 0)), (9, "snare", rng.uniform(-2, 0))]
    hits += [(s, "snare", rng.uniform(-14, -8)) for s in (2, 8, 11) if rng.random() < 0.2]
    return hits, 12


def twostep(rng, bar, bars):
    hits = [(s, "hat", rng.uniform(-9, -5)) for s in range(0, 16, 2)]
    hits += [(s, "hat", rng.uniform(-14, -10)) for s in (3, 7, 11, 15) if rng.random() < 0.3]
    hits += [(0, "kick", rng.uniform(-1, 0)), (10, "kick", rng.uniform(-3, 0))]
    hits += [(4, "snare", rng.uniform(-2, 0)), (12, "snare", rng.uniform(-2, 0))]
    hits += [(s, "snare", rng.uniform(-14, -8)) for s in (7, 9, 15) if rng.random() < 0.3]
    return hits, 16


PATTERNS = {f.__name__: f for f in (rock, house, funk, halftime, hiphop, shuffle, twostep)}


def drum_hits(style, tempo_bpm, bars, rng):
    """(time s, instrument, gain dB) of every hit of `bars` bars of `style`, from LEAD_S."""
    bar_s = 4 * 60.0 / tempo_bpm
    hits = []
    for bar in range(bars):
        pattern, steps = PATTERNS[style](rng, bar, bars)
        hits += [(LEAD_S + bar * bar_s + position * bar_s / steps, instrument, round(gain, 2))
                 for position, instrument, gain in pattern]
    return sorted(hits)


def load(path, rate):
    """A one-shot as eval/drum_corpus.cpp loads it (mono, from its first sample above 1 % of its
    peak, scaled to peak 1), resampled to `rate`."""
    audio, native = soundfile.read(path, dtype="float64", always_2d=True)
    audio = audio.mean(axis=1)
    peak = np.max(np.abs(audio))
    audio = audio[np.argmax(np.abs(audio) > 0.01 * peak):] / peak
    if native != rate:
        g = np.gcd(native, rate)
        audio = scipy.signal.resample_poly(audio, rate // g, native // g)
    return audio


def place(mix, sample, time_s, gain_db, rate):
    start = int(round(time_s * rate))
    end = min(len(mix), start + len(sample))
    mix[start:end] += 10 ** (gain_db / 20) * sample[:end - start]


def layer_for(gain_db, layered):
    """The item of `layered` ([(highest velocity, anything)], softest first) a hit of gain_db
    plays: the layer of velocity 10 ** (gain_db / 40) (a level of 40 log10 v, so 0 to -24 dB spans
    velocities 1 to 0.25: the loud hits and the ghost notes of a kit sampled at several strengths
    take their own recordings, duller when soft, as a drummer's do)."""
    velocity = 10 ** (gain_db / 40)
    return next((item for top, item in layered if velocity <= top), layered[-1][1])


def drum_stem(hits, samples, length, rate):
    """`samples`: {instrument: [(highest velocity, audio)]}, each hit playing its velocity's layer
    (one-shots are one layer)."""
    stem = np.zeros(length)
    for t, instrument, gain in hits:
        place(stem, layer_for(gain, samples[instrument]), t, gain, rate)
    return stem


def load_layers(layers, rate):
    return [(top, load(path, rate)) for top, path in layers]


def rms(x):
    return float(np.sqrt(np.mean(np.square(x))))


# The bed.
def chords_of(song):
    root, mode = song["key"], song["mode"]
    scale = SCALES[mode]
    chords = []
    for degree_root in song["progression"]:
        step = min(range(7), key=lambda i: (scale[i] - degree_root) % 12)
        chords.append([root + scale[(step + k) % 7] + 12 * ((step + k) // 7) for k in (0, 2, 4)])
    return chords


def note(events, channel, pitch, velocity, start_s, end_s):
    events += [(start_s, [0x90 | channel, pitch, velocity]), (end_s, [0x80 | channel, pitch, 0])]


def bed_events(song, role, offset_s):
    """MIDI events (channel 0) of one bed part of `song`, its bars from offset_s + LEAD_S."""
    rng = np.random.default_rng([song["seed"], role_seed(role)])
    beat_s = 60.0 / song["tempo_bpm"]
    bar_s = 4 * beat_s
    start = offset_s + LEAD_S
    chords = chords_of(song)
    events = [(offset_s, [0xC0, song["programs"][role]])]
    for bar in range(song["bars"]):
        t0 = start + bar * bar_s
        chord = chords[bar % len(chords)]
        if role == "bass":
            onsets = sorted({0, *[s for s in (3, 6, 8, 10, 12, 14) if rng.random() < 0.45]})
            for i, s in enumerate(onsets):
                end = onsets[i + 1] if i + 1 < len(onsets) else 16
                pitch = 36 + (chord[0] % 12) + (7 if rng.random() < 0.2 else 0)
                note(events, 0, pitch, int(rng.integers(90, 115)), t0 + s * bar_s / 16,
                     t0 + (end - 0.3) * bar_s / 16)
        elif role == "chords" and song["chord_style"] == "pad":
            for p in chord:
                note(events, 0, 48 + p % 12 + 12, int(rng.integers(65, 90)), t0, t0 + bar_s * 0.98)
        elif role == "chords":  # stabs on the off-beats or on the beats
            offbeat = rng.random() < 0.5
            for beat in range(4):
                t = t0 + (beat + 0.5 * offbeat) * beat_s
                for p in chord:
                    note(events, 0, 60 + p % 12, int(rng.integers(70, 100)), t, t + 0.4 * beat_s)
        elif role == "melody":
            scale = SCALES[song["mode"]]
            degree = int(rng.integers(0, 7))
            s = int(rng.integers(0, 3)) * 2
            while s < 16:
                length = int(rng.choice([2, 2, 4, 6]))
                degree = int(np.clip(degree + rng.integers(-2, 3), 0, 9))
                pitch = 72 + song["key"] % 12 + scale[degree % 7] + 12 * (degree // 7)
                if rng.random() < 0.8:
                    note(events, 0, pitch, int(rng.integers(75, 105)), t0 + s * bar_s / 16,
                         t0 + (s + length - 0.2) * bar_s / 16)
                s += length
    return events


def role_seed(role):
    """A fixed number per role, so each part of a song draws from its own random stream."""
    return sum(ord(c) for c in role)


def render_parts(songs, font, rate, work):
    """Renders the bass, chords and melody of `songs` (one soundfont, one rate) by fluidsynth,
    each role of every song in its own slot of one file; returns {name: {role: mono audio}}."""
    out = {song["name"]: {} for song in songs}
    for role in ("bass", "chords", "melody"):
        events = []
        for i, song in enumerate(songs):
            events += bed_events(song, role, i * SLOT_S)
        mid = work / f"{font}-{rate}-{role}.mid"
        wav = work / f"{font}-{rate}-{role}.wav"
        mid.write_bytes(gm_kits.smf(events))
        subprocess.run(["fluidsynth", "-ni", "-q", "-R", "0", "-C", "0", "-g", "0.5",
                        "-r", str(rate), "-T", "wav", "-O", "float", "-F", str(wav), FONTS[font],
                        str(mid)], check=True, capture_output=True)
        audio, _ = soundfile.read(wav, dtype="float64", always_2d=True)
        audio = audio.mean(axis=1)
        slot = int(SLOT_S * rate)
        for i, song in enumerate(songs):
            part = audio[i * slot:(i + 1) * slot][:song["length"]]
            out[song["name"]][role] = np.pad(part, (0, song["length"] - len(part)))
        mid.unlink()
        wav.unlink()
    return out


def voice_part(song, work):
    """espeak-ng phrases on the bar starts (every bar, or every other), each trimmed to its first
    sample above 1 % of its peak so it starts on the beat."""
    rng = np.random.default_rng([song["seed"], role_seed("voice")])
    rate = song["rate"]
    part = np.zeros(song["length"])
    bar_s = 4 * 60.0 / song["tempo_bpm"]
    every = 1 if bar_s > 2.5 else 2
    for bar in range(0, song["bars"], every):
        wav = work / f"{song['name']}-voice-{bar}.wav"
        text = str(rng.choice(song["phrases"]))
        subprocess.run(["espeak-ng", "-v", song["voice"], "-s", str(int(rng.integers(120, 170))),
                        "-p", str(song["pitch"]), "-w", str(wav), text],
                       check=True, capture_output=True)
        place(part, load(wav, rate), LEAD_S + bar * bar_s, 0.0, rate)
        wav.unlink()
    return part


def bed_mix(parts):
    """The parts summed, each at its PART_DB re RMS 1."""
    return sum(10 ** (PART_DB[role] / 20) * x / max(rms(x), 1e-12) for role, x in parts.items())


# The corpus.
def kits_of(part, gm_samples):
    """{kit: {instrument: [(highest velocity, sample path)]}} of the part's kits (one-shots: one
    layer)."""
    if part.startswith("recorded"):
        return recorded_kits.kits(part)
    if part == "tuning":
        return {name: {"kick": [(1.0, SONIC_PI / f"{k}.flac")],
                       "snare": [(1.0, SONIC_PI / f"{s}.flac")],
                       "hat": [(1.0, SONIC_PI / f"{h}.flac")]}
                for name, k, s, h in sonic_pi_kits()}
    kits = gm_kits.render(gm_samples)
    return {kit: {i: [(1.0, pathlib.Path(gm_samples) / f"{kit}_{i}.flac")]
                  for i in gm_kits.INSTRUMENTS} for kit in kits}


def songs_of(part, kits):
    """The song specs of one part, deterministic from its seed."""
    rng = np.random.default_rng(SEEDS[part])
    beds_of = BEDS_OF[part]
    fonts = ["fluid"] if beds_of == "tuning" else ["timgm6mb", "musescore"]
    programs, voices = PROGRAMS[beds_of], VOICES[beds_of]
    styles = STYLES[beds_of]
    songs = []

    def bed(index, name, length_s=None, tempo=None):
        mode = str(rng.choice(["major", "minor"]))
        chord_style = str(rng.choice(["pad", "stabs"]))
        tempo = tempo or float(rng.uniform(90, 130))
        # About 10 s of bars for a song; a gain series' bed covers at least length_s.
        bars = int(np.ceil(length_s * tempo / 240)) if length_s else \
            max(2, int(round(10.0 * tempo / 240)))
        return {"name": name, "seed": SEEDS[part] * 1000 + index, "mode": mode,
                "key": int(rng.integers(0, 12)),
                "progression": [int(d) for d in PROGRESSIONS[mode][rng.integers(0, 3)]],
                "chord_style": chord_style, "tempo_bpm": round(tempo, 2), "bars": bars,
                "font": fonts[index % len(fonts)],
                "programs": {"bass": int(rng.choice(programs["bass"])),
                             "chords": int(rng.choice(programs[chord_style])),
                             "melody": int(rng.choice(programs["melody"]))},
                "voice": str(rng.choice(voices["voices"])), "pitch": int(rng.integers(30, 75)),
                "phrases": voices["phrases"]}

    index = 0
    for kit in kits:
        for _ in range(SONGS_PER_KIT):
            style = styles[index % len(styles)]
            tempo = float(rng.uniform(*TEMPO_BPM[style]))
            song = bed(index, f"{part}-{index:02d}-{style}-{kit}", tempo=tempo)
            song.update(kit=kit, style=style, rate=48000 if index % 4 == 3 else 44100,
                        fx=str(rng.choice(list(FX), p=[0.4, 0.2, 0.2, 0.2])))
            song["length"] = int((LEAD_S + song["bars"] * 240 / tempo + TAIL_S) * song["rate"])
            songs.append(song)
            index += 1
    for kit in kits:  # one bed per kit for its isolated hits, as long as the gain series
        song = bed(index, f"{part}-gainbed-{kit}", length_s=9.0)
        song.update(kit=kit, style="gain", rate=44100, fx="dry",
                    length=int((0.25 + 9 + 1.0) * 44100))
        songs.append(song)
        index += 1
    return songs


def level_name(level_db):
    return "alone" if level_db is None else f"bed{level_db:+d}dB"


def write_hits(path, hits):
    path.write_text("time_s,instrument,gain_db\n" +
                    "".join(f"{t:.6f},{i},{g:.2f}\n" for t, i, g in hits))


def processed(mix, rate, fx, work):
    """The mix through sox's effects `fx` (none: itself), then peak-normalised to -1 dBFS; and
    that normalisation's gain."""
    if FX[fx]:
        scale = 0.25 / np.max(np.abs(mix))  # headroom inside sox
        with tempfile.TemporaryDirectory(dir=work) as tmp:
            src, dst = pathlib.Path(tmp) / "in.wav", pathlib.Path(tmp) / "out.wav"
            soundfile.write(src, mix * scale, rate, subtype="FLOAT")
            subprocess.run(["sox", "-V1", str(src), "-e", "floating-point", str(dst)] + FX[fx],
                           check=True, capture_output=True)
            out, _ = soundfile.read(dst, dtype="float64")
        mix = out[:len(mix)] / scale
    else:
        scale = 1.0
    gain = PEAK / np.max(np.abs(mix))
    return mix * gain, gain


def in_noise(mix, seed):
    """The mix with white noise NOISE_DB re its RMS added, peak-normalised again."""
    noise = np.random.default_rng([seed, role_seed("noise")]).standard_normal(len(mix))
    noisy = mix + noise * rms(mix) * 10 ** (NOISE_DB / 20)
    return noisy * PEAK / np.max(np.abs(noisy))


def write_song(song, bed, kit_samples, out, work):
    """The song's mixes: alone and at each bed level; returns their manifest entries."""
    rate = song["rate"]
    samples = {i: load_layers(layers, rate) for i, layers in kit_samples.items()}
    hits = drum_hits(song["style"], song["tempo_bpm"], song["bars"],
                     np.random.default_rng([song["seed"], role_seed("drums")]))
    drums = drum_stem(hits, samples, song["length"], rate)
    entries = []
    for level in (None,) + BED_LEVELS_DB:
        name = f"{song['name']}-{level_name(level)}"
        entries.append({"name": name, "song": song["name"], "kit": song["kit"],
                        "style": song["style"], "tempo_bpm": song["tempo_bpm"],
                        "bed_db": level, "fx": song["fx"], "rate": rate, "font": song["font"],
                        "programs": song["programs"], "voice": song["voice"]})
        if (out / f"{name}.wav").exists() and \
                (level is not None or (out / f"{name}.noise.wav").exists()):
            continue
        scaled_bed = 0 if level is None else bed * rms(drums) / rms(bed) * 10 ** (level / 20)
        mix, gain = processed(drums + scaled_bed, rate, song["fx"], work)
        soundfile.write(out / f"{name}.wav", mix, rate, subtype="PCM_24")
        if level is None:
            soundfile.write(out / f"{name}.noise.wav", in_noise(mix, song["seed"]), rate,
                            subtype="PCM_24")
        if level is not None:
            soundfile.write(out / f"{name}.drums.wav", drums * gain, rate, subtype="PCM_24")
            soundfile.write(out / f"{name}.bed.wav", scaled_bed * gain, rate, subtype="PCM_24")
        write_hits(out / f"{name}.hits.csv", hits)
    return entries


def gain_hits(instrument, rng):
    """drum_corpus.cpp's gain_series: 9 hits 1 s apart from 0.25 s, gains 0..-24 dB in 3 dB steps
    minus 1 dB, shuffled."""
    gains = rng.permutation(np.arange(0, -27, -3))
    return [(0.25 + i, instrument, float(g) - 1.0) for i, g in enumerate(gains)]


def write_gain_series(song, bed, kit_samples, out):
    """The kit's kick and snare series alone and over its bed at each GAIN_BED_LEVELS_DB."""
    rate, entries = song["rate"], []
    for instrument in ("kick", "snare"):
        layered = load_layers(kit_samples[instrument], rate)
        hits = gain_hits(instrument, np.random.default_rng([song["seed"], role_seed(instrument)]))
        drums = drum_stem(hits, {instrument: layered}, song["length"], rate)
        loudest = layer_for(-1, layered)
        reference = rms(10 ** (-1 / 20) * loudest[:int(REFERENCE_S * rate)])
        for level in (None,) + GAIN_BED_LEVELS_DB:
            name = f"{song['name'].replace('gainbed', 'gain')}-{instrument}-{level_name(level)}"
            entries.append({"name": name, "kit": song["kit"], "instrument": instrument,
                            "bed_db": level, "rate": rate, "font": song["font"]})
            if (out / f"{name}.wav").exists():
                continue
            scaled_bed = 0 if level is None else bed * reference / rms(bed) * 10 ** (level / 20)
            mix = drums + scaled_bed
            gain = PEAK / np.max(np.abs(mix))
            soundfile.write(out / f"{name}.wav", mix * gain, rate, subtype="PCM_24")
            if level is not None:
                soundfile.write(out / f"{name}.drums.wav", drums * gain, rate, subtype="PCM_24")
                soundfile.write(out / f"{name}.bed.wav", scaled_bed * gain, rate,
                                subtype="PCM_24")
            write_hits(out / f"{name}.hits.csv", hits)
    return entries


def beds(songs, work, jobs):
    """Each song's bed stem, cached as work/beds/NAME.bed.wav."""
    cache = work / "beds"
    cache.mkdir(parents=True, exist_ok=True)
    todo = [s for s in songs if not (cache / f"{s['name']}.bed.wav").exists()]
    groups = {}
    for song in todo:
        groups.setdefault((song["font"], song["rate"]), []).append(song)
    with concurrent.futures.ThreadPoolExecutor(jobs) as pool:
        rendered = {}
        for parts in pool.map(lambda key: render_parts(groups[key], *key, cache), groups):
            rendered.update(parts)
        voices = dict(zip([s["name"] for s in todo],
                          pool.map(lambda s: voice_part(s, cache), todo)))
    for song in todo:
        parts = dict(rendered[song["name"]], voice=voices[song["name"]])
        soundfile.write(cache / f"{song['name']}.bed.wav", bed_mix(parts), song["rate"],
                        subtype="FLOAT")
    return {s["name"]: soundfile.read(cache / f"{s['name']}.bed.wav", dtype="float64")[0]
            for s in songs}


def build(work, gm_samples, parts=("tuning", "held-out"), jobs=2):
    """Writes the corpus of `parts` into work/PART/ (cached); returns {part: manifest}, each
    {"mixes": [...], "gain": [...]}."""
    work = pathlib.Path(work)
    manifests = {}
    for part in parts:
        out = work / part
        out.mkdir(parents=True, exist_ok=True)
        kits = kits_of(part, gm_samples)
        songs = songs_of(part, kits)
        bed = beds(songs, work, jobs)
        with concurrent.futures.ThreadPoolExecutor(jobs) as pool:
            mixes = pool.map(lambda s: write_song(s, bed[s["name"]], kits[s["kit"]], out, work),
                             [s for s in songs if s["style"] != "gain"])
            gains = pool.map(lambda s: write_gain_series(s, bed[s["name"]], kits[s["kit"]], out),
                             [s for s in songs if s["style"] == "gain"])
            manifest = {"mixes": [e for m in mixes for e in m],
                        "gain": [e for g in gains for e in g]}
        (out / "manifest.json").write_text(json.dumps(manifest, indent=1))
        manifests[part] = manifest
    return manifests


if __name__ == "__main__":
    import sys
    result = build(pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[1]) / "gm-samples")
    for part, manifest in result.items():
        print(part, len(manifest["mixes"]), "mixes,", len(manifest["gain"]), "isolated-hit files")
