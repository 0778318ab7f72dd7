package dolphin.dsl.vocabulary;

import groovy.lang.DelegatesTo;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.lang.reflect.Parameter;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.TreeSet;

/**
 * Every word of the language, where it may be written and its forms, read from the public methods
 * marked {@link Word}: the script's base class and the platform's word classes give the top-level
 * words; a closure parameter that names the class of its words ({@code @DelegatesTo}) opens a block
 * of that class's words; a word that returns an object with words of its own ({@code waitFor} gives
 * {@code then}) leads to them; the categories' {@code getX} methods are the units. The checker, the
 * language server, the GDSL file and {@code dolphin words} all read this one description.
 */
public final class Vocabulary {

    private final WordScope script;
    private final WordScope units;
    private final Map<Class<?>, WordScope> byType;

    private Vocabulary(WordScope script, WordScope units, Map<Class<?>, WordScope> byType) {
        this.script = script;
        this.units = units;
        this.byType = byType;
    }

    /**
     * Reads the vocabulary.
     *
     * @param scriptClass the scripts' base class
     * @param wordClasses the classes whose words scripts may also write at the top level: the
     *                    platform's word objects and the classes whose static methods are imported
     * @param categories the category classes whose {@code getX(Number)} methods are units
     */
    public static Vocabulary of(Class<?> scriptClass, List<Class<?>> wordClasses, List<Class<?>> categories) {
        Map<String, WordEntry> top = new LinkedHashMap<>(wordsOf(scriptClass));
        for (Class<?> c : wordClasses) {
            wordsOf(c).forEach(top::putIfAbsent);
        }
        WordScope script = new WordScope(WordScope.ScopeKind.SCRIPT, scriptClass, List.of(), top);
        Map<String, WordEntry> unitWords = new LinkedHashMap<>();
        for (Class<?> c : categories) {
            unitWords.putAll(unitsOf(c));
        }
        WordScope units = new WordScope(WordScope.ScopeKind.UNITS, Number.class, List.of(), unitWords);

        // Blocks and chains, found from the words that open them, breadth first.
        Map<Class<?>, List<String>> openers = new LinkedHashMap<>();
        Map<Class<?>, WordScope.ScopeKind> kinds = new LinkedHashMap<>();
        Deque<Map<String, WordEntry>> pending = new ArrayDeque<>(List.of(top));
        while (!pending.isEmpty()) {
            for (WordEntry w : pending.poll().values()) {
                for (Signature s : w.signatures()) {
                    for (Param p : s.params()) {
                        if (p.block() != null) {
                            reach(p.block(), WordScope.ScopeKind.BLOCK, w.name(), openers, kinds, pending);
                        }
                    }
                    if (s.returns() != scriptClass && hasWords(s.returns())) {
                        reach(s.returns(), WordScope.ScopeKind.CHAIN, w.name(), openers, kinds, pending);
                    }
                }
            }
        }
        Map<Class<?>, WordScope> byType = new LinkedHashMap<>();
        byType.put(scriptClass, script);
        openers.forEach((type, names) -> byType.put(type, new WordScope(kinds.get(type), type, names, wordsOf(type))));
        return new Vocabulary(script, units, byType);
    }

    private static void reach(Class<?> type, WordScope.ScopeKind kind, String opener, Map<Class<?>, List<String>> openers,
                              Map<Class<?>, WordScope.ScopeKind> kinds, Deque<Map<String, WordEntry>> pending) {
        List<String> names = openers.get(type);
        if (names == null) {
            names = new ArrayList<>();
            openers.put(type, names);
            kinds.put(type, kind);
            pending.add(wordsOf(type));
        }
        if (!names.contains(opener)) {
            names.add(opener);
        }
    }

    /** The script's top-level words (also visible inside every block, after the block's own). */
    public WordScope script() {
        return script;
    }

    /** The units: {@code 10.minutes}, {@code 2.km}. */
    public WordScope units() {
        return units;
    }

