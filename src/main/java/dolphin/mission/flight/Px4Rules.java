package dolphin.mission.flight;

import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.enums.MAV_FRAME;
import dolphin.mavlink.Autopilot;
import dolphin.mavlink.VehicleFamily;
import dolphin.mission.model.FlightWay;
import dolphin.mission.model.MissionItem;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

/**
 * How PX4 flies a mission (docs/px4.md), read in PX4-Autopilot's navigator and mavlink modules and
 * checked on its SITL: armed in the mode it is in, started by AUTO.MISSION and MAV_CMD_MISSION_START;
 * held in AUTO.LOITER, cut short by AUTO.RTL. It takes a command with a position in a global frame
 * and any other in MAV_FRAME_MISSION only, and flies the commands its mission feasibility check
 * allows; a mission that ends with a landing ends on the ground, disarmed, still in AUTO.MISSION,
 * and any other holds where it ends (COMPLETE).
 */
enum Px4Rules implements FlightRules {
    MULTICOPTER {
        @Override
        public Set<FlightWay> flightWays() {
            return Set.of(FlightWay.AS_THE_VEHICLE_DOES, FlightWay.VERTICAL);
        }

        /** RTL lands where it launched (RTL_LAND_DELAY 0). */
        @Override
        public boolean landsAfter(int command) {
            return command == MAV_CMD.MAV_CMD_NAV_LAND || command == MAV_CMD.MAV_CMD_NAV_RETURN_TO_LAUNCH;
        }
    },
    FIXED_WING {
        @Override
        public Set<FlightWay> flightWays() {
            return Set.of(FlightWay.AS_THE_VEHICLE_DOES, FlightWay.RUNWAY);
        }

        @Override
        public boolean stops() {
            return false;
        }

        @Override
        public Optional<String> cannotFly(MissionItem item) {
            return item.command() == MAV_CMD.MAV_CMD_NAV_VTOL_TAKEOFF || item.command() == MAV_CMD.MAV_CMD_NAV_VTOL_LAND
                    ? Optional.of("PX4 flies VTOL items only on a VTOL airframe") : refusal(item);
        }

        /** NAV_LOITER_RAD 80 m. */
        @Override
        public double loiterRadius() {
            return 80;
        }

        @Override
        public List<String> parameters() {
            return List.of(FixedWingApproach.LANDING_ANGLE);
        }

        /** As any PX4 vehicle, its landings' approaches checked as PX4 checks them ({@link FixedWingApproach}). */
        @Override
        public Boarded onBoard(List<MissionItem> items, Boarding boarding) {
            Boarded boarded = super.onBoard(items, boarding);
            FixedWingApproach.refusal(boarded.items(), boarding.parameter(FixedWingApproach.LANDING_ANGLE)
                    .orElse(FixedWingApproach.DEFAULT_ANGLE)).ifPresent(why -> {
                        throw new IllegalArgumentException(why);
                    });
            return boarded;
        }
    },
    /**
     * A take-off and a landing become NAV_VTOL_TAKEOFF and NAV_VTOL_LAND: PX4 flies a whole mission
     * as a multicopter after a NAV_TAKEOFF (it transitions only after NAV_VTOL_TAKEOFF, Mission::set_mission_items),
     * and lands as one after a NAV_VTOL_LAND, back-transitioning on the way (MissionBase::handleLanding).
     */
    VTOL {
        @Override
        public Set<FlightWay> flightWays() {
            return Set.of(FlightWay.AS_THE_VEHICLE_DOES, FlightWay.VERTICAL);
        }

        @Override
        MissionItem flown(MissionItem i) {
            int command = switch (i.command()) {
                case MAV_CMD.MAV_CMD_NAV_TAKEOFF -> MAV_CMD.MAV_CMD_NAV_VTOL_TAKEOFF;
                case MAV_CMD.MAV_CMD_NAV_LAND -> MAV_CMD.MAV_CMD_NAV_VTOL_LAND;
                default -> i.command();
            };
            return command == i.command() || i.seq() == 0 ? i : new MissionItem(i.seq(), command, i.frame(), 0, 0, 0, i.param4(),
                    i.x(), i.y(), i.z(), i.autocontinue());
        }

        @Override
        public boolean stops() {
            return false;
        }

        @Override
        public boolean landsAfter(int command) {
            return command == MAV_CMD.MAV_CMD_NAV_LAND || command == MAV_CMD.MAV_CMD_NAV_VTOL_LAND;
        }
    };

