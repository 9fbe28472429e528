#!/usr/bin/env python3
"""Run the real Cura 4.13 GUI under Xvfb with the CuraHarness plugin, one job at a time.

    tests/e2e/cura_driver.py tests/e2e/jobs/creality_ender3_default.json [more jobs...]
        [--out-dir tests/data/cura_slice] [--engine /path/to/engine] [--screenshot-dir DIR]
        [--timeout 180] [--keep-home] [--log-dir DIR]
        [--plugin-package MixEngine-x.y.z.curapackage] [--env KEY=VALUE ...]

Each job gets a fresh temporary HOME (fresh ~/.config/cura, ~/.local/share/cura, ~/.cache),
the plugin copied into ~/.local/share/cura/4.13/plugins/CuraHarness, and a job file the plugin
reads via $CURA_HARNESS_JOB. --plugin-package installs a .curapackage into that HOME first with
plugin/install.py (the documented install command). Cura runs as `timeout T xvfb-run -a -s "-screen 0 1600x1000x24" cura`
in its own session; the whole process group is killed at the end.
The driver itself needs only the standard library (any python3); Cura runs on /usr/bin/python3.
Exit status: 0 when every job produced its fixture, 1 otherwise.
"""
import argparse
import configparser
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import zipfile

HERE = os.path.dirname(os.path.abspath(__file__))
INSTALLER = os.path.normpath(os.path.join(HERE, "..", "..", "plugin", "install.py"))
PLUGIN_SRC = os.path.join(HERE, "cura_harness")
DEFAULT_OUT = os.path.normpath(os.path.join(HERE, "..", "data", "cura_slice"))
CURA_VERSION = "4.13"
XVFB_SCREEN = "-screen 0 1600x1000x24"


def schedule_package(home, package):
    """What dropping a .curapackage on Cura does (UM/PackageManager.installPackage): a copy in the cache and a
    "to_install" entry in packages.json; Cura installs it at its next start, before loading plugins."""
    cache = os.path.join(home, ".cache", "cura", CURA_VERSION, "cura_packages")
    os.makedirs(cache, exist_ok=True)
    with zipfile.ZipFile(package) as archive:
        info = json.loads(archive.read("package.json"))
    target = os.path.join(cache, info["package_id"] + ".curapackage")
    shutil.copy(package, target)
    info.update(is_active=True, is_bundled=False, is_installed=False)
    data = os.path.join(home, ".local", "share", "cura", CURA_VERSION)
    os.makedirs(data, exist_ok=True)
    with open(os.path.join(data, "packages.json"), "w") as f:
        json.dump({"version": 1, "installed": {}, "to_remove": [], "dismissed": [],
                   "to_install": {info["package_id"]: {"package_info": info, "filename": target}}}, f)


