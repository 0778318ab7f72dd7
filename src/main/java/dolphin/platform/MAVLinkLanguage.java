package dolphin.platform;

import dolphin.mavlink.MAVLinkNode;
import com.MAVLink.Messages.MAVLinkMessage;
import dolphin.core.Node;
import dolphin.core.NodeSet;
import dolphin.dsl.DslException;
import dolphin.dsl.DslExtension;
import dolphin.dsl.ScriptContext;
import dolphin.dsl.check.CallCheck;
import dolphin.dsl.vocabulary.Word;
import dolphin.mavlink.codec.MessageTable;
import dolphin.mission.dsl.MissionRecorder;
import dolphin.mission.dsl.PositionWords;
import dolphin.core.EnvironmentException;
import dolphin.mission.flight.MissionService;
import dolphin.mission.flight.MissionTask;
import dolphin.mission.model.Mission;
import dolphin.mission.file.MissionFile;
import dolphin.mission.model.MissionItem;
import dolphin.mission.model.RawItemPoint;
import dolphin.mission.model.HeightCheck;
import dolphin.mission.model.Underwater;
import com.MAVLink.enums.MAV_FRAME;
import dolphin.mission.transfer.TransferResult;
import dolphin.sensor.DeclaredSensors;
import dolphin.sensor.FleetFile;
import dolphin.sensor.Sensor;
import dolphin.sensor.SensorService;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.function.Consumer;
import java.util.function.Supplier;
import org.codehaus.groovy.control.customizers.ImportCustomizer;

/**
 * What the MAVLink platform adds to the language: the generated message classes and enums imported
 * into scripts, the words {@code mission { }}, {@code pos { }} and {@code moveDistance { }} (static
 * imports of {@code dolphin.mission.dsl.MissionDsl}, so IDEs see them), {@code move(position, { })}
 * ({@link PositionWords}), {@code sendMessage(vehicles, message)}, {@code downloadMission(vehicle)} and
 * {@code fenceBreached(vehicle)}, and the sensor words ({@link SensorWords}). Usable without a link, e.g. to
 * check scripts or build missions without vehicles.
 */
public final class MAVLinkLanguage implements DslExtension {

    private final Consumer<Sensor> install;
    private final Supplier<DeclaredSensors> declaredSensors;

    /** The language without vehicles and without a fleet file: for checking and dry runs. */
    public MAVLinkLanguage() {
        this(FleetFile.NONE);
    }

    /** The language without vehicles, checking sensor names against a fleet file ({@code dolphin check --fleet}). */
    public MAVLinkLanguage(FleetFile fleet) {
        DeclaredSensors declared = DeclaredSensors.of(fleet);
        this.install = sensor -> { };
        this.declaredSensors = () -> declared;
    }

    /** The language on vehicles: sensors a script adds are read by the communications' sensor layer. */
    MAVLinkLanguage(SensorService sensors) {
        this.install = sensors::add;
        this.declaredSensors = sensors::declared;
    }

    @Override
    public void addImports(ImportCustomizer imports) {
        imports.addStarImports("com.MAVLink.minimal", "com.MAVLink.standard", "com.MAVLink.common",
                "com.MAVLink.ardupilotmega", "com.MAVLink.enums", "com.MAVLink.Messages", "dolphin.sensor");
        // named by string: MissionDsl is a Groovy class, compiled after the Java sources
        imports.addStaticStars("dolphin.mission.dsl.MissionDsl");
    }

    @Override
    public List<Class<?>> wordClasses() {
        try {
            return List.of(Words.class, SensorWords.class, PositionWords.class, Class.forName("dolphin.mission.dsl.MissionDsl"));
        } catch (ClassNotFoundException e) {
            throw new IllegalStateException(e);
        }
    }

    /**
     * A mission file that {@code missionFromFile 'path'} names must exist (relative to the current
     * directory); sensor names and telemetry fields must be possible ({@link SensorCallCheck}, made anew
     * for each check, as it remembers the script's {@code declareSensors}).
     */
    @Override
    public List<CallCheck> callChecks() {
        return List.of(new SensorCallCheck(declaredSensors.get()), (word, constants) -> {
            if (!"missionFromFile".equals(word) || constants.isEmpty()
                    || !(constants.get(constants.size() - 1) instanceof String path) || Files.exists(Path.of(path))) {
                return null;
            }
            return "missionFromFile: no file " + path + " (paths are relative to " + Path.of("").toAbsolutePath() + ")";
        });
    }

