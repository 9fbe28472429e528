"""Extensions → MixEngine → "Target colour of the selected models…": a colour dialog (QtQuick.Dialogs
ColorDialog, qml/TargetColourDialog.qml) that writes mixing_target_color into the selected models'
Per Model Settings, where it then shows as #rrggbb next to the other per-model settings (Colour mode:
MixEngine mixes the filaments to that colour)."""
import os

from PyQt5.QtCore import QObject, pyqtProperty, pyqtSignal, pyqtSlot

from UM.Logger import Logger
from UM.Message import Message
from UM.Scene.Selection import Selection

from . import TargetColour

ITEM = "Target colour of the selected models..."


class TargetColourPicker(QObject):
    colourChanged = pyqtSignal()

    def __init__(self, app, parent=None):
        super().__init__(parent)
        self._app = app
        self._dialog = None
        self._colour = "#808080"

    @pyqtProperty(str, notify=colourChanged)
    def colour(self):
        return self._colour

    def run(self):
        nodes = Selection.getAllSelectedObjects()
        if not nodes:
            Message("Select a model first, then pick its target colour.", title="MixEngine").show()
            return
        stack = self._app.getGlobalContainerStack()
        default = stack.getProperty(TargetColour.KEY, "value") if stack else None
        self._colour = TargetColour.currentColour(nodes, default)
        self.colourChanged.emit()
        if self._dialog is None:
            path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "qml", "TargetColourDialog.qml")
            self._dialog = self._app.createQmlComponent(path, {"manager": self})
        if self._dialog is None:
            Logger.log("e", "[MixEngine] the colour dialog could not be created")
            return
        self._dialog.open()

    @pyqtSlot(str)
    def accept(self, colour):
        from cura.Settings.SettingOverrideDecorator import SettingOverrideDecorator
        nodes = Selection.getAllSelectedObjects()
        count = TargetColour.applyColour(nodes, colour, SettingOverrideDecorator)
        Logger.log("i", "[MixEngine] mixing_target_color %s on %d model(s)", TargetColour.normalise(colour), count)
