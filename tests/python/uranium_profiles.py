"""Loads MixEngine's printer profiles in the real Uranium 4.13 that Cura 4.13 runs on (Debian's
python3-uranium and uranium-plugins), the way Cura finds them: a temporary resource folder laid out as
definitions/ + extruders/ next to /usr/share/cura/resources, Uranium's ContainerRegistry with the
LocalContainerProvider plugin loaded through the PluginRegistry, all metadata indexed, then each definition
and extruder train loaded (deserialised with its whole `inherits` chain) by id.

Run it with the system interpreter, not the test venv (test_printer_profiles.py does so):
    /usr/bin/python3 uranium_profiles.py RESOURCE_DIR ID [ID ...]
RESOURCE_DIR holds definitions/*.def.json and extruders/*.def.json. Prints one JSON object:
    {"definitions": {id: {"metadata": {...}, "values": {key: default_value}, "relative_extrusion": bool,
                          "override_warnings": [keys], "class": "...", "inherited_files": [paths]}},
     "registry_metadata": {id: the registry's metadata, inherited entries included},
     "is_definition_class": bool, "errors": [log lines of type e/c], "warnings": [all w lines]}
A definition that fails to load is missing from "definitions" and its exception is in "errors".
HOME and the XDG folders must point at a scratch directory: Uranium writes its cache and database there.
"""
import json
import os
import sys

from cura.CuraApplication import CuraApplication
from UM.Application import Application
from UM.Logger import Logger
from UM.MimeTypeDatabase import MimeType, MimeTypeDatabase
from UM.PluginRegistry import PluginRegistry
from UM.Preferences import Preferences
from UM.Resources import Resources
from UM.Settings.ContainerRegistry import ContainerRegistry
from UM.Settings.ContainerStack import ContainerStack
from UM.Settings.DefinitionContainer import DefinitionContainer
from UM.VersionUpgradeManager import VersionUpgradeManager

CURA_RESOURCES = "/usr/share/cura/resources"
URANIUM_PLUGINS = "/usr/lib/uranium/plugins"
DEFINITION_MIME = "application/x-uranium-definitioncontainer"
EXTRUDER_RESOURCE = CuraApplication.ResourceTypes.ExtruderStack  # Cura's "extruders" storage type
KEYS = ["machine_name", "machine_gcode_flavor", "machine_extruder_count", "machine_width", "machine_depth",
        "machine_height", "machine_heated_bed", "machine_start_gcode", "machine_end_gcode", "prime_tower_enable",
        "machine_use_extruder_offset_to_offset_coords", "extruder_nr", "machine_nozzle_size", "material_diameter",
        "machine_nozzle_offset_x", "machine_nozzle_offset_y", "machine_extruder_start_code",
        "machine_extruder_end_code"]


class HeadlessApp(Application):
    """Uranium's non-Qt Application base, enough for the registries (no event loop, no Qt window)."""

    def __init__(self):
        super().__init__(name="cura", version="4.13.0", api_version="7.9.0")
        self._preferences = Preferences()
        self._preferences.addPreference("general/disabled_plugins", "")
        self._preferences.addPreference("general/plugins_to_remove", "")

    def processEvents(self):
        pass

    def callLater(self, func, *args, **kwargs):
        func(*args, **kwargs)


class Capture:
    """A Uranium log output that keeps every line."""

    def __init__(self):
        self.lines = []

    def log(self, log_type, message):
        self.lines.append((log_type, message))


def registry_for(resource_dir):
    app = HeadlessApp()
    CuraApplication._initializeSettingDefinitions()  # Cura's extra setting properties (settable_per_*, resolve, ...)
    Resources.ApplicationIdentifier = "cura"
    Resources.ApplicationVersion = "4.13.0"
    Resources.addSearchPath(CURA_RESOURCES)
    Resources.addSearchPath(resource_dir)
    Resources.addStorageType(EXTRUDER_RESOURCE, "extruders")
    MimeTypeDatabase.addMimeType(MimeType(name=DEFINITION_MIME,
                                          comment="Uranium Definition Container", suffixes=["def.json"]))
    # Definition files of version 2 are current, as CuraApplication declares them: no upgrade step runs.
    upgrades = VersionUpgradeManager(app)
    upgrades.setCurrentVersions({
        ("machine", DefinitionContainer.Version): (Resources.DefinitionContainers, DEFINITION_MIME),
        ("extruder", DefinitionContainer.Version): (Resources.DefinitionContainers, DEFINITION_MIME)})
    registry = ContainerRegistry(app)
    registry.addResourceType(EXTRUDER_RESOURCE, "extruder_train")
    plugins = PluginRegistry(app)
    plugins.addPluginLocation(URANIUM_PLUGINS)
    os.makedirs(Resources.getConfigStoragePath(), exist_ok=True)  # Cura makes it at start-up
    plugins.initializeBeforePluginsAreLoaded()
    plugins.loadPlugin("LocalContainerProvider")
    registry.loadAllMetadata()
    return registry


def plain(value):
    """JSON-able form of a property value (SettingFunction and friends as their text)."""
    if value is None or isinstance(value, (bool, int, float, str)):
        return value
    if isinstance(value, (list, tuple)):
        return [plain(v) for v in value]
    if isinstance(value, dict):
        return {str(k): plain(v) for k, v in value.items()}
    return str(value)


def describe(registry, container_id, capture):
    before = len(capture.lines)
    found = registry.findDefinitionContainers(id=container_id)
    new_lines = capture.lines[before:]
    if not found:
        return None
    definition = found[0]
    warnings = [m for t, m in new_lines if t == "w"]
    overridden = [m.split("Unable to override setting ", 1)[1].strip() for m in warnings
                  if "Unable to override setting " in m]
    values = {k: plain(definition.getProperty(k, "default_value")) for k in KEYS
              if definition.getProperty(k, "type") is not None}
    out = {"class": type(definition).__name__, "metadata": plain(definition.getMetaData()), "values": values,
           "override_warnings": overridden, "inherited_files": definition.getInheritedFiles()}
    if definition.getProperty("relative_extrusion", "type") is not None:
        # Evaluate a `value` formula through a one-container stack, as Cura's global stack would.
        stack = ContainerStack(container_id + "_probe_stack")
        stack.addContainer(definition)
        out["relative_extrusion"] = plain(stack.getProperty("relative_extrusion", "value"))
    return out


def main(resource_dir, ids):
    capture = Capture()
    Logger.addLogger(capture)
    registry = registry_for(resource_dir)
    result = {"definitions": {}, "registry_metadata": {}}
    for container_id in ids:
        metadata = registry.findDefinitionContainersMetadata(id=container_id)
        if metadata:
            result["registry_metadata"][container_id] = plain(metadata[0])
        described = describe(registry, container_id, capture)
        if described is not None:
            result["definitions"][container_id] = described
    result["is_definition_class"] = all(d["class"] == DefinitionContainer.__name__
                                        for d in result["definitions"].values())
    result["errors"] = [m for t, m in capture.lines if t in ("e", "c")]
    result["warnings"] = [m for t, m in capture.lines if t == "w"]
    json.dump(result, sys.stdout)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2:])
