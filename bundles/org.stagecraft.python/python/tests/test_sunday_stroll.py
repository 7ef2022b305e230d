"""Sunday Stroll's control logic on recorded sonar rings, the Pioneer's sonar numbering, and the
program against the test server."""

from __future__ import annotations

import math
import random
import re

import pytest

import sunday_stroll as stroll
from conftest import recording
from player_trace import traces_dir
from stagecraft_player.interfaces.ranger import RangerGeometry, RangerRanges
from stagecraft_player.xdr import XdrReader


def recorded_geometry() -> RangerGeometry:
    rec = recording("pioneer-laser-sonar.gt")
    reply = next(a[-1] for k, answers in rec.replies.items() if k[:3] == (62, 0, 1) for a in answers)
    return RangerGeometry.read(XdrReader(reply.body))


def recorded_rings() -> list[tuple[float, ...]]:
    rec = recording("pioneer-laser-sonar.gt")
    return [RangerRanges.read(XdrReader(m.body)).ranges for r in rec.rounds for m in r.data
            if (m.header.interf, m.header.index, m.header.subtype) == (62, 0, 1)]


def readings(ring: tuple[float, ...]) -> list[stroll.Reading]:
    geom = recorded_geometry()
    return [stroll.Reading(geom.bearing(i), r) for i, r in enumerate(ring)]


def test_the_sonar_numbering_is_the_world_files() -> None:
    """Sonar i of the recorded geometry is the i-th p2dxsonar of pioneer.inc: 0 left, 7 right."""
    text = (traces_dir() / "worlds" / "pioneer.inc").read_text()
    block = text[text.index("define p2dx_sonar ranger"):text.index("define p2dx_sonar_front")]
    poses = [tuple(float(v) for v in p.split()) for p in re.findall(r"p2dxsonar\(\s*pose \[([^\]]+)\]", block)]
    geom = recorded_geometry()
    assert len(poses) == len(geom.element_poses) == 16
    for (x, y, _, yaw), pose in zip(poses, geom.element_poses):
        assert (pose.px, pose.py) == pytest.approx((x, y)) and math.degrees(pose.pyaw) == pytest.approx(yaw, abs=1e-3)
    half = math.radians(60)
    assert [i for i, p in enumerate(geom.element_poses) if abs(p.pyaw) <= half] == [1, 2, 3, 4, 5, 6]


def test_a_close_obstacle_stops_the_robot_and_turns_it_toward_the_free_side() -> None:
    rings = recorded_rings()
    ring = next(r for r in rings if min(r[1:7]) < 0.6)
    # on a Pioneer sonars 0-3 look left of ahead, 4-7 right: the free side by the world's numbering
    left, right = sum(ring[0:4]) / 4, sum(ring[4:8]) / 4
    s = stroll.Stroller(random.Random(1))
    speed, turn = s.step(readings(ring), now=0.0)
    assert s.mode is stroll.Mode.AVOIDING
    assert speed == 0.0, "no turning while moving into a wall"
    assert turn != 0 and (turn > 0) == (left > right)


def test_blocked_on_the_left_turns_right_and_blocked_on_the_right_turns_left() -> None:
    base = list(recorded_rings()[0])
    open_ring = [5.0] * 16
    for blocked, side in (((1, 2, 3), -1), ((4, 5, 6), 1)):
        ring = list(open_ring)
        for i in blocked:
            ring[i] = 0.3
        speed, turn = stroll.Stroller(random.Random(2)).step(readings(tuple(ring)), 0.0)
        assert speed == 0.0 and math.copysign(1, turn) == side
    assert len(base) == 16


def test_it_keeps_turning_on_the_spot_until_the_way_is_clear_then_strolls_on() -> None:
    s = stroll.Stroller(random.Random(3))
    blocked = [5.0] * 16
    blocked[3] = blocked[4] = 0.4
    blocked[0] = 0.5  # the left is tighter: turn right
    first = s.step(readings(tuple(blocked)), 0.0)
    nearly = list(blocked)
    nearly[3] = nearly[4] = 0.7  # past the stop distance but within the margin: still turning
    assert s.step(readings(tuple(nearly)), 0.1) == first
    assert first[0] == 0.0 and first[1] < 0
    speed, _ = s.step(readings((5.0,) * 16), 0.2)
    assert s.mode is stroll.Mode.STROLLING and speed == pytest.approx(0.3)


def test_random_turns_are_sharp_both_ways_and_change_over_time() -> None:
    s = stroll.Stroller(random.Random(4))
    clear = readings((5.0,) * 16)
    turns = [s.step(clear, t * 0.1)[1] for t in range(600)]
    assert min(abs(t) for t in turns) >= math.radians(15)
    assert max(turns) > math.radians(40) and min(turns) < -math.radians(40)
    assert len(set(turns)) >= 10  # a new random turn every one to three seconds


def test_the_program_strolls_against_the_test_player(serve) -> None:
    server = serve("pioneer-laser-sonar.gt", rounds=30)
    assert stroll.main(["--host", "127.0.0.1", "--port", str(server.port), "--rounds", "30", "--seed", "5"]) == 0
    assert server.wait_until_served(10), "the server saw the program close its connection"
    assert server.unanswered == []
    commands = [XdrReader(m.body) for m in server.received if (m.header.interf, m.header.type) == (4, 2)]
    assert len(commands) == 31
    for c in commands[:-1]:
        vx, _, va = c.float64(), c.float64(), c.float64()
        assert (vx == 0.0) or (vx == pytest.approx(0.3)), "stopped, or strolling at cruise speed"
        assert va != 0.0, "always turning: at random while strolling, on the spot while avoiding"
