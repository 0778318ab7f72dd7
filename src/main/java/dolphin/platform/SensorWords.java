package dolphin.platform;

import dolphin.core.EnvironmentException;
import dolphin.dsl.DslException;
import dolphin.dsl.ScriptContext;
import dolphin.dsl.vocabulary.Word;
import dolphin.mavlink.MAVLinkNode;
import dolphin.sensor.DeclaredSensors;
import dolphin.sensor.Reading;
import dolphin.sensor.Sensor;
import dolphin.sensor.SensorService;
import dolphin.sensor.TelemetryField;
import dolphin.sensor.VehicleReadings;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Consumer;
import java.util.function.Supplier;

/**
 * The words that read sensors and telemetry (docs/sensors.md). A value a script reads is current or an
 * error, never a made-up 0: the first read of a name waits up to 5 s for the vehicle to send it, as
 * {@code battery} does; a reading older than its sensor's freshness limit, a NaN or an infinite value
 * is an error; {@code sensorKnown} tests for a current value without waiting or failing.
 */
public final class SensorWords {

    private final ScriptContext context;
    private final Consumer<Sensor> install;
    private final Supplier<DeclaredSensors> declaredAhead;
    private final Set<String> declaredByScript = ConcurrentHashMap.newKeySet();

    SensorWords(ScriptContext context, Consumer<Sensor> install, Supplier<DeclaredSensors> declaredAhead) {
        this.context = context;
        this.install = install;
        this.declaredAhead = declaredAhead;
    }

    @Word("The vehicle's latest value under this name (waits for the first); options maxAge (seconds), component: sensor(v, 'SMOKE') > 20")
    public double sensor(Object vehicle, String name) {
        return sensor(Map.of(), vehicle, name);
    }

    @Word("The vehicle's latest value under this name (waits for the first); options maxAge (seconds), component: sensor(v, 'SMOKE') > 20")
    public double sensor(Map<String, Object> options, Object vehicle, String name) {
        Asked asked = ask("sensor", options, vehicle, name);
        MAVLinkNode node = asked.node();
        ReadingOptions o = asked.options();
        VehicleReadings readings = asked.readings();
        List<Reading> found = await("sensor", node, () -> named(readings, name, o));
        if (found.isEmpty()) {
            List<String> sent = readings.all().stream().map(Reading::name).distinct().toList();
            throw new EnvironmentException("sensor: vehicle " + node.getId() + " has sent no " + name
                    + (o.component() == null ? "" : " from component " + o.component()) + " in "
                    + MAVLinkNode.TELEMETRY_WAIT.toSeconds() + " s ("
                    + (sent.isEmpty() ? "no readings at all" : "it sends " + String.join(", ", sent)) + ")");
        }
        Reading r = one("sensor", node, name, found);
        long now = node.communications().clock().nanoTime();
        long limit = o.maxAgeNanos(r.freshNanos());
        if (now - r.nanos() > limit) {
            throw new EnvironmentException(String.format("sensor: vehicle %s's %s is %.1f s old, older than its %s s limit:"
                    + " the sensor stopped reporting (sensorKnown(v, '%s') tests for a current value)",
                    node.getId(), name, r.ageSeconds(now), seconds(limit), name));
        }
        if (!r.finite()) {
            throw new EnvironmentException("sensor: vehicle " + node.getId() + " sent " + name + " = " + r.value()
                    + " (component " + r.component() + ", " + r.source() + "): not a number a condition can use");
        }
        return r.value();
    }

    @Word("Whether the vehicle has a current, finite value under this name, without waiting; options maxAge, component")
    public boolean sensorKnown(Object vehicle, String name) {
        return sensorKnown(Map.of(), vehicle, name);
    }

    @Word("Whether the vehicle has a current, finite value under this name, without waiting; options maxAge, component")
    public boolean sensorKnown(Map<String, Object> options, Object vehicle, String name) {
        Asked asked = ask("sensorKnown", options, vehicle, name);
        List<Reading> found = named(asked.readings(), name, asked.options());
        if (found.isEmpty()) {
            return false;
        }
        Reading r = one("sensorKnown", asked.node(), name, found);
        long now = asked.node().communications().clock().nanoTime();
        return now - r.nanos() <= asked.options().maxAgeNanos(r.freshNanos()) && r.finite();
    }

    @Word("A field of the vehicle's latest message, in Dolphin's units: telemetry(v, 'VFR_HUD', 'groundspeed'); options maxAge, component")
    public Object telemetry(Object vehicle, String message, String field) {
        return telemetry(Map.of(), vehicle, message, field);
    }

