package dolphin.mission.dsl

import dolphin.dsl.Blocks
import dolphin.core.Position
import dolphin.dsl.DolphinScript
import dolphin.mission.flight.MissionTask
import dolphin.mission.model.Mission
import dolphin.dsl.vocabulary.Word
import groovy.transform.CompileStatic

import java.util.concurrent.atomic.AtomicInteger

/**
 * The MAVLink platform's top-level words that IDEs can see: {@code mission { }} (docs/mission-commands.md) and
 * the position words {@code pos { }} and {@code moveDistance { }} (docs/mission-commands.md, "Position words"). MAVLinkLanguage
 * imports them into every script with a static star import, so every public static method here is
 * a script word. None may share a name with a mission command: Groovy binds static imports at
 * compile time, so such a method would capture the command inside mission blocks (this is why the
 * position word {@code move(p, { ... })} is a platform word, {@link PositionWords}).
 */
@CompileStatic
final class MissionDsl {

    private static final AtomicInteger UNNAMED = new AtomicInteger()

    private MissionDsl() {
    }

    /**
     * Builds a mission as a platform task usable with every Dolphin operator. Inside the block the
     * mission commands come first; script variables and words stay visible. The default name is
     * {@code MissionPlan_line<N>}, N being the script line of the {@code mission} word.
     */
    @Word('A mission: the block\'s commands as one task, flown by the vehicles it runs on')
    static MissionTask mission(@DelegatesTo(value = MissionBuilder, strategy = Closure.DELEGATE_FIRST) Closure commands) {
        if (commands == null) {
            throw new dolphin.dsl.DslException('mission: expected a block of mission commands, mission { ... }')
        }
        MissionBuilder builder = new MissionBuilder(defaultName(), commands)
        Blocks.run(commands, builder)
        Mission m = builder.build()
        recorded(commands.thisObject, m)
        new MissionTask(m)
    }

    /** Hands the mission to the run's MissionRecorder, if the engine has one (dolphin mission's dry run). */
    private static void recorded(Object script, Mission m) {
        if (script instanceof DolphinScript) {
            for (Object w : ((DolphinScript) script).platformWords) {
                MissionRecorder.report(w, m)
            }
        }
    }

    /** {@code pos { lat x; lon y; hae h }}: a position in degrees and metres above mean sea level; each defaults to 0. */
    @Word('A position: pos { lat 40.1; lon -8.6; hae 120 }, degrees and metres above mean sea level')
    static Position pos(@DelegatesTo(value = PositionBuilder, strategy = Closure.DELEGATE_FIRST) Closure coordinates) {
        PositionBuilder.build(coordinates)
    }

    /** {@code moveDistance { north n; east e; down d }}: an offset in metres for {@code move(position, offset)}. */
    @Word('An offset for move(position, offset): moveDistance { north 10; east 5; down -3 }, metres')
    static NedOffset moveDistance(@DelegatesTo(value = NedBuilder, strategy = Closure.DELEGATE_FIRST) Closure offset) {
        NedBuilder.build('moveDistance', offset)
    }

    /** "MissionPlan_line" + the line of the code that called mission, else a running number. */
    private static String defaultName() {
        for (StackTraceElement e : new Throwable().stackTrace) {
            String c = e.className
            if (c == MissionDsl.name || c.startsWith('java.') || c.startsWith('jdk.') || c.startsWith('sun.')
                    || c.startsWith('groovy.') || c.startsWith('org.codehaus.groovy.') || c.startsWith('org.apache.groovy.')) {
                continue
            }
            if (e.lineNumber > 0) {
                return 'MissionPlan_line' + e.lineNumber
            }
            break
        }
        'MissionPlan_' + UNNAMED.incrementAndGet()
    }
}
