"""Poses and sizes as Player defines them (player.h): doubles, metres and radians."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, ClassVar

from .units import QuantityView
from .xdr import XdrReader, XdrWriter


class _WithUnits:
    UNITS: ClassVar[dict[str, str]] = {}

    @property
    def q(self) -> Any:
        """The fields as pint quantities: ``pose.q.pa.to("deg")``."""
        return QuantityView(self)


@dataclass(frozen=True)
class Pose2d(_WithUnits):
    """player_pose2d: x, y [m] and yaw [rad]."""

    px: float = 0.0
    py: float = 0.0
    pa: float = 0.0
    UNITS: ClassVar[dict[str, str]] = {"px": "m", "py": "m", "pa": "rad"}
    XDR_SIZE: ClassVar[int] = 24

    @staticmethod
    def read(r: XdrReader) -> Pose2d:
        return Pose2d(r.float64(), r.float64(), r.float64())

    def write(self, w: XdrWriter) -> None:
        w.float64(self.px).float64(self.py).float64(self.pa)


@dataclass(frozen=True)
class Pose3d(_WithUnits):
    """player_pose3d: position [m] and roll, pitch, yaw [rad]."""

    px: float = 0.0
    py: float = 0.0
    pz: float = 0.0
    proll: float = 0.0
    ppitch: float = 0.0
    pyaw: float = 0.0
    UNITS: ClassVar[dict[str, str]] = {"px": "m", "py": "m", "pz": "m", "proll": "rad", "ppitch": "rad",
                                       "pyaw": "rad"}
    XDR_SIZE: ClassVar[int] = 48

    @staticmethod
    def read(r: XdrReader) -> Pose3d:
        return Pose3d(r.float64(), r.float64(), r.float64(), r.float64(), r.float64(), r.float64())

    def write(self, w: XdrWriter) -> None:
        for v in (self.px, self.py, self.pz, self.proll, self.ppitch, self.pyaw):
            w.float64(v)


@dataclass(frozen=True)
class Bbox2d(_WithUnits):
    """player_bbox2d: width and length [m]."""

    sw: float = 0.0
    sl: float = 0.0
    UNITS: ClassVar[dict[str, str]] = {"sw": "m", "sl": "m"}

    @staticmethod
    def read(r: XdrReader) -> Bbox2d:
        return Bbox2d(r.float64(), r.float64())


@dataclass(frozen=True)
class Bbox3d(_WithUnits):
    """player_bbox3d: width, length, height [m]."""

    sw: float = 0.0
    sl: float = 0.0
    sh: float = 0.0
    UNITS: ClassVar[dict[str, str]] = {"sw": "m", "sl": "m", "sh": "m"}
    XDR_SIZE: ClassVar[int] = 24

    @staticmethod
    def read(r: XdrReader) -> Bbox3d:
        return Bbox3d(r.float64(), r.float64(), r.float64())

    def write(self, w: XdrWriter) -> None:
        w.float64(self.sw).float64(self.sl).float64(self.sh)


@dataclass(frozen=True)
class DeviceGeometry:
    """A device's pose on the robot and its size: the GET_GEOM reply of position2d, laser, ...

    Simulators may leave parts of it uninitialised (Stage's position2d sends garbage for the
    pose's z, roll and the height), so use only the fields your driver fills in.
    """

    pose: Pose3d
    size: Bbox3d

    @staticmethod
    def read(r: XdrReader) -> DeviceGeometry:
        return DeviceGeometry(Pose3d.read(r), Bbox3d.read(r))
