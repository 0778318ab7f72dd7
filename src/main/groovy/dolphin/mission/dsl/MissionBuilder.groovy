package dolphin.mission.dsl

import dolphin.dsl.Blocks
import dolphin.core.Position
import dolphin.dsl.DslException
import dolphin.mission.model.CameraPoint
import dolphin.mission.model.CameraStopPoint
import dolphin.mission.model.ChangeSpeed
import dolphin.mission.model.DelayCommand
import dolphin.mission.model.DroneCommand
import dolphin.mission.model.Fence
import dolphin.mission.model.FlightLimits
import dolphin.mission.model.FlightWay
import dolphin.mission.model.GoToPoint
import dolphin.mission.model.HeightCheck
import dolphin.mission.model.JumpToItem
import dolphin.mission.model.LandingPoint
import dolphin.mission.model.LoiterPoint
import dolphin.mission.model.LoiterTimePoint
import dolphin.mission.model.LoiterTurnsPoint
import dolphin.mission.model.Mission
import dolphin.mission.model.MissionPoint
import dolphin.mission.model.RallyPoints
import dolphin.mission.model.SurveyArea
import dolphin.mission.model.SurveyDirection
import dolphin.mission.model.TakeOffPoint
import dolphin.mission.model.Underwater
import dolphin.mission.survey.HeightReference
import dolphin.mission.survey.MappingItem
import dolphin.mission.survey.TransectPoint
import dolphin.dsl.vocabulary.Suggestions
import dolphin.dsl.vocabulary.Vocabulary
import dolphin.dsl.vocabulary.Word
import dolphin.dsl.vocabulary.WordEntry
import groovy.transform.CompileStatic
import groovy.transform.PackageScope
import org.codehaus.groovy.runtime.InvokerHelper

/**
 * The delegate of {@code mission { ... }} (docs/mission-commands.md): each command
 * appends a DroneCommand, in source order. Heights are metres above mean sea level, latitudes and
 * longitudes degrees, distances metres, times seconds.
 *
 * <p>Position tracking (docs/mission-commands.md, "Position tracking"): relative commands start from the last
 * <em>registered</em> position, or from the mission's home when none is registered yet. goPos, move*,
 * takeOff, returnHome*, altitude and surveyArea register a position; loiter*, landingPoint and home
 * do not. *FromHome start from the home named with {@code home}; returnHome and returnHomeAndLoiter
 * arrive over it at the last registered height (docs/mission-commands.md, "Safe heights").
 *
 * <p>No item but a landing may be lower than home plus {@link HeightCheck#CLEARANCE} unless the
 * mission says {@code allowBelowHome true}: checked when the mission is built if it names its home,
 * else by the executor against the vehicle's home.
 *
 * <p>The builder answers its own commands first; everything else (script variables, other words)
 * falls through to the script. It has no properties of its own, so script variables are never
 * shadowed.
 */
@CompileStatic
class MissionBuilder {

    /** The commands, read from this class's {@link Word} methods: their names and forms for error messages. */
    @PackageScope
    static final Map<String, WordEntry> COMMANDS = Vocabulary.wordsOf(MissionBuilder)

    /** The most items a MAVLink mission can have (seq and count are 16-bit). */
    @PackageScope
    static final int MAX_ITEMS = 65535

    private String missionName
    private Position missionHome
    private boolean belowHomeAllowed
    private FlightLimits limits = FlightLimits.RUN
    /** Set by maxDepth: the mission is under water (docs/underwater.md). */
    private Underwater water
    /** Where each point was written: an exception made there, whose stack trace gives a later error that line. */
    private final Map<MissionPoint, DslException> origins = new IdentityHashMap<>()
    private Position lastRegistered
    /** Why there is no last registered position after a mapping item whose end height is not known here, else null. */
    private String unknownEnd
    private final List<DroneCommand> commands = []
    private Fence missionFence = Fence.NONE
    private boolean fenceEnabled
    private final List<Position> rallyPoints = []
    /** Where the rally points were given, for a height error. */
    private DslException rallyOrigin
    /** Jumps, with the error to throw (made at the jump's line) if the target does not exist. */
    private final Map<JumpToItem, DslException> jumps = [:]
    /** The closure this builder runs, to reach the script's variables and words. */
    private final Closure body

    @PackageScope
    MissionBuilder(String defaultName, Closure body) {
        this.missionName = defaultName
        this.body = body
    }

    // ---- naming, safety and home

