package dolphin.dsl.check

import dolphin.core.VehiclelessPlatform
import dolphin.docs.DocsExamplesSpec
import dolphin.dsl.Engine
import dolphin.dsl.ScriptError
import dolphin.dsl.vocabulary.Vocabulary
import dolphin.dsl.vocabulary.WordEntry
import dolphin.dsl.vocabulary.WordScope
import dolphin.platform.MAVLinkLanguage
import java.nio.file.Files
import java.nio.file.Path
import org.codehaus.groovy.ast.ClassCodeVisitorSupport
import org.codehaus.groovy.ast.expr.BinaryExpression
import org.codehaus.groovy.ast.expr.ClosureExpression
import org.codehaus.groovy.ast.expr.DeclarationExpression
import org.codehaus.groovy.ast.expr.Expression
import org.codehaus.groovy.ast.expr.MethodCallExpression
import org.codehaus.groovy.ast.expr.TupleExpression
import org.codehaus.groovy.ast.expr.VariableExpression
import org.codehaus.groovy.ast.stmt.ExpressionStatement
import org.codehaus.groovy.control.CompilationUnit
import org.codehaus.groovy.control.CompilerConfiguration
import org.codehaus.groovy.control.Phases
import org.codehaus.groovy.control.SourceUnit
import org.codehaus.groovy.reflection.ReflectionCache
import org.codehaus.groovy.runtime.InvokerHelper
import org.codehaus.groovy.syntax.Types
import spock.lang.Shared
import spock.lang.Specification

/**
 * The check against single mistakes (the figure in README.md's status table): every correct example (dsl-examples/,
 * the correct scripts under src/test/resources, the groovy blocks of docs/ that must pass) is made
 * wrong in one place at a time, in five ways: a word misspelt by one edit, a wrong number of
 * arguments, an argument of a wrong type, a block's word copied outside its block, a variable read
 * under a name never assigned. The check must report each at its line, naming the word or variable,
 * for at least 95 % of each kind. The figures are printed and written to target/mistake-corpus.txt.
 */
class MistakeCorpusSpec extends Specification {

    static final int PER_KIND_AND_SCRIPT = 5
    static final double REQUIRED = 0.95

    enum Mistake { MISSPELT, ARGUMENT_COUNT, ARGUMENT_TYPE, OUTSIDE_ITS_BLOCK, UNDEFINED_VARIABLE }

    /** One mutated script: what was done, where the finding must be, a text it must contain. */
    static final class Mutant {
        String origin
        Mistake kind
        String source
        int line
        String mentions
        String change

        String toString() { "${origin} ${kind} line ${line}: ${change}" }
    }

    @Shared
    Engine engine = new Engine(new VehiclelessPlatform('none'))
    @Shared
    Vocabulary vocabulary

    def setupSpec() {
        engine.addExtension(new MAVLinkLanguage())
        vocabulary = engine.vocabulary()
    }

    /** Every correct example, by where it comes from. */
    static Map<String, String> corpus() {
        Map<String, String> scripts = new TreeMap<>()
        List<Path> files = []
        Files.list(Path.of('dsl-examples')).withCloseable { s -> files.addAll(s.filter { it.toString().endsWith('.dolphin') }.toList()) }
        Files.list(Path.of('src/test/resources/sitl')).withCloseable { s -> files.addAll(s.filter { it.toString().endsWith('.dolphin') }.toList()) }
        files << Path.of('src/test/resources/scripts/good.dolphin')
        files.each { scripts[it.toString()] = Files.readString(it) }
        DocsExamplesSpec.blocks().findAll { it.kind == 'groovy' && !it.has('exit') }.each { b ->
            scripts["${b.doc}:${b.line}".toString()] = b.text
        }
        scripts
    }

    def "every example of the corpus is correct: no finding"() {
        when:
        Map<String, List<String>> wrong = corpus().collectEntries { name, text -> [name, check(text)*.toString()] }
                .findAll { it.value } as Map<String, List<String>>

        then:
        wrong == [:]
    }

