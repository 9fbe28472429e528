"""Setting parity with CuraEngine 4.13: change one setting at a time, slice with both engines, and say whether
MixEngine's print changes as CuraEngine's does (issue 19). Used by test_parity.py and tests/bench/parity.sh;
no pytest import here.

What is compared
  Both engines get the same *resolved* values (side_by_side.resolve: MixEngine evaluates Cura's formulas for
  the Ender-3 with the change applied, and both engines receive every resolved value), so a changed parent
  setting reaches both engines through the children its formulas drive.

  A flip is one (key, value) with the value taken from the setting's type: booleans negated, every other enum
  option, numbers moved inside their limits, `[int]` lists given one angle, strings given an extra comment.
  A flip runs in the first *context* (a few structure switches such as support or brim) where the setting's
  own `enabled` formula is true, so sub-settings are flipped with their structure switched on.

Verdicts (verdict()): compared on G-code signatures (signature()), not on bytes:
  cura-unchanged      CuraEngine's G-code does not change, and MixEngine's changes no figure clearly and no
                      ;TYPE: (otherwise not honoured: MixEngine changes where CuraEngine does not).
  honoured            MixEngine's G-code changes too, and wherever CuraEngine's changed clearly in the same
                      direction and by a size within SIZE_BAND (1/3 to 3 times) of CuraEngine's change:
                      filament, extruded length, layer count; travel length and retractions for travel
                      settings, mean extrusion speed for speed and cooling settings (elsewhere they follow
                      path order more than the setting); the G-code commands and ;TYPE: features CuraEngine
                      adds or drops; the temperature commands (M104/M109/M140/M190/M141/M191 with their
                      values) it adds; and the speed (F), fan (M106 S), acceleration (M204) and jerk (M205)
                      values it starts or stops writing for a speed, fan, acceleration or jerk setting's
                      new and old value (_value_failure; other values, such as those of a slowed-down layer,
                      follow each engine's time estimate).
  not honoured: ...   otherwise, with the first reason.
Distinctness (enum_substitutions): two options of an enum setting that CuraEngine prints differently must
print differently in MixEngine (no option is quietly printed as another).

Scenes (SCENES): "ender3", the Ender-3 with MODEL, every setting, and the same on two more models (SINGLES:
"ender3_shelf", wide overhangs and support standing on the model; "ender3_slivers", thin features and seven
parts); "s5_dual", the Ultimaker S5 with one part per
extruder and only the settings that matter with two extruders (DualScene). `python parity.py --scene s5_dual
[--explain key=value ...]` runs or explains that scene. In the two-extruder scene only temperature commands with a
value some setting gives are compared (verdict's set_temperatures): the standby temperatures CuraEngine computes
follow its own time estimates.

The list of settings MixEngine does not honour yet is settings/mixengine/not_honoured.json: the engine warns
about them, the plugin shows them, and test_parity.py runs every entry as a strict xfail.
"""
import hashlib
import json
import math
import os
import re
import uuid
from collections import Counter
from pathlib import Path

import helpers
import side_by_side as sbs

NOT_HONOURED = helpers.REPO / "settings" / "mixengine" / "not_honoured.json"
MODEL = "parity"  # side_by_side.GENERATED: pillars and a bridge with overhangs, a thin fin, a tube
CACHE = sbs.CACHE_DIR / "parity"

# Structures switched on so that their sub-settings are enabled (first match wins; {} is the plain print).
CONTEXTS = [
    {},
    {"support_enable": "True"},
    {"support_enable": "True", "support_interface_enable": "True"},
    {"support_enable": "True", "support_structure": "tree"},
    {"adhesion_type": "brim"},
    {"adhesion_type": "raft"},
    {"adhesion_type": "none"},
    {"ironing_enabled": "True"},
    {"magic_spiralize": "True"},
    {"bridge_settings_enabled": "True"},
    {"bridge_settings_enabled": "True", "bridge_enable_more_layers": "True"},
    {"coasting_enable": "True"},
    {"acceleration_enabled": "True"},
    {"jerk_enabled": "True"},
    {"draft_shield_enabled": "True"},
    {"draft_shield_enabled": "True", "draft_shield_height_limitation": "limited"},
    {"magic_fuzzy_skin_enabled": "True"},
    {"mold_enabled": "True"},
    {"conical_overhang_enabled": "True"},
    {"wall_0_wipe_dist": "0.4", "travel_retract_before_outer_wall": "True"},
    {"retraction_hop_enabled": "True"},
    {"retraction_combing": "infill"},
    {"infill_pattern": "zigzag"},
    {"infill_pattern": "cubicsubdiv"},
    {"infill_pattern": "cross_3d"},
    {"support_enable": "True", "support_pattern": "cross"},
    {"infill_pattern": "lines"},
    {"infill_pattern": "lightning"},
    {"gradual_infill_steps": "2"},
    {"clean_between_layers": "True"},
    {"adaptive_layer_height_enabled": "True"},
    {"machine_heated_build_volume": "True"},
    {"material_flow_dependent_temperature": "True"},
    {"support_enable": "True", "support_use_towers": "True"},
    {"support_enable": "True", "support_conical_enabled": "True"},
    {"wireframe_enabled": "True"},
    {"prime_blob_enable": "True"},
    {"cool_fan_enabled": "True", "cool_min_layer_time_fan_speed_max": "20"},
    # issue 28: contexts that switch on the settings no context above shows
    {"roofing_layer_count": "1"},
    {"infill_pattern": "concentric"},
    {"top_bottom_pattern": "concentric"},
    {"infill_support_enabled": "True"},
    {"speed_equalize_flow_enabled": "True"},
    {"wall_min_flow": "20"},
    {"acceleration_enabled": "True", "ironing_enabled": "True"},
    {"jerk_enabled": "True", "ironing_enabled": "True"},
    {"acceleration_enabled": "True", "roofing_layer_count": "1"},
    {"jerk_enabled": "True", "roofing_layer_count": "1"},
    {"acceleration_enabled": "True", "support_enable": "True", "support_interface_enable": "True"},
    {"jerk_enabled": "True", "support_enable": "True", "support_interface_enable": "True"},
    {"adhesion_type": "raft", "acceleration_enabled": "True"},
    {"adhesion_type": "raft", "jerk_enabled": "True"},
    {"support_enable": "True", "support_pattern": "lines"},
    {"support_enable": "True", "support_skip_some_zags": "True"},
    {"support_enable": "True", "support_xy_overrides_z": "z_overrides_xy"},
    {"support_enable": "True", "gradual_support_infill_steps": "2"},
    {"support_enable": "True", "support_fan_enable": "True"},
    {"adhesion_type": "brim", "support_enable": "True"},
    {"carve_multiple_volumes": "True"},
    {"clean_between_layers": "True", "wipe_hop_enable": "True"},
    {"wireframe_enabled": "True", "wireframe_strategy": "knot"},
]

