"""tactus studio in a real browser (headless Chromium through Selenium and chromium-driver).

`tactus studio CLIP --port 0 --no-browser` serves the page; the browser opens the URL it prints,
moves three controls of different types (a slider, a choice, an on/off box) with real input
events, and the plots change (canvas pixels differ) and the vibration the page fetched equals
`tactus render --set` with the same values sample for sample. A saved preset renders bit for bit
as the command line's --set; exports equal `tactus export`'s files; A/B, undo and play work;
a wrong value shows the command line's one-line error; requests without the token get 403 and
paths outside the session are refused. test_latency measures the time from a control change to
the redrawn plots (every plot the change changed, the sensation meter's included) over 50
changes of a 30-second clip, and where it went (render, answer, parsing, drawing), printed with
the load average; TACTUS_STUDIO_SCREENSHOT=FILE also saves a screenshot of the page.

usage: TACTUS=build/release/bin/tactus python3 -m pytest tests/studio/studio_test.py"""
import base64
import http.client
import json
import os
import shutil
import statistics
import subprocess
import urllib.parse

import numpy as np
import pytest
import soundfile
from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import Select, WebDriverWait

TACTUS = os.environ.get("TACTUS", "build/release/bin/tactus")
AMEN = "/usr/share/sonic-pi/samples/loop_amen_full.flac"
CLIP_S = 30
SLIDER, CHOICE, TOGGLE = "envelope.decay_ms", "mapping.frequency.curve", "flutter.equalize"