    /** Allows items lower than home plus the clearance (HeightCheck): the script's explicit choice. */
    @Word('Allows items lower than home plus 2 m: the script\'s explicit choice')
    void allowBelowHome(boolean allowed) {
        belowHomeAllowed = allowed
    }

    /** How long the flight may make no progress toward an item before it fails (docs/failures.md, "A stall"). */
    @Word('How long the vehicle may make no progress toward an item before the mission fails: stallLimit 2.minutes')
    void stallLimit(Number seconds) {
        limits = limits.withStallLimit(Args.duration('stallLimit', 'stall limit', seconds))
    }

    /** How long a pilot may hold the vehicle out of AUTO before the mission fails (docs/failures.md, "A pilot's pause"). */
    @Word('How long a pilot may hold the vehicle out of AUTO before the mission fails: takeoverTimeout 5.minutes')
    void takeoverTimeout(Number seconds) {
        limits = limits.withTakeoverTimeout(Args.duration('takeoverTimeout', 'takeover timeout', seconds))
    }

    /** The mission's name: its task id in messages and exports. */
    @Word('The mission\'s name: its task id in messages and exports')
    void name(String name) {
        if (name == null || name.trim().isEmpty()) {
            throw new DslException('name: the mission name must not be empty')
        }
        missionName = name
    }

    /**
     * The mission's home: item 0 (the home placeholder) and, when flown, the vehicle's home
     * (DO_SET_HOME before the upload). Emits no item and registers no position.
     */
    @Word('The mission\'s home (item 0), set on the vehicle before the upload; adds no item')
    void home(Number lat, Number lon, Number hae = 0) {
        setHome(Args.position('home', lat, lon, hae))
    }

    @Word('The mission\'s home (item 0), set on the vehicle before the upload; adds no item')
    void home(Position position) {
        setHome(Args.position('home', position))
    }

    private void setHome(Position p) {
        if (missionHome != null) {
            throw new DslException("home: this mission already has a home, ${missionHome}; a mission has one home")
        }
        if (water != null) {
            throw new DslException("home: name the mission's home before maxDepth: the surface is at its height")
        }
        missionHome = p
    }

    // ---- under water (docs/underwater.md)

    /**
     * Makes the mission an underwater one, for a submarine: its items stay between the surface (home's
     * height, or sea level when the mission names no home) and {@code metres} below it.
     */
    @Word('An underwater mission, at most this many metres below the surface (home\'s height, else sea level)')
    void maxDepth(Number metres) {
        if (water != null) {
            throw new DslException("maxDepth: this mission already has a depth limit, ${water.maxDepth()} m; it has one")
        }
        water = new Underwater(missionHome != null ? missionHome.hae() : 0, Args.positive('maxDepth', 'depth limit', metres))
    }

    /** NAV_WAYPOINT straight down (or up) at the last position, {@code metres} below the surface; registers it. */
    @Word('A waypoint at the last position, this many metres below the surface (after maxDepth)')
    void dive(Number metres) {
        Underwater w = underwater('dive')
        waypoint('dive', lastPosition('dive').atHeight(w.heightAt(Args.notNegative('dive', 'depth', metres))))
    }

    /** NAV_LAND at the last position at the surface: ArduSub rises there (its landing); registers it. */
    @Word('Rises to the surface at the last position (after maxDepth)')
    void surface() {
        Underwater w = underwater('surface')
        Position up = lastPosition('surface').atHeight(w.surface())
        add(new LandingPoint('surface', up, Float.NaN, 0))
        register(up)
    }

    private Underwater underwater(String word) {
        if (water == null) {
            throw new DslException("${word}: say first that the mission is under water and how deep it may go:"
                    + " 'maxDepth METRES'")
        }
        water
    }

    // ---- going somewhere

    /** NAV_WAYPOINT at (lat, lon, hae); registers it. */
    @Word('A waypoint at a position (degrees, metres above mean sea level)')
    void goPos(Number lat, Number lon, Number hae = 0) {
        waypoint('goPos', Args.position('goPos', lat, lon, hae))
    }

    @Word('A waypoint at a position (degrees, metres above mean sea level)')
    void goPos(Position position) {
        waypoint('goPos', Args.position('goPos', position))
    }

