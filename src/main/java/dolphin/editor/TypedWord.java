package dolphin.editor;

/**
 * The word completion works on: what is typed of it before the cursor, and the whole of it, which a
 * chosen item replaces ({@code mv|oe} becomes {@code move}, not {@code moveoe}). With nothing typed,
 * the empty place at the cursor: a word after it is another word, left alone.
 *
 * @param typed its text before the cursor
 * @param whole its text, the part after the cursor too
 * @param start its first character's offset
 * @param end the offset just after it
 * @param argumentsFollow whether something stands after it on its line (its arguments, maybe), so
 *        that inserting placeholders for them would write them twice
 */
record TypedWord(String typed, String whole, int start, int end, boolean argumentsFollow) {

    static TypedWord at(String text, CursorContext context) {
        int cursor = context.offset();
        int start = context.prefixStart();
        int end = cursor;
        while (start < cursor && end < text.length() && Character.isJavaIdentifierPart(text.charAt(end))) {
            end++;
        }
        return new TypedWord(text.substring(start, cursor), text.substring(start, end), start, end, somethingAfter(text, end));
    }

    /** Anything on the line after this offset but blanks, closing brackets, a comma, a semicolon or a comment. */
    private static boolean somethingAfter(String text, int from) {
        int at = from;
        while (at < text.length() && (text.charAt(at) == ' ' || text.charAt(at) == '\t')) {
            at++;
        }
        if (at == text.length() || text.startsWith("//", at) || text.startsWith("/*", at)) {
            return false;
        }
        return "\r\n)]},;".indexOf(text.charAt(at)) < 0;
    }
}
