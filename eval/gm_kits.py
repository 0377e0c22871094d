"""The held-out drum corpus's one-shot hits: General MIDI drum kits of three soundfonts from
Debian packages (fluid-soundfont-gm, musescore-general-soundfont-small, timgm6mb-soundfont),
rendered by fluidsynth one note at a time (note-on at time 0, velocity 100, reverb and chorus
off) and written as NAME.flac with the leading silence trimmed, so a hit placed at t starts at t.
eval/drum_corpus.cpp's gm_kits() places them as it places Sonic Pi's samples. None of these
kits was used to tune tactus."""

import pathlib
import struct
import subprocess

import numpy as np
import soundfile

SOUNDFONTS = {
    "fluid": "/usr/share/sounds/sf2/FluidR3_GM.sf2",
    "musescore": "/usr/share/sounds/sf3/MuseScore_General.sf3",
    "timgm6mb": "/usr/share/sounds/sf2/TimGM6mb.sf2",
}
# kit name: (soundfont, GM drum-kit program, kick, snare, hat notes). 35 is the acoustic bass
# drum (a softer attack than 36), 40 the electric snare, 44 the pedal hi-hat.
KITS = {
    "gm-fluid-standard": ("fluid", 0, 36, 38, 42),
    "gm-fluid-room-soft": ("fluid", 8, 35, 40, 44),
    "gm-fluid-808": ("fluid", 25, 36, 38, 42),
    "gm-fluid-jazz": ("fluid", 32, 35, 38, 42),
    "gm-musescore-standard": ("musescore", 0, 36, 38, 42),
    "gm-musescore-power": ("musescore", 16, 36, 38, 44),
    "gm-timgm6mb-standard": ("timgm6mb", 0, 35, 38, 42),
    "gm-timgm6mb-electronic": ("timgm6mb", 24, 36, 40, 42),
}
INSTRUMENTS = ("kick", "snare", "hat")
RATE_HZ = 44100
SLOT_S = 4.0  # each note is rendered alone in a slot this long
NOTE_S = 1.5  # note-on to note-off; the release rings on in the slot
TRIM_LEVEL = 1e-4  # leading samples below this are dropped
TAIL_DB = -60  # the hit ends where it stays this far below its peak (then a 5 ms fade)


def varlen(t):
    out = [t & 0x7F]
    t >>= 7
    while t:
        out.insert(0, 0x80 | (t & 0x7F))
        t >>= 7
    return bytes(out)


def smf(events):
    """A one-track Standard MIDI File of (time s, message bytes) events at 960 ticks a second
    (480 per quarter at the default 120 BPM); at the same tick, note-offs come first, the other
    events in the order given."""
    ticks_per_second = 960
    timed = sorted(((int(round(t * ticks_per_second)), message[0] & 0xF0 != 0x80, message)
                    for t, message in events), key=lambda e: e[:2])
    track, now = b"", 0
    for tick, _, message in timed:
        track += varlen(tick - now) + bytes(message)
        now = tick
    track += varlen(0) + bytes([0xFF, 0x2F, 0])
    return (b"MThd" + struct.pack(">IHHH", 6, 0, 1, ticks_per_second // 2) +
            b"MTrk" + struct.pack(">I", len(track)) + track)


def midi_file(notes):
    """A Standard MIDI File on channel 10: for each (program, note) a program change and the note
    (velocity 100) at the start of its slot."""
    events = []
    for i, (program, note) in enumerate(notes):
        on = i * SLOT_S
        events += [(on, [0xC9, program]), (on, [0x99, note, 100]), (on + NOTE_S, [0x89, note, 0])]
    return smf(events)


def trimmed(hit, rate):
    """The hit from its first audible sample to where it has decayed TAIL_DB below its peak."""
    start = int(np.argmax(np.abs(hit) > TRIM_LEVEL))
    hit = hit[start:]
    loud = np.nonzero(np.abs(hit) > np.max(np.abs(hit)) * 10 ** (TAIL_DB / 20))[0]
    fade = int(0.005 * rate)
    hit = hit[:loud[-1] + 1 + fade].copy()
    hit[-fade:] *= np.linspace(1, 0, fade)
    return hit


def render(directory):
    """Writes every kit's hits into `directory` as KIT_INSTRUMENT.flac; returns the kit names."""
    directory = pathlib.Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    for font, path in SOUNDFONTS.items():
        names, notes = [], []
        for kit, (kit_font, program, *kit_notes) in KITS.items():
            if kit_font != font:
                continue
            for instrument, note in zip(INSTRUMENTS, kit_notes):
                names.append(directory / f"{kit}_{instrument}.flac")
                notes.append((program, note))
        if all(name.exists() for name in names):
            continue
        mid, wav = directory / f"{font}.mid", directory / f"{font}.wav"
        mid.write_bytes(midi_file(notes))
        # -R 0 -C 0: no reverb, no chorus; the drums as dry as the soundfont has them.
        subprocess.run(["fluidsynth", "-ni", "-q", "-R", "0", "-C", "0", "-g", "1.0",
                        "-r", str(RATE_HZ), "-T", "wav", "-O", "float", "-F", str(wav), path,
                        str(mid)], check=True, capture_output=True)
        audio, rate = soundfile.read(wav, dtype="float32", always_2d=True)
        mono = audio.mean(axis=1)
        slot = int(SLOT_S * rate)
        for i, name in enumerate(names):
            soundfile.write(name, trimmed(mono[i * slot:(i + 1) * slot], rate), rate,
                            subtype="PCM_24")
        mid.unlink()
        wav.unlink()
    return list(KITS)


if __name__ == "__main__":
    import sys
    print("\n".join(render(sys.argv[1])))
