package dolphin.core;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;

/**
 * The components a node carries (cameras, sensors, actuators); compared by name, ignoring case, so
 * {@code payload 'camera'} finds a component announced as "Camera".
 */
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
        return new Payload(Arrays.stream(names).map(Component::named).toList());
    }

    /** True when every required component name is present. */
    public boolean compatibleWith(List<String> required) {
        return required.stream().allMatch(this::has);
    }

    public boolean has(String name) {
        return components.stream().anyMatch(c -> c.name().equalsIgnoreCase(name));
    }

    /**
     * This payload with the component: added when its name is new, or replacing a component of that
     * name that had fewer details (a camera first known by its heartbeat, then by its CAMERA_INFORMATION).
     */
    public Payload with(Component component) {
        ArrayList<Component> list = new ArrayList<>(components);
        for (int i = 0; i < list.size(); i++) {
            if (list.get(i).name().equalsIgnoreCase(component.name())) {
                if (list.get(i).parameters().size() >= component.parameters().size()) {
                    return this;
                }
                list.set(i, component);
                return new Payload(list);
            }
        }
        list.add(component);
        return new Payload(list);
    }

    public List<String> names() {
        return components.stream().map(Component::name).toList();
    }
}
