"""The live view over the Foxglove WebSocket protocol, with a real client: Python ``websockets``.

``./stagecraft spy --foxglove 0`` relays a recorded Pioneer session (laser, sonar, odometry) from a
replaying Player to a replaying robot program while viewers watch: the handshake selects
``foxglove.websocket.v1``, serverInfo and advertise come first, subscriptions get binary message
frames whose JSON is valid against the JSON Schema the channel advertised (``jsonschema``), a
robot's channels are unadvertised when its connection ends, and a viewer that stops reading does
not stall the relay: both ends get exactly the recorded bytes, and the spy counts what that viewer
missed. Needs the command line tool built (``./stagecraft test`` builds it before pytest);
``STAGECRAFT_JAVA=0`` turns this into a skip, as for test_java_decoder.py.
"""

from __future__ import annotations

import asyncio
import base64
import json
import os
import re
import signal
import socket
import struct
import subprocess
import threading
from pathlib import Path

import jsonschema
import pytest
from websockets.asyncio.client import ClientConnection, connect
from websockets.exceptions import InvalidHandshake

from player_trace import traces_dir

REPO = Path(__file__).resolve().parents[4]
TRACE = "pioneer-laser-sonar.gt.trace.jsonl"
SUBPROTOCOL = "foxglove.websocket.v1"


def recorded_chunks(conn: int = 1) -> dict[str, list[bytes]]:
    """The bytes each side sent on one recorded connection, chunk by chunk, in order."""
    chunks: dict[str, list[bytes]] = {"s2c": [], "c2s": []}
    with open(traces_dir() / TRACE, encoding="utf-8") as f:
        for line in f:
            r = json.loads(line)
            if r.get("conn") == conn and "data" in r:
                chunks[r["dir"]].append(base64.b64decode(r["data"]))
    return chunks


def read_all(sock: socket.socket, into: bytearray) -> None:
    while data := sock.recv(65536):
        into += data


class ReplayingPlayer:
    """Player's side of the recording: sends the first ``head`` chunks, waits for ``go``, sends the rest."""

    def __init__(self, chunks: list[bytes], head: int) -> None:
        self.listener = socket.create_server(("127.0.0.1", 0))
        self.port = self.listener.getsockname()[1]
        self.chunks, self.head = chunks, head
        self.go = threading.Event()
        self.received = bytearray()
        self.errors: list[BaseException] = []
        self.thread = threading.Thread(target=self._serve, daemon=True)
        self.thread.start()

    def _serve(self) -> None:
        try:
            conn, _ = self.listener.accept()
            with conn:
                reader = threading.Thread(target=read_all, args=(conn, self.received), daemon=True)
                reader.start()
                for i, chunk in enumerate(self.chunks):
                    if i == self.head and not self.go.wait(60):
                        raise TimeoutError("the viewers did not subscribe within 60 s")
                    conn.sendall(chunk)
                reader.join(60)  # until the robot program closes
        except BaseException as e:  # reported by the test
            self.errors.append(e)


