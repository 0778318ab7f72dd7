package dolphin.sensor;

/**
 * One value a vehicle sent under a name, as a sensor read it from a message.
 *
 * @param name what the value is (NAMED_VALUE_FLOAT's name, or the name a sensor class gives it)
 * @param value the value as sent; NaN or infinite values are kept, and refused when a script reads them
 * @param unit its unit ("m", "degC", ...), or "" when the sender does not say
 * @param component the MAVLink component id that sent it
 * @param source the message it came in, e.g. "NAMED_VALUE_FLOAT"
 * @param nanos clock time it arrived
 * @param freshNanos how long it counts as the sensor's current value (the sensor's freshness limit)
 */
public record Reading(String name, double value, String unit, int component, String source, long nanos, long freshNanos) {

    public double ageSeconds(long now) {
        return (now - nanos) / 1e9;
    }

    public boolean fresh(long now) {
        return now - nanos <= freshNanos;
    }

    public boolean finite() {
        return Double.isFinite(value);
    }
}
