package dolphin.core;

/** A sphere: every position within {@code radius} metres (ECEF straight line) of {@code center}. */
public record Area(Position center, double radius) {

    public boolean contains(Position p) {
        return p != null && center.distanceTo(p) <= radius;
    }

    @Override
    public String toString() {
        return center + " ^ " + radius + " m";
    }
}
