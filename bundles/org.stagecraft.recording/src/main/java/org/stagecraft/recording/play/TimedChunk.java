package org.stagecraft.recording.play;

/**
 * The bytes one recv() returned in the recording, and when: seconds after the connection was opened.
 */
public record TimedChunk(double offset, byte[] data) {
}
