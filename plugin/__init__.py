# MixEngine plugin for Cura 4.13 (SDK 7.9.0). See README.md in this folder.
import os

from UM.Logger import Logger
from UM.Resources import Resources

from . import PluginPaths
from .MixEngineExtension import MixEngineExtension


def getMetaData():
    return {}


def register(app):
    settings_dir = PluginPaths.settingsDir()
    if settings_dir:
        # Runs before Cura loads any definition, so the printers in settings/definitions and their
        # extruder trains in settings/extruders are found like Cura's own.
        Resources.addSearchPath(settings_dir)
        Logger.log("i", "[MixEngine] resource search path %s (definitions: %s)", settings_dir,
                   ", ".join(sorted(os.listdir(os.path.join(settings_dir, "definitions"))))
                   if os.path.isdir(os.path.join(settings_dir, "definitions")) else "none")
    return {"extension": MixEngineExtension(app, settings_dir)}
