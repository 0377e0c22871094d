#!/usr/bin/python3
"""tactus report in a real browser: headless Chromium loads the page of the Amen break and of a
19 ms tick with no script error, the page says it has drawn every plot, and a screenshot shows
drawn pixels (the series' colours) in each plot area that has values. The onsets are drawn in
their drum part's colour, with a legend naming the four parts, and the waveform shows every onset
(the Amen break's in two parts at least). The page is one file with
nothing fetched: no external script, style, link or image; the sound and the vibration are WAV
data URIs.

usage: report_test.py TACTUS CHROMIUM
(TACTUS_REPORT_SCREENSHOTS=DIR keeps the screenshots there, to look at.)"""
import base64
import html
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

from PIL import Image

TACTUS, CHROMIUM = sys.argv[1], sys.argv[2]
SOUNDS = {"amen": "/usr/share/sonic-pi/samples/loop_amen_full.flac",
          "tick": "/usr/share/sonic-pi/samples/elec_tick.flac"}
WINDOW = (1200, 2700)
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message)


def chromium(profile, *arguments):
    command = [CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
               "--no-first-run", "--disable-background-networking", "--disable-component-update",
               "--disable-sync", "--hide-scrollbars", "--force-device-scale-factor=1",
               f"--window-size={WINDOW[0]},{WINDOW[1]}", f"--user-data-dir={profile}", *arguments]
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


with tempfile.TemporaryDirectory(prefix="tactus-report-") as work:
    for name, sound in SOUNDS.items():
        page = os.path.join(work, name + ".html")
        run = subprocess.run([TACTUS, "report", sound, "-o", page], capture_output=True, text=True)
        check(run.returncode == 0, f"{name}: tactus report failed: {run.stderr}")
        text = open(page, encoding="utf-8").read()
        # Self-contained: nothing is fetched.
        check(not re.search(r'<(script|img|link|iframe)[^>]*\s(src|href)\s*=\s*"(?!data:)', text),
              f"{name}: the page refers to an outside file")
        check("url(http" not in text, f"{name}: the style fetches something")
        for label, uri in re.findall(r'<span>(\w+)</span><audio controls src="data:audio/wav;base64,([^"]+)"', text):
            wav = base64.b64decode(uri)
            check(wav[:4] == b"RIFF" and wav[8:12] == b"WAVE" and len(wav) > 1000,
                  f"{name}: the {label} player holds no WAV")
        check(text.count("<audio controls") == 2, f"{name}: two players expected")
        legend = re.findall(r'<span class="onset-part" data-part="(\w+)" data-colour="(#[0-9a-f]{6})"',
                            text)
        check([part for part, _ in legend] == ["kick", "snare", "hat", "other"],
              f"{name}: the onset legend names the four drum parts: {legend}")
        colours = [colour for _, colour in legend]
        onsets = re.search(r"<tr><th>onsets</th><td>(\d+)</td></tr>", text)
        check(onsets is not None, f"{name}: no onset count in the summary")

        profile = os.path.join(work, "profile-" + name)
        dom = chromium(profile, "--dump-dom", "file://" + page)
        check(dom.returncode == 0, f"{name}: chromium --dump-dom failed: {dom.stderr[-500:]}")
        check("<title>tactus report: drawn</title>" in dom.stdout, f"{name}: the page did not draw")
        errors = re.search(r'<div id="errors">(.*?)</div>', dom.stdout, re.S)
        check(errors is not None and errors.group(1).strip() == "",
              f"{name}: script errors: {errors.group(1) if errors else 'no #errors element'}")
        status = re.search(r'<div id="status" data-plots="([^"]*)"[^>]*>drawn (\d+) plots</div>',
                           dom.stdout)
        check(status is not None, f"{name}: no drawn status")
        if status is None:
            continue
        areas = json.loads(html.unescape(status.group(1)))
        check(len(areas) == 9 == int(status.group(2)), f"{name}: {len(areas)} plots drawn, 9 expected")
        shown = re.search(r'data-onsets="([^"]*)"', dom.stdout)
        check(shown is not None, f"{name}: no onset lines counted")
        if shown and onsets:
            per_part = json.loads(html.unescape(shown.group(1)))
            print(f"{name}: onset lines in the waveform by part: {per_part}")
            check(sum(per_part.values()) == int(onsets.group(1)) > 0,
                  f"{name}: the waveform shows {per_part}, the summary {onsets.group(1)} onsets")
            if name == "amen":
                check(sum(1 for n in per_part.values() if n > 0) >= 2,
                      f"{name}: the Amen break's onsets in one part only: {per_part}")

        shutil.rmtree(profile, ignore_errors=True)
        shot = os.path.join(work, name + ".png")
        taken = chromium(profile, f"--screenshot={shot}", "file://" + page)
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
