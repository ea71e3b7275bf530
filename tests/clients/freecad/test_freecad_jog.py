# Inside freecadcmd: the plugin's jog buttons against a real messd. Pressing a direction button
# (a real mouse press on the Qt button) jogs the machine at the chosen speed for as long as it is
# held (keep-alives keep messd's dead-man quiet; a frozen panel is stopped by it); letting go,
# sliding off, a lost button grab or closing the panel stop it. Refusals and messd's stops are
# shown with their time and cleared when they no longer hold; the layout never moves a button.
# JogControl's keep-alive timing is also checked on a virtual clock. argv: BIN_DIR SOURCE_DIR
import os
import socket
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from plugin_test import Messd, Operator, check, connect_panel, finish, mouse, panel_module, pump  # noqa: E402

import FreeCAD  # noqa: E402
import imess_capture  # noqa: E402
import imess_jog  # noqa: E402
from PySide import QtCore  # noqa: E402


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
    check(not jog.press("+X") and "not connected" in session.events.text("jog"), "a closed link: nothing sent, the event says why")
    FreeCAD.closeDocument(doc.Name)


def speed(session, app, seconds):
    """mm/s the probe moved over `seconds` of CurrCor, while the panel's timer runs."""
    pump(app, 0.25)
    a, ta = session.position, time.monotonic()
    pump(app, seconds)
    return (session.position - a).Length / (time.monotonic() - ta)


def panel_checks():
    mod, warnings, app = panel_module()
    messd = Messd(real_speed=True)
    doc = FreeCAD.newDocument("jogpanel")
    panel = mod.CapturePanel()
    panel.resize(420, 1000)
    panel.show()
    buttons = panel.jog_buttons
    app.processEvents()
    layout = {name: b.mapTo(panel, QtCore.QPoint(0, 0)) for name, b in buttons.items()}

    mouse(buttons["+X"], "press")
    mouse(buttons["+X"], "release")
    check(panel.events.text("link") == "connect to messd first", "jog before Connect: %s" % panel.events.lines())
    check(sorted(buttons) == sorted(imess_jog.DIRECTIONS) and panel.checked_speed() == 20.0,
          "six direction buttons, 20 % chosen at start")
    check(connect_panel(panel, app, messd.port), "Connect: %s" % panel.events.lines())
    s = panel.session
    state = lambda name: lambda: s.state == name  # noqa: E731

    start = s.position
    mouse(buttons["+X"], "press")
    check(pump(app, 2, state("jog")) and s.holds_control(), "press +X: the machine jogs, the panel holds control")
    v = speed(s, app, 1.5)
    check(s.state == "jog" and 10 < v < 24 and s.events.text("jog") == "jog +X at 20 %" and
          s.events.text("messd") is None, "held 1.75 s: +X at 20 %% of MaxSpeed 100 (%.1f mm/s), the dead-man quiet: %s"
          % (v, panel.events.lines()))
    mouse(buttons["+X"], "release")
    check(pump(app, 2, state("idle")) and s.position.x > start.x + 30, "letting go of +X stops: %s" % s.position)
    pump(app, 0.2)
    check(s.events.text("jog") == "jog +X ended", "the jog's event says it ended: %s" % panel.events.lines())

    mouse(panel.speed_buttons[100.0], "press")
    mouse(panel.speed_buttons[100.0], "release")
    mouse(buttons["+Y"], "press")
    pump(app, 0.3, state("jog"))
    v = speed(s, app, 1.0)
    mouse(buttons["+Y"], "move", inside=False)
    check(75 < v < 125 and pump(app, 2, state("idle")), "+Y at 100 %% (%.1f mm/s); sliding off the held button stops"
          % v)
    mouse(buttons["+Y"], "release", inside=False)

    mouse(panel.speed_buttons[2.0], "press")
    mouse(panel.speed_buttons[2.0], "release")
    mouse(buttons["+Z"], "press")
    pump(app, 1, state("jog"))
    time.sleep(1.0)  # FreeCAD hangs: no keep-alive for 1 s
    check(pump(app, 1, lambda: s.state == "idle" and panel.jog.moving is None) and
          s.events.text("jog").startswith("jog stopped by messd: Warn WatchExpired"),
          "a frozen panel is stopped by messd's dead-man, and it is shown: %s" % panel.events.lines())
    mouse(buttons["+Z"], "release")

    buttons["-X"].pressed.emit()  # pressed, but the button is not down (its grab was lost)
    check(pump(app, 2, lambda: s.events.text("jog") == "jog -X ended"), "a held button no longer down stops at the next "
          "tick: %s" % panel.events.lines())

    op = Operator(messd.port)
    op.request("Hello operator")
    op.request("Take force")
    check(pump(app, 2, lambda: s.control.startswith("operator ")) and "control: operator" in panel.state.text() and
          s.events.text("control").startswith("controlled by operator 127.0.0.1"),
          "another client took control: %r, %s" % (panel.state.text(), panel.events.lines()))
    mouse(buttons["+Z"], "press")
    check(pump(app, 2, lambda: (s.events.text("jog") or "").startswith("StartMv refused: Err 209")) and panel.jog.moving is None
          and s.state == "idle", "a refused jog is shown: %s" % panel.events.lines())
    mouse(buttons["+Z"], "release")
    op.request("Release")
    check(pump(app, 2, lambda: s.control == "none") and s.events.text("jog") is None and
          not any("Err 209" in text for _, text in panel.events.lines()),
          "control freed: the refusal no longer holds and is gone: %s" % panel.events.lines())
    mouse(buttons["+Z"], "press")
    check(pump(app, 2, state("jog")) and s.events.text("jog") == "jog +Z at 2 %", "now the jog works: %s"
          % panel.events.lines())
    mouse(buttons["+Z"], "release")
    check(pump(app, 2, lambda: s.events.text("jog") == "jog +Z ended"), "and ends: %s" % panel.events.lines())

    before = len(s.points)
    pump(app, 0.3)  # the servo loops settle
    mouse(panel.measure_button, "press")
    mouse(panel.measure_button, "release")
    check(pump(app, 2, lambda: len(s.points) == before + 1) and (s.points[-1].Measured - s.position).Length < 0.01,
          "Measure here: the standing position is a point: %s %s" % (panel.events.lines(), s.position))

    op.request("Take force")
    op.sock.sendall(b"GoTo 430 330 300\n")
    pump(app, 2, state("move"))
    mouse(panel.stop_button, "press")
    mouse(panel.stop_button, "release")
    check(pump(app, 3, state("idle")) and s.position.z < 290, "Stop stops another client's move: z %.3f" % s.position.z)
    op.request("Release")
    op.close()

    mouse(buttons["-X"], "press")
    pump(app, 2, state("jog"))
    panel.close()
    check(pump(app, 2, state("idle")) and s.connected(), "closing the panel stops the jog, capture goes on")

    check(all(b.mapTo(panel, QtCore.QPoint(0, 0)) == layout[n] for n, b in buttons.items()),
          "after all these events no jog button moved on the panel")

    panel.show()
    mouse(buttons["-Y"], "press")
    pump(app, 2, state("jog"))
    messd.stop()
    pump(app, 1, lambda: not s.connected())
    check(not s.connected() and not panel.timer.isActive() and panel.jog.held is None and
          "link ended (closed by messd)" in s.events.text("link"), "a lost link ends the jog and the polling: %s"
          % panel.events.lines())
    mouse(buttons["-Y"], "release")
    check(not warnings, "no warnings: %s" % warnings)
    FreeCAD.closeDocument(doc.Name)


finish("freecad jog", control_checks, panel_checks)
