#!/usr/bin/env python3
"""A stand-in for Player in the Tool Manager's tests (Player itself is not installable here).

Run like Player:  player-standin.py -p PORT file.cfg

It reads the cfg it is given with a parser of its own (not the Tool Manager's, so the rewritten
copy is checked independently), listens on every port a `provides` address names (PORT for those
that name none), and serves each accepted connection the server side of one recorded connection of
a Player trace (STANDIN_TRACE, connection STANDIN_CONN, default the first), while collecting what
the client sends. When the client has closed, it reports on stdout whether that was byte for byte
what the recorded client sent.

It also checks what must hold for the copy: every `worldfile`/`include` path is absolute and exists.
A line "crash N" on stdin makes it exit with code N (a crash mid-session, on demand).
With STANDIN_CONNECTION_LOG=FILE it appends one JSON line per connection: the port, whether the
banner went out ("sent", or "failed: ..." as Player's "failed to send ident string"), how the
connection ended ("eof" = orderly close, "reset" = Player's "other error on client"), bytes received.
"""
import base64
import json
import os
import re
import socket
import sys
import threading


SAY_LOCK = threading.Lock()


def say(text):
    # Connections are served on threads of their own; print() writes the text and the newline
    # separately, so two reports at once could run into one line. One whole write under a lock.
    with SAY_LOCK:
        sys.stdout.write("standin: " + text + "\n")
        sys.stdout.flush()


def strip_comments(text):
    out = []
    for line in text.splitlines():
        kept, in_string = [], False
        for ch in line:
            if ch == '"':
                in_string = not in_string
            if ch == '#' and not in_string:
                break
            kept.append(ch)
        out.append("".join(kept))
    return "\n".join(out)


def provided_ports(cfg_text, default_port):
    ports = []
    for body in re.findall(r'\bprovides\s*\[(.*?)\]', strip_comments(cfg_text), re.S):
        for addr in re.findall(r'"([^"]*)"', body):
            fields = addr.split(":")
            robot = fields[-3] if len(fields) >= 3 else ""
            port = int(robot) if robot else default_port
            if port not in ports:
                ports.append(port)
    return ports


def check_paths(cfg_text):
    ok = True
    for key, path in re.findall(r'\b(worldfile|include)\s+"([^"]*)"', strip_comments(cfg_text)):
        if not os.path.isabs(path) or not os.path.exists(path):
            say("path problem: %s \"%s\"" % (key, path))
            ok = False
    return ok


def recorded(trace, conn):
    c2s, s2c, first = [], [], None
    with open(trace) as f:
        for n, line in enumerate(f):
            if n == 0:
                continue
            rec = json.loads(line)
            if "data" not in rec:
                continue
            if first is None:
                first = rec["conn"]
            if rec["conn"] != (conn or first):
                continue
            (c2s if rec["dir"] == "c2s" else s2c).append(base64.b64decode(rec["data"]))
    return b"".join(c2s), s2c


BANNER_BYTES = 32  # Player's PLAYER_IDENT_STRLEN: sent as soon as a client is accepted


def log_connection(record):
    """One JSON line per connection to STANDIN_CONNECTION_LOG, if set: how it began and ended."""
    path = os.environ.get("STANDIN_CONNECTION_LOG")
    if not path:
        return
    with LOG_LOCK, open(path, "a") as f:
        f.write(json.dumps(record) + "\n")


LOG_LOCK = threading.Lock()


def serve(sock, port, expected, chunks):
    # Like Player: the ident string (banner) at once, the rest only once the client has spoken
    # (Player sends data only to clients that subscribed).  A client that reads the banner and
    # closes leaves no unread bytes, so its close is an orderly FIN.
    data = b"".join(chunks)
    banner, rest = data[:BANNER_BYTES], data[BANNER_BYTES:]
    spoke = threading.Event()
    record = {"port": port, "banner": "not sent", "end": None, "bytes_in": 0}

    def send():
        try:
            sock.sendall(banner)
            record["banner"] = "sent"
        except OSError as e:
            # what Player reports as "failed to send ident string"
            record["banner"] = "failed: " + e.__class__.__name__
            return
        spoke.wait()
        try:
            if rest:
                sock.sendall(rest)
            sock.shutdown(socket.SHUT_WR)
        except OSError:
            pass
    sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
    sender = threading.Thread(target=send, daemon=True)
    sender.start()
    got = bytearray()
    try:
        while True:
            b = sock.recv(65536)
            if not b:
                record["end"] = "eof"  # the client closed in order (FIN)
                break
            got += b
            spoke.set()
    except ConnectionResetError:
        record["end"] = "reset"  # what Player reports as "other error on client"
    except OSError as e:
        record["end"] = "error: " + e.__class__.__name__
    spoke.set()
    sender.join()
    sock.close()
    record["bytes_in"] = len(got)
    log_connection(record)
    say("served port=%d bytes_in=%d match=%s" % (port, len(got), "true" if bytes(got) == expected else "false"))


def accept_loop(server, port, expected, chunks):
    while True:
        conn, _ = server.accept()
        threading.Thread(target=serve, args=(conn, port, expected, chunks), daemon=True).start()


def main(argv):
    default_port, cfg = 6665, None
    i = 0
    while i < len(argv):
        if argv[i] == "-p":
            default_port = int(argv[i + 1])
            i += 2
        else:
            cfg = argv[i]
            i += 1
    if cfg is None:
        say("usage: player-standin.py -p PORT file.cfg")
        return 2
    with open(cfg) as f:
        text = f.read()
    paths_ok = check_paths(text)
    ports = provided_ports(text, default_port)
    expected, chunks = recorded(os.environ["STANDIN_TRACE"], int(os.environ.get("STANDIN_CONN", "0")))
    say("cfg %s paths=%s" % (cfg, "ok" if paths_ok else "bad"))
    for port in ports:
        server = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
        server.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        server.bind(("127.0.0.1", port))
        server.listen(16)
        threading.Thread(target=accept_loop, args=(server, port, expected, chunks), daemon=True).start()
    say("listening on " + " ".join(str(p) for p in ports))
    for line in sys.stdin:
        words = line.split()
        if len(words) == 2 and words[0] == "crash":
            say("crashing with exit code " + words[1])
            os._exit(int(words[1]))
    # stdin closed: keep serving until stopped, as Player does
    threading.Event().wait()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
