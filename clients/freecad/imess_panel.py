# IMESS capture panel for FreeCAD: a dock panel that connects to messd, shows the live probe,
# puts every measured point into the active document as it arrives, a scan's points into a point
# cloud per scan, jogs the machine (press and
# hold), fits and relates features with messcap, inspects against a plan and colours points by
# deviation. Its layout never changes size while it runs. All logic is in the imess_*.py modules.
"""The IMESS dock panel (opened by the IMESS workbench, InitGui.py)."""

import os

import FreeCAD
import FreeCADGui
from PySide import QtCore, QtGui

import imess_capture
import imess_deviation
import imess_events
import imess_fit
import imess_inspect
import imess_jog
import imess_view

POLL_MS = 50  # the socket is polled, never waited on: the GUI never blocks
JOG_GRID = {"+Y": (0, 1), "-X": (1, 0), "+X": (1, 2), "-Y": (2, 1), "+Z": (0, 3), "-Z": (2, 3)}  # row, column
STOP_CELL = (1, 1)
NO_FEATURE = "(none)"
RESULT_ROWS = 8


def fixed_rows(tree, rows):
    """A list exactly `rows` lines high: what it shows never moves what is below it."""
    tree.setRootIsDecorated(False)
    tree.setUniformRowHeights(True)
    tree.setHorizontalScrollBarPolicy(QtCore.Qt.ScrollBarAlwaysOff)
    line = tree.fontMetrics().height() + 4
    tree.setFixedHeight(line * rows + tree.header().sizeHint().height() + 2 * tree.frameWidth() + 2)
    tree.setTextElideMode(QtCore.Qt.ElideRight)


def fixed_label(text=""):
    """One line that never wraps and never widens the panel (long text is cut, shown whole as tip)."""
    label = QtGui.QLabel(text)
    label.setWordWrap(False)
    label.setSizePolicy(QtGui.QSizePolicy.Ignored, QtGui.QSizePolicy.Fixed)
    label.setTextInteractionFlags(QtCore.Qt.TextSelectableByMouse)
    return label


