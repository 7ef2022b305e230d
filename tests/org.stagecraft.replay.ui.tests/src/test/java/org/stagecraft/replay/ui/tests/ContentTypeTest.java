package org.stagecraft.replay.ui.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;

import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;

import org.eclipse.core.runtime.Platform;
import org.eclipse.core.runtime.content.IContentType;
import org.eclipse.ui.IEditorDescriptor;
import org.eclipse.ui.PlatformUI;
import org.junit.jupiter.api.Test;
import org.stagecraft.replay.ui.SessionLogEditor;

/**
 * Which files the Session Log editor takes: spy logs by extension, traces and writelog files only when
 * their first line says so (a .log or .jsonl of another kind stays with the text editor).
 */
class ContentTypeTest {
    private static String typeOf(String name, String content) throws Exception {
        IContentType t = Platform.getContentTypeManager()
                .findContentTypeFor(new ByteArrayInputStream(content.getBytes(StandardCharsets.UTF_8)), name);
        return t == null ? null : t.getId();
    }

    @Test
    void headersDecideForCommonExtensions() throws Exception {
        assertEquals("org.stagecraft.replay.ui.writelog",
                typeOf("writelog_2026_11_24_10_00.log", "## Player version 3.1.1 \n## File version 0.3.0 \n"));
        assertNotEquals("org.stagecraft.replay.ui.writelog", typeOf("build.log", "[INFO] BUILD SUCCESS\n"));
        assertEquals("org.stagecraft.replay.ui.playerTrace",
                typeOf("x.trace.jsonl", "{\"format\":\"player-trace\",\"version\":1}\n{\"t\":0.1}\n"));
        assertNotEquals("org.stagecraft.replay.ui.playerTrace", typeOf("other.jsonl", "{\"format\":\"something-else\"}\n"));
        assertEquals("org.stagecraft.replay.ui.spyLog", typeOf("session.mcap", "\u0089MCAP0\r\n"));
    }

    @Test
    void theEditorIsRegisteredUnderItsAgreedId() {
        IEditorDescriptor d = PlatformUI.getWorkbench().getEditorRegistry().findEditor(SessionLogEditor.ID);
        assertNotNull(d, "the demo opens the live spy log by this id");
        assertEquals("org.stagecraft.replay.ui.sessionLogEditor", d.getId());
        IEditorDescriptor forMcap = PlatformUI.getWorkbench().getEditorRegistry().getDefaultEditor("session.mcap");
        assertEquals(SessionLogEditor.ID, forMcap.getId());
    }
}
