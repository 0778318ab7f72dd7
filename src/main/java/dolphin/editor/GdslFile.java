package dolphin.editor;

import dolphin.dsl.vocabulary.Vocabulary;
import dolphin.dsl.vocabulary.WordEntry;
import dolphin.dsl.vocabulary.WordScope;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;

/**
 * The GDSL file (IntelliJ IDEA's Groovy DSL descriptor) for Dolphin scripts, written from the
 * {@link Vocabulary}: with {@code *.dolphin} files read as Groovy, IntelliJ's bundled Groovy plugin
 * completes the words and shows their parameters and lines (docs/editors.md, "IntelliJ without a
 * server: the GDSL file"). The jar ships it as {@value #RESOURCE}; {@code dolphin words --gdsl}
 * prints it.
 */
public final class GdslFile {

    /** Where the jar holds the file: IntelliJ reads every *.gdsl file of a library on the classpath. */
    public static final String RESOURCE = "dolphin/dolphin.gdsl";

    private static final String INDENT = "    ";

    private GdslFile() {
    }

    public static String of(Vocabulary vocabulary) {
        StringBuilder out = new StringBuilder();
        out.append("""
                // Dolphin's words for IntelliJ IDEA's Groovy plugin, in *.dolphin files read as Groovy
                // (docs/editors.md, "IntelliJ without a server: the GDSL file").
                // Written from the language's vocabulary by `dolphin words --gdsl`: do not edit.

                """);
        WordScope script = vocabulary.script();
        out.append("// The scripts' base class: its words (pick, execute, waitFor, ...) resolve as its methods, and the\n")
                .append("// words after them (then, run, onError) as methods of the classes they return.\n")
                .append("scriptSuperClass(pattern: ").append(GdslMember.literal(".*\\.dolphin"))
                .append(", superClass: ").append(GdslMember.literal(GdslMember.typeName(script.type()))).append(")\n\n")
                .append("def script = context(filetypes: ['dolphin'], scope: scriptScope())\n")
                .append("def block = context(filetypes: ['dolphin'], scope: closureScope())\n")
                .append("def number = context(filetypes: ['dolphin'], ctype: 'java.lang.Number')\n\n");

        Map<String, WordEntry> inherited = Vocabulary.wordsOf(script.type());
        List<WordEntry> added = script.words().values().stream().filter(w -> !inherited.containsKey(w.name())).toList();
        out.append("// The platform's words and those imported into every script\n")
                .append("contributor(script) {\n");
        added.forEach(w -> GdslMember.methods(w).forEach(m -> out.append(INDENT).append(m).append('\n')));
        out.append("}\n");

        for (WordScope s : vocabulary.scopes()) {
            if (s.kind() == WordScope.ScopeKind.BLOCK) {
                out.append('\n').append(block(s));
            }
        }

        out.append("\n// The units, ").append(vocabulary.units().where()).append('\n')
                .append("contributor(number) {\n");
        vocabulary.units().words().values().forEach(u -> out.append(INDENT).append(GdslMember.property(u)).append('\n'));
        return out.append("}\n").toString();
    }

    /** A block's words, inside the closure of any word that opens it. */
    private static String block(WordScope s) {
        String inside = s.openers().stream().map(o -> "enclosingCall(" + GdslMember.literal(o) + ")")
                .collect(Collectors.joining(" || "));
        StringBuilder out = new StringBuilder("// The words ").append(s.where()).append('\n')
                .append("contributor(block) {\n")
                .append(INDENT).append("if (").append(inside).append(") {\n");
        s.words().values().forEach(w -> GdslMember.methods(w).forEach(m -> out.append(INDENT).append(INDENT).append(m).append('\n')));
        return out.append(INDENT).append("}\n}\n").toString();
    }
}
