package dolphin.cli;

import dolphin.core.VehiclelessPlatform;
import dolphin.core.ManualClock;
import dolphin.dsl.Engine;
import dolphin.dsl.EngineListener;
import dolphin.dsl.Halt;
import dolphin.dsl.ScriptResult;
import dolphin.dsl.ScriptRun;
import dolphin.platform.MAVLinkLanguage;
import dolphin.mission.dsl.MissionRecorder;
import dolphin.mission.model.Mission;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Set;

/**
 * Runs a script without vehicles, on a virtual clock that jumps over waits, and records every
 * Mission its {@code mission { }} blocks build: {@code dolphin mission} shows them, {@code dolphin
 * check} uses it to find the mistakes that only building a mission reveals (a waypoint below home).
 * With no vehicles the script ends at its first {@code pick} (it halts there), and at its first
 * {@code ask}, which nobody answers.
 *
 * @param result how the script ended; null when it was stopped at the time limit
 * @param missions the missions built, in order, each once
 * @param messages the script's own messages and the engine's notes
 */
record DryRun(ScriptResult result, List<Mission> missions, List<String> messages) {

    static DryRun of(String source, String file, Duration timeLimit) throws InterruptedException {
        return of(source, file, timeLimit, false);
    }

    /**
     * As {@link #of(String, String, Duration)}; a rehearsal ({@link Engine#setRehearsal}) goes on past
     * its picks with stand-in vehicles and runs no execute, so the missions built after a pick are
     * built too, up to the first word that needs a vehicle's telemetry.
     */
    static DryRun of(String source, String file, Duration timeLimit, boolean rehearse) throws InterruptedException {
        Set<Mission> seen = Collections.newSetFromMap(new IdentityHashMap<>());
        List<Mission> missions = Collections.synchronizedList(new ArrayList<>());
        Engine engine = new Engine(new VehiclelessPlatform("dry run"), ManualClock.autoAdvancing());
        engine.addExtension(new MAVLinkLanguage());
        engine.setRehearsal(rehearse);
        // Nobody answers a dry run: it stops at its first question, as at its first pick.
        engine.setInput(prompt -> {
            throw new Halt("ask: a dry run has nobody to answer '" + prompt + "'");
        });
        engine.addExtension(new MissionRecorder(m -> {
            synchronized (seen) {
                if (seen.add(m)) {
                    missions.add(m);
                }
            }
        }));
        List<String> messages = Collections.synchronizedList(new ArrayList<>());
        engine.addListener(new EngineListener() {
            @Override
            public void message(String text) {
                messages.add(text);
            }
        });
        ScriptResult result;
        try (engine) {
            ScriptRun run = engine.run(source, file);
            result = run.await(timeLimit);
            if (result == null) {
                // Without vehicles a script that never picks one (a loop of its own) never ends.
                run.stop();
                run.await();
            }
        }
        synchronized (missions) {
            synchronized (messages) {
                return new DryRun(result, List.copyOf(missions), List.copyOf(messages));
            }
        }
    }

    /** The script's error as file:line: message, or null when it had none. */
    String error() {
        return result == null || result.error() == null ? null : result.error().toString();
    }
}
