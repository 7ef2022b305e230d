"""fiducial (interface 10): detected markers (e.g. Stage's fiducial finder), with id and pose."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, ClassVar

from ..geometry import Bbox2d, Bbox3d, Pose3d, _WithUnits
from ..proxy import Proxy
from ..units import QuantityLike, to_si
from ..xdr import XdrReader, XdrWriter

DATA_SCAN = 1
REQ_GET_GEOM = 1
REQ_GET_FOV = 2
REQ_SET_FOV = 3
REQ_GET_ID = 7
REQ_SET_ID = 8


@dataclass(frozen=True)
class FiducialItem:
    """player_fiducial_item: a marker's id (-1 if unknown), pose and pose uncertainty."""

    id: int
    pose: Pose3d
    upose: Pose3d

    @staticmethod
    def read(r: XdrReader) -> FiducialItem:
        return FiducialItem(r.int32(), Pose3d.read(r), Pose3d.read(r))


@dataclass(frozen=True)
class FiducialScan:
    fiducials: tuple[FiducialItem, ...]

    @staticmethod
    def read(r: XdrReader) -> FiducialScan:
        return FiducialScan(tuple(r.structs(4 + 2 * Pose3d.XDR_SIZE, FiducialItem.read)))


@dataclass(frozen=True)
class FiducialGeometry:
    """player_fiducial_geom: the detector's pose and size, and the markers' size."""

    pose: Pose3d
    size: Bbox3d
    fiducial_size: Bbox2d

    @staticmethod
    def read(r: XdrReader) -> FiducialGeometry:
        return FiducialGeometry(Pose3d.read(r), Bbox3d.read(r), Bbox2d.read(r))


@dataclass(frozen=True)
class FiducialFov(_WithUnits):
    """player_fiducial_fov: the range of distances and the angle the detector sees."""

    min_range: float
    max_range: float
    view_angle: float
    UNITS: ClassVar[dict[str, str]] = {"min_range": "m", "max_range": "m", "view_angle": "rad"}

    @staticmethod
    def read(r: XdrReader) -> FiducialFov:
        return FiducialFov(r.float32(), r.float32(), r.float32())


class Fiducial(Proxy):
    """A fiducial finder. Fields as in Player: ``fiducials``."""

    INTERFACE = "fiducial"
    DATA = {DATA_SCAN: FiducialScan.read}

    def __init__(self, client: Any, device: int | str = 0, *, subscribe: bool = True) -> None:
        self.fiducials: tuple[FiducialItem, ...] = ()
        self.geometry: FiducialGeometry | None = None
        super().__init__(client, device, subscribe=subscribe)

    def _take(self, subtype: int, record: Any) -> None:
        self.fiducials = record.fiducials

    def get_geometry(self) -> FiducialGeometry:
        self.geometry = FiducialGeometry.read(self._reader(self._request(REQ_GET_GEOM), "GET_GEOM"))
        return self.geometry

    def get_fov(self) -> FiducialFov:
        return FiducialFov.read(self._reader(self._request(REQ_GET_FOV), "GET_FOV"))

    def set_fov(self, min_range: QuantityLike, max_range: QuantityLike, view_angle: QuantityLike) -> None:
        body = XdrWriter().float32(to_si(min_range, "length", "min_range"))
        body.float32(to_si(max_range, "length", "max_range")).float32(to_si(view_angle, "angle", "view_angle"))
        self._request(REQ_SET_FOV, body.to_bytes())

    def get_id(self) -> int:
        """REQ GET_ID: the id this robot shows to other fiducial finders."""
        return self._reader(self._request(REQ_GET_ID, XdrWriter().uint32(0).to_bytes()), "GET_ID").uint32()

    def set_id(self, marker_id: int) -> None:
        self._request(REQ_SET_ID, XdrWriter().uint32(marker_id).to_bytes())