class Spy:
    """``./stagecraft spy --listen 0 --to PLAYER --foxglove 0`` and the addresses it prints."""

    def __init__(self, player_port: int, *extra: str) -> None:
        self.proc = subprocess.Popen(
            [str(REPO / "stagecraft"), "spy", "--listen", "0", "--to", f"127.0.0.1:{player_port}",
             "--foxglove", "0", *extra],
            cwd=REPO, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        self.lines: list[str] = []
        self.listen_port = int(self._await(r"spying 127\.0\.0\.1:(\d+) -> ").group(1))
        self.ws = self._await(r"serving Foxglove on (ws://127\.0\.0\.1:\d+)$").group(1)

    def _await(self, pattern: str) -> re.Match[str]:
        assert self.proc.stderr is not None
        for line in self.proc.stderr:  # blocks until the spy prints (or ends)
            self.lines.append(line.rstrip("\n"))
            m = re.search(pattern, self.lines[-1])
            if m:
                return m
        raise AssertionError(f"the spy ended without printing /{pattern}/:\n" + "\n".join(self.lines))

    def stop(self) -> str:
        """Ctrl-C, and the 'stopped:' totals line."""
        self.proc.send_signal(signal.SIGINT)
        line = self._await(r"^stopped: (.*)$").group(1)
        assert self.proc.wait(30) == 0, "\n".join(self.lines)
        return line


@pytest.fixture
def java_tool() -> None:
    if os.environ.get("STAGECRAFT_JAVA") == "0":
        pytest.skip("STAGECRAFT_JAVA=0: the Java side is not available")
    bundles = REPO / "bundles"
    needed = [bundles / b / "target" / "classes" / "org" for b in ("org.stagecraft.foxglove", "org.stagecraft.cli")]
    needed += [bundles / "org.stagecraft.cli" / "target" / "lib" / j for j in ("Java-WebSocket.jar", "slf4j-api.jar")]
    missing = [str(p) for p in needed if not p.exists()]
    if missing:
        pytest.fail(f"the Java command line tool is not built ({', '.join(missing)} missing): run "
                    f"./mvnw install -DskipTests in {REPO}; set STAGECRAFT_JAVA=0 to skip this check", pytrace=False)


class Viewer:
    """A Foxglove client: subscribes to every channel it is told of, validates every message frame."""

    def __init__(self, ws: ClientConnection) -> None:
        self.ws = ws
        self.channels: dict[int, dict] = {}
        self.validators: dict[int, jsonschema.protocols.Validator] = {}
        self.sub_channel: dict[int, int] = {}
        self.messages: dict[str, int] = {}
        self.unadvertised: set[int] = set()
        self.statuses: list[dict] = []
        self.times: list[int] = []
        self.next_sub = 0

    async def handle(self, frame: str | bytes) -> None:
        if isinstance(frame, str):
            msg = json.loads(frame)
            if msg["op"] == "advertise":
                subs = []
                for c in msg["channels"]:
                    assert c["encoding"] == "json" and c["schemaEncoding"] == "jsonschema", c
                    schema = json.loads(c["schema"])
                    cls = jsonschema.validators.validator_for(schema)
                    cls.check_schema(schema)
                    self.channels[c["id"]] = c
                    self.validators[c["id"]] = cls(schema)
                    subs.append({"id": self.next_sub, "channelId": c["id"]})
                    self.sub_channel[self.next_sub] = c["id"]
                    self.next_sub += 1
                if subs:
                    await self.ws.send(json.dumps({"op": "subscribe", "subscriptions": subs}))
            elif msg["op"] == "unadvertise":
                self.unadvertised.update(msg["channelIds"])
            elif msg["op"] == "status":
                self.statuses.append(msg)
            else:
                raise AssertionError(f"unexpected {msg}")
        else:
            if frame[0] == 2:
                self.times.append(struct.unpack_from("<Q", frame, 1)[0])
                return
            assert frame[0] == 1, f"unknown binary opcode {frame[0]}"
            sub, log_time = struct.unpack_from("<IQ", frame, 1)
            channel = self.sub_channel[sub]
            message = json.loads(frame[13:].decode("utf-8"))
            self.validators[channel].validate(message)  # raises with the path of what is wrong
            assert log_time > 1_600_000_000 * 10**9, f"log time {log_time} is no epoch time"
            topic = self.channels[channel]["topic"]
            self.messages[topic] = self.messages.get(topic, 0) + 1


async def open_viewer(uri: str, **kwargs: object) -> tuple[Viewer, dict]:
    ws = await connect(uri, subprotocols=[SUBPROTOCOL], max_size=None, **kwargs)
    assert ws.subprotocol == SUBPROTOCOL
    info = json.loads(await ws.recv())
    assert info["op"] == "serverInfo", info
    first = json.loads(await ws.recv())
    assert first["op"] == "advertise", first  # always one at once, even before any robot
    return Viewer(ws), info


def test_a_client_without_the_subprotocol_is_refused(java_tool: None) -> None:
    player = ReplayingPlayer([], 0)
    spy = Spy(player.port)
    try:
        async def plain_client() -> None:
            with pytest.raises(InvalidHandshake):
                await connect(spy.ws)  # offers no subprotocol
        asyncio.run(plain_client())
    finally:
        spy.stop()


def test_live_view_of_a_recorded_session(java_tool: None) -> None:
    chunks = recorded_chunks()
    head = len(chunks["s2c"]) // 4  # the setup and some data: channels appear, then viewers subscribe
    player = ReplayingPlayer(chunks["s2c"], head)
    # at most 16 messages wait for a viewer (and the server's 256 kB socket buffer): far less than the session
    spy = Spy(player.port, "--foxglove-queue", "16")
    try:
        totals, viewer, frozen_port, program_got = asyncio.run(session(spy, player, chunks))
    finally:
        if spy.proc.poll() is None:
            spy.proc.kill()
    assert not player.errors, player.errors
    # the wire: both ends got exactly the recorded bytes, a frozen viewer notwithstanding
    assert bytes(program_got) == b"".join(chunks["s2c"])
    assert bytes(player.received) == b"".join(chunks["c2s"])
    # what the live viewer saw
    topics = set(viewer.messages)
    schema_names = {c["schemaName"] for c in viewer.channels.values()}
    assert {"foxglove.LaserScan", "foxglove.FrameTransform", "foxglove.PoseInFrame"} <= schema_names, schema_names
    assert any(viewer.channels[c]["schemaName"] == "foxglove.LaserScan" and viewer.channels[c]["topic"] in topics
               for c in viewer.channels), viewer.messages
    assert sum(viewer.messages.values()) > 100, viewer.messages
    assert viewer.times, "no time message although serverInfo announces 'time'"
    # the robot's channels went when its connection ended
    robot_channels = {c for c, ch in viewer.channels.items() if ch["topic"].startswith("/robot")}
    assert robot_channels and robot_channels <= viewer.unadvertised, (robot_channels, viewer.unadvertised)
    # the frozen viewer's drops are counted, and said when it goes (the spy closes it at the stop)
    assert re.search(r"foxglove 2 viewers served, [1-9]\d* dropped, 0 not converted", totals), totals
    gone = [line for line in spy.lines if f"foxglove: viewer 127.0.0.1:{frozen_port} disconnected" in line]
    assert gone, "\n".join(spy.lines)
    m = re.search(r": (\d+) frames sent, (\d+) dropped$", gone[0])
    assert m and int(m.group(2)) > 0, gone[0]
    print(f"\nspy totals: {totals}\nlive viewer: {sum(viewer.messages.values())} messages on {len(topics)} topics;"
          f" frozen viewer: {m.group(1)} frames sent, {m.group(2)} dropped")


async def session(spy: Spy, player: ReplayingPlayer, chunks: dict[str, list[bytes]]):
    viewer, info = await open_viewer(spy.ws)
    assert "time" in info["capabilities"], info
    # a viewer that subscribes and then reads nothing more: a tiny receive window, a queue of one message
    frozen_sock = socket.create_connection(("127.0.0.1", int(spy.ws.rsplit(":", 1)[1])))
    frozen_sock.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
    frozen, _ = await open_viewer(spy.ws, sock=frozen_sock, max_queue=1)

    program = socket.create_connection(("127.0.0.1", spy.listen_port))
    program_got = bytearray()
    reader = threading.Thread(target=read_all, args=(program, program_got), daemon=True)
    reader.start()
    program.sendall(b"".join(chunks["c2s"]))

    loop = asyncio.get_running_loop()
    # both viewers subscribe to the channels the setup and the first scans brought (the laser among
    # them), then Player sends the rest
    for v in (viewer, frozen):
        while not any(c["schemaName"] == "foxglove.LaserScan" for c in v.channels.values()):
            try:
                await v.handle(await asyncio.wait_for(v.ws.recv(), 20))
            except TimeoutError:
                raise AssertionError(f"no laser channel advertised within 20 s: {v.channels}") from None
    # a barrier: the server answers a viewer's requests in order, so once this one's error comes
    # back, the subscriptions sent before it are in effect
    for v in (viewer, frozen):
        await v.ws.send(json.dumps({"op": "unsubscribe", "subscriptionIds": [999999]}))
        while not any("no subscription 999999" in s["message"] for s in v.statuses):
            await v.handle(await asyncio.wait_for(v.ws.recv(), 20))
    player.go.set()  # from now on, the frozen viewer reads nothing

    expected = sum(len(c) for c in chunks["s2c"])
    # the program's bytes and the viewer's frames come on separate paths: the last frame may be in
    # before the reader has the last bytes, and then no frame follows, so the count is polled
    deadline = loop.time() + 30
    while len(program_got) < expected:
        if loop.time() > deadline:
            raise AssertionError(f"the robot program got {len(program_got)} of {expected} bytes")
        try:
            await viewer.handle(await asyncio.wait_for(viewer.ws.recv(), 0.2))
        except TimeoutError:
            pass
    program.shutdown(socket.SHUT_WR)
    await loop.run_in_executor(None, reader.join, 30)
    program.close()
    # the connection has ended: every robot channel is unadvertised
    while not any(c.startswith("/robot") for c in (viewer.channels[i]["topic"] for i in viewer.unadvertised)):
        await viewer.handle(await asyncio.wait_for(viewer.ws.recv(), 30))
    while True:  # the rest that was sent before the unadvertise
        try:
            await viewer.handle(await asyncio.wait_for(viewer.ws.recv(), 2))
        except TimeoutError:
            break
    frozen_port = frozen.ws.local_address[1]
    totals = await loop.run_in_executor(None, spy.stop)
    await viewer.ws.close()
    frozen.ws.transport.abort()
    return totals, viewer, frozen_port, program_got
