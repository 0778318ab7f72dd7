package dolphin.web;

import groovy.json.JsonGenerator;

/** The web view's JSON writer (Groovy's), with characters as they are rather than \\u escapes. */
final class Json {

    private static final JsonGenerator GENERATOR = new JsonGenerator.Options().disableUnicodeEscaping().build();

    private Json() {
    }

    static String write(Object value) {
        return GENERATOR.toJson(value);
    }

    /** Seconds as the stream gives them: to a tenth. */
    static double tenths(double seconds) {
        return Math.round(seconds * 10) / 10.0;
    }
}
