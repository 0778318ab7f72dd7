package dolphin.mission.dsl;

import dolphin.dsl.Blocks;
import dolphin.dsl.DslException;
import groovy.lang.Closure;
import groovy.lang.GroovyObject;
import groovy.lang.GroovyRuntimeException;
import groovy.lang.MetaClass;
import groovy.lang.MissingPropertyException;
import java.util.Set;
import org.codehaus.groovy.runtime.InvokerHelper;

/**
 * The delegate of a small builder block ({@code pos { }}, {@code moveDistance { }}): its words are
 * methods; it has no properties, so names in the block reach the script's variables (Groovy would
 * otherwise expose the builder's private fields and shadow them). A word read as a variable, as in
 * {@code down -3} (which Groovy reads as {@code down - 3}), is a script error that says so.
 */
abstract class ClosureDelegate implements GroovyObject {

    private final String block;
    private final Set<String> words;
    private Closure<?> body;
    private transient MetaClass metaClass;

    ClosureDelegate(String block, Set<String> words) {
        this.block = block;
        this.words = words;
    }

    /** Runs the block with this object as its delegate. */
    final void run(Closure<?> block) {
        if (block == null) {
            return;
        }
        body = block;
        Blocks.run(block, this);
    }

    @Override
    public MetaClass getMetaClass() {
        if (metaClass == null) {
            metaClass = InvokerHelper.getMetaClass(getClass());
        }
        return metaClass;
    }

    @Override
    public void setMetaClass(MetaClass metaClass) {
        this.metaClass = metaClass;
    }

    @Override
    public Object getProperty(String name) {
        if (words.contains(name)) {
            try {
                return body == null ? null : InvokerHelper.getProperty(body.getOwner(), name);
            } catch (GroovyRuntimeException e) {
                throw new DslException(block + ": '" + name + "' needs its value, e.g. '" + name + " 10'; a negative value"
                        + " needs parentheses, e.g. '" + name + "(-10)' (Groovy reads '" + name + " -10' as '" + name + " minus 10')");
            }
        }
        throw new MissingPropertyException(name, getClass());
    }

    @Override
    public void setProperty(String name, Object value) {
        throw new MissingPropertyException(name, getClass());
    }
}
