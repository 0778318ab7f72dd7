package dolphin.mavlink;

import com.MAVLink.common.msg_sys_status;
import com.MAVLink.enums.MAV_LANDED_STATE;
import com.MAVLink.enums.MISSION_STATE;
import com.MAVLink.minimal.msg_heartbeat;
import dolphin.core.Position;
import java.util.ArrayList;
import java.util.List;

/**
 * What the ground station knows of a vehicle, as an immutable snapshot. The communications thread
 * replaces it on each update (from the vehicle's autopilot component only); script and UI threads
 * read whole snapshots, so they never see half an update.
 *
 * @param heartbeat the last autopilot heartbeat; null before the first
 * @param heartbeatNanos clock time of that heartbeat
 * @param autopilot the autopilot the vehicle runs, from its first heartbeat
 * @param family its kind, from the same heartbeat, and for an ArduPlane its EXTENDED_SYS_STATE
 * @param systemStatus the last SYS_STATUS; null before the first
 * @param position the last GLOBAL_POSITION_INT, height above mean sea level; null before the first
 * @param relativeAlt metres above home from the same message
 * @param heading degrees from north (0..360) from the same message, NaN when the vehicle does not know it
 * @param home the vehicle's home from HOME_POSITION; null until reported
 * @param landedState MAV_LANDED_STATE from EXTENDED_SYS_STATE (0 = undefined)
 * @param vtolState MAV_VTOL_STATE from EXTENDED_SYS_STATE: how a QuadPlane flies (0 = undefined: not a VTOL)
 * @param missionSeq the current mission item (MISSION_CURRENT.seq) numbered as the runtime numbers items, home 0
 *        and the first item 1 ({@link Autopilot#missionSeq}), -1 before the first and while the vehicle names none
 *        (UINT16_MAX: PX4 between taking a new mission and its navigator's first word on it)
 * @param missionTotal MISSION_CURRENT.total (items excluding home), 0 when the vehicle has no mission, -1 when unknown
 * @param missionState MISSION_CURRENT.mission_state (MISSION_STATE), 0 when unknown
 * @param missionId MISSION_CURRENT.mission_id, the vehicle's id of the mission it holds (PX4: its CRC32, as in the
 *        upload's final MISSION_ACK), 0 when the vehicle gives none
 * @param statusTexts the last STATUSTEXT lines, oldest first
 * @param ekfFlags EKF_STATUS_REPORT.flags (ArduPilot's EKF_STATUS_FLAGS), -1 before the first
 * @param fenceBreached FENCE_STATUS.breach_status: the vehicle is outside its fence; false before the first
 *        (ArduPilot sends FENCE_STATUS only with its fence on)
 * @param bootMillis the vehicle's time since boot (GLOBAL_POSITION_INT.time_boot_ms), -1 before the first
 * @param reboots how often that time went back by more than {@link #REBOOT_STEP_MILLIS}: the vehicle rebooted
 */
