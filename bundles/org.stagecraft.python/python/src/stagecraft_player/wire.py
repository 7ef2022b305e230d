"""The Player 3 wire format: the ident banner, the 40-byte message header, message framing.

Facts (from Player's ``player.h`` and its XDR generator): after a 32-byte ident string that the
server sends first, every message is a 40-byte XDR header followed by ``size`` bytes of XDR
payload. A reply carries the interface, index and subtype of the request it answers.
"""

from __future__ import annotations

import enum
import struct
from dataclasses import dataclass

from .errors import PlayerProtocolError

IDENT_LENGTH = 32
HEADER_SIZE = 40
#: Player's own limit on a payload (PLAYER_MAX_MESSAGE_SIZE); XDR may take up to four times that.
MAX_PAYLOAD = 4 * 8 * 1024 * 1024

_HEADER = struct.Struct(">IIIIIIdII")


class MsgType(enum.IntEnum):
    DATA = 1
    CMD = 2
    REQ = 3
    RESP_ACK = 4
    SYNCH = 5
    RESP_NACK = 6


#: Interface codes (the numbers in the names of Player's interface definition files).
INTERFACES: dict[str, int] = {
    "player": 1, "power": 2, "gripper": 3, "position2d": 4, "sonar": 5, "laser": 6, "blobfinder": 7,
    "ptz": 8, "audio": 9, "fiducial": 10, "speech": 12, "gps": 13, "bumper": 14, "dio": 20, "aio": 21,
    "ir": 22, "wifi": 23, "localize": 25, "position3d": 30, "simulation": 31, "blinkenlight": 33,
    "camera": 40, "map": 42, "planner": 44, "log": 45, "joystick": 49, "speech_recognition": 50,
    "opaque": 51, "position1d": 52, "actarray": 53, "limb": 54, "graphics2d": 55, "rfid": 56, "wsn": 57,
    "graphics3d": 58, "health": 59, "imu": 60, "pointcloud3d": 61, "ranger": 62, "vectormap": 63,
    "blackboard": 64, "stereo": 65, "coopobject": 66,
}
INTERFACE_NAMES: dict[int, str] = {code: name for name, code in INTERFACES.items()}


def interface_name(code: int) -> str:
    return INTERFACE_NAMES.get(code, f"interface{code}")


@dataclass(frozen=True)
class DeviceAddress:
    """A device on a server: interface code and index (host and robot are the server's)."""

    interf: int
    index: int
    host: int = 0
    robot: int = 0

    @property
    def interface(self) -> str:
        return interface_name(self.interf)

    def __str__(self) -> str:
        return f"{self.interface}:{self.index}"

    @staticmethod
    def parse(text: str) -> DeviceAddress:
        """``"laser:0"`` (or ``"laser"`` for index 0), the way Player's configuration names devices."""
        name, _, index = text.strip().partition(":")
        if name not in INTERFACES:
            raise ValueError(f"'{text}' is not a device address: unknown interface '{name}' "
                             f"(known: {', '.join(sorted(INTERFACES))})")
        try:
            number = int(index) if index else 0
        except ValueError:
            raise ValueError(f"'{text}' is not a device address: index '{index}' is not a number") from None
        if number < 0:
            raise ValueError(f"'{text}' is not a device address: negative index")
        return DeviceAddress(INTERFACES[name], number)


@dataclass(frozen=True)
class Header:
    """player_msghdr. ``host``/``robot`` are ignored by the server on what a client sends."""

    host: int
    robot: int
    interf: int
    index: int
    type: int
    subtype: int
    timestamp: float
    seq: int
    size: int

    def pack(self) -> bytes:
        return _HEADER.pack(self.host, self.robot, self.interf, self.index, self.type, self.subtype,
                            self.timestamp, self.seq, self.size)

    @staticmethod
    def unpack(data: bytes) -> Header:
        return Header(*_HEADER.unpack(data))

    def describe(self) -> str:
        """``laser:0 REQ 2`` — for messages."""
        try:
            kind = MsgType(self.type).name
        except ValueError:
            kind = f"type{self.type}"
        return f"{interface_name(self.interf)}:{self.index} {kind} {self.subtype}"


@dataclass(frozen=True)
class Message:
    header: Header
    body: bytes

    def to_bytes(self) -> bytes:
        return self.header.pack() + self.body


def encode(interf: int, index: int, msgtype: int, subtype: int, body: bytes, *, robot: int = 0,
           timestamp: float = 0.0) -> bytes:
    """A whole message as a client sends it (host 0; the server fills in the real address)."""
    return Header(0, robot, interf, index, msgtype, subtype, timestamp, 0, len(body)).pack() + body


def parse_ident(ident: bytes) -> str:
    """The server's banner text; raises if these 32 bytes are not a Player ident."""
    text = ident.split(b"\0", 1)[0].decode("ascii", errors="replace")
    if not text.startswith("Player v."):
        raise PlayerProtocolError(f"not a Player server: its first {len(ident)} bytes are {ident!r}, "
                                  f"not a 'Player v.' banner")
    return text


class Framer:
    """Cuts a byte stream (arriving in any chunks) into messages; one per direction and connection."""

    def __init__(self, *, expect_ident: bool) -> None:
        self._buffer = bytearray()
        self._need_ident = expect_ident
        self.ident: str | None = None

    def feed(self, chunk: bytes) -> list[Message]:
        self._buffer += chunk
        out: list[Message] = []
        if self._need_ident:
            if len(self._buffer) < IDENT_LENGTH:
                return out
            self.ident = parse_ident(bytes(self._buffer[:IDENT_LENGTH]))
            del self._buffer[:IDENT_LENGTH]
            self._need_ident = False
        while len(self._buffer) >= HEADER_SIZE:
            header = Header.unpack(bytes(self._buffer[:HEADER_SIZE]))
            if header.size > MAX_PAYLOAD:
                raise PlayerProtocolError(f"message header announces {header.size} payload bytes "
                                          f"({header.describe()}), more than Player ever sends")
            end = HEADER_SIZE + header.size
            if len(self._buffer) < end:
                break
            out.append(Message(header, bytes(self._buffer[HEADER_SIZE:end])))
            del self._buffer[:end]
        return out

    @property
    def pending(self) -> int:
        """Bytes held back: the start of a message not complete yet."""
        return len(self._buffer)
