package dolphin.testing

import dolphin.core.ManualClock
import dolphin.core.TaskEvent
import dolphin.dsl.Engine
import dolphin.dsl.EngineListener
import dolphin.dsl.ScriptResult
import java.time.Duration

/** Runs scripts on a TestPlatform under virtual time and collects what the engine reports. */
class ScriptHarness {
    final ManualClock clock = ManualClock.autoAdvancing()
    final TestPlatform platform = new TestPlatform()
    final Engine engine = new Engine(platform, clock)
    final List<String> messages = new java.util.concurrent.CopyOnWriteArrayList()
    final List<TaskEvent> events = new java.util.concurrent.CopyOnWriteArrayList()

    ScriptHarness(int vehicles = 0) {
        (1..<(vehicles + 1)).each { platform.addNode(String.valueOf(it)) }
        engine.addListener(new EngineListener() {
            void message(String text) { messages << text }

            void taskEvent(TaskEvent e) { events << e }
        })
    }

    /** Runs a script to its end; fails the test if it takes more than 20 s of real time. */
    ScriptResult run(String source, String file = 'test.dolphin') {
        def result = engine.run(source, file).await(Duration.ofSeconds(20))
        assert result != null: 'script did not end within 20 s'
        result
    }

    /** Schedules a change at a virtual time, measured from now. */
    void at(double seconds, Closure change) {
        clock.schedule(Duration.ofNanos((long) (seconds * 1e9)), change as Runnable)
    }

    double now() { clock.seconds() }
}
