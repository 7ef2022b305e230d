#!/usr/bin/env python3
"""Test helper: drives position2d:0 at a fixed speed and turn rate for some rounds, then stops.

    drive.py --port PORT [--speed M_PER_S] [--turn RAD_PER_S] [--rounds N] [--distance M]

With --distance it stops as soon as the robot's pose is that far from where it started (or after
--rounds rounds, whichever is first; the exit code is then 3).

Uses Stagecraft's pure-Python client (stagecraft_player); prints one line per 10 rounds.
"""
import argparse
import math

from stagecraft_player import Client


def main() -> int:
    p = argparse.ArgumentParser()
    p.add_argument("--host", default="127.0.0.1")
    p.add_argument("--port", type=int, required=True)
    p.add_argument("--speed", type=float, default=0.3)
    p.add_argument("--turn", type=float, default=0.2)
    p.add_argument("--rounds", type=int, default=100)
    p.add_argument("--distance", type=float, default=0.0)
    a = p.parse_args()
    with Client(a.host, a.port) as client:
        robot = client.position2d("position2d:0")
        robot.enable_motors(True)
        start = None
        reached = a.distance <= 0
        try:
            for i in range(a.rounds):
                client.read()
                if start is None:
                    start = (robot.px, robot.py)
                if a.distance > 0 and math.hypot(robot.px - start[0], robot.py - start[1]) >= a.distance:
                    reached = True
                    break
                robot.set_speed(a.speed, a.turn)
                if i % 10 == 0:
                    print(f"drive: port {a.port} round {i} pose {robot.px:.3f} {robot.py:.3f} {robot.pa:.3f}", flush=True)
        finally:
            robot.stop()
    print(f"drive: port {a.port} done" + ("" if reached else f", but not {a.distance} m away after {a.rounds} rounds"),
          flush=True)
    return 0 if reached else 3


if __name__ == "__main__":
    raise SystemExit(main())
