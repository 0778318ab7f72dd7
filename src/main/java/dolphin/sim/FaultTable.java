package dolphin.sim;

import com.MAVLink.enums.COPTER_MODE;
import com.MAVLink.enums.EKF_STATUS_FLAGS;
import com.MAVLink.enums.MAV_SEVERITY;
import com.MAVLink.enums.PLANE_MODE;
import com.MAVLink.enums.ROVER_MODE;
import com.MAVLink.enums.SUB_MODE;
import java.util.List;
import java.util.Optional;
import java.util.Set;

/**
 * Every text, severity and time of the simulated faults, and each family's row, in one place, with
 * the ArduPilot source each follows (V4.8.0-dev, git 64a9c787, the version of the SITL recordings).
 * When recordings of the faults on SITL say otherwise, this is what to change (docs/mavlink.md,
 * "Faults"). Times are seconds of clock time from the moment the fault is injected, unless said.
 */
final class FaultTable {

    private FaultTable() {
    }

    // ---- A copter's lost motor: ArduCopter/crash_check.cpp (Copter::thrust_loss_check), SITL's physics

    /** MAV_SEVERITY_EMERGENCY, with the lost motor's number (AP_MotorsMatrix's lost motor index + 1). */
    static final String THRUST_LOSS = "Potential Thrust Loss (%d)";
    static final int THRUST_LOSS_SEVERITY = MAV_SEVERITY.MAV_SEVERITY_EMERGENCY;
    /**
     * The first one, after the fall: the check needs THRUST_LOSS_CHECK_TRIGGER_SEC of descent at full
     * throttle with level attitude, which the tumbling fall never has but the copter standing level on
     * the ground (SITL's ground contact levels it) does, armed, not landed, still trying to climb.
     */
    static final double THRUST_LOSS_FIRST = 1;
    /**
     * Then again each time the motors library ends the thrust boost the text turned on and the check
     * has run its second again: every 2 s in SITL, as long as it stays armed and not landed.
     */
    static final double THRUST_LOSS_REPEAT = 2;
    /** SITL's copter frame (+) has 4 motors. */
    static final int COPTER_MOTORS = 4;
    /** It falls at up to g (a quad without one motor cannot hold its attitude, so it tumbles)... */
    static final double FALL_ACCEL = 9.81;
    /** ...to the speed SITL's copter hit the ground at mid-survey, "SIM Hit ground at 13.8 m/s". */
    static final double FALL_SPEED = 13.8;

    // ---- A plane's engine failure: ArduPlane/is_flying.cpp

    /**
     * It glides down at its sink rate and, on the ground, counts as not flying (ON_GROUND, STANDBY)
     * once is_flying's probability has fallen below 0.1: 15 of its 5 Hz updates at 0.85 each. No text:
     * CRASH_DETECT is 0 by default, so crash_detection_update says nothing.
     */
    static final double PLANE_LANDED_AFTER = 3;

    // ---- A GPS loss (SIM_GPS1_ENABLE 0): libraries/AP_GPS, libraries/AP_NavEKF3, the vehicle's ekf_check.cpp

    /** AP_GPS's GPS_TIMEOUT_MS: the receiver is given up, GPS_RAW_INT says NO_GPS. */
    static final double GPS_TIMEOUT = 4;
    /**
     * EKF3's posRetryTimeNoVel_ms (no velocity source but the GPS): the horizontal position times out
     * (posTimeout, velTimeout), so EKF_STATUS_REPORT keeps only {@link #EKF_POSITION_LOST}.
     */
    static final double POSITION_TIMEOUT = 7;
    static final int EKF_POSITION_LOST = EKF_STATUS_FLAGS.EKF_ATTITUDE | EKF_STATUS_FLAGS.EKF_VELOCITY_VERT
            | EKF_STATUS_FLAGS.EKF_POS_VERT_ABS;
    /** ekf_check runs at 10 Hz and fails after EKF_CHECK_ITERATIONS_MAX (10) checks without a position. */
    static final double EKF_CHECK = 1;
    /**
     * EKF3's tiltDriftTimeMax_ms: nothing has aided it, so it stops aiding ("EKF3 IMU%u stopped
     * aiding", WARNING, one per core: SITL runs two, EK3_IMU_MASK 3) and, reset, reports the flags of
     * its constant position mode, those it had at boot.
     */
    static final double AIDING_TIMEOUT = 15;
    static final List<String> STOPPED_AIDING = List.of("EKF3 IMU0 stopped aiding", "EKF3 IMU1 stopped aiding");
    static final int STOPPED_AIDING_SEVERITY = MAV_SEVERITY.MAV_SEVERITY_WARNING;
    static final int EKF_NOT_AIDING = NavigationState.EKF_BOOTING;

