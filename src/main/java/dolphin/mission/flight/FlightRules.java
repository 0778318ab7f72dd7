package dolphin.mission.flight;

import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.enums.MAV_FRAME;
import dolphin.mavlink.VehicleFamily;
import dolphin.mission.model.MissionItem;
import dolphin.mission.model.Underwater;
import java.util.List;
import java.util.Optional;
import java.util.Set;

/**
 * What differs between ArduPilot families when a mission is flown (docs/mavlink.md, "How each
 * family flies a mission"): how the vehicle is armed and started, which mode holds it, and which
 * missions end with the vehicle on the ground. The executor asks these questions and never names a
 * family itself.
 */
public interface FlightRules {

    /** The rules for a family; other autopilots fly as Rover does (arm, AUTO, done at COMPLETE). */
    static FlightRules of(VehicleFamily family) {
        return switch (family) {
            case COPTER, HELI -> Copter.RULES;
            case PLANE, VTOL -> Plane.RULES;
            case SUB -> Sub.RULES;
            default -> Rover.RULES;
        };
    }

    /** Whether the vehicle goes under water, so flies underwater missions ({@code maxDepth}) and only those. */
    default boolean underwater() {
        return false;
    }

    /** Whether the vehicle can stop where it is, as hover-and-capture surveys need; a plane cannot. */
    default boolean stops() {
        return true;
    }

    /** The items as this family must receive them; by default as the mission made them (heights above mean sea level). */
    default List<MissionItem> onBoard(List<MissionItem> items, Underwater water) {
        return items;
    }

    /** Why the family cannot fly this item, or empty when it can. */
    default Optional<String> cannotFly(MissionItem item) {
        return Optional.empty();
    }

    /** The mode a flight cut short ends in: back to its launch, by default. */
    default String cutShortMode() {
        return "RTL";
    }

    /** The mode to arm in, or empty (the default) to arm in the mode the vehicle is in. */
    default Optional<String> armMode() {
        return Optional.empty();
    }

    /** Whether AUTO must be followed by MAV_CMD_MISSION_START before the vehicle moves; by default AUTO starts it. */
    default boolean needsMissionStart() {
        return false;
    }

    /** The mode that holds the vehicle where it is, e.g. before its mission is replaced. */
    String holdMode();

    /**
     * The modes a pilot or another ground station takes the vehicle into to hold it or fly it by hand:
     * leaving AUTO for one of these pauses the mission until AUTO is back (ArduPilot resumes at its
     * current item). Any other mode (RTL, LAND, SMART_RTL, SURFACE) ends the mission's purpose
     * (docs/failures.md, "A pilot's pause").
     */
    Set<String> takeoverModes();

    /** Whether the vehicle flies, so being on the ground with items left is an accident; rovers and subs do not. */
    default boolean flies() {
        return false;
    }

    /** The family's default WP_RADIUS, in metres. */
    double waypointRadius();

    /**
     * How close to a waypoint item the vehicle counts as there, in metres: there, it is doing the item's
     * own waiting, which is no stall. By default the family's WP_RADIUS: AP_Mission keeps an item's
     * acceptance radius (param2) on ArduPlane only.
     */
    default double arrivalRadius(MissionItem waypoint) {
        return waypointRadius();
    }

    /** Whether the vehicle holds at this waypoint once there: its param1 is a hold time, in seconds. */
    default boolean holdsAt(MissionItem waypoint) {
        return waypoint.command() == MAV_CMD.MAV_CMD_NAV_WAYPOINT && waypoint.param1() > 0;
    }

    /** The radius the vehicle circles a loiter item at when the item names none (ArduPilot's default). */
    double loiterRadius();

    /** Whether a mission whose last navigation command is {@code command} ends on the ground, disarmed. */
    boolean landsAfter(int command);

