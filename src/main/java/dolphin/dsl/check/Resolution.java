package dolphin.dsl.check;

import groovy.lang.MetaMethod;
import java.util.List;

/**
 * What a name called with arguments reaches.
 *
 * @param reach what the name reaches
 * @param method the method reached (METHOD)
 * @param owner the class whose methods of that name were considered (METHOD, WRONG_ARGUMENTS)
 * @param named those methods (WRONG_ARGUMENTS)
 */
record Resolution(Reach reach, MetaMethod method, Class<?> owner, List<MetaMethod> named) {

    enum Reach {
        /** A method of a builder, the script's base class, a platform word class or Groovy's. */
        METHOD,
        /** A method the script declares. */
        SCRIPT_METHOD,
        /** A script variable, holding a closure to call. */
        VARIABLE,
        /** Inside a closure whose delegate cannot be known. */
        UNKNOWABLE,
        /** Methods of that name exist, but none takes these arguments. */
        WRONG_ARGUMENTS,
        /** Nothing of that name. */
        MISSING
    }

    static final Resolution SCRIPT_METHOD = new Resolution(Reach.SCRIPT_METHOD, null, null, List.of());
    static final Resolution VARIABLE = new Resolution(Reach.VARIABLE, null, null, List.of());
    static final Resolution UNKNOWABLE = new Resolution(Reach.UNKNOWABLE, null, null, List.of());
    static final Resolution MISSING = new Resolution(Reach.MISSING, null, null, List.of());

    /** Whether the call reaches something that takes it: a method or a variable holding a closure. */
    boolean answers() {
        return reach == Reach.METHOD || reach == Reach.SCRIPT_METHOD || reach == Reach.VARIABLE;
    }

    static Resolution method(MetaMethod m, Class<?> owner) {
        return new Resolution(Reach.METHOD, m, owner, List.of(m));
    }

    static Resolution wrong(Class<?> owner, List<MetaMethod> named) {
        return new Resolution(Reach.WRONG_ARGUMENTS, null, owner, named);
    }
}