    /** ArduCopter's modes whose requires_position() is true (ArduCopter/mode.h; AUTO's unless in its no-GPS submodes). */
    private static final Set<Integer> COPTER_POSITION_MODES = Set.of(COPTER_MODE.COPTER_MODE_AUTO, COPTER_MODE.COPTER_MODE_GUIDED,
            COPTER_MODE.COPTER_MODE_LOITER, COPTER_MODE.COPTER_MODE_RTL, COPTER_MODE.COPTER_MODE_CIRCLE,
            COPTER_MODE.COPTER_MODE_DRIFT, COPTER_MODE.COPTER_MODE_POSHOLD, COPTER_MODE.COPTER_MODE_BRAKE,
            COPTER_MODE.COPTER_MODE_THROW, COPTER_MODE.COPTER_MODE_AVOID_ADSB, COPTER_MODE.COPTER_MODE_SMART_RTL,
            COPTER_MODE.COPTER_MODE_FOLLOW, COPTER_MODE.COPTER_MODE_ZIGZAG);

    /** ArduRover's modes whose requires_position() is false (Rover/mode.h); every other one needs it. */
    private static final Set<Integer> ROVER_POSITIONLESS_MODES = Set.of(ROVER_MODE.ROVER_MODE_MANUAL, ROVER_MODE.ROVER_MODE_ACRO,
            ROVER_MODE.ROVER_MODE_STEERING, ROVER_MODE.ROVER_MODE_HOLD);

    /**
     * ArduCopter/ekf_check.cpp: "EKF variance: %s" with "position lost" (the variances are not over
     * FS_EKF_THRESH: without GPS there is nothing to innovate), checked disarmed too; then, armed in a
     * mode that needs a position, failsafe_ekf_event: set_mode_land_with_pause (FS_EKF_ACTION 1, LAND,
     * and a 4 s pause before the descent) and "EKF Failsafe: changed to %s Mode" with the mode's
     * name() ("LAND"); in another mode (LAND itself included), "EKF Failsafe".
     */
    static final EkfFailsafe COPTER_EKF = new EkfFailsafe("EKF variance: position lost", true, COPTER_POSITION_MODES::contains,
            COPTER_MODE.COPTER_MODE_LAND, "EKF Failsafe: changed to %s Mode", Optional.of("EKF Failsafe"), 4);

    /**
     * Rover/ekf_check.cpp: checked only armed; "EKF variance", then failsafe_ekf_event: HOLD (FS_EKF_ACTION
     * 1) in a mode that needs a position, and "EKF failsafe"; in another mode nothing more.
     */
    static final EkfFailsafe ROVER_EKF = new EkfFailsafe("EKF variance", false, m -> !ROVER_POSITIONLESS_MODES.contains(m),
            ROVER_MODE.ROVER_MODE_HOLD, "EKF failsafe", Optional.empty(), 0);

    // ---- Each family's row: its motors and what losing one does, its EKF failsafe, a pilot's takeover mode

    static final Failures COPTER = new Failures(COPTER_MOTORS, Optional.of(ThrustLoss::new), Optional.of(COPTER_EKF),
            COPTER_MODE.COPTER_MODE_LOITER);
    /** One engine; ArduPlane's EKF failsafe acts only in a quadplane's VTOL modes (ArduPlane/ekf_check.cpp): not simulated. */
    static final Failures PLANE = new Failures(1, Optional.of(motor -> new EngineFailure()), Optional.empty(),
            PLANE_MODE.PLANE_MODE_LOITER);
    /** A rover's motors are not simulated apart: a stall stands for a rover that cannot go on. */
    static final Failures ROVER = new Failures(0, Optional.empty(), Optional.of(ROVER_EKF), ROVER_MODE.ROVER_MODE_HOLD);
    static final Failures SUB = new Failures(0, Optional.empty(), Optional.empty(), SUB_MODE.SUB_MODE_POSHOLD);
}
