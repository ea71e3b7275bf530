# Inside freecadcmd: the plugin's jog buttons against a fake messd. Pressing a direction button
# (a real mouse press on the Qt button) sends Watch once and StartMv at the chosen speed,
# keep-alives flow while it is held, letting go / sliding off / closing the panel / a lost
# button grab send StopMv; refusals and messd's own stops are shown; a lost link ends cleanly.
# JogControl's keep-alive timing is also checked on a virtual clock. argv: BIN_DIR SOURCE_DIR
import os
import socket
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from fake_messd import FakeMessd  # noqa: E402
from plugin_test import check, finish, macro_namespace  # noqa: E402

import FreeCAD  # noqa: E402
import imess_capture  # noqa: E402
import imess_jog  # noqa: E402
from PySide import QtCore, QtGui  # noqa: E402


class Clock:
    now = 0.0

    def __call__(self):
        return self.now


def control_checks():
    """JogControl on a socket pair with a virtual clock: what goes out, and when."""
    doc = FreeCAD.newDocument("jogcontrol")
    ours, daemon = socket.socketpair()
    daemon.settimeout(2)
    clock = Clock()
    session = imess_capture.CaptureSession(doc, sock=ours, clock=clock)
    jog = imess_jog.JogControl(session)

    def sent():
        ours.setblocking(False)
        try:
            return daemon.recv(65536).decode().split("\n")[:-1]
        except (BlockingIOError, socket.timeout):
            return []

    clock.now = 100.0
    check(not jog.tick() and sent() == [], "a capture-only session stays passive: no Watch, no keep-alives")
    jog.press("+Y")
    check(sent() == ["Watch 500", "StartMv 0.000 20.000 0.000"], "the first jog arms the dead-man, then starts")
    clock.now = 100.05
    check(not jog.tick(), "no keep-alive before 100 ms")
    clock.now = 100.0 + imess_jog.KEEPALIVE_MOVING + 1e-9
    check(jog.tick() and sent() == [""], "a blank keep-alive every 100 ms while held")
    jog.set_speed(100.0)
    check(sent() == ["StartMv 0.000 100.000 0.000"], "a new speed while held goes on at that speed")
    jog.release("-Y")
    check(sent() == [], "releasing another button does nothing")
    jog.release("+Y")
    check(sent() == ["StopMv"], "releasing the held button stops")
    daemon.sendall(b"Ok Watch\nOk StartMv\nOk StartMv\nOk StopMv\nState idle\n")
    session.poll()
    check(not session.pending and jog.keepalive_interval() == imess_jog.KEEPALIVE_IDLE,
          "idle and answered: keep-alives slow down to %s s" % imess_jog.KEEPALIVE_IDLE)
    clock.now = 110.0
    check(not jog.tick(), "no keep-alive 10 s after the last line while idle")
    clock.now = 100.0 + imess_jog.KEEPALIVE_MOVING + imess_jog.KEEPALIVE_IDLE + 1e-6
    check(jog.tick() and sent() == [""], "an idle keep-alive after 30 s (messd never drops the owner)")
    daemon.sendall(b"State jog\n")
    session.poll()
    check(jog.keepalive_interval() == imess_jog.KEEPALIVE_MOVING, "a machine moving for someone else: fast keep-alives")
    for bad, call in (("direction", lambda: jog.press("+W")), ("speed", lambda: jog.set_speed(50))):
        try:
            call()
            check(False, "a bad %s is refused" % bad)
        except imess_capture.CaptureError as e:
            check("accepted" in str(e), "a bad %s names the accepted ones: %s" % (bad, e))
    daemon.close()
    session.poll()
    check(not jog.press("+X") and "not connected" in jog.note, "a closed link: nothing sent, the note says why")
    FreeCAD.closeDocument(doc.Name)


def mouse(button, kind, inside=True):
    """A left-button mouse event on a Qt button, at its centre or well outside it."""
    pos = QtCore.QPointF(button.rect().center()) if inside else QtCore.QPointF(-50, -50)
    event_type = {"press": QtCore.QEvent.MouseButtonPress, "release": QtCore.QEvent.MouseButtonRelease,
                  "move": QtCore.QEvent.MouseMove}[kind]
    buttons = QtCore.Qt.NoButton if kind == "release" else QtCore.Qt.LeftButton
    which = QtCore.Qt.NoButton if kind == "move" else QtCore.Qt.LeftButton
    QtGui.QApplication.sendEvent(button, QtGui.QMouseEvent(event_type, pos, which, buttons, QtCore.Qt.NoModifier))


