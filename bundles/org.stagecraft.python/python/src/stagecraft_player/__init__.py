"""stagecraft_player: a pure-Python client for the Player 3 robot server, with units.

    from stagecraft_player import Client, m, s, deg

    with Client("localhost", 6665) as client:
        robot = client.position2d(0)
        laser = client.laser(0)
        client.read()
        robot.set_speed(0.3 * m/s, 20 * deg/s)

See docs/python-client.md in the Stagecraft repository.
"""

from .client import Client, DataMessage, DataMode, DeviceInfo, Reply
from .errors import (ConnectionLost, DeviceRefused, PlayerConnectionError, PlayerError, PlayerProtocolError,
                     PlayerTimeout, RequestRefused, UnitError, WrongInterface)
from .geometry import Bbox2d, Bbox3d, DeviceGeometry, Pose2d, Pose3d
from .interfaces.blobfinder import Blob, Blobfinder, BlobfinderData
from .interfaces.bumper import Bumper, BumperDefine, BumperGeometry, BumperState
from .interfaces.fiducial import Fiducial, FiducialFov, FiducialGeometry, FiducialItem, FiducialScan
from .interfaces.laser import Laser, LaserConfig, LaserScan, LaserScanAngle, LaserScanPose
from .interfaces.position2d import Position2d, Position2dData
from .interfaces.ranger import Ranger, RangerConfig, RangerGeometry, RangerIntensities, RangerRanges
from .interfaces.simulation import Simulation
from .interfaces.sonar import Sonar, SonarGeometry, SonarRanges
from .proxy import Proxy
from .units import Hz, Quantity, cm, deg, m, mm, ms, rad, s, to_si, ureg
from .wire import DeviceAddress

__version__ = "0.1.0"

__all__ = [
    "Client", "DataMessage", "DataMode", "DeviceInfo", "Reply",
    "ConnectionLost", "DeviceRefused", "PlayerConnectionError", "PlayerError", "PlayerProtocolError",
    "PlayerTimeout", "RequestRefused", "UnitError", "WrongInterface",
    "Bbox2d", "Bbox3d", "DeviceGeometry", "Pose2d", "Pose3d",
    "Blob", "Blobfinder", "BlobfinderData", "Bumper", "BumperDefine", "BumperGeometry", "BumperState",
    "Fiducial", "FiducialFov", "FiducialGeometry", "FiducialItem", "FiducialScan",
    "Laser", "LaserConfig", "LaserScan", "LaserScanAngle", "LaserScanPose",
    "Position2d", "Position2dData",
    "Ranger", "RangerConfig", "RangerGeometry", "RangerIntensities", "RangerRanges",
    "Simulation", "Sonar", "SonarGeometry", "SonarRanges", "Proxy",
    "Hz", "Quantity", "cm", "deg", "m", "mm", "ms", "rad", "s", "to_si", "ureg",
    "DeviceAddress",
]
