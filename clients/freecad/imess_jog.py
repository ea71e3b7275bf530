# IMESS jog pendant logic for FreeCAD, without the GUI: press-and-hold jogging along ±X ±Y ±Z at
# the 1996 panel's speeds (2, 20, 100 % of MaxSpeed), stop, "measure here" (ForcePt), and the
# dead-man: Watch 500 before the first motion, keep-alives while a jog is held.
"""Jog buttons' behaviour on a CaptureSession (testable under freecadcmd)."""

from imess_capture import CaptureError

SPEEDS = (2.0, 20.0, 100.0)  # percent of MaxSpeed, as the 1996 panel and messjog
DEFAULT_SPEED = 20.0
DIRECTIONS = {  # button name -> unit direction
    "+X": (1, 0, 0), "-X": (-1, 0, 0),
    "+Y": (0, 1, 0), "-Y": (0, -1, 0),
    "+Z": (0, 0, 1), "-Z": (0, 0, -1),
}
# Dead-man: messd stops the machine when the plugin, in control, is silent this long. While a
# jog is held (or the machine moves, or a reply is due) a blank line goes out every
# KEEPALIVE_MOVING seconds, otherwise every KEEPALIVE_IDLE (so messd never drops a silent owner).
WATCH_MS = 500
KEEPALIVE_MOVING = 0.1
KEEPALIVE_IDLE = 30.0
MOVING_STATES = ("jog", "move", "retract", "home", "stopping")
_STOPPED_BY_MESSD = ("Warn WatchExpired", "Warn ControlTaken", "Fault ")


def start_line(direction, percent):
    """'StartMv 0.000 -20.000 0.000' for a button and a speed."""
    return "StartMv %.3f %.3f %.3f" % tuple(c * percent for c in DIRECTIONS[direction])


class JogControl:
    """What the jog buttons do, on one CaptureSession.

    press(d) starts a jog the moment a direction button goes down, release(d) stops it when the
    button comes up (press and hold, as on a pendant). stop() is the Stop button, measure_here()
    sends ForcePt, tick() sends keep-alives and is called from the panel's poll timer. Every
    method returns True when it sent something. The session's event log shows the jog while it
    runs ("jog", replaced by "… ended" when the machine stands again), refusals ("jog",
    "measure": cleared when control changes hands, as they no longer hold) and messd's stops.
    """

    def __init__(self, session):
        self.session = session
        self.speed = DEFAULT_SPEED
        self.held = None       # the direction whose button is down
        self.moving = None     # the direction messd was asked to jog and has not stopped, as far as we know
        self.machine_state = ""
        self.watching = False  # Watch sent on this connection
        self.active = None     # the direction of the jog shown as running in the events
        self.refused = set()   # event topics that hold a refusal
        self.events = session.events
        session.observers.append(self.on_line)

    # --- buttons --------------------------------------------------------------------------
    def press(self, direction):
        if direction not in DIRECTIONS:
            raise CaptureError("unknown jog direction %r; accepted: %s" % (direction, " ".join(DIRECTIONS)))
        self.held = direction
        return self._start(direction)

    def release(self, direction):
        """The button came up: stop (also when messd already stopped - a stop never hurts)."""
        if self.held != direction:
            return False
        self.held = None
        return self.stop()

    def stop(self):
        self.held = None
        self.moving = None
        return self._send("StopMv")

    def set_speed(self, percent):
        """Chooses 2, 20 or 100 %; a held jog goes on in the same direction at the new speed."""
        if percent not in SPEEDS:
            raise CaptureError("jog speed %r %%; accepted: %s" % (percent, ", ".join("%g" % s for s in SPEEDS)))
        self.speed = percent
        if self.held is not None and self.moving == self.held:
            return self._start(self.held)
        return False

    def measure_here(self):
        return self._arm() and self._send("ForcePt")

    # --- time and messd -------------------------------------------------------------------
    def keepalive_interval(self):
        busy = (self.held is not None or self.moving is not None or self.machine_state in MOVING_STATES
                or bool(self.session.pending))
        return KEEPALIVE_MOVING if busy else KEEPALIVE_IDLE

    def tick(self, now=None):
        """From the poll timer: a keep-alive when one is due; forgets motion when the link is gone."""
        if not self.session.connected():
            self.held = self.moving = None
            return False
        if not self.watching:
            return False
        now = self.session.clock() if now is None else now
        if self.session.last_sent is not None and now - self.session.last_sent < self.keepalive_interval():
            return False
        return self._send("")

    def on_line(self, line, answered):
        """Every line messd sends (a CaptureSession observer)."""
        verb, _, args = line.partition(" ")
        if verb == "State":
            self.machine_state = args.strip()
            if self.machine_state != "jog" and "StartMv" not in self.session.pending:
                self.moving = None  # stopped by a hit, a limit, another client
            if self.active and self.machine_state not in ("jog", "stopping") and "StartMv" not in self.session.pending:
                self.post("jog", "jog %s ended" % self.active)
        elif verb == "Ok" and answered == "StopMv" and self.active and self.machine_state not in ("jog", "stopping") \
                and "StartMv" not in self.session.pending:
            self.post("jog", "jog %s ended" % self.active)  # stopped before it ever ran: no State line comes
        elif line.startswith(_STOPPED_BY_MESSD):
            self.moving = None
            self.post("jog", "jog stopped by messd: %s" % line)
        elif verb == "Control":
            for topic in self.refused:
                self.events.clear(topic)  # who holds control changed: the refusal no longer holds
            self.refused.clear()
        elif verb == "Err" and answered in ("StartMv", "ForcePt", "Watch"):
            if answered == "StartMv" and "StartMv" not in self.session.pending:
                self.moving = None
            topic = "measure" if answered == "ForcePt" else "jog"
            self.post(topic, "%s refused: %s" % ("Measure here" if answered == "ForcePt" else answered, line))
            self.refused.add(topic)

    def post(self, topic, text):
        if topic == "jog":
            self.active = None
        self.refused.discard(topic)
        self.events.post(topic, text)

    # --- sending --------------------------------------------------------------------------
    def _start(self, direction):
        if not self._arm():
            return False
        self.moving = direction
        if not self._send(start_line(direction, self.speed)):
            self.moving = None
            return False
        self.post("jog", "jog %s at %g %%" % (direction, self.speed))
        self.active = direction
        return True

    def _arm(self):
        """Watch before the first motion command of a connection: messd then stops the machine
        when the plugin falls silent (FreeCAD hangs, the network breaks)."""
        if self.watching:
            return True
        if self._send("Watch %d" % WATCH_MS):
            self.watching = True
        return self.watching

    def _send(self, line):
        if not self.session.connected():
            self.post("jog", "not connected to messd: %s not sent" % (line or "keep-alive"))
            self.held = self.moving = None
            return False
        try:
            self.session.send(line)
        except CaptureError as e:
            self.post("jog", str(e))
            self.held = self.moving = None
            return False
        return True