@pytest.fixture(scope="module")
def clip(tmp_path_factory):
    """30 s of the Amen break, looped: a real drum recording, as a 16-bit WAV."""
    x, rate = soundfile.read(AMEN)
    path = tmp_path_factory.mktemp("studio") / "amen30.wav"
    soundfile.write(path, np.concatenate([x] * (CLIP_S * rate // len(x) + 1))[:CLIP_S * rate],
                    rate, subtype="PCM_16")
    return path


@pytest.fixture(scope="module")
def server(clip, tmp_path_factory):
    # A temporary folder of its own: other studios on the machine make and remove theirs.
    temp = tmp_path_factory.mktemp("studio-temp")
    folders = lambda: {n for n in os.listdir(temp) if n.startswith("tactus-studio-")}
    process = subprocess.Popen([TACTUS, "studio", str(clip), "--port", "0", "--no-browser"],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                               env=dict(os.environ, TMPDIR=str(temp)))
    url = process.stdout.readline().strip()
    assert url.startswith("http://127.0.0.1:") and "?token=" in url, url
    assert len(folders()) == 1
    yield url
    process.terminate()
    assert process.wait(timeout=10) == 0
    assert folders() == set(), "the session's folder was left behind"


@pytest.fixture(scope="module")
def browser(server):
    options = webdriver.ChromeOptions()
    options.binary_location = "/usr/bin/chromium"
    for a in ["--headless", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
              "--window-size=1400,1000", "--force-device-scale-factor=1",
              "--autoplay-policy=no-user-gesture-required"]:
        options.add_argument(a)
    driver = webdriver.Chrome(service=Service("/usr/bin/chromedriver"),
                              options=options)
    driver.set_script_timeout(120)
    driver.get(server)
    wait_for_samples(driver)
    yield driver
    driver.quit()


def wait_for_samples(driver, after=0):
    """Waits for a render newer than `after` whose samples the page holds; returns its id."""
    WebDriverWait(driver, 120).until(lambda d: d.execute_script(
        "return window.studio && studio.samplesReady > arguments[0] && !studio.inFlight && "
        "studio.render && studio.samplesReady === studio.render.render", after))
    return driver.execute_script("return studio.render.render")


def page_vibration(driver):
    """The last render's vibration as the page holds it (float32, bit for bit)."""
    data = driver.execute_async_script("""
        const done = arguments[0], bytes = new Uint8Array(studio.vibration.buffer);
        let s = ""; for (let i = 0; i < bytes.length; i += 0x8000)
          s += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
        done(btoa(s));""")
    return np.frombuffer(base64.b64decode(data), dtype="<f4")


def sent_settings(driver):
    """The settings of the last render, in the order the page sent them (the table's)."""
    return dict(driver.execute_script("return Object.entries(studio.render.sent.settings)"))


def control(driver, key):
    """The control of `key`, its group opened and scrolled to, once it is shown. The group is
    opened by the script, not by a click on its title: on a loaded machine the page's layout can
    move under a pointer click as the renders of earlier changes come in."""
    element = driver.find_element("id", "param-" + key)

    def shown(_):
        driver.execute_script("arguments[0].closest('details').open = true;"
                              "arguments[0].scrollIntoView({block: 'center'})", element)
        return element.is_displayed()
    WebDriverWait(driver, 10).until(shown)
    return element


def canvases(driver):
    return driver.execute_script(
        "return Array.from(document.querySelectorAll('#plots canvas')).map(c => c.toDataURL())")


def cli(*args):
    run = subprocess.run([TACTUS, *map(str, args)], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    return run


def sets(settings):
    out = []
    for key, value in settings.items():
        out += ["--set", f"{key}={value}"]
    return out


def cli_render(clip, tmp_path, name, *args):
    out = tmp_path / name
    cli("render", clip, "-o", out, "--force", *args)
    samples, _ = soundfile.read(out, dtype="float32")
    return samples


def assert_equals_render(vibration, latency, rendered):
    """The page's vibration is the rendered one after the engine's latency (zeros before it)."""
    assert len(rendered) == latency + len(vibration)
    assert not np.any(rendered[:latency])
    diff = np.abs(rendered[latency:] - vibration)
    assert np.array_equal(rendered[latency:], vibration), f"differs by up to {diff.max()}"


def test_three_controls_change_the_plots_and_equal_render(browser, clip, tmp_path):
    before_pixels, before = canvases(browser), browser.execute_script("return studio.render.render")
    assert len(before_pixels) == 9
    slider = control(browser, SLIDER)
    slider.send_keys(*[Keys.ARROW_RIGHT] * 40)  # real key presses on the range input
    Select(control(browser, CHOICE)).select_by_visible_text("lin")
    control(browser, TOGGLE).click()
    last = wait_for_samples(browser, before)
    # Keys and clicks each re-render; wait until the last change's render is in.
    while browser.execute_script("return studio.pending || studio.inFlight"):
        last = wait_for_samples(browser, last)
    settings = sent_settings(browser)
    assert set(settings) == {SLIDER, CHOICE, TOGGLE}, settings
    after_pixels = canvases(browser)
    changed = [a != b for a, b in zip(before_pixels, after_pixels)]
    assert changed[6] and changed[7], "the vibration and felt plots did not change"
    assert browser.execute_script("return studio.render.analysis") == "replayed"
    latency = browser.execute_script("return studio.render.latency_frames")
    rendered = cli_render(clip, tmp_path, "cli.wav", *sets(settings))
    assert_equals_render(page_vibration(browser), latency, rendered)


def test_unchanged_plots_are_not_sent_again(browser):
    """A live setting leaves the sound's plots as they were: the answer names them by digest
    only, and the plots the page holds equal, value for value, those of a whole answer."""
    slider = control(browser, SLIDER)
    last = browser.execute_script("return studio.renders")
    slider.send_keys(Keys.ARROW_RIGHT)
    WebDriverWait(browser, 60).until(lambda d: d.execute_script(
        "return studio.renders > arguments[0] && !studio.inFlight && !studio.pending", last))
    resent = browser.execute_script("return studio.render.resent")
    assert "vibration" in resent and "felt" in resent, resent
    assert not {"waveform", "loudness", "brightness", "noisiness", "pitch"} & set(resent), resent
    same = browser.execute_async_script("""
        const done = arguments[0], held = studio.render.plots;
        postJson("/api/render", studio.render.sent).then((res) => res.json()).then((whole) => {
          const key = (p) => JSON.stringify(Object.assign({}, p, {digest: 0}));
          done(whole.plots.length === held.length &&
               whole.plots.every((p, i) => !p.same && key(p) === key(held[i])));
        });""")
    assert same, "the plots the page holds differ from a whole answer's"


def test_preset_renders_bit_for_bit(browser, clip, tmp_path):
    settings = sent_settings(browser)
    assert settings, "no setting changed: run with the previous test"
    text = browser.execute_async_script("studio.savePreset().then(arguments[0])")
    preset = tmp_path / "saved.toml"
    preset.write_text(text)
    from_preset = cli_render(clip, tmp_path, "preset.wav", "--preset", preset)
    from_set = cli_render(clip, tmp_path, "set.wav", *sets(settings))
    assert np.array_equal(from_preset, from_set)
    latency = browser.execute_script("return studio.render.latency_frames")
    assert_equals_render(page_vibration(browser), latency, from_preset)


@pytest.mark.parametrize("format", [".ahap", ".haptic", ".android.json"])
def test_export_equals_tactus_export(browser, clip, tmp_path, format):
    settings = sent_settings(browser)
    data = browser.execute_async_script("""
        studio.exportFormat(arguments[0]).then((b) => {
          const bytes = new Uint8Array(b); let s = "";
          for (let i = 0; i < bytes.length; i += 0x8000)
            s += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
          arguments[1](btoa(s)); });""", format)
    out = tmp_path / ("cli" + format)
    cli("export", clip, "-o", out, *sets(settings))
    assert base64.b64decode(data) == out.read_bytes()


def test_batch_export_equals_tactus_export_to_a_folder(server, browser, clip, tmp_path):
    """Every listed sound in every format, as `tactus export FILES -O DIR` writes them."""
    token = urllib.parse.parse_qs(urllib.parse.urlsplit(server).query)["token"][0]
    tick = "/usr/share/sonic-pi/samples/elec_blip.flac"
    status, _ = request(server, "POST", "/api/upload?name=blip.flac", token,
                        open(tick, "rb").read())
    assert status == 200
    settings = sent_settings(browser)
    pairs = browser.execute_async_script("""
        studio.exportBatch([".ahap", ".haptic", ".android.json", ".ogg"]).then((files) =>
          arguments[0](files.map(([name, b]) => {
            const bytes = new Uint8Array(b); let s = "";
            for (let i = 0; i < bytes.length; i += 0x8000)
              s += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
            return [name, btoa(s)]; })));""")
    page = {name: base64.b64decode(data) for name, data in pairs}
    local = tmp_path / "in"
    local.mkdir()
    shutil.copy(clip, local / "amen30.wav")
    shutil.copy(tick, local / "blip.flac")
    listed = json.loads(request(server, "GET", "/api/files", token)[1])["files"]
    cli("export", *[local / f for f in listed if (local / f).exists()], "-O", tmp_path / "out",
        *sets(settings))
    written = {p.name: p for p in (tmp_path / "out").iterdir()}
    assert {"amen30.ahap", "blip.ahap", "blip.ogg"} <= set(page)
    for name, data in page.items():
        if name not in written:  # a sound another test uploaded, not in this folder
            continue
        if name.endswith(".ogg"):  # a random serial number: the decoded channels compared
            (tmp_path / name).write_bytes(data)
            a, _ = soundfile.read(tmp_path / name)
            b, _ = soundfile.read(written[name])
            assert a.shape == b.shape and np.max(np.abs(a - b)) < 1e-3, name
        else:
            assert data == written[name].read_bytes(), name


def test_ogg_export_has_the_same_vibration(browser, clip, tmp_path):
    """Vorbis streams carry a random serial number: the decoded channels are compared."""
    settings = sent_settings(browser)
    data = browser.execute_async_script("""
        studio.exportFormat(".ogg").then((b) => {
          const bytes = new Uint8Array(b); let s = "";
          for (let i = 0; i < bytes.length; i += 0x8000)
            s += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
          arguments[0](btoa(s)); });""")
    page_ogg, cli_ogg = tmp_path / "page.ogg", tmp_path / "cli.ogg"
    page_ogg.write_bytes(base64.b64decode(data))
    cli("export", clip, "-o", cli_ogg, *sets(settings))
    a, _ = soundfile.read(page_ogg)
    b, _ = soundfile.read(cli_ogg)
    assert a.shape == b.shape and np.max(np.abs(a - b)) < 1e-3


def test_ab_and_undo(browser):
    a = sent_settings(browser)
    browser.find_element("id", "slotB").click()
    wait_for_samples(browser, browser.execute_script("return studio.samplesReady"))
    control(browser, TOGGLE).click()
    b_render = wait_for_samples(browser, browser.execute_script("return studio.samplesReady"))
    b = sent_settings(browser)
    assert b != a and b_render
    browser.find_element("id", "slotA").click()
    wait_for_samples(browser, browser.execute_script("return studio.samplesReady"))
    assert sent_settings(browser) == a
    browser.find_element("id", "slotB").click()
    wait_for_samples(browser, browser.execute_script("return studio.samplesReady"))
    assert sent_settings(browser) == b
    browser.find_element("id", "undo").click()  # the toggle's change in B
    wait_for_samples(browser, browser.execute_script("return studio.samplesReady"))
    assert sent_settings(browser) == a
    browser.find_element("id", "slotA").click()
    wait_for_samples(browser, browser.execute_script("return studio.samplesReady"))


def test_play_moves_the_playhead(browser):
    browser.find_element("id", "play").click()
    WebDriverWait(browser, 20).until(lambda d: d.execute_script(
        "return studio.playing && studio.playhead > 0.2"))
    assert not browser.find_element("id", "error").text
    browser.find_element("id", "stop").click()
    assert not browser.execute_script("return studio.playing")


def test_error_names_the_parameter(browser):
    control(browser, "envelope.attack_ms")
    number = browser.find_elements("css selector", "#param-envelope\\.attack_ms + input")[0]
    number.clear()
    number.send_keys("99999", Keys.ENTER)
    WebDriverWait(browser, 30).until(lambda d: d.find_element("id", "error").text)
    text = browser.find_element("id", "error").text
    assert "envelope.attack_ms" in text and "out of range" in text and "\n" not in text, text
    browser.find_element("id", "undo").click()
    WebDriverWait(browser, 30).until(lambda d: not d.find_element("id", "error").text)


def request(url, method, path, token=None, body=None, headers=None):
    parts = urllib.parse.urlsplit(url)
    connection = http.client.HTTPConnection(parts.hostname, parts.port, timeout=60)
    headers = dict(headers or {})
    if token:
        headers["X-Tactus-Token"] = token
    connection.request(method, path, body=body, headers=headers)
    response = connection.getresponse()
    return response.status, response.read()


def test_token_and_paths(server, tmp_path):
    token = urllib.parse.parse_qs(urllib.parse.urlsplit(server).query)["token"][0]
    assert request(server, "GET", "/")[0] == 403
    assert request(server, "GET", "/?token=" + "0" * 32)[0] == 403
    assert request(server, "GET", "/api/files")[0] == 403
    assert request(server, "POST", "/api/render", body=b"{}")[0] == 403
    assert request(server, "GET", "/?token=" + token)[0] == 200
    status, body = request(server, "GET", "/../../../etc/passwd", token)
    assert status == 404 and b"root:" not in body
    status, body = request(server, "GET", "/%2e%2e/%2e%2e/etc/passwd", token)
    assert status == 404 and b"root:" not in body
    status, body = request(server, "POST", "/api/render", token,
                           json.dumps({"file": "../../../../etc/passwd"}))
    assert status == 404 and b"not a file of this session" in body
    status, body = request(server, "POST", "/api/render", token,
                           json.dumps({"file": "amen30.wav", "preset": "/etc/passwd"}))
    assert status == 404 and b"no such preset" in body
    status, body = request(server, "POST", "/api/upload?name=..%2Fescaped.wav", token,
                           open(AMEN, "rb").read())
    assert status == 400 and b"not a plain file name" in body
    assert not any(p.name == "escaped.wav" for p in (tmp_path / "..").iterdir())
    status, body = request(server, "POST", "/api/upload?name=notes.wav", token, b"not audio")
    assert status == 400 and b"not a sound file" in body
    status, body = request(server, "POST", "/api/upload?name=tick.flac", token,
                           open("/usr/share/sonic-pi/samples/elec_tick.flac", "rb").read())
    assert status == 200
    assert "tick.flac" in json.loads(request(server, "GET", "/api/files", token)[1])["files"]
    status, body = request(server, "POST", "/api/render", token, b"{not json")
    assert status == 400 and json.loads(body)["error"]


def test_kept_analysis_renders_as_tactus_render(server, clip, tmp_path):
    """A change that leaves the analysis's parameters as they were plays the file's analysis
    back; the vibration equals `tactus render --set` bit for bit, whether analysed or replayed,
    a render ringing out past what was analysed included (then it is analysed again)."""
    token = urllib.parse.parse_qs(urllib.parse.urlsplit(server).query)["token"][0]
    onsets = {"onset.threshold": "11.5"}  # an analysis no render has made yet
    held = {"mapping.gate_db": "-120", "envelope.sustain": "1"}
    for step, (settings, analysis) in enumerate([
            (onsets, "analysed"),
            (onsets | {"envelope.decay_ms": "300", "mapping.amplitude.source": "pitch_confidence",
                       "post.drive_db": "3"}, "replayed"),
            (onsets | {"envelope.decay_ms": "5000", "flutter.weight": "0.3"}, "replayed"),
            # Held at full amplitude in the silence after the sound: rings out for the longest
            # tail (10 s), past what was analysed, so analysed again, and kept for the next.
            (onsets | held | {"mapping.amplitude.source": "pitch_confidence",
                              "mapping.amplitude.in_min": "1", "mapping.amplitude.in_max": "0"},
             "analysed"),
            (onsets | held | {"mapping.amplitude.source": "onset_odf",
                              "mapping.amplitude.in_min": "100", "mapping.amplitude.in_max": "-100"},
             "replayed"),
            ({"onset.threshold": "12.5"}, "analysed")]):
        status, body = request(server, "POST", "/api/render", token, json.dumps(
            {"file": clip.name, "settings": settings}))
        assert status == 200, body
        answer = json.loads(body)
        assert answer["analysis"] == analysis, (step, settings)
        status, data = request(server, "GET",
                               f"/api/samples?render={answer['render']}&what=vibration", token)
        assert status == 200
        rendered = cli_render(clip, tmp_path, f"kept{step}.wav", *sets(settings))
        assert_equals_render(np.frombuffer(data, dtype="<f4"), answer["latency_frames"], rendered)


def test_answers_are_not_compressed(server):
    """A browser asks for Brotli; on loopback compressing a render's 1.4 MB only costs time."""
    token = urllib.parse.parse_qs(urllib.parse.urlsplit(server).query)["token"][0]
    parts = urllib.parse.urlsplit(server)
    connection = http.client.HTTPConnection(parts.hostname, parts.port, timeout=60)
    connection.request("POST", "/api/render", body=json.dumps({"file": "amen30.wav"}),
                       headers={"X-Tactus-Token": token, "Accept-Encoding": "gzip, deflate, br"})
    response = connection.getresponse()
    body = response.read()
    assert response.status == 200 and response.getheader("Content-Encoding") is None
    assert json.loads(body)["frames"] > 0


def test_port_in_use(server, clip):
    """A second studio on the first one's port is refused, not let in beside it."""
    port = urllib.parse.urlsplit(server).port
    run = subprocess.run([TACTUS, "studio", clip, "--port", str(port), "--no-browser"],
                         capture_output=True, text=True, timeout=30)
    assert run.returncode == 1 and run.stdout == ""
    assert run.stderr == (f"tactus: error: 127.0.0.1:{port}: cannot listen there (address in use "
                          "or not this machine's)\n"), run.stderr


def test_command_line_errors(tmp_path):
    run = subprocess.run([TACTUS, "studio", tmp_path / "missing.wav", "--no-browser"],
                         capture_output=True, text=True, timeout=30)
    assert run.returncode == 1
    assert run.stderr == f"tactus: error: {tmp_path / 'missing.wav'}: no such file or directory\n"


def test_file_picker_uploads_as_drop_does(browser, tmp_path):
    """Two files chosen in the picker (<input type=file>): the sound is uploaded, listed and
    rendered; the text file is refused with the upload's own one-line error."""
    notes = tmp_path / "picked-notes.wav"
    notes.write_text("not audio")
    sound = "/usr/share/sonic-pi/samples/drum_cymbal_closed.flac"
    before = browser.execute_script("return studio.samplesReady")
    browser.find_element("id", "pick").send_keys(f"{sound}\n{notes}")
    WebDriverWait(browser, 30).until(lambda d: d.find_element("id", "error").text)
    error = browser.find_element("id", "error").text
    assert error == "picked-notes.wav: not a sound file tactus reads", error
    listed = [o.text for o in Select(browser.find_element("id", "file")).options]
    assert "drum_cymbal_closed.flac" in listed and "picked-notes.wav" not in listed, listed
    WebDriverWait(browser, 30).until(lambda d: d.execute_script(
        "return studio.render.file === 'drum_cymbal_closed.flac' && !studio.inFlight"))
    assert browser.execute_script("return document.getElementById('pick').value") == ""
    picked = wait_for_samples(browser, before)
    # Back to the clip, for the tests after this one.
    Select(browser.find_element("id", "file")).select_by_visible_text("amen30.wav")
    wait_for_samples(browser, picked)
    assert browser.execute_script("return studio.render.file") == "amen30.wav"


def test_latency(browser):
    """50 slider changes, each waited for: change -> redrawn plots, measured in the page."""
    slider = control(browser, SLIDER)
    browser.execute_script("studio.latencies = []; studio.legs = []")
    for i in range(50):
        last = browser.execute_script("return studio.renders")
        slider.send_keys(Keys.ARROW_RIGHT if i % 2 else Keys.ARROW_LEFT)
        WebDriverWait(browser, 30).until(lambda d: d.execute_script(
            "return studio.renders > arguments[0] && !studio.inFlight", last))
    latencies = browser.execute_script("return studio.latencies")
    median = statistics.median(latencies)
    p95 = sorted(latencies)[int(0.95 * (len(latencies) - 1))]
    render_ms = browser.execute_script("return studio.render.render_ms")
    print(f"\nstudio latency over {len(latencies)} changes of a {CLIP_S} s clip: "
          f"median {median:.0f} ms, p95 {p95:.0f} ms (the last render took {render_ms:.0f} ms)")
    legs = browser.execute_script("return studio.legs")
    print("medians (ms): " + ", ".join(f"{leg} {statistics.median(x[leg] for x in legs):.1f}"
                                       for leg in ["render", "answer", "parse", "draw"]) +
          f"; load average {os.getloadavg()[0]:.2f}")
    assert len(latencies) >= 50 and median > 0
    if os.environ.get("TACTUS_STUDIO_SCREENSHOT"):  # zoomed in on the first bars
        browser.execute_script("studio.view = {t0: 0, t1: 3.5}; studio.loop = [0.85, 1.7]; draw()")
        browser.save_screenshot(os.environ["TACTUS_STUDIO_SCREENSHOT"])
