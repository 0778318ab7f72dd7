package dolphin.sim

import com.MAVLink.common.msg_mission_current
import com.MAVLink.common.msg_mission_item_reached
import com.MAVLink.common.msg_statustext
import com.MAVLink.enums.COPTER_MODE
import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_MISSION_RESULT
import com.MAVLink.enums.MAV_MODE_FLAG
import com.MAVLink.enums.MAV_RESULT
import com.MAVLink.enums.MISSION_STATE
import com.MAVLink.enums.PLANE_MODE
import dolphin.core.Position
import dolphin.mission.model.MissionItem
import spock.lang.Specification

import static dolphin.sim.MissionProtocolSpec.HOME
import static dolphin.sim.MissionProtocolSpec.rel

/** Simulated vehicles flying missions in AUTO, RTL and the start rules (ardupilot-behaviour.md §2.5). */
class MissionFlightSpec extends Specification {

    RawGroundStation gcs

    def cleanup() {
        gcs?.close()
    }

    static double horizontal(Position a, Position b) {
        def ned = a.displacementTo(b)
        Math.hypot(ned[0], ned[1])
    }

    void setMode(int mode, int expected = MAV_RESULT.MAV_RESULT_ACCEPTED) {
        assert gcs.command(MAV_CMD.MAV_CMD_DO_SET_MODE, [MAV_MODE_FLAG.MAV_MODE_FLAG_CUSTOM_MODE_ENABLED, mode]).result == expected
    }

    void arm(int expected = MAV_RESULT.MAV_RESULT_ACCEPTED) {
        assert gcs.command(MAV_CMD.MAV_CMD_COMPONENT_ARM_DISARM, [1]).result == expected
    }

    /**
     * The items reached, once the ground station has heard item {@code last} reached and the mission
     * COMPLETE: the vehicle's own state changes before those frames have crossed the socket.
     */
    List<Integer> reachedThrough(int from, int last) {
        gcs.await(from, msg_mission_item_reached) { it.seq == last }
        gcs.await(from, msg_mission_current) { it.mission_state == MISSION_STATE.MISSION_STATE_COMPLETE }
        gcs.since(from, msg_mission_item_reached)*.seq
    }

    /**
     * The index in the received messages where a copter's mission ended on its NAV_LAND as ArduCopter
     * ends it: "Disarming motors", then the mission started over (MISSION_CURRENT back at item 1).
     */
    int landingEnd(int from, double seconds) {
        def disarming = gcs.await(from, msg_statustext, seconds) { it.text == 'Disarming motors' }
        int at = gcs.indexOf(from) { it.is(disarming) }
        gcs.await(at, msg_mission_current) { it.seq == 1 }
        at
    }

    static final List<MissionItem> COPTER_MISSION = [
            MissionItem.at(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, HOME, 0, 0, 0, 0),
            rel(1, MAV_CMD.MAV_CMD_NAV_TAKEOFF, 0, 0, 10),
            MissionItem.command(2, MAV_CMD.MAV_CMD_DO_CHANGE_SPEED, 1, 5, -1, 0),
            rel(3, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 30, 0, 10),
            rel(4, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 30, 30, 15),
            rel(5, MAV_CMD.MAV_CMD_NAV_LOITER_TIME, 30, 30, 15, 3),
            MissionItem.command(6, MAV_CMD.MAV_CMD_IMAGE_START_CAPTURE, 0, 2, 0, 0),
            rel(7, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 0, 30, 10),
            rel(8, MAV_CMD.MAV_CMD_NAV_LAND, 0, 30, 0)]