public record VehicleState(msg_heartbeat heartbeat, long heartbeatNanos, Autopilot autopilot, VehicleFamily family,
                           msg_sys_status systemStatus, long systemStatusNanos,
                           Position position, double relativeAlt, double heading, long positionNanos, Position home,
                           int landedState, int vtolState, int missionSeq, int missionTotal, int missionState, long missionId,
                           List<String> statusTexts, int ekfFlags, boolean fenceBreached, long bootMillis, int reboots) {

    public static final int STATUS_LINES = 20;
    /**
     * How far back time since boot must go to count as a reboot: a reboot starts it again from 0, long
     * after a mission could start, while frames reordered on a link are seconds apart at most.
     */
    public static final long REBOOT_STEP_MILLIS = 5_000;
    private static final int ARMED_FLAG = 128;

    /** MISSION_CURRENT.total of a vehicle that holds no mission. */
    private static final int NO_MISSION = 65535;
    /** MISSION_CURRENT.seq of a vehicle that names no current item. */
    private static final int NO_ITEM = 65535;

    /** Before an ArduPilot vehicle's first message. */
    public static VehicleState initial(VehicleFamily family) {
        return initial(Autopilot.ARDUPILOT, family);
    }

    public static VehicleState initial(Autopilot autopilot, VehicleFamily family) {
        return new VehicleState(null, 0, autopilot, family, null, 0, null, 0, Double.NaN, 0, null, 0, 0, -1, -1, 0, 0, List.of(), -1, false, -1, 0);
    }

    public boolean armed() {
        return heartbeat != null && (heartbeat.base_mode & ARMED_FLAG) != 0;
    }

    public long customMode() {
        return heartbeat == null ? -1 : heartbeat.custom_mode;
    }

    /** The vehicle's modes, by its autopilot and family. */
    public ModeTable modes() {
        return autopilot.modes(family);
    }

    public String modeName() {
        return heartbeat == null ? "unknown" : modes().name(heartbeat.custom_mode);
    }

    /** Whether the vehicle's last heartbeat says this mode. */
    public boolean inMode(String name) {
        return heartbeat != null && modes().number(name).orElse(-1) == heartbeat.custom_mode;
    }

    /** What the vehicle is, e.g. "ArduCopter", "PX4 multicopter". */
    public String kind() {
        return autopilot.label(family);
    }

    /** Whether this plane may still turn out a VTOL: its autopilot tells by EXTENDED_SYS_STATE, and none has come yet. */
    public boolean mayBeVtol() {
        return autopilot.tellsVtolByState() && family == VehicleFamily.PLANE && landedState == MAV_LANDED_STATE.MAV_LANDED_STATE_UNDEFINED;
    }

    /**
     * True while a mission is being flown, so {@link #missionSeq()} is the item the vehicle flies:
     * MISSION_CURRENT also counts items during an upload, and older firmware reports no mission state
     * (then AUTO and armed say it).
     */
    public boolean flyingMission() {
        return missionState == MISSION_STATE.MISSION_STATE_ACTIVE || missionState == MISSION_STATE.MISSION_STATE_PAUSED
                || missionState == MISSION_STATE.MISSION_STATE_UNKNOWN && armed() && inMode(autopilot.missionMode());
    }

    /** Remaining battery in percent (0..100), or -1 when the vehicle does not know it or has not said. */
    public int batteryPercent() {
        return systemStatus == null ? -1 : systemStatus.battery_remaining;
    }

    public VehicleState withHeartbeat(msg_heartbeat hb, long nanos) {
        return new VehicleState(hb, nanos, autopilot, family, systemStatus, systemStatusNanos, position, relativeAlt,
                heading, positionNanos, home, landedState, vtolState, missionSeq, missionTotal, missionState, missionId, statusTexts, ekfFlags, fenceBreached, bootMillis, reboots);
    }

    public VehicleState withSystemStatus(msg_sys_status s, long nanos) {
        return new VehicleState(heartbeat, heartbeatNanos, autopilot, family, s, nanos, position, relativeAlt,
                heading, positionNanos, home, landedState, vtolState, missionSeq, missionTotal, missionState, missionId, statusTexts, ekfFlags, fenceBreached, bootMillis, reboots);
    }

    public VehicleState withPosition(Position p, double relAlt, double hdg, long nanos) {
        return new VehicleState(heartbeat, heartbeatNanos, autopilot, family, systemStatus, systemStatusNanos, p, relAlt, hdg,
                nanos, home, landedState, vtolState, missionSeq, missionTotal, missionState, missionId, statusTexts, ekfFlags, fenceBreached, bootMillis, reboots);
    }

    public VehicleState withHome(Position h) {
        return new VehicleState(heartbeat, heartbeatNanos, autopilot, family, systemStatus, systemStatusNanos, position, relativeAlt,
                heading, positionNanos, h, landedState, vtolState, missionSeq, missionTotal, missionState, missionId, statusTexts, ekfFlags, fenceBreached, bootMillis, reboots);
    }

    /** EXTENDED_SYS_STATE: the landed state, and the VTOL state, which tells a QuadPlane from a plane. */
    public VehicleState withExtendedState(int landed, int vtol) {
        return new VehicleState(heartbeat, heartbeatNanos, autopilot, autopilot.tellsVtolByState() ? family.withVtolState(vtol) : family, systemStatus, systemStatusNanos, position, relativeAlt,
                heading, positionNanos, home, landed, vtol, missionSeq, missionTotal, missionState, missionId, statusTexts, ekfFlags, fenceBreached, bootMillis, reboots);
    }

    /** MISSION_CURRENT as the vehicle sent it: its seq is numbered the runtime's way here. */
    public VehicleState withMissionCurrent(int seq, int total, int state, long id) {
        return new VehicleState(heartbeat, heartbeatNanos, autopilot, family, systemStatus, systemStatusNanos, position, relativeAlt,
                heading, positionNanos, home, landedState, vtolState, seq == NO_ITEM ? -1 : autopilot.missionSeq(seq),
                total == NO_MISSION ? 0 : total, state, id, statusTexts, ekfFlags, fenceBreached, bootMillis, reboots);
    }

    /** MISSION_CURRENT without the mission's id (older firmware, ArduPilot). */
    public VehicleState withMissionCurrent(int seq, int total, int state) {
        return withMissionCurrent(seq, total, state, 0);
    }

    public VehicleState withEkfFlags(int flags) {
        return new VehicleState(heartbeat, heartbeatNanos, autopilot, family, systemStatus, systemStatusNanos, position, relativeAlt,
                heading, positionNanos, home, landedState, vtolState, missionSeq, missionTotal, missionState, missionId, statusTexts, flags, fenceBreached, bootMillis, reboots);
    }

    /** From FENCE_STATUS.breach_status. */
    public VehicleState withFenceBreached(boolean breached) {
        return new VehicleState(heartbeat, heartbeatNanos, autopilot, family, systemStatus, systemStatusNanos, position, relativeAlt,
                heading, positionNanos, home, landedState, vtolState, missionSeq, missionTotal, missionState, missionId, statusTexts, ekfFlags, breached, bootMillis, reboots);
    }

    public VehicleState withStatusText(String line) {
        List<String> lines = new ArrayList<>(statusTexts);
        lines.add(line);
        if (lines.size() > STATUS_LINES) {
            lines.remove(0);
        }
        return new VehicleState(heartbeat, heartbeatNanos, autopilot, family, systemStatus, systemStatusNanos, position, relativeAlt,
                heading, positionNanos, home, landedState, vtolState, missionSeq, missionTotal, missionState, missionId, List.copyOf(lines), ekfFlags, fenceBreached, bootMillis, reboots);
    }

    /** The vehicle's time since boot; going back by more than {@link #REBOOT_STEP_MILLIS} counts a reboot. */
    public VehicleState withBootTime(long millis) {
        int r = bootMillis >= 0 && millis + REBOOT_STEP_MILLIS < bootMillis ? reboots + 1 : reboots;
        return new VehicleState(heartbeat, heartbeatNanos, autopilot, family, systemStatus, systemStatusNanos, position, relativeAlt,
                heading, positionNanos, home, landedState, vtolState, missionSeq, missionTotal, missionState, missionId, statusTexts, ekfFlags,
                fenceBreached, millis, r);
    }
}
