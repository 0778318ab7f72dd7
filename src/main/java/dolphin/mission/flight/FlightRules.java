package dolphin.mission.flight;

import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.enums.MAV_FRAME;
import com.MAVLink.enums.MAV_MODE_FLAG;
import dolphin.mavlink.Autopilot;
import dolphin.mavlink.VehicleFamily;
import dolphin.mavlink.VehicleState;
import dolphin.mission.model.FlightWay;
import dolphin.mission.model.MissionItem;
import dolphin.mission.model.Underwater;
import java.util.List;
import java.util.Optional;
import java.util.Set;

/**
 * What differs between autopilots and their families when a mission is flown (docs/mavlink.md, "How
 * each family flies a mission"; docs/px4.md): how the vehicle is armed and started, which mode flies
 * the mission and which holds it, and which missions end with the vehicle on the ground. The
 * executor asks these questions and never names an autopilot or a family itself.
 */
public interface FlightRules {

    /** The rules for the vehicle's autopilot and family. */
    static FlightRules of(VehicleState vehicle) {
        return vehicle.autopilot() == Autopilot.PX4 ? Px4Rules.of(vehicle.family()) : of(vehicle.family());
    }

    /** The rules for an ArduPilot family; other autopilots fly as Rover does (arm, AUTO, done at COMPLETE). */
    static FlightRules of(VehicleFamily family) {
        return switch (family) {
            case COPTER -> Copter.MULTIROTOR;
            case HELI -> Copter.HELICOPTER;
            case PLANE -> Plane.FIXED_WING;
            case VTOL -> Plane.VTOL;
            case SUB -> Sub.RULES;
            default -> Rover.RULES;
        };
    }

    /** A command the family needs at a point of the flight, e.g. a helicopter's motor interlock. */
    record FamilyCommand(String what, int command, float... params) {
    }

    /** The ways this family takes off and lands: a script's explicit other way is refused before upload. */
    default Set<FlightWay> flightWays() {
        return Set.of(FlightWay.AS_THE_VEHICLE_DOES);
    }

    /** The parameters {@link #onBoard} reads from the vehicle, by name; none by default. */
    default List<String> parameters() {
        return List.of();
    }

    /** Whether the vehicle goes under water, so flies underwater missions ({@code maxDepth}) and only those. */
    default boolean underwater() {
        return false;
    }

    /** Whether the vehicle can stop where it is, as hover-and-capture surveys need; a plane cannot. */
    default boolean stops() {
        return true;
    }

    /**
     * The items as this family must receive them, and the seqs of the items it added; by default as
     * the mission made them (heights above mean sea level).
     *
     * @throws IllegalArgumentException when the vehicle cannot fly the mission as written, saying why
     */
    default Boarded onBoard(List<MissionItem> items, Boarding boarding) {
        return new Boarded(items, List.of());
    }

    /** Why the family cannot fly this item, or empty when it can. */
    default Optional<String> cannotFly(MissionItem item) {
        return Optional.empty();
    }

    /** The mode the vehicle flies its mission in: ArduPilot's AUTO, by default. */
    default String missionMode() {
        return "AUTO";
    }

    /** The mode a flight cut short ends in: back to its launch, by default. */
    default String cutShortMode() {
        return "RTL";
    }

    /** The mode to arm in, or empty (the default) to arm in the mode the vehicle is in. */
    default Optional<String> armMode() {
        return Optional.empty();
    }

    /**
     * Sent to a disarmed vehicle that has a position estimate, before its pre-arm checks are judged,
     * each until accepted: what those checks need that only the ground station gives (a helicopter's
     * motor interlock off). Never to an armed one: a helicopter's interlock off in flight is autorotation.
     */
    default List<FamilyCommand> onTheGround() {
        return List.of();
    }

    /** Sent once armed, each until accepted, before the mission starts. */
    default List<FamilyCommand> afterArming() {
        return List.of();
    }

    /** Sent once the mission has ended on the ground, disarmed. */
    default List<FamilyCommand> afterLanding() {
        return List.of();
    }

    /** Whether AUTO may be refused for a while once armed (a helicopter's rotor runs up): asked again until the start deadline. */
    default boolean autoWaitsAfterArming() {
        return false;
    }

    /** Whether AUTO must be followed by MAV_CMD_MISSION_START before the vehicle moves; by default AUTO starts it. */
    default boolean needsMissionStart() {
        return false;
    }

    /**
     * Whether MAV_CMD_MISSION_START makes the first item current itself (PX4, by its param1), so the
     * first item needs no MAV_CMD_DO_SET_MISSION_CURRENT, which PX4 does not take.
     */
    default boolean missionStartFromFirstItem() {
        return false;
    }

    /**
     * Whether the vehicle's fence is switched on by MAV_CMD_DO_FENCE_ENABLE (ArduPilot); PX4 takes no
     * such command and keeps to a fence from its upload on, by its GF_ACTION.
     */
    default boolean fenceSwitch() {
        return true;
    }

