package dolphin.dsl

import dolphin.core.Position
import dolphin.core.Task
import dolphin.core.TaskEvent
import dolphin.core.VehicleEvent
import dolphin.testing.FlyTask
import dolphin.testing.ScriptHarness
import org.codehaus.groovy.control.customizers.ImportCustomizer
import spock.lang.Specification
import spock.lang.TempDir

import java.nio.file.Files
import java.nio.file.Path
import java.time.Duration
import java.util.concurrent.CountDownLatch
import java.util.concurrent.TimeUnit

import static dolphin.core.TaskEvent.Kind.COMPLETED as EV_COMPLETED
import static dolphin.core.TaskEvent.Kind.STARTED
import static dolphin.core.TaskEvent.Kind.STOPPED as EV_STOPPED
import static dolphin.dsl.ScriptResult.Outcome.COMPLETED
import static dolphin.dsl.ScriptResult.Outcome.SCRIPT_ERROR
import static dolphin.dsl.ScriptResult.Outcome.STOPPED

/** The embedding API of {@link Engine}: bind, variable, listeners, events, run, check, stop (design §7, reference B.7). */
class EngineSpec extends Specification {

    ScriptHarness h = new ScriptHarness(1)

    @TempDir
    Path dir

    def "bind sets a variable every later run starts with; variable reads the script's variables"() {
        given:
        h.engine.bind('home', Position.fromDegrees(41, -8, 0))
        h.engine.bind('legs', 3)

        when:
        h.run('''
            far = home ^ 1.km
            total = legs * 2
            legs = 10
        ''')

        then:
        h.engine.variable('total') == 6
        h.engine.variable('legs') == 10                    // the run's own value
        h.engine.variable('far').radius == 1000d
        h.engine.variable('nothing') == null
        h.engine.variable('_') == '_'
    }

    def "a bound value is given afresh to each run; unbind removes it"() {
        given:
        h.engine.bind('legs', 3)

        when:
        h.run('legs = 10')
        h.run('seen = legs')
        h.engine.unbind('legs')
        def r = h.run('seen = legs')

        then:
        r.outcome == SCRIPT_ERROR
        r.error.message.contains("unknown name 'legs'")
        h.engine.variable('legs') == null
    }

    def "a listener hears scriptStarted, the messages and scriptFinished with the result, in order"() {
        given:
        def heard = new java.util.concurrent.CopyOnWriteArrayList()
        h.engine.addListener(new EngineListener() {
            void scriptStarted(String name) { heard << "started ${name}".toString() }

            void message(String text) { heard << "message ${text}".toString() }

            void scriptFinished(String name, ScriptResult result) { heard << "finished ${name} ${result.outcome}".toString() }
        })

        when:
        def r = h.run("message 'hello'", 'hello.dolphin')

        then:
        r.outcome == COMPLETED
        heard == ['started hello.dolphin', 'message hello', 'finished hello.dolphin COMPLETED']
    }

    def "scriptFinished gets the same result as the run"() {
        given:
        ScriptResult finished = null
        h.engine.addListener(new EngineListener() {
            void scriptFinished(String name, ScriptResult result) { finished = result }
        })

        when:
        def r = h.run("halt 'enough'")

        then:
        finished.is(r)
        r.message == 'enough'
    }

    def "a removed listener hears nothing more"() {
        given:
        def heard = []
        def listener = new EngineListener() {
            void message(String text) { heard << text }
        }
        h.engine.addListener(listener)
        h.run("message 'one'")
        h.engine.removeListener(listener)

        when:
        h.run("message 'two'")

        then:
        heard == ['one']
    }

    def "task events: STARTED and COMPLETED with the vehicles, the state and the virtual time"() {
        when:
        h.run('''
            v = pick { }
            execute fly('a', 5)
            execute failing('f', 2, 'boom')
        ''')

        then:
        def platformEvents = h.events.findAll { it.platformTask }
        platformEvents.collect { "${it.kind} ${it.task.id} ${it.vehicles} ${it.state} @${it.time}".toString() } ==
                ['STARTED a [1] UNDEFINED @0.0', 'COMPLETED a [1] DONE @5.0',
                 'STARTED f [1] UNDEFINED @5.0', 'COMPLETED f [1] ERROR: boom @7.0']
    }

