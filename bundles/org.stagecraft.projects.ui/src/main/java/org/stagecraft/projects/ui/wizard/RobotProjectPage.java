package org.stagecraft.projects.ui.wizard;

import java.util.EnumMap;
import java.util.Map;

import org.eclipse.jdt.annotation.NonNullByDefault;
import org.eclipse.jface.dialogs.Dialog;
import org.eclipse.swt.SWT;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Group;
import org.eclipse.swt.widgets.Label;
import org.eclipse.ui.dialogs.WizardNewProjectCreationPage;
import org.stagecraft.projects.ui.RobotProjects;
import org.stagecraft.projects.ui.layout.ProgramTemplate;
import org.stagecraft.projects.ui.layout.RobotProjectLayout;

/** The project's name and location (the platform's page), and the program to start with. */
public final class RobotProjectPage extends WizardNewProjectCreationPage {
    private final Map<ProgramTemplate, Button> buttons = new EnumMap<>(ProgramTemplate.class);
    private ProgramTemplate template = ProgramTemplate.LASER_SENTINEL;

    public RobotProjectPage() {
        super("robotProject");
        setTitle("Robot Project");
        setDescription("A robot program in Python with a Stage world to run it in: Pioneer 2DX with sonar and laser.");
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public void createControl(Composite parent) {
        super.createControl(parent);
        Composite top = (Composite) getControl();
        Group group = new Group(top, SWT.NONE);
        group.setText("Program");
        group.setLayout(new GridLayout(2, false));
        group.setLayoutData(new GridData(SWT.FILL, SWT.TOP, true, false));
        for (ProgramTemplate t : ProgramTemplate.values()) {
            Button b = new Button(group, SWT.RADIO);
            b.setText(t.label());
            b.setSelection(t == template);
            b.setData(t);
            b.addListener(SWT.Selection, e -> {
                if (b.getSelection()) {
                    template = t;
                }
            });
            Label l = new Label(group, SWT.WRAP);
            l.setText(RobotProjectLayout.programPath(t) + ": " + t.description());
            l.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
            buttons.put(t, b);
        }
        Label world = new Label(top, SWT.WRAP);
        world.setText("The world: " + RobotProjectLayout.WORLD + ", with Player cfgs " + RobotProjectLayout.WINDOWED_CFG
                + " (Stage window) and " + RobotProjectLayout.HEADLESS_CFG + " (headless), each with a Robot Session launch"
                + " configuration. " + (RobotProjects.pyDevInstalled()
                        ? "PyDev is installed: the project is a PyDev project that resolves the stagecraft_player library."
                        : "PyDev is not installed: the program runs with the Python interpreter of the Stagecraft Tools preferences."));
        GridData gd = new GridData(SWT.FILL, SWT.TOP, true, false);
        gd.widthHint = 400;
        world.setLayoutData(gd);
        Dialog.applyDialogFont(top);
    }

    public ProgramTemplate template() {
        return template;
    }

    /** Selects a template (also before the controls exist). */
    public void setTemplate(ProgramTemplate t) {
        template = t;
        buttons.forEach((k, b) -> {
            if (!b.isDisposed()) {
                b.setSelection(k == t);
            }
        });
    }
}
