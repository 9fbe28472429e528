"""Scripted Cura 4.13 session: set up a machine from a JSON job, slice, record the Slice message.

The job file is named by the environment variable CURA_HARNESS_JOB (see tests/e2e/README.md for
all fields). Without it this extension does nothing, so installing the plugin is harmless.
"""
import json
import os
import time

from PyQt5.QtCore import QTimer, QUrl
from PyQt5.QtGui import QGuiApplication

from UM.Backend.Backend import BackendState
from UM.Backend.SignalSocket import SignalSocket
from UM.Extension import Extension
from UM.Logger import Logger
from UM.Scene.Iterator.DepthFirstIterator import DepthFirstIterator

from . import HarnessSteps, SliceRecord

DEFAULT_MODEL = "/usr/lib/cura/plugins/SimulationView/resources/nozzle.stl"


def _perPosition(value, count):
    """A job field that is either one value for all extruders or {"position": value}."""
    if value is None:
        return {}
    if isinstance(value, dict):
        return {str(k): v for k, v in value.items()}
    return {str(i): value for i in range(count)}


class HarnessExtension(Extension):
    def __init__(self, app):
        super().__init__()
        self._app = app
        self._t0 = time.time()
        self._job = None
        job_path = os.environ.get("CURA_HARNESS_JOB")
        if not job_path:
            return
        with open(job_path, encoding="utf-8") as f:
            self._job = json.load(f)
        self._status = {"job": job_path, "events": {}, "errors": [], "slice_messages_sent": 0}
        self._slice = None
        self._finished = False
        self._models = list(self._job.get("models") or [DEFAULT_MODEL])
        self._loaded_nodes = set()
        self._model_nodes = []  # [nodes of model n], in load order
        self._installSendHook()
        app.initializationFinished.connect(self._onInitializationFinished)
        Logger.log("i", "[CuraHarness] job %s", job_path)

    # ---- bookkeeping -------------------------------------------------------------------
    def _event(self, name):
        self._status["events"][name] = round(time.time() - self._t0, 3)
        Logger.log("i", "[CuraHarness] %s at %.2f s", name, self._status["events"][name])

    def _error(self, text):
        self._status["errors"].append(text)
        Logger.log("e", "[CuraHarness] %s", text)

    # ---- outgoing message hook (reference §8.5) -----------------------------------------
    def _installSendHook(self):
        original = SignalSocket.sendMessage
        harness = self

        def sendMessage(socket, message):
            if message.getTypeName() == "cura.proto.Slice":
                harness._slice = SliceRecord.sliceToDict(message)
                harness._status["slice_messages_sent"] += 1
                harness._event("slice_sent")
                harness._status["engine_command"] = HarnessSteps.engineCommand(harness._app)
                if not harness._job.get("wait_for_done", True):
                    harness._app.callLater(harness._finish, "slice sent")
            return original(socket, message)

        SignalSocket.sendMessage = sendMessage

    # ---- scripted session ---------------------------------------------------------------
    def _onInitializationFinished(self):
        self._event("initialization_finished")
        QTimer.singleShot(int(float(self._job.get("timeout", 150)) * 1000), self._onTimeout)
        self._app.callLater(self._setUp)

    def _setUp(self):
        try:
            self._setUpMachine()
        except Exception as e:  # record and stop rather than hang until the timeout
            Logger.logException("e", "[CuraHarness] set-up failed")
            self._finish("set-up failed: %r" % e)
            return
        backend = self._app.getBackend()
        backend.backendStateChange.connect(self._onBackendState)
        HarnessSteps.installLayerCounter(self._app, self._status)
        backend.backendError.connect(self._onBackendError)  # a bound method: UM signals keep weak references
        if self._job.get("probe_settings"):
            self._status["settings_probe"] = HarnessSteps.probeSettings(self._app, self._job["probe_settings"])
        if self._job.get("plugin_status"):
            plugin = HarnessSteps.pluginObject(self._job["plugin_status"])
            self._status["plugin_status"] = plugin.status() if hasattr(plugin, "status") else None
        self._app.fileCompleted.connect(self._onFileCompleted)
        # The build volume follows a new machine on a timer; a model arranged before that can land
        # outside the plate (seen with a 190 mm plate: "Nothing to slice").
        QTimer.singleShot(int(self._job.get("load_delay_ms", 1500)), self._loadNextModel)

    def _setUpMachine(self):
        job, app = self._job, self._app
        engine = job.get("engine")
        prefs = app.getPreferences()
        if engine and prefs.getValue("backend/location") != engine:
            # cura.cfg written by the driver normally did this already (reference §7).
            prefs.setValue("backend/location", engine)
            backend = app.getBackend()
            backend._terminate()
            backend._createSocket()
        machine_manager = app.getMachineManager()
        if not machine_manager.addMachine(job["machine"]):
            raise RuntimeError("addMachine(%s) failed" % job["machine"])
        self._event("machine_added")
        self._tidyGui()
        stack = app.getGlobalContainerStack()
        count = len(stack.extruderList)
        for position, name in _perPosition(job.get("variant"), count).items():
            machine_manager.setVariantByName(position, name)
            if stack.extruderList[int(position)].variant.getName() != name:
                raise RuntimeError("variant %s not available for extruder %s" % (name, position))
        for position, material in _perPosition(job.get("material"), count).items():
            if not machine_manager.setMaterialById(position, material):
                raise RuntimeError("material %s not available for extruder %s" % (material, position))
        if job.get("quality"):
            machine_manager.setQualityGroupByQualityType(job["quality"])
        if job.get("intent"):
            machine_manager.setIntentByCategory(job["intent"])
            if machine_manager.activeIntentCategory != job["intent"]:
                raise RuntimeError("intent %s not available" % job["intent"])
        for key, value in job.get("global", {}).items():
            self._setUserValue(stack, key, value)
        for position, values in job.get("extruders", {}).items():
            for key, value in values.items():
                self._setUserValue(stack.extruderList[int(position)], key, value)
        self._event("settings_applied")

    def _setUserValue(self, stack, key, value):
        stack.userChanges.setProperty(key, "value", value)
        if stack.userChanges.getProperty(key, "value") is None:
            raise RuntimeError("could not set %s on %s" % (key, stack.getId()))

    def _loadNextModel(self):
        loaded = self._status.setdefault("models", [])
        if len(loaded) == len(self._models):
            self._event("models_loaded")
            if self._job.get("support_blockers"):
                added = HarnessSteps.addSupportBlockers(self._app, self._model_nodes, self._job["support_blockers"])
                self._status["support_blockers"] = added
                self._event("support_blockers_added")
            if self._job.get("actions"):
                HarnessSteps.ActionRunner(self._app, self._status, self._job["actions"], self._afterActions).start()
            else:
                self._afterActions()
            return
        entry = self._models[len(loaded)]
        path = entry["path"] if isinstance(entry, dict) else entry
        self._app.readLocalFile(QUrl.fromLocalFile(os.path.abspath(path)), "open_as_model", False)

    def _onFileCompleted(self, file_name):
        loaded = self._status.setdefault("models", [])
        if len(loaded) == len(self._models):
            return
        entry = self._models[len(loaded)]
        root = self._app.getController().getScene().getRoot()
        new_nodes = [n for n in DepthFirstIterator(root)
                     if n.callDecoration("isSliceable") and id(n) not in self._loaded_nodes]
        self._loaded_nodes.update(id(n) for n in new_nodes)
        self._model_nodes.append(new_nodes)
        if isinstance(entry, dict) and "extruder" in entry:
            extruder = self._app.getGlobalContainerStack().extruderList[int(entry["extruder"])]
            for node in new_nodes:
                node.callDecoration("setActiveExtruder", extruder.getId())
        if isinstance(entry, dict) and entry.get("settings"):
            for node in new_nodes:
                HarnessSteps.setPerObjectSettings(node, entry["settings"])
        loaded.append({"file": file_name, "nodes": len(new_nodes)})
        self._loadNextModel()

    def _afterActions(self):
        if not self._job.get("slice", True):
            self._app.callLater(self._finish, "done")
            return
        QTimer.singleShot(int(self._job.get("settle_ms", 1000)), self._sliceNow)

    def _sliceNow(self):
        if self._slice is not None or self._finished:
            return
        attempt = self._status["slice_attempts"] = self._status.get("slice_attempts", 0) + 1
        self._event("force_slice" if attempt == 1 else "force_slice_%d" % attempt)
        self._app.getBackend().forceSlice()
        if attempt < 4:  # watchdog: no Slice sent yet -> log where the threads are, try again
            QTimer.singleShot(45000, lambda: attempt == self._status["slice_attempts"] and self._slice is None
                              and (HarnessSteps.logThreadStacks(), self._sliceNow()))

    def _onBackendError(self, job):
        HarnessSteps.recordBackendError(self._app, self._status, job)

    def _onBackendState(self, state):
        self._status["backend_state"] = BackendState(state).name
        if self._slice is None:
            # StartSliceJob failed or was cancelled (e.g. by a late scene change): retry a few times.
            if state == BackendState.Error and self._status.get("slice_attempts", 0) in (1, 2, 3):
                self._error("backend error before the Slice was sent; retrying")
                QTimer.singleShot(3000, self._sliceNow)
            return
        if state == BackendState.Done:
            self._event("slice_done")
            self._app.callLater(self._finish, "done")
        elif state == BackendState.Error:
            self._app.callLater(self._finish, "backend error")

    def _onTimeout(self):
        self._error("timeout after %s s" % self._job.get("timeout", 150))
        self._finish("timeout")

    # ---- results -------------------------------------------------------------------------
    def _fixture(self):
        stack = self._app.getGlobalContainerStack()
        first = SliceRecord.stackContainers(stack.extruderList[0])
        fixture = {
            "machine": self._job["machine"],
            "variant": first["variant"],
            "material": first["material"],
            "quality": SliceRecord.stackContainers(stack)["quality"],
            "intent": first["intent"],
            "user": {"global": self._job.get("global", {}), "extruders": self._job.get("extruders", {})},
            "containers": {"global": SliceRecord.stackContainers(stack),
                           "extruders": [SliceRecord.stackContainers(e) for e in stack.extruderList]},
            "engine": self._app.getPreferences().getValue("backend/location"),
        }
        fixture.update(self._slice)
        objects = [o for ol in self._slice["object_lists"] for o in ol["objects"]]
        fixture["objects"] = objects
        if all(not ol["settings"] for ol in self._slice["object_lists"]) and len(self._slice["object_lists"]) == 1:
            del fixture["object_lists"]  # the usual case: one mesh group, no group settings
        else:
            for ol in fixture["object_lists"]:
                ol["objects"] = [o["name"] for o in ol["objects"]]
        return fixture

    def _writeJson(self, path, data):
        os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
        with open(path + ".tmp", "w", encoding="utf-8") as f:
            json.dump(data, f, indent=1, ensure_ascii=False)
            f.write("\n")
        os.replace(path + ".tmp", path)

    def _finish(self, reason):
        if self._finished:
            return
        self._finished = True
        self._status["finish_reason"] = reason
        self._status["nodes"] = HarnessSteps.nodeStates(self._app)
        try:
            if self._job.get("gcode_output") and self._status.get("backend_state") == "Done":
                self._status["gcode_chunks"] = HarnessSteps.dumpGcode(self._app, self._job["gcode_output"])
            if not self._job.get("slice", True):
                pass  # nothing sliced, no fixture
            elif self._slice is not None and self._app.getGlobalContainerStack() is not None:
                self._writeJson(self._job["output"], self._fixture())
                self._event("fixture_written")
            else:
                self._error("no Slice message captured (%s)" % reason)
        except Exception as e:
            Logger.logException("e", "[CuraHarness] writing the fixture failed")
            self._error("writing the fixture failed: %r" % e)
        if self._job.get("preview") and self._status.get("backend_state") == "Done":
            HarnessSteps.showPreview(self._app, self._status, self._screenshotAndClose,
                                     self._job.get("camera"))
            return
        # Give the GUI a moment to show the final state before the screenshot.
        QTimer.singleShot(1500 if self._job.get("screenshot") else 0, self._screenshotAndClose)

    def _screenshotAndClose(self):
        if self._job.get("screenshot"):
            self._grab(self._job["screenshot"], "screenshot_saved")
        pending = list(self._job.get("screenshots") or [])
        if pending:
            self._nextScreenshot(pending)
            return
        self._close()

    def _grab(self, path, event):
        try:
            QGuiApplication.primaryScreen().grabWindow(0).save(path)
            self._event(event)
        except Exception as e:
            self._error("screenshot failed: %r" % e)

    def _nextScreenshot(self, pending):
        """job["screenshots"]: [{"path", "layer_view_type", "layer"}] one after another: the Preview's colour
        scheme (0 Material Color, 1 Line Type, ...) and the layer slider (null: the top) are set first,
        the screen is grabbed 2.5 s later (delay_ms)."""
        if not pending:
            self._close()
            return
        shot = pending.pop(0)
        if "layer_view_type" in shot:
            self._app.getPreferences().setValue("layerview/layer_view_type", int(shot["layer_view_type"]))
        view = self._app.getController().getActiveView()
        if "layer" in shot and hasattr(view, "setLayer"):  # the layer slider's upper handle
            view.setLayer(int(shot["layer"]) if shot["layer"] is not None else view.getMaxLayers())

        def grab():
            self._grab(shot["path"], "screenshot_%s" % os.path.basename(shot["path"]))
            self._nextScreenshot(pending)

        QTimer.singleShot(int(shot.get("delay_ms", 2500)), grab)

    def _close(self):
        try:  # what Cura's print information shows: the time per feature (from PrintTimeMaterialEstimates)
            info = self._app.getPrintInformation()
            self._status["print_times_per_feature"] = {k: int(v) for k, v in info.getFeaturePrintTimes().items()}
            self._status["print_time_s"] = int(info.currentPrintTime)
        except Exception as e:
            self._error("print information: %r" % e)
        if self._job.get("plugin_status"):
            plugin = HarnessSteps.pluginObject(self._job["plugin_status"])
            self._status["plugin_status_end"] = plugin.status() if hasattr(plugin, "status") else None
        self._status["visible_messages"] = [m.getText() for m in self._app.getVisibleMessages()]
        if self._job.get("status"):
            self._writeJson(self._job["status"], self._status)
        for plugin_id in self._job.get("disable_plugins", []):  # as the Marketplace's "Disable" does
            HarnessSteps.pluginRegistry().disablePlugin(plugin_id)
        for package_id in self._job.get("remove_packages", []):  # as the Marketplace's "Uninstall" does
            self._app.getPackageManager().removePackage(package_id, force_add=True)
        if not self._job.get("keep_open"):
            QTimer.singleShot(200, self._app.closeApplication)

    def _tidyGui(self):
        """Cosmetic, for screenshots: hide the first-run wizard a fresh profile shows over everything
        and the start-up messages ("plugin X could not be loaded"); maximise the window."""
        for message in list(self._app.getVisibleMessages()):
            message.hide()
        window = self._app.getMainWindow()
        if window is None:
            return
        window.setGeometry(window.screen().availableGeometry())  # no window manager under Xvfb
        pending = [window.contentItem()]
        while pending:
            item = pending.pop()
            if item.metaObject().className().startswith("WelcomeDialogItem"):
                item.setProperty("visible", False)
            pending.extend(item.childItems())