    /**
     * NAV_TAKEOFF at the position, pitch in degrees; registers it, so relative commands after it
     * start at the take-off height (the report: "move the drone relative to its position").
     */
    @Word('Take-off to the position; pitch in degrees (planes)')
    void takeOff(Position position, Number pitch = TakeOffPoint.DEFAULT_PITCH) {
        addRegistered(new TakeOffPoint('takeOff', Args.position('takeOff', position), (float) Args.number('takeOff', 'pitch', pitch), Float.NaN))
    }

    @Word('Take-off to the position with a pitch and a heading, degrees')
    void takeOffWithYaw(Position position, Number pitch, Number yaw = Float.NaN) {
        addRegistered(new TakeOffPoint('takeOffWithYaw', Args.position('takeOffWithYaw', position),
                (float) Args.number('takeOffWithYaw', 'pitch', pitch), Args.yaw('takeOffWithYaw', yaw)))
    }

    /** A take-off flown vertically, where the vehicle can do both (a QuadPlane): docs/vtol.md. */
    @Word('Takes off vertically (a VTOL take-off) and climbs to the position\'s height')
    void takeOffVertically(Position position) {
        addRegistered(new TakeOffPoint('takeOffVertically', Args.position('takeOffVertically', position), 0f, Float.NaN,
                FlightWay.VERTICAL))
    }

    /** A take-off on a runway, where the vehicle can do both (a QuadPlane whose Q_OPTIONS allow it): docs/vtol.md. */
    @Word('Takes off on a runway (a plane\'s take-off) to the position; pitch in degrees')
    void takeOffOnRunway(Position position, Number pitch = TakeOffPoint.DEFAULT_PITCH) {
        addRegistered(new TakeOffPoint('takeOffOnRunway', Args.position('takeOffOnRunway', position),
                (float) Args.number('takeOffOnRunway', 'pitch', pitch), Float.NaN, FlightWay.RUNWAY))
    }

    /** NAV_WAYPOINT north/east/up metres from the last registered position (or home); registers it. */
    @Word('A waypoint north, east and up of the last position, metres; move(p, { north n; east e }) is a position')
    void move(Number north, Number east, Number up = 0) {
        waypoint('move', relative('move', lastPosition('move'), north, east, up))
    }

    /** Inside a mission too, move(position, { ... }) is the position word: it returns a position and adds nothing. */
    @Word('A waypoint north, east and up of the last position, metres; move(p, { north n; east e }) is a position')
    Position move(Position position, @DelegatesTo(value = NedBuilder, strategy = Closure.DELEGATE_FIRST) Closure offset) {
        NedBuilder.build('move', offset).from(Args.position('move', position))
    }

    @Word('A waypoint north, east and up of the last position, metres; move(p, { north n; east e }) is a position')
    Position move(Position position, NedOffset offset) {
        new PositionWords().move(position, offset)
    }

    /** NAV_WAYPOINT north/east/up metres from home; registers it. */
    @Word('A waypoint north, east and up of home, metres')
    void moveFromHome(Number north, Number east, Number up) {
        waypoint('moveFromHome', relative('moveFromHome', homeFor('moveFromHome'), north, east, up))
    }

    @Word('Moves north, east and up of the last position (metres) and circles there until the mission goes on')
    void moveAndLoiterPos(Number north, Number east, Number up, Number radius = LoiterPoint.DEFAULT_RADIUS) {
        String w = 'moveAndLoiterPos'
        Position p = relative(w, lastPosition(w), north, east, up)
        addRegistered(new LoiterPoint(w, p, Args.radius(w, radius)))
    }

    @Word('Moves north, east and up of the last position (metres) and circles there a number of turns')
    void moveAndLoiterTurns(Number north, Number east, Number up, Number turns = LoiterTurnsPoint.DEFAULT_TURNS,
                            Number radius = LoiterPoint.DEFAULT_RADIUS) {
        String w = 'moveAndLoiterTurns'
        Position p = relative(w, lastPosition(w), north, east, up)
        addRegistered(new LoiterTurnsPoint(w, p, turnCount(w, turns), Args.radius(w, radius)))
    }

    @Word('Moves north, east and up of the last position (metres) and circles there for a time, seconds')
    void moveAndLoiterTime(Number north, Number east, Number up, Number seconds, Number radius = LoiterPoint.DEFAULT_RADIUS) {
        String w = 'moveAndLoiterTime'
        Position p = relative(w, lastPosition(w), north, east, up)
        addRegistered(new LoiterTimePoint(w, p, loiterSeconds(w, seconds), Args.radius(w, radius)))
    }