# Not flipped: the machine's identity and shape of the scene (extruder count, build volume, head shape,
# names and ids), and settings the command line cannot carry or that only Cura's frontend reads.
SKIP_TYPES = {"category", "polygon", "polygons", "extruder", "optional_extruder"}
SKIP_KEYS = {
    "machine_extruder_count", "extruders_enabled_count", "machine_name", "machine_width", "machine_depth",
    "machine_height", "machine_shape", "machine_center_is_zero", "machine_show_variants", "material_guid",
    "material_type", "material_brand", "material_name", "material_is_support_material", "material_diameter",
    "extruder_nr", "extruder_prime_pos_abs", "machine_extruder_start_pos_abs", "machine_extruder_end_pos_abs",
    "machine_extruder_cooling_fan_number", "center_object", "mesh_position_x", "mesh_position_y",
    "mesh_position_z", "mesh_rotation_matrix", "machine_nozzle_id", "machine_buildplate_type",
    "material_bed_temp_prepend", "material_print_temp_prepend", "material_bed_temp_wait",
    "material_print_temp_wait", "machine_use_extruder_offset_to_offset_coords",
    "infill_mesh", "cutting_mesh", "support_mesh", "anti_overhang_mesh", "infill_mesh_order",
    "support_mesh_drop_down", "mold_enabled_meshes", "print_sequence", "user_defined_print_order_enabled",
    "machine_scale_fan_speed_zero_to_one", "machine_max_feedrate_x", "machine_max_feedrate_y",
}


# ---------------------------------------------------------------------------------------------------------
# Scenes: a printer, its models and the settings flipped on it.

class SingleScene:
    """The Ender-3 (one extruder) with one model: every flippable fdmprinter / fdmextruder setting."""
    contexts = CONTEXTS

    def __init__(self, name, model):
        self.name, self.model = name, model

    def resolve(self, settings):
        """(global, extruder 0) resolved with SETTINGS as the user's global values."""
        return sbs.resolve(settings)

    def slice_args(self, settings):
        g, e = sbs.resolve(settings)
        return [*sbs.slice_args(g, e), "-l", sbs.model_path(self.model)]

    def model_paths(self):
        return [sbs.model_path(self.model)]

    def keys(self):
        return [k for k, node in definitions().items()
                if node.get("type") not in SKIP_TYPES and k not in SKIP_KEYS]

    def is_enabled(self, key, values):
        return is_enabled(definitions()[key], values)

    def set_temperatures(self, *contexts):
        """None: every temperature command is compared (one extruder: the values follow settings)."""
        return None

    flip_values = {}
    key_contexts = {}


