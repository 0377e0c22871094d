#!/usr/bin/env bash
# `tactus render` of a 10 ms file stays cheap to start: at most LIMIT instructions from exec to
# exit, counted by callgrind (the figure `make bench-instructions` reports; deterministic on any
# load). 46 M when `tactus` loaded the live and studio commands' libraries and built every
# command's options; 23.6 M since, half of it the render's tail (the vibration dying away).
# usage: render_start_instructions.sh TACTUS [LIMIT]
set -euo pipefail
tactus=$1
limit=${2:-30000000}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
sox -n -r 48000 -c 1 -e floating-point -b 32 "$work/ten_ms.wav" synth 0.01 sine 100
valgrind --tool=callgrind --callgrind-out-file=/dev/null "$tactus" render "$work/ten_ms.wav" \
  -o "$work/out.wav" 2>"$work/log"
counted=$(sed -n 's/.*Collected : \([0-9]*\).*/\1/p' "$work/log")
echo "tactus render of a 10 ms file: $counted instructions (at most $limit)"
[ -s "$work/out.wav" ] && [ -n "$counted" ] && [ "$counted" -le "$limit" ]
