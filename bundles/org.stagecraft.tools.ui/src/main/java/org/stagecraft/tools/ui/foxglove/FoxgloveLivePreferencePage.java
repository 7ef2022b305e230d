package org.stagecraft.tools.ui.foxglove;

import org.eclipse.jdt.annotation.NonNullByDefault;
import org.eclipse.jdt.annotation.Nullable;
import org.eclipse.jface.preference.PreferencePage;
import org.eclipse.swt.SWT;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Text;
import org.eclipse.ui.IWorkbench;
import org.eclipse.ui.IWorkbenchPreferencePage;
import org.osgi.service.prefs.BackingStoreException;

/** Preferences &gt; Stagecraft Tools &gt; Foxglove Live: on/off and the address ([ADDR:]PORT). */
public final class FoxgloveLivePreferencePage extends PreferencePage implements IWorkbenchPreferencePage {
    private @Nullable Button enabled;
    private @Nullable Text address;

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public void init(IWorkbench workbench) {
        setDescription("Serve the live streams of the workbench (every Robot Session's spy) over the Foxglove WebSocket"
                + " protocol: in Foxglove or Lichtblick, open a Foxglove WebSocket connection to ws://localhost:PORT.");
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    protected Control createContents(Composite parent) {
        Composite c = new Composite(parent, SWT.NONE);
        c.setLayout(new GridLayout(2, false));
        enabled = new Button(c, SWT.CHECK);
        enabled.setText("Serve the live streams to Foxglove");
        enabled.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false, 2, 1));
        enabled.setSelection(FoxgloveLivePreferences.enabled());
        new Label(c, SWT.NONE).setText("Address ([ADDR:]PORT; loopback unless an address is given):");
        address = new Text(c, SWT.BORDER);
        address.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
        address.setText(FoxgloveLivePreferences.addressText());
        address.addModifyListener(e -> validate());
        return c;
    }

    private void validate() {
        try {
            FoxgloveLivePreferences.parse(address.getText());
            setErrorMessage(null);
            setValid(true);
        } catch (IllegalArgumentException e) {
            setErrorMessage(e.getMessage());
            setValid(false);
        }
    }

    @Override
    protected void performDefaults() {
        enabled.setSelection(false);
        address.setText(FoxgloveLivePreferences.DEFAULT_ADDRESS);
        super.performDefaults();
    }

    @Override
    public boolean performOk() {
        try {
            FoxgloveLive.get().followPreferences();
            FoxgloveLivePreferences.set(enabled.getSelection(), address.getText().trim());
            return true;
        } catch (BackingStoreException e) {
            setErrorMessage("cannot save: " + e.getMessage());
            return false;
        }
    }
}
