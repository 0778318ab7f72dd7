package dolphin.cli;

import dolphin.dsl.Engine;
import dolphin.dsl.ScriptError;
import dolphin.mavlink.MAVLinkLanguage;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code dolphin check SCRIPT...}: compiles scripts and prints their mistakes as file:line:column: message. */
@Command(name = "check", mixinStandardHelpOptions = true,
        description = "Compiles scripts without running them and prints their errors as file:line:column: message. "
                + "Exit 0 when every script compiles, 1 when one has errors, 2 when a script cannot be read.")
final class CheckCommand implements Callable<Integer> {

    @Spec
    private CommandSpec spec;

    @Parameters(arity = "1..*", paramLabel = "SCRIPT", description = "The .dolphin scripts to check.")
    private List<Path> scripts = new ArrayList<>();

    @Override
    public Integer call() {
        PrintWriter err = spec.commandLine().getErr();
        Engine engine = new Engine(new DryRunPlatform());
        engine.addExtension(new MAVLinkLanguage());
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
            }
        }
        err.flush();
        return code;
    }
}
