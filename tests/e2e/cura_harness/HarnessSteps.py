"""Optional steps of a harness job (see tests/e2e/README.md, "Checking a plugin"):

- count the LayerOptimized messages Cura receives (the preview data) and record the engine command;
- run menu items of other plugins' extensions (e.g. MixEngine's orientation) and undo them;
- probe setting definitions, values and the visible-settings preference;
- after the slice: dump scene.gcode_dict, switch to the Preview stage (SimulationView) and wait
  until the layer view has been built, so the screenshot shows the sliced print.
"""
import json
import sys
import time
import traceback

from PyQt5.QtCore import QTimer

from UM.Logger import Logger
from UM.Math.Vector import Vector
from UM.PluginRegistry import PluginRegistry
from UM.Settings.SettingInstance import SettingInstance
from UM.Scene.Iterator.DepthFirstIterator import DepthFirstIterator


def installLayerCounter(app, status):
    """Wrap the backend's LayerOptimized handler (reference §8.5) to count preview layers."""
    backend = app.getBackend()
    name = "cura.proto.LayerOptimized"
    original = backend._message_handlers.get(name)
    status["layer_optimized_received"] = 0
    status["layer_optimized_ids"] = []

    def counted(message):
        status["layer_optimized_received"] += 1
        status["layer_optimized_ids"].append(message.id)
        if original:
            original(message)

    backend._message_handlers[name] = counted


def logThreadStacks():
    """Every thread's stack into cura.log (why did StartSliceJob not finish?)."""
    for thread_id, frame in sys._current_frames().items():
        Logger.log("w", "[CuraHarness] thread %s:\n%s", thread_id, "".join(traceback.format_stack(frame)))


def recordBackendError(app, status, job):
    """Why StartSliceJob gave up: its result and the keys in error on each stack."""
    stack = app.getGlobalContainerStack()
    entry = {"result": str(job.getResult()) if hasattr(job, "getResult") else None,
             "cancelled": job.isCancelled() if hasattr(job, "isCancelled") else None,
             "error": repr(job.getError()) if hasattr(job, "getError") and job.getError() else None}
    if stack is not None:
        entry["error_keys"] = {s.getId(): s.getErrorKeys() for s in [stack] + list(stack.extruderList)}
    entry["nodes"] = nodeStates(app)
    status.setdefault("backend_errors", []).append(entry)
    Logger.log("w", "[CuraHarness] backend error: %s", entry)


def engineCommand(app):
    process = getattr(app.getBackend(), "_process", None)
    return list(process.args) if process is not None else None


def sliceableNodes(app):
    root = app.getController().getScene().getRoot()
    return [n for n in DepthFirstIterator(root) if n.callDecoration("isSliceable")]


def boundingBox(node):
    box = node.getBoundingBox()
    return [[v.x, v.y, v.z] for v in (box.minimum, box.maximum)] if box else None


def nodeStates(app):
    """Name, outside-the-build-volume flag and bounding box (scene frame, Y up) of each model."""
    return [{"name": n.getName(), "outside": n.isOutsideBuildArea(), "bbox": boundingBox(n)} for n in sliceableNodes(app)]


def nodeTransforms(app):
    """{node name: 4x4 world transformation (rows)} of the sliceable nodes."""
    return {n.getName(): n.getWorldTransformation().getData().tolist() for n in sliceableNodes(app)}


def probeSettings(app, keys):
    """For each key: the global stack's value, the machine definition's default_value and
    settable_per_mesh, and whether it is in general/visible_settings."""
    stack = app.getGlobalContainerStack()
    definition = stack.getBottom()
    visible = set((app.getPreferences().getValue("general/visible_settings") or "").split(";"))
    result = {"definition": definition.getId()}
    for key in keys:
        found = definition.findDefinitions(key=key)
        result[key] = {"value": stack.getProperty(key, "value"),
                       "default_value": found[0].default_value if found else None,
                       "settable_per_mesh": found[0].settable_per_mesh if found else None,
                       "visible": key in visible, "defined": bool(found),
                       # the settings panel lists an enum's options only when they are an OrderedDict
                       "options_type": type(found[0].options).__name__ if found else None}
    return result


def pluginRegistry():
    return PluginRegistry.getInstance()


def pluginObject(plugin_id):
    try:
        return PluginRegistry.getInstance().getPluginObject(plugin_id)
    except Exception:  # not installed / not loaded
        return None


