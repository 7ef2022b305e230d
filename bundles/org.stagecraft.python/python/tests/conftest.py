"""Shared fixtures: the recorded traces, the test Player server, the example programs."""

from __future__ import annotations

import json
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(HERE.parent / "examples"))

from player_trace import traces_dir  # noqa: E402
from recorded_player import RecordedPlayer, Recording  # noqa: E402

_recordings: dict[str, Recording] = {}


@pytest.fixture(scope="session")
def traces() -> Path:
    return traces_dir()


def recording(name: str) -> Recording:
    """A shared trace, framed and arranged once per test run."""
    if name not in _recordings:
        _recordings[name] = Recording.load(traces_dir() / f"{name}.trace.jsonl")
    return _recordings[name]


@pytest.fixture
def serve() -> Iterator:
    """``serve("pioneer-laser-sonar.gt")`` starts a test Player server on that recording."""
    servers: list[RecordedPlayer] = []

    def start(name: str, **kwargs: object) -> RecordedPlayer:
        server = RecordedPlayer(recording(name), **kwargs)  # type: ignore[arg-type]
        servers.append(server)
        return server.__enter__()

    yield start
    for s in servers:
        s.stop()
        assert not s.errors, f"the test Player server failed: {s.errors}"


def groundtruth(name: str) -> tuple[list[dict], list[dict]]:
    """(events, data lines) of a ground-truth file, in file order."""
    events, data = [], []
    with open(traces_dir() / name, encoding="utf-8") as f:
        for number, line in enumerate(f):
            record = json.loads(line)
            if number == 0:
                continue
            (events if "event" in record else data).append(record)
    return events, data
