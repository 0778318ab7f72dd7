package dolphin.editor;

import dolphin.dsl.vocabulary.Param;
import dolphin.dsl.vocabulary.WordEntry;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;

/** How the editor shows a word: its usages, and the units of its number parameters. */
final class WordText {

    private WordText() {
    }

    /** {@code goPos(lat, lon[, hae]) or goPos(position)}. */
    static String usages(WordEntry word) {
        return String.join(" or ", word.usages());
    }

    /** The units of the word's parameters, names that share one together: {@code lat, lon: degrees; hae: metres above mean sea level}. */
    static String units(WordEntry word) {
        Map<String, List<String>> byUnit = new LinkedHashMap<>();
        word.signatures().forEach(s -> s.params().forEach(p -> {
            if (!p.unit().isEmpty()) {
                List<String> names = byUnit.computeIfAbsent(p.unit(), u -> new ArrayList<>());
                if (!names.contains(p.name())) {
                    names.add(p.name());
                }
            }
        }));
        return byUnit.entrySet().stream().map(e -> String.join(", ", e.getValue()) + ": " + e.getKey())
                .collect(Collectors.joining("; "));
    }

    /** The unit of the word's parameter of this name, "" for none. */
    static String unitOf(WordEntry word, String parameter) {
        return word.signatures().stream().flatMap(s -> s.params().stream()).filter(p -> p.name().equals(parameter))
                .map(Param::unit).filter(u -> !u.isEmpty()).findFirst().orElse("");
    }
}
