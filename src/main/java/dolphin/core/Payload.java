package dolphin.core;

import java.util.List;
import java.util.Map;

/** The components a node carries (sensors, actuators); compared by name. */
public record Payload(List<Component> components) {

    public static final Payload NONE = new Payload(List.of());

    public Payload {
        components = List.copyOf(components);
    }

    public record Component(String name, Map<String, Object> parameters) {
        public Component {
            parameters = Map.copyOf(parameters);
        }

        public static Component named(String name) {
            return new Component(name, Map.of());
        }
    }

    public static Payload of(String... names) {
        return new Payload(java.util.Arrays.stream(names).map(Component::named).toList());
    }

    /** True when every required component name is present. */
    public boolean compatibleWith(List<String> required) {
        return required.stream().allMatch(r -> components.stream().anyMatch(c -> c.name().equals(r)));
    }
}
