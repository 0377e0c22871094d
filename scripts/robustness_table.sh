#!/usr/bin/env bash
# Runs tactus on every bad input of docs/robustness.md and prints the table's rows: what was
# given, the exact last line tactus wrote on stderr, the exit code, and the test that checks it.
# The inputs are made here (libsndfile through python3-soundfile, sox, lame) in a temporary
# directory, and named relative to it so the messages are short.
#   scripts/robustness_table.sh [build/release] > table.md
set -uo pipefail
build=$(realpath "${1:-build/release}")
tactus="$build/bin/tactus"
python=/usr/bin/python3
work=$(mktemp -d)
trap 'umount "$work/small" 2>/dev/null; rm -rf "$work"' EXIT
cd "$work"

# Inputs: real files written with libsndfile, then cut, corrupted or mislabelled.
"$python" - <<'EOF'
import numpy as np, soundfile as sf
rate = 44100
t = np.arange(3 * rate) / rate
beat = (0.8 * np.sin(2 * np.pi * 60 * t) * np.exp(-((t % 0.5) / 0.08))).astype(np.float32)
sf.write("drums.wav", beat, rate, subtype="PCM_16")
sf.write("drums.flac", beat, rate, subtype="PCM_16")
sf.write("drums.mp3", beat, rate, format="MP3")
sf.write("silent.wav", np.zeros(0, np.float32), rate, subtype="PCM_16")
sf.write("low.wav", beat[:4000], 4000, subtype="PCM_16")
sf.write("high.wav", beat[:4000], 384000, subtype="PCM_16")
sf.write("wide.wav", np.tile(beat[:, None], (1, 64)), rate, subtype="PCM_16")
bad = beat.copy()
bad[::97] = np.array([np.nan, np.inf, -np.inf, 1e-40, 3e38], np.float32)[np.arange(len(bad[::97])) % 5]
sf.write("nan.wav", bad, rate, subtype="FLOAT")
sf.write("dc.wav", 0.5 * beat + 0.4, rate, subtype="FLOAT")
sf.write("square.wav", np.where((np.arange(3 * rate) // 441) % 2, 1.0, -1.0).astype(np.float32),
         rate, subtype="FLOAT")
sf.write("long.wav", np.tile(beat, 100), rate, subtype="PCM_16")
sf.write("beat30.wav", np.tile(beat, 10), rate, subtype="PCM_16")
for name in ("drums.wav", "drums.flac", "drums.mp3"):
    data = open(name, "rb").read()
    open("cut." + name.split(".")[1], "wb").write(data[: len(data) // 2])
data = bytearray(open("drums.flac", "rb").read())
data[4096::997] = bytes(255 - b for b in data[4096::997])
open("corrupt.flac", "wb").write(data)
open("header.wav", "wb").write(open("drums.wav", "rb").read()[:30])
open("notes.wav", "w").write("not audio\n")
open("empty.wav", "w").close()
open("picture.png", "wb").write(b"\x89PNG\r\n\x1a\n" + bytes(range(256)) * 4)
open("decai.toml", "w").write("[envelope]\ndecai_ms = 3\n")
open("slow.toml", "w").write('[envelope]\ndecay_ms = "slow"\n')
open("hot.toml", "w").write("[post]\nceiling_db = 3\n")
open("syntax.toml", "w").write("[envelope]\ndecay_ms = = 3\n")
EOF
lame --quiet -t -b 128 beat30.wav tagless.mp3  # constant bitrate, no Xing/Info tag
mkdir sub locked && chmod 555 locked
cp drums.wav locked.wav && chmod 000 locked.wav
echo "keep me" > exists.wav
chmod 755 "$work"
nobody="setpriv --reuid=65534 --regid=65534 --clear-groups"
[ "$(id -u)" -eq 0 ] || nobody=""

cell() { printf '%s' "$1" | sed 's/|/\\|/g'; }
# row DESCRIPTION TEST COMMAND...: runs COMMAND, reports its last stderr line and exit code.
row() {
  local description=$1 test=$2
  shift 2
  local err code
  err=$("$@" 2>&1 >/dev/null)
  code=$?
  rm -f out.wav out.csv
  printf '| %s | `%s` | %s | %s |\n' "$description" "$(cell "$(tail -n 1 <<<"$err")")" "$code" "$test"
}
# After a run that must fail: anything left beside the output?
leftovers() { ls -A "${1:-.}" | grep -E '^(out\.|\.out\.)' | tr '\n' ' '; }

echo '| input | tactus says (stderr, last line) | exit | test |'
echo '|---|---|---|---|'
row "missing file (every command taking input paths)" BadInput.MissingInputFile "$tactus" render nosuch.wav -o out.wav
row "directory as input (with no sound files in it)" BadInput.InputIsADirectory "$tactus" render sub -o out.wav
row "unreadable file (mode 000, not root)" BadInput.UnreadableInputFile $nobody "$tactus" render locked.wav -o out.wav
row "empty file" BadInput.EmptyFile "$tactus" render empty.wav -o out.wav
row "text file named .wav" BadInput.TextFileNamedWav "$tactus" render notes.wav -o out.wav
row "unsupported format (PNG)" BadInput.UnsupportedFormat "$tactus" render picture.png -o out.wav
row "WAV header without data" BadInput.WavHeaderWithoutData "$tactus" render header.wav -o out.wav
row "truncated WAV (half)" BadInput.TruncatedWav "$tactus" render cut.wav -o out.wav
row "truncated FLAC (half)" BadInput.TruncatedFlac "$tactus" render cut.flac -o out.wav
row "corrupt FLAC (every 997th byte inverted)" BadInput.CorruptFlac "$tactus" render corrupt.flac -o out.wav
row "truncated MP3 (half)" BadInput.Mp3IsReadAndTruncatedMp3Refused "$tactus" render cut.mp3 -o out.wav
row "zero frames" BadInput.ZeroFrames "$tactus" render silent.wav -o out.wav
row "sample rate 4 kHz" BadInput.SampleRatesOutsideTheSupportedRange "$tactus" render low.wav -o out.wav
row "sample rate 384 kHz" BadInput.SampleRatesOutsideTheSupportedRange "$tactus" render high.wav -o out.wav
row "MP3 (valid)" BadInput.Mp3IsReadAndTruncatedMp3Refused "$tactus" render drums.mp3 -o out.wav
row "MP3 without a length tag (constant bitrate: its estimated length 3047 frames over what decodes)" BadInput.Mp3WithoutLengthTagIsReadToItsEnd "$tactus" render tagless.mp3 -o out.wav
row "64 channels (downmixed)" BadInput.ManyChannelsAreDownmixed "$tactus" render wide.wav -o out.wav
row "NaN, ±Inf, denormal, 3e38 samples" BadInput.NonFiniteAndDenormalSamplesNeverReachTheOutput "$tactus" render nan.wav -o out.wav
row "DC offset 0.4" BadInput.DcOffsetDoesNotChangeTheVibration "$tactus" render dc.wav -o out.wav
row "full-scale square wave" BadInput.FullScaleSquareWaveStaysUnderTheCeiling "$tactus" render square.wav -o out.wav
row "--set unknown key" BadInput.UnknownKeySuggestsTheNearest "$tactus" render drums.wav -o out.wav --set envelope.decay=100
row "preset unknown key" BadInput.UnknownKeySuggestsTheNearest "$tactus" render drums.wav -o out.wav --preset decai.toml
row "preset wrong type" BadInput.WrongTypeInPreset "$tactus" render drums.wav -o out.wav --preset slow.toml
row "--set wrong type" BadInput.WrongTypeInPreset "$tactus" render drums.wav -o out.wav --set envelope.decay_ms=slow
row "--set out of range" BadInput.OutOfRangeValueStatesTheRangeAndUnit "$tactus" render drums.wav -o out.wav --set envelope.decay_ms=-3
row "preset out of range" BadInput.OutOfRangeValueStatesTheRangeAndUnit "$tactus" render drums.wav -o out.wav --preset hot.toml
row "--set without =" BadInput.MalformedAssignment "$tactus" render drums.wav -o out.wav --set envelope.decay_ms
row "--set newline in key" BadInput.ControlCharactersInAKeyStayOnOneLine "$tactus" render drums.wav -o out.wav --set "$(printf 'a\nb=1')"
row "TOML syntax error" BadInput.TomlSyntaxErrorGivesLineAndColumn "$tactus" render drums.wav -o out.wav --preset syntax.toml
row "missing preset name" BadInput.MissingPreset "$tactus" render drums.wav -o out.wav --preset nonesuch
row "missing preset file" BadInput.MissingPreset "$tactus" render drums.wav -o out.wav --preset gone.toml
row "output is the input" BadInput.OutputIsTheInput "$tactus" render drums.wav -o drums.wav --force
row "existing output, no --force" BadInput.ExistingOutputNeedsForce "$tactus" render drums.wav -o exists.wav
row "existing analyze -o, no --force" BadInput.ExistingOutputNeedsForce "$tactus" analyze drums.wav -o exists.wav
row "output directory missing" BadInput.OutputDirectoryMissing "$tactus" render drums.wav -o nowhere/out.wav
row "output is a directory" BadInput.OutputIsADirectory "$tactus" render drums.wav -o sub --force
row "unwritable directory (not root)" BadInput.UnwritableDirectory $nobody "$tactus" render drums.wav -o locked/out.wav
row "stdout on a full device (analyze > /dev/full)" BadInput.StdoutOnAFullDevice sh -c "'$tactus' analyze drums.wav >/dev/full"
row "existing onsets -o, no --force" BadInput.ExistingOutputNeedsForce "$tactus" onsets drums.wav -o exists.wav
if mkdir small && mount -t tmpfs -o size=64k tmpfs small 2>/dev/null; then
  row "full disk (64 KiB tmpfs), render" FullDisk.RenderAndAnalyzeReportNoSpaceAndLeaveNothing "$tactus" render long.wav -o small/out.wav
  row "full disk (64 KiB tmpfs), analyze" FullDisk.RenderAndAnalyzeReportNoSpaceAndLeaveNothing "$tactus" analyze long.wav -o small/out.csv
  echo "| full disk: files left in the tmpfs | \`$(ls -A small | tr '\n' ' ')\` | | |"
fi
for signal in INT TERM HUP KILL; do
  "$tactus" render long.wav -o out.wav 2>/dev/null &
  pid=$!
  while kill -0 "$pid" 2>/dev/null && ! ls -A | grep -q '^\.out\.wav\.tmp-'; do sleep 0.001; done
  sleep 0.05
  kill -"$signal" "$pid"
  wait "$pid"
  code=$?
  test=Interrupted.SigintAndSigtermLeaveNoFile
  [ "$signal" = KILL ] && test=Interrupted.SigkillLeavesOnlyTheHiddenTemporary
  echo "| SIG$signal during render: files left | \`$(leftovers | sed 's/tmp-[0-9]*/tmp-PID/')\` | $code | $test |"
  rm -f .out.wav.tmp-* out.wav
done
# Hours-long input: streamed, so peak memory is that of a 10 s file.
sox -n -r 8000 -b 16 short.wav synth 10 sine 60 tremolo 2 90
sox -n -r 8000 -b 16 hour.wav synth 1:00:00 sine 60 tremolo 2 90
# Peak RSS from GNU time: ru_maxrss counts the image a child was forked from, and time's is small.
for input in short.wav hour.wav; do
  /usr/bin/time -f %M -o rss.txt "$tactus" render "$input" -o out.wav 2>message.txt
  code=$?
  rss=$(awk '{printf "%.1f", $1 / 1024}' rss.txt)
  echo "| $input (8 kHz): peak RSS $rss MiB | \`$(tail -n 1 message.txt)\` | $code | |"
  rm -f out.wav rss.txt message.txt
done
