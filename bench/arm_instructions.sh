#!/usr/bin/env bash
# A small board's cost of a block, counted under qemu-user (valgrind does not run there and
# Debian's qemu ships no instruction-counting plugin): Engine::process on the Amen break at
# 48 kHz mono, default preset, 64-frame blocks (bench/startup_bench.cpp), run for two lengths;
# the difference in instructions executed, over the difference in blocks, is a block's cost
# without the program's start-up and the engine's prepare. qemu logs each translated block's
# instructions once (in_asm) and each execution of a block (exec, nochain: every one logged).
# usage: bench/arm_instructions.sh BUILD_DIR QEMU   (build/arm64 qemu-aarch64-static)
set -euo pipefail
build=$1
qemu=$2
if [ ! -x "$build/bin/tactus_startup_bench" ]; then
  echo "arm_instructions.sh: $build/bin/tactus_startup_bench is missing (cmake --build $build --target tactus_startup_bench)" >&2
  exit 1
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkfifo "$work/log"

# Instructions the guest executes in `startup_bench process SECONDS 64`.
count() {
  awk '
    function close_block() { if (pc != "") size[pc] = n; pc = ""; inside = 0 }
    /^IN:/ { close_block(); inside = 1; n = 0; next }
    inside && /^0x[0-9a-f]+:/ {
      if (pc == "") { pc = substr($1, 3, length($1) - 3); sub(/^0+/, "", pc) }
      ++n; next
    }
    /^Trace/ {
      close_block()
      split($4, field, "/"); start = substr(field[2], 1); sub(/^0+/, "", start)
      total += size[start]; next
    }
    inside && !/^0x/ { close_block() }
    END { printf "%.0f\n", total }' "$work/log" &
  local reader=$!
  "$qemu" -d in_asm,exec,nochain -D "$work/log" "$build/bin/tactus_startup_bench" process "$1" 64
  wait "$reader"
}

short=$(count 0.5)
long=$(count 1.5)
blocks=$((48000 / 64))  # the second more the long run has
per_block=$(((long - short) / blocks))
echo "instructions per 64-frame block at 48 kHz: $per_block"
