package dolphin.cli;

import dolphin.core.Position;
import dolphin.sim.LinearField;
import dolphin.sim.PlumeField;
import dolphin.sim.SimEquipment;
import dolphin.sim.SimField;
import dolphin.sim.SimSensor;
import dolphin.sim.SysidSet;
import groovy.json.JsonException;
import groovy.json.JsonSlurper;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * The simulated fleet's sensors and cameras from a JSON file (docs/guide.md):
 * {@code {"sensors": [{"name", "plume": {lat, lon, radius, peak, background?} | "field": {lat, lon,
 * base, gradient, bearing}, "vehicles"?: [sysid...]}...], "cameras": [sysid...] | "all"}}. Unknown
 * keys are refused, so a misspelt one is not silently left out.
 */
final class EquipmentFile {

    private static final List<String> TOP = List.of("sensors", "cameras");
    private static final List<String> SENSOR = List.of("name", "plume", "field", "vehicles");
    private static final List<String> PLUME = List.of("lat", "lon", "radius", "peak", "background");
    private static final List<String> FIELD = List.of("lat", "lon", "base", "gradient", "bearing");

    private EquipmentFile() {
    }

    /** What the file says; IllegalArgumentException naming the entry when it says it wrongly. */
    static SimEquipment read(Path file) throws IOException {
        Object root;
        try {
            root = new JsonSlurper().parseText(Files.readString(file, StandardCharsets.UTF_8));
        } catch (JsonException e) {
            throw new IllegalArgumentException("not JSON: " + e.getMessage());
        }
        Map<?, ?> top = object("the file", root, TOP);
        List<SimSensor> sensors = new ArrayList<>();
        Object list = top.get("sensors");
        if (list != null) {
            if (!(list instanceof List<?> entries)) {
                throw new IllegalArgumentException("sensors: expected a list, got " + list);
            }
            for (int i = 0; i < entries.size(); i++) {
                try {
                    sensors.add(sensor(entries.get(i)));
                } catch (IllegalArgumentException e) {
                    throw new IllegalArgumentException("sensors[" + i + "]: " + e.getMessage(), e);
                }
            }
        }
        Object cameras = top.get("cameras");
        try {
            return new SimEquipment(sensors, cameras == null ? SysidSet.NONE : vehicles(cameras));
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("cameras: " + e.getMessage(), e);
        }
    }

    private static SimSensor sensor(Object entry) {
        Map<?, ?> s = object("a sensor", entry, SENSOR);
        if (!(s.get("name") instanceof String name)) {
            throw new IllegalArgumentException("expected a \"name\" string, got " + s.get("name"));
        }
        if (s.containsKey("plume") == s.containsKey("field")) {
            throw new IllegalArgumentException(name + ": expected either \"plume\" or \"field\"");
        }
        try {
            SimField field = s.containsKey("plume") ? plume(s.get("plume")) : linear(s.get("field"));
            return new SimSensor(name, field, s.containsKey("vehicles") ? vehicles(s.get("vehicles")) : SysidSet.ALL);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(name + ": " + e.getMessage(), e);
        }
    }

    private static PlumeField plume(Object value) {
        Map<?, ?> p = object("plume", value, PLUME);
        return new PlumeField(place(p), number(p, "radius"), number(p, "peak"), p.containsKey("background") ? number(p, "background") : 0);
    }

    private static LinearField linear(Object value) {
        Map<?, ?> f = object("field", value, FIELD);
        return new LinearField(place(f), number(f, "base"), number(f, "gradient"), number(f, "bearing"));
    }

    private static Position place(Map<?, ?> m) {
        return Position.fromDegrees(number(m, "lat"), number(m, "lon"), 0);
    }

    /** A list of system ids, or "all". */
    private static SysidSet vehicles(Object value) {
        if ("all".equals(value)) {
            return SysidSet.ALL;
        }
        if (!(value instanceof List<?> list)) {
            throw new IllegalArgumentException("expected a list of system ids or \"all\", got " + value);
        }
        List<Integer> ids = new ArrayList<>();
        for (Object o : list) {
            if (!(o instanceof Integer id)) {
                throw new IllegalArgumentException("expected a list of system ids or \"all\", got " + o + " in " + value);
            }
            ids.add(id);
        }
        return SysidSet.of(ids);
    }

    private static Map<?, ?> object(String what, Object value, List<String> keys) {
        if (!(value instanceof Map<?, ?> m)) {
            throw new IllegalArgumentException(what + ": expected an object, got " + value);
        }
        for (Object k : m.keySet()) {
            if (!keys.contains(k)) {
                throw new IllegalArgumentException(what + ": unknown key \"" + k + "\"; expected " + String.join(", ", keys));
            }
        }
        return m;
    }

    private static double number(Map<?, ?> m, String key) {
        Object v = m.get(key);
        if (!(v instanceof Number n)) {
            throw new IllegalArgumentException(v == null ? "missing \"" + key + "\"" : "\"" + key + "\": expected a number, got " + v);
        }
        return n.doubleValue();
    }
}
