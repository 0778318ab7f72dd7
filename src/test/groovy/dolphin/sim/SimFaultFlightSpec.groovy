package dolphin.sim

import com.MAVLink.ardupilotmega.msg_ekf_status_report
import com.MAVLink.common.msg_extended_sys_state
import com.MAVLink.common.msg_gps_raw_int
import com.MAVLink.common.msg_mission_current
import com.MAVLink.common.msg_mission_item_reached
import com.MAVLink.common.msg_statustext
import com.MAVLink.common.msg_sys_status
import com.MAVLink.enums.COPTER_MODE
import com.MAVLink.enums.GPS_FIX_TYPE
import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_LANDED_STATE
import com.MAVLink.enums.MAV_MISSION_RESULT
import com.MAVLink.enums.MAV_RESULT
import com.MAVLink.enums.MAV_SEVERITY
import com.MAVLink.enums.MAV_STATE
import com.MAVLink.enums.MISSION_STATE
import com.MAVLink.enums.PLANE_MODE
import com.MAVLink.enums.ROVER_MODE
import com.MAVLink.minimal.msg_heartbeat
import com.MAVLink.standard.msg_global_position_int
import dolphin.mission.model.MissionItem
import spock.lang.Specification

import static dolphin.sim.MissionProtocolSpec.rel
import static dolphin.sim.SimDriver.HOME
import static dolphin.sim.SimVehicleSpec.horizontal

/**
 * Faults injected into one simulated vehicle at a time after its first arming, on the fake clock of
 * {@link SimDriver}, no sockets (docs/mavlink.md, "Faults"): what the vehicle sends, in which order
 * and when, as {@link FaultTable} says ArduPilot does; and what must not happen without them.
 */
class SimFaultFlightSpec extends Specification {

    static final MissionItem HOME_ITEM = MissionItem.at(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, HOME, 0, 0, 0, 0)
    /** A survey at 30 m: 200 m north, 100 m east, back south, then home (RTL lands and disarms). */
    static final List<MissionItem> SURVEY = [HOME_ITEM, rel(1, MAV_CMD.MAV_CMD_NAV_TAKEOFF, 0, 0, 30),
                                            rel(2, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 200, 0, 30), rel(3, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 200, 100, 30),
                                            rel(4, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 0, 100, 30),
                                            new MissionItem(5, MAV_CMD.MAV_CMD_NAV_RETURN_TO_LAUNCH, 3, 0, 0, 0, 0, 0, 0, 0, true)]
    static final List<Integer> STREAMED = [msg_sys_status.MAVLINK_MSG_ID_SYS_STATUS, msg_global_position_int.MAVLINK_MSG_ID_GLOBAL_POSITION_INT,
                                           msg_mission_current.MAVLINK_MSG_ID_MISSION_CURRENT, msg_extended_sys_state.MAVLINK_MSG_ID_EXTENDED_SYS_STATE,
                                           msg_gps_raw_int.MAVLINK_MSG_ID_GPS_RAW_INT, msg_ekf_status_report.MAVLINK_MSG_ID_EKF_STATUS_REPORT]
    /** The texts of the faults, none of which a flight without them may say. */
    static final List<String> FAULT_TEXTS = ['Potential Thrust Loss', 'EKF variance', 'EKF Failsafe', 'stopped aiding', 'EKF failsafe']

    SimDriver d
    long armedAt

    /** Vehicle 1 of kind {@code kind} with {@code faults} injected, streaming at 4 Hz. */
    SimDriver vehicle(VehicleKind kind, List<String> faults, SimOptions options = SimOptions.DEFAULT) {
        d = new SimDriver(kind, faults.inject(options) { SimOptions o, String f -> o.withFault(SimFault.parse(f)) })
        STREAMED.each { assert d.command(MAV_CMD.MAV_CMD_SET_MESSAGE_INTERVAL, [it, 250_000]).result == MAV_RESULT.MAV_RESULT_ACCEPTED }
        d
    }

