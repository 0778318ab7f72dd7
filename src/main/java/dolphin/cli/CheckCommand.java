package dolphin.cli;

import dolphin.core.VehiclelessPlatform;
import dolphin.dsl.Engine;
import dolphin.dsl.ScriptError;
import dolphin.platform.MAVLinkLanguage;
import dolphin.sensor.FleetFile;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code dolphin check SCRIPT...}: compiles scripts and prints their mistakes as file:line:column: message. */
@Command(name = "check", mixinStandardHelpOptions = true,
        description = {"Compiles scripts and prints their errors as file:line:column: message.",
                "Every name is looked up as the script will when it runs: unknown words (with did you mean), wrong "
                        + "arguments, a block's words outside it, unknown units, variables never assigned; all at once.",
                "A script without such mistakes is then rehearsed without vehicles: its picks give stand-ins, its "
                        + "executes run nothing, so that its missions are built and their mistakes (an item below home) "
                        + "found too, up to the first word that needs a vehicle's telemetry.",
                "Exit 0 when every script is correct, 1 when one has errors, 2 when a script cannot be read."})
final class CheckCommand implements Callable<Integer> {

    /** A script that loops without picking vehicles never ends without them: what it built by then is checked. */
    private static final Duration DRY_RUN_LIMIT = Duration.ofSeconds(10);

    @Spec
    private CommandSpec spec;

    @Parameters(arity = "1..*", paramLabel = "SCRIPT", description = "The .dolphin scripts to check.")
    private List<Path> scripts = new ArrayList<>();

    @Option(names = "--fleet", paramLabel = "FILE", converter = Converters.FleetFileConverter.class,
            description = "A fleet file: the sensors it lists are the names sensor(v, 'NAME') may read (docs/sensors.md).")
    private FleetFile fleet = FleetFile.NONE;

    @Override
    public Integer call() throws InterruptedException {
        PrintWriter err = spec.commandLine().getErr();
        Engine engine = new Engine(new VehiclelessPlatform("dry run"));
        engine.addExtension(new MAVLinkLanguage(fleet));
        int code = 0;
        for (Path script : scripts) {
            String source = Main.readScript("check", script, err);
            if (source == null) {
                return Main.USAGE;
            }
            List<ScriptError> errors = engine.check(source, script.toString());
            errors.forEach(err::println);
            if (!errors.isEmpty()) {
                code = 1;
            } else {
                String missionError = DryRun.of(source, script.toString(), DRY_RUN_LIMIT, true).error();
                if (missionError != null) {
                    err.println(missionError);
                    code = 1;
                }
            }
        }
        err.flush();
        return code;
    }
}
