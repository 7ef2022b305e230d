#!/usr/bin/env python3
"""Laser Sentinel: a Pioneer with a 180-degree laser turns, smoothly, to face the nearest object.

Only objects nearer than ``--max-range`` are "interesting"; with none in sight the robot stands
still. It never drives, only turns on the spot, so it is safe to leave running.

    python3 laser_sentinel.py [--host localhost] [--port 6665] [--max-range 3]

Runs unchanged against a real Player/Stage (tests/traces/worlds/pioneer-laser-sonar.cfg) and
inside a Stagecraft Robot Session (the session puts stagecraft_player on PYTHONPATH).
"""

from __future__ import annotations

import argparse
import math
import sys
from dataclasses import dataclass

from stagecraft_player import Client, LaserScan, PlayerError, RequestRefused, deg, m, s, to_si

#: Beyond this an object is not interesting (also: a beam at the laser's maximum hit nothing).
MAX_INTERESTING_RANGE = 3.0 * m
#: Turn rate per radian of bearing: smooth, fast when far off, slow near the target.
GAIN = 1.2 / s
MAX_TURN_RATE = 60 * deg / s
#: Close enough to facing it: stop turning (no hunting round the target).
DEADBAND = 2 * deg


@dataclass(frozen=True)
class Target:
    bearing: float  # [rad] on the robot: 0 ahead, positive to the left
    range: float  # [m]


def nearest_object(scan: LaserScan, max_range: float, mount_yaw: float = 0.0) -> Target | None:
    """The nearest return nearer than ``max_range`` [m] (and than the laser's own maximum).

    Beam i looks at ``scan.angle(i)`` — the first beam is on the robot's right — so the bearing
    comes from the scan's own angles, never from the index alone.
    """
    limit = min(max_range, scan.max_range)
    best: Target | None = None
    for bearing, r in scan.beams():
        if 0.0 < r < limit and (best is None or r < best.range):
            best = Target(bearing + mount_yaw, r)
    return best


def turn_rate(target: Target | None) -> float:
    """The turn rate [rad/s] to face ``target``: proportional to its bearing, limited, zero when faced."""
    if target is None:
        return 0.0
    bearing = math.atan2(math.sin(target.bearing), math.cos(target.bearing))
    if abs(bearing) < to_si(DEADBAND, "angle"):
        return 0.0
    limit = to_si(MAX_TURN_RATE, "angular_speed")
    return max(-limit, min(limit, to_si(GAIN, "frequency") * bearing))


def main(argv: list[str] | None = None) -> int:
    # the module's docstring read through sys.modules: PyDev's code analysis does not know a module's
    # own __doc__ and marks the bare name as an undefined variable
    parser = argparse.ArgumentParser(description=str(sys.modules[__name__].__doc__).splitlines()[0])
    parser.add_argument("--host", default="localhost")
    parser.add_argument("--port", type=int, default=6665)
    parser.add_argument("--position", default="position2d:0", help="the robot base (default position2d:0)")
    parser.add_argument("--laser", default="laser:0", help="the laser (default laser:0)")
    parser.add_argument("--max-range", type=float, default=MAX_INTERESTING_RANGE.m_as(m),
                        help="objects farther than this [m] are ignored (default %(default)s)")
    parser.add_argument("--rounds", type=int, default=0, help="stop after this many rounds of data (0: run until stopped)")
    args = parser.parse_args(argv)

    try:
        with Client(args.host, args.port) as client:
            robot = client.position2d(args.position)
            laser = client.laser(args.laser)
            try:
                mount_yaw = laser.get_geometry().pose.pyaw
            except RequestRefused:
                mount_yaw = 0.0  # a driver without geometry: assume the laser looks ahead
            robot.enable_motors(True)
            print(f"laser sentinel: watching {laser.address} ({laser.driver}) up to {args.max_range} m", flush=True)
            rounds = 0
            try:
                while args.rounds == 0 or rounds < args.rounds:
                    client.read()
                    rounds += 1
                    if laser.scan is None:
                        continue
                    robot.set_speed(0.0, turn_rate(nearest_object(laser.scan, args.max_range, mount_yaw)))
            finally:
                robot.stop()
    except KeyboardInterrupt:
        return 0
    except PlayerError as e:
        print(f"laser sentinel: {e}")
        return 1
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