    /**
     * A copter flying SURVEY with {@code faults}, started as the executor starts it (GUIDED, armed,
     * AUTO, MISSION_START), until {@code seconds} after the arming; the mark of what it sends next.
     */
    int copterSurvey(List<String> faults, double seconds = 0) {
        vehicle(VehicleKind.COPTER, faults)
        assert d.upload(SURVEY) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        d.setMode(COPTER_MODE.COPTER_MODE_GUIDED)
        assert d.arm().result == MAV_RESULT.MAV_RESULT_ACCEPTED
        armedAt = d.now
        d.setMode(COPTER_MODE.COPTER_MODE_AUTO)
        assert d.command(MAV_CMD.MAV_CMD_MISSION_START).result == MAV_RESULT.MAV_RESULT_ACCEPTED
        runToAfterArming(seconds)
        d.mark()
    }

    /** Ticks until {@code seconds} of clock time after the arming. */
    void runToAfterArming(double seconds) {
        d.runTo(armedAt + (long) (seconds * 1e9))
    }

    /** Seconds after the arming at which frame {@code i} was sent. */
    double sinceArming(int i) {
        (d.sent[i].at - armedAt) / 1e9
    }

    /** The index of the first frame from {@code from} on that matches; fails when none does. */
    int first(int from, Closure<Boolean> match) {
        int i = d.indexOf(from, match)
        assert i >= 0
        i
    }

    static Closure<Boolean> text(String t) {
        return { it instanceof msg_statustext && it.text == t }
    }

    static Closure<Boolean> inMode(int mode) {
        return { it instanceof msg_heartbeat && it.custom_mode == mode }
    }

    /** The STATUSTEXTs sent from frame {@code from} on: [seconds after arming, severity, text]. */
    List<List> texts(int from) {
        (from..<d.sent.size()).findAll { d.sent[it].message instanceof msg_statustext }
                .collect { [sinceArming(it), d.sent[it].message.severity, d.sent[it].message.text] }
    }

    double heightAboveHome() {
        d.vehicle.position().hae() - HOME.hae()
    }

    def "a copter that loses a motor mid-survey falls, hits the ground, switches EKF lanes, and says Potential Thrust Loss every 11 s, armed in AUTO at its item"() {
        given:
        int from = copterSurvey(['motor=2@30'], 30)
        int item = d.vehicle.missionCurrent()
        assert item == 2 && heightAboveHome() > 29

        when: 'the motor stops, and 45 s go by'
        runToAfterArming(75)
        def said = texts(from)

        then: 'down in 3 s at the 14.6 m/s of SITL'
        said[0][1] == MAV_SEVERITY.MAV_SEVERITY_INFO
        said[0][2] == 'SIM Hit ground at 14.600000 m/s'
        double hit = said[0][0] as double
        Math.abs(hit - 33) <= 0.1

        and: 'at the hit EKF3 switches to lane 1 (CRITICAL) and AP_AHRS says so (WARNING), and back a quarter of a second later'
        said[1..4]*.drop(1) == [[MAV_SEVERITY.MAV_SEVERITY_CRITICAL, 'EKF3 lane switch 1'], [MAV_SEVERITY.MAV_SEVERITY_WARNING, 'EKF primary changed:1'],
                                [MAV_SEVERITY.MAV_SEVERITY_CRITICAL, 'EKF3 lane switch 0'], [MAV_SEVERITY.MAV_SEVERITY_WARNING, 'EKF primary changed:0']]
        [said[1..4]*.getAt(0), [0.05, 0.05, 0.3, 0.3]].transpose().every { t, after -> Math.abs((t as double) - hit - after) < 0.01 }

        and: 'the thrust-loss text 4 s after the hit and every 11 s, at EMERGENCY, naming motor 1, the one opposite, as SITL named 2 for 1'
        said.drop(5)*.getAt(2).every { it == 'Potential Thrust Loss (1)' }
        said.drop(5)*.getAt(1).every { it == MAV_SEVERITY.MAV_SEVERITY_EMERGENCY }
        said.drop(5).collect { (it[0] as double) - hit }.withIndex().every { double t, int i -> Math.abs(t - (4 + 11 * i)) <= 0.1 }
        said.size() == 5 + 4

        and: 'on the ground, armed, in AUTO, its item unchanged, IN_AIR as ArduCopter without land_complete, ACTIVE'
        heightAboveHome() == 0
        d.vehicle.armed()
        d.vehicle.mode() == COPTER_MODE.COPTER_MODE_AUTO
        d.vehicle.missionCurrent() == item
        d.vehicle.missionState() == MISSION_STATE.MISSION_STATE_ACTIVE
        d.since(from, msg_mission_item_reached).empty
        d.since(from, msg_extended_sys_state).last().landed_state == MAV_LANDED_STATE.MAV_LANDED_STATE_IN_AIR
        d.since(from, msg_global_position_int).last().relative_alt == 0
        d.since(from, msg_mission_current).last().with { it.seq == item && it.mission_state == MISSION_STATE.MISSION_STATE_ACTIVE }
        d.since(from, msg_heartbeat).last().system_status == MAV_STATE.MAV_STATE_ACTIVE

        when: 'the ground station disarms it'
        assert d.command(MAV_CMD.MAV_CMD_COMPONENT_ARM_DISARM, [0]).result == MAV_RESULT.MAV_RESULT_ACCEPTED
        int disarmed = d.mark()
        d.run(10)

        then: 'it says no more, and is landed'
        !texts(disarmed)*.getAt(2).any { it.startsWith('Potential Thrust Loss') }
        d.vehicle.landedState() == MAV_LANDED_STATE.MAV_LANDED_STATE_ON_GROUND
    }

