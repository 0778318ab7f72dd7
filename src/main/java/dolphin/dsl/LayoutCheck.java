package dolphin.dsl;

import dolphin.dsl.check.QuickFix;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Pattern;

/**
 * Finds {@code execute} standing alone on a line, as the report prints its four-vehicle example.
 * Groovy ends the statement at the line break, so the {@code v1: ...} entries below it become
 * labels and the script fails with an obscure message or, worse, runs nothing. Read from the text:
 * such a script often does not parse ({@code v1: a, v2: b} is no statement). The fix joins the lines.
 */
final class LayoutCheck {

    private static final Pattern BARE_EXECUTE = Pattern.compile("^\\s*execute\\s*(//.*)?$");
    private static final Pattern ENTRY = Pattern.compile("^\\s*[A-Za-z_$][\\w$]*\\s*:.*");

    private LayoutCheck() {
    }

    static List<ScriptError> check(String source, String file) {
        List<ScriptError> errors = new ArrayList<>();
        String[] lines = source.split("\\R", -1);
        for (int i = 0; i < lines.length; i++) {
            if (!BARE_EXECUTE.matcher(lines[i]).matches()) {
                continue;
            }
            String next = nextCodeLine(lines, i + 1);
            String entry = next != null && ENTRY.matcher(next).matches()
                    ? " the '" + next.strip().split("\\s*:")[0] + ":' entry on the next line is not its argument."
                    : "";
            errors.add(new ScriptError(file, i + 1, lines[i].indexOf("execute") + 1,
                    "'execute' stands alone on its line, so it has no task:" + entry
                    + " Groovy ends a statement at the line break. Expected the first task on the same line,"
                    + " e.g. 'execute v1: task1,' with further 'v2: task2' entries on the next lines.", joined(lines, i)));
        }
        return errors;
    }

    /** The fix: the next line moved up behind 'execute', when it comes right after it and no comment is in the way. */
    private static List<QuickFix> joined(String[] lines, int i) {
        String here = lines[i];
        if (here.contains("//") || i + 1 >= lines.length || lines[i + 1].isBlank() || lines[i + 1].strip().startsWith("//")) {
            return List.of();
        }
        int end = here.indexOf("execute") + "execute".length();
        int indent = lines[i + 1].length() - lines[i + 1].stripLeading().length();
        return List.of(new QuickFix("Join the next line to 'execute'", i + 1, end + 1, i + 2, indent + 1, " "));
    }

    private static String nextCodeLine(String[] lines, int from) {
        for (int j = from; j < lines.length; j++) {
            String t = lines[j].strip();
            if (!t.isEmpty() && !t.startsWith("//")) {
                return t;
            }
        }
        return null;
    }
}
