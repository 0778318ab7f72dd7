package dolphin.editor

import dolphin.dsl.Units
import dolphin.dsl.vocabulary.LanguageWords
import dolphin.dsl.vocabulary.Vocabulary
import dolphin.dsl.vocabulary.WordEntry
import dolphin.dsl.vocabulary.WordScope
import java.util.regex.Pattern
import org.codehaus.groovy.control.CompilerConfiguration
import spock.lang.Shared
import spock.lang.Specification

/**
 * The GDSL file run as IntelliJ runs it, against a stand-in for IntelliJ's GDSL host (IntelliJ itself
 * cannot run here): its top level declares the contexts, the contributors and the script's base
 * class; each contributor is then run at a place in a script, as IntelliJ does while completing
 * there, and what it contributes is recorded. Every word must come out at the places where the
 * runtime accepts it, with its parameters' names and types.
 */
class GdslContributionsSpec extends Specification {

    @Shared
    Vocabulary language = LanguageWords.vocabulary()
    @Shared
    GdslHostScript host = GdslHostScript.run(GdslFile.of(language))

    def "*.dolphin scripts get Dolphin's base class, matched as IntelliJ matches the pattern against the file's path"() {
        given:
        Map declared = host.superClasses[0]
        def matches = { String path -> Pattern.matches('.*' + declared.pattern, path) }

        expect:
        host.superClasses.size() == 1
        declared.superClass == language.script().type().name
        matches('/home/pilot/missions/survey.dolphin')
        !matches('/home/pilot/build.gradle')
        !matches('/home/pilot/survey.dolphin.bak')
    }

    def "every context is for .dolphin files only"() {
        expect:
        host.contributors*.context*.filetypes.unique() == [['dolphin']]
    }

    def "at the top level: the words the base class lacks are contributed, the others are its methods"() {
        given:
        def contributed = host.at(GdslPlace.topLevel())
        Class<?> base = Class.forName(host.superClasses[0].superClass)
        def inherited = language.script().words().values().findAll { w -> base.methods.any { it.name == w.name() } }
        def added = language.script().words().values() - inherited

        expect:
        signatures(contributed.methods) == expected(added)
        contributed.properties == []
        inherited*.name().containsAll(['pick', 'execute', 'waitFor', 'release'])
        added*.name().toSet() == ['mission', 'pos', 'moveDistance', 'move', 'sendMessage', 'downloadMission', 'fenceBreached', 'takenOver', 'takeovers',
                                  'missionFromFile', 'sensor', 'sensorKnown', 'telemetry', 'payloads', 'useSensor',
                                  'declareSensors'] as Set
    }

    def "inside a block opened by #opener: the block's words, with their parameters, and the top-level ones"() {
        given:
        def contributed = host.at(GdslPlace.inside([opener]))
        def topLevel = signatures(host.at(GdslPlace.topLevel()).methods)

        expect:
        signatures(contributed.methods) == topLevel + expected(scope.words().values())

        where:
        [opener, scope] << LanguageWords.vocabulary().scopes().findAll { it.kind() == WordScope.ScopeKind.BLOCK }
                .collectMany { s -> s.openers().collect { [it, s] } }
    }

    def "inside a closure that opens no block, only the top-level words"() {
        expect:
        host.at(GdslPlace.inside(['action'])).methods == host.at(GdslPlace.topLevel()).methods
        host.at(GdslPlace.inside(['waitFor'])).methods == host.at(GdslPlace.topLevel()).methods
    }

    def "a block inside a block sees both, as Groovy resolves through the enclosing closures"() {
        given:
        def names = host.at(GdslPlace.inside(['mission', 'fence'])).methods*.name as Set

        expect:
        names.containsAll(['polygon', 'inclusion', 'enable', 'goPos', 'takeOff', 'mission'])
    }

    def "the words after a word come from the class the word returns: #opener leads to #scope.type().simpleName"() {
        given:
        def declaring = language.scopes().find { it.words().containsKey(opener) }
        def returning = declaring.words()[opener].signatures().findAll { it.returns() == scope.type() }
        def contributed = host.everyPlace().collectMany { host.at(it).methods }.findAll { it.name == opener }
        Class<?> base = Class.forName(host.superClasses[0].superClass)

        expect:
        !returning.isEmpty()
        contributed ? contributed*.type.toSet() == [scope.type().canonicalName] as Set
                : base.methods.findAll { it.name == opener }*.returnType.contains(scope.type())

        where:
        [opener, scope] << LanguageWords.vocabulary().scopes().findAll { it.kind() == WordScope.ScopeKind.CHAIN }
                .collectMany { s -> s.openers().collect { [it, s] } }
    }

    def "the units are properties of numbers, of the type the category's getters return"() {
        given:
        def contributed = host.at(GdslPlace.onNumber())

        expect:
        contributed.methods == []
        contributed.properties.collect { [it.name, it.type, it.doc] }.toSet() ==
                language.units().words().values().collect { [it.name(), 'double', it.description()] }.toSet()
        language.units().words().keySet().every { Units.getMethod('get' + it.capitalize(), Number).returnType == double }
    }

