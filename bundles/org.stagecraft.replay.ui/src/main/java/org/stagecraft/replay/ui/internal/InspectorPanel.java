package org.stagecraft.replay.ui.internal;

import org.stagecraft.views.RobotDataBreakpointCommand;
import java.io.IOException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;

import org.eclipse.jdt.annotation.Nullable;
import org.eclipse.jface.resource.JFaceResources;
import org.eclipse.jface.viewers.ColumnLabelProvider;
import org.eclipse.jface.viewers.TreeViewer;
import org.eclipse.jface.viewers.TreeViewerColumn;
import org.eclipse.swt.SWT;
import org.eclipse.swt.custom.SashForm;
import org.eclipse.swt.graphics.Color;
import org.stagecraft.replay.log.HoldMarks;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Table;
import org.eclipse.swt.widgets.TableColumn;
import org.eclipse.swt.widgets.TableItem;
import org.eclipse.swt.widgets.Text;
import org.stagecraft.replay.analysis.HexDump;
import org.stagecraft.replay.analysis.InspectorRow;
import org.stagecraft.replay.analysis.MessageColumns;
import org.stagecraft.replay.analysis.MessageFilter;
import org.stagecraft.replay.analysis.MessageWindow;
import org.stagecraft.replay.log.LogMessage;
import org.stagecraft.replay.log.SessionLog;
import org.stagecraft.replay.session.SharedLog;

/**
 * The packet inspector: a virtual table of a {@link MessageWindow} (a few hundred filtered entries
 * around the replay position, read in the background with a cursor), filter fields (streams, free
 * text), and for the selected entry its decoded field tree and hex dump. Selecting a row hands the
 * entry to {@code onSelect} (the editor moves the replay there). Problems and gaps are marked in red.
 */
public final class InspectorPanel {
    /** Rows read on each side of the anchor, and entries skipped at most looking for them. */
    public static final int HALF_WINDOW = 200, SCAN_LIMIT = 200_000;

    private final Composite root;
    private final Text streams, text;
    private final Label status;
    private final Table table;
    private final TreeViewer fields;
    private final Text hex;
    private final ExecutorService reader;
    private final Consumer<LogMessage> onSelect;
    private final java.util.function.LongSupplier replayPosition;
    private final AtomicLong generation = new AtomicLong();
    private final Color marked = new Color(255, 222, 222);
    /** The robot hold's colour (as on the timeline): program messages held back from Player. */
    private final Color heldBack = new Color(226, 214, 248);
    private final Color breakpointHit = new Color(255, 205, 205);
    private volatile HoldMarks holds = HoldMarks.none();
    private @Nullable SharedLog shared;
    private @Nullable SessionLog log;
    private MessageColumns columns;
    private MessageFilter filter;
    private MessageWindow window = new MessageWindow(java.util.List.of(), 0, true, true);
    private boolean loading;
    /** The newest {@link #follow} that came while reading, or null. */
    private @Nullable Followed pendingFollow;
    /** The replay position the current window was read around. */
    private long readAt;
    private @Nullable LogMessage detailed;

