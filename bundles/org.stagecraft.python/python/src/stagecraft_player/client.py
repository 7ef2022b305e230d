"""The connection to a Player server: banner, data modes, subscriptions, requests and rounds of data.

Like libplayerc, the client is single-threaded and synchronous: nothing happens between calls.
While it waits for a reply it keeps every DATA message that arrives (the proxies see it), and a
reply that answers nothing it asked for is set aside as a *stray reply* rather than taken for the
answer to the request in flight — Player sends such replies: the laser driver ``rangertolaser``
answers one SET_CONFIG with two NACKs.
"""

from __future__ import annotations

import enum
import logging
import select
import socket
import time
from collections import deque
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from .errors import (ConnectionLost, DeviceRefused, PlayerConnectionError, PlayerProtocolError,
                     PlayerTimeout, RequestRefused)
from .wire import INTERFACES, DeviceAddress, Framer, Header, Message, MsgType, encode
from .xdr import XdrReader, XdrWriter

if TYPE_CHECKING:
    from .interfaces.blobfinder import Blobfinder
    from .interfaces.bumper import Bumper
    from .interfaces.fiducial import Fiducial
    from .interfaces.laser import Laser
    from .interfaces.position2d import Position2d
    from .interfaces.ranger import Ranger
    from .interfaces.simulation import Simulation
    from .interfaces.sonar import Sonar
    from .proxy import Proxy

log = logging.getLogger(__name__)

PLAYER = INTERFACES["player"]
# Requests of the "player" interface (the server itself).
REQ_DEVLIST = 1
REQ_DRIVERINFO = 2
REQ_DEV = 3
REQ_DATA = 4
REQ_DATAMODE = 5
REQ_ADD_REPLACE_RULE = 10
SYNCH_OK = 1

ACCESS_OPEN = 1
ACCESS_CLOSE = 2
ACCESS_ERROR = 3


class DataMode(enum.IntEnum):
    """PUSH: the server sends data as it comes. PULL: one round of data per :meth:`Client.read`."""

    PUSH = 1
    PULL = 2


@dataclass(frozen=True)
class Reply:
    """A RESP_ACK: its header and its XDR payload."""

    header: Header
    body: bytes


@dataclass(frozen=True)
class DataMessage:
    """One DATA message as :meth:`Client.read` returns it: header, device, decoded record.

    ``record`` is the payload decoded by the device's proxy, or the raw bytes when no proxy of
    this client reads that device or the proxy does not know the subtype.
    """

    header: Header
    record: Any

    @property
    def device(self) -> DeviceAddress:
        return DeviceAddress(self.header.interf, self.header.index)

    @property
    def subtype(self) -> int:
        return self.header.subtype

    @property
    def timestamp(self) -> float:
        return self.header.timestamp


@dataclass(frozen=True)
class DeviceInfo:
    """An entry of the server's device list: where it is and which driver provides it."""

    address: DeviceAddress
    driver: str

    def __str__(self) -> str:
        return f"{self.address} ({self.driver})"


def _device_req(address: DeviceAddress, access: int) -> bytes:
    w = XdrWriter().uint32(0).uint32(0).uint32(address.interf).uint32(address.index)
    return w.uint32(access).counted_bytes(b"").to_bytes()


def _read_addr(r: XdrReader) -> DeviceAddress:
    host, robot, interf, index = r.uint32(), r.uint32(), r.uint32(), r.uint32()
    return DeviceAddress(interf, index, host, robot)


