#!/usr/bin/python3
"""tactus report in a real browser: headless Chromium loads the page of the Amen break, of a
19 ms tick and of five minutes of quiet noise with one loud hit, with no script or player error,
the page records (hidden, nothing shown: no "drawn" text, its title kept) that it has drawn every
plot, no axis title runs into its tick labels, and a screenshot shows drawn pixels (the series'
colours) in each plot area that has values. The onsets are drawn in their drum part's colour,
with a legend naming the four parts, and the waveform shows every onset (the Amen break's in two
parts at least). The page is one file with nothing fetched: no external script, style, link or
image; the sound and the vibration are Ogg Vorbis data URIs that decode to the sound (as long as
the page says, its envelope the input's) and that the browser loads. Plots are thinned keeping
each bucket's extremes: the long file's one hit keeps the felt envelope's peak (1.0) and the
loudness plot's maximum is the one `tactus analyze` prints; its page stays under 3 MB. A
layout's page (column-4) names each output's felt envelope on one scale, and plots each one's
drive and sensation, its summary giving each one's meter.

usage: report_test.py TACTUS CHROMIUM
(TACTUS_REPORT_SCREENSHOTS=DIR keeps the screenshots there, to look at.)"""
import base64
import html
import io
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

import numpy as np
import soundfile
from PIL import Image

TACTUS, CHROMIUM = sys.argv[1], sys.argv[2]
SOUNDS = {"amen": "/usr/share/sonic-pi/samples/loop_amen_full.flac",
          "tick": "/usr/share/sonic-pi/samples/elec_tick.flac",
          "column": "/usr/share/sonic-pi/samples/loop_amen_full.flac"}
OPTIONS = {"column": ["--layout", "column-4"]}  # a layout: each output plotted and metered
PLOTS = {"column": 7 + 2 * 4}  # each of column-4's outputs adds its drive and sensation
WINDOW_WIDTH, WINDOW_HEIGHT_PER_PLOT = 1200, 300
LONG_S, LONG_RATE = 300, 44100  # the long file: quiet noise with one loud hit in the middle
MAX_PAGE_BYTES = 3_000_000      # its page (two 120 s WAV players alone took 28 MB)
MAX_PLAYER_S = 120              # what the players hold at most
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message)


def chromium(profile, plots, *arguments):
    command = [CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
               "--no-first-run", "--disable-background-networking", "--disable-component-update",
               "--disable-sync", "--hide-scrollbars", "--force-device-scale-factor=1",
               f"--window-size={WINDOW_WIDTH},{WINDOW_HEIGHT_PER_PLOT * plots}", f"--user-data-dir={profile}", *arguments]
    return subprocess.run(command, capture_output=True, text=True, timeout=120)


def onset_line(pixel, colours):
    """A pixel of an onset line: one of the parts' colours blended with the white under it."""
    q = [255 - v for v in pixel[:3]]
    for colour in colours:
        d = [255 - int(colour[i:i + 2], 16) for i in (1, 3, 5)]
        t = sum(a * b for a, b in zip(q, d)) / max(1, sum(b * b for b in d))
        if 0 < t <= 1.2 and all(abs(a - t * b) <= 20 for a, b in zip(q, d)):
            return True
    return False


def coloured(pixel, colours):
    """A series' colour: saturated, and not an onset line drawn under the series."""
    r, g, b = pixel[:3]
    if max(r, g, b) - min(r, g, b) < 60:
        return False  # white, greys, black: background, grid, axes, text
    return not onset_line(pixel, colours)


def write_long_file(path):
    """Five minutes of noise at -40 dBFS RMS and, in the middle, one loud 20 ms hit."""
    rng = np.random.default_rng(7)
    x = 0.01 * rng.standard_normal(LONG_S * LONG_RATE)
    hit = np.arange(int(0.02 * LONG_RATE))
    at = LONG_S // 2 * LONG_RATE
    x[at:at + hit.size] += 0.9 * np.sign(rng.standard_normal(hit.size)) * np.exp(-hit / 200)
    soundfile.write(path, np.clip(x, -1, 1), LONG_RATE, subtype="PCM_16")


