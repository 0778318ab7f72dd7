package dolphin.mission.survey;

/** Numbers in messages: whole numbers without ".0". */
final class Numbers {

    private Numbers() {
    }

    static String format(double v) {
        return v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v) : Double.toString(v);
    }
}
