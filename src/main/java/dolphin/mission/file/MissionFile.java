package dolphin.mission.file;

import dolphin.mission.model.Fence;
import dolphin.mission.model.MissionItem;
import dolphin.mission.model.RallyPoints;
import dolphin.mission.model.VehicleProfile;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

/**
 * What a mission file holds: a mission's items (item 0 the home; empty for a file of only a fence
 * or only rally points), a geofence, rally points, and the vehicle the file was made for.
 */
public record MissionFile(List<MissionItem> mission, Fence fence, RallyPoints rally, VehicleProfile vehicle) {

    public MissionFile {
        mission = List.copyOf(mission);
    }

    /** A mission alone, for an ArduPilot copter. */
    public static MissionFile of(List<MissionItem> mission) {
        return new MissionFile(mission, Fence.NONE, RallyPoints.NONE, VehicleProfile.ARDUPILOT_COPTER);
    }

    public MissionFile withFence(Fence f) {
        return new MissionFile(mission, f, rally, vehicle);
    }

    public MissionFile withRally(RallyPoints r) {
        return new MissionFile(mission, fence, r, vehicle);
    }

    public MissionFile withVehicle(VehicleProfile v) {
        return new MissionFile(mission, fence, rally, v);
    }

    public boolean hasMission() {
        return !mission.isEmpty();
    }

    /**
     * Any mission file, by its content, not its name: JSON is a QGroundControl plan or .mission
     * ({@link PlanFile}), anything else a text file ({@link WaypointsFile}: QGC WPL 110 or 120, or
     * MAVProxy's fence and rally files).
     *
     * @throws IllegalArgumentException saying what is wrong and where
     */
    public static MissionFile read(String text) {
        String t = MissionFileText.withoutBom(text).stripLeading();
        return t.startsWith("{") ? PlanFile.readFile(text) : WaypointsFile.readFile(text);
    }

    /** Any mission file, UTF-8 with or without a byte-order mark; errors start with the file's name. */
    public static MissionFile read(Path file) throws IOException {
        return MissionFileText.parse(file, MissionFile::read);
    }
}
