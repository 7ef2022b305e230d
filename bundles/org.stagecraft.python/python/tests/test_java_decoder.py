"""Cross-language check: every message this client sends, recorded by the test Player server in
the shared trace format, frames and decodes with Stagecraft's own Java decoder
(``./stagecraft decode``) without an error, with the fields the client meant and the payload sizes
the traces' README gives for Player's layouts.

``./stagecraft test`` builds the Java side before it runs pytest, so there this test always runs.
Run alone, it needs the command line tool built (``./mvnw install -DskipTests``); only
``STAGECRAFT_JAVA=0`` turns it into a skip.
"""

from __future__ import annotations

import json
import os
import subprocess
from pathlib import Path

import pytest

from stagecraft_player import Client, DataMode, PlayerError, deg, m, s
from stagecraft_player.interfaces.fiducial import Fiducial

REPO = Path(__file__).resolve().parents[4]


def stagecraft_decode(trace: Path) -> list[dict]:
    if os.environ.get("STAGECRAFT_JAVA") == "0":
        pytest.skip("STAGECRAFT_JAVA=0: the Java side is not available")
    # what ./stagecraft puts on the command line tool's class path (it would start a Maven build without them)
    bundles = REPO / "bundles"
    needed = [bundles / b / "target" / "classes" / "org" for b in (
        "org.stagecraft.mcap", "org.stagecraft.player", "org.stagecraft.recording", "org.stagecraft.streams",
        "org.stagecraft.spy", "org.stagecraft.foxglove", "org.stagecraft.replay", "org.stagecraft.cli")]
    needed += [bundles / "org.stagecraft.cli" / "target" / "lib" / jar
               for jar in ("gson.jar", "zstd-jni.jar", "Java-WebSocket.jar", "slf4j-api.jar")]
    missing = [str(p) for p in needed if not p.exists()]
    if missing:
        pytest.fail(f"the Java command line tool is not built ({', '.join(missing)} missing): run "
                    f"./mvnw install -DskipTests in {REPO} (./stagecraft test builds it before pytest); "
                    f"set STAGECRAFT_JAVA=0 to skip this check", pytrace=False)
    result = subprocess.run([str(REPO / "stagecraft"), "decode", str(trace)], capture_output=True, text=True,
                            timeout=300, cwd=REPO)
    assert result.returncode == 0, f"./stagecraft decode {trace} failed:\n{result.stderr}"
    return [json.loads(line) for line in result.stdout.splitlines() if line.strip()]


def exercise_every_message(client: Client) -> None:
    """Sends each kind of message the library has: data mode, device list, subscriptions, every
    proxy's commands and requests (refusals from the recorded server are fine: what counts here
    is what the client sent)."""
    client.devices()
    robot, laser, sonar, lranger, sim = (client.position2d(0), client.laser(0), client.ranger(0), client.ranger(1),
                                         client.simulation(0))
    calls = [
        robot.get_geometry, lambda: robot.enable_motors(True), lambda: robot.set_odometry(1 * m, 200 * m / 100, 0.5),
        robot.reset_odometry, lambda: robot.set_velocity_mode(1), lambda: robot.set_position_mode(False),
        lambda: robot.set_speed_pid(1.0, 0.1, 0.01), lambda: robot.set_position_pid(2.0, 0.2, 0.02),
        lambda: robot.set_speed_profile(0.5 * m / s, 0.25 * m / s**2),
        lambda: robot.set_speed(0.3 * m / s, 20 * deg / s), lambda: robot.set_velocity(0.1, 0.2, 0.3),
        lambda: robot.go_to(-5, -6, 90 * deg), lambda: robot.set_car(0.2, 0.1), lambda: robot.set_velocity_heading(0.1, 0),
        laser.get_geometry, laser.get_config, laser.get_id, lambda: laser.set_power(True),
        lambda: laser.set_config(min_angle=-90 * deg, max_angle=90 * deg, resolution=1 * deg, max_range=8 * m,
                                 range_res=0.02 * m, intensity=True, scanning_frequency=10),
        sonar.get_geometry, sonar.get_config, lambda: sonar.set_power(True), lambda: sonar.set_intensity_data(False),
        lambda: sonar.set_config(min_angle=-0.13, max_angle=0.13, angular_res=0.26, min_range=0, max_range=5,
                                 range_res=0.02, frequency=10),
        lambda: lranger.get_int_property("no_such_property"), lambda: lranger.set_int_property("k", 7),
        lambda: laser.get_double_property("no_such_property"), lambda: laser.set_double_property("k", 2.5),
        lambda: robot.get_string_property("k"), lambda: robot.set_string_property("k", "v"),
        lambda: robot.get_bool_property("k"), lambda: robot.set_bool_property("k", True),
        lambda: sim.get_pose2d("r0"), lambda: sim.set_pose2d("r0", -5.5, -6.5, 90 * deg), lambda: sim.get_pose3d("r0"),
        lambda: sim.get_color("r0"), lambda: sim.set_color("r0", 0, 1, 0, 1),
        lambda: client.set_datamode(DataMode.PUSH), lambda: client.add_replace_rule(), lambda: client.set_datamode(DataMode.PULL),
        client.read,
    ]
    fiducial = Fiducial(client, 0, subscribe=False)
    calls += [fiducial.get_geometry, fiducial.get_fov, lambda: fiducial.set_fov(0.1, 5 * m, 180 * deg), fiducial.get_id,
              lambda: fiducial.set_id(42), lambda: client.subscribe("bumper:0"), lambda: client.subscribe("sonar:0"),
              robot.unsubscribe]
    for call in calls:
        try:
            call()
        except PlayerError:
            pass


