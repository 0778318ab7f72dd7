package dolphin.mission.file;

import dolphin.mission.model.Fence;
import dolphin.mission.model.Mission;
import dolphin.mission.model.MissionItem;
import dolphin.mission.model.RallyPoints;
import dolphin.mission.model.VehicleProfile;
import dolphin.mission.survey.MappingItem;
import java.io.IOException;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * What a mission file holds: a mission's items (item 0 the home; empty for a file of only a fence
 * or only rally points), a geofence, rally points, the vehicle the file was made for, and the
 * mission's mapping items (surveys, corridor and structure scans) by the seq of their first item,
 * which a plan writes as QGroundControl's editable complex items. Reading a file gives none: its
 * complex items are read as the items they expand to.
 */
public record MissionFile(List<MissionItem> mission, Fence fence, RallyPoints rally, VehicleProfile vehicle,
                          Map<Integer, MappingItem> mappingItems) {

    public MissionFile {
        mission = List.copyOf(mission);
        mappingItems = Map.copyOf(mappingItems);
    }

    public MissionFile(List<MissionItem> mission, Fence fence, RallyPoints rally, VehicleProfile vehicle) {
        this(mission, fence, rally, vehicle, Map.of());
    }

    /** A mission alone, for an ArduPilot copter. */
    public static MissionFile of(List<MissionItem> mission) {
        return new MissionFile(mission, Fence.NONE, RallyPoints.NONE, VehicleProfile.ARDUPILOT_COPTER);
    }

    /**
     * A Mission with its fence, rally points, vehicle profile and mapping items.
     *
     * @param items the mission's items as {@link Mission#items} gave them
     */
    public static MissionFile of(Mission mission, List<MissionItem> items) {
        Map<Integer, MappingItem> mapping = new HashMap<>();
        for (Mission.NumberedPoint n : mission.numberedPoints()) {
            if (n.point() instanceof MappingItem m) {
                mapping.put(n.firstSeq(), m);
            }
        }
        return new MissionFile(items, mission.fence(), mission.rally(), mission.vehicleProfile(), mapping);
    }

    public MissionFile withFence(Fence f) {
        return new MissionFile(mission, f, rally, vehicle, mappingItems);
    }

    public MissionFile withRally(RallyPoints r) {
        return new MissionFile(mission, fence, r, vehicle, mappingItems);
    }

    public MissionFile withVehicle(VehicleProfile v) {
        return new MissionFile(mission, fence, rally, v, mappingItems);
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
