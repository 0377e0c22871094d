#!/bin/sh
# The plugin binaries export the entry points hosts look up: clap_entry in the .clap;
# GetPluginFactory, ModuleEntry and ModuleExit in the VST3 bundle's binary (nm -D).
# Usage: entry_symbols.sh PLUGIN.clap PLUGIN.vst3/Contents/ARCH-linux/PLUGIN.so
set -eu
check() {
    if nm -D --defined-only "$1" | awk '{print $3}' | grep -qx "$2"; then
        echo "$1: exports $2"
    else
        echo "$1: does not export $2" >&2
        exit 1
    fi
}
check "$1" clap_entry
for symbol in GetPluginFactory ModuleEntry ModuleExit; do check "$2" "$symbol"; done