    /**
     * Whether the vehicle checks a mission after its upload, and takes no mode or start for it until
     * MISSION_CURRENT shows it valid (PX4's feasibility check: an infeasible mission is NO_MISSION).
     */
    default boolean checksMissionAfterUpload() {
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
     * A traditional helicopter (docs/vtol.md, "Helicopters") arms only with its motor interlock off
     * (RC8_OPTION 32, which its SITL has on: "Arm: Motor Interlock Enabled"), needs it on once armed,
     * and refuses AUTO until its rotor has run up ("runup not complete", about 13 s on SITL); the
     * interlock goes off again once it has landed.
     */
    enum Copter implements FlightRules {
        MULTIROTOR(false),
        HELICOPTER(true);

        /** RC_Channel::AUX_FUNC::MOTOR_INTERLOCK, switched by MAV_CMD_DO_AUX_FUNCTION: 0 low (off), 2 high (on). */
        private static final float MOTOR_INTERLOCK = 32;
        private static final FamilyCommand INTERLOCK_OFF = new FamilyCommand("motor interlock off (DO_AUX_FUNCTION 32 low)",
                MAV_CMD.MAV_CMD_DO_AUX_FUNCTION, MOTOR_INTERLOCK, 0);
        private static final FamilyCommand INTERLOCK_ON = new FamilyCommand("motor interlock on (DO_AUX_FUNCTION 32 high)",
                MAV_CMD.MAV_CMD_DO_AUX_FUNCTION, MOTOR_INTERLOCK, 2);

        private final boolean interlock;

        Copter(boolean interlock) {
            this.interlock = interlock;
        }

        @Override
        public Set<FlightWay> flightWays() {
            return Set.of(FlightWay.AS_THE_VEHICLE_DOES, FlightWay.VERTICAL);
        }

        @Override
        public Optional<String> armMode() {
            return Optional.of("GUIDED");
        }

        @Override
        public List<FamilyCommand> onTheGround() {
            return interlock ? List.of(INTERLOCK_OFF) : List.of();
        }

        @Override
        public List<FamilyCommand> afterArming() {
            return interlock ? List.of(INTERLOCK_ON) : List.of();
        }

        @Override
        public List<FamilyCommand> afterLanding() {
            return interlock ? List.of(INTERLOCK_OFF) : List.of();
        }

        @Override
        public boolean autoWaitsAfterArming() {
            return interlock;
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
                    "FLOWHOLD", "ZIGZAG", "AUTOTUNE");
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
     * itself to RTL and circles home; only LAND ends on the ground. A QuadPlane (VTOL, docs/vtol.md)
     * takes off and lands vertically unless the script says otherwise ({@link VtolItems}), is armed in
     * AUTO with its first item current, as ArduPlane's own tests do, disarms itself once landed and
     * stays in AUTO; cut short it lands vertically at home (QRTL: RTL circles there with Q_RTL_MODE 0).
     */
    enum Plane implements FlightRules {
        FIXED_WING {
            @Override
            public Optional<String> cannotFly(MissionItem item) {
                return item.command() == MAV_CMD.MAV_CMD_NAV_VTOL_TAKEOFF || item.command() == MAV_CMD.MAV_CMD_NAV_VTOL_LAND
                        ? Optional.of("ArduPlane flies VTOL items only on a QuadPlane (Q_ENABLE, and rebooted since)")
                        : Optional.empty();
            }
        },
        VTOL {
            @Override
            public Set<FlightWay> flightWays() {
                return Set.of(FlightWay.values());
            }

            @Override
            public List<String> parameters() {
                return VtolItems.PARAMETERS;
            }

            @Override
            public Boarded onBoard(List<MissionItem> items, Boarding boarding) {
                return new VtolItems(boarding).onBoard(items);
            }

            @Override
            public Optional<String> armMode() {
                return Optional.of("AUTO");
            }

            @Override
            public String cutShortMode() {
                return "QRTL";
            }

            /** Landed in AUTO, ArduPlane refuses to arm ("In landing sequence") until it leaves AUTO or gets a new mission. */
            @Override
            public List<FamilyCommand> afterLanding() {
                return List.of(LANDING_SEQUENCE_ENDED);
            }

            @Override
            public boolean landsAfter(int command) {
                return command == MAV_CMD.MAV_CMD_NAV_LAND || command == MAV_CMD.MAV_CMD_NAV_VTOL_LAND;
            }
        };

        /** QLOITER, which ends a landed mission's landing sequence (Plane::set_mode) and holds the vehicle if armed by hand. */
        private static final FamilyCommand LANDING_SEQUENCE_ENDED = new FamilyCommand("QLOITER, which ends ArduPlane's landing"
                + " sequence", MAV_CMD.MAV_CMD_DO_SET_MODE, MAV_MODE_FLAG.MAV_MODE_FLAG_CUSTOM_MODE_ENABLED,
                Autopilot.ARDUPILOT.modes(VehicleFamily.VTOL).number("QLOITER").orElseThrow());

        @Override
        public Set<FlightWay> flightWays() {
            return Set.of(FlightWay.AS_THE_VEHICLE_DOES, FlightWay.RUNWAY);
        }

        @Override
        public String holdMode() {
            return "LOITER";
        }

        @Override
        public Set<String> takeoverModes() {
            return Set.of("LOITER", "CIRCLE", "MANUAL", "STABILIZE", "TRAINING", "ACRO", "FLY_BY_WIRE_A", "FLY_BY_WIRE_B",
                    "CRUISE", "GUIDED", "AUTOTUNE", "QSTABILIZE", "QHOVER", "QLOITER", "QACRO", "QAUTOTUNE", "THERMAL");
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
        public Boarded onBoard(List<MissionItem> items, Boarding boarding) {
            Underwater water = boarding.water();
            return new Boarded(items.stream().map(i -> i.seq() == 0 || MissionItem.altitudeReference(i.frame()) != MAV_FRAME.MAV_FRAME_GLOBAL ? i
                    : new MissionItem(i.seq(), i.command(), MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT, i.param1(), i.param2(),
                            i.param3(), i.param4(), i.x(), i.y(), onBoardHeight(water, i.z()), i.autocontinue()))
                    .toList(), List.of());
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
