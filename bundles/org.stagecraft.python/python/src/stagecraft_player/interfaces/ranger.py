"""ranger (interface 62): any set of range sensors — a laser, a sonar ring, IR arrays.

Stage provides a Pioneer's 16 sonars and its laser as rangers. For a ring of sonars the
elements are in the order of their element poses from GET_GEOM (on a Pioneer: 0 on the left,
counting clockwise round the front to 7 on the right, then on round the back to 15).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, ClassVar

from ..geometry import Bbox3d, Pose3d, _WithUnits
from ..proxy import Proxy
from ..units import QuantityLike, to_si
from ..xdr import XdrReader, XdrWriter

DATA_RANGE = 1
DATA_INTNS = 3
DATA_GEOM = 5
REQ_GET_GEOM = 1
REQ_POWER = 2
REQ_INTNS = 3
REQ_SET_CONFIG = 4
REQ_GET_CONFIG = 5


@dataclass(frozen=True)
class RangerRanges(_WithUnits):
    """player_ranger_data_range: one range [m] per beam or element."""

    ranges: tuple[float, ...]
    UNITS: ClassVar[dict[str, str]] = {"ranges": "m"}

    @staticmethod
    def read(r: XdrReader) -> RangerRanges:
        return RangerRanges(tuple(r.doubles()))


@dataclass(frozen=True)
class RangerIntensities:
    """player_ranger_data_intns: one intensity per beam or element (units are the driver's)."""

    intensities: tuple[float, ...]

    @staticmethod
    def read(r: XdrReader) -> RangerIntensities:
        return RangerIntensities(tuple(r.doubles()))


@dataclass(frozen=True)
class RangerGeometry:
    """player_ranger_geom: the device's pose and size, and each element's pose and size."""

    pose: Pose3d
    size: Bbox3d
    element_poses: tuple[Pose3d, ...]
    element_sizes: tuple[Bbox3d, ...]

    @staticmethod
    def read(r: XdrReader) -> RangerGeometry:
        pose, size = Pose3d.read(r), Bbox3d.read(r)
        poses = tuple(r.structs(Pose3d.XDR_SIZE, Pose3d.read))
        sizes = tuple(r.structs(Bbox3d.XDR_SIZE, Bbox3d.read))
        return RangerGeometry(pose, size, poses, sizes)

    def bearing(self, element: int) -> float:
        """The direction element ``element`` looks in, on the robot [rad] (0 ahead, left positive)."""
        return self.element_poses[element].pyaw


@dataclass(frozen=True)
class RangerConfig(_WithUnits):
    """player_ranger_config."""

    min_angle: float
    max_angle: float
    angular_res: float
    min_range: float
    max_range: float
    range_res: float
    frequency: float
    UNITS: ClassVar[dict[str, str]] = {"min_angle": "rad", "max_angle": "rad", "angular_res": "rad",
                                       "min_range": "m", "max_range": "m", "range_res": "m", "frequency": "Hz"}

    @staticmethod
    def read(r: XdrReader) -> RangerConfig:
        return RangerConfig(*(r.float64() for _ in range(7)))

    def to_bytes(self) -> bytes:
        w = XdrWriter()
        for v in (self.min_angle, self.max_angle, self.angular_res, self.min_range, self.max_range,
                  self.range_res, self.frequency):
            w.float64(v)
        return w.to_bytes()


class Ranger(Proxy):
    """A ranger. Fields as in Player: ``ranges``, ``intensities``; ``geometry`` after
    :meth:`get_geometry` (element poses: where each sonar sits and looks)."""

    INTERFACE = "ranger"
    DATA = {DATA_RANGE: RangerRanges.read, DATA_INTNS: RangerIntensities.read, DATA_GEOM: RangerGeometry.read}

    def __init__(self, client: Any, device: int | str = 0, *, subscribe: bool = True) -> None:
        self.ranges: tuple[float, ...] = ()
        self.intensities: tuple[float, ...] = ()
        self.geometry: RangerGeometry | None = None
        self.config: RangerConfig | None = None
        super().__init__(client, device, subscribe=subscribe)

    def _take(self, subtype: int, record: Any) -> None:
        if subtype == DATA_RANGE:
            self.ranges = record.ranges
        elif subtype == DATA_INTNS:
            self.intensities = record.intensities
        else:
            self.geometry = record

    @property
    def element_count(self) -> int:
        return len(self.ranges)

    def get_geometry(self) -> RangerGeometry:
        self.geometry = RangerGeometry.read(self._reader(self._request(REQ_GET_GEOM), "GET_GEOM"))
        return self.geometry

    def get_config(self) -> RangerConfig:
        self.config = RangerConfig.read(self._reader(self._request(REQ_GET_CONFIG), "GET_CONFIG"))
        return self.config

    def set_config(self, *, min_angle: QuantityLike, max_angle: QuantityLike, angular_res: QuantityLike,
                   min_range: QuantityLike, max_range: QuantityLike, range_res: QuantityLike,
                   frequency: QuantityLike) -> None:
        config = RangerConfig(to_si(min_angle, "angle", "min_angle"), to_si(max_angle, "angle", "max_angle"),
                              to_si(angular_res, "angle", "angular_res"), to_si(min_range, "length", "min_range"),
                              to_si(max_range, "length", "max_range"), to_si(range_res, "length", "range_res"),
                              to_si(frequency, "frequency", "frequency"))
        self._request(REQ_SET_CONFIG, config.to_bytes())

    def set_power(self, on: bool) -> None:
        self._request(REQ_POWER, XdrWriter().uint32(int(on)).to_bytes())

    def set_intensity_data(self, on: bool) -> None:
        """REQ INTNS: switch intensity data on or off."""
        self._request(REQ_INTNS, XdrWriter().uint32(int(on)).to_bytes())

    def readings(self) -> list[tuple[float, float]]:
        """(bearing on the robot [rad], range [m]) per element; needs :meth:`get_geometry` first."""
        if self.geometry is None:
            raise RuntimeError(f"{self.address}: call get_geometry() first to know where each element looks")
        return [(self.geometry.bearing(i), r) for i, r in enumerate(self.ranges)]


def normalize_angle(a: float) -> float:
    """``a`` wrapped into (-pi, pi]."""
    a = math.fmod(a + math.pi, 2 * math.pi)
    return (a + 2 * math.pi if a <= 0 else a) - math.pi