class Client:
    """A connection to one Player server.

    ``Client("localhost", 6665)`` connects, checks the server's banner and, like libplayerc,
    asks for PULL mode. Use it as a context manager, or call :meth:`close`.

    ``timeout`` (seconds) bounds every wait: for the connection, a reply, a round of data.
    """

    def __init__(self, host: str = "localhost", port: int = 6665, *, timeout: float = 10.0,
                 datamode: DataMode = DataMode.PULL) -> None:
        self.host = host
        self.port = port
        self.timeout = timeout
        self.stray_replies: list[Header] = []
        self._proxies: dict[tuple[int, int], Proxy] = {}
        self._incoming: deque[Message] = deque()
        self._unread: list[DataMessage] = []
        self._framer = Framer(expect_ident=True)
        self._closed = False
        self._sock = self._connect()
        try:
            self.banner = self._read_banner()
            self.datamode: DataMode | None = None
            self.set_datamode(datamode)
        except BaseException:
            self._sock.close()
            raise

    # -- connection ---------------------------------------------------------------------------

    @property
    def where(self) -> str:
        return f"Player at {self.host}:{self.port}"

    def _connect(self) -> socket.socket:
        try:
            sock = socket.create_connection((self.host, self.port), timeout=self.timeout)
        except ConnectionRefusedError:
            raise PlayerConnectionError(f"cannot connect to {self.where}: connection refused "
                                        f"(is Player running and listening on port {self.port}?)") from None
        except ConnectionResetError:
            # accepted, then reset before connect() returned: the same as a reset before the banner
            raise self._ended_before_banner("reset") from None
        except socket.timeout:
            raise PlayerTimeout(f"cannot connect to {self.where}: no answer within {self.timeout} s") from None
        except OSError as e:
            raise PlayerConnectionError(f"cannot connect to {self.where}: {e.strerror or e}") from None
        sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        return sock

    def _read_banner(self) -> str:
        deadline = time.monotonic() + self.timeout
        try:
            while self._framer.ident is None:
                self._fill(deadline, "the server's banner")
        except PlayerProtocolError as e:
            raise PlayerConnectionError(f"{self.host}:{self.port} is not a Player server: {e}") from None
        except ConnectionLost as e:
            # A reset or end before the banner does not say what the server is: with Stagecraft's
            # Network Spy on this port it is what a client sees when Player behind the spy is not
            # running, so say what happened and where to look instead of guessing.
            how = "reset" if isinstance(e.__context__, ConnectionResetError) else "closed"
            raise self._ended_before_banner(how) from None
        return self._framer.ident

    def _ended_before_banner(self, how: str) -> ConnectionLost:
        return ConnectionLost(f"{self.where}: the connection was {how} before Player's banner arrived; if it "
                              f"goes through Stagecraft's Network Spy, Player may not be running behind it "
                              f"(check the spy's messages)")

    @property
    def server_version(self) -> str:
        """The version in the banner, e.g. ``3.1.1-dev``."""
        return self.banner.removeprefix("Player v.")

    def close(self) -> None:
        """Closes the connection (Player drops this client's subscriptions with it)."""
        if not self._closed:
            self._closed = True
            self._sock.close()

    def __enter__(self) -> Client:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    # -- bytes in and out ---------------------------------------------------------------------

    def _send(self, interf: int, index: int, msgtype: MsgType, subtype: int, body: bytes) -> None:
        if self._closed:
            raise PlayerConnectionError(f"the connection to {self.where} is closed")
        # like libplayerc: robot = the port connected to for device messages, 0 for the server's own
        robot = 0 if interf == PLAYER else self.port
        try:
            self._sock.sendall(encode(interf, index, msgtype, subtype, body, robot=robot, timestamp=time.time()))
        except OSError as e:
            raise ConnectionLost(f"{self.where} is gone: sending failed ({e.strerror or e})") from None

    def _fill(self, deadline: float, waiting_for: str) -> None:
        """Receives one chunk, waiting at most until ``deadline``; frames it into ``_incoming``."""
        remaining = deadline - time.monotonic()
        if remaining <= 0:
            raise PlayerTimeout(f"{self.where}: timed out waiting for {waiting_for}")
        self._sock.settimeout(remaining)
        try:
            chunk = self._sock.recv(65536)
        except socket.timeout:
            raise PlayerTimeout(f"{self.where}: timed out after {self.timeout} s waiting for {waiting_for}") from None
        except OSError as e:
            raise ConnectionLost(f"{self.where} is gone while waiting for {waiting_for} ({e.strerror or e})") from None
        if not chunk:
            raise ConnectionLost(f"{self.where} closed the connection while this client waited for "
                                 f"{waiting_for} (did Player stop?)")
        self._incoming.extend(self._framer.feed(chunk))

    def _drain_socket(self) -> None:
        """Frames whatever has already arrived, without waiting."""
        while select.select([self._sock], [], [], 0)[0]:
            self._fill(time.monotonic() + self.timeout, "data that was ready")

    def _next(self, deadline: float, waiting_for: str) -> Message:
        while not self._incoming:
            self._fill(deadline, waiting_for)
        return self._incoming.popleft()

    def _deadline(self, timeout: float | None) -> tuple[float, float]:
        t = self.timeout if timeout is None else timeout
        return time.monotonic() + t, t

    # -- dispatch -----------------------------------------------------------------------------

    def _attach(self, proxy: Proxy) -> None:
        key = (proxy.address.interf, proxy.address.index)
        if key in self._proxies and self._proxies[key] is not proxy:
            raise ValueError(f"this client already has a proxy for {proxy.address}")
        self._proxies[key] = proxy

    def _data(self, msg: Message) -> DataMessage:
        proxy = self._proxies.get((msg.header.interf, msg.header.index))
        record: Any = msg.body if proxy is None else proxy._on_data(msg.header, msg.body)
        return DataMessage(msg.header, record)

    def _stray(self, msg: Message, while_doing: str) -> None:
        self.stray_replies.append(msg.header)
        log.warning("%s: ignored a reply to no request in flight (%s) while %s", self.where,
                    msg.header.describe(), while_doing)

    def _set_aside_arrived(self, while_doing: str) -> None:
        """Takes in what has already arrived, without waiting, before a request goes out.

        Replies are matched by interface, index and subtype only, so a late extra reply to an
        earlier request (rangertolaser's second NACK) would answer the next identical request if it
        were still queued when that request is sent; no request is in flight now, so any reply that
        has arrived is a stray. DATA is kept for the proxies and the next :meth:`read`.
        """
        self._drain_socket()
        kept: deque[Message] = deque()
        while self._incoming:
            msg = self._incoming.popleft()
            if msg.header.type == MsgType.DATA:
                self._unread.append(self._data(msg))
            elif msg.header.type in (MsgType.RESP_ACK, MsgType.RESP_NACK):
                self._stray(msg, while_doing)
            else:
                kept.append(msg)
        self._incoming = kept

    # -- requests and commands ----------------------------------------------------------------

    def request(self, interf: int, index: int, subtype: int, body: bytes = b"", *,
                timeout: float | None = None) -> Reply:
        """Sends a REQ and returns its RESP_ACK; a RESP_NACK raises :class:`RequestRefused`.

        The reply is the first RESP_ACK/RESP_NACK with the request's interface, index and
        subtype that arrives after the request is sent (replies already there are set aside
        first); other replies are strays (kept in :attr:`stray_replies`), DATA goes to the
        proxies and to the next :meth:`read`.
        """
        what = Header(0, 0, interf, index, MsgType.REQ, subtype, 0, 0, len(body)).describe()
        self._set_aside_arrived(f"before sending {what}")
        self._send(interf, index, MsgType.REQ, subtype, body)
        deadline, t = self._deadline(timeout)
        while True:
            msg = self._next(deadline, f"the reply to {what}")
            h = msg.header
            if h.type == MsgType.DATA:
                self._unread.append(self._data(msg))
            elif h.type in (MsgType.RESP_ACK, MsgType.RESP_NACK):
                if (h.interf, h.index, h.subtype) != (interf, index, subtype):
                    self._stray(msg, f"waiting for the reply to {what}")
                elif h.type == MsgType.RESP_ACK:
                    return Reply(h, msg.body)
                else:
                    raise RequestRefused(f"{self.where} refused {what} (RESP_NACK: the driver does not "
                                         f"support it or failed)", body=msg.body)
            # SYNCH outside a PULL round carries nothing: skipped

    def command(self, interf: int, index: int, subtype: int, body: bytes) -> None:
        """Sends a CMD (Player does not answer commands)."""
        self._send(interf, index, MsgType.CMD, subtype, body)

    def set_datamode(self, mode: DataMode) -> None:
        self.request(PLAYER, 0, REQ_DATAMODE, XdrWriter().uint32(int(mode)).to_bytes())
        self.datamode = DataMode(mode)

    def add_replace_rule(self, *, interf: int = -1, index: int = -1, msgtype: int = MsgType.DATA,
                         subtype: int = -1, replace: bool = True) -> None:
        """Asks the server to keep only the newest queued message of a kind (-1 = any)."""
        body = XdrWriter().int32(interf).int32(index).int32(msgtype).int32(subtype).int32(int(replace))
        self.request(PLAYER, 0, REQ_ADD_REPLACE_RULE, body.to_bytes())

    # -- devices ------------------------------------------------------------------------------

    def devices(self) -> list[DeviceInfo]:
        """The server's devices and their drivers (DEVLIST, then DRIVERINFO for each)."""
        r = XdrReader(self.request(PLAYER, 0, REQ_DEVLIST).body, "player DEVLIST reply")
        out = []
        for address in r.structs(16, _read_addr):
            body = XdrWriter().uint32(address.host).uint32(address.robot).uint32(address.interf)
            body.uint32(address.index).counted_bytes(b"")
            info = XdrReader(self.request(PLAYER, 0, REQ_DRIVERINFO, body.to_bytes()).body, "player DRIVERINFO reply")
            _read_addr(info)
            out.append(DeviceInfo(address, info.string()))
        return out

    def subscribe(self, address: DeviceAddress | str) -> str:
        """Subscribes to a device; returns its driver's name. A refusal raises :class:`DeviceRefused`."""
        address = DeviceAddress.parse(address) if isinstance(address, str) else address
        try:
            reply = self.request(PLAYER, 0, REQ_DEV, _device_req(address, ACCESS_OPEN))
        except RequestRefused as e:
            raise DeviceRefused(f"{self.where} refused to subscribe to {address}: {self._why_refused(address)}",
                                body=e.body) from None
        r = XdrReader(reply.body, "player DEV reply")
        granted, access, driver = _read_addr(r), r.uint32(), r.string()
        if access != ACCESS_OPEN or (granted.interf, granted.index) != (address.interf, address.index):
            raise DeviceRefused(f"{self.where} did not open {address}: it granted access {access} "
                                f"to {granted}")
        return driver

    def unsubscribe(self, address: DeviceAddress | str) -> None:
        address = DeviceAddress.parse(address) if isinstance(address, str) else address
        try:
            self.request(PLAYER, 0, REQ_DEV, _device_req(address, ACCESS_CLOSE))
        except RequestRefused as e:
            raise DeviceRefused(f"{self.where} refused to unsubscribe from {address}", body=e.body) from None

    def _why_refused(self, address: DeviceAddress) -> str:
        try:
            known = self.devices()
        except (RequestRefused, PlayerTimeout, PlayerProtocolError):
            return "no such device, or its driver failed"
        if any((d.address.interf, d.address.index) == (address.interf, address.index) for d in known):
            return "the device exists but its driver failed to start"
        hint = ""
        if address.interface == "sonar" and any(d.address.interface == "ranger" for d in known):
            hint = " (Stage provides sonar rings as ranger devices: use a Ranger proxy)"
        return f"no such device; it has {', '.join(str(d) for d in known)}{hint}"

    # -- data ---------------------------------------------------------------------------------

    def read(self, timeout: float | None = None) -> list[DataMessage]:
        """Waits for new data and returns it, after the proxies have taken it in.

        PULL mode: one round — REQ DATA, its ACK, everything the server queued, SYNCH.
        PUSH mode: waits for at least one DATA message, then returns all that has arrived.
        """
        deadline, _ = self._deadline(timeout)
        out, self._unread = self._unread, []
        if self.datamode == DataMode.PULL:
            self.request(PLAYER, 0, REQ_DATA, timeout=timeout)
            while True:
                msg = self._next(deadline, "the end of a round of data (SYNCH)")
                if msg.header.type == MsgType.DATA:
                    out.append(self._data(msg))
                elif msg.header.type == MsgType.SYNCH:
                    return out + self._unread_take()
                elif msg.header.type in (MsgType.RESP_ACK, MsgType.RESP_NACK):
                    self._stray(msg, "reading a round of data")
        while not out:
            msg = self._next(deadline, "data (PUSH mode)")
            if msg.header.type == MsgType.DATA:
                out.append(self._data(msg))
            elif msg.header.type in (MsgType.RESP_ACK, MsgType.RESP_NACK):
                self._stray(msg, "reading data")
        self._drain_socket()
        while self._incoming:
            msg = self._incoming.popleft()
            if msg.header.type == MsgType.DATA:
                out.append(self._data(msg))
            elif msg.header.type in (MsgType.RESP_ACK, MsgType.RESP_NACK):
                self._stray(msg, "reading data")
        return out

    def _unread_take(self) -> list[DataMessage]:
        taken, self._unread = self._unread, []
        return taken

    # -- proxies ------------------------------------------------------------------------------

    def position2d(self, device: int | str = 0) -> Position2d:
        from .interfaces.position2d import Position2d
        return Position2d(self, device)

    def laser(self, device: int | str = 0) -> Laser:
        from .interfaces.laser import Laser
        return Laser(self, device)

    def ranger(self, device: int | str = 0) -> Ranger:
        from .interfaces.ranger import Ranger
        return Ranger(self, device)

    def sonar(self, device: int | str = 0) -> Sonar:
        from .interfaces.sonar import Sonar
        return Sonar(self, device)

    def bumper(self, device: int | str = 0) -> Bumper:
        from .interfaces.bumper import Bumper
        return Bumper(self, device)

    def fiducial(self, device: int | str = 0) -> Fiducial:
        from .interfaces.fiducial import Fiducial
        return Fiducial(self, device)

    def blobfinder(self, device: int | str = 0) -> Blobfinder:
        from .interfaces.blobfinder import Blobfinder
        return Blobfinder(self, device)

    def simulation(self, device: int | str = 0) -> Simulation:
        from .interfaces.simulation import Simulation
        return Simulation(self, device)
