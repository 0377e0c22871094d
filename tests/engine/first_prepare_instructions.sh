#!/usr/bin/env bash
# A process's first Engine::prepare (48 kHz, default settings) stays cheap: at most LIMIT
# instructions, counted by callgrind inside measured_first_prepare of tactus_startup_bench (the
# figure `make bench-instructions` reports; deterministic on any load). 18 M when the default
# flattening was fitted in it and each FFT size imported its wisdom alone; 5.5 M since.
# usage: first_prepare_instructions.sh STARTUP_BENCH [LIMIT]
set -euo pipefail
bench=$1
limit=${2:-8000000}
log=$(mktemp)
trap 'rm -f "$log"' EXIT
valgrind --tool=callgrind --callgrind-out-file=/dev/null --collect-atstart=no \
  --toggle-collect=measured_first_prepare "$bench" prepare 2>"$log"
counted=$(sed -n 's/.*Collected : \([0-9]*\).*/\1/p' "$log")
echo "first Engine::prepare: $counted instructions (at most $limit)"
[ -n "$counted" ] && [ "$counted" -le "$limit" ]
