package dolphin.dsl;

import groovy.lang.Binding;
import groovy.lang.GroovyClassLoader;
import groovy.lang.GroovyCodeSource;
import groovy.lang.Script;
import dolphin.dsl.check.CallCheck;
import dolphin.dsl.check.FixableSyntaxException;
import dolphin.dsl.check.ScriptLanguage;
import dolphin.dsl.check.WordCheck;
import dolphin.dsl.vocabulary.Vocabulary;
import groovy.transform.ThreadInterrupt;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import org.codehaus.groovy.control.CompilationFailedException;
import org.codehaus.groovy.control.CompilationUnit;
import org.codehaus.groovy.control.Phases;
import org.codehaus.groovy.control.CompilerConfiguration;
import org.codehaus.groovy.control.MultipleCompilationErrorsException;
import org.codehaus.groovy.control.customizers.ASTTransformationCustomizer;
import org.codehaus.groovy.control.customizers.ImportCustomizer;
import org.codehaus.groovy.control.messages.ExceptionMessage;
import org.codehaus.groovy.control.messages.Message;
import org.codehaus.groovy.control.messages.SyntaxErrorMessage;
import org.codehaus.groovy.runtime.InvokerHelper;
import org.codehaus.groovy.syntax.SyntaxException;

/**
 * Compiles Dolphin scripts: imports, base class, the layout and execute checks, and the check of
 * every name against the language ({@link WordCheck}), so a script with a mistake is refused
 * before it runs, with all its mistakes.
 */
final class ScriptCompiler {

    static final String BASE_CLASS = "dolphin.dsl.DolphinScript";

    private final List<DslExtension> extensions;
    private final Set<String> presetVariables;

    /**
     * @param presetVariables the variables every run starts with, which scripts use without assigning
     */
    ScriptCompiler(List<DslExtension> extensions, Set<String> presetVariables) {
        this.extensions = extensions;
        this.presetVariables = presetVariables;
    }

    /** The language the scripts are checked against: the vocabulary and the platform's checks. */
    ScriptLanguage language() {
        List<Class<?>> wordClasses = new ArrayList<>();
        List<Class<?>> categories = new ArrayList<>(List.of(Units.class));
        List<CallCheck> callChecks = new ArrayList<>();
        for (DslExtension e : extensions) {
            wordClasses.addAll(e.wordClasses());
            categories.addAll(e.categories());
            callChecks.addAll(e.callChecks());
        }
        Class<?> base = baseClass();
        boolean wordsKnown = extensions.stream().allMatch(e -> !declares(e, "words", ScriptContext.class) || declares(e, "wordClasses"));
        return new ScriptLanguage(Vocabulary.of(base, wordClasses, categories), base, wordClasses, categories, presetVariables,
                callChecks,
                wordsKnown);
    }

    /** Whether the extension's class overrides the interface's default method. */
    private static boolean declares(DslExtension e, String method, Class<?>... parameters) {
        try {
            return e.getClass().getMethod(method, parameters).getDeclaringClass() != DslExtension.class;
        } catch (NoSuchMethodException x) {
            return false;
        }
    }

    /** The scripts' base class: a Groovy class, compiled after this one, so found by name. */
    static Class<?> baseClass() {
        try {
            return Class.forName(BASE_CLASS);
        } catch (ClassNotFoundException e) {
            throw new IllegalStateException(e);
        }
    }

    private CompilerConfiguration configuration(boolean checked) {
        CompilerConfiguration config = new CompilerConfiguration();
        config.setScriptBaseClass(BASE_CLASS);
        ImportCustomizer imports = new ImportCustomizer();
        imports.addStaticStars("java.lang.Math");
        imports.addStarImports("dolphin.core", "dolphin.dsl");
        extensions.forEach(e -> e.addImports(imports));
        // ThreadInterrupt makes loops and closures check for interrupts, so stop() ends any script.
        config.addCompilationCustomizers(imports, new ASTTransformationCustomizer(ThreadInterrupt.class),
                new ExecuteKeyCheck(), new SplitInstructionCheck(), new ExecuteOperandCheck(), new LabelCheck(),
                new HandlerOperandCheck(), new DuringCountCheck());
        if (checked) {
            config.addCompilationCustomizers(new WordCheck(language()));
        }
        return config;
    }

