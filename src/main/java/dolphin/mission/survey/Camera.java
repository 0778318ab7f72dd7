package dolphin.mission.survey;

import java.util.Objects;

/**
 * A camera as QGroundControl's CameraCalc sees it (docs/qgc-surveys.md §1.1): sensor in mm, image
 * in px, focal length in mm, the shortest interval between photos in s. {@code fixedOrientation}
 * only says the camera cannot be turned to portrait; no formula uses it.
 */
public record Camera(String name, double sensorWidth, double sensorHeight, int imageWidth, int imageHeight,
                     double focalLength, double minTriggerInterval, boolean fixedOrientation) {

    /** QGroundControl's name for a camera given by its numbers. */
    public static final String CUSTOM = "Custom Camera";
    /** QGroundControl's name for no camera: the spacing and trigger distance typed in (docs/qgc-surveys.md §1.3). */
    public static final String MANUAL = "Manual (no camera specs)";


    public Camera {
        Objects.requireNonNull(name, "name");
        if (name.isBlank()) {
            throw new IllegalArgumentException("a camera needs a name, got a blank one");
        }
        positive(name, "sensor width", sensorWidth, "mm");
        positive(name, "sensor height", sensorHeight, "mm");
        positive(name, "focal length", focalLength, "mm");
        if (imageWidth <= 0) {
            throw new IllegalArgumentException("camera '" + name + "': the image width must be above 0 px, got "
                    + imageWidth);
        }
        if (imageHeight <= 0) {
            throw new IllegalArgumentException("camera '" + name + "': the image height must be above 0 px, got "
                    + imageHeight);
        }
        if (!(minTriggerInterval >= 0) || Double.isInfinite(minTriggerInterval)) {
            throw new IllegalArgumentException("camera '" + name + "': the minimum trigger interval must be 0 s or more, got "
                    + Numbers.format(minTriggerInterval));
        }
    }

    private static void positive(String camera, String what, double value, String unit) {
        if (!(value > 0) || Double.isInfinite(value)) {
            throw new IllegalArgumentException("camera '" + camera + "': the " + what + " must be above 0 " + unit
                    + ", got " + Numbers.format(value));
        }
    }
}
