# A scripted messd for the FreeCAD plugin tests: accepts one client on a loopback port, records
# every line it sends with the time it arrived, answers each non-blank line "Ok VERB" (or a
# scripted Err), and pushes events on request.
import socket
import threading
import time


class FakeMessd:
    def __init__(self):
        self.server = socket.socket()
        self.server.bind(("127.0.0.1", 0))
        self.server.listen(1)
        self.port = self.server.getsockname()[1]
        self.refuse = {}     # verb -> the Err line to answer instead of Ok
        self.received = []   # (time.monotonic(), line), blank keep-alives included
        self.conn = None
        self.lock = threading.Lock()
        threading.Thread(target=self._serve, daemon=True).start()

    def _serve(self):
        self.conn, _ = self.server.accept()
        buf = b""
        while True:
            try:
                chunk = self.conn.recv(4096)
            except OSError:
                return
            if not chunk:
                return
            buf += chunk
            while b"\n" in buf:
                raw, buf = buf.split(b"\n", 1)
                line = raw.decode().rstrip("\r")
                with self.lock:
                    self.received.append((time.monotonic(), line))
                if line.strip():
                    verb = line.split()[0]
                    self.push(self.refuse.get(verb, "Ok " + verb))

    def push(self, line):
        try:
            self.conn.sendall((line + "\n").encode())
        except OSError:
            pass

    def lines(self, blank=False):
        """What the client sent, in order; without keep-alives unless blank."""
        with self.lock:
            return [line for _, line in self.received if blank or line.strip()]

    def times(self):
        with self.lock:
            return [t for t, _ in self.received]

    def drop_client(self):
        self.conn.shutdown(socket.SHUT_RDWR)
        self.conn.close()

    def close(self):
        self.server.close()
