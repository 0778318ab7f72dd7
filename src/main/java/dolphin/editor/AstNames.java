package dolphin.editor;

import java.util.Comparator;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.Map;
import org.codehaus.groovy.ast.CodeVisitorSupport;
import org.codehaus.groovy.ast.MethodNode;
import org.codehaus.groovy.ast.ModuleNode;
import org.codehaus.groovy.ast.Parameter;
import org.codehaus.groovy.ast.expr.BinaryExpression;
import org.codehaus.groovy.ast.expr.Expression;
import org.codehaus.groovy.ast.expr.TupleExpression;
import org.codehaus.groovy.ast.expr.VariableExpression;
import org.codehaus.groovy.ast.stmt.ForStatement;
import org.codehaus.groovy.control.CompilationUnit;
import org.codehaus.groovy.control.Phases;

/**
 * The names a script assigns or declares, from Groovy's syntax tree (parsed to the CONVERSION phase,
 * nothing resolved): assignments, {@code def} variables (also {@code def (a, b) = ...}), for-loop
 * variables and methods. Throws when the script does not parse: {@link ScriptNames} reads those.
 */
final class AstNames {

    private AstNames() {
    }

    static Map<String, NamedPlace> of(String text) {
        CompilationUnit unit = new CompilationUnit();
        unit.addSource("script.dolphin", text);
        unit.compile(Phases.CONVERSION);
        ModuleNode module = unit.getAST().getModules().get(0);
        LineMap lines = new LineMap(text);
        Map<String, NamedPlace> found = new HashMap<>();
        Collector collector = new Collector(lines, found);
        module.getStatementBlock().visit(collector);
        for (MethodNode m : module.getMethods()) {
            int line = m.getLineNumber() - 1;
            int name = lines.lineText(line).indexOf(m.getName(), m.getColumnNumber() - 1);
            if (name >= 0) {
                collector.keep(new NamedPlace(m.getName(), lines.lineStart(line) + name, true));
            }
            m.getCode().visit(collector);
        }
        Map<String, NamedPlace> inOrder = new LinkedHashMap<>();
        found.values().stream().sorted(Comparator.comparingInt(NamedPlace::offset)).forEach(p -> inOrder.put(p.name(), p));
        return inOrder;
    }

    /** Keeps the earliest place of each name. */
    private static final class Collector extends CodeVisitorSupport {
        private final LineMap lines;
        private final Map<String, NamedPlace> found;

        Collector(LineMap lines, Map<String, NamedPlace> found) {
            this.lines = lines;
            this.found = found;
        }

        @Override
        public void visitBinaryExpression(BinaryExpression e) {
            if ("=".equals(e.getOperation().getText())) {
                assigned(e.getLeftExpression());
            }
            super.visitBinaryExpression(e);
        }

        @Override
        public void visitForLoop(ForStatement loop) {
            Parameter v = loop.getVariable();
            if (v != null && v.getLineNumber() > 0) {
                keep(new NamedPlace(v.getName(), offset(v.getLineNumber(), v.getColumnNumber()), false));
            }
            super.visitForLoop(loop);
        }

        private void assigned(Expression left) {
            if (left instanceof VariableExpression v && v.getLineNumber() > 0) {
                keep(new NamedPlace(v.getName(), offset(v.getLineNumber(), v.getColumnNumber()), false));
            } else if (left instanceof TupleExpression t) {
                t.getExpressions().forEach(this::assigned);
            }
        }

        void keep(NamedPlace p) {
            found.merge(p.name(), p, (a, b) -> a.offset() <= b.offset() ? a : b);
        }

        private int offset(int line, int column) {
            return lines.lineStart(line - 1) + column - 1;
        }
    }
}
