package dolphin.dsl;

import groovy.lang.Closure;
import groovy.lang.DelegatesTo;

/** What the language's blocks share: running a block with its builder. */
public final class Blocks {

    private Blocks() {
    }

    /**
     * Runs a copy of {@code block} with {@code delegate} resolving its names first (DELEGATE_FIRST), so
     * that the block's words reach the builder and everything else the script; the caller's closure is
     * left as it was. Returns what the block returns.
     */
    public static Object run(@DelegatesTo(strategy = Closure.DELEGATE_FIRST) Closure<?> block, Object delegate, Object... arguments) {
        Closure<?> c = (Closure<?>) block.clone();
        c.setDelegate(delegate);
        c.setResolveStrategy(Closure.DELEGATE_FIRST);
        return c.call(arguments);
    }
}
