package org.stagecraft.pydev.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IMarker;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.runtime.NullProgressMonitor;
import org.eclipse.jface.text.Document;
import org.eclipse.jface.text.IDocument;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.python.pydev.ast.analysis.messages.IMessage;
import org.python.pydev.ast.codecompletion.revisited.modules.AbstractModule;
import org.python.pydev.ast.codecompletion.revisited.modules.SourceModule;
import org.python.pydev.core.autoedit.DefaultIndentPrefs;
import org.python.pydev.plugin.nature.PythonNature;
import org.stagecraft.projects.ui.RobotProjects;
import org.stagecraft.projects.ui.layout.ProgramTemplate;
import org.stagecraft.tests.support.ErrorLogGuard.LogsErrors;

import com.python.pydev.analysis.AnalysisPreferences;
import com.python.pydev.analysis.OccurrencesAnalyzer;

/**
 * Issue 24, item 1: the program of a new Robot Project shows no error in PyDev the moment it is
 * created. Each template's program goes through PyDev's own code analysis (the analyzer behind its
 * problem markers), in the PyDev project the wizard's operation makes; a file with a real error shows
 * that the analysis runs and reports.
 */
// PyDev logs its first analysis of a new project as an ERROR ("Info: Rebuilding internal caches"): PyDev's, not ours
@LogsErrors({ "^org\\.python\\.pydev\\.shared_core: Info: Rebuilding internal caches" })
class TemplateAnalysisTest {
    private final List<IProject> projects = new ArrayList<>();

    @BeforeAll
    static void pyDevWithPython3() throws Exception {
        PyDevInterpreter.configure(PyDevInterpreter.onPath("python3"));
    }

    @AfterEach
    void deleteProjects() throws Exception {
        for (IProject p : projects) {
            p.delete(true, true, new NullProgressMonitor());
        }
    }

    @ParameterizedTest
    @EnumSource(ProgramTemplate.class)
    void aNewRobotProjectsProgramHasNoErrorInPyDevsAnalysis(ProgramTemplate template) throws Exception {
        RobotProjects.Created created = create("Analysed" + template.name(), template);
        assertEquals(List.of(), errors(created.program()), template + ": " + created.program().getFullPath());
    }

    @Test
    void theAnalysisReportsAnUndefinedName() throws Exception {
        RobotProjects.Created created = create("AnalysedControl", ProgramTemplate.EMPTY);
        IFile broken = created.program().getParent().getFile(new org.eclipse.core.runtime.Path("broken.py"));
        broken.create(new ByteArrayInputStream("print(no_such_name)\n".getBytes(StandardCharsets.UTF_8)), true, null);
        List<String> errors = errors(broken);
        assertTrue(errors.stream().anyMatch(e -> e.contains("Undefined variable: no_such_name")), errors.toString());
    }

    private RobotProjects.Created create(String name, ProgramTemplate template) throws Exception {
        RobotProjects.Created created = RobotProjects.create(new RobotProjects.Spec(name, null, template), null);
        projects.add(created.project());
        assertTrue(created.project().hasNature(PythonNature.PYTHON_NATURE_ID), "a PyDev project");
        return created;
    }

    /** What PyDev's analysis of {@code file} reports as errors: "line N: message". */
    private static List<String> errors(IFile file) throws Exception {
        PythonNature nature = PythonNature.getPythonNature(file.getProject());
        Await.until("PyDev's nature of " + file.getProject().getName() + " is ready", Duration.ofMinutes(2),
                () -> nature != null && nature.isOkToUse() && nature.getAstManager() != null, () -> "");
        String text = new String(file.getContents().readAllBytes(), StandardCharsets.UTF_8);
        IDocument doc = new Document(text);
        String module = file.getName().replaceFirst("\\.py$", "");
        SourceModule source = AbstractModule.createModuleFromDoc(module, file.getLocation().toFile(), doc, nature, true);
        IMessage[] messages = new OccurrencesAnalyzer().analyzeDocument(nature, source, new AnalysisPreferences(file), doc,
                new NullProgressMonitor(), DefaultIndentPrefs.get(file));
        List<String> errors = new ArrayList<>();
        for (IMessage m : messages) {
            if (m.getSeverity() == IMarker.SEVERITY_ERROR) {
                errors.add("line " + m.getStartLine(doc) + ": " + m.getMessage());
            }
        }
        return errors;
    }
}