    @Override
    public List<Object> words(ScriptContext context) {
        return List.of(new Words(context), new SensorWords(context, install, declaredSensors), new PositionWords());
    }

    /** The platform's DSL words. */
    public static final class Words {
        /** How long, in real time, downloadMission waits at most (the transfer itself times out sooner). */
        static final java.time.Duration DOWNLOAD_DEADLINE = java.time.Duration.ofSeconds(120);
        private final ScriptContext context;

        Words(ScriptContext context) {
            this.context = context;
        }

        /** Sends a raw MAVLink message to every vehicle of the set, at once (not a task). */
        @Word("Sends a MAVLink message to every vehicle of the set, at once")
        public void sendMessage(NodeSet vehicles, MAVLinkMessage message) {
            context.needsVehicle("sendMessage", vehicles);
            for (Node n : vehicles) {
                if (!(n instanceof MAVLinkNode node)) {
                    throw new DslException("sendMessage: vehicle " + n.getId() + " is not a MAVLink vehicle");
                }
                node.send(message);
                context.listener().message("sent " + MessageTable.get().name(message.msgid) + " to vehicle " + node.getId());
            }
        }

        /**
         * The vehicle's current mission, downloaded (MISSION_REQUEST_LIST ...), as a Mission whose
         * home is the vehicle's item 0 and whose points are its items 1, 2, ... Blocks the script
         * until the download ends; fails with the download's error.
         */
        @Word("The vehicle's current mission, downloaded, as a mission task")
        public MissionTask downloadMission(Object vehicle) {
            MAVLinkNode node = OneVehicle.of(context, "downloadMission", vehicle);
            TransferResult r;
            try {
                r = MissionService.of(node.communications()).vehicle(node).transfers().download().download().get(DOWNLOAD_DEADLINE.toSeconds(), TimeUnit.SECONDS);
            } catch (TimeoutException e) {
                throw new EnvironmentException("downloadMission: no answer from vehicle " + node.getId() + " within "
                        + DOWNLOAD_DEADLINE.toSeconds() + " s");
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new EnvironmentException("downloadMission: interrupted while downloading from vehicle " + node.getId());
            } catch (ExecutionException e) {
                throw new EnvironmentException("downloadMission: " + e.getCause());
            }
            List<MissionItem> items = r.orThrow();
            context.listener().message("downloaded " + items.size() + " mission items from vehicle " + node.getId());
            return new MissionTask(RawItemPoint.mission("mission of vehicle " + node.getId(), items));
        }

        /**
         * Whether the vehicle is outside its fence now, as its last FENCE_STATUS said (docs/airspace.md);
         * false before any, as ArduPilot sends FENCE_STATUS only with its fence on. A condition:
         * {@code waitFor { fenceBreached(v) } then ...}, {@code survey / { fenceBreached(v) }}.
         */
        @Word("Whether the vehicle is outside its fence now")
        public boolean fenceBreached(Object vehicle) {
            return OneVehicle.of(context, "fenceBreached", vehicle).state().fenceBreached();
        }

        /**
         * Whether someone else holds the vehicle out of AUTO now, pausing a mission of ours on it
         * (docs/failures.md, "A pilot's pause"). A condition: {@code waitFor { takenOver(v) } then ...}.
         */
        @Word("Whether a pilot or another ground station holds the vehicle out of AUTO now, pausing its mission")
        public boolean takenOver(Object vehicle) {
            MAVLinkNode node = OneVehicle.of(context, "takenOver", vehicle);
            return MissionService.of(node.communications()).vehicle(node).takenOver();
        }

        /**
         * How many times a pilot or another ground station took the vehicle out of AUTO while a mission
         * of ours flew on it: after a mission that ended DONE, more than before means it was paused.
         */
        @Word("How many times a pilot or another ground station paused a mission on the vehicle")
        public int takeovers(Object vehicle) {
            MAVLinkNode node = OneVehicle.of(context, "takeovers", vehicle);
            return MissionService.of(node.communications()).vehicle(node).takeovers();
        }

