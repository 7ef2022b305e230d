package org.stagecraft.spy;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.channels.WritableByteChannel;

/** A channel that accepts {@code budget} bytes and then fails like a full disk (after a partial write). */
public final class FillingChannel implements WritableByteChannel {
    private final FileChannel file;
    private long budget;

    public FillingChannel(FileChannel file, long budget) {
        this.file = file;
        this.budget = budget;
    }

    @Override
    public int write(ByteBuffer src) throws IOException {
        if (budget <= 0) {
            throw new IOException("No space left on device");
        }
        int n = (int) Math.min(budget, src.remaining());
        ByteBuffer part = src.slice().limit(n);
        int written = file.write(part);
        src.position(src.position() + written);
        budget -= written;
        return written;
    }

    @Override
    public boolean isOpen() {
        return file.isOpen();
    }

    @Override
    public void close() throws IOException {
        file.close();
    }
}
