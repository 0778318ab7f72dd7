package dolphin.docs;

import dolphin.core.NodeSet;
import dolphin.core.Platform;
import dolphin.core.TaskEvent;
import dolphin.dsl.Engine;
import dolphin.dsl.EngineListener;
import dolphin.dsl.ScriptError;
import dolphin.dsl.ScriptResult;
import dolphin.dsl.ScriptRun;
import java.util.List;
import java.util.function.Consumer;

public final class EmbeddingExample {

    /** A platform without vehicles; an IDE would pass the MAVLink platform here. */
    static final class NoVehicles implements Platform {
        @Override
        public String getName() {
            return "no vehicles";
        }

        @Override
        public NodeSet getConnectedNodes() {
            return new NodeSet();
        }
    }

    public static ScriptResult demo(Consumer<String> console) throws Exception {
        try (Engine engine = new Engine(new NoVehicles())) {
            engine.addListener(new EngineListener() {
                @Override
                public void message(String text) {
                    console.accept("message: " + text);
                }

                @Override
                public void taskEvent(TaskEvent event) {
                    console.accept("task " + event.kind() + ": " + event.task().getId());
                }
            });

            // Check a script the way an editor would, without running it.
            List<ScriptError> errors = engine.check("execute\nv1: idle(1)", "editor.dolphin");
            errors.forEach(e -> console.accept("error: " + e));

            // Run a script on its own thread, with a variable handed in by the host.
            engine.bind("greeting", "hello from the host");
            ScriptRun run = engine.run("""
                    message greeting
                    execute idle(0.2) >> action { message 'idle done' }
                    answer = 6 * 7
                    """, "inline.dolphin");
            ScriptResult result = run.await();
            console.accept("answer: " + engine.variable("answer"));
            return result;
        }
    }

    public static void main(String[] args) throws Exception {
        ScriptResult result = demo(System.out::println);
        System.out.println(result.outcome() + ", exit code " + result.exitCode());
    }
}
