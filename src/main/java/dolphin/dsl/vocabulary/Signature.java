package dolphin.dsl.vocabulary;

import java.util.List;

/**
 * One form of a word, as one public method declares it.
 *
 * @param params its parameters, in order
 * @param varargs whether the last parameter takes any number of values
 * @param returns what the word gives back
 */
public record Signature(List<Param> params, boolean varargs, Class<?> returns) {

    public Signature {
        params = List.copyOf(params);
    }

    /** Whether a call with this many arguments can match it. */
    public boolean takes(int arguments) {
        return varargs ? arguments >= params.size() - 1 : arguments == params.size();
    }

    /** Whether the other form's parameters are this one's, some left out, in the same order. */
    boolean contains(Signature other) {
        int at = 0;
        for (Param p : other.params) {
            while (at < params.size() && !same(params.get(at), p)) {
                at++;
            }
            if (at == params.size()) {
                return false;
            }
            at++;
        }
        return true;
    }

    static boolean same(Param a, Param b) {
        return a.name().equals(b.name()) && a.type().equals(b.type());
    }
}
