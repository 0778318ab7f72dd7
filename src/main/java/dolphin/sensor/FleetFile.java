package dolphin.sensor;

import dolphin.core.Payload;
import groovy.json.JsonException;
import groovy.json.JsonSlurper;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;

/**
 * What the user says of vehicles that do not announce it themselves (docs/sensors.md, "Fleet files"):
 * by system id, a name, a Dolphin type, the payloads they carry and the sensors they send.
 * <pre>
 * {"vehicles": [{"sysid": 3, "name": "diver", "type": "UUV", "payloads": ["Sidescan", {"name": "Camera", "model": "A7"}],
 *                "sensors": ["SMOKE"]}]}
 * </pre>
 */
public record FleetFile(String source, Map<Integer, FleetEntry> vehicles) {

    public static final FleetFile NONE = new FleetFile("", Map.of());

    /** One vehicle's entry; name and type are null when the file does not give them. */
    public record FleetEntry(int sysid, String name, String type, List<Payload.Component> payloads, List<String> sensors) {
        public FleetEntry {
            payloads = List.copyOf(payloads);
            sensors = List.copyOf(sensors);
        }
    }

    private static final Set<String> VEHICLE_KEYS = Set.of("sysid", "name", "type", "payloads", "sensors");

    public FleetFile {
        vehicles = Map.copyOf(vehicles);
    }

    /** Every sensor name the file declares, on any vehicle. */
    public Set<String> sensorNames() {
        Set<String> names = new TreeSet<>();
        vehicles.values().forEach(v -> names.addAll(v.sensors()));
        return names;
    }

    public FleetEntry vehicle(int sysid) {
        return vehicles.get(sysid);
    }

    /** Reads a fleet file; an IllegalArgumentException names the file, the entry and what was expected. */
    public static FleetFile read(Path file) throws IOException {
        Object json;
        try {
            json = new JsonSlurper().parseText(Files.readString(file));
        } catch (NoSuchFileException e) {
            throw new IllegalArgumentException(file + ": no such fleet file");
        } catch (JsonException e) {
            throw new IllegalArgumentException(file + ": not JSON: " + e.getMessage().lines().findFirst().orElse(""));
        }
        if (!(json instanceof Map<?, ?> root) || !(root.get("vehicles") instanceof List<?> list) || root.size() != 1) {
            throw new IllegalArgumentException(file + ": expected {\"vehicles\": [...]} and nothing else");
        }
        Map<Integer, FleetEntry> vehicles = new LinkedHashMap<>();
        for (int i = 0; i < list.size(); i++) {
            String where = file + ": vehicle " + (i + 1);
            FleetEntry v = vehicle(where, list.get(i));
            if (vehicles.put(v.sysid(), v) != null) {
                throw new IllegalArgumentException(where + ": sysid " + v.sysid() + " is given twice");
            }
        }
        return new FleetFile(file.toString(), vehicles);
    }

    private static FleetEntry vehicle(String where, Object entry) {
        if (!(entry instanceof Map<?, ?> map)) {
            throw new IllegalArgumentException(where + ": expected an object with sysid, name, type, payloads, sensors; got " + entry);
        }
        for (Object key : map.keySet()) {
            if (!VEHICLE_KEYS.contains(String.valueOf(key))) {
                throw new IllegalArgumentException(where + ": unknown key '" + key + "' (expected sysid, name, type, payloads, sensors)");
            }
        }
        if (!(map.get("sysid") instanceof Integer sysid) || sysid < 1 || sysid > 255) {
            throw new IllegalArgumentException(where + ": sysid must be a system id from 1 to 255, got " + map.get("sysid"));
        }
        where += " (sysid " + sysid + ")";
        String name = text(where, "name", map.get("name"));
        String type = text(where, "type", map.get("type"));
        List<Payload.Component> payloads = new ArrayList<>();
        for (Object p : list(where, "payloads", map.get("payloads"))) {
            payloads.add(payload(where, p));
        }
        Set<String> sensors = new LinkedHashSet<>();
        for (Object s : list(where, "sensors", map.get("sensors"))) {
            String sensor = text(where, "sensors", s);
            if (sensor == null || sensor.isEmpty()) {
                throw new IllegalArgumentException(where + ": sensors: expected names, got " + s);
            }
            sensors.add(sensor);
        }
        return new FleetEntry(sysid, name, type, payloads, List.copyOf(sensors));
    }

    private static Payload.Component payload(String where, Object p) {
        if (p instanceof String name && !name.isBlank()) {
            return Payload.Component.named(name);
        }
        if (p instanceof Map<?, ?> map && map.get("name") instanceof String name && !name.isBlank()) {
            Map<String, Object> parameters = new LinkedHashMap<>();
            map.forEach((k, v) -> {
                if (!"name".equals(k) && v != null) {
                    parameters.put(String.valueOf(k), v);
                }
            });
            return new Payload.Component(name, parameters);
        }
        throw new IllegalArgumentException(where + ": payloads: expected a name or an object with a name, got " + p);
    }

    private static List<?> list(String where, String key, Object value) {
        if (value == null) {
            return List.of();
        }
        if (value instanceof List<?> l) {
            return l;
        }
        throw new IllegalArgumentException(where + ": " + key + ": expected a list, got " + value);
    }

    private static String text(String where, String key, Object value) {
        if (value == null || value instanceof String) {
            return (String) value;
        }
        throw new IllegalArgumentException(where + ": " + key + ": expected text, got " + value);
    }
}
