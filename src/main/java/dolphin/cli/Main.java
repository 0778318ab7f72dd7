package dolphin.cli;

import java.io.PrintWriter;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

/** The {@code dolphin} command. Exit codes: 0 done, 1 script or task error, 2 usage error. */
@Command(name = "dolphin", mixinStandardHelpOptions = true, versionProvider = Main.Version.class,
        description = "Runs Dolphin scripts that orchestrate vehicles.",
        subcommands = {RunCommand.class, SimCommand.class, CheckCommand.class, MissionCommand.class,
                CommandLine.HelpCommand.class, WordsCommand.class, LspCommand.class})
public final class Main implements Runnable {

    public static final int USAGE = 2;

    @Spec
    private CommandSpec spec;

    @Override
    public void run() {
        throw new ParameterException(spec.commandLine(), "Missing command: expected one of "
                + String.join(", ", spec.subcommands().keySet()));
    }

    public static void main(String[] args) {
        quietLogs();
        System.exit(commandLine(new PrintWriter(System.out, true), new PrintWriter(System.err, true)).execute(args));
    }

    /** Short log lines on standard error (link events, discovered vehicles), unless the user configured logging. */
    private static void quietLogs() {
        String prefix = "org.slf4j.simpleLogger.";
        java.util.Map.of("showThreadName", "false", "showLogName", "false", "showDateTime", "true",
                "dateTimeFormat", "HH:mm:ss", "levelInBrackets", "true")
                .forEach((k, v) -> {
                    if (System.getProperty(prefix + k) == null) {
                        System.setProperty(prefix + k, v);
                    }
                });
    }

    /** The command line with its output streams, so tests can run it in process. */
    public static CommandLine commandLine(PrintWriter out, PrintWriter err) {
        CommandLine cl = new CommandLine(new Main());
        cl.setOut(out);
        cl.setErr(err);
        cl.setExitCodeExceptionMapper(e -> e instanceof ParameterException ? USAGE : 1);
        return cl;
    }

    /** The script's text, or null after telling why it cannot be read (a usage error). */
    static String readScript(String command, java.nio.file.Path script, PrintWriter err) {
        try {
            return java.nio.file.Files.readString(script, java.nio.charset.StandardCharsets.UTF_8);
        } catch (java.nio.file.NoSuchFileException e) {
            err.println("dolphin " + command + ": cannot read " + script + ": no such file");
        } catch (java.io.IOException e) {
            err.println("dolphin " + command + ": cannot read " + script + ": " + e.getMessage());
        }
        err.flush();
        return null;
    }

    /** Rejects a speed-up that is not a positive, finite number: a usage error. */
    static void checkSpeedup(CommandSpec spec, double speedup) {
        if (!(speedup > 0) || Double.isInfinite(speedup)) {
            throw new ParameterException(spec.commandLine(), "--speedup must be a positive number, got " + speedup);
        }
    }

    static final class Version implements CommandLine.IVersionProvider {
        @Override
        public String[] getVersion() {
            String v = Main.class.getPackage().getImplementationVersion();
            return new String[] {"dolphin " + (v == null ? "(development build)" : v)};
        }
    }
}