    /**
     * The script's mistakes found without running it; empty when there are none. Compiled up to the
     * check of its names (CANONICALIZATION), not into classes: a third of the time, for editors that
     * check as the user types. What only making the class finds (a script too long for one JVM method)
     * is found when it runs, before anything else.
     */
    List<ScriptError> check(String source, String file) {
        List<ScriptError> errors = LayoutCheck.check(source, file);
        if (!errors.isEmpty()) {
            return errors;
        }
        CompilerConfiguration config = configuration(true);
        try (GroovyClassLoader loader = new GroovyClassLoader(getClass().getClassLoader(), config)) {
            CompilationUnit unit = new CompilationUnit(config, null, loader);
            unit.addSource(codeName(file), source);
            unit.compile(Phases.CANONICALIZATION);
            return List.of();
        } catch (CompilationFailedException e) {
            return compileErrors(e, source, file);
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    /** Compiles a script into an instance bound to {@code binding}; throws {@link ScriptCompileException}. */
    Script parse(String source, String file, Binding binding, GroovyClassLoader loader) {
        List<ScriptError> errors = LayoutCheck.check(source, file);
        if (!errors.isEmpty()) {
            throw new ScriptCompileException(errors);
        }
        try {
            Class<?> type = loader.parseClass(codeSource(source, file), false);
            return InvokerHelper.createScript(type, binding);
        } catch (CompilationFailedException e) {
            throw new ScriptCompileException(compileErrors(e, source, file));
        }
    }

    /** The loader scripts are compiled, checked, in. */
    GroovyClassLoader newLoader() {
        return new GroovyClassLoader(getClass().getClassLoader(), configuration(true));
    }

    /**
     * The loader an {@code ask} answer is compiled in: beside the script's classes, with the same
     * imports, but not checked, since it uses variables that exist only while the script runs.
     */
    GroovyClassLoader answerLoader(GroovyClassLoader scriptLoader) {
        return new GroovyClassLoader(scriptLoader, configuration(false));
    }

    /**
     * The class file name Groovy sees; stack frames carry it, so errors can be mapped back to the
     * script. Groovy names the script class after the file, and a script cannot assign a variable
     * of its class's name (fleet.dolphin could not say {@code fleet = pick ...}), nor be named like
     * a primitive type (long.dolphin): the prefix keeps both apart from what users write.
     */
    static String codeName(String file) {
        String base = file.replace('\\', '/');
        return "dolphin_script_" + base.substring(base.lastIndexOf('/') + 1);
    }

    private static GroovyCodeSource codeSource(String source, String file) {
        GroovyCodeSource cs = new GroovyCodeSource(source, codeName(file), "/groovy/script");
        cs.setCachable(false);
        return cs;
    }

    private static List<ScriptError> compileErrors(CompilationFailedException e, String source, String file) {
        var brackets = BracketCheck.check(source, file);
        if (brackets.isPresent()) {
            return List.of(brackets.get());
        }
        List<ScriptError> out = new ArrayList<>();
        if (e instanceof MultipleCompilationErrorsException m && m.getErrorCollector().getErrors() != null) {
            for (Message msg : m.getErrorCollector().getErrors()) {
                if (msg instanceof SyntaxErrorMessage s) {
                    SyntaxException se = s.getCause();
                    ScriptError error = new ScriptError(file, se.getStartLine(), se.getStartColumn(), cleanSyntaxMessage(se.getOriginalMessage()),
                            se instanceof FixableSyntaxException f ? f.fixes() : List.of());
                    out.add(DuringCountCheck.explain(error, source).orElse(error));
                } else if (msg instanceof ExceptionMessage x) {
                    out.add(new ScriptError(file, 0, 0, x.getCause().getMessage()));
                }
            }
        }
        if (out.isEmpty()) {
            out.add(new ScriptError(file, 0, 0, e.getMessage()));
        }
        return out;
    }

    private static String cleanSyntaxMessage(String m) {
        String s = m.strip();
        int at = s.indexOf("\n");
        return at > 0 ? s.substring(0, at).strip() : s;
    }

    /** Compile errors carried to the run's result. */
    static final class ScriptCompileException extends RuntimeException {
        final List<ScriptError> errors;

        ScriptCompileException(List<ScriptError> errors) {
            super(errors.get(0).toString(), null, false, false);
            this.errors = errors;
        }
    }
}
