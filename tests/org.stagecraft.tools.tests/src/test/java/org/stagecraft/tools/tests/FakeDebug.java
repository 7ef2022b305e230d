package org.stagecraft.tools.tests;

import java.lang.reflect.Array;
import java.lang.reflect.Proxy;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Supplier;

import org.eclipse.debug.core.DebugEvent;
import org.eclipse.debug.core.DebugPlugin;
import org.eclipse.debug.core.IDebugEventSetListener;
import org.eclipse.debug.core.ILaunch;
import org.eclipse.debug.core.model.IDebugTarget;
import org.eclipse.debug.core.model.IThread;

/**
 * A debug model of our own, standing in for PyDev's: a launch with one target and its threads, made of
 * dynamic proxies (every method not given answers false, null or an empty array), and a way to fire
 * their debug events and know that every listener has had them.
 */
final class FakeDebug {
    final ILaunch launch;
    final IDebugTarget target;
    final List<IThread> threads = new CopyOnWriteArrayList<>();
    /** Which threads say they are suspended (for a scan of a launch linked late). */
    final List<IThread> suspendedNow = new CopyOnWriteArrayList<>();
    /** How often someone asked the target to suspend (it fires nothing itself: the test does). */
    final java.util.concurrent.atomic.AtomicInteger suspendRequests = new java.util.concurrent.atomic.AtomicInteger();

    FakeDebug(int threadCount) {
        IDebugTarget[] t = new IDebugTarget[1];
        launch = fake(ILaunch.class, Map.of("getDebugTargets", () -> new IDebugTarget[] {t[0]}, "getLaunchMode",
                () -> "debug", "toString", () -> "fake launch"));
        t[0] = fake(IDebugTarget.class, Map.of("getLaunch", () -> launch, "getDebugTarget", () -> t[0], "getThreads",
                () -> threads.toArray(IThread[]::new), "hasThreads", () -> !threads.isEmpty(), "getModelIdentifier",
                () -> "org.stagecraft.tests.fake", "toString", () -> "fake target", "canSuspend", () -> true, "suspend", () -> {
                    suspendRequests.incrementAndGet();
                    return null;
                }));
        target = t[0];
        for (int i = 0; i < threadCount; i++) {
            IThread[] self = new IThread[1];
            String name = "thread " + i;
            self[0] = fake(IThread.class, Map.of("getLaunch", () -> launch, "getDebugTarget", () -> target,
                    "isSuspended", () -> suspendedNow.contains(self[0]), "getModelIdentifier", () -> "org.stagecraft.tests.fake",
                    "getName", () -> name, "toString", () -> name));
            threads.add(self[0]);
        }
    }

    @SuppressWarnings("unchecked")
    static <T> T fake(Class<T> type, Map<String, Supplier<Object>> answers) {
        return (T) Proxy.newProxyInstance(FakeDebug.class.getClassLoader(), new Class<?>[] {type}, (proxy, m, args) -> {
            Supplier<Object> a = answers.get(m.getName());
            if (a != null) {
                return a.get();
            }
            return switch (m.getName()) {
                case "equals" -> proxy == args[0];
                case "hashCode" -> System.identityHashCode(proxy);
                default -> m.getReturnType() == boolean.class ? false
                        : m.getReturnType() == int.class ? 0
                        : m.getReturnType().isArray() ? Array.newInstance(m.getReturnType().getComponentType(), 0) : null;
            };
        });
    }

    static DebugEvent event(Object source, int kind, int detail) {
        return new DebugEvent(source, kind, detail);
    }

    /**
     * Fires one event set and returns once every debug event listener has had it: the platform calls the
     * listeners one after the other, so a listener added after the session's has it last.
     */
    static void fire(DebugEvent... events) throws InterruptedException {
        java.util.concurrent.CountDownLatch seen = new java.util.concurrent.CountDownLatch(1);
        IDebugEventSetListener last = set -> {
            if (set.length == events.length && set.length > 0 && set[0] == events[0]) {
                seen.countDown();
            }
        };
        DebugPlugin.getDefault().addDebugEventListener(last);
        try {
            DebugPlugin.getDefault().fireDebugEventSet(events);
            if (!seen.await(30, java.util.concurrent.TimeUnit.SECONDS)) {
                throw new AssertionError("the debug events were not delivered within 30 s");
            }
        } finally {
            DebugPlugin.getDefault().removeDebugEventListener(last);
        }
    }
}
