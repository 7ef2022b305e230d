"""Sun XDR (RFC 4506) as Player uses it: big-endian, every item padded to 4 bytes.

Player's XDR generator maps its C types like this (the mapping the readers and writers follow):
8- and 16-bit integers take a whole 4-byte word, ``uint64_t`` takes 4 bytes (a quirk of the
generator on 64-bit Linux), ``int64_t`` 8. A variable-length array has its ``*_count`` member
where it is declared and then its own element count again (``xdr_array``); byte arrays and
strings are ``xdr_bytes`` (count, bytes, zero padding), strings counting their trailing NUL.
"""

from __future__ import annotations

import struct
from collections.abc import Callable, Sequence
from typing import TypeVar

from .errors import PlayerProtocolError

T = TypeVar("T")

_U32 = struct.Struct(">I")
_I32 = struct.Struct(">i")
_F32 = struct.Struct(">f")
_F64 = struct.Struct(">d")


def _pad(n: int) -> int:
    return (4 - n % 4) % 4


class XdrWriter:
    """Builds an XDR payload item by item."""

    def __init__(self) -> None:
        self._parts: list[bytes] = []

    def uint32(self, value: int) -> XdrWriter:
        """uint8, uint16 and uint32 alike: each takes a 4-byte word."""
        self._parts.append(_U32.pack(value & 0xFFFFFFFF))
        return self

    def int32(self, value: int) -> XdrWriter:
        """Any signed integer up to 32 bits."""
        self._parts.append(_I32.pack(value))
        return self

    def float32(self, value: float) -> XdrWriter:
        self._parts.append(_F32.pack(value))
        return self

    def float64(self, value: float) -> XdrWriter:
        self._parts.append(_F64.pack(value))
        return self

    def opaque(self, data: bytes) -> XdrWriter:
        """xdr_bytes: count, the bytes, zero padding."""
        self._parts.append(_U32.pack(len(data)) + data + b"\0" * _pad(len(data)))
        return self

    def counted_bytes(self, data: bytes) -> XdrWriter:
        """A ``foo_count`` member followed by ``foo`` as xdr_bytes (Player's byte arrays)."""
        return self.uint32(len(data)).opaque(data)

    def string(self, text: str) -> XdrWriter:
        """A Player string member: ``name_count`` then the bytes with their NUL."""
        return self.counted_bytes(text.encode("utf-8") + b"\0")

    def floats(self, values: Sequence[float]) -> XdrWriter:
        """``foo_count`` then xdr_array of floats (the count twice)."""
        self.uint32(len(values)).uint32(len(values))
        for v in values:
            self.float32(v)
        return self

    def doubles(self, values: Sequence[float]) -> XdrWriter:
        self.uint32(len(values)).uint32(len(values))
        for v in values:
            self.float64(v)
        return self

    def to_bytes(self) -> bytes:
        return b"".join(self._parts)


class XdrReader:
    """Reads an XDR payload; running past its end raises :class:`PlayerProtocolError`."""

    def __init__(self, data: bytes, what: str = "payload") -> None:
        self._data = data
        self._pos = 0
        self._what = what

    @property
    def position(self) -> int:
        return self._pos

    @property
    def remaining(self) -> int:
        return len(self._data) - self._pos

    def _take(self, n: int) -> bytes:
        if self._pos + n > len(self._data):
            raise PlayerProtocolError(
                f"{self._what}: needs {n} more bytes at offset {self._pos}, only {self.remaining} left "
                f"(payload of {len(self._data)} bytes)")
        chunk = self._data[self._pos:self._pos + n]
        self._pos += n
        return chunk

    def uint32(self) -> int:
        return int(_U32.unpack(self._take(4))[0])

    def uint8(self) -> int:
        """An 8-bit value in its 4-byte word (the value is in the last byte)."""
        return self.uint32() & 0xFF

    def int32(self) -> int:
        return int(_I32.unpack(self._take(4))[0])

    def float32(self) -> float:
        return float(_F32.unpack(self._take(4))[0])

    def float64(self) -> float:
        return float(_F64.unpack(self._take(8))[0])

    def opaque(self) -> bytes:
        n = self.uint32()
        data = self._take(n)
        self._take(_pad(n))
        return data

    def counted_bytes(self) -> bytes:
        self.uint32()  # the struct's own count member; xdr_bytes repeats it
        return self.opaque()

    def string(self) -> str:
        return self.counted_bytes().split(b"\0", 1)[0].decode("utf-8", errors="replace")

    def _array_count(self, min_element_bytes: int) -> int:
        self.uint32()  # the *_count member
        n = self.uint32()  # xdr_array's own count: the one that tells how many follow
        if n * min_element_bytes > self.remaining:
            raise PlayerProtocolError(
                f"{self._what}: array of {n} elements at offset {self._pos - 4} does not fit in the "
                f"{self.remaining} bytes left")
        return n

    def floats(self) -> list[float]:
        return [self.float32() for _ in range(self._array_count(4))]

    def doubles(self) -> list[float]:
        return [self.float64() for _ in range(self._array_count(8))]

    def structs(self, min_element_bytes: int, read: Callable[[XdrReader], T]) -> list[T]:
        return [read(self) for _ in range(self._array_count(min_element_bytes))]
