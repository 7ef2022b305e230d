package org.stagecraft.mcap;

/**
 * One Message record as a reader meets it. Its data is a view into the decompressed chunk, valid only
 * during the visit: {@code data} is read with {@link #in()} or copied with {@link #copyData()}.
 */
public record Message(int channel, long sequence, long logTime, long publishTime, byte[] array, int offset,
        int length) {

    /** The data, bounds-checked. */
    public RecordInput in() {
        return new RecordInput(array, offset, length);
    }

    public byte[] copyData() {
        return java.util.Arrays.copyOfRange(array, offset, offset + length);
    }
}