class DualScene:
    """The Ultimaker S5 (two extruder trains, Griffin, prime tower and acceleration/jerk on by default) with
    one part per extruder (side_by_side: dual_a on extruder 0, dual_b on extruder 1, both printing up to
    5 mm, extruder 0 alone above). Both engines get the resolved global values and both trains' values.
    Only the settings that matter with two extruders are flipped (DUAL_KEY_PATTERNS and every
    fdmextruder setting); a flip of an fdmextruder setting (nozzle offset, start code, prime position...)
    is a user value of the second train, any other flip a user value of the global stack, which both
    trains see."""
    name = "s5_dual"
    machine = helpers.CURA_DEFS / "ultimaker_s5.def.json"
    models = (("dual_a", 0), ("dual_b", 1))
    contexts = [
        {},
        {"ooze_shield_enabled": "True"},
        {"prime_blob_enable": "True"},
        {"machine_extruders_share_nozzle": "True"},
        {"retraction_hop_enabled": "True"},
    ]
    key_contexts = {}
    # Values that mean something on this bed and print (the generic flips would put the tower off the bed
    # or raise the final temperature above the printing one).
    flip_values = {
        "prime_tower_position_x": ["250"], "prime_tower_position_y": ["60"], "layer_start_x": ["0"],
        "layer_start_y": ["0"], "material_print_temperature": ["220"], "material_print_temperature_layer_0": ["215"],
        "material_initial_print_temperature": ["180"], "material_final_print_temperature": ["170"],
        "machine_extruder_start_pos_x": ["0"], "machine_extruder_end_pos_x": ["0"],
        # values that cross what this print needs: every idle time below the window (the nozzles stay
        # hot), and a minimal length above the brim's (the second extruder's lines grow)
        "machine_min_cool_heat_time_window": ["1000"], "skirt_brim_minimal_length": ["2000"],
    }

    def _split(self, settings):
        train = {k: v for k, v in settings.items() if k in _extruder_keys()}
        return {k: v for k, v in settings.items() if k not in train}, {1: train}

    def resolve(self, settings):
        """(global, extruder 1) resolved with SETTINGS (fdmextruder keys for extruder 1, the rest global)."""
        g, trains = sbs.resolve_machine(self.machine, *self._split(settings))
        return g, trains[1]

    def slice_args(self, settings):
        g, trains = sbs.resolve_machine(self.machine, *self._split(settings))
        models = [(sbs.model_path(name), nr) for name, nr in self.models]
        return sbs.multi_slice_args(self.machine, g, trains, models)

    def model_paths(self):
        return [sbs.model_path(name) for name, _ in self.models]

    def keys(self):
        extruder_keys = _extruder_keys()
        return [k for k, node in definitions().items()
                if node.get("type") not in SKIP_TYPES and k not in SKIP_KEYS - DUAL_UNSKIPPED
                and (k in extruder_keys or any(re.fullmatch(p, k) for p in DUAL_KEY_PATTERNS))]

    def is_enabled(self, key, values):
        node = definitions()[key]
        return is_enabled(dict(node, **_machine_enabled(self.machine).get(key, {})), values)

    def set_temperatures(self, *contexts):
        """The temperatures settings give in CONTEXTS (both trains), and 0 (a nozzle switched off): the
        temperature commands compared (parity.verdict)."""
        values = {0.0}
        for context in contexts:
            g, trains = sbs.resolve_machine(self.machine, *self._split(context))
            for scope in (g, *trains):
                values.update(float(v) for k, v in scope.items() if _TEMPERATURE_KEY.fullmatch(k))
        return values


# The settings flipped in the two-extruder scene besides fdmextruder's own (issue "Cura setting parity I").
DUAL_KEY_PATTERNS = [
    r"switch_extruder_.*", r"prime_tower_.*", r"prime_blob_enable", r"material_.*temperature.*",
    r"machine_nozzle_.*speed", r"material_extrusion_cool_down_speed", r"machine_extruders_share.*",
    r"machine_always_write_active_tool", r"retraction_hop_after_extruder_switch.*", r"layer_start_[xy]",
    r"speed_equalize_flow_.*", r"speed_prime_tower", r"skirt_brim_minimal_length", r"ooze_shield_.*", r"acceleration_.*", r"jerk_.*",
    r"machine_min_cool_heat_time_window",
]
_TEMPERATURE_KEY = re.compile(r"(material_(?!flow_dependent).*|build_volume_|default_material_.*)temperature(_layer_0)?")
DUAL_UNSKIPPED = {"machine_extruder_cooling_fan_number"}  # a train's own fan (M106 P<n>) matters here


def _extruder_keys():
    """The keys fdmextruder.def.json defines (a train's own settings)."""
    out = {}
    _flatten(json.loads((helpers.CURA_DEFS / "fdmextruder.def.json").read_text()).get("settings", {}), out)
    return set(out)


def _machine_enabled(machine):
    """{key: {"enabled": formula}} from the `overrides` of MACHINE's definition chain (nearest wins)."""
    found, path = {}, Path(machine)
    while path.is_file():
        data = json.loads(path.read_text())
        for key, node in data.get("overrides", {}).items():
            if "enabled" in node and key not in found:
                found[key] = {"enabled": node["enabled"]}
        parent = data.get("inherits")
        path = helpers.CURA_DEFS / f"{parent}.def.json" if parent else Path()
    return found


SINGLE = SingleScene("ender3", MODEL)
# The same sweep on models of other character (side_by_side.GENERATED): wide overhangs, bridges and support
# standing on the model (shelf); thin walls, a wedge, pins, a small hole and seven parts (slivers).
SINGLES = (SINGLE, SingleScene("ender3_shelf", "shelf"), SingleScene("ender3_slivers", "slivers"))
DUAL = DualScene()
SCENES = {scene.name: scene for scene in (*SINGLES, DUAL)}


def load_not_honoured():
    """key -> (values or None, why, multi_extruder_only, substituted): None = any value other than the
    definitions' is not honoured; multi_extruder_only: listed for prints with two or more extruders alone (the
    entry's "multi_extruder_only": true), so it is expected to fail in the two-extruder scene only; substituted:
    the listed options print as another option (the entry's "substituted": true; the distinctness test's
    finding, while each option alone may still change the print as CuraEngine's does)."""
    entries = json.loads(NOT_HONOURED.read_text())["settings"]
    out = {}
    for key, entry in entries.items():
        if isinstance(entry, str):
            out[key] = (None, entry, False, False)
        else:
            values = tuple(str(v) for v in entry["values"]) if "values" in entry else None
            out[key] = (values, entry["why"], bool(entry.get("multi_extruder_only", False)),
                        bool(entry.get("substituted", False)))
    return out


def is_listed(listed, key, value):
    if key not in listed:
        return None
    values, why = listed[key][:2]
    return why if values is None or str(value) in values else None


# ---------------------------------------------------------------------------------------------------------
# Definitions: type, options, limits and `enabled` formula of every fdmprinter / fdmextruder setting.

def _flatten(settings, out, category=None):
    for key, node in settings.items():
        node = dict(node, category=category or key)
        out[key] = node
        _flatten(node.get("children", {}), out, category or key)


