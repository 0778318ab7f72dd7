package dolphin.cli;

import dolphin.core.Clock;
import dolphin.core.TaskEvent;
import dolphin.core.VehicleEvent;
import dolphin.dsl.EngineListener;
import dolphin.dsl.ScriptResult;
import dolphin.mavlink.MAVLinkNode;
import java.time.Duration;
import java.util.List;
import java.util.Locale;
import java.util.function.Supplier;

/**
 * What `dolphin run` prints: the script's messages, its platform tasks' events, the vehicles' events
 * and the vehicles' status, on a {@link Screen}. A display thread refreshes the status every
 * {@link #PERIOD} of the display clock (real time: it paces what a person reads, whatever the
 * speed-up of the run).
 */
final class RunConsole implements EngineListener, AutoCloseable {

    static final Duration PERIOD = Duration.ofMillis(250);

    private final Screen screen;
    private final StatusBoard board = new StatusBoard();
    private final Supplier<List<MAVLinkNode>> nodes;
    private final Clock displayClock;
    private final Thread display;
    private volatile boolean running = true;
    /** Keeps a task's line and its vehicles' status together, without a refresh or a vehicle event's line between them. */
    private final Object showing = new Object();

    RunConsole(Screen screen, Supplier<List<MAVLinkNode>> nodes, Clock displayClock) {
        this.screen = screen;
        this.nodes = nodes;
        this.displayClock = displayClock;
        this.display = new Thread(this::displayLoop, "dolphin status");
        display.setDaemon(true);
    }

    /** The timestamp of a line: seconds of the run's clock since the run started. */
    static Supplier<String> stamp(Clock clock) {
        double start = clock.seconds();
        return () -> String.format(Locale.ROOT, "[%8.1f s] ", clock.seconds() - start);
    }

    void start() {
        display.start();
    }

    /** Shows the status now (the display thread does this every period). */
    void refresh() {
        synchronized (showing) {
            screen.refresh(board.statuses(nodes.get()));
        }
    }

    private void displayLoop() {
        try {
            while (running) {
                refresh();
                displayClock.sleep(PERIOD);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    @Override
    public void message(String text) {
        screen.line(text);
    }

    @Override
    public void taskEvent(TaskEvent event) {
        if (!event.isPlatformTask()) {
            return;
        }
        synchronized (showing) {
            board.taskEvent(event);
            screen.line("task " + event.task().getId() + " " + event.kind().name().toLowerCase(Locale.ROOT)
                    + (event.vehicles().isEmpty() ? "" : " on vehicle " + String.join(",", event.vehicles()))
                    + (event.kind() == TaskEvent.Kind.COMPLETED ? ": " + event.state() : ""));
            List<MAVLinkNode> onIt = nodes.get().stream().filter(n -> event.vehicles().contains(n.getId())).toList();
            screen.taskChanged(board.statuses(onIt));
        }
    }

    /** On the thread that raised it (the communications thread for contact): the screens are synchronized. */
    @Override
    public void vehicleEvent(VehicleEvent event) {
        synchronized (showing) {
            screen.line(event.line());
        }
    }

    @Override
    public void scriptFinished(String name, ScriptResult result) {
        refresh();
        screen.line(name + ": " + result.outcome().name().toLowerCase(Locale.ROOT)
                + (result.message() == null ? "" : " (" + result.message() + ")"));
    }

    /** Stops the display thread; the last status stays on the screen. */
    @Override
    public void close() throws InterruptedException {
        running = false;
        display.interrupt();
        display.join(2000);
    }
}