    /** The commands with a position, which PX4 takes in a global frame (MavlinkMissionManager::parse_mavlink_mission_item). */
    private static final Set<Integer> POSITIONAL = Set.of(MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_CMD.MAV_CMD_NAV_LOITER_UNLIM,
            MAV_CMD.MAV_CMD_NAV_LOITER_TIME, MAV_CMD.MAV_CMD_NAV_LAND, MAV_CMD.MAV_CMD_NAV_TAKEOFF,
            MAV_CMD.MAV_CMD_NAV_LOITER_TO_ALT, MAV_CMD.MAV_CMD_NAV_ROI, MAV_CMD.MAV_CMD_DO_SET_ROI,
            MAV_CMD.MAV_CMD_DO_SET_ROI_LOCATION, MAV_CMD.MAV_CMD_NAV_VTOL_TAKEOFF, MAV_CMD.MAV_CMD_NAV_VTOL_LAND,
            MAV_CMD.MAV_CMD_CONDITION_GATE);

    /** What PX4's mission feasibility check lets a mission hold (FeasibilityChecker::checkMissionItemValidity). */
    private static final Set<Integer> FLOWN = Set.of(MAV_CMD.MAV_CMD_NAV_WAYPOINT, MAV_CMD.MAV_CMD_NAV_LOITER_UNLIM,
            MAV_CMD.MAV_CMD_NAV_LOITER_TIME, MAV_CMD.MAV_CMD_NAV_RETURN_TO_LAUNCH, MAV_CMD.MAV_CMD_NAV_LAND,
            MAV_CMD.MAV_CMD_NAV_TAKEOFF, MAV_CMD.MAV_CMD_NAV_LOITER_TO_ALT, MAV_CMD.MAV_CMD_NAV_VTOL_TAKEOFF,
            MAV_CMD.MAV_CMD_NAV_VTOL_LAND, MAV_CMD.MAV_CMD_NAV_DELAY, MAV_CMD.MAV_CMD_CONDITION_GATE, MAV_CMD.MAV_CMD_DO_WINCH,
            MAV_CMD.MAV_CMD_DO_GRIPPER, MAV_CMD.MAV_CMD_DO_JUMP, MAV_CMD.MAV_CMD_DO_CHANGE_SPEED, MAV_CMD.MAV_CMD_DO_SET_HOME,
            MAV_CMD.MAV_CMD_DO_LAND_START, MAV_CMD.MAV_CMD_DO_TRIGGER_CONTROL, MAV_CMD.MAV_CMD_DO_DIGICAM_CONTROL,
            MAV_CMD.MAV_CMD_COMPONENT_ARM_DISARM, MAV_CMD.MAV_CMD_IMAGE_START_CAPTURE, MAV_CMD.MAV_CMD_IMAGE_STOP_CAPTURE,
            MAV_CMD.MAV_CMD_VIDEO_START_CAPTURE, MAV_CMD.MAV_CMD_VIDEO_STOP_CAPTURE, MAV_CMD.MAV_CMD_DO_CONTROL_VIDEO,
            MAV_CMD.MAV_CMD_DO_MOUNT_CONFIGURE, MAV_CMD.MAV_CMD_DO_MOUNT_CONTROL, MAV_CMD.MAV_CMD_DO_GIMBAL_MANAGER_PITCHYAW,
            MAV_CMD.MAV_CMD_DO_GIMBAL_MANAGER_CONFIGURE, MAV_CMD.MAV_CMD_DO_SET_ACTUATOR, MAV_CMD.MAV_CMD_DO_SET_ROI,
            MAV_CMD.MAV_CMD_DO_SET_ROI_LOCATION, MAV_CMD.MAV_CMD_DO_SET_ROI_WPNEXT_OFFSET, MAV_CMD.MAV_CMD_DO_SET_ROI_NONE,
            MAV_CMD.MAV_CMD_DO_SET_CAM_TRIGG_DIST, MAV_CMD.MAV_CMD_OBLIQUE_SURVEY, MAV_CMD.MAV_CMD_DO_SET_CAM_TRIGG_INTERVAL,
            MAV_CMD.MAV_CMD_SET_CAMERA_MODE, MAV_CMD.MAV_CMD_SET_CAMERA_SOURCE, MAV_CMD.MAV_CMD_SET_CAMERA_ZOOM,
            MAV_CMD.MAV_CMD_SET_CAMERA_FOCUS, MAV_CMD.MAV_CMD_DO_VTOL_TRANSITION);

