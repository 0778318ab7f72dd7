package dolphin.sim;

import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.enums.MAV_PARAM_TYPE;
import com.MAVLink.enums.MAV_VTOL_STATE;
import com.MAVLink.enums.PLANE_MODE;
import dolphin.core.Position;
import dolphin.mavlink.VehicleFamily;
import dolphin.mission.model.MissionItem;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

/**
 * ArduPlane with Q_ENABLE 1 as SITL runs it with {@code --model quadplane} and quadplane.parm: a plane
 * (heartbeat MAV_TYPE_FIXED_WING, boots in FLY_BY_WIRE_A, 1 Hz streams) that cruises at AIRSPEED_CRUISE
 * 25 m/s, reaches waypoints within WP_RADIUS's default 90 m and takes off and lands on its lift
 * motors. NAV_TAKEOFF and NAV_VTOL_TAKEOFF climb straight up at Q_PILOT_SPD_UP to their altitude above
 * where it is, and are reached there; on the next leg it transitions ({@link VtolLift}). NAV_LAND and
 * NAV_VTOL_LAND (Q_OPTIONS 0: both are VTOL landings), QRTL and QLAND land vertically
 * ({@link VtolLanding}), then it disarms by itself; in AUTO its mission stays at the landing, ACTIVE.
 * QLOITER and QHOVER hover where they began. RTL (Q_RTL_MODE 0) circles home as a plane. Its
 * EXTENDED_SYS_STATE says its VTOL state. Its arming checks are AP_Arming_Plane's mission check of a
 * landing after a waypoint, "In landing sequence", and the modes it does not arm in. It answers the
 * parameters of {@link #PARAMS}.
 */
final class QuadPlaneFirmware extends PlaneFirmware {

    /** WP_RADIUS's default, which ArduPlane answers as an AP_Int16. */
    private static final int WP_RADIUS = 90;
    private static final Performance PERFORMANCE = new Performance(25, 5, 3, WP_RADIUS, 60, 0, 25);
    /** Q_PILOT_SPD_UP: the vertical take-off's climb (QuadPlane::do_vtol_takeoff). */
    static final double VTOL_CLIMB = 2.5;

    static final List<FirmwareParam> PARAMS = List.of(
            new FirmwareParam("Q_ENABLE", 1, MAV_PARAM_TYPE.MAV_PARAM_TYPE_INT8),
            new FirmwareParam("AIRSPEED_CRUISE", 25, MAV_PARAM_TYPE.MAV_PARAM_TYPE_REAL32),
            new FirmwareParam("TECS_LAND_ARSPD", -1, MAV_PARAM_TYPE.MAV_PARAM_TYPE_REAL32),
            new FirmwareParam("Q_TRANS_DECEL", (float) VtolLanding.TRANS_DECEL, MAV_PARAM_TYPE.MAV_PARAM_TYPE_REAL32),
            new FirmwareParam("Q_OPTIONS", 0, MAV_PARAM_TYPE.MAV_PARAM_TYPE_INT32),
            new FirmwareParam("Q_RTL_MODE", 0, MAV_PARAM_TYPE.MAV_PARAM_TYPE_INT8),
            new FirmwareParam("Q_ASSIST_SPEED", (float) VtolLift.ASSIST_SPEED, MAV_PARAM_TYPE.MAV_PARAM_TYPE_REAL32),
            new FirmwareParam("Q_TRANSITION_MS", 5000, MAV_PARAM_TYPE.MAV_PARAM_TYPE_INT16),
            new FirmwareParam("Q_LAND_FINAL_ALT", (float) VtolLanding.FINAL_ALT, MAV_PARAM_TYPE.MAV_PARAM_TYPE_REAL32),
            new FirmwareParam("Q_RTL_ALT", 15, MAV_PARAM_TYPE.MAV_PARAM_TYPE_REAL32),
            new FirmwareParam("WP_RADIUS", WP_RADIUS, MAV_PARAM_TYPE.MAV_PARAM_TYPE_INT16));

