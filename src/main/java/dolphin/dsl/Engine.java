package dolphin.dsl;

import dolphin.core.Clock;
import dolphin.core.Environment;
import dolphin.core.Platform;
import dolphin.core.RuntimeListener;
import dolphin.core.SystemClock;
import dolphin.core.TaskEvent;
import dolphin.core.TaskTree;
import dolphin.core.VehicleEvent;
import dolphin.dsl.vocabulary.Vocabulary;
import groovy.lang.Binding;
import groovy.lang.Closure;
import groovy.lang.GroovyClassLoader;
import groovy.lang.Script;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Function;
import org.codehaus.groovy.runtime.GroovyCategorySupport;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The Dolphin script engine on a platform: the embedding API for the command line, IDEs and GUIs.
 * One script runs at a time, on its own thread. See docs/embedding.md.
 */
public final class Engine implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(Engine.class);

    private final Platform platform;
    private final Environment environment;
    private final List<EngineListener> listeners = new CopyOnWriteArrayList<>();
    private final List<DslExtension> extensions = new CopyOnWriteArrayList<>();
    private final Map<String, Object> presets = new LinkedHashMap<>();
    private volatile Function<String, String> input;
    private volatile Binding lastBinding = new Binding();
    private volatile boolean rehearsal;
    private ScriptRun current;

    public Engine(Platform platform) {
        this(platform, SystemClock.REAL);
    }

    public Engine(Platform platform, Clock clock) {
        this.platform = platform;
        this.environment = new Environment(platform, clock, new Fanout());
        this.input = platform::askForInput;
        if (platform instanceof DslExtension e) {
            extensions.add(e);
        }
    }

    public Platform getPlatform() {
        return platform;
    }

    public Environment getEnvironment() {
        return environment;
    }

    public void addListener(EngineListener listener) {
        listeners.add(listener);
    }

    public void removeListener(EngineListener listener) {
        listeners.remove(listener);
    }

    public void addExtension(DslExtension extension) {
        extensions.add(extension);
    }

    /** Where {@code ask} reads its answers; by default the platform's (standard input). */
    public void setInput(Function<String, String> input) {
        this.input = input;
    }

    /**
     * Makes later runs rehearsals ({@link ScriptContext#rehearsal()}): the script runs without
     * vehicles up to its end or to its first word that needs one, so that everything it builds on
     * the way (its missions) is built and checked.
     */
    public void setRehearsal(boolean rehearsal) {
        this.rehearsal = rehearsal;
    }

    /** Sets a variable that every later script run starts with. */
    public synchronized void bind(String name, Object value) {
        presets.put(name, value);
    }

    public synchronized void unbind(String name) {
        presets.remove(name);
    }

    /** A variable of the running (or last) script, or a bound one; null if there is none. */
    public Object variable(String name) {
        Binding b = lastBinding;
        if (b.hasVariable(name)) {
            return b.getVariable(name);
        }
        synchronized (this) {
            return presets.get(name);
        }
    }

    /** Compiles a script without running it; returns its mistakes, empty when there are none. */
    public List<ScriptError> check(String source, String file) {
        return compiler().check(source, file);
    }

    /** The words scripts may write with this engine's extensions (docs/editors.md, "One vocabulary"). */
    public Vocabulary vocabulary() {
        return compiler().language().vocabulary();
    }

    /** A compiler for this engine's extensions and bound variables ({@code _}, the execute key, among them). */
    private synchronized ScriptCompiler compiler() {
        Set<String> preset = new LinkedHashSet<>(presets.keySet());
        preset.add("_");
        return new ScriptCompiler(List.copyOf(extensions), preset);
    }

    public List<ScriptError> check(Path file) throws IOException {
        return check(Files.readString(file, StandardCharsets.UTF_8), file.toString());
    }

    public ScriptRun run(Path file) throws IOException {
        return run(Files.readString(file, StandardCharsets.UTF_8), file.toString());
    }

    /**
     * Starts a script on a new thread. Throws IllegalStateException if one is already running.
     *
     * @param file the name used in error messages, e.g. the script's path
     */
    public synchronized ScriptRun run(String source, String file) {
        if (current != null && !current.isDone()) {
            throw new IllegalStateException("a script is already running: " + current.name());
        }
        ScriptRun run = new ScriptRun(file);
        Binding binding = new Binding(new LinkedHashMap<>(presets));
        binding.setVariable("_", "_");
        lastBinding = binding;
        current = run;
        Thread t = new Thread(() -> execute(source, file, binding, run), "dolphin-script");
        run.started(t);
        t.start();
        return run;
    }

    /** Stops the running script, if any. */
    public synchronized void stop() {
        if (current != null) {
            current.stop();
        }
    }

    /** Stops the running script and waits for it to end. The platform is the caller's to close. */
    @Override
    public void close() throws InterruptedException {
        ScriptRun run;
        synchronized (this) {
            run = current;
        }
        if (run != null) {
            run.stop();
            run.await();
        }
    }

    private void execute(String source, String file, Binding binding, ScriptRun run) {
        ScriptContext context = new ScriptContext(environment, prompt -> input.apply(prompt), rehearsal);
        ScriptCompiler compiler = compiler();
        Fanout out = (Fanout) environment.getListener();
        out.scriptStarted(file);
        ScriptResult result;
        Script script = null;
        try (GroovyClassLoader loader = compiler.newLoader(); GroovyClassLoader answers = compiler.answerLoader(loader)) {
            script = compiler.parse(source, file, binding, loader);
            List<Object> words = new ArrayList<>();
            for (DslExtension e : extensions) {
                words.addAll(e.words(context));
            }
            context.setWords(words);
            context.setEvaluator(code -> evaluate(compiler, answers, binding, context, code));
            ((DslScript) script).attach(context);
            Script toRun = script;
            runWithCategories(categories(), () -> {
                toRun.run();
                ((DslScript) toRun).scriptEnded();
            });
            result = run.stopRequested() ? stopped()
                    : context.taskErrors() > 0
                    ? new ScriptResult(ScriptResult.Outcome.TASK_ERROR, context.taskErrors() + " task(s) ended in ERROR", null)
                    : new ScriptResult(ScriptResult.Outcome.COMPLETED, null, null);
        } catch (ScriptCompiler.ScriptCompileException e) {
            result = new ScriptResult(ScriptResult.Outcome.SCRIPT_ERROR, e.errors.size() + " compile error(s)", e.errors.get(0));
            e.errors.forEach(err -> out.message(err.toString()));
        } catch (Throwable t) {
            Throwable cause = unwrap(t);
            if (run.stopRequested()) {
                result = stopped();
            } else if (cause instanceof Halt h) {
                result = new ScriptResult(ScriptResult.Outcome.HALTED, h.getMessage(), null);
                out.message("halted: " + h.getMessage());
            } else {
                ScriptError error = RuntimeErrors.describe(cause, file, knownWords(script, context.words()), binding.getVariables().keySet());
                result = new ScriptResult(ScriptResult.Outcome.SCRIPT_ERROR, error.message(), error);
                out.message(error.toString());
                LOG.debug("script error", cause);
            }
        } finally {
            environment.releaseAll();
        }
        out.scriptFinished(file, result);
        run.finish(result);
    }

    /** An {@code ask} answer, compiled like a script (imports, words, units) and run with the script's variables. */
    private static Object evaluate(ScriptCompiler compiler, GroovyClassLoader loader, Binding binding, ScriptContext context,
                                   String code) {
        Script answer;
        try {
            answer = compiler.parse(code, "answer.groovy", binding, loader);
        } catch (ScriptCompiler.ScriptCompileException e) {
            throw new DslException("ask: the answer '" + code + "' is not valid: " + e.errors.get(0).message());
        }
        ((DslScript) answer).attach(context);
        return answer.run();
    }

    private static ScriptResult stopped() {
        return new ScriptResult(ScriptResult.Outcome.STOPPED, "stopped", null);
    }

    private List<Class<?>> categories() {
        List<Class<?>> all = new ArrayList<>();
        all.add(Units.class);
        extensions.forEach(e -> all.addAll(e.categories()));
        return all;
    }

    @SuppressWarnings({"rawtypes", "unchecked"})
    private static void runWithCategories(List<Class<?>> categories, Runnable body) {
        GroovyCategorySupport.use((List<Class>) (List) categories, new Closure<Object>(null) {
            @SuppressWarnings("unused")
            public Object doCall() {
                body.run();
                return null;
            }
        });
    }

    /** The names a script could have meant: DSL words, its own methods and the platform words. */
    private static Set<String> knownWords(Script script, List<Object> words) {
        Set<String> names = new LinkedHashSet<>();
        if (script != null) {
            script.getMetaClass().getMethods().forEach(m -> names.add(m.getName()));
        }
        for (Object w : words) {
            for (java.lang.reflect.Method m : w.getClass().getMethods()) {
                names.add(m.getName());
            }
        }
        return names;
    }

    private static Throwable unwrap(Throwable t) {
        Throwable c = t;
        while ((c instanceof org.codehaus.groovy.runtime.InvokerInvocationException
                || c instanceof java.lang.reflect.InvocationTargetException) && c.getCause() != null) {
            c = c.getCause();
        }
        return c;
    }

    /** Sends runtime messages and events to every listener; a failing listener is logged, not fatal. */
    private final class Fanout implements RuntimeListener {
        @Override
        public void message(String text) {
            each(l -> l.message(text));
        }

        @Override
        public void taskEvent(TaskEvent event) {
            each(l -> l.taskEvent(event));
        }

        @Override
        public void executeStarted(TaskTree tree) {
            each(l -> l.executeStarted(tree));
        }

        @Override
        public void vehicleEvent(VehicleEvent event) {
            each(l -> l.vehicleEvent(event));
        }

        void scriptStarted(String name) {
            each(l -> l.scriptStarted(name));
        }

        void scriptFinished(String name, ScriptResult result) {
            each(l -> l.scriptFinished(name, result));
        }

        private void each(java.util.function.Consumer<EngineListener> call) {
            for (EngineListener l : listeners) {
                try {
                    call.accept(l);
                } catch (RuntimeException e) {
                    LOG.warn("engine listener failed", e);
                }
            }
        }
    }
}
