package org.stagecraft.tools.tests;

import java.time.Duration;
import java.util.List;

import org.stagecraft.tools.process.Readiness;
import org.stagecraft.tools.process.ToolSpec;
import org.stagecraft.tools.types.ToolDefinition;
import org.stagecraft.tools.types.ToolType;

/** A contributed tool type: echoes its definition's command and counts as ready when it said so. */
public final class EchoToolType implements ToolType {
    @Override
    public ToolSpec toSpec(ToolDefinition d) {
        return ToolSpec.of(d.name(), List.of("sh", "-c", "echo echo-tool " + d.command() + "; exec sleep 300"))
                .withReadiness(Readiness.line("^echo-tool "), Duration.ofSeconds(d.readyWithinSeconds()));
    }
}
