package org.stagecraft.spy.proxy;

/**
 * A robot program's connection through the spy.
 *
 * @param id       1, 2, ... in accept order, unique per spy
 * @param port     the port the robot program connected to (the original Player port)
 * @param client   the robot program's address, e.g. "127.0.0.1:40312"
 * @param listen   the address it connected to, e.g. "127.0.0.1:6665"
 * @param upstream where the spy relays it, e.g. "127.0.0.1:7665"
 */
public record ConnectionInfo(int id, int port, String client, String listen, String upstream) {
}
