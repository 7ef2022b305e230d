"""A late extra reply must not answer the next identical request.

Player's ``rangertolaser`` answers one SET_CONFIG with two NACKs (see the traces' README). Replies
are matched by interface, index and subtype, so if the second NACK is still unread when the same
request is sent again, it would be taken for that request's answer. A scripted server sends the two
NACKs, then answers the repeated request with an ACK; the client must return the ACK and keep the
extra NACK as a stray reply.
"""

from __future__ import annotations

import select
import socket
import threading

import pytest

from stagecraft_player import Client, RequestRefused
from stagecraft_player.wire import INTERFACES, Framer, Header, MsgType

LASER = INTERFACES["laser"]
SET_CONFIG = 2
ACK_BODY = b"\0\0\0\x07"


def _reply(req: Header, msgtype: int, body: bytes = b"") -> bytes:
    return Header(0, req.robot, req.interf, req.index, msgtype, req.subtype, 0.0, 0, len(body)).pack() + body


class DoubleNackServer:
    """ACKs everything, except that the first laser SET_CONFIG gets two NACKs, sent one by one
    (``together``: in one write)."""

    def __init__(self, together: bool) -> None:
        self.together = together
        self.listener = socket.create_server(("127.0.0.1", 0))
        self.port = self.listener.getsockname()[1]
        self.both_nacks_sent = threading.Event()
        self.requests: list[Header] = []
        self.errors: list[BaseException] = []
        self.thread = threading.Thread(target=self._serve, daemon=True)
        self.thread.start()

    def _serve(self) -> None:
        try:
            conn, _ = self.listener.accept()
            with conn:
                conn.sendall(b"Player v.3.1.1".ljust(32, b"\0"))
                framer = Framer(expect_ident=False)
                nacked = False
                while True:
                    chunk = conn.recv(65536)
                    if not chunk:
                        return
                    for msg in framer.feed(chunk):
                        h = msg.header
                        self.requests.append(h)
                        if (h.interf, h.subtype) == (LASER, SET_CONFIG) and not nacked:
                            nacked = True
                            nack = _reply(h, MsgType.RESP_NACK)
                            if self.together:
                                conn.sendall(nack + nack)
                            else:
                                conn.sendall(nack)
                                conn.sendall(nack)
                            self.both_nacks_sent.set()
                        else:
                            conn.sendall(_reply(h, MsgType.RESP_ACK, ACK_BODY))
        except BaseException as e:  # reported by the test
            self.errors.append(e)
        finally:
            self.listener.close()


@pytest.mark.parametrize("together", [False, True], ids=["nacks-in-two-writes", "nacks-in-one-write"])
def test_a_leftover_second_nack_does_not_answer_the_same_request_sent_again(together: bool) -> None:
    server = DoubleNackServer(together)
    with Client("127.0.0.1", server.port, timeout=5) as client:
        with pytest.raises(RequestRefused):
            client.request(LASER, 0, SET_CONFIG, b"config")
        assert server.both_nacks_sent.wait(5), "the scripted server did not send its two NACKs"
        # the second NACK is on this client's socket (or already framed) before the request goes out
        assert client._incoming or select.select([client._sock], [], [], 5)[0]
        reply = client.request(LASER, 0, SET_CONFIG, b"config")
        assert reply.header.type == MsgType.RESP_ACK and reply.body == ACK_BODY
        assert [(h.interf, h.index, h.type, h.subtype) for h in client.stray_replies] == \
            [(LASER, 0, MsgType.RESP_NACK, SET_CONFIG)]
    server.thread.join(5)
    assert not server.errors, server.errors
    assert [(h.interf, h.subtype) for h in server.requests].count((LASER, SET_CONFIG)) == 2
