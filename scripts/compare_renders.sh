#!/usr/bin/env bash
# Renders the Amen break (stereo, and mixed down to mono with sox) with two tactus programs
# (say, one built from an earlier commit and this one) for the tfd preset, the four-channel
# preset and the lra-175 actuator, and compares the sample data (not the bytes: a WAV's PEAK
# chunk holds a time stamp). Exits 1 if any render differs (by more than --tolerance, in full
# scale, when given: another machine's build). --emulator runs NEW_TACTUS under a program (an Arm
# build under qemu-aarch64-static, say: make test-arm).
# usage: scripts/compare_renders.sh [--tolerance X] [--emulator PROGRAM] OLD_TACTUS NEW_TACTUS
set -euo pipefail
tolerance=0
emulator=()
while [ $# -gt 2 ]; do
  case $1 in
    --tolerance) tolerance=$2 ;;
    --emulator) emulator=("$2") ;;
    *) echo "compare_renders.sh: unknown option $1" >&2; exit 2 ;;
  esac
  shift 2
done
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
    "${emulator[@]}" "$new" render "$input" -o "$work/$name.new.wav" ${c#*:} 2>/dev/null
  done
done
/usr/bin/python3 - "$work" "$tolerance" "${names[@]}" <<'PY'
import sys, numpy, soundfile
work, tolerance, names = sys.argv[1], float(sys.argv[2]), sys.argv[3:]
different = 0
for name in names:
    a, _ = soundfile.read(f"{work}/{name}.old.wav", dtype="float32")
    b, _ = soundfile.read(f"{work}/{name}.new.wav", dtype="float32")
    if a.shape != b.shape:
        different += 1
        print(f"{name:24} DIFFERENT shapes {a.shape} and {b.shape}")
        continue
    if numpy.array_equal(a.view(numpy.uint32), b.view(numpy.uint32)):
        print(f"{name:24} {a.shape[0]} samples: bit-identical")
        continue
    largest = numpy.abs(a.astype(numpy.float64) - b).max()
    different += not largest <= tolerance
    print(f"{name:24} {a.shape[0]} samples: largest difference {largest:.3g}, " +
          (f"within {tolerance:g}" if largest <= tolerance else "DIFFERENT"))
sys.exit(1 if different else 0)
PY
