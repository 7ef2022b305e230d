package org.stagecraft.mcap;

import java.util.Map;
import java.util.Set;

import org.eclipse.jdt.annotation.Nullable;

/**
 * A chunk of the file, from the chunk index or found by scanning.
 *
 * @param seq           its place in the file, from 0
 * @param offset        where its record starts
 * @param length        its record's length, opcode and length field included
 * @param startTime     earliest log time of its messages
 * @param endTime       latest log time of its messages
 * @param messageCounts messages per channel when known (scanned chunks), else null
 * @param channels      the channels it has messages on (from the chunk index or the scan)
 * @param messageIndexOffsets where its message index records are, by channel (from the chunk index; empty when scanned)
 * @param messageIndexLength  the length of its message index records together (0 when scanned)
 */
public record ChunkInfo(int seq, long offset, long length, long startTime, long endTime, Set<Integer> channels,
        @Nullable Map<Integer, Long> messageCounts, Map<Integer, Long> messageIndexOffsets, long messageIndexLength) {
}
