"""The filament mix in Cura's layer view (Preview stage, "Material Color" scheme).

On a mixing printer (mixing_mode dual, gradient or color) the material of a line is the colour the
engine predicts for what leaves the nozzle there: its pigment model after the mixing chamber, written
into the G-code as ";PREDICTED_COLOR:#rrggbb" comments. When Cura's ProcessSlicedLayersJob builds the
layer view of a slice (LayerDataBuilder.build, wrapped here), every extruding move of the G-code Cura
holds for that build plate is read with the colour in force (MixGCode) and that colour is written into
the "colors" vertex attribute of the line the move printed, which only the Material Color scheme draws
(LayerRecolour). The plugin computes no colour of its own: G-code without these comments (an older
engine) leaves Cura's colours as they are. The layer slider and the simulation use the same vertices,
so they follow. Line Type, Speed, ... and non-mixing printers are untouched. A legend of the channels
(qml/MixLegend.qml) shows over the Preview while the Material Color scheme is on.

Private Cura API: the wrapped LayerDataBuilder.build, the caller's job (its build plate), and
scene.gcode_dict. Any failure is logged and leaves Cura's own colours.
"""
import os
import sys
import time

from PyQt5.QtCore import QObject, pyqtProperty, pyqtSignal

from UM.Backend.Backend import BackendState
from UM.Logger import Logger

from cura import LayerDataBuilder

from . import LayerRecolour, MixColours, MixGCode

CHANNEL_NAMES = "ABCDEFGH"
LAYER_VIEW_TYPE = "layerview/layer_view_type"  # 0 = Material Color (SimulationView)
MATERIAL_COLOR = 0


class MixLegend(QObject):
    """What the legend overlay shows: the channels (name, colour) and whether to show it."""
    changed = pyqtSignal()

    def __init__(self, parent=None):
        super().__init__(parent)
        self._channels = []
        self._shown = False
        self._title = "Filament mix"

    @pyqtProperty("QVariantList", notify=changed)
    def channels(self):
        return self._channels

    @pyqtProperty(bool, notify=changed)
    def shown(self):
        return self._shown

    @pyqtProperty(str, notify=changed)
    def title(self):
        return self._title

    def set(self, channels, shown, title):
        if (channels, shown, title) != (self._channels, self._shown, self._title):
            self._channels, self._shown, self._title = channels, shown, title
            self.changed.emit()


def _hex(rgb):
    return "#%02x%02x%02x" % tuple(int(round(max(0.0, min(1.0, c)) * 255)) for c in rgb)


def _callerJob():
    """The ProcessSlicedLayersJob that called LayerDataBuilder.build (None for other callers, such as
    the G-code reader)."""
    frame = sys._getframe(2)
    caller = frame.f_locals.get("self") if frame else None
    return caller if type(caller).__name__ == "ProcessSlicedLayersJob" else None


