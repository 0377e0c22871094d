#!/usr/bin/env bash
# `cmake --install` of the build tree into a temporary prefix, then as a user of the installed
# package: examples/drum_engine.cpp built with find_package(tactus) and with pkg-config, and
# run; it links the DSP core alone (no libsndfile, no toml++); the installed program finds its
# presets and actuator profiles beside itself, with no environment, and renders a file loading
# none of the live and studio commands' libraries; those commands run their installed helpers.
# usage: install_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$1
source=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix

cmake --install "$build" --prefix "$prefix" >"$work/install.log"
for f in include/tactus/engine/engine.hpp lib/libtactus_dsp.a lib/libtactus_files.a \
         lib/cmake/tactus/tactusConfig.cmake lib/pkgconfig/tactus-dsp.pc lib/pkgconfig/tactus.pc \
         bin/tactus share/tactus/presets/tfd.toml share/tactus/actuators/lra-175.toml; do
  [ -e "$prefix/$f" ] || { echo "not installed: $f" >&2; exit 1; }
done

echo "== find_package(tactus)"
cmake -S "$source/examples" -B "$work/cmake" -G Ninja -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_PREFIX_PATH="$prefix" >"$work/configure.log"
cmake --build "$work/cmake" >"$work/build.log"
"$work/cmake/drum_engine"

echo "== pkg-config tactus-dsp"
export PKG_CONFIG_PATH=$prefix/lib/pkgconfig
# shellcheck disable=SC2046
c++ "$source/examples/drum_engine.cpp" -o "$work/drum_engine" $(pkg-config --cflags --libs tactus-dsp)
"$work/drum_engine"

for program in "$work/cmake/drum_engine" "$work/drum_engine"; do
  if ldd "$program" | grep -E 'libsndfile|libtomlplusplus'; then
    echo "$program: the DSP core pulled in file or TOML libraries" >&2
    exit 1
  fi
done

echo "== installed tactus, no environment"
sox -n -r 48000 -c 2 "$work/drums.wav" synth 2 pluck 100 tremolo 4 100
home=$work/home
mkdir -p "$home"
env -i HOME="$home" PATH=/usr/bin:/bin "$prefix/bin/tactus" presets | grep -q '^tfd '
env -i HOME="$home" PATH=/usr/bin:/bin "$prefix/bin/tactus" render "$work/drums.wav" \
    -o "$work/vibration.wav" --preset four-channel --actuator lra-175
[ -s "$work/vibration.wav" ]
LD_DEBUG=libs "$prefix/bin/tactus" render "$work/drums.wav" -o "$work/again.wav" 2>"$work/libs.log"
if grep -Eo 'lib(rtaudio|jack|asound|lo|pulse|ssl|crypto|brotli[a-z]*)\.so[.0-9]*' "$work/libs.log" |
    sort -u | grep .; then
  echo "the installed tactus render loads the live or studio commands' libraries" >&2
  exit 1
fi
if [ -e "$build/libexec/tactus/tactus-live" ]; then
  [ -x "$prefix/libexec/tactus/tactus-live" ] || { echo "not installed: tactus-live" >&2; exit 1; }
  env -i HOME="$home" PATH=/usr/bin:/bin "$prefix/bin/tactus" devices | grep '^jack ' >/dev/null
  env -i HOME="$home" PATH=/usr/bin:/bin "$prefix/bin/tactus" live --help | grep -- '--backend' >/dev/null
  # The helper finds the presets installed with the package.
  if env -i HOME="$home" PATH=/usr/bin:/bin "$prefix/bin/tactus" live --preset nosuch \
      2>"$work/live.err"; then exit 1; fi
  grep -q "no preset named 'nosuch' (known: drums" "$work/live.err"
fi
if [ -e "$build/libexec/tactus/tactus-studio" ]; then
  env -i HOME="$home" PATH=/usr/bin:/bin "$prefix/bin/tactus" studio --help | grep -- '--port' >/dev/null
fi
echo "installed package OK"
