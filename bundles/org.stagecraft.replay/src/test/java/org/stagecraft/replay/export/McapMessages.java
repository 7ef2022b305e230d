package org.stagecraft.replay.export;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import com.github.luben.zstd.Zstd;

/**
 * A small MCAP reader written for these tests from the MCAP specification, independent of the spy
 * log's reader: the schemas, channels and messages of a file's chunks.
 */
final class McapMessages {
    record Schema(int id, String name, String encoding, byte[] data) {
    }

    record Channel(int id, int schemaId, String topic, String encoding, Map<String, String> metadata) {
    }

    record Message(int channel, long logTime, byte[] data) {
    }

    final Map<Integer, Schema> schemas = new HashMap<>();
    final Map<Integer, Channel> channels = new HashMap<>();
    final List<Message> messages = new ArrayList<>();

    static McapMessages read(Path file) throws IOException {
        McapMessages m = new McapMessages();
        ByteBuffer b = ByteBuffer.wrap(Files.readAllBytes(file)).order(ByteOrder.LITTLE_ENDIAN);
        b.position(8);
        m.records(b, true);
        return m;
    }

    private void records(ByteBuffer b, boolean top) {
        while (b.remaining() >= 9) {
            int op = b.get() & 0xff;
            long len = b.getLong();
            ByteBuffer r = b.slice(b.position(), (int) len).order(ByteOrder.LITTLE_ENDIAN);
            b.position(b.position() + (int) len);
            switch (op) {
                case 0x03 -> {
                    int id = r.getShort() & 0xffff;
                    schemas.put(id, new Schema(id, str(r), str(r), bytes(r, r.getInt())));
                }
                case 0x04 -> {
                    int id = r.getShort() & 0xffff;
                    int schema = r.getShort() & 0xffff;
                    String topic = str(r);
                    String enc = str(r);
                    int mapLen = r.getInt();
                    ByteBuffer mr = r.slice(r.position(), mapLen).order(ByteOrder.LITTLE_ENDIAN);
                    Map<String, String> meta = new LinkedHashMap<>();
                    while (mr.hasRemaining()) {
                        meta.put(str(mr), str(mr));
                    }
                    channels.put(id, new Channel(id, schema, topic, enc, meta));
                }
                case 0x05 -> {
                    int ch = r.getShort() & 0xffff;
                    r.getInt();
                    long logTime = r.getLong();
                    r.getLong();
                    messages.add(new Message(ch, logTime, bytes(r, r.remaining())));
                }
                case 0x06 -> {
                    r.getLong();
                    r.getLong();
                    long raw = r.getLong();
                    r.getInt();
                    String compression = str(r);
                    long n = r.getLong();
                    byte[] packed = bytes(r, (int) n);
                    byte[] plain = compression.isEmpty() ? packed : Zstd.decompress(packed, (int) raw);
                    records(ByteBuffer.wrap(plain).order(ByteOrder.LITTLE_ENDIAN), false);
                }
                case 0x0F -> {
                    if (top) {
                        return; // the summary only repeats definitions
                    }
                }
                default -> {
                    // other records are not needed here
                }
            }
        }
    }

    private static String str(ByteBuffer r) {
        return new String(bytes(r, r.getInt()), StandardCharsets.UTF_8);
    }

    private static byte[] bytes(ByteBuffer r, int n) {
        byte[] a = new byte[n];
        r.get(a);
        return a;
    }
}