def make_home(engine, package=None, cfg_location=None, cfg_values=(), via_cura=False):
    home = tempfile.mkdtemp(prefix="cura_e2e_")
    if package and via_cura:
        schedule_package(home, os.path.abspath(package))
    elif package:
        subprocess.run([sys.executable, INSTALLER, os.path.abspath(package), "--home", home], check=True,
                       stdout=subprocess.DEVNULL)
    plugins = os.path.join(home, ".local", "share", "cura", CURA_VERSION, "plugins")
    shutil.copytree(PLUGIN_SRC, os.path.join(plugins, "CuraHarness"),
                    ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
    config = os.path.join(home, ".config", "cura", CURA_VERSION)
    os.makedirs(config)
    cfg = configparser.ConfigParser(interpolation=None)
    cfg.read_dict({"general": {"version": "7"}, "metadata": {"setting_version": "19"}})
    engine = engine or cfg_location
    if engine:  # reference §7: cura.cfg is read after plugins load and wins over plugin defaults
        cfg.read_dict({"backend": {"location": engine}})
    for item in cfg_values:  # e.g. view/settings_visible=True
        key, value = item.split("=", 1)
        section, name = key.split("/", 1)
        cfg.read_dict({section: {name: value}})
    if engine or cfg_values:
        with open(os.path.join(config, "cura.cfg"), "w") as f:
            cfg.write(f)
    os.makedirs(os.path.join(home, ".cache"), exist_ok=True)
    return home


def cfg_backend_location(home):
    """[backend] location in cura.cfg after Cura exited (None: not set, Cura's default)."""
    cfg = configparser.ConfigParser(interpolation=None)
    cfg.read(os.path.join(home, ".config", "cura", CURA_VERSION, "cura.cfg"), encoding="utf-8")
    return cfg.get("backend", "location", fallback=None)


def cura_env(home, job_path, extra=()):
    env = {k: v for k, v in os.environ.items()
           if k not in ("PYTHONPATH", "PYTHONHOME", "VIRTUAL_ENV", "DISPLAY", "XAUTHORITY")
           and not k.startswith("XDG_") and not k.startswith("PYENV")}
    env.update(HOME=home, CURA_HARNESS_JOB=job_path,
               XDG_CONFIG_HOME=os.path.join(home, ".config"),
               XDG_DATA_HOME=os.path.join(home, ".local", "share"),
               XDG_CACHE_HOME=os.path.join(home, ".cache"),
               PATH="/usr/bin:/bin:/usr/sbin:/sbin:" + env.get("PATH", ""))
    env.update(kv.split("=", 1) for kv in extra)
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
    home = make_home(engine, args.plugin_package, args.cfg_backend, args.cfg, args.via_cura)
    job["status"] = os.path.join(home, "harness_status.json")
    job["timeout"] = job.get("timeout", args.timeout - 30)
    if engine:
        job["engine"] = os.path.abspath(engine)
    if args.screenshot_dir:
        job["screenshot"] = os.path.abspath(os.path.join(args.screenshot_dir, name + ".png"))
    for key in ("screenshot", "gcode_output"):
        if job.get(key):
            job[key] = os.path.abspath(job[key])
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
                                cwd=home, env=cura_env(home, job_path, args.env), stdout=log, stderr=subprocess.STDOUT,
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
    sliced = job.get("slice", True)
    ok = os.path.exists(job["output"]) if sliced else status.get("finish_reason") == "done"
    summary = {"job": name, "ok": ok, "cura_exit": rc, "wall_s": round(wall, 1),
               "events_s": status.get("events"), "errors": status.get("errors"),
               "backend_state": status.get("backend_state"), "output": job["output"] if sliced else None,
               "cfg_backend_location": cfg_backend_location(home)}
    if ok and sliced:
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
    parser.add_argument("--plugin-package", help="install this .curapackage into the temporary HOME "
                        "(plugin/install.py --home)")
    parser.add_argument("--via-cura", action="store_true", help="let Cura install --plugin-package at its start, "
                        "as after dropping the file on its window (instead of plugin/install.py)")
    parser.add_argument("--cfg-backend", metavar="PATH", help="only write [backend] location = PATH into cura.cfg "
                        "(the location a user had before installing a plugin that changes it); the harness leaves it alone")
    parser.add_argument("--cfg", action="append", default=[], metavar="SECTION/KEY=VALUE",
                        help="extra cura.cfg preference (repeatable), e.g. view/settings_visible=True")
    parser.add_argument("--env", action="append", default=[], metavar="KEY=VALUE",
                        help="extra environment variable for Cura (repeatable), e.g. MIXENGINE_ENGINE=/usr/bin/CuraEngine")
    args = parser.parse_args()
    if not shutil.which("xvfb-run") or not os.path.exists("/usr/bin/cura"):
        sys.exit("need /usr/bin/cura and xvfb-run (apt-get install cura xvfb xauth)")
    results = [run_job(j, args) for j in args.jobs]
    sys.exit(0 if all(results) else 1)


if __name__ == "__main__":
    main()
