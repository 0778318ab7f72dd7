package dolphin.dsl.check;

import dolphin.dsl.vocabulary.Suggestions;
import dolphin.dsl.vocabulary.Vocabulary;
import dolphin.dsl.vocabulary.WordEntry;
import dolphin.dsl.vocabulary.WordScope;
import groovy.lang.Closure;
import groovy.lang.MetaMethod;
import java.util.Arrays;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.stream.Collectors;
import org.codehaus.groovy.ast.ClassNode;

/**
 * What the check says of each mistake: the forms a word takes, where a word belongs, the names
 * that were probably meant. {@code visible} is always the scopes a name reaches where the mistake
 * is, innermost first.
 */
final class FindingMessages {

    private final Vocabulary vocabulary;
    private final Assignments assignments;
    private final Set<String> variables;
    private final ClassNode script;

    FindingMessages(Vocabulary vocabulary, Assignments assignments, Set<String> variables, ClassNode script) {
        this.vocabulary = vocabulary;
        this.assignments = assignments;
        this.variables = variables;
        this.script = script;
    }

    /** "goPos: expected (lat, lon[, hae]) or (position), got (String)", with a hint for a position. */
    String wrongArguments(String name, Class<?> owner, List<MetaMethod> named, Class<?>[] argTypes, List<WordScope> visible) {
        WordEntry word = vocabulary.scopeOf(owner).map(s -> s.words().get(name))
                .orElseGet(() -> vocabulary.script().words().get(name));
        String forms = word != null ? word.formsText() : named.stream()
                .map(m -> Arrays.stream(m.getNativeParameterTypes()).map(Class::getSimpleName).collect(Collectors.joining(", ", "(", ")")))
                .distinct().collect(Collectors.joining(" or "));
        String got = Arrays.stream(argTypes).map(t -> t == null ? "?" : t == java.util.LinkedHashMap.class ? "Map"
                : t == java.util.ArrayList.class ? "List" : groovy.lang.GString.class.isAssignableFrom(t) ? "String"
                : Closure.class.isAssignableFrom(t) ? "{ block }" : t.getSimpleName()).collect(Collectors.joining(", ", "(", ")"));
        boolean positionWanted = named.stream().anyMatch(m -> Arrays.stream(m.getNativeParameterTypes())
                .anyMatch(t -> t.getSimpleName().equals("Position")));
        boolean numberGiven = Arrays.stream(argTypes).anyMatch(ExpressionTypes::isNumber);
        String hint = positionWanted && numberGiven && argTypes.length <= 2
                ? "; a position is pos { lat ...; lon ...; hae ... } or location(lat, lon, hae)" : "";
        return name + ": expected " + forms + ", got " + got + hint + elsewhereForm(name, argTypes.length, visible);
    }

    /** "; move(north, east[, up]) can only be used inside mission { }": the word of a block not open here that takes as many arguments. */
    private String elsewhereForm(String name, int arguments, List<WordScope> visible) {
        for (WordScope s : vocabulary.scopesWith(name)) {
            WordEntry w = s.words().get(name);
            if (!visible.contains(s) && w.takes(arguments)) {
                return "; " + String.join(" or ", w.usages()) + " can only be used " + s.where();
            }
        }
        return "";
    }

    /** A name nothing answers: where it belongs if it is a word elsewhere, else what it may have meant. */
    FindingText missing(String name, List<WordScope> visible) {
        List<WordScope> elsewhere = vocabulary.scopesWith(name).stream().filter(s -> !visible.contains(s)).toList();
        if (!elsewhere.isEmpty()) {
            return FindingText.of(belongsElsewhere(name, elsewhere.get(0)));
        }
        WordScope innermost = visible.get(0);
        String kind = innermost.kind() == WordScope.ScopeKind.BLOCK ? " in " + String.join(" / ",
                innermost.openers().stream().map(o -> o + " { }").toList()) : "";
        List<String> near = Suggestions.near(name, innermost.words().keySet());
        if (near.isEmpty()) {
            near = Suggestions.near(name, visibleNames(visible));
        }
        if (near.isEmpty()) {
            return elsewhereNear(name, visible, "unknown command '" + name + "'" + kind);
        }
        return new FindingText("unknown command '" + name + "'" + kind + Suggestions.didYouMean(near), near);
    }

