"""A headless Chromium driven over the DevTools protocol, Python standard library only.

Chromium speaks the protocol over a pipe when started with --remote-debugging-pipe:
it reads commands from its file descriptor 3 and writes replies and events to 4,
each message JSON ended by a NUL byte. A pipe needs no port, no WebSocket client
and no package: that is why the browser test drives it this way.
"""
import base64
import json
import os
import queue
import subprocess
import threading
import time

# Flags that work on a machine with no GPU, no display and no network: WebGL2 runs
# on SwiftShader (a CPU renderer) through ANGLE, and the background services that
# would try to reach the internet are off.
FLAGS = ["--headless", "--no-sandbox", "--disable-gpu-sandbox", "--no-first-run", "--disable-background-networking",
         "--disable-component-update", "--disable-sync", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
         "--force-device-scale-factor=1", "--hide-scrollbars", "--font-render-hinting=none",
         "--remote-debugging-pipe"]


class ProtocolError(Exception):
    pass


class Browser:
    def __init__(self, executable, profile, timeout=30):
        self.timeout = timeout
        to_child, self._write = os.pipe()
        self._read, from_child = os.pipe()

        def as_fd_3_and_4():  # in the child, before exec: copies first, in case a pipe is 3 or 4 already
            commands, replies = os.dup(to_child), os.dup(from_child)
            os.dup2(commands, 3)  # dup2 makes 3 and 4 inheritable: they survive exec
            os.dup2(replies, 4)

        self.process = subprocess.Popen([executable, *FLAGS, "--user-data-dir=" + str(profile), "about:blank"],
                                        stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                                        stderr=subprocess.DEVNULL, close_fds=False, preexec_fn=as_fd_3_and_4)
        os.close(to_child)
        os.close(from_child)
        self._next_id = 0
        self._messages = queue.Queue()
        self.events = []  # every event received, in order: (session, method, params)
        threading.Thread(target=self._reader, daemon=True).start()

    def _reader(self):
        pending = b""
        while True:
            chunk = os.read(self._read, 1 << 16)
            if not chunk:
                self._messages.put(None)
                return
            pending += chunk
            *whole, pending = pending.split(b"\0")
            for message in whole:
                self._messages.put(json.loads(message))

    def send(self, method, params=None, session=None):
        """Sends a command and returns its result; events met meanwhile go to self.events."""
        self._next_id += 1
        message = {"id": self._next_id, "method": method, "params": params or {}}
        if session:
            message["sessionId"] = session
        os.write(self._write, json.dumps(message).encode() + b"\0")
        deadline = time.monotonic() + self.timeout
        while True:
            reply = self._take(deadline, method)
            if reply.get("id") == self._next_id:
                if "error" in reply:
                    raise ProtocolError(f"{method}: {reply['error'].get('message')}")
                return reply["result"]
            if "method" in reply:
                self.events.append((reply.get("sessionId"), reply["method"], reply.get("params", {})))

    def wait_for_event(self, session, method):
        deadline = time.monotonic() + self.timeout
        seen = 0
        while True:
            for event in self.events[seen:]:
                if event[0] == session and event[1] == method:
                    self.events.remove(event)
                    return event[2]
            seen = len(self.events)
            reply = self._take(deadline, method)
            if "method" in reply:
                self.events.append((reply.get("sessionId"), reply["method"], reply.get("params", {})))

    def _take(self, deadline, waiting_for):
        try:
            reply = self._messages.get(timeout=max(0.01, deadline - time.monotonic()))
        except queue.Empty:
            raise ProtocolError(f"no answer to {waiting_for} within {self.timeout} s") from None
        if reply is None:
            raise ProtocolError(f"Chromium closed the pipe while waiting for {waiting_for}")
        return reply

    def close(self):
        try:
            self.send("Browser.close")
        except ProtocolError:
            pass
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()
        os.close(self._write)


