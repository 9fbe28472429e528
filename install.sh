#!/usr/bin/env bash
# Installs everything MixEngine needs to build and test, from Debian packages only.
# Idempotent: a second run installs nothing new. Run as root (or with sudo available).
#   ./install.sh          build + test dependencies (make test)
#   ./install.sh --engine what configuring the build, building the engine and slicing need (make demo)
set -euo pipefail

ENGINE_PACKAGES=(
  # build
  g++ cmake ninja-build pkg-config ccache clang-format make
  libprotobuf-dev protobuf-compiler
  libeigen3-dev libcgal-dev libgmp-dev libmpfr-dev libboost-dev
  libpolyclipping-dev nlohmann-json3-dev lib3mf-dev libzip-dev zlib1g-dev libpng-dev libjpeg-dev libfftw3-dev liblcms2-dev
  libmimalloc-dev
  # the configure step finds GoogleTest, clang-format and Python 3 (tests/CMakeLists.txt) even when only the
  # engine is built
  libgtest-dev python3
  # Cura's definitions (the engine's defaults without -j, and -j <id>) and its material profiles (--profiles)
  cura fdm-materials
)
TEST_PACKAGES=(
  # tests
  python3-venv python3-pip
  # the reference engine
  cura-engine
  # end-to-end tests with the real Cura under Xvfb
  xvfb xauth python3-arcus
  # corpus fetching (apt-get download; npm comes with the base machine) and end-to-end tools
  xz-utils unzip ca-certificates
  # reliability: libFuzzer targets (tests/fuzz, clang with its sanitizer runtimes), peak RSS (tests/bench/memory.sh)
  clang libclang-rt-14-dev time
)

PACKAGES=("${ENGINE_PACKAGES[@]}")
case "${1:-}" in
  --engine) ;;
  "") PACKAGES+=("${TEST_PACKAGES[@]}") ;;
  *) echo "usage: ./install.sh [--engine]" >&2; exit 2 ;;
esac

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install.sh: all ${#PACKAGES[@]} Debian packages already installed"
  exit 0
fi

echo "install.sh: installing ${missing[*]}"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install.sh: done"