    /**
     * @param replayPosition where the replay is now (a new filter reads its window there)
     * @param onSelect       told about a row the user chose
     */
    public InspectorPanel(Composite parent, MessageColumns columns, ExecutorService reader,
            java.util.function.LongSupplier replayPosition, Consumer<LogMessage> onSelect) {
        this.columns = columns;
        this.replayPosition = replayPosition;
        this.reader = reader;
        this.onSelect = onSelect;
        this.filter = MessageFilter.all(columns);
        root = new Composite(parent, SWT.NONE);
        root.setLayout(new GridLayout(1, false));

        Composite bar = new Composite(root, SWT.NONE);
        bar.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
        bar.setLayout(new GridLayout(7, false));
        new Label(bar, SWT.NONE).setText("Streams:");
        streams = new Text(bar, SWT.BORDER | SWT.SEARCH);
        streams.setMessage("laser:0, position2d * or type=1 dev=6");
        streams.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
        new Label(bar, SWT.NONE).setText("Text:");
        text = new Text(bar, SWT.BORDER | SWT.SEARCH);
        text.setMessage("subtype, device, summary\u2026");
        text.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
        Button earlier = new Button(bar, SWT.PUSH);
        earlier.setText("\u25C0 Earlier");
        Button later = new Button(bar, SWT.PUSH);
        later.setText("Later \u25B6");
        status = new Label(bar, SWT.NONE);
        status.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
        status.setText("");
        streams.addListener(SWT.DefaultSelection, e -> applyFilter());
        text.addListener(SWT.DefaultSelection, e -> applyFilter());
        earlier.addListener(SWT.Selection, e -> pageEarlier());
        later.addListener(SWT.Selection, e -> pageLater());

        SashForm split = new SashForm(root, SWT.HORIZONTAL);
        split.setLayoutData(new GridData(SWT.FILL, SWT.FILL, true, true));
        table = new Table(split, SWT.VIRTUAL | SWT.FULL_SELECTION | SWT.SINGLE | SWT.BORDER);
        table.setHeaderVisible(true);
        table.setLinesVisible(true);
        int[] widths = { 90, 150, 40, 100, 80, 110, 50, 420 };
        for (int i = 0; i < MessageColumns.TITLES.length; i++) {
            TableColumn c = new TableColumn(table, i == 6 ? SWT.RIGHT : SWT.LEFT);
            c.setText(MessageColumns.TITLES[i]);
            c.setWidth(widths[i]);
        }
        table.addListener(SWT.SetData, e -> fill((TableItem) e.item, table.indexOf((TableItem) e.item)));
        table.addListener(SWT.Selection, e -> rowSelected(table.getSelectionIndex()));

        SashForm detail = new SashForm(split, SWT.VERTICAL);
        fields = new TreeViewer(detail, SWT.BORDER | SWT.FULL_SELECTION);
        fields.getTree().setHeaderVisible(true);
        TreeViewerColumn name = new TreeViewerColumn(fields, SWT.LEFT);
        name.getColumn().setText("Field");
        name.getColumn().setWidth(160);
        name.setLabelProvider(ColumnLabelProvider.createTextProvider(FieldTreeContent::name));
        TreeViewerColumn value = new TreeViewerColumn(fields, SWT.LEFT);
        value.getColumn().setText("Value");
        value.getColumn().setWidth(160);
        value.setLabelProvider(ColumnLabelProvider.createTextProvider(FieldTreeContent::value));
        fields.setContentProvider(new FieldTreeContent());
        fields.getTree().setMenu(breakpointMenu());
        hex = new Text(detail, SWT.MULTI | SWT.READ_ONLY | SWT.V_SCROLL | SWT.H_SCROLL | SWT.BORDER);
        hex.setFont(JFaceResources.getTextFont());
        detail.setWeights(55, 45);
        split.setWeights(62, 38);
    }

    /** The fields' context menu: a robot data breakpoint on the field, starting from the value it has here. */
    private org.eclipse.swt.widgets.Menu breakpointMenu() {
        org.eclipse.swt.widgets.Menu menu = new org.eclipse.swt.widgets.Menu(fields.getTree());
        org.eclipse.swt.widgets.MenuItem add = new org.eclipse.swt.widgets.MenuItem(menu, SWT.PUSH);
        add.setText("Add Robot Data Breakpoint...");
        menu.addListener(SWT.Show, e -> add.setEnabled(breakpointText() != null));
        add.addListener(SWT.Selection, e -> {
            String text = breakpointText();
            if (text != null) {
                RobotDataBreakpointCommand.ask(text, status::setText);
            }
        });
        return menu;
    }

    /**
     * The robot data breakpoint offered for the selected field ({@code laser:0 min(ranges) < 0.287}), or null: only
     * messages from Player can stop a program, and only fields that hold numbers.
     */
    public @Nullable String breakpointText() {
        LogMessage m = detailed;
        org.eclipse.swt.widgets.TreeItem[] sel = fields.getTree().getSelection();
        if (m == null || m.decoded() == null || m.dir() != org.stagecraft.player.wire.Direction.SERVER_TO_CLIENT || sel.length != 1) {
            return null;
        }
        java.util.ArrayDeque<String> names = new java.util.ArrayDeque<>();
        for (org.eclipse.swt.widgets.TreeItem i = sel[0]; i != null; i = i.getParentItem()) {
            names.push(String.valueOf(FieldTreeContent.name(i.getData())));
        }
        StringBuilder path = new StringBuilder();
        for (String n : names) {
            path.append(n.startsWith("[") || path.isEmpty() ? "" : ".").append(n);
        }
        org.stagecraft.replay.fields.Field f = FieldTreeContent.fieldOf(sel[0].getData());
        org.stagecraft.player.wire.MessageHeader h = m.decoded().header();
        String iface = org.stagecraft.core.extensions.Contributions.workbench().codecs().interfaceName(h.interf());
        return f == null || iface == null ? null : org.stagecraft.replay.fields.BreakpointText.of(iface, h, path.toString(), f);
    }

    public Composite control() {
        return root;
    }

    public Table table() {
        return table;
    }