    @Word('Moves north, east and up of home (metres) and circles there until the mission goes on')
    void moveAndLoiterFromHome(Number north, Number east, Number up, Number radius = LoiterPoint.DEFAULT_RADIUS) {
        String w = 'moveAndLoiterFromHome'
        Position p = relative(w, homeFor(w), north, east, up)
        addRegistered(new LoiterPoint(w, p, Args.radius(w, radius)))
    }

    @Word('Moves north, east and up of home (metres) and circles there a number of turns')
    void moveAndLoiterTurnsFromHome(Number north, Number east, Number up, Number turns = LoiterTurnsPoint.DEFAULT_TURNS,
                                    Number radius = LoiterPoint.DEFAULT_RADIUS) {
        String w = 'moveAndLoiterTurnsFromHome'
        Position p = relative(w, homeFor(w), north, east, up)
        addRegistered(new LoiterTurnsPoint(w, p, turnCount(w, turns), Args.radius(w, radius)))
    }

    @Word('Moves north, east and up of home (metres) and circles there for a time, seconds')
    void moveAndLoiterTimeFromHome(Number north, Number east, Number up, Number seconds,
                                   Number radius = LoiterPoint.DEFAULT_RADIUS) {
        String w = 'moveAndLoiterTimeFromHome'
        Position p = relative(w, homeFor(w), north, east, up)
        addRegistered(new LoiterTimePoint(w, p, loiterSeconds(w, seconds), Args.radius(w, radius)))
    }

    // ---- loitering and landing at a given position (none of these registers it)

    @Word('Circles a position until the mission goes on; radius in metres')
    void loiterPos(Position position, Number radius = LoiterPoint.DEFAULT_RADIUS) {
        add(new LoiterPoint('loiterPos', Args.position('loiterPos', position), Args.radius('loiterPos', radius)))
    }

    @Word('Circles a position until the mission goes on; radius in metres')
    void loiterPos(Number lat, Number lon, Number hae, Number radius = LoiterPoint.DEFAULT_RADIUS) {
        add(new LoiterPoint('loiterPos', Args.position('loiterPos', lat, lon, hae), Args.radius('loiterPos', radius)))
    }

    @Word('Circles a position a number of turns; radius in metres')
    void loiterTurns(Number lat, Number lon, Number hae, Number turns = LoiterTurnsPoint.DEFAULT_TURNS,
                     Number radius = LoiterPoint.DEFAULT_RADIUS) {
        String w = 'loiterTurns'
        add(new LoiterTurnsPoint(w, Args.position(w, lat, lon, hae), turnCount(w, turns), Args.radius(w, radius)))
    }

    @Word('Circles a position for a time, seconds; radius in metres')
    void loiterTime(Number lat, Number lon, Number hae, Number seconds, Number radius = LoiterPoint.DEFAULT_RADIUS) {
        String w = 'loiterTime'
        add(new LoiterTimePoint(w, Args.position(w, lat, lon, hae), loiterSeconds(w, seconds), Args.radius(w, radius)))
    }

    /** NAV_LAND; yaw NaN lets the vehicle choose; landMode is PRECISION_LAND_MODE (0 disabled). */
    @Word('Lands at a position; yaw in degrees, landMode 0 (plain) or a precision-landing mode')
    void landingPoint(Number lat, Number lon, Number hae = 0, Number yaw = Float.NaN, Number landMode = 0) {
        String w = 'landingPoint'
        add(new LandingPoint(w, Args.position(w, lat, lon, hae), Args.yaw(w, yaw), Args.landMode(w, landMode)))
    }

    @Word('Lands at a position; yaw in degrees, landMode 0 (plain) or a precision-landing mode')
    void landingPoint(Position position, Number yaw = Float.NaN, Number landMode = 0) {
        String w = 'landingPoint'
        add(new LandingPoint(w, Args.position(w, position), Args.yaw(w, yaw), Args.landMode(w, landMode)))
    }

    @Word('Lands vertically at a position (a VTOL landing); yaw in degrees')
    void landVertically(Position position, Number yaw = Float.NaN) {
        String w = 'landVertically'
        add(new LandingPoint(w, Args.position(w, position), Args.yaw(w, yaw), 0, FlightWay.VERTICAL))
    }

    @Word('Lands on a runway at a position (a plane\'s landing); yaw in degrees')
    void landOnRunway(Position position, Number yaw = Float.NaN) {
        String w = 'landOnRunway'
        add(new LandingPoint(w, Args.position(w, position), Args.yaw(w, yaw), 0, FlightWay.RUNWAY))
    }