    def "every type the file names is a class IntelliJ can find on the classpath"() {
        given:
        def members = host.everyPlace().collectMany { host.at(it).methods + host.at(it).properties }
        def types = (members*.type + members.collectMany { (it.params ?: [:]).values() as List }).toSet()

        expect:
        types.every { GdslPlace.resolves(it) }
        types.contains('dolphin.dsl.DolphinScript.Then')
        types.contains('dolphin.core.Position[]')
    }

    def "each member's documentation is its word's line (move has one at the top level, another in mission { })"() {
        given:
        Map<String, List<String>> lines = language.scopes().collectMany { it.words().values() }
                .groupBy { it.name() }.collectEntries { k, v -> [k, v*.description()] }
        def methods = host.everyPlace().collectMany { host.at(it).methods }

        expect:
        methods.every { m -> lines[m.name].any { m.doc.startsWith(it.replace('&', '&amp;').replace('<', '&lt;').replace('>', '&gt;')) } }
        lines.move.size() == 2
    }

    /** The forms as the file declares them: name, return type and the parameters in order. */
    private static Set<List> signatures(List<Map> methods) {
        methods.collect { [it.name, it.type, (it.params as Map).collect { k, v -> [k, v] }] }.toSet()
    }

    private static Set<List> expected(Collection<WordEntry> words) {
        words.collectMany { w ->
            w.signatures().collect { s ->
                [w.name(), s.returns().canonicalName, s.params().collect { [it.name(), it.type().canonicalName] }]
            }
        }.toSet()
    }
}

/** Where in a script IntelliJ asks for members: at the top level, inside closures given to words, after a number. */
final class GdslPlace {
    /** The words whose closures enclose the place, outermost first. */
    List<String> enclosing = []
    boolean inClosure
    /** The qualifier's type, as in 10.minutes; null for a plain name. */
    String qualifier

    static GdslPlace topLevel() { new GdslPlace() }

    static GdslPlace inside(List<String> words) { new GdslPlace(enclosing: words, inClosure: true) }

    static GdslPlace onNumber() { new GdslPlace(qualifier: 'java.lang.Integer') }

    /** Whether a context, made by the file's context(...) call, applies here. */
    boolean matches(Map context) {
        if (!(context.filetypes as List).contains('dolphin')) {
            return false
        }
        if (context.ctype) {
            return qualifier != null && Number.isAssignableFrom(Class.forName(qualifier)) && context.ctype == Number.name
        }
        qualifier == null && (context.scope == 'script' || (context.scope == 'closure' && inClosure))
    }

    /** A type name as IntelliJ reads it: primitives, arrays, nested classes by their dotted names. */
    static boolean resolves(String name) {
        if (name in ['void', 'boolean', 'int', 'long', 'double', 'float']) {
            return true
        }
        String binary = name.endsWith('[]') ? name[0..-3] : name
        while (true) {
            try {
                Class.forName(binary)
                return true
            } catch (ClassNotFoundException e) {
                int dot = binary.lastIndexOf('.')
                if (dot < 0) {
                    return false
                }
                binary = binary.substring(0, dot) + '$' + binary.substring(dot + 1)
            }
        }
    }
}

/** What contributors give at a place, recorded. */
final class GdslMembers {
    final GdslPlace place
    final List<Map> methods = []
    final List<Map> properties = []

    GdslMembers(GdslPlace place) { this.place = place }

    void method(Map method) { methods << method }

    void property(Map property) { properties << property }

    /** The enclosing call of that name whose closure holds the place, or null. */
    Object enclosingCall(String name) { name in place.enclosing ? [name: name] : null }
}

/**
 * The stand-in for IntelliJ's GDSL script base class: the top-level calls a GDSL file may make. A
 * call it does not know fails the test, as IntelliJ would refuse the file.
 */
abstract class GdslHostScript extends Script {
    final List<Map> superClasses = []
    final List<Map> contributors = []

    static GdslHostScript run(String gdsl) {
        def config = new CompilerConfiguration(scriptBaseClass: GdslHostScript.name)
        GdslHostScript script = (GdslHostScript) new GroovyShell(GdslHostScript.classLoader, config).parse(gdsl, 'dolphin.gdsl')
        script.run()
        script
    }

    Map context(Map args) { args }

    String scriptScope(Map args = [:]) { 'script' }

    String closureScope(Map args = [:]) { 'closure' }

    void scriptSuperClass(Map args) { superClasses << args }

    void contributor(Map context, Closure body) { contributors << [context: context, body: body] }

    /** Runs every contributor whose context applies at the place, as IntelliJ does while completing there. */
    GdslMembers at(GdslPlace place) {
        GdslMembers members = new GdslMembers(place)
        contributors.findAll { place.matches(it.context) }.each {
            Closure body = ((Closure) it.body).rehydrate(members, members, members)
            body.resolveStrategy = Closure.DELEGATE_ONLY
            body.call()
        }
        members
    }

    /** A place for each kind of context the file contributes to, and inside each block. */
    List<GdslPlace> everyPlace() {
        [GdslPlace.topLevel(), GdslPlace.onNumber()] + LanguageWords.vocabulary().scopes()
                .collectMany { it.openers() }.collect { GdslPlace.inside([it]) }
    }
}
