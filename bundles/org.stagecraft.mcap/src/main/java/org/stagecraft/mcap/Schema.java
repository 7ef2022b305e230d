package org.stagecraft.mcap;

/** A Schema record: how the messages of the channels that name it are laid out. */
public record Schema(int id, String name, String encoding, byte[] data) {
    public Schema {
        data = data == null ? new byte[0] : data.clone();
    }

    @Override
    public byte[] data() {
        return data.clone();
    }
}
