"""Where the plugin finds its files: the settings folder and the mixengine binary.

No Cura imports here, so the rules can be unit-tested outside Cura.

Settings folder (MixEngine's setting fragments in mixengine/, printers in definitions/ and extruders/):
  1. <plugin>/settings            - the installed package (package.py copies the repo's settings/ there)
  2. <plugin>/../settings         - running straight from a checkout (plugin/ next to settings/)

Engine binary, first hit wins:
  1. $MIXENGINE_ENGINE            - override for tests and development (e.g. /usr/bin/CuraEngine)
  2. preference mixengine/engine_path, when not empty
  3. <plugin>/mixengine           - the binary shipped inside the .curapackage
  4. <plugin>/../build/mixengine  - a checkout's build
  5. `mixengine` on $PATH
"""
import os
import shutil
import stat

ENGINE_ENV = "MIXENGINE_ENGINE"
ENGINE_NAME = "mixengine"


def pluginDir():
    """The plugin's folder, symlinks resolved (a checkout's plugin/ linked into Cura's plugin folder
    then still finds ../settings and ../build)."""
    return os.path.dirname(os.path.realpath(__file__))


def settingsDir(plugin_dir=None):
    """The folder holding mixengine/, definitions/ and extruders/, or None."""
    plugin_dir = plugin_dir or pluginDir()
    for candidate in (os.path.join(plugin_dir, "settings"), os.path.join(plugin_dir, os.pardir, "settings")):
        if os.path.isdir(os.path.join(candidate, "mixengine")):
            return os.path.normpath(candidate)
    return None


def fragmentFiles(settings_dir):
    """MixEngine's setting fragments (settings/mixengine/*.def.json), sorted by name."""
    folder = os.path.join(settings_dir, "mixengine")
    return [os.path.join(folder, name) for name in sorted(os.listdir(folder)) if name.endswith(".def.json")]


def ensureExecutable(path):
    """Cura's own package installer extracts with zipfile, which drops the executable bit."""
    mode = os.stat(path).st_mode
    if not mode & stat.S_IXUSR:
        os.chmod(path, mode | stat.S_IXUSR | stat.S_IXGRP | stat.S_IXOTH)


def findEngine(preference_value="", plugin_dir=None, environ=None, mixengine_only=False):
    """(path, how) of the engine to use, or (None, reason) when there is none.

    An explicit choice (environment or preference) must exist; it is never silently replaced by
    another binary. mixengine_only (for `mixengine orient`) passes over an explicit choice of
    another engine, such as CuraEngine used for testing the slicing path."""
    environ = os.environ if environ is None else environ
    plugin_dir = plugin_dir or pluginDir()
    for value, how in ((environ.get(ENGINE_ENV, ""), "$" + ENGINE_ENV), (preference_value or "", "preference")):
        if value and mixengine_only and not os.path.basename(value).startswith(ENGINE_NAME):
            continue
        if value:
            path = os.path.abspath(os.path.expanduser(value))
            if os.path.isfile(path):
                return path, how
            return None, "%s names %s, which does not exist" % (how, path)
    bundled = os.path.join(plugin_dir, ENGINE_NAME)
    if os.path.isfile(bundled):
        ensureExecutable(bundled)
        return bundled, "bundled"
    checkout = os.path.normpath(os.path.join(plugin_dir, os.pardir, "build", ENGINE_NAME))
    if os.path.isfile(checkout) and os.access(checkout, os.X_OK):
        return checkout, "checkout build"
    on_path = shutil.which(ENGINE_NAME)
    if on_path:
        return os.path.abspath(on_path), "PATH"
    return None, "no mixengine binary next to the plugin, in ../build or on PATH"
