#!/usr/bin/env bash
# Renders the Amen break with two tactus programs (say, one built from an earlier commit and
# this one) for the tfd preset, the four-channel preset and the lra-175 actuator, and compares
# the sample data (not the bytes: a WAV's PEAK chunk holds a time stamp).
# usage: scripts/compare_renders.sh OLD_TACTUS NEW_TACTUS
set -euo pipefail
old=$1
new=$2
amen=/usr/share/sonic-pi/samples/loop_amen_full.flac
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cases=("tfd:--preset tfd" "four-channel:--preset four-channel" "lra-175:--actuator lra-175")
for c in "${cases[@]}"; do
  name=${c%%:*}
  # shellcheck disable=SC2086
  "$old" render "$amen" -o "$work/$name.old.wav" ${c#*:} 2>/dev/null
  # shellcheck disable=SC2086
  "$new" render "$amen" -o "$work/$name.new.wav" ${c#*:} 2>/dev/null
done
/usr/bin/python3 - "$work" "${cases[@]%%:*}" <<'PY'
import sys, numpy, soundfile
work, names = sys.argv[1], sys.argv[2:]
different = 0
for name in names:
    a, _ = soundfile.read(f"{work}/{name}.old.wav", dtype="float32")
    b, _ = soundfile.read(f"{work}/{name}.new.wav", dtype="float32")
    same = a.shape == b.shape and numpy.array_equal(a.view(numpy.uint32), b.view(numpy.uint32))
    different += not same
    print(f"{name:14} {a.shape[0]} samples: " +
          ("bit-identical" if same else f"DIFFERENT (largest difference {numpy.abs(a - b).max():g})"))
sys.exit(1 if different else 0)
PY
