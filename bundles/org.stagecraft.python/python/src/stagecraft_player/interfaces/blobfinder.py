"""blobfinder (interface 7): coloured blobs in a camera image."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, ClassVar

from ..geometry import _WithUnits
from ..proxy import Proxy
from ..xdr import XdrReader

DATA_BLOBS = 1


@dataclass(frozen=True)
class Blob(_WithUnits):
    """player_blobfinder_blob: a blob's colour, area, centre and bounding box [pixels], range [m]."""

    id: int
    color: int
    area: int
    x: int
    y: int
    left: int
    right: int
    top: int
    bottom: int
    range: float
    UNITS: ClassVar[dict[str, str]] = {"range": "m"}

    @staticmethod
    def read(r: XdrReader) -> Blob:
        blob_id, color, area, x, y = r.uint32(), r.uint32(), r.uint32(), r.uint32(), r.uint32()
        left, right, top, bottom = r.uint32(), r.uint32(), r.uint32(), r.uint32()
        return Blob(blob_id, color, area, x, y, left, right, top, bottom, r.float32())


@dataclass(frozen=True)
class BlobfinderData:
    """player_blobfinder_data: the image size and the blobs found in it."""

    width: int
    height: int
    blobs: tuple[Blob, ...]

    @staticmethod
    def read(r: XdrReader) -> BlobfinderData:
        width, height = r.uint32(), r.uint32()
        return BlobfinderData(width, height, tuple(r.structs(40, Blob.read)))


class Blobfinder(Proxy):
    """A blob finder. Fields as in Player: ``width height blobs``."""

    INTERFACE = "blobfinder"
    DATA = {DATA_BLOBS: BlobfinderData.read}

    def __init__(self, client: Any, device: int | str = 0, *, subscribe: bool = True) -> None:
        self.width = self.height = 0
        self.blobs: tuple[Blob, ...] = ()
        super().__init__(client, device, subscribe=subscribe)

    def _take(self, subtype: int, record: Any) -> None:
        self.width, self.height, self.blobs = record.width, record.height, record.blobs
