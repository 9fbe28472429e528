"""The MixEngine extension: settings, backend location, the orientation and target colour menu items.

Timeline in Cura 4.13:
  plugin load (register)       settings folder added to the resource search path (by __init__.py),
                               containerLoadComplete hooked, shutdown hooked
  loadAllMetadata / machines   every machine definition gets MixEngine's categories (SettingsInjector)
  initializationFinished       cura.cfg has been read: backend/location -> mixengine (engine respawned),
                               MixEngine's settings made visible once; the layer view learns the mix
                               (MixPreview: LayerDataBuilder.build wrapped, legend overlay created); the
                               settings MixEngine does not act on are watched (SettingsNotice); each
                               slice's mixing report becomes one message (MixReportNotice)
  shutdown                     backend/location given back before the preferences are saved
"""
import os

from UM.Extension import Extension
from UM.Logger import Logger
from UM.Message import Message
from UM.PluginRegistry import PluginRegistry

from . import BackendLocation, NotHonoured, PluginPaths, SettingFragments
from .MixPreview import MixPreview
from .MixReportNotice import MixReportNotice
from .OrientAction import OrientAction
from .SettingsInjector import SettingsInjector
from .SettingsNotice import SettingsNotice
from .TargetColourPicker import ITEM as COLOUR_ITEM
from .TargetColourPicker import TargetColourPicker

PLUGIN_ID = "MixEngine"
VISIBLE = "general/visible_settings"
VISIBILITY_DONE = "mixengine/visibility_added"  # keys made visible once; the user may hide them again
ORIENT_ITEM = "Optimize dual-nozzle orientation"


class MixEngineExtension(Extension):
    def __init__(self, app, settings_dir):
        super().__init__()
        self._app = app
        self._settings_dir = settings_dir
        self._backend = None
        self._injector = None
        self.engine_path, self.engine_how = None, "not looked up yet"
        prefs = app.getPreferences()
        for key in (BackendLocation.PREVIOUS, BackendLocation.ENGINE_PATH, VISIBILITY_DONE):
            prefs.addPreference(key, "")
        if settings_dir:
            self._injector = SettingsInjector(PluginPaths.fragmentFiles(settings_dir))
            self._injector.connect()
        else:
            Logger.log("e", "[MixEngine] no settings folder next to the plugin: no MixEngine settings")
        self.orient = OrientAction(app, lambda: self._findEngine(mixengine_only=True))
        self.preview = MixPreview(app, defaultChannelColours(settings_dir))
        self.notice = SettingsNotice(app, NotHonoured.load(settings_dir), self._slicesWithMixEngine)
        self.report_notice = MixReportNotice(app)
        self.setMenuName("MixEngine")
        self.addMenuItem(ORIENT_ITEM, self.orient.run)
        self.colour_picker = TargetColourPicker(app)
        self.addMenuItem(COLOUR_ITEM, self.colour_picker.run)
        app.initializationFinished.connect(self._onInitializationFinished)
        app.applicationShuttingDown.connect(self._onShutdown)

    # ---- state for tests and the log ---------------------------------------------------------
    def status(self):
        return {"engine": self.engine_path, "engine_how": self.engine_how,
                "settings_dir": self._settings_dir,
                "backend_active": bool(self._backend and self._backend.active),
                "injected": list(self._injector.injected) if self._injector else [],
                "keys": self._injector.allKeys() if self._injector else [],
                "preview": dict(self.preview.last),
                "legend": {"shown": self.preview.legend.shown, "channels": self.preview.legend.channels},
                "not_honoured": [list(r) for r in self.notice.rows], "not_honoured_message": self.notice.text(),
                "mixing_report": self.report_notice.status()}

    def _slicesWithMixEngine(self):
        return bool(self._backend and self._backend.active and self.engine_path
                    and os.path.basename(self.engine_path).startswith(PluginPaths.ENGINE_NAME))

    def _findEngine(self, mixengine_only=False):
        preference = self._app.getPreferences().getValue(BackendLocation.ENGINE_PATH)
        return PluginPaths.findEngine(preference, mixengine_only=mixengine_only)

    # ---- start-up ----------------------------------------------------------------------------
    def _onInitializationFinished(self):
        self._showSettings()
        try:
            self.preview.install()
            self.preview.createLegend(os.path.join(os.path.dirname(os.path.abspath(__file__)), "qml", "MixLegend.qml"))
        except Exception:
            Logger.logException("e", "[MixEngine] the layer view will not show the mix")
        try:
            self.report_notice.connect()
        except Exception:
            Logger.logException("e", "[MixEngine] the mixing report will not be shown")
        self.engine_path, self.engine_how = self._findEngine()
        if self.engine_path is None:
            Logger.log("e", "[MixEngine] %s; Cura keeps its engine", self.engine_how)
            Message("MixEngine is not slicing: %s." % self.engine_how, title="MixEngine").show()
            return
        Logger.log("i", "[MixEngine] engine %s (%s)", self.engine_path, self.engine_how)
        self._backend = BackendLocation.BackendLocation(self._app.getPreferences(), self.engine_path,
                                                        respawn=self._respawn,
                                                        log=lambda t: Logger.log("i", "[MixEngine] %s", t))
        self._backend.activate()
        self.notice.connect()

    def _respawn(self):
        """Replace the engine Cura spawned at start-up with the old location (private backend API)."""
        backend = self._app.getBackend()
        process = getattr(backend, "_process", None)
        if process is None or list(process.args)[:1] == [self.engine_path]:
            return  # nothing spawned yet: the next spawn reads the new location
        backend._terminate()
        backend._createSocket()

    def _showSettings(self):
        """Add MixEngine's keys to the visible settings once per key (later hiding is respected)."""
        if not self._injector:
            return
        prefs = self._app.getPreferences()
        done = set(filter(None, (prefs.getValue(VISIBILITY_DONE) or "").split(";")))
        visible = [k for k in (prefs.getValue(VISIBLE) or "").split(";") if k]
        new = [k for k in self._injector.allKeys() if k not in done and k not in visible]
        if new:
            prefs.setValue(VISIBLE, ";".join(visible + new))
        prefs.setValue(VISIBILITY_DONE, ";".join(sorted(done | set(self._injector.allKeys()))))

    # ---- shutdown ----------------------------------------------------------------------------
    def _onShutdown(self):
        if not self._backend:
            return
        registry = PluginRegistry.getInstance()
        package_manager = self._app.getPackageManager()
        reasons = [r for r, flagged in (
            ("disabled", PLUGIN_ID in registry.getDisabledPlugins()),
            ("scheduled for removal", PLUGIN_ID in package_manager.getToRemovePackageIDs()
             or PLUGIN_ID in getattr(registry, "_plugins_to_remove", []))) if flagged]
        restored = self._backend.restore()
        Logger.log("i", "[MixEngine] shutdown%s: backend/location back to %s",
                   " (plugin %s)" % " and ".join(reasons) if reasons else "", restored)
        try:
            self._app.savePreferences()
        except Exception:
            Logger.logException("w", "[MixEngine] saving the restored backend/location failed")


def defaultChannelColours(settings_dir):
    """The default of mixing_channel_colors in the mixing fragment ("" when absent)."""
    path = os.path.join(settings_dir or "", "mixengine", "mixing.def.json")
    if not os.path.isfile(path):
        return ""
    for key, category in SettingFragments.categories(SettingFragments.loadFragment(path)):
        found = SettingFragments.findSetting(key, category, "mixing_channel_colors")
        if found is not None:
            return found.get("default_value", "")
    return ""
