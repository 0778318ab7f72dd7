package dolphin.sim;

import com.MAVLink.common.msg_fence_status;
import com.MAVLink.enums.FENCE_BREACH;
import com.MAVLink.enums.FENCE_MITIGATE;
import dolphin.core.Position;
import dolphin.mission.model.Fence;

/**
 * A simulated vehicle's fence watch, as ArduPilot's AC_Fence does it for its polygon fence (which
 * holds the inclusion and exclusion polygons and circles): off until FENCE_ENABLE
 * (MAV_CMD_DO_FENCE_ENABLE 1); then a position outside an inclusion region or inside an exclusion
 * one, while armed, is a breach, counted once until the vehicle is back inside. The vehicle says
 * "Polygon fence breached" and "Fence breach cleared" and takes the fence action (docs/airspace.md).
 */
final class FenceGuard {

    /** What a check found. */
    enum Change { NONE, BREACHED, CLEARED }

    private boolean enabled;
    private boolean breached;
    private int breachCount;
    private long breachMillis;

    void enable(boolean on) {
        enabled = on;
        if (!on) {
            breached = false;
        }
    }

    boolean enabled() {
        return enabled;
    }

    /** Checks a position against the stored fence (not while disarmed, as ArduPilot takes no action then). */
    Change check(Fence fence, Position p, boolean armed, long bootMillis) {
        if (!enabled || !armed || fence.isEmpty()) {
            return Change.NONE;
        }
        boolean outside = fence.breachedBy(p).isPresent();
        if (outside && !breached) {
            breached = true;
            breachCount++;
            breachMillis = bootMillis;
            return Change.BREACHED;
        }
        if (!outside && breached) {
            breached = false;
            return Change.CLEARED;
        }
        return Change.NONE;
    }

    /** FENCE_STATUS, which ArduPilot sends while its fence is on. */
    msg_fence_status status() {
        msg_fence_status s = new msg_fence_status();
        s.breach_status = (short) (breached ? 1 : 0);
        s.breach_count = breachCount;
        s.breach_type = (short) (breachCount == 0 ? FENCE_BREACH.FENCE_BREACH_NONE : FENCE_BREACH.FENCE_BREACH_BOUNDARY);
        s.breach_time = breachMillis;
        s.breach_mitigation = (short) FENCE_MITIGATE.FENCE_MITIGATE_NONE;
        return s;
    }
}
