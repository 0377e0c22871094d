#!/usr/bin/env bash
# Installs, from Debian packages, whatever tactus needs to build, test and run its demo.
# Idempotent: only missing packages are installed; uses sudo when not root.
# usage: scripts/setup.sh [arm]   (arm: also the cross toolchains, qemu-user-static and the arm64
# and armhf -dev packages the library, the command line, tactus~ and their tests need, for
# `make test-arm`; the two architectures are added to dpkg when missing)
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config clang-format clang-tidy clang libclang-rt-14-dev
  libsndfile1-dev libvorbis-dev libogg-dev libfftw3-dev libtomlplusplus-dev libreaderwriterqueue-dev nlohmann-json3-dev libcli11-dev libfmt-dev
  libgtest-dev libgmock-dev libbenchmark-dev valgrind
  sonic-pi-samples aubio-tools sox lame puredata-core puredata-extra puredata-dev time
  python3 python3-numpy python3-scipy python3-soundfile python3-mir-eval
  fluidsynth fluid-soundfont-gm musescore-general-soundfont-small timgm6mb-soundfont espeak-ng
  hydrogen-drumkits
  dpf-source liblilv-dev lv2-dev lilv-utils sordi jackd2 ardour
  python3-dev pybind11-dev python3-pytest python3-matplotlib python3-distributed python3-pandas
  vamp-plugin-sdk vamp-examples
  libjs-dygraphs chromium python3-pil
  librtaudio-dev liblo-dev libjack-jackd2-dev libasound2-dev
  libcpp-httplib-dev chromium-driver python3-selenium
)

sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
if [ "${1:-}" = arm ]; then
  packages+=(qemu-user-static crossbuild-essential-arm64 crossbuild-essential-armhf)
  for arch in arm64 armhf; do
    if ! dpkg --print-foreign-architectures | grep -qx "$arch"; then
      echo "setup: adding the $arch architecture to dpkg" >&2
      $sudo dpkg --add-architecture "$arch"  # its packages are then missing: apt-get update below
    fi
    # libvorbis-dev brings libogg-dev, libgmock-dev libgtest-dev; the header-only packages
    # (nlohmann-json, CLI11, readerwriterqueue, puredata-dev) are the host's.
    for p in libsndfile1-dev libfftw3-dev libvorbis-dev libtomlplusplus-dev libfmt-dev libgmock-dev; do
      packages+=("$p:$arch")
    done
  done
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "setup: installing ${missing[*]}" >&2
# A mirror caught mid-sync serves an index of the wrong size: try again, then go on with the
# indexes that did come (the install below fails, naming the package, if one is missing).
for attempt in 1 2 3; do
  $sudo apt-get update -qq && break
  echo "setup: apt-get update failed (attempt $attempt of 3)" >&2
  sleep $((attempt * 10))
done
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
