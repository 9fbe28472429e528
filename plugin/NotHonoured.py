"""Cura settings MixEngine does not act on yet (no Cura imports).

The list is settings/mixengine/not_honoured.json, the one the engine warns from (its "about" field
describes it): "settings" maps a key to a reason (any value other than the definitions' is not
honoured) or to {"values": [...], "why": reason} (only those values are not honoured).
"""
import json
import os


def load(settings_dir):
    """{key: entry} of settings_dir/mixengine/not_honoured.json ({} when the file is absent)."""
    path = os.path.join(settings_dir or "", "mixengine", "not_honoured.json")
    if not os.path.isfile(path):
        return {}
    with open(path, encoding="utf-8") as f:
        return dict(json.load(f).get("settings", {}))


def normalised(value):
    """One form for the ways a value is written: Python objects from Cura's stacks, JSON values and the
    strings Cura sends ("True", "0.2", "raft")."""
    if isinstance(value, bool):
        return value
    if isinstance(value, (int, float)):
        return float(value)
    text = str(value).strip()
    if text in ("True", "true", "False", "false"):
        return text in ("True", "true")
    try:
        return float(text)
    except ValueError:
        return text


def multiExtruderOnly(entry):
    """True for an entry that holds only for prints with two or more extruders ("multi_extruder_only")."""
    return isinstance(entry, dict) and bool(entry.get("multi_extruder_only", False))


def reason(entry):
    return entry.get("why", "") if isinstance(entry, dict) else str(entry)


def notHonoured(entry, value, default):
    """True when `value` of a setting with this list entry has no effect in MixEngine: the engine's rule,
    a value other than the definitions' default that the entry lists (every value, or its "values")."""
    if normalised(value) == normalised(default):
        return False
    if isinstance(entry, dict) and "values" in entry:
        return normalised(value) in [normalised(v) for v in entry["values"]]
    return True


def offending(entries, found):
    """found: iterable of (key, value, default, where) for the values in force. Returns
    [(key, value, reason, [where, ...])] of the entries whose value is not honoured, in list order,
    one row per key and value."""
    rows = {}
    for key, value, default, where in found:
        entry = entries.get(key)
        if entry is None or not notHonoured(entry, value, default):
            continue
        row = rows.setdefault((key, str(normalised(value))), [key, value, reason(entry), []])
        if where not in row[3]:
            row[3].append(where)
    order = list(entries)
    return [tuple(r) for r in sorted(rows.values(), key=lambda r: (order.index(r[0]), str(r[1])))]


def messageText(rows, label=lambda key: key, shown=lambda key, value: str(value)):
    """The text of Cura's message for `rows` (offending()); label/shown name a key and its value."""
    lines = ["MixEngine does not act on these settings yet, so the print will not follow them:"]
    for key, value, why, where in rows:
        place = "" if where == ["global"] else " (%s)" % ", ".join(where)
        lines.append("• %s = %s%s: %s" % (label(key), shown(key, value), place, why))
    return "\n".join(lines)
