"""simulation (interface 31): the simulator itself — where its models are, their properties."""

from __future__ import annotations

import struct
from typing import Any

from ..geometry import Pose2d, Pose3d
from ..proxy import Proxy
from ..units import QuantityLike, to_si
from ..xdr import XdrWriter

REQ_GET_POSE2D = 1
REQ_SET_POSE2D = 2
REQ_GET_POSE3D = 3
REQ_SET_POSE3D = 4
REQ_GET_PROPERTY = 5
REQ_SET_PROPERTY = 6


class Simulation(Proxy):
    """The simulator. Models are named as in the world file (e.g. Stage's ``"r0"``)."""

    INTERFACE = "simulation"

    def __init__(self, client: Any, device: int | str = 0, *, subscribe: bool = True) -> None:
        super().__init__(client, device, subscribe=subscribe)

    def get_pose2d(self, name: str) -> Pose2d:
        body = XdrWriter().string(name)
        Pose2d().write(body)
        r = self._reader(self._request(REQ_GET_POSE2D, body.to_bytes()), "GET_POSE2D")
        r.string()
        return Pose2d.read(r)

    def set_pose2d(self, name: str, px: QuantityLike, py: QuantityLike, pa: QuantityLike) -> None:
        body = XdrWriter().string(name)
        Pose2d(to_si(px, "length", "px"), to_si(py, "length", "py"), to_si(pa, "angle", "pa")).write(body)
        self._request(REQ_SET_POSE2D, body.to_bytes())

    def get_pose3d(self, name: str) -> tuple[Pose3d, float]:
        """The model's pose and the simulation time as the simulator gives it (Stage 4.3: microseconds)."""
        body = XdrWriter().string(name)
        Pose3d().write(body)
        r = self._reader(self._request(REQ_GET_POSE3D, body.float64(0.0).to_bytes()), "GET_POSE3D")
        r.string()
        return Pose3d.read(r), r.float64()

    def get_property(self, name: str, prop: str, size: int, index: int = 0) -> bytes:
        """A model property as the simulator's raw memory (``size`` bytes; the layout is the simulator's)."""
        body = XdrWriter().string(name).string(prop).uint32(index).counted_bytes(b"\0" * size)
        r = self._reader(self._request(REQ_GET_PROPERTY, body.to_bytes()), "GET_PROPERTY")
        r.string(), r.string(), r.uint32()
        return r.counted_bytes()

    def set_property(self, name: str, prop: str, value: bytes, index: int = 0) -> None:
        body = XdrWriter().string(name).string(prop).uint32(index).counted_bytes(value)
        self._request(REQ_SET_PROPERTY, body.to_bytes())

    def get_color(self, name: str) -> tuple[float, float, float, float]:
        """Stage's "color" property: red, green, blue, alpha in 0..1.

        Player passes property values as the simulator's raw memory: 4 floats in its byte order,
        taken here to be little-endian (x86, ARM).
        """
        red, green, blue, alpha = struct.unpack("<4f", self.get_property(name, "color", 16))
        return red, green, blue, alpha

    def set_color(self, name: str, red: float, green: float, blue: float, alpha: float = 1.0) -> None:
        self.set_property(name, "color", struct.pack("<4f", red, green, blue, alpha))
