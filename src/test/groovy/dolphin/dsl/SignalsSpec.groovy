package dolphin.dsl

import dolphin.testing.ScriptHarness
import spock.lang.Specification

/** {@code post}, {@code consume} and both forms of {@code poll} (reference A.2 "Signals"). */
class SignalsSpec extends Specification {

    ScriptHarness h = new ScriptHarness(1)

    private Object v(String name) { h.engine.variable(name) }

    def "post adds values under their keys and says so; poll 'k' sees any value"() {
        when:
        h.run('''
            before = poll 'go'
            post go: 1, colour: 'red'
            after = poll 'go'
            other = poll 'stop'
        ''')

        then:
        v('before') == false
        v('after') == true
        v('other') == false
        h.messages.contains('posted [go:1, colour:red]')
    }

    def "poll k: { pred } is true when, for every key, some value satisfies the closure"() {
        when:
        h.run('''
            post go: 1
            post go: 7
            post colour: 'red'
            a = poll go: { it > 5 }
            b = poll go: { it > 10 }
            c = poll go: { it > 5 }, colour: { it == 'red' }
            d = poll go: { it > 5 }, colour: { it == 'blue' }
            e = poll missing: { true }
        ''')

        then:
        v('a') == true
        v('b') == false
        v('c') == true
        v('d') == false
        v('e') == false
    }

    def "consume takes all pairs or nothing"() {
        when:
        h.run('''
            post go: 1, colour: 'red'
            partial = consume go: 1, colour: 'blue'
            goLeft = poll 'go'
            all = consume go: 1, colour: 'red'
            goGone = !(poll 'go')
            colourGone = !(poll 'colour')
            again = consume go: 1
        ''')

        then:
        v('partial') == false
        v('goLeft') == true
        v('all') == true
        v('goGone') == true
        v('colourGone') == true
        v('again') == false
        h.messages.count { it.startsWith('consumed') } == 1
        h.messages.contains('consumed [go:1, colour:red]')
    }

    def "a key keeps a set of values; consuming one leaves the others"() {
        when:
        h.run('''
            post job: 'a'
            post job: 'b'
            post job: 'a'
            one = consume job: 'a'
            two = consume job: 'a'
            rest = poll job: { it == 'b' }
        ''')

        then:
        v('one') == true
        v('two') == false       // a set: posting 'a' twice keeps one
        v('rest') == true
    }

    def "signals coordinate tasks: a guard waits for a post from another branch"() {
        when:
        h.run('''
            v = pick { }
            t = (idle(4) >> action { post ready: true }) | (waitFor { consume ready: true } then fly('go', 1))
            execute t
        ''')

        then:
        h.platform.journal*.toString() == ['start go 1 @4.0', 'done go 1 @5.0']
    }

    def "signals are cleared at each script start"() {
        given:
        h.run("post go: 1")

        when:
        h.run("seen = poll 'go'")

        then:
        v('seen') == false
    }
}
