package dolphin.mission.file;

import dolphin.mission.model.Mission;
import dolphin.mission.model.MissionItem;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.stream.Collectors;

/** The mission file formats, by the name the command line uses ({@code --export plan|waypoints|geojson}). */
public enum MissionFormat {

    /** QGroundControl's JSON plan. */
    PLAN("plan", PlanFile.EXTENSION),
    /** QGC WPL 110: Mission Planner, MAVProxy, pymavlink. */
    WAYPOINTS("waypoints", WaypointsFile.EXTENSION),
    /** GeoJSON for maps; export only. */
    GEOJSON("geojson", GeoJsonFile.EXTENSION);

    private final String id;
    private final String extension;

    MissionFormat(String id, String extension) {
        this.id = id;
        this.extension = extension;
    }

    public String id() {
        return id;
    }

    /** The file name extension, with its dot. */
    public String extension() {
        return extension;
    }

    /** The file's text for a mission's items, item 0 the home (as {@link Mission#items} gives them). */
    public String write(String name, List<MissionItem> items) {
        return write(name, MissionFile.of(items));
    }

    /**
     * The file's text for a mission with its fence and rally points. A QGC WPL file holds one kind
     * of items: this is the mission's, {@link WaypointsFile#writeItems} writes the fence's and rally points'.
     */
    public String write(String name, MissionFile file) {
        return switch (this) {
            case PLAN -> PlanFile.write(file);
            case WAYPOINTS -> WaypointsFile.write(file.mission());
            case GEOJSON -> GeoJsonFile.write(name, file);
        };
    }

    /** True for the formats {@link #read} can import. */
    public boolean canRead() {
        return this != GEOJSON;
    }

    /**
     * The items of a file's text, item 0 the home.
     *
     * @throws IllegalArgumentException for a text that is not such a file
     * @throws UnsupportedOperationException for GeoJSON, which is export only
     */
    public List<MissionItem> read(String text) {
        return switch (this) {
            case PLAN -> PlanFile.read(text);
            case WAYPOINTS -> WaypointsFile.read(text);
            case GEOJSON -> throw new UnsupportedOperationException("GeoJSON is export only: it does not keep every"
                    + " item's parameters and frame");
        };
    }

    /** The format named {@code id} (case-insensitive). */
    public static MissionFormat parse(String id) {
        for (MissionFormat f : values()) {
            if (f.id.equalsIgnoreCase(id.strip())) {
                return f;
            }
        }
        throw new IllegalArgumentException("unknown format '" + id + "': expected one of " + names());
    }

    /** "plan, waypoints, geojson". */
    public static String names() {
        return Arrays.stream(values()).map(MissionFormat::id).collect(Collectors.joining(", "));
    }

    @Override
    public String toString() {
        return id.toLowerCase(Locale.ROOT);
    }
}
