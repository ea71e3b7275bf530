# What the FreeCAD plugin tests share (they run inside freecadcmd): argv (BIN_DIR SOURCE_DIR),
# the plugin on sys.path, check(), the GUI macro loaded with stand-ins for what freecadcmd
# lacks (FreeCADGui's selection, modal dialogs), and the exit status.
import os
import sys
import traceback

BIN_DIR, SOURCE_DIR = sys.argv[1], sys.argv[2]
PLUGIN_DIR = os.path.join(SOURCE_DIR, "clients", "freecad")
sys.path.insert(0, PLUGIN_DIR)
MESSCAP = os.path.join(BIN_DIR, "messcap")
os.environ["IMESS_MESSCAP"] = MESSCAP  # the plugin's way to be told which messcap to run
failures = []


def check(condition, text):
    if not condition:
        failures.append(text)
        print("FAIL " + text)
    return condition


class Gui:
    """freecadcmd has no FreeCADGui: the selection and updateGui the macro uses."""

    selected = []
    app = None

    class Selection:
        @staticmethod
        def getSelection():
            return list(Gui.selected)

    @staticmethod
    def updateGui():
        Gui.app.processEvents()


def macro_namespace():
    """The macro's definitions (not its final show_panel()) on an offscreen Qt, FreeCADGui
    replaced by Gui; QMessageBox.warning records into the returned list instead of waiting for
    a click. Returns (namespace, warnings, app)."""
    from PySide import QtGui

    app = QtGui.QApplication.instance() or QtGui.QApplication([])
    Gui.app = app
    path = os.path.join(PLUGIN_DIR, "IMESS_Capture.FCMacro")
    source = open(path).read()
    check(source.rstrip().endswith("show_panel()"), "the macro ends by showing its panel")
    ns = {"__file__": path}
    exec(compile(source.rstrip()[: -len("show_panel()")], "IMESS_Capture.FCMacro", "exec"), ns)
    ns["FreeCADGui"] = Gui
    warnings = []
    QtGui.QMessageBox.warning = staticmethod(lambda parent, title, text: warnings.append(text))
    return ns, warnings, app


def finish(name, *steps):
    """Runs the steps, prints the summary and exits 1 on any failure or exception."""
    import time

    started = time.time()
    try:
        for step in steps:
            step()
    except Exception:  # noqa: BLE001 - any exception fails the test with its traceback
        traceback.print_exc()
        failures.append("exception")
    print("%s: %d failures, %.1f s" % (name, len(failures), time.time() - started))
    sys.stdout.flush()
    os._exit(1 if failures else 0)
