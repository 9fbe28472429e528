"""Turn an outgoing cura.proto.Slice (an Arcus PythonMessage) into plain JSON-able data.

Only setting values are kept: vertices are reduced to a vertex count.
Must run inside the patched SignalSocket.sendMessage, before the message is sent.
"""


def _text(value):
    if isinstance(value, (bytes, bytearray)):
        return bytes(value).decode("utf-8", errors="replace")
    return str(value)


def _settings(parent, field="settings"):
    """Repeated cura.proto.Setting -> {name: value-string}, sorted by name.

    Cura fills the message from stack.getAllKeys(), a set: its order changes from run to run,
    so sorting keeps re-recorded fixtures diffable.
    """
    out = {}
    for i in range(parent.repeatedMessageCount(field)):
        setting = parent.getRepeatedMessage(field, i)
        out[setting.name] = _text(setting.value)
    return dict(sorted(out.items()))


def sliceToDict(msg):
    record = {
        "global_settings": _settings(msg.getMessage("global_settings")),
        "limit_to_extruder": {},
        "extruders": [],
        "object_lists": [],
    }
    for i in range(msg.repeatedMessageCount("limit_to_extruder")):
        entry = msg.getRepeatedMessage("limit_to_extruder", i)
        record["limit_to_extruder"][entry.name] = int(entry.extruder)
    record["limit_to_extruder"] = dict(sorted(record["limit_to_extruder"].items()))
    for i in range(msg.repeatedMessageCount("extruders")):
        extruder = msg.getRepeatedMessage("extruders", i)
        record["extruders"].append({"id": int(extruder.id),
                                    "settings": _settings(extruder.getMessage("settings"))})
    for i in range(msg.repeatedMessageCount("object_lists")):
        object_list = msg.getRepeatedMessage("object_lists", i)
        objects = []
        for j in range(object_list.repeatedMessageCount("objects")):
            obj = object_list.getRepeatedMessage("objects", j)
            objects.append({
                "name": _text(obj.name),
                "settings": _settings(obj),
                # triangle soup of float32 x,y,z: 12 bytes per vertex, 3 vertices per face
                "vertex_count": len(obj.vertices) // 12,
            })
        record["object_lists"].append({"settings": _settings(object_list), "objects": objects})
    return record


def stackContainers(stack):
    """Ids of the containers Cura used in one (global or extruder) stack, top to bottom."""
    return {
        "user": stack.userChanges.getId(),
        "quality_changes": stack.qualityChanges.getId(),
        "intent": stack.intent.getId(),
        "quality": stack.quality.getId(),
        "material": stack.material.getId(),
        "variant": stack.variant.getId(),
        "definition_changes": stack.definitionChanges.getId(),
        "definition": stack.definition.getId(),
    }
