package dolphin.mission.dsl;

import dolphin.dsl.DslExtension;
import dolphin.dsl.ScriptContext;
import dolphin.mission.model.Mission;
import java.util.List;
import java.util.Objects;
import java.util.function.Consumer;

/**
 * Hands every Mission that a script builds with {@code mission { }} or {@code missionFromFile} to a
 * consumer, as it is built:
 * how {@code dolphin mission} collects a script's missions in a dry run. Add it to an engine next
 * to the MAVLink language:
 *
 * <pre>{@code
 * engine.addExtension(new MAVLinkLanguage());
 * engine.addExtension(new MissionRecorder(missions::add));
 * }</pre>
 *
 * <p>It adds no word to the language: its word object has no methods. {@code mission { }} finds it
 * among the script run's platform words ({@code MissionDsl}). The consumer runs on the
 * script thread; a mission built twice (a loop, a function called twice) is reported each time.
 */
public final class MissionRecorder implements DslExtension {

    private final Consumer<Mission> consumer;

    public MissionRecorder(Consumer<Mission> consumer) {
        this.consumer = Objects.requireNonNull(consumer, "consumer");
    }

    @Override
    public List<Object> words(ScriptContext context) {
        return List.of(new Hook(consumer));
    }

    /** None: the hook is no word. */
    @Override
    public List<Class<?>> wordClasses() {
        return List.of();
    }

    /**
     * Called by {@code mission { }} for each platform word object of the run, with the mission it
     * built: hands the mission over when the object is a recorder's.
     */
    public static void report(Object word, Mission mission) {
        if (word instanceof Hook hook && mission != null) {
            hook.consumer.accept(mission);
        }
    }

    /**
     * The recorder's word object for one script run. It has no methods of its own: Groovy calls
     * even package-private methods of word objects, so any method here would be a script word.
     */
    static final class Hook {
        private final Consumer<Mission> consumer;

        Hook(Consumer<Mission> consumer) {
            this.consumer = consumer;
        }
    }
}