    // ---- home again (each registers where it ends)

    /** NAV_WAYPOINT over home at the last registered height; registers it. */
    @Word('A waypoint over home at the last height')
    void returnHome() {
        waypoint('returnHome', overHome('returnHome'))
    }

    /** NAV_LOITER_UNLIM over home at the last registered height; registers it. */
    @Word('Flies over home at the last height and circles there; radius in metres')
    void returnHomeAndLoiter(Number radius = LoiterPoint.DEFAULT_RADIUS) {
        String w = 'returnHomeAndLoiter'
        addRegistered(new LoiterPoint(w, overHome(w), Args.radius(w, radius)))
    }

    /** NAV_LAND at home: the vehicle flies there at the height it has, then lands; registers home. */
    @Word('Flies to home and lands there')
    void returnHomeAndLand(Number yaw = Float.NaN, Number landMode = 0) {
        homeLanding('returnHomeAndLand', yaw, landMode, FlightWay.AS_THE_VEHICLE_DOES)
    }

    @Word('Flies to home and lands there vertically (a VTOL landing)')
    void returnHomeAndLandVertically(Number yaw = Float.NaN) {
        homeLanding('returnHomeAndLandVertically', yaw, 0, FlightWay.VERTICAL)
    }

    @Word('Flies to home and lands there on a runway (a plane\'s landing)')
    void returnHomeAndLandOnRunway(Number yaw = Float.NaN) {
        homeLanding('returnHomeAndLandOnRunway', yaw, 0, FlightWay.RUNWAY)
    }

    private void homeLanding(String w, Number yaw, Number landMode, FlightWay way) {
        Position h = homeFor(w)
        add(new LandingPoint(w, h, Args.yaw(w, yaw), Args.landMode(w, landMode), way))
        register(h)
    }

    // ---- speed, height, time

    /** DO_CHANGE_SPEED: m/s; speedType 0 airspeed (default), 1 ground speed, 2 climb, 3 descent. */
    @Word('Changes speed, m/s; speedType 0 airspeed, 1 ground speed, 2 climb, 3 descent')
    void speed(Number newSpeed, Number speedType = ChangeSpeed.DEFAULT_TYPE) {
        add(new ChangeSpeed((float) Args.positive('speed', 'speed', newSpeed), Args.speedType('speed', speedType)))
    }

    /**
     * A NAV_WAYPOINT at the last registered position (or home) at the new height, metres above mean
     * sea level (ArduPilot rejects DO_CHANGE_ALTITUDE items: docs/decisions.md, "Missions"); registers that position.
     */
    @Word('A waypoint at the last position at a new height, metres above mean sea level')
    void altitude(Number height) {
        Position from = lastPosition('altitude')
        waypoint('altitude', from.atHeight(Args.number('altitude', 'height', height)))
    }

    /** NAV_DELAY: wait this many seconds before the next navigation command. */
    @Word('Waits this many seconds before the next navigation item')
    void delay(Number seconds) {
        add(new DelayCommand((float) Args.notNegative('delay', 'time', seconds)))
    }

    // ---- survey

    /** The survey pattern of SurveyArea from the last registered position (or home); registers that base. */
    @Word('A lawnmower survey of a length by width rectangle, lines spacing metres apart')
    void surveyArea(Number length, Number width, Number spacing = SurveyArea.DEFAULT_SPACING,
                    String direction = SurveyArea.DEFAULT_DIRECTION.name()) {
        lawnmower(lastPosition('surveyArea'), length, width, spacing, direction)
    }

    @Word('A lawnmower survey of a length by width rectangle, lines spacing metres apart')
    void surveyArea(Number length, Number width, String direction) {
        lawnmower(lastPosition('surveyArea'), length, width, SurveyArea.DEFAULT_SPACING, direction)
    }

    @Word('A lawnmower survey of a length by width rectangle, lines spacing metres apart')
    void surveyArea(Position base, Number length, Number width, Number spacing = SurveyArea.DEFAULT_SPACING,
                    String direction = SurveyArea.DEFAULT_DIRECTION.name()) {
        lawnmower(Args.position('surveyArea', base), length, width, spacing, direction)
    }

    @Word('A lawnmower survey of a length by width rectangle, lines spacing metres apart')
    void surveyArea(Position base, Number length, Number width, String direction) {
        lawnmower(Args.position('surveyArea', base), length, width, SurveyArea.DEFAULT_SPACING, direction)
    }

