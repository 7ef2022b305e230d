package org.stagecraft.spy;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;

/** {@link FillingChannel} as the file channel the writers get for a path: they can cut the file back. */
public final class FillingFile extends ForwardingFileChannel {
    private final FillingChannel filling;

    public FillingFile(FileChannel file, long budget) {
        super(file);
        this.filling = new FillingChannel(file, budget);
    }

    @Override
    public int write(ByteBuffer src) throws IOException {
        return filling.write(src);
    }
}
