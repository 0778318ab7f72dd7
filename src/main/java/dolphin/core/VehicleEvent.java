package dolphin.core;

import java.util.Objects;

/**
 * Something that happened to a vehicle that a person watching the fleet should hear of, whether or
 * not a task runs on it: contact lost or regained, a pilot taking it over or handing it back, a
 * warning that it makes no progress, a link it is heard on or sent to through. Platforms raise them;
 * an engine hands them to its listeners ({@link RuntimeListener#vehicleEvent}) on the thread that
 * raised them (docs/embedding.md).
 *
 * @param vehicle the vehicle's node id, e.g. "1" or "1@2"
 * @param text what happened as a person reads it, without the vehicle: "no contact for 3 s"
 * @param time when, in seconds of the run's {@link Clock}
 */
public record VehicleEvent(String vehicle, EventKind kind, String text, double time) {

    /** What happened. Not named {@code Kind}: that simple name is {@link TaskEvent.Kind}'s (docs/architecture.md, "Layers"). */
    public enum EventKind {
        /** Nothing heard from the vehicle for a few seconds (its connection timeout has not ended yet). */
        CONTACT_LOST,
        /** The vehicle is heard again after a {@link #CONTACT_LOST}. */
        CONTACT_AGAIN,
        /** A pilot took the vehicle out of the mode its task flies it in. */
        TAKEN_OVER,
        /** The pilot gave the vehicle back to its task. */
        HANDED_BACK,
        /** A warning: the vehicle makes no progress on its task. */
        STALLING,
        /** The vehicle is heard on one more link, or what is sent to it goes through another of its links. */
        LINK_CHANGED
    }

    public VehicleEvent {
        Objects.requireNonNull(vehicle, "vehicle");
        Objects.requireNonNull(kind, "kind");
        Objects.requireNonNull(text, "text");
    }

    /** The event as one line of prose, naming the vehicle: "vehicle 1: no contact for 3 s". */
    public String line() {
        return "vehicle " + vehicle + ": " + text;
    }
}
