#!/usr/bin/env bash
# Creates or reuses the test virtualenv and prints the path of its python on stdout.
#   tests/python/venv.sh            -> e.g. /root/.cache/mixengine-venv/bin/python
# The venv lives in ${MIXENGINE_VENV:-$HOME/.cache/mixengine-venv}. requirements.txt is
# (re)installed only when its content changed since the last install (stamp file).
set -euo pipefail
HERE=$(cd "$(dirname "$0")" && pwd)
VENV=${MIXENGINE_VENV:-$HOME/.cache/mixengine-venv}
REQ=$HERE/requirements.txt
STAMP=$VENV/.requirements.sha256

if [ ! -x "$VENV/bin/python" ]; then
  echo "venv.sh: creating $VENV" >&2
  "${PYTHON:-python3}" -m venv "$VENV" >&2
fi
want=$(sha256sum "$REQ" | cut -d' ' -f1)
if [ "$(cat "$STAMP" 2>/dev/null)" != "$want" ]; then
  echo "venv.sh: installing $REQ" >&2
  "$VENV/bin/python" -m pip install -q --disable-pip-version-check -r "$REQ" >&2
  echo "$want" >"$STAMP"
fi
echo "$VENV/bin/python"
