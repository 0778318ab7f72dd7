package dolphin.sim;

import com.MAVLink.enums.COPTER_MODE;
import com.MAVLink.enums.MAV_PARAM_TYPE;
import com.MAVLink.enums.MAV_RESULT;
import com.MAVLink.enums.MAV_TYPE;
import dolphin.mavlink.VehicleFamily;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

/**
 * ArduCopter's traditional helicopter as SITL runs it with {@code --model heli} and copter-heli.parm
 * (heartbeat MAV_TYPE_HELICOPTER): the copter, with its motor interlock on RC8 (RC8_OPTION 32), which
 * is on at boot, SITL's RC8 at 1500 being MIDDLE. While it is on, arming is refused; MAV_CMD_DO_AUX_FUNCTION
 * (function 32; 0 LOW off, 1 MIDDLE or 2 HIGH on) switches it. Armed, it enters a mode without manual
 * throttle (AUTO, GUIDED, LOITER...) only once its rotor has run up: H_RSC_RAMP_TIME and then
 * H_RSC_RUNUP_TIME after the interlock went on while armed (AP_MotorsHeli_RSC; SITL refused AUTO 11 s
 * after and accepted it 13.5 s after). Not simulated: autorotation when the interlock goes off in
 * flight (the flight goes on; only the rotor's run-up starts over).
 */
final class HeliFirmware extends CopterFirmware {

    /** RC_Channel::AUX_FUNC::MOTOR_INTERLOCK. */
    static final int MOTOR_INTERLOCK = 32;
    /** H_RSC_RAMP_TIME and H_RSC_RUNUP_TIME, seconds: the rotor's run-up once the interlock is on, armed. */
    static final double RUNUP_SECONDS = 1 + 10;

    /** The modes with manual throttle (Mode::has_manual_throttle), which a rotor not run up may enter. */
    private static final Set<Integer> MANUAL_THROTTLE = Set.of(COPTER_MODE.COPTER_MODE_STABILIZE, COPTER_MODE.COPTER_MODE_ACRO);
    /** The names ArduCopter's modes give themselves (Mode::name), for the refusal's text. */
    private static final Map<Integer, String> NAMES = Map.ofEntries(Map.entry(COPTER_MODE.COPTER_MODE_ALT_HOLD, "Altitude Hold"),
            Map.entry(COPTER_MODE.COPTER_MODE_AUTO, "Auto"), Map.entry(COPTER_MODE.COPTER_MODE_GUIDED, "Guided"),
            Map.entry(COPTER_MODE.COPTER_MODE_LOITER, "Loiter"), Map.entry(COPTER_MODE.COPTER_MODE_RTL, "RTL"),
            Map.entry(COPTER_MODE.COPTER_MODE_CIRCLE, "Circle"), Map.entry(COPTER_MODE.COPTER_MODE_LAND, "Land"),
            Map.entry(COPTER_MODE.COPTER_MODE_DRIFT, "Drift"), Map.entry(COPTER_MODE.COPTER_MODE_SPORT, "Sport"),
            Map.entry(COPTER_MODE.COPTER_MODE_AUTOTUNE, "Autotune"), Map.entry(COPTER_MODE.COPTER_MODE_POSHOLD, "Position Hold"),
            Map.entry(COPTER_MODE.COPTER_MODE_BRAKE, "Brake"), Map.entry(COPTER_MODE.COPTER_MODE_GUIDED_NOGPS, "Guided No GPS"),
            Map.entry(COPTER_MODE.COPTER_MODE_SMART_RTL, "Smart RTL"), Map.entry(COPTER_MODE.COPTER_MODE_SYSTEMID, "SystemID"),
            Map.entry(COPTER_MODE.COPTER_MODE_AUTOROTATE, "Autorotate"), Map.entry(COPTER_MODE.COPTER_MODE_AUTO_RTL, "Auto RTL"));

    static final List<FirmwareParam> PARAMS = List.of(
            new FirmwareParam("RC8_OPTION", MOTOR_INTERLOCK, MAV_PARAM_TYPE.MAV_PARAM_TYPE_INT16),
            new FirmwareParam("H_RSC_RAMP_TIME", 1, MAV_PARAM_TYPE.MAV_PARAM_TYPE_INT8),
            new FirmwareParam("H_RSC_RUNUP_TIME", 10, MAV_PARAM_TYPE.MAV_PARAM_TYPE_INT8));

    private boolean interlock = true;
    /** Clock time (ns) the interlock went on while armed, from which the rotor runs up; negative: it does not. */
    private long runupStart = -1;

    @Override
    public int mavType() {
        return MAV_TYPE.MAV_TYPE_HELICOPTER;
    }

    @Override
    public VehicleFamily family() {
        return VehicleFamily.HELI;
    }

    /** AP_Arming_Copter::run_pre_arm_checks: the interlock must be off to arm. */
    @Override
    public Optional<String> armRefusal(int mode, MissionView mission) {
        return interlock ? Optional.of("Arm: Motor Interlock Enabled") : super.armRefusal(mode, mission);
    }

    /** Copter::set_mode's heli block: armed, only a manual-throttle mode before the run-up is complete. */
    @Override
    public Optional<String> modeRefusal(int mode, boolean located, boolean missionPresent, boolean armed, long now) {
        if (armed && !MANUAL_THROTTLE.contains(mode) && !runUp(now)) {
            return Optional.of("Mode change to " + NAMES.getOrDefault(mode, modes().name(mode)) + " failed: runup not complete");
        }
        return Optional.empty();
    }

    private boolean runUp(long now) {
        return interlock && runupStart >= 0 && now - runupStart >= RUNUP_SECONDS * 1e9;
    }

    /** RC8's MotorInterlock switched: on at MIDDLE or HIGH; going on while armed starts the rotor's run-up. */
    @Override
    public int auxFunction(int function, int position, boolean armed, long now) {
        if (function != MOTOR_INTERLOCK || position < 0 || position > 2) {
            return MAV_RESULT.MAV_RESULT_UNSUPPORTED;
        }
        interlock = position != 0;
        if (!interlock) {
            runupStart = -1;
        } else if (runupStart < 0 && armed) {
            runupStart = now;
        }
        return MAV_RESULT.MAV_RESULT_ACCEPTED;
    }

    /** SITL's RC8 is read again at boot: MIDDLE, the interlock on, nothing run up. */
    @Override
    public void rebooted() {
        interlock = true;
        runupStart = -1;
    }

    @Override
    public List<FirmwareParam> params() {
        return PARAMS;
    }

    @Override
    public Failures failures() {
        return FaultTable.HELI;
    }
}
