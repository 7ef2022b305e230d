"""Clear errors: no server, not a Player server, a server that goes away or never answers,
a device address of the wrong interface."""

from __future__ import annotations

import socket
import threading

import pytest

from stagecraft_player import (Client, ConnectionLost, Laser, PlayerConnectionError, PlayerTimeout, WrongInterface)


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class OneShotServer:
    """Accepts one client, sends ``banner`` and then does what ``then`` says."""

    def __init__(self, banner: bytes, then: str) -> None:
        self.listener = socket.create_server(("127.0.0.1", 0))
        self.port = self.listener.getsockname()[1]
        self.release = threading.Event()
        self.then = then
        self.thread = threading.Thread(target=self._run, daemon=True)
        self.banner = banner
        self.thread.start()

    def _run(self) -> None:
        conn, _ = self.listener.accept()
        with conn:
            conn.sendall(self.banner)
            if self.then == "close-after-first-request":
                got = b""
                while len(got) < 44:  # the whole DATAMODE request, so closing sends FIN, not a reset
                    got += conn.recv(44 - len(got))
                return
            self.release.wait(30)  # "hang": keep the connection open, never answer

    def close(self) -> None:
        self.release.set()
        self.thread.join(10)
        self.listener.close()


def test_no_server_is_a_clear_connection_error() -> None:
    port = free_port()
    with pytest.raises(PlayerConnectionError, match=f"cannot connect to Player at 127.0.0.1:{port}: connection refused"):
        Client("127.0.0.1", port, timeout=2)


@pytest.mark.parametrize("ending", ["reset", "closed"])
def test_a_connection_ended_before_the_banner_says_so_without_guessing_the_server(ending: str) -> None:
    """What a robot program sees through the spy when Player behind it is not running."""
    listener = socket.create_server(("127.0.0.1", 0))
    port = listener.getsockname()[1]

    def end_at_once() -> None:
        conn, _ = listener.accept()
        if ending == "reset":
            conn.setsockopt(socket.SOL_SOCKET, socket.SO_LINGER, b"\1\0\0\0\0\0\0\0")  # linger 0: RST
        conn.close()

    thread = threading.Thread(target=end_at_once, daemon=True)
    thread.start()
    try:
        with pytest.raises(ConnectionLost) as lost:
            Client("127.0.0.1", port, timeout=5)
        message = str(lost.value)
        assert f"Player at 127.0.0.1:{port}: the connection was {ending} before Player's banner arrived" in message
        assert "Network Spy, Player may not be running" in message and "check the spy's messages" in message
        assert "is it a Player server" not in message
    finally:
        thread.join(10)
        listener.close()


def test_a_server_that_is_not_player_is_named() -> None:
    server = OneShotServer(b"SSH-2.0-OpenSSH_9.6\r\n".ljust(32, b"\0"), then="hang")
    try:
        with pytest.raises(PlayerConnectionError, match=f"127.0.0.1:{server.port} is not a Player server"):
            Client("127.0.0.1", server.port, timeout=2)
    finally:
        server.close()


def test_a_server_that_goes_away_raises_connection_lost() -> None:
    server = OneShotServer(b"Player v.3.1.1-dev".ljust(32, b"\0"), then="close-after-first-request")
    try:
        with pytest.raises(ConnectionLost, match="closed the connection while this client waited for the reply "
                                                 "to player:0 REQ 5"):
            Client("127.0.0.1", server.port, timeout=5)
    finally:
        server.close()


def test_a_server_that_never_answers_times_out_naming_the_request() -> None:
    server = OneShotServer(b"Player v.3.1.1-dev".ljust(32, b"\0"), then="hang")
    try:
        with pytest.raises(PlayerTimeout, match=r"timed out after 0.3 s waiting for the reply to player:0 REQ 5"):
            Client("127.0.0.1", server.port, timeout=0.3)
    finally:
        server.close()


def test_the_end_of_the_recording_is_a_lost_server_in_the_middle_of_a_read(serve) -> None:
    server = serve("python-client.sentinel", rounds=3)
    with Client("127.0.0.1", server.port) as client:
        client.position2d(0)
        for _ in range(3):
            client.read()
        with pytest.raises(ConnectionLost, match="did Player stop"):
            client.read()


def test_a_device_of_another_interface_is_refused_before_anything_is_sent(serve) -> None:
    server = serve("python-client.sentinel", rounds=0)
    with Client("127.0.0.1", server.port) as client:
        with pytest.raises(WrongInterface, match="Laser reads 'laser' devices, but 'ranger:1' is a 'ranger' device"):
            Laser(client, "ranger:1")
        with pytest.raises(TypeError):
            client.laser(1.5)  # type: ignore[arg-type]
    assert [m.header.subtype for m in server.received] == [5]  # only the data mode request
