package dolphin.mission.model;

import com.MAVLink.enums.MAV_CMD;
import dolphin.core.EnvironmentException;
import dolphin.core.Position;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;

/**
 * A MAVLink mission: the commands of a {@code mission { }} block (or of a file), turned into the
 * items a vehicle flies, with the fence and rally points that go with it. Item 0 is always the home
 * placeholder, which ArduPilot overwrites with its home; real items start at 1 (docs/decisions.md,
 * "Missions"). Flying it is the flight layer's {@code MissionTask}; the same Mission may fly on
 * several vehicles at once, so it holds no per-flight state.
 */
public final class Mission {

    private final String id;
    private final Position home;
    private final boolean belowHomeAllowed;
    private final List<DroneCommand> droneCommands = new ArrayList<>();
    private volatile Fence fence = Fence.NONE;
    private volatile RallyPoints rally = RallyPoints.NONE;
    private volatile boolean fenceEnabled;
    private volatile VehicleProfile vehicleProfile = VehicleProfile.ARDUPILOT_COPTER;
    private volatile Underwater underwater;
    private volatile FlightLimits limits = FlightLimits.RUN;

    /** @param home the home the script named, or null */
    public Mission(String name, Position home, List<DroneCommand> commands) {
        this(name, home, commands, false);
    }

    /**
     * @param belowHomeAllowed true when the script allows items lower than home plus the clearance
     *        ({@code allowBelowHome true}; see {@link HeightCheck})
     */
    public Mission(String name, Position home, List<DroneCommand> commands, boolean belowHomeAllowed) {
        this.id = name;
        this.home = home;
        this.belowHomeAllowed = belowHomeAllowed;
        setDroneCommands(commands);
    }

    /** Whether the script allowed items lower than home plus the clearance. */
    public boolean belowHomeAllowed() {
        return belowHomeAllowed;
    }

    /** The bounds of an underwater mission ({@code maxDepth}), or empty for one flown or driven in the air. */
    public Optional<Underwater> underwater() {
        return Optional.ofNullable(underwater);
    }

    public void setUnderwater(Underwater bounds) {
        underwater = bounds;
    }

    /** The script's stall limit and takeover timeout for this mission, where it sets them. */
    public FlightLimits limits() {
        return limits;
    }

    public void setLimits(FlightLimits limits) {
        this.limits = limits;
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

    /** The mission's name, as the script gave it or the default. */
    public String getId() {
        return id;
    }

    /** A mission point and the seq of its first item. */
    public record NumberedPoint(int firstSeq, MissionPoint point) {
    }

    /** The mission points in order, each with the seq of its first item: the first point's is 1, home being 0. */
    public List<NumberedPoint> numberedPoints() {
        List<NumberedPoint> out = new ArrayList<>();
        int seq = 1;
        for (DroneCommand c : droneCommands) {
            if (c instanceof MissionPoint p) {
                out.add(new NumberedPoint(seq, p));
                seq += p.messageCount();
            }
        }
        return out;
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

    /**
     * The take-offs and landings of {@link #items} that say how they are to be flown, by seq; any
     * other item is flown as the vehicle does, as are items read from a file, which say it by their
     * command. One pass over the points: a survey's items are not made again per item.
     */
    public Map<Integer, FlightWay> ways() {
        Map<Integer, FlightWay> ways = new TreeMap<>();
        for (NumberedPoint n : numberedPoints()) {
            FlightWay way = n.point() instanceof TakeOffPoint t ? t.way()
                    : n.point() instanceof LandingPoint l ? l.way() : FlightWay.AS_THE_VEHICLE_DOES;
            if (way != FlightWay.AS_THE_VEHICLE_DOES) {
                ways.put(n.firstSeq(), way);
            }
        }
        return ways;
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
            if (c instanceof MissionPoint p) {
                // a generated pattern (a survey) has no position of its own: its first item's, at sea level,
                // since its heights may be above a home not known here
                for (MissionItem item : p.items(1)) {
                    if (item.frame() != MissionItem.MISSION && (item.x() != 0 || item.y() != 0)) {
                        return Position.fromDegrees(item.x() * 1e-7, item.y() * 1e-7, 0);
                    }
                }
            }
        }
        throw new EnvironmentException("mission " + getId() + " has no home: name one with 'home', or give it a position");
    }

    /**
     * The commands that are not mission items, keyed by item seq: key 0 for those before the
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

    @Override
    public String toString() {
        return id;
    }
}
