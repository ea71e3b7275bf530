# IMESS panel events for FreeCAD, without the GUI: what happened, with the time it happened, one
# entry per topic (a jog, the control, a fit ...), so a newer event of a topic replaces the older
# one and a state that ended is cleared instead of being shown as if it still held.
"""The panel's event list (testable under freecadcmd)."""

import time

ROWS = 6  # the panel shows this many, newest first; its height never changes


class EventLog:
    """Events by topic. post() replaces the topic's entry (a refused jog by the next jog),
    clear() removes it (a jog that ended, a refusal made stale by a change of control)."""

    def __init__(self, clock=time.time, rows=ROWS):
        self.clock = clock
        self.rows = rows
        self.entries = {}  # topic -> (time, order, text)
        self.version = 0   # changes whenever the list changes: the panel redraws only then

    def post(self, topic, text):
        self.version += 1
        self.entries[topic] = (self.clock(), self.version, text)

    def clear(self, topic):
        if self.entries.pop(topic, None) is not None:
            self.version += 1

    def text(self, topic):
        """The topic's current text, or None."""
        entry = self.entries.get(topic)
        return entry[2] if entry else None

    def lines(self):
        """[(\"12:04:31\", text), ...], newest first, at most `rows`."""
        newest = sorted(self.entries.values(), key=lambda e: e[:2], reverse=True)[: self.rows]
        return [(time.strftime("%H:%M:%S", time.localtime(t)), text) for t, _, text in newest]