    def "a copter whose motor stops before it lifts off stays on the ground: no impact, so no lane switch, and landed, so no thrust loss"() {
        given:
        int from = copterSurvey(['motor@0'], 0)

        when:
        runToAfterArming(30)

        then:
        heightAboveHome() == 0
        d.vehicle.armed()
        texts(from).empty
    }

    def "a copter that loses its GPS mid-survey: NO_GPS after 4 s, the EKF's position gone after 7, then a lane switch, LAND, EKF variance and the failsafe's text; it lands and disarms"() {
        given:
        int from = copterSurvey(['gps@30'], 30)

        when:
        runToAfterArming(80)

        then: 'GPS_RAW_INT: a 3D fix with 10 satellites until AP_GPS gives the receiver up 4 s on, then NO_GPS without a position'
        int noGps = first(from) { it instanceof msg_gps_raw_int && it.fix_type != GPS_FIX_TYPE.GPS_FIX_TYPE_3D_FIX }
        Math.abs(sinceArming(noGps) - 34) <= 0.3
        d.since(from, msg_gps_raw_int).takeWhile { it.fix_type == GPS_FIX_TYPE.GPS_FIX_TYPE_3D_FIX }.every { it.satellites_visible == 10 }
        d.sent.drop(noGps)*.message.findAll { it instanceof msg_gps_raw_int }
                .every { it.fix_type == GPS_FIX_TYPE.GPS_FIX_TYPE_NO_GPS && it.lat == 0 && it.satellites_visible == 0 }

        and: 'EKF_STATUS_REPORT: 831 until the position times out 7 s on, then attitude, vertical velocity and height (37)'
        int lost = first(from) { it instanceof msg_ekf_status_report && it.flags != NavigationState.EKF_LOCATED }
        Math.abs(sinceArming(lost) - 37) <= 0.3
        d.sent[lost].message.flags == 37

        and: 'a second later, in this order, as SITL: "EKF3 lane switch 1", the heartbeat in LAND, "EKF variance: position lost", "EKF Failsafe: changed to Land Mode"'
        int lane = first(from, text('EKF3 lane switch 1'))
        int land = first(from, inMode(COPTER_MODE.COPTER_MODE_LAND))
        int variance = first(from, text('EKF variance: position lost'))
        int failsafe = first(from, text('EKF Failsafe: changed to Land Mode'))
        lane < land && land < variance && variance < failsafe
        Math.abs(sinceArming(lane) - 38) <= 0.1
        [land, variance, failsafe].every { sinceArming(it) == sinceArming(lane) }
        [lane, variance, failsafe].every { d.sent[it].message.severity == MAV_SEVERITY.MAV_SEVERITY_CRITICAL }
        d.sent.drop(land)*.message.findAll { it instanceof msg_heartbeat }.every { it.system_status == MAV_STATE.MAV_STATE_CRITICAL }
        d.sent.take(land)*.message.findAll { it instanceof msg_heartbeat }.every { it.system_status != MAV_STATE.MAV_STATE_CRITICAL }

        and: 'LAND reports LANDING from its start, its pause included'
        Math.abs(sinceArming(first(land) { it instanceof msg_extended_sys_state }) - 38) <= 0.3
        d.sent.drop(land)*.message.find { it instanceof msg_extended_sys_state }.landed_state == MAV_LANDED_STATE.MAV_LANDED_STATE_LANDING

        and: 'EKF3 stops aiding 15 s on, one text per core at WARNING, lane 1 (the primary) first, and reports its constant position mode (167)'
        int aiding = first(from, text('EKF3 IMU1 stopped aiding'))
        d.sent[aiding + 1].message.text == 'EKF3 IMU0 stopped aiding'
        d.sent[aiding].message.severity == MAV_SEVERITY.MAV_SEVERITY_WARNING
        Math.abs(sinceArming(aiding) - 45) <= 0.1
        d.since(aiding, msg_ekf_status_report).every { it.flags == 167 }

        and: 'SmartRTL gives up 15 s after the position timed out (WARNING)'
        int smartRtl = first(from, text('SmartRTL deactivated: bad position'))
        Math.abs(sinceArming(smartRtl) - 52) <= 0.1
        d.sent[smartRtl].message.severity == MAV_SEVERITY.MAV_SEVERITY_WARNING

        and: 'it landed where it was, out on the survey, after the 4 s pause, and disarmed, EKF3 back on lane 0; the texts in all'
        texts(from)*.getAt(2) == ['EKF3 lane switch 1', 'EKF primary changed:1', 'EKF variance: position lost', 'EKF Failsafe: changed to Land Mode',
                                  'EKF3 IMU1 stopped aiding', 'EKF3 IMU0 stopped aiding', 'SmartRTL deactivated: bad position',
                                  'SIM Hit ground at 0.500000 m/s', 'Disarming motors', 'EKF primary changed:0']
        !d.vehicle.armed()
        d.vehicle.mode() == COPTER_MODE.COPTER_MODE_LAND
        heightAboveHome() == 0
        horizontal(d.vehicle.position(), HOME) > 100
    }

