package dolphin.mission.model;

import dolphin.mission.flight.MissionExecutor;
import com.MAVLink.Messages.MAVLinkMessage;
import com.MAVLink.enums.MAV_CMD;
import dolphin.core.EnvironmentException;
import dolphin.core.NodeFilter;
import dolphin.core.PlatformTask;
import dolphin.core.PlatformTaskExecutor;
import dolphin.core.Position;
import dolphin.mavlink.MAVLinkNode;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A MAVLink mission as a Dolphin task (report Listing 5): the commands of a {@code mission { }}
 * block, turned into the items a vehicle flies. Item 0 is always the home placeholder, which
 * ArduPilot overwrites with its home; real items start at 1 (design §5). The same Mission object
 * may fly on several vehicles at once (E-3): it holds no per-flight state.
 */
public final class Mission extends PlatformTask {

    private final Position home;
    private final boolean belowHomeAllowed;
    private final List<DroneCommand> droneCommands = new ArrayList<>();
    private volatile Fence fence = Fence.NONE;
    private volatile RallyPoints rally = RallyPoints.NONE;
    private volatile boolean fenceEnabled;
    private volatile VehicleProfile vehicleProfile = VehicleProfile.ARDUPILOT_COPTER;

    /** @param home the home the script named, or null */
    public Mission(String name, Position home, List<DroneCommand> commands) {
        this(name, home, commands, false);
    }

    /**
     * @param belowHomeAllowed true when the script allows items lower than home plus the clearance
     *        ({@code allowBelowHome true}; see {@link HeightCheck})
     */
    public Mission(String name, Position home, List<DroneCommand> commands, boolean belowHomeAllowed) {
        super(name);
        this.home = home;
        this.belowHomeAllowed = belowHomeAllowed;
        setDroneCommands(commands);
    }

    /** Whether the script allowed items lower than home plus the clearance. */
    public boolean belowHomeAllowed() {
        return belowHomeAllowed;
    }

    public void setDroneCommands(List<DroneCommand> commands) {
        droneCommands.clear();
        droneCommands.addAll(commands);
    }

    public List<DroneCommand> getCommandList() {
        return List.copyOf(droneCommands);
    }

    /**
     * The geofence and rally points uploaded with the mission (docs/airspace.md), and whether the
     * fence is switched on when the mission starts (the script's choice: {@code fence { enable true }}).
     */
    public void setAirspace(Fence fence, RallyPoints rally, boolean fenceEnabled) {
        this.fence = fence;
        this.rally = rally;
        this.fenceEnabled = fenceEnabled;
    }

    public Fence fence() {
        return fence;
    }

    public RallyPoints rally() {
        return rally;
    }

    public boolean fenceEnabled() {
        return fenceEnabled;
    }

    /** The vehicle a mission file was made for, kept for export; an ArduPilot copter for a script's mission. */
    public VehicleProfile vehicleProfile() {
        return vehicleProfile;
    }

    public void setVehicleProfile(VehicleProfile profile) {
        this.vehicleProfile = profile;
    }

    /** The home the script named ({@code home ...}), or null. */
    public Position getHome() {
        return home;
    }

    @Override
    public String kind() {
        return "mission";
    }

    /** The number of items, the home placeholder included: what MISSION_COUNT says. */
    public int missionPoints() {
        return 1 + droneCommands.stream().filter(c -> c instanceof MissionPoint).mapToInt(c -> ((MissionPoint) c).messageCount()).sum();
    }

    /**
     * The items to upload: item 0 at the mission's home, else the vehicle's home (may be null when
     * building without a vehicle), else the first position in the mission; then each point's items.
     */
    public List<MissionItem> items(Position vehicleHome) {
        List<MissionItem> items = new ArrayList<>();
        items.add(MissionItem.at(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, placeholderHome(vehicleHome), 0, 0, 0, 0));
        int seq = 1;
        for (DroneCommand c : droneCommands) {
            if (c instanceof MissionPoint p) {
                List<MissionItem> emitted = p.items(seq);
                items.addAll(emitted);
                seq += emitted.size();
            }
        }
        return items;
    }

    private Position placeholderHome(Position vehicleHome) {
        if (home != null) {
            return home;
        }
        if (vehicleHome != null) {
            return vehicleHome;
        }
        for (DroneCommand c : droneCommands) {
            if (c instanceof MissionPoint p && p.getPosition() != null) {
                return p.getPosition();
            }
        }
        throw new EnvironmentException("mission " + getId() + " has no home: name one with 'home', or give it a position");
    }

    /** The MISSION_ITEM_INT messages for a vehicle (report's toMissionMessages). */
    public List<MAVLinkMessage> toMissionMessages(MAVLinkNode dest) {
        List<MAVLinkMessage> out = new ArrayList<>();
        for (MissionItem i : items(dest.getHome())) {
            out.add(i.toMessage(dest.getMavLinkId(), dest.getAutopilotCompid()));
        }
        return out;
    }

    /**
     * The commands that are not mission items, keyed by item seq (F-3): key 0 for those before the
     * first mission point (sent before the upload), key k for those after the point whose last
     * item is k (sent when the vehicle reports item k reached).
     */
    public Map<Integer, List<DroneCommand>> nonMissionCommands() {
        Map<Integer, List<DroneCommand>> byKey = new LinkedHashMap<>();
        int lastSeq = 0;
        for (DroneCommand c : droneCommands) {
            if (c instanceof MissionPoint p) {
                lastSeq += p.messageCount();
            } else {
                byKey.computeIfAbsent(c.executeOnStartup() ? 0 : lastSeq, k -> new ArrayList<>()).add(c);
            }
        }
        return byKey;
    }

    /** The report's droneCommandsToMissionItem: the non-mission commands' messages, keyed by item seq. */
    public Map<Integer, List<MAVLinkMessage>> droneCommandsToMissionItem(MAVLinkNode dest) {
        Map<Integer, List<MAVLinkMessage>> out = new LinkedHashMap<>();
        nonMissionCommands().forEach((k, cmds) -> cmds.forEach(c -> out.computeIfAbsent(k, x -> new ArrayList<>())
                .addAll(c.toMavLinkMessage(dest))));
        return out;
    }

    /** One vehicle of any type. */
    @Override
    public List<NodeFilter> getRequirements() {
        return List.of(NodeFilter.ANY);
    }

    /** A new executor that uploads, starts and follows this mission on its vehicle. */
    @Override
    public PlatformTaskExecutor getExecutor() {
        return new MissionExecutor(this);
    }
}
