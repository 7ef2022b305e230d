package org.stagecraft.replay.analysis;

import java.util.OptionalDouble;
import java.util.function.Function;

import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.streams.StreamPattern;

/**
 * What one plot series shows: a number taken from the bodies of the messages of some streams.
 *
 * @param label   the legend text, e.g. "position2d:0 pos.px"
 * @param streams which streams (a device's DATA, a derived stream, ...)
 * @param value   the number in a body, empty when the body has none (e.g. a field path such as
 *                {@code pos.px} or {@code min(ranges)})
 */
public record SeriesSpec(String label, StreamPattern streams, Function<MessageBody, OptionalDouble> value) {
}