    def "single mistakes are reported at their line, at least 95 % of each kind"() {
        given:
        List<Mutant> mutants = corpus().collectMany { name, text -> mutants(name, text) }

        when:
        Map<Mistake, List<Mutant>> missed = [:]
        Map<Mistake, Integer> made = [:]
        mutants.each { Mutant m ->
            made[m.kind] = (made[m.kind] ?: 0) + 1
            List<ScriptError> found = check(m.source)
            if (!found.any { it.line == m.line && it.message.contains(m.mentions) }) {
                missed.computeIfAbsent(m.kind) { [] } << m
                m.change += " -> " + (found ? found*.toString().join(' | ') : 'no finding')
            }
        }
        String table = Mistake.values().collect { k ->
            int n = made[k] ?: 0
            int ok = n - (missed[k]?.size() ?: 0)
            String.format('%-20s %5d made %5d reported at their line %6.1f %%', k, n, ok, n ? 100.0 * ok / n : 0d)
        }.join('\n')
        Files.createDirectories(Path.of('target'))
        Files.writeString(Path.of('target/mistake-corpus.txt'), table + '\n\nmissed:\n' + missed.values().flatten().join('\n') + '\n')
        println "mistake corpus (${corpus().size()} scripts):\n${table}"

        then:
        Mistake.values().every { (made[it] ?: 0) >= 20 }
        Mistake.values().findAll { k -> (made[k] - (missed[k]?.size() ?: 0)) < REQUIRED * made[k] }.isEmpty()
    }

    List<ScriptError> check(String source) {
        engine.check(source, 'mutant.dolphin')
    }

    // ---- making mistakes

    /** The call sites and variable reads of a correct script, from its syntax tree. */
    static final class Site {
        MethodCallExpression call
        List<Expression> args
        List<String> blocks
        ClosureExpression enclosing
        boolean wholeLine
    }

    List<Mutant> mutants(String origin, String text) {
        List<String> lines = text.readLines()
        List<Site> sites = []
        List<VariableExpression> reads = []
        Set<String> names = []
        boolean usesBinding = false
        def unit = new CompilationUnit(new CompilerConfiguration(scriptBaseClass: 'dolphin.dsl.DolphinScript'))
        unit.addSource('corpus.groovy', text)
        unit.compile(Phases.CONVERSION)
        Set<Expression> targets = Collections.newSetFromMap(new IdentityHashMap<>())
        Set<Expression> statements = Collections.newSetFromMap(new IdentityHashMap<>())
        List<List> stack = []
        def visitor = new ClassCodeVisitorSupport() {
            SourceUnit getSourceUnit() { null }

            void visitExpressionStatement(ExpressionStatement s) {
                statements << s.expression
                super.visitExpressionStatement(s)
            }

            void visitDeclarationExpression(DeclarationExpression d) {
                (d.leftExpression instanceof TupleExpression ? ((TupleExpression) d.leftExpression).expressions : [d.leftExpression]).each {
                    targets << it
                    names << it.text
                }
                d.rightExpression.visit(this)
            }

            void visitBinaryExpression(BinaryExpression b) {
                if (Types.isAssignment(b.operation.type)) {
                    targets << b.leftExpression
                    if (b.leftExpression instanceof VariableExpression) {
                        names << b.leftExpression.text
                    }
                }
                super.visitBinaryExpression(b)
            }

            void visitVariableExpression(VariableExpression v) {
                usesBinding |= v.name == 'binding'
                if (!(v in targets) && v.lineNumber > 0 && !v.thisExpression && !v.superExpression && v.name != 'it'
                        && !Character.isUpperCase(v.name.charAt(0))) {
                    reads << v
                }
            }

            void visitClosureExpression(ClosureExpression c) {
                c.parameters?.each { names << it.name }
                super.visitClosureExpression(c)
            }

            void visitMethodCallExpression(MethodCallExpression call) {
                String name = call.methodAsString
                List<Expression> args = call.arguments instanceof TupleExpression ? ((TupleExpression) call.arguments).expressions : [call.arguments]
                if (call.implicitThis && name && vocabulary.names().contains(name)) {
                    sites << new Site(call: call, args: args, blocks: stack.collect { it[0] } as List<String>,
                            enclosing: stack ? stack[-1][1] as ClosureExpression : null,
                            wholeLine: call in statements && call.lineNumber == call.lastLineNumber
                                    && lines[call.lineNumber - 1].trim() == callText(lines, call).trim())
                }
                call.objectExpression.visit(this)
                boolean opens = call.implicitThis && vocabulary.scopes().any { it.kind() == WordScope.ScopeKind.BLOCK && name in it.openers() }
                args.each { a ->
                    if (a instanceof ClosureExpression && opens) {
                        stack << [name, a]
                        a.code.visit(this)
                        stack.removeLast()
                    } else {
                        a.visit(this)
                    }
                }
            }
        }
        unit.AST.classes.each { visitor.visitClass(it) }
        names.addAll(vocabulary.names())

        Random random = new Random(origin.hashCode())
        List<Mutant> out = []
        out += pick(sites.collect { misspelt(origin, lines, it, names, random) }, random)
        out += pick(sites.collect { argumentCount(origin, lines, it) }, random)
        out += pick(sites.collect { argumentType(origin, lines, it, random) }, random)
        out += pick(sites.collect { outsideItsBlock(origin, lines, it) }, random)
        if (!usesBinding) {
            out += pick(reads.collect { undefined(origin, lines, it, names) }, random)
        }
        out
    }