class MixPreview:
    def __init__(self, app, default_colours):
        self._app = app
        self._default_colours = default_colours
        self.legend = MixLegend()
        self._legend_item = None
        self._mix_active = False
        self._channels = []
        self.last = {"state": "no layer view built yet"}

    # ---- installation ------------------------------------------------------------------------
    def install(self):
        builder = LayerDataBuilder.LayerDataBuilder
        original = getattr(builder, "_mixengine_original_build", None) or builder.build
        preview = self

        def build(self, material_color_map, line_type_brightness=1.0):
            layer_data = original(self, material_color_map, line_type_brightness)
            job = _callerJob()
            if job is not None:
                preview.recolour(self, layer_data, job.getBuildPlate())
            return layer_data

        builder._mixengine_original_build = original
        builder.build = build
        prefs = self._app.getPreferences()
        prefs.preferenceChanged.connect(self._onPreferenceChanged)
        controller = self._app.getController()
        controller.activeStageChanged.connect(self._updateLegend)
        controller.activeViewChanged.connect(self._updateLegend)
        self._app.getBackend().backendStateChange.connect(self._onBackendState)

    def createLegend(self, qml_path):
        """The overlay in the main window (after initializationFinished)."""
        if not os.path.isfile(qml_path):
            Logger.log("w", "[MixEngine] no legend: %s missing", qml_path)
            return
        item = self._app.createQmlComponent(qml_path, {"mixLegend": self.legend})
        window = self._app.getMainWindow()
        if item is None or window is None:
            Logger.log("w", "[MixEngine] the mix legend could not be created")
            return
        item.setParentItem(window.contentItem())
        self._legend_item = item

    # ---- the layer view ----------------------------------------------------------------------
    def _settings(self):
        stack = self._app.getGlobalContainerStack()
        if stack is None or stack.getProperty("mixing_mode", "value") in (None, "single"):
            return None
        channels = int(stack.getProperty("mixing_channels", "value") or 2)
        return {
            "dialect": stack.getProperty("mixing_dialect", "value"),
            "colours": MixColours.channelColours(stack.getProperty("mixing_channel_colors", "value"), channels,
                                                 self._default_colours),
        }

    def recolour(self, builder, layer_data, build_plate):
        t0 = time.time()
        try:
            settings = self._settings()
            chunks = getattr(self._app.getController().getScene(), "gcode_dict", {}).get(build_plate)
            if settings is None or not chunks:
                self._done({"state": "not a mixing slice" if settings is None else "no G-code"}, None)
                return
            info = self._recolour(builder, layer_data, chunks, settings)
        except Exception as e:  # never break Cura's layer view
            Logger.logException("w", "[MixEngine] colouring the layer view by mix failed")
            info, settings = {"state": "failed: %r" % e}, None
        info["seconds"] = round(time.time() - t0, 3)
        self._done(info, settings)

    def _recolour(self, builder, layer_data, chunks, settings):
        moves = MixGCode.read(chunks, settings["dialect"])
        if not moves.extrusions():
            return {"state": "no extrusion in the G-code"}
        if not moves.predicted():
            return {"state": "no predicted colour in the G-code; colours left alone", "moves": moves.extrusions()}
        attribute = layer_data.getAttribute("colors")
        layer_ids = MixGCode.viewLayerIds(moves)
        result = LayerRecolour.recolour(builder.getLayers(), attribute["value"], moves, moves.moveColours(),
                                        layer_ids)
        if result is None:
            return {"state": "vertex count differs from the layer view; colours left alone"}
        attribute["value"] = result.colours
        attribute["value"].setflags(write=False)
        return {"state": "coloured", "lines": result.lines, "matched": result.matched,
                "coloured": result.coloured, "layers": len(moves.order), "moves": moves.extrusions(),
                "predicted_moves": moves.predicted(), "distinct_colours": len(moves.colours),
                "malformed_comments": moves.malformed}

    def _done(self, info, settings):
        info["channels"] = [_hex(c) for c in settings["colours"]] if settings else []
        self.last = info
        Logger.log("i", "[MixEngine] layer view by mix: %s", info)
        active = info.get("state") == "coloured"
        channels = [{"name": CHANNEL_NAMES[i], "color": c} for i, c in enumerate(info["channels"])] if active else []
        self._app.callLater(self._setMixActive, active, channels)

    # ---- the legend --------------------------------------------------------------------------
    def _setMixActive(self, active, channels):
        self._mix_active = active
        self._channels = channels
        self._updateLegend()

    def _onBackendState(self, state):
        if state == BackendState.Processing:  # a new slice: the old layer view and its legend go
            self._setMixActive(False, [])

    def _onPreferenceChanged(self, name):
        if name == LAYER_VIEW_TYPE:
            self._updateLegend()

    def _updateLegend(self):
        controller = self._app.getController()
        stage = controller.getActiveStage()
        view = controller.getActiveView()
        scheme = self._app.getPreferences().getValue(LAYER_VIEW_TYPE)
        in_preview = (stage is not None and stage.getPluginId() == "PreviewStage" and view is not None
                      and view.getPluginId() == "SimulationView")
        shown = bool(self._mix_active and in_preview and str(scheme) == str(MATERIAL_COLOR))
        self.legend.set(self._channels, shown, "Filament mix")
