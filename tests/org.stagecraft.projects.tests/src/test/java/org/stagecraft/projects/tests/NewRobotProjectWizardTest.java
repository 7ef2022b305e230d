package org.stagecraft.projects.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.atomic.AtomicReference;

import org.eclipse.core.commands.Command;
import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.jface.viewers.StructuredSelection;
import org.eclipse.jface.wizard.WizardDialog;
import org.eclipse.swt.widgets.Display;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.ui.IEditorPart;
import org.eclipse.ui.IWorkbench;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.commands.ICommandService;
import org.eclipse.ui.wizards.IWizardDescriptor;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.stagecraft.projects.ui.layout.ProgramTemplate;
import org.stagecraft.projects.ui.wizard.NewRobotProjectWizard;

/** File &gt; New &gt; Stagecraft &gt; Robot Project as a user finishes it, and the Configure command. */
class NewRobotProjectWizardTest {
    static final String WIZARD = "org.stagecraft.projects.ui.newRobotProject";

    /** A wizard dialog whose Finish a test can press. */
    static final class Dialog extends WizardDialog {
        Dialog(Shell shell, NewRobotProjectWizard wizard) {
            super(shell, wizard);
        }

        void finish() {
            finishPressed();
        }
    }

    @BeforeEach
    @AfterEach
    void clean() throws CoreException {
        Display.getDefault().syncExec(() -> PlatformUI.getWorkbench().getActiveWorkbenchWindow().getActivePage().closeAllEditors(false));
        Projects.clean();
    }

    @Test
    void wizardIsUnderNewStagecraftAndFinishingMakesTheProjectAndOpensTheProgram() throws Exception {
        AtomicReference<Object> result = new AtomicReference<>();
        Display.getDefault().syncExec(() -> {
            try {
                IWorkbench wb = PlatformUI.getWorkbench();
                IWizardDescriptor d = wb.getNewWizardRegistry().findWizard(WIZARD);
                assertNotNull(d, "no new wizard " + WIZARD);
                assertEquals("Robot Project", d.getLabel());
                assertEquals("Stagecraft", d.getCategory().getLabel());
                NewRobotProjectWizard wizard = (NewRobotProjectWizard) d.createWizard();
                wizard.init(wb, StructuredSelection.EMPTY);
                wizard.preset("Strollers", ProgramTemplate.SUNDAY_STROLL);
                Dialog dialog = new Dialog(wb.getActiveWorkbenchWindow().getShell(), wizard);
                dialog.create();
                assertEquals("Strollers", wizard.page().getProjectName());
                assertEquals(ProgramTemplate.SUNDAY_STROLL, wizard.page().template());
                assertTrue(wizard.canFinish(), "name given, template chosen: " + wizard.page().getErrorMessage());
                dialog.finish();
                assertEquals(WizardDialog.OK, dialog.getReturnCode(), "the wizard finished");
                result.set(wizard.created());
                IEditorPart editor = wb.getActiveWorkbenchWindow().getActivePage().getActiveEditor();
                assertNotNull(editor, "the program is open in an editor");
                assertEquals(wizard.created().program(), editor.getEditorInput().getAdapter(IFile.class));
            } catch (CoreException e) {
                result.set(e);
            }
        });
        if (result.get() instanceof CoreException e) {
            throw e;
        }
        IProject p = ResourcesPlugin.getWorkspace().getRoot().getProject("Strollers");
        assertTrue(p.isOpen(), "the project exists");
        assertTrue(p.getFile("src/sunday_stroll.py").exists());
        assertTrue(p.getFile("worlds/pioneer-laser-sonar.world").exists());
        assertEquals(2, Projects.robotSessions().size());
    }

    @Test
    void wizardWithoutANameCannotFinish() {
        Display.getDefault().syncExec(() -> {
            IWorkbench wb = PlatformUI.getWorkbench();
            NewRobotProjectWizard wizard = new NewRobotProjectWizard();
            wizard.init(wb, StructuredSelection.EMPTY);
            Dialog dialog = new Dialog(wb.getActiveWorkbenchWindow().getShell(), wizard);
            dialog.create();
            try {
                assertTrue(!wizard.canFinish(), "an empty name must not finish");
            } finally {
                dialog.close();
            }
        });
        assertEquals(0, ResourcesPlugin.getWorkspace().getRoot().getProjects().length);
    }

    @Test
    void configureCommandIsDefinedAndHandled() {
        Display.getDefault().syncExec(() -> {
            ICommandService cs = PlatformUI.getWorkbench().getService(ICommandService.class);
            Command c = cs.getCommand("org.stagecraft.projects.ui.configureRobotProject");
            assertTrue(c.isDefined(), "command defined");
            try {
                assertEquals("Configure as Robot Project", c.getName());
            } catch (org.eclipse.core.commands.common.NotDefinedException e) {
                throw new AssertionError(e);
            }
            assertTrue(c.isHandled(), "a handler is active");
        });
    }
}
