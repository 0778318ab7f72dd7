package dolphin.sim;

import dolphin.core.Position;

/** The checks every {@link SimField} makes of its parameters, so a bad one is refused with its name, never read as NaN. */
final class FieldChecks {

    private FieldChecks() {
    }

    static void finite(String what, double value) {
        if (!Double.isFinite(value)) {
            throw new IllegalArgumentException(what + " must be a finite number, got " + value);
        }
    }

    static void onEarth(String what, Position p) {
        double lat = p.latitudeDegrees();
        double lon = p.longitudeDegrees();
        if (!(Math.abs(lat) <= 90 && Math.abs(lon) <= 180)) {
            throw new IllegalArgumentException(what + " must have a latitude in [-90, 90] and a longitude in [-180, 180], got "
                    + lat + ", " + lon);
        }
    }
}