    /** What a script may write instead of a command PX4 does not fly. */
    private static final Map<Integer, String> INSTEAD = Map.of(
            MAV_CMD.MAV_CMD_NAV_LOITER_TURNS, "loiter for a time (NAV_LOITER_TIME) instead",
            MAV_CMD.MAV_CMD_NAV_SPLINE_WAYPOINT, "use plain waypoints",
            MAV_CMD.MAV_CMD_CONDITION_YAW, "set the heading at a waypoint (its param4) instead",
            MAV_CMD.MAV_CMD_CONDITION_DELAY, "hold at a waypoint (its param1) or add a NAV_DELAY instead",
            MAV_CMD.MAV_CMD_DO_SET_SERVO, "use DO_SET_ACTUATOR instead");

    static FlightRules of(VehicleFamily family) {
        return switch (family) {
            case PLANE -> FIXED_WING;
            case VTOL -> VTOL;
            default -> MULTICOPTER;
        };
    }

    /** Each item as this kind of vehicle flies it; commands without a position in MAV_FRAME_MISSION, as PX4 takes them only. */
    @Override
    public Boarded onBoard(List<MissionItem> items, Boarding boarding) {
        return new Boarded(items.stream().map(this::flown).map(i -> i.seq() == 0 || POSITIONAL.contains(i.command())
                || i.frame() == MAV_FRAME.MAV_FRAME_MISSION ? i : new MissionItem(i.seq(), i.command(), MAV_FRAME.MAV_FRAME_MISSION,
                i.param1(), i.param2(), i.param3(), i.param4(), i.x(), i.y(), i.z(), i.autocontinue())).toList(), List.of());
    }

    /** The item as this kind of vehicle must be told to fly it; as written, by default. */
    MissionItem flown(MissionItem i) {
        return i;
    }

    @Override
    public Optional<String> cannotFly(MissionItem item) {
        return refusal(item);
    }

    /** Why PX4 would refuse the item, or its feasibility check fail the mission over it. */
    private static Optional<String> refusal(MissionItem item) {
        if (item.seq() == 0) {
            return Optional.empty();
        }
        if (!FLOWN.contains(item.command())) {
            String instead = INSTEAD.get(item.command());
            return Optional.of("PX4's missions do not fly this command" + (instead != null ? ": " + instead : ""));
        }
        if (POSITIONAL.contains(item.command()) && MissionItem.altitudeReference(item.frame()) == MAV_FRAME.MAV_FRAME_GLOBAL_TERRAIN_ALT) {
            return Optional.of("PX4 takes no height above terrain in a mission: give the height above home or sea level");
        }
        return Optional.empty();
    }

    @Override
    public String missionMode() {
        return Autopilot.PX4.missionMode();
    }

    @Override
    public boolean needsMissionStart() {
        return true;
    }

    @Override
    public boolean fenceSwitch() {
        return false;
    }

    @Override
    public boolean checksMissionAfterUpload() {
        return true;
    }

    @Override
    public boolean missionStartFromFirstItem() {
        return true;
    }

    @Override
    public String holdMode() {
        return "AUTO.LOITER";
    }

    @Override
    public String cutShortMode() {
        return "AUTO.RTL";
    }

    /** A pilot's modes, and Hold: PX4 resumes the mission at its current item when AUTO.MISSION is back. */
    @Override
    public Set<String> takeoverModes() {
        return Set.of("AUTO.LOITER", "MANUAL", "ALTCTL", "POSCTL", "POSCTL.ORBIT", "STABILIZED", "ACRO", "OFFBOARD");
    }

    @Override
    public boolean flies() {
        return true;
    }

    /** NAV_ACC_RAD 10 m. */
    @Override
    public double waypointRadius() {
        return 10;
    }

    /** NAV_LOITER_RAD: a multicopter hovers on the spot. */
    @Override
    public double loiterRadius() {
        return 2;
    }

    @Override
    public boolean landsAfter(int command) {
        return command == MAV_CMD.MAV_CMD_NAV_LAND;
    }
}
