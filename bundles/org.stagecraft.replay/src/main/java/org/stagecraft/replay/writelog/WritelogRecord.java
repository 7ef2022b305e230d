package org.stagecraft.replay.writelog;

import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.codec.PlayerEncoder;
import org.stagecraft.player.wire.MessageHeader;

/**
 * One message line of a writelog file.
 *
 * @param line          1-based line number in the file
 * @param time          the first column: the message's timestamp in seconds, which readlog also paces by
 * @param host          the device's host as the unsigned 32-bit number Player wrote
 * @param robot         the device's robot, i.e. the Player port
 * @param interfaceName Player's interface name as written, e.g. "position2d"
 * @param interf        its interface code
 * @param index         device index
 * @param type          Player message type (1 data, 4 reply)
 * @param subtype       message subtype
 * @param body          the payload, built with the codec's message classes
 */
public record WritelogRecord(long line, double time, long host, long robot, String interfaceName, int interf,
        int index, int type, int subtype, MessageBody body) {

    /** The Player header this message would have had on the wire, with the given sequence number. */
    public MessageHeader header(int seq) {
        return new MessageHeader((int) host, (int) robot, interf, index, type, subtype, time, seq,
                PlayerEncoder.encodeBody(body).length);
    }
}
