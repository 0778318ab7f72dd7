package dolphin.mission.survey;

/**
 * What a survey yields: gsd in cm/px (NaN for a manual grid), QGC's CameraShots estimate
 * (docs/qgc-surveys.md §1.4) and the flight path length in metres, turnarounds and joins included.
 */
public record Coverage(double gsd, int photos, double pathLength) {
}
