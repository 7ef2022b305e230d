"""position2d (interface 4): a mobile base — odometry, velocity and position commands."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, ClassVar

from ..geometry import DeviceGeometry, Pose2d, _WithUnits
from ..proxy import Proxy
from ..units import QuantityLike, to_si
from ..xdr import XdrReader, XdrWriter

DATA_STATE = 1
DATA_GEOM = 2
CMD_VEL = 1
CMD_POS = 2
CMD_CAR = 3
CMD_VEL_HEAD = 4
REQ_GET_GEOM = 1
REQ_MOTOR_POWER = 2
REQ_VELOCITY_MODE = 3
REQ_POSITION_MODE = 4
REQ_SET_ODOM = 5
REQ_RESET_ODOM = 6
REQ_SPEED_PID = 7
REQ_POSITION_PID = 8
REQ_SPEED_PROF = 9


@dataclass(frozen=True)
class Position2dData(_WithUnits):
    """player_position2d_data: odometric pose, velocity, and whether the motors are stalled."""

    px: float
    py: float
    pa: float
    vx: float
    vy: float
    va: float
    stall: int
    UNITS: ClassVar[dict[str, str]] = {"px": "m", "py": "m", "pa": "rad", "vx": "m/s", "vy": "m/s",
                                       "va": "rad/s"}

    @staticmethod
    def read(r: XdrReader) -> Position2dData:
        pos, vel = Pose2d.read(r), Pose2d.read(r)
        return Position2dData(pos.px, pos.py, pos.pa, vel.px, vel.py, vel.pa, r.uint8())


class Position2d(Proxy):
    """A robot base. Fields as in Player: ``px py pa`` (odometry), ``vx vy va``, ``stall``.

    Commands take quantities or plain SI numbers::

        robot.set_speed(0.3 * m/s, 20 * deg/s)
    """

    INTERFACE = "position2d"
    DATA = {DATA_STATE: Position2dData.read, DATA_GEOM: DeviceGeometry.read}

    def __init__(self, client: Any, device: int | str = 0, *, subscribe: bool = True) -> None:
        self.px = self.py = self.pa = 0.0
        self.vx = self.vy = self.va = 0.0
        self.stall = 0
        self.data: Position2dData | None = None
        self.geometry: DeviceGeometry | None = None
        super().__init__(client, device, subscribe=subscribe)

    def _take(self, subtype: int, record: Any) -> None:
        if subtype == DATA_STATE:
            self.data = record
            self.px, self.py, self.pa = record.px, record.py, record.pa
            self.vx, self.vy, self.va = record.vx, record.vy, record.va
            self.stall = record.stall
        elif subtype == DATA_GEOM:
            self.geometry = record

    @property
    def pose(self) -> Pose2d:
        return Pose2d(self.px, self.py, self.pa)

    # -- commands -----------------------------------------------------------------------------

    def set_velocity(self, vx: QuantityLike, vy: QuantityLike, va: QuantityLike, *, enable: bool = True) -> None:
        """CMD VEL: forward and sideways speed, turn rate (``state`` = ``enable``)."""
        body = XdrWriter().float64(to_si(vx, "speed", "vx")).float64(to_si(vy, "speed", "vy"))
        body.float64(to_si(va, "angular_speed", "va")).uint32(int(enable))
        self._command(CMD_VEL, body.to_bytes())

    def set_speed(self, xspeed: QuantityLike, yawspeed: QuantityLike) -> None:
        """CMD VEL for a differential drive: forward speed and turn rate (counter-clockwise positive)."""
        self.set_velocity(xspeed, 0.0, yawspeed)

    def stop(self) -> None:
        self.set_velocity(0.0, 0.0, 0.0)

    def go_to(self, px: QuantityLike, py: QuantityLike, pa: QuantityLike, *, vx: QuantityLike = 0.0,
              va: QuantityLike = 0.0) -> None:
        """CMD POS: drive to a pose in odometry coordinates (``vx``/``va``: speed limits, if the driver uses them)."""
        body = XdrWriter()
        Pose2d(to_si(px, "length", "px"), to_si(py, "length", "py"), to_si(pa, "angle", "pa")).write(body)
        Pose2d(to_si(vx, "speed", "vx"), 0.0, to_si(va, "angular_speed", "va")).write(body)
        self._command(CMD_POS, body.uint32(1).to_bytes())

    def set_car(self, velocity: QuantityLike, angle: QuantityLike) -> None:
        """CMD CAR: speed and steering angle (car-like robots)."""
        body = XdrWriter().float64(to_si(velocity, "speed", "velocity")).float64(to_si(angle, "angle", "angle"))
        self._command(CMD_CAR, body.to_bytes())

    def set_velocity_heading(self, velocity: QuantityLike, heading: QuantityLike) -> None:
        """CMD VEL_HEAD: speed and absolute heading."""
        body = XdrWriter().float64(to_si(velocity, "speed", "velocity")).float64(to_si(heading, "angle", "heading"))
        self._command(CMD_VEL_HEAD, body.to_bytes())

    # -- requests -----------------------------------------------------------------------------

    def get_geometry(self) -> DeviceGeometry:
        """REQ GET_GEOM: the base's pose on the robot and its size."""
        self.geometry = DeviceGeometry.read(self._reader(self._request(REQ_GET_GEOM), "GET_GEOM"))
        return self.geometry

    def enable_motors(self, on: bool = True) -> None:
        """REQ MOTOR_POWER."""
        self._request(REQ_MOTOR_POWER, XdrWriter().uint32(int(on)).to_bytes())

    def set_velocity_mode(self, mode: int) -> None:
        """REQ VELOCITY_MODE (driver-specific values; Stage refuses it)."""
        self._request(REQ_VELOCITY_MODE, XdrWriter().uint32(mode).to_bytes())

    def set_position_mode(self, position: bool) -> None:
        """REQ POSITION_MODE: True for position control (CMD POS), False for velocity control."""
        self._request(REQ_POSITION_MODE, XdrWriter().uint32(int(position)).to_bytes())

    def set_odometry(self, px: QuantityLike, py: QuantityLike, pa: QuantityLike) -> None:
        """REQ SET_ODOM: make the odometry read this pose now."""
        body = XdrWriter()
        Pose2d(to_si(px, "length", "px"), to_si(py, "length", "py"), to_si(pa, "angle", "pa")).write(body)
        self._request(REQ_SET_ODOM, body.to_bytes())

    def reset_odometry(self) -> None:
        """REQ RESET_ODOM: odometry back to (0, 0, 0)."""
        self._request(REQ_RESET_ODOM)

    def set_speed_pid(self, kp: float, ki: float, kd: float) -> None:
        self._request(REQ_SPEED_PID, XdrWriter().float32(kp).float32(ki).float32(kd).to_bytes())

    def set_position_pid(self, kp: float, ki: float, kd: float) -> None:
        self._request(REQ_POSITION_PID, XdrWriter().float32(kp).float32(ki).float32(kd).to_bytes())

    def set_speed_profile(self, speed: QuantityLike, acc: QuantityLike) -> None:
        """REQ SPEED_PROF: maximum speed [m/s] and acceleration [m/s²] for position control."""
        acc_si = to_si(acc, "acceleration", "acc")
        self._request(REQ_SPEED_PROF, XdrWriter().float32(to_si(speed, "speed", "speed")).float32(acc_si).to_bytes())
