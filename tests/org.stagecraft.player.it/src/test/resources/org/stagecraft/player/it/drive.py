#!/usr/bin/env python3
"""Test helper: drives position2d:0 at a fixed speed and turn rate for some rounds, then stops.

    drive.py --port PORT [--speed M_PER_S] [--turn RAD_PER_S] [--rounds N]

Uses Stagecraft's pure-Python client (stagecraft_player); prints one line per 10 rounds.
"""
import argparse

from stagecraft_player import Client


def main() -> int:
    p = argparse.ArgumentParser()
    p.add_argument("--host", default="127.0.0.1")
    p.add_argument("--port", type=int, required=True)
    p.add_argument("--speed", type=float, default=0.3)
    p.add_argument("--turn", type=float, default=0.2)
    p.add_argument("--rounds", type=int, default=100)
    a = p.parse_args()
    with Client(a.host, a.port) as client:
        robot = client.position2d("position2d:0")
        robot.enable_motors(True)
        try:
            for i in range(a.rounds):
                client.read()
                robot.set_speed(a.speed, a.turn)
                if i % 10 == 0:
                    print(f"drive: port {a.port} round {i} pose {robot.px:.3f} {robot.py:.3f} {robot.pa:.3f}", flush=True)
        finally:
            robot.stop()
    print(f"drive: port {a.port} done", flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