    def "a copter flies takeoff, speed, waypoints, loiter time, camera and land after GUIDED, arm, AUTO, MISSION_START"() {
        given:
        gcs = new RawGroundStation(VehicleKind.COPTER, 20)
        def sim = gcs.vehicle()
        assert gcs.upload(COPTER_MISSION) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        int from = gcs.mark()

        when:
        setMode(COPTER_MODE.COPTER_MODE_GUIDED)
        arm()
        setMode(COPTER_MODE.COPTER_MODE_AUTO)
        long started = gcs.clock.nanoTime()
        assert gcs.command(MAV_CMD.MAV_CMD_MISSION_START, [0, 0]).result == MAV_RESULT.MAV_RESULT_ACCEPTED
        int landed = landingEnd(from, 30)
        double seconds = (gcs.clock.nanoTime() - started) / 1e9
        def reached = gcs.since(from, msg_mission_item_reached)*.seq
        def current = gcs.since(from, msg_mission_current)

        then: 'landed at the landing point, disarmed, still in AUTO'
        !sim.armed()
        horizontal(sim.position(), HOME.displace(0, 30, 0)) < 1.5
        Math.abs(sim.position().hae() - HOME.hae()) < 0.05
        sim.mode() == COPTER_MODE.COPTER_MODE_AUTO
        sim.cameraCommands() == 1

        and: 'reached in order up to the last waypoint; the landing never, as in ArduCopter SITL (it disarms before the item completes, and the disarm starts the mission over)'
        reached == [2, 3, 4, 5, 7]

        and: 'coalesced as ArduPilot does: the takeoff completes in the tick that runs DO_CHANGE_SPEED (2); the camera item (6) is never reported, AP_Mission completes it itself'
        current.any { it.seq == 1 && it.mission_state == MISSION_STATE.MISSION_STATE_ACTIVE && it.total == 8 }
        current.any { it.seq == 8 && it.mission_state == MISSION_STATE.MISSION_STATE_ACTIVE }
        !current.any { it.mission_state == MISSION_STATE.MISSION_STATE_COMPLETE }
        gcs.since(from, msg_statustext)*.text.containsAll(['Reached command #3', 'Mission: 8 Land'])

        and: 'the mission started over: item 1 current and ACTIVE though disarmed'
        gcs.since(landed, msg_mission_current).last().seq == 1
        gcs.since(landed, msg_mission_current).last().mission_state == MISSION_STATE.MISSION_STATE_ACTIVE

        and: 'at 5 m/s the flight took long enough: 10 m climb, 30 + 30 + 30 m legs, 3 s loiter, 10 m descent, 2 s to detect the landing'
        seconds > 4 + 18 + 3 + 6 + 2
        seconds < 90
    }

    /** Takeoff, A, B, a DO_JUMP to {@code target} {@code times} times, land at home. */
    static List<MissionItem> jumpMission(int target, int times) {
        [MissionItem.at(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, HOME, 0, 0, 0, 0),
         rel(1, MAV_CMD.MAV_CMD_NAV_TAKEOFF, 0, 0, 10),
         rel(2, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 20, 0, 10),
         rel(3, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 20, 20, 10),
         MissionItem.command(4, MAV_CMD.MAV_CMD_DO_JUMP, target, times, 0, 0),
         rel(5, MAV_CMD.MAV_CMD_NAV_LAND, 0, 0, 0)]
    }

    /**
     * A copter stored {@code jumpMission(target, times)} and started in AUTO; the mark before its
     * start. ArduPilot refuses a jump past the end at upload, so such a mission is left by an upload
     * refused at that jump after a longer mission (the truncated list keeps the longer one's items).
     */
    int flyJumps(int target, int times) {
        gcs = new RawGroundStation(VehicleKind.COPTER, 20)
        def items = jumpMission(target, times)
        if (target < items.size()) {
            assert gcs.upload(items) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        } else {
            def longer = items + (items.size()..target).collect { rel(it, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 20, 20, 10) }
            assert gcs.upload(longer) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
            assert gcs.upload(items) == MAV_MISSION_RESULT.MAV_MISSION_ERROR
            assert gcs.vehicle().mission().drop(1) == items.drop(1)
        }
        int from = gcs.mark()
        setMode(COPTER_MODE.COPTER_MODE_GUIDED)
        arm()
        setMode(COPTER_MODE.COPTER_MODE_AUTO)
        assert gcs.command(MAV_CMD.MAV_CMD_MISSION_START, [0, 0]).result == MAV_RESULT.MAV_RESULT_ACCEPTED
        from
    }