def test_every_message_the_client_sends_decodes_with_the_java_decoder(serve, tmp_path: Path) -> None:
    trace = tmp_path / "python-client.trace.jsonl"
    server = serve("requests.reqclient", trace=trace)
    with Client("127.0.0.1", server.port, timeout=5) as client:
        exercise_every_message(client)
    assert server.wait_until_served(10)
    decoded = stagecraft_decode(trace)

    errors = [d for d in decoded if "error" in d]
    assert errors == [], f"the Java decoder found errors: {errors[:3]}"
    sent = [d for d in decoded if d["dir"] == "c2s"]
    assert len(sent) == len(server.received) > 60
    for d, msg in zip(sent, server.received):
        h = msg.header
        assert (d["interf"], d["index"], d["type"], d["subtype"], d["size"]) == \
            (h.interf, h.index, h.type, h.subtype, len(msg.body))
        assert isinstance(d["body"], dict), f"no Java decoder took {d['iface']} type {d['type']} subtype {d['subtype']}"

    def bodies(iface: str, msgtype: int, subtype: int) -> list[dict]:
        return [d["body"] for d in sent if (d["iface"], d["type"], d["subtype"]) == (iface, msgtype, subtype)]

    def size(iface: str, msgtype: int, subtype: int) -> int:
        return next(d["size"] for d in sent if (d["iface"], d["type"], d["subtype"]) == (iface, msgtype, subtype))

    # payload sizes as the traces' README gives them for Player's layouts
    assert size("player", 3, 3) == 28 and size("player", 3, 5) == 4 and size("player", 3, 10) == 20
    assert size("position2d", 2, 1) == 28 and size("position2d", 2, 2) == 52
    assert size("position2d", 2, 3) == 16 and size("position2d", 2, 4) == 16 and size("position2d", 3, 5) == 24
    assert size("laser", 3, 2) == 28 and size("ranger", 3, 4) == 56
    assert size("simulation", 3, 2) == 36 and size("simulation", 3, 6) == 56

    # the fields, by Player's names, are what the client meant
    subscribes = [(b["addr"]["interf"], b["addr"]["index"], b["access"]) for b in bodies("player", 3, 3)]
    assert (4, 0, 1) in subscribes and (5, 0, 1) in subscribes and (14, 0, 1) in subscribes and (4, 0, 2) in subscribes
    assert [b["mode"] for b in bodies("player", 3, 5)] == [2, 1, 2]
    assert bodies("player", 3, 10) == [{"interf": -1, "index": -1, "type": 1, "subtype": -1, "replace": 1}]
    vel = bodies("position2d", 2, 1)
    assert vel[0]["vel"]["px"] == 0.3 and vel[0]["vel"]["pa"] == pytest.approx(0.3490658503988659) and vel[0]["state"] == 1
    assert vel[1]["vel"] == {"px": 0.1, "py": 0.2, "pa": 0.3}
    pos = bodies("position2d", 2, 2)[0]
    assert pos["pos"]["px"] == -5.0 and pos["pos"]["pa"] == pytest.approx(1.5707963267948966)
    assert bodies("position2d", 2, 3)[0] == {"velocity": 0.2, "angle": 0.1}
    assert bodies("position2d", 3, 5)[0]["pose"] == {"px": 1.0, "py": 2.0, "pa": 0.5}
    assert bodies("position2d", 3, 9)[0] == {"speed": 0.5, "acc": 0.25}
    config = bodies("laser", 3, 2)[0]
    assert config["max_range"] == 8.0 and config["intensity"] == 1 and config["scanning_frequency"] == 10.0
    assert bodies("ranger", 3, 4)[0]["max_range"] == 5.0
    assert bodies("ranger", 3, 253)[0] == {"key_count": 2, "key": "k", "value": 7}
    assert bodies("laser", 3, 251)[0]["value"] == 2.5
    assert bodies("position2d", 3, 249)[0]["value"] == "v"
    assert bodies("position2d", 3, 247)[0]["value"] == 1
    sim = bodies("simulation", 3, 2)[0]
    assert sim["name"] == "r0" and sim["pose"]["px"] == -5.5 and sim["pose"]["pa"] == pytest.approx(1.5707963267948966)
    assert bodies("simulation", 3, 6)[0]["prop"] == "color" and bodies("simulation", 3, 6)[0]["value_count"] == 16
    fov = bodies("fiducial", 3, 3)[0]
    assert fov["max_range"] == 5.0 and fov["view_angle"] == pytest.approx(3.1415927, rel=1e-6)
    assert bodies("fiducial", 3, 8)[0] == {"id": 42}
    # the server's side of the conversation (recorded Player replies) decodes too
    assert any(d["dir"] == "s2c" and d.get("ident") == "Player v.3.1.1-dev" for d in decoded)
