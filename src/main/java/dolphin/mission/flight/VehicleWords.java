package dolphin.mission.flight;

import com.MAVLink.enums.MAV_SEVERITY;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.stream.Collectors;

/**
 * What a vehicle said while its mission flew (STATUSTEXT), with the severity and the clock time each
 * text arrived: the words an error quotes. A failsafe explains itself in a text sent a moment after
 * it changes the mode ("EKF Failsafe: changed to Land Mode"), so errors are judged a moment after the
 * first sign and quote what came around it (docs/failures.md). Fed on the communications thread,
 * read on the script thread.
 */
final class VehicleWords {

    /** One text: its MAV_SEVERITY and when it arrived, in clock nanoseconds. */
    record Said(int severity, String text, long at) {

        /**
         * EMERGENCY, ALERT or CRITICAL: ArduPilot's thrust loss, crash, EKF and failsafe messages; but
         * not its internal errors ("Internal Errors 0x20000000"), a flag of a bug caught in the
         * firmware, which flies on: ArduRover SITL says it as every mission starts (docs/failures.md).
         */
        boolean severe() {
            return severity <= MAV_SEVERITY.MAV_SEVERITY_CRITICAL && !text.startsWith(INTERNAL_ERRORS);
        }

        /** A warning or worse; ArduPilot's chatter ("Mission: 3 WP", "EKF3 IMU0 is using GPS") is below. */
        boolean warning() {
            return severity <= MAV_SEVERITY.MAV_SEVERITY_WARNING;
        }

        /** A failsafe's words ("EKF Failsafe: changed to Land Mode", "Radio Failsafe", "GCS Failsafe"). */
        boolean failsafe() {
            return warning() && text.toLowerCase(Locale.ROOT).contains("failsafe");
        }
    }

    /** AP_InternalError's report (GCS_MAVLINK): "Internal Errors 0x%x". */
    static final String INTERNAL_ERRORS = "Internal Errors ";
    /** How long before the first sign a text still explains it. */
    static final long BEFORE_NANOS = 3_000_000_000L;
    /** How long after the first sign the executor waits for the vehicle's explanation before it fails the mission. */
    static final long WAIT_NANOS = 2_000_000_000L;
    private static final int KEPT = 64;

    private final Deque<Said> said = new ArrayDeque<>();

    synchronized void heard(int severity, String text, long now) {
        said.addLast(new Said(severity, text, now));
        if (said.size() > KEPT) {
            said.removeFirst();
        }
    }

    /** The first severe text at or after {@code since}. */
    synchronized Optional<Said> firstSevere(long since) {
        return said.stream().filter(s -> s.at() >= since && s.severe()).findFirst();
    }

    /** Whether a failsafe spoke around a sign at {@code sign}, up to {@code now}. */
    synchronized boolean failsafeAround(long sign, long now) {
        return around(sign, now).stream().anyMatch(Said::failsafe);
    }

    /**
     * The warnings and worse said around a sign at {@code sign}, up to {@code now}, quoted and joined
     * ("'EKF variance', 'EKF Failsafe: changed to Land Mode'"); empty when there were none.
     */
    synchronized String quote(long sign, long now) {
        return quoted(around(sign, now));
    }

    /** The warnings and worse said from {@code since} up to {@code now}, quoted and joined as {@link #quote}. */
    synchronized String quoteSince(long since, long now) {
        return quoted(said.stream().filter(s -> s.at() >= since && s.at() <= now).toList());
    }

    private static String quoted(List<Said> texts) {
        return texts.stream().filter(Said::warning).map(s -> "'" + s.text() + "'").distinct().collect(Collectors.joining(", "));
    }

    private List<Said> around(long sign, long now) {
        return said.stream().filter(s -> s.at() >= sign - BEFORE_NANOS && s.at() <= now).toList();
    }
}