    def "DO_JUMP sends the mission back to its target p2 more times, is never reached, and announces jumps as AP_Mission does"() {
        when:
        int from = flyJumps(2, 2)
        def sim = gcs.vehicle()
        landingEnd(from, 30)
        def reached = gcs.since(from, msg_mission_item_reached)*.seq

        then: 'A and B three times (once, then two jumps), then the landing at home (never reported reached by a copter)'
        reached.count(2) == 3
        reached.count(3) == 3
        !reached.contains(4)
        reached.last() == 3
        horizontal(sim.position(), HOME) < 1.5

        and: 'the first jump is silent, the second says which of how many'
        def texts = gcs.since(from, msg_statustext)*.text
        texts.contains('Mission: 4 Jump 2/2')
        !texts.any { it.startsWith('Mission: 4 Jump 1/') }
    }

    def "a DO_JUMP to an item outside the mission ends the mission there: the copter hovers, mission COMPLETE"() {
        when:
        int from = flyJumps(9, 1)
        def sim = gcs.vehicle()
        gcs.waitFor(30, 'mission complete') { sim.missionState() == MISSION_STATE.MISSION_STATE_COMPLETE }

        then:
        sim.armed()
        reachedThrough(from, 3).last() == 3
        horizontal(sim.position(), HOME.displace(20, 20, 0)) < 1.5
    }

    def "a copter armed in GUIDED and switched to AUTO waits for MISSION_START (p1 = p2 = 0, else DENIED)"() {
        given:
        gcs = new RawGroundStation(VehicleKind.COPTER, 20)
        def sim = gcs.vehicle()
        assert gcs.upload(COPTER_MISSION) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED

        when:
        setMode(COPTER_MODE.COPTER_MODE_GUIDED)
        arm()
        setMode(COPTER_MODE.COPTER_MODE_AUTO)
        long t0 = gcs.clock.nanoTime()
        gcs.waitFor(5, '3 s of clock time') { gcs.clock.nanoTime() - t0 > 3e9 }

        then: 'still on the ground, armed; its mission already runs (ModeAuto::run starts it on entering AUTO), at the take-off'
        sim.armed()
        Math.abs(sim.position().hae() - HOME.hae()) < 0.01
        sim.missionState() == MISSION_STATE.MISSION_STATE_ACTIVE
        sim.missionCurrent() == 1

        and:
        gcs.command(MAV_CMD.MAV_CMD_MISSION_START, [1, 0]).result == MAV_RESULT.MAV_RESULT_DENIED
        gcs.command(MAV_CMD.MAV_CMD_MISSION_START, [0, 0]).result == MAV_RESULT.MAV_RESULT_ACCEPTED

        when:
        gcs.waitFor(10, 'climbing') { sim.position().hae() > HOME.hae() + 2 }

        then:
        sim.missionState() == MISSION_STATE.MISSION_STATE_ACTIVE
    }

    def "a copter armed on the ground in AUTO without MISSION_START disarms itself after 10 s"() {
        given:
        gcs = new RawGroundStation(VehicleKind.COPTER, 20)
        def sim = gcs.vehicle()
        assert gcs.upload(COPTER_MISSION) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        setMode(COPTER_MODE.COPTER_MODE_GUIDED)
        arm()

        when:
        setMode(COPTER_MODE.COPTER_MODE_AUTO)
        long t0 = gcs.clock.nanoTime()
        gcs.waitFor(10, 'disarmed') { !sim.armed() }
        double after = (gcs.clock.nanoTime() - t0) / 1e9

        then: 'the 10 s DISARM_DELAY; the bound above allows 250 ms of real time (20x) for the polling and a slow machine'
        after >= 9.5
        after < 15
        Math.abs(sim.position().hae() - HOME.hae()) < 0.01
    }

