package dolphin.core;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.function.Consumer;

/**
 * What a vehicle platform (MAVLink, a test platform, ...) gives the runtime. Platforms that extend
 * the script language also implement {@code dolphin.dsl.DslExtension}.
 */
public interface Platform {

    /** A short name for messages, e.g. "MAVLink". */
    String getName();

    /** The nodes that can be picked now: connected ones only. Iteration order is pick order. */
    NodeSet getConnectedNodes();

    /** A task known to the platform by name ({@code task 'id'} in scripts). */
    default Task getPlatformTask(String id) {
        throw new EnvironmentException("the " + getName() + " platform has no named tasks: task '" + id + "'");
    }

    /**
     * Called by the environment with a callback to run whenever telemetry that conditions may read
     * arrives, so the task tree is stepped at once instead of at the next tick.
     */
    default void setTelemetryListener(Runnable onTelemetry) {
    }

    /**
     * Called by the environment with where the platform's {@link VehicleEvent}s go, replacing the one
     * given before. The platform calls it on whichever thread notices the event, with or without a
     * script running; a platform without such events ignores it.
     */
    default void setVehicleEventListener(Consumer<VehicleEvent> listener) {
    }

    /** Reads one line for {@code ask}; by default from standard input, which stays open for later asks. */
    default String askForInput(String prompt) {
        System.out.println(prompt);
        try {
            return StdinHolder.READER.readLine();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** Releases the platform's resources (sockets, threads). */
    default void close() {
    }

    /** One shared reader, so a second {@code ask} still reads (the original closed standard input after the first). */
    final class StdinHolder {
        static final BufferedReader READER = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));

        private StdinHolder() {
        }
    }
}
