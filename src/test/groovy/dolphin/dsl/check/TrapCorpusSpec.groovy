package dolphin.dsl.check

import dolphin.core.VehiclelessPlatform
import dolphin.dsl.Engine
import dolphin.dsl.ScriptError
import dolphin.platform.MAVLinkLanguage
import java.nio.file.Files
import java.nio.file.Path
import org.codehaus.groovy.ast.ClassCodeVisitorSupport
import org.codehaus.groovy.ast.expr.BinaryExpression
import org.codehaus.groovy.ast.expr.ClosureExpression
import org.codehaus.groovy.ast.expr.DeclarationExpression
import org.codehaus.groovy.ast.expr.Expression
import org.codehaus.groovy.ast.expr.MapExpression
import org.codehaus.groovy.ast.expr.MethodCallExpression
import org.codehaus.groovy.ast.expr.TupleExpression
import org.codehaus.groovy.ast.expr.VariableExpression
import org.codehaus.groovy.ast.stmt.ExpressionStatement
import org.codehaus.groovy.control.CompilationUnit
import org.codehaus.groovy.control.CompilerConfiguration
import org.codehaus.groovy.control.Phases
import org.codehaus.groovy.control.SourceUnit
import spock.lang.Shared
import spock.lang.Specification

import static dolphin.testing.FixApplier.applied

/**
 * The traps of the Groovy embedding, as MistakeCorpusSpec does for typos: every correct example of the
 * corpus is made wrong in one place at a time by writing it as Groovy reads it differently (a task
 * or a duration after a key without its parentheses, a second word on the next line, execute alone on its line, an
 * entry without its comma, an operator after an onError block, a parenthesis right after execute, a
 * def key). Every mutant must be explained at its line, and the fix of the finding that explains it
 * must give a script that checks clean. The figures are printed and written to target/trap-corpus.txt.
 */
class TrapCorpusSpec extends Specification {

    enum Trap { TASK_AFTER_KEY, DURATION_AFTER_KEY, SECOND_WORD_ON_NEXT_LINE, EXECUTE_ALONE, ENTRY_WITHOUT_COMMA, OPERATOR_AFTER_HANDLER,
        PARENTHESIS_AFTER_EXECUTE, DEF_KEY }

    static final class Mutant {
        String origin
        Trap trap
        String source
        int line
        String mentions
        String outcome = ''

        String toString() { "${origin} ${trap} line ${line}${outcome}" }
    }

    @Shared
    Engine engine = new Engine(new VehiclelessPlatform('none'))

    def setupSpec() {
        engine.addExtension(new MAVLinkLanguage())
    }

    def "every trap mutant of the corpus is explained at its line, and its fix checks clean"() {
        given:
        List<Mutant> mutants = MistakeCorpusSpec.corpus().collectMany { name, text -> mutants(name, text) }

        when:
        Map<Trap, List<Mutant>> unexplained = [:]
        Map<Trap, List<Mutant>> unfixed = [:]
        mutants.each { Mutant m ->
            List<ScriptError> found = engine.check(m.source, 'mutant.dolphin')
            ScriptError explaining = found.find { it.line() == m.line && it.message().contains(m.mentions) }
            if (explaining == null) {
                m.outcome = ' -> ' + (found ? found*.toString().join(' | ') : 'no finding')
                unexplained.computeIfAbsent(m.trap) { [] } << m
                return
            }
            List<ScriptError> after = explaining.fixes() ? engine.check(applied(m.source, explaining.fixes()[0]), 'mutant.dolphin') : null
            if (after != []) {
                m.outcome = ' -> ' + (after == null ? 'no fix' : 'after the fix: ' + after*.toString().join(' | '))
                unfixed.computeIfAbsent(m.trap) { [] } << m
            }
        }
        String table = Trap.values().collect { t ->
            int n = mutants.count { it.trap == t }
            String.format('%-26s %4d made %4d explained %4d fixed', t, n, n - (unexplained[t]?.size() ?: 0),
                    n - (unexplained[t]?.size() ?: 0) - (unfixed[t]?.size() ?: 0))
        }.join('\n')
        Files.createDirectories(Path.of('target'))
        Files.writeString(Path.of('target/trap-corpus.txt'), table + '\n\nunexplained or unfixed:\n' +
                (unexplained.values().flatten() + unfixed.values().flatten()).join('\n') + '\n')
        println "trap corpus (${mutants.size()} mutants):\n${table}"

        then:
        Trap.values().every { t -> mutants.any { it.trap == t } }
        unexplained.values().flatten() == []
        unfixed.values().flatten() == []
    }

    // ---- making traps

