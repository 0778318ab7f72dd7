package dolphin.mission.survey;

/**
 * QGroundControl's CameraCalc (docs/qgc-surveys.md §1): how far apart the lines and the photos are.
 * Altitude in m (the distance to the surface), gsd in cm/px, overlaps in %, footprints in m;
 * {@code spacing} is QGC's AdjustedFootprintSide (m between transects) and {@code triggerDistance}
 * its AdjustedFootprintFrontal (m between photos, 0 = the camera is not triggered). A manual grid
 * has no camera: its gsd, overlaps and footprints are NaN.
 *
 * <p>The canonical constructor takes stored values as they are (QGC does not recompute them when it
 * loads a plan, §1.3), checking only that they are usable.
 */
public record PhotoGrid(Camera camera, boolean landscape, boolean valueSetIsDistance, double altitude, double gsd,
                        double frontOverlap, double sideOverlap, double footprintSide, double footprintFrontal,
                        double spacing, double triggerDistance) {

    public PhotoGrid {
        positive("altitude (distance to the surface)", altitude, "m");
        positive("transect spacing", spacing, "m");
        if (!(triggerDistance >= 0) || Double.isInfinite(triggerDistance)) {
            throw new IllegalArgumentException("the trigger distance must be 0 m (no photos) or more, got "
                    + Numbers.format(triggerDistance));
        }
        if (camera != null) {
            positive("ground sample distance", gsd, "cm/px");
            overlap("front", frontOverlap);
            overlap("side", sideOverlap);
        }
    }

    /** The grid of a camera flown at {@code altitude} m: the gsd follows (§1.2, ValueSetIsDistance). */
    public static PhotoGrid atAltitude(Camera c, boolean landscape, double altitude, double frontOverlap, double sideOverlap) {
        positive("altitude (distance to the surface)", altitude, "m");
        double gsd = altitude * c.sensorWidth() * 100 / (c.imageWidth() * c.focalLength());
        return of(c, landscape, true, altitude, gsd, frontOverlap, sideOverlap);
    }

    /** The grid of a camera flown for a ground sample distance of {@code gsdCm} cm/px: the altitude follows (§1.2). */
    public static PhotoGrid atGsd(Camera c, boolean landscape, double gsdCm, double frontOverlap, double sideOverlap) {
        positive("ground sample distance", gsdCm, "cm/px");
        double altitude = c.imageWidth() * gsdCm * c.focalLength() / (c.sensorWidth() * 100);
        return of(c, landscape, false, altitude, gsdCm, frontOverlap, sideOverlap);
    }

    /** QGC's "Manual (no camera specs)": the three numbers as typed (§1.3). */
    public static PhotoGrid manual(double altitude, double spacing, double triggerDistance) {
        return new PhotoGrid(null, true, true, altitude, Double.NaN, Double.NaN, Double.NaN, Double.NaN, Double.NaN,
                spacing, triggerDistance);
    }

    private static PhotoGrid of(Camera c, boolean landscape, boolean valueSetIsDistance, double altitude, double gsd,
                                double frontOverlap, double sideOverlap) {
        java.util.Objects.requireNonNull(c, "camera");
        overlap("front", frontOverlap);
        overlap("side", sideOverlap);
        // QGC assumes square pixels: only the image width and sensor width enter the gsd (§1.2)
        double side = (landscape ? c.imageWidth() : c.imageHeight()) * gsd / 100;
        double frontal = (landscape ? c.imageHeight() : c.imageWidth()) * gsd / 100;
        return new PhotoGrid(c, landscape, valueSetIsDistance, altitude, gsd, frontOverlap, sideOverlap, side, frontal,
                side * (100 - sideOverlap) / 100, frontal * (100 - frontOverlap) / 100);
    }

    /** True for a manual grid (no camera). */
    public boolean manual() {
        return camera == null;
    }

    private static void positive(String what, double value, String unit) {
        if (!(value > 0) || Double.isInfinite(value)) {
            throw new IllegalArgumentException("the " + what + " must be above 0 " + unit + ", got " + Numbers.format(value));
        }
    }

    private static void overlap(String which, double value) {
        // 0 % leaves gaps as soon as the vehicle drifts; 100 % never moves on to the next line or photo
        if (!(value > 0 && value < 100)) {
            throw new IllegalArgumentException("the " + which + " overlap must be above 0 % and below 100 %, got "
                    + Numbers.format(value) + " %");
        }
    }
}