    def "in the LAND failsafe's pause the copter holds its height 4 s, then descends"() {
        given:
        copterSurvey(['gps@30'], 38.1)
        assert d.vehicle.mode() == COPTER_MODE.COPTER_MODE_LAND
        double height = heightAboveHome()

        when:
        runToAfterArming(41.9)
        double paused = heightAboveHome()
        runToAfterArming(45)

        then:
        paused == height
        heightAboveHome() < height - 3
    }

    def "a rover that loses its GPS in AUTO: HOLD, EKF variance, EKF failsafe, as ArduRover's ekf_check; it stands there, armed"() {
        given:
        vehicle(VehicleKind.ROVER, ['gps@10'])
        assert d.upload([HOME_ITEM, rel(1, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 300, 0, 0)]) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        assert d.arm().result == MAV_RESULT.MAV_RESULT_ACCEPTED
        armedAt = d.now
        d.setMode(ROVER_MODE.ROVER_MODE_AUTO)
        int from = d.mark()

        when:
        runToAfterArming(45)
        def at = d.vehicle.position()
        d.run(10)

        then: 'the heartbeat in HOLD first, then the texts, as SITL sent them; no lane switch'
        int hold = first(from, inMode(ROVER_MODE.ROVER_MODE_HOLD))
        int variance = first(from, text('EKF variance'))
        int failsafe = first(from, text('EKF failsafe'))
        hold < variance && variance < failsafe
        Math.abs(sinceArming(variance) - 18) <= 0.1

        and: 'EKF3 stops aiding 15 s on, lane 0 first; SmartRTL gives up 15 s after that'
        texts(from)*.getAt(2) == ['Mission: 1 WP', 'Internal Errors 0x20000000', 'EKF variance', 'EKF failsafe', 'EKF3 IMU0 stopped aiding', 'EKF3 IMU1 stopped aiding',
                                  'SmartRTL deactivated: bad position']
        Math.abs(sinceArming(first(from, text('SmartRTL deactivated: bad position'))) - 40) <= 0.1
        d.vehicle.armed()
        horizontal(d.vehicle.position(), at) < 0.01
        d.since(from, msg_heartbeat).last().system_status == MAV_STATE.MAV_STATE_CRITICAL
    }

