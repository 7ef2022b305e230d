"""Units: quantities convert to the SI values Player takes, wrong dimensions are errors."""

from __future__ import annotations

import math
import struct

import pytest

from stagecraft_player import Client, UnitError, cm, deg, m, ms, rad, s, to_si
from stagecraft_player.wire import MsgType


def test_quantities_convert_to_si() -> None:
    assert to_si(30 * cm, "length") == pytest.approx(0.3)
    assert to_si(90 * deg, "angle") == pytest.approx(math.pi / 2)
    assert to_si(20 * deg / s, "angular_speed") == pytest.approx(math.radians(20))
    assert to_si(300 * mm_per_s(), "speed") == pytest.approx(0.3)
    assert to_si(500 * ms, "time") == pytest.approx(0.5)
    assert to_si(0.25, "speed") == 0.25 and to_si(2, "angle") == 2.0


def mm_per_s():
    from stagecraft_player import mm
    return mm / s


@pytest.mark.parametrize("value,kind,message", [
    (0.3 * m / s, "angular_speed", "expected an angular speed (e.g. 20 * deg/s), got 0.3 m/s"),
    (3 * m, "speed", "expected a speed"),
    (1 * s, "angle", "expected an angle"),
    (True, "speed", "boolean"),
    ("fast", "speed", "got str 'fast'"),
    (float("nan"), "length", "NaN"),
])
def test_a_wrong_quantity_is_a_clear_error(value, kind, message) -> None:
    with pytest.raises(UnitError, match=message.replace("(", r"\(").replace(")", r"\)").replace("*", r"\*")):
        to_si(value, kind, "xspeed")


def test_set_speed_sends_si_values_and_refuses_wrong_units(serve) -> None:
    server = serve("python-client.sentinel", rounds=0)
    with Client("127.0.0.1", server.port) as client:
        robot = client.position2d(0)
        robot.set_speed(0.3 * m / s, 20 * deg / s)
        robot.set_speed(0.1, 0.5 * rad / s)
        with pytest.raises(UnitError, match="yawspeed|va"):
            robot.set_speed(0.3 * m / s, 0.3 * m / s)
        # a request after the commands: once it is answered, the server has received them all
        client.request(1, 0, 5, struct.pack(">I", 2))
    commands = [m.body for m in server.received if m.header.type == MsgType.CMD]
    assert len(commands) == 2, "the command with a unit error was never sent"
    vx, vy, va, state = struct.unpack(">dddI", commands[0])
    assert (vx, vy, state) == (0.3, 0.0, 1) and va == pytest.approx(math.radians(20))
    assert struct.unpack(">dddI", commands[1])[::2] == (0.1, 0.5)


def test_data_fields_are_si_and_convertible(serve) -> None:
    server = serve("python-client.sentinel", rounds=2)
    with Client("127.0.0.1", server.port) as client:
        laser = client.laser(0)
        client.read()
    scan = laser.scan
    assert scan is not None
    assert scan.q.max_range.to("cm").magnitude == pytest.approx(scan.max_range * 100)
    assert scan.q.min_angle.to("deg").magnitude == pytest.approx(-90, abs=1e-4)
    assert [r.to("m").magnitude for r in scan.q.ranges] == list(scan.ranges)
    with pytest.raises(AttributeError, match="has no unit"):
        scan.q.id  # noqa: B018