def panel_checks():
    ns, warnings, app = macro_namespace()
    daemon = FakeMessd()
    doc = FreeCAD.newDocument("jogpanel")
    panel = ns["CapturePanel"]()
    buttons = panel.jog_buttons

    def pump(seconds):
        end = time.time() + seconds
        while time.time() < end:
            app.processEvents()
            time.sleep(0.005)

    def after(count, seconds=2.0):
        """The non-blank lines sent after the first `count`, once they stop changing."""
        end = time.time() + seconds
        seen = -1
        while time.time() < end:
            pump(0.05)
            now = len(daemon.lines())
            if now == seen:
                break
            seen = now
        return daemon.lines()[count:]

    mouse(buttons["+X"], "press")
    mouse(buttons["+X"], "release")
    check("connect to messd first" in panel.status.text(), "jog before Connect: %r" % panel.status.text())
    check(sorted(buttons) == sorted(imess_jog.DIRECTIONS) and panel.checked_speed() == 20.0,
          "six direction buttons, 20 % chosen at start")

    panel.host.setText("127.0.0.1")
    panel.port.setValue(daemon.port)
    panel.toggle()
    check(after(0) == ["Hello FreeCAD"], "Connect says Hello and nothing else: %s" % daemon.lines())

    n = len(daemon.lines())
    mouse(buttons["+X"], "press")
    check(after(n) == ["Watch 500", "StartMv 20.000 0.000 0.000"], "press +X: Watch, then StartMv at 20 %%: %s"
          % daemon.lines()[n:])
    held_from = time.monotonic()
    pump(0.6)
    during = [t for t in daemon.times() if t >= held_from]
    gaps = [b - a for a, b in zip([held_from] + during, during + [time.monotonic()])]
    check(len(daemon.lines(blank=True)) - len(daemon.lines()) >= 3 and max(gaps) < imess_jog.WATCH_MS / 1000.0,
          "keep-alives while held, never silent as long as the dead-man (largest gap %.3f s)" % max(gaps))
    n = len(daemon.lines())
    mouse(buttons["+X"], "release")
    check(after(n) == ["StopMv"], "letting go of +X stops: %s" % daemon.lines()[n:])

    mouse(panel.speed_buttons[100.0], "press")
    mouse(panel.speed_buttons[100.0], "release")
    check(panel.checked_speed() == 100.0, "the 100 % button is chosen")
    n = len(daemon.lines())
    mouse(buttons["-Z"], "press")
    check(after(n) == ["StartMv 0.000 0.000 -100.000"], "-Z at 100 %%, no second Watch: %s" % daemon.lines()[n:])
    n = len(daemon.lines())
    mouse(buttons["-Z"], "move", inside=False)
    check(after(n) == ["StopMv"], "sliding off the held button stops: %s" % daemon.lines()[n:])
    mouse(buttons["-Z"], "release", inside=False)
    check(after(n) == ["StopMv"], "and the release outside adds nothing")

    mouse(panel.speed_buttons[2.0], "press")
    mouse(panel.speed_buttons[2.0], "release")
    n = len(daemon.lines())
    mouse(buttons["+Y"], "press")
    after(n)
    daemon.push("Warn WatchExpired silent for 500 ms: the machine was stopped")
    pump(0.2)
    check(panel.jog.moving is None and "jog stopped by messd" in panel.status.text(),
          "messd's dead-man stop is shown: %r" % panel.status.text())
    mouse(buttons["+Y"], "release")
    check(after(n) == ["StartMv 0.000 2.000 0.000", "StopMv"], "2 %%, and a stop on release all the same: %s"
          % daemon.lines()[n:])

    n = len(daemon.lines())
    buttons["-X"].pressed.emit()  # pressed, but the button is not down (its grab was lost)
    check(after(n) == ["StartMv -2.000 0.000 0.000", "StopMv"], "a held button no longer down stops at the next tick: %s"
          % daemon.lines()[n:])

    daemon.refuse["StartMv"] = "Err 209 the machine is controlled by messjog at 127.0.0.1 (client 1)"
    n = len(daemon.lines())
    mouse(buttons["+Z"], "press")
    after(n)
    check(panel.jog.moving is None and "StartMv refused: Err 209" in panel.status.text(),
          "a refused jog is shown: %r" % panel.status.text())
    mouse(buttons["+Z"], "release")
    check(after(n) == ["StartMv 0.000 0.000 2.000", "StopMv"], "the refused jog's release still stops: %s"
          % daemon.lines()[n:])
    del daemon.refuse["StartMv"]

    n = len(daemon.lines())
    mouse(panel.measure_button, "press")
    mouse(panel.measure_button, "release")
    mouse(panel.stop_button, "press")
    mouse(panel.stop_button, "release")
    check(after(n) == ["ForcePt", "StopMv"], "Measure here sends ForcePt, Stop sends StopMv: %s"
          % daemon.lines()[n:])

    n = len(daemon.lines())
    mouse(buttons["+X"], "press")
    after(n)
    panel.close()
    check(after(n) == ["StartMv 2.000 0.000 0.000", "StopMv"], "closing the panel stops the jog: %s" % daemon.lines()[n:])
    check(panel.session.connected(), "and capture goes on")

    n = len(daemon.lines())
    mouse(buttons["-Y"], "press")
    after(n)
    daemon.drop_client()
    pump(0.3)
    check(not panel.session.connected() and not panel.timer.isActive() and panel.jog.held is None,
          "a lost link ends the jog and the polling: %r" % panel.status.text())
    mouse(buttons["-Y"], "release")
    check(not warnings, "no warnings: %s" % warnings)
    daemon.close()
    FreeCAD.closeDocument(doc.Name)


finish("freecad jog", control_checks, panel_checks)
