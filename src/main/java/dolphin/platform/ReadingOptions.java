package dolphin.platform;

import dolphin.dsl.DslException;
import java.time.Duration;
import java.util.Map;

/**
 * The options of {@code sensor}, {@code sensorKnown} and {@code telemetry}: {@code maxAge} in seconds
 * (instead of the sensor's freshness limit) and {@code component}, the MAVLink component id to read
 * from (when several components send the same name).
 */
record ReadingOptions(Duration maxAge, Integer component) {

    static ReadingOptions of(String word, Map<String, Object> options) {
        Duration maxAge = null;
        Integer component = null;
        for (Map.Entry<String, Object> e : options.entrySet()) {
            switch (e.getKey()) {
                case "maxAge" -> {
                    if (!(e.getValue() instanceof Number n) || !(n.doubleValue() > 0) || Double.isInfinite(n.doubleValue())) {
                        throw new DslException(word + ": maxAge must be a positive number of seconds, got " + e.getValue());
                    }
                    maxAge = Duration.ofNanos((long) (n.doubleValue() * 1e9));
                }
                case "component" -> {
                    if (!(e.getValue() instanceof Integer c) || c < 0 || c > 255) {
                        throw new DslException(word + ": component must be a MAVLink component id from 0 to 255, got " + e.getValue());
                    }
                    component = c;
                }
                default -> throw new DslException(word + ": unknown option '" + e.getKey() + "' (expected maxAge, component)");
            }
        }
        return new ReadingOptions(maxAge, component);
    }

    long maxAgeNanos(long sensorFreshNanos) {
        return maxAge == null ? sensorFreshNanos : maxAge.toNanos();
    }
}