    def "a #kind reports ArduRover's internal error (CRITICAL) once as its mission first starts armed, and its heartbeat is CRITICAL from then on; a copter does not"() {
        given:
        vehicle(kind, [])
        assert d.upload([HOME_ITEM, rel(1, MAV_CMD.MAV_CMD_NAV_TAKEOFF, 0, 0, 30), rel(2, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 100, 0, 30)]) ==
                MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED

        when: 'disarmed, the mission started from its first item as dolphin starts it (DO_SET_MISSION_CURRENT, reset)'
        d.command(MAV_CMD.MAV_CMD_DO_SET_MISSION_CURRENT, [1, 1])
        d.run(2)

        then:
        !texts(0).any { it[2].startsWith('Internal Errors') }
        d.since(0, msg_heartbeat).every { it.system_status != MAV_STATE.MAV_STATE_CRITICAL }

        when: 'armed, started again, in AUTO, then HOLD and AUTO again'
        int from = d.mark()
        d.setMode(guided)
        assert d.arm().result == MAV_RESULT.MAV_RESULT_ACCEPTED
        d.command(MAV_CMD.MAV_CMD_DO_SET_MISSION_CURRENT, [1, 1])
        d.setMode(auto)
        d.command(MAV_CMD.MAV_CMD_MISSION_START)
        d.run(5)
        d.setMode(hold)
        d.setMode(auto)
        d.run(5)
        def said = texts(from)*.getAt(2)

        then: 'the text right after the start of the first item, once'
        said.findAll { it.startsWith('Internal Errors') } == errors
        !errors || said[said.indexOf('Internal Errors 0x20000000') - 1] == 'Mission: 1 Takeoff'
        texts(from).findAll { it[2].startsWith('Internal Errors') }.every { it[1] == MAV_SEVERITY.MAV_SEVERITY_CRITICAL }
        (d.since(from, msg_heartbeat).last().system_status == MAV_STATE.MAV_STATE_CRITICAL) == !errors.empty

        where:
        kind               | guided                           | auto                         | hold                           || errors
        VehicleKind.ROVER  | ROVER_MODE.ROVER_MODE_MANUAL     | ROVER_MODE.ROVER_MODE_AUTO   | ROVER_MODE.ROVER_MODE_HOLD     || ['Internal Errors 0x20000000']
        VehicleKind.BOAT   | ROVER_MODE.ROVER_MODE_MANUAL     | ROVER_MODE.ROVER_MODE_AUTO   | ROVER_MODE.ROVER_MODE_HOLD     || ['Internal Errors 0x20000000']
        VehicleKind.COPTER | COPTER_MODE.COPTER_MODE_GUIDED   | COPTER_MODE.COPTER_MODE_AUTO | COPTER_MODE.COPTER_MODE_LOITER || []
    }

    def "a pilot takes a copter over mid-survey: LOITER, held there 15 s, then AUTO at the same item; the survey ends as it would have"() {
        given:
        int from = copterSurvey(['takeover=15@30'], 29.99)
        int item = d.vehicle.missionCurrent()
        d.tick()
        def taken = d.vehicle.position()

        when:
        runToAfterArming(44.9)

        then: 'LOITER at once, the mission stopped at its item, the copter braking to the point and staying there'
        Math.abs(sinceArming(first(from, inMode(COPTER_MODE.COPTER_MODE_LOITER))) - 30) <= 0.06
        d.vehicle.mode() == COPTER_MODE.COPTER_MODE_LOITER
        d.vehicle.missionCurrent() == item
        d.since(from, msg_mission_current).last().mission_state == MISSION_STATE.MISSION_STATE_NOT_STARTED
        horizontal(d.vehicle.position(), taken) < 1
        Math.abs(heightAboveHome() - 30) < 0.1
        d.since(from, msg_mission_item_reached).empty

        when:
        int back = d.mark()
        d.runUntil(300, 'the end of the survey') { !d.vehicle.armed() }

        then: 'AUTO after 15 s, the same item started again, then every item reached in order, home and disarmed'
        Math.abs(sinceArming(first(back, inMode(COPTER_MODE.COPTER_MODE_AUTO))) - 45) <= 0.06
        texts(back)[0][2] == "Mission: ${item} WP".toString()
        d.since(from, msg_mission_item_reached)*.seq == (item..5).toList()
        d.vehicle.missionState() == MISSION_STATE.MISSION_STATE_COMPLETE
        horizontal(d.vehicle.position(), HOME) < 1.5
        !texts(from)*.getAt(2).any { t -> FAULT_TEXTS.any { t.contains(it) } }
    }

