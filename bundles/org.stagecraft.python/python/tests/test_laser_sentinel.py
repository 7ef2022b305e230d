"""Laser Sentinel's control logic on recorded laser scans, and the program against the test server."""

from __future__ import annotations

import dataclasses
import math

import pytest

import laser_sentinel as sentinel
from conftest import recording
from stagecraft_player import LaserScan
from stagecraft_player.xdr import XdrReader


def recorded_scans(name: str = "pioneer-laser-sonar.gt") -> list[LaserScan]:
    rec = recording(name)
    return [LaserScan.read(XdrReader(m.body)) for r in rec.rounds for m in r.data
            if (m.header.interf, m.header.subtype) == (6, 1)]


def test_the_recorded_laser_scans_counter_clockwise_from_the_right() -> None:
    scan = recorded_scans()[0]
    assert len(scan.ranges) == 180
    assert math.degrees(scan.angle(0)) == pytest.approx(-90, abs=1e-4)  # first beam: the robot's right
    assert math.degrees(scan.angle(179)) == pytest.approx(89, abs=1e-3)
    assert scan.angle(90) == pytest.approx(0, abs=1e-6)


def test_nearest_object_on_the_right_turns_the_robot_clockwise() -> None:
    scans = recorded_scans()
    scan = next(s for s in scans if s.ranges.index(min(s.ranges)) < 60 and min(s.ranges) < 3)
    target = sentinel.nearest_object(scan, 3.0)
    assert target is not None and target.range == min(scan.ranges)
    assert target.bearing < 0
    assert sentinel.turn_rate(target) < 0


def test_nearest_object_on_the_left_turns_the_robot_counter_clockwise() -> None:
    scans = recorded_scans()
    scan = next(s for s in scans if s.ranges.index(min(s.ranges)) > 120 and min(s.ranges) < 3)
    target = sentinel.nearest_object(scan, 3.0)
    assert target is not None and target.bearing > 0
    assert sentinel.turn_rate(target) > 0


def test_objects_beyond_the_interesting_range_are_ignored() -> None:
    scan = recorded_scans()[0]
    nearest = min(scan.ranges)
    assert sentinel.nearest_object(scan, nearest) is None  # strictly nearer than the limit only
    assert sentinel.turn_rate(sentinel.nearest_object(scan, nearest * 0.9)) == 0.0
    # a beam at the laser's maximum is no object, even with a generous limit
    empty = dataclasses.replace(scan, ranges=(scan.max_range,) * 180)
    assert sentinel.nearest_object(empty, 100.0) is None


def test_an_in_range_object_wins_over_a_nearer_one_that_is_not_in_the_scan() -> None:
    scan = recorded_scans()[0]
    ranges = [scan.max_range] * 180
    ranges[170] = 4.0  # left, but beyond 3 m
    ranges[20] = 2.5  # right, interesting
    target = sentinel.nearest_object(dataclasses.replace(scan, ranges=tuple(ranges)), 3.0)
    assert target is not None and target.bearing == pytest.approx(scan.angle(20))
    assert sentinel.turn_rate(target) < 0


def test_turning_is_smooth_limited_and_stops_when_facing() -> None:
    t = sentinel.Target
    assert sentinel.turn_rate(t(math.radians(10), 1)) == pytest.approx(1.2 * math.radians(10))
    assert sentinel.turn_rate(t(math.radians(-80), 1)) == pytest.approx(-math.radians(60))
    assert sentinel.turn_rate(t(math.radians(1), 1)) == 0.0
    small, large = sentinel.turn_rate(t(0.1, 1)), sentinel.turn_rate(t(0.3, 1))
    assert 0 < small < large


def test_the_program_faces_the_nearest_object_against_the_test_player(serve) -> None:
    server = serve("pioneer-laser-sonar.gt", rounds=20)
    assert sentinel.main(["--host", "127.0.0.1", "--port", str(server.port), "--rounds", "20"]) == 0
    assert server.wait_until_served(10), "the server saw the program close its connection"
    assert server.unanswered == []
    commands = [m for m in server.received if (m.header.interf, m.header.type, m.header.subtype) == (4, 2, 1)]
    assert len(commands) == 21  # one per round, and the stop at the end
    scans = [LaserScan.read(XdrReader(m.body)) for r in server.recording.rounds[:20] for m in r.data
             if m.header.interf == 6]
    first_turn = XdrReader(commands[0].body[16:24]).float64()
    # the recorded Pioneer starts with its nearest object on its right: it turns clockwise
    assert sentinel.nearest_object(scans[0], 3.0).bearing < 0 and first_turn < 0
    assert XdrReader(commands[-1].body).float64() == 0.0 and XdrReader(commands[-1].body[16:]).float64() == 0.0
