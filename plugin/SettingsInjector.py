"""Adds MixEngine's setting categories to every machine definition Cura loads.

Cura has no public API for adding settings; this follows the pattern of public plugins (reference
§8.2): on ContainerRegistry.containerLoadComplete, for every non-extruder DefinitionContainer that
lacks the category, build SettingDefinitions from the fragment JSON and hook them into the
container's private tree (_definitions, _definition_cache, _updateRelations). The machine
definition (e.g. mixengine_makerpi_m2030x) carries a full merged copy of the tree, so the
settings go into every definition, not only fdmprinter. The definition's own overrides of our keys
(its "inherits" chain, root first) are merged in first, so a printer's mixing defaults show.
"""
from UM.Logger import Logger
from UM.Resources import Resources
from UM.Settings.ContainerRegistry import ContainerRegistry
from UM.Settings.DefinitionContainer import DefinitionContainer
from UM.Settings.SettingDefinition import SettingDefinition

from . import SettingFragments


class SettingsInjector:
    def __init__(self, fragment_paths):
        self._categories = []  # [(key, dict)]
        for path in fragment_paths:
            self._categories.extend(SettingFragments.categories(SettingFragments.loadFragment(path)))
        self._keys = [k for key, d in self._categories for k in SettingFragments.settingKeys(key, d)]
        self._json_cache = {}
        self.injected = []  # definition ids, for the log and the tests

    def categoryKeys(self):
        return [key for key, _ in self._categories]

    def allKeys(self):
        return list(self._keys)

    def connect(self):
        ContainerRegistry.getInstance().containerLoadComplete.connect(self._onContainerLoadComplete)

    def _readDefinition(self, definition_id):
        if definition_id not in self._json_cache:
            try:
                path = Resources.getPath(Resources.DefinitionContainers, definition_id + ".def.json")
                self._json_cache[definition_id] = SettingFragments.readJson(path)
            except (FileNotFoundError, OSError, ValueError):
                self._json_cache[definition_id] = None
        return self._json_cache[definition_id]

    def _onContainerLoadComplete(self, container_id):
        registry = ContainerRegistry.getInstance()
        if not registry.isLoaded(container_id):
            return  # findContainers on a half-loaded id can recurse forever
        found = registry.findContainers(id=container_id)
        if not found or not isinstance(found[0], DefinitionContainer):
            return
        container = found[0]
        if container.getMetaDataEntry("type") == "extruder":
            return
        try:
            self.inject(container)
        except Exception:  # a broken fragment must not take Cura down
            Logger.logException("e", "[MixEngine] adding settings to %s failed", container_id)

    def inject(self, container):
        overrides = SettingFragments.collectOverrides(container.getId(), self._readDefinition, self._keys)
        added = []
        for key, definition in self._categories:
            if container.findDefinitions(key=key):
                continue
            self._addCategory(container, key, SettingFragments.withOverrides(key, definition, overrides))
            added.append(key)
        if added:
            self.injected.append(container.getId())
            Logger.log("i", "[MixEngine] added %s to %s (%d printer overrides)",
                       ", ".join(added), container.getId(), len(overrides))

    @staticmethod
    def _addCategory(container, key, data):
        category = SettingDefinition(key, container, None, None)
        category.deserialize(data)
        container._definitions.append(category)  # private: no public API for adding settings
        pending = [category]
        while pending:
            definition = pending.pop()
            container._definition_cache[definition.key] = definition
            pending.extend(definition.children)
        container._updateRelations(category)
