package dolphin.mission.flight

import com.MAVLink.common.msg_command_ack
import com.MAVLink.common.msg_command_long
import com.MAVLink.common.msg_mission_ack
import com.MAVLink.common.msg_mission_count
import com.MAVLink.common.msg_mission_current
import com.MAVLink.common.msg_mission_item_reached
import com.MAVLink.common.msg_statustext
import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_MISSION_RESULT
import com.MAVLink.enums.MAV_MISSION_TYPE
import com.MAVLink.enums.MAV_RESULT
import com.MAVLink.enums.MAV_SEVERITY
import com.MAVLink.enums.MISSION_STATE
import com.MAVLink.minimal.msg_heartbeat
import dolphin.mavlink.Autopilot
import dolphin.mavlink.Px4Modes
import dolphin.mavlink.VehicleFamily
import dolphin.mavlink.VehicleState
import dolphin.sim.TlogFile
import java.nio.file.Path
import spock.lang.Specification

import static dolphin.mission.flight.FeasibilityWatch.Feasibility.FEASIBLE
import static dolphin.mission.flight.FeasibilityWatch.Feasibility.INFEASIBLE
import static dolphin.mission.flight.FeasibilityWatch.Feasibility.PENDING

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

    def "PX4 names the mission it took: the final MISSION_ACK's opaque_id is MISSION_CURRENT's mission_id from then on"() {
        given:
        def messages = from('px4-copter-first-flight')
        msg_mission_ack ack = messages.find { it instanceof msg_mission_ack && it.mission_type == MAV_MISSION_TYPE.MAV_MISSION_TYPE_MISSION }
        List<msg_mission_current> after = messages.drop(messages.indexOf(ack)).findAll { it instanceof msg_mission_current }

        expect:
        ack.type == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        ack.opaque_id != 0
        after.every { it.mission_id == ack.opaque_id }
        after.first().mission_state == MISSION_STATE.MISSION_STATE_NOT_STARTED
    }

    /**
     * The executor's reading of PX4's verdict ({@link FeasibilityWatch}) on each mission upload of a recording: a watch
     * begun on the vehicle's state as MAVLinkCommunications puts it when the upload began, hearing each MISSION_CURRENT,
     * given the id of the upload's final ACK; its verdicts from that ACK until the vehicle armed, those in a row as one.
     * An ACK repeated for the last item sent again is the same upload's.
     */
    static List<List<FeasibilityWatch.Feasibility>> verdicts(String recording) {
        List<List<FeasibilityWatch.Feasibility>> all = []
        VehicleState state = VehicleState.initial(Autopilot.PX4, VehicleFamily.COPTER)
        FeasibilityWatch watch = null
        boolean judging = false
        for (record in TlogFile.read(RECORDINGS.resolve(recording + '.tlog'))) {
            def m = record.frame.message()
            if (m instanceof msg_mission_count && record.frame.sysid() == 208 && m.mission_type == MAV_MISSION_TYPE.MAV_MISSION_TYPE_MISSION) {
                watch = new FeasibilityWatch(m.count, state)
                judging = false
            } else if (m instanceof msg_mission_ack && record.frame.sysid() == 1 && m.mission_type == MAV_MISSION_TYPE.MAV_MISSION_TYPE_MISSION
                    && m.type == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED && watch != null && !judging) {
                watch.uploaded(m.opaque_id)
                judging = true
                all << [watch.verdict()]
            } else if (m instanceof msg_mission_current && record.frame.sysid() == 1) {
                state = state.withMissionCurrent(m.seq, m.total, m.mission_state, m.mission_id)
                watch?.heard(m.seq, m.total, m.mission_state, m.mission_id)
                if (judging) {
                    all[-1] = changes(all[-1] + [watch.verdict()])
                }
            } else if (m instanceof msg_heartbeat && record.frame.sysid() == 1 && (m.base_mode & 128) != 0) {
                watch = null    // armed: the check is over
                judging = false
            }
        }
        all
    }

    def "#recording: PX4's verdict on each mission as the executor reads it: #expected"() {
        expect:
        verdicts(recording) == expected

        where:
        recording                  || expected
        'px4-copter-first-flight'  || [[PENDING, FEASIBLE]]
        'px4-copter-fence-refused' || [[PENDING]]     // NO_MISSION since boot: two checked reports before the recording ends
        'px4-copter-fenced-hop'    || [[PENDING, FEASIBLE]]
        'px4-copter-same-mission'  || [[PENDING, FEASIBLE], [FEASIBLE], [PENDING, INFEASIBLE]]
        'px4-copter-refused-after-flight' || [[PENDING, INFEASIBLE]]   // no current item ever; COMPLETE, then NO_MISSION held
    }

    def "the same mission again is not taken again: COMPLETE stays under its id, and MISSION_START flies it again; a new one is named at once with the earlier COMPLETE and no current item"() {
        given:
        def messages = from('px4-copter-same-mission')
        List<msg_mission_ack> acks = messages.findAll { it instanceof msg_mission_ack && it.mission_type == MAV_MISSION_TYPE.MAV_MISSION_TYPE_MISSION }
        def currents = { int from, int to -> messages.subList(from, to).findAll { it instanceof msg_mission_current } }
        int second = messages.indexOf(acks[1]), third = messages.indexOf(acks[2])
        def armedAgain = messages.drop(second).find { it instanceof msg_heartbeat && (it.base_mode & 128) != 0 }

        expect:
        acks.size() == 3
        acks[0].opaque_id == acks[1].opaque_id && acks[2].opaque_id != acks[0].opaque_id
        currents(0, second).last().mission_state == MISSION_STATE.MISSION_STATE_COMPLETE
        currents(0, second).last().mission_id == acks[1].opaque_id
        changes(currents(second, third)*.mission_state) == [MISSION_STATE.MISSION_STATE_ACTIVE]
        armedAgain != null && messages.indexOf(armedAgain) < third
        with(currents(third, messages.size()).first()) {
            seq == 65535 && mission_id == acks[2].opaque_id && mission_state == MISSION_STATE.MISSION_STATE_COMPLETE
        }
        currents(third, messages.size()).last().mission_state == MISSION_STATE.MISSION_STATE_NO_MISSION
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
