package dolphin.cli;

import dolphin.core.VehiclelessPlatform;
import dolphin.dsl.Engine;
import dolphin.dsl.vocabulary.Suggestions;
import dolphin.dsl.vocabulary.Vocabulary;
import dolphin.dsl.vocabulary.WordEntry;
import dolphin.dsl.vocabulary.WordScope;
import dolphin.editor.GdslFile;
import dolphin.platform.MAVLinkLanguage;
import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code dolphin words [SCOPE] [--gdsl]}: the words of the language, where they go and what they do. */
@Command(name = "words", mixinStandardHelpOptions = true,
        description = {"Lists the words of the language, where each may be written, how and what it does: at the "
                + "script's top level, inside each block (mission { }, pick { }, ...), after another word (then after "
                + "waitFor) and the units.",
                "Exit 0, or 2 for an unknown scope or a scope given with --gdsl."})
final class WordsCommand implements Callable<Integer> {

    /** Usages longer than this take a line of their own, so that the descriptions stay in one column. */
    private static final int USAGE_COLUMN = 44;

    @Spec
    private CommandSpec spec;

    @Parameters(arity = "0..1", paramLabel = "SCOPE",
            description = "Only this scope: script, units, or a word that opens a block or leads to words (mission, pick, "
                    + "fence, waitFor, ...).")
    private String scope;

    @Option(names = "--gdsl", description = "Print the GDSL file for IntelliJ IDEA instead (docs/dolphin.gdsl).")
    private boolean gdsl;

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        Engine engine = new Engine(new VehiclelessPlatform("dry run"));
        engine.addExtension(new MAVLinkLanguage());
        Vocabulary vocabulary = engine.vocabulary();
        if (gdsl) {
            if (scope != null) {
                err.println("dolphin words: --gdsl prints the whole file: give no scope");
                err.flush();
                return Main.USAGE;
            }
            out.print(GdslFile.of(vocabulary));
            out.flush();
            return 0;
        }
        Map<String, List<WordScope>> byName = scopesByName(vocabulary);
        List<WordScope> shown = scope == null ? vocabulary.scopes() : byName.get(scope);
        if (shown == null) {
            String near = Suggestions.didYouMean(scope, byName.keySet());
            err.println("dolphin words: unknown scope '" + scope + "'" + (near.isEmpty() ? "." : near)
                    + " Known scopes: " + String.join(", ", byName.keySet()));
            err.flush();
            return Main.USAGE;
        }
        out.print(listing(shown));
        out.flush();
        return 0;
    }

    /** The names a scope goes by: script, units, and each word that opens a block or leads to a chain. */
    private static Map<String, List<WordScope>> scopesByName(Vocabulary vocabulary) {
        Map<String, List<WordScope>> byName = new LinkedHashMap<>();
        byName.put("script", List.of(vocabulary.script()));
        for (WordScope s : vocabulary.scopes()) {
            s.openers().forEach(o -> byName.computeIfAbsent(o, k -> new ArrayList<>()).add(s));
        }
        byName.put("units", List.of(vocabulary.units()));
        return byName;
    }

    /** Each scope under its heading, each word's usages in one column and its description beside the first. */
    private static String listing(List<WordScope> scopes) {
        StringBuilder text = new StringBuilder();
        for (WordScope s : scopes) {
            if (!text.isEmpty()) {
                text.append('\n');
            }
            text.append(heading(s)).append('\n');
            int column = s.words().values().stream().flatMap(w -> w.usages().stream())
                    .mapToInt(String::length).filter(n -> n <= USAGE_COLUMN).max().orElse(0) + 4;
            for (WordEntry w : s.words().values()) {
                List<String> usages = w.usages();
                String first = "  " + usages.get(0);
                text.append(first);
                text.append(first.length() + 2 > column ? "\n" + " ".repeat(column) : " ".repeat(column - first.length()));
                text.append(w.description()).append('\n');
                usages.subList(1, usages.size()).forEach(u -> text.append("  ").append(u).append('\n'));
            }
        }
        return text.toString();
    }

    private static String heading(WordScope s) {
        if (s.kind() == WordScope.ScopeKind.UNITS) {
            return "Units, " + s.where();
        }
        String where = s.where();
        return Character.toUpperCase(where.charAt(0)) + where.substring(1);
    }
}