def definitions():
    out = {}
    for name in ("fdmprinter", "fdmextruder"):
        data = json.loads((helpers.CURA_DEFS / f"{name}.def.json").read_text())
        _flatten(data.get("settings", {}), out)
    return out


class _Values(dict):
    """The namespace of an `enabled` formula: setting keys, Cura's helper functions and Python builtins."""

    def __init__(self, values):
        super().__init__()
        self.values = values

    def __missing__(self, name):
        if name in self.values:
            return _typed(self.values[name])
        helpers_ = {
            "resolveOrValue": lambda k: _typed(self.values.get(k)),
            "extruderValue": lambda e, k: _typed(self.values.get(k)),
            "extruderValues": lambda k: [_typed(self.values.get(k))],
            "defaultExtruderPosition": lambda: "0",
            "valueFromContainer": lambda *a: None,
            "math": math, "any": any, "all": all, "len": len, "min": min, "max": max, "sum": sum,
            "int": int, "float": float, "round": round, "str": str, "abs": abs, "True": True, "False": False,
            "None": None, "list": list, "map": map,
        }
        if name in helpers_:
            return helpers_[name]
        raise NameError(name)


def _typed(text):
    """A resolved value as printed by `mixengine settings --json` (text) in its Python type."""
    if text is None or not isinstance(text, str):
        return text
    if text in ("True", "False"):
        return text == "True"
    try:
        return int(text)
    except ValueError:
        pass
    try:
        return float(text)
    except ValueError:
        return text


def _categories():
    return {key: node["category"] for key, node in definitions().items()}


def is_enabled(node, values):
    """The setting's `enabled` formula evaluated on resolved values (an unreadable formula counts as true)."""
    formula = node.get("enabled", True)
    if isinstance(formula, bool):
        return formula
    try:
        return bool(eval(str(formula), {"__builtins__": {}}, _Values(values)))  # noqa: S307 (Cura's formulas)
    except Exception:  # noqa: BLE001 - a formula this small evaluator cannot read counts as enabled
        return True


# ---------------------------------------------------------------------------------------------------------
# Flips: the changed values tried for one setting.

def _limit(node, name):
    text = node.get(name)
    try:
        return float(text) if text is not None else None
    except (TypeError, ValueError):
        return None


def _number_flips(node, current, is_int):
    lo = _limit(node, "minimum_value") if _limit(node, "minimum_value") is not None else -1e9
    lo_warn = _limit(node, "minimum_value_warning")
    hi = min(x for x in (_limit(node, "maximum_value"), _limit(node, "maximum_value_warning"), 1e9)
             if x is not None)
    if current == 0:
        candidate = 1.0 if hi >= 1 else hi / 2
    else:
        candidate = current * 1.5
        if candidate > hi or (lo_warn is not None and candidate < lo_warn):
            candidate = current * 0.6
    if is_int:
        candidate = int(round(candidate)) if int(round(candidate)) != int(current) else int(current) + 1
    if candidate < lo or candidate > hi or candidate == current:
        return []
    return [str(candidate) if is_int else f"{candidate:.4g}"]


def flips(key, node, current):
    """The values to try for KEY whose resolved value is CURRENT (text)."""
    kind = node.get("type")
    if kind == "bool":
        return ["False" if current == "True" else "True"]
    if kind == "enum":
        return [o for o in node.get("options", {}) if o != current]
    if kind in ("float", "int"):
        try:
            value = float(current)
        except (TypeError, ValueError):
            return []
        return _number_flips(node, value, kind == "int")
    if kind == "[int]":
        return ["[30]"] if current.replace(" ", "") != "[30]" else ["[60]"]
    if kind == "str":
        return [(current or "") + "\\n;parity"] if key.endswith("gcode") else []
    return []


def context_for(key, scene):
    """The first of the scene's contexts in which the setting is enabled, with its resolved values
    (global, the train its flips go to); None if in none."""
    for context in ([scene.key_contexts[key]] if key in scene.key_contexts else []) + list(scene.contexts):
        g, e = scene.resolve(context)
        if scene.is_enabled(key, {**g, **e}):
            return context, g, e
    return None


# ---------------------------------------------------------------------------------------------------------
# G-code signatures.

_WORD = re.compile(r"([A-Z])(-?[0-9.]+)")
TEMPERATURE_COMMANDS = ("M104", "M109", "M140", "M190", "M141", "M191")
# The values compared for speed, fan, acceleration and jerk (besides F on every move): command -> words.
VALUE_WORDS = {"M106": ("S",), "M204": ("S", "P", "T"), "M205": ("X", "Y", "Z", "E")}


