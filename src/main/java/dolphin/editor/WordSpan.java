package dolphin.editor;

/**
 * The name (Java identifier) at a place in a text: the one the place is in, or the one it ends.
 *
 * @param start its first character
 * @param end just after its last
 */
record WordSpan(int start, int end) {

    /** The name at {@code offset}, or null when there is none. */
    static WordSpan at(String text, int offset) {
        int at = Math.max(0, Math.min(offset, text.length()));
        if ((at == text.length() || !Character.isJavaIdentifierPart(text.charAt(at)))
                && at > 0 && Character.isJavaIdentifierPart(text.charAt(at - 1))) {
            at--;
        }
        if (at >= text.length() || !Character.isJavaIdentifierPart(text.charAt(at))) {
            return null;
        }
        int start = at;
        while (start > 0 && Character.isJavaIdentifierPart(text.charAt(start - 1))) {
            start--;
        }
        int end = at;
        while (end < text.length() && Character.isJavaIdentifierPart(text.charAt(end))) {
            end++;
        }
        return Character.isJavaIdentifierStart(text.charAt(start)) ? new WordSpan(start, end) : null;
    }

    String of(String text) {
        return text.substring(start, end);
    }
}
