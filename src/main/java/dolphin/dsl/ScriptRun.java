package dolphin.dsl;

import java.time.Duration;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;

/** A script running on its own thread. */
public final class ScriptRun {

    private final String name;
    private final CompletableFuture<ScriptResult> result = new CompletableFuture<>();
    private volatile Thread thread;
    private volatile boolean stopRequested;

    ScriptRun(String name) {
        this.name = name;
    }

    public String name() {
        return name;
    }

    /** Waits for the script to end. */
    public ScriptResult await() throws InterruptedException {
        try {
            return result.get();
        } catch (ExecutionException e) {
            throw new IllegalStateException(e.getCause());
        }
    }

    /** Waits at most {@code timeout} (real time); null if the script is still running. */
    public ScriptResult await(Duration timeout) throws InterruptedException {
        try {
            return result.get(timeout.toNanos(), TimeUnit.NANOSECONDS);
        } catch (TimeoutException e) {
            return null;
        } catch (ExecutionException e) {
            throw new IllegalStateException(e.getCause());
        }
    }

    public boolean isDone() {
        return result.isDone();
    }

    /** Stops the script: running tasks are stopped (their vehicles told) and vehicles released. */
    public void stop() {
        stopRequested = true;
        Thread t = thread;
        if (t != null) {
            t.interrupt();
        }
    }

    boolean stopRequested() {
        return stopRequested;
    }

    void started(Thread t) {
        thread = t;
        if (stopRequested) {
            t.interrupt();
        }
    }

    void finish(ScriptResult r) {
        result.complete(r);
    }
}
