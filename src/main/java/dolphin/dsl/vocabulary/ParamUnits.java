package dolphin.dsl.vocabulary;

import java.util.Map;
import java.util.Set;

/**
 * The unit of a word's number parameter, by its name: one name, one meaning across the language
 * (a {@code radius} is always metres, a {@code pitch} always degrees). A number parameter whose name
 * is in neither table fails the vocabulary test, so a new word cannot leave its units unsaid.
 */
final class ParamUnits {

    private static final Map<String, String> UNITS = Map.ofEntries(
            Map.entry("lat", "degrees"), Map.entry("lon", "degrees"), Map.entry("degrees", "degrees"),
            Map.entry("pitch", "degrees"), Map.entry("yaw", "degrees"),
            Map.entry("hae", "metres above mean sea level"), Map.entry("height", "metres above mean sea level"),
            Map.entry("north", "metres"), Map.entry("east", "metres"), Map.entry("up", "metres"),
            Map.entry("down", "metres"), Map.entry("metres", "metres"), Map.entry("radius", "metres"),
            Map.entry("length", "metres"), Map.entry("width", "metres"), Map.entry("spacing", "metres"),
            Map.entry("seconds", "seconds"), Map.entry("timeBetween", "seconds"),
            Map.entry("millis", "milliseconds"), Map.entry("newSpeed", "m/s"), Map.entry("percent", "%"),
            Map.entry("centimetresPerPixel", "cm/px"));

    /** Number parameters that count or pick something and have no unit. */
    private static final Set<String> UNITLESS = Set.of("turns", "photos", "item", "repetitions", "speedType",
            "landMode", "n", "x", "value");

    private ParamUnits() {
    }

    /** The unit of the parameter, "" for none; null for a number parameter this table does not know. */
    static String of(String name, Class<?> type) {
        if (!isNumber(type)) {
            return "";
        }
        String unit = UNITS.get(name);
        return unit != null ? unit : UNITLESS.contains(name) ? "" : null;
    }

    static boolean isNumber(Class<?> type) {
        return Number.class.isAssignableFrom(type) || type == int.class || type == long.class || type == double.class
                || type == float.class;
    }
}
