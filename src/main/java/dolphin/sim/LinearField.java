package dolphin.sim;

import dolphin.core.Position;

/**
 * A field that changes at a steady rate, e.g. gas or temperature: {@code base} at the reference
 * point, rising by {@code gradient} per metre towards {@code bearing} (degrees from north) and
 * falling as much away from it; level across that direction.
 */
public record LinearField(Position reference, double base, double gradient, double bearing) implements SimField {

    public LinearField {
        FieldChecks.onEarth("the reference point", reference);
        FieldChecks.finite("the base value", base);
        FieldChecks.finite("the gradient", gradient);
        FieldChecks.finite("the bearing", bearing);
    }

    @Override
    public double valueAt(Position p) {
        double[] ned = reference.displacementTo(p);
        double b = Math.toRadians(bearing);
        return base + gradient * (ned[0] * Math.cos(b) + ned[1] * Math.sin(b));
    }
}