    @Word("A field of the vehicle's latest message, in Dolphin's units: telemetry(v, 'VFR_HUD', 'groundspeed'); options maxAge, component")
    public Object telemetry(Map<String, Object> options, Object vehicle, String message, String field) {
        TelemetryField f;
        try {
            f = TelemetryField.of(message, field);
        } catch (IllegalArgumentException e) {
            throw new DslException("telemetry: " + e.getMessage());
        }
        MAVLinkNode node = OneVehicle.of(context, "telemetry", vehicle);
        ReadingOptions o = ReadingOptions.of("telemetry", options);
        int component = o.component() == null ? node.getAutopilotCompid() : o.component();
        VehicleReadings readings = SensorService.of(node.communications()).readings(node);
        List<VehicleReadings.LastMessage> got = await("telemetry", node, () -> {
            VehicleReadings.LastMessage r = readings.message(component, f.msgid());
            return r == null ? List.of() : List.of(r);
        });
        if (got.isEmpty()) {
            throw new EnvironmentException("telemetry: vehicle " + node.getId() + " has sent no " + message + " from component "
                    + component + " in " + MAVLinkNode.TELEMETRY_WAIT.toSeconds() + " s (is it in its telemetry streams?)");
        }
        VehicleReadings.LastMessage r = got.get(0);
        long now = node.communications().clock().nanoTime();
        long limit = o.maxAgeNanos(Sensor.DEFAULT_FRESHNESS.toNanos());
        if (now - r.nanos() > limit) {
            throw new EnvironmentException(String.format("telemetry: vehicle %s's last %s is %.1f s old, older than the %s s limit",
                    node.getId(), message, (now - r.nanos()) / 1e9, seconds(limit)));
        }
        Object value = f.valueIn(r.message());
        if (value instanceof Double d && !Double.isFinite(d)) {
            throw new EnvironmentException("telemetry: vehicle " + node.getId() + " sent " + message + "." + field + " = " + d
                    + ": the vehicle does not know it");
        }
        return value;
    }

    @Word("The names of the payloads the vehicle carries, as it announces them or a fleet file says")
    public List<String> payloads(Object vehicle) {
        return OneVehicle.of(context, "payloads", vehicle).getPayload().names();
    }

    @Word("Reads the script's own sensor class from now on: useSensor new GasSensor()")
    public void useSensor(Sensor sensor) {
        if (sensor == null) {
            throw new DslException("useSensor: expected a sensor (an object of a class that implements Sensor), got null");
        }
        install.accept(sensor);
        context.listener().message("reading sensor " + sensor.getClass().getSimpleName()
                + (sensor.names().isEmpty() ? "" : " (" + String.join(", ", sensor.names()) + ")"));
    }

    @Word("Names the sensors the script's vehicles send, so a misspelt name is an error: declareSensors 'SMOKE', 'CO2'")
    public void declareSensors(String... names) {
        for (String n : names) {
            String mistake = SensorNameRules.declarationMistake(n, declaredAhead.get());
            if (mistake != null) {
                throw new DslException("declareSensors: " + mistake);
            }
        }
        declaredByScript.addAll(List.of(names));
    }

    /** What a sensor word asks about: the vehicle, the options, and the vehicle's readings; the name checked. */
    private record Asked(MAVLinkNode node, ReadingOptions options, VehicleReadings readings) {
    }

    private Asked ask(String word, Map<String, Object> options, Object vehicle, String name) {
        MAVLinkNode node = OneVehicle.of(context, word, vehicle);
        ReadingOptions o = ReadingOptions.of(word, options);
        String mistake = SensorNameRules.mistake(name, declaredAhead.get(), declaredByScript);
        if (mistake != null) {
            throw new DslException(word + ": " + mistake);
        }
        return new Asked(node, o, SensorService.of(node.communications()).readings(node));
    }

    private static List<Reading> named(VehicleReadings readings, String name, ReadingOptions o) {
        return readings.named(name).stream().filter(r -> o.component() == null || r.component() == o.component()).toList();
    }

    /** The one reading of a name; several components sending it is the script's to settle. */
    private static Reading one(String word, MAVLinkNode node, String name, List<Reading> found) {
        if (found.size() > 1) {
            List<String> components = found.stream().map(r -> String.valueOf(r.component())).toList();
            throw new EnvironmentException(word + ": vehicle " + node.getId() + " sends " + name + " from components "
                    + String.join(" and ", components) + "; say which: " + word + "(v, '" + name + "', component: "
                    + components.get(components.size() - 1) + ")");
        }
        return found.get(0);
    }

    /** What {@code find} finds once the vehicle has sent it, waiting as battery(v) does; empty at the deadline. */
    private static <T> List<T> await(String word, MAVLinkNode node, Supplier<List<T>> find) {
        node.awaitWithin(word, () -> !find.get().isEmpty());
        return find.get();
    }

    private static String seconds(long nanos) {
        double s = nanos / 1e9;
        return s == Math.rint(s) ? String.valueOf((long) s) : String.valueOf(s);
    }
}