class CapturePanel(QtGui.QDockWidget):
    def __init__(self):
        super().__init__("IMESS capture")
        self.setObjectName("IMESS_Capture")
        self.session = None
        self.jog = None
        self.run = None  # a running imess_inspect.PlanRun
        self.plan = ""
        self.events = imess_events.EventLog()
        self.shown_events = -1
        self.follower = imess_view.ViewFollower(self.events)
        w = QtGui.QWidget()
        form = QtGui.QFormLayout(w)
        self.add_link_rows(form)
        self.add_jog_rows(form)
        self.add_event_rows(form)
        self.add_fit_rows(form)
        self.add_inspection_rows(form)
        self.add_result_rows(form)
        scroll = QtGui.QScrollArea()
        scroll.setWidget(w)
        scroll.setWidgetResizable(True)
        scroll.setHorizontalScrollBarPolicy(QtCore.Qt.ScrollBarAlwaysOff)
        self.setWidget(scroll)
        # As wide as its buttons need: the dock never cuts them off (a low screen scrolls it up and down).
        self.setMinimumWidth(w.minimumSizeHint().width() + scroll.verticalScrollBar().sizeHint().width()
                             + 2 * scroll.frameWidth() + 4)
        self.timer = QtCore.QTimer(self)
        self.timer.timeout.connect(self.tick)
        self.show_events()

    # --- building -------------------------------------------------------------------------
    def button(self, text, tip, action):
        b = QtGui.QPushButton(text)
        b.setToolTip(tip)
        b.clicked.connect(lambda checked=False: action())
        return b

    def add_link_rows(self, form):
        row = QtGui.QHBoxLayout()
        self.host = QtGui.QLineEdit(imess_capture.DEFAULT_HOST)
        self.port = QtGui.QSpinBox()
        self.port.setRange(1, 65535)
        self.port.setValue(imess_capture.DEFAULT_PORT)
        self.connect_button = QtGui.QPushButton("Connect")
        self.connect_button.clicked.connect(self.toggle)
        row.addWidget(self.host, 1)
        row.addWidget(self.port)
        row.addWidget(self.connect_button)
        form.addRow("messd", row)
        self.position = fixed_label("-")
        self.position.setFont(QtGui.QFontDatabase.systemFont(QtGui.QFontDatabase.FixedFont))
        self.state = fixed_label("not connected")
        form.addRow("Probe", self.position)
        form.addRow("State", self.state)

    def add_jog_rows(self, form):
        grid = QtGui.QGridLayout()
        self.jog_buttons = {}
        for name, (row, column) in JOG_GRID.items():
            b = QtGui.QPushButton(name)
            b.setToolTip("hold to jog %s; the machine stops when you let go" % name)
            b.pressed.connect(lambda d=name: self.jog_press(d))
            b.released.connect(lambda d=name: self.jog_release(d))
            grid.addWidget(b, row, column)
            self.jog_buttons[name] = b
        self.stop_button = self.button("Stop", "stop any motion (StopMv), also a plan messcap measures", self.jog_stop)
        grid.addWidget(self.stop_button, *STOP_CELL)
        form.addRow("Jog (hold)", grid)
        speeds = QtGui.QHBoxLayout()
        self.speed_group = QtGui.QButtonGroup(self)
        self.speed_buttons = {}
        for percent in imess_jog.SPEEDS:
            b = QtGui.QPushButton("%g %%" % percent)
            b.setCheckable(True)
            b.setChecked(percent == imess_jog.DEFAULT_SPEED)
            b.setToolTip("jog at %g %% of MaxSpeed (x SpeedLevel)" % percent)
            b.clicked.connect(lambda checked=False, p=percent: self.jog_speed(p))
            self.speed_group.addButton(b)
            speeds.addWidget(b)
            self.speed_buttons[percent] = b
        form.addRow("Speed", speeds)
        row = QtGui.QHBoxLayout()
        self.measure_button = self.button("Measure here", "take the current position as a point (ForcePt)",
                                          self.measure_here)
        self.follow_box = QtGui.QCheckBox("Follow")
        self.follow_box.setChecked(True)
        self.follow_box.setToolTip("fit the 3-D view to the probe and the points as they come; "
                                   "moving the view yourself turns it off")
        self.follow_box.toggled.connect(self.follow)
        row.addWidget(self.measure_button)
        row.addWidget(self.follow_box)
        form.addRow("", row)

    def add_event_rows(self, form):
        self.event_list = QtGui.QTreeWidget()
        self.event_list.setColumnCount(2)
        self.event_list.setHeaderLabels(["time", "event"])
        fixed_rows(self.event_list, imess_events.ROWS)
        self.event_list.setColumnWidth(0, self.event_list.fontMetrics().horizontalAdvance("00:00:00") + 16)
        form.addRow(self.event_list)

    def add_fit_rows(self, form):
        rows = (imess_fit.FIT_KINDS[:3], imess_fit.FIT_KINDS[3:])
        for label, kinds in zip(("Fit selection", ""), rows):
            row = QtGui.QHBoxLayout()
            for kind in kinds:
                row.addWidget(self.button(kind.capitalize(), "fit a %s to the selected points (messcap fit %s)" % (kind, kind),
                                          lambda k=kind: self.fit(k)))
            form.addRow(label, row)
        row = QtGui.QHBoxLayout()
        for value in imess_fit.RELATE_VALUES:
            row.addWidget(self.button(value.capitalize(), "%s between two selected fitted features, the first selected "
                                      "the reference (messcap relate)" % value, lambda v=value: self.relate(v)))
        form.addRow("Relate two", row)

    def add_inspection_rows(self, form):
        row = QtGui.QHBoxLayout()
        self.plan_label = fixed_label("no plan")
        row.addWidget(self.button("Plan...", "choose the inspection plan (docs/metrology.md §14)", self.choose_plan))
        row.addWidget(self.plan_label, 1)
        form.addRow("Plan", row)
        row = QtGui.QHBoxLayout()
        self.feature_box = QtGui.QComboBox()
        self.feature_box.addItem(NO_FEATURE)
        self.feature_box.setToolTip("the plan feature the next measured points measure")
        self.feature_box.currentTextChanged.connect(self.choose_feature)
        row.addWidget(self.feature_box, 1)
        row.addWidget(self.button("Assign", "give the selected points this feature", self.assign))
        form.addRow("Feature", row)
        row = QtGui.QHBoxLayout()
        self.inspect_button = self.button("Inspect", "messcap inspect the selected (else all) points that have a "
                                          "feature against the plan, and colour them by deviation", self.inspect)
        self.measure_plan_button = self.button("Measure plan", "messcap measures the plan on the machine (it takes "
                                               "control) while the points come in here; then they are coloured",
                                               self.measure_plan)
        row.addWidget(self.inspect_button)
        row.addWidget(self.measure_plan_button)
        row.addWidget(self.button("Report...", "colour points from a messcap inspect --json report", self.open_report))
        form.addRow("Deviations", row)
        self.update_plan_buttons()

    def add_result_rows(self, form):
        self.result_list = QtGui.QTreeWidget()
        self.result_list.setColumnCount(2)
        self.result_list.setHeaderLabels(["result", "value"])
        fixed_rows(self.result_list, RESULT_ROWS)
        self.result_list.setColumnWidth(0, self.result_list.fontMetrics().horizontalAdvance("M" * 12))
        self.result_list.setHorizontalScrollBarPolicy(QtCore.Qt.ScrollBarAsNeeded)
        form.addRow(self.result_list)

    # --- the link -------------------------------------------------------------------------
    def toggle(self):
        if self.session is not None and self.session.connected():
            self.jog_stop_if_moving()
            if self.run is not None:
                self.run.cancel("disconnected")
                self.run = None
                self.update_plan_buttons()
            self.session.close("disconnected")
            self.timer.stop()
            self.connect_button.setText("Connect")
            self.tick_labels()
            return
        doc = FreeCAD.ActiveDocument or FreeCAD.newDocument("IMESS")
        self.session = imess_capture.CaptureSession(doc, self.host.text().strip(), self.port.value(), events=self.events)
        self.session.feature = self.current_feature()
        self.jog = imess_jog.JogControl(self.session)
        self.jog.set_speed(self.checked_speed())
        try:
            self.session.connect()
        except imess_capture.CaptureError as e:
            self.events.post("link", str(e))
            self.show_events()
            return
        self.follower.follow(self.follow_box.isChecked())
        self.connect_button.setText("Disconnect")
        self.timer.start(POLL_MS)
        self.tick_labels()

    def tick(self):
        s = self.session
        try:
            if s.poll():
                FreeCADGui.updateGui()
        except Exception as e:  # a broken document must not leave a timer firing into it
            self.timer.stop()
            self.jog_stop_if_moving()
            self.events.post("link", "stopped: %s" % e)
            self.show_events()
            return
        # A held button that is no longer down (focus lost, the mouse grabbed elsewhere) stops.
        if self.jog.held is not None and not self.jog_buttons[self.jog.held].isDown():
            self.jog.release(self.jog.held)
        self.jog.tick()
        if self.run is not None and self.run.tick() in ("done", "failed"):
            run, self.run = self.run, None
            self.update_plan_buttons()
            if run.state == "done":
                self.colour(s.doc, run.report)
        self.follow_view()
        self.tick_labels()
        if not s.connected():
            self.timer.stop()
            self.connect_button.setText("Connect")

    def tick_labels(self):
        s = self.session
        if s is not None and s.position is not None:
            self.position.setText("X %10.3f   Y %10.3f   Z %10.3f" % (s.position.x, s.position.y, s.position.z))
        scanned = ", %d scanned" % s.scans.points if s is not None and s.scans.points else ""
        if s is None:
            text = "not connected"
        elif not s.connected():
            text = "not connected; %d points captured%s" % (len(s.points), scanned)
        else:
            holder = s.control.split(" ")[0] if s.control not in ("", "none") else ""
            control = "control: this panel" if s.holds_control() else ("control: %s" % holder if holder else "control free")
            text = "%s   %d points%s   %s" % (s.state or "connected", len(s.points), scanned, control)
        self.state.setText(text)
        self.state.setToolTip(text)
        self.show_events()

    def show_events(self):
        if self.events.version == self.shown_events:
            return
        self.shown_events = self.events.version
        self.event_list.clear()
        for when, text in self.events.lines():
            item = QtGui.QTreeWidgetItem([when, text])
            item.setToolTip(1, text)
            self.event_list.addTopLevelItem(item)

    def closeEvent(self, event):  # noqa: N802 - Qt's name
        self.jog_stop_if_moving()  # closing the panel never leaves a jog running
        super().closeEvent(event)

    # --- the view -------------------------------------------------------------------------
    def gui_view(self):
        """The 3-D view of the session's document, or None (no GUI, no such view)."""
        if not FreeCAD.GuiUp or self.session is None:
            return None
        try:
            gui_doc = FreeCADGui.getDocument(self.session.doc.Name)
            view = gui_doc.activeView() if gui_doc is not None else None
        except Exception:  # noqa: BLE001 - the document was closed under the panel
            return None
        return view if view is not None and hasattr(view, "getCameraNode") else None

    def follow_view(self):
        s = self.session
        if self.follower.update(self.gui_view(), s.position, s.points, s.tip_radius, s.scans.extent):
            FreeCADGui.updateGui()
        if self.follow_box.isChecked() != self.follower.following:
            self.follow_box.blockSignals(True)
            self.follow_box.setChecked(self.follower.following)
            self.follow_box.blockSignals(False)

    def follow(self, on):
        self.follower.follow(on)
        if on and self.session is not None:
            self.follow_view()
        self.show_events()

    # --- jogging --------------------------------------------------------------------------
    def checked_speed(self):
        for percent, b in self.speed_buttons.items():
            if b.isChecked():
                return percent
        return imess_jog.DEFAULT_SPEED

    def connected(self):
        if self.session is None or not self.session.connected():
            self.events.post("link", "connect to messd first")
            self.show_events()
            return False
        return True

    def jog_press(self, direction):
        if self.connected():
            self.jog.press(direction)
            self.show_events()

    def jog_release(self, direction):
        if self.jog is not None and self.session.connected():
            self.jog.release(direction)

    def jog_stop(self):
        if self.connected():
            self.jog.stop()
            if self.run is not None:  # between two of its moves a StopMv finds nothing to stop
                self.run.cancel("Stop pressed")
                self.run = None
                self.update_plan_buttons()
            self.show_events()

    def jog_stop_if_moving(self):
        if self.jog is not None and self.session.connected() and (self.jog.held or self.jog.moving):
            self.jog.stop()

    def jog_speed(self, percent):
        if self.jog is not None:
            self.jog.set_speed(percent)

    def measure_here(self):
        if self.connected():
            self.jog.measure_here()

    # --- results --------------------------------------------------------------------------
    def add_result(self, name, value, kind="fit", first=True):
        item = QtGui.QTreeWidgetItem([name, value])
        item.setToolTip(0, name)
        item.setToolTip(1, value)
        item.setData(0, QtCore.Qt.UserRole, kind)
        if first:
            self.result_list.insertTopLevelItem(0, item)
        else:
            self.result_list.addTopLevelItem(item)
        return item

    def results(self):
        """[(name, value), ...] as the list shows them, top first."""
        items = [self.result_list.topLevelItem(i) for i in range(self.result_list.topLevelItemCount())]
        return [(i.text(0), i.text(1)) for i in items]

    def note(self, topic, text):
        self.events.post(topic, text)
        self.show_events()

    # --- features -------------------------------------------------------------------------
    def fit(self, kind):
        doc = FreeCAD.ActiveDocument
        selection = FreeCADGui.Selection.getSelection()
        if doc is None or not selection:
            self.note("fit", "select the measured points to fit first")
            return
        try:
            obj = imess_fit.fit_feature(doc, kind, selection)
        except imess_capture.CaptureError as e:
            self.note("fit", "fit %s failed: %s" % (kind, e))
            QtGui.QMessageBox.warning(self, "IMESS fit %s" % kind, str(e))
            return
        self.add_result(obj.Label, obj.Result)
        self.note("fit", "%s: %s" % (obj.Label, obj.Result))

    def relate(self, value):
        doc = FreeCAD.ActiveDocument
        selection = FreeCADGui.Selection.getSelection()
        if doc is None or len(selection) != 2:
            self.note("fit", "select two fitted features (the first is the reference), then press %s"
                      % value.capitalize())
            return
        try:
            obj = imess_fit.relate_features(doc, value, selection[0], selection[1])
        except imess_capture.CaptureError as e:
            self.note("fit", "%s failed: %s" % (value, e))
            QtGui.QMessageBox.warning(self, "IMESS %s" % value, str(e))
            return
        self.add_result("%s %s-%s" % (value, selection[0].Label, selection[1].Label), obj.Result)
        self.note("fit", obj.Label)

    # --- plans and deviations -------------------------------------------------------------
    def choose_plan(self, path=None):
        if path is None:
            path, _ = QtGui.QFileDialog.getOpenFileName(self, "Inspection plan", os.path.dirname(self.plan) or "",
                                                        "Inspection plans (*.json)")
        if not path:
            return
        try:
            plan = imess_inspect.read_plan(path)
        except imess_capture.CaptureError as e:
            self.note("plan", str(e))
            QtGui.QMessageBox.warning(self, "IMESS plan", str(e))
            return
        self.plan = path
        self.plan_label.setText("%s (%s)" % (plan["part"], os.path.basename(path)))
        self.plan_label.setToolTip(path)
        self.feature_box.blockSignals(True)
        self.feature_box.clear()
        self.feature_box.addItem(NO_FEATURE)
        for name, kind in plan["features"]:
            self.feature_box.addItem(name)
            self.feature_box.setItemData(self.feature_box.count() - 1, kind, QtCore.Qt.ToolTipRole)
        self.feature_box.blockSignals(False)
        self.choose_feature(NO_FEATURE)
        self.update_plan_buttons()
        self.note("plan", "plan %s: %d features" % (plan["part"], len(plan["features"])))

    def update_plan_buttons(self):
        self.inspect_button.setEnabled(bool(self.plan))
        self.measure_plan_button.setEnabled(bool(self.plan) and self.run is None)

    def current_feature(self):
        text = self.feature_box.currentText()
        return "" if text == NO_FEATURE else text

    def choose_feature(self, _text=None):
        if self.session is not None:
            self.session.feature = self.current_feature()

    def assign(self):
        points = [o for o in FreeCADGui.Selection.getSelection() if hasattr(o, "Measured")]
        if not points:
            self.note("plan", "select measured points to give them the feature")
            return
        for o in points:
            imess_capture.set_feature(o, self.current_feature())
        feature = self.current_feature()
        self.note("plan", "%d points %s" % (len(points), "measure %s" % feature if feature else "have no feature now"))

    def inspect(self):
        doc = FreeCAD.ActiveDocument
        objects = FreeCADGui.Selection.getSelection()
        if not objects and doc is not None and doc.getObject(imess_capture.POINT_GROUP) is not None:
            objects = doc.getObject(imess_capture.POINT_GROUP).Group
        try:
            if doc is None or not objects:
                raise imess_capture.CaptureError("no points to inspect: capture or select some first")
            report, used, skipped = imess_inspect.inspect_points(self.plan, objects)
        except imess_capture.CaptureError as e:
            self.note("inspect", "inspection failed: %s" % e)
            QtGui.QMessageBox.warning(self, "IMESS inspect", str(e))
            return
        self.note("inspect", "messcap inspected %d points%s" % (used, " (%d without a feature left out)" % skipped
                                                                 if skipped else ""))
        self.colour(doc, report)

    def measure_plan(self):
        if not self.connected():
            return
        run = imess_inspect.PlanRun(self.plan, self.session)
        try:
            run.start()
        except imess_capture.CaptureError as e:
            self.note("inspect", str(e))
            return
        self.run = run
        self.update_plan_buttons()
        self.show_events()

    def open_report(self, path=None):
        if path is None:
            path, _ = QtGui.QFileDialog.getOpenFileName(self, "messcap inspect report", "", "JSON (*.json)")
        doc = FreeCAD.ActiveDocument
        if path and doc is not None:
            self.colour(doc, path)

    def colour(self, doc, report):
        try:
            s = imess_deviation.colour_points(doc, report)
        except imess_capture.CaptureError as e:
            self.note("inspect", "cannot colour: %s" % e)
            QtGui.QMessageBox.warning(self, "IMESS deviations", str(e))
            return
        for i in reversed(range(self.result_list.topLevelItemCount())):
            if self.result_list.topLevelItem(i).data(0, QtCore.Qt.UserRole) == "inspection":
                self.result_list.takeTopLevelItem(i)
        rows = [imess_inspect.characteristic_row(c) for c in s["report"]["characteristics"]]
        for name, value in reversed(rows):
            self.add_result(name, value, "inspection")
        added = " (%d added: not captured here)" % s["added"] if s["added"] else ""
        self.note("colour", "%d points coloured%s, %d out; %s" % (s["points"], added, s["out_of_tolerance"],
                                                                 imess_inspect.summary_text(s["report"]["summary"], len(rows))))


def show_panel():
    main = FreeCADGui.getMainWindow()
    old = main.findChild(QtGui.QDockWidget, "IMESS_Capture")
    if old is not None:
        old.show()
        old.raise_()
        return old
    panel = CapturePanel()
    main.addDockWidget(QtCore.Qt.RightDockWidgetArea, panel)
    return panel
