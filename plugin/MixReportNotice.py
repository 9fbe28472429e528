"""One Cura message after a mixing slice: what the engine's ;MIXING.* report says (MixReport.py).

When a slice is done (BackendState.Done) the G-code Cura holds for the active build plate
(scene.gcode_dict; its first chunk is the prefix, the G-code header, where the engine writes the report)
is read. A mixing print's report replaces the previous message: how much of the visible surface comes out
right, the purge (in grams too when the material's density is known) and what twice the tolerance would
need, the volume that could not be purged, and whether printing the models one at a time would remove the
changes. A slice without the report (not a mixing print, or another engine) hides the message, and so
does the start of a new slice (its figures no longer hold).

Private Cura API: scene.gcode_dict (set by CuraEngineBackend). Any failure is logged and hides the message.
"""
from UM.Backend.Backend import BackendState
from UM.Logger import Logger
from UM.Message import Message

from . import MixReport

STALE = (BackendState.NotStarted, BackendState.Processing, BackendState.Error, BackendState.Disabled)


class MixReportNotice:
    def __init__(self, app):
        self._app = app
        self._message = None
        self.last = {"state": "no slice yet"}

    def connect(self):
        self._app.getBackend().backendStateChange.connect(self._onBackendState)

    def text(self):
        return self._message.getText() if self._message else None

    def visible(self):
        return bool(self._message and self._message.visible)

    def status(self):
        return dict(self.last, visible=self.visible(), message=self.text())

    def _onBackendState(self, state):
        if state == BackendState.Done:
            self.update()
        elif state in STALE and self._message is not None:
            self._hide()
            self.last = {"state": "hidden: a new slice"}

    def update(self):
        """Read the report of the G-code Cura holds and show it (or hide the message when there is none)."""
        try:
            report = MixReport.read(self._gcode())
            if report is None:
                self._hide()
                self.last = {"state": "not a mixing slice"}
                return
            density = self._density()
            text = MixReport.messageText(report, density)
        except Exception as e:  # never break Cura's slicing
            Logger.logException("w", "[MixEngine] reading the mixing report failed")
            self._hide()
            self.last = {"state": "failed: %r" % e}
            return
        self._hide()
        self._message = Message(text, lifetime=0, title=MixReport.TITLE)
        self._message.show()
        self.last = {"state": "shown", "density": density, "report": report.asDict()}
        Logger.log("i", "[MixEngine] mixing report: %s", report.lines)

    def _hide(self):
        if self._message is not None:
            self._message.hide()
            self._message = None

    def _gcode(self):
        scene = self._app.getController().getScene()
        model = self._app.getMultiBuildPlateModel() if hasattr(self._app, "getMultiBuildPlateModel") else None
        plate = model.activeBuildPlate if model is not None else 0
        return getattr(scene, "gcode_dict", {}).get(plate)

    def _density(self):
        """The density (g/cm³) of the material of the enabled extruders, None when unknown or when they differ."""
        stack = self._app.getGlobalContainerStack()
        if stack is None:
            return None
        found = set()
        for extruder in stack.extruderList:
            if not extruder.isEnabled:
                continue
            properties = extruder.material.getMetaDataEntry("properties", None) or {}
            try:
                density = float(properties.get("density"))
            except (TypeError, ValueError):
                return None
            if density <= 0:
                return None
            found.add(density)
        return found.pop() if len(found) == 1 else None
