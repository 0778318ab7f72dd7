package dolphin.editor;

import dolphin.core.Clock;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.Consumer;
import java.util.function.Function;
import org.eclipse.lsp4j.Diagnostic;
import org.eclipse.lsp4j.PublishDiagnosticsParams;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Checks scripts as the user types, off the protocol's thread: a change waits until its document has
 * been quiet for a while (every change starts the wait again), then the latest text is checked on
 * this scheduler's own thread and its diagnostics published. All waiting is on the {@link Clock}.
 * A document closed while it is checked gets no diagnostics after the empty list its closing sent.
 */
final class DiagnosticsScheduler implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(DiagnosticsScheduler.class);

    /** The checker's thread: a deeply nested script needs a deep stack to compile. */
    private static final long STACK_BYTES = 64L << 20;

    private record PendingCheck(OpenDocument document, long dueNanos) {
    }

    private final Clock clock;
    private final long quietNanos;
    private final Function<OpenDocument, List<Diagnostic>> checker;
    private final Consumer<PublishDiagnosticsParams> publisher;
    private final ReentrantLock lock = new ReentrantLock();
    private final Condition changed = lock.newCondition();
    private final Map<String, PendingCheck> pending = new LinkedHashMap<>();
    private final Set<String> open = new HashSet<>();
    private final Clock.Wakeup wakeup;
    private final Object publishing = new Object();
    private volatile boolean stopped;
    private Thread thread;

    DiagnosticsScheduler(Clock clock, Duration quiet, Function<OpenDocument, List<Diagnostic>> checker,
                         Consumer<PublishDiagnosticsParams> publisher) {
        this.clock = clock;
        this.quietNanos = quiet.toNanos();
        this.checker = checker;
        this.publisher = publisher;
        this.wakeup = clock.newWakeup();
    }

    /** Starts the thread that checks documents as they become due. */
    void start() {
        thread = new Thread(null, this::work, "dolphin-lsp-checker", STACK_BYTES);
        thread.setDaemon(true);
        thread.start();
    }

    /** The document's new text: checked once it has been quiet for the quiet period. */
    void changed(OpenDocument document) {
        lock.lock();
        try {
            synchronized (publishing) {
                open.add(document.uri());
            }
            pending.put(document.uri(), new PendingCheck(document, clock.nanoTime() + quietNanos));
            changed.signalAll();
        } finally {
            lock.unlock();
        }
    }

    /** The document is closed: its pending check is dropped and its diagnostics cleared. */
    void closed(String uri) {
        lock.lock();
        try {
            pending.remove(uri);
        } finally {
            lock.unlock();
        }
        synchronized (publishing) {
            open.remove(uri);
            publisher.accept(new PublishDiagnosticsParams(uri, List.of()));
        }
    }

    /** Checks every document whose quiet period has passed and publishes its diagnostics; how many it checked. */
    int runDueChecks() {
        List<OpenDocument> due = new ArrayList<>();
        lock.lock();
        try {
            long now = clock.nanoTime();
            pending.values().removeIf(p -> {
                if (p.dueNanos() <= now) {
                    due.add(p.document());
                    return true;
                }
                return false;
            });
        } finally {
            lock.unlock();
        }
        for (OpenDocument d : due) {
            List<Diagnostic> diagnostics = checker.apply(d);
            synchronized (publishing) {
                if (open.contains(d.uri()) && !stopped) {
                    publisher.accept(new PublishDiagnosticsParams(d.uri(), diagnostics, d.version()));
                }
            }
        }
        return due.size();
    }

    /** Whether a change waits for its check. */
    boolean hasPending() {
        lock.lock();
        try {
            return !pending.isEmpty();
        } finally {
            lock.unlock();
        }
    }

    private void work() {
        while (!stopped) {
            try {
                long wait = nanosUntilDue();
                if (wait > 0) {
                    wakeup.await(Duration.ofNanos(wait));
                } else if (!stopped) {
                    runDueChecks();
                }
            } catch (InterruptedException e) {
                return;
            } catch (RuntimeException e) {
                // a client gone while we published, a checker bug: the next change is checked all the same
                if (!stopped) {
                    LOG.warn("checking scripts failed", e);
                }
            }
        }
    }

    /** Waits (without a clock: nothing is due) for a change, then says how long until the earliest is due. */
    private long nanosUntilDue() throws InterruptedException {
        lock.lock();
        try {
            while (pending.isEmpty() && !stopped) {
                changed.await();
            }
            long earliest = pending.values().stream().mapToLong(PendingCheck::dueNanos).min().orElse(clock.nanoTime());
            return earliest - clock.nanoTime();
        } finally {
            lock.unlock();
        }
    }

    @Override
    public void close() {
        stopped = true;
        lock.lock();
        try {
            changed.signalAll();
        } finally {
            lock.unlock();
        }
        wakeup.wake();
        if (thread != null) {
            thread.interrupt();
        }
    }
}
