package org.stagecraft.core.extensions;

/**
 * The names of Stagecraft's extension points and of every element and attribute their schemas
 * ({@code schema/*.exsd}) define, written once: the registries read {@code plugin.xml} through these
 * constants, never through string literals, so a name changed in a schema is changed here and found
 * by the compiler everywhere it is read.
 */
public final class ExtensionXml {
    private ExtensionXml() {
    }

    // attributes several elements share
    /** A contribution's unique id. */
    public static final String ATT_ID = "id";
    /** A contribution's human-readable name (an interface's Player name for {@link #EL_INTERFACE}). */
    public static final String ATT_NAME = "name";
    /** The class the platform creates (a public no-argument constructor). */
    public static final String ATT_CLASS = "class";

    // org.stagecraft.core.decoders (schema/decoders.exsd)
    public static final String DECODERS = "org.stagecraft.core.decoders";
    /** A class implementing {@code org.stagecraft.player.codec.CodecContribution}: {@link #ATT_CLASS}. */
    public static final String EL_CODEC = "codec";
    /** Names an interface code: {@link #ATT_CODE}, {@link #ATT_NAME}. */
    public static final String EL_INTERFACE = "interface";
    /** The interface code, 0..65535. */
    public static final String ATT_CODE = "code";

    // org.stagecraft.core.streamProcessors (schema/streamProcessors.exsd)
    public static final String STREAM_PROCESSORS = "org.stagecraft.core.streamProcessors";
    /** A class implementing {@code org.stagecraft.streams.StreamProcessor}: {@link #ATT_ID}, {@link #ATT_NAME}, {@link #ATT_CLASS}. */
    public static final String EL_PROCESSOR = "processor";

    // org.stagecraft.views.renderers (org.stagecraft.views/schema/renderers.exsd)
    public static final String RENDERERS = "org.stagecraft.views.renderers";
    /** A class extending {@code org.stagecraft.views.StreamRenderer}: id, name, class and the defaults below. */
    public static final String EL_RENDERER = "renderer";
    /** The stream pattern a new layer of the renderer starts with. */
    public static final String ATT_DEFAULT_PATTERN = "defaultPattern";
    /** The colour a new layer starts with, {@code #RRGGBB}. */
    public static final String ATT_DEFAULT_COLOUR = "defaultColour";
    /** The opacity a new layer starts with, 0..1. */
    public static final String ATT_DEFAULT_ALPHA = "defaultAlpha";

    // org.stagecraft.tools.ui.toolTypes (org.stagecraft.tools.ui/schema/toolTypes.exsd)
    public static final String TOOL_TYPES = "org.stagecraft.tools.ui.toolTypes";
    /** A class implementing {@code org.stagecraft.tools.types.ToolType}: id, name, class. */
    public static final String EL_TOOL_TYPE = "toolType";
}
