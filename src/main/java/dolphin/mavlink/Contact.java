package dolphin.mavlink;

import com.MAVLink.ardupilotmega.msg_radio;
import com.MAVLink.common.msg_radio_status;
import dolphin.core.Clock;
import dolphin.core.VehicleEvent;
import java.time.Duration;
import java.util.Optional;

/**
 * Whether a vehicle is heard (docs/decisions.md, "Contact"): silent once nothing has come from its
 * autopilot for {@link #SILENCE}, heard again at its next message; each change is one
 * {@link VehicleEvent}. Independent of the connection timeout, which goes on deciding when a vehicle
 * is lost. {@link #heard} and {@link #check} run on the communications thread; {@link #silence} on any.
 */
final class Contact {

    /** Three heartbeats and some fifty stream messages missed: no ordinary loss, yet long before a timeout. */
    private static final Duration SILENCE = Duration.ofSeconds(3);
    private static final long NOT_SILENT = Long.MIN_VALUE;

    private final String vehicle;
    private final Clock clock;
    /** The last sign of life; the communications thread's own. */
    private long heardNanos;
    /** The last sign of life before the silence, while the vehicle is silent: one field, so readers see both at once. */
    private volatile long silentFrom = NOT_SILENT;

    Contact(String vehicle, Clock clock) {
        this.vehicle = vehicle;
        this.clock = clock;
        this.heardNanos = clock.nanoTime();
    }

    /**
     * Whether a message from the autopilot is a sign of the vehicle's life. A telemetry radio's own
     * status is not: it keeps coming while the vehicle is gone, as system 51 component 68 from a SiK
     * radio, or relayed under other ids by routers.
     */
    static boolean isSignOfLife(int msgid) {
        return msgid != msg_radio_status.MAVLINK_MSG_ID_RADIO_STATUS && msgid != msg_radio.MAVLINK_MSG_ID_RADIO;
    }

    /** A message from the autopilot came; the end of a silence, if it ends one. */
    Optional<VehicleEvent> heard(int msgid) {
        if (!isSignOfLife(msgid)) {
            return Optional.empty();
        }
        long now = clock.nanoTime();
        heardNanos = now;
        long from = silentFrom;
        if (from == NOT_SILENT) {
            return Optional.empty();
        }
        silentFrom = NOT_SILENT;
        return Optional.of(event(VehicleEvent.EventKind.CONTACT_AGAIN, "contact again after " + wholeSeconds(now - from) + " s"));
    }

    /** Called every tick: the start of a silence, once, when the vehicle has not been heard for {@link #SILENCE}. */
    Optional<VehicleEvent> check() {
        long silence = clock.nanoTime() - heardNanos;
        if (silentFrom != NOT_SILENT || silence < SILENCE.toNanos()) {
            return Optional.empty();
        }
        silentFrom = heardNanos;
        return Optional.of(event(VehicleEvent.EventKind.CONTACT_LOST, "no contact for " + wholeSeconds(silence) + " s"));
    }

    /** How long the vehicle has been silent, since its last sign of life; empty while it is heard. */
    Optional<Duration> silence() {
        long from = silentFrom;
        return from == NOT_SILENT ? Optional.empty() : Optional.of(Duration.ofNanos(clock.nanoTime() - from));
    }

    private VehicleEvent event(VehicleEvent.EventKind kind, String text) {
        return new VehicleEvent(vehicle, kind, text, clock.seconds());
    }

    /** Whole seconds, rounded down as a counter shows them: the table's last "no contact 30 s" comes before "after 30 s". */
    private static long wholeSeconds(long nanos) {
        return nanos / 1_000_000_000L;
    }
}
