package org.stagecraft.projects.ui.wizard;

import java.lang.reflect.InvocationTargetException;
import java.net.URI;
import java.util.concurrent.atomic.AtomicReference;

import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.jdt.annotation.NonNullByDefault;
import org.eclipse.jdt.annotation.Nullable;
import org.eclipse.jface.dialogs.ErrorDialog;
import org.eclipse.jface.viewers.IStructuredSelection;
import org.eclipse.jface.wizard.Wizard;
import org.eclipse.ui.IEditorDescriptor;
import org.eclipse.ui.INewWizard;
import org.eclipse.ui.IWorkbench;
import org.eclipse.ui.IWorkbenchPage;
import org.eclipse.ui.IWorkbenchWindow;
import org.eclipse.ui.PartInitException;
import org.eclipse.ui.ide.IDE;
import org.eclipse.ui.wizards.newresource.BasicNewResourceWizard;
import org.stagecraft.projects.ui.RobotProjects;
import org.stagecraft.projects.ui.layout.ProgramTemplate;

/** File &gt; New &gt; Stagecraft &gt; Robot Project: {@link RobotProjects#create} with what the page asks. */
public final class NewRobotProjectWizard extends Wizard implements INewWizard {
    /** The text editor, by id (org.eclipse.ui.editors), for .py files when no editor is registered for them. */
    static final String TEXT_EDITOR = "org.eclipse.ui.DefaultTextEditor";

    private @Nullable IWorkbench workbench;
    private @Nullable RobotProjectPage page;
    private RobotProjects.@Nullable Created created;
    private @Nullable String presetName;
    private @Nullable ProgramTemplate presetTemplate;

    public NewRobotProjectWizard() {
        setWindowTitle("New Robot Project");
        setNeedsProgressMonitor(true);
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public void init(IWorkbench wb, IStructuredSelection selection) {
        this.workbench = wb;
    }

    @Override
    public void addPages() {
        page = new RobotProjectPage();
        if (presetName != null) {
            page.setInitialProjectName(presetName);
        }
        if (presetTemplate != null) {
            page.setTemplate(presetTemplate);
        }
        addPage(page);
    }

    public @Nullable RobotProjectPage page() {
        return page;
    }

    /** What the last finish made, or null. */
    public RobotProjects.@Nullable Created created() {
        return created;
    }

    @Override
    public boolean performFinish() {
        URI location = page.useDefaults() ? null : page.getLocationURI();
        RobotProjects.Spec spec;
        try {
            spec = new RobotProjects.Spec(page.getProjectName(), location, page.template());
        } catch (IllegalArgumentException e) {
            page.setErrorMessage(e.getMessage());
            return false;
        }
        AtomicReference<RobotProjects.Created> result = new AtomicReference<>();
        try {
            getContainer().run(true, false, monitor -> {
                try {
                    result.set(RobotProjects.create(spec, monitor));
                } catch (CoreException e) {
                    throw new InvocationTargetException(e);
                }
            });
        } catch (InvocationTargetException e) {
            IStatus status = e.getCause() instanceof CoreException ce ? ce.getStatus()
                    : org.eclipse.core.runtime.Status.error(String.valueOf(e.getCause()), e.getCause());
            ErrorDialog.openError(getShell(), "New Robot Project", "Could not create " + spec.name(), status);
            return false;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return false;
        }
        created = result.get();
        show(created);
        return true;
    }

    private void show(RobotProjects.Created c) {
        IWorkbench wb = workbench != null ? workbench : org.eclipse.ui.PlatformUI.getWorkbench();
        IWorkbenchWindow window = wb.getActiveWorkbenchWindow();
        if (window == null) {
            return;
        }
        BasicNewResourceWizard.selectAndReveal(c.program(), window);
        IWorkbenchPage p = window.getActivePage();
        if (p == null) {
            return;
        }
        // never the system editor: an external program for .py files is not what the user asked for
        IEditorDescriptor d = wb.getEditorRegistry().getDefaultEditor(c.program().getName());
        String editor = d != null && d.isInternal() ? d.getId() : TEXT_EDITOR;
        try {
            IDE.openEditor(p, c.program(), editor);
        } catch (PartInitException e) {
            RobotProjectsUi.log(e.getStatus());
        }
    }

    /** The name and template the page starts with; call before the wizard's dialog is created. */
    public void preset(String projectName, ProgramTemplate template) {
        presetName = projectName;
        presetTemplate = template;
    }
}
