package dolphin.core;

/** A runtime error a script cannot recover from: bad arguments, no vehicles for a task, an interrupt. */
public class EnvironmentException extends RuntimeException {
    public EnvironmentException(String message) {
        super(message);
    }

    public EnvironmentException(String message, Throwable cause) {
        super(message, cause);
    }
}
