#!/usr/bin/env bash
# Record Cura 4.13 Slice-message fixtures (or run the end-to-end harness against another engine).
#   tests/e2e/run_cura.sh                          # every job in tests/e2e/jobs -> tests/data/cura_slice/
#   tests/e2e/run_cura.sh jobs/creality_ender3_user.json --out-dir /tmp/out --engine build/mixengine
# Extra arguments are passed to cura_driver.py (see --help). Needs: cura, xvfb, xauth (Debian).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
cd "$here"
jobs=()
while [ $# -gt 0 ] && [[ "$1" == *.json ]]; do jobs+=("$1"); shift; done
if [ ${#jobs[@]} -eq 0 ]; then jobs=(jobs/*.json); fi
# The driver needs only the standard library; Cura itself always runs on /usr/bin/python3.
exec /usr/bin/python3 "$here/cura_driver.py" "${jobs[@]}" "$@"
