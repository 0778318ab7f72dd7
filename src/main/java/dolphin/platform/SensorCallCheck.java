package dolphin.platform;

import dolphin.dsl.check.CallCheck;
import dolphin.sensor.DeclaredSensors;
import dolphin.sensor.TelemetryField;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

/**
 * {@code dolphin check}'s view of the sensor words: a name no vehicle can send (over 10 characters), a
 * name the fleet file or the script's {@code declareSensors} does not declare, a telemetry message or
 * field that MAVLink does not define. Remembers the script's declarations as the walk meets them, so
 * one instance serves one check.
 */
final class SensorCallCheck implements CallCheck {

    private final DeclaredSensors declared;
    private final Set<String> declaredByScript = new HashSet<>();

    SensorCallCheck(DeclaredSensors declared) {
        this.declared = declared;
    }

    @Override
    public String mistake(String word, List<Object> constants) {
        switch (word) {
            case "declareSensors" -> {
                for (Object c : constants) {
                    if (c instanceof String name) {
                        String m = SensorNameRules.declarationMistake(name, declared);
                        if (m != null) {
                            return "declareSensors: " + m;
                        }
                        declaredByScript.add(name);
                    }
                }
                return null;
            }
            case "sensor", "sensorKnown" -> {
                if (!constants.isEmpty() && constants.get(constants.size() - 1) instanceof String name) {
                    String m = SensorNameRules.mistake(name, declared, declaredByScript);
                    return m == null ? null : word + ": " + m;
                }
                return null;
            }
            case "telemetry" -> {
                int n = constants.size();
                if (n >= 2 && constants.get(n - 2) instanceof String message && constants.get(n - 1) instanceof String field) {
                    try {
                        TelemetryField.of(message, field);
                    } catch (IllegalArgumentException e) {
                        return "telemetry: " + e.getMessage();
                    }
                }
                return null;
            }
            default -> {
                return null;
            }
        }
    }
}
