package dolphin.mission.flight

import com.MAVLink.common.msg_command_ack
import com.MAVLink.common.msg_command_long
import com.MAVLink.common.msg_mission_current
import com.MAVLink.common.msg_mission_item_reached
import com.MAVLink.common.msg_statustext
import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_RESULT
import com.MAVLink.enums.MAV_SEVERITY
import com.MAVLink.enums.MISSION_STATE
import com.MAVLink.minimal.msg_heartbeat
import dolphin.mavlink.Autopilot
import dolphin.mavlink.Px4Modes
import dolphin.mavlink.VehicleFamily
import dolphin.sim.TlogFile
import java.nio.file.Path
import spock.lang.Specification

/**
 * What real PX4 SITL (SIH) said and did while the project's scripts flew against it
 * (src/test/resources/sitl-recordings, px4-*): the wire the runtime's PX4 side is built on (docs/px4.md).
 */
class Px4RecordingSpec extends Specification {

    static final Path RECORDINGS = Path.of('src/test/resources/sitl-recordings')

    /** The messages of the vehicle (system 1, component 1), or of our ground station (208), in order. */
    static List from(String recording, int system = 1) {
        TlogFile.read(RECORDINGS.resolve(recording + '.tlog')).findAll { it.frame.sysid() == system && it.frame.message() != null }
                .findAll { system != 1 || it.frame.compid() == 1 }*.frame*.message()
    }

    static List<Object> changes(List values) {
        values.inject([]) { List out, v -> out.empty || out.last() != v ? out + [v] : out } as List<Object>
    }

    def "PX4 says it is PX4, every mode it was in is in PX4's table, and the first flight went from AUTO.LOITER to AUTO.MISSION"() {
        given:
        List<msg_heartbeat> beats = from('px4-copter-first-flight').findAll { it instanceof msg_heartbeat }

        expect:
        beats.every { Autopilot.of(it.autopilot) == Autopilot.PX4 && VehicleFamily.of(it.type, it.autopilot) == VehicleFamily.COPTER }
        beats.every { Px4Modes.TABLE.contains(it.custom_mode) }
        changes(beats.collect { Px4Modes.TABLE.name(it.custom_mode) }).take(2) == ['AUTO.LOITER', 'AUTO.MISSION']
    }

    def "AUTO.MISSION asked as main mode 4 and sub mode 4 is ACCEPTED, and so is MISSION_START from the first item"() {
        given:
        List<msg_command_long> asked = from('px4-copter-first-flight', 208).findAll { it instanceof msg_command_long }
        List<msg_command_ack> acks = from('px4-copter-first-flight').findAll { it instanceof msg_command_ack }
        def mode = asked.find { it.command == MAV_CMD.MAV_CMD_DO_SET_MODE }
        def start = asked.find { it.command == MAV_CMD.MAV_CMD_MISSION_START }

        expect:
        [mode.param1, mode.param2, mode.param3] == [1f, 4f, 4f]
        start.param1 == 0f
        acks.find { it.command == MAV_CMD.MAV_CMD_DO_SET_MODE }.result == MAV_RESULT.MAV_RESULT_ACCEPTED
        acks.find { it.command == MAV_CMD.MAV_CMD_MISSION_START }.result == MAV_RESULT.MAV_RESULT_ACCEPTED
        !asked.any { it.command == MAV_CMD.MAV_CMD_DO_SET_MISSION_CURRENT }
    }

    def "MISSION_CURRENT: 65535 items and no mission at first, then the mission's items without home, NOT_STARTED, ACTIVE, COMPLETE after the landing"() {
        given:
        List<msg_mission_current> current = from('px4-copter-first-flight').findAll { it instanceof msg_mission_current }

        expect:
        current.first().total == 65535
        current.first().mission_state == MISSION_STATE.MISSION_STATE_NO_MISSION
        changes(current*.mission_state) == [MISSION_STATE.MISSION_STATE_NO_MISSION, MISSION_STATE.MISSION_STATE_NOT_STARTED,
                                           MISSION_STATE.MISSION_STATE_ACTIVE, MISSION_STATE.MISSION_STATE_COMPLETE]
        current.last().total == 4
        current*.seq.max() == 3
    }

    def "MISSION_ITEM_REACHED comes again and again for the same item, as the executor takes it"() {
        given:
        List<Integer> reached = from('px4-copter-first-flight').findAll { it instanceof msg_mission_item_reached }*.seq

        expect:
        reached.countBy { it }.values().max() > 1
        reached.max() == 3
    }

    def "a mission that leaves the fence is refused after its upload with a CRITICAL text, and MISSION_CURRENT says no mission"() {
        given:
        def messages = from('px4-copter-fence-refused')
        msg_statustext refusal = messages.find { it instanceof msg_statustext && it.getText().startsWith('Geofence violation') }
        List<msg_mission_current> after = messages.drop(messages.indexOf(refusal)).findAll { it instanceof msg_mission_current }

        expect: 'the text as PX4 writes it, a tab at its end'
        refusal.getText() == 'Geofence violation for waypoint 3\t'
        refusal.severity == MAV_SEVERITY.MAV_SEVERITY_CRITICAL
        after.every { it.mission_state == MISSION_STATE.MISSION_STATE_NO_MISSION }
        !messages.any { it instanceof msg_heartbeat && (it.base_mode & 128) != 0 }
    }

    def "#recording: a flight that went well says nothing the fault rule stops for"() {
        given:
        def said = from(recording).findAll { it instanceof msg_statustext }.collect {
            new VehicleWords.Said(it.severity, it.getText().strip(), 0)
        }

        expect:
        !said.empty
        said.findAll { it.severe() }*.text() == []

        where:
        recording << ['px4-copter-first-flight', 'px4-copter-fenced-hop']
    }
}
