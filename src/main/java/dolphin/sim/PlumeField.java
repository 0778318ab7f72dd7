package dolphin.sim;

import dolphin.core.Position;

/**
 * A plume, e.g. of smoke: {@code peak} at the centre, falling linearly to nothing at {@code radius}
 * metres and beyond, so any positive threshold means "inside the radius"; {@code background} is
 * added everywhere.
 */
public record PlumeField(Position centre, double radius, double peak, double background) implements SimField {

    public PlumeField {
        FieldChecks.onEarth("the centre", centre);
        if (!(radius > 0 && Double.isFinite(radius))) {
            throw new IllegalArgumentException("the radius must be a positive number of metres, got " + radius);
        }
        FieldChecks.finite("the peak", peak);
        FieldChecks.finite("the background", background);
    }

    @Override
    public double valueAt(Position p) {
        double d = centre.horizontalDistanceTo(p);
        return background + (d < radius ? peak * (1 - d / radius) : 0);
    }
}
