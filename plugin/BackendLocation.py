"""Points Cura's backend at mixengine while the plugin runs, and gives the old engine back.

Cura reads the preference backend/location every time it spawns its engine (reference §7). At
start-up (initializationFinished, when cura.cfg has been read) the plugin remembers the current
location in mixengine/previous_backend_location, unless it is already a MixEngine binary, sets its
own, and respawns the engine Cura started with the old one (_terminate + _createSocket, private).

At every clean shutdown the previous location is written back before Cura saves its preferences,
so cura.cfg never names mixengine while Cura is closed: a plugin that is disabled or removed in the
Marketplace (it is not loaded at the next start) leaves Cura on its old engine without a further
step. If Cura crashed while the plugin was active and the plugin is then deleted by hand,
`python3 install.py --uninstall` puts the previous location back into cura.cfg.

Only Preferences-like objects (getValue/setValue/resetPreference) are used, so the logic can be
tested without Cura.
"""
import os

LOCATION = "backend/location"
PREVIOUS = "mixengine/previous_backend_location"
ENGINE_PATH = "mixengine/engine_path"


def isMixEngine(path):
    return bool(path) and os.path.basename(str(path)).startswith("mixengine")


class BackendLocation:
    def __init__(self, preferences, engine_path, respawn=None, log=None):
        self._prefs = preferences
        self._engine = engine_path
        self._respawn = respawn or (lambda: None)
        self._log = log or (lambda text: None)
        self.active = False

    def activate(self):
        """Make mixengine Cura's engine. Returns True when the location was changed."""
        current = self._prefs.getValue(LOCATION)
        if current == self._engine:
            self.active = True
            return False
        if current and not isMixEngine(current):
            self._prefs.setValue(PREVIOUS, current)
        self._prefs.setValue(LOCATION, self._engine)
        self.active = True
        self._log("backend/location: %s -> %s" % (current, self._engine))
        self._respawn()
        return True

    def restore(self):
        """Give back the location that was in use before MixEngine. Returns the restored value."""
        current = self._prefs.getValue(LOCATION)
        if not isMixEngine(current):
            return current  # someone chose another engine meanwhile: leave it
        previous = self._prefs.getValue(PREVIOUS)
        if previous and not isMixEngine(previous):
            self._prefs.setValue(LOCATION, previous)
        else:
            self._prefs.resetPreference(LOCATION)  # the default Cura found itself (its CuraEngine)
        restored = self._prefs.getValue(LOCATION)
        self._log("backend/location restored: %s -> %s" % (current, restored))
        self.active = False
        return restored
