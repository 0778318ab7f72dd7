package dolphin.cli;

import dolphin.core.EnvironmentException;
import dolphin.dsl.ScriptResult;
import dolphin.mission.model.Mission;
import dolphin.mission.file.MissionFile;
import dolphin.mission.file.MissionFormat;
import dolphin.mission.model.MissionItem;
import dolphin.mission.model.MissionTable;
import dolphin.mission.file.WaypointsFile;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code dolphin mission SCRIPT [--export FORMAT] [--out DIR]}: builds a script's missions without
 * vehicles (a dry run) and prints each as a table, or writes one file per mission.
 *
 * <p>The dry run ({@link DryRun}) runs the script on a platform without vehicles and a clock that
 * jumps over waits (a {@code pick { timeout 30 }} takes no real time). With no vehicles, the script
 * ends at its first {@code pick}: the missions it defines before are the ones shown, which suits
 * scripts that define their missions first and fly them afterwards. Item 0 is the mission's home,
 * or its first position when it names none (there is no vehicle home).
 */
@Command(name = "mission", mixinStandardHelpOptions = true,
        description = {"Builds the missions of a script without vehicles (a dry run) and prints each as a table of its "
                + "mission items, or writes them to files with --export.",
                "The script runs without vehicles, on a clock that does not wait, until its end or its first pick "
                        + "(which finds no vehicles): define missions before picking vehicles.",
                "Exit 0 when done, 1 on a script error, 2 on a usage error."})
final class MissionCommand implements Callable<Integer> {

    @Option(names = "--time-limit", paramLabel = "SECONDS", defaultValue = "60",
            description = "Stop a dry run that has not ended after this much real time (default: ${DEFAULT-VALUE}).")
    private double timeLimit;

    @Spec
    private CommandSpec spec;

    @Parameters(paramLabel = "SCRIPT", description = "The .dolphin script whose missions to build.")
    private Path script;

    @Option(names = "--export", paramLabel = "FORMAT", converter = Converters.Format.class,
            description = "Write each mission to a file instead of printing it: plan (QGroundControl), waypoints "
                    + "(QGC WPL 110: Mission Planner, MAVProxy) or geojson (maps). The file is named after the mission.")
    private MissionFormat format;

    @Option(names = "--out", paramLabel = "DIR",
            description = "With --export: the directory to write to, created if missing (default: the current directory).")
    private Path out;

    @Override
    public Integer call() throws InterruptedException {
        PrintWriter stdout = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        if (out != null && format == null) {
            throw new ParameterException(spec.commandLine(), "--out needs --export: without it the missions are printed");
        }
        String source = Main.readScript("mission", script, err);
        if (source == null) {
            return Main.USAGE;
        }
        Path dir = null;
        if (format != null) {
            dir = outputDirectory(err);
            if (dir == null) {
                return Main.USAGE;
            }
        }

        List<Mission> missions = dryRun(source, err);
        if (missions == null) {
            return 1;
        }
        if (missions.isEmpty()) {
            err.println("dolphin mission: " + script + " builds no mission (no mission { } ran before the script ended"
                    + " or reached its first pick)");
            err.flush();
            return 0;
        }
        List<List<MissionItem>> itemLists = new ArrayList<>();
        for (Mission m : missions) {
            try {
                itemLists.add(m.items(null));
            } catch (EnvironmentException e) {
                err.println("dolphin mission: " + script + ": " + e.getMessage());
                return 1;
            }
        }
        if (format == null) {
            for (int i = 0; i < missions.size(); i++) {
                Mission m = missions.get(i);
                List<MissionItem> items = itemLists.get(i);
                if (i > 0) {
                    stdout.println();
                }
                stdout.println("mission " + m.getId() + ": " + items.size() + " items (item 0 is the home"
                        + (m.getHome() == null ? ": the first position, the mission names none" : "") + ")");
                stdout.print(MissionTable.format(items));
                CoverageLines.of(m).forEach(stdout::println);
                if (!m.fence().isEmpty()) {
                    stdout.println("fence of " + m.getId() + ": " + m.fence().describe()
                            + (m.fenceEnabled() ? ", enabled at the start" : ", not enabled by the mission"));
                    stdout.print(MissionTable.format(m.fence().items()));
                }
                if (!m.rally().isEmpty()) {
                    stdout.println("rally points of " + m.getId() + ": " + m.rally().size());
                    stdout.print(MissionTable.format(m.rally().items()));
                }
            }
            stdout.flush();
            return 0;
        }
        Set<String> taken = new HashSet<>();
        for (int i = 0; i < missions.size(); i++) {
            Mission m = missions.get(i);
            MissionFile contents = MissionFile.of(m, itemLists.get(i));
            String base = fileName(m.getId());
            Map<Path, String> files = new LinkedHashMap<>();
            try {
                files.put(dir.resolve(uniqueName(base, format.extension(), taken)), format.write(m.getId(), contents));
                if (format == MissionFormat.WAYPOINTS) {
                    // a QGC WPL file holds one kind of items: the fence and rally points get files of their own
                    if (!m.fence().isEmpty()) {
                        files.put(dir.resolve(uniqueName(base + ".fence", format.extension(), taken)),
                                WaypointsFile.writeItems(m.fence().items()));
                    }
                    if (!m.rally().isEmpty()) {
                        files.put(dir.resolve(uniqueName(base + ".rally", format.extension(), taken)),
                                WaypointsFile.writeItems(m.rally().items()));
                    }
                }
            } catch (IllegalArgumentException e) {
                err.println("dolphin mission: " + script + ": mission " + m.getId() + " cannot be written as "
                        + format + ": " + e.getMessage());
                return 1;
            }
            for (Map.Entry<Path, String> f : files.entrySet()) {
                try {
                    Files.writeString(f.getKey(), f.getValue(), StandardCharsets.UTF_8);
                } catch (IOException e) {
                    err.println("dolphin mission: cannot write " + f.getKey() + ": " + e.getMessage());
                    return Main.USAGE;
                }
                stdout.println(f.getKey());
            }
        }
        stdout.flush();
        return 0;
    }

