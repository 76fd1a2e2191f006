"""The grader's side of the result channel: the bytes the sandboxed harness writes into a pipe,
read as records that are checked before anything is believed.

A record is a 4-byte big-endian length (1 to 64 KiB), that many bytes of a JSON object, then,
for an `end` record whose status is `ok`, the value: 8 × prod(shape) bytes of little-endian
float64. The records must come in the one order the harness writes them: start and end of the
import, then start and end of each call of the batch, in the batch's order. A value may hold at
most the call's `max_values` numbers, and the values of a session at most its byte budget.

Anything else (a header too long or not JSON, an unknown or repeated call, a shape over the
budget, bytes after a failed import) breaks the channel: the reader stops, the grader kills the
child, and the call in progress gets the verdict `forbidden`. The reader never allocates more than
one record's bytes plus one read, whatever it is fed, and never raises.

What this cannot tell apart: a record the harness wrote from one the student's code wrote in the
same process (the audit hook can be switched off, the pipe's descriptor found in /proc/self/fd).
Forging the result of a call (or, in order, of the calls after it, whose inputs it can read) is
no more than returning those values, which the student's functions can do anyway; what the
channel guarantees is that nothing sent can hang, crash or exhaust the grader, or be read as a
call it is not.
"""

import json
import math

import numpy as np

from . import untrusted

HEADER_MAX = 65536
DEFAULT_VALUES = 3 * 1024 * 1024      # a value of a call without a canvas: a 1024² RGB image
STATUSES = ("ok", "error", "timeout", "memory", "forbidden", "crashed")


class Broken(Exception):
    pass


def max_values(call):
    """The most numbers a call's result may hold: twice its canvas (a transposed or padded
    canvas is still graded), else DEFAULT_VALUES (render_img's own 512² canvas fits)."""
    shape = call.get("canvas_shape")
    if isinstance(shape, list) and shape and all(isinstance(n, int) and n > 0 for n in shape):
        return max(2 * math.prod(shape), 4096)
    return DEFAULT_VALUES


def _header(data):
    try:
        header = json.loads(data.decode("utf-8"))
    except Exception as e:  # noqa: BLE001 - UnicodeError, ValueError, RecursionError: all bytes
        raise Broken(f"a record that is not JSON ({type(e).__name__})") from None
    if not isinstance(header, dict):
        raise Broken("a record that is not a JSON object")
    return header


def _shape(header, limit):
    shape = header.get("shape")
    if not (isinstance(shape, list) and len(shape) <= 3
            and all(type(n) is int and n >= 0 for n in shape)):
        raise Broken(f"a declared shape {untrusted.one_line(repr(shape))[:80]} that is not an "
                     "array shape of at most 3 dimensions")
    if max(shape, default=0) > limit or math.prod(shape) > limit:
        raise Broken(f"a value of shape {tuple(shape)}: more than the {limit} numbers this call "
                     "may return")
    return shape


class Reader:
    """Feed it the channel's bytes as they come; read started, ended, broken, payload_bytes."""

    def __init__(self, calls, budget_bytes):
        self.ids = ["import"] + [c["id"] for c in calls]
        self.limits = {c["id"]: max_values(c) for c in calls}
        self.budget = budget_bytes
        self.buffer = bytearray()
        self.position = 0                 # records accepted (2 per call)
        self.pending = None               # (header length, header, value bytes) of a record
        self.started, self.ended = [], {}
        self.broken = None
        self.finished = False
        self.payload_bytes = 0

    def current(self):
        """The call the child is in (or about to start): the one a broken channel costs."""
        return self.ids[self.position // 2] if self.position // 2 < len(self.ids) else None

    def feed(self, data):
        if self.broken or self.finished:
            return
        self.buffer += data
        try:
            while not self.finished and self._one():
                pass
        except Broken as e:
            self.broken = str(e)
            self.buffer = bytearray()

    def _one(self):
        if self.pending is None:
            if len(self.buffer) < 4:
                return False
            size = int.from_bytes(self.buffer[:4], "big")
            if not 1 <= size <= HEADER_MAX:
                raise Broken(f"a record header of {size} bytes (1 to {HEADER_MAX})")
            if len(self.buffer) < 4 + size:
                return False
            header = _header(bytes(self.buffer[4:4 + size]))
            self.pending = (size, header, self._check(header))
        size, header, nbytes = self.pending
        if len(self.buffer) < 4 + size + nbytes:
            return False
        payload = bytes(self.buffer[4 + size:4 + size + nbytes])
        del self.buffer[:4 + size + nbytes]
        self.pending = None
        self._accept(header, payload)
        return True

    def _check(self, header):
        """The record's value size, once the record is known to be the one expected next."""
        event = "start" if self.position % 2 == 0 else "end"
        call = self.current()
        if header.get("event") != event or header.get("call") != call:
            got = untrusted.one_line(f"{header.get('event')!r} {header.get('call')!r}")[:120]
            raise Broken(f"a record {got} where {event} of {call!r} was due")
        if event == "start" or header.get("status") != "ok" or call == "import":
            return 0
        shape = _shape(header, self.limits[call])
        nbytes = 8 * math.prod(shape)
        if nbytes > self.budget - self.payload_bytes:
            raise Broken(f"more than {self.budget} bytes of results in all")
        return nbytes

    def _accept(self, header, payload):
        call = self.current()
        self.position += 1
        if header["event"] == "start":
            self.started.append(call)
            return
        self.payload_bytes += len(payload)
        self.ended[call] = _record(header, payload)
        if self.position == 2 * len(self.ids) or (call == "import"
                                                   and header.get("status") != "ok"):
            self.finished = True


def _record(header, payload):
    """An end record's fields, each of a known type and size, control characters escaped."""
    status = header.get("status")
    detail = untrusted.clean(str(header.get("detail", ""))[:4000])
    if status not in STATUSES:
        status, detail = "crashed", f"unreadable status {untrusted.one_line(repr(status))[:80]}"
    skipped = header.get("skipped", [])
    skipped = [untrusted.one_line(str(s))[:200] for s in skipped[:20]] \
        if isinstance(skipped, list) else []
    value = None
    if status == "ok" and "shape" in header:
        value = np.frombuffer(payload, dtype="<f8").reshape(header["shape"]).astype(np.float64)
    return {"status": status, "detail": detail, "value": value, "skipped": skipped,
            "returned": untrusted.one_line(str(header.get("returned", "")))[:40]}
