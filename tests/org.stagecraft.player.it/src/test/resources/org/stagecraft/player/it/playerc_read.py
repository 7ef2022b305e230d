#!/usr/bin/env python3
"""Test helper: reads laser:0, ranger:0 (sonar) and position2d:0 with libplayerc's own Python bindings
(`import playerc`, built with Player) and prints what libplayerc decoded as one JSON line.

    playerc_read.py HOST PORT
"""
import json
import sys

import playerc


def main() -> int:
    host, port = sys.argv[1], int(sys.argv[2])
    c = playerc.playerc_client(None, host, port)
    if c.connect() != 0:
        print("connect failed: " + playerc.playerc_error_str(), file=sys.stderr)
        return 2
    laser = playerc.playerc_laser(c, 0)
    sonar = playerc.playerc_ranger(c, 0)
    pos = playerc.playerc_position2d(c, 0)
    for dev in (laser, sonar, pos):
        if dev.subscribe(playerc.PLAYERC_OPEN_MODE) != 0:
            print("subscribe failed: " + playerc.playerc_error_str(), file=sys.stderr)
            return 3
    # a few rounds so that every device has data
    for _ in range(5):
        if c.read() is None:
            print("read failed: " + playerc.playerc_error_str(), file=sys.stderr)
            return 4
    out = {
        "laser_count": laser.scan_count,
        "laser_res": laser.scan_res,
        "laser_max_range": laser.max_range,
        "laser_ranges": [laser.ranges[i] for i in range(laser.scan_count)],
        "sonar_count": sonar.ranges_count,
        "sonar_ranges": [sonar.ranges[i] for i in range(sonar.ranges_count)],
        "pose": [pos.px, pos.py, pos.pa],
    }
    print(json.dumps(out), flush=True)
    for dev in (laser, sonar, pos):
        dev.unsubscribe()
    c.disconnect()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
