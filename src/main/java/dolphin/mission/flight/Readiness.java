package dolphin.mission.flight;

import com.MAVLink.common.msg_sys_status;
import com.MAVLink.enums.EKF_STATUS_FLAGS;
import com.MAVLink.enums.MAV_SYS_STATUS_SENSOR;
import dolphin.mavlink.VehicleState;
import java.util.List;
import java.util.Optional;

/**
 * Whether a vehicle can take a mission yet (docs/mavlink.md, "Readiness"): it has a position
 * estimate (a position, and its EKF's absolute horizontal position when it reports EKF status), a home when the mission names none, and, while disarmed, passing pre-arm checks. A
 * vehicle just switched on has none of these for a while (ArduPilot: about 40 s until its EKF has a
 * position), and says why in its "PreArm: ..." texts, which are quoted when there is one.
 */
final class Readiness {

    private static final String PREARM = "PreArm:";

    private Readiness() {
    }

    /** What the vehicle still lacks, or empty when it is ready. */
    static Optional<String> missing(VehicleState s, boolean needsHome) {
        Optional<String> unlocated = unlocated(s, needsHome);
        if (unlocated.isPresent()) {
            return unlocated;
        }
        if (!s.armed() && prearmFailing(s.systemStatus())) {
            return Optional.of(prearmText(s).orElse("pre-arm checks failing"));
        }
        return Optional.empty();
    }

    /**
     * What the vehicle lacks apart from its pre-arm checks: a position estimate, and a home when the
     * mission names none. A vehicle that has them has booted and read its RC inputs.
     */
    static Optional<String> unlocated(VehicleState s, boolean needsHome) {
        if (s.position() == null) {
            return Optional.of(prearmText(s).orElse("no position estimate yet"));
        }
        if (!ekfHasPosition(s.ekfFlags())) {
            return Optional.of("no position estimate yet (EKF: no absolute horizontal position)");
        }
        if (needsHome && s.home() == null) {
            return Optional.of(prearmText(s).orElse("no home position yet"));
        }
        return Optional.empty();
    }

    /**
     * Whether ArduPilot's EKF has an absolute horizontal position outside its constant-position mode,
     * as ArduPilot's own modes need for AUTO (ArduRover refuses AUTO until then, though it sends a
     * position and passes its pre-arm checks earlier); true when the vehicle sends no EKF_STATUS_REPORT.
     */
    private static boolean ekfHasPosition(int flags) {
        return flags < 0 || ((flags & EKF_STATUS_FLAGS.EKF_POS_HORIZ_ABS) != 0 && (flags & EKF_STATUS_FLAGS.EKF_CONST_POS_MODE) == 0);
    }

    /** ArduPilot reports its pre-arm checks as a sensor in SYS_STATUS: enabled and unhealthy while they fail. */
    private static boolean prearmFailing(msg_sys_status status) {
        int bit = MAV_SYS_STATUS_SENSOR.MAV_SYS_STATUS_PREARM_CHECK;
        return status != null && (status.onboard_control_sensors_enabled & bit) != 0
                && (status.onboard_control_sensors_health & bit) == 0;
    }

    /** The vehicle's latest "PreArm: ..." text, if it sent one. */
    static Optional<String> prearmText(VehicleState s) {
        List<String> texts = s.statusTexts();
        for (int i = texts.size() - 1; i >= 0; i--) {
            if (texts.get(i).startsWith(PREARM)) {
                return Optional.of(texts.get(i));
            }
        }
        return Optional.empty();
    }
}
