package dolphin.mission.model;

/**
 * The direction of a survey: the first word says whether the first pass flies north
 * or south, the second whether the passes step east or west.
 */
public enum SurveyDirection {
    NORTH_EAST(1, 1),
    NORTH_WEST(1, -1),
    SOUTH_EAST(-1, 1),
    SOUTH_WEST(-1, -1);

    private final int northSign;
    private final int eastSign;

    SurveyDirection(int northSign, int eastSign) {
        this.northSign = northSign;
        this.eastSign = eastSign;
    }

    /** +1 when the first pass flies north, -1 when it flies south. */
    public int northSign() {
        return northSign;
    }

    /** +1 when the passes step east, -1 when they step west. */
    public int eastSign() {
        return eastSign;
    }

    /** The direction with exactly this name (case matters, as in the original). */
    public static SurveyDirection parse(String name) {
        for (SurveyDirection d : values()) {
            if (d.name().equals(name)) {
                return d;
            }
        }
        throw new IllegalArgumentException("unknown direction '" + name
                + "': expected NORTH_EAST, NORTH_WEST, SOUTH_EAST or SOUTH_WEST");
    }
}
