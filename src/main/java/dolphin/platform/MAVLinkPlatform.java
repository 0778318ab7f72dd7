package dolphin.platform;

import dolphin.mavlink.LinkHealth;
import dolphin.mavlink.MAVLinkCommunications;
import dolphin.mavlink.MAVLinkNode;
import dolphin.core.Node;
import dolphin.core.NodeSet;
import dolphin.core.Platform;
import dolphin.core.VehicleEvent;
import dolphin.dsl.DslExtension;
import dolphin.dsl.ScriptContext;
import dolphin.dsl.check.CallCheck;
import dolphin.sensor.SensorService;
import java.util.List;
import java.util.Optional;
import java.util.function.Consumer;
import org.codehaus.groovy.control.customizers.ImportCustomizer;

/** MAVLink vehicles for Dolphin scripts: the connected vehicles for pick, and the {@link MAVLinkLanguage}. */
public final class MAVLinkPlatform implements Platform, DslExtension {

    private final MAVLinkCommunications comms;
    private final MAVLinkLanguage language;
    private volatile Consumer<VehicleEvent> vehicleEvents = e -> { };

    /**
     * Attaches the sensor layer at once, so readings and payloads are known before a script asks, and
     * listens to the vehicle events from the start, so they reach the engine between scripts too.
     */
    public MAVLinkPlatform(MAVLinkCommunications comms) {
        this.comms = comms;
        this.language = new MAVLinkLanguage(SensorService.of(comms));
        comms.addVehicleEventListener(e -> vehicleEvents.accept(e));
    }

    public MAVLinkCommunications communications() {
        return comms;
    }

    /**
     * The health of the link a vehicle is reached through, by the vehicle's id ("1", "1@2"): its traffic,
     * losses and telemetry radio, now (docs/embedding.md, "Link health"). Empty for an id no vehicle
     * has. From any thread.
     */
    public Optional<LinkHealth> linkHealth(String vehicleId) {
        return Optional.ofNullable(comms.node(vehicleId)).map(MAVLinkNode::linkHealth);
    }

    @Override
    public String getName() {
        return "MAVLink";
    }

    /** Vehicles heard within their connection timeout, by system id. */
    @Override
    public NodeSet getConnectedNodes() {
        return new NodeSet(comms.nodes().stream().filter(Node::isConnected).toList());
    }

    @Override
    public void setTelemetryListener(Runnable onTelemetry) {
        comms.setTelemetryListener(onTelemetry);
    }

    /** The communications' vehicle events, and those the mission layer publishes on them, on the thread that raised each. */
    @Override
    public void setVehicleEventListener(Consumer<VehicleEvent> listener) {
        vehicleEvents = listener == null ? e -> { } : listener;
    }

    @Override
    public void addImports(ImportCustomizer imports) {
        language.addImports(imports);
    }

    @Override
    public List<Object> words(ScriptContext context) {
        return language.words(context);
    }

    @Override
    public List<Class<?>> wordClasses() {
        return language.wordClasses();
    }

    @Override
    public List<CallCheck> callChecks() {
        return language.callChecks();
    }

    @Override
    public void close() {
        comms.close();
    }
}
