package org.stagecraft.replay.analysis;

/**
 * The packet inspector's hex dump: 16 bytes a line, offset, hex in two groups of eight, printable
 * ASCII (others as '.'). Player messages are big-endian XDR, so 4-byte groups line up with fields.
 */
public final class HexDump {
    private HexDump() {
    }

    public static String of(byte[] b) {
        StringBuilder out = new StringBuilder(b.length * 4 + 16);
        for (int line = 0; line < b.length; line += 16) {
            out.append(String.format("%08x  ", line));
            for (int i = 0; i < 16; i++) {
                if (line + i < b.length) {
                    out.append(String.format("%02x ", b[line + i] & 0xff));
                } else {
                    out.append("   ");
                }
                if (i == 7) {
                    out.append(' ');
                }
            }
            out.append(" |");
            for (int i = 0; i < 16 && line + i < b.length; i++) {
                int c = b[line + i] & 0xff;
                out.append(c >= 0x20 && c < 0x7f ? (char) c : '.');
            }
            out.append("|\n");
        }
        return out.toString();
    }
}
