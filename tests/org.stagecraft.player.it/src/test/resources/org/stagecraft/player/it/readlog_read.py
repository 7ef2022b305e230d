#!/usr/bin/env python3
"""Test helper: asks a Player whose devices are served by the readlog driver for the geometry of
position2d:0, laser:0, ranger:0 and ranger:1 (GET_GEOM, which libplayerc's get_geom sends and which
returns 0 only on Player's ACK), then reads ROUNDS rounds of data, all with libplayerc's own Python
bindings (`import playerc`), and prints one JSON object.

    readlog_read.py HOST PORT ROUNDS
"""
import json
import sys

import playerc


def fail(code: int, what: str) -> int:
    print(what + ": " + playerc.playerc_error_str(), file=sys.stderr)
    return code


def main() -> int:
    host, port, rounds = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    c = playerc.playerc_client(None, host, port)
    if c.connect() != 0:
        return fail(2, "connect failed")
    pos = playerc.playerc_position2d(c, 0)
    laser = playerc.playerc_laser(c, 0)
    sonar = playerc.playerc_ranger(c, 0)
    ranger1 = playerc.playerc_ranger(c, 1)
    for name, dev in (("position2d:0", pos), ("laser:0", laser), ("ranger:0", sonar), ("ranger:1", ranger1)):
        if dev.subscribe(playerc.PLAYERC_OPEN_MODE) != 0:
            return fail(3, "subscribe to " + name + " failed")
    out = {"geom": {}}
    out["geom"]["position2d:0"] = {"ack": pos.get_geom() == 0, "pose": list(pos.pose), "size": list(pos.size)}
    out["geom"]["laser:0"] = {"ack": laser.get_geom() == 0, "pose": list(laser.pose), "size": list(laser.size)}
    for name, r in (("ranger:0", sonar), ("ranger:1", ranger1)):
        ack = r.get_geom() == 0
        dp, ds = r.device_pose, r.device_size
        out["geom"][name] = {"ack": ack, "element_count": r.element_count,
                             "device_pose": [dp.px, dp.py, dp.pz, dp.proll, dp.ppitch, dp.pyaw],
                             "device_size": [ds.sw, ds.sl, ds.sh]}
    poses, scans, sonars = [], [], []
    for _ in range(rounds):
        if c.read() is None:
            return fail(4, "read failed")
        if pos.info.fresh:
            poses.append([pos.px, pos.py, pos.pa])
            pos.info.fresh = 0
        if laser.info.fresh:
            scans.append([laser.ranges[i] for i in range(laser.scan_count)])
            laser.info.fresh = 0
        if sonar.info.fresh:
            sonars.append([sonar.ranges[i] for i in range(sonar.ranges_count)])
            sonar.info.fresh = 0
    out["poses"], out["scans"], out["sonar"] = poses, scans, sonars
    print(json.dumps(out), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