    def "a copter in AUTO cannot be armed, and AUTO is refused when armed on the ground without a takeoff first"() {
        given:
        gcs = new RawGroundStation(VehicleKind.COPTER, 20)
        def sim = gcs.vehicle()
        assert gcs.upload([COPTER_MISSION[0], rel(1, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 30, 0, 10)]) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        int from = gcs.mark()

        when:
        setMode(COPTER_MODE.COPTER_MODE_AUTO)
        arm(MAV_RESULT.MAV_RESULT_FAILED)
        setMode(COPTER_MODE.COPTER_MODE_GUIDED)
        arm()
        setMode(COPTER_MODE.COPTER_MODE_AUTO, MAV_RESULT.MAV_RESULT_FAILED)

        then:
        gcs.await(from, msg_statustext) { it.text == 'Auto: Missing Takeoff Cmd' }
        gcs.command(MAV_CMD.MAV_CMD_MISSION_START, [0, 0]).result == MAV_RESULT.MAV_RESULT_FAILED
        sim.mode() == COPTER_MODE.COPTER_MODE_GUIDED
    }

    def "a plane armed in AUTO takes off at once and switches itself to RTL at the end of the mission"() {
        given:
        gcs = new RawGroundStation(VehicleKind.PLANE, 20)
        def sim = gcs.vehicle()
        def items = [COPTER_MISSION[0], rel(1, MAV_CMD.MAV_CMD_NAV_TAKEOFF, 0, 0, 30, 10),
                     rel(2, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 400, 0, 50), rel(3, MAV_CMD.MAV_CMD_NAV_WAYPOINT, 400, 400, 50)]
        assert gcs.upload(items) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        int from = gcs.mark()

        when:
        setMode(PLANE_MODE.PLANE_MODE_AUTO)
        arm()
        gcs.waitFor(5, 'taking off') { sim.position().hae() > HOME.hae() + 2 }
        gcs.waitFor(20, 'RTL') { sim.mode() == PLANE_MODE.PLANE_MODE_RTL }

        then:
        gcs.await(from, msg_statustext) { it.text == 'Mission complete, changing mode to RTL' }
        sim.missionState() == MISSION_STATE.MISSION_STATE_COMPLETE
        reachedThrough(from, 3).last() == 3

        when: 'it flies home and loiters over it'
        gcs.waitFor(20, 'near home') { horizontal(sim.position(), HOME) < 70 }
        long t0 = gcs.clock.nanoTime()
        gcs.waitFor(5, '20 s of clock time') { gcs.clock.nanoTime() - t0 > 20e9 }

        then:
        sim.armed()
        horizontal(sim.position(), HOME) < 70
        sim.position().hae() > HOME.hae() + 40
    }

    def "RTL brings a copter home, lands it and disarms it"() {
        given: 'a copter loitering 60 m from home at 20 m'
        gcs = new RawGroundStation(VehicleKind.COPTER, 20)
        def sim = gcs.vehicle()
        def items = [COPTER_MISSION[0], rel(1, MAV_CMD.MAV_CMD_NAV_TAKEOFF, 0, 0, 20),
                     rel(2, MAV_CMD.MAV_CMD_NAV_LOITER_UNLIM, 60, 0, 20)]
        assert gcs.upload(items) == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED
        setMode(COPTER_MODE.COPTER_MODE_GUIDED)
        arm()
        assert gcs.command(MAV_CMD.MAV_CMD_MISSION_START, [0, 0]).result == MAV_RESULT.MAV_RESULT_ACCEPTED
        gcs.waitFor(20, 'at the loiter point') { horizontal(sim.position(), HOME.displace(60, 0, 0)) < 1 }
        long t0 = gcs.clock.nanoTime()
        gcs.waitFor(5, '5 s of loiter') { gcs.clock.nanoTime() - t0 > 5e9 }
        assert sim.armed() && sim.missionState() == MISSION_STATE.MISSION_STATE_ACTIVE

        when:
        setMode(COPTER_MODE.COPTER_MODE_RTL)
        long t1 = gcs.clock.nanoTime()
        gcs.waitFor(20, 'disarmed') { !sim.armed() }
        double seconds = (gcs.clock.nanoTime() - t1) / 1e9

        then:
        horizontal(sim.position(), HOME) < 1.5
        Math.abs(sim.position().hae() - HOME.hae()) < 0.05
        seconds > 25
        seconds < 60
    }
}
