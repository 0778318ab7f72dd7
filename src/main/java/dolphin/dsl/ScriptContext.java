package dolphin.dsl;

import dolphin.core.Environment;
import dolphin.core.RuntimeListener;
import java.util.List;
import java.util.function.Function;

/** What a running script's DSL words work with; one per script run. */
public final class ScriptContext {

    private final Environment environment;
    private final SignalSet signals = new SignalSet();
    private final Function<String, String> input;
    private List<Object> words = List.of();
    private Function<String, Object> evaluator = code -> {
        throw new IllegalStateException("no script is running");
    };
    private int taskErrors;
    private final boolean rehearsal;
    private int rehearsedExecutes;

    ScriptContext(Environment environment, Function<String, String> input, boolean rehearsal) {
        this.environment = environment;
        this.input = input;
        this.rehearsal = rehearsal;
    }

    /**
     * Whether this run is a rehearsal: {@code pick} gives stand-ins ({@link dolphin.core.StandInNode})
     * at once, {@code execute} runs nothing, a word that needs telemetry ends the run ({@link Halt}).
     */
    public boolean rehearsal() {
        return rehearsal;
    }

    /** An execute a rehearsal skips; a script that loops on executes alone ends after {@value #REHEARSED_EXECUTES}. */
    void rehearsedExecute() {
        if (++rehearsedExecutes > REHEARSED_EXECUTES) {
            throw new Halt("the rehearsal ran " + REHEARSED_EXECUTES + " executes: a loop that only ends with vehicles");
        }
    }

    /** Ends a rehearsal at a word that needs a vehicle's telemetry. */
    public void needsVehicle(String word, Object vehicle) {
        if (vehicle instanceof dolphin.core.StandInNode || vehicle instanceof dolphin.core.NodeSet set
                && set.stream().anyMatch(dolphin.core.StandInNode.class::isInstance)) {
            throw new Halt(word + ": a rehearsal has no vehicles to ask");
        }
    }

    static final int REHEARSED_EXECUTES = 1000;

    public Environment environment() {
        return environment;
    }

    public RuntimeListener listener() {
        return environment.getListener();
    }

    public SignalSet signals() {
        return signals;
    }

    public String readInput(String prompt) {
        return input.apply(prompt);
    }

    /** Evaluates a line of input (an {@code ask} answer) as script code: the script's variables, words and units. */
    public Object evaluate(String code) {
        return evaluator.apply(code);
    }

    void setEvaluator(Function<String, Object> evaluator) {
        this.evaluator = evaluator;
    }

    /** The platform words of this run, from the engine's extensions. */
    public List<Object> words() {
        return words;
    }

    void setWords(List<Object> words) {
        this.words = List.copyOf(words);
    }

    /** Counts a root task that ended in ERROR, so the run's outcome says so. */
    public void taskFailed() {
        taskErrors++;
    }

    int taskErrors() {
        return taskErrors;
    }
}
