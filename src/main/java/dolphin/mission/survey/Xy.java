package dolphin.mission.survey;

/** A point of the local plane: x metres east, y metres north of the projection origin. */
record Xy(double x, double y) {

    Xy plus(double dx, double dy) {
        return new Xy(x + dx, y + dy);
    }

    double distanceTo(Xy o) {
        return Math.hypot(x - o.x, y - o.y);
    }
}
