#!/bin/sh
# Ardour's VST3 scanner (Debian ardour) loads the VST3 bundle, instantiates its one class and
# indexes it: the plugin found, two inputs and four outputs. Its cache goes to a fresh HOME.
# Usage: vst3_scan.sh ardour-vst3-scanner PLUGIN.vst3
set -eu
scanner=$1
bundle=$2
home=$(mktemp -d)
trap 'rm -rf "$home"' EXIT
out=$(HOME=$home XDG_CACHE_HOME=$home/.cache LD_LIBRARY_PATH=$(dirname "$scanner") \
      "$scanner" -f -v "$bundle" 2>&1) || { echo "$out"; exit 1; }
echo "$out"
echo "$out" | grep -q "Found Plugin: tactus" || { echo "scanner did not find tactus" >&2; exit 1; }
echo "$out" | grep -q 'n_inputs="2" n_outputs="4"' || { echo "wrong ports" >&2; exit 1; }