    static List<Mutant> pick(List<Mutant> candidates, Random random) {
        List<Mutant> made = candidates.findAll()
        Collections.shuffle(made, random)
        made.take(PER_KIND_AND_SCRIPT)
    }

    /** The scope whose word the call is: the innermost enclosing block that has it, else the script's. */
    WordEntry word(Site s) {
        for (String opener : s.blocks.reverse()) {
            WordScope scope = vocabulary.scopes().find { it.kind() == WordScope.ScopeKind.BLOCK && opener in it.openers() }
            if (scope?.words()?.containsKey(s.call.methodAsString)) {
                return scope.words()[s.call.methodAsString]
            }
        }
        vocabulary.script().words()[s.call.methodAsString]
    }

    Mutant misspelt(String origin, List<String> lines, Site s, Set<String> names, Random random) {
        String name = s.call.methodAsString
        List<String> variants = []
        for (int i = 1; i < name.length(); i++) {
            variants << name.substring(0, i) + name.substring(i + 1)
            if (i < name.length() - 1) {
                variants << name.substring(0, i) + name[i + 1] + name[i] + name.substring(i + 2)
            }
            variants << name.substring(0, i) + (name[i] == 'x' ? 'q' : 'x') + name.substring(i + 1)
        }
        variants = variants.findAll { v -> !(v in names) && !known(v) }
        if (!variants) {
            return null
        }
        String typo = variants[random.nextInt(variants.size())]
        def at = s.call.method
        mutant(origin, Mistake.MISSPELT, replace(lines, at.lineNumber, at.columnNumber, at.columnNumber + name.length(), typo),
                at.lineNumber, typo, "${name} -> ${typo}")
    }

    /** Whether the script's base class or Groovy answers the name: a typo that happens to be a real method. */
    static boolean known(String name) {
        !InvokerHelper.getMetaClass(Class.forName('dolphin.dsl.DolphinScript')).respondsTo(null, name).isEmpty()
    }

    Mutant argumentCount(String origin, List<String> lines, Site s) {
        WordEntry w = word(s)
        int n = s.args.size()
        if (w == null || s.args.any { it instanceof ClosureExpression } || !oneLine(s)) {
            return null
        }
        int line = s.call.lineNumber
        if (n > 0 && !w.takes(n + 1)) {
            Expression last = s.args[-1]
            return mutant(origin, Mistake.ARGUMENT_COUNT, replace(lines, line, last.lastColumnNumber, last.lastColumnNumber, ', 7'),
                    line, s.call.methodAsString, "${s.call.methodAsString}: ${n} -> ${n + 1} arguments")
        }
        if (n >= 2 && !w.takes(n - 1)) {
            return mutant(origin, Mistake.ARGUMENT_COUNT, replace(lines, line, s.args[-2].lastColumnNumber, s.args[-1].lastColumnNumber, ''),
                    line, s.call.methodAsString, "${s.call.methodAsString}: ${n} -> ${n - 1} arguments")
        }
        null
    }

