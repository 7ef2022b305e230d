package org.stagecraft.projects.ui.layout;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.StringReader;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import javax.xml.parsers.DocumentBuilderFactory;

import org.junit.jupiter.api.Test;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.Node;
import org.w3c.dom.NodeList;
import org.xml.sax.InputSource;

/** .pydevproject as PyDev reads it, checked with a separate XML parse of the written text. */
class PyDevProjectFileTest {
    private static final String CLIENT = "/opt/stagecraft/plugins/org.stagecraft.python_0.1.0.v20261125/python/src";
    private static final String OLD_CLIENT = "/opt/stagecraft/plugins/org.stagecraft.python_0.1.0.v20260101/python/src";

    @Test
    void newFileHasSourceFolderClientLibraryAndInterpreterDefaults() throws Exception {
        PyDevProjectFile f = PyDevProjectFile.empty();
        assertTrue(f.configure("src", CLIENT));
        String xml = f.toXml();
        Document d = dom(xml);
        assertEquals("pydev_project", d.getDocumentElement().getNodeName());
        assertTrue(xml.contains("<?eclipse-pydev version=\"1.0\"?>"), xml);
        assertEquals(Map.of(PyDevProjectFile.SOURCE_PATH, List.of("/${PROJECT_DIR_NAME}/src"),
                PyDevProjectFile.EXTERNAL_SOURCE_PATH, List.of(CLIENT)), pathProperties(d));
        assertEquals(Map.of("org.python.pydev.PYTHON_PROJECT_VERSION", "python interpreter",
                "org.python.pydev.PYTHON_PROJECT_INTERPRETER", "Default"), properties(d));
    }

    @Test
    void projectFolderAsSourceWhenNoFolderIsGiven() throws Exception {
        PyDevProjectFile f = PyDevProjectFile.empty();
        f.configure("", null);
        Map<String, List<String>> paths = pathProperties(dom(f.toXml()));
        assertEquals(List.of("/${PROJECT_DIR_NAME}"), paths.get(PyDevProjectFile.SOURCE_PATH));
        assertNull(paths.get(PyDevProjectFile.EXTERNAL_SOURCE_PATH), "no client folder, no library: " + paths);
    }

    @Test
    void configuringAgainChangesNothing() throws Exception {
        PyDevProjectFile f = PyDevProjectFile.empty();
        f.configure("src", CLIENT);
        String first = f.toXml();
        PyDevProjectFile again = PyDevProjectFile.parse(first);
        assertFalse(again.configure("src", CLIENT));
        assertEquals(first, again.toXml());
    }

    @Test
    void existingSettingsAreKeptAndAnOldClientIsReplaced() throws Exception {
        String existing = """
                <?xml version="1.0" encoding="UTF-8" standalone="no"?>
                <?eclipse-pydev version="1.0"?><pydev_project>
                <pydev_pathproperty name="org.python.pydev.PROJECT_SOURCE_PATH">
                <path>/${PROJECT_DIR_NAME}/lib</path>
                </pydev_pathproperty>
                <pydev_pathproperty name="org.python.pydev.PROJECT_EXTERNAL_SOURCE_PATH">
                <path>/home/me/numpy-stubs</path>
                <path>%s</path>
                </pydev_pathproperty>
                <pydev_property name="org.python.pydev.PYTHON_PROJECT_INTERPRETER">python3.12</pydev_property>
                <pydev_variables_property name="org.python.pydev.PROJECT_VARIABLE_SUBSTITUTION">
                <key>ROBOT</key>
                <value>r0</value>
                </pydev_variables_property>
                </pydev_project>
                """.formatted(OLD_CLIENT);
        PyDevProjectFile f = PyDevProjectFile.parse(existing);
        assertTrue(f.configure("src", CLIENT));
        Document d = dom(f.toXml());
        Map<String, List<String>> paths = pathProperties(d);
        assertEquals(List.of("/${PROJECT_DIR_NAME}/lib"), paths.get(PyDevProjectFile.SOURCE_PATH), "the user's source folder stays alone");
        assertEquals(List.of("/home/me/numpy-stubs", CLIENT), paths.get(PyDevProjectFile.EXTERNAL_SOURCE_PATH));
        assertEquals("python3.12", properties(d).get(PyDevProjectFile.PROJECT_INTERPRETER), "the user's interpreter stays");
        assertEquals("python interpreter", properties(d).get(PyDevProjectFile.PROJECT_VERSION));
        NodeList vars = d.getElementsByTagName("pydev_variables_property");
        assertEquals(1, vars.getLength(), "other entries are kept");
        assertEquals("r0", ((Element) vars.item(0)).getElementsByTagName("value").item(0).getTextContent());
    }

    @Test
    void recognisesStagecraftClientFoldersOnly() {
        assertTrue(PyDevProjectFile.isStagecraftClientPath(CLIENT));
        assertTrue(PyDevProjectFile.isStagecraftClientPath("/work/checkout/bundles/org.stagecraft.python/python/src/"));
        assertTrue(PyDevProjectFile.isStagecraftClientPath("C:\\eclipse\\plugins\\org.stagecraft.python_0.1.0\\python\\src"));
        assertFalse(PyDevProjectFile.isStagecraftClientPath("/home/me/python/src"));
        assertFalse(PyDevProjectFile.isStagecraftClientPath("/opt/org.stagecraft.python/python/src/stagecraft_player"));
    }

    @Test
    void brokenFilesAreRefusedWithTheReason() {
        IOException notXml = assertThrows(IOException.class, () -> PyDevProjectFile.parse("<pydev_project>"));
        assertTrue(notXml.getMessage().startsWith(".pydevproject is not well-formed XML"), notXml.getMessage());
        IOException wrongRoot = assertThrows(IOException.class, () -> PyDevProjectFile.parse("<projectDescription/>"));
        assertTrue(wrongRoot.getMessage().contains("<projectDescription>") && wrongRoot.getMessage().contains("<pydev_project>"),
                wrongRoot.getMessage());
    }

    private static Document dom(String xml) throws Exception {
        return DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(new InputSource(new StringReader(xml)));
    }

    private static Map<String, List<String>> pathProperties(Document d) {
        Map<String, List<String>> out = new LinkedHashMap<>();
        NodeList props = d.getDocumentElement().getElementsByTagName("pydev_pathproperty");
        for (int i = 0; i < props.getLength(); i++) {
            Element p = (Element) props.item(i);
            List<String> paths = new ArrayList<>();
            NodeList children = p.getChildNodes();
            for (int j = 0; j < children.getLength(); j++) {
                Node c = children.item(j);
                if (c instanceof Element e) {
                    assertEquals("path", e.getNodeName());
                    paths.add(e.getTextContent());
                }
            }
            assertNull(out.put(p.getAttribute("name"), paths), "one element per property");
        }
        return out;
    }

    private static Map<String, String> properties(Document d) {
        Map<String, String> out = new LinkedHashMap<>();
        NodeList props = d.getDocumentElement().getElementsByTagName("pydev_property");
        for (int i = 0; i < props.getLength(); i++) {
            Element p = (Element) props.item(i);
            out.put(p.getAttribute("name"), p.getTextContent());
        }
        return out;
    }
}
