package dolphin.mission.flight;

import com.MAVLink.enums.MAV_RESULT;
import dolphin.mavlink.CommandResult;
import dolphin.mavlink.VehicleState;
import java.time.Duration;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.concurrent.CompletableFuture;
import java.util.function.Consumer;
import java.util.function.Function;
import java.util.function.Predicate;
import java.util.function.Supplier;

/**
 * The commands of the MissionExecutor's PREPARE and START (hold mode, DO_SET_HOME, AUTO,
 * MISSION_START), sent one after the other on a vehicle, stepped on the script thread with the
 * clock's time. A command counts as done when it is accepted, or when it went unanswered but the
 * vehicle's state shows it took effect (on a lossy link every COMMAND_ACK may be lost). A waitable
 * command refused for now (FAILED, TEMPORARILY_REJECTED: DO_SET_HOME without a position estimate) is
 * sent again after the retry pause, saying what it waits for; any other refusal is a failure.
 */
final class CommandSteps {

    /** A command: what it is (for messages), how to send it, how the vehicle's state shows it took effect. */
    record Step(String what, Supplier<CompletableFuture<CommandResult>> send, Predicate<VehicleState> effect,
                boolean waitable) {
        Step(String what, Supplier<CompletableFuture<CommandResult>> send, Predicate<VehicleState> effect) {
            this(what, send, effect, false);
        }
    }

    private final Deque<Step> steps = new ArrayDeque<>();
    private final String vehicleId;
    private final Supplier<VehicleState> vehicle;
    private final Duration retry;
    private final Consumer<String> waiting;
    private final Function<CompletableFuture<CommandResult>, CompletableFuture<CommandResult>> watch;
    private CompletableFuture<CommandResult> pending;
    private long nextAttempt = Long.MIN_VALUE;
    private String failure;

    /**
     * @param waiting told what a refused-for-now command waits for
     * @param watch applied to each command sent (the executor's wake-up when it completes)
     */
    CommandSteps(String vehicleId, Supplier<VehicleState> vehicle, Duration retry, Consumer<String> waiting,
                 Function<CompletableFuture<CommandResult>, CompletableFuture<CommandResult>> watch) {
        this.vehicleId = vehicleId;
        this.vehicle = vehicle;
        this.retry = retry;
        this.waiting = waiting;
        this.watch = watch;
    }

    void add(Step step) {
        steps.add(step);
    }

    /** Why the steps failed; null while they have not. */
    String failure() {
        return failure;
    }

    /** Sends or follows the next command at clock time {@code now}; true once every step is done. */
    boolean run(long now) {
        while (failure == null) {
            if (pending == null) {
                if (steps.isEmpty()) {
                    return true;
                }
                if (now < nextAttempt) {
                    return false;
                }
                pending = watch.apply(steps.peek().send().get());
            }
            if (!pending.isDone()) {
                return false;
            }
            CommandResult r = pending.join();
            pending = null;
            Step step = steps.peek();
            if (tookEffect(r, step.effect())) {
                steps.poll();
            } else if (step.waitable() && refusedForNow(r)) {
                waiting.accept(step.what() + " " + r.resultName()
                        + Readiness.prearmText(vehicle.get()).map(t -> " (" + t + ")").orElse(""));
                nextAttempt = now + retry.toNanos();
                return false;
            } else {
                failure = refusal(step.what(), r);
            }
        }
        return false;
    }

    /** Accepted, or unanswered while the vehicle's state shows the command took effect. */
    boolean tookEffect(CommandResult r, Predicate<VehicleState> effect) {
        return r.accepted() || (r.result() == CommandResult.NO_ACK && effect.test(vehicle.get()));
    }

    /** A refusal, or silence: a vehicle that never answered may not have heard the command at all. */
    String refusal(String what, CommandResult r) {
        return "vehicle " + vehicleId + (r.result() == CommandResult.NO_ACK
                ? " did not answer " + what + ": no COMMAND_ACK after " + r.attempts() + " attempt(s)"
                : " refused " + what + ": " + r.resultName());
    }

    private static boolean refusedForNow(CommandResult r) {
        return r.result() == MAV_RESULT.MAV_RESULT_FAILED || r.result() == MAV_RESULT.MAV_RESULT_TEMPORARILY_REJECTED;
    }
}
