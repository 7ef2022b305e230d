#!/usr/bin/env python3
"""Sunday Stroll: a Pioneer with 16 sonars wanders about, turning at random.

When an obstacle comes too close in front it stops, turns on the spot toward the side with more
free space until the way ahead is clear, and strolls on. It never turns while driving into a
wall: the avoiding turn is made standing still.

    python3 sunday_stroll.py [--host localhost] [--port 6665] [--sonar ranger:0]

Stage provides a Pioneer's sonar ring as ``ranger:0``; a real Pioneer under p2os as ``sonar:0``.
Which way each sonar looks comes from the device's geometry (GET_GEOM), not from its number.
"""

from __future__ import annotations

import argparse
import enum
import math
import random
import sys
import time
from collections.abc import Sequence
from dataclasses import dataclass

from stagecraft_player import Client, PlayerError, Ranger, Sonar, deg, m, s, to_si

CRUISE_SPEED = 0.3 * m / s
#: Stop when something is nearer than this in front.
MIN_CLEARANCE = 0.6 * m
#: ... and go on once the way ahead is clear by this much more (no dithering at the threshold).
CLEARANCE_MARGIN = 0.3 * m
#: The sonars looking within this angle of straight ahead watch the way ahead.
FRONT_HALF_ANGLE = 60 * deg
AVOID_TURN_RATE = 40 * deg / s
#: Random turns while strolling: a rate up to this either way, held for a random while.
MAX_RANDOM_TURN_RATE = 60 * deg / s
MIN_RANDOM_TURN_RATE = 15 * deg / s
TURN_HOLD = (1.0 * s, 3.0 * s)


@dataclass(frozen=True)
class Reading:
    bearing: float  # where the sonar looks on the robot [rad], 0 ahead, positive left
    range: float  # [m]


def front_clearance(readings: Sequence[Reading]) -> float:
    """The nearest range seen by the sonars that look ahead."""
    half = to_si(FRONT_HALF_ANGLE, "angle")
    return min((r.range for r in readings if abs(_wrap(r.bearing)) <= half), default=math.inf)


def free_side(readings: Sequence[Reading]) -> int:
    """+1 if there is more room on the left (front-left quarter and side), -1 if on the right."""
    left = [r.range for r in readings if 0 < _wrap(r.bearing) <= math.pi / 2]
    right = [r.range for r in readings if -math.pi / 2 <= _wrap(r.bearing) < 0]
    return 1 if sum(left) / max(len(left), 1) >= sum(right) / max(len(right), 1) else -1


def _wrap(a: float) -> float:
    return math.atan2(math.sin(a), math.cos(a))


class Mode(enum.Enum):
    STROLLING = "strolling"
    AVOIDING = "avoiding"


class Stroller:
    """The control logic, free of any I/O: sonar readings and the time in, speed and turn rate out."""

    def __init__(self, rng: random.Random | None = None) -> None:
        self.rng = rng or random.Random()
        self.mode = Mode.STROLLING
        self.turn = 0.0
        self.turn_until = -math.inf
        self.avoid_side = 1

    def random_turn(self) -> float:
        """A turn rate [rad/s] of random size and side, never a mere wobble."""
        lo = to_si(MIN_RANDOM_TURN_RATE, "angular_speed")
        hi = to_si(MAX_RANDOM_TURN_RATE, "angular_speed")
        return self.rng.choice((-1, 1)) * self.rng.uniform(lo, hi)

    def step(self, readings: Sequence[Reading], now: float) -> tuple[float, float]:
        """(forward speed [m/s], turn rate [rad/s]) for these readings at time ``now`` [s]."""
        clearance = front_clearance(readings)
        stop_at = to_si(MIN_CLEARANCE, "length")
        if self.mode is Mode.STROLLING and clearance < stop_at:
            self.mode = Mode.AVOIDING
            self.avoid_side = free_side(readings)
        elif self.mode is Mode.AVOIDING and clearance > stop_at + to_si(CLEARANCE_MARGIN, "length"):
            self.mode = Mode.STROLLING
            self.turn_until = -math.inf
        if self.mode is Mode.AVOIDING:
            return 0.0, self.avoid_side * to_si(AVOID_TURN_RATE, "angular_speed")
        if now >= self.turn_until:
            self.turn = self.random_turn()
            self.turn_until = now + self.rng.uniform(*(to_si(t, "time") for t in TURN_HOLD))
        return to_si(CRUISE_SPEED, "speed"), self.turn


def sonar_readings(device: Ranger | Sonar) -> list[Reading]:
    """The latest ranges with the bearing each sonar looks in (from the device's geometry)."""
    if isinstance(device, Ranger):
        return [Reading(b, r) for b, r in device.readings()]
    return [Reading(p.pyaw, r) for p, r in zip(device.poses, device.ranges)]


def main(argv: list[str] | None = None) -> int:
    # the module's docstring read through sys.modules: PyDev's code analysis does not know a module's
    # own __doc__ and marks the bare name as an undefined variable
    parser = argparse.ArgumentParser(description=str(sys.modules[__name__].__doc__).splitlines()[0])
    parser.add_argument("--host", default="localhost")
    parser.add_argument("--port", type=int, default=6665)
    parser.add_argument("--position", default="position2d:0", help="the robot base (default position2d:0)")
    parser.add_argument("--sonar", default="ranger:0", help="the sonar ring: ranger:N (Stage) or sonar:N (p2os)")
    parser.add_argument("--seed", type=int, default=None, help="seed for the random turns (repeatable walks)")
    parser.add_argument("--rounds", type=int, default=0, help="stop after this many rounds of data (0: run until stopped)")
    args = parser.parse_args(argv)

    try:
        with Client(args.host, args.port) as client:
            robot = client.position2d(args.position)
            sonar: Ranger | Sonar = client.sonar(args.sonar) if args.sonar.startswith("sonar") else client.ranger(args.sonar)
            sonar.get_geometry()
            robot.enable_motors(True)
            stroller = Stroller(random.Random(args.seed))
            print(f"sunday stroll: {sonar.address} ({sonar.driver}), stopping at {MIN_CLEARANCE:~P}", flush=True)
            rounds = 0
            try:
                while args.rounds == 0 or rounds < args.rounds:
                    client.read()
                    rounds += 1
                    readings = sonar_readings(sonar)
                    if not readings:
                        continue
                    speed, turn = stroller.step(readings, time.monotonic())
                    robot.set_speed(speed, turn)
            finally:
                robot.stop()
    except KeyboardInterrupt:
        return 0
    except PlayerError as e:
        print(f"sunday stroll: {e}")
        return 1
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
