package dolphin.core;

import java.util.Objects;

/** How far a task has got: UNDEFINED (not run, or stopped), IN_PROGRESS, DONE or ERROR, with a message. */
public final class CompletionState {

    public enum Type { UNDEFINED, IN_PROGRESS, DONE, ERROR }

    public static final CompletionState UNDEFINED = new CompletionState(Type.UNDEFINED, null);
    public static final CompletionState IN_PROGRESS = new CompletionState(Type.IN_PROGRESS, null);
    public static final CompletionState DONE = new CompletionState(Type.DONE, null);

    private final Type type;
    private final String message;

    public CompletionState(Type type, String message) {
        this.type = Objects.requireNonNull(type);
        this.message = message;
    }

    public static CompletionState done(String message) {
        return new CompletionState(Type.DONE, message);
    }

    public static CompletionState error(String message) {
        return new CompletionState(Type.ERROR, message);
    }

    public Type getType() {
        return type;
    }

    public String getMessage() {
        return message;
    }

    public boolean finished() {
        return type == Type.DONE || type == Type.ERROR;
    }

    public boolean isDone() {
        return type == Type.DONE;
    }

    public boolean isError() {
        return type == Type.ERROR;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof CompletionState c && c.type == type && Objects.equals(c.message, message);
    }

    @Override
    public int hashCode() {
        return Objects.hash(type, message);
    }

    @Override
    public String toString() {
        return message == null ? type.name() : type + ": " + message;
    }
}
