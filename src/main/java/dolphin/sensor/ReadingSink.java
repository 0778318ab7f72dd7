package dolphin.sensor;

/** Where a {@link Sensor} puts the readings it finds in a message. */
@FunctionalInterface
public interface ReadingSink {

    /**
     * @param name the reading's name, as scripts ask for it: {@code sensor(v, 'NAME')}
     * @param value its value, in {@code unit}
     * @param unit its unit, "" when unknown
     */
    void put(String name, double value, String unit);

    default void put(String name, double value) {
        put(name, value, "");
    }
}