    List<Mutant> mutants(String origin, String text) {
        List<String> lines = text.readLines()
        def unit = new CompilationUnit(new CompilerConfiguration(scriptBaseClass: 'dolphin.dsl.DolphinScript'))
        unit.addSource('corpus.groovy', text)
        unit.compile(Phases.CONVERSION)
        List<Mutant> out = []
        Map<String, Integer> keys = [:]
        List<DeclarationExpression> declarations = []
        List<BinaryExpression> assignments = []
        Set<Expression> statements = Collections.newSetFromMap(new IdentityHashMap<>())
        List<MethodCallExpression> calls = []
        def visitor = new ClassCodeVisitorSupport() {
            SourceUnit getSourceUnit() { null }

            void visitExpressionStatement(ExpressionStatement s) {
                statements << s.expression
                if (s.expression instanceof BinaryExpression && s.expression.operation.text == '=') {
                    statements << s.expression.rightExpression
                    if (s.expression.leftExpression instanceof VariableExpression && !(s.expression instanceof DeclarationExpression)) {
                        assignments << (BinaryExpression) s.expression
                    }
                }
                super.visitExpressionStatement(s)
            }

            void visitMethodCallExpression(MethodCallExpression call) {
                calls << call
                super.visitMethodCallExpression(call)
            }

            void visitDeclarationExpression(DeclarationExpression d) {
                declarations << d
                super.visitDeclarationExpression(d)
            }
        }
        unit.AST.classes.each { visitor.visitClass(it) }
        for (MethodCallExpression call : calls) {
            List<Expression> args = call.arguments instanceof TupleExpression ? ((TupleExpression) call.arguments).expressions : [call.arguments]
            boolean execute = call.implicitThis && call.methodAsString == 'execute'
            boolean secondWord = !call.implicitThis && call.methodAsString in ['then', 'run', 'onError']
            if (execute) {
                args.findAll { it instanceof MapExpression }.each { m ->
                    ((MapExpression) m).mapEntryExpressions.each { keys.putIfAbsent(it.keyExpression.text, it.keyExpression.lineNumber) }
                }
                out.addAll([executeAlone(origin, lines, call), parenthesisAfterExecute(origin, lines, call, args)].findAll())
            }
            if (execute || secondWord) {
                args.findAll { it instanceof MapExpression }.each { m ->
                    ((MapExpression) m).mapEntryExpressions.each { e ->
                        out.addAll([taskAfterKey(origin, lines, e.valueExpression), durationAfterKey(origin, lines, e.valueExpression)].findAll())
                    }
                }
            }
            if (secondWord && call in statements) {
                out.addAll([secondWordOnNextLine(origin, lines, call), operatorAfterHandler(origin, lines, call, args)].findAll())
            }
        }
        out.addAll(entriesWithoutComma(origin, lines))
        out.addAll(defKeys(origin, lines, keys, assignments, declarations))
        out
    }

    /** {@code v: watch(t) onError ...} written {@code v: watch t onError ...}. */
    static Mutant taskAfterKey(String origin, List<String> lines, Expression value) {
        if (!(value instanceof MethodCallExpression) || value.methodAsString != 'watch' || !value.implicitThis) {
            return null
        }
        List<Expression> args = ((TupleExpression) value.arguments).expressions
        if (args.size() != 1 || !(args[0] instanceof VariableExpression)) {
            return null
        }
        String task = args[0].text
        String line = lines[value.lineNumber - 1]
        int at = value.columnNumber - 1
        if (!line.startsWith("watch(${task})", at)) {
            return null
        }
        mutant(origin, Trap.TASK_AFTER_KEY, replaced(lines, value.lineNumber, line.substring(0, at) + "watch ${task}" +
                line.substring(at + "watch(${task})".length())), value.lineNumber, "'onError' is read here as an argument")
    }

    /** {@code v: during(30) run t} written {@code v: during 30 run t}. */
    static Mutant durationAfterKey(String origin, List<String> lines, Expression value) {
        if (!(value instanceof MethodCallExpression) || value.methodAsString != 'during' || !value.implicitThis) {
            return null
        }
        List<Expression> args = ((TupleExpression) value.arguments).expressions
        String line = lines[value.lineNumber - 1]
        int at = value.columnNumber - 1
        if (args.size() != 1 || !line.startsWith("during(${args[0].text})", at)) {
            return null
        }
        mutant(origin, Trap.DURATION_AFTER_KEY, replaced(lines, value.lineNumber, line.substring(0, at) + "during ${args[0].text}" +
                line.substring(at + "during(${args[0].text})".length())), value.lineNumber, "Expected the duration in parentheses")
    }

    /** {@code waitFor { c } then t} with {@code then t} moved to the next line. */
    static Mutant secondWordOnNextLine(String origin, List<String> lines, MethodCallExpression call) {
        Expression word = call.method
        String line = lines[word.lineNumber - 1]
        if (word.lineNumber != call.objectExpression.lastLineNumber || !line.startsWith(call.methodAsString, word.columnNumber - 1)) {
            return null
        }
        String indent = line.takeWhile { it == ' ' } + '    '
        List<String> copy = new ArrayList<>(lines)
        copy[word.lineNumber - 1] = line.substring(0, word.columnNumber - 1).stripTrailing()
        copy.add(word.lineNumber, indent + line.substring(word.columnNumber - 1))
        mutant(origin, Trap.SECOND_WORD_ON_NEXT_LINE, copy.join('\n') + '\n', word.lineNumber + 1,
                "'${call.methodAsString}' begins a new statement")
    }

