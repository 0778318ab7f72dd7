package dolphin.sensor;

import com.MAVLink.Messages.MAVLinkMessage;
import dolphin.core.Clock;
import dolphin.core.Payload;
import dolphin.mavlink.MAVLinkCommunications;
import dolphin.mavlink.MAVLinkNode;
import dolphin.mavlink.codec.MessageTable;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import java.util.ServiceConfigurationError;
import java.util.ServiceLoader;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The sensor layer on one {@link MAVLinkCommunications} (docs/sensors.md): it sees every message from
 * every component of each vehicle, hands each to the {@link Sensor}s that read its kind, keeps each
 * vehicle's {@link VehicleReadings}, learns payloads ({@link PayloadDiscovery}) and applies the fleet
 * file. Attached as an extension of the communications; the link layer knows nothing of it.
 */
public final class SensorService {

    private static final Logger LOG = LoggerFactory.getLogger(SensorService.class);

    private final MAVLinkCommunications comms;
    private final Clock clock;
    private final Map<Class<?>, Sensor> sensors = new ConcurrentHashMap<>();
    private final Map<Class<?>, List<Sensor>> routes = new ConcurrentHashMap<>();
    private final Map<MAVLinkNode, VehicleReadings> vehicles = new ConcurrentHashMap<>();
    private final Set<String> refusals = ConcurrentHashMap.newKeySet();
    private final PayloadDiscovery payloads;
    private volatile FleetFile fleet = FleetFile.NONE;

    private SensorService(MAVLinkCommunications comms) {
        this.comms = comms;
        this.clock = comms.clock();
        this.payloads = PayloadDiscovery.over(comms);
        add(new NamedValues());
        installed().forEach(this::add);
        comms.addComponentListener(this::message);
    }

    /** The sensor layer of these communications, attached on first use. */
    public static SensorService of(MAVLinkCommunications comms) {
        return comms.extension(SensorService.class, SensorService::new);
    }

    /**
     * The sensors installed on the class path ({@code META-INF/services/dolphin.sensor.Sensor}); one
     * that cannot be made is left out with a warning that names it, so the others still work.
     */
    public static List<Sensor> installed() {
        List<Sensor> found = new ArrayList<>();
        var it = ServiceLoader.load(Sensor.class).iterator();
        while (true) {
            try {
                if (!it.hasNext()) {
                    return found;
                }
                found.add(it.next());
            } catch (ServiceConfigurationError e) {
                LOG.warn("sensor not loaded: {}", e.getMessage());
            }
        }
    }

    /** Reads the sensor's messages from now on, instead of any earlier sensor of the same class. */
    public void add(Sensor sensor) {
        Set<Class<? extends MAVLinkMessage>> kinds = Set.copyOf(sensor.messages());
        Sensor before = sensors.put(sensor.getClass(), sensor);
        if (before != null) {
            routes.values().forEach(list -> list.remove(before));
        }
        kinds.forEach(k -> routes.computeIfAbsent(k, x -> new CopyOnWriteArrayList<>()).add(sensor));
    }

    public Collection<Sensor> sensors() {
        return List.copyOf(sensors.values());
    }

    /** The names the fleet file and the sensors declare ahead; readings named by their messages are not among them. */
    public DeclaredSensors declared() {
        Set<String> classes = new java.util.TreeSet<>();
        sensors.values().forEach(s -> classes.addAll(s.names()));
        return new DeclaredSensors(fleet.sensorNames(), classes);
    }

    public VehicleReadings readings(MAVLinkNode node) {
        return vehicles.computeIfAbsent(node, n -> new VehicleReadings());
    }

    public FleetFile fleet() {
        return fleet;
    }

    /** Applies a fleet file to the vehicles known now and to those discovered later. */
    public void useFleet(FleetFile file) {
        fleet = file;
        comms.nodes().forEach(this::applyFleet);
    }

    private void applyFleet(MAVLinkNode node) {
        FleetFile.FleetEntry v = fleet.vehicle(node.getMavLinkId());
        if (v == null) {
            return;
        }
        node.declare(v.name(), v.type());
        v.payloads().forEach(node::addPayload);
        v.sensors().forEach(s -> node.addPayload(Payload.Component.named(s)));
    }

    private void message(MAVLinkNode node, int component, MAVLinkMessage message) {
        long now = clock.nanoTime();
        VehicleReadings readings = vehicles.get(node);
        if (readings == null) {
            readings = readings(node);
            applyFleet(node);
        }
        readings.received(component, message, now);
        payloads.message(node, component, message);
        List<Sensor> readers = routes.get(message.getClass());
        if (readers == null) {
            return;
        }
        VehicleReadings into = readings;
        String source = MessageTable.get().name(message.msgid);
        for (Sensor s : readers) {
            long fresh = s.freshness().toNanos();
            try {
                s.read(message, (name, value, unit) -> {
                    into.put(new Reading(name, value, unit == null ? "" : unit, component, source, now, fresh));
                    payloads.readingNamed(node, name);
                });
            } catch (RuntimeException e) {
                refuse(node, component, source, s, e);
            }
        }
        comms.wakeScript();
    }

    /** Bad input from a vehicle is logged once per vehicle, component, message and sensor, and skipped. */
    private void refuse(MAVLinkNode node, int component, String source, Sensor s, RuntimeException e) {
        if (refusals.add(node.getId() + "/" + component + "/" + source + "/" + s.getClass().getName())) {
            LOG.warn("vehicle {} component {}: {} not read by {}: {} (further ones are skipped silently)", node.getId(), component,
                    source, s.getClass().getSimpleName(), e.getMessage());
        }
    }
}
