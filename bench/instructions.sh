#!/usr/bin/env bash
# Start-up cost, counted (`make bench-instructions`): instructions executed, by valgrind's
# callgrind (deterministic: the same figures on any load), and one time on the wall clock.
#   whole process     `tactus render` of a 10 ms file (48 kHz mono), everything from exec to exit
#   Engine::prepare   the first in a process, and another engine's with the same settings
#                     (bench/startup_bench.cpp, counted inside the call alone)
#   Engine::process   per second of 48 kHz mono audio (the Amen break), default preset,
#                     512-frame blocks
#   per block         Engine::process of one 64-frame block at 48 kHz (the Amen break, default
#                     preset, 2 s after a second's warm-up): instructions at the median, 99th
#                     percentile and largest; a block's work, apart from caches and the machine
#   floors            what no change of ours can lower: a program linked as the engine that
#                     returns at once (the dynamic loader and the libraries' start-up), and
#                     FFTW's first plan, of 2 points (its planner made, which every process's
#                     first Engine::prepare pays)
#   structural swap   Engine::set() of the hop on the control thread of a running engine (64-frame
#                     blocks): the new pipeline built and primed; median and largest of 20 (ms,
#                     this machine, whatever else runs), and its instructions
# usage: bench/instructions.sh [BUILD_DIR]   (default build/release)
set -euo pipefail
build=${1:-build/release}
tactus=$build/bin/tactus
bench=$build/bin/tactus_startup_bench
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Instructions callgrind counts for a command; extra callgrind options first, then --.
count() {
  local options=()
  while [ "$1" != -- ]; do options+=("$1"); shift; done
  shift
  valgrind --tool=callgrind --callgrind-out-file="$work/out" "${options[@]}" "$@" \
    >"$work/stdout" 2>"$work/log"
  sed -n 's/.*Collected : \([0-9]*\).*/\1/p' "$work/log"
}
# Instructions inside calls of one function of startup_bench.
inside() {
  local function=$1
  shift
  count --collect-atstart=no "--toggle-collect=$function" -- "$bench" "$@"
}

/usr/bin/python3 -c "
import numpy, soundfile
t = numpy.arange(480) / 48000
soundfile.write('$work/ten_ms.wav', (0.5 * numpy.sin(2 * numpy.pi * 100 * t)).astype('float32'),
                48000, subtype='FLOAT')"
seconds=10
whole=$(count -- "$tactus" render "$work/ten_ms.wav" -o "$work/out.wav" --force)
floor=$(count -- "$bench" floor)
fftw=$(inside measured_fftw_planner fftw)
first=$(inside measured_first_prepare prepare)
again=$(inside measured_prepare_again prepare)
process=$(inside measured_process process $seconds)
# One callgrind dump per block (--dump-after: $work/out.1, .2, ...), each that block's count alone.
count --collect-atstart=no --toggle-collect=measured_block --dump-after=measured_block -- \
  "$bench" blocks 2 >/dev/null
read -r block_p50 block_p99 block_max < <(
  for dump in "$work"/out.*; do sed -n 's/^totals: \([0-9]*\).*/\1/p' "$dump"; done |
    sort -n | awk '{ n[NR] = $1 } END { print n[int(NR / 2) + 1], n[int(NR * 0.99) + 1], n[NR] }')
swaps=4
swap_instructions=$(inside measured_swap swap $swaps)
read -r swap_median swap_max < <("$bench" swap 20)

printf '%-58s %14s\n' "whole process, tactus render of a 10 ms file" "$whole"
printf '%-58s %14s\n' "floor: a program linked as the engine, returning at once" "$floor"
printf '%-58s %14s\n' "floor: FFTW's first plan in a process (2 points)" "$fftw"
printf '%-58s %14s\n' "Engine::prepare, the first in the process" "$first"
printf '%-58s %14s\n' "Engine::prepare, another engine, same settings" "$again"
printf '%-58s %14s\n' "Engine::process, per second of 48 kHz mono (default preset)" \
  "$((process / seconds))"
printf '%-58s %14s\n' "Engine::process, a 64-frame block: median / p99 / largest" \
  "$block_p50 / $block_p99 / $block_max"
printf '%-58s %14s\n' "structural swap (control thread), instructions each" \
  "$((swap_instructions / swaps))"
printf '%-58s %14s\n' "structural swap (control thread), ms median / largest" \
  "$swap_median / $swap_max"
