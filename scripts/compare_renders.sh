#!/usr/bin/env bash
# Renders the Amen break (stereo, and mixed down to mono with sox) with two tactus programs
# (say, one built from an earlier commit and this one) for the tfd preset, the four-channel
# preset and the lra-175 actuator, and compares the sample data (not the bytes: a WAV's PEAK
# chunk holds a time stamp). Exits 1 if any render differs.
# usage: scripts/compare_renders.sh OLD_TACTUS NEW_TACTUS
set -euo pipefail
old=$1
new=$2
amen=/usr/share/sonic-pi/samples/loop_amen_full.flac
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
sox "$amen" "$work/amen-mono.flac" remix -
cases=("tfd:--preset tfd" "four-channel:--preset four-channel" "lra-175:--actuator lra-175")
names=()
for input in "$amen" "$work/amen-mono.flac"; do
  channels=$(soxi -c "$input")
  for c in "${cases[@]}"; do
    name=${c%%:*}-$channels-channel
    names+=("$name")
    # shellcheck disable=SC2086
    "$old" render "$input" -o "$work/$name.old.wav" ${c#*:} 2>/dev/null
    # shellcheck disable=SC2086
    "$new" render "$input" -o "$work/$name.new.wav" ${c#*:} 2>/dev/null
  done
done
/usr/bin/python3 - "$work" "${names[@]}" <<'PY'
import sys, numpy, soundfile
work, names = sys.argv[1], sys.argv[2:]
different = 0
for name in names:
    a, _ = soundfile.read(f"{work}/{name}.old.wav", dtype="float32")
    b, _ = soundfile.read(f"{work}/{name}.new.wav", dtype="float32")
    same = a.shape == b.shape and numpy.array_equal(a.view(numpy.uint32), b.view(numpy.uint32))
    different += not same
    print(f"{name:24} {a.shape[0]} samples: " +
          ("bit-identical" if same else f"DIFFERENT (largest difference {numpy.abs(a - b).max():g})"))
sys.exit(1 if different else 0)
PY
