"""sonar (interface 5): a sonar ring on a real robot (p2os on a Pioneer). Stage uses ranger instead."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, ClassVar

from ..geometry import Pose3d, _WithUnits
from ..proxy import Proxy
from ..xdr import XdrReader, XdrWriter

DATA_RANGES = 1
DATA_GEOM = 2
REQ_GET_GEOM = 1
REQ_POWER = 2


@dataclass(frozen=True)
class SonarRanges(_WithUnits):
    """player_sonar_data: one range [m] per transducer."""

    ranges: tuple[float, ...]
    UNITS: ClassVar[dict[str, str]] = {"ranges": "m"}

    @staticmethod
    def read(r: XdrReader) -> SonarRanges:
        return SonarRanges(tuple(r.floats()))


@dataclass(frozen=True)
class SonarGeometry:
    """player_sonar_geom: where each transducer sits and looks."""

    poses: tuple[Pose3d, ...]

    @staticmethod
    def read(r: XdrReader) -> SonarGeometry:
        return SonarGeometry(tuple(r.structs(Pose3d.XDR_SIZE, Pose3d.read)))


class Sonar(Proxy):
    """A sonar ring. Fields as in Player: ``ranges``; ``poses`` after :meth:`get_geometry`."""

    INTERFACE = "sonar"
    DATA = {DATA_RANGES: SonarRanges.read, DATA_GEOM: SonarGeometry.read}

    def __init__(self, client: Any, device: int | str = 0, *, subscribe: bool = True) -> None:
        self.ranges: tuple[float, ...] = ()
        self.poses: tuple[Pose3d, ...] = ()
        super().__init__(client, device, subscribe=subscribe)

    def _take(self, subtype: int, record: Any) -> None:
        if subtype == DATA_RANGES:
            self.ranges = record.ranges
        else:
            self.poses = record.poses

    def get_geometry(self) -> SonarGeometry:
        geom = SonarGeometry.read(self._reader(self._request(REQ_GET_GEOM), "GET_GEOM"))
        self.poses = geom.poses
        return geom

    def set_power(self, on: bool) -> None:
        self._request(REQ_POWER, XdrWriter().uint32(int(on)).to_bytes())
