package dolphin.mission.flight;

import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.enums.MAV_LANDED_STATE;
import dolphin.mavlink.VehicleState;
import java.util.Locale;
import java.util.Optional;

/**
 * The faults that end a mission while it flies, whatever the family (docs/failures.md): the vehicle
 * reports an emergency (a STATUSTEXT at EMERGENCY, ALERT or CRITICAL: ArduPilot's thrust loss,
 * crash, EKF and failsafe messages), is disarmed, is on the ground with items left, or rebooted.
 * Each but the reboot is judged {@link VehicleWords#WAIT_NANOS} after its first sign, so that the
 * error quotes what the vehicle said around it; a disarm also waits for the next position, up to 4 s,
 * which may show a reboot. Fed one snapshot at a time with the clock's time.
 */
final class FlightAlarms {

    /** Higher than this above home, a flying vehicle has been airborne: a later landed state ON_GROUND is news. */
    private static final double AIRBORNE_METRES = 5;
    /**
     * How long a disarm may wait for the vehicle's next position, whose time since boot tells a reboot: a
     * rebooted ArduPilot streams nothing until the ground station asks again, 3 s into the silence.
     */
    private static final long DISARM_WAIT_NANOS = 4_000_000_000L;
    /** This close to home's height, a flying vehicle is down, whatever its landed state says. */
    private static final double DOWN_METRES = 0.5;

    private final FlightRules rules;
    private final ItemNames names;
    private final String vehicle;
    private final VehicleWords words;
    private final long since;
    private final int rebootsBefore;
    private boolean sawArmed;
    private boolean airborne;
    private long disarmedAt = -1;
    private long groundedAt = -1;

    /**
     * @param since the clock time the mission started (AUTO asked): texts from then on count
     * @param rebootsBefore the vehicle's {@link VehicleState#reboots()} then
     */
    FlightAlarms(FlightRules rules, ItemNames names, String vehicle, VehicleWords words, long since, int rebootsBefore) {
        this.rules = rules;
        this.names = names;
        this.vehicle = vehicle;
        this.words = words;
        this.since = since;
        this.rebootsBefore = rebootsBefore;
    }

    /**
     * One look at the vehicle: the error, or empty while none is due.
     *
     * @param current the item under way
     * @param mayBeDown whether the vehicle may be on the ground: someone else holds it (a pilot may land
     *        it), or the mission's last landing has begun (ArduCopter restarts its mission on the ground
     *        before it disarms)
     */
    Optional<String> judge(VehicleState s, int current, boolean mayBeDown, long now) {
        String item = names.item(current);
        if (s.reboots() > rebootsBefore) {
            return Optional.of(String.format(Locale.ROOT, "vehicle %s rebooted during %s: its time since boot went back to"
                    + " %.1f s%s", vehicle, item, s.bootMillis() / 1000.0, ItemNames.where(s)));
        }
        var severe = words.firstSevere(since);
        if (severe.isPresent() && now >= severe.get().at() + VehicleWords.WAIT_NANOS) {
            return Optional.of("vehicle " + vehicle + " reported " + words.quote(severe.get().at(), now) + " during " + item
                    + ItemNames.whereWithout(s));
        }
        sawArmed |= s.armed();
        disarmedAt = sawArmed && !s.armed() ? first(disarmedAt, now) : -1;
        if (disarmedAt >= 0 && now >= disarmedAt + VehicleWords.WAIT_NANOS
                && (s.positionNanos() > disarmedAt || now >= disarmedAt + DISARM_WAIT_NANOS)) {
            return Optional.of("vehicle " + vehicle + " disarmed during " + item + saying(disarmedAt, now, s));
        }
        airborne |= rules.flies() && (s.landedState() == MAV_LANDED_STATE.MAV_LANDED_STATE_IN_AIR
                || s.position() != null && s.relativeAlt() > AIRBORNE_METRES);
        groundedAt = !mayBeDown && airborne && s.armed() && down(s) && !landingOrTakeoff(current) ? first(groundedAt, now) : -1;
        if (groundedAt >= 0 && now >= groundedAt + VehicleWords.WAIT_NANOS) {
            return Optional.of("vehicle " + vehicle + " is on the ground during " + item + " with items left"
                    + saying(groundedAt, now, s));
        }
        return Optional.empty();
    }

    /**
     * On the ground by its landed state, or by its height: a copter with a dead motor lies on the ground
     * reporting IN_AIR (SITL, copter-fault-motor), and no item but a landing is lower than home plus 2 m.
     */
    private static boolean down(VehicleState s) {
        return s.landedState() == MAV_LANDED_STATE.MAV_LANDED_STATE_ON_GROUND || s.position() != null && s.relativeAlt() < DOWN_METRES;
    }

    /** Items that start or end on the ground. */
    private boolean landingOrTakeoff(int seq) {
        int command = names.get(seq).command();
        return rules.landsAfter(command) || command == MAV_CMD.MAV_CMD_NAV_LAND || command == MAV_CMD.MAV_CMD_NAV_VTOL_LAND
                || command == MAV_CMD.MAV_CMD_NAV_TAKEOFF || command == MAV_CMD.MAV_CMD_NAV_VTOL_TAKEOFF;
    }

    private String saying(long sign, long now, VehicleState s) {
        String said = words.quote(sign, now);
        return said.isEmpty() ? ItemNames.where(s) : ", saying " + said + ItemNames.whereWithout(s);
    }

    private static long first(long seen, long now) {
        return seen >= 0 ? seen : now;
    }
}
