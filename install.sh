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

# fetch_clipper_source VERSION DIR: Debian's source package libpolyclipping=VERSION, through a private apt
# configuration (the machine's own sources as deb-src, its own keyrings; nothing under /etc or /var changes),
# its clipper.cpp / clipper.hpp and licence copied into DIR, with DIR/VERSION written last.
fetch_clipper_source() (
  version="$1" dir="$2"
  work="$(mktemp -d)"
  trap 'rm -rf "$work"' EXIT
  mkdir -p "$work/parts" "$work/lists/partial" "$work/cache/archives/partial" "$work/x"
  if [ -f /etc/apt/sources.list ]; then sed -n 's/^deb /deb-src /p' /etc/apt/sources.list > "$work/sources.list"; fi
  touch "$work/sources.list"
  for f in /etc/apt/sources.list.d/*.sources; do
    [ -f "$f" ] && sed 's/^Types:.*/Types: deb-src/' "$f" > "$work/parts/$(basename "$f")"
  done
  for f in /etc/apt/sources.list.d/*.list; do
    [ -f "$f" ] && sed -n 's/^deb /deb-src /p' "$f" > "$work/parts/$(basename "$f")"
  done
  apt=(apt-get -qq -o "Dir::Etc::SourceList=$work/sources.list" -o "Dir::Etc::SourceParts=$work/parts"
             -o "Dir::State::Lists=$work/lists" -o "Dir::Cache=$work/cache" -o "APT::Sandbox::User=$(id -un)")
  "${apt[@]}" update >/dev/null || return 1
  (cd "$work" && "${apt[@]}" source --download-only "libpolyclipping=$version" >/dev/null) || return 1
  tar -xjf "$work"/libpolyclipping_*.orig.tar.* -C "$work/x" || return 1
  cpp="$(find "$work/x" -path '*/cpp/clipper.cpp' | head -n 1)"
  [ -n "$cpp" ] || return 1
  rm -rf "$dir" && mkdir -p "$dir"
  cp "$cpp" "$(dirname "$cpp")/clipper.hpp" "$dir/"
  tar -xJf "$work"/libpolyclipping_*.debian.tar.* -C "$work/x" debian/copyright && cp "$work/x/debian/copyright" "$dir/"
  echo "$version" > "$dir/VERSION"
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install.sh: all ${#PACKAGES[@]} Debian packages already installed"
else
  echo "install.sh: installing ${missing[*]}"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# Clipper's source, from Debian's own source package of the installed libpolyclipping-dev (the same version,
# checked by apt against Debian's signed index), unpacked into $MIXENGINE_DEPS/polyclipping (default
# ~/.cache/mixengine-deps). engine/CMakeLists.txt compiles it into the engine: Debian's shared build of the
# same code (position-independent, hardened, every call between its own functions through the PLT) makes a
# whole slice ~8% slower. Without it the build links the shared library, with a note.
DEPS="${MIXENGINE_DEPS:-$HOME/.cache/mixengine-deps}"
CLIPPER_VERSION="$(dpkg-query -W -f='${Version}' libpolyclipping-dev)"
if [ "$(cat "$DEPS/polyclipping/VERSION" 2>/dev/null)" = "$CLIPPER_VERSION" ]; then
  echo "install.sh: Clipper $CLIPPER_VERSION source already in $DEPS/polyclipping"
elif fetch_clipper_source "$CLIPPER_VERSION" "$DEPS/polyclipping"; then
  echo "install.sh: Clipper $CLIPPER_VERSION source in $DEPS/polyclipping"
else
  echo "install.sh: warning: Clipper's source package could not be fetched; the engine links Debian's shared build (slower)" >&2
fi
echo "install.sh: done"