    public MessageWindow window() {
        return window;
    }

    public MessageFilter filter() {
        return filter;
    }

    public TreeViewer fields() {
        return fields;
    }

    public String hexText() {
        return hex.getText();
    }

    public String statusText() {
        return status.getText();
    }

    /** The entry whose fields and bytes are shown. */
    public @Nullable LogMessage detailed() {
        return detailed;
    }

    /**
     * A new (or reloaded) log; pages around {@code position}. Reads hold the log ({@link SharedLog}),
     * so a reload that replaces it does not close it under a read still running.
     */
    public void setLog(SharedLog newLog, long position) {
        shared = newLog;
        log = newLog.log();
        window = new MessageWindow(java.util.List.of(), 0, true, true);
        table.setItemCount(0);
        pageAround(position, null);
    }

    /** Sets the filter fields and applies them (the same as typing and pressing Enter). */
    public void setFilter(String streamText, String freeText) {
        streams.setText(streamText);
        text.setText(freeText);
        applyFilter();
    }

    private void applyFilter() {
        try {
            filter = MessageFilter.of(streams.getText(), text.getText(), columns);
        } catch (IllegalArgumentException e) {
            status.setText(e.getMessage());
            status.getParent().layout();
            return;
        }
        pageAround(replayPosition.getAsLong(), null);
    }

    /**
     * The replay moved to {@code position} after publishing {@code last}: selects its row, reading a
     * new window when the position left the one held.
     */
    public void follow(long position, @Nullable LogMessage last) {
        if (log == null) {
            return;
        }
        if (loading) {
            // a read is under way: the newest place the replay moved to is followed once it is shown
            // (dropped, a seek made while reading left the inspector where the read was)
            pendingFollow = new Followed(position, last);
            return;
        }
        // an empty window (a sparse filter) is read again only once the replay has moved on a second:
        // each read may skip up to SCAN_LIMIT entries on each side
        boolean outside = window.isEmpty() ? !(window.atStart() && window.atEnd()) && Math.abs(position - readAt) > 1_000_000_000L
                : (position < window.rows().get(0).message().timeNanos() && !window.atStart())
                        || (position > window.rows().get(window.rows().size() - 1).message().timeNanos() && !window.atEnd());
        if (outside) {
            pageAround(position, last);
            return;
        }
        select(last);
    }

    private void select(@Nullable LogMessage last) {
        int i = window.indexOf(last);
        if (i >= 0 && last != null) { // found: not null
            table.setSelection(i);
            table.showSelection();
            // once more after the layout this frame may still do (the status line, a resize): GTK scrolls to
            // the row against the size the table had when asked, which left it just below a small table
            table.getDisplay().asyncExec(() -> {
                if (!table.isDisposed() && table.getSelectionIndex() == i) {
                    table.showSelection();
                }
            });
            showDetails(last);
        } else {
            table.deselectAll();
        }
    }

    private void pageEarlier() {
        if (!window.isEmpty() && log != null) {
            pageAround(window.rows().get(0).message(), false);
        }
    }

    private void pageLater() {
        if (!window.isEmpty() && log != null) {
            pageAround(window.rows().get(window.rows().size() - 1).message(), true);
        }
    }

    /** A window ending (earlier) or starting (later) at an entry. */
    private void pageAround(LogMessage edge, boolean later) {
        SharedLog s = shared;
        MessageFilter f = filter;
        load(s, l -> later ? MessageWindow.around(l, f, edge, 0, 2 * HALF_WINDOW, SCAN_LIMIT)
                : MessageWindow.around(l, f, edge, 2 * HALF_WINDOW, 1, SCAN_LIMIT), null);
    }

    private void pageAround(long position, @Nullable LogMessage last) {
        SharedLog s = shared;
        if (s == null) {
            return;
        }
        MessageFilter f = filter;
        readAt = position;
        load(s, l -> MessageWindow.around(l, f, position, HALF_WINDOW, HALF_WINDOW, SCAN_LIMIT), last);
    }

    private interface WindowRead {
        MessageWindow read(SessionLog log) throws IOException;
    }

    /** Reads a window off the UI thread; only the newest request's result is shown. */
    private void load(@Nullable SharedLog s, WindowRead read, @Nullable LogMessage select) {
        long g = generation.incrementAndGet();
        loading = true;
        status.setText("reading\u2026");
        var display = table.getDisplay();
        reader.execute(() -> {
            if (!s.acquire()) {
                return; // replaced and closed meanwhile: the new log's own read is on its way
            }
            MessageWindow w;
            String error = null;
            try {
                w = read.read(s.log());
            } catch (IOException | RuntimeException e) {
                w = null;
                error = "cannot read the log: " + e.getMessage();
            } finally {
                s.release();
            }
            MessageWindow result = w;
            String problem = error;
            if (!display.isDisposed()) {
                display.asyncExec(() -> shown(g, result, problem, select));
            }
        });
    }