    def "task events: operators' tasks report too, and a cut-short task is STOPPED"() {
        given:
        h.at(3) { h.platform.node('1').battery = 0.1 }

        when:
        h.run('''
            v = pick { }
            execute fly('a', 100) / { battery(v) < 0.5 }
        ''')

        then:
        h.events.collect { "${it.kind} ${it.task.id} @${it.time}".toString() } ==
                ['STARTED (a / {...}) @0.0', 'STARTED a @0.0', 'STOPPED a @3.0', 'COMPLETED (a / {...}) @3.0']
    }

    def "a second run while one is running throws IllegalStateException"() {
        given:
        def asking = new CountDownLatch(1)
        def answer = new CountDownLatch(1)
        h.engine.setInput { String p -> asking.countDown(); answer.await(10, TimeUnit.SECONDS); '42' }

        when:
        def first = h.engine.run("x = ask 'wait'", 'first.dolphin')
        assert asking.await(10, TimeUnit.SECONDS)
        h.engine.run("message 'second'", 'second.dolphin')

        then:
        def e = thrown(IllegalStateException)
        e.message.contains('a script is already running: first.dolphin')

        when:
        answer.countDown()
        def result = first.await(Duration.ofSeconds(10))

        then:
        result.outcome == COMPLETED
        h.engine.variable('x') == 42
        !h.messages.contains('second')
    }

    def "after a run has ended, the engine runs the next one, whose vehicles are free again"() {
        when:
        def a = h.run('v = pick { }')
        def b = h.run('w = pick { }')

        then:
        a.outcome == COMPLETED
        b.outcome == COMPLETED
        h.platform.node('1').releases == ['1', '1']
    }

    def "check compiles without running and returns the mistakes"() {
        given:
        def started = []
        h.engine.addListener(new EngineListener() {
            void scriptStarted(String name) { started << name }
        })

        when:
        def good = h.engine.check("v = pick { }\nmessage 'ran'", 'good.dolphin')
        def bad = h.engine.check("v = pick {\nmessage 'ran'", 'bad.dolphin')

        then:
        good.isEmpty()
        bad.size() == 1
        bad[0].file == 'bad.dolphin'
        bad[0].line == 1
        bad[0].message.contains("expected a '}'")
        started.isEmpty()
        h.messages.isEmpty()
        h.platform.node('1').releases.isEmpty()
    }

    def "check finds a variable the script never assigns, and run refuses the script"() {
        expect:
        h.engine.check('execute nosuch', 'late.dolphin')*.toString() ==
                ["late.dolphin:1:9: unknown name 'nosuch'. Expected a variable assigned in the script (names are case-sensitive)"]
        h.run('execute nosuch', 'late.dolphin').outcome == SCRIPT_ERROR
    }

    def "run and check read a script file; errors name the file's path"() {
        given:
        Path file = dir.resolve('mission.dolphin')
        Files.writeString(file, "v = pick { }\nx = position(v + nosuch)\n")

        when:
        def checked = h.engine.check(file)
        def r = h.engine.run(file).await(Duration.ofSeconds(20))

        then:
        checked*.toString() == ["${file}:2:18: unknown name 'nosuch'. Expected a variable assigned in the script (names are case-sensitive)".toString()]
        r.outcome == SCRIPT_ERROR
        r.error.file == file.toString()
        r.error.line == 2
        r.error.message.contains("unknown name 'nosuch'")
    }

    def "Engine.stop stops the running task (its vehicle is told), releases the vehicles and ends the run as STOPPED"() {
        given:
        h.at(30) { h.engine.stop() }

        when:
        def r = h.run('''
            v = pick { }
            execute fly('a', 100)
            message 'after'
        ''')

        then:
        r.outcome == STOPPED
        r.exitCode() == 1
        h.platform.journal*.toString() == ['start a 1 @0.0', 'stop a 1 @30.0']
        h.events.find { it.kind == EV_STOPPED && it.task.id == 'a' }.time == 30.0d
        h.platform.node('1').releases == ['1']
        !h.messages.contains('after')
    }

    def "ScriptRun.stop from another thread stops a running task"() {
        given:
        def flying = new CountDownLatch(1)
        h.engine.addListener(new EngineListener() {
            void taskEvent(TaskEvent e) { if (e.kind == STARTED && e.task.id == 'a') flying.countDown() }
        })

        when:
        def run = h.engine.run('''
            v = pick { }
            execute fly('a', 1e9)
        ''', 'long.dolphin')
        assert flying.await(10, TimeUnit.SECONDS)
        run.stop()
        def r = run.await(Duration.ofSeconds(10))

        then:
        r.outcome == STOPPED
        h.platform.journal*.kind == ['start', 'stop']
        h.platform.node('1').releases == ['1']
        run.isDone()
    }