def envelope(x, rate):
    """RMS in 2 ms windows."""
    n = int(0.002 * rate)
    x = x[:len(x) // n * n].reshape(-1, n)
    return np.sqrt((x * x).mean(axis=1))


def plot_rows(text, plot_id):
    plots = json.loads(re.search(r'id="plot-data">(.*?)</script>', text, re.S).group(1))
    return next(p["rows"] for p in plots if p["id"] == plot_id)


def attribute(tag, name):
    found = re.search(r'\s' + name + r'="([^"]*)"', tag)
    return html.unescape(found.group(1)) if found else None


with tempfile.TemporaryDirectory(prefix="tactus-report-") as work:
    SOUNDS["long"] = os.path.join(work, "long.wav")
    write_long_file(SOUNDS["long"])
    for name, sound in SOUNDS.items():
        page = os.path.join(work, name + ".html")
        run = subprocess.run([TACTUS, "report", sound, "-o", page, *OPTIONS.get(name, [])],
                             capture_output=True, text=True)
        check(run.returncode == 0, f"{name}: tactus report failed: {run.stderr}")
        text = open(page, encoding="utf-8").read()
        # Self-contained: nothing is fetched.
        check(not re.search(r'<(script|img|link|iframe)[^>]*\s(src|href)\s*=\s*"(?!data:)', text),
              f"{name}: the page refers to an outside file")
        check("url(http" not in text, f"{name}: the style fetches something")
        # The players: Ogg Vorbis that decodes to the sound, as long as the page says it is (at
        # most MAX_PLAYER_S), the sound player's envelope the input's.
        length = re.search(r"<tr><th>input</th><td>.*? \(([0-9.]+) s at", text)
        check(length is not None, f"{name}: no input length in the summary")
        expected_s = min(MAX_PLAYER_S, float(length.group(1))) if length else 0
        players = re.findall(r'<span>(\w+)</span><audio controls data-label="\w+" '
                             r'src="data:audio/ogg;base64,([^"]+)"', text)
        check([label for label, _ in players] == ["sound", "vibration"],
              f"{name}: two Ogg players expected, found {[label for label, _ in players]}")
        decoded = {}
        for label, uri in players:
            ogg = base64.b64decode(uri)
            check(ogg[:4] == b"OggS", f"{name}: the {label} player holds no Ogg")
            audio, rate = soundfile.read(io.BytesIO(ogg))
            decoded[label] = audio.size / rate
            check(abs(audio.size / rate - expected_s) < 0.05,
                  f"{name}: the {label} player holds {audio.size / rate:.3f} s, not {expected_s:.3f}")
            if label == "sound":
                source, source_rate = soundfile.read(sound, always_2d=True)
                source = source.mean(axis=1)[:audio.size]
                check(rate == source_rate, f"{name}: the sound player at {rate} Hz, not {source_rate}")
                level_db = 10 * np.log10(np.mean(audio[:source.size] ** 2) / np.mean(source ** 2))
                a, b = envelope(audio, rate), envelope(source, rate)
                n = min(a.size, b.size)
                r = np.corrcoef(a[:n], b[:n])[0, 1]
                print(f"{name}: the sound player's level {level_db:+.2f} dB re the input, "
                      f"envelope correlation {r:.4f}, {len(uri)} bytes of base64")
                check(abs(level_db) <= 1, f"{name}: the sound player is {level_db:+.2f} dB off")
                if name != "long":  # steady noise: an envelope without a shape to follow
                    check(r >= 0.95, f"{name}: the sound player's envelope correlates {r:.3f} "
                                     "with the input's")
        if name == "column":  # each output's felt envelope, named, on one scale
            felt = [r for r in plot_rows(text, "felt")]
            check(re.search(r'"labels":\["bottom","lower","upper","top"\]', text) is not None,
                  f"{name}: the felt plot's series are not the layout's outputs")
            peaks = [max(r[k] for r in felt if r[k] is not None) for k in range(1, 5)]
            print(f"{name}: each output's felt peak re the loudest: "
                  + " ".join(f"{p:.3f}" for p in peaks))
            check(max(peaks) >= 0.999 and min(peaks) > 0, f"{name}: felt peaks {peaks}")
            # Each output's drive and sensation plotted, and metered in the summary.
            for output in ("bottom", "lower", "upper", "top"):
                drive = plot_rows(text, f"vibration-{output}")
                sensation = [r[5] for r in plot_rows(text, f"sensation-{output}") if r[5] is not None]
                combined = re.search(rf"<tr><th>{output}: combined</th><td>max (-?[0-9.]+) dB SL", text)
                print(f"{name}: {output}: drive peak {max(r[2] for r in drive):.3f}, "
                      f"combined sensation max {max(sensation):.1f} dB SL")
                check(max(r[2] for r in drive) > 0.01, f"{name}: {output}'s drive plot is empty")
                check(combined is not None and abs(float(combined.group(1)) - max(sensation)) < 0.05,
                      f"{name}: {output}'s summary does not give its sensation plot's maximum")
        if name == "long":
            size = os.path.getsize(page)
            print(f"{name}: page {size} bytes")
            check(size <= MAX_PAGE_BYTES, f"{name}: the page weighs {size} bytes, over {MAX_PAGE_BYTES}")
            felt = max(r[1] for r in plot_rows(text, "felt") if r[1] is not None)
            check(felt >= 0.999, f"{name}: the felt plot tops out at {felt}, its peak is 1")
            analysed = subprocess.run([TACTUS, "analyze", sound, "-o", "-"], capture_output=True,
                                      text=True)
            lines = [l for l in analysed.stdout.splitlines() if not l.startswith("#")]
            column = lines[0].split(",").index("loudness_db")
            loudest = max(float(l.split(",")[column]) for l in lines[1:])
            plotted = max(r[1] for r in plot_rows(text, "loudness") if r[1] is not None)
            print(f"{name}: felt plot peak {felt}, loudness plot max {plotted} dB "
                  f"(analyze: {loudest:.4f} dB)")
            check(abs(plotted - loudest) <= 1e-3 * abs(loudest) + 1e-3,
                  f"{name}: the loudness plot tops out at {plotted} dB, analyze says {loudest}")
        legend = re.findall(r'<span class="onset-part" data-part="(\w+)" data-colour="(#[0-9a-f]{6})"',
                            text)
        check([part for part, _ in legend] == ["kick", "snare", "hat", "other"],
              f"{name}: the onset legend names the four drum parts: {legend}")
        colours = [colour for _, colour in legend]
        onsets = re.search(r"<tr><th>onsets</th><td>(\d+)</td></tr>", text)
        check(onsets is not None, f"{name}: no onset count in the summary")

        profile = os.path.join(work, "profile-" + name)
        plots = PLOTS.get(name, 9)
        dom = chromium(profile, plots, "--virtual-time-budget=5000", "--dump-dom", "file://" + page)
        check(dom.returncode == 0, f"{name}: chromium --dump-dom failed: {dom.stderr[-500:]}")
        title = f"<title>tactus report: {os.path.basename(sound)}</title>"
        now = re.search('<title>.*?</title>', dom.stdout)
        check(title in dom.stdout, f"{name}: the title changed: {now.group(0) if now else None}")
        errors = re.search(r'<div id="errors">(.*?)</div>', dom.stdout, re.S)
        check(errors is not None and errors.group(1).strip() == "",
              f"{name}: script errors: {errors.group(1) if errors else 'no #errors element'}")
        # Nothing left for tests on the page: the text outside scripts and styles never says "drawn".
        shown_text = re.sub(r"<(script|style)\b.*?</\1>", "", dom.stdout, flags=re.S)
        shown_text = html.unescape(re.sub(r"<[^>]*>", " ", shown_text))
        check("drawn" not in shown_text, f"{name}: the page shows 'drawn'")
        status = re.search(r'<div id="status"[^>]*>', dom.stdout)
        check(status is not None and attribute(status.group(0), "hidden") is not None,
              f"{name}: no hidden #status")
        if status is None or attribute(status.group(0), "data-drawn") is None:
            check(False, f"{name}: the page did not draw")
            continue
        areas = json.loads(attribute(status.group(0), "data-plots"))
        check(len(areas) == plots == int(attribute(status.group(0), "data-drawn")),
              f"{name}: {len(areas)} plots drawn, {plots} expected")
        for area in areas:
            check(area["overlaps"] == 0,
                  f"{name}: plot {area['id']}: an axis title runs into {area['overlaps']} tick labels")
        for label, seconds in re.findall(r'<audio [^>]*data-label="(\w+)"[^>]*data-duration="([^"]*)"',
                                         dom.stdout):
            check(abs(float(seconds) - decoded.get(label, -1)) < 0.05,
                  f"{name}: the browser reads the {label} player as {seconds} s")
        check(len(re.findall(r"<audio [^>]*data-duration=", dom.stdout)) == 2,
              f"{name}: the browser did not load both players")
        shown = attribute(status.group(0), "data-onsets")
        check(shown is not None, f"{name}: no onset lines counted")
        if shown and onsets:
            per_part = json.loads(shown)
            print(f"{name}: onset lines in the waveform by part: {per_part}")
            check(sum(per_part.values()) == int(onsets.group(1)) > 0,
                  f"{name}: the waveform shows {per_part}, the summary {onsets.group(1)} onsets")
            if name == "amen":
                check(sum(1 for n in per_part.values() if n > 0) >= 2,
                      f"{name}: the Amen break's onsets in one part only: {per_part}")

        shutil.rmtree(profile, ignore_errors=True)
        shot = os.path.join(work, name + ".png")
        taken = chromium(profile, plots, f"--screenshot={shot}", "file://" + page)
        check(taken.returncode == 0 and os.path.exists(shot), f"{name}: no screenshot: {taken.stderr[-500:]}")
        if not os.path.exists(shot):
            continue
        image = Image.open(shot).convert("RGB")
        if os.environ.get("TACTUS_REPORT_SCREENSHOTS"):
            shutil.copy(shot, os.path.join(os.environ["TACTUS_REPORT_SCREENSHOTS"], name + ".png"))
        for area in areas:
            x, y, w, h = area["x"], area["y"], area["w"], area["h"]
            check(y + h <= image.height, f"{name}: plot {area['id']} is below the screenshot")
            box = image.crop((x, y, x + w, y + h))
            drawn = sum(1 for p in box.getdata() if coloured(p, colours))
            print(f"{name}: {area['id']:<11} {area['values']:>5} values, {drawn:>6} drawn pixels "
                  f"in {w}x{h}")
            if area["values"] > 0:
                check(drawn >= min(20, 4 * area["values"]),
                      f"{name}: plot {area['id']} has {area['values']} values but {drawn} drawn pixels")

print("FAILED" if failures else "passed", len(failures), "failure(s)")
sys.exit(1 if failures else 0)
