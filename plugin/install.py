#!/usr/bin/env python3
"""Install the MixEngine .curapackage into Cura 4.13's user folder, or remove it again.

    python3 plugin/install.py [PACKAGE.curapackage] [--home DIR]   # default: newest build/MixEngine-*.curapackage
    python3 plugin/install.py --uninstall [--home DIR]

Install does what Cura's own package installer does at its next start (UM/PackageManager.py), at
once: files/plugins/* of the package go to <data>/plugins/MixEngine/ (so plugin.json ends up in
<data>/plugins/MixEngine/MixEngine/), and the package is recorded as installed in
<data>/packages.json, so Cura's Marketplace lists it and can uninstall it. <data> is
$XDG_DATA_HOME/cura/4.13 (default ~/.local/share/cura/4.13). Unlike Cura's installer it keeps the
executable bit of the bundled mixengine binary. Restart Cura afterwards.

--uninstall removes the folder and the packages.json entry and, if cura.cfg
($XDG_CONFIG_HOME/cura/4.13/cura.cfg) still names a mixengine binary as [backend] location (Cura
was killed while the plugin was active), puts back the location the plugin recorded as previous
([mixengine] previous_backend_location), or removes the key so Cura uses its own CuraEngine.
Run it while Cura is closed. Standard library only.
"""
import argparse
import configparser
import glob
import json
import os
import shutil
import sys
import tempfile
import zipfile

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
PACKAGE_ID = "MixEngine"
CURA_VERSION = "4.13"


def curaDirs(home=None):
    """(data dir, config dir) of Cura 4.13 for this user (or for the HOME given)."""
    if home:
        data_root, config_root = os.path.join(home, ".local", "share"), os.path.join(home, ".config")
    else:
        data_root = os.environ.get("XDG_DATA_HOME") or os.path.expanduser("~/.local/share")
        config_root = os.environ.get("XDG_CONFIG_HOME") or os.path.expanduser("~/.config")
    return os.path.join(data_root, "cura", CURA_VERSION), os.path.join(config_root, "cura", CURA_VERSION)


def newestPackage():
    found = sorted(glob.glob(os.path.join(REPO, "build", PACKAGE_ID + "-*.curapackage")), key=os.path.getmtime)
    if not found:
        raise SystemExit("install.py: no build/%s-*.curapackage; run `make plugin` first" % PACKAGE_ID)
    return found[-1]


def readPackageInfo(archive):
    info = json.loads(archive.read("package.json").decode("utf-8"))
    if info.get("package_id") != PACKAGE_ID or info.get("package_type") != "plugin":
        raise SystemExit("install.py: not a MixEngine plugin package (package.json: %s)" % info.get("package_id"))
    return info


def extract(archive, destination):
    """Extract files/plugins/* into destination, keeping the executable bits."""
    prefix = "files/plugins/"
    for member in archive.infolist():
        if not member.filename.startswith(prefix) or member.is_dir():
            continue
        relative = member.filename[len(prefix):]
        target = os.path.normpath(os.path.join(destination, relative))
        if not target.startswith(os.path.normpath(destination) + os.sep):
            raise SystemExit("install.py: unsafe path in package: %s" % member.filename)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        with archive.open(member) as src, open(target, "wb") as dst:
            shutil.copyfileobj(src, dst)
        mode = (member.external_attr >> 16) & 0o777
        os.chmod(target, mode or 0o644)


def updatePackagesJson(data_dir, package_info):
    path = os.path.join(data_dir, "packages.json")
    management = {"version": 1, "installed": {}, "to_remove": [], "to_install": {}, "dismissed": []}
    if os.path.exists(path):
        with open(path, encoding="utf-8") as f:
            management.update(json.load(f))
    installed = management.setdefault("installed", {})
    if package_info is None:
        installed.pop(PACKAGE_ID, None)
    else:
        info = dict(package_info, is_active=True, is_bundled=False, is_installed=True)
        installed[PACKAGE_ID] = {"package_info": info, "filename": ""}
    management["to_install"].pop(PACKAGE_ID, None)
    management["to_remove"] = [p for p in management.get("to_remove", []) if p != PACKAGE_ID]
    os.makedirs(data_dir, exist_ok=True)
    with open(path + ".tmp", "w", encoding="utf-8") as f:
        json.dump(management, f, sort_keys=True, indent=4)
    os.replace(path + ".tmp", path)


def install(package, home=None):
    data_dir, _ = curaDirs(home)
    plugin_root = os.path.join(data_dir, "plugins", PACKAGE_ID)
    with zipfile.ZipFile(package) as archive:
        info = readPackageInfo(archive)
        os.makedirs(os.path.dirname(plugin_root), exist_ok=True)
        staging = tempfile.mkdtemp(prefix=".mixengine_install_", dir=os.path.dirname(plugin_root))
        try:
            extract(archive, staging)
            if not os.path.isfile(os.path.join(staging, PACKAGE_ID, "plugin.json")):
                raise SystemExit("install.py: %s has no files/plugins/%s/plugin.json" % (package, PACKAGE_ID))
            shutil.rmtree(plugin_root, ignore_errors=True)
            os.rename(staging, plugin_root)
        finally:
            shutil.rmtree(staging, ignore_errors=True)
    updatePackagesJson(data_dir, info)
    return os.path.join(plugin_root, PACKAGE_ID), info["package_version"]


def restoreBackendLocation(config_dir):
    """Returns a description of what was done to cura.cfg."""
    path = os.path.join(config_dir, "cura.cfg")
    if not os.path.exists(path):
        return "no cura.cfg"
    cfg = configparser.ConfigParser(interpolation=None)
    cfg.read(path, encoding="utf-8")
    location = cfg.get("backend", "location", fallback="")
    if not os.path.basename(location).startswith("mixengine"):
        return "backend/location is %s: left alone" % (location or "Cura's default")
    previous = cfg.get("mixengine", "previous_backend_location", fallback="")
    if previous and not os.path.basename(previous).startswith("mixengine"):
        cfg.set("backend", "location", previous)
        done = "backend/location %s -> %s" % (location, previous)
    else:
        cfg.remove_option("backend", "location")
        done = "backend/location %s removed (Cura uses its own CuraEngine)" % location
    with open(path + ".tmp", "w", encoding="utf-8") as f:
        cfg.write(f)
    os.replace(path + ".tmp", path)
    return done


def uninstall(home=None):
    data_dir, config_dir = curaDirs(home)
    plugin_root = os.path.join(data_dir, "plugins", PACKAGE_ID)
    removed = os.path.isdir(plugin_root)
    shutil.rmtree(plugin_root, ignore_errors=True)
    if os.path.exists(os.path.join(data_dir, "packages.json")):
        updatePackagesJson(data_dir, None)
    return removed, restoreBackendLocation(config_dir)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("package", nargs="?", help="the .curapackage (default: newest in build/)")
    parser.add_argument("--home", help="install for this HOME instead of the current user's folders")
    parser.add_argument("--uninstall", action="store_true", help="remove the plugin and restore backend/location")
    args = parser.parse_args()
    if args.uninstall:
        removed, backend = uninstall(args.home)
        print("MixEngine plugin %s; %s" % ("removed" if removed else "was not installed", backend))
        return
    folder, version = install(args.package or newestPackage(), args.home)
    print("MixEngine %s installed in %s; restart Cura" % (version, folder))


if __name__ == "__main__":
    sys.exit(main())
