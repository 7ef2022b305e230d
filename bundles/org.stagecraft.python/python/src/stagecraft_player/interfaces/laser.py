"""laser (interface 6): a scanning range finder, e.g. a SICK LMS200 (180 beams over 180°)."""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass
from typing import Any, ClassVar

from ..geometry import DeviceGeometry, Pose2d, _WithUnits
from ..proxy import Proxy
from ..units import QuantityLike, to_si
from ..xdr import XdrReader, XdrWriter

DATA_SCAN = 1
DATA_SCANPOSE = 2
DATA_SCANANGLE = 3
REQ_GET_GEOM = 1
REQ_SET_CONFIG = 2
REQ_GET_CONFIG = 3
REQ_POWER = 4
REQ_GET_ID = 5


@dataclass(frozen=True)
class LaserScan(_WithUnits):
    """player_laser_data. Beam ``i`` points at ``min_angle + i * resolution``: counter-clockwise,
    so on a robot the first beam is on the right (-90° for a 180° laser) and the last on the left.
    """

    min_angle: float
    max_angle: float
    resolution: float
    max_range: float
    ranges: tuple[float, ...]
    intensity: tuple[int, ...]
    id: int
    UNITS: ClassVar[dict[str, str]] = {"min_angle": "rad", "max_angle": "rad", "resolution": "rad",
                                       "max_range": "m", "ranges": "m"}

    @staticmethod
    def read(r: XdrReader) -> LaserScan:
        min_angle, max_angle, resolution, max_range = r.float32(), r.float32(), r.float32(), r.float32()
        ranges = tuple(r.floats())
        intensity = tuple(r.counted_bytes())
        return LaserScan(min_angle, max_angle, resolution, max_range, ranges, intensity, r.uint32())

    def angle(self, i: int) -> float:
        """Bearing of beam ``i`` [rad] in the laser's frame (0 = straight ahead, left positive)."""
        return self.min_angle + i * self.resolution

    def beams(self) -> Iterator[tuple[float, float]]:
        """(bearing [rad], range [m]) of every beam, right to left."""
        for i, r in enumerate(self.ranges):
            yield self.angle(i), r

    def points(self) -> list[tuple[float, float]]:
        """The hits as (x, y) [m] in the laser's frame (x ahead, y to the left)."""
        return [(r * math.cos(a), r * math.sin(a)) for a, r in self.beams()]


@dataclass(frozen=True)
class LaserScanPose:
    """player_laser_data_scanpose: a scan and the laser's pose when it was taken."""

    scan: LaserScan
    pose: Pose2d

    @staticmethod
    def read(r: XdrReader) -> LaserScanPose:
        return LaserScanPose(LaserScan.read(r), Pose2d.read(r))


@dataclass(frozen=True)
class LaserScanAngle(_WithUnits):
    """player_laser_data_scanangle: ranges each with its own bearing."""

    max_range: float
    ranges: tuple[float, ...]
    angles: tuple[float, ...]
    intensity: tuple[int, ...]
    id: int
    UNITS: ClassVar[dict[str, str]] = {"max_range": "m", "ranges": "m", "angles": "rad"}

    @staticmethod
    def read(r: XdrReader) -> LaserScanAngle:
        max_range = r.float32()
        ranges, angles = tuple(r.floats()), tuple(r.floats())
        return LaserScanAngle(max_range, ranges, angles, tuple(r.counted_bytes()), r.uint32())


@dataclass(frozen=True)
class LaserConfig(_WithUnits):
    """player_laser_config."""

    min_angle: float
    max_angle: float
    resolution: float
    max_range: float
    range_res: float
    intensity: int
    scanning_frequency: float
    UNITS: ClassVar[dict[str, str]] = {"min_angle": "rad", "max_angle": "rad", "resolution": "rad",
                                       "max_range": "m", "range_res": "m", "scanning_frequency": "Hz"}

    @staticmethod
    def read(r: XdrReader) -> LaserConfig:
        return LaserConfig(r.float32(), r.float32(), r.float32(), r.float32(), r.float32(), r.uint8(), r.float32())

    def to_bytes(self) -> bytes:
        w = XdrWriter().float32(self.min_angle).float32(self.max_angle).float32(self.resolution)
        w.float32(self.max_range).float32(self.range_res).uint32(self.intensity).float32(self.scanning_frequency)
        return w.to_bytes()


class Laser(Proxy):
    """A laser. Fields as in Player's laser data: ``min_angle max_angle resolution max_range
    ranges intensity id``; ``scan`` is the latest :class:`LaserScan` (``None`` before the first).
    """

    INTERFACE = "laser"
    DATA = {DATA_SCAN: LaserScan.read, DATA_SCANPOSE: LaserScanPose.read, DATA_SCANANGLE: LaserScanAngle.read}

    def __init__(self, client: Any, device: int | str = 0, *, subscribe: bool = True) -> None:
        self.scan: LaserScan | None = None
        self.scan_pose: Pose2d | None = None
        self.scan_angle: LaserScanAngle | None = None
        self.geometry: DeviceGeometry | None = None
        super().__init__(client, device, subscribe=subscribe)

    def _take(self, subtype: int, record: Any) -> None:
        if subtype == DATA_SCAN:
            self.scan = record
        elif subtype == DATA_SCANPOSE:
            self.scan, self.scan_pose = record.scan, record.pose
        else:
            self.scan_angle = record

    def _field(self, name: str) -> Any:
        if self.scan is None:
            raise AttributeError(f"{self.address} has sent no scan yet (call client.read() first)")
        return getattr(self.scan, name)

    min_angle = property(lambda self: self._field("min_angle"))
    max_angle = property(lambda self: self._field("max_angle"))
    resolution = property(lambda self: self._field("resolution"))
    max_range = property(lambda self: self._field("max_range"))
    ranges = property(lambda self: self._field("ranges"))
    intensity = property(lambda self: self._field("intensity"))
    id = property(lambda self: self._field("id"))

    def get_geometry(self) -> DeviceGeometry:
        """REQ GET_GEOM: the laser's pose on the robot and its size."""
        self.geometry = DeviceGeometry.read(self._reader(self._request(REQ_GET_GEOM), "GET_GEOM"))
        return self.geometry

    def get_config(self) -> LaserConfig:
        return LaserConfig.read(self._reader(self._request(REQ_GET_CONFIG), "GET_CONFIG"))

    def set_config(self, *, min_angle: QuantityLike, max_angle: QuantityLike, resolution: QuantityLike,
                   max_range: QuantityLike, range_res: QuantityLike, intensity: bool,
                   scanning_frequency: QuantityLike) -> None:
        """REQ SET_CONFIG, every field given (libplayerc leaves ``max_range`` unset; this does not)."""
        config = LaserConfig(to_si(min_angle, "angle", "min_angle"), to_si(max_angle, "angle", "max_angle"),
                             to_si(resolution, "angle", "resolution"), to_si(max_range, "length", "max_range"),
                             to_si(range_res, "length", "range_res"), int(intensity),
                             to_si(scanning_frequency, "frequency", "scanning_frequency"))
        self._request(REQ_SET_CONFIG, config.to_bytes())

    def set_power(self, on: bool) -> None:
        self._request(REQ_POWER, XdrWriter().uint32(int(on)).to_bytes())

    def get_id(self) -> int:
        """REQ GET_ID: the device's serial number."""
        return self._reader(self._request(REQ_GET_ID), "GET_ID").uint32()
