package dolphin.platform

import com.MAVLink.minimal.msg_heartbeat
import dolphin.core.Position
import dolphin.dsl.ScriptResult
import dolphin.mavlink.FleetHarness
import dolphin.sim.SimOptions
import dolphin.sim.VehicleKind
import java.util.concurrent.CopyOnWriteArrayList
import spock.lang.AutoCleanup
import spock.lang.Specification
import spock.lang.Timeout

/**
 * A submarine out of contact while it dives (docs/underwater.md, "The connection timeout"): a
 * simulated ArduSub at Comporta, silent deeper than 1 m, flies a dive of more than a minute under
 * water, over real UDP on loopback at ten times real time. With the report's 10 minutes it stays
 * picked, its mission is followed through the silence and ends DONE; with 30 s it is lost after 30 s
 * of silence, a clear error naming it.
 */
class DiveSilenceSpec extends Specification {

    static final Position COMPORTA = Position.fromDegrees(38.43462, -8.86118, 0)

    @AutoCleanup
    FleetHarness h = new FleetHarness()
    List<String> messages = new CopyOnWriteArrayList<>()

    /** The longest time the ground station heard no heartbeat, up to the script's end, in clock seconds. */
    volatile double longestSilence = 0

    static String script(String timeout) {
        """
        sub = pick { type 'UUV'; timeout 60 }
        setConnectionTimeout ${timeout}
        deep = mission {
            name 'deep'
            maxDepth 10
            goPos 38.43462, -8.86118, 0
            dive 5
            move 60, 0
            surface()
        }
        execute sub: deep
        message "back at \${Math.round(position(sub).hae())} m"
        """
    }

    ScriptResult dive(String timeout) {
        long last = -1
        h.comms.messageHandler().on(msg_heartbeat) { node, m ->
            long now = h.clock.nanoTime()
            if (last >= 0) {
                longestSilence = Math.max(longestSilence, (now - last) / 1e9)
            }
            last = now
        }
        h.fleet(h.config(1, VehicleKind.SUB).withHome(COMPORTA).withOptions(SimOptions.DEFAULT.withDiveSilence(1)))
        def result = h.run(script(timeout), 'dive.dolphin', messages)
        longestSilence = Math.max(longestSilence, (h.clock.nanoTime() - last) / 1e9)
        result
    }

    @Timeout(60)
    def "under the report's 10 minutes the dive's silence is waited out and the mission ends DONE, back at the surface"() {
        when:
        def r = dive('10.minutes')

        then:
        r.outcome == ScriptResult.Outcome.COMPLETED
        messages.contains('mission deep on vehicle 1: done')
        messages.last() == 'back at 0 m'
        longestSilence >= 60
    }

    @Timeout(60)
    def "under 30 s the silent sub is lost after 30 s: an error naming the vehicle"() {
        when:
        def r = dive('30')

        then:
        r.outcome == ScriptResult.Outcome.TASK_ERROR
        messages.any { it.contains('vehicle 1 lost: no contact within its connection timeout of 30 s') }
        !messages.contains('mission deep on vehicle 1: done')
        longestSilence >= 30
    }
}
