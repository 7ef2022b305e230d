"""Requests, replies and Player's quirks, against the recorded requests session (libplayerc's
``reqclient``): the values the client decodes equal what libplayerc decoded (the steps file), and
the bytes it sends are the bytes libplayerc sent."""

from __future__ import annotations

import json

import pytest


from player_trace import traces_dir
from stagecraft_player import Client, DataMode, DeviceRefused, RequestRefused
from stagecraft_player.wire import MsgType


def steps() -> dict[str, dict]:
    out = {}
    with open(traces_dir() / "requests.reqclient.steps.jsonl", encoding="utf-8") as f:
        next(f)
        for line in f:
            try:
                s = json.loads(line)
            except json.JSONDecodeError:
                continue  # two property steps quote the key without escaping it; their values are not used
            out[s["step"].split(" (")[0]] = s
    return out


@pytest.fixture
def client(serve):
    server = serve("requests.reqclient")
    with Client("127.0.0.1", server.port, timeout=5) as c:
        c.server = server  # type: ignore[attr-defined]
        yield c


def test_device_list_and_drivers_equal_libplayerc(client) -> None:
    devices = client.devices()
    expected = steps()["get_devlist"]["devices"]
    assert [[d.address.host, d.address.robot, d.address.interf, d.address.index, d.driver] for d in devices] == expected


def test_subscribing_a_missing_device_is_refused_naming_it_and_what_the_server_has(client) -> None:
    client.position2d(0)
    with pytest.raises(DeviceRefused) as e:
        client.sonar(0)
    message = str(e.value)
    assert "refused to subscribe to sonar:0" in message and f"127.0.0.1:{client.port}" in message
    assert "position2d:0 (stage)" in message and "laser:0 (rangertolaser)" in message
    assert "Stage provides sonar rings as ranger devices" in message
    # Player's NACK to a subscription carries a device request with access ERROR (3)
    assert len(e.value.body) == 28 and e.value.body[16:20] == b"\0\0\0\x03"


def test_position2d_requests_and_refusals(client) -> None:
    s = steps()
    robot = client.position2d(0)
    geom = robot.get_geometry()
    assert [geom.pose.px, geom.pose.py, geom.pose.pyaw] == s["position2d GET_GEOM"]["pose"]
    assert [geom.size.sl, geom.size.sw] == s["position2d GET_GEOM"]["size"]
    robot.enable_motors(True)
    robot.set_odometry(1, 2, 0.5)
    robot.reset_odometry()
    with pytest.raises(RequestRefused, match=r"refused position2d:0 REQ 3 \(RESP_NACK"):
        robot.set_velocity_mode(1)
    robot.set_position_mode(False)
    with pytest.raises(RequestRefused):
        robot.set_speed_pid(1.0, 0.1, 0.01)
    with pytest.raises(RequestRefused):
        robot.get_int_property("no_such_property")


def test_laser_config_and_the_double_nack_of_rangertolaser(client) -> None:
    s = steps()
    laser = client.laser(0)
    geom = laser.get_geometry()
    assert [geom.pose.px, geom.pose.py, geom.pose.pyaw] == s["laser GET_GEOM"]["pose"]
    config = laser.get_config()
    step = s["laser GET_CONFIG"]
    assert (config.min_angle, config.max_angle) == pytest.approx((step["min_angle"], step["max_angle"]), rel=1e-8)
    assert config.intensity == step["intensity"] and config.scanning_frequency == step["scanning_frequency"]
    with pytest.raises(RequestRefused):
        laser.set_config(min_angle=config.min_angle, max_angle=config.max_angle, resolution=config.resolution,
                         max_range=config.max_range, range_res=config.range_res, intensity=True,
                         scanning_frequency=config.scanning_frequency)
    # the second NACK of the same SET_CONFIG arrives later: it must not answer the next request
    with pytest.raises(RequestRefused, match="laser:0 REQ 5"):
        laser.get_id()
    assert [(h.interf, h.index, h.type, h.subtype) for h in client.stray_replies] == \
        [tuple(x) for x in s["drain"]["stray_replies"]]
    assert client.stray_replies[0].type == MsgType.RESP_NACK
    with pytest.raises(RequestRefused):
        laser.get_double_property("no_such_property")


