#!/usr/bin/env bash
# Installs, from Debian packages, whatever tactus needs to build, test and run its demo.
# Idempotent: only missing packages are installed; uses sudo when not root.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config clang-format clang-tidy clang libclang-rt-14-dev
  libsndfile1-dev libvorbis-dev libogg-dev libfftw3-dev libtomlplusplus-dev libreaderwriterqueue-dev nlohmann-json3-dev libcli11-dev libfmt-dev
  libgtest-dev libgmock-dev libbenchmark-dev valgrind
  sonic-pi-samples aubio-tools sox lame puredata-core puredata-extra puredata-dev time
  python3 python3-numpy python3-scipy python3-soundfile python3-mir-eval
  fluidsynth fluid-soundfont-gm musescore-general-soundfont-small timgm6mb-soundfont espeak-ng
  dpf-source liblilv-dev lv2-dev lilv-utils sordi jackd2 ardour
  python3-dev pybind11-dev python3-pytest python3-matplotlib python3-distributed python3-pandas
  vamp-plugin-sdk vamp-examples
  libjs-dygraphs chromium python3-pil
  librtaudio-dev liblo-dev libjack-jackd2-dev libasound2-dev
  libcpp-httplib-dev chromium-driver python3-selenium
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
echo "setup: installing ${missing[*]}" >&2
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
