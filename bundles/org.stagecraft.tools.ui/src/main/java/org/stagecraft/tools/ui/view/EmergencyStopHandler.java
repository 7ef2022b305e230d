package org.stagecraft.tools.ui.view;

import java.util.Map;

import org.eclipse.core.commands.AbstractHandler;
import org.eclipse.core.commands.ExecutionEvent;
import org.eclipse.jdt.annotation.NonNullByDefault;
import org.eclipse.jdt.annotation.Nullable;
import org.eclipse.ui.commands.IElementUpdater;
import org.eclipse.ui.menus.UIElement;
import org.stagecraft.tools.ui.CommandButtons;
import org.stagecraft.tools.ui.launch.EmergencyStop;

/**
 * The emergency stop button (Tools view and Robot View toolbars): toggles {@link EmergencyStop}; the
 * button shows whether it is engaged, and its tooltip what pressing it does and what it cannot stop.
 */
public final class EmergencyStopHandler extends AbstractHandler implements IElementUpdater {
    public static final String COMMAND = "org.stagecraft.tools.ui.emergencyStop";

    /** The stop changes on other threads (a session starting, another button): buttons follow on the UI thread. */
    private final Runnable refresh = CommandButtons.refresher(COMMAND);

    public EmergencyStopHandler() {
        EmergencyStop.get().addListener(refresh);
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public @Nullable Object execute(ExecutionEvent event) {
        EmergencyStop.get().toggle();
        refresh.run(); // a toggle on an unchanged set of sessions still flips the button
        return null;
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public void updateElement(UIElement element, @SuppressWarnings("rawtypes") Map parameters) {
        EmergencyStop stop = EmergencyStop.get();
        element.setChecked(stop.isEngaged());
        element.setText(stop.isEngaged() ? "Release Robots" : "Emergency Stop");
        element.setTooltip(stop.tooltip());
    }

    @Override
    public void dispose() {
        EmergencyStop.get().removeListener(refresh);
        super.dispose();
    }
}
