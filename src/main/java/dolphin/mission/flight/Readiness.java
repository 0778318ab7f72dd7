package dolphin.mission.flight;

import com.MAVLink.enums.EKF_STATUS_FLAGS;
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

    private Readiness() {
    }

    /** What the vehicle still lacks, or empty when it is ready. */
    static Optional<String> missing(VehicleState s, boolean needsHome) {
        Optional<String> unlocated = unlocated(s, needsHome);
        if (unlocated.isPresent()) {
            return unlocated;
        }
        if (!s.armed() && s.autopilot().prearmFailing(s.systemStatus())) {
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

    /** The vehicle's latest text about a failing pre-arm check ("PreArm: ...", PX4's "Preflight Fail: ..."), if it sent one. */
    static Optional<String> prearmText(VehicleState s) {
        List<String> texts = s.statusTexts();
        String prefix = s.autopilot().prearmPrefix();
        for (int i = texts.size() - 1; i >= 0; i--) {
            if (texts.get(i).startsWith(prefix)) {
                return Optional.of(texts.get(i));
            }
        }
        return Optional.empty();
    }
}
