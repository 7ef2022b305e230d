package org.stagecraft.tools.ui.foxglove;

import java.util.Map;

import org.eclipse.core.commands.AbstractHandler;
import org.eclipse.core.commands.ExecutionEvent;
import org.eclipse.core.commands.ExecutionException;
import org.eclipse.jdt.annotation.NonNullByDefault;
import org.eclipse.jdt.annotation.Nullable;
import org.eclipse.ui.commands.IElementUpdater;
import org.eclipse.ui.menus.UIElement;
import org.stagecraft.tools.ui.CommandButtons;
import org.osgi.service.prefs.BackingStoreException;

/**
 * The "Foxglove Live" toolbar toggle: turns the preference on or off ({@link FoxgloveLive} follows it);
 * the button shows whether the live streams are being served, and its tooltip where, or why not.
 */
public final class FoxgloveLiveHandler extends AbstractHandler implements IElementUpdater {
    public static final String COMMAND = "org.stagecraft.tools.ui.foxgloveLive";

    private final Runnable refresh = CommandButtons.refresher(COMMAND);

    public FoxgloveLiveHandler() {
        FoxgloveLive.get().addListener(refresh);
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public @Nullable Object execute(ExecutionEvent event) throws ExecutionException {
        FoxgloveLive.get().followPreferences();
        try {
            FoxgloveLivePreferences.setEnabled(!FoxgloveLivePreferences.enabled());
        } catch (BackingStoreException e) {
            throw new ExecutionException("cannot save the Foxglove live preference: " + e.getMessage(), e);
        }
        refresh.run();
        return null;
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public void updateElement(UIElement element, @SuppressWarnings("rawtypes") Map parameters) {
        FoxgloveLive live = FoxgloveLive.get();
        element.setChecked(live.isServing());
        element.setTooltip(live.isServing() ? "Serving the live streams to Foxglove at " + live.uri() + " (press to stop)"
                : live.problem() != null ? live.problem()
                        : "Serve the live streams to Foxglove or Lichtblick at " + FoxgloveLivePreferences.addressText());
    }

    @Override
    public void dispose() {
        FoxgloveLive.get().removeListener(refresh);
        super.dispose();
    }
}
