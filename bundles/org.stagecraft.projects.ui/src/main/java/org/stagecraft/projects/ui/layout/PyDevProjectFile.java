package org.stagecraft.projects.ui.layout;

import java.io.IOException;
import java.io.StringReader;
import java.io.StringWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Predicate;

import javax.xml.XMLConstants;
import javax.xml.parsers.DocumentBuilder;
import javax.xml.parsers.DocumentBuilderFactory;
import javax.xml.parsers.ParserConfigurationException;
import javax.xml.transform.OutputKeys;
import javax.xml.transform.Transformer;
import javax.xml.transform.TransformerException;
import javax.xml.transform.TransformerFactory;
import javax.xml.transform.dom.DOMSource;
import javax.xml.transform.stream.StreamResult;

import org.eclipse.jdt.annotation.Nullable;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.Node;
import org.w3c.dom.NodeList;
import org.xml.sax.InputSource;
import org.xml.sax.SAXException;

/**
 * A PyDev project file ({@code .pydevproject}), read and written without PyDev: the XML in which
 * PyDev keeps a project's source folders ({@value #SOURCE_PATH}), external libraries
 * ({@value #EXTERNAL_SOURCE_PATH}), interpreter and grammar. Entries of others are kept as they are.
 *
 * <pre>
 * &lt;?xml version="1.0" encoding="UTF-8" standalone="no"?&gt;
 * &lt;?eclipse-pydev version="1.0"?&gt;
 * &lt;pydev_project&gt;
 *   &lt;pydev_pathproperty name="org.python.pydev.PROJECT_SOURCE_PATH"&gt;
 *     &lt;path&gt;/${PROJECT_DIR_NAME}/src&lt;/path&gt;
 *   &lt;/pydev_pathproperty&gt;
 *   &lt;pydev_pathproperty name="org.python.pydev.PROJECT_EXTERNAL_SOURCE_PATH"&gt;
 *     &lt;path&gt;/.../plugins/org.stagecraft.python_0.1.0.v.../python/src&lt;/path&gt;
 *   &lt;/pydev_pathproperty&gt;
 *   &lt;pydev_property name="org.python.pydev.PYTHON_PROJECT_VERSION"&gt;python interpreter&lt;/pydev_property&gt;
 *   &lt;pydev_property name="org.python.pydev.PYTHON_PROJECT_INTERPRETER"&gt;Default&lt;/pydev_property&gt;
 * &lt;/pydev_project&gt;
 * </pre>
 */
public final class PyDevProjectFile {
    public static final String FILE_NAME = ".pydevproject";
    public static final String SOURCE_PATH = "org.python.pydev.PROJECT_SOURCE_PATH";
    public static final String EXTERNAL_SOURCE_PATH = "org.python.pydev.PROJECT_EXTERNAL_SOURCE_PATH";
    /** The grammar: "python 3.12" and so on, or "python interpreter" (the interpreter's own version). */
    public static final String PROJECT_VERSION = "org.python.pydev.PYTHON_PROJECT_VERSION";
    /** The interpreter by its name in PyDev's preferences, or "Default". */
    public static final String PROJECT_INTERPRETER = "org.python.pydev.PYTHON_PROJECT_INTERPRETER";
    public static final String VERSION_OF_INTERPRETER = "python interpreter";
    public static final String DEFAULT_INTERPRETER = "Default";
    /** PyDev replaces this by the project's folder name in source paths. */
    public static final String PROJECT_DIR = "${PROJECT_DIR_NAME}";

    private static final String ROOT = "pydev_project";
    private static final String PATH_PROPERTY = "pydev_pathproperty";
    private static final String PROPERTY = "pydev_property";
    private static final String PATH = "path";

    private final Document doc;

    private PyDevProjectFile(Document doc) {
        this.doc = doc;
    }

    /** A file with no entries yet. */
    public static PyDevProjectFile empty() {
        Document d = builder().newDocument();
        d.appendChild(d.createProcessingInstruction("eclipse-pydev", "version=\"1.0\""));
        d.appendChild(d.createElement(ROOT));
        return new PyDevProjectFile(d);
    }

    /** An existing file's text; an {@link IOException} saying what is wrong if it is not a PyDev project file. */
    public static PyDevProjectFile parse(String xml) throws IOException {
        Document d;
        try {
            d = builder().parse(new InputSource(new StringReader(xml)));
        } catch (SAXException e) {
            throw new IOException(FILE_NAME + " is not well-formed XML: " + e.getMessage(), e);
        }
        if (!ROOT.equals(d.getDocumentElement().getNodeName())) {
            throw new IOException(FILE_NAME + " has root element <" + d.getDocumentElement().getNodeName()
                    + ">, not <" + ROOT + ">");
        }
        return new PyDevProjectFile(d);
    }

    /** The source path entry for a folder of the project ("" for the project folder itself). */
    public static String sourcePath(String folder) {
        return "/" + PROJECT_DIR + (folder == null || folder.isEmpty() ? "" : "/" + folder);
    }

    /**
     * Whether {@code path} is where a Stagecraft install keeps its Python client: the
     * {@code python/src} folder of some version of the bundle {@code org.stagecraft.python}. Such
     * entries are replaced when the client moves (a new version of the IDE).
     */
    public static boolean isStagecraftClientPath(String path) {
        String p = path.replace('\\', '/');
        while (p.endsWith("/")) {
            p = p.substring(0, p.length() - 1);
        }
        return p.endsWith("/python/src") && p.contains("org.stagecraft.python");
    }

