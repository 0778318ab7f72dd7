package dolphin.core;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;

/**
 * The runtime a script talks to: the platform, the set of vehicles the script has bound with
 * pick, the default connection timeout and the loop that drives a task tree.
 *
 * <p>The bound set is touched by the script thread only; {@link #wake()} is the one method other
 * threads call.
 */
public final class Environment {

    /** The tick: the task tree is stepped at least this often (the original's 100 ms). */
    public static final Duration TICK = Duration.ofMillis(100);

    private final Platform platform;
    private final Clock clock;
    private final RuntimeListener listener;
    private final Clock.Wakeup wakeup;
    private final NodeSet bound = new NodeSet();
    private double defaultConnectionTimeout = Node.DEFAULT_CONNECTION_TIMEOUT;

    public Environment(Platform platform, Clock clock, RuntimeListener listener) {
        this.platform = platform;
        this.clock = clock;
        this.listener = listener;
        this.wakeup = clock.newWakeup();
        platform.setTelemetryListener(this::wake);
        platform.setVehicleEventListener(listener::vehicleEvent);
    }

    public Platform getPlatform() {
        return platform;
    }

    public Clock getClock() {
        return clock;
    }

    public RuntimeListener getListener() {
        return listener;
    }

    /** A copy of the vehicles currently bound by the script. */
    public synchronized NodeSet getBound() {
        return bound.copy();
    }

    public double getDefaultConnectionTimeout() {
        return defaultConnectionTimeout;
    }

    /** Sets the timeout given to vehicles picked from now on. */
    public void setDefaultConnectionTimeout(double seconds) {
        defaultConnectionTimeout = Node.validateConnectionTimeout(seconds);
    }

    /**
     * The script's {@code setConnectionTimeout secs}: the timeout of the vehicles it holds and of
     * those it picks from now on (docs/runtime-semantics.md): the report's Listing 1 picks its UUVs,
     * then gives them 10 minutes to dive out of contact.
     */
    public synchronized void setConnectionTimeout(double seconds) {
        setDefaultConnectionTimeout(seconds);
        for (Node n : bound) {
            n.setConnectionTimeout(defaultConnectionTimeout);
        }
    }

    /** Steps the running task tree as soon as possible (called when telemetry arrives). */
    public void wake() {
        wakeup.wake();
    }

    /**
     * Picks {@code count} free vehicles matching {@code filter}, retrying until {@code timeout}
     * seconds have passed since the first attempt (one attempt when 0), sleeping max(1 s, timeout/10), at most 60 s,
     * between attempts. Returns {@link NodeSet#EMPTY} when no attempt succeeds.
     */
    public NodeSet select(NodeFilter filter, int count, double timeout) throws InterruptedException {
        if (count <= 0) {
            throw new EnvironmentException("pick: the vehicle count must be positive, got " + count);
        }
        if (!(timeout >= 0)) { // NaN too: it would make the retry loop spin forever
            throw new EnvironmentException("pick: the timeout must not be negative, got " + timeout);
        }
        double first = clock.seconds();
        // The original's max(1 s, timeout/10), capped at a minute so long (or infinite) timeouts still retry.
        Duration pauseBetween = Duration.ofNanos((long) (Math.min(60.0, Math.max(1.0, 0.1 * timeout)) * 1e9));
        while (true) {
            NodeSet chosen = attempt(filter, count);
            if (chosen != NodeSet.EMPTY) {
                return chosen;
            }
            if (clock.seconds() - first >= timeout) {
                return NodeSet.EMPTY;
            }
            clock.sleep(pauseBetween);
        }
    }

    private synchronized NodeSet attempt(NodeFilter filter, int count) {
        NodeSet available = NodeSet.difference(platform.getConnectedNodes(), bound);
        NodeSet chosen = new NodeSet();
        for (int i = 0; i < count; i++) {
            Node match = null;
            for (Node n : available) {
                if (!chosen.contains(n) && filter.matchedBy(n)) {
                    match = n;
                    break;
                }
            }
            if (match == null) {
                return NodeSet.EMPTY;
            }
            chosen.add(match);
        }
        for (Node n : chosen) {
            n.setConnectionTimeout(defaultConnectionTimeout);
            bound.add(n);
        }
        listener.message("picked " + chosen + " from the free vehicles " + available);
        return chosen;
    }

    /** Unbinds vehicles so they can be picked again; nothing is sent to them. */
    public synchronized void release(NodeSet vehicles) {
        bound.removeAll(vehicles);
    }

    /** Releases every bound vehicle, calling {@link Node#release()} on each. */
    public void releaseAll() {
        List<Node> nodes;
        synchronized (this) {
            nodes = new ArrayList<>();
            bound.forEach(nodes::add);
            bound.clear();
        }
        for (Node n : nodes) {
            try {
                n.release();
            } catch (RuntimeException e) {
                listener.message("releasing vehicle " + n.getId() + " failed: " + e.getMessage());
            }
        }
    }

    public void pause(double seconds) throws InterruptedException {
        clock.sleep(Duration.ofNanos((long) (seconds * 1e9)));
    }

    /**
     * Allocates vehicles from the bound set, runs the task to completion on this thread and
     * returns its final state. A root ERROR is reported to the listener (the original dropped it). An
     * interrupt or an exception from the tree stops the tree first, so vehicles are told.
     */
    public CompletionState run(Task task) throws InterruptedException {
        Allocation allocation = new Allocation();
        if (!task.allocate(getBound(), allocation)) {
            String why = allocation.failure();
            throw new EnvironmentException("no vehicles to run task " + task.getId()
                    + (why == null ? "" : ": " + why) + " (bound vehicles: " + getBound() + ")");
        }
        TaskExecutor executor = task.getExecutor();
        executor.initialize(new TaskContext(clock, listener), allocation);
        listener.executeStarted(TaskTree.of(executor));
        long nextTick = clock.nanoTime();
        try {
            executor.start();
            while (true) {
                CompletionState cs = executor.step();
                if (executor.isCompleted()) {
                    if (cs.isError()) {
                        listener.message("task " + task.getId() + " ended in ERROR: " + cs.getMessage());
                    }
                    return cs;
                }
                long now = clock.nanoTime();
                if (now >= nextTick) {
                    // this step was the tick; a step made early by wake() keeps the tick it came before
                    nextTick += TICK.toNanos();
                    if (nextTick < now) {
                        nextTick = now;
                    }
                }
                wakeup.await(Duration.ofNanos(nextTick - now));
            }
        } catch (InterruptedException | RuntimeException | Error e) {
            executor.stop();
            throw e;
        }
    }
}
