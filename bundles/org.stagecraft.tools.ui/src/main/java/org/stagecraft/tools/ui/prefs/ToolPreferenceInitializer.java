package org.stagecraft.tools.ui.prefs;

import org.eclipse.core.runtime.preferences.AbstractPreferenceInitializer;

/** Defaults: {@code player} and {@code python3} from the PATH. */
public final class ToolPreferenceInitializer extends AbstractPreferenceInitializer {
    @Override
    public void initializeDefaultPreferences() {
        ToolPreferences.initializeDefaults();
    }
}
