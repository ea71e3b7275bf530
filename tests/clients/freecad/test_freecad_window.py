# In a real FreeCAD window (run_in_freecad_gui.py: Xvfb, the add-on linked into FreeCAD's Mod
# folder): FreeCAD loads the add-on as the workbench IMESS and none of its files as a macro;
# choosing the workbench opens the panel; Connect to a real messd fits the 3-D view to the probe
# at a part's scale, and to the points an operator measures as they come; the probe and the
# points are visible (pixels on the screen); a held jog button moves the machine and no event
# moves a button; moving the view by hand stops the following until Follow is ticked again.
# With a screenshot folder it also measures the short plan and saves the panel's views.
import json
import os
import sys

ARGS = json.loads(os.environ["IMESS_GUI_TEST"])
sys.stdout = open(ARGS["output"], "w", buffering=1)
sys.stderr = sys.stdout
sys.argv = [os.path.abspath(__file__) if "__file__" in globals() else "test_freecad_window.py", ARGS["bin"], ARGS["source"]]
sys.path.insert(0, os.path.join(ARGS["source"], "tests", "clients", "freecad"))
from plugin_test import SHORT_PLAN, Messd, Operator, check, finish, mouse, pump  # noqa: E402

import FreeCAD  # noqa: E402
import FreeCADGui  # noqa: E402
from PySide import QtCore, QtGui  # noqa: E402

APP = QtGui.QApplication.instance()
state = {}


def on_screen(view, p):
    """p's pixel in the 3-D view, and whether it is inside it."""
    x, y = view.getPointOnScreen(p)
    w, h = view.getSize()
    return (x, y), 0 <= x < w and 0 <= y < h


def ball_pixels(view, centre, radius):
    """The probe ball's radius on the screen: the largest of its axes' projections."""
    c, _ = on_screen(view, centre)
    return max(((a - b) ** 2 + (c2 - d) ** 2) ** 0.5 for a, c2 in [c] for b, d in
               [on_screen(view, centre + FreeCAD.Vector(*v) * radius)[0] for v in ((1, 0, 0), (0, 1, 0), (0, 0, 1))])


def click(widget):
    mouse(widget, "press")
    mouse(widget, "release")


def shot(name):
    if ARGS["shots"]:
        os.makedirs(ARGS["shots"], exist_ok=True)
        pump(APP, 0.5)
        main = FreeCADGui.getMainWindow()
        image = QtGui.QApplication.primaryScreen().grabWindow(0, main.x(), main.y(), main.width(), main.height())
        image.save(os.path.join(ARGS["shots"], name))


def window_checks():
    import imess_panel

    check("IMESSWorkbench" in FreeCADGui.listWorkbenches(), "FreeCAD loaded the add-on from its Mod folder")
    macros = FreeCAD.getUserMacroDir(True)
    check(not os.path.isdir(macros) or not [f for f in os.listdir(macros) if f.startswith(("imess", "IMESS"))],
          "no file of the add-on is a macro")
    main = FreeCADGui.getMainWindow()
    main.setGeometry(QtGui.QApplication.primaryScreen().availableGeometry())
    doc = FreeCAD.newDocument("window")
    FreeCADGui.activateWorkbench("IMESSWorkbench")
    pump(APP, 0.5)
    panel = main.findChild(QtGui.QDockWidget, "IMESS_Capture")
    check(isinstance(panel, imess_panel.CapturePanel) and panel.isVisible(), "choosing the workbench opens the panel")
    messd = Messd()
    state["messd"] = messd
    panel.host.setText("127.0.0.1")
    panel.port.setValue(messd.port)
    layout = {n: b.mapToGlobal(QtCore.QPoint(0, 0)) for n, b in panel.jog_buttons.items()}
    click(panel.connect_button)
    s = panel.session
    check(pump(APP, 5, lambda: s.position is not None and panel.follower.fitted is not None), "Connect: %s"
          % panel.events.lines())
    pump(APP, 0.3)
    view = FreeCADGui.getDocument(doc.Name).activeView()
    _, inside = on_screen(view, s.position)
    radius = ball_pixels(view, s.position, s.tip_radius)
    span = [panel.follower.fitted[1][i] - panel.follower.fitted[0][i] for i in range(3)]
    check(inside and radius >= 6 and min(span) >= 80, "after Connect the view shows the probe at a part's scale: ball "
          "radius %.1f px, view box %s mm" % (radius, ["%.0f" % v for v in span]))

    op = Operator(messd.port)
    op.start()
    seen = []
    while op.is_alive():
        pump(APP, 0.2)
        seen.append(all(on_screen(view, o.Measured)[1] for o in s.points) and on_screen(view, s.position)[1])
    pump(APP, 1, lambda: len(s.points) == 7)
    check(op.error is None and len(s.points) == 7, "7 points: %s" % op.error)
    check(all(seen) and all(on_screen(view, o.Measured)[1] for o in s.points),
          "every point and the probe stayed in view while they came (%d of %d looks)" % (seen.count(True), len(seen)))
    check(all(o.ViewObject.PointSize >= 8 for o in s.points), "points drawn 8 px or larger")
    op.close()
    FreeCADGui.Selection.clearSelection()
    for o in s.points[3:]:
        FreeCADGui.Selection.addSelection(o)
    panel.fit("circle")
    check(panel.results() and panel.results()[0][1].startswith("Ø "), "the circle in the results: %s" % panel.results())
    shot("freecad-panel-capture.png")

    before = s.position
    mouse(panel.jog_buttons["+X"], "press")
    # held until the machine reports the jog and has gone 5 mm (a loaded host answers late)
    moving = pump(APP, 10, lambda: s.state == "jog" and s.position.x > before.x + 5)
    mouse(panel.jog_buttons["+X"], "release")
    check(moving and pump(APP, 5, lambda: s.state == "idle") and s.position.x > before.x + 5,
          "a held +X jogged the machine in the real window: %s -> %s" % (before, s.position))
    check(all(b.mapToGlobal(QtCore.QPoint(0, 0)) == layout[n] for n, b in panel.jog_buttons.items()),
          "no event moved a jog button")

    view.viewFront()  # the user turns the view
    pump(APP, 0.5)
    check(not panel.follower.following and not panel.follow_box.isChecked() and
          (panel.events.text("view") or "").startswith("the view was moved"), "moving the view by hand stops following: %s"
          % panel.events.lines())
    camera = view.getCamera()
    mouse(panel.jog_buttons["+Z"], "press")
    pump(APP, 1.5)
    mouse(panel.jog_buttons["+Z"], "release")
    pump(APP, 1, lambda: s.state == "idle")
    check(view.getCamera() == camera, "then the view stays where the user put it")
    panel.follow_box.click()  # (its label, not the middle of its stretched box, takes a mouse click)
    pump(APP, 0.5)
    check(panel.follower.following and view.getCamera() != camera and on_screen(view, s.position)[1],
          "ticking Follow fits the view again")

    if ARGS["shots"]:
        view.viewIsometric()
        pump(APP, 0.3)
        panel.follow_box.click()
        panel.choose_plan(SHORT_PLAN)
        panel.measure_plan()
        pump(APP, 100, lambda: panel.run is None)
        check("16 points coloured" in (panel.events.text("colour") or ""), "the plan measured: %s" % panel.events.lines())
        FreeCADGui.Selection.clearSelection()
        shot("freecad-panel-inspection.png")
    panel.toggle()
    messd.stop()


def run():
    try:
        finish("freecad window", window_checks)
    finally:
        if "messd" in state:
            state["messd"].stop()


QtCore.QTimer.singleShot(500, run)
