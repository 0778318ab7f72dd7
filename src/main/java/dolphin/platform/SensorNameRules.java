package dolphin.platform;

import dolphin.dsl.vocabulary.Suggestions;
import dolphin.sensor.DeclaredSensors;
import dolphin.sensor.NamedValues;
import java.util.List;
import java.util.Set;

/** What makes a sensor name a mistake, the same for {@code dolphin check} and at run time. */
final class SensorNameRules {

    private SensorNameRules() {
    }

    /**
     * The mistake in a name {@code declareSensors} gives, or null: a blank name, or one no vehicle can
     * send and no sensor class gives. Whether it is declared elsewhere does not matter: it declares it.
     */
    static String declarationMistake(String name, DeclaredSensors declared) {
        return mistake(name, new DeclaredSensors(Set.of(), declared.classes()), Set.of());
    }

    /** The mistake, or null when the name may be read. */
    static String mistake(String name, DeclaredSensors declared, Set<String> scriptDeclared) {
        Set<String> all = declared.all(scriptDeclared);
        if (name.isBlank()) {
            return "a sensor name is needed, e.g. 'SMOKE'";
        }
        if (name.length() > NamedValues.MAX_NAME && !all.contains(name)) {
            return "'" + name + "' has " + name.length() + " characters: NAMED_VALUE_FLOAT names have at most "
                    + NamedValues.MAX_NAME + ", so no vehicle can send it (did the sender cut it to '"
                    + name.substring(0, NamedValues.MAX_NAME) + "'?)";
        }
        if ((!declared.fleet().isEmpty() || !scriptDeclared.isEmpty()) && !all.contains(name)) {
            List<String> near = Suggestions.near(name, all);
            return "no sensor '" + name + "' is declared (declared: " + String.join(", ", all) + ")"
                    + (near.isEmpty() ? "" : "; did you mean '" + near.get(0) + "'?");
        }
        return null;
    }
}
