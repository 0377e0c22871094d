"""Bad command lines of `tactus live`, `devices` and `calibrate`: each exits non-zero with one
line on stderr naming what is wrong, before any device is opened; --help works everywhere;
`devices` prints none of alsa-lib's own messages.

usage: cli_errors_test.py TACTUS"""

import os
import subprocess
import sys
import tempfile

tactus = sys.argv[1]
AMEN = "/usr/share/sonic-pi/samples/loop_amen.flac"
failed = 0

with tempfile.TemporaryDirectory() as d:
    existing = os.path.join(d, "exists.toml")
    open(existing, "w").write("name = 'x'\n")
    # Any JACK server these would reach is a name no server has.
    env = dict(os.environ, JACK_DEFAULT_SERVER=f"tactus-no-server-{os.getpid()}")
    cases = [
        (["live"], "--input"),
        (["live", "--play", AMEN, "--input", "x"], "either --input"),
        (["live", "--input", "x", "--loop"], "--loop"),
        (["live", "--play", AMEN, "--actuator-channels", "0"], "--actuator-channels"),
        (["live", "--play", AMEN, "--actuator-channels", "1,1"], "named twice"),
        (["live", "--play", AMEN, "--sound-channels", "1"], "both an actuator and a sound"),
        (["live", "--play", AMEN, "--osc-port", "99999"], "--osc-port"),
        (["live", "--play", AMEN, "--osc-send", "host:"], "--osc-send"),
        (["live", "--play", AMEN, "--set", "post.drive_db=99"], "post.drive_db"),
        (["live", "--play", AMEN, "--actuator", "nope"], "nope"),
        (["live", "--play", AMEN, "--actuator-channels", "1,2", "--actuator-gain-db", "0,0,0"],
         "--actuator-gain-db"),
        (["live", "--play", AMEN, "--backend", "coreaudio"], "--backend"),
        (["live", "--play", AMEN, "--block", "8"], "--block"),
        (["live", "--play", os.path.join(d, "missing.wav")], "missing.wav"),
        (["live", "--backend", "jack", "--play", AMEN], "jack"),
        (["calibrate", "--output", "x:1", "--input", "x:1", "-o", existing], "already exists"),
        (["calibrate", "--output", "x", "--input", "x:1", "-o", os.path.join(d, "p.toml")],
         "DEV:CH"),
    ]
    for args, expected in cases:
        r = subprocess.run([tactus, *args], capture_output=True, text=True, env=env, timeout=60)
        lines = [l for l in r.stderr.splitlines() if l.startswith("tactus: error:")]
        ok = r.returncode != 0 and len(lines) == 1 and expected in lines[0]
        print(("ok: " if ok else "FAIL: ") + " ".join(args) + " -> " + " | ".join(lines))
        failed += not ok
    for command in ["live", "devices", "calibrate"]:
        r = subprocess.run([tactus, command, "--help"], capture_output=True, text=True)
        ok = r.returncode == 0 and "Usage" in r.stdout
        print(("ok: " if ok else "FAIL: ") + command + " --help")
        failed += not ok
    r = subprocess.run([tactus, "devices"], capture_output=True, text=True, env=env, timeout=60)
    ok = r.returncode == 0 and "jack" in r.stdout and "alsa" in r.stdout
    print(("ok: " if ok else "FAIL: ") + "devices lists the backends")
    failed += not ok
    # alsa-lib's own lines ("ALSA lib confmisc.c:855:(parse_card) cannot find card '0'" on a
    # machine without a sound card) stay silent: the listing says what there is.
    noise = [l for l in r.stderr.splitlines() if l.startswith("ALSA lib")]
    print(("ok: " if not noise else "FAIL: ") + f"devices prints no alsa-lib noise ({len(noise)} lines)")
    failed += bool(noise)
    assert sorted(os.listdir(d)) == ["exists.toml"], "nothing written"
sys.exit(1 if failed else 0)
