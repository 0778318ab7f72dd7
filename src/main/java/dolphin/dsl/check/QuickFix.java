package dolphin.dsl.check;

/**
 * A correction an editor can apply to a script: the text from {@code line:column} up to
 * {@code endLine:endColumn} (1-based, the end excluded, as Groovy's syntax tree counts) replaced by
 * {@code replacement}, with a title that says what it does.
 */
public record QuickFix(String title, int line, int column, int endLine, int endColumn, String replacement) {

    /** A name on one line replaced by another: "Change 'mvoe' to 'move'". */
    public static QuickFix rename(int line, int column, String name, String replacement) {
        return new QuickFix("Change '" + name + "' to '" + replacement + "'", line, column, line, column + name.length(), replacement);
    }
}