    def "a takeover hands back AUTO only if its mode is still on: a ground station's RTL meanwhile stands"() {
        given:
        copterSurvey(['takeover=15@30'], 35)

        when:
        d.setMode(COPTER_MODE.COPTER_MODE_RTL)
        runToAfterArming(50)

        then:
        d.vehicle.mode() == COPTER_MODE.COPTER_MODE_RTL
    }

    def "a rover's takeover holds it in HOLD, a plane's circles it in LOITER, by default"() {
        when:
        vehicle(kind, ['takeover=10@1'])
        assert d.upload([HOME_ITEM, rel(1, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 500, 0, 50)]) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        d.arm()
        d.setMode(auto)
        d.run(5)

        then:
        d.vehicle.mode() == hold

        where:
        kind               | auto                       | hold
        VehicleKind.ROVER  | ROVER_MODE.ROVER_MODE_AUTO | ROVER_MODE.ROVER_MODE_HOLD
        VehicleKind.PLANE  | PLANE_MODE.PLANE_MODE_AUTO | PLANE_MODE.PLANE_MODE_LOITER
    }

    def "a stall keeps a copter in AUTO at its item without progress for its duration, then it goes on"() {
        given:
        int from = copterSurvey(['stall=20@30'], 30)
        int item = d.vehicle.missionCurrent()
        def stalled = d.vehicle.position()

        when:
        runToAfterArming(49.9)

        then: 'braked to a stop where the wind met it, still AUTO and ACTIVE at the same item'
        d.vehicle.mode() == COPTER_MODE.COPTER_MODE_AUTO
        d.vehicle.missionCurrent() == item
        d.since(from, msg_mission_current).every { it.seq == item && it.mission_state == MISSION_STATE.MISSION_STATE_ACTIVE }
        d.since(from, msg_mission_item_reached).empty
        horizontal(d.vehicle.position(), stalled) < 1

        when:
        d.runUntil(300, 'the end of the survey') { !d.vehicle.armed() }

        then:
        d.since(from, msg_mission_item_reached)*.seq == (item..5).toList()
    }

    def "a stall for ever: no progress in AUTO however long, but RTL from the ground station brings the copter home"() {
        given:
        int from = copterSurvey(['stall@30'], 30)
        int item = d.vehicle.missionCurrent()

        when:
        runToAfterArming(200)

        then:
        d.vehicle.mode() == COPTER_MODE.COPTER_MODE_AUTO
        d.vehicle.missionCurrent() == item
        d.since(from, msg_mission_item_reached).empty

        when:
        d.setMode(COPTER_MODE.COPTER_MODE_RTL)
        d.runUntil(120, 'the landing at home') { !d.vehicle.armed() }

        then:
        horizontal(d.vehicle.position(), HOME) < 1.5
    }

    def "a reboot mid-survey: time since boot from 0, disarmed in STABILIZE, its streams and its place in the mission forgotten, and the copter falls"() {
        given:
        int from = copterSurvey(['reboot@30'], 30)
        long bootMillisBefore = d.since(0, msg_global_position_int).last().time_boot_ms

        when:
        d.run(10)

        then: 'the first heartbeat at once, then no stream until asked again, as a copter after boot'
        bootMillisBefore >= 29_000
        d.since(from, msg_heartbeat).every { it.custom_mode == COPTER_MODE.COPTER_MODE_STABILIZE && (it.base_mode & 128) == 0 }
        d.vehicle.streams().isEmpty()
        d.since(from, msg_global_position_int).empty
        texts(from)*.getAt(2) == ['SIM Hit ground at 14.600000 m/s']
        heightAboveHome() == 0
        d.vehicle.missionCurrent() == 0
        d.vehicle.missionState() == MISSION_STATE.MISSION_STATE_NOT_STARTED
        d.vehicle.mission().size() == SURVEY.size()

        when: 'asked again, GLOBAL_POSITION_INT counts from the reboot'
        d.command(MAV_CMD.MAV_CMD_SET_MESSAGE_INTERVAL, [msg_global_position_int.MAVLINK_MSG_ID_GLOBAL_POSITION_INT, 250_000])
        d.run(1)

        then:
        d.since(from, msg_global_position_int).last().time_boot_ms.with { it >= 10_000 && it <= 11_000 }
    }

