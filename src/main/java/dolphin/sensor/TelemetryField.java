package dolphin.sensor;

import com.MAVLink.Messages.MAVLinkMessage;
import dolphin.dsl.vocabulary.Suggestions;
import dolphin.mavlink.codec.MessageTable;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.UncheckedIOException;
import java.lang.reflect.Array;
import java.lang.reflect.Field;
import java.nio.charset.StandardCharsets;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * One field of one MAVLink message as scripts name it, {@code telemetry(v, 'VFR_HUD', 'groundspeed')},
 * with its unit converted to Dolphin's ({@link FieldUnits}). An element of an array field is named
 * with its index: {@code 'voltages[0]'}. The fields and units come from the table the build generates
 * from the pinned pymavlink (dolphin/mavlink/fields.tsv).
 *
 * @param message the message name, e.g. "VFR_HUD"
 * @param field the field name, e.g. "groundspeed"
 * @param index the array element, -1 for a whole field
 * @param msgid the message's id
 * @param type the field's MAVLink type, e.g. "float", "char"
 * @param arrayLength the array's length, 0 for a plain field
 * @param mavlinkUnit the unit the XML gives, "" for none
 */
public record TelemetryField(String message, String field, int index, int msgid, String type, int arrayLength,
                             String mavlinkUnit) {

    private record Declared(String type, int arrayLength, String unit) {
    }

    private static final Pattern ELEMENT = Pattern.compile("(\\w+)\\[(\\d+)]");
    private static final Map<String, Map<String, Declared>> FIELDS = load();

    /** The field, or an IllegalArgumentException that says what exists instead. */
    public static TelemetryField of(String message, String field) {
        Map<String, Declared> fields = FIELDS.get(message);
        if (fields == null) {
            List<String> near = Suggestions.near(message, FIELDS.keySet());
            throw new IllegalArgumentException("no MAVLink message " + message
                    + (near.isEmpty() ? " (names are upper case, e.g. VFR_HUD)" : "; did you mean " + quoted(near) + "?"));
        }
        Matcher element = ELEMENT.matcher(field);
        String name = element.matches() ? element.group(1) : field;
        Declared d = fields.get(name);
        if (d == null) {
            List<String> near = Suggestions.near(name, fields.keySet());
            throw new IllegalArgumentException(message + " has no field " + name
                    + (near.isEmpty() ? "" : "; did you mean " + quoted(near) + "?") + " (its fields: " + String.join(", ", fields.keySet()) + ")");
        }
        int index = element.matches() ? Integer.parseInt(element.group(2)) : -1;
        boolean text = "char".equals(d.type());
        if (index >= 0 && (d.arrayLength() == 0 || text)) {
            throw new IllegalArgumentException(message + "." + name + " is not an array of numbers");
        }
        if (index >= d.arrayLength() && d.arrayLength() > 0) {
            throw new IllegalArgumentException(message + "." + name + " has " + d.arrayLength() + " elements, 0 to "
                    + (d.arrayLength() - 1) + "; got " + index);
        }
        if (index < 0 && d.arrayLength() > 0 && !text) {
            throw new IllegalArgumentException(message + "." + name + " is an array of " + d.arrayLength()
                    + "; name an element, e.g. '" + name + "[0]'");
        }
        return new TelemetryField(message, name, index, MessageTable.get().id(message), d.type(), d.arrayLength(), d.unit());
    }

    /** The unit the value is given in, after conversion; "" when MAVLink gives none. */
    public String unit() {
        return FieldUnits.of(mavlinkUnit).unit();
    }

    public boolean text() {
        return "char".equals(type);
    }

    /** The field's value in a message of this kind: a String for text, else a Double in {@link #unit()}. */
    public Object valueIn(MAVLinkMessage m) {
        try {
            Field f = m.getClass().getField(field);
            Object raw = f.get(m);
            if (text()) {
                return text((byte[]) raw);
            }
            Object element = index >= 0 ? Array.get(raw, index) : raw;
            return ((Number) element).doubleValue() * FieldUnits.of(mavlinkUnit).factor();
        } catch (NoSuchFieldException | IllegalAccessException e) {
            throw new IllegalStateException("the bindings of " + message + " lack field " + field, e);
        }
    }

    private static String text(byte[] bytes) {
        int end = 0;
        while (end < bytes.length && bytes[end] != 0) {
            end++;
        }
        return new String(bytes, 0, end, StandardCharsets.US_ASCII);
    }

    private static String quoted(List<String> names) {
        return String.join(" or ", names.stream().map(n -> "'" + n + "'").toList());
    }

    private static Map<String, Map<String, Declared>> load() {
        String resource = "/dolphin/mavlink/fields.tsv";
        try (InputStream in = TelemetryField.class.getResourceAsStream(resource)) {
            if (in == null) {
                throw new IllegalStateException("missing " + resource + ": the build generates it (harness/generate-bindings.sh)");
            }
            Map<String, Map<String, Declared>> fields = new LinkedHashMap<>();
            new BufferedReader(new InputStreamReader(in, StandardCharsets.US_ASCII)).lines()
                    .filter(l -> !l.startsWith("#") && !l.isBlank())
                    .map(l -> l.split("\t", -1))
                    .forEach(f -> fields.computeIfAbsent(f[0], k -> new LinkedHashMap<>())
                            .put(f[1], new Declared(f[2], Integer.parseInt(f[3]), f[4])));
            return fields;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
