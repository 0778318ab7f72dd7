package dolphin.mission.model;

import java.time.Duration;
import java.util.Optional;

/**
 * How long a mission's flight may make no progress, and how long someone else may hold it, as its
 * script says ({@code stallLimit}, {@code takeoverTimeout} in {@code mission { }}); each null
 * where the script leaves it to the run's settings (docs/failures.md).
 */
public record FlightLimits(Duration stallLimit, Duration takeoverTimeout) {

    public static final FlightLimits RUN = new FlightLimits(null, null);

    public Optional<Duration> stall() {
        return Optional.ofNullable(stallLimit);
    }

    public Optional<Duration> takeover() {
        return Optional.ofNullable(takeoverTimeout);
    }

    public FlightLimits withStallLimit(Duration limit) {
        return new FlightLimits(limit, takeoverTimeout);
    }

    public FlightLimits withTakeoverTimeout(Duration timeout) {
        return new FlightLimits(stallLimit, timeout);
    }
}
