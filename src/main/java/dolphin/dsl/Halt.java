package dolphin.dsl;

/** Thrown by {@code halt} and by a pick that finds no vehicles: the script ends and its vehicles are released. */
public final class Halt extends RuntimeException {
    public Halt(String message) {
        super(message, null, false, false);
    }
}
