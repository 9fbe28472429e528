#!/usr/bin/env bash
# Peak memory of MixEngine and of Debian's CuraEngine 4.13 slicing the same 2-million-triangle model with the
# same arguments (the machine and settings of tests/bench/bench_slice.py), measured by /usr/bin/time -v
# ("Maximum resident set size"); prints both, their wall times and the ratio MixEngine / CuraEngine.
#   tests/bench/memory.sh BUILD_DIR [CELLS]
# The model (tests/bench/dense_model.py, CELLS x CELLS heightfield cells, default 1000: 2,012,000 triangles,
# 100 MB) is generated once into ${MIXENGINE_BENCH_CACHE:-~/.cache/mixengine-bench}; it is not committed.
set -euo pipefail
HERE=$(cd "$(dirname "$0")" && pwd)
BUILD=$(cd "${1:?usage: tests/bench/memory.sh BUILD_DIR [CELLS]}" && pwd)
CELLS=${2:-1000}
CACHE=${MIXENGINE_BENCH_CACHE:-$HOME/.cache/mixengine-bench}
MODEL=$CACHE/dense_${CELLS}.stl
PY=$("$HERE/../python/venv.sh")
[ -x /usr/bin/time ] || { echo "memory.sh: /usr/bin/time missing (Debian package 'time', see install.sh)" >&2; exit 1; }
[ -f "$MODEL" ] || "$PY" "$HERE/dense_model.py" "$MODEL" --cells "$CELLS"

DEFS=/usr/share/cura/resources/definitions
export CURA_ENGINE_SEARCH_PATH=$DEFS:/usr/share/cura/resources/extruders
ARGS=(slice -j "$DEFS/creality_ender3.def.json" -s center_object=true -s layer_height=0.2 -s layer_height_0=0.2
      -s wall_line_count=2 -s infill_sparse_density=20 -s top_layers=4 -s bottom_layers=4
      -s material_print_temperature=210 -s material_bed_temperature=60 -s adhesion_type=skirt -l "$MODEL")
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT

measure() { # NAME BINARY: runs one slice under /usr/bin/time -v; prints "rss_kib wall_s layers"
  local name=$1 bin=$2 rc=0
  /usr/bin/time -v -o "$TMP/$name.time" "$bin" "${ARGS[@]}" -o "$TMP/$name.gcode" >"$TMP/$name.log" 2>&1 || rc=$?
  if [ "$rc" -ne 0 ]; then
    echo "memory.sh: $name failed (exit $rc):" >&2
    tail -5 "$TMP/$name.log" >&2
    exit 1
  fi
  local rss wall layers
  rss=$(awk -F': ' '/Maximum resident set size/ {print $2}' "$TMP/$name.time")
  wall=$(awk -F': ' '/Elapsed \(wall clock\)/ {print $2}' "$TMP/$name.time")
  layers=$(grep -m1 '^;LAYER_COUNT:' "$TMP/$name.gcode" | cut -d: -f2)
  echo "$rss $wall $layers"
}

tris=$("$PY" -c "import struct,sys; print(struct.unpack_from('<I', open(sys.argv[1],'rb').read(84), 80)[0])" "$MODEL")
echo "model $(basename "$MODEL"): $tris triangles, $(du -m "$MODEL" | cut -f1) MB; machine creality_ender3, 0.2 mm layers"
read -r cura_rss cura_wall cura_layers < <(measure CuraEngine /usr/bin/CuraEngine)
read -r me_rss me_wall me_layers < <(measure mixengine "$BUILD/mixengine")
printf '%-12s %12s %10s %7s\n' engine "peak RSS MiB" "wall" layers
printf '%-12s %12d %10s %7s\n' CuraEngine $((cura_rss / 1024)) "$cura_wall" "$cura_layers"
printf '%-12s %12d %10s %7s\n' mixengine $((me_rss / 1024)) "$me_wall" "$me_layers"
awk -v a="$me_rss" -v b="$cura_rss" 'BEGIN { printf "peak RSS ratio mixengine / CuraEngine: %.2f\n", a / b }'
