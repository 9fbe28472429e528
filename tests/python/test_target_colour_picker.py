"""Issue 18, part 4 in Cura: the target colour picker. TargetColour.py (no Qt) on stand-ins for Cura's
scene nodes and per-object stacks; the dialog's QML loaded by Debian's Qt 5 (the Qt Cura 4.13 runs
on) with a manager object, accepted, and its colour written back."""
import subprocess
import sys
import textwrap

import helpers

sys.path.insert(0, str(helpers.REPO / "plugin"))
import TargetColour  # noqa: E402


class Container:
    def __init__(self):
        self.values = {}

    def setProperty(self, key, prop, value):
        self.values[(key, prop)] = value


class Stack:
    def __init__(self, inherited="#808080"):
        self.top = Container()
        self.inherited = inherited

    def getTop(self):
        return self.top

    def getProperty(self, key, prop):
        return self.top.values.get((key, prop), self.inherited)


class Node:
    def __init__(self, stack=None):
        self.stack = stack

    def callDecoration(self, name):
        assert name == "getStack"
        return self.stack

    def addDecorator(self, decorator):
        self.stack = decorator


def test_normalise_accepts_what_qt_and_users_write():
    assert TargetColour.normalise("#FF8000") == "#ff8000"
    assert TargetColour.normalise("ff8000") == "#ff8000"
    assert TargetColour.normalise("#ccff8000") == "#ff8000"  # QColor #aarrggbb
    assert TargetColour.normalise("orange") is None
    assert TargetColour.normalise("#ff80") is None


def test_apply_writes_every_selected_model_and_decorates_a_bare_one():
    decorated, bare = Node(Stack()), Node(None)
    assert TargetColour.applyColour([decorated, bare], "#FF8000", Stack) == 2
    for node in (decorated, bare):
        assert node.stack.top.values == {("mixing_target_color", "value"): "#ff8000"}
    assert TargetColour.currentColour([bare], "#808080") == "#ff8000"
    assert TargetColour.applyColour([decorated], "not a colour", Stack) == 0


def test_current_colour_falls_back_to_the_global_value():
    assert TargetColour.currentColour([Node(None)], "#00FF00") == "#00ff00"
    assert TargetColour.currentColour([], None) == "#808080"


def test_the_dialog_qml_loads_and_accepts_a_colour(tmp_path):
    script = textwrap.dedent(f"""
        import sys
        from PyQt5.QtCore import QObject, QUrl, pyqtProperty, pyqtSlot, QTimer
        from PyQt5.QtGui import QGuiApplication
        from PyQt5.QtQml import QQmlComponent, QQmlEngine
        app = QGuiApplication(sys.argv)
        class Manager(QObject):
            got = None
            @pyqtProperty(str, constant=True)
            def colour(self):
                return "#ff8000"
            @pyqtSlot(str)
            def accept(self, colour):
                Manager.got = colour
        engine = QQmlEngine()
        manager = Manager()
        engine.rootContext().setContextProperty("manager", manager)
        component = QQmlComponent(engine, QUrl.fromLocalFile("{helpers.REPO / 'plugin' / 'qml' / 'TargetColourDialog.qml'}"))
        dialog = component.create()
        if dialog is None:
            print("ERRORS", [e.toString() for e in component.errors()])
            sys.exit(1)
        print("COLOUR", dialog.property("color").name())
        dialog.setProperty("color", "#00a3e0")
        dialog.accepted.emit()
        print("ACCEPTED", Manager.got)
    """)
    proc = subprocess.run(["/usr/bin/python3", "-c", script], capture_output=True, text=True, timeout=120,
                          env={"QT_QPA_PLATFORM": "offscreen", "PATH": "/usr/bin:/bin", "HOME": str(tmp_path)})
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert "COLOUR #ff8000" in proc.stdout, proc.stdout
    assert TargetColour.normalise(proc.stdout.split("ACCEPTED ")[1].strip()) == "#00a3e0", proc.stdout
