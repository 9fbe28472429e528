#!/usr/bin/env python3
"""Run the real Cura 4.13 GUI under Xvfb with the CuraHarness plugin, one job at a time.

    tests/e2e/cura_driver.py tests/e2e/jobs/creality_ender3_default.json [more jobs...]
        [--out-dir tests/data/cura_slice] [--engine /path/to/engine] [--screenshot-dir DIR]
        [--timeout 180] [--keep-home] [--log-dir DIR]

Each job gets a fresh temporary HOME (fresh ~/.config/cura, ~/.local/share/cura, ~/.cache),
the plugin copied into ~/.local/share/cura/4.13/plugins/CuraHarness, and a job file the plugin
reads via $CURA_HARNESS_JOB. Cura runs as `timeout T xvfb-run -a -s "-screen 0 1600x1000x24" cura`
in its own session; the whole process group is killed at the end.
The driver itself needs only the standard library (any python3); Cura runs on /usr/bin/python3.
Exit status: 0 when every job produced its fixture, 1 otherwise.
"""
import argparse
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
PLUGIN_SRC = os.path.join(HERE, "cura_harness")
DEFAULT_OUT = os.path.normpath(os.path.join(HERE, "..", "data", "cura_slice"))
CURA_VERSION = "4.13"
XVFB_SCREEN = "-screen 0 1600x1000x24"


def make_home(engine):
    home = tempfile.mkdtemp(prefix="cura_e2e_")
    plugins = os.path.join(home, ".local", "share", "cura", CURA_VERSION, "plugins")
    shutil.copytree(PLUGIN_SRC, os.path.join(plugins, "CuraHarness"),
                    ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
    config = os.path.join(home, ".config", "cura", CURA_VERSION)
    os.makedirs(config)
    if engine:  # reference §7: cura.cfg is read after plugins load and wins over plugin defaults
        with open(os.path.join(config, "cura.cfg"), "w") as f:
            f.write("[general]\nversion = 7\n\n[metadata]\nsetting_version = 19\n\n"
                    "[backend]\nlocation = %s\n" % engine)
    os.makedirs(os.path.join(home, ".cache"))
    return home


def cura_env(home, job_path):
    env = {k: v for k, v in os.environ.items()
           if k not in ("PYTHONPATH", "PYTHONHOME", "VIRTUAL_ENV", "DISPLAY", "XAUTHORITY")
           and not k.startswith("XDG_") and not k.startswith("PYENV")}
    env.update(HOME=home, CURA_HARNESS_JOB=job_path,
               XDG_CONFIG_HOME=os.path.join(home, ".config"),
               XDG_DATA_HOME=os.path.join(home, ".local", "share"),
               XDG_CACHE_HOME=os.path.join(home, ".cache"),
               PATH="/usr/bin:/bin:/usr/sbin:/sbin:" + env.get("PATH", ""))
    return env


def kill_group(proc):
    """Stop Cura, Xvfb and the engine: they all share the session started for xvfb-run."""
    for sig, wait in ((signal.SIGTERM, 5), (signal.SIGKILL, 5)):
        try:
            os.killpg(proc.pid, sig)
        except ProcessLookupError:
            return
        try:
            proc.wait(timeout=wait)
        except subprocess.TimeoutExpired:
            pass
    try:  # children may outlive the leader
        os.killpg(proc.pid, signal.SIGKILL)
    except ProcessLookupError:
        pass


def run_job(job_file, args):
    with open(job_file) as f:
        job = json.load(f)
    name = job.get("name") or os.path.splitext(os.path.basename(job_file))[0]
    engine = args.engine or job.get("engine")
    job["output"] = os.path.abspath(job.get("output") or os.path.join(args.out_dir, name + ".json"))
    if os.path.abspath(job["output"]) == os.path.abspath(job_file):
        sys.exit("%s: the fixture would overwrite the job file; use another --out-dir" % job_file)
    home = make_home(engine)
    job["status"] = os.path.join(home, "harness_status.json")
    job["timeout"] = job.get("timeout", args.timeout - 30)
    if engine:
        job["engine"] = os.path.abspath(engine)
    if args.screenshot_dir:
        job["screenshot"] = os.path.abspath(os.path.join(args.screenshot_dir, name + ".png"))
    models = job.get("models") or []
    job["models"] = [dict(m, path=os.path.abspath(m["path"])) if isinstance(m, dict) else os.path.abspath(m)
                     for m in models] or None
    job_path = os.path.join(home, "harness_job.json")
    with open(job_path, "w") as f:
        json.dump(job, f, indent=1)
    if os.path.exists(job["output"]):
        os.remove(job["output"])

    t0 = time.time()
    log_path = os.path.join(home, "cura_stdout.log")
    with open(log_path, "w") as log:
        proc = subprocess.Popen(["timeout", str(args.timeout), "xvfb-run", "-a", "-s", XVFB_SCREEN, "cura"],
                                cwd=home, env=cura_env(home, job_path), stdout=log, stderr=subprocess.STDOUT,
                                stdin=subprocess.DEVNULL, start_new_session=True)
        try:
            rc = proc.wait(timeout=args.timeout + 10)
        except subprocess.TimeoutExpired:
            rc = "killed"
        finally:
            kill_group(proc)
    wall = time.time() - t0

    status = {}
    status_path = job["status"]
    if os.path.exists(status_path):
        with open(status_path) as f:
            status = json.load(f)
    ok = os.path.exists(job["output"])
    summary = {"job": name, "ok": ok, "cura_exit": rc, "wall_s": round(wall, 1),
               "events_s": status.get("events"), "errors": status.get("errors"),
               "backend_state": status.get("backend_state"), "output": job["output"]}
    if ok:
        with open(job["output"]) as f:
            fx = json.load(f)
        summary["counts"] = {"global": len(fx["global_settings"]), "limit_to_extruder": len(fx["limit_to_extruder"]),
                             "extruders": [len(e["settings"]) for e in fx["extruders"]],
                             "objects": [len(o["settings"]) for o in fx["objects"]]}
    if args.log_dir:
        os.makedirs(args.log_dir, exist_ok=True)
        cura_log = os.path.join(home, ".local", "share", "cura", CURA_VERSION, "cura.log")
        for src, suffix in ((cura_log, ".cura.log"), (log_path, ".stdout.log"), (status_path, ".status.json")):
            if os.path.exists(src):
                shutil.copy(src, os.path.join(args.log_dir, name + suffix))
    if args.keep_home:
        summary["home"] = home
    else:
        shutil.rmtree(home, ignore_errors=True)
    print(json.dumps(summary), flush=True)
    return ok


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("jobs", nargs="+", help="job JSON files (see tests/e2e/README.md)")
    parser.add_argument("--out-dir", default=DEFAULT_OUT, help="where <job name>.json fixtures go")
    parser.add_argument("--engine", help="engine binary for Cura (preference backend/location)")
    parser.add_argument("--screenshot-dir", help="save <job name>.png of the Xvfb screen after slicing")
    parser.add_argument("--timeout", type=int, default=180, help="hard limit per Cura run, seconds")
    parser.add_argument("--keep-home", action="store_true", help="keep the temporary HOME for inspection")
    parser.add_argument("--log-dir", help="copy cura.log / stdout / harness status here")
    args = parser.parse_args()
    if not shutil.which("xvfb-run") or not os.path.exists("/usr/bin/cura"):
        sys.exit("need /usr/bin/cura and xvfb-run (apt-get install cura xvfb xauth)")
    results = [run_job(j, args) for j in args.jobs]
    sys.exit(0 if all(results) else 1)


if __name__ == "__main__":
    main()
