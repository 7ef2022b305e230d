"""A test Player server: a real TCP server on loopback that answers like the recorded Player.

It sends the recorded banner, answers each request with the reply Player gave to the same
request in the recording (byte for byte — including Player's quirks: the NACK with a body, the
second NACK of ``rangertolaser``), serves the recorded rounds of data in PULL mode and streams
the recorded data in PUSH mode, only for the devices the client subscribed. It records every
byte both ways as a ``player-trace`` file when asked, and notes requests it has no recorded
reply for (answered with a NACK so the client does not hang).
"""

from __future__ import annotations

import select
import socket
import threading
import time
from collections import defaultdict
from dataclasses import dataclass, field
from pathlib import Path

from player_trace import Event, TraceWriter, read_events
from stagecraft_player.wire import Framer, Header, Message, MsgType
from stagecraft_player.xdr import XdrReader

PLAYER, REQ_DEV, REQ_DATA, REQ_DATAMODE = 1, 3, 4, 5
SIMULATION = 31


def request_key(h: Header, body: bytes) -> tuple[object, ...]:
    """What makes two requests "the same" for finding the recorded reply.

    Bodies that carry values libplayerc leaves uninitialised (e.g. the pose in GET_POSE2D) or
    that only set values (SET_ODOM) do not take part; device requests are told apart by device
    and access, simulation requests by the model's name.
    """
    key: tuple[object, ...] = (h.interf, h.index, h.subtype)
    if h.interf == PLAYER and h.subtype in (2, 3):
        return key + (body[8:20] if h.subtype == 3 else body[8:16],)
    if h.interf == SIMULATION:
        return key + (XdrReader(body).string(),)
    return key


@dataclass
class Round:
    """One recorded PULL round: the ACK to REQ DATA, the data queued for the client, the SYNCH."""

    ack: Message
    before: list[Message] = field(default_factory=list)
    data: list[Message] = field(default_factory=list)
    synch: Message | None = None


@dataclass
class Recording:
    """The server side of one recorded connection, arranged for answering."""

    banner: bytes
    replies: dict[tuple[object, ...], list[list[Message]]] = field(default_factory=lambda: defaultdict(list))
    rounds: list[Round] = field(default_factory=list)
    pushed: list[Message] = field(default_factory=list)
    #: the devices the recorded client subscribed to (interf, index)
    devices: set[tuple[int, int]] = field(default_factory=set)

    @staticmethod
    def load(path: Path, conn: int = 1) -> Recording:
        banner, events = read_events(path, conn)
        rec = Recording(banner.encode("ascii").ljust(32, b"\0"))
        rec._arrange(events)
        return rec

    def _arrange(self, events: list[Event]) -> None:
        pending: list[tuple[tuple[object, ...], Header]] = []
        last_answer: dict[tuple[int, int, int], list[Message]] = {}
        round_: Round | None = None
        push = False
        carry: list[Message] = []  # data Player sent while a request was in flight: it goes with the reply
        for e in events:
            h = e.message.header
            if e.dir == "c2s":
                if h.type == MsgType.REQ:
                    pending.append((request_key(h, e.message.body), h))
                    if h.interf == PLAYER and h.subtype == REQ_DEV and XdrReader(e.message.body[16:]).uint32() == 1:
                        self.devices.add((XdrReader(e.message.body[8:]).uint32(), XdrReader(e.message.body[12:]).uint32()))
                    if h.interf == PLAYER and h.subtype == REQ_DATAMODE:
                        push = XdrReader(e.message.body).uint32() == 1
                continue
            if h.type in (MsgType.RESP_ACK, MsgType.RESP_NACK):
                triple = (h.interf, h.index, h.subtype)
                match = next((p for p in pending if (p[1].interf, p[1].index, p[1].subtype) == triple), None)
                if match is None:  # a second reply to one request (rangertolaser's double NACK)
                    last_answer[triple].append(e.message)
                    continue
                pending.remove(match)
                answer = carry + [e.message]
                last_answer[triple] = answer
                if triple == (PLAYER, 0, REQ_DATA):
                    round_ = Round(e.message, before=carry)
                    self.rounds.append(round_)
                else:
                    self.replies[match[0]].append(answer)
                carry = []
            elif h.type == MsgType.SYNCH:
                if round_ is not None:
                    round_.synch = e.message
                round_ = None
            elif h.type == MsgType.DATA:
                if round_ is not None:
                    round_.data.append(e.message)
                elif push:
                    self.pushed.append(e.message)
                else:
                    carry.append(e.message)


