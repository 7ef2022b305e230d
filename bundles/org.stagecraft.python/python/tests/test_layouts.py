"""Payload layouts of the interfaces the recordings do not carry (Stage in these worlds has no
bumper, fiducial or blobfinder; sonar is Player's p2os interface), built byte by byte from
Player's definitions: counts twice before arrays, 8-bit values in 4-byte words."""

from __future__ import annotations

import struct

from stagecraft_player import BlobfinderData, BumperGeometry, BumperState, FiducialScan, SonarGeometry, SonarRanges
from stagecraft_player.xdr import XdrReader

POSE3D = struct.pack(">6d", 1.0, 2.0, 0.5, 0.0, 0.0, 0.25)


def test_bumper_state_and_geometry() -> None:
    state = BumperState.read(XdrReader(struct.pack(">II", 3, 3) + bytes([1, 0, 1, 0])))
    assert state.bumpers == (1, 0, 1)
    geom = BumperGeometry.read(XdrReader(struct.pack(">II", 1, 1) + POSE3D + struct.pack(">ff", 0.25, 0.5)))
    assert geom.bumper_def[0].pose.py == 2.0 and geom.bumper_def[0].length == 0.25 and geom.bumper_def[0].radius == 0.5


def test_fiducial_scan() -> None:
    item = struct.pack(">i", -1) + POSE3D + struct.pack(">6d", *([0.01] * 6))
    scan = FiducialScan.read(XdrReader(struct.pack(">II", 2, 2) + item + struct.pack(">i", 7) + POSE3D + bytes(48)))
    assert [f.id for f in scan.fiducials] == [-1, 7]
    assert scan.fiducials[0].pose.pyaw == 0.25 and scan.fiducials[0].upose.px == 0.01


def test_blobfinder_blobs() -> None:
    blob = struct.pack(">9If", 3, 0xFF0000, 120, 40, 30, 35, 45, 25, 35, 2.5)
    data = BlobfinderData.read(XdrReader(struct.pack(">IIII", 320, 240, 1, 1) + blob))
    assert (data.width, data.height) == (320, 240)
    b = data.blobs[0]
    assert (b.id, b.color, b.area, b.x, b.y, b.left, b.right, b.top, b.bottom, b.range) == \
        (3, 0xFF0000, 120, 40, 30, 35, 45, 25, 35, 2.5)


def test_sonar_ranges_are_floats_and_geometry_poses() -> None:
    assert SonarRanges.read(XdrReader(struct.pack(">II2f", 2, 2, 0.5, 4.0))).ranges == (0.5, 4.0)
    assert SonarGeometry.read(XdrReader(struct.pack(">II", 1, 1) + POSE3D)).poses[0].px == 1.0
