package dolphin.editor;

import dolphin.core.VehiclelessPlatform;
import dolphin.dsl.Engine;
import dolphin.dsl.ScriptError;
import dolphin.platform.MAVLinkLanguage;
import java.util.ArrayList;
import java.util.List;
import org.eclipse.lsp4j.Diagnostic;
import org.eclipse.lsp4j.DiagnosticSeverity;
import org.eclipse.lsp4j.Range;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A script's mistakes as editor diagnostics: what {@code dolphin check} finds by compiling it
 * ({@link Engine#check}), without the rehearsal, which would run the script's code. A script too large
 * to check at typing speed, or one the compiler fails on, gets one diagnostic saying so: bad input
 * never ends the server.
 */
final class ScriptChecker {

    private static final Logger LOG = LoggerFactory.getLogger(ScriptChecker.class);

    /** About 30,000 lines; a 10,000-line script takes about half a second to check. */
    static final int MAX_CHARACTERS = 1_000_000;

    private final Engine engine;

    ScriptChecker(Engine engine) {
        this.engine = engine;
    }

    /** An engine with the words of the MAVLink platform, as {@code dolphin check} uses. */
    static ScriptChecker withMavlinkWords() {
        Engine engine = new Engine(new VehiclelessPlatform("editor"));
        engine.addExtension(new MAVLinkLanguage());
        return new ScriptChecker(engine);
    }

    Engine engine() {
        return engine;
    }

    List<Diagnostic> check(OpenDocument document) {
        String text = document.text();
        LineMap lines = document.lines();
        if (text.length() > MAX_CHARACTERS) {
            return List.of(diagnostic(new Range(lines.position(0), lines.position(lines.lineEnd(0))),
                    "not checked: the script has " + text.length() + " characters, more than the "
                            + MAX_CHARACTERS + " the editor checks as you type; run dolphin check on it"));
        }
        List<ScriptError> errors;
        try {
            errors = engine.check(text, fileName(document.uri()));
        } catch (RuntimeException | StackOverflowError e) {
            LOG.warn("checking {} failed", document.uri(), e);
            return List.of(diagnostic(new Range(lines.position(0), lines.position(lines.lineEnd(0))),
                    "the checker failed on this script: " + e));
        }
        List<Diagnostic> found = new ArrayList<>();
        for (ScriptError e : errors) {
            found.add(diagnostic(ErrorRange.of(e, text, lines), e.message()));
        }
        return found;
    }

    private static Diagnostic diagnostic(Range range, String message) {
        return new Diagnostic(range, message, DiagnosticSeverity.Error, "dolphin");
    }

    /** The name messages give the script: the last part of its URI. */
    static String fileName(String uri) {
        String path = uri.replace('\\', '/');
        return path.substring(path.lastIndexOf('/') + 1);
    }
}
