package dolphin.editor;

import dolphin.core.VehiclelessPlatform;
import dolphin.dsl.Engine;
import dolphin.dsl.ScriptError;
import dolphin.platform.MAVLinkLanguage;
import dolphin.dsl.check.QuickFix;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.eclipse.lsp4j.CodeAction;
import org.eclipse.lsp4j.CodeActionKind;
import org.eclipse.lsp4j.Diagnostic;
import org.eclipse.lsp4j.DiagnosticSeverity;
import org.eclipse.lsp4j.Range;
import org.eclipse.lsp4j.TextEdit;
import org.eclipse.lsp4j.WorkspaceEdit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A script's mistakes as editor diagnostics: what {@code dolphin check} finds by compiling it
 * ({@link Engine#check}), without the rehearsal, which would run the script's code. A script too large
 * to check at typing speed, or one the compiler fails on, gets one diagnostic saying so: bad input
 * never ends the server. Each diagnostic comes with the corrections the check knows, as quick fixes.
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

    List<FixableDiagnostic> check(OpenDocument document) {
        String text = document.text();
        LineMap lines = document.lines();
        if (text.length() > MAX_CHARACTERS) {
            return List.of(unfixable(new Range(lines.position(0), lines.position(lines.lineEnd(0))),
                    "not checked: the script has " + text.length() + " characters, more than the "
                            + MAX_CHARACTERS + " the editor checks as you type; run dolphin check on it"));
        }
        List<ScriptError> errors;
        try {
            errors = engine.check(text, fileName(document.uri()));
        } catch (RuntimeException | StackOverflowError e) {
            LOG.warn("checking {} failed", document.uri(), e);
            return List.of(unfixable(new Range(lines.position(0), lines.position(lines.lineEnd(0))),
                    "the checker failed on this script: " + e));
        }
        List<FixableDiagnostic> found = new ArrayList<>();
        for (ScriptError e : errors) {
            Diagnostic d = diagnostic(ErrorRange.of(e, text, lines), e.message());
            found.add(new FixableDiagnostic(d, e.fixes().stream().map(f -> action(f, d, document, e.fixes().size() == 1)).toList()));
        }
        return found;
    }

    private static FixableDiagnostic unfixable(Range range, String message) {
        return new FixableDiagnostic(diagnostic(range, message), List.of());
    }

    private static Diagnostic diagnostic(Range range, String message) {
        return new Diagnostic(range, message, DiagnosticSeverity.Error, "dolphin");
    }

    /** A fix as the protocol's quick fix of its diagnostic: one edit of the checked text; the only fix is the preferred one. */
    private static CodeAction action(QuickFix fix, Diagnostic d, OpenDocument document, boolean only) {
        LineMap lines = document.lines();
        Range range = new Range(lines.position(offset(lines, fix.line(), fix.column())),
                lines.position(offset(lines, fix.endLine(), fix.endColumn())));
        CodeAction action = new CodeAction(fix.title());
        action.setKind(CodeActionKind.QuickFix);
        action.setDiagnostics(List.of(d));
        action.setEdit(new WorkspaceEdit(Map.of(document.uri(), List.of(new TextEdit(range, fix.replacement())))));
        action.setIsPreferred(only);
        return action;
    }

    /** The offset of a 1-based line and column, kept on the text. */
    private static int offset(LineMap lines, int line, int column) {
        int l = Math.min(Math.max(line, 1), lines.lineCount()) - 1;
        return Math.min(lines.lineStart(l) + Math.max(column, 1) - 1, lines.lineEnd(l));
    }

    /** The name messages give the script: the last part of its URI. */
    static String fileName(String uri) {
        String path = uri.replace('\\', '/');
        return path.substring(path.lastIndexOf('/') + 1);
    }
}