    def "an outage: nothing from the vehicle and nothing heard by it for its duration, while it flies on; then heard again"() {
        given:
        int from = copterSurvey(['outage=10@30'], 30)
        def before = d.vehicle.position()

        when:
        runToAfterArming(39.9)
        int handled = d.vehicle.commandsHandled()
        d.command(MAV_CMD.MAV_CMD_DO_SET_MODE, [1, COPTER_MODE.COPTER_MODE_RTL])

        then: 'silent both ways, the survey going on'
        d.mark() == from
        d.vehicle.commandsHandled() == handled
        d.vehicle.mode() == COPTER_MODE.COPTER_MODE_AUTO
        horizontal(d.vehicle.position(), before) > 50

        when:
        runToAfterArming(41)

        then:
        Math.abs(sinceArming(from) - 40) <= 0.06
        !d.since(from, msg_heartbeat).empty
    }

    def "a plane whose engine fails glides down at 2 m/s, hits the ground, and 9.5 s later is ON_GROUND; armed in AUTO, nothing said but SITL's"() {
        given:
        vehicle(VehicleKind.PLANE, ['motor@40'])
        assert d.upload([HOME_ITEM, rel(1, MAV_CMD.MAV_CMD_NAV_TAKEOFF, 0, 0, 30), rel(2, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 2000, 0, 30)]) ==
                MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        assert d.arm().result == MAV_RESULT.MAV_RESULT_ACCEPTED
        armedAt = d.now
        d.setMode(PLANE_MODE.PLANE_MODE_AUTO)
        runToAfterArming(40)
        double height = heightAboveHome()
        int from = d.mark()

        when:
        runToAfterArming(45)

        then: 'losing 2 m a second, still moving on'
        Math.abs(heightAboveHome() - (height - 10)) < 0.2

        when:
        d.runUntil(30, 'the ground') { heightAboveHome() == 0 }
        long hit = d.now
        d.runUntil(15, 'ON_GROUND') { d.vehicle.landedState() == MAV_LANDED_STATE.MAV_LANDED_STATE_ON_GROUND }

        then:
        Math.abs((d.now - hit) / 1e9 - 9.5) <= 0.1
        texts(from)*.getAt(2) == ['SIM Hit ground at 2.000000 m/s']
        d.vehicle.armed()
        d.vehicle.mode() == PLANE_MODE.PLANE_MODE_AUTO
        d.vehicle.missionCurrent() == 2
    }

    def "faults count from the first arming: a copter that never arms never has them, one that arms late has them late"() {
        given:
        vehicle(VehicleKind.COPTER, ['gps@10'], SimOptions.DEFAULT.withWarmup(41))

        when: 'a minute and a half disarmed'
        d.run(90)

        then:
        d.since(0, msg_gps_raw_int).every { it.fix_type != GPS_FIX_TYPE.GPS_FIX_TYPE_NO_GPS }

        when: 'armed at 90 s'
        d.setMode(COPTER_MODE.COPTER_MODE_GUIDED)
        assert d.arm().result == MAV_RESULT.MAV_RESULT_ACCEPTED
        armedAt = d.now
        int from = d.mark()
        runToAfterArming(20)

        then: 'the receiver given up 10 + 4 s after the arming'
        Math.abs(sinceArming(first(from) { it instanceof msg_gps_raw_int && it.fix_type == GPS_FIX_TYPE.GPS_FIX_TYPE_NO_GPS }) - 14) <= 0.3
    }

    def "a fault for another system id leaves this vehicle alone"() {
        when:
        copterSurvey(['motor@30:2', 'gps@30:2'], 60)

        then:
        heightAboveHome() > 29
        d.vehicle.mode() == COPTER_MODE.COPTER_MODE_AUTO
    }

    def "without faults a whole survey says none of their texts, its GPS and EKF stay good and its heartbeat never CRITICAL"() {
        when:
        copterSurvey([])
        d.runUntil(300, 'the end of the survey') { !d.vehicle.armed() }

        then:
        d.since(0, msg_mission_item_reached)*.seq == [1, 2, 3, 4, 5]
        !texts(0)*.getAt(2).any { t -> FAULT_TEXTS.any { t.contains(it) } }
        d.since(0, msg_gps_raw_int).every { it.fix_type == GPS_FIX_TYPE.GPS_FIX_TYPE_3D_FIX }
        d.since(0, msg_ekf_status_report).every { it.flags == NavigationState.EKF_LOCATED }
        d.since(0, msg_heartbeat).every { it.system_status != MAV_STATE.MAV_STATE_CRITICAL }
    }
}
