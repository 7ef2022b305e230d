"""XDR, the header and the framer, on bytes from the recordings."""

from __future__ import annotations

import base64
import json
import random

import pytest

from player_trace import read_events, traces_dir
from stagecraft_player.errors import PlayerProtocolError
from stagecraft_player.wire import DeviceAddress, Framer, Header, MsgType, parse_ident
from stagecraft_player.xdr import XdrReader, XdrWriter


def test_header_of_the_readme_example_unpacks_to_its_fields() -> None:
    # the RESP_ACK to DATAMODE quoted in tests/traces/README.md
    raw = bytes.fromhex("0100007f00001df100000001000000000000000400000005" "3fc999999999999a" "0000000000000000")
    h = Header.unpack(raw)
    assert (h.host, h.robot, h.interf, h.index, h.type, h.subtype) == (16777343, 7665, 1, 0, MsgType.RESP_ACK, 5)
    assert h.timestamp == 0.2 and h.seq == 0 and h.size == 0
    assert h.pack() == raw


def test_strings_count_their_nul_and_pad_to_four_bytes() -> None:
    data = XdrWriter().string("stage").to_bytes()
    assert data == bytes.fromhex("00000006" "00000006") + b"stage\0\0\0"
    assert XdrReader(data).string() == "stage"


def test_arrays_carry_their_count_twice() -> None:
    data = XdrWriter().floats([1.0, 2.0]).to_bytes()
    assert data[:8] == bytes.fromhex("00000002 00000002".replace(" ", ""))
    assert XdrReader(data).floats() == [1.0, 2.0]


def test_a_short_payload_is_an_error_naming_offset_and_what() -> None:
    with pytest.raises(PlayerProtocolError, match=r"laser:0 DATA.*needs 4 more bytes at offset 8"):
        r = XdrReader(b"\0" * 8, "laser:0 DATA subtype 1")
        r.float64(), r.uint32()


def test_an_array_longer_than_its_payload_is_refused() -> None:
    with pytest.raises(PlayerProtocolError, match="does not fit"):
        XdrReader(bytes.fromhex("000000ff000000ff") + b"\0" * 8).doubles()


def test_banner_must_be_player() -> None:
    assert parse_ident(b"Player v.3.1.1-dev".ljust(32, b"\0")) == "Player v.3.1.1-dev"
    with pytest.raises(PlayerProtocolError, match="not a Player server"):
        parse_ident(b"SSH-2.0-OpenSSH_9.6".ljust(32, b"\0"))


def test_device_addresses_parse_like_player_writes_them() -> None:
    assert DeviceAddress.parse("laser:1") == DeviceAddress(6, 1)
    assert DeviceAddress.parse("ranger") == DeviceAddress(62, 0)
    assert str(DeviceAddress(4, 0)) == "position2d:0"
    with pytest.raises(ValueError, match="unknown interface 'lazer'"):
        DeviceAddress.parse("lazer:0")
    with pytest.raises(ValueError, match="index 'x'"):
        DeviceAddress.parse("laser:x")


def _server_stream(name: str) -> bytes:
    out = bytearray()
    with open(traces_dir() / name, encoding="utf-8") as f:
        next(f)
        for line in f:
            record = json.loads(line)
            if record.get("dir") == "s2c" and record.get("conn") == 1:
                out += base64.b64decode(record["data"])
    return bytes(out)


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_framing_does_not_depend_on_how_the_stream_is_chunked(seed: int) -> None:
    stream = _server_stream("python-client.sentinel.trace.jsonl")
    _, recorded = read_events(traces_dir() / "python-client.sentinel.trace.jsonl")
    expected = [e.message for e in recorded if e.dir == "s2c"]
    framer = Framer(expect_ident=True)
    got = []
    rng = random.Random(seed)
    i = 0
    while i < len(stream):
        n = 1 if rng.random() < 0.3 else rng.randint(1, 3000)
        got += framer.feed(stream[i:i + n])
        i += n
    assert framer.ident == "Player v.3.1.1-dev"
    assert got == expected
    assert framer.pending == 0
