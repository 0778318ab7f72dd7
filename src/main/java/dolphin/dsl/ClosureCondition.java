package dolphin.dsl;

import dolphin.core.Condition;
import groovy.lang.Closure;
import org.codehaus.groovy.runtime.typehandling.DefaultTypeTransformation;

/** A script closure as a guard, with Groovy truth (null, 0 and empty are false). */
public record ClosureCondition(Closure<?> closure) implements Condition {
    @Override
    public boolean holds() {
        return DefaultTypeTransformation.castToBoolean(closure.call());
    }
}
