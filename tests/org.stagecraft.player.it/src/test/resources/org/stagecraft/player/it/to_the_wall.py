#!/usr/bin/env python3
"""Test helper: drives position2d:0 straight ahead, reading the laser each round, until the nearest laser
return is closer than --stop metres (or --rounds rounds pass), then stops the robot.

    to_the_wall.py --port PORT [--speed M_PER_S] [--stop M] [--rounds N]

Prints one line per laser scan it read: "scan SEQ TIMESTAMP MIN", so a test can compare what the
program read with the spy's log. Uses Stagecraft's pure-Python client (stagecraft_player).
"""
import argparse

from stagecraft_player import Client


def main() -> int:
    p = argparse.ArgumentParser()
    p.add_argument("--host", default="127.0.0.1")
    p.add_argument("--port", type=int, required=True)
    p.add_argument("--speed", type=float, default=0.4)
    p.add_argument("--stop", type=float, default=0.5)
    p.add_argument("--rounds", type=int, default=600)
    a = p.parse_args()
    with Client(a.host, a.port) as client:
        robot = client.position2d("position2d:0")
        laser = client.laser("laser:0")
        robot.enable_motors(True)
        try:
            for _ in range(a.rounds):
                for m in client.read():
                    if m.header.interf == 6 and m.header.type == 1 and hasattr(m.record, "ranges"):
                        nearest = min(m.record.ranges)
                        print(f"scan {m.header.seq} {m.header.timestamp!r} {nearest!r}", flush=True)
                        if nearest < a.stop:
                            print("stopped", flush=True)
                            return 0
                robot.set_speed(a.speed, 0.0)
        finally:
            robot.stop()
    print(f"never nearer than {a.stop} m in {a.rounds} rounds", flush=True)
    return 3


if __name__ == "__main__":
    raise SystemExit(main())
