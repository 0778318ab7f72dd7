package dolphin.mission.model;

import com.MAVLink.enums.MAV_AUTOPILOT;
import com.MAVLink.enums.MAV_TYPE;

/**
 * What a QGroundControl plan says about the vehicle it was made for: firmware (MAV_AUTOPILOT),
 * vehicle type (MAV_TYPE, which picks QGroundControl's vehicle profile: a plane's plan must not
 * reopen as a multirotor) and the speeds it plans with, in m/s. Kept from an imported plan and
 * written back on export.
 */
public record VehicleProfile(int firmwareType, int vehicleType, double cruiseSpeed, double hoverSpeed) {

    /** QGroundControl's defaults for a new plan. */
    public static final double CRUISE_SPEED = 15;
    public static final double HOVER_SPEED = 5;

    /** An ArduPilot quadcopter at QGroundControl's default speeds. */
    public static final VehicleProfile ARDUPILOT_COPTER = ardupilot(MAV_TYPE.MAV_TYPE_QUADROTOR);

    /** An ArduPilot vehicle of a MAV_TYPE at QGroundControl's default speeds. */
    public static VehicleProfile ardupilot(int vehicleType) {
        return new VehicleProfile(MAV_AUTOPILOT.MAV_AUTOPILOT_ARDUPILOTMEGA, vehicleType, CRUISE_SPEED, HOVER_SPEED);
    }
}
