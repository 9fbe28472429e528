"""Test-side access to Cura's socket protocol: runs tests/python/cura_frontend.py (the real libArcus
through Debian's python3-arcus, with Cura's installed Cura.proto) against the engine, with the
settings Cura would send for a given machine and user values."""
import json
import os
import subprocess
from pathlib import Path

import helpers

FRONTEND = Path(__file__).resolve().parent / "cura_frontend.py"
DEBIAN_PYTHON = "/usr/bin/python3"


def debian_python_env():
    """Cura's Python environment: Debian's interpreter without the venv's variables."""
    env = {k: v for k, v in os.environ.items()
           if k not in ("PYTHONPATH", "PYTHONHOME", "VIRTUAL_ENV") and not k.startswith("PYENV")}
    return env


def resolved_settings(definition, *settings, extruder_settings=()):
    """What Cura sends for `definition` with user values `settings` ("key=value"): every global key
    and every key of each extruder train, evaluated (`mixengine settings --json`)."""
    args = ["settings", "-j", definition, "--json"]
    for s in settings:
        args += ["-s", s]
    for nr, values in extruder_settings:
        args.append(f"-e{nr}")
        for s in values:
            args += ["-s", s]
    proc = helpers.mixengine(*args)
    assert proc.returncode == 0, proc.stderr
    data = json.loads(proc.stdout)
    return data["global"], {str(i): values for i, values in enumerate(data["extruders"])}


def slice_over_socket(engine, tmp_path, global_settings, extruders, groups, timeout=300, **job_fields):
    """Runs one slice through the socket; returns the frontend's result dict (see cura_frontend.py)."""
    job = {"engine": str(engine), "global": global_settings, "extruders": extruders, "groups": groups,
           "timeout": timeout, **job_fields}
    job_file, result_file = tmp_path / "job.json", tmp_path / "result.json"
    job_file.write_text(json.dumps(job))
    proc = subprocess.run([DEBIAN_PYTHON, str(FRONTEND), str(job_file), str(result_file)], capture_output=True,
                          text=True, timeout=timeout + 60, env=debian_python_env())
    assert proc.returncode == 0, f"frontend failed: {proc.stderr[-2000:]}"
    return json.loads(result_file.read_text())


def one_object(path, name=None, **settings):
    """A mesh group holding one model, as Cura sends it (extruder_nr always present)."""
    values = {"extruder_nr": "0", **{k: str(v) for k, v in settings.items()}}
    return {"settings": {}, "objects": [{"name": name or str(path), "stl": str(path), "settings": values}]}
