"""The result channel's reader (channel.py) fed anything: random bytes, random records, the
harness's own records cut at random places. It never raises, never holds more than one record
and one read, and either accepts the records in the one order the harness writes them or says the
channel is broken."""

import json
import os
import re
import threading

import numpy as np
from hypothesis import HealthCheck, given, settings, strategies as st

from scantrace.grade import channel, harness

CALLS = [{"id": "a", "canvas_shape": [4, 4, 3]}, {"id": "b"}, {"id": "c", "canvas_shape": [2, 2, 3]}]
BUDGET = 10_000_000
CONTROL = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f]")
MOST = 4 + channel.HEADER_MAX + 8 * channel.DEFAULT_VALUES   # one record at most


def _bytes_of_harness(records):
    """What harness._Status writes for these records, read back from a real pipe."""
    read_fd, write_fd = os.pipe()
    chunks = []
    reader = threading.Thread(target=lambda: chunks.extend(iter(lambda: os.read(read_fd, 65536),
                                                                b"")))
    reader.start()
    status = harness._Status(write_fd)
    for payload, record in records:
        status.write(payload, **record)
    os.close(write_fd)
    reader.join()
    os.close(read_fd)
    return b"".join(chunks)


def _feed(reader, data, cuts):
    points = sorted({min(c, len(data)) for c in cuts} | {0, len(data)})
    for a, b in zip(points, points[1:]):
        reader.feed(data[a:b])
        assert len(reader.buffer) <= MOST + (b - a)


def _check_invariants(reader):
    order = reader.ids
    assert reader.started == order[:len(reader.started)]
    assert set(reader.ended) <= set(reader.started)
    for call, record in reader.ended.items():
        assert record["status"] in channel.STATUSES
        if record["value"] is not None:
            assert record["value"].size <= reader.limits[call]
            assert record["value"].dtype == np.float64
        assert len(record["detail"]) <= 6 * 4000   # an escape is at most 6 characters
        assert not CONTROL.search(record["detail"] + record["returned"])
    assert reader.payload_bytes <= BUDGET


@settings(max_examples=300, deadline=2000, suppress_health_check=[HealthCheck.too_slow])
@given(st.binary(max_size=5000), st.lists(st.integers(0, 5000), max_size=20))
def test_random_bytes_give_a_verdict_never_an_exception(data, cuts):
    reader = channel.Reader(CALLS, BUDGET)
    _feed(reader, data, cuts)
    _check_invariants(reader)
    if data[:4] != b"" and not reader.started:
        # Random bytes almost never make a record: the channel is broken or still incomplete.
        assert reader.broken or len(data) < 4 + int.from_bytes(data[:4].ljust(4, b"\0"), "big")


_json = st.recursive(st.none() | st.booleans() | st.integers() | st.floats(allow_nan=False)
                     | st.text(max_size=20),
                     lambda children: st.lists(children, max_size=4)
                     | st.dictionaries(st.text(max_size=8), children, max_size=4), max_leaves=20)
_header = st.fixed_dictionaries({"event": st.sampled_from(["start", "end", "x"]),
                                 "call": st.sampled_from(["import", "a", "b", "c", "z"])},
                                optional={"status": st.sampled_from(list(channel.STATUSES)
                                                                    + ["bogus", 3]),
                                          "shape": st.lists(st.integers(-2, 70), max_size=4)
                                          | _json,
                                          "detail": st.text(max_size=300) | _json,
                                          "skipped": _json, "returned": _json})


@settings(max_examples=300, deadline=2000, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(st.tuples(_header, st.binary(max_size=600)), max_size=10),
       st.lists(st.integers(0, 20000), max_size=10))
def test_random_records_are_accepted_in_order_or_break_the_channel(records, cuts):
    data = b"".join(len(json.dumps(h).encode()).to_bytes(4, "big") + json.dumps(h).encode() + p
                    for h, p in records)
    reader = channel.Reader(CALLS, BUDGET)
    _feed(reader, data, cuts)
    _check_invariants(reader)


@settings(max_examples=100, deadline=4000)
@given(st.lists(st.integers(0, 3000), max_size=8), st.text(max_size=200))
def test_the_harness_records_read_back_whatever_the_cuts(cuts, detail):
    """A model run of the harness's writer (its own _Status through a real pipe): the values come
    back equal, the error detail with its control characters escaped."""
    a = np.arange(48.0).reshape(4, 4, 3) / 7
    records = [(b"", {"event": "start", "call": "import"}),
               (b"", {"event": "end", "call": "import", "status": "ok", "skipped": []}),
               (b"", {"event": "start", "call": "a"}),
               (a.astype("<f8").tobytes(), {"event": "end", "call": "a", "status": "ok",
                                             "shape": [4, 4, 3], "returned": "ndarray"}),
               (b"", {"event": "start", "call": "b"}),
               (b"", {"event": "end", "call": "b", "status": "error", "detail": detail}),
               (b"", {"event": "start", "call": "c"}),
               (b"", {"event": "end", "call": "c", "status": "timeout", "detail": "t"})]
    reader = channel.Reader(CALLS, BUDGET)
    _feed(reader, _bytes_of_harness(records), cuts)
    assert reader.broken is None and reader.finished
    assert np.array_equal(reader.ended["a"]["value"], a)
    assert reader.ended["b"]["status"] == "error" and "\x1b" not in reader.ended["b"]["detail"]
    assert not CONTROL.search(reader.ended["b"]["detail"])
    assert reader.ended["c"]["status"] == "timeout"
    assert reader.payload_bytes == a.nbytes


def test_a_value_over_the_session_budget_breaks_the_channel():
    records = [(b"", {"event": "start", "call": "import"}),
               (b"", {"event": "end", "call": "import", "status": "ok"}),
               (b"", {"event": "start", "call": "a"}),
               (bytes(8 * 48), {"event": "end", "call": "a", "status": "ok", "shape": [4, 4, 3]})]
    reader = channel.Reader(CALLS, 8 * 47)
    reader.feed(_bytes_of_harness(records))
    assert reader.broken == "more than 376 bytes of results in all"
    assert reader.current() == "a" and "a" not in reader.ended
