#!/usr/bin/env bash
# ScopedFlushDenormals compiled for aarch64 (Raspberry Pi, Bela, Apple Silicon) by clang: the
# scope reads FPCR, writes it back with FZ (bit 24) set, runs a block's work (here: scaling a
# buffer in memory) and restores FPCR; the work stays between the two writes.
# usage: denormals_aarch64.sh SOURCE_DIR
set -euo pipefail
asm=$(printf '%s\n' '#include "tactus/dsp/denormals.hpp"' \
  'void scale(float* x, int n) { tactus::ScopedFlushDenormals flush; for (int i = 0; i < n; ++i) x[i] *= 0.5f; }' |
  clang++ -std=c++20 -O2 -target aarch64-linux-gnu -I"$1/src" -x c++ -S -o - - | grep -v '^[[:space:]]*[./]')
# here-strings, not echo | grep -q: grep leaving early would end echo with SIGPIPE, a failure
# under pipefail.
fail() { echo "aarch64: $1" >&2; echo "$asm" >&2; exit 1; }
grep -Eiq 'mrs[[:space:]]+x[0-9]+, *fpcr' <<<"$asm" || fail "FPCR is not read"
grep -Eiq 'orr[[:space:]]+x[0-9]+, *x[0-9]+, *#0x1000000' <<<"$asm" || fail "FZ (bit 24) is not set"
# Every fmul comes after the first FPCR write and before the last.
writes=$(grep -Ein 'msr[[:space:]]+fpcr' <<<"$asm" | cut -d: -f1)
first=${writes%%$'\n'*}
last=${writes##*$'\n'}
[ "$first" != "$last" ] || fail "FPCR is not restored"
muls=$(grep -Ein 'fmul' <<<"$asm" | cut -d: -f1)
[ -n "$muls" ] || fail "no multiply"
for m in $muls; do
  [ "$m" -gt "$first" ] && [ "$m" -lt "$last" ] || fail "a multiply at line $m is outside the scope"
done
echo "aarch64: FPCR.FZ set around the block's work and restored"
