"""Menu action "Optimize dual-nozzle orientation".

The selected models (all models on the plate when nothing is selected) are split by the extruder
that prints them: part A = the models of the lower extruder position, part B = the other one. Both
are written, as placed in the scene, to temporary binary STL files in the engine's Z-up frame, and
`mixengine orient A.stl B.stl --offset dx,dy --report r.json` runs on a worker thread with the
nozzle offset and the dual_orientation_* settings of the active printer. The rotation of the report
is turned into the scene's frame and applied to every model about the parts' common centre as one
GroupedOperation (RotateOperation + TranslateOperation per model), so Ctrl+Z undoes it in one step.
Cura then drops the models back onto the plate.
"""
import json
import os
import shutil
import subprocess
import tempfile
import threading

import numpy
from UM.Logger import Logger
from UM.Math.Quaternion import Quaternion
from UM.Math.Vector import Vector
from UM.Message import Message
from UM.Operations.GroupedOperation import GroupedOperation
from UM.Operations.RotateOperation import RotateOperation
from UM.Operations.TranslateOperation import TranslateOperation
from UM.Scene.Iterator.DepthFirstIterator import DepthFirstIterator
from UM.Scene.Selection import Selection

from . import OrientMath

TITLE = "Dual-nozzle orientation"
# setting key -> `mixengine orient` option (orientation.def.json)
SETTING_FLAGS = (("dual_orientation_method", "--method"), ("dual_orientation_measure", "--measure"),
                 ("dual_orientation_objective", "--objective"), ("dual_orientation_resolution", "--resolution"),
                 ("dual_orientation_verify_count", "--verify"), ("dual_orientation_grid_step", "--grid-step"))


def _isTopLevel(node):
    parent = node.getParent()
    return parent is None or not parent.callDecoration("isGroup")


def _leaves(node):
    if node.callDecoration("isGroup"):
        return [c for c in DepthFirstIterator(node) if c is not node and c.callDecoration("isSliceable")]
    return [node] if node.callDecoration("isSliceable") else []


def _extruderPosition(node):
    position = node.callDecoration("getActiveExtruderPosition")
    try:
        return int(position)
    except (TypeError, ValueError):
        return 0


def _engineCorners(node):
    """The node's triangles in world coordinates, engine frame (x, -z, y), one row per corner."""
    mesh = node.getMeshDataTransformed()
    vertices = mesh.getVertices()
    if mesh.hasIndices():
        vertices = vertices[mesh.getIndices().reshape(-1)]
    corners = vertices[:, [0, 2, 1]].astype("float64")
    corners[:, 1] *= -1
    return corners