class _Reader:
    def __init__(self):
        self.relative, self.x, self.y, self.e = False, 0.0, 0.0, 0.0
        self.s = {"filament": 0.0, "extrude_len": 0.0, "travel_len": 0.0, "retractions": 0, "layers": 0,
                  "speed_x_len": 0.0}
        self.commands, self.types, self.temps = Counter(), Counter(), set()
        self.values = set()  # VALUE_WORDS as written ("F1500", "M106 S127.5", "M204 S500", "M205 X8")
        self.f_last = 0.0

    def comment(self, line):
        if line.startswith(";LAYER:"):
            self.s["layers"] += 1
        elif line.startswith(";TYPE:"):
            self.types[line[6:].strip()] += 1

    def move(self, words):
        x, y = words.get("X", self.x), words.get("Y", self.y)
        dist = math.hypot(x - self.x, y - self.y)
        de = 0.0
        if "E" in words:
            de = words["E"] if self.relative else words["E"] - self.e
            self.e = words["E"] if not self.relative else self.e + words["E"]
        if de > 0 and dist > 0:
            self.s["filament"] += de
            self.s["extrude_len"] += dist
            self.s["speed_x_len"] += dist * words.get("F", self.f_last)
        elif de < 0:
            self.s["retractions"] += 1
        elif dist > 0:
            self.s["travel_len"] += dist
        if "F" in words:
            self.f_last = words["F"]
            self.values.add(f"F{words['F']:g}")
        self.x, self.y = x, y

    def command(self, code, words, line):
        self.commands[code] += 1
        if code in ("M82", "M83"):
            self.relative = code == "M83"
        elif code == "G92" and "E" in words:
            self.e = words["E"]
        elif code == "G10":
            self.s["retractions"] += 1
        for letter in VALUE_WORDS.get(code, ()):
            if letter in words:
                self.values.add(f"{code} {letter}{words[letter]:g}")
        if code in TEMPERATURE_COMMANDS:
            self.temps.add(f"{code} S{float(words.get('S', words.get('R', 0))):g}"
                           + (f" T{int(words['T'])}" if "T" in words else ""))


def signature(path):
    """Digest of the G-code (comments other than ;LAYER:/;TYPE: left out) and the compared figures."""
    reader, digest = _Reader(), hashlib.sha256()
    with open(path, encoding="utf-8", errors="replace") as f:
        for raw in f:
            line = raw.strip()
            if not line:
                continue
            if line.startswith(";"):
                if line.startswith((";LAYER:", ";TYPE:")):
                    digest.update(line.encode())
                    reader.comment(line)
                continue
            code_part = line.split(";", 1)[0].strip()
            digest.update(code_part.encode())
            parts = code_part.split(None, 1)
            code = parts[0]
            words = {k: float(v) for k, v in _WORD.findall(parts[1] if len(parts) > 1 else "")
                     if v not in ("-", ".", "-.")}
            if code in ("G0", "G1"):
                reader.move(words)
            else:
                reader.command(code, words, line)
    s = reader.s
    figures = {k: s[k] for k in ("filament", "extrude_len", "travel_len", "retractions", "layers")}
    figures["mean_speed"] = s["speed_x_len"] / s["extrude_len"] if s["extrude_len"] else 0.0
    return {"digest": digest.hexdigest(), "figures": figures, "commands": sorted(reader.commands),
            "types": sorted(reader.types), "temps": sorted(reader.temps), "values": sorted(reader.values)}


# (relative threshold, absolute threshold): a change counts as clear when it passes both.
THRESHOLDS = {"filament": (0.003, 0.5), "extrude_len": (0.005, 5.0), "travel_len": (0.03, 20.0),
              "retractions": (0.03, 2), "layers": (0.0, 1), "mean_speed": (0.05, 60.0)}


def _clear(delta, base, metric):
    rel, absolute = THRESHOLDS[metric]
    return abs(delta) >= absolute and abs(delta) >= rel * abs(base)


# Figures whose direction depends on path order as much as on the setting are compared only for the
# settings that are about them: travel for the travel category, speed for speed and cooling.
CATEGORY_METRICS = {"travel_len": ("travel",), "retractions": ("travel",), "mean_speed": ("speed", "cooling")}


def _only_set_temperatures(sig, set_temperatures):
    """SIG with only the temperature commands whose value is one of SET_TEMPERATURES (values of settings):
    the intermediate values CuraEngine's preheat model computes from its own time estimates (a standby
    temperature the nozzle only cools down to) depend on those estimates and are not compared."""
    if set_temperatures is None:
        return sig
    kept = [t for t in sig["temps"] if float(t.split()[1][1:]) in set_temperatures]
    return dict(sig, temps=kept)


# MixEngine's change of a figure is the same size as CuraEngine's when it lies in SIZE_BAND times CuraEngine's
# (or the two differ by less than a clear change, THRESHOLDS).
SIZE_BAND = (1 / 3, 3.0)


def _metrics(category):
    """The figures compared for a setting of CATEGORY (all of them when the category is not known)."""
    return [m for m in THRESHOLDS
            if m not in CATEGORY_METRICS or category is None or category in CATEGORY_METRICS[m]]


def _figure_failure(cura_base, cura_flip, mix_base, mix_flip, category):
    """The first figure CuraEngine changes clearly that MixEngine does not change the same way by a size
    within SIZE_BAND; None when every one does."""
    for metric in _metrics(category):
        base = cura_base["figures"][metric]
        dc = cura_flip["figures"][metric] - base
        dm = mix_flip["figures"][metric] - mix_base["figures"][metric]
        if not _clear(dc, base, metric):
            continue
        if dc * dm <= 0:
            return f"{metric} CuraEngine {dc:+.4g}, MixEngine {dm:+.4g}"
        ratio = dm / dc
        if not SIZE_BAND[0] <= ratio <= SIZE_BAND[1] and _clear(dm - dc, base, metric):
            return f"{metric} size CuraEngine {dc:+.4g}, MixEngine {dm:+.4g} (x{ratio:.2g}, outside 1/3..3)"
    return None


def _mix_only_change(mix_base, mix_flip, category):
    """What MixEngine changes clearly (a figure, a ;TYPE: added or dropped) when CuraEngine's G-code does not
    change at all; None when nothing."""
    for metric in _metrics(category):
        base = mix_base["figures"][metric]
        dm = mix_flip["figures"][metric] - base
        if _clear(dm, base, metric):
            return f"{metric} MixEngine {dm:+.4g} where CuraEngine's G-code does not change"
    changed = set(mix_flip["types"]) ^ set(mix_base["types"])
    if changed:
        return f"MixEngine's features {sorted(changed)[:4]} change where CuraEngine's G-code does not"
    return None


