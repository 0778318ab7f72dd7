package dolphin.core;

/** What executors need from the environment they run in. */
public record TaskContext(Clock clock, RuntimeListener listener) {
}
