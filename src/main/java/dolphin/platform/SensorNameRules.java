package dolphin.platform;

import dolphin.dsl.vocabulary.Suggestions;
import dolphin.sensor.DeclaredSensors;
import java.util.List;
import java.util.Set;

/** What makes a sensor name a mistake, the same for {@code dolphin check} and at run time. */
final class SensorNameRules {

    /** NAMED_VALUE_FLOAT's name is a char[10]. */
    static final int NAMED_VALUE_MAX = 10;

    private SensorNameRules() {
    }

    /** The mistake, or null when the name may be read. */
    static String mistake(String name, DeclaredSensors declared, Set<String> scriptDeclared) {
        Set<String> all = declared.all(scriptDeclared);
        if (name.isBlank()) {
            return "a sensor name is needed, e.g. 'SMOKE'";
        }
        if (name.length() > NAMED_VALUE_MAX && !all.contains(name)) {
            return "'" + name + "' has " + name.length() + " characters: NAMED_VALUE_FLOAT names have at most "
                    + NAMED_VALUE_MAX + ", so no vehicle can send it (did the sender cut it to '"
                    + name.substring(0, NAMED_VALUE_MAX) + "'?)";
        }
        if ((!declared.fleet().isEmpty() || !scriptDeclared.isEmpty()) && !all.contains(name)) {
            List<String> near = Suggestions.near(name, all);
            return "no sensor '" + name + "' is declared (declared: " + String.join(", ", all) + ")"
                    + (near.isEmpty() ? "" : "; did you mean '" + near.get(0) + "'?");
        }
        return null;
    }
}