    /**
     * Stagecraft's settings: {@code sourceFolder} as a source folder unless the project has source
     * folders already, the Python client folder as the one Stagecraft client library (replacing an
     * older one), and interpreter and grammar "Default"/"python interpreter" unless set.
     *
     * @param clientFolder absolute path of the client's folder, or null if it is not installed
     * @return whether anything changed
     */
    public boolean configure(String sourceFolder, @Nullable String clientFolder) {
        boolean changed = false;
        if (paths(SOURCE_PATH).isEmpty()) {
            changed |= addPath(SOURCE_PATH, sourcePath(sourceFolder));
        }
        if (clientFolder != null) {
            changed |= removePaths(EXTERNAL_SOURCE_PATH, p -> isStagecraftClientPath(p) && !p.equals(clientFolder)) > 0;
            changed |= addPath(EXTERNAL_SOURCE_PATH, clientFolder);
        }
        changed |= setPropertyIfAbsent(PROJECT_VERSION, VERSION_OF_INTERPRETER);
        changed |= setPropertyIfAbsent(PROJECT_INTERPRETER, DEFAULT_INTERPRETER);
        return changed;
    }

    /** The paths of a path property, in order (empty if there is none). */
    public List<String> paths(String property) {
        List<String> out = new ArrayList<>();
        Element p = find(PATH_PROPERTY, property);
        if (p != null) {
            for (Element path : children(p, PATH)) {
                out.add(path.getTextContent().trim());
            }
        }
        return out;
    }

    /** Adds a path at the end of a path property (made if needed); false if it is there already. */
    public boolean addPath(String property, String path) {
        if (paths(property).contains(path)) {
            return false;
        }
        Element p = find(PATH_PROPERTY, property);
        if (p == null) {
            p = doc.createElement(PATH_PROPERTY);
            p.setAttribute("name", property);
            doc.getDocumentElement().appendChild(p);
        }
        Element e = doc.createElement(PATH);
        e.setTextContent(path);
        p.appendChild(e);
        return true;
    }

    /** Removes the paths of a property that match; how many. */
    public int removePaths(String property, Predicate<String> which) {
        Element p = find(PATH_PROPERTY, property);
        int n = 0;
        if (p != null) {
            for (Element path : children(p, PATH)) {
                if (which.test(path.getTextContent().trim())) {
                    p.removeChild(path);
                    n++;
                }
            }
        }
        return n;
    }

    /** A plain property's value, or null. */
    public @Nullable String property(String name) {
        Element p = find(PROPERTY, name);
        return p == null ? null : p.getTextContent().trim();
    }

    /** Sets a plain property unless it has a value; whether it was set. */
    public boolean setPropertyIfAbsent(String name, String value) {
        if (property(name) != null && !property(name).isEmpty()) {
            return false;
        }
        Element p = find(PROPERTY, name);
        if (p == null) {
            p = doc.createElement(PROPERTY);
            p.setAttribute("name", name);
            doc.getDocumentElement().appendChild(p);
        }
        p.setTextContent(value);
        return true;
    }

    /** The file's text (UTF-8 XML, indented). */
    public String toXml() {
        try {
            stripWhitespace(doc.getDocumentElement());
            TransformerFactory f = TransformerFactory.newInstance();
            f.setAttribute(XMLConstants.ACCESS_EXTERNAL_DTD, "");
            f.setAttribute(XMLConstants.ACCESS_EXTERNAL_STYLESHEET, "");
            Transformer t = f.newTransformer();
            t.setOutputProperty(OutputKeys.ENCODING, "UTF-8");
            t.setOutputProperty(OutputKeys.INDENT, "yes");
            t.setOutputProperty("{http://xml.apache.org/xslt}indent-amount", "2");
            StringWriter w = new StringWriter();
            t.transform(new DOMSource(doc), new StreamResult(w));
            // the JDK writes the processing instruction on the declaration's line
            return w.toString().replace("?><?eclipse-pydev", "?>\n<?eclipse-pydev").replace("?><" + ROOT, "?>\n<" + ROOT);
        } catch (TransformerException e) {
            throw new IllegalStateException("cannot write " + FILE_NAME + ": " + e.getMessage(), e);
        }
    }

    private @Nullable Element find(String element, String name) {
        for (Element e : children(doc.getDocumentElement(), element)) {
            if (name.equals(e.getAttribute("name"))) {
                return e;
            }
        }
        return null;
    }

    private static List<Element> children(Element parent, String name) {
        List<Element> out = new ArrayList<>();
        NodeList nodes = parent.getChildNodes();
        for (int i = 0; i < nodes.getLength(); i++) {
            if (nodes.item(i) instanceof Element e && name.equals(e.getNodeName())) {
                out.add(e);
            }
        }
        return out;
    }

    /** Whitespace-only text between elements goes, so that indenting the output does not add more. */
    private static void stripWhitespace(Element e) {
        NodeList nodes = e.getChildNodes();
        for (int i = nodes.getLength() - 1; i >= 0; i--) {
            Node n = nodes.item(i);
            if (n.getNodeType() == Node.TEXT_NODE && n.getTextContent().isBlank() && nodes.getLength() > 1) {
                e.removeChild(n);
            } else if (n instanceof Element child) {
                stripWhitespace(child);
            }
        }
    }

    private static DocumentBuilder builder() {
        try {
            DocumentBuilderFactory f = DocumentBuilderFactory.newInstance();
            f.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
            f.setXIncludeAware(false);
            f.setExpandEntityReferences(false);
            DocumentBuilder b = f.newDocumentBuilder();
            b.setErrorHandler(new org.xml.sax.helpers.DefaultHandler()); // errors become exceptions, not stderr
            return b;
        } catch (ParserConfigurationException e) {
            throw new IllegalStateException(e);
        }
    }
}
