package org.stagecraft.tools.types;

import org.stagecraft.tools.process.ToolSpec;

/**
 * A kind of tool: how a user's {@link ToolDefinition} becomes something to run. Plug-ins contribute
 * types through the {@code org.stagecraft.tools.ui.toolTypes} extension point (e.g. a simulator that
 * needs a generated config file, or a type that fills in a readiness check the user would otherwise
 * have to know); {@link GenericToolType} runs the command as written.
 */
public interface ToolType {
    /**
     * @throws IllegalArgumentException naming the tool and the field that is wrong
     */
    ToolSpec toSpec(ToolDefinition definition);
}