class OrientAction:
    def __init__(self, app, find_engine):
        self._app = app
        self._findEngine = find_engine  # () -> (path or None, how)
        self._busy = False
        self.last_result = None  # {"status": ..., "report": {...}, "nodes": [...]} for tests and the log

    def isBusy(self):
        return self._busy

    # ---- main thread: collect, export, start ----------------------------------------------
    def run(self):
        if self._busy:
            return
        try:
            self._start()
        except Exception as e:
            Logger.logException("e", "[MixEngine] orientation failed")
            self._done({"status": "error", "error": str(e)})

    def _nodes(self):
        selected = [n for n in Selection.getAllSelectedObjects() if _leaves(n)]
        if selected:
            return [n for n in selected if _isTopLevel(n)] or selected
        root = self._app.getController().getScene().getRoot()
        return [n for n in DepthFirstIterator(root)
                if n is not root and _isTopLevel(n) and _leaves(n) and n.getParent() is root]

    def _start(self):
        nodes = self._nodes()
        parts = {}
        for node in nodes:
            for leaf in _leaves(node):
                parts.setdefault(_extruderPosition(leaf), []).append(leaf)
        if len(parts) != 2:
            self._done({"status": "not_two_parts", "positions": sorted(parts)},
                       "Put the models on two extruders (part A on one nozzle, part B on the other): "
                       "the orientation pass needs exactly two parts; found %d." % len(parts))
            return
        engine, how = self._findEngine()
        if engine is None:
            self._done({"status": "no_engine", "error": how}, "No mixengine binary: " + how)
            return
        low, high = sorted(parts)
        stack = self._app.getGlobalContainerStack()
        extruders = stack.extruderList
        offset = [extruders[high].getProperty(k, "value") - extruders[low].getProperty(k, "value")
                  for k in ("machine_nozzle_offset_x", "machine_nozzle_offset_y")]
        workdir = tempfile.mkdtemp(prefix="mixengine_orient_")
        files = []
        for position in (low, high):
            path = os.path.join(workdir, "part_%s_extruder%d.stl" % ("ab"[len(files)], position))
            corners = numpy.concatenate([_engineCorners(n) for n in parts[position]])
            with open(path, "wb") as f:
                f.write(OrientMath.binaryStl(corners))
            files.append(path)
        report = os.path.join(workdir, "report.json")
        command = [engine, "orient", files[0], files[1], "--offset", "%g,%g" % tuple(offset), "--report", report]
        command += self._settingFlags(stack)
        self._busy = True
        message = Message("Searching the orientation with the least nozzle interference...", title=TITLE,
                          lifetime=0, progress=-1, dismissable=False)
        message.show()
        Logger.log("i", "[MixEngine] %s", " ".join(command))
        threading.Thread(target=self._runEngine, args=(command, report, workdir, nodes, message),
                         name="MixEngineOrient", daemon=True).start()

    @staticmethod
    def _settingFlags(stack):
        flags = []
        for key, flag in SETTING_FLAGS:
            value = stack.getProperty(key, "value")
            if value is None:
                continue
            if key == "dual_orientation_grid_step":
                value = int(round(float(value)))  # the command takes whole degrees
            flags += [flag, str(value)]
        return flags

    # ---- worker thread ---------------------------------------------------------------------
    def _runEngine(self, command, report_path, workdir, nodes, message):
        result = {"status": "error", "command": command}
        try:
            proc = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=900,
                                  stdin=subprocess.DEVNULL)
            result["stdout"] = proc.stdout.decode("utf-8", "replace")
            result["stderr"] = proc.stderr.decode("utf-8", "replace")
            if proc.returncode != 0:
                result["error"] = result["stderr"].strip() or "exit code %d" % proc.returncode
            else:
                with open(report_path, encoding="utf-8") as f:
                    result["report"] = json.load(f)
                result["status"] = result["report"].get("status", "ok")
        except Exception as e:
            result["error"] = repr(e)
        finally:
            shutil.rmtree(workdir, ignore_errors=True)
        self._app.callLater(self._apply, result, nodes, message)

    # ---- main thread: rotate ---------------------------------------------------------------
    def _apply(self, result, nodes, message):
        message.hide()
        if result["status"] == "nothing_to_optimise":
            self._done(result, "Nothing to optimise: only one part.")
            return
        if result["status"] != "ok":
            self._done(result, "mixengine orient failed: %s" % result.get("error", result["status"]))
            return
        report = result["report"]
        rotation = OrientMath.engineToSceneRotation(tuple(tuple(r) for r in report["rotation"]))
        if not OrientMath.isRotation(rotation):
            self._done(dict(result, status="error"), "mixengine orient returned a matrix that is not a rotation.")
            return
        centre = OrientMath.engineToScenePoint(report["centre_mm"])
        shift = Vector(*OrientMath.translationAfterRotation(rotation, centre))
        quaternion = Quaternion(*OrientMath.quaternionFromMatrix(rotation))
        operation = GroupedOperation()
        for node in nodes:
            operation.addOperation(RotateOperation(node, quaternion))
            operation.addOperation(TranslateOperation(node, shift))
        operation.push()
        result["scene_rotation"] = [list(r) for r in rotation]
        result["nodes"] = [n.getName() for n in nodes]
        self._done(result, "Rotated %d model(s): latitude %.1f°, longitude %.1f°, spin %.1f°. Interference "
                   "V %.1f mm³ before, %.1f mm³ after (Ctrl+Z undoes it)."
                   % (len(nodes), report.get("latitude_deg", 0), report.get("longitude_deg", 0),
                      report.get("spin_deg", 0), report.get("v_before_mm3", 0), report.get("v_after_mm3", 0)))

    def _done(self, result, text=None):
        self.last_result = result
        self._busy = False
        if text:
            Logger.log("i", "[MixEngine] orientation: %s", text)
            Message(text, title=TITLE).show()
