package dolphin.core;

/** A vehicle (or any networked asset) a script can pick and task. */
public interface Node {

    double MIN_CONNECTION_TIMEOUT = 5;
    double MAX_CONNECTION_TIMEOUT = 3600;
    double DEFAULT_CONNECTION_TIMEOUT = 20;

    /** Unique among the platform's nodes; for MAVLink the decimal system id. */
    String getId();

    /** A name the user gave the node (a fleet file's), else its id; {@code pick { id 'scout' }} matches either. */
    default String getName() {
        return getId();
    }

    /** "UAV", "UGV", "USV", "UUV", ... */
    String getType();

    /** The last known position, or null while none is known. */
    Position getPosition();

    Payload getPayload();

    /** Called when the engine lets go of the node at the end of a script. */
    void release();

    /** Seconds without contact after which the node counts as lost. */
    double getConnectionTimeout();

    void setConnectionTimeout(double seconds);

    /** Heard from within its connection timeout. A lost node cannot be picked and its tasks fail. */
    boolean isConnected();

    /** Checks a connection timeout against the allowed range of 5 to 3600 s. */
    static double validateConnectionTimeout(double seconds) {
        if (!(seconds >= MIN_CONNECTION_TIMEOUT && seconds <= MAX_CONNECTION_TIMEOUT)) {
            throw new EnvironmentException(String.format(
                    "connection timeout must be between %.0f and %.0f seconds, got %s",
                    MIN_CONNECTION_TIMEOUT, MAX_CONNECTION_TIMEOUT, seconds));
        }
        return seconds;
    }
}
