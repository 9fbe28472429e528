"""One Cura message naming the active settings MixEngine does not act on yet (NotHonoured.py).

Checked (debounced) whenever a value, a profile, the printer or a per-model setting changes, while
Cura slices with mixengine. The values in force come from the global stack, every enabled extruder
stack and every model's per-object settings; the default a value is compared with is the machine
definition's (its `value` formula evaluated on the same stack, else its default_value). The message
is replaced only when the list changes, so a message the user closed stays closed until then.
"""
from PyQt5.QtCore import QTimer

from UM.Logger import Logger
from UM.Message import Message
from UM.Scene.Iterator.DepthFirstIterator import DepthFirstIterator
from UM.Settings.SettingFunction import SettingFunction

from . import NotHonoured

TITLE = "MixEngine: settings without effect"


class SettingsNotice:
    def __init__(self, app, entries, active):
        self._app = app
        self._entries = entries
        self._active = active  # () -> True while the backend is mixengine
        self._message = None
        self._rows = []
        self._stacks = []
        self._timer = QTimer()
        self._timer.setSingleShot(True)
        self._timer.setInterval(300)
        self._timer.timeout.connect(self.check)

    @property
    def rows(self):
        return list(self._rows)

    def text(self):
        return self._message.getText() if self._message else None

    def connect(self):
        if not self._entries:
            return
        self._app.globalContainerStackChanged.connect(self._onStackChanged)
        self._app.getController().getScene().sceneChanged.connect(self._schedule)
        self._onStackChanged()

    def _onStackChanged(self):
        for stack in self._stacks:
            stack.propertyChanged.disconnect(self._onPropertyChanged)
            stack.containersChanged.disconnect(self._schedule)
        stack = self._app.getGlobalContainerStack()
        self._stacks = [stack] + list(stack.extruderList) if stack else []
        for s in self._stacks:
            s.propertyChanged.connect(self._onPropertyChanged)
            s.containersChanged.connect(self._schedule)
        self._schedule()

    def _onPropertyChanged(self, key, property_name):
        if property_name == "value":
            self._schedule()

    def _schedule(self, *args):
        self._timer.start()

    # ---- the check ---------------------------------------------------------------------------
    def _default(self, definition, stack, key):
        value = definition.getProperty(key, "value")
        if value is None:
            value = definition.getProperty(key, "default_value")
        return value(stack) if isinstance(value, SettingFunction) else value

    def _found(self, stack):
        definition = stack.definition
        extruders = [e for e in stack.extruderList if e.isEnabled]
        keys = [k for k in self._entries if definition.findDefinitions(key=k)
                and (len(extruders) > 1 or not NotHonoured.multiExtruderOnly(self._entries[k]))]
        for key in keys:
            if stack.getProperty(key, "enabled") is False:
                continue  # hidden in Cura: neither engine reads it (the engine's rule too)
            yield key, stack.getProperty(key, "value"), self._default(definition, stack, key), "global"
            for extruder in extruders:
                # one extruder (a mixing printer): its values are the print's, named without a place
                where = "extruder %s" % extruder.getMetaDataEntry("position", "0") if len(extruders) > 1 else "global"
                yield key, extruder.getProperty(key, "value"), self._default(definition, extruder, key), where
        root = self._app.getController().getScene().getRoot()
        for node in DepthFirstIterator(root):
            node_stack = node.callDecoration("getStack") if node.callDecoration("isSliceable") else None
            if node_stack is None:
                continue
            for key in keys:
                if node_stack.getTop().getProperty(key, "value") is not None:
                    yield (key, node_stack.getProperty(key, "value"), self._default(definition, stack, key),
                           node.getName())

    def check(self):
        stack = self._app.getGlobalContainerStack()
        try:
            rows = NotHonoured.offending(self._entries, self._found(stack)) if stack and self._active() else []
        except Exception:
            Logger.logException("w", "[MixEngine] checking the settings MixEngine does not act on failed")
            return
        if rows == self._rows:
            return
        self._rows = rows
        if self._message:
            self._message.hide()
            self._message = None
        if rows:
            text = NotHonoured.messageText(rows, lambda key: self._label(stack, key),
                                           lambda key, value: self._shown(stack, key, value))
            self._message = Message(text, lifetime=0, title=TITLE)
            self._message.show()
            Logger.log("i", "[MixEngine] settings without effect: %s", [r[0] for r in rows])

    @staticmethod
    def _label(stack, key):
        found = stack.definition.findDefinitions(key=key)
        return found[0].label if found else key

    @staticmethod
    def _shown(stack, key, value):
        found = stack.definition.findDefinitions(key=key)
        options = getattr(found[0], "options", None) if found else None
        if options and str(value) in options:
            return options[str(value)]
        return {True: "on", False: "off"}.get(value, str(value)) if isinstance(value, bool) else str(value)
