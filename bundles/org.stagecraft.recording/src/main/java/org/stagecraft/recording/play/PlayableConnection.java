package org.stagecraft.recording.play;

import java.io.IOException;

/**
 * A recorded connection as a replay needs it: where it was, how long it lasted, and each side as a
 * fresh {@link ChunkSource} per replay, so that a connection served many times (or from a large
 * log) is read from its source each time instead of being held in memory.
 */
public interface PlayableConnection {

    /** The connection number in the recording. */
    int conn();

    /** The Player port the recorded client connected to. */
    int port();

    /** Seconds from open to close (or to the last chunk when the close was not recorded). */
    double length();

    /** What Player sent (the ident banner first), timed from the connection's open. */
    ChunkSource openServer() throws IOException;

    /** What the robot program sent, timed from the connection's open. */
    ChunkSource openClient() throws IOException;
}