    /** {@code execute v1: t} written {@code execute}, then {@code v1: t} on the next line. */
    static Mutant executeAlone(String origin, List<String> lines, MethodCallExpression call) {
        String line = lines[call.lineNumber - 1]
        if (!(line ==~ /^\s*execute\s+\S.*/) || line.indexOf('execute') != call.columnNumber - 1) {
            return null
        }
        String indent = line.takeWhile { it == ' ' }
        List<String> copy = new ArrayList<>(lines)
        copy[call.lineNumber - 1] = indent + 'execute'
        copy.add(call.lineNumber, indent + '    ' + line.substring(line.indexOf('execute') + 'execute'.length()).strip())
        mutant(origin, Trap.EXECUTE_ALONE, copy.join('\n') + '\n', call.lineNumber, "'execute' stands alone on its line")
    }

    /** {@code execute a >> b} written {@code execute (a) >> b}. */
    static Mutant parenthesisAfterExecute(String origin, List<String> lines, MethodCallExpression call, List<Expression> args) {
        if (args.size() != 1 || !(args[0] instanceof BinaryExpression) || !(args[0].operation.text in ['>>', '|', '/'])) {
            return null
        }
        Expression left = ((BinaryExpression) args[0]).leftExpression
        if (left.lineNumber != left.lastLineNumber || lines[call.lineNumber - 1].substring(call.columnNumber - 1).startsWith('execute(')) {
            return null
        }
        String line = lines[left.lineNumber - 1]
        String wrapped = line.substring(0, left.columnNumber - 1) + '(' + line.substring(left.columnNumber - 1, left.lastColumnNumber - 1) + ')' +
                line.substring(left.lastColumnNumber - 1)
        mutant(origin, Trap.PARENTHESIS_AFTER_EXECUTE, replaced(lines, left.lineNumber, wrapped), call.lineNumber,
                "Groovy takes the parentheses after 'execute' as its whole argument list")
    }

    /** {@code watch(t) onError { ... }} followed by {@code >> idle(1)}, without parentheses around the watch. */
    static Mutant operatorAfterHandler(String origin, List<String> lines, MethodCallExpression call, List<Expression> args) {
        if (call.methodAsString != 'onError' || args.size() != 1 || !(args[0] instanceof ClosureExpression)) {
            return null
        }
        Expression handler = args[0]
        String line = lines[handler.lastLineNumber - 1]
        if (line.substring(handler.lastColumnNumber - 1).trim()) {
            return null
        }
        mutant(origin, Trap.OPERATOR_AFTER_HANDLER, replaced(lines, handler.lastLineNumber, line + ' >> idle(1)'), handler.lineNumber,
                "'>> ...' after the onError block applies to the")
    }

    /** An entry of a call over several lines, {@code v1: a,} then {@code v2: b}, with its comma lost. */
    static List<Mutant> entriesWithoutComma(String origin, List<String> lines) {
        List<Mutant> out = []
        for (int i = 0; i + 1 < lines.size(); i++) {
            if (lines[i] =~ /^\s*(\w+\s*=\s*)?(execute\s+)?[A-Za-z_]\w*\s*:.*,\s*$/ && lines[i + 1] =~ /^\s*[A-Za-z_]\w*\s*:\s*\S/
                    && !(lines[i] =~ /\/\//)) {
                out << mutant(origin, Trap.ENTRY_WITHOUT_COMMA, replaced(lines, i + 1, lines[i].replaceFirst(/,\s*$/, '')), i + 2,
                        "is read as a label, not as an entry of the call on line ${i + 1}")
            }
        }
        out
    }

    /** A vehicle set an execute names by its key, assigned with {@code def}. */
    static List<Mutant> defKeys(String origin, List<String> lines, Map<String, Integer> keys, List<BinaryExpression> assignments,
                                List<DeclarationExpression> declarations) {
        Set<String> declared = declarations.collect { it.leftExpression.text } as Set
        assignments.findAll { keys.containsKey(it.leftExpression.text) && !(it.leftExpression.text in declared) }
                .unique { it.leftExpression.text }
                .findAll { a -> lines[a.lineNumber - 1].substring(a.columnNumber - 1).startsWith(a.leftExpression.text) }
                .collect { a ->
                    String line = lines[a.lineNumber - 1]
                    mutant(origin, Trap.DEF_KEY, replaced(lines, a.lineNumber, line.substring(0, a.columnNumber - 1) + 'def ' +
                            line.substring(a.columnNumber - 1)), keys[a.leftExpression.text], "'${a.leftExpression.text}' is declared with 'def'")
                }
    }

    static String replaced(List<String> lines, int line, String with) {
        List<String> copy = new ArrayList<>(lines)
        copy[line - 1] = with
        copy.join('\n') + '\n'
    }

    static Mutant mutant(String origin, Trap trap, String source, int line, String mentions) {
        new Mutant(origin: origin, trap: trap, source: source, line: line, mentions: mentions)
    }
}
