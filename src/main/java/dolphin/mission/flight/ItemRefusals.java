package dolphin.mission.flight;

import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.enums.MAV_SEVERITY;
import com.MAVLink.enums.MISSION_STATE;
import dolphin.mission.model.MissionItem;
import java.time.Duration;
import java.util.BitSet;
import java.util.List;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Finds an item the vehicle refused in flight, from what it says about its items in the order it
 * says it (docs/mavlink.md, "Refused items"). ArduPilot refuses an item it cannot fly by warning
 * ("Bad alt frame", "Skipping invalid cmd #31") and going on to the next one in the same update,
 * without MISSION_ITEM_REACHED: a mission of such items "ends" at once without moving. Snapshots
 * taken at the script's pace miss that, so this is fed each MISSION_CURRENT, STATUSTEXT and
 * MISSION_ITEM_REACHED on the communications thread, as they come, and asked on the script thread.
 *
 * <ul>
 * <li>An item is <em>refused</em> when the vehicle passes it within {@link #WINDOW} of starting it,
 *     without reporting it reached, after a warning (or worse) while it was under way. A lost
 *     MISSION_ITEM_REACHED alone, or a warning during a long leg, is not a refusal.</li>
 * <li>A mission <em>started over</em> when its current item goes back before the mission is over,
 *     with no DO_JUMP in it and no jump of ours pending; ArduCopter's restart as it disarms after
 *     the landing that ends a mission, and the reset to 0 on a disarm, are not.</li>
 * </ul>
 */
final class ItemRefusals {

    /** How soon after starting an item the vehicle must pass it for the item to count as refused. */
    static final Duration WINDOW = Duration.ofSeconds(3);
    /** AP_Mission says "Mission: 3 WP" as it starts item 3, before the vehicle refuses or flies it. */
    private static final Pattern STARTED = Pattern.compile("^Mission: (\\d+) ");

    private final List<MissionItem> items;
    private final ItemNames names;
    private final String vehicle;
    private final int last;
    private final int lastNav;
    private final boolean jumpsInMission;
    /** Whether the mission ends on the ground, where ArduCopter restarts it as it disarms. */
    private final boolean landsAtEnd;
    private final BitSet reached = new BitSet();
    private boolean watching;
    /** The item under way, and since when (-1: not yet seen started). */
    private int under;
    private long underSince = -1;
    /** The first warning heard while {@link #under} was under way. */
    private String complaint;
    /** The item a jump of ours goes back to, until the vehicle shows it; -1 when none. */
    private int jumpTo = -1;
    private boolean over;
    private String verdict;

    ItemRefusals(FlightRules rules, List<MissionItem> items, String vehicle) {
        this.items = List.copyOf(items);
        this.names = new ItemNames(items);
        this.vehicle = vehicle;
        this.last = items.size() - 1;
        this.lastNav = MissionEnd.lastNavigation(items);
        this.landsAtEnd = rules.landsAfter(items.get(lastNav).command());
        this.jumpsInMission = items.stream().anyMatch(i -> i.command() == MAV_CMD.MAV_CMD_DO_JUMP);
    }

    /** The mission is about to start at item 1 (before AUTO): from now on the vehicle's words count. Once only. */
    synchronized void begin() {
        if (!watching) {
            watching = true;
            under = 1;
        }
    }

    synchronized void reached(int seq) {
        if (seq >= 0) {
            reached.set(seq);
        }
    }

    /** MISSION_CURRENT. */
    synchronized void current(int seq, int missionState, long now) {
        if (!watching || verdict != null || over) {
            return;
        }
        if (missionState == MISSION_STATE.MISSION_STATE_COMPLETE) {
            checkPassed(now);
            over = true;
            return;
        }
        if (seq == under && underSince < 0 && missionState == MISSION_STATE.MISSION_STATE_ACTIVE) {
            underSince = now;
        }
        moveTo(seq, now);
    }

    /** STATUSTEXT: an item started, or a warning about the item under way. */
    synchronized void text(int severity, String text, long now) {
        if (!watching || verdict != null || over) {
            return;
        }
        Matcher started = STARTED.matcher(text);
        if (started.find()) {
            int seq = Integer.parseInt(started.group(1));
            if (seq <= last && isNavigation(seq)) {
                moveTo(seq, now);
                underSince = now;
            }
        } else if (severity <= MAV_SEVERITY.MAV_SEVERITY_WARNING && complaint == null) {
            complaint = text;
        }
    }

    /** Our MISSION_SET_CURRENT back to {@code item} (jumpToItem): the way back is ours, not a restart. */
    synchronized void jumped(int item) {
        jumpTo = item;
    }

    /** The refusal or restart found, as the mission's error; empty while there is none. */
    synchronized Optional<String> refusal() {
        return Optional.ofNullable(verdict);
    }

    private void moveTo(int seq, long now) {
        if (seq == under) {
            return;
        }
        if (seq > under) {
            checkPassed(now);
        } else if (seq >= 1 && !jumpsInMission && !(landsAtEnd && under >= lastNav) && !(jumpTo >= 0 && seq <= jumpTo)) {
            verdict = "vehicle " + vehicle + " started its mission over at item " + seq + " before finishing "
                    + item(under) + (complaint != null ? ", after '" + complaint + "'" : "")
                    + ": it is not flying the mission as uploaded";
            return;
        }
        if (jumpTo >= 0 && seq <= jumpTo) {
            jumpTo = -1;
        }
        if (seq < 1) {
            return;
        }
        under = seq;
        underSince = -1;
        complaint = null;
    }

    /** The item under way is passed: refused if quickly, unreached, after a warning. */
    private void checkPassed(long now) {
        boolean quick = underSince < 0 || now - underSince <= WINDOW.toNanos();
        if (under >= 1 && under <= last && isNavigation(under) && !reached.get(under) && complaint != null && quick) {
            verdict = "vehicle " + vehicle + " refused " + item(under) + ": '" + complaint + "'";
        }
    }

    private boolean isNavigation(int seq) {
        return items.get(seq).command() < MAV_CMD.MAV_CMD_NAV_LAST;
    }

    private String item(int seq) {
        return names.item(seq);
    }
}