def given_values(*scopes):
    """The written forms of every number in the resolved SCOPES ({key: text}): F (mm/min, one decimal),
    M106 S (0..255, one decimal), M204 (whole mm/s²) and M205 (two decimals), as CuraEngine writes them."""
    numbers = set()
    for scope in scopes:
        for text in scope.values():
            try:
                numbers.add(float(text))
            except (TypeError, ValueError):
                continue
    return {"F": {round(x * 60, 1) for x in numbers}, "M106": {round(x * 2.55, 1) for x in numbers},
            "M204": {float(round(x)) for x in numbers}, "M205": {round(x, 2) for x in numbers}}


def _is_given(written, given):
    """WRITTEN ("F1500", "M204 S500") is a value some setting gives (given_values)."""
    code, _, word = written.partition(" ")
    if not word:
        code, word = "F", written
    digits = {"F": 1, "M106": 1, "M204": 0, "M205": 2}[code]
    return round(float(word.lstrip("FSPTXYZE")), digits) in given[code]


def _value_failure(cura_base, cura_flip, mix_base, mix_flip, given):
    """For a speed, fan, acceleration or jerk setting, GIVEN = (written forms of its new value, of its old
    value) (given_values): a form of the new value CuraEngine starts writing and MixEngine does not, or a form
    of the old value CuraEngine stops writing while MixEngine keeps it; None when neither (or GIVEN is None)."""
    if given is None:
        return None
    new, old = given
    before, after = set(cura_base.get("values", ())), set(cura_flip.get("values", ()))
    mix_before, mix_after = set(mix_base.get("values", ())), set(mix_flip.get("values", ()))
    missing = sorted(v for v in after - before - mix_after if _is_given(v, new))
    if missing:
        return f"CuraEngine writes {missing[:4]}, MixEngine does not"
    kept = sorted(v for v in (before - after) & mix_before & mix_after if _is_given(v, old))
    if kept:
        return f"CuraEngine stops writing {kept[:4]}, MixEngine does not"
    return None


def writes_values(key):
    """KEY is a speed, fan, acceleration or jerk setting: its value is written as F, M106 S, M204 or M205."""
    return any(word in key for word in ("speed", "acceleration", "jerk"))


def _feature_failure(cura_base, cura_flip, mix_flip):
    """A G-code command, ;TYPE: or temperature command CuraEngine adds that MixEngine lacks, or drops that
    MixEngine keeps; None when none."""
    for field in ("commands", "types", "temps"):
        added = set(cura_flip[field]) - set(cura_base[field])
        dropped = set(cura_base[field]) - set(cura_flip[field])
        missing = added - set(mix_flip[field])
        kept = (dropped & set(mix_flip[field])) if field != "temps" else set()
        if missing:
            return f"CuraEngine adds {field} {sorted(missing)[:4]}"
        if kept:
            return f"CuraEngine drops {field} {sorted(kept)[:4]}"
    return None


def verdict(cura_base, cura_flip, mix_base, mix_flip, category=None, set_temperatures=None, given=None):
    """"honoured", "cura-unchanged" or "not honoured: <the first reason>" for one changed setting: the four
    signatures, the setting's category (CATEGORY_METRICS), the temperatures compared (None: all) and, for a
    speed, fan, acceleration or jerk setting, the written forms of its new and old values (_value_failure;
    None: values are not compared)."""
    cura_base, cura_flip, mix_base, mix_flip = (_only_set_temperatures(sig, set_temperatures)
                                                for sig in (cura_base, cura_flip, mix_base, mix_flip))
    if cura_flip["digest"] == cura_base["digest"]:
        extra = _mix_only_change(mix_base, mix_flip, category)
        return f"not honoured: {extra}" if extra else "cura-unchanged"
    if mix_flip["digest"] == mix_base["digest"]:
        return "not honoured: MixEngine's G-code does not change"
    failure = (_figure_failure(cura_base, cura_flip, mix_base, mix_flip, category)
               or _feature_failure(cura_base, cura_flip, mix_flip)
               or _value_failure(cura_base, cura_flip, mix_base, mix_flip, given))
    return f"not honoured: {failure}" if failure else "honoured"


# ---------------------------------------------------------------------------------------------------------
# Running one flip.

CATEGORIES = _categories()
SIGNATURE_VERSION = 2  # 2: signatures carry the written values (issue 28)
SETTING_TYPES = {key: node.get("type") for key, node in definitions().items()}

def _cache_path(kind, args):
    stat = os.stat(helpers.CURA_BIN)
    key = hashlib.sha256(json.dumps([kind, SIGNATURE_VERSION, stat.st_size, int(stat.st_mtime),
                                     *map(str, args)]).encode())
    return CACHE / f"{key.hexdigest()[:24]}.json"