    /** Modes whose quad motors are off: the transition is forced complete (QuadPlane::update). */
    private static final Set<Integer> MANUAL = Set.of(PLANE_MODE.PLANE_MODE_MANUAL, PLANE_MODE.PLANE_MODE_ACRO,
            PLANE_MODE.PLANE_MODE_TRAINING);
    /** The VTOL modes other than QRTL, which fly on their lift motors from the start (in_vtol_mode). */
    private static final Set<Integer> HOVERING = Set.of(PLANE_MODE.PLANE_MODE_QSTABILIZE, PLANE_MODE.PLANE_MODE_QHOVER,
            PLANE_MODE.PLANE_MODE_QLOITER, PLANE_MODE.PLANE_MODE_QLAND, PLANE_MODE.PLANE_MODE_QAUTOTUNE,
            PLANE_MODE.PLANE_MODE_QACRO);
    /** Modes it does not arm in (Mode::_pre_arm_checks false), with the names their refusal gives them. */
    private static final Map<Integer, String> NOT_ARMABLE = Map.of(PLANE_MODE.PLANE_MODE_RTL, "RTL",
            PLANE_MODE.PLANE_MODE_QLAND, "QLand", PLANE_MODE.PLANE_MODE_QRTL, "QRTL");
    /** Plane::is_land_command. */
    private static final Set<Integer> LANDINGS = Set.of(MAV_CMD.MAV_CMD_NAV_LAND, MAV_CMD.MAV_CMD_NAV_VTOL_LAND,
            MAV_CMD.MAV_CMD_NAV_PAYLOAD_PLACE);

    private final VtolLift lift = new VtolLift();

    @Override
    public VehicleFamily family() {
        return VehicleFamily.VTOL;
    }

    @Override
    public Performance performance() {
        return PERFORMANCE;
    }

    /** NAVL1_PERIOD: quadplane.parm's. */
    @Override
    double l1Period() {
        return 14;
    }

    @Override
    public List<FirmwareParam> params() {
        return PARAMS;
    }

    /**
     * AP_Arming_Plane: the mission's landings first (mission_checks), then "In landing sequence", then
     * the mode's own checks (ModeAuto::_pre_arm_checks: the mission must go on with a take-off).
     */
    @Override
    public Optional<String> armRefusal(int mode, MissionView mission) {
        Optional<String> tooShort = landingTooShort(mission.items());
        if (tooShort.isPresent()) {
            return tooShort;
        }
        boolean takeoffNext = takeoffNext(mission);
        if (mission.running() && mission.current() < mission.items().size()
                && LANDINGS.contains(mission.items().get(mission.current()).command()) && !takeoffNext) {
            return Optional.of("Arm: In landing sequence");
        }
        if (NOT_ARMABLE.containsKey(mode)) {
            return Optional.of("Arm: " + NOT_ARMABLE.get(mode) + " mode not armable");
        }
        if (mode == autoMode() && !takeoffNext) {
            return Optional.of("Arm: Auto missing takeoff waypoint");
        }
        return Optional.empty();
    }

    /**
     * AP_Arming_Plane::mission_checks: a landing straight after a NAV_WAYPOINT must lie at least 0.75
     * stopping distances at the landing airspeed (TECS_LAND_ARSPD, -1: AIRSPEED_CRUISE) from it.
     */
    static Optional<String> landingTooShort(List<MissionItem> items) {
        double min = 0.75 * VtolLanding.stoppingDistance(PERFORMANCE.speed());
        for (int i = 2; i < items.size(); i++) {
            MissionItem previous = items.get(i - 1);
            MissionItem item = items.get(i);
            if (LANDINGS.contains(item.command()) && previous.command() == MAV_CMD.MAV_CMD_NAV_WAYPOINT
                    && location(item).horizontalDistanceTo(location(previous)) < min) {
                return Optional.of(String.format(Locale.ROOT, "Arm: VTOL land too short, min %.0fm", min));
            }
        }
        return Optional.empty();
    }