class RecordedPlayer:
    """Serves one client at a time with a :class:`Recording`; ``with RecordedPlayer(rec) as p``."""

    def __init__(self, recording: Recording, *, trace: Path | None = None, rounds: int | None = None) -> None:
        self.recording = recording
        self.trace_path = trace
        self.max_rounds = len(recording.rounds) if rounds is None else rounds
        self.received: list[Message] = []
        self.unanswered: list[Header] = []
        self.subscribed: set[tuple[int, int]] = set()
        self.rounds_served = 0
        self.pushed_sent = 0
        self.errors: list[BaseException] = []
        self._listener = socket.create_server(("127.0.0.1", 0))
        self.port = self._listener.getsockname()[1]
        self._stop = threading.Event()
        self._served = threading.Event()
        self._used: dict[tuple[object, ...], int] = defaultdict(int)
        self._thread = threading.Thread(target=self._serve, name=f"recorded-player-{self.port}", daemon=True)

    def __enter__(self) -> RecordedPlayer:
        self._thread.start()
        return self

    def __exit__(self, *exc: object) -> None:
        self.stop()

    def stop(self) -> None:
        self._stop.set()
        self._listener.close()
        self._thread.join(timeout=10)

    def wait_until_served(self, timeout: float = 10.0) -> bool:
        """True once the client's connection has ended (closed by either side)."""
        return self._served.wait(timeout)

    # -- serving ------------------------------------------------------------------------------

    def _serve(self) -> None:
        try:
            self._listener.settimeout(None)
            conn, _ = self._listener.accept()
        except OSError:
            return
        writer = TraceWriter(self.trace_path, "recorded-player", self.port) if self.trace_path else None
        try:
            with conn:
                self._session(conn, writer)
        except (ConnectionError, BrokenPipeError):
            pass  # the client went away: that ends the session
        except BaseException as e:  # reported by the tests
            self.errors.append(e)
        finally:
            if writer:
                writer.event("close", time.monotonic())
                writer.close()
            self._served.set()

    def _send(self, conn: socket.socket, data: bytes, writer: TraceWriter | None) -> None:
        if writer:
            writer.chunk("s2c", data, time.monotonic())
        conn.sendall(data)

    def _session(self, conn: socket.socket, writer: TraceWriter | None) -> None:
        if writer:
            writer.event("open", time.monotonic())
        framer = Framer(expect_ident=False)
        self._send(conn, self.recording.banner, writer)
        push = False
        while not self._stop.is_set():
            # PUSH data flows once the client has subscribed what the recorded client had (as the
            # recorded stream holds those devices' data from the start), so every run sees all of it
            streaming = (push and self.pushed_sent < len(self.recording.pushed)
                         and self.subscribed >= self.recording.devices)
            ready, _, _ = select.select([conn], [], [], 0 if streaming else 0.05)
            if ready:
                chunk = conn.recv(65536)
                if not chunk:
                    return
                if writer:
                    writer.chunk("c2s", chunk, time.monotonic())
                for msg in framer.feed(chunk):
                    self.received.append(msg)
                    push = self._answer(conn, msg, writer, push)
                    if self.rounds_served > self.max_rounds:
                        return  # the recording is used up: Player "goes away"
            elif streaming:
                self._stream(conn, writer)

    def _answer(self, conn: socket.socket, msg: Message, writer: TraceWriter | None, push: bool) -> bool:
        h = msg.header
        if h.type != MsgType.REQ:
            return push
        if h.interf == PLAYER and h.subtype == REQ_DATA:
            self.rounds_served += 1
            if self.rounds_served <= self.max_rounds:
                self._serve_round(conn, writer)
            return push
        key = request_key(h, msg.body)
        answers = self.recording.replies.get(key)
        if not answers:
            self.unanswered.append(h)
            nack = Header(h.host, h.robot, h.interf, h.index, MsgType.RESP_NACK, h.subtype, 0.0, 0, 0)
            self._send(conn, nack.pack(), writer)
            return push
        answer = answers[min(self._used[key], len(answers) - 1)]
        self._used[key] += 1
        self._send(conn, b"".join(m.to_bytes() for m in answer
                                  if m.header.type != MsgType.DATA or self._wanted(m)), writer)
        reply = next(m for m in answer if m.header.type != MsgType.DATA)
        if h.interf == PLAYER and h.subtype == REQ_DEV and reply.header.type == MsgType.RESP_ACK:
            r = XdrReader(msg.body)
            r.uint32(), r.uint32()
            device, access = (r.uint32(), r.uint32()), r.uint32()
            (self.subscribed.add if access == 1 else self.subscribed.discard)(device)
        if h.interf == PLAYER and h.subtype == REQ_DATAMODE:
            return XdrReader(msg.body).uint32() == 1
        return push

    def _wanted(self, m: Message) -> bool:
        return (m.header.interf, m.header.index) in self.subscribed

    def _serve_round(self, conn: socket.socket, writer: TraceWriter | None) -> None:
        rec = self.recording
        i = self.rounds_served - 1
        round_ = rec.rounds[i]
        if round_.synch is None:
            raise AssertionError(f"recorded round {i} has no SYNCH (the recording ends inside it)")
        before = b"".join(m.to_bytes() for m in round_.before if self._wanted(m))
        data = b"".join(m.to_bytes() for m in round_.data if self._wanted(m))
        self._send(conn, before + round_.ack.to_bytes() + data + round_.synch.to_bytes(), writer)

    def _stream(self, conn: socket.socket, writer: TraceWriter | None) -> None:
        """Sends the next few recorded PUSH messages (a handful per turn, so requests get answered)."""
        batch = []
        while self.pushed_sent < len(self.recording.pushed) and len(batch) < 8:
            m = self.recording.pushed[self.pushed_sent]
            self.pushed_sent += 1
            if self._wanted(m):
                batch.append(m.to_bytes())
        if batch:
            self._send(conn, b"".join(batch), writer)
