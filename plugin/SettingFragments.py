"""MixEngine's setting fragments and the printer overrides of their keys, as plain JSON.

The fragments settings/mixengine/*.def.json have the shape of Cura's fdmprinter.def.json
({"settings": {category: {"type": "category", "children": {...}}}}); they are the single source of
truth for the keys the plugin adds to Cura. A printer definition may override those keys in its
"overrides" block (e.g. mixing_dialect); Uranium drops such overrides while the keys are still
unknown to it, so the plugin re-applies them, walking the definition's "inherits" chain root first.

No Cura imports here, so this can be unit-tested outside Cura.
"""
import collections
import copy
import json


def readJson(path):
    """Parsed JSON with OrderedDicts, as Uranium parses definitions: its settings model turns only an
    OrderedDict "options" into the items of an enum's drop-down (a plain dict shows an empty list)."""
    with open(path, encoding="utf-8") as f:
        return json.load(f, object_pairs_hook=collections.OrderedDict)


def loadFragment(path):
    fragment = readJson(path)
    if not isinstance(fragment.get("settings"), dict):
        raise ValueError("%s: no \"settings\" object" % path)
    return fragment


def categories(fragment):
    """[(category key, category dict)] of one fragment, in file order."""
    return list(fragment["settings"].items())


def settingKeys(key, definition):
    """The key and every key below it."""
    keys = [key]
    for child_key, child in definition.get("children", {}).items():
        keys.extend(settingKeys(child_key, child))
    return keys


def findSetting(key, definition, wanted):
    """The dict of setting `wanted` inside (key, definition), or None."""
    if key == wanted:
        return definition
    for child_key, child in definition.get("children", {}).items():
        found = findSetting(child_key, child, wanted)
        if found is not None:
            return found
    return None


def inheritsChain(definition_id, read_definition, limit=64):
    """[definition_id, parent, grandparent, ...] following "inherits"; stops at a missing file."""
    chain = []
    current = definition_id
    while current and current not in chain and len(chain) < limit:
        data = read_definition(current)
        if data is None:
            break
        chain.append(current)
        current = data.get("inherits")
    return chain


def collectOverrides(definition_id, read_definition, keys):
    """{key: properties} that the definition and its ancestors override for `keys`.

    Root first, so a nearer definition wins, as in Uranium's own merge. read_definition(id) returns
    the parsed .def.json or None."""
    wanted = set(keys)
    result = {}
    for ancestor in reversed(inheritsChain(definition_id, read_definition)):
        overrides = read_definition(ancestor).get("overrides") or {}
        for key, properties in overrides.items():
            if key in wanted and isinstance(properties, dict):
                result.setdefault(key, {}).update(properties)
    return result


def withOverrides(key, definition, overrides):
    """A deep copy of the category (key, definition) with the overrides merged into its settings."""
    merged = copy.deepcopy(definition)
    for setting_key, properties in overrides.items():
        target = findSetting(key, merged, setting_key)
        if target is not None:
            target.update(copy.deepcopy(properties))
    return merged


def settablePerMesh(key, definition):
    """Keys below (key, definition) whose "settable_per_mesh" is true (the per-object settings)."""
    found = []
    if definition.get("type") != "category" and definition.get("settable_per_mesh") is True:
        found.append(key)
    for child_key, child in definition.get("children", {}).items():
        found.extend(settablePerMesh(child_key, child))
    return found
