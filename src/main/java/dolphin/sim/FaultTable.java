package dolphin.sim;

import com.MAVLink.enums.COPTER_MODE;
import com.MAVLink.enums.EKF_STATUS_FLAGS;
import com.MAVLink.enums.MAV_SEVERITY;
import com.MAVLink.enums.PLANE_MODE;
import com.MAVLink.enums.ROVER_MODE;
import com.MAVLink.enums.SUB_MODE;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.stream.IntStream;

/**
 * Every text, severity and time of the simulated faults, and each family's row, in one place, with
 * the ArduPilot source each follows (V4.8.0-dev, git 64a9c787, the version of the SITL recordings).
 * Where the recordings of the faults injected into SITL (src/test/resources/sitl-recordings, the
 * *-fault-* ones, checked by FaultRecordingConformanceSpec) say otherwise than the source or than an
 * earlier guess, the recordings win; each such value says so. Times are seconds of clock time from the
 * moment the fault is injected, unless said; the recordings' are the vehicle's own (time_boot_ms).
 */
final class FaultTable {

    private FaultTable() {
    }

    // ---- EKF3's lanes (libraries/AP_NavEKF3/AP_NavEKF3.cpp, AP_AHRS): SITL runs two cores, EK3_IMU_MASK 3

    /** NavEKF3::UpdateFilter's core selection, armed only: MAV_SEVERITY_CRITICAL. */
    static final String LANE_SWITCH = "EKF3 lane switch %d";
    static final int LANE_SWITCH_SEVERITY = MAV_SEVERITY.MAV_SEVERITY_CRITICAL;
    /** AP_AHRS on each change of the EKF's primary lane, the switches' and the disarm's (EKF3 forces lane 0 disarmed). */
    static final String PRIMARY_CHANGED = "EKF primary changed:%d";
    static final int PRIMARY_CHANGED_SEVERITY = MAV_SEVERITY.MAV_SEVERITY_WARNING;
    static final int EKF_CORES = 2;

    // ---- A copter's lost motor: ArduCopter/crash_check.cpp (Copter::thrust_loss_check), SITL's physics

    /** MAV_SEVERITY_EMERGENCY, with the motor ArduCopter takes for lost (AP_MotorsMatrix's lost motor index + 1). */
    static final String THRUST_LOSS = "Potential Thrust Loss (%d)";
    static final int THRUST_LOSS_SEVERITY = MAV_SEVERITY.MAV_SEVERITY_EMERGENCY;
    /**
     * The motor the text names when motor N of SITL's + quad stops. Recorded: motor 1 failed, "(2)" (in
     * each run that the README quotes): ArduCopter took the opposite motor for the lost one
     * (AP_MotorsMatrix's + frame: 1 right, 2 left, 3 front, 4 back); the other motors by the same rule,
     * not recorded.
     */
    static final Map<Integer, Integer> THRUST_LOSS_NAMED = Map.of(1, 2, 2, 1, 3, 4, 4, 3);
    /**
     * The first one, after the fall: the check needs THRUST_LOSS_CHECK_TRIGGER_SEC of descent at full
     * throttle with level attitude, which the copter hopping on the ground at full throttle has, armed,
     * never landed. Recorded: 4 s after the hit in the kept run, 2.5 and 12.75 s in two others.
     */
    static final double THRUST_LOSS_FIRST = 4;
    /** Then again, as long as it stays armed and not landed: recorded every 7 to 16 s, 11 on average. */
    static final double THRUST_LOSS_REPEAT = 11;
    /** SITL's copter frame (+) has 4 motors. */
    static final int COPTER_MOTORS = 4;
    /**
     * It falls (a quad without one motor cannot hold its attitude, so it tumbles) to the speed SITL's
     * copter hit the ground at from 30 m, "SIM Hit ground at 14.59516 m/s", 3.0 s after the motor
     * stopped: less than g's 2.5 s for SITL's drag, so an acceleration that makes those 3.0 s.
     */
    static final double FALL_ACCEL = 7.7;
    static final double FALL_SPEED = 14.6;
    /**
     * The hit makes EKF3 switch to lane 1 (CRITICAL, and "EKF primary changed:1") and, this much later,
     * back to lane 0. Recorded in two of three runs, 3.0 and 3.25 s after the injection; the third said
     * neither (its thrust loss came first, 15.75 s after the injection).
     */
    static final double LANE_SWITCH_BACK = 0.25;

    // ---- A plane's engine failure: ArduPlane/is_flying.cpp, SITL's physics

