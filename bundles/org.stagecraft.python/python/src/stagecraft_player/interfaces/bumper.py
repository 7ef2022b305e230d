"""bumper (interface 14): contact switches round the robot."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, ClassVar

from ..geometry import Pose3d, _WithUnits
from ..proxy import Proxy
from ..xdr import XdrReader

DATA_STATE = 1
DATA_GEOM = 2
REQ_GET_GEOM = 1


@dataclass(frozen=True)
class BumperState:
    """player_bumper_data: one byte per bumper, non-zero when pressed."""

    bumpers: tuple[int, ...]

    @staticmethod
    def read(r: XdrReader) -> BumperState:
        return BumperState(tuple(r.counted_bytes()))


@dataclass(frozen=True)
class BumperDefine(_WithUnits):
    """player_bumper_define: a bumper's pose, length and radius of curvature."""

    pose: Pose3d
    length: float
    radius: float
    UNITS: ClassVar[dict[str, str]] = {"length": "m", "radius": "m"}

    @staticmethod
    def read(r: XdrReader) -> BumperDefine:
        return BumperDefine(Pose3d.read(r), r.float32(), r.float32())


@dataclass(frozen=True)
class BumperGeometry:
    bumper_def: tuple[BumperDefine, ...]

    @staticmethod
    def read(r: XdrReader) -> BumperGeometry:
        return BumperGeometry(tuple(r.structs(Pose3d.XDR_SIZE + 8, BumperDefine.read)))


class Bumper(Proxy):
    """Bumpers. Fields as in Player: ``bumpers``; ``bumper_def`` after :meth:`get_geometry`."""

    INTERFACE = "bumper"
    DATA = {DATA_STATE: BumperState.read, DATA_GEOM: BumperGeometry.read}

    def __init__(self, client: Any, device: int | str = 0, *, subscribe: bool = True) -> None:
        self.bumpers: tuple[int, ...] = ()
        self.bumper_def: tuple[BumperDefine, ...] = ()
        super().__init__(client, device, subscribe=subscribe)

    def _take(self, subtype: int, record: Any) -> None:
        if subtype == DATA_STATE:
            self.bumpers = record.bumpers
        else:
            self.bumper_def = record.bumper_def

    def pressed(self) -> list[int]:
        """Indices of the bumpers pressed now."""
        return [i for i, b in enumerate(self.bumpers) if b]

    def get_geometry(self) -> BumperGeometry:
        geom = BumperGeometry.read(self._reader(self._request(REQ_GET_GEOM), "GET_GEOM"))
        self.bumper_def = geom.bumper_def
        return geom
