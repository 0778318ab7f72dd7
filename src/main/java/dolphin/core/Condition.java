package dolphin.core;

/** A guard evaluated on the script thread at each step; Groovy closures coerce to it. */
@FunctionalInterface
public interface Condition {
    boolean holds();
}
