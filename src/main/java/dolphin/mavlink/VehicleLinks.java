package dolphin.mavlink;

import dolphin.mavlink.codec.Frame;
import dolphin.mavlink.link.Link;
import java.net.SocketAddress;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.concurrent.CopyOnWriteArrayList;

/**
 * The links one vehicle is heard on, and the one its sends go through, its path (docs/mavlink.md,
 * "One vehicle on two links"). The path is the link the vehicle was discovered on until it has been
 * silent for {@link #SILENT}; then it is the link that brings the vehicle's next frame. So it moves
 * only when it must, never back and forth between two working links. The communications thread
 * changes it; any thread reads it.
 */
final class VehicleLinks {

    /** Six of each 4 Hz message we ask for and a heartbeat and a half: no working link is that quiet. */
    static final long SILENT = 1_500_000_000L;

    /** One link of the vehicle: where it is heard on it, when last, and how many of its frames were duplicates. */
    static final class Traffic {
        private final Link link;
        private volatile SocketAddress address;
        private volatile long heardNanos;
        private volatile long duplicates;

        private Traffic(Link link, SocketAddress address, long now) {
            this.link = link;
            this.address = address;
            this.heardNanos = now;
        }

        Link link() {
            return link;
        }

        /** Where replies on this link go: where the vehicle was last heard on it. */
        SocketAddress address() {
            return address;
        }

        /** Frames this link brought after another link had. */
        long duplicates() {
            return duplicates;
        }
    }

    private final List<Traffic> links = new CopyOnWriteArrayList<>();
    private volatile Traffic path;
    /** Read only once the vehicle has several links; the communications thread's. */
    private RecentFrames recent = new RecentFrames();

    VehicleLinks(Link link, SocketAddress address, long now) {
        path = new Traffic(link, address, now);
        links.add(path);
    }

    /**
     * Another link brings the same vehicle; the path stays where it is. {@code seen} are the vehicle's
     * frames processed while they were told apart, so the new link's late copies of them are known as
     * duplicates too.
     */
    void join(Link link, SocketAddress address, long now, RecentFrames seen) {
        links.add(new Traffic(link, address, now));
        recent = seen;
    }

    /** Every link of the vehicle, in the order it was heard on them. */
    List<Traffic> all() {
        return List.copyOf(links);
    }

    /** The link the vehicle was discovered on. */
    Link first() {
        return links.get(0).link;
    }

    Traffic path() {
        return path;
    }

    /**
     * A sign of the vehicle's life came on {@code link} from {@code peer} (a message from its autopilot,
     * {@link Contact#isSignOfLife}), first or again. The change of path, when this makes one.
     */
    Optional<String> heard(Link link, SocketAddress peer, long now) {
        Traffic on = traffic(link);
        on.address = peer;
        on.heardNanos = now;
        Traffic from = path;
        long silence = now - from.heardNanos;
        if (on == from || silence < SILENT) {
            return Optional.empty();
        }
        path = on;
        return Optional.of(String.format(Locale.ROOT, "now through %s: %s silent %.1f s", link, from.link, silence / 1e9));
    }

    /**
     * Whether another of the vehicle's links brought this frame in the last {@link RecentFrames#WINDOW}:
     * then it is counted as that link's duplicate and must not be processed again.
     */
    boolean duplicate(Link link, Frame frame, long now) {
        if (links.size() > 1 && recent.firstLink(frame, link.index(), now) >= 0) {
            traffic(link).duplicates++;
            return true;
        }
        return false;
    }

    private Traffic traffic(Link link) {
        for (Traffic t : links) {
            if (t.link == link) {
                return t;
            }
        }
        throw new IllegalArgumentException("vehicle not heard on " + link);
    }
}
