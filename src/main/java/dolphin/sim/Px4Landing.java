package dolphin.sim;

import com.MAVLink.enums.MAV_LANDED_STATE;
import dolphin.core.Position;

/**
 * A PX4 multicopter's landing (a mission's landing item, AUTO.LAND): over the landing point at its
 * height, still in the air (MissionBase's move to the landing point), then down, LANDING, at
 * MPC_Z_VEL_MAX_DN above MPC_LAND_ALT1 and MPC_LAND_SPEED below MPC_LAND_ALT2, in proportion between
 * them (FlightTaskAuto::_prepareLandSetpoints). It is over when the land detector has seen the ground
 * for LNDMC_TRIG_TIME (its three stages, a third each).
 */
final class Px4Landing extends Landing {

    static final double MPC_Z_VEL_MAX_DN = 1.5;
    static final double MPC_LAND_SPEED = 0.7;
    static final double MPC_LAND_ALT1 = 10;
    static final double MPC_LAND_ALT2 = 5;
    static final double LNDMC_TRIG_TIME = 1;

    /** Lands at {@code over} (lat, lon; its height does not matter), or where it is when null. */
    Px4Landing(Craft craft, Position over) {
        super(craft, over);
    }

    @Override
    double sinkRate(Craft craft) {
        return sinkRate(craft.height());
    }

    /** The descent's speed at {@code height} above ground, metres a second. */
    static double sinkRate(double height) {
        double share = Math.min(1, Math.max(0, (height - MPC_LAND_ALT2) / (MPC_LAND_ALT1 - MPC_LAND_ALT2)));
        return MPC_LAND_SPEED + share * (MPC_Z_VEL_MAX_DN - MPC_LAND_SPEED);
    }

    @Override
    double detectSeconds() {
        return LNDMC_TRIG_TIME;
    }

    /** In the air on its way to the landing point, LANDING from the descent on. */
    @Override
    public int landedState() {
        return descending() ? MAV_LANDED_STATE.MAV_LANDED_STATE_LANDING : MAV_LANDED_STATE.MAV_LANDED_STATE_IN_AIR;
    }
}
