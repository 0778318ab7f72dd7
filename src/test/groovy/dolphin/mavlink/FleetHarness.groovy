package dolphin.mavlink

import dolphin.core.SystemClock
import dolphin.dsl.Engine
import dolphin.dsl.EngineListener
import dolphin.dsl.ScriptResult
import dolphin.platform.MAVLinkPlatform
import java.time.Duration
import dolphin.mavlink.codec.SigningKey
import dolphin.sim.FaultModel
import dolphin.sim.SimEquipment
import dolphin.sim.SimFleet
import dolphin.sim.SimOptions
import dolphin.sim.VehicleKind
import spock.util.concurrent.PollingConditions

/**
 * A ground station and simulated fleets on loopback UDP, sharing one clock that runs ten times
 * faster than real time unless told otherwise. Close it to stop everything and free the sockets.
 */
class FleetHarness implements AutoCloseable {
    static final double SPEEDUP = 10

    final SystemClock clock
    final MAVLinkCommunications comms
    final List<SimFleet> fleets = []

    FleetHarness(MAVLinkConfig config = MAVLinkConfig.of('udpin:127.0.0.1:0'), double speedup = SPEEDUP) {
        clock = new SystemClock(speedup)
        comms = new MAVLinkCommunications(config, clock)
        comms.start()
    }

    int port() { comms.links()[0].localPort() }

    SimFleet fleet(int count, VehicleKind kind = VehicleKind.COPTER, int firstSysid = 1, SimOptions options = SimOptions.DEFAULT,
                   FaultModel faults = FaultModel.NONE, SigningKey key = null, SimEquipment equipment = SimEquipment.NONE) {
        fleet(config(count, kind).withFirstSysid(firstSysid).withOptions(options).withFaults(faults).withSigningKey(key)
                .withEquipment(equipment))
    }

    /** The defaults of a fleet sending to this ground station, for a spec to change. */
    SimFleet.Config config(int count, VehicleKind kind) {
        SimFleet.Config.of(count, kind, new InetSocketAddress('127.0.0.1', port()))
    }

    SimFleet fleet(SimFleet.Config config) {
        def f = new SimFleet(config, clock)
        f.start()
        fleets << f
        f
    }

    /** Waits up to {@code seconds} of real time for the condition (a closure with assertions). */
    void eventually(double seconds = 10, Closure condition) {
        new PollingConditions(timeout: seconds, delay: 0.02).eventually(condition)
    }

    MAVLinkNode node(String id) { comms.node(id) }

    /** Runs a script on the MAVLink platform over this ground station, its messages into {@code messages}; fails after 30 s. */
    ScriptResult run(String script, String name, List<String> messages) {
        def engine = new Engine(new MAVLinkPlatform(comms), clock)
        engine.addListener(new EngineListener() {
            void message(String text) { messages << text }
        })
        def result = engine.run(script, name).await(Duration.ofSeconds(30))
        assert result != null: "${name} did not end in 30 s"
        result
    }

    @Override
    void close() {
        fleets.each { it.close() }
        comms.close()
    }
}
