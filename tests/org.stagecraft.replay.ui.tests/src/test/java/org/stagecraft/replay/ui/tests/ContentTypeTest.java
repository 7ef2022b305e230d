package org.stagecraft.replay.ui.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;

import java.io.ByteArrayInputStream;
import java.io.StringReader;
import java.nio.charset.StandardCharsets;

import org.eclipse.core.runtime.Platform;
import org.eclipse.core.runtime.content.IContentDescriber;
import org.eclipse.core.runtime.content.IContentType;
import org.eclipse.ui.IEditorDescriptor;
import org.eclipse.ui.PlatformUI;
import org.junit.jupiter.api.Test;
import org.stagecraft.replay.log.LogFormat;
import org.stagecraft.replay.log.SessionLogs;
import org.stagecraft.replay.ui.SessionLogEditor;
import org.stagecraft.replay.ui.internal.HeaderDescriber;

/**
 * Which files the Session Log editor takes: spy logs by extension, traces and writelog files only when
 * the core ({@code SessionLogs.formatOf}) recognises their first bytes (a .log or .jsonl of another kind stays with the text editor).
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
    void everyLogTheCoreCanOpenIsOfferedToTheEditor() throws Exception {
        // writelog data without Player's "##" header lines: the core opens it, so the editor takes it
        String bare = "# a comment\n\n0.5 0 6665 sonar 0 1 1 1 0.5\n";
        assertEquals(java.util.Optional.of(LogFormat.WRITELOG), SessionLogs.formatOf(bare.getBytes(StandardCharsets.US_ASCII)));
        assertEquals("org.stagecraft.replay.ui.writelog", typeOf("sonar.log", bare));
        // a trace header whose keys are spaced differently: the core's rule, not an exact string
        String spaced = "{ \"format\" : \"player-trace\", \"version\": 1 }\n";
        assertEquals(java.util.Optional.of(LogFormat.PLAYER_TRACE), SessionLogs.formatOf(spaced.getBytes(StandardCharsets.UTF_8)));
        assertEquals("org.stagecraft.replay.ui.playerTrace", typeOf("spaced.jsonl", spaced));
        // the text variant (an open document) decides the same
        HeaderDescriber writelog = new HeaderDescriber(LogFormat.WRITELOG);
        assertEquals(IContentDescriber.VALID, writelog.describe(new StringReader(bare), null));
        assertEquals(IContentDescriber.INVALID, writelog.describe(new StringReader("[INFO] BUILD SUCCESS\n"), null));
        assertEquals(IContentDescriber.INVALID, new HeaderDescriber(LogFormat.PLAYER_TRACE).describe(new StringReader(bare), null));
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