    Mutant argumentType(String origin, List<String> lines, Site s, Random random) {
        WordEntry w = word(s)
        if (w == null || s.args.isEmpty() || s.args.any { it instanceof ClosureExpression } || !oneLine(s)
                || s.args.any { it.class.simpleName == 'MapExpression' || it.class.simpleName == 'NamedArgumentListExpression' }) {
            return null
        }
        int n = s.args.size()
        int i = random.nextInt(n)
        def forms = w.signatures().findAll { it.takes(n) }
        String replacement = [["'text'", String], ['7', Integer]].find { value, type ->
            forms.every { sig -> !fits(sig.params()[Math.min(i, sig.params().size() - 1)].type(), type) }
        }?.get(0)
        if (replacement == null) {
            return null
        }
        Expression a = s.args[i]
        mutant(origin, Mistake.ARGUMENT_TYPE, replace(lines, a.lineNumber, a.columnNumber, a.lastColumnNumber, replacement),
                a.lineNumber, s.call.methodAsString, "${s.call.methodAsString}: argument ${i + 1} ${a.text} -> ${replacement}")
    }

    static boolean fits(Class<?> param, Class<?> arg) {
        ReflectionCache.getCachedClass(param).isAssignableFrom(arg)
    }

    /** A block's word, its whole line copied just after the block, where its block is not open. */
    Mutant outsideItsBlock(String origin, List<String> lines, Site s) {
        if (s.enclosing == null || !s.wholeLine || lines[s.enclosing.lastLineNumber - 1].trim() != '}') {
            return null
        }
        WordScope inner = vocabulary.scopes().find { it.kind() == WordScope.ScopeKind.BLOCK && s.blocks[-1] in it.openers() }
        if (!inner?.words()?.containsKey(s.call.methodAsString)) {
            return null
        }
        List<String> copy = new ArrayList<>(lines)
        int after = s.enclosing.lastLineNumber
        copy.add(after, lines[s.call.lineNumber - 1].trim())
        mutant(origin, Mistake.OUTSIDE_ITS_BLOCK, copy.join('\n') + '\n', after + 1, s.call.methodAsString,
                "${s.call.methodAsString} copied out of ${s.blocks[-1]} { } to line ${after + 1}")
    }

    Mutant undefined(String origin, List<String> lines, VariableExpression v, Set<String> names) {
        String wrong = [v.name + '2', v.name + 'x', 'my' + v.name].find { !(it in names) }
        mutant(origin, Mistake.UNDEFINED_VARIABLE, replace(lines, v.lineNumber, v.columnNumber, v.columnNumber + v.name.length(), wrong),
                v.lineNumber, wrong, "${v.name} -> ${wrong}")
    }

    static boolean oneLine(Site s) {
        s.call.lineNumber == s.call.lastLineNumber && s.args.every { it.lineNumber == s.call.lineNumber && it.lastLineNumber == s.call.lineNumber }
    }

    static String callText(List<String> lines, MethodCallExpression call) {
        lines[call.lineNumber - 1].substring(call.columnNumber - 1, call.lastColumnNumber - 1)
    }

    /** The script with columns [from, to) of a line (1-based) replaced. */
    static String replace(List<String> lines, int line, int from, int to, String with) {
        List<String> copy = new ArrayList<>(lines)
        String l = copy[line - 1]
        copy[line - 1] = l.substring(0, from - 1) + with + l.substring(to - 1)
        copy.join('\n') + '\n'
    }

    static Mutant mutant(String origin, Mistake kind, String source, int line, String mentions, String change) {
        new Mutant(origin: origin, kind: kind, source: source, line: line, mentions: mentions, change: change)
    }
}
