package dolphin.mission.flight;

import dolphin.mission.model.MissionItem;
import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.enums.MAV_LANDED_STATE;
import com.MAVLink.enums.MISSION_STATE;
import dolphin.core.Position;
import dolphin.mavlink.EnumNames;
import dolphin.mavlink.VehicleState;
import java.time.Duration;
import java.util.List;
import java.util.Locale;

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
 * <li>Leaving AUTO is someone else's hand, unless it happens at the last navigation item and the
 *     mission's end follows within the grace period: ArduPlane switches itself to RTL in the same
 *     tick as, and before, its last MISSION_ITEM_REACHED.</li>
 * <li>A landing that makes no progress, or a vehicle disarmed in mid-mission, is an error naming the
 *     item and what the vehicle reported.</li>
 * </ul>
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
    /** How many of the vehicle's last texts may tell of a fence breach. */
    private static final int RECENT_TEXTS = 5;

    private final List<MissionItem> items;
    private final String vehicle;
    private final Duration modeGrace;
    private final Duration landingStall;
    private final int last;
    private final int lastNav;
    private final boolean landing;
    private final boolean endless;
    private boolean active;
    private boolean sawArmed;
    private boolean sawAuto;
    private boolean landingSeen;
    private long leftAutoAt = -1;
    private Position progressFrom;
    private long progressAt;

    MissionEnd(FlightRules rules, List<MissionItem> items, String vehicle, Duration modeGrace, Duration landingStall) {
        this.items = items;
        this.vehicle = vehicle;
        this.modeGrace = modeGrace;
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
     * @param auto whether the vehicle is in AUTO
     * @param now the clock's time
     */
    Verdict judge(VehicleState s, int reached, boolean auto, long now) {
        boolean missionActive = s.missionState() == MISSION_STATE.MISSION_STATE_ACTIVE;
        active |= missionActive;
        sawArmed |= s.armed();
        boolean complete = active && s.missionState() == MISSION_STATE.MISSION_STATE_COMPLETE;
        if (landing) {
            landingSeen |= complete || reached >= lastNav || (missionActive && s.missionSeq() >= lastNav);
            if (landingSeen) {
                return landed(s, reached, auto, now);
            }
        } else if (!endless && (complete || reached >= last)) {
            return Verdict.DONE;
        }
        if (sawArmed && !s.armed()) {
            return Verdict.failed("vehicle " + vehicle + " disarmed during " + item(current(s, reached)) + where(s));
        }
        return modeCheck(s, reached, auto, now);
    }

    /** The landing item was current: done on the ground and disarmed; someone else's mode or no progress is an error. */
    private Verdict landed(VehicleState s, int reached, boolean auto, long now) {
        int landed = s.landedState();
        boolean down = landed != MAV_LANDED_STATE.MAV_LANDED_STATE_IN_AIR && landed != MAV_LANDED_STATE.MAV_LANDED_STATE_TAKEOFF
                && landed != MAV_LANDED_STATE.MAV_LANDED_STATE_LANDING;
        if (!s.armed() && down) {
            return Verdict.DONE;
        }
        Verdict mode = modeCheck(s, reached, auto, now);
        if (mode.error() != null) {
            return mode;
        }
        Position p = s.position();
        if (progressFrom == null || (p != null && p.distanceTo(progressFrom) >= PROGRESS_METRES)) {
            progressFrom = p;
            progressAt = now;
        } else if (now - progressAt > landingStall.toNanos()) {
            return Verdict.failed("vehicle " + vehicle + " did not finish " + item(lastNav) + ": no progress for "
                    + landingStall.toSeconds() + " s" + where(s));
        }
        return Verdict.RUNNING;
    }

    private Verdict modeCheck(VehicleState s, int reached, boolean auto, long now) {
        if (auto) {
            sawAuto = true;
            leftAutoAt = -1;
            return Verdict.RUNNING;
        }
        if (!sawAuto) {
            return Verdict.RUNNING;
        }
        int current = current(s, reached);
        if (current >= lastNav) {
            // Possibly the vehicle's own end of mission, reported a moment later.
            if (leftAutoAt < 0) {
                leftAutoAt = now;
            }
            if (now - leftAutoAt <= modeGrace.toNanos()) {
                return Verdict.RUNNING;
            }
        }
        if (fenceBreached(s)) {
            return Verdict.failed("vehicle " + vehicle + " breached its fence during " + item(current) + " and left AUTO"
                    + " for " + s.modeName() + " (its fence action)" + where(s));
        }
        return Verdict.failed("vehicle " + vehicle + " left AUTO for " + s.modeName() + " during " + item(current)
                + ", before the mission ended" + where(s));
    }

    /**
     * FENCE_STATUS says so, or one of the vehicle's last few texts ("Polygon fence breached": ArduPilot
     * says it before it changes mode, while FENCE_STATUS comes with its next telemetry).
     */
    private static boolean fenceBreached(VehicleState s) {
        List<String> texts = s.statusTexts();
        return s.fenceBreached() || texts.subList(Math.max(0, texts.size() - RECENT_TEXTS), texts.size()).stream()
                .anyMatch(t -> t.endsWith("fence breached") || t.endsWith("fences breached"));
    }

    /** The item under way: the vehicle's current item while it reports one, else the one after the last reached. */
    private int current(VehicleState s, int reached) {
        int seq = s.missionSeq() > 0 ? s.missionSeq() : reached + 1;
        return Math.max(1, Math.min(seq, last));
    }

    private String item(int seq) {
        return "item " + seq + " of " + last + " (" + items.get(seq).commandName() + ")";
    }

    /** What the vehicle last reported, for errors. */
    private static String where(VehicleState s) {
        StringBuilder b = new StringBuilder(": ").append(s.armed() ? "armed" : "disarmed").append(", ").append(s.modeName());
        b.append(", landed state ").append(EnumNames.name(MAV_LANDED_STATE.class, "MAV_LANDED_STATE_", s.landedState()));
        if (s.position() != null) {
            b.append(String.format(Locale.ROOT, ", %.1f m above home", s.relativeAlt()));
        }
        List<String> texts = s.statusTexts();
        if (!texts.isEmpty()) {
            b.append(", last text '").append(texts.get(texts.size() - 1)).append('\'');
        }
        return b.toString();
    }
}
