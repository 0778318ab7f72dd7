package dolphin.mavlink;

import com.MAVLink.ardupilotmega.msg_ekf_status_report;
import com.MAVLink.common.msg_battery_status;
import com.MAVLink.common.msg_extended_sys_state;
import com.MAVLink.common.msg_home_position;
import com.MAVLink.common.msg_mission_current;
import com.MAVLink.common.msg_sys_status;
import com.MAVLink.minimal.msg_heartbeat;
import com.MAVLink.standard.msg_global_position_int;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * The telemetry the runtime asks each vehicle for, fitted to the link the vehicles share
 * (docs/radios.md, "Telemetry budget"): the streams of every vehicle on a link may use at most
 * {@link #SHARE} of its bytes per second, the rest being left to transfers, commands and texts.
 * When they would use more, the streams slow down one after the other in {@link #STREAMS}' order,
 * each halved until it reaches its slowest rate before the next one slows: what the runtime reads
 * least often first, position and battery last. A link whose bandwidth nobody knows (a network
 * link not sized with {@code ?bps=}) gets every stream at its wanted rate.
 */
public final class TelemetryBudget {

    /** The part of a link's bytes per second the streams asked for may use. */
    public static final double SHARE = 0.5;
    /** A MAVLink 2 frame's bytes besides its payload (unsigned). */
    private static final int FRAME_OVERHEAD = 12;
    /** The vehicle's heartbeat, sent at 1 Hz whatever is asked: counted, never slowed. */
    private static final int HEARTBEAT_BYTES = FRAME_OVERHEAD + msg_heartbeat.MAVLINK_MSG_LENGTH;

    /**
     * One stream the runtime asks for.
     *
     * @param fast whether it goes at the configured telemetry rate (else at 1 Hz)
     * @param slowestHz the rate it never goes below, however full the link
     * @param optional sent by some autopilots only (EKF_STATUS_REPORT is ArduPilot's)
     */
    public record AskedStream(int msgid, String name, int frameBytes, boolean fast, double slowestHz, boolean optional) {
    }

    /** Every stream asked for, in the order they slow down on a full link. */
    public static final List<AskedStream> STREAMS = List.of(
            stream(msg_home_position.MAVLINK_MSG_ID_HOME_POSITION, "HOME_POSITION", msg_home_position.MAVLINK_MSG_LENGTH, false, 0.1, false),
            stream(msg_ekf_status_report.MAVLINK_MSG_ID_EKF_STATUS_REPORT, "EKF_STATUS_REPORT", msg_ekf_status_report.MAVLINK_MSG_LENGTH,
                    false, 0.2, true),
            stream(msg_extended_sys_state.MAVLINK_MSG_ID_EXTENDED_SYS_STATE, "EXTENDED_SYS_STATE",
                    msg_extended_sys_state.MAVLINK_MSG_LENGTH, false, 0.5, false),
            stream(msg_battery_status.MAVLINK_MSG_ID_BATTERY_STATUS, "BATTERY_STATUS", msg_battery_status.MAVLINK_MSG_LENGTH, false,
                    0.2, false),
            stream(msg_mission_current.MAVLINK_MSG_ID_MISSION_CURRENT, "MISSION_CURRENT", msg_mission_current.MAVLINK_MSG_LENGTH, true,
                    0.5, false),
            stream(msg_sys_status.MAVLINK_MSG_ID_SYS_STATUS, "SYS_STATUS", msg_sys_status.MAVLINK_MSG_LENGTH, true, 0.5, false),
            stream(msg_global_position_int.MAVLINK_MSG_ID_GLOBAL_POSITION_INT, "GLOBAL_POSITION_INT",
                    msg_global_position_int.MAVLINK_MSG_LENGTH, true, 1, false));

    /**
     * The rates asked of each vehicle on a link.
     *
     * @param hz message id to rate, in {@link #STREAMS}' order
     * @param bytesPerSecond what the streams and heartbeats of all the link's vehicles use at these rates
     * @param fits whether that is within the link's share (false: every stream is at its slowest and still does not fit)
     */
    public record StreamRates(Map<Integer, Double> hz, double bytesPerSecond, boolean fits, boolean slowed) {

        /** "GLOBAL_POSITION_INT 1 Hz, SYS_STATUS 0.5 Hz, ..." for the streams below their wanted rate. */
        public String slowedText(double fastHz) {
            List<String> slow = new ArrayList<>();
            for (AskedStream s : STREAMS) {
                double wanted = s.fast() ? fastHz : 1;
                double got = hz.get(s.msgid());
                if (got < wanted) {
                    slow.add(s.name() + " " + String.format(Locale.ROOT, "%.3g", got).replaceAll("\\.?0+$", "") + " Hz");
                }
            }
            return String.join(", ", slow);
        }
    }

    private TelemetryBudget() {
    }

    private static AskedStream stream(int msgid, String name, int payload, boolean fast, double slowestHz, boolean optional) {
        return new AskedStream(msgid, name, FRAME_OVERHEAD + payload, fast, slowestHz, optional);
    }

    /**
     * The rates for {@code vehicles} vehicles sharing a link of {@code bytesPerSecond} (NaN: not
     * known, so no limit), each stream wanted at {@code fastHz} or 1 Hz.
     */
    public static StreamRates plan(double fastHz, int vehicles, double bytesPerSecond) {
        Map<Integer, Double> hz = new LinkedHashMap<>();
        for (AskedStream s : STREAMS) {
            hz.put(s.msgid(), s.fast() ? fastHz : 1.0);
        }
        double budget = Double.isNaN(bytesPerSecond) ? Double.POSITIVE_INFINITY : SHARE * bytesPerSecond;
        int n = Math.max(1, vehicles);
        boolean slowed = false;
        for (AskedStream s : STREAMS) {
            while (used(hz, n) > budget && hz.get(s.msgid()) > s.slowestHz()) {
                hz.put(s.msgid(), Math.max(s.slowestHz(), hz.get(s.msgid()) / 2));
                slowed = true;
            }
        }
        double used = used(hz, n);
        return new StreamRates(java.util.Collections.unmodifiableMap(hz), used, used <= budget, slowed);
    }

    private static double used(Map<Integer, Double> hz, int vehicles) {
        double perVehicle = HEARTBEAT_BYTES;
        for (AskedStream s : STREAMS) {
            perVehicle += s.frameBytes() * hz.get(s.msgid());
        }
        return perVehicle * vehicles;
    }
}
