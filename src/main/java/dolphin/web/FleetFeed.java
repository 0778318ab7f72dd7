package dolphin.web;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Supplier;

/**
 * Turns samples of the fleet, its links and the program into {@link Frame}s, a few times a second, on the
 * sampler thread. A frame keeps each vehicle's, link's, mission's and the trees' JSON with the number of
 * the frame that last changed it, so a viewer that has frame N is sent only what changed after N,
 * however many frames it missed. Tracks (each vehicle's path, thinned as it grows) are sent whole
 * only in a snapshot; a viewer extends them from the positions that follow.
 */
final class FleetFeed {

    /** A piece of JSON and the frame that last changed it. */
    record Stamped(String json, long frame) {
    }

    /** What the viewers are sent, as of one sample; immutable. */
    record FeedFrame(long number, double time, Map<String, Stamped> vehicles, Map<String, Stamped> links, Map<String, Stamped> missions,
                     Stamped executes) {
    }

    private final Supplier<List<VehicleSample>> fleet;
    private final Supplier<List<LinkView>> linkViews;
    private final TaskBoard board;
    private final Map<String, VehicleView> views = new HashMap<>();
    private final Map<String, Stamped> vehicles = new LinkedHashMap<>();
    private final Map<String, LinkView> linksShown = new HashMap<>();
    private final Map<String, Stamped> links = new LinkedHashMap<>();
    private final Map<String, Stamped> missions = new LinkedHashMap<>();
    private final Map<String, Object> missionKeys = new HashMap<>();
    private final Map<String, Track> tracks = new LinkedHashMap<>();
    private long number;
    private long boardVersion = -1;
    private Stamped executes = new Stamped("[]", 0);
    private volatile FeedFrame latest = new FeedFrame(0, 0, Map.of(), Map.of(), Map.of(), executes);

    /**
     * @param links every link's view: apart from the vehicles, which name theirs, so a link's rates
     *              changing each second send one link again, not every vehicle on it
     */
    FleetFeed(Supplier<List<VehicleSample>> fleet, Supplier<List<LinkView>> links, TaskBoard board) {
        this.fleet = fleet;
        this.linkViews = links;
        this.board = board;
    }

    /** Samples the fleet and the program into the next frame (sampler thread). */
    FeedFrame sample(double time) {
        List<VehicleSample> samples = fleet.get();
        List<LinkView> linkSamples = linkViews.get();
        synchronized (this) {
            long n = ++number;
            for (VehicleSample s : samples) {
                VehicleView v = s.view();
                if (!v.equals(views.put(v.id(), v))) {
                    vehicles.put(v.id(), new Stamped(v.json(), n));
                }
                if (v.position() != null) {
                    tracks.computeIfAbsent(v.id(), id -> new Track()).add(v.position());
                }
                if (s.missionKey() != null && s.missionKey() != missionKeys.get(v.id())) {
                    missionKeys.put(v.id(), s.missionKey());
                    String drawn = s.missionGeoJson().get();
                    if (drawn != null) {
                        missions.put(v.id(), new Stamped(drawn, n));
                    }
                }
            }
            for (LinkView l : linkSamples) {
                if (!l.equals(linksShown.put(l.name(), l))) {
                    links.put(l.name(), new Stamped(l.json(), n));
                }
            }
            long version = board.version();
            if (version != boardVersion) {
                boardVersion = version;
                executes = new Stamped(Json.write(board.json()), n);
            }
            latest = new FeedFrame(n, time, Map.copyOf(vehicles), Map.copyOf(links), Map.copyOf(missions), executes);
            return latest;
        }
    }

    FeedFrame latest() {
        return latest;
    }

    /** Every vehicle's track as JSON: {"1": [[lat, lon], ...], ...}. */
    synchronized String tracksJson() {
        Map<String, Object> all = new LinkedHashMap<>();
        tracks.forEach((id, t) -> all.put(id, t.points()));
        return Json.write(all);
    }

    /**
     * The JSON of what changed in {@code frame} after frame {@code after} (0: everything), with the
     * log entries {@code log} and {@code extra} members (raw JSON, each starting with a comma).
     */
    static String update(FeedFrame frame, long after, EventLog.Since log, String extra) {
        StringBuilder b = new StringBuilder(256);
        b.append("{\"frame\":").append(frame.number()).append(",\"time\":").append(Json.tenths(frame.time()));
        b.append(",\"vehicles\":[");
        appendChanged(b, frame.vehicles(), after, false);
        b.append("],\"links\":{");
        appendChanged(b, frame.links(), after, true);
        b.append("},\"missions\":{");
        appendChanged(b, frame.missions(), after, true);
        b.append('}');
        if (frame.executes().frame() > after || after == 0) {
            b.append(",\"executes\":").append(frame.executes().json());
        }
        b.append(",\"log\":").append(Json.write(logJson(log.entries())));
        if (log.lost() > 0) {
            b.append(",\"logLost\":").append(log.lost());
        }
        b.append(extra);
        return b.append('}').toString();
    }

    private static void appendChanged(StringBuilder b, Map<String, Stamped> items, long after, boolean keyed) {
        boolean first = true;
        for (Map.Entry<String, Stamped> e : items.entrySet()) {
            if (e.getValue().frame() <= after) {
                continue;
            }
            if (!first) {
                b.append(',');
            }
            first = false;
            if (keyed) {
                b.append(Json.write(e.getKey())).append(':');
            }
            b.append(e.getValue().json());
        }
    }

    private static List<Object> logJson(List<EventLog.Entry> entries) {
        List<Object> list = new ArrayList<>(entries.size());
        for (EventLog.Entry e : entries) {
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("seq", e.seq());
            m.put("time", Json.tenths(e.time()));
            m.put("kind", e.kind());
            m.put("vehicle", e.vehicle());
            m.put("text", e.text());
            list.add(m);
        }
        return list;
    }
}