    private void lawnmower(Position base, Number length, Number width, Number spacing, String direction) {
        String w = 'surveyArea'
        double l = Args.notNegative(w, 'length', length)
        double wd = Args.notNegative(w, 'width', width)
        double s = Args.positive(w, 'spacing', spacing)
        SurveyDirection d
        try {
            d = SurveyDirection.parse(direction)
        } catch (IllegalArgumentException e) {
            throw new DslException("${w}: ${e.message}")
        }
        SurveyArea area
        try {
            area = new SurveyArea(base, l, wd, s, d)
        } catch (IllegalArgumentException e) {
            throw new DslException("${w}: ${e.message}")
        }
        add(area)
        register(base)
    }

    // ---- mapping (docs/mission-commands.md, "Mapping")

    /** QGroundControl's survey over a polygon: lines at a grid angle, photos by distance or hovering. */
    @Word('A survey over a polygon with a camera: QGroundControl\'s flight lines and photo triggers')
    void survey(@DelegatesTo(value = SurveyBuilder, strategy = Closure.DELEGATE_FIRST) Closure block) {
        mapping('survey', SurveyBuilder.build({ -> missionFence }, block))
    }

    /** QGroundControl's corridor scan: lines along a path, as many as cover its width. */
    @Word('A corridor scan: flight lines along a path (a road, a river) covering its width')
    void corridorScan(@DelegatesTo(value = CorridorBuilder, strategy = Closure.DELEGATE_FIRST) Closure block) {
        mapping('corridorScan', CorridorBuilder.build({ -> missionFence }, block))
    }

    /** QGroundControl's structure scan: rings around a footprint, layer by layer, photographing the walls. */
    @Word('A structure scan: rings around a building at a distance, layer by layer')
    void structureScan(@DelegatesTo(value = StructureBuilder, strategy = Closure.DELEGATE_FIRST) Closure block) {
        mapping('structureScan', StructureBuilder.build({ -> missionFence }, block))
    }

    /**
     * Adds a mapping item and registers where it ends, when its height is known here: above home with a
     * home, or above sea level. Otherwise relative commands after it have no position to start from.
     */
    private void mapping(String word, MappingItem item) {
        if (water != null) {
            throw new DslException("${word}: the mission is under water (maxDepth); surveys here fly at a height above"
                    + ' the ground: under water, use surveyArea at a depth')
        }
        add(item)
        TransectPoint end = item.path().last()
        double height = item.lastHeight()
        Double hae = switch (item.heightReference()) {
            case HeightReference.ABOVE_HOME -> missionHome == null ? null : missionHome.hae() + height
            case HeightReference.ABOVE_SEA_LEVEL -> height
            default -> null
        }
        if (hae == null) {
            lastRegistered = null
            String above = item.heightReference() == HeightReference.ABOVE_HOME ? 'home, and the mission names no home'
                    : 'the terrain'
            unknownEnd = "${word} ends at a height above ${above}"
        } else {
            register(Position.fromDegrees(end.latitude(), end.longitude(), hae))
        }
    }

    // ---- camera

    /** IMAGE_START_CAPTURE for one picture. */
    @Word('Takes one photo')
    void capturePhoto() {
        add(new CameraPoint('capturePhoto', 0f, 1))
    }

    /** IMAGE_START_CAPTURE for {@code photos} pictures, {@code timeBetween} seconds apart. */
    @Word('Takes photos, timeBetween seconds apart')
    void captureSeveralPhotos(Number photos, Number timeBetween = CameraPoint.DEFAULT_INTERVAL) {
        String w = 'captureSeveralPhotos'
        int n = Args.whole(w, 'number of photos', photos, 1, Integer.MAX_VALUE)
        add(new CameraPoint(w, (float) Args.positive(w, 'interval', timeBetween), n))
    }

    /** IMAGE_START_CAPTURE every {@code timeBetween} seconds until stopCapturing. */
    @Word('Takes a photo every timeBetween seconds until stopCapturing')
    void captureUntilStop(Number timeBetween = CameraPoint.DEFAULT_INTERVAL) {
        add(new CameraPoint('captureUntilStop', (float) Args.positive('captureUntilStop', 'interval', timeBetween), 0))
    }

