package org.stagecraft.tools.types;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.stagecraft.tools.process.Readiness;
import org.stagecraft.tools.process.RestartPolicy;
import org.stagecraft.tools.process.ToolSpec;

/** A user's text fields become what is run, or an error naming the tool and the field. */
class GenericToolTypeTest {
    private final GenericToolType type = new GenericToolType();

    private static ToolDefinition def(String command, String args, String readiness, String restart) {
        return new ToolDefinition("sim", null, command, args, "", Map.of(), readiness, restart, 12, true);
    }

    @Test
    void argumentsAreSplitLikeAShellDoes() {
        assertEquals(List.of("-a", "two words", "it's", "x\"y", "back\\slash", "end"),
                CommandLine.split("  -a \"two words\" \"it's\" 'x\"y' back\\\\slash end "));
        assertEquals(List.of(""), CommandLine.split("''"));
        assertEquals(List.of(), CommandLine.split("   "));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> CommandLine.split("a \"b"));
        assertTrue(e.getMessage().contains("unclosed \""), e.getMessage());
    }

    @Test
    void aDefinitionBecomesASpec() {
        ToolSpec s = type.toSpec(new ToolDefinition("stage", null, "stage", "-g 'my world.world'", "/tmp/w",
                Map.of("K", "v"), "port:localhost:6670,6671", "always:2", 12, true));
        assertEquals(List.of("stage", "-g", "my world.world"), s.command());
        assertEquals(Path.of("/tmp/w"), s.workingDir());
        assertEquals(Map.of("K", "v"), s.environment());
        assertEquals(new Readiness.PortsOpen("localhost", List.of(6670, 6671)), s.readiness());
        assertEquals(RestartPolicy.always(2), s.restart());
        assertEquals(Duration.ofSeconds(12), s.readyWithin());
        assertEquals(new Readiness.PortsOpen("127.0.0.1", List.of(7000)), GenericToolType.readiness(def("x", "", "port:7000", "")));
        assertEquals("a line matching 'up and running'",
                GenericToolType.readiness(def("x", "", "line:up and running", "")).describe());
        assertEquals(new Readiness.Started(), type.toSpec(def("x", "", "", "")).readiness());
        assertNull(type.toSpec(def("x", "", "", "")).workingDir());
    }

    @Test
    void mistakesNameTheToolAndTheField() {
        assertEquals("tool 'sim': no command given",
                assertThrows(IllegalArgumentException.class, () -> type.toSpec(def(" ", "", "", ""))).getMessage());
        assertTrue(assertThrows(IllegalArgumentException.class, () -> type.toSpec(def("x", "", "when ready", "")))
                .getMessage().startsWith("tool 'sim': readiness 'when ready' is not"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> type.toSpec(def("x", "", "line:(", "")))
                .getMessage().startsWith("tool 'sim': readiness 'line:('"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> type.toSpec(def("x", "", "", "sometimes")))
                .getMessage().startsWith("tool 'sim': restart policy 'sometimes'"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> type.toSpec(def("x", "'a", "", "")))
                .getMessage().startsWith("tool 'sim': arguments: unclosed '"));
    }
}
