"""The client against recorded Player/Stage sessions: every value it decodes equals what
libplayerc decoded from the same bytes (the ground-truth files), in the same order."""

from __future__ import annotations

import struct

import pytest

from conftest import groundtruth
from stagecraft_player import Client, DataMessage, DataMode, LaserScan, Position2dData
from stagecraft_player.interfaces.ranger import RangerIntensities, RangerRanges


def f32(x: float) -> float:
    """``x`` rounded to a float (libplayerc's laser fields are floats, printed with 9 digits)."""
    return struct.unpack("f", struct.pack("f", x))[0]


def check_against_groundtruth(msg: DataMessage, gt: dict) -> None:
    h = msg.header
    assert (h.host, h.robot, h.interf, h.index, h.type, h.subtype, h.seq) == \
        (gt["host"], gt["robot"], gt["interf"], gt["index"], gt["type"], gt["subtype"], gt["seq"])
    assert h.timestamp == gt["timestamp"]
    d = gt["decoded"]
    rec = msg.record
    if gt["iface"] == "position2d":
        assert isinstance(rec, Position2dData)
        assert (rec.px, rec.py, rec.pa, rec.vx, rec.vy, rec.va, rec.stall) == \
            (d["px"], d["py"], d["pa"], d["vx"], d["vy"], d["va"], d["stall"])
    elif gt["iface"] == "laser":
        assert isinstance(rec, LaserScan)
        assert len(rec.ranges) == d["scan_count"]
        assert rec.min_angle == f32(d["scan_start"]) and rec.resolution == f32(d["scan_res"])
        assert rec.max_range == d["max_range"] and rec.id == d["scan_id"]
        # libplayerc's intensity_on follows the laser's config, not the scan: not compared
        assert len(rec.intensity) in (0, len(rec.ranges))
        assert list(rec.ranges[:3]) == d["first3"]
        assert min(rec.ranges) == d["min_range"]
    elif h.subtype == 1:
        assert isinstance(rec, RangerRanges)
        assert len(rec.ranges) == d["ranges_count"] == d["element_count"] or d["element_count"] == 1
        assert list(rec.ranges[:3]) == d["first3"]
        assert min(rec.ranges) == d["min_range"]
        if "ranges" in d:
            assert list(rec.ranges) == d["ranges"]
    else:
        assert isinstance(rec, RangerIntensities)
        assert len(rec.intensities) == d["intensities_count"]
        assert list(rec.intensities[:3]) == d["first3_intensities"]


def subscribe_like_the_groundtruth_client(client: Client, events: list[dict]) -> dict[str, object]:
    """Subscribes and asks geometry in the order the ground-truth client did; checks what it got."""
    proxies: dict[str, object] = {}
    for e in events:
        if e["event"] == "subscribe":
            proxy = {"position2d": client.position2d, "laser": client.laser,
                     "ranger": client.ranger}[e["iface"]](e["index"])
            assert proxy.driver == e["driver"]
            proxies[f"{e['iface']}:{e['index']}"] = proxy
        elif e["event"] == "get_geom":
            geom = proxies[f"{e['iface']}:{e['index']}"].get_geometry()  # type: ignore[attr-defined]
            if e["iface"] == "ranger":
                assert [geom.pose.px, geom.pose.py, geom.pose.pz, geom.pose.proll, geom.pose.ppitch,
                        geom.pose.pyaw] == e["device_pose"]
                assert [geom.size.sw, geom.size.sl, geom.size.sh] == e["device_size"]
                assert len(geom.element_poses) == e["element_count"]
                for pose, (x, y, yaw) in zip(geom.element_poses, e["element_poses_xy_yaw"]):
                    # the ground truth prints these with 6 significant digits
                    assert pose.px == pytest.approx(x, abs=5e-6) and pose.py == pytest.approx(y, abs=5e-6)
                    assert pose.pyaw == pytest.approx(yaw, abs=5e-6)
            else:
                assert [geom.pose.px, geom.pose.py, geom.pose.pyaw] == e["pose"]
                assert [geom.size.sl, geom.size.sw] == e["size"]
        elif e["event"] == "motor_power_on":
            proxies["position2d:0"].enable_motors(True)  # type: ignore[attr-defined]
    return proxies


def test_pull_mode_decodes_every_message_as_libplayerc_did(serve) -> None:
    events, expected = groundtruth("pioneer-laser-sonar.gt.groundtruth.jsonl")
    server = serve("pioneer-laser-sonar.gt")
    got: list[DataMessage] = []
    with Client("127.0.0.1", server.port, timeout=10) as client:
        assert client.banner == "Player v.3.1.1-dev" and client.server_version == "3.1.1-dev"
        assert client.datamode == DataMode.PULL
        proxies = subscribe_like_the_groundtruth_client(client, events)
        rounds = next(e["read_rounds"] for e in events if e["event"] == "done")
        for _ in range(min(rounds, len(server.recording.rounds))):
            got += client.read()
        assert client.stray_replies == []
        laser = proxies["laser:0"]
        assert laser.scan is not None and laser.fresh  # type: ignore[attr-defined]
    assert server.unanswered == []
    assert len(got) == len(expected) == 2085
    for msg, gt in zip(got, expected):
        check_against_groundtruth(msg, gt)


def test_push_mode_decodes_the_stream_as_libplayerc_did(serve) -> None:
    events, expected = groundtruth("rates.headless-push.groundtruth.jsonl")
    server = serve("rates.headless-push")
    got: list[DataMessage] = []
    with Client("127.0.0.1", server.port, timeout=10) as client:
        client.set_datamode(DataMode.PUSH)
        subscribe_like_the_groundtruth_client(client, events)
        while len(got) < len(expected):
            batch = client.read()
            assert batch, "a PUSH read returns at least one message"
            got += batch
    assert server.unanswered == []
    for msg, gt in zip(got, expected):
        check_against_groundtruth(msg, gt)


def test_proxies_keep_the_latest_values_under_player_names(serve) -> None:
    _, expected = groundtruth("pioneer-laser-sonar.gt.groundtruth.jsonl")
    server = serve("pioneer-laser-sonar.gt", rounds=5)
    with Client("127.0.0.1", server.port) as client:
        robot, sonar = client.position2d(0), client.ranger(0)
        got = []
        for _ in range(5):
            got += client.read()
    last_pose = [m for m in got if m.header.interf == 4][-1].record
    assert (robot.px, robot.py, robot.pa, robot.vx, robot.vy, robot.va, robot.stall) == \
        (last_pose.px, last_pose.py, last_pose.pa, last_pose.vx, last_pose.vy, last_pose.va, last_pose.stall)
    assert robot.data is not None
    assert robot.data.q.pa.to("deg").magnitude == pytest.approx(last_pose.pa * 180 / 3.141592653589793)
    last_sonar = [m for m in got if (m.header.interf, m.header.index, m.header.subtype) == (62, 0, 1)][-1]
    assert sonar.ranges == last_sonar.record.ranges and len(sonar.ranges) == 16
