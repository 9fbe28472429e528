"""The numeric settings of Cura's fdmprinter.def.json and their bounds, for test_random_settings.py.

Bounds are Cura's: minimum_value / maximum_value, else minimum_value_warning / maximum_value_warning. They are
Python expressions, so they are evaluated here by Python itself, in a namespace of every setting's resolved
value as MixEngine computes it (`mixengine settings --json`, global scope overlaid with extruder 0), typed by
the definitions, plus Cura's functions (extruderValue(s), resolveOrValue, defaultExtruderPosition) and
`math`. An end whose expression fails or gives no finite number is left out (the caller counts them).
"""
import ast
import json
import math
from dataclasses import dataclass

import helpers

NUMERIC = ("int", "float")
SWITCH_TYPES = ("bool", "enum")


@dataclass
class SettingDef:
    key: str
    type: str
    node: dict

    def text(self, field):
        value = self.node.get(field)
        return None if value is None else str(value)


def definitions(path=helpers.FDMPRINTER):
    """key -> SettingDef for every setting of the definition file (categories left out)."""
    found = {}

    def walk(children):
        for key, node in children.items():
            if node.get("type") != "category":
                found[key] = SettingDef(key, node.get("type", ""), node)
            walk(node.get("children", {}))
    walk(json.loads(path.read_text())["settings"])
    return found


def _typed(text, kind):
    if kind == "float":
        return float(text)
    if kind in ("int", "extruder", "optional_extruder"):
        return int(float(text))
    if kind == "bool":
        return text == "True"
    if kind in ("str", "enum"):
        return text
    try:
        return ast.literal_eval(text)
    except (ValueError, SyntaxError):
        return text


def resolved_context(defs):
    """The resolved values of MixEngine's default machine (fdmprinter), typed, extruder 0 over global."""
    proc = helpers.mixengine("settings", "--json", timeout=120)
    assert proc.returncode == 0, f"mixengine settings failed: {proc.stderr[-500:]}"
    doc = json.loads(proc.stdout)
    merged = dict(doc["global"])
    merged.update(doc["extruders"][0])
    return {k: _typed(v, defs[k].type if k in defs else "") for k, v in merged.items()}


class BoundEvaluator:
    """Evaluates Cura's bound expressions against a resolved context."""

    def __init__(self, context):
        self.context = context
        self.namespace = {
            "math": math,
            "extruderValue": lambda _n, key: context[key],
            "extruderValues": lambda key: [context[key]],
            "resolveOrValue": lambda key: context[key],
            "defaultExtruderPosition": lambda: "0",
            "valueFromContainer": lambda _i, key: context[key],
            "extruderValueFromContainer": lambda _n, key, _i: context[key],
        }

    def value(self, expression):
        """The finite number an expression gives, or None."""
        if expression is None:
            return None
        try:
            result = eval(expression, dict(self.namespace), dict(self.context))  # Cura's own formulas
        except Exception:  # noqa: BLE001 - a bound we cannot evaluate is left out, not an error
            return None
        if isinstance(result, bool) or not isinstance(result, (int, float)) or not math.isfinite(result):
            return None
        return result


@dataclass
class Bounds:
    key: str
    type: str
    low: float | None   # the hard bound if there is one, else the warning bound
    high: float | None
    warn_low: float | None
    warn_high: float | None

    def clamp_int(self):
        if self.type == "int":
            self.low = None if self.low is None else math.ceil(self.low)
            self.high = None if self.high is None else math.floor(self.high)
            self.warn_low = None if self.warn_low is None else math.ceil(self.warn_low)
            self.warn_high = None if self.warn_high is None else math.floor(self.warn_high)
        return self


def numeric_bounds(defs, evaluator):
    """Bounds of every int/float setting; ends that cannot be evaluated are None."""
    result = []
    for key, d in sorted(defs.items()):
        if d.type not in NUMERIC:
            continue
        hard_low, hard_high = evaluator.value(d.text("minimum_value")), evaluator.value(d.text("maximum_value"))
        warn_low = evaluator.value(d.text("minimum_value_warning"))
        warn_high = evaluator.value(d.text("maximum_value_warning"))
        low = hard_low if hard_low is not None else warn_low
        high = hard_high if hard_high is not None else warn_high
        if low is not None and high is not None and low > high:
            low = high = None  # contradictory bounds at the default values: nothing sensible to try
        result.append(Bounds(key, d.type, low, high, warn_low, warn_high).clamp_int())
    return result


def switch_options(defs):
    """key -> list of values for every bool and enum setting (the feature switches)."""
    options = {}
    for key, d in defs.items():
        if d.type == "bool":
            options[key] = ["True", "False"]
        elif d.type == "enum" and isinstance(d.node.get("options"), dict):
            options[key] = sorted(d.node["options"])
    return options


def format_value(value, kind):
    """Text for -s key=value, as Cura's str() would give it."""
    if kind == "int":
        return str(int(value))
    return repr(float(value))
