package dolphin.mission.dsl

import dolphin.core.ManualClock
import dolphin.core.NodeSet
import dolphin.core.Platform
import dolphin.dsl.Engine
import dolphin.dsl.ScriptResult
import dolphin.platform.MAVLinkLanguage
import dolphin.mission.model.Mission
import spock.lang.Specification
import spock.lang.Timeout

/** The hook through which dolphin mission collects the missions a script builds. */
@Timeout(30)
class MissionRecorderSpec extends Specification {

    static final class NoVehicles implements Platform {
        String getName() { 'no vehicles' }

        NodeSet getConnectedNodes() { new NodeSet() }
    }

    List<Mission> recorded = []

    ScriptResult run(String source, boolean withRecorder = true) {
        Engine engine = new Engine(new NoVehicles(), ManualClock.autoAdvancing())
        engine.addExtension(new MAVLinkLanguage())
        if (withRecorder) {
            engine.addExtension(new MissionRecorder({ Mission m -> recorded << m }))
        }
        engine.run(source, 'recorder.dolphin').await()
    }

    def "every mission a script builds is handed over as it is built, in order, each build once"() {
        when:
        def r = run('''a = mission { name 'a'; goPos 1, 2, 3 }
def make(n) { mission { name n; goPos 1, 2, 3 } }
b = make('b')
c = make('c')
same = a
''')

        then:
        r.outcome() == ScriptResult.Outcome.COMPLETED
        recorded*.id == ['a', 'b', 'c']
    }

    def "missions built before the first pick are recorded even though the script halts there"() {
        when:
        def r = run('''a = mission { name 'before'; goPos 1, 2, 3 }
v = pick { timeout 30 }
b = mission { name 'after'; goPos 1, 2, 3 }
''')

        then:
        r.outcome() == ScriptResult.Outcome.HALTED
        recorded*.id == ['before']
    }

    def "a mission whose block fails is not recorded"() {
        when:
        def r = run('''a = mission { name 'empty' }''')

        then:
        r.outcome() == ScriptResult.Outcome.SCRIPT_ERROR
        recorded.isEmpty()
    }

    def "the recorder adds no word: a script cannot call its hook"() {
        when:
        def r = run('built(null)')

        then:
        r.outcome() == ScriptResult.Outcome.SCRIPT_ERROR
        r.error().message().contains("unknown command 'built'")
    }

    def "without a recorder, missions build as usual"() {
        when:
        def r = run("a = mission { name 'a'; goPos 1, 2, 3 }", false)

        then:
        r.outcome() == ScriptResult.Outcome.COMPLETED
        recorded.isEmpty()
    }

    def "the consumer must be given"() {
        when:
        new MissionRecorder(null)

        then:
        thrown(NullPointerException)
    }
}
