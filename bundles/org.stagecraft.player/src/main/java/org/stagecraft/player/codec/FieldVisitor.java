package org.stagecraft.player.codec;

import org.eclipse.jdt.annotation.Nullable;

/**
 * Receives the fields of a decoded body in wire order, named as in Player's interface definitions
 * (e.g. {@code min_angle}, {@code ranges_count}, {@code pos}). Used to print JSON, fill the packet
 * inspector's field tree and pick plot values without knowing each message class. Inside a list,
 * names are null.
 */
public interface FieldVisitor {
    /** Any integer field; unsigned 32-bit fields arrive as their unsigned value. */
    void integer(@Nullable String name, long value);

    /** A 32-bit float, kept as float so it prints with float precision. */
    void float32(@Nullable String name, float value);

    void float64(@Nullable String name, double value);

    /** A Player string (char array), without its terminating NUL. */
    void text(@Nullable String name, String value);

    /** Opaque bytes with no numeric meaning (e.g. compressed map cells, property values). */
    void opaque(@Nullable String name, byte[] value);

    void beginStruct(@Nullable String name);

    void endStruct();

    void beginList(@Nullable String name);

    void endList();
}
