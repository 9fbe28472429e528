"""The colour picker's part that needs no Qt: reading and writing mixing_target_color (#rrggbb) on the
selected models' per-object setting stacks, the stacks Cura's Per Model Settings tool edits. A model
without per-object settings gets them (Cura's SettingOverrideDecorator, passed in as `decorate`)."""
import re

KEY = "mixing_target_color"
_HEX = re.compile(r"^#?([0-9a-fA-F]{6})$")
_HEX_ALPHA = re.compile(r"^#([0-9a-fA-F]{2})([0-9a-fA-F]{6})$")  # QColor.name(HexArgb): #aarrggbb


def normalise(text):
    """'#FF8000', 'ff8000' or Qt's '#ffff8000' → '#ff8000'; None when it is no colour."""
    text = (text or "").strip()
    match = _HEX.match(text) or _HEX_ALPHA.match(text)
    if not match:
        return None
    return "#" + match.groups()[-1].lower()


def currentColour(nodes, default):
    """The first selected model's own target colour, else the value its stack resolves (default)."""
    for node in nodes:
        stack = node.callDecoration("getStack")
        if stack is not None:
            value = normalise(stack.getProperty(KEY, "value"))
            if value:
                return value
    return normalise(default) or "#808080"


def applyColour(nodes, colour, decorate):
    """Sets mixing_target_color on every node's per-object settings; returns how many were set."""
    colour = normalise(colour)
    if colour is None:
        return 0
    count = 0
    for node in nodes:
        stack = node.callDecoration("getStack")
        if stack is None:
            node.addDecorator(decorate())
            stack = node.callDecoration("getStack")
        if stack is None:
            continue
        stack.getTop().setProperty(KEY, "value", colour)
        count += 1
    return count
