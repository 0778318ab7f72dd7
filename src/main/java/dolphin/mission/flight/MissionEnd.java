package dolphin.mission.flight;

import dolphin.mission.model.MissionItem;
import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.enums.MAV_LANDED_STATE;
import com.MAVLink.enums.MISSION_STATE;
import dolphin.core.Position;
import dolphin.mavlink.VehicleState;
import java.time.Duration;
import java.util.List;

/**
 * Decides, from what the vehicle reports, whether a running mission is done, still going, or has
 * gone wrong (docs/mavlink.md, "How each family flies a mission"). It is fed one snapshot at a
 * time with the clock's time, so its rules are tested without vehicles:
 *
 * <ul>
 * <li>A mission that ends on the ground (its family's {@link FlightRules#landsAfter}) is done once
 *     its landing item has been current and the vehicle is disarmed and not in the air. ArduCopter
 *     never reports the LAND reached and restarts the mission when it disarms, so neither
 *     MISSION_ITEM_REACHED nor MISSION_CURRENT can say it.</li>
 * <li>Any other mission is done when the last item is reached or the mission is COMPLETE, except
 *     one that ends in an unlimited loiter: only a condition ends that.</li>
 * <li>A landing that makes no progress in AUTO is an error naming the item and what the vehicle reported.</li>
 * </ul>
 * Who else changes the mode is {@link Takeovers}' to judge; a disarm or a fault in mid-mission, {@link FlightAlarms}'.
 */
final class MissionEnd {

    /** The outcome of one look at the vehicle. */
    record Verdict(boolean done, String error) {
        static final Verdict RUNNING = new Verdict(false, null);
        static final Verdict DONE = new Verdict(true, null);

        static Verdict failed(String why) {
            return new Verdict(false, why);
        }

        boolean running() {
            return !done && error == null;
        }
    }

    /** How far a vehicle must move for a landing to count as progressing. */
    static final double PROGRESS_METRES = 1;

    private final ItemNames names;
    private final String vehicle;
    private final Duration landingStall;
    private final int last;
    private final int lastNav;
    private final boolean landing;
    private final boolean endless;
    private boolean active;
    private boolean landingSeen;
    private Position progressFrom;
    private long progressAt;

    MissionEnd(FlightRules rules, List<MissionItem> items, String vehicle, Duration landingStall) {
        this.names = new ItemNames(items);
        this.vehicle = vehicle;
        this.landingStall = landingStall;
        this.last = items.size() - 1;
        this.lastNav = lastNavigation(items);
        int lastCommand = items.get(lastNav).command();
        this.landing = rules.landsAfter(lastCommand);
        this.endless = lastCommand == MAV_CMD.MAV_CMD_NAV_LOITER_UNLIM;
    }

    /** The last navigation item's seq (home, 0, when the mission has none). */
    static int lastNavigation(List<MissionItem> items) {
        for (int i = items.size() - 1; i > 0; i--) {
            if (items.get(i).command() < MAV_CMD.MAV_CMD_NAV_LAST) {
                return i;
            }
        }
        return 0;
    }

    /**
     * One look at the vehicle.
     *
     * @param s the vehicle's latest snapshot
     * @param reached the highest item known to be reached (MISSION_ITEM_REACHED, or passed per MISSION_CURRENT)
     * @param auto whether the vehicle is in AUTO: out of it, a landing is someone else's and makes no progress of its own
     * @param now the clock's time
     */
    Verdict judge(VehicleState s, int reached, boolean auto, long now) {
        boolean missionActive = s.missionState() == MISSION_STATE.MISSION_STATE_ACTIVE;
        active |= missionActive;
        boolean complete = active && s.missionState() == MISSION_STATE.MISSION_STATE_COMPLETE;
        if (landing) {
            landingSeen |= complete || reached >= lastNav || (missionActive && s.missionSeq() >= lastNav);
            if (landingSeen) {
                return landed(s, reached, auto, now);
            }
        } else if (!endless && (complete || reached >= last)) {
            return Verdict.DONE;
        }
        return Verdict.RUNNING;
    }

    /** The landing item was current: done on the ground and disarmed; no progress in AUTO is an error. */
    private Verdict landed(VehicleState s, int reached, boolean auto, long now) {
        int landed = s.landedState();
        boolean down = landed != MAV_LANDED_STATE.MAV_LANDED_STATE_IN_AIR && landed != MAV_LANDED_STATE.MAV_LANDED_STATE_TAKEOFF
                && landed != MAV_LANDED_STATE.MAV_LANDED_STATE_LANDING;
        if (!s.armed() && down) {
            return Verdict.DONE;
        }
        Position p = s.position();
        if (!auto || progressFrom == null || (p != null && p.distanceTo(progressFrom) >= PROGRESS_METRES)) {
            progressFrom = p;
            progressAt = now;
        } else if (now - progressAt > landingStall.toNanos()) {
            return Verdict.failed("vehicle " + vehicle + " did not finish " + names.item(lastNav) + ": no progress for "
                    + landingStall.toSeconds() + " s" + ItemNames.where(s));
        }
        return Verdict.RUNNING;
    }

    /** Whether the landing that ends the mission has begun: its item has been current. */
    boolean landing() {
        return landingSeen;
    }

    /** The item under way: the vehicle's current item while it reports one, else the one after the last reached. */
    int current(VehicleState s, int reached) {
        int seq = s.missionSeq() > 0 ? s.missionSeq() : reached + 1;
        return Math.max(1, Math.min(seq, last));
    }

}