    /**
     * ArduCopter: armed in GUIDED (it refuses to arm in AUTO), started by MISSION_START; LAND and
     * RETURN_TO_LAUNCH end on the ground, where it disarms itself without reporting the item reached.
     */
    enum Copter implements FlightRules {
        RULES;

        @Override
        public Optional<String> armMode() {
            return Optional.of("GUIDED");
        }

        @Override
        public boolean needsMissionStart() {
            return true;
        }

        @Override
        public String holdMode() {
            return "LOITER";
        }

        @Override
        public Set<String> takeoverModes() {
            return Set.of("LOITER", "BRAKE", "POSHOLD", "ALT_HOLD", "STABILIZE", "ACRO", "GUIDED", "CIRCLE", "SPORT", "DRIFT",
                    "FLOWHOLD", "ZIGZAG");
        }

        @Override
        public boolean flies() {
            return true;
        }

        /** WPNAV_RADIUS 200 cm. */
        @Override
        public double waypointRadius() {
            return 2;
        }

        /** CIRCLE_RADIUS 1000 cm. */
        @Override
        public double loiterRadius() {
            return 10;
        }

        @Override
        public boolean landsAfter(int command) {
            return command == MAV_CMD.MAV_CMD_NAV_LAND || command == MAV_CMD.MAV_CMD_NAV_RETURN_TO_LAUNCH;
        }
    }

    /**
     * ArduPlane: armed in its current mode and started by AUTO; at the end of a mission it switches
     * itself to RTL and circles home; only LAND ends on the ground.
     */
    enum Plane implements FlightRules {
        RULES;

        @Override
        public String holdMode() {
            return "LOITER";
        }

        @Override
        public Set<String> takeoverModes() {
            return Set.of("LOITER", "CIRCLE", "MANUAL", "STABILIZE", "TRAINING", "ACRO", "FLY_BY_WIRE_A", "FLY_BY_WIRE_B",
                    "CRUISE", "GUIDED", "QSTABILIZE", "QHOVER", "QLOITER", "QACRO", "THERMAL");
        }

        @Override
        public boolean flies() {
            return true;
        }

        /** WP_RADIUS 90 m. */
        @Override
        public double waypointRadius() {
            return 90;
        }

        @Override
        public double arrivalRadius(MissionItem waypoint) {
            return Math.max(waypoint.param2(), waypointRadius());
        }

        /** AP_Mission keeps ArduPlane's waypoint param1 as pass-by distances, never a hold (docs/decisions.md). */
        @Override
        public boolean holdsAt(MissionItem waypoint) {
            return false;
        }

        /** WP_LOITER_RAD 60 m. */
        @Override
        public double loiterRadius() {
            return 60;
        }

        @Override
        public boolean stops() {
            return false;
        }

        @Override
        public boolean landsAfter(int command) {
            return command == MAV_CMD.MAV_CMD_NAV_LAND;
        }
    }

    /** Rover: armed in its current mode, started by AUTO, stops (HOLD) at the end; it never lands. */
    enum Rover implements FlightRules {
        RULES;

        @Override
        public String holdMode() {
            return "HOLD";
        }

        @Override
        public Set<String> takeoverModes() {
            return Set.of("HOLD", "LOITER", "MANUAL", "ACRO", "STEERING", "GUIDED", "SIMPLE", "CIRCLE");
        }

        /** WP_RADIUS 2 m. */
        @Override
        public double waypointRadius() {
            return 2;
        }

        /** LOIT_RADIUS 2 m. */
        @Override
        public double loiterRadius() {
            return 2;
        }

        @Override
        public boolean landsAfter(int command) {
            return false;
        }
    }

    /**
     * ArduSub (docs/underwater.md): every item's height is relative to home, at the surface, and
     * negative (a depth): ArduSub refuses any other frame with "Bad alt frame". Armed in MANUAL, its
     * boot mode (AUTO while disarmed races through the mission without moving), started by AUTO;
     * holds position and depth in POSHOLD; at the end of a mission it holds its depth in AUTO, so a
     * mission that should end at the surface ends with a surfacing (NAV_LAND). It has no RTL: cut
     * short, it rises to the surface (SURFACE).
     */
    enum Sub implements FlightRules {
        RULES;