def cura_signature(settings, scene=None):
    """CuraEngine's signature for a settings context (cached on disk: CuraEngine is the slow half)."""
    scene = scene or SINGLE
    args = scene.slice_args(settings)
    cached = _cache_path("cura", args + [sbs._file_digest(path) for path in scene.model_paths()])
    if cached.is_file():
        return json.loads(cached.read_text())
    out = sbs._TMP / f"parity-cura-{cached.stem}-{uuid.uuid4().hex[:8]}.gcode"
    proc = helpers.run([helpers.CURA_BIN, "slice", *args, "-o", out], env=helpers.CURA_ENV)
    result = signature(out) if proc.returncode == 0 and out.exists() else {"error": proc.stderr[-300:]}
    out.unlink(missing_ok=True)
    if "error" in result:
        return result  # not cached: a failure is reported, and tried again next time
    CACHE.mkdir(parents=True, exist_ok=True)
    tmp = cached.with_suffix(f".{os.getpid()}.tmp")
    tmp.write_text(json.dumps(result))
    tmp.replace(cached)
    return result


_MIX_MEMO = {}


def mix_signature(settings, scene=None):
    """MixEngine's signature for a settings context (memoised in this process)."""
    scene = scene or SINGLE
    memo_key = (scene.name, tuple(sorted(settings.items())))
    if memo_key not in _MIX_MEMO:
        _MIX_MEMO[memo_key] = _mix_signature(settings, scene)
    return _MIX_MEMO[memo_key]


def _mix_signature(settings, scene):
    name = hashlib.sha256(repr((scene.name, sorted(settings.items()))).encode()).hexdigest()[:16]
    out = sbs._TMP / f"parity-mix-{name}-{uuid.uuid4().hex[:8]}.gcode"
    proc = helpers.run([helpers.BIN, "slice", *scene.slice_args(settings), "-o", out], env=helpers.CURA_ENV)
    result = signature(out) if proc.returncode == 0 and out.exists() else {"error": proc.stderr[-300:]}
    out.unlink(missing_ok=True)
    return result


def judge(context, key, value, scene=None):
    """The verdict for setting KEY=VALUE on top of CONTEXT (in SCENE, the single-extruder one by default)."""
    return judge_outcome(context, key, value, scene)["verdict"]


def judge_outcome(context, key, value, scene=None):
    """{"verdict", "digests"}: the verdict for KEY=VALUE on CONTEXT in SCENE and the G-code digests of the four
    prints (CuraEngine's and MixEngine's, base and changed; empty when a print failed), which
    enum_substitutions compares across a setting's options."""
    scene = scene or SINGLE
    flipped = dict(context, **{key: value})
    try:
        cb, cf = cura_signature(context, scene), cura_signature(flipped, scene)
        mb, mf = mix_signature(context, scene), mix_signature(flipped, scene)
    except RuntimeError as err:  # mixengine settings refused the value
        return {"verdict": f"error: {str(err)[-200:]}", "digests": {}}
    digests = {name: sig.get("digest") for name, sig in
               (("cura_base", cb), ("cura", cf), ("mix_base", mb), ("mix", mf))}
    if "error" in cf:  # CuraEngine itself cannot print it (e.g. an arithmetic exception): nothing to match
        return {"verdict": f"cura-failed: {cf['error'].strip().splitlines()[-1:] if cf['error'] else ''}",
                "digests": {}}
    for name, sig in (("CuraEngine base", cb), ("MixEngine", mf), ("MixEngine base", mb)):
        if "error" in sig:
            text = sig["error"].strip().splitlines()[-1:] if sig["error"] else ""
            return {"verdict": f"error: {name} failed: {text}", "digests": {}}
    given = None
    if writes_values(key):
        given = (given_values({key: value}), given_values({key: current_value(key, context, scene)}))
    text = verdict(cb, cf, mb, mf, CATEGORIES.get(key), scene.set_temperatures(context, flipped), given)
    return {"verdict": text, "digests": digests}


def enum_substitutions(outcomes, current):
    """["a prints as b"]: pairs of a setting's options that CuraEngine prints differently and MixEngine the same.
    OUTCOMES: [(value, digests)] of one enum setting's flips in one context (judge_outcome), CURRENT the value
    the context resolves it to (whose prints are the flips' bases)."""
    prints = {}
    for value, digests in outcomes:
        if digests:
            prints[current] = (digests["cura_base"], digests["mix_base"])
            prints[value] = (digests["cura"], digests["mix"])
    found = []
    options = sorted(prints)
    for i, a in enumerate(options):
        for b in options[i + 1:]:
            if prints[a][0] != prints[b][0] and prints[a][1] == prints[b][1]:
                found.append(f"{a} prints as {b}")
    return found


def current_value(key, context, scene):
    """KEY's resolved value (text) in CONTEXT of SCENE."""
    g, e = scene.resolve(context)
    return e.get(key, g.get(key))


def all_flips(keys=None, scene=None):
    """[(key, value, context)] for every flippable setting of the scene (or those in KEYS)."""
    scene = scene or SINGLE
    defs = definitions()
    out = []
    for key in scene.keys():
        node = defs[key]
        if keys is not None and key not in keys:
            continue
        found = context_for(key, scene)
        if found is None:
            continue
        context, g, e = found
        current = e.get(key, g.get(key))
        if current is None:
            continue
        for value in scene.flip_values.get(key) or flips(key, node, current):
            out.append((key, value, context))
    return out