    /**
     * It glides down in its mode, TECS trading height for airspeed: recorded, from 60 m to the ground
     * in 30.1 s ("SIM Hit ground at 1.672376 m/s"), so 2 m/s, less than the 3 m/s it sinks at flying.
     */
    static final double PLANE_GLIDE_SINK = 2;
    /**
     * On the ground it counts as not flying (EXTENDED_SYS_STATE ON_GROUND) once is_flying's probability
     * has fallen below 0.1: recorded 9.5 s after the hit (it slides on, which keeps the probability up;
     * the 15 updates at 5 Hz that a stopped plane needs would be 3 s). No text: CRASH_DETECT is 0 by
     * default, so crash_detection_update says nothing.
     */
    static final double PLANE_LANDED_AFTER = 9.5;

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
     * EKF3's tiltDriftTimeMax_ms: nothing has aided it, so it stops aiding, one text per core (WARNING),
     * and, reset, reports the flags of its constant position mode, those it had at boot. Recorded: the
     * copter, whose primary lane was 1 by then, said IMU1 first; the rover, on lane 0, IMU0 first: the
     * primary core first, then the others.
     */
    static final double AIDING_TIMEOUT = 15;
    static final String STOPPED_AIDING = "EKF3 IMU%d stopped aiding";
    static final int STOPPED_AIDING_SEVERITY = MAV_SEVERITY.MAV_SEVERITY_WARNING;
    static final int EKF_NOT_AIDING = NavigationState.EKF_BOOTING;
    /**
     * AP_SmartRTL deactivates itself after SMARTRTL_TIMEOUT (15 s) without a good position, armed
     * (WARNING). Recorded 22.2 s after the GPS fell silent on the copter (its position bad from EKF3's
     * timeout, 7 s) and 30.1 s on the rover (whose position counts as good until EKF3 stops aiding, 15 s).
     */
    static final String SMART_RTL_OFF = "SmartRTL deactivated: bad position";
    static final int SMART_RTL_OFF_SEVERITY = MAV_SEVERITY.MAV_SEVERITY_WARNING;
    static final double SMART_RTL_TIMEOUT = 15;

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
     * and a 4 s pause before the descent, LAND's LANDING state from the start) and "EKF Failsafe:
     * changed to Land Mode" (recorded so: the mode's name in the text is "Land", not LAND); in another
     * mode (LAND itself included), "EKF Failsafe". Recorded: EKF3 switched to lane 1 just before, and
     * LAND's heartbeat came before both texts. Its SmartRTL gives up once the EKF's position timed out.
     */
    static final EkfFailsafe COPTER_EKF = new EkfFailsafe("EKF variance: position lost", true, COPTER_POSITION_MODES::contains,
            COPTER_MODE.COPTER_MODE_LAND, "EKF Failsafe: changed to Land Mode", Optional.of("EKF Failsafe"), 4, true,
            POSITION_TIMEOUT + SMART_RTL_TIMEOUT);

    /**
     * Rover/ekf_check.cpp: checked only armed; "EKF variance", then failsafe_ekf_event: HOLD (FS_EKF_ACTION
     * 1) in a mode that needs a position, and "EKF failsafe"; in another mode nothing more. Recorded:
     * HOLD's heartbeat before both texts, no lane switch; its SmartRTL gives up once EKF3 stopped aiding.
     */
    static final EkfFailsafe ROVER_EKF = new EkfFailsafe("EKF variance", false, m -> !ROVER_POSITIONLESS_MODES.contains(m),
            ROVER_MODE.ROVER_MODE_HOLD, "EKF failsafe", Optional.empty(), 0, false, AIDING_TIMEOUT + SMART_RTL_TIMEOUT);

    // ---- ArduRover's internal error as its mission starts

    /**
     * ArduRover SITL flags AP_InternalError invalid_arg_or_result ("SCurve::calculate_track created zero
     * length path" on its console) when its mission starts a nav item armed, and says so once (CRITICAL):
     * recorded in rover-square, boat-square and both rover-fault recordings. From then on its heartbeat
     * says MAV_STATE_CRITICAL. Not a fault of the vehicle's: it drives on (docs/failures.md).
     */
    static final String ROVER_INTERNAL_ERROR = "Internal Errors 0x20000000";

    // ---- Each family's row: its motors and what losing one does, its EKF failsafe, a pilot's takeover mode, its internal error

    static final Failures COPTER = new Failures(COPTER_MOTORS, Optional.of(ThrustLoss::new), Optional.of(COPTER_EKF),
            COPTER_MODE.COPTER_MODE_LOITER, Optional.empty());
    /** One engine; ArduPlane's EKF failsafe acts only in a quadplane's VTOL modes (ArduPlane/ekf_check.cpp): not simulated. */
    static final Failures PLANE = new Failures(1, Optional.of(motor -> new EngineFailure()), Optional.empty(),
            PLANE_MODE.PLANE_MODE_LOITER, Optional.empty());
    /** A rover's motors are not simulated apart: a stall stands for a rover that cannot go on. */
    static final Failures ROVER = new Failures(0, Optional.empty(), Optional.of(ROVER_EKF), ROVER_MODE.ROVER_MODE_HOLD,
            Optional.of(ROVER_INTERNAL_ERROR));
    static final Failures SUB = new Failures(0, Optional.empty(), Optional.empty(), SUB_MODE.SUB_MODE_POSHOLD, Optional.empty());
    /** A QuadPlane's lost motor (a lift motor or its engine) and its VTOL modes' EKF failsafe are not simulated. */
    static final Failures QUADPLANE = new Failures(0, Optional.empty(), Optional.empty(), PLANE_MODE.PLANE_MODE_LOITER,
            Optional.empty());
    /** A helicopter's one rotor has no thrust loss check (a multicopter's, Copter::thrust_loss_check); its EKF failsafe is the copter's. */
    static final Failures HELI = new Failures(0, Optional.empty(), Optional.of(COPTER_EKF), COPTER_MODE.COPTER_MODE_LOITER,
            Optional.empty());

    /** The EKF3 cores' "stopped aiding" texts, the primary lane's first. */
    static List<String> stoppedAiding(int primary) {
        return IntStream.range(0, EKF_CORES).map(i -> (primary + i) % EKF_CORES)
                .mapToObj(core -> String.format(Locale.ROOT, STOPPED_AIDING, core)).toList();
    }
}
