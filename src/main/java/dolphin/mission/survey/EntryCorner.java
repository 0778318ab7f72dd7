package dolphin.mission.survey;

import java.util.Locale;

/**
 * Where a survey starts: QGroundControl's entryLocation / EntryPoint 0..3 is {@link #ordinal()}.
 * The names are only names; the real corner depends on the angle (docs/qgc-surveys.md §2.3).
 */
public enum EntryCorner {
    TOP_LEFT, TOP_RIGHT, BOTTOM_LEFT, BOTTOM_RIGHT;

    /** {@code topLeft}, {@code top left}, {@code TOP_LEFT}, {@code top-left}, case aside. */
    public static EntryCorner parse(String s) {
        String n = s == null ? "" : s.replaceAll("[\\s_-]", "").toLowerCase(Locale.ROOT);
        for (EntryCorner c : values()) {
            if (c.name().replace("_", "").toLowerCase(Locale.ROOT).equals(n)) {
                return c;
            }
        }
        throw new IllegalArgumentException("unknown entry corner '" + s
                + "': expected topLeft, topRight, bottomLeft or bottomRight");
    }

    /** QGC's entry number, 0..3. */
    public static EntryCorner ofQgc(int entry) {
        if (entry < 0 || entry > 3) {
            throw new IllegalArgumentException("a QGroundControl entry location is 0 to 3, got " + entry);
        }
        return values()[entry];
    }

    boolean reversesPoints() {
        return this == BOTTOM_LEFT || this == BOTTOM_RIGHT;
    }

    boolean reversesOrder() {
        return this == TOP_RIGHT || this == BOTTOM_RIGHT;
    }
}
