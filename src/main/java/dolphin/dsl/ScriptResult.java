package dolphin.dsl;

/** How a script run ended. */
public record ScriptResult(Outcome outcome, String message, ScriptError error) {

    public enum Outcome {
        /** The script ran to its end and every executed task finished DONE. */
        COMPLETED,
        /** The script ran to its end, but an executed task ended in ERROR. */
        TASK_ERROR,
        /** {@code halt}, or a pick that found no vehicles. */
        HALTED,
        /** A compile-time or run-time mistake in the script; see {@link #error()}. */
        SCRIPT_ERROR,
        /** Stopped from outside ({@link ScriptRun#stop()}). */
        STOPPED
    }

    /** 0 when completed, 1 otherwise (the command line's convention). */
    public int exitCode() {
        return outcome == Outcome.COMPLETED ? 0 : 1;
    }

    @Override
    public String toString() {
        return outcome + (error != null ? ": " + error : message != null ? ": " + message : "");
    }
}
