#!/usr/bin/env python3
"""Build MixEngine-<version>.curapackage, the Cura 4.13 package of the MixEngine plugin.

    python3 plugin/package.py [--engine build/mixengine | --no-engine] [--out build] [--no-strip]

The package is a zip file as Cura's Marketplace and drag-and-drop installer expect it:
    package.json                              package_id MixEngine, package_type plugin, sdk_version 7.9.0
    files/plugins/MixEngine/plugin.json       the plugin (api 7, supported_sdk_versions ["7.9.0"])
    files/plugins/MixEngine/*.py, README.md
    files/plugins/MixEngine/qml/*.qml         the mix legend over the Preview
    files/plugins/MixEngine/settings/...      a copy of the repository's settings/ folder (setting
                                              fragments, printer and extruder definitions)
    files/plugins/MixEngine/mixengine         the engine binary (debug symbols stripped), unless --no-engine
The version is plugin.json's. The zip is reproducible (fixed dates, sorted names). Standard library only.
Prints the path of the package.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import zipfile

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
PACKAGE_ID = "MixEngine"
SDK_VERSION = "7.9.0"
PLUGIN_FILES = ("plugin.json", "README.md")
NOT_SHIPPED = ("package.py", "install.py")  # tools, not part of the plugin
ZIP_DATE = (2024, 1, 1, 0, 0, 0)


def pluginMetadata():
    with open(os.path.join(HERE, "plugin.json"), encoding="utf-8") as f:
        return json.load(f)


def packageJson(meta):
    return {
        "package_id": PACKAGE_ID,
        "package_type": "plugin",
        "display_name": meta["name"],
        "description": meta["description"],
        "package_version": meta["version"],
        "sdk_version": SDK_VERSION,
        "sdk_version_semver": SDK_VERSION,
        "author": {"author_id": "MixEngine", "display_name": meta["author"]},
        "tags": ["slicing", "mixing", "dual extrusion"],
    }


def pluginSources():
    """(archive name, path) of the plugin's own files."""
    names = sorted(n for n in os.listdir(HERE) if n.endswith(".py") and n not in NOT_SHIPPED)
    names += [n for n in PLUGIN_FILES if os.path.isfile(os.path.join(HERE, n))]
    qml = os.path.join(HERE, "qml")
    if os.path.isdir(qml):
        names += ["qml/" + n for n in sorted(os.listdir(qml)) if n.endswith(".qml")]
    return [(n, os.path.join(HERE, *n.split("/"))) for n in names]


def settingsSources(settings_dir):
    files = []
    for root, dirs, names in os.walk(settings_dir):
        dirs.sort()
        for name in sorted(names):
            if name.endswith(".json"):
                path = os.path.join(root, name)
                files.append((os.path.join("settings", os.path.relpath(path, settings_dir)), path))
    return files


def strippedEngine(engine, workdir, strip):
    if not strip or not shutil.which("strip"):
        return engine
    out = os.path.join(workdir, "mixengine")
    subprocess.run(["strip", "--strip-debug", "-o", out, engine], check=True)
    return out


def addFile(archive, name, path=None, data=None, executable=False):
    info = zipfile.ZipInfo(name, date_time=ZIP_DATE)
    info.compress_type = zipfile.ZIP_DEFLATED
    info.external_attr = (0o100755 if executable else 0o100644) << 16
    if data is None:
        with open(path, "rb") as f:
            data = f.read()
    archive.writestr(info, data)


def build(out_dir, engine=None, strip=True, settings_dir=None):
    meta = pluginMetadata()
    settings_dir = settings_dir or os.path.join(REPO, "settings")
    if not os.path.isdir(os.path.join(settings_dir, "mixengine")):
        raise SystemExit("package.py: %s has no mixengine/ setting fragments" % settings_dir)
    os.makedirs(out_dir, exist_ok=True)
    target = os.path.join(out_dir, "%s-%s.curapackage" % (PACKAGE_ID, meta["version"]))
    root = "files/plugins/%s/" % PACKAGE_ID
    with tempfile.TemporaryDirectory() as workdir:
        partial = os.path.join(workdir, "package.zip")
        with zipfile.ZipFile(partial, "w") as archive:
            addFile(archive, "package.json", data=json.dumps(packageJson(meta), indent=4) + "\n")
            for name, path in pluginSources() + settingsSources(settings_dir):
                addFile(archive, root + name, path)
            if engine:
                if not (os.path.isfile(engine) and os.access(engine, os.X_OK)):
                    raise SystemExit("package.py: engine %s is not an executable file (build it first)" % engine)
                addFile(archive, root + "mixengine", strippedEngine(engine, workdir, strip), executable=True)
        shutil.move(partial, target)
    return target


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    group = parser.add_mutually_exclusive_group()
    group.add_argument("--engine", help="mixengine binary to ship (default: build/mixengine if it exists)")
    group.add_argument("--no-engine", action="store_true", help="ship no binary (the plugin then looks on PATH)")
    parser.add_argument("--out", default=os.path.join(REPO, "build"), help="output folder (default: build/)")
    parser.add_argument("--settings", help="settings folder to copy (default: the repository's settings/)")
    parser.add_argument("--no-strip", action="store_true", help="keep the binary's debug information")
    args = parser.parse_args()
    engine = None
    if not args.no_engine:
        engine = args.engine or os.path.join(REPO, "build", "mixengine")
        if not args.engine and not os.path.isfile(engine):
            print("package.py: no %s; packaging without an engine binary" % engine, file=sys.stderr)
            engine = None
    print(build(os.path.abspath(args.out), engine, strip=not args.no_strip, settings_dir=args.settings))


if __name__ == "__main__":
    main()