class Page:
    """One tab, with what it logs as errors gathered in self.errors."""

    def __init__(self, browser, width, height):
        self.browser = browser
        target = browser.send("Target.createTarget", {"url": "about:blank"})
        self.target = target["targetId"]
        self.session = browser.send("Target.attachToTarget", {"targetId": self.target, "flatten": True})["sessionId"]
        for domain in ("Page", "Runtime", "Log"):
            self.send(domain + ".enable")
        self.send("Emulation.setDeviceMetricsOverride",
                  {"width": width, "height": height, "deviceScaleFactor": 1, "mobile": False})

    def send(self, method, params=None):
        return self.browser.send(method, params, self.session)

    def open(self, url):
        self.send("Page.navigate", {"url": url})
        self.browser.wait_for_event(self.session, "Page.loadEventFired")

    def evaluate(self, expression):
        result = self.send("Runtime.evaluate", {"expression": expression, "returnByValue": True})
        if "exceptionDetails" in result:
            details = result["exceptionDetails"]
            raise ProtocolError(f"{expression[:60]}...: "
                                f"{details.get('exception', {}).get('description') or details.get('text')}")
        return result["result"].get("value")

    def wait_until(self, expression, what):
        deadline = time.monotonic() + self.browser.timeout
        while not self.evaluate(expression):
            if time.monotonic() > deadline:
                raise ProtocolError(f"{what}: not within {self.browser.timeout} s")
            time.sleep(0.05)

    def errors(self):
        """Console errors, uncaught exceptions and failed loads of this page so far."""
        found = []
        for session, method, params in self.browser.events:
            if session != self.session:
                continue
            if method == "Runtime.exceptionThrown":
                details = params["exceptionDetails"]
                found.append(details.get("exception", {}).get("description") or details.get("text"))
            elif method == "Runtime.consoleAPICalled" and params["type"] in ("error", "assert", "warning"):
                found.append(" ".join(str(a.get("value", a.get("description"))) for a in params["args"]))
            elif method == "Log.entryAdded" and params["entry"]["level"] in ("error", "warning"):
                found.append(params["entry"]["text"])
        return found

    def click(self, x, y):
        for kind in ("mousePressed", "mouseReleased"):
            self.send("Input.dispatchMouseEvent", {"type": kind, "x": x, "y": y, "button": "left", "clickCount": 1})

    def drag(self, start, end, steps=8):
        self.send("Input.dispatchMouseEvent", {"type": "mousePressed", "x": start[0], "y": start[1], "button": "left",
                                               "clickCount": 1})
        for k in range(1, steps + 1):
            x = start[0] + (end[0] - start[0]) * k / steps
            y = start[1] + (end[1] - start[1]) * k / steps
            self.send("Input.dispatchMouseEvent", {"type": "mouseMoved", "x": x, "y": y, "button": "left", "buttons": 1})
        self.send("Input.dispatchMouseEvent", {"type": "mouseReleased", "x": end[0], "y": end[1], "button": "left",
                                               "clickCount": 1})

    def hover(self, x, y):
        self.send("Input.dispatchMouseEvent", {"type": "mouseMoved", "x": x, "y": y})

    def box(self, selector):
        """The element's box in page pixels: x, y, width, height."""
        return self.evaluate(f"(() => {{ const r = document.querySelector({json.dumps(selector)})"
                             ".getBoundingClientRect(); return [r.x, r.y, r.width, r.height]; })()")

    def full_page_screenshot(self, width):
        """The whole page, as tall as it is (at most 16 000 px): the window is made that
        tall for the shot, then set back."""
        height = min(self.evaluate("document.documentElement.scrollHeight"), 16000)
        self.send("Emulation.setDeviceMetricsOverride",
                  {"width": width, "height": height, "deviceScaleFactor": 1, "mobile": False})
        shot = self.screenshot()
        self.send("Emulation.setDeviceMetricsOverride",
                  {"width": width, "height": 900, "deviceScaleFactor": 1, "mobile": False})
        return shot

    def screenshot(self, clip=None):
        params = {"format": "png", "captureBeyondViewport": clip is None}
        if clip:
            params["clip"] = {"x": clip[0], "y": clip[1], "width": clip[2], "height": clip[3], "scale": 1}
        return base64.b64decode(self.send("Page.captureScreenshot", params)["data"])
