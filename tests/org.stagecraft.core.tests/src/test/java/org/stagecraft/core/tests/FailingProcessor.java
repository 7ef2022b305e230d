package org.stagecraft.core.tests;

import org.stagecraft.streams.ProcessorContext;
import org.stagecraft.streams.StreamProcessor;

/** Contributed through plugin.xml; its start throws, which must be reported and not stop the others. */
public final class FailingProcessor implements StreamProcessor {
    @Override
    public void start(ProcessorContext ctx) {
        throw new IllegalStateException("no sonar configured");
    }
}
