package dolphin.mavlink

import com.MAVLink.common.msg_sys_status
import dolphin.core.EnvironmentException
import dolphin.core.ManualClock
import java.time.Duration
import spock.lang.Specification

/**
 * battery(v) right after a vehicle boots, on a manual clock (no socket, no real time): ArduPilot reports
 * battery_remaining -1 until its battery monitor has read the battery, so -1 is waited out, up to the
 * 5 s of the first report, before it is an error.
 */
class BatteryWaitSpec extends Specification {

    ManualClock clock = ManualClock.autoAdvancing()
    MAVLinkNode node = new MAVLinkNode('1', 'UAV', new MAVLinkCommunications(MAVLinkConfig.of('udpin:127.0.0.1:0'), clock),
            null, null, 1, 1, dolphin.mavlink.Autopilot.ARDUPILOT, VehicleFamily.COPTER, clock)

    void report(int percent) {
        node.update { it.withSystemStatus(new msg_sys_status(battery_remaining: percent as byte), clock.nanoTime()) }
    }

    def "a level of -1 at boot is waited out: the level that follows is the answer"() {
        given: 'the first SYS_STATUS says -1; 2 s later the monitor has read the battery'
        report(-1)
        clock.schedule(Duration.ofSeconds(2)) { report(87) }

        expect:
        node.batteryRemaining() == 0.87d
        clock.seconds() >= 2 && clock.seconds() < 2.1
    }

    def "a level that stays -1 for 5 s is a clear error: no battery monitor"() {
        given:
        report(-1)

        when:
        node.batteryRemaining()

        then:
        EnvironmentException e = thrown()
        e.message == 'battery: vehicle 1 reports no battery level (battery_remaining -1 for 5 s: no battery monitor configured)'
        clock.seconds() >= 5
    }

    def "no SYS_STATUS in 5 s says so"() {
        when:
        node.batteryRemaining()

        then:
        EnvironmentException e = thrown()
        e.message.startsWith('battery: vehicle 1 has sent no SYS_STATUS in 5 s')
        clock.seconds() >= 5
    }

    def "a level already known is answered at once"() {
        given:
        report(55)

        expect:
        node.batteryRemaining() == 0.55d
        clock.seconds() == 0
    }
}
