package dolphin.dsl.check;

/**
 * Where a name is looked up: the script, or a closure inside it. A block's closure resolves its
 * names on its builder first, then on the enclosing frames (DELEGATE_FIRST); a plain closure on the
 * enclosing frames; a closure whose delegate the checker cannot know ({@code obj.with { }}, a closure
 * given to the script's own method) stops every lookup: nothing is reported inside it.
 *
 * @param block the builder class of a block's closure, or null
 * @param unknown whether names inside cannot be known
 * @param outer the enclosing frame; null for the script
 */
record LookupFrame(Class<?> block, boolean unknown, LookupFrame outer) {

    static final LookupFrame SCRIPT = new LookupFrame(null, false, null);

    LookupFrame block(Class<?> builder) {
        return new LookupFrame(builder, false, this);
    }

    LookupFrame plain() {
        return new LookupFrame(null, false, this);
    }

    LookupFrame unknowable() {
        return new LookupFrame(null, true, this);
    }
}
