package dolphin.web;

import java.util.function.Supplier;

/**
 * One vehicle at one sample: its view, and the mission it flies, known by {@code missionKey} (the
 * mission's executor; null when none), drawn as GeoJSON only when the key is new.
 */
record VehicleSample(VehicleView view, Object missionKey, Supplier<String> missionGeoJson) {
}