        /** What ArduSub's Sub::start_command starts (ArduSub/commands_logic.cpp); it ignores anything else. */
        private static final Set<Integer> FLOWN = Set.of(MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_CMD.MAV_CMD_NAV_LAND,
                MAV_CMD.MAV_CMD_NAV_LOITER_UNLIM, MAV_CMD.MAV_CMD_NAV_LOITER_TURNS, MAV_CMD.MAV_CMD_NAV_LOITER_TIME,
                MAV_CMD.MAV_CMD_NAV_GUIDED_ENABLE, MAV_CMD.MAV_CMD_NAV_DELAY, MAV_CMD.MAV_CMD_CONDITION_DELAY,
                MAV_CMD.MAV_CMD_CONDITION_DISTANCE, MAV_CMD.MAV_CMD_CONDITION_YAW, MAV_CMD.MAV_CMD_DO_CHANGE_SPEED,
                MAV_CMD.MAV_CMD_DO_SET_HOME, MAV_CMD.MAV_CMD_DO_SET_ROI_LOCATION, MAV_CMD.MAV_CMD_DO_SET_ROI_NONE,
                MAV_CMD.MAV_CMD_DO_SET_ROI, MAV_CMD.MAV_CMD_DO_MOUNT_CONTROL, MAV_CMD.MAV_CMD_DO_GUIDED_LIMITS);

        @Override
        public boolean underwater() {
            return true;
        }

        /** Heights above mean sea level become heights above home, at the surface: minus the depth. */
        @Override
        public List<MissionItem> onBoard(List<MissionItem> items, Underwater water) {
            return items.stream().map(i -> i.seq() == 0 || MissionItem.altitudeReference(i.frame()) != MAV_FRAME.MAV_FRAME_GLOBAL ? i
                    : new MissionItem(i.seq(), i.command(), MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT, i.param1(), i.param2(),
                            i.param3(), i.param4(), i.x(), i.y(), onBoardHeight(water, i.z()), i.autocontinue()))
                    .toList();
        }

        /** Minus the depth, never above the surface (ArduSub refuses a height above home), and 0 rather than -0. */
        private static float onBoardHeight(Underwater water, float hae) {
            return (float) Math.min(0, -water.depthOf(hae)) + 0f;
        }

        @Override
        public Optional<String> cannotFly(MissionItem item) {
            return switch (item.command()) {
                case MAV_CMD.MAV_CMD_NAV_TAKEOFF -> Optional.of("a submarine does not take off (ArduSub ignores NAV_TAKEOFF):"
                        + " dive instead");
                case MAV_CMD.MAV_CMD_NAV_RETURN_TO_LAUNCH -> Optional.of("ArduSub has no return to launch: surface at home"
                        + " with returnHomeAndLand");
                default -> FLOWN.contains(item.command()) || item.seq() == 0 ? Optional.empty()
                        : Optional.of("ArduSub ignores this command");
            };
        }

        @Override
        public Optional<String> armMode() {
            return Optional.of("MANUAL");
        }

        @Override
        public String holdMode() {
            return "POSHOLD";
        }

        @Override
        public Set<String> takeoverModes() {
            return Set.of("POSHOLD", "ALT_HOLD", "STABILIZE", "MANUAL", "ACRO", "GUIDED", "CIRCLE", "SURFTRAK");
        }

        /** WPNAV_RADIUS 200 cm. */
        @Override
        public double waypointRadius() {
            return 2;
        }

        @Override
        public double loiterRadius() {
            return 10;
        }

        @Override
        public String cutShortMode() {
            return "SURFACE";
        }

        @Override
        public boolean landsAfter(int command) {
            return false;
        }
    }
}