def run_all(workers=2, progress=None, keys=None, scene=None):
    """{"key=value": {key, value, context, verdict}} for every flip (of KEYS) in SCENE, judged on WORKERS
    threads."""
    from concurrent.futures import ThreadPoolExecutor
    scene = scene or SINGLE
    todo = all_flips(keys, scene)
    contexts = [dict(c) for c in {tuple(sorted(c.items())) for _, _, c in todo}]
    with ThreadPoolExecutor(max_workers=workers) as pool:  # each context's base once, before the flips
        list(pool.map(lambda c: cura_signature(c, scene), contexts))
        list(pool.map(lambda c: mix_signature(c, scene), contexts))
    with ThreadPoolExecutor(max_workers=workers) as pool:
        results = {}
        futures = {pool.submit(judge_outcome, c, k, v, scene): (k, v, c) for k, v, c in todo}
        for done, future in enumerate(futures, 1):
            key, value, context = futures[future]
            outcome = future.result()
            results[f"{key}={value}"] = {"key": key, "value": value, "context": context,
                                         "verdict": outcome["verdict"], "digests": outcome["digests"],
                                         "current": current_value(key, context, scene)}
            if progress:
                progress(done, len(futures), key, value, results[f"{key}={value}"]["verdict"])
    return results


def explain(key, value, scene=None):
    """Text: the context, the verdict, and what changed in each engine's signature (for a person)."""
    scene = scene or SINGLE
    found = context_for(key, scene)
    context = found[0] if found else {}
    flipped = dict(context, **{key: value})
    sigs = {"CuraEngine": (cura_signature(context, scene), cura_signature(flipped, scene)),
            "MixEngine": (mix_signature(context, scene), mix_signature(flipped, scene))}
    lines = [f"{key}={value} on {scene.name}, {context or 'the plain print'}: {judge(context, key, value, scene)}"]
    for engine, (base, flip) in sigs.items():
        figures = {m: round(flip["figures"][m] - base["figures"][m], 3) for m in THRESHOLDS}
        lines.append(f"  {engine}: changed {base['digest'] != flip['digest']}, deltas {figures}")
        for field in ("commands", "types", "temps"):
            plus, minus = set(flip[field]) - set(base[field]), set(base[field]) - set(flip[field])
            if plus or minus:
                lines.append(f"    {field}: +{sorted(plus)} -{sorted(minus)}")
    return "\n".join(lines)


# Reasons for whole families of settings (a key's first matching prefix); other keys get their verdict.
FAMILY_REASONS = [
    (("bridge_",), "bridge settings are not built yet"),
    (("coasting_",), "coasting is not built yet"),
    (("magic_fuzzy_skin_",), "fuzzy skin is not built yet"),
    (("mold_",), "molds are not built yet"),
    (("wireframe_",), "wire printing is not built"),
    (("clean_between_layers", "wipe_", "max_extrusion_before_wipe"), "the wipe script between layers is not built yet"),
    (("adaptive_layer_height_",), "adaptive layer heights are not built yet"),
    (("conical_overhang_",), "'make overhang printable' is not built yet"),
    (("magic_spiralize", "smooth_spiralized_contours"), "spiralize (vase mode) is not built yet"),
]


def _reason(key, verdict_text):
    for prefixes, reason in FAMILY_REASONS:
        if key.startswith(prefixes):
            return reason
    detail = verdict_text.replace("not honoured: ", "")
    if detail == "MixEngine's G-code does not change":
        return "does not change MixEngine's print yet"
    detail = re.sub(r" CuraEngine [-+][^,]*, MixEngine [-+]\S*", " moves the other way or not at all", detail)
    return f"changes the print unlike CuraEngine ({detail})"


def list_from(results):
    """not_honoured.json's "settings" rebuilt from whole sweeps (one or more scenes' results merged), with the
    reasons above; a key is listed whole when every judged value fails in every scene, else by value."""
    by_key = {}
    for outcome in results.values():
        if outcome["verdict"].startswith(("cura-unchanged", "cura-failed")):
            continue
        by_key.setdefault(outcome["key"], []).append(outcome)
    listed = {}
    for key in sorted(by_key):
        failing = [o for o in by_key[key] if o["verdict"] != "honoured"]
        if not failing:
            continue
        why = _reason(key, failing[0]["verdict"])
        if len(failing) == len(by_key[key]) and SETTING_TYPES.get(key) != "enum":
            listed[key] = why
        else:
            listed[key] = {"values": list(dict.fromkeys(o["value"] for o in failing)), "why": why}
    return listed


if __name__ == "__main__":
    import sys
    if len(sys.argv) > 2 and sys.argv[1] == "--write-list":  # --write-list SWEEP.json...: the list rebuilt
        document = json.loads(NOT_HONOURED.read_text())  # from sweeps of the single-extruder scenes
        kept = {k: e for k, e in document["settings"].items() if isinstance(e, dict) and e.get("multi_extruder_only")}
        merged = {}  # one sweep per file (scene); a key fails when it fails in any of them
        for nr, name in enumerate(sys.argv[2:]):
            merged.update({f"{nr}:{k}": o for k, o in json.loads(Path(name).read_text()).items()})
        document["settings"] = dict(sorted({**list_from(merged), **kept}.items()))
        NOT_HONOURED.write_text(json.dumps(document, indent=2) + "\n")
        print(f"{NOT_HONOURED}: {len(document['settings'])} settings")
        sys.exit(0)
    chosen = SINGLE
    if len(sys.argv) > 2 and sys.argv[1] == "--scene":  # --scene s5_dual: the two-extruder scene
        chosen = SCENES[sys.argv[2]]
        del sys.argv[1:3]
    if len(sys.argv) > 2 and sys.argv[1] == "--explain":
        for flip in sys.argv[2:]:
            print(explain(*flip.split("=", 1), scene=chosen))
        sys.exit(0)
    report = run_all(progress=lambda i, n, k, v, r: print(f"[{i}/{n}] {k}={v}: {r}", flush=True), scene=chosen)
    Path(sys.argv[1] if len(sys.argv) > 1 else "parity.json").write_text(json.dumps(report, indent=1))
