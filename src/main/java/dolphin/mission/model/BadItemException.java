package dolphin.mission.model;

/**
 * An item that cannot be what its list says it is, with its index in the list, so that a file
 * reader can name the line or JSON path the item came from.
 */
public final class BadItemException extends IllegalArgumentException {

    private final int index;

    public BadItemException(int index, String message) {
        super(message);
        this.index = index;
    }

    /** The item's index in the list that was read (0 for the first). */
    public int index() {
        return index;
    }
}
