package dolphin.mission.flight;

import dolphin.mavlink.VehicleState;
import java.time.Duration;
import java.util.List;

/**
 * Tells a pilot's pause from an abort while a mission flies (docs/failures.md, "A pilot's pause").
 * Someone else's change of mode out of AUTO is judged {@link VehicleWords#WAIT_NANOS} after it, once
 * the vehicle has said why:
 *
 * <ul>
 * <li>to one of the family's {@link FlightRules#takeoverModes() takeover modes}, with no failsafe
 *     speaking, it is a <em>takeover</em>: the mission pauses, and goes on when the vehicle is back in
 *     AUTO (ArduPilot resumes at its current item); not back within the takeover timeout, it fails;</li>
 * <li>to any other mode (RTL, LAND, a failsafe's choice, the fence's action) it fails, quoting the
 *     vehicle's words;</li>
 * <li>at the last navigation item, the mission's own end may still follow within the grace period:
 *     ArduPlane switches itself to RTL just before it reports its last item reached.</li>
 * </ul>
 * Fed one snapshot at a time with the clock's time, so it is tested without vehicles.
 */
final class Takeovers {

    /**
     * What one look found: whose hand the vehicle is in; {@code text} says it, for the error as the script
     * reads it, for a takeover or a hand-back as a vehicle event (without the vehicle's name).
     */
    record Look(Hand hand, String text) {
        enum Hand { FLYING, LEFT, TAKEN_OVER, PAUSED, HANDED_BACK, FAILED }

        static final Look FLYING = new Look(Hand.FLYING, null);
        static final Look LEFT = new Look(Hand.LEFT, null);
        static final Look PAUSED = new Look(Hand.PAUSED, null);

    }

    /** How many of the vehicle's last texts may tell of a fence breach. */
    private static final int RECENT_TEXTS = 5;
    private static final long SECOND = 1_000_000_000L;

    private final FlightRules rules;
    private final ItemNames names;
    private final String vehicle;
    private final VehicleWords words;
    private final int lastNav;
    private final Duration grace;
    private final Duration timeout;
    private boolean sawAuto;
    private AutoPhase phase = new InAuto();

    /**
     * @param grace how long after leaving AUTO at the last navigation item the mission's end may still come
     * @param timeout how long a takeover may last before the mission fails
     */
    Takeovers(FlightRules rules, ItemNames names, String vehicle, VehicleWords words, int lastNav, Duration grace,
              Duration timeout) {
        this.rules = rules;
        this.names = names;
        this.vehicle = vehicle;
        this.words = words;
        this.lastNav = lastNav;
        this.grace = grace;
        this.timeout = timeout;
    }

    /** Whether the mission is paused by someone else's hand now. */
    boolean paused() {
        return phase instanceof Paused;
    }

    /**
     * One look at the vehicle.
     *
     * @param auto whether the vehicle is in AUTO
     * @param current the item under way
     */
    Look look(VehicleState s, boolean auto, int current, long now) {
        if (auto) {
            sawAuto = true;
            AutoPhase was = phase;
            phase = new InAuto();
            return was instanceof Paused p ? new Look(Look.Hand.HANDED_BACK, "back in " + rules.missionMode() + " after " + seconds(now - p.since)
                    + " s: " + names.item(current)) : Look.FLYING;
        }
        if (!sawAuto) {
            return Look.FLYING;
        }
        return phase.look(s, current, now);
    }

    private abstract static class AutoPhase {
        abstract Look look(VehicleState s, int current, long now);
    }

    /** Flying the mission in AUTO; a change of mode starts a {@link Left}. */
    private final class InAuto extends AutoPhase {
        @Override
        Look look(VehicleState s, int current, long now) {
            phase = new Left(s.modeName(), now, -1);
            return phase.look(s, current, now);
        }
    }

    /**
     * Out of AUTO, waiting for the vehicle's words (and, at the last item, for the mission's end).
     * {@code pausedSince} is when the takeover began, when this change came during one; -1 otherwise.
     */
    private final class Left extends AutoPhase {
        private final String mode;
        private final long since;
        private final long pausedSince;

        Left(String mode, long since, long pausedSince) {
            this.mode = mode;
            this.since = since;
            this.pausedSince = pausedSince;
        }

        @Override
        Look look(VehicleState s, int current, long now) {
            if (!s.modeName().equals(mode)) {
                phase = new Left(s.modeName(), now, pausedSince);
                return Look.LEFT;
            }
            long waited = now - since;
            if (waited < VehicleWords.WAIT_NANOS || current >= lastNav && waited <= grace.toNanos()) {
                return Look.LEFT;
            }
            String item = names.item(current);
            if (fenceBreached(s)) {
                return new Look(Look.Hand.FAILED, "vehicle " + vehicle + " breached its fence during " + item
                        + " and left " + rules.missionMode() + " for " + mode + " (its fence action)" + ItemNames.where(s));
            }
            String said = words.quote(since, now);
            if (rules.takeoverModes().contains(mode) && !words.failsafeAround(since, now)) {
                if (pausedSince >= 0) {
                    phase = new Paused(pausedSince);
                    return Look.PAUSED;
                }
                phase = new Paused(since);
                return new Look(Look.Hand.TAKEN_OVER, "taken over: " + mode + " during " + item);
            }
            return new Look(Look.Hand.FAILED, "vehicle " + vehicle + " left " + rules.missionMode() + " for " + mode + " during " + item
                    + ", before the mission ended" + (said.isEmpty() ? ItemNames.where(s)
                    : ", saying " + said + ItemNames.whereWithout(s)));
        }
    }

    /** Held or flown by someone else in one of the takeover modes, since {@code since}. */
    private final class Paused extends AutoPhase {
        private final long since;

        Paused(long since) {
            this.since = since;
        }

        @Override
        Look look(VehicleState s, int current, long now) {
            if (!rules.takeoverModes().contains(s.modeName())) {
                phase = new Left(s.modeName(), now, since);
                return Look.LEFT;
            }
            if (now - since > timeout.toNanos()) {
                return new Look(Look.Hand.FAILED, "vehicle " + vehicle + " taken over: " + s.modeName() + " for "
                        + seconds(now - since) + " s during " + names.item(current) + ", not handed back to " + rules.missionMode() + " within"
                        + " the takeover timeout of " + timeout.toSeconds() + " s" + ItemNames.where(s));
            }
            return Look.PAUSED;
        }
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

    private static long seconds(long nanos) {
        return Math.round(nanos / (double) SECOND);
    }
}
