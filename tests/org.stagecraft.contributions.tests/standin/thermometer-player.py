#!/usr/bin/env python3
"""A stand-in for a Player whose driver provides the made-up "thermometer" interface (300).

No real Player driver provides that interface: it is the worked example of docs/extending-decoders.md,
so the contributions test needs a server that speaks it. Run like Player:
    thermometer-player.py -p PORT file.cfg
It listens on 127.0.0.1:PORT and serves every accepted connection like Player: the 32-byte ident banner
at once, then, once the client has sent something (Player sends data only to subscribed clients), the
messages in STANDIN_MESSAGES (a file of whole Player messages the test encoded), unchanged, one every
20 ms as a driver publishes its readings, then waits for the client to close. The cfg is not read:
every device is on the default port.
"""
import os
import socket
import struct
import sys
import threading
import time

BANNER = b"Player v.3.1.1".ljust(32, b"\0")
HEADER = 40  # Player's message header; its last field is the payload size (XDR unsigned int)
PERIOD = 0.02


def split(data):
    """The whole messages in data, in order."""
    out, at = [], 0
    while at + HEADER <= len(data):
        size = struct.unpack(">I", data[at + HEADER - 4:at + HEADER])[0]
        out.append(data[at:at + HEADER + size])
        at += HEADER + size
    return out


def serve(sock, messages):
    sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
    try:
        sock.sendall(BANNER)
        if sock.recv(65536):
            for m in messages:
                sock.sendall(m)
                time.sleep(PERIOD)  # the driver's rate: readings spread over time (a busy machine may still join two)
        while sock.recv(65536):
            pass
    except OSError:
        pass
    finally:
        sock.close()


def main(argv):
    port = 6665
    if "-p" in argv:
        port = int(argv[argv.index("-p") + 1])
    with open(os.environ["STANDIN_MESSAGES"], "rb") as f:
        messages = split(f.read())
    server = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    server.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    server.bind(("127.0.0.1", port))
    server.listen(16)
    print("thermometer stand-in: listening on %d" % port, flush=True)
    while True:
        conn, _ = server.accept()
        threading.Thread(target=serve, args=(conn, messages), daemon=True).start()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
