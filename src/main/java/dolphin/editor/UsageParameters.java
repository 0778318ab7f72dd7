package dolphin.editor;

import java.util.ArrayList;
import java.util.List;

/**
 * Where each parameter is in a usage such as {@code goPos(lat, lon[, hae])} or
 * {@code move(position, { offset })}: the names and closures after the word, in order, as
 * [start, end) offsets, which signature help highlights.
 */
final class UsageParameters {

    private UsageParameters() {
    }

    static List<int[]> of(String usage, String word) {
        List<int[]> found = new ArrayList<>();
        int at = word.length();
        while (at < usage.length()) {
            char c = usage.charAt(at);
            if (c == '{') {
                int close = usage.indexOf('}', at);
                int end = close < 0 ? usage.length() : close + 1;
                found.add(new int[] {at, end});
                at = end;
            } else if (Character.isJavaIdentifierStart(c)) {
                int start = at;
                while (at < usage.length() && (Character.isJavaIdentifierPart(usage.charAt(at)) || usage.charAt(at) == '.')) {
                    at++;
                }
                found.add(new int[] {start, at});
            } else {
                at++;
            }
        }
        return found;
    }
}