    /** IMAGE_STOP_CAPTURE. */
    @Word('Stops taking photos')
    void stopCapturing() {
        add(new CameraStopPoint())
    }

    // ---- jumps

    /**
     * A ground-side jump, as in the original: when the vehicle reaches the item before this command, the ground
     * station sends it to item {@code item} (the uploaded seq, home = 0), at most {@code repetitions}
     * times. Emits no item.
     */
    @Word('When the item before it is reached, goes back to item number item, at most repetitions times')
    void jumpToItem(Number item, Number repetitions = 1) {
        String w = 'jumpToItem'
        int target = Args.whole(w, 'item', item, 0, MAX_ITEMS - 1)
        int times = Args.whole(w, 'number of repetitions', repetitions, 1, Integer.MAX_VALUE)
        if (!commands.any { it instanceof MissionPoint }) {
            throw new DslException("${w}: no mission item before it: the jump happens when the item before it is reached")
        }
        JumpToItem j = new JumpToItem(target, times)
        commands << (DroneCommand) j
        jumps[j] = new DslException("${w}: there is no item ${target}")
    }

    // ---- airspace (docs/airspace.md)

    /** The mission's geofence, uploaded before it; {@code enable true} switches it on at the start. */
    @Word('The mission\'s geofence: inclusion and exclusion polygons and circles, a return point')
    void fence(@DelegatesTo(value = FenceBuilder, strategy = Closure.DELEGATE_FIRST) Closure regions) {
        if (!missionFence.isEmpty()) {
            throw new DslException('fence: the mission has a fence already: one fence { } block a mission')
        }
        FenceBuilder b = FenceBuilder.build(regions)
        missionFence = b.fence()
        fenceEnabled = b.enabled()
    }

    /** Rally points, uploaded before the mission: where the vehicle may return instead of home. */
    @Word('Rally points: where the vehicle may return instead of home')
    void rally(Position... points) {
        if (points == null || points.length == 0) {
            throw new DslException('rally: expected one or more positions')
        }
        points.each { Position p -> rallyPoints << Args.position('rally', p) }
        rallyOrigin = new DslException('rally')
    }

    // ---- building

    @PackageScope
    Mission build() {
        if (!commands.any { it instanceof MissionPoint }) {
            throw new DslException("mission '${missionName}' has no items: expected at least one mission command"
                    + " (goPos, move, takeOff, surveyArea, ...)")
        }
        Mission m = new Mission(missionName, missionHome, commands, belowHomeAllowed)
        m.setUnderwater(water)
        m.setLimits(limits)
        if (missionHome != null && !belowHomeAllowed && water == null) {
            Position low = rallyPoints.find { Position p -> p.hae() < missionHome.hae() + HeightCheck.CLEARANCE }
            if (low != null) {
                DslException e = new DslException("rally: the rally point ${low} is lower than home plus " +
                        "${HeightCheck.CLEARANCE as int} m (${missionHome.hae() + HeightCheck.CLEARANCE} m); a vehicle returning there" +
                        " would fly into the ground. Say 'allowBelowHome true' if it is meant")
                e.stackTrace = rallyOrigin.stackTrace
                throw e
            }
        }
        m.setAirspace(missionFence, RallyPoints.at(rallyPoints), fenceEnabled)
        HeightCheck.firstUnsafe(m, missionHome).ifPresent { HeightCheck.Unsafe low ->
            DslException e = new DslException(low.message())
            e.stackTrace = origins[low.point()].stackTrace
            throw e
        }
        int count = m.missionPoints()
        if (count > MAX_ITEMS) {
            throw new DslException("mission '${missionName}' has ${count} items, home included; a MAVLink mission holds"
                    + " at most ${MAX_ITEMS}")
        }
        jumps.each { JumpToItem j, DslException e ->
            if (j.item() >= count) {
                DslException full = new DslException("${e.message}: mission '${missionName}' has items 0 to ${count - 1}"
                        + " (0 is home)")
                full.stackTrace = e.stackTrace
                throw full
            }
        }
        m
    }

    // ---- position tracking

    private void waypoint(String word, Position p) {
        addRegistered(new GoToPoint(word, p))
    }

    /** Adds a point and makes its position the one later relative commands start from. */
    private void addRegistered(MissionPoint point) {
        add(point)
        register(point.position)
    }

    private void add(DroneCommand c) {
        if (c instanceof MissionPoint) {
            origins[(MissionPoint) c] = new DslException('')
        }
        commands << c
    }