        /**
         * A mission task from a mission file (docs/mission-files.md, "Missions from files"): any
         * format {@link MissionFile#read(Path)} reads, its fence and rally points with it. The path is
         * relative to the current directory. Item 0 of the file (its planned home) is not flown: the
         * vehicle's home takes its place, as ArduPilot does, and no DO_SET_HOME is sent. The fence
         * stays as the vehicle has it unless {@code enableFence: true}; items lower than home plus the
         * clearance are refused at the flight unless {@code allowBelowHome: true}. {@code maxDepth: 30}
         * makes it an underwater mission, for a submarine (docs/underwater.md), its surface at the
         * height of the file's planned home (sea level when it has none above mean sea level).
         */
        @Word("A mission task from a mission file (QGroundControl .plan, .waypoints, ...); options enableFence, allowBelowHome, maxDepth, name")
        public MissionTask missionFromFile(String path) {
            return missionFromFile(Map.of(), path);
        }

        @Word("A mission task from a mission file (QGroundControl .plan, .waypoints, ...); options enableFence, allowBelowHome, maxDepth, name")
        public MissionTask missionFromFile(Map<String, Object> options, String path) {
            for (String key : options.keySet()) {
                if (!List.of("enableFence", "name", "allowBelowHome", "maxDepth").contains(key)) {
                    throw new DslException("missionFromFile: unknown option '" + key
                            + "' (expected enableFence, allowBelowHome, maxDepth, name)");
                }
            }
            MissionFile file;
            try {
                file = MissionFile.read(Path.of(path));
            } catch (java.nio.file.NoSuchFileException e) {
                throw new DslException("missionFromFile: no file " + path + " (paths are relative to "
                        + Path.of("").toAbsolutePath() + ")");
            } catch (java.io.IOException e) {
                throw new DslException("missionFromFile: cannot read " + path + ": " + e.getMessage());
            } catch (IllegalArgumentException e) {
                throw new DslException("missionFromFile: " + e.getMessage());
            }
            if (!file.hasMission()) {
                throw new DslException("missionFromFile: " + path + " holds " + (file.fence().isEmpty() ? "rally points"
                        : "a fence") + " but no mission");
            }
            String name = options.containsKey("name") ? String.valueOf(options.get("name"))
                    : Path.of(path).getFileName().toString().replaceFirst("\\.[^.]*$", "");
            Mission m = RawItemPoint.mission(name, null, file.mission(), Boolean.TRUE.equals(options.get("allowBelowHome")));
            m.setAirspace(file.fence(), file.rally(), Boolean.TRUE.equals(options.get("enableFence")));
            m.setVehicleProfile(file.vehicle());
            if (options.containsKey("maxDepth")) {
                m.setUnderwater(underwater(options.get("maxDepth"), file.mission().get(0)));
                HeightCheck.firstUnsafe(m, null).ifPresent(u -> {
                    throw new DslException("missionFromFile: " + path + ": " + u.message());
                });
            }
            context.words().forEach(w -> MissionRecorder.report(w, m));
            context.listener().message("read " + (file.mission().size() - 1) + " mission items"
                    + (file.fence().isEmpty() ? "" : ", a fence of " + file.fence().describe())
                    + (file.rally().isEmpty() ? "" : ", " + file.rally().size() + (file.rally().size() == 1 ? " rally point" : " rally points")) + " from " + path);
            return new MissionTask(m);
        }

        /** The bounds {@code maxDepth:} gives a file's mission: the surface at its planned home, if that is above mean sea level. */
        private static Underwater underwater(Object maxDepth, MissionItem plannedHome) {
            if (!(maxDepth instanceof Number depth)) {
                throw new DslException("missionFromFile: maxDepth must be a number of metres, got " + maxDepth);
            }
            double surface = MissionItem.altitudeReference(plannedHome.frame()) == MAV_FRAME.MAV_FRAME_GLOBAL ? plannedHome.z() : 0;
            try {
                return new Underwater(surface, depth.doubleValue());
            } catch (IllegalArgumentException e) {
                throw new DslException("missionFromFile: " + e.getMessage());
            }
        }
    }
}
