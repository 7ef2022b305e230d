package org.stagecraft.tools.ui.prefs;

import org.eclipse.core.runtime.preferences.AbstractPreferenceInitializer;

/** Defaults: {@code player} and {@code python3} from the PATH; the Foxglove live view off, on 127.0.0.1:8765. */
public final class ToolPreferenceInitializer extends AbstractPreferenceInitializer {
    @Override
    public void initializeDefaultPreferences() {
        ToolPreferences.initializeDefaults();
        org.stagecraft.tools.ui.foxglove.FoxgloveLivePreferences.initializeDefaults();
    }
}