    private void register(Position p) {
        lastRegistered = p
        unknownEnd = null
    }

    /** Where relative commands start: the last registered position, else home. */
    private Position lastPosition(String word) {
        if (lastRegistered != null) {
            return lastRegistered
        }
        if (unknownEnd != null) {
            throw new DslException("${word}: there is no position to start from: the ${unknownEnd}; name the"
                    + " mission's home ('home lat, lon, hae') before it, or go to a position (goPos, ...) first")
        }
        if (missionHome != null) {
            return missionHome
        }
        throw new DslException("${word}: there is no position to start from yet: name the mission's home"
                + " ('home lat, lon, hae') or go to a position (goPos, ...) before it")
    }

    /** Home's latitude and longitude at the last registered height: returning never goes lower than the mission flew. */
    private Position overHome(String word) {
        Position h = homeFor(word)
        if (lastRegistered == null && unknownEnd != null) {
            throw new DslException("${word}: there is no height to return at: the ${unknownEnd}; name the mission's"
                    + " home ('home lat, lon, hae') before it, or use returnHomeAndLand()")
        }
        if (lastRegistered == null) {
            throw new DslException("${word}: there is no height to return at yet: the mission goes nowhere before it;"
                    + " go somewhere first (takeOff, goPos, move, ...), or use returnHomeAndLand()")
        }
        h.atHeight(lastRegistered.hae())
    }

    private Position homeFor(String word) {
        if (missionHome == null) {
            throw new DslException("${word}: the mission has no home yet: write 'home lat, lon, hae' before it")
        }
        missionHome
    }

    private static Position relative(String word, Position from, Number north, Number east, Number up) {
        NedOffset.offset(from, Args.number(word, 'north offset', north), Args.number(word, 'east offset', east),
                -Args.number(word, 'up offset', up))
    }

    private static int turnCount(String word, Number turns) {
        Args.whole(word, 'number of turns', turns, 1, 65535)
    }

    private static int loiterSeconds(String word, Number seconds) {
        Args.whole(word, 'time', seconds, 0, 65535)
    }

    // ---- what the builder does not answer

    /**
     * A command called with arguments it does not take: a script error listing its forms. A name
     * close to a command (a typo) that the script does not know either: a script error suggesting the
     * command. Anything else goes on to the script (variables holding closures, platform words).
     */
    def methodMissing(String name, Object args) {
        Object[] argv = args instanceof Object[] ? (Object[]) args : [args] as Object[]
        if (COMMANDS.containsKey(name)) {
            throw new DslException("${name}: expected ${COMMANDS[name].formsText()}, got ${types(argv)}")
        }
        List<String> close = Suggestions.near(name, COMMANDS.keySet())
        if (!close.isEmpty()) {
            try {
                return InvokerHelper.invokeMethod(body.owner, name, argv)
            } catch (GroovyRuntimeException e) {
                if (!missing(e, name)) {
                    throw e
                }
                throw new DslException("unknown mission command '${name}'; did you mean ${close.collect { "'${it}'" }.join(' or ')}?")
            }
        }
        throw new MissingMethodException(name, MissionBuilder, argv)
    }

    /** No properties: names go on to the script, except that a command without its () gets a hint. */
    @Override
    Object getProperty(String name) {
        if (COMMANDS.containsKey(name)) {
            try {
                return InvokerHelper.getProperty(body.owner, name)
            } catch (GroovyRuntimeException ignored) {
                throw new DslException("'${name}' is a mission command, but Groovy read it as a variable here: write"
                        + " '${name}()' or '${name} arguments'; a negative first argument needs parentheses, e.g."
                        + " '${name}(-10, ...)' (Groovy reads '${name} -10' as '${name} minus 10')")
            }
        }
        throw new MissingPropertyException(name, MissionBuilder)
    }

    @Override
    void setProperty(String name, Object value) {
        throw new MissingPropertyException(name, MissionBuilder)
    }

    /** Whether e (or what it wraps) says that the method {@code name} does not exist. */
    private static boolean missing(Throwable e, String name) {
        for (Throwable t = e; t != null; t = t.cause == t ? null : t.cause) {
            if (t instanceof MissingMethodException) {
                return ((MissingMethodException) t).method == name
            }
        }
        false
    }

    private static String types(Object[] args) {
        '(' + args.collect { Object a -> a == null ? 'null' : a instanceof GString ? 'String' : a.getClass().simpleName }.join(', ') + ')'
    }

}