    /** "; did you mean 'takeOff'? It can only be used inside mission { }": a word of a block not open here. */
    private FindingText elsewhereNear(String name, List<WordScope> visible, String unknown) {
        for (WordScope s : vocabulary.scopes()) {
            if (visible.contains(s)) {
                continue;
            }
            List<String> close = Suggestions.near(name, s.words().keySet());
            if (!close.isEmpty()) {
                return new FindingText(unknown + "; did you mean '" + close.get(0) + "'? It " + belongsElsewhere(close.get(0), s)
                        .replaceFirst("^'[^']*' (is|can)", "$1"), List.of(close.get(0)));
            }
        }
        return FindingText.of(unknown);
    }

    private static String belongsElsewhere(String name, WordScope scope) {
        return switch (scope.kind()) {
            case UNITS -> "'" + name + "' is a unit: write it after a number, as in 10." + name;
            case CHAIN -> "'" + name + "' can only follow " + String.join(" or ", scope.openers());
            default -> "'" + name + "' can only be used " + scope.where();
        };
    }

    FindingText unknownName(String name, List<WordScope> visible) {
        for (WordScope s : visible) {
            if (s.words().containsKey(name)) {
                return FindingText.of(s.kind() == WordScope.ScopeKind.SCRIPT
                        ? "'" + name + "' is a command, but Groovy read it as a variable here. Expected it with its arguments,"
                        + " e.g. '" + name + "()', and in parentheses when it is the argument of another command,"
                        + " e.g. 'execute(during(10) run task)'"
                        : "'" + name + "' is a command of " + s.where().replaceFirst("^inside ", "") + ", but Groovy read it as a"
                        + " variable here: write it with its arguments, as in " + String.join(" or ", s.words().get(name).usages())
                        + (s.words().get(name).takes(0) ? "" : "; a negative value needs parentheses, '" + name + "(-2)' (Groovy reads '"
                        + name + " -2' as '" + name + " minus 2')"));
            }
        }
        List<WordScope> elsewhere = vocabulary.scopesWith(name);
        if (!elsewhere.isEmpty()) {
            return FindingText.of(belongsElsewhere(name, elsewhere.get(0)));
        }
        Integer local = assignments.localLines.get(name);
        String hint = local != null
                ? ": it is declared with 'def' on line " + local + ", which the script's methods cannot see;"
                + " assign it without 'def' to make it a script variable"
                : ". Expected a variable assigned in the script (names are case-sensitive)";
        Set<String> known = new LinkedHashSet<>(variables);
        known.addAll(assignments.localLines.keySet());
        List<String> near = Suggestions.near(name, known);
        return new FindingText("unknown name '" + name + "'" + Suggestions.didYouMean(near) + hint, near);
    }

    /** "'thne' cannot follow waitFor or when: expected 'then'". */
    FindingText wrongFollower(WordScope chain, String name) {
        String expected = String.join(" or ", chain.words().keySet());
        List<String> near = Suggestions.near(name, chain.words().keySet());
        return new FindingText("'" + name + "' cannot follow " + String.join(" or ", chain.openers()) + ": expected '" + expected + "'"
                + (near.isEmpty() ? "" : ", did you mean it?"), near);
    }

    FindingText unknownUnit(String name) {
        List<String> near = Suggestions.near(name, vocabulary.units().words().keySet());
        return new FindingText("unknown unit '" + name + "'" + Suggestions.didYouMean(near)
                + " Units: " + String.join(", ", vocabulary.units().words().keySet()), near);
    }

    private Set<String> visibleNames(List<WordScope> visible) {
        Set<String> names = new LinkedHashSet<>();
        visible.forEach(s -> names.addAll(s.words().keySet()));
        script.getMethods().stream().filter(m -> m.getLineNumber() > 0 && m.getDeclaringClass().equals(script)).forEach(m -> names.add(m.getName()));
        names.addAll(variables);
        return names;
    }

}