    /** The scope whose words are the methods of this class: the script's, a block's or a chain's. */
    public Optional<WordScope> scopeOf(Class<?> type) {
        return Optional.ofNullable(byType.get(type));
    }

    /** Every scope: the script first, then blocks and chains as they were found, then the units. */
    public List<WordScope> scopes() {
        List<WordScope> all = new ArrayList<>(byType.values());
        all.add(units);
        return all;
    }

    /** The scopes that have a word of this name. */
    public List<WordScope> scopesWith(String name) {
        return scopes().stream().filter(s -> s.words().containsKey(name)).toList();
    }

    /** Every word's name, in all scopes, sorted. */
    public List<String> names() {
        TreeSet<String> names = new TreeSet<>();
        scopes().forEach(s -> names.addAll(s.words().keySet()));
        return List.copyOf(names);
    }

    static boolean hasWords(Class<?> type) {
        return !type.isPrimitive() && Arrays.stream(type.getMethods()).anyMatch(m -> m.isAnnotationPresent(Word.class));
    }

    /** The class's words: its public methods marked {@link Word}, grouped by name. */
    public static Map<String, WordEntry> wordsOf(Class<?> type) {
        Map<String, List<Method>> byName = new LinkedHashMap<>();
        Arrays.stream(type.getMethods())
                .filter(m -> m.isAnnotationPresent(Word.class) && !m.isBridge())
                .sorted(Comparator.comparing(Method::getName).thenComparingInt(Method::getParameterCount))
                .forEach(m -> byName.computeIfAbsent(m.getName(), k -> new ArrayList<>()).add(m));
        Map<String, WordEntry> words = new LinkedHashMap<>();
        byName.forEach((name, methods) -> words.put(name, new WordEntry(name, description(methods),
                methods.stream().map(Vocabulary::signature).distinct().toList(), false)));
        return words;
    }

    private static Map<String, WordEntry> unitsOf(Class<?> category) {
        Map<String, WordEntry> words = new LinkedHashMap<>();
        Arrays.stream(category.getMethods())
                .filter(m -> m.isAnnotationPresent(Word.class) && Modifier.isStatic(m.getModifiers())
                        && m.getName().startsWith("get") && m.getParameterCount() == 1)
                .sorted(Comparator.comparing(Method::getName))
                .forEach(m -> {
                    String name = Character.toLowerCase(m.getName().charAt(3)) + m.getName().substring(4);
                    words.put(name, new WordEntry(name, m.getAnnotation(Word.class).value(), List.of(), true));
                });
        return words;
    }

    /** The description of a word written in several methods: the first that says more than the others. */
    private static String description(List<Method> methods) {
        return methods.stream().map(m -> m.getAnnotation(Word.class).value())
                .max(Comparator.comparingInt(String::length)).orElse("");
    }

    private static Signature signature(Method m) {
        List<Param> params = new ArrayList<>();
        for (Parameter p : m.getParameters()) {
            if (!p.isNamePresent()) {
                throw new IllegalStateException(m + ": compiled without parameter names (javac -parameters, groovyc --parameters)");
            }
            DelegatesTo d = p.getAnnotation(DelegatesTo.class);
            Class<?> block = d == null || d.value() == DelegatesTo.Target.class ? null : d.value();
            String unit = ParamUnits.of(p.getName(), p.getType());
            params.add(new Param(p.getName(), p.getType(), unit == null ? "" : unit, block));
        }
        return new Signature(params, m.isVarArgs(), m.getReturnType());
    }

    /** The number parameters of words whose unit {@link ParamUnits} does not know: a new word must say. */
    public List<String> parametersWithoutUnits() {
        List<String> missing = new ArrayList<>();
        for (WordScope s : scopes()) {
            s.words().values().forEach(w -> w.signatures().forEach(sig -> sig.params().forEach(p -> {
                if (ParamUnits.of(p.name(), p.type()) == null) {
                    missing.add(s.type().getSimpleName() + "." + w.name() + "(" + p.name() + ")");
                }
            })));
        }
        return missing;
    }
}