    def "a busy #loop is stoppable"() {
        given:
        def looping = new CountDownLatch(1)
        h.engine.addListener(new EngineListener() {
            void message(String text) { if (text == 'looping') looping.countDown() }
        })

        when:
        def run = h.engine.run("""
            v = pick { }
            n = 0
            message 'looping'
            ${loop}
        """, 'loop.dolphin')
        assert looping.await(10, TimeUnit.SECONDS)
        h.engine.stop()
        def r = run.await(Duration.ofSeconds(10))

        then:
        r != null
        r.outcome == STOPPED
        h.platform.node('1').releases == ['1']

        where:
        loop << ['while (true) { }', 'while (true) { n++ }', 'for (;;) { n = n + 1 }', '(1..Integer.MAX_VALUE).each { n++ ; while (true) {} }']
    }

    def "close stops the running script and waits for it"() {
        given:
        def looping = new CountDownLatch(1)
        h.engine.addListener(new EngineListener() {
            void message(String text) { looping.countDown() }
        })
        def run = h.engine.run("message 'go'\nwhile (true) { }", 'loop.dolphin')
        assert looping.await(10, TimeUnit.SECONDS)

        when:
        h.engine.close()

        then:
        run.isDone()
        run.await().outcome == STOPPED
    }

    def "a listener that throws does not break the script or the other listeners"() {
        given:
        def heard = []
        h.engine.addListener(new EngineListener() {
            void message(String text) { throw new IllegalStateException('listener bug') }
        })
        h.engine.addListener(new EngineListener() {
            void message(String text) { heard << text }
        })

        when:
        def r = h.run("message 'still here'")

        then:
        r.outcome == COMPLETED
        heard == ['still here']
    }

    def "vehicle events reach every listener on the thread that raised them, with no script running and while one pauses; one that throws stops none"() {
        given:
        def heard = new java.util.concurrent.CopyOnWriteArrayList()
        h.engine.addListener(new EngineListener() {
            void vehicleEvent(VehicleEvent e) { throw new IllegalStateException('listener bug') }
        })
        h.engine.addListener(new EngineListener() {
            void vehicleEvent(VehicleEvent e) { heard << [e.text(), Thread.currentThread().name] }
        })
        def lost = new VehicleEvent('1', VehicleEvent.EventKind.CONTACT_LOST, 'no contact for 3 s', 3)
        def again = new VehicleEvent('1', VehicleEvent.EventKind.CONTACT_AGAIN, 'contact again after 31 s', 34)

        when: 'no script runs'
        Thread.start('MAVLink communications') { h.platform.vehicleEvent(lost) }.join()

        then:
        heard == [['no contact for 3 s', 'MAVLink communications']]

        when: 'the script pauses; the event comes from the clock on the script thread'
        h.at(5) { h.platform.vehicleEvent(again) }
        def r = h.run('pause 10')

        then:
        r.outcome == COMPLETED
        heard[1] == ['contact again after 31 s', 'dolphin-script']
        heard.size() == 2
    }

    def "an extension adds words, imports and categories for scripts only"() {
        given:
        h.engine.addExtension(new DslExtension() {
            void addImports(ImportCustomizer imports) { imports.addImport('Dur', Duration.name) }

            List<Object> words(ScriptContext context) { [new SurveyWords(h)] }

            List<Class<?>> categories() { [NauticalUnits] }
        })

        when:
        def r = h.run('''
            v = pick { }
            d = Dur.ofSeconds(5)
            execute survey('s1', d.seconds)
            miles = 2.nmi
        ''')

        then:
        r.outcome == COMPLETED
        h.platform.journal*.toString() == ['start s1 1 @0.0', 'done s1 1 @5.0']
        h.engine.variable('miles') == 3704d
    }

    def "the platform's words come after the language's: a platform cannot redefine message"() {
        given:
        h.engine.addExtension(new DslExtension() {
            List<Object> words(ScriptContext context) { [new ShadowWords()] }
        })

        when:
        h.run("message 'x'")

        then:
        h.messages == ['x']
        ShadowWords.calls == 0
    }

    static class SurveyWords {
        final ScriptHarness h

        SurveyWords(ScriptHarness h) { this.h = h }

        Task survey(String id, Number seconds) { new FlyTask(h.platform, id, seconds.doubleValue()) }
    }

    static class ShadowWords {
        static int calls

        void message(Object text) { calls++ }
    }
}

/** A category an extension contributes: nautical miles. */
class NauticalUnits {
    static double getNmi(Number n) { n.doubleValue() * 1852 }
}
