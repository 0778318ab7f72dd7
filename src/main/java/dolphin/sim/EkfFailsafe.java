package dolphin.sim;

import java.util.Optional;
import java.util.function.IntPredicate;

/**
 * A firmware's answer to an EKF that lost its horizontal position (its ekf_check and
 * failsafe_ekf_event), as {@link GpsLoss} plays it: what it says, where it acts, the mode it
 * switches to and what it says then. Every text is MAV_SEVERITY_CRITICAL.
 *
 * @param varianceText said once ekf_check has failed EKF_CHECK_ITERATIONS_MAX times in a row
 * @param checksDisarmed whether the check runs while disarmed too (it acts only armed)
 * @param needsPosition the modes it acts in: those whose requires_position() is true
 * @param mode the mode it switches to
 * @param actionText said after the switch
 * @param noActionText said, armed, in a mode it does not act in; empty: nothing
 * @param pauseSeconds how long it holds where it is before it moves in {@code mode} (ArduCopter's
 *        set_mode_land_with_pause: LAND_WITH_DELAY_MS)
 * @param laneSwitch whether EKF3 switches to its second lane just before, armed (as the copter's did)
 * @param smartRtlOff when, after the GPS fell silent, AP_SmartRTL gives up for want of a position, armed
 */
record EkfFailsafe(String varianceText, boolean checksDisarmed, IntPredicate needsPosition, int mode, String actionText,
                   Optional<String> noActionText, double pauseSeconds, boolean laneSwitch, double smartRtlOff) {
}