def test_ranger_geometry_and_config(client) -> None:
    s = steps()
    sonar = client.ranger(0)
    assert len(sonar.get_geometry().element_poses) == s["ranger:0 GET_GEOM"]["element_count"]
    config = sonar.get_config()
    step = s["ranger:0 GET_CONFIG"]
    assert [config.min_angle, config.max_angle, config.angular_res, config.min_range, config.max_range,
            config.range_res, config.frequency] == [step[k] for k in (
                "min_angle", "max_angle", "angular_res", "min_range", "max_range", "range_res", "frequency")]
    with pytest.raises(RequestRefused):
        sonar.set_config(**{k: getattr(config, k) for k in (
            "min_angle", "max_angle", "angular_res", "min_range", "max_range", "range_res", "frequency")})
    laser_ranger = client.ranger(1)
    with pytest.raises(RequestRefused):
        laser_ranger.set_power(True)
    with pytest.raises(RequestRefused):
        laser_ranger.set_intensity_data(True)


def test_simulation_poses_and_properties(client) -> None:
    s = steps()
    sim = client.simulation(0)
    pose = sim.get_pose2d("r0")
    assert [pose.px, pose.py, pose.pa] == s["simulation GET_POSE2D r0"]["pose"]
    sim.set_pose2d("r0", -5.5, -6.5, 1.5707963267948966)
    assert list(sim.get_pose2d("r0").__dict__.values()) == s["simulation GET_POSE2D r0 again"]["pose"]
    with pytest.raises(RequestRefused):
        sim.get_pose2d("no_such_model")
    assert list(sim.get_color("r0")) == s["simulation GET_PROPERTY r0 color"]["rgba"]
    sim.set_color("r0", 0, 1, 0, 1)
    with pytest.raises(RequestRefused):
        sim.set_property("r0", "mass", (7).to_bytes(4, "little"))


def test_push_and_pull_switching_and_a_replace_rule(client) -> None:
    client.position2d(0)
    client.set_datamode(DataMode.PUSH)
    assert client.datamode == DataMode.PUSH
    client.add_replace_rule(interf=-1, index=-1, subtype=-1, replace=True)
    client.set_datamode(DataMode.PULL)
    assert client.datamode == DataMode.PULL
    assert client.server.unanswered == []  # type: ignore[attr-defined]


def _sent(messages, interf: int, msgtype: int, subtype: int) -> list[bytes]:
    return [m.body for m in messages if (m.header.interf, m.header.type, m.header.subtype) == (interf, msgtype, subtype)]


def test_the_client_sends_the_bytes_libplayerc_sent(client) -> None:
    """Same requests, same payloads (timestamps aside): proof of the layouts against the real client."""
    robot = client.position2d(0)
    laser = client.laser(0)
    sim = client.simulation(0)
    robot.enable_motors(True)
    robot.set_odometry(1, 2, 0.5)
    robot.set_position_mode(False)
    robot.set_velocity(0.3, 0, 0.2)
    robot.set_car(0.2, 0.1)
    robot.go_to(-5, -6, 0)
    laser.get_config()
    sim.set_pose2d("r0", -5.5, -6.5, 1.5707963267948966)
    sim.set_color("r0", 0, 1, 0, 1)
    robot.unsubscribe()
    ours = client.server.received  # type: ignore[attr-defined]
    _, events = __import__("player_trace").read_events(traces_dir() / "requests.reqclient.trace.jsonl")
    theirs = [e.message for e in events if e.dir == "c2s"]
    for interf, msgtype, subtype in [(1, 3, 5), (1, 3, 3), (4, 3, 2), (4, 3, 5), (4, 3, 4), (4, 2, 1), (4, 2, 3),
                                     (4, 2, 2), (6, 3, 3), (31, 3, 2)]:
        mine = _sent(ours, interf, msgtype, subtype)
        assert mine, (interf, msgtype, subtype)
        for body in mine:
            assert body in _sent(theirs, interf, msgtype, subtype), (interf, msgtype, subtype, body.hex())
    assert _sent(ours, 31, 3, 6)[0] == _sent(theirs, 31, 3, 6)[0]
    headers = {(m.header.interf, m.header.robot) for m in ours}
    assert (1, 0) in headers and (4, client.port) in headers  # robot: 0 for the server, the port for devices