    /** The --out directory (created if missing), or null after saying why it cannot be written to. */
    private Path outputDirectory(PrintWriter err) {
        Path dir = out == null ? Path.of("") : out;
        String shown = out == null ? "the current directory" : out.toString();
        try {
            Files.createDirectories(dir.toAbsolutePath());
        } catch (IOException e) {
            err.println("dolphin mission: cannot create the directory " + shown + ": " + describe(e));
            return null;
        }
        if (!Files.isWritable(dir.toAbsolutePath())) {
            err.println("dolphin mission: cannot write to " + shown + ": permission denied");
            return null;
        }
        return dir;
    }

    /**
     * Runs the script without vehicles and returns the missions it built, in order (each once), or
     * null after printing the script's error (file:line).
     */
    private List<Mission> dryRun(String source, PrintWriter err) throws InterruptedException {
        DryRun run = DryRun.of(source, script.toString(), java.time.Duration.ofMillis((long) (timeLimit * 1000)));
        ScriptResult result = run.result();
        if (result == null) {
            err.println("dolphin mission: " + script + ": the dry run was stopped after " + timeLimit
                    + " s (a script that loops without picking vehicles does not end without them); "
                    + run.missions().size() + " mission(s) built by then");
            err.flush();
            return null;
        }
        String error = run.error();
        // The script's own messages (and the engine's notes), on standard error: standard output is the tables.
        run.messages().stream().filter(m -> !m.equals(error)).forEach(err::println);
        switch (result.outcome()) {
            case SCRIPT_ERROR -> {
                err.println(error != null ? error : script + ": " + result.message());
                err.flush();
                return null;
            }
            case TASK_ERROR, STOPPED -> {
                err.println("dolphin mission: " + script + ": " + result.message());
                err.flush();
                return null;
            }
            case HALTED -> err.println("dolphin mission: the dry run stops there: it has no vehicles to pick; "
                    + run.missions().size() + " mission(s) built before it");
            default -> {
            }
        }
        err.flush();
        return run.missions();
    }

    /** A mission's name as a file name: letters, digits, '.', '_' and '-' kept, runs of others as '_'. */
    static String fileName(String missionName) {
        String s = missionName == null ? "" : missionName.strip().replaceAll("[^A-Za-z0-9._-]+", "_");
        s = s.replaceAll("^[._]+", "").replaceAll("_+$", "");
        return s.isEmpty() ? "mission" : s;
    }

    /** base + extension, or base-2, base-3, ... when taken (case-insensitively: some file systems ignore case). */
    static String uniqueName(String base, String extension, Set<String> taken) {
        String name = base + extension;
        for (int n = 2; !taken.add(name.toLowerCase(Locale.ROOT)); n++) {
            name = base + "-" + n + extension;
        }
        return name;
    }

    private static String describe(IOException e) {
        if (e instanceof java.nio.file.FileAlreadyExistsException) {
            return "a file of that name is in the way";
        }
        if (e instanceof java.nio.file.AccessDeniedException) {
            return "permission denied";
        }
        return e.getMessage();
    }
}
