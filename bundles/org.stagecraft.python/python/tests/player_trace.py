"""Reading and writing recordings in the shared ``player-trace`` JSON-lines format.

A recording holds the bytes each recv() returned, per connection and direction, in the order the
recording proxy saw them. Here they are framed into messages (with this package's framer) and
kept in that order, which is what the test Player server needs to answer like the real one.
"""

from __future__ import annotations

import base64
import json
import os
from dataclasses import dataclass
from pathlib import Path

from stagecraft_player.wire import Framer, Message


def traces_dir() -> Path:
    """``$STAGECRAFT_TRACES`` or the checkout's own recorded corpus, ``tests/traces``."""
    env = os.environ.get("STAGECRAFT_TRACES")
    path = Path(env) if env else Path(__file__).resolve().parents[4] / "tests" / "traces"
    path = path.resolve()
    if not (path / "README.md").is_file():
        raise FileNotFoundError(f"the recorded Player traces are not at {path} (set STAGECRAFT_TRACES)")
    return path


@dataclass(frozen=True)
class Event:
    """One framed message of a recording, with the direction and the time it was seen."""

    t: float
    dir: str  # "c2s" or "s2c"
    message: Message


def read_events(path: Path, conn: int = 1) -> tuple[str, list[Event]]:
    """The server banner and every message of connection ``conn``, in recorded order."""
    framers = {"s2c": Framer(expect_ident=True), "c2s": Framer(expect_ident=False)}
    events: list[Event] = []
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            record = json.loads(line)
            if number == 1:
                if record.get("format") != "player-trace":
                    raise ValueError(f"{path}:1: not a player-trace recording")
                continue
            if record.get("conn") != conn or "data" not in record:
                continue
            for message in framers[record["dir"]].feed(base64.b64decode(record["data"])):
                events.append(Event(record["t"], record["dir"], message))
    banner = framers["s2c"].ident
    if banner is None:
        raise ValueError(f"{path}: connection {conn} has no server banner")
    return banner, events


class TraceWriter:
    """Writes a connection's traffic as a ``player-trace`` recording (the shared format)."""

    def __init__(self, path: Path, scenario: str, port: int) -> None:
        self._file = open(path, "w", encoding="utf-8")
        self._port = port
        self._t0: float | None = None
        header = {"format": "player-trace", "version": 1, "scenario": scenario, "world": "",
                  "created": "test"}
        self._file.write(json.dumps(header) + "\n")

    def _t(self, now: float) -> float:
        if self._t0 is None:
            self._t0 = now
        return round(now - self._t0, 6)

    def event(self, kind: str, now: float) -> None:
        self._file.write(json.dumps({"conn": 1, "event": kind, "t": self._t(now), "port": self._port}) + "\n")

    def chunk(self, direction: str, data: bytes, now: float) -> None:
        line = {"t": self._t(now), "conn": 1, "port": self._port, "dir": direction,
                "data": base64.b64encode(data).decode("ascii")}
        self._file.write(json.dumps(line) + "\n")

    def close(self) -> None:
        self._file.close()