class ActionRunner:
    """Runs job["actions"] one after another: {"plugin": id, "menu": item, "undo": bool}.
    Records node transforms before, after and after undo, and the plugin's last_result."""

    def __init__(self, app, status, actions, on_done):
        self._app = app
        self._status = status
        self._pending = list(actions)
        self._on_done = on_done
        status["actions"] = []

    def start(self):
        self._next()

    def _next(self):
        if not self._pending:
            self._on_done()
            return
        action = self._pending.pop(0)
        record = {"action": action, "before": nodeTransforms(self._app)}
        self._status["actions"].append(record)
        extension = pluginObject(action["plugin"])
        if extension is None or action["menu"] not in extension.getMenuItemList():
            record["error"] = "no menu item %r in plugin %r" % (action["menu"], action["plugin"])
            self._next()
            return
        record["t_start"] = time.time()
        extension.activateMenuItem(action["menu"])
        self._waitIdle(extension, record, action)

    def _waitIdle(self, extension, record, action):
        worker = getattr(extension, "orient", None)  # the MixEngine extension's asynchronous action
        if worker is not None and worker.isBusy() and time.time() - record["t_start"] < 600:
            QTimer.singleShot(200, lambda: self._waitIdle(extension, record, action))
            return
        record["seconds"] = round(time.time() - record["t_start"], 2)
        record["result"] = getattr(worker, "last_result", None)
        QTimer.singleShot(1500, lambda: self._afterSettle(record, action))  # let PlatformPhysics drop the models

    def _afterSettle(self, record, action):
        record["after"] = nodeTransforms(self._app)
        if action.get("undo"):
            self._app.getOperationStack().undo()
            record["after_undo"] = nodeTransforms(self._app)
            if action.get("redo"):
                self._app.getOperationStack().redo()
                record["after_redo"] = nodeTransforms(self._app)
        self._next()


def setPerObjectSettings(node, values):
    """Per-model settings, as Cura's per-model settings tool adds them (a SettingInstance in the top
    container of the node's stack). A key that is not settable per mesh raises."""
    stack = node.callDecoration("getStack")
    top = stack.getTop()
    for key, value in values.items():
        definition = stack.getSettingDefinition(key)
        if definition is None or not definition.settable_per_mesh:
            raise RuntimeError("%s is not a per-object setting" % key)
        instance = SettingInstance(definition, top)
        instance.setProperty("value", value)
        top.addInstance(instance)


def addSupportBlockers(app, model_nodes, blockers):
    """Support blockers as the toolbar's Support Blocker tool adds them: the tool's own method makes its
    10 mm cube (anti_overhang_mesh) on model `model` at `position` (scene frame, mm, Y up), as a click on
    that model at that point does. Returns the names and anti_overhang_mesh values of the cubes added."""
    tool = app.getController().getTool("SupportEraser")
    if tool is None:
        raise RuntimeError("the Support Blocker tool (SupportEraser) is not loaded")
    added = []
    for blocker in blockers:
        parent = model_nodes[int(blocker.get("model", 0))][0]
        before = set(id(n) for n in DepthFirstIterator(app.getController().getScene().getRoot()))
        tool._createEraserMesh(parent, Vector(*blocker["position"]))
        for node in DepthFirstIterator(app.getController().getScene().getRoot()):
            if id(node) not in before:
                stack = node.callDecoration("getStack")
                added.append({"name": node.getName(),
                              "anti_overhang_mesh": bool(stack and stack.getProperty("anti_overhang_mesh", "value"))})
    return added


def dumpGcode(app, path):
    """scene.gcode_dict[0] as {"chunks": [...]} (chunk boundaries kept)."""
    scene = app.getController().getScene()
    chunks = list(getattr(scene, "gcode_dict", {}).get(0) or [])
    with open(path, "w", encoding="utf-8") as f:
        json.dump({"chunks": chunks}, f)
    return len(chunks)


def sceneLayerCount(app):
    """Layers in the preview's layer data (built by ProcessSlicedLayersJob), or 0."""
    root = app.getController().getScene().getRoot()
    for node in DepthFirstIterator(root):
        layer_data = node.callDecoration("getLayerData")
        if layer_data:
            return len(layer_data.getLayers())
    return 0


def showPreview(app, status, then, camera=None, deadline_s=90):
    """Switch to the Preview stage and call then() once the layer view exists (or at the deadline).
    camera: {"position": [x, y, z], "look_at": [x, y, z]} in the scene frame (mm, Y up)."""
    controller = app.getController()
    controller.setActiveStage("PreviewStage")
    controller.setActiveView("SimulationView")
    if camera:
        active = controller.getScene().getActiveCamera()
        active.setPosition(Vector(*camera["position"]))
        active.lookAt(Vector(*camera.get("look_at", (0, 0, 0))))
    t0 = time.time()

    def poll():
        layers = sceneLayerCount(app)
        if layers or time.time() - t0 > deadline_s:
            status["scene_layers"] = layers
            status["preview_wait_s"] = round(time.time() - t0, 2)
            Logger.log("i", "[CuraHarness] preview: %d layers in the scene", layers)
            QTimer.singleShot(3000, then)  # let the view render the layers
        else:
            QTimer.singleShot(500, poll)

    poll()
