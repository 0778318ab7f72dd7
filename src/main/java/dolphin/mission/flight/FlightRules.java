package dolphin.mission.flight;

import com.MAVLink.enums.MAV_CMD;
import dolphin.mavlink.VehicleFamily;
import java.util.Optional;

/**
 * What differs between ArduPilot families when a mission is flown (docs/mavlink.md, "How each
 * family flies a mission"): how the vehicle is armed and started, which mode holds it, and which
 * missions end with the vehicle on the ground. The executor asks these questions and never names a
 * family itself.
 */
public interface FlightRules {

    /** The rules for a family; ArduSub and other autopilots fly as Rover does (arm, AUTO, done at COMPLETE). */
    static FlightRules of(VehicleFamily family) {
        return switch (family) {
            case COPTER -> Copter.RULES;
            case PLANE -> Plane.RULES;
            default -> Rover.RULES;
        };
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
        public boolean landsAfter(int command) {
            return false;
        }
    }
}