    private static Position location(MissionItem item) {
        return Position.fromDegrees(item.x() * 1e-7, item.y() * 1e-7, 0);
    }

    /** AP_Mission::starts_with_takeoff_cmd: the first nav item from the current one (or the first) is a take-off. */
    private static boolean takeoffNext(MissionView mission) {
        for (int i = Math.max(1, mission.current()); i < mission.items().size(); i++) {
            int command = mission.items().get(i).command();
            if (command == MAV_CMD.MAV_CMD_NAV_TAKEOFF || command == MAV_CMD.MAV_CMD_NAV_VTOL_TAKEOFF) {
                return true;
            }
            if (MissionFlight.nav(command) && command != MAV_CMD.MAV_CMD_NAV_DELAY) {
                return false;
            }
        }
        return false;
    }

    /** QuadPlane::is_vtol_takeoff and is_vtol_land: with Q_OPTIONS 0, the plane's take-off and landing are VTOL ones too. */
    @Override
    public int fliesAs(int command) {
        return switch (command) {
            case MAV_CMD.MAV_CMD_NAV_VTOL_TAKEOFF -> MAV_CMD.MAV_CMD_NAV_TAKEOFF;
            case MAV_CMD.MAV_CMD_NAV_VTOL_LAND -> MAV_CMD.MAV_CMD_NAV_LAND;
            default -> command;
        };
    }

    /** QuadPlane::do_vtol_takeoff: param7 above where it stands, whatever the frame. */
    @Override
    public double takeoffAltitude(MissionItem item, double itemAltitude, Craft craft) {
        return craft.position().hae() + item.z();
    }

    /** Straight up where it stands, on its lift motors. */
    @Override
    public Manoeuvre takeoff(Craft craft, double altitude) {
        return new Takeoff(craft, altitude, (alt, dt) -> {
            lift.hover();
            craft.climbTo(alt, VTOL_CLIMB, VtolLanding.DESCENT, dt);
        }, 0);
    }

    /** As a plane, after a transition if it was hovering. */
    @Override
    public boolean reach(Craft craft, Position target, double radius, double endSpeed, double dt) {
        craft.fly(target, endSpeed, radius, lift.forward(craft, dt), dt);
        return craft.distanceTo(target) <= radius;
    }

    @Override
    public Manoeuvre landing(Craft craft, Position over) {
        return new VtolLanding(this, lift, craft, over);
    }

    @Override
    public boolean completesLanding() {
        return false;
    }

    @Override
    public boolean fliesIn(int mode) {
        return mode == PLANE_MODE.PLANE_MODE_QRTL || mode == PLANE_MODE.PLANE_MODE_QLAND
                || mode == PLANE_MODE.PLANE_MODE_QLOITER || mode == PLANE_MODE.PLANE_MODE_QHOVER;
    }

    /** QRTL lands at home, QLAND where it is; QLOITER and QHOVER hover where they began. */
    @Override
    public Manoeuvre modeFlight(int mode, Craft craft, Position home) {
        return switch (mode) {
            case PLANE_MODE.PLANE_MODE_QRTL -> new VtolLanding(this, lift, craft, home);
            case PLANE_MODE.PLANE_MODE_QLAND -> new VtolLanding(this, lift, craft, null);
            default -> {
                Position at = craft.position();
                yield dt -> {
                    lift.hover();
                    craft.fly(at, dt);
                    return false;
                };
            }
        };
    }

    /** SLT_Transition::get_mav_vtol_state, and MC on the ground in AUTO, where its mission starts with a VTOL take-off. */
    @Override
    public int vtolState(int mode, boolean onGround) {
        if (MANUAL.contains(mode)) {
            return MAV_VTOL_STATE.MAV_VTOL_STATE_FW;
        }
        if (HOVERING.contains(mode) || onGround && mode == autoMode()) {
            return MAV_VTOL_STATE.MAV_VTOL_STATE_MC;
        }
        return lift.mavState();
    }

    @Override
    public Failures failures() {
        return FaultTable.QUADPLANE;
    }
}
