package dolphin.editor;

/**
 * One token of a statement as {@link CodeScanner} reads it.
 *
 * @param kind what it is
 * @param text a word's or symbol's text; for a closed bracket, the word before it (or "")
 * @param start its first character's offset
 * @param end the offset just after it
 */
record ScanToken(TokenKind kind, String text, int start, int end) {

    enum TokenKind {
        WORD, NUMBER, STRING, SYMBOL,
        /** a closed { } */
        BLOCK,
        /** a closed ( ) or [ ] */
        GROUP
    }

    boolean is(TokenKind k, String t) {
        return kind == k && text.equals(t);
    }
}