    private void shown(long g, @Nullable MessageWindow w, @Nullable String error, @Nullable LogMessage select) {
        if (table.isDisposed() || g != generation.get()) {
            return;
        }
        loading = false;
        Followed pending = pendingFollow;
        pendingFollow = null;
        if (w == null) {
            status.setText(error);
            return;
        }
        window = w;
        table.clearAll();
        table.setItemCount(w.rows().size());
        status.setText(describe(w));
        status.getParent().layout();
        if (select != null) {
            select(select);
        } else if (w.anchorIndex() < w.rows().size()) {
            table.setTopIndex(Math.max(0, w.anchorIndex() - 5));
        }
        if (pending != null) {
            follow(pending.position(), pending.last());
        }
    }

    /** Where the replay moved while a read was under way. */
    private record Followed(long position, @Nullable LogMessage last) {
    }

    private String describe(MessageWindow w) {
        if (w.isEmpty()) {
            return w.atStart() && w.atEnd() ? "no entry matches " + filter
                    : "no match within " + SCAN_LIMIT + " entries; move the replay or change the filter";
        }
        long start = log.startNanos();
        return w.rows().size() + " entries, " + MessageColumns.time(w.rows().get(0).message().timeNanos(), start) + " to "
                + MessageColumns.time(w.rows().get(w.rows().size() - 1).message().timeNanos(), start) + " s"
                + (w.atStart() ? ", from the start" : "") + (w.atEnd() ? ", to the end" : "");
    }

    private void fill(TableItem item, int index) {
        if (index < 0 || index >= window.rows().size()) {
            return;
        }
        InspectorRow row = window.rows().get(index);
        String[] cells = columns.row(row.message(), log.startNanos());
        if (row.gapBytes() > 0) {
            cells[7] = "[" + row.gapBytes() + " bytes missing before] " + cells[7];
        }
        boolean own = row.message().kind() == LogMessage.Kind.HOLD; // what Stagecraft did: its text says so
        boolean held = !own && holds.heldBack(row.message());
        if (held) {
            cells[7] = "[held back from Player by the robot hold] " + cells[7];
        }
        boolean broke = !own && holds.triggeredBreak(row.message());
        if (broke) {
            cells[7] = "[a robot data breakpoint stopped here] " + cells[7];
        }
        item.setText(cells);
        if (row.marked()) {
            item.setBackground(marked);
        } else if (broke) {
            item.setBackground(breakpointHit);
        } else if (held || own) {
            item.setBackground(heldBack);
        }
    }

    /** The log's robot holds: held-back program messages get their own colour and a note. */
    public void setHolds(HoldMarks marks) {
        holds = marks == null ? HoldMarks.none() : marks;
        if (!table.isDisposed()) {
            table.clearAll();
        }
    }

    /** Whether row {@code index} is shown as the message a robot data breakpoint stopped at (for tests). */
    public boolean rowTriggeredBreak(int index) {
        return index >= 0 && index < window.rows().size() && holds.triggeredBreak(window.rows().get(index).message());
    }

    /** Whether row {@code index} is shown as held back (for tests). */
    public boolean rowHeldBack(int index) {
        return index >= 0 && index < window.rows().size() && holds.heldBack(window.rows().get(index).message());
    }

    /** Selects row {@code index} as a user would (tests: the same path as a click). */
    public void selectRow(int index) {
        table.setSelection(index);
        rowSelected(index);
    }

    private void rowSelected(int index) {
        if (index < 0 || index >= window.rows().size()) {
            return;
        }
        LogMessage m = window.rows().get(index).message();
        showDetails(m);
        if (m.kind() != LogMessage.Kind.HOLD) { // a hold's row is no recorded message: the replay stays where it is
            onSelect.accept(m);
        }
    }

    private void showDetails(LogMessage m) {
        if (m == detailed) {
            return;
        }
        detailed = m;
        if (m.decoded() != null && m.decoded().body() != null) {
            fields.setInput(FieldTreeContent.input(m.decoded().body()));
            fields.expandToLevel(2);
        } else {
            fields.setInput(null);
        }
        String head = m.isProblem() ? "problem: " + columns.summary(m) + "\n\n" : "";
        hex.setText(head + HexDump.of(m.bytes()));
    }
}
